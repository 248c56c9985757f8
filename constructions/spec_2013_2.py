"""Cam profile for S = aφ by inversion ("cam profile radii").

- A disc cam and a translating flat-faced follower: the follower is turned back to each
  division point, its face lines are drawn, and the profile is their exact envelope (for
  S = aφ an involute of the circle of radius a, which is checked).
- The velocity plan and the similar triangle OBB′ put the contact point S′ along the face, so
  r = √((r0 + S)² + S′²).
- Reports the radius vectors at the division points beside the seed's, the smallest radius of
  curvature, the largest pressure angle and the profile; explains the jump of S′ at φ = 0 (a
  straight piece of the face, a rigid impact).
- Variants through ``--set``: a full turn (rise, outer dwell, return), five motion laws, knife-edge
  and roller followers with an offset e (the roller profile offset exactly along the normals),
  either sense of rotation. A cusp or an undercut (base circle too small, roller too large, a drop
  of S′) is an error naming the step.
- Sheet (A2): the profile at 2:1 with the radius vectors (the rest of the rise in thin lines),
  the S(φ) and S′(φ) graphs, the mechanism with the velocity plan and ΔOBB′, and the tables of
  data and results.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_2.py, the sheet and its scales in sheets_2013_2.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, SeedValue, lazy, rounded
from geomcad.units import MM

if TYPE_CHECKING:
    from .p2013_2 import Geometry

#: The motion laws of geomcad.kinematics.motion_laws.LAWS, spelled out here so that the parameter
#: list loads without numpy (a test keeps the two equal).
LAWS = ("linear", "constant_acceleration", "harmonic", "cycloidal", "poly345")

ID = "2013-2"
#: The seed's profile drawing: 2:1, k_l = 0.0005 m/mm.
SEED_K_L = 0.0005

PARAMS = (
    Param("H", 0.04, "stroke of the follower on the rise", "m", gt=0.0, display="mm"),
    Param("phi_rise_deg", 180.0, "rise angle φ_у", "deg", gt=0.0, le=360.0),
    Param("r0", 0.04, "base circle radius of the theoretical profile", "m", gt=0.0, display="mm"),
    Param("n_div", 4, "number of equal intervals of the span", "1", integer=True, ge=1, le=360),
    Param(
        "span_fraction",
        0.5,
        "part of the program (rise + dwell + return) the division points cover",
        "1",
        gt=0.0,
        le=1.0,
    ),
    Param(
        "omega_sign",
        1,
        "+1: the cam turns counter-clockwise, −1: clockwise",
        integer=True,
        symbol="ω",
    ),
    Param("phi_dwell_deg", 0.0, "outer dwell after the rise", "deg", ge=0.0, lt=360.0),
    Param("phi_return_deg", 0.0, "return angle (0: no return phase)", "deg", ge=0.0, lt=360.0),
    Param("law", "linear", "the follower's motion law (rise and return)", choices=LAWS),
    Param("follower", "flat", "the follower", choices=("flat", "knife", "roller")),
    Param("e", 0.0, "offset of the follower's axis from O", "m", display="mm"),
    Param("r_roller", 0.0, "roller radius (roller follower)", "m", ge=0.0, display="mm"),
)

RESULTS = (
    ResultSpec("phi", "rad", "cam angles φ_i of the division points", symbol="φ_i", display="deg"),
    ResultSpec(
        "S",
        "m",
        "follower displacement S_i at the division points",
        "l",
        symbol="S_i",
        display="mm",
    ),
    ResultSpec(
        "r",
        "m",
        "radius vectors r_i of the profile at the division points",
        "l",
        symbol="r_i",
        display="mm",
    ),
    ResultSpec("a", "m", "H/φ_rise (= S′ of the linear law)", "l", display="mm"),
    ResultSpec("pressure_angle_max_deg", "deg", "largest pressure angle along the profile"),
    ResultSpec("rho_min", "m", "smallest radius of curvature of the profile", "l"),
    ResultSpec("profile", "m", "profile points [x, y] in the cam's frame"),
)

_R_PRINTED = ("41,98", "46,77", "51,6", "56,45", "61,34")
SEED: dict[str, SeedValue | tuple[SeedValue, ...]] = {
    "a": rounded(12.73, 2, "S′ = a = 40/π = 12,73 мм", MM),
    "r": tuple(
        rounded(float(t.replace(",", ".")), len(t.split(",")[1]), f"r_{i} = {t} мм", MM)
        for i, t in enumerate(_R_PRINTED)
    ),
}

PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Cam profile for S = a·φ, translating flat-faced follower (radius vectors by inversion)",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_2:build", __package__),
    draw=lazy(".sheets_2013_2:sheets", __package__),
    scales=lazy(".sheets_2013_2:scales", __package__),
    seed_k_l=SEED_K_L,
)
