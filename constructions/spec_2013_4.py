"""Profile shift from a gear-tooth caliper reading.

- The chord s̄ at the height h̄ below the tip circle fixes the circle d_y through its ends and
  half the angular tooth thickness ψ_y (tg ψ_y = s̄/(d_a − 2h̄)); the tangent from the chord's end
  to the base circle gives α_y; the involute relation gives the pitch thickness s and the shift x.
- Checks it by cutting the tooth with the GOST 13755 rack at that shift (the flank is the
  envelope of the rack's flank, exactly on the involute) and reading the caliper on it again.
- Reports the seed's garbled ψ_y formula and the rounding in its d_y and α_y.
- The library (``geomcad.kinematics.gears``) also predicts chordal and constant-chord readings and
  the span W over k teeth from x, recovers x from each, and refuses impossible readings, pointed
  tips and chords in the fillet.
- Sheet (A3, 5:1): one generated tooth with the producing rack, the circles d_a, d, d_f, d_b, d_y
  (GOST 2.402), the chord and height dimensioned, the construction of ψ_y and α_y, and tables.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_4.py, the sheet and its scales in sheets_2013_4.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, erratum, lazy, rounded
from geomcad.units import MM

if TYPE_CHECKING:
    from .p2013_4 import Geometry

ID = "2013-4"

PARAMS = (
    Param("m", 0.01, "module", "m", gt=0.0, display="mm"),
    Param(
        "alpha_deg",
        20.0,
        "profile angle of the basic rack (GOST 13755: 20°)",
        "deg",
        gt=0.0,
        lt=90.0,
    ),
    Param("z", 40, "number of teeth", "1", integer=True, ge=1),
    Param("d_a", 0.42, "tip diameter", "m", gt=0.0, display="mm"),
    Param(
        "s_chord",
        0.0181,
        "chordal thickness s̄ read by the caliper",
        "m",
        gt=0.0,
        symbol="s̄",
        display="mm",
    ),
    Param(
        "h_chord",
        0.0091,
        "chordal height h̄ (from the tip circle to the chord)",
        "m",
        gt=0.0,
        symbol="h̄",
        display="mm",
    ),
)

RESULTS = (
    ResultSpec("d", "m", "pitch diameter m·z", "l", display="mm"),
    ResultSpec("d_b", "m", "base diameter d·cos α", "l", display="mm"),
    ResultSpec("d_y", "m", "diameter of the circle through the chord's ends", "l", display="mm"),
    ResultSpec("psi_y", "rad", "half the tooth's angular thickness at d_y: tan ψ_y = s̄/(d_a − 2h̄)"),
    ResultSpec("alpha_y_deg", "deg", "pressure angle of the involute at d_y: cos α_y = d_b/d_y"),
    ResultSpec("s", "m", "tooth thickness on the pitch circle", "l", display="mm"),
    ResultSpec("x", "1", "profile shift coefficient"),
)

SEED = {
    "d": rounded(400.0, 0, "d = 400 мм", MM),
    "d_b": rounded(375.88, 2, "d_b = 375,88 мм", MM),
    "d_y": erratum(
        402.25 * MM,
        "it is s̄/sin ψ_y with ψ_y rounded to 2,579° (sin 2,579° instead of sin 2,57928°); "
        "exactly d_y = √(s̄² + (d_a − 2h̄)²) = 402,207 мм",
        "d_y = 402,25 мм",
    ),
    "psi_y": rounded(0.04502, 5, "φ_y = 2,579° = 0,04502 рад"),
    "alpha_y_deg": erratum(
        20.86,
        "it follows from the seed's d_y = 402,25 мм (cos α_y = 375,88/402,25); from the exact "
        "d_y = 402,207 мм, α_y = 20,847°",
        "α_y = 20,86°",
    ),
    "s": rounded(18.83, 2, "s = 18,83 мм", MM),
    "x": rounded(0.43, 2, "x = 0,43"),
}

#: What the seed should have written for the half angular thickness (its formula is garbled).
CORRECT_PSI_FORMULA = "tg ψ_y = (s̄_y/2)/(d_a/2 − h̄_ay) = s̄_y/(d_a − 2h̄_ay) = 18,1/401,8 = 0,04505"
#: The seed's text as printed (LaTeX): tan φ_y/2 over (d_a − 2h̄) = 18,1/(420 − 2·9,1).
SEED_PSI_FORMULA = r"\frac{\tan \phi_y / 2}{d_a - 2\bar{h}_{ay}} = \frac{18,1}{420 - 2 \cdot 9,1}"


#: The seed's misprinted formula: a note with every solve of the seed's data.
SEED_NOTES = (
    "seed formula garbled: for the half angular thickness it prints "
    "«tan φ_y/2 / (d_a − 2h̄_ay) = 18,1/(420 − 2·9,1)»; the geometry (the chord's ends lie "
    "s̄/2 either side of the tooth's axis, r_a − h̄ from the centre) gives "
    f"«{CORRECT_PSI_FORMULA}», which is the number the seed then uses",
)


PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Profile shift from a gear-tooth caliper measurement",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    seed_notes=SEED_NOTES,
    build=lazy(".p2013_4:build", __package__),
    draw=lazy(".sheets_2013_4:sheets", __package__),
    scales=lazy(".sheets_2013_4:scales", __package__),
)
