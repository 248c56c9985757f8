"""One unit table. SI inside (m, rad, m/s, N); degrees only in names ending in ``_deg``.

The sheet is in millimetres of paper; a scale factor k converts model units to sheet mm
(k_l in m/mm, k_v in (m/s)/mm, k_F in N/mm).
"""

from __future__ import annotations

import math

MM = 1.0e-3  #: one millimetre in metres


def deg(x_deg: float) -> float:
    """Degrees to radians."""
    return math.radians(x_deg)


def to_deg(x_rad: float) -> float:
    """Radians to degrees."""
    return math.degrees(x_rad)


def wrap_deg(x_deg: float) -> float:
    """An angle in degrees brought into [0, 360)."""
    r = math.fmod(x_deg, 360.0)
    if r < 0.0:
        r += 360.0
    return 0.0 if r == 360.0 else r
