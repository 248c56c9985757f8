"""Velocity and acceleration analogues of the simple mechanisms of the dynamics problems.

An analogue is a derivative with respect to the driving link's angle φ: the velocity analogue
v_q = dr/dφ (m/rad) is the velocity at φ' = 1 rad/s, the acceleration analogue a_q = d²r/dφ² is
the acceleration at φ' = 1 rad/s and φ'' = 0. A real motion then has v = v_q·φ' and
a = a_q·φ'² + v_q·φ''. Rotations likewise: ω_q = dθ/dφ, ε_q = d²θ/dφ².

The functions below solve the vector equations of the velocity and acceleration plans of three
small mechanisms in closed form, over arrays of φ at once:

- a body turning with the driving link about a fixed centre (a crank, a disc, a flywheel), and a
  point on it (the crank pin, V_A = ω × OA);
- a slotted yoke: a translating body whose straight slot is driven by the crank pin,
  V_A2 = V_A1 + V_A2A1 with V_A2 ∥ the guide and V_A2A1 ∥ the slot (no Coriolis term: the yoke
  does not turn);
- a wheel that rolls without slip on a fixed straight base and is driven, without slip, at its hub
  radius r by a translating member on the side away from the base: its instantaneous centre is
  the base contact P, so ω = V_D / (R + r) and V_C = ω·R.

They are kept apart from the dynamic model on purpose: when the general velocity-plan solver
(``geomcad.kinematics.plan``) lands, these mechanisms switch to it and the dynamic model, which
only reads :class:`Motion` objects, does not change.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import DegenerateInput, ParameterError
from geomcad.geom import PointLike, Vec, vec

Array = npt.NDArray[np.float64]
ArrayLike = float | npt.ArrayLike


def _arr(phi: ArrayLike) -> Array:
    return np.asarray(phi, dtype=np.float64)


F = TypeVar("F", bound=Callable[[Any], Any])


def remember_last(fn: F) -> F:
    """``fn(φ)`` with a memory of one scalar φ: asked again for the same φ (as an equation of
    motion's right-hand side asks for a part's motion several times per evaluation), it returns
    the same result without computing it again. Arrays of φ are always computed."""
    last: list[Any] = [None, None]

    def once(phi: Any) -> Any:
        if isinstance(phi, float | int) or (isinstance(phi, np.ndarray) and phi.ndim == 0):
            x = float(phi)
            if last[0] is not None and last[0] == x:
                return last[1]
            result = fn(phi)
            last[0], last[1] = x, result
            return result
        return fn(phi)

    return once  # type: ignore[return-value]


@dataclass(frozen=True)
class Motion:
    """The position of a body (a reference point x, y and an angle θ) and its analogues.

    Every field is an array of the shape of the φ it was evaluated at (0-d for a single φ):
    ``vx, vy, w`` are dx/dφ, dy/dφ, dθ/dφ; ``ax, ay, e`` are the second derivatives.
    """

    x: Array
    y: Array
    theta: Array
    vx: Array
    vy: Array
    w: Array
    ax: Array
    ay: Array
    e: Array

    def point(self) -> Vec:
        """The reference point at a single φ."""
        return Vec(float(self.x), float(self.y))

    def velocity(self, dphi: float) -> tuple[Vec, float]:
        """(V of the reference point, ω of the body) at a single φ for φ' = ``dphi``."""
        return Vec(float(self.vx) * dphi, float(self.vy) * dphi), float(self.w) * dphi

    def acceleration(self, dphi: float, ddphi: float) -> tuple[Vec, float]:
        """(a of the reference point, ε of the body) at a single φ: a = a_q·φ'² + v_q·φ''."""
        d2 = dphi * dphi
        a = Vec(
            float(self.ax) * d2 + float(self.vx) * ddphi,
            float(self.ay) * d2 + float(self.vy) * ddphi,
        )
        return a, float(self.e) * d2 + float(self.w) * ddphi

    def translated(self, d: PointLike) -> Motion:
        """The same motion of the point shifted by ``d`` on a body that does not turn."""
        dv = vec(d)
        return Motion(self.x + dv.x, self.y + dv.y, self.theta, self.vx, self.vy, self.w,
                      self.ax, self.ay, self.e)  # fmt: skip


def turning(phi: ArrayLike, centre: PointLike = (0.0, 0.0)) -> Motion:
    """A body that turns with the driving link about the fixed ``centre``: θ = φ, ω_q = 1."""
    p = _arr(phi)
    c = vec(centre)
    zero = np.zeros_like(p)
    return Motion(zero + c.x, zero + c.y, p, zero, zero, zero + 1.0, zero, zero, zero)


