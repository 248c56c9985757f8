"""The machine's dynamics reduced to the crank, and the flywheel, as linkages.md settles them.

Over the numbered positions and over a dense sweep of a turn at constant ω1:

- the reduced moment of inertia I_pr = Σ(m·V_S² + J·ω²)/ω1² over every moving link (the crank
  too), and its derivative dI_pr/dφ = 2Σ(m·V_S·a_S + J·ω·ε)/ω1³ (the sweep's accelerations are
  the time derivatives along the motion at constant ω1);
- the reduced moment of the loads M_pr = ΣP/ω1 over the file's loads and the weights (no inertia
  loads), so that M_pr·ω1 is their power;
- A_cycle = −∮ΣP dt over a turn, M_drive = A_cycle/2π; with ψ the crank's turn from position 0
  (in its sense of rotation), ΔA(ψ) = M_drive·ψ + sign(ω1)·∫₀^ψ M_pr dψ′ (the cumulative integral
  of the dense sweep, trapezoids: M_pr is continuous, a load switching on where its point rests);
- ω_max,min = |ω1|·(1 ± δ/2); the smallest flywheel that keeps ω within them over the whole
  cycle, J_fw = (max_ψ[½ω_min²·I_pr − ΔA] − min_ψ[½ω_max²·I_pr − ΔA]) / (½(ω_max² − ω_min²)),
  0 when that is negative. Each extreme is refined off the dense sweep by a bounded scalar search
  (ΔA between samples by Gauss–Legendre).

**Wittenbauer's energy–mass diagram** ΔT(I_pr) (ΔT = ΔA, the machine's kinetic energy over its
value at position 0) constructs the same number: the tangent of slope ½ω_max² that leaves every
point of the curve below it, and the tangent of slope ½ω_min² that leaves them above, cut the
ΔT axis (I_pr = 0) in a segment ab; J_fw = ab/(½(ω_max² − ω_min²)), and the tangents meet at O′
= (−J_fw, −T0), the origin of the energy of the machine with its flywheel.

The check: the equation of motion (J_fw + I_pr)·ψ″ + ½·I_pr′·ψ′² = M_drive + sign(ω1)·M_pr,
integrated by ``solve_ivp`` over :data:`CYCLES` turns from ψ = 0 at the energy T0 of O′; δ
achieved over the last turn stands beside the asked δ.

The flywheel's dimensions (``[dynamics]`` ``flywheel``, ``density`` kg/m³, ``ratio``):
``"disc"``, a solid disc of diameter D and width b = ratio·D, J = π·ρ·b·D⁴/32; ``"rim"``, a rim
of mean diameter D with a square section b = h = ratio·D (spokes and hub left out),
J = m·D²/4, m = ρ·π·D·b·h.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.integrate import cumulative_trapezoid, solve_ivp
from scipy.interpolate import CubicSpline
from scipy.optimize import minimize_scalar

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import ConstructionError
from geomcad.geom import Line, Vec
from geomcad.linkage.cycle import Cycle, numbered
from geomcad.linkage.loads import (
    Range,
    centre_arrays,
    force_value,
    guide_coordinate,
    moment_value,
    ranges,
    slider_group,
    stroke_sign,
)
from geomcad.linkage.model import Linkage
from geomcad.linkage.sweep import State, output_velocity, sweep

Arr = npt.NDArray[np.float64]

#: Samples of a turn in the dense sweep (ψ from 0 to 2π, both ends).
DENSE = 8192
#: Gauss–Legendre nodes for ΔA between the sweep's samples.
GAUSS = 8
#: Turns integrated by the check.
CYCLES = 3
#: The check's relative tolerance.
ODE_RTOL = tol.FLYWHEEL_ODE_RTOL
#: Samples of the last turn read for ω's extremes.
OMEGA_SAMPLES = 20001


@dataclass(frozen=True)
class Reduced:
    """I_pr, dI_pr/dφ and M_pr at crank angles ``phi`` (arrays)."""

    phi: Arr
    I_pr: Arr
    dI_pr: Arr
    M_pr: Arr


def reduce(lk: Linkage, st: State, rng: dict[str, Range], cyc: Cycle | None = None) -> Reduced:
    """The reduced inertia and moment of the loads over a sweep (module docstring)."""
    w1 = lk.omega
    n = st.phi.shape[0]
    energy = np.zeros(n)
    denergy = np.zeros(n)
    power = np.zeros(n)
    for i in lk.moving_links:
        m = lk.masses.get(i)
        if m is None:
            continue
        V = centre_arrays(lk, i, st.vel)
        a = centre_arrays(lk, i, st.acc)
        w, e = st.omega[i], st.eps[i]
        energy += m.mass * np.einsum("ij,ij->i", V, V) + m.J * w * w
        denergy += 2.0 * (m.mass * np.einsum("ij,ij->i", V, a) + m.J * w * e)
        power += -m.mass * lk.gravity * V[:, 1]
    moving = stroke_sign(lk, cyc, st.phi, output_velocity(lk, st)) if cyc is not None else None
    for ld in lk.loads:
        if ld.point:
            g = slider_group(lk, ld.point)
            s, d = guide_coordinate(lk, g, st)
            f = force_value(lk, ld, rng[ld.point], s, st.v_rel[ld.point], moving)
            power += f * np.einsum("ij,ij->i", d, st.vel[ld.point])
        else:
            power += moment_value(ld, st.omega[ld.link], moving) * st.omega[ld.link]
    return Reduced(st.phi, energy / w1**2, denergy / w1**3, power / w1)


@dataclass
class Flywheel:
    """The dynamics of a linkage file: the numbered positions' I_pr and M_pr, the dense sweep
    (ψ, I_pr, M_pr, ΔA), the cycle's works, the flywheel, the Wittenbauer construction, the
    check by the equation of motion and the flywheel's dimensions."""

    phis: list[float]
    I_pr: list[float]
    M_pr: list[float]
    psi: Arr
    dense: Reduced
    dA: Arr
    A_cycle: float
    M_drive: float
    omega_max: float
    omega_min: float
    J_flywheel: float
    T0: float
    tangents: tuple[Line, Line]
    touch: tuple[Vec, Vec]
    segment: tuple[float, float]
    c: Construction
    delta_achieved: float = math.nan
    omega_psi: Arr | None = None
    omega_t: Arr | None = None
    D: float = 0.0
    b: float = 0.0
    mass: float = 0.0


