"""One unit table. SI inside (m, rad, m/s, N); degrees only in names ending in ``_deg``.

The sheet is in millimetres of paper; a scale factor k converts model units to sheet mm
(k_l in m/mm, k_v in (m/s)/mm, k_F in N/mm).
"""

from __future__ import annotations

import math

MM = 1.0e-3  #: one millimetre in metres

#: The physical range of a quantity by its unit: (smallest, largest) magnitude other than 0.
#: Wide enough for any real machine, narrow enough that float64 arithmetic stays exact enough
#: (a length from a micron to a kilometre). A parameter may declare its own ``span``.
PHYSICAL: dict[str, tuple[float, float]] = {
    "m": (1e-6, 1e3),
    "kg": (1e-6, 1e6),
    "kg·m²": (1e-9, 1e6),
    "N": (1e-6, 1e8),
    "N·m": (1e-6, 1e7),
    "N/m": (1e-3, 1e9),
    "N·s/m": (1e-3, 1e7),
    "Pa": (1e-3, 1e11),
    "m/s": (1e-6, 1e4),
    "m/s²": (1e-3, 1e4),
    "rad/s": (1e-6, 1e5),
    "rpm": (1e-3, 1e6),
    "1/s": (1e-6, 1e4),
    "s": (1e-6, 1e4),
    "deg": (1e-6, 1e6),
    "1": (0.0, 1e6),
}


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
