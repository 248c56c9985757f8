"""The motion of a machine: the kinetic-energy theorem and the equation of motion integrated.

Two independent ways to the same angular velocity of the driving link:

- **energy** (:func:`omega_by_energy`): from the kinetic-energy theorem
  ½·J_pr(φ)·ω² − ½·J_pr(φ0)·ω0² = ∫ M_pr dφ, for loads that depend on the position only; the
  work is a scipy ``quad`` integral, and the time to get there is ∫ dφ/ω (:func:`time_by_energy`);
- **integration** (:func:`integrate`, :func:`reach`): J_pr·φ'' + ½·J_pr'·φ'² = M_pr(φ, φ', t)
  as a first-order system for (φ, φ'), solved by scipy's ``solve_ivp`` (DOP853) with the
  tolerances :data:`geomcad.tol.ODE_RTOL` and :data:`geomcad.tol.ODE_ATOL`.

Every integration has a budget (:data:`MAX_EVALUATIONS` evaluations of the equation,
:data:`MAX_SECONDS` of wall clock); spent, it is a :class:`ConstructionError` naming the step and
what makes the motion costly (a stiff spring, a fast excitation, many turns). A stiff equation —
a strong damper, whose motion decays much faster than the span integrated — is handed to
``LSODA``, which switches to an implicit (BDF) method where the equation is stiff.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import cumulative_trapezoid, quad, solve_ivp

from geomcad import tol
from geomcad.construction.guard import Budget
from geomcad.dynamics.analogues import Array
from geomcad.dynamics.model import ReducedModel
from geomcad.errors import ConstructionError

#: Points at which the kinetic energy is checked to stay positive on the way to a position.
PATH_SAMPLES = 2049
#: The integrator used by :func:`integrate` and :func:`reach`.
METHOD = "DOP853"
#: How many times :func:`reach` doubles its time horizon before it gives up.
MAX_DOUBLINGS = 40
#: The integrator for a stiff equation (LSODA: Adams where it can, BDF where it is stiff).
STIFF_METHOD = "LSODA"
#: An equation is stiff when its fastest decay rate times the span integrated exceeds this.
STIFF_SPAN = 200.0
#: The budget of one integration: evaluations of the equation of motion, and wall-clock seconds
#: (a safety net only; the count of evaluations decides on any machine).
MAX_EVALUATIONS = 6000
MAX_SECONDS = 20.0

STEP_ENERGY = "ω from the kinetic-energy theorem"
STEP_ODE = "φ(t) from the equation of motion (solve_ivp)"


def ode_settings(method: str = METHOD) -> str:
    """The integrator and its tolerances, in words (for notes and sheets)."""
    return f"solve_ivp ({method}, rtol = {tol.ODE_RTOL:g}, atol = {tol.ODE_ATOL:g})"


def rates(model: ReducedModel, phi: float, omega: float, t: float = 0.0) -> tuple[float, float]:
    """The linearised equation's rates at a state: (fastest decay rate, fastest oscillation
    frequency) in 1/s, from the eigenvalues of the Jacobian of (φ, φ') ↦ (φ', φ'') by central
    differences (the stiffness a strong damper brings, the frequency a stiff spring brings)."""
    h_p = tol.DIFF_STEP * max(1.0, abs(phi))
    h_w = tol.DIFF_STEP * max(1.0, abs(omega))
    a = float(model.phi_ddot(phi + h_p, omega, t) - model.phi_ddot(phi - h_p, omega, t)) / (2 * h_p)
    b = float(model.phi_ddot(phi, omega + h_w, t) - model.phi_ddot(phi, omega - h_w, t)) / (2 * h_w)
    lam = np.roots([1.0, -b, -a])  # λ² − bλ − a = 0
    decay = float(max(0.0, -float(np.min(lam.real))))
    freq = float(np.max(np.abs(lam.imag)))
    return decay, freq


def _budget(
    model: ReducedModel, phi0: float, omega0: float, t0: float, span: float
) -> tuple[Budget, str]:
    """The budget of an integration over ``span`` seconds and the method it picks."""
    decay, freq = rates(model, phi0, omega0, t0)
    method = STIFF_METHOD if decay * span > STIFF_SPAN else METHOD
    hints = []
    if freq * span > 100.0:
        hints.append(
            f"the equation oscillates at ≈ {freq:.3g} rad/s (a stiff spring or a light inertia), "
            f"≈ {freq * span / (2.0 * math.pi):.3g} times over the {span:.3g} s integrated"
        )
    if decay * span > STIFF_SPAN:
        hints.append(f"it is stiff (a motion decaying at ≈ {decay:.3g} 1/s, {STIFF_METHOD} used)")
    hints.append(
        "a long run or a fast drive makes many turns to follow; shorten the time or soften the "
        "parameters"
    )
    return Budget(STEP_ODE, MAX_EVALUATIONS, MAX_SECONDS, "; ".join(hints)), method


def _need_positional(model: ReducedModel) -> None:
    if not model.positional:
        raise ConstructionError(
            STEP_ENERGY,
            "a load depends on φ' or on t, so its work depends on the motion and the theorem "
            "gives no closed answer; integrate the equation of motion instead",
        )


def work(model: ReducedModel, phi0: float, phi: float) -> float:
    """The work of the loads from φ0 to φ: ∫ M_pr(ψ) dψ (J), by scipy ``quad``."""
    _need_positional(model)
    w, _ = quad(lambda x: float(model.M_pr(x)), phi0, phi, epsrel=tol.QUAD_REL, epsabs=0.0,
                limit=200)  # fmt: skip
    return float(w)


def omega_by_energy(model: ReducedModel, phi0: float, phi: float, omega0: float = 0.0) -> float:
    """ω1 at φ from the kinetic-energy theorem, starting at φ0 with ω0 (φ > φ0, ω ≥ 0).

    Raises :class:`ConstructionError` when the kinetic energy reaches zero on the way (the driving
    moment cannot bring the machine from φ0 to φ: it stops, or turns back, before).
    """
    _need_positional(model)
    if not phi > phi0:
        raise ConstructionError(STEP_ENERGY, f"the position φ must lie ahead of φ0 = {phi0:.6g}")
    t0 = 0.5 * float(model.J_pr(phi0)) * omega0 * omega0
    path = np.linspace(phi0, phi, PATH_SAMPLES)
    w_path = cumulative_trapezoid(model.M_pr(path), path, initial=0.0)
    t_path = t0 + w_path[1:]
    if np.any(t_path <= 0.0):
        i = int(np.argmax(t_path <= 0.0)) + 1
        start = "from rest" if omega0 == 0.0 else f"with ω0 = {omega0:.6g} rad/s"
        raise ConstructionError(
            STEP_ENERGY,
            f"the work of the loads from φ0 = {math.degrees(phi0):.6g}° to "
            f"{math.degrees(path[i]):.6g}° is {w_path[i]:.6g} J, so the kinetic energy "
            f"{t0:.6g} J + work reaches zero: starting {start} the loads cannot bring the machine "
            f"to φ = {math.degrees(phi):.6g}° (it stops or turns back before)",
        )
    t_end = t0 + work(model, phi0, phi)
    return math.sqrt(2.0 * t_end / float(model.J_pr(phi)))


def omega_curve(model: ReducedModel, phi0: float, phis: Array, omega0: float = 0.0) -> Array:
    """ω1(φ) by the kinetic-energy theorem over an ascending array of φ ≥ φ0 (for diagrams);
    the work is integrated along the array (trapezoids on a refined grid)."""
    _need_positional(model)
    fine = np.linspace(phi0, float(phis[-1]), max(PATH_SAMPLES, 8 * len(phis)))
    w = cumulative_trapezoid(model.M_pr(fine), fine, initial=0.0)
    t = 0.5 * float(model.J_pr(phi0)) * omega0**2 + np.interp(phis, fine, w)
    return np.asarray(np.sqrt(np.maximum(2.0 * t / model.J_pr(phis), 0.0)), dtype=np.float64)


def time_by_energy(model: ReducedModel, phi0: float, phi: float) -> float:
    """The time from rest at φ0 to φ: t = ∫ dψ/ω(ψ), ω from the kinetic-energy theorem.

    Near the start ω ∝ √(ψ − φ0), so the integrand is written as g(ψ)/√(ψ − φ0) with a smooth g
    and integrated by ``quad`` with the algebraic weight (ψ − φ0)^(−1/2).
    """
    _need_positional(model)
    omega_by_energy(model, phi0, phi)  # the kinetic energy stays positive on the way

    def g(x: float) -> float:
        if x <= phi0:
            m0 = float(model.M_pr(phi0))
            return math.sqrt(float(model.J_pr(phi0)) / (2.0 * m0)) if m0 > 0.0 else math.inf
        w = work(model, phi0, x)
        return math.sqrt((x - phi0) * float(model.J_pr(x)) / (2.0 * w))

    t, _ = quad(g, phi0, phi, weight="alg", wvar=(-0.5, 0.0), epsrel=tol.QUAD_REL, limit=200)
    if not math.isfinite(t):
        raise ConstructionError(
            STEP_ENERGY, "the machine starts from an equilibrium and never leaves it in finite time"
        )
    return float(t)


@dataclass(frozen=True, repr=False)
class Trajectory:
    """A solved motion: ``t``, ``phi`` and ``omega`` arrays (s, rad, rad/s), and the dense
    solution ``sol(t) -> [φ, φ']`` over [t0, t_end]."""

    t: Array
    phi: Array
    omega: Array
    sol: Any
    t_end: float
    method: str = METHOD

    def __str__(self) -> str:
        return (
            f"motion over t = {self.t[0]:.6g}…{self.t_end:.6g} s: φ = {self.phi[-1]:.9g} rad, "
            f"φ' = {self.omega[-1]:.9g} rad/s at the end"
        )

    def at(self, t: float) -> tuple[float, float]:
        """(φ, φ') at time ``t``."""
        y = self.sol(t)
        return float(y[0]), float(y[1])


def _rhs(model: ReducedModel, budget: Budget) -> Any:
    def f(t: float, y: Array) -> list[float]:
        budget.spend()
        return [float(y[1]), float(model.phi_ddot(y[0], y[1], t))]

    return f


def integrate(
    model: ReducedModel,
    phi0: float,
    omega0: float,
    t_end: float,
    t0: float = 0.0,
    samples: int = 401,
) -> Trajectory:
    """The motion from (φ0, ω0) at t0 to t_end by ``solve_ivp``; ``samples`` points for plots."""
    if not t_end > t0:
        raise ConstructionError(STEP_ODE, f"the end time {t_end:g} s must follow t0 = {t0:g} s")
    budget, method = _budget(model, phi0, omega0, t0, t_end - t0)
    res = solve_ivp(
        _rhs(model, budget), (t0, t_end), [phi0, omega0], method=method, rtol=tol.ODE_RTOL,
        atol=tol.ODE_ATOL, dense_output=True,
    )  # fmt: skip
    if res.status != 0:
        raise ConstructionError(STEP_ODE, f"the integrator failed: {res.message}")
    ts = np.linspace(t0, t_end, samples)
    y = res.sol(ts)
    return Trajectory(ts, y[0], y[1], res.sol, t_end, method)


@dataclass(frozen=True, repr=False)
class Arrival:
    """When and how fast the machine reaches a position: time ``t`` (s), ``omega`` (rad/s) and the
    trajectory up to then."""

    t: float
    omega: float
    trajectory: Trajectory

    def __str__(self) -> str:
        return f"reached at t = {self.t:.9g} s with φ' = {self.omega:.9g} rad/s"


def reach(
    model: ReducedModel, phi0: float, phi: float, omega0: float = 0.0, t0: float = 0.0
) -> Arrival:
    """Integrate from (φ0, ω0) until φ reaches ``phi`` (> φ0), by ``solve_ivp`` with a terminal
    event. The time horizon starts at the constant-acceleration estimate and doubles until the
    position is reached; a machine that stops (φ' falls to zero) first is a
    :class:`ConstructionError`.
    """
    if not phi > phi0:
        raise ConstructionError(STEP_ODE, f"the position φ must lie ahead of φ0 = {phi0:.6g}")
    acc = float(model.phi_ddot(phi0, omega0, t0))
    gap = phi - phi0
    guess = gap / omega0 if omega0 > 0.0 else math.sqrt(2.0 * gap / acc) if acc > 0.0 else 1.0

    def arrive(t: float, y: Array) -> float:
        return float(y[0]) - phi

    def stop(t: float, y: Array) -> float:
        return float(y[1])

    arrive.terminal = True  # type: ignore[attr-defined]
    arrive.direction = 1.0  # type: ignore[attr-defined]
    stop.terminal = True  # type: ignore[attr-defined]
    stop.direction = -1.0  # type: ignore[attr-defined]
    if omega0 == 0.0 and acc <= 0.0:
        raise ConstructionError(
            STEP_ODE,
            f"at rest at φ0 = {math.degrees(phi0):.6g}° the loads give φ'' = {acc:.6g} rad/s² ≤ 0: "
            "the machine does not start towards φ",
        )
    horizon = 4.0 * guess
    budget, method = _budget(model, phi0, omega0, t0, horizon)
    for _ in range(MAX_DOUBLINGS):
        res = solve_ivp(
            _rhs(model, budget), (t0, t0 + horizon), [phi0, omega0], method=method,
            rtol=tol.ODE_RTOL, atol=tol.ODE_ATOL, dense_output=True, events=(arrive, stop),
        )  # fmt: skip
        if res.status == -1:
            raise ConstructionError(STEP_ODE, f"the integrator failed: {res.message}")
        if res.t_events[0].size:
            t_hit = float(res.t_events[0][0])
            w_hit = float(res.y_events[0][0][1])
            ts = np.linspace(t0, t_hit, 401)
            y = res.sol(ts)
            return Arrival(t_hit, w_hit, Trajectory(ts, y[0], y[1], res.sol, t_hit, method))
        if res.t_events[1].size:
            t_stop = float(res.t_events[1][0])
            phi_stop = float(res.y_events[1][0][0])
            raise ConstructionError(
                STEP_ODE,
                f"the machine stops at t = {t_stop:.6g} s, φ = {math.degrees(phi_stop):.6g}°, "
                f"before it reaches φ = {math.degrees(phi):.6g}°",
            )
        horizon *= 2.0
    raise ConstructionError(
        STEP_ODE, f"φ = {math.degrees(phi):.6g}° is not reached within {horizon:.6g} s"
    )