def dynamics(lk: Linkage, cyc: Cycle | None, positions: int) -> Flywheel:
    """The dynamics of the linkage (module docstring); ``positions``: how many numbered."""
    assert lk.dynamics is not None
    delta = lk.dynamics.delta
    rng = ranges(lk, cyc)
    sign = 1.0 if lk.omega > 0 else -1.0
    phis = numbered(lk, cyc, positions)
    red_n = reduce(lk, sweep(lk, phis, order=2), rng, cyc)
    phi0 = phis[0]
    psi = np.linspace(0.0, 2.0 * math.pi, DENSE + 1)

    def at(psi_: npt.ArrayLike) -> Reduced:
        ph = phi0 + sign * np.atleast_1d(np.asarray(psi_, dtype=np.float64))
        return reduce(lk, sweep(lk, ph, order=2), rng, cyc)

    dense = at(psi)
    W = cumulative_trapezoid(dense.M_pr, psi, initial=0.0) * sign  # the loads' work from ψ = 0
    A_cycle = -float(W[-1])
    M_drive = A_cycle / (2.0 * math.pi)
    dA = M_drive * psi + W
    w = abs(lk.omega)
    w_max, w_min = w * (1.0 + delta / 2.0), w * (1.0 - delta / 2.0)
    k_max, k_min = 0.5 * w_max**2, 0.5 * w_min**2

    gx, gw = np.polynomial.legendre.leggauss(GAUSS)

    def dA_at(x: float) -> float:
        """ΔA at any ψ: the nearest sample's plus Gauss–Legendre over the rest (less than half
        a step of the sweep)."""
        k = int(np.clip(round(x / (psi[1] - psi[0])), 0, DENSE))
        lo = float(psi[k])
        half = 0.5 * (x - lo)
        extra = half * float(np.dot(gw, at(lo + half * (gx + 1.0)).M_pr))
        return float(dA[k] + M_drive * (x - lo) + sign * extra)

    def extreme(kk: float, largest: bool) -> tuple[float, float, float]:
        """ψ, I_pr and ΔA where k·I_pr − ΔA is largest (or smallest), refined."""
        f = kk * dense.I_pr - dA
        i = int(np.argmax(f) if largest else np.argmin(f))
        lo, hi = psi[max(i - 1, 0)], psi[min(i + 1, DENSE)]
        sgn = -1.0 if largest else 1.0

        def g(x: float) -> float:
            return sgn * (kk * float(at(x).I_pr[0]) - dA_at(x))

        best = (float(psi[i]), float(sgn * f[i]))
        if hi > lo:
            r = minimize_scalar(g, bounds=(float(lo), float(hi)), method="bounded",
                                options={"xatol": tol.MIN_ANGLE})  # fmt: skip
            if r.success and float(r.fun) < best[1]:
                best = (float(r.x), float(r.fun))
        x = best[0]
        return x, float(at(x).I_pr[0]), dA_at(x)

    c = Construction(f"{lk.title}: Wittenbauer's energy–mass diagram")
    c.value("A_cycle", A_cycle, "−∮ΣP dt over a turn: the work of the resistances per cycle")
    c.value("M_drive", M_drive, "A_cycle/2π: the constant motor moment")
    c.value("omega_max", w_max, f"|ω1|·(1 + δ/2), δ = {delta:g}")
    c.value("omega_min", w_min, f"|ω1|·(1 − δ/2), δ = {delta:g}")
    # the upper tangent (slope ½ω_max²) touches where ½ω_max²·I − ΔA is smallest
    _, I_hi, A_hi = extreme(k_max, largest=False)
    _, I_lo, A_lo = extreme(k_min, largest=True)
    t_hi = c.record(
        "tangent ω_max",
        "the tangent of slope ½ω_max² above the curve ΔT(I_pr)",
        Line.of(Vec(I_hi, A_hi), Vec(1.0, k_max)),
    )
    t_lo = c.record(
        "tangent ω_min",
        "the tangent of slope ½ω_min² below the curve ΔT(I_pr)",
        Line.of(Vec(I_lo, A_lo), Vec(1.0, k_min)),
    )
    axis = c.line("ΔT axis", Vec(0.0, 0.0), Vec(0.0, 1.0), "the ΔT axis, I_pr = 0", role="aux")
    a_pt = c.intersect("a", t_hi, axis, op="tangent ω_max ∩ the ΔT axis")
    b_pt = c.intersect("b", t_lo, axis, op="tangent ω_min ∩ the ΔT axis")
    ab = c.value("ab", a_pt.y - b_pt.y, "the segment the tangents cut on the ΔT axis (J)")
    J = c.value("J_flywheel", max(ab / (k_max - k_min), 0.0), "ab / (½(ω_max² − ω_min²)), ≥ 0")
    if ab > 0.0:
        origin = c.intersect("O'", t_hi, t_lo, op="the tangents meet at (−J_fw, −T0)")
        T0 = -origin.y
    else:
        T0 = J * k_min + (k_min * I_lo - A_lo)
    c.value("T0", T0, "the energy of the machine with its flywheel at position 0")
    fw = Flywheel(
        phis,
        [float(x) for x in red_n.I_pr],
        [float(x) for x in red_n.M_pr],
        psi,
        dense,
        dA,
        A_cycle,
        M_drive,
        w_max,
        w_min,
        J,
        T0,
        (t_hi, t_lo),
        (Vec(I_hi, A_hi), Vec(I_lo, A_lo)),
        (float(a_pt.y), float(b_pt.y)),
        c,
    )
    check(lk, fw)
    _dimensions(lk, fw)
    return fw


