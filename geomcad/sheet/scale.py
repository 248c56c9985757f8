"""Scales: the factor k that maps a model quantity to sheet millimetres, and its printed label.

TMM writes a drawing's scale as a factor: k_l (μ_l) in m/mm for the mechanism, k_v in (m/s)/mm for
a velocity plan, k_a, k_F in N/mm. A mechanism's k_l is chosen so that the drawing's ratio is a
GOST 2.302 scale (k_l = 0.005 m/mm is 1:5); plan factors are rounded to 1, 2, 2.5, 4 or 5 × 10^n.
Some schools write the inverse (mm per unit): :class:`ScaleStyle` makes the symbol and the
direction a setting.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Literal

from geomcad import tol
from geomcad.errors import ParameterError
from geomcad.sheet.lang import Lang, Words, current

Quantity = Literal["l", "v", "a", "F"]

#: GOST 2.302 ratios (paper : nature), reductions and enlargements, as fractions.
GOST_RATIOS: tuple[Fraction, ...] = tuple(
    sorted(
        {Fraction(1, n) for n in (1, 2, 4, 5, 10, 15, 20, 25, 40, 50, 75, 100, 200, 400, 500)}
        | {Fraction(5, 2) ** -1, Fraction(5, 2)}
        | {Fraction(n) for n in (2, 4, 5, 10, 20, 40, 50, 100)}
    )
)

#: Mantissas of plan factors (DESIGN.md rule 6).
NICE = (1.0, 2.0, 2.5, 4.0, 5.0)
#: Mantissas of velocity and acceleration plan factors (1, 2 or 5 × 10^n: easy to read off).
PLAN_NICE = (1.0, 2.0, 5.0)

#: The units of the factors (``l``, ``v``, ``a``, ``F``; ``inv_*`` for mm per unit), per language.
WORDS = Words(__package__, "scale")


@dataclass(frozen=True)
class ScaleStyle:
    """How a scale factor is printed: the symbol (``μ`` or ``k``), the direction, the language.

    ``inverse`` prints mm per unit (1/k), as some schools do. Russian uses a decimal comma. The
    language defaults to the one being drawn (:func:`geomcad.sheet.lang.current`).
    """

    symbol: str = "μ"
    inverse: bool = False
    lang: Lang = field(default_factory=current)


#: A number this large or larger is written in plain digits (grouped by threes), never as a
#: power of ten: a sheet's values are in units that keep them short (kN for large forces).
PLAIN_FROM = 1.0


#: The separator of a long number's groups of three digits (GOST 8.417-2002, 6.5; ГОСТ 2.105,
#: 4.2.17): a narrow no-break space (U+202F), so that ``11 130`` reads as one number, never as
#: two; the shipped font draws it (``scripts/patch_osifont.py``).
GROUP_SEP = "\u202f"


def group_digits(s: str) -> str:
    """A plain number's whole part of five or more digits in groups of three, parted by
    :data:`GROUP_SEP` (GOST 8.417: ``11 130``, ``1 250 000``); four digits stay whole
    (``8544``)."""
    sign = s[0] if s[:1] in "-\u2013" else ""
    body = s[len(sign) :]
    whole, dot, frac = body.partition(".")
    if len(whole) < 5 or not whole.isdigit():
        return s
    groups = [whole[max(0, i - 3) : i] for i in range(len(whole), 0, -3)][::-1]
    return sign + GROUP_SEP.join(groups) + dot + frac


#: The significant figures of a value on a sheet: a table column's largest value, a load, a
#: result and a value in the order of construction (3–4 figures: a ТММ table reads −149,8,
#: never −149,806).
FIGURES = 4


def fmt_number(x: float, lang: str | None = None, digits: int = 6, *, zeros: bool = False) -> str:
    """A number for a sheet: up to ``digits`` significant digits, no trailing zeros (with
    ``zeros``, exactly ``digits``, trailing zeros kept: 367,0 and 58,40), a decimal comma in
    Russian (a point in English), a typographic minus; ``lang`` defaults to the language being
    drawn. A large number is written in plain digits, its whole part grouped by threes
    (``11 130``, not ``1,113·10⁴``); only a number below 10^−``digits`` takes a power of
    ten. Every single value of a sheet is written by it (a column of one quantity by
    :func:`fmt_column`), so that one value reads the same wherever it is printed."""
    if x == 0.0:
        return "0"
    s = f"{x:#.{digits}g}" if zeros else f"{x:.{digits}g}"
    if "e" in s and abs(x) >= PLAIN_FROM:
        s = f"{float(s):.0f}"
    if "e" in s:
        mant, exp = s.split("e")
        s = f"{mant.rstrip('.')}·10^{{{int(exp)}}}"
    else:
        s = group_digits(s.rstrip("."))
    s = s.replace("-", "\u2013")
    return s.replace(".", ",") if (lang or current()) == "ru" else s


def column_places(xs: Sequence[float], digits: int = FIGURES) -> int:
    """The one count of decimals of a table column of one quantity: those that write its
    largest magnitude to ``digits`` significant figures (−149,8 beside −0,7; 4,937 beside
    0,126), or fewer where they write every value exactly (0 / 15 / 30; 0,05 / 0,10). The
    smaller values keep fewer figures: the column reads at the precision of its largest, as a
    plan measured at one μ does. A value within ``tol.DERIVED`` of the largest is round-off
    of a zero and asks for nothing."""
    big = max((abs(x) for x in xs), default=0.0)
    if big == 0.0 or not math.isfinite(big):
        return 0
    cap = max(0, digits - 1 - math.floor(math.log10(big)))
    if cap > 0 and abs(round(big, cap)) >= 10.0 ** (digits - cap):  # 9,9996 → 10,00
        cap -= 1
    return next(
        (d for d in range(cap) if all(abs(x - round(x, d)) <= tol.DERIVED * big for x in xs)),
        cap,
    )


def fmt_column(xs: Sequence[float], lang: str | None = None, digits: int = FIGURES) -> list[str]:
    """A table column of one quantity, every number with the same count of decimals
    (:func:`column_places`: ``digits`` significant figures at its largest magnitude: 1,830 /
    3,870 / 9,078; −288,9 / −0,7). A decimal comma in Russian (a point in English), a
    typographic minus, a whole part of five or more digits grouped by threes."""
    places = column_places(xs, digits)
    return [fmt_fixed(x, places, lang) for x in xs]


#: An angle on a sheet is written to this many decimals of a degree where one of the sheet's
#: angles is not whole (0,1°: as a protractor reads it).
ANGLE_PLACES = 1


def angle_places(degrees: Sequence[float]) -> int:
    """The one count of decimals every angle of a sheet is written with: none where all of
    ``degrees`` are whole, else :data:`ANGLE_PLACES` (``3,7°`` beside ``92,5°``, never
    ``3,749°`` beside ``92,51°``)."""
    whole = all(abs(x - round(x)) <= 10.0**-ANGLE_PLACES / 2.0 for x in degrees)
    return 0 if whole else ANGLE_PLACES


def fmt_fixed(x: float, places: int, lang: str | None = None) -> str:
    """A number with exactly ``places`` decimals, a decimal comma in Russian (a point in
    English), a typographic minus, a whole part of five or more digits grouped by threes."""
    s = f"{x:.{places}f}"
    if float(s) == 0.0:
        s = s.lstrip("-")
    s = group_digits(s).replace("-", "\u2013")
    return s.replace(".", ",") if (lang or current()) == "ru" else s


@dataclass(frozen=True)
class Scale:
    """``k`` model units per sheet millimetre for quantity ``q`` (l, v, a or F)."""

    k: float
    q: Quantity = "l"

    def __post_init__(self) -> None:
        if not (self.k > 0.0 and math.isfinite(self.k)):
            raise ParameterError(f"k_{self.q}", self.k, "a scale factor must be positive")

    def mm(self, value: float) -> float:
        """A model quantity as sheet millimetres."""
        return value / self.k

    def model(self, mm: float) -> float:
        """Sheet millimetres as the model quantity."""
        return mm * self.k

    @property
    def ratio(self) -> Fraction | None:
        """The drawing's ratio paper : nature for a length scale (k in m/mm), when it is GOST."""
        if self.q != "l":
            return None
        r = Fraction(1, 1000) / Fraction(self.k).limit_denominator(10**9)
        for g in GOST_RATIOS:
            if abs(float(g) - float(r)) <= tol.DERIVED * float(r):
                return g
        return None

    def ratio_text(self) -> str:
        """``1:5``, ``2:1``, ``1:2,5`` — GOST 2.302's way to write the ratio, or ``''``."""
        r = self.ratio
        if r is None:
            return ""
        if r >= 1:
            return f"{fmt_number(float(r))}:1"
        return f"1:{fmt_number(float(1 / r))}"

    def label(self, style: ScaleStyle | None = None) -> str:
        """The factor as the subject writes it, as label markup: ``μ_l = 0,005 м/мм``."""
        style = style or ScaleStyle()
        unit = WORDS(f"inv_{self.q}" if style.inverse else self.q, style.lang)
        value = 1.0 / self.k if style.inverse else self.k
        q = "V" if self.q == "v" and style.symbol == "μ" else self.q
        return f"{style.symbol}_{q} = {fmt_number(value, style.lang)} {unit}"


