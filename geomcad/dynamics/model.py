"""A machine's dynamic model reduced to its driving link.

Every moving body is a :class:`Part`: a :class:`Body` (mass m, moment of inertia J about its
centre of mass) and its :class:`~geomcad.dynamics.analogues.Motion` as a function of the driving
link's angle φ. The kinetic energy is T = ½·J_pr(φ)·φ'², with the reduced moment of inertia

    J_pr(φ) = Σ (m·v_S² + J·ω²) / ω1² = Σ (m·|v_qS|² + J·ω_q²),

summed over the parts with their velocity analogues (v_qS = dr_S/dφ, ω_q = dθ/dφ), and its
derivative dJ_pr/dφ = Σ 2(m·v_qS·a_qS + J·ω_q·ε_q) from the acceleration analogues.

The loads are reduced to the driving link by equal power: a force F at a point with velocity
analogue v_q contributes F·v_q, a moment M on a body with ω_q contributes M·ω_q, so
M_pr·φ' = Σ P. The machine's equation of motion (from dT/dt = Σ P) is then

    J_pr(φ)·φ'' + ½·(dJ_pr/dφ)·φ'² = M_pr(φ, φ', t).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from geomcad import tol
from geomcad.dynamics.analogues import Array, ArrayLike, Motion
from geomcad.errors import ConstructionError, ParameterError

MotionFn = Callable[[Array], Motion]
#: A load's value as a function of (φ, φ', t), each an array of one shape.
LoadFn = Callable[[Array, Array, Array], Array]
ForceFn = Callable[[Array, Array, Array], tuple[Array, Array]]

#: Points per turn at which J_pr is sampled before its minimum is refined.
TURN_SAMPLES = 721


@dataclass(frozen=True)
class Body:
    """A rigid body: mass ``m`` (kg) and moment of inertia ``J`` (kg·m²) about its centre of mass.

    A negative or non-finite mass or moment of inertia is a :class:`ParameterError`.
    """

    name: str
    m: float
    J: float = 0.0

    def __post_init__(self) -> None:
        for what, v in (("m", self.m), ("J", self.J)):
            if not (math.isfinite(v) and v >= 0.0):
                raise ParameterError(
                    f"{what} of {self.name}", v, "a mass or a moment of inertia cannot be negative"
                )


@dataclass(frozen=True)
class Part:
    """A moving body and the motion of its centre of mass and its angle, as functions of φ."""

    body: Body
    motion: MotionFn


@dataclass(frozen=True)
class Torque:
    """A moment ``M(φ, φ', t)`` (N·m, counter-clockwise positive) on the body moving as ``motion``.

    ``positional`` says that M depends on φ only (the energy method needs it).
    """

    name: str
    motion: MotionFn
    M: LoadFn
    positional: bool = True

    def reduced(self, phi: Array, dphi: Array, t: Array) -> Array:
        """Its share of M_pr: M·ω_q."""
        return self.M(phi, dphi, t) * self.motion(phi).w


@dataclass(frozen=True)
class Force:
    """A force ``F(φ, φ', t) = (Fx, Fy)`` (N) at the point moving as ``motion``."""

    name: str
    motion: MotionFn
    F: ForceFn
    positional: bool = True

    def reduced(self, phi: Array, dphi: Array, t: Array) -> Array:
        """Its share of M_pr: F·v_q."""
        fx, fy = self.F(phi, dphi, t)
        m = self.motion(phi)
        return fx * m.vx + fy * m.vy


Load = Torque | Force


def _arrays(phi: ArrayLike, dphi: ArrayLike, t: ArrayLike) -> tuple[Array, Array, Array]:
    p, d, tt = np.broadcast_arrays(
        np.asarray(phi, dtype=np.float64),
        np.asarray(dphi, dtype=np.float64),
        np.asarray(t, dtype=np.float64),
    )
    return p, d, tt


class ReducedModel:
    """The dynamic model of a one-degree-of-freedom machine reduced to its driving link."""

    def __init__(self, parts: Sequence[Part], loads: Sequence[Load] = ()) -> None:
        self.parts = tuple(parts)
        self.loads = tuple(loads)

    @property
    def positional(self) -> bool:
        """True when every load depends on φ only (then M_pr(φ) has a work integral)."""
        return all(ld.positional for ld in self.loads)

    # -- inertia -------------------------------------------------------------------------------
    def inertia_terms(self, phi: ArrayLike) -> dict[str, Array]:
        """Each part's share of J_pr: m·|v_qS|² + J·ω_q² (kg·m²)."""
        p = np.asarray(phi, dtype=np.float64)
        out: dict[str, Array] = {}
        for part in self.parts:
            mo = part.motion(p)
            b = part.body
            out[b.name] = b.m * (mo.vx**2 + mo.vy**2) + b.J * mo.w**2
        return out

    def J_pr(self, phi: ArrayLike) -> Array:
        """The reduced moment of inertia J_pr(φ) (kg·m²)."""
        p = np.asarray(phi, dtype=np.float64)
        return np.asarray(sum(self.inertia_terms(p).values(), np.zeros_like(p)))

    def dJ_pr(self, phi: ArrayLike) -> Array:
        """dJ_pr/dφ (kg·m²/rad) = Σ 2(m·v_qS·a_qS + J·ω_q·ε_q)."""
        p = np.asarray(phi, dtype=np.float64)
        total = np.zeros_like(p)
        for part in self.parts:
            mo = part.motion(p)
            b = part.body
            total = total + 2.0 * (b.m * (mo.vx * mo.ax + mo.vy * mo.ay) + b.J * mo.w * mo.e)
        return total

    # -- loads ---------------------------------------------------------------------------------
    def moment_terms(
        self, phi: ArrayLike, dphi: ArrayLike = 0.0, t: ArrayLike = 0.0
    ) -> dict[str, Array]:
        """Each load's share of M_pr (N·m), by equal power."""
        p, d, tt = _arrays(phi, dphi, t)
        return {ld.name: ld.reduced(p, d, tt) for ld in self.loads}

    def M_pr(self, phi: ArrayLike, dphi: ArrayLike = 0.0, t: ArrayLike = 0.0) -> Array:
        """The reduced moment of the loads M_pr(φ, φ', t) (N·m)."""
        p, d, tt = _arrays(phi, dphi, t)
        return np.asarray(sum(self.moment_terms(p, d, tt).values(), np.zeros_like(p)))

    # -- the equation of motion ----------------------------------------------------------------
    def phi_ddot(self, phi: ArrayLike, dphi: ArrayLike, t: ArrayLike = 0.0) -> Array:
        """φ'' from J_pr·φ'' + ½·J_pr'·φ'² = M_pr."""
        p, d, tt = _arrays(phi, dphi, t)
        return (self.M_pr(p, d, tt) - 0.5 * self.dJ_pr(p) * d * d) / self.J_pr(p)

    def residual(self, phi: float, dphi: float, ddphi: float, t: float = 0.0) -> float:
        """J_pr·φ'' + ½·J_pr'·φ'² − M_pr at a state (zero on a motion of the machine)."""
        j = float(self.J_pr(phi))
        dj = float(self.dJ_pr(phi))
        return j * ddphi + 0.5 * dj * dphi * dphi - float(self.M_pr(phi, dphi, t))

    def check_inertia(self, phi0: float = 0.0, span: float = 2.0 * math.pi) -> float:
        """The smallest J_pr over φ0 … φ0 + span (a turn by default); zero anywhere there is a
        :class:`ConstructionError`, since the equation of motion cannot be solved for φ''.

        The minimum is found on a grid and refined with scipy's bounded ``minimize_scalar``; J_pr
        counts as zero below :data:`geomcad.tol.DERIVED` of its largest value.
        """
        grid = phi0 + np.linspace(0.0, span, TURN_SAMPLES)
        j = self.J_pr(grid)
        i = int(np.argmin(j))
        lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
        res = minimize_scalar(
            lambda x: float(self.J_pr(x)), bounds=(lo, hi), method="bounded",
            options={"xatol": tol.ROOT_ANGLE},
        )  # fmt: skip
        at, jmin = (float(res.x), float(res.fun)) if res.fun < j[i] else (float(grid[i]), j[i])
        jmax = float(np.max(j))
        if not jmin > tol.DERIVED * jmax:
            raise ConstructionError(
                "J_pr(φ) over a turn",
                f"the reduced moment of inertia is zero at φ = {math.degrees(at) % 360.0:.6g}° "
                "(no part there has inertia that moves with the driving link), so the equation "
                "of motion J_pr·φ'' + ½·J_pr'·φ'² = M_pr cannot be solved for φ''",
            )
        return float(jmin)
