"""Six-bar synthesis by the coefficient of velocity change K ("circle through B0B1").

- Extreme positions, θ = 180°(K − 1)/(K + 1); the perpendicular at B0 and the ray at 90° − θ meet
  in O; the circle OB0B1 and its mirror image are the loci of O1; the lines at e from the path
  cut them.
- Reports all four solutions (with a Grashof crank-rocker flag) and the seed's one in full, and
  checks it by analysis: the synthesized six-bar is run through a full crank turn and its actual
  stroke and K are measured.
- Sheet (A3, 1:5): the mechanism in its mid and extreme positions, the whole construction, the
  dimensions O1B0 and O1B1, and tables of the data, the results, every solution and the order
  of construction.
- Sheet ``2013-6-kinematics`` (A3, 1:5): the synthesized six-bar at the crank 60° past the
  slider's left extreme (ω1 = 10 rad/s), its velocity and acceleration plans with their vector
  equations, and the slider's s, v, a over a turn from the vectorized sweep, with the plans'
  values marked on the curves.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_6.py, the sheets in sheets_2013_6*.py; they load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, lazy, measured, measured_value, rounded

if TYPE_CHECKING:
    from .p2013_6 import Geometry

ID = "2013-6"
SEED_K_L = 0.005  # m/mm: the seed's k_l = 0.2 / 40

PARAMS = (
    Param("H", 0.2, "slider stroke", "m", gt=0.0),
    Param("K", 1.3, "coefficient of velocity change of the slider (1 < K < 3)", "1", gt=1.0),
    Param("l3", 0.3, "rocker O2B", "m", gt=0.0),
    Param("l4", 0.3, "link BC", "m", gt=0.0),
    Param("e", 0.3, "distance of the crank centre O1 from the slider path", "m", gt=0.0),
)

RESULTS = (
    ResultSpec("theta_deg", "deg", "angle θ = 180°·(K − 1)/(K + 1) between the rod's dead centres"),
    ResultSpec(
        "O1B0",
        "m",
        "distance O1B0 (folded dead centre for the seed's solution)",
        "l",
        symbol="O_1B_0",
    ),
    ResultSpec(
        "O1B1",
        "m",
        "distance O1B1 (extended dead centre for the seed's solution)",
        "l",
        symbol="O_1B_1",
    ),
    ResultSpec("l1", "m", "crank O1A", "l"),
    ResultSpec("l2", "m", "connecting rod AB", "l"),
    ResultSpec("H_check", "m", "slider stroke of the synthesized six-bar over a crank turn", "l"),
    ResultSpec("K_check", "1", "coefficient of velocity change measured over a crank turn"),
    ResultSpec("solutions", "", "every candidate O1, by line (y = l3 − e first), then by x"),
)

SEED = {
    "theta_deg": rounded(23.5, 1, "Θ = 23,5°"),
    "O1B1": measured(89.5, SEED_K_L, "O1B1 = 89,5 мм"),
    "O1B0": measured(63.5, SEED_K_L, "O1B0 = 63,5 мм"),
    "l1": measured_value(0.065, SEED_K_L, "l1 = 0,065 м"),
    "l2": measured_value(0.383, SEED_K_L, "l2 = 0,383 м"),
}

PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Six-bar synthesis by the coefficient of velocity change K (circle through B0B1)",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_6:build", __package__),
    draw=lazy(".sheets_2013_6:sheets", __package__),
    motion=lazy(".sheets_2013_6_kin:motion", __package__),
    scales=lazy(".sheets_2013_6:scales", __package__),
    seed_k_l=SEED_K_L,
)
