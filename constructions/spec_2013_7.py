"""Centrifugal governor with friction in its six joints (force polygons with friction circles).

- The relative rotations come from the linkage's velocities; ρ = (d/2)·sin(arctan f) gives the
  friction circles at B, F and H.
- Link 3's line of action is the common tangent of its friction circles whose moments oppose both
  relative rotations (the internal one, α = arcsin(2ρ/BF)); then the sleeve's force triangle
  (R32), P = G6 + R36 through Q, the point K where P's line meets the inertia force's, R76 as the
  tangent from K to H's friction circle that opposes the arm's rotation, and the arm's force
  polygon (F_i, hence ω).
- Solves the same governor without friction (ω rises from 19.32 to 20.36 rad/s with f = 0.3) and
  slowing down (``direction=-1``, lower ω); refuses overlapping friction circles and self-locking
  with an error naming the step.
- Sheet (A3, composed by the layout step): the half-governor (1:2.5 at the seed's data) with the
  friction circles to scale and the tangent reaction lines, the joints B, F, H enlarged (2:1),
  the force plans of the sleeve and the arm (μ_F = 1 N/mm; the frictionless polygon dashed), and
  tables.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build and draw live in p2013_7.py and load on first use.

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.problem import (
    Param,
    Problem,
    ResultSpec,
    SeedValue,
    lazy,
    measured_value,
    rounded,
)
from geomcad.verify import ANGLE_PRECISION_DEG

if TYPE_CHECKING:
    from .p2013_7 import Geometry

ID = "2013-7"
SEED_K_L = 0.002  # m/mm: the seed's k_l
SEED_K_F = 1.0  # N/mm: the seed's k_F

PARAMS = (
    Param("m2", 10.0, "mass of the sleeve 2", "kg", gt=0.0),
    Param("m_ball", 1.0, "mass of each ball (C, D)", "kg", gt=0.0),
    Param("f", 0.3, "friction coefficient in the six joints A, B, E, F, G, H", "1", ge=0.0),
    Param("d", 0.032, "pin diameter of each joint", "m", gt=0.0, display="mm"),
    Param("l_AB", 0.1, "distance AB between the sleeve's pivots", "m", gt=0.0, symbol="AB"),
    Param("l_GH", 0.1, "distance GH between the collar's pivots", "m", gt=0.0, symbol="GH"),
    Param("l_FH", 0.15, "arm 6: H to F", "m", gt=0.0, symbol="FH"),
    Param("l_DH", 0.22, "arm 6: H to the ball's centre D", "m", gt=0.0, symbol="DH"),
    Param("l_BF", 0.15, "link 3, BF", "m", gt=0.0, symbol="BF"),
    Param("theta_deg", 45.0, "angle of the arm HD to the vertical", "deg", gt=0.0, lt=90.0),
    Param("g", 9.81, "gravitational acceleration", "m/s²", gt=0.0),
    Param(
        "direction",
        1,
        "+1: slowly accelerating (the balls rise), −1: slowly slowing down (they sink)",
        "1",
        integer=True,
    ),
)

RESULTS = (
    ResultSpec("rho", "m", "friction-circle radius ρ = (d/2)·sin(arctan f)", "l", display="mm"),
    ResultSpec("alpha_deg", "deg", "inclination α of link 3's line of action to BF"),
    ResultSpec("R32", "N", "reaction of link 3 on the sleeve 2", "F"),
    ResultSpec("P", "N", "P = G_6 + R_36 (the ball's weight and link 3's pull on the arm)", "F"),
    ResultSpec("beta_deg", "deg", "inclination of R_76's line to the horizontal"),
    ResultSpec("F_i", "N", "inertia force of the ball D, m·r_D·ω² (Ф_6)", "F"),
    ResultSpec("r_D", "m", "radius at which the ball D turns", "l"),
    ResultSpec("omega", "rad/s", "angular velocity of the shaft"),
    ResultSpec(
        "omega_no_friction", "rad/s", "the same governor's ω with f = 0", symbol="ω (f = 0)"
    ),
)


def _omega_tol() -> float:
    """The seed's ω = √(85,1/0,206) = 20,3 rad/s carries the drawing precision of F_i (0.5 mm at
    k_F), the rounding of m·r_D to 0,206 and its own rounding to 0.1 rad/s."""
    f_i, mr, w = 85.1, 0.206, math.sqrt(85.1 / 0.206)
    from_f = 0.5 * SEED_K_F * w / (2.0 * f_i)
    from_r = 0.0005 * w / (2.0 * mr)
    return from_f + from_r + 0.05


SEED: dict[str, SeedValue] = {
    "rho": rounded(0.0046, 4, "ρ = 0,0046 м"),
    "alpha_deg": rounded(3.5, 1, "α = 3,5°"),
    "R32": rounded(74.0, 0, "R_32 = 74 Н"),
    "P": measured_value(80.8, SEED_K_F, "P = 80,8 Н"),
    # an angle read off the drawing with a protractor
    "beta_deg": SeedValue(63.2, "measured", ANGLE_PRECISION_DEG, "63,2°"),
    "F_i": measured_value(85.1, SEED_K_F, "F_i = 85,1 Н"),
    "r_D": rounded(0.206, 3, "F_i = 0,206ω² (m·r_D = 0,206 кг·м)"),
    "omega": SeedValue(20.3, "measured", _omega_tol(), "ω = 20,3 рад/с"),
}

PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Centrifugal governor: force polygons with friction circles",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_7:build", __package__),
    draw=lazy(".sheets_2013_7:sheets", __package__),
    seed_k_l=SEED_K_L,
    scales=lazy(".sheets_2013_7:scales", __package__),
)