def gost_length_scale(extent_m: float, room_mm: float) -> Scale:
    """The largest GOST 2.302 scale at which ``extent_m`` metres fit in ``room_mm`` millimetres.

    A drawing too large even at the smallest listed reduction is a :class:`ParameterError`.
    """
    if not (0.0 < extent_m < math.inf and 0.0 < room_mm < math.inf):
        raise ParameterError("extent", extent_m, "a drawing needs a finite positive size and room")
    fitting = [g for g in GOST_RATIOS if extent_m * 1000.0 * float(g) <= room_mm]
    if not fitting:
        raise ParameterError(
            "extent", extent_m, f"too large for {room_mm:g} mm even at 1:{1 / GOST_RATIOS[0]}"
        )
    return Scale(float(Fraction(1, 1000) / fitting[-1]), "l")


def gost_scale_to_fit(width_m: float, height_m: float, room_w_mm: float, room_h_mm: float) -> Scale:
    """The largest GOST 2.302 scale at which a drawing ``width_m`` × ``height_m`` fits a field
    ``room_w_mm`` × ``room_h_mm`` (both directions at once; errors as
    :func:`gost_length_scale`)."""
    return gost_length_scale(max(width_m * room_h_mm / room_w_mm, height_m), room_h_mm)


def nice_factor(
    value_max: float, room_mm: float, q: Quantity, mantissas: tuple[float, ...] = NICE
) -> Scale:
    """The smallest factor m × 10^n (m one of ``mantissas``: 1, 2, 2.5, 4 or 5 by default) at
    which ``value_max`` fits in ``room_mm``."""
    if not (0.0 < value_max < math.inf and 0.0 < room_mm < math.inf):
        raise ParameterError(f"k_{q}", value_max, "a plan needs a finite positive size and room")
    raw = value_max / room_mm
    e = math.floor(math.log10(raw))
    for exp in (e, e + 1):
        for m in mantissas:
            k = m * 10.0**exp
            if k >= raw:
                return Scale(k, q)
    return Scale(10.0 ** (e + 2), q)  # unreachable: 10^(e+1) ≥ raw always


def nice_below(value_min: float, mm: float, q: Literal["F"] = "F") -> Scale:
    """The largest factor 1, 2, 2.5, 4, 5 × 10^n at which ``value_min`` is at least ``mm``."""
    raw = value_min / mm
    e = math.floor(math.log10(raw))
    for exp in (e, e - 1):
        for m in (5.0, 4.0, 2.5, 2.0, 1.0):
            k = m * 10.0**exp
            if k <= raw * (1.0 + tol.REL_LENGTH):
                return Scale(k, q)
    return Scale(10.0 ** (e - 1), q)  # unreachable
