"""Planetary gear ratio u_1H2 of the compound train 1 – 2-5 – 6 – H1-4 – H2-7, gear 3 fixed.

- Coaxiality gives z4 and z7 (given explicitly, they are checked); Chebyshev's W; Willis' chain
  u_1H2 = 1 − u_12·u_5H1^(7)·u_43 in exact fractions (``u1H2_fraction``: 731/11 for the seed).
- Checks it twice: by solving the mesh equations in absolute angular velocities exactly, and
  graphically by Smirnov's plan of linear velocities and its angle diagram, whose slopes give
  every ω and the ratio.
- Reports the seed's misprinted coaxiality condition and its rounded intermediate ratio (66,46
  for 66,45).
- Sheet (A3): the kinematic scheme (GOST 2.770) to scale, the plan of linear velocities on the
  same radii, the angle diagram, and tables of the results and of the angular velocities found
  three ways.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_5.py, the sheet in sheets_2013_5.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, erratum, lazy, rounded

if TYPE_CHECKING:
    from .p2013_5 import Geometry

ID = "2013-5"

PARAMS = (
    Param("z1", 20, "teeth of the input sun 1", "1", integer=True, ge=1),
    Param("z2", 100, "teeth of the ring 2 (internal; block 2-5)", "1", integer=True, ge=1),
    Param("z3", 60, "teeth of the fixed central gear 3", "1", integer=True, ge=1),
    Param("z5", 22, "teeth of the pinion 5 (block 2-5)", "1", integer=True, ge=1),
    Param("z6", 26, "teeth of the planet 6 (on carrier H1)", "1", integer=True, ge=1),
    Param(
        "z4",
        None,
        "teeth of gear 4 (block H1-4); default from coaxiality z4 = z2 − z1 − z3",
        "1",
        integer=True,
        ge=1,
        optional=True,
    ),
    Param(
        "z7",
        None,
        "teeth of the ring 7 (block H2-7); default from coaxiality z7 = z5 + 2·z6",
        "1",
        integer=True,
        ge=1,
        optional=True,
    ),
    Param("m", 0.002, "module (sizes the drawing only)", "m", gt=0.0, display="mm"),
)

RESULTS = (
    ResultSpec("W", "1", "degree of freedom, Chebyshev: W = 3n − 2p_l − p_h"),
    ResultSpec("z4", "1", "teeth of gear 4 (coaxiality of 1–2 and 4–3)"),
    ResultSpec("z7", "1", "teeth of the ring 7 (coaxiality of 5–6 and 6–7)"),
    ResultSpec("u12", "1", "u_12 = z2/z1 (internal pair, carrier H2 held)"),
    ResultSpec("u5H1_7", "1", "u_5H1^(7) = 1 + z7/z5 (ring 7 held)", symbol="u_{5H1}^{(7)}"),
    ResultSpec("u43", "1", "u_43 = −z3/z4 (external pair, carrier H2 held)"),
    ResultSpec("u13_H2", "1", "u_13^(H2) = u_12·u_5H1^(7)·u_43", symbol="u_{13}^{(H2)}"),
    ResultSpec("u1H2", "1", "u_1H2 = ω_1/ω_H2 = 1 − u_13^(H2)"),
    ResultSpec("u1H2_fraction", "1", "u_1H2 exactly, as [numerator, denominator]"),
)

SEED = {
    "W": rounded(1, 0, "W = 1"),
    "z4": rounded(20, 0, "z4 = 20"),
    "z7": rounded(74, 0, "z7 = 74"),
    "u12": rounded(5, 0, "u12 = 5"),
    "u5H1_7": rounded(4.364, 3, "u5H1(7) = 4,364"),
    "u43": rounded(-3, 0, "u43 = −3"),
    "u1H2": erratum(
        66.46,
        "it multiplies the rounded u_5H1^(7) = 4,364: 1 + 5·4,364·3 = 66,46; exactly "
        "u_5H1^(7) = 48/11 and u_1H2 = 1 + 5·(48/11)·3 = 731/11 = 66,4545…, i.e. 66,45",
        "u1H2(3) = 66,46",
    ),
}

#: The seed's coaxiality condition as printed, and as the geometry has it.
SEED_Z4_FORMULA = "z1 − z2 = z4 + z3"
CORRECT_Z4_FORMULA = "z2 − z1 = z3 + z4"

#: The seed's misprinted condition: a note with every solve of the seed's data.
SEED_NOTES = (
    "seed misprint in the coaxiality condition for z4: it prints «z1 − z2 = z4 + z3; "
    "100 − 20 = z4 + 60»; the centre distance of the internal pair 1–2 is m(z2 − z1)/2 and of "
    "the external pair 4–3 m(z3 + z4)/2, so the condition is «z2 − z1 = z3 + z4» (its numbers "
    "already use it, so z4 = 20 is right)",
)


PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Planetary gear ratio u_1H2 (Willis; plan of linear velocities)",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    seed_notes=SEED_NOTES,
    build=lazy(".p2013_5:build", __package__),
    draw=lazy(".sheets_2013_5:sheets", __package__),
    scales=lazy(".sheets_2013_5:scales", __package__),
)
