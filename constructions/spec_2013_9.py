"""Valve mechanism: a disc with a pin in a rod's slot, a spring, a damper, M(t) = M0 + M1·sin Ωt.

- The model reduced to the disc from the slotted yoke's velocity analogues:
  J_pr = J + m·r²·cos²φ, dJ_pr/dφ, M_pr by equal power.
- The equation of motion J_pr·φ'' + ½·J_pr'·φ'² = M_pr at the state; the forces on the disc and
  the rod with their d'Alembert inertia loads by kinetostatics (which must need no balancing
  moment: the Lagrange equation checked by a force balance); the motion from rest by ``solve_ivp``.
- Names the four slips of the seed's derivation (its final line is wrong in two terms).
- Two A3 sheets: the mechanism and its parts with every force and moment at μ_F; φ(t), φ'(t),
  the derivation.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build and draw live in p2013_9.py and load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, lazy

if TYPE_CHECKING:
    from .p2013_9 import Data

ID = "2013-9"

PARAMS = (
    Param("J", 0.05, "disc's moment of inertia about O", "kg·m²"),
    Param("m", 2.0, "mass of the rod with its slotted guide", "kg"),
    Param("r", 0.05, "radius of the pin A on the disc", "m", gt=0.0),
    Param("c", 4000.0, "spring stiffness (the spring is free at φ = 0)", "N/m"),
    Param("k", 20.0, "damping constant (damper force k·x')", "N·s/m"),
    Param("M0", 2.0, "constant part of the driving moment M(t) = M0 + M1·sin(Ωt)", "N·m"),
    Param("M1", 0.0, "amplitude of the driving moment's harmonic part", "N·m"),
    Param("Omega", 0.0, "circular frequency Ω of the driving moment", "rad/s"),
    Param("t", 0.0, "time of the state", "s"),
    Param("phi_deg", 30.0, "disc angle φ at the state", "deg", turn=True),
    Param("phi_dot", 10.0, "angular velocity φ' at the state", "rad/s", symbol="φ'"),
    Param("T", 0.5, "duration of the motion from rest at φ = 0", "s", gt=0.0),
)

RESULTS = (
    ResultSpec("J_pr", "kg·m²", "reduced moment of inertia J + m·r²·cos²φ at the state"),
    ResultSpec("dJ_pr", "kg·m²", "dJ_pr/dφ = −m·r²·sin 2φ at the state (signed)"),
    ResultSpec("M_pr", "N·m", "reduced moment of the loads at the state (signed)"),
    ResultSpec(
        "phi_ddot", "rad/s²", "φ'' from the equation of motion at the state (signed)", symbol="φ''"
    ),
    ResultSpec("N_pin", "N", "force of the pin on the rod", "F"),
    ResultSpec("F_spring", "N", "spring force c·|x|", "F"),
    # forces shorter than two arrowheads at μ_F are drawn as points, so they are not read off
    ResultSpec("F_damper", "N", "damper force k·|x'|"),
    ResultSpec("F_inertia_rod", "N", "rod's inertia force m·|x''|"),
    ResultSpec("M_inertia_disc", "N·m", "disc's inertia moment J·|φ''|"),
    ResultSpec("phi_T", "rad", "φ at t = T after starting from rest at φ = 0"),
    ResultSpec("omega_T", "rad/s", "φ' at t = T after starting from rest at φ = 0"),
)

PROBLEM: Problem[Data] = Problem(
    id=ID,
    title="Valve mechanism: reduced inertia and moment, equation of motion, loads on the parts",
    params=PARAMS,
    results=RESULTS,
    seed={},
    build=lazy(".p2013_9:build", __package__),
    draw=lazy(".sheets_2013_9:sheets", __package__),
    scales=lazy(".sheets_2013_9:scales", __package__),
)