def check(lk: Linkage, fw: Flywheel) -> None:
    """Integrate the equation of motion with the flywheel (module docstring) and set
    ``delta_achieved``, ``omega_psi`` and ``omega_t`` (ω over the last turn)."""
    sign = 1.0 if lk.omega > 0 else -1.0
    psi = fw.psi
    # I, dI/dφ and Q as the columns of one periodic spline: one call per step of the ODE
    columns = (fw.dense.I_pr, fw.dense.dI_pr * sign, fw.M_drive + sign * fw.dense.M_pr)
    IdIQ = CubicSpline(psi, np.column_stack([_periodic(c) for c in columns]), bc_type="periodic")
    J = fw.J_flywheel
    two_pi = 2.0 * math.pi

    def rhs(_t: float, y: npt.NDArray[np.float64]) -> list[float]:
        x = float(y[0]) % two_pi
        w = float(y[1])
        i, di, q = IdIQ(x).tolist()
        return [w, (q - 0.5 * di * w * w) / (J + i)]

    w0 = math.sqrt(2.0 * fw.T0 / (J + float(fw.dense.I_pr[0])))

    def turn(k: int, last: bool) -> object:
        def ev(_t: float, y: npt.NDArray[np.float64]) -> float:
            return float(y[0]) - k * two_pi

        ev.terminal = last  # type: ignore[attr-defined]
        ev.direction = 1.0  # type: ignore[attr-defined]
        return ev

    t_turn = two_pi / fw.omega_min
    sol = solve_ivp(
        rhs,
        (0.0, (CYCLES + 1) * t_turn * 2.0),
        [0.0, w0],
        method="DOP853",
        rtol=ODE_RTOL,
        atol=ODE_RTOL * fw.omega_max,
        dense_output=True,
        events=[turn(CYCLES - 1, False), turn(CYCLES, True)],
    )
    ends = sol.t_events
    if not sol.success or len(ends[1]) == 0 or len(ends[0]) == 0:
        raise ConstructionError("the flywheel's check (solve_ivp)", "the machine did not turn")
    t0, t1 = float(ends[0][0]), float(ends[1][0])
    t = np.linspace(t0, t1, OMEGA_SAMPLES)
    y = sol.sol(t)
    w = y[1]
    hi, lo = float(np.max(w)), float(np.min(w))
    fw.delta_achieved = (hi - lo) / (0.5 * (hi + lo))
    fw.omega_psi = np.asarray(y[0] - (CYCLES - 1) * two_pi, dtype=np.float64)
    fw.omega_t = np.asarray(w, dtype=np.float64)


def _periodic(y: Arr) -> Arr:
    out = np.array(y, dtype=np.float64)
    out[-1] = out[0]
    return out


def _dimensions(lk: Linkage, fw: Flywheel) -> None:
    assert lk.dynamics is not None
    d = lk.dynamics
    J = fw.J_flywheel
    if J <= 0.0:
        return
    if d.flywheel == "disc":
        D = (32.0 * J / (math.pi * d.density * d.ratio)) ** 0.2
        b = d.ratio * D
        mass = d.density * math.pi * D * D / 4.0 * b
    else:
        D = (4.0 * J / (math.pi * d.density * d.ratio**2)) ** 0.2
        b = d.ratio * D
        mass = d.density * math.pi * D * b * b
    fw.D, fw.b, fw.mass = D, b, mass
