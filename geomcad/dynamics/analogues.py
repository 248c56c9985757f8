"""Velocity and acceleration analogues of the simple mechanisms of the dynamics problems.

An analogue is a derivative with respect to the driving link's angle φ: the velocity analogue
v_q = dr/dφ (m/rad) is the velocity at φ' = 1 rad/s, the acceleration analogue a_q = d²r/dφ² is
the acceleration at φ' = 1 rad/s and φ'' = 0. A real motion then has v = v_q·φ' and
a = a_q·φ'² + v_q·φ''. Rotations likewise: ω_q = dθ/dφ, ε_q = d²θ/dφ².

The lever mechanisms below are plans for the one sweep kernel of
:mod:`geomcad.kinematics.chain` (the kernel of every linkage file and of 2013-6's six-bar), swept
at ω1 = 1 rad/s and ε1 = 0 over arrays of φ at once:

- a body turning with the driving link about a fixed centre (a crank, a disc, a flywheel): the
  kernel's crank, θ = φ, ω_q = its ω1; and a point on it (the crank pin, V_A = ω × OA);
- a slotted yoke: a translating body whose straight slot is driven by the crank pin: the crank and
  a PRP group, V_A2 = V_A1 + V_A2A1 with V_A2 ∥ the guide and V_A2A1 ∥ the slot (no Coriolis
  term: the yoke does not turn).

One mechanism stays a closed form, because it is no lever mechanism: a wheel that rolls without
slip on a fixed straight base and is driven, without slip, at its hub radius r by a translating
member on the side away from the base. Rolling without slip is a higher pair (two of them), which
the kernel's groups (revolute and prismatic pairs only) cannot state; its instantaneous centre is
the base contact P, so ω = V_D / (R + r) and V_C = ω·R.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import DegenerateInput, ParameterError
from geomcad.geom import PointLike, Vec, vec
from geomcad.kinematics.chain import PRP, Chain, Crank, State, run

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


#: The crank angles at which the kernel is swept for a linear mechanism's coefficients (0, π/2
#: and π), and one more at which their superposition is checked against the kernel.
BASIS = (0.0, math.pi / 2.0, math.pi, 1.0)
#: Coefficients below this fraction of the largest quantity are what cos π/2 and sin π leave.
ROUNDING = 16.0 * float(np.finfo(np.float64).eps)


@dataclass(frozen=True)
class Linear:
    """Quantities of a mechanism that are linear in its crank pin, q(φ) = k0 + kc·cos φ +
    ks·sin φ, their coefficients read off the sweep kernel (:func:`linear`).

    A crank and the groups driven by its pin through prismatic pairs that do not turn (a
    slotted yoke, PRP) are such a mechanism: positions, velocity and acceleration analogues are
    all linear in A = O + r(cos φ, sin φ) and its derivatives. Evaluating the superposition costs
    a few array operations at any φ, so an equation of motion may ask for it at one φ at a time.
    """

    names: tuple[str, ...]
    k: Array  # (3, len(names)): k0, kc, ks

    def __call__(self, phi: ArrayLike) -> dict[str, Array]:
        """Every quantity at φ (rad), each in the shape of φ."""
        p = _arr(phi)
        c, s = np.cos(p), np.sin(p)
        k0, kc, ks = self.k
        vals = k0 + np.multiply.outer(c, kc) + np.multiply.outer(s, ks)
        return {n: vals[..., i] for i, n in enumerate(self.names)}


def linear(chain: Chain, read: Callable[[State], dict[str, Array]]) -> Linear:
    """The quantities ``read`` takes from the kernel's state of ``chain`` (swept at ω1 = 1,
    ε1 = 0, accelerations included) as a :class:`Linear` superposition.

    The kernel is swept at φ = 0, π/2, π (k0 = (q(0) + q(π))/2, kc = (q(0) − q(π))/2,
    ks = q(π/2) − k0) and at φ = 1 rad, where the superposition must give the kernel's numbers:
    a mechanism that is not linear in its crank pin raises :class:`DegenerateInput`.
    """
    got = read(run(chain, np.array(BASIS), order=2))
    names = tuple(got)
    F = np.stack([np.asarray(got[n], dtype=np.float64) for n in names], axis=1)  # (4, m)
    k0 = 0.5 * (F[0] + F[2])
    kc = 0.5 * (F[0] - F[2])
    ks = F[1] - k0
    check = k0 + kc * math.cos(BASIS[3]) + ks * math.sin(BASIS[3])
    scale = float(np.max(np.abs(F))) if F.size else 0.0
    if not np.allclose(check, F[3], rtol=0.0, atol=tol.DERIVED * scale):
        raise DegenerateInput("analogues", "the mechanism is not linear in its crank pin")
    k = np.stack([k0, kc, ks])
    # cos π/2 and sin π are not exactly 0 in floating point: what they leave is rounding
    k[np.abs(k) <= ROUNDING * scale] = 0.0
    return Linear(names, k)


def _crank(r: float, c: Vec) -> Chain:
    return Chain({"O": (c.x, c.y)}, Crank("O", "A", r), ())


def _motion(name: str, link: int) -> Callable[[State], dict[str, Array]]:
    """The kernel's position, velocity and acceleration of a point, ω and ε of its link."""

    def read(st: State) -> dict[str, Array]:
        P, V, a = st.pos[name], st.vel[name], st.acc[name]
        return {
            "x": P[:, 0], "y": P[:, 1], "vx": V[:, 0], "vy": V[:, 1], "w": st.omega[link],
            "ax": a[:, 0], "ay": a[:, 1], "e": st.eps[link],
        }  # fmt: skip

    return read