def crank_point(phi: ArrayLike, r: float, centre: PointLike = (0.0, 0.0)) -> Motion:
    """The point A at radius ``r`` on the driving link: A = O + r(cos φ, sin φ).

    V_A = ω × OA is perpendicular to OA (v_q = r(−sin φ, cos φ)); at ε = 0 its acceleration is the
    normal one, from A to O (a_q = −r(cos φ, sin φ)).
    """
    p = _arr(phi)
    c = vec(centre)
    cs, sn = np.cos(p), np.sin(p)
    zero = np.zeros_like(p)
    return Motion(c.x + r * cs, c.y + r * sn, p, -r * sn, r * cs, zero + 1.0,
                  -r * cs, -r * sn, zero)  # fmt: skip


@dataclass(frozen=True)
class Yoke:
    """A slotted yoke at some φ: the yoke's motion, the pin's, and the slip along the slot.

    ``s`` (with ``vs``, ``as_``) is the yoke's displacement along its guide direction ``u``;
    ``rel`` (with ``vrel``, ``arel``) is the velocity and acceleration analogue of the yoke's point
    under the pin relative to the pin (V_A2A1 = vrel·slot), signed along the slot direction.
    """

    body: Motion
    pin: Motion
    u: Vec
    slot: Vec
    s: Array
    vs: Array
    as_: Array
    vrel: Array
    arel: Array


def slotted_yoke(
    phi: ArrayLike,
    r: float,
    guide_angle: float,
    slot_angle: float,
    centre: PointLike = (0.0, 0.0),
    body0: PointLike = (0.0, 0.0),
) -> Yoke:
    """A yoke that translates along a guide at ``guide_angle`` (rad) and is driven by the crank
    pin at radius ``r`` about ``centre`` in its straight slot at ``slot_angle``.

    Position: the slot line, which passes through ``centre`` when the yoke's displacement s is 0,
    carries the pin: (A − O − s·u) × slot = 0. Velocity plan: s'·u = V_A1 + V_A2A1 with
    V_A2A1 ∥ slot, solved by Cramer's rule. Acceleration plan: the same equation with a_A1 (the
    yoke does not turn, so there is no Coriolis term). ``body0`` is the yoke's reference point
    (its centre of mass) at s = 0.

    Raises :class:`DegenerateInput` when the slot is parallel to the guide (the pin cannot drive
    the yoke along it) and :class:`ParameterError` when r is not positive.
    """
    if not r > 0.0:
        raise ParameterError("r", r, "the crank radius must be positive")
    u = Vec(float(np.cos(guide_angle)), float(np.sin(guide_angle)))
    sd = Vec(float(np.cos(slot_angle)), float(np.sin(slot_angle)))
    det = u.cross(sd)
    if abs(det) <= tol.ANGLE:  # |u × slot| is the sine of the angle between them
        raise DegenerateInput(
            "slotted yoke", "the slot is parallel to the guide: the pin cannot drive the yoke"
        )
    pin = crank_point(phi, r, centre)
    o = vec(centre)

    def along_guide(x: Array, y: Array) -> Array:
        # the u-component of the decomposition (x, y) = a·u − b·slot
        return (x * sd.y - y * sd.x) / det

    def along_slot(x: Array, y: Array) -> Array:
        return -(u.x * y - u.y * x) / det

    s = along_guide(pin.x - o.x, pin.y - o.y)
    vs = along_guide(pin.vx, pin.vy)
    as_ = along_guide(pin.ax, pin.ay)
    vrel = along_slot(pin.vx, pin.vy)
    arel = along_slot(pin.ax, pin.ay)
    b0 = vec(body0)
    zero = np.zeros_like(s)
    body = Motion(b0.x + s * u.x, b0.y + s * u.y, zero, vs * u.x, vs * u.y, zero,
                  as_ * u.x, as_ * u.y, zero)  # fmt: skip
    return Yoke(body, pin, u, sd, s, vs, as_, vrel, arel)


def rolling_wheel(drive: Motion, u: PointLike, R: float, r: float, centre0: PointLike) -> Motion:
    """A wheel rolling without slip on a fixed straight base along ``u``, driven without slip at
    its hub radius ``r`` by a member that translates along ``u`` on the side away from the base.

    The base lies to the right of ``u`` (below the wheel for u = (1, 0)); the wheel's centre is
    ``centre0`` when the driving member's reference point has no component along u. The base
    contact P is the instantaneous centre, the drive contact D is R + r from it on the line PC:
    ω = −V_D/(R + r) (clockwise for a drive moving along u) and V_C = ω × PC = V_D·R/(R + r).

    Returns the motion of the wheel's centre and its angle (0 at the start).
    """
    if not (R > 0.0 and r >= 0.0):
        raise ParameterError("R", R, "the rolling radius must be positive and the hub radius ≥ 0")
    d = vec(u).unit()
    c0 = vec(centre0)
    k = R / (R + r)
    s = drive.x * d.x + drive.y * d.y
    vs = drive.vx * d.x + drive.vy * d.y
    as_ = drive.ax * d.x + drive.ay * d.y
    return Motion(c0.x + k * s * d.x, c0.y + k * s * d.y, -s / (R + r),
                  k * vs * d.x, k * vs * d.y, -vs / (R + r),
                  k * as_ * d.x, k * as_ * d.y, -as_ / (R + r))  # fmt: skip
