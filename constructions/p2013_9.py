"""2013-9 · Valve mechanism: reduced inertia, reduced moment, equation of motion.

A disc 1 (moment of inertia J) carries a pin A at radius r that works in the straight slot of a
rod 2 (mass m, with its guide). The rod slides along its own axis; a spring c, free at φ = 0, and
a damper k act on it; a moment M(t) = M0 + M1·sin(Ωt) drives the disc. Horizontal plane: no
weights.

Frame and conventions (settled here; they change no result): O at the origin, A = r(cos φ, sin φ)
with φ counter-clockwise; the rod's axis is the y axis through O and its slot is perpendicular to
it, so the rod's coordinate along its axis is x = r·sin φ (the seed's x). Forces on the rod are
positive along +x (up the axis on the sheet).

The model (:mod:`geomcad.dynamics`): the disc turns with φ; the rod's velocity analogue comes from
the velocity plan of the slotted yoke, V_A2 = V_A1 + V_A2A1. Then

    J_pr = J + m·r²·cos²φ,   dJ_pr/dφ = −m·r²·sin 2φ,
    M_pr = M(t) − ½·c·r²·sin 2φ − k·r²·cos²φ·φ'      (equal power),
    J_pr·φ'' + ½·(dJ_pr/dφ)·φ'² = M_pr.

The seed's derivation has four slips (see ``NOTES``); its final line is wrong in two terms.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad.construction import Construction
from geomcad.dynamics import (
    Body,
    Force,
    Kinetostatics,
    Part,
    Reactions,
    ReducedModel,
    Torque,
    Trajectory,
    Yoke,
    integrate,
    ode_settings,
    slotted_yoke,
    turning,
)
from geomcad.dynamics.analogues import Array, remember_last
from geomcad.errors import ParameterError
from geomcad.geom import Vec
from geomcad.problem import Build, ParamValue
from geomcad.units import deg

NOTES = [
    "seed slip: the spring's power is written N = −c·x'·x'; it is −c·x·x' (the seed's next "
    "expression, −c·r·sin φ·r·cos φ·φ', is right)",
    "seed slip: in dE/dt the term −m·r²·cos φ·sin φ·φ'² must carry φ'³ (d/dt of "
    "½·m·r²·cos²φ·φ'² gives −m·r²·sin φ·cos φ·φ'³ + m·r²·cos²φ·φ'·φ'')",
    "seed error in the final equation: the term −m·r²·½·sin 2φ·φ'²/2 has a spurious /2; it is "
    "−½·m·r²·sin 2φ·φ'² = ½·(dJ_pr/dφ)·φ'²",
    "seed error in the final equation: m·r²·cos²φ·φ' must be m·r²·cos²φ·φ'' (it is part of "
    "J_pr·φ''); the correct line is (J + m·r²·cos²φ)·φ'' − ½·m·r²·sin 2φ·φ'² = "
    "M(t) − ½·c·r²·sin 2φ − k·r²·cos²φ·φ'",
]


@dataclass(frozen=True)
class RodShape:
    """The rod's drawn shape, in units of r, relative to its slot's centre line (y = x): only
    the points where the spring and the damper act and where its guide holds it enter the
    kinetostatics, and they change no reported result (only the guide's couple)."""

    slot_half: float = 1.15  # the slot runs from −1.15r to 1.15r across the axis
    frame: float = 0.2  # the crosshead reaches 0.2r above and below the slot's centre line
    top: float = 3.2  # the stem's top, with the crossbar
    bar_half: float = 0.6  # the spring (left) and the damper (right) hang at ±0.6r
    guide: tuple[float, float] = (1.45, 2.05)  # the fixed guide's bushing (absolute, units of r)
    ground: float = 4.7  # the fixed support above the spring and the damper (absolute)
    centre: float = 1.6  # the rod's centre of mass above the slot's centre line


ROD = RodShape()


@dataclass(frozen=True)
class Data:
    """What the sheets draw."""

    r: float
    phi: float
    dphi: float
    ddphi: float
    x: float
    xd: float
    xdd: float
    yoke: Yoke
    reactions: Reactions
    motion: Trajectory
    M_t: float


def _nonneg(p: Mapping[str, ParamValue], name: str, what: str) -> float:
    v = float(p[name])
    if v < 0.0:
        raise ParameterError(name, v, f"{what} cannot be negative")
    return v


def model_of(
    J: float, m: float, r: float, c: float, k: float, M: Any, steady: bool = False
) -> tuple[ReducedModel, Any]:
    """The reduced model of the valve mechanism and the rod's motion function.

    ``M(t)`` is the driving moment (``steady``: it does not change with t); the rod's analogues
    come from the slotted yoke's velocity plan (guide along +y, slot along x). Without damping
    and with a steady moment every load depends on φ only, and the energy method applies.
    """

    @remember_last
    def rod(phi: Array) -> Any:
        return slotted_yoke(phi, r, math.pi / 2.0, 0.0).body

    disc = Part(Body("1", 0.0, J), turning)
    rod_part = Part(Body("2", m, 0.0), rod)

    def drive(phi: Array, dphi: Array, t: Array) -> Array:
        return np.asarray(M(t), dtype=np.float64) + 0.0 * phi

    def spring(phi: Array, dphi: Array, t: Array) -> tuple[Array, Array]:
        x = rod(phi).y  # the rod's coordinate along its axis, 0 at φ = 0
        return 0.0 * x, -c * x

    def damper(phi: Array, dphi: Array, t: Array) -> tuple[Array, Array]:
        xd = rod(phi).vy * dphi
        return 0.0 * xd, -k * xd

    loads = (
        Torque("M(t)", turning, drive, positional=steady),
        Force("F_spring", rod, spring),
        Force("F_damper", rod, damper, positional=k == 0.0),
    )
    return ReducedModel((disc, rod_part), loads), rod


def build(p: Mapping[str, ParamValue]) -> Build[Data]:
    """The reduced model at the state, the kinetostatics of disc and rod, and the motion from
    rest."""
    J = _nonneg(p, "J", "the disc's moment of inertia")
    m = _nonneg(p, "m", "the rod's mass")
    c_ = _nonneg(p, "c", "the spring stiffness")
    k = _nonneg(p, "k", "the damping constant")
    r = float(p["r"])
    M0, M1, Om = float(p["M0"]), float(p["M1"]), float(p["Omega"])
    t, phi, dphi, T = float(p["t"]), deg(float(p["phi_deg"])), float(p["phi_dot"]), float(p["T"])

    def M(tt: Any) -> Any:
        return M0 + M1 * np.sin(Om * np.asarray(tt, dtype=np.float64))

    c = Construction("2013-9: valve mechanism, reduced model and equation of motion")
    model, _ = model_of(J, m, r, c_, k, M, steady=M1 == 0.0 or Om == 0.0)
    c.run("J_pr,min", "the smallest J_pr(φ) over a turn (must be > 0)", model.check_inertia)
    j_pr = c.value("J_pr", float(model.J_pr(phi)), "Σ(m·v_q² + J·ω_q²) at φ")
    dj_pr = c.value("dJ_pr", float(model.dJ_pr(phi)), "Σ 2(m·v_q·a_q + J·ω_q·ε_q) at φ")
    m_pr = c.value("M_pr", float(model.M_pr(phi, dphi, t)), "M(t)·1 + F_spring·v_q + F_damper·v_q")
    ddphi = c.value("φ''", float(model.phi_ddot(phi, dphi, t)), "(M_pr − ½·J_pr'·φ'²)/J_pr")
    # the rod's motion at the state, from its analogues
    y = slotted_yoke(phi, r, math.pi / 2.0, 0.0)
    x = float(y.body.y)
    xd = float(y.body.vy) * dphi
    xdd = float(y.body.ay) * dphi**2 + float(y.body.vy) * ddphi
    # kinetostatics: d'Alembert loads, the reactions, and a balancing moment that must vanish
    ks = kinetostatics(J, m, r, c_, k, float(M(t)), phi, x, xd, xdd, ddphi)
    R = c.run("reactions", "equilibrium of disc and rod with their inertia loads", ks.solve)
    n_pin = abs(R.magnitudes["R_{12}"])
    c.value(
        "M_b", R.magnitudes["M_b"], "balancing moment on the disc (0: Lagrange = kinetostatics)"
    )
    # the motion from rest at φ = 0
    traj = c.run("φ(t)", f"equation of motion from rest at φ = 0 to t = T, {ode_settings()}",
                 lambda: integrate(model, 0.0, 0.0, T))  # fmt: skip
    phi_T, omega_T = traj.at(T)
    results: dict[str, Any] = {
        "J_pr": j_pr,
        "dJ_pr": dj_pr,
        "M_pr": m_pr,
        "phi_ddot": ddphi,
        "N_pin": n_pin,
        "F_spring": abs(c_ * x),
        "F_damper": abs(k * xd),
        "F_inertia_rod": abs(m * xdd),
        "M_inertia_disc": abs(J * ddphi),
        "phi_T": phi_T,
        "omega_T": omega_T,
    }
    notes = [*NOTES, f"the motion from rest is integrated by {ode_settings(traj.method)}"]
    data = Data(r, phi, dphi, ddphi, x, xd, xdd, y, R, traj, float(M(t)))
    return Build(results, c, notes, data=data)


def kinetostatics(
    J: float,
    m: float,
    r: float,
    c: float,
    k: float,
    M: float,
    phi: float,
    x: float,
    xd: float,
    xdd: float,
    ddphi: float,
) -> Kinetostatics:
    """Disc 1 and rod 2 at the state, each with its d'Alembert loads; link 0 is the frame.

    Disc: M, M_Ф1 = −J·φ'', the bearing R_01 at O, the rod's push R_21 at A and a balancing
    moment M_b (zero when φ'' satisfies the equation of motion). Rod: Ф_2 = −m·x'', the spring
    −c·x and the damper −k·x' along its axis, the pin's push R_12 at A normal to the slot, and
    its guide's reaction R_02 (across the axis) and couple M_02. The loads' names are keys
    (``Phi_2``, ``M_Phi1``, ``F_spring``, ``F_damper``); the sheets write them in their language.
    """
    ks = Kinetostatics("kinetostatics of disc and rod")
    A = Vec(r * math.cos(phi), r * math.sin(phi))
    S2 = Vec(0.0, x + ROD.centre * r)
    top = x + ROD.top * r
    ks.body("1", J=J, eps=ddphi, inertia_names=("Phi_1", "M_Phi1"))
    ks.body("2", m=m, centre=S2, a=(0.0, xdd), inertia_names=("Phi_2", "M_Phi2"))
    ks.torque("1", "M(t)", M)
    ks.force("2", "F_spring", Vec(0.0, -c * x), Vec(-ROD.bar_half * r, top))
    ks.force("2", "F_damper", Vec(0.0, -k * xd), Vec(ROD.bar_half * r, top))
    ks.joint("R_{01}", None, "1", (0.0, 0.0))
    ks.contact("R_{12}", "1", "2", A, (0.0, 1.0))
    ks.contact("R_{02}", None, "2", Vec(0.0, 0.5 * sum(ROD.guide) * r), (1.0, 0.0))
    ks.couple("M_{02}", None, "2")
    ks.balancing_torque("M_b", "1")
    return ks
