"""Punch-press motor and flywheel.

- The load diagram F(s): the force falls linearly from F_max = π·d·h·τ to 0 over the plate.
- The work of one hole is its area, E = F_max·h/2 (the formula the seed's text lost, restored);
  the motor's power N = E·z; ω_max = πn/30, ω_min from δ; the flywheel
  J = 2E/(ω_max² − ω_min²) (``geomcad.dynamics.flywheel``).
- Reports the exact J beside the seed's 1,89, which it computed from rounded speeds.
- Sheet (A3): the load diagram with the work hatched, the flywheel's energy balance ΔT(t) over
  two cycles, the kinematic scheme of the press with its flywheel, the results and the solution
  step by step.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_8.py, the sheet in sheets_2013_8.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, erratum, lazy, rounded

if TYPE_CHECKING:
    from .p2013_8 import Data

ID = "2013-8"

PARAMS = (
    Param("d_hole", 0.05, "diameter of the hole", "m", gt=0.0, symbol="d", display="mm"),
    Param("h_plate", 0.03, "thickness of the plate", "m", gt=0.0, symbol="h", display="mm"),
    Param("tau", 6e7, "shear strength of the plate's steel", "Pa", gt=0.0, display="MPa"),
    Param("n_rpm", 1500, "nominal (largest) speed of the motor shaft", "rpm", gt=0.0, symbol="n"),
    Param("delta", 0.1, "coefficient of speed fluctuation δ (0 < δ < 2)", "1"),
    Param("holes_per_s", 1, "holes punched per second", "1/s", gt=0.0, symbol="z"),
)

RESULTS = (
    ResultSpec("F_max", "N", "largest punching force π·d·h·τ", "F", display="kN"),
    ResultSpec("E", "J", "work of one hole: the area under F(s)"),
    ResultSpec("N", "W", "mean power of the motor, E per cycle"),
    ResultSpec("omega_max", "rad/s", "nominal (largest) angular velocity π·n/30"),
    ResultSpec("omega_min", "rad/s", "smallest angular velocity ω_max·(2 − δ)/(2 + δ)"),
    ResultSpec("J", "kg·m²", "flywheel's moment of inertia 2E/(ω_max² − ω_min²)"),
)

J_NOTE = (
    "it is computed from the rounded speeds 157 and 142 rad/s (2·4241/(157² − 142²) = 1.891); "
    "the exact speeds ω_max = 50π and ω_min = 19/21·ω_max give J = 1.8951 kg·m², which rounds "
    "to 1.90"
)

SEED = {
    "F_max": rounded(282.7, 1, "F_max = 282,7 кН", unit=1000.0),
    "N": rounded(4241.0, 0, "N = 4241 Вт"),
    "omega_max": rounded(157.0, 0, "ω_max = 157 рад/с"),
    "omega_min": rounded(142.0, 0, "ω_min = 142 рад/с"),
    "J": erratum(1.89, J_NOTE, "J = 1,89 кг·м²"),
}

PROBLEM: Problem[Data] = Problem(
    id=ID,
    title="Punch-press motor and flywheel: the work of a hole, the power, the flywheel's J",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_8:build", __package__),
    draw=lazy(".sheets_2013_8:sheets", __package__),
    scales=lazy(".sheets_2013_8:scales", __package__),
)
