"""Mechanism with a cross, solved by its velocity plan.

- Each vector equation (V_B3 = V_B2 + V_B3B2 with V_B3B2 along the slot;
  V_C4 = V_C3 + V_C4C3 = V_C5 + V_C4C5) is drawn as two lines of known direction that meet.
- c3 is the image of C on link 3 by similarity; ω3 = ω5 because the cross slides on both links
  at a fixed right angle; F_red = M·ω5/v_A by equal power.
- Sheet (A3): the mechanism at a GOST scale (1:2.5) with the links numbered and α, l_AB, l_O1O2
  dimensioned, the plan at μ_V = 0,02 (m/s)/mm with its lines and lettered points, the results
  and the order of the plan.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_3.py, the sheet and its scales in sheets_2013_3.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, lazy, rounded

if TYPE_CHECKING:
    from .p2013_3 import Geometry

ID = "2013-3"

PARAMS = (
    Param("v_A", 1.0, "velocity of link 1 along O1O2 (+: towards O2)", "m/s"),
    Param("l_AB", 0.1, "link AB (= O1B: triangle O1AB is isosceles)", "m", gt=0.0),
    Param("l_O1O2", 0.2, "distance between the pivots O1 and O2", "m", gt=0.0),
    Param("M", 10.0, "moment on link 5 (shaft O2)", "N·m"),
    Param(
        "alpha_deg",
        60.0,
        "base angle α of triangle O1AB = slot angle to O1O2",
        "deg",
        gt=0.0,
        lt=90.0,
    ),
)

RESULTS = (
    ResultSpec("V_B3", "m/s", "velocity of point B of link 3 (pb3)", "v"),
    ResultSpec("V_B3B2", "m/s", "sliding velocity of block 2 in the slot of link 3 (b2b3)", "v"),
    ResultSpec("omega3", "rad/s", "angular velocity of the slotted link 3"),
    ResultSpec("V_C3", "m/s", "velocity of point C of link 3 (pc3)", "v"),
    ResultSpec("omega5", "rad/s", "angular velocity of link 5 (= ω3)"),
    ResultSpec("V_C5", "m/s", "velocity of point C of link 5 (pc5)", "v"),
    ResultSpec("V_C4", "m/s", "velocity of the cross's centre C (pc4)", "v"),
    ResultSpec("F_red", "N", "force on link 1 equivalent to M by equal power"),
)

SEED = {
    "V_B3": rounded(0.866, 3, "V_B3 = 0,866 м/с"),
    "V_B3B2": rounded(0.5, 1, "V_B3B2 = 0,5 м/с"),
    "omega3": rounded(8.66, 2, "ω3 = 8,66 рад/с"),
    "V_C3": rounded(0.866, 3, "V_C3 = V_B3"),
    "omega5": rounded(8.66, 2, "ω5 = ω3 = 8,66 рад/с"),
    "V_C5": rounded(1.5, 1, "V_C5 = 8,66·0,173 = 1,5 м/с"),
    "V_C4": rounded(1.73, 2, "V_C4 = 1,73 м/с"),
    "F_red": rounded(86.6, 1, "F = 86,6 Н"),
}

PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Mechanism with a cross: velocity plan",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_3:build", __package__),
    draw=lazy(".sheets_2013_3:sheets", __package__),
    scales=lazy(".sheets_2013_3:scales", __package__),
)