def _as_motion(q: dict[str, Array], theta: Array, pre: str = "") -> Motion:
    return Motion(q[pre + "x"], q[pre + "y"], theta, q[pre + "vx"], q[pre + "vy"], q[pre + "w"],
                  q[pre + "ax"], q[pre + "ay"], q[pre + "e"])  # fmt: skip


@lru_cache(maxsize=64)
def _crank_model(r: float, cx: float, cy: float, point: str) -> Linear:
    return linear(_crank(r, Vec(cx, cy)), _motion(point, 1))


def turning(phi: ArrayLike, centre: PointLike = (0.0, 0.0)) -> Motion:
    """A body that turns with the driving link about the fixed ``centre``: the kernel's crank,
    θ = φ, ω_q = ω1 = 1, ε_q = 0; the reference point is the centre."""
    c = vec(centre)
    p = _arr(phi)
    return _as_motion(_crank_model(1.0, c.x, c.y, "O")(p), p + 0.0)


def crank_point(phi: ArrayLike, r: float, centre: PointLike = (0.0, 0.0)) -> Motion:
    """The point A at radius ``r`` on the driving link (the kernel's crank joint):
    A = O + r(cos φ, sin φ).

    V_A = ω × OA is perpendicular to OA (v_q = r(−sin φ, cos φ)); at ε = 0 its acceleration is the
    normal one, from A to O (a_q = −r(cos φ, sin φ)).
    """
    c = vec(centre)
    p = _arr(phi)
    return _as_motion(_crank_model(r, c.x, c.y, "A")(p), p + 0.0)


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


@lru_cache(maxsize=64)
def _yoke_model(
    r: float, guide: tuple[float, float], slot: tuple[float, float], o: Vec, b0: Vec
) -> Linear:
    u, sd = np.array(guide), np.array(slot)
    crank = _crank(r, o)
    # the yoke's point J on the guide line through O (J = O at s = 0), driven by the pin A
    chain = Chain(crank.frame, crank.crank, (PRP("J", "A", (o.x, o.y), guide, slot, (2, 3)),))
    pin = _motion("A", 1)

    def read(st: State) -> dict[str, Array]:
        J, VJ, aJ = st.pos["J"], st.vel["J"], st.acc["J"]
        s, vs, as_ = (J - o.array()) @ u, VJ @ u, aJ @ u
        return {
            **{"pin_" + k: v for k, v in pin(st).items()},
            "x": b0.x + s * u[0], "y": b0.y + s * u[1], "vx": vs * u[0], "vy": vs * u[1],
            "w": st.omega[3], "ax": as_ * u[0], "ay": as_ * u[1], "e": st.eps[3],
            "s": s, "vs": vs, "as": as_,
            # V_A2A1 = V_J − V_A and a_A2A1 = a_J − a_A lie along the slot
            "vrel": (VJ - st.vel["A"]) @ sd, "arel": (aJ - st.acc["A"]) @ sd,
        }  # fmt: skip

    return linear(chain, read)


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

    The kernel's crank and PRP group: the slot line, which passes through ``centre`` when the
    yoke's displacement s is 0, carries the pin, (A − O − s·u) × slot = 0; the velocity plan
    s'·u = V_A1 + V_A2A1 with V_A2A1 ∥ slot; the acceleration plan the same equation with a_A1
    (the yoke does not turn, so there is no Coriolis term). ``body0`` is the yoke's reference
    point (its centre of mass) at s = 0.

    Raises :class:`DegenerateInput` when the slot is parallel to the guide (the pin cannot drive
    the yoke along it) and :class:`ParameterError` when r is not positive.
    """
    if not r > 0.0:
        raise ParameterError("r", r, "the crank radius must be positive")
    u = Vec(float(np.cos(guide_angle)), float(np.sin(guide_angle)))
    sd = Vec(float(np.cos(slot_angle)), float(np.sin(slot_angle)))
    if abs(u.cross(sd)) <= tol.ANGLE:  # |u × slot| is the sine of the angle between them
        raise DegenerateInput(
            "slotted yoke", "the slot is parallel to the guide: the pin cannot drive the yoke"
        )
    p = _arr(phi)
    q = _yoke_model(r, (u.x, u.y), (sd.x, sd.y), vec(centre), vec(body0))(p)
    zero = q["w"]
    return Yoke(_as_motion(q, zero), _as_motion(q, p + 0.0, "pin_"), u, sd,
                q["s"], q["vs"], q["as"], q["vrel"], q["arel"])  # fmt: skip


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
