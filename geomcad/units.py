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


#: The units a sheet may write a quantity in other than its SI unit, as the subject does (a module
#: in mm, a force in kN, an energy in kJ): display unit → (its SI unit, display units per SI unit).
DISPLAY: dict[str, tuple[str, float]] = {
    "mm": ("m", 1e3),
    "kN": ("N", 1e-3),
    "kN·m": ("N·m", 1e-3),
    "kJ": ("J", 1e-3),
    "kW": ("W", 1e-3),
    "MPa": ("Pa", 1e-6),
    "deg": ("rad", 180.0 / math.pi),
}


def check_display(name: str, unit: str, display: str) -> None:
    """Refuse a display unit that is not one of :data:`DISPLAY` for ``unit`` (a spec's mistake,
    found when its module loads)."""
    if display and display != unit and DISPLAY.get(display, ("", 0.0))[0] != unit:
        raise ValueError(f"{name}: cannot write a quantity in {unit!r} in {display!r}")


def to_display(x: float, unit: str, display: str) -> float:
    """``x`` in the SI ``unit`` written in ``display`` (the same number when it is ``unit``).

    >>> to_display(0.0025, "m", "mm"), to_display(37600.0, "N", "kN")
    (2.5, 37.6)
    """
    if not display or display == unit:
        return x
    check_display("a value", unit, display)
    f = DISPLAY[display][1]
    return x * f if f >= 1.0 else x / round(1.0 / f)  # kN: x / 1000, exact where x·0.001 is not
