"""Roles and their line styles (GOST 2.303 on a Russian sheet, ISO 128 on an English one), and dash
patterns fitted to each line.

Every item on a sheet has a role: what it is on the drawing. The role fixes its layer (one SVG
group per role) and its line: weight as a multiple of the main line S, type (solid, dashed,
dash-dot, two-dot), and whether closed shapes are filled.

A dash-dot line must start and end with a dash, and a circle's centre must lie where two dashes
cross; SVG's ``stroke-dasharray`` alone does not do that, so :func:`fit_open` and
:func:`fit_closed` choose the dash length for each line's own length.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Literal

from geomcad.sheet.lang import Lang, current
from geomcad.sheet.model import Dash

LineType = Literal["solid", "dashed", "dashdot", "twodot"]

#: Main solid line S (mm) by format: 0.7 on A3/A4, 0.8 on A2, 1.0 on A1 and A0.
MAIN_LINE = {"A4": 0.7, "A3": 0.7, "A2": 0.8, "A1": 1.0, "A0": 1.0}


@dataclass(frozen=True, slots=True)
class Style:
    """A role's look: ``weight`` × S, the line type, the stroke colour and the fill of shapes."""

    weight: float
    line: LineType = "solid"
    stroke: str = "#000000"
    fill: str = "none"


#: The roles, in drawing order (later layers are drawn on top).
STYLES: dict[str, Style] = {
    "ground": Style(1 / 3),  # hatching of the frame's supports
    "construction": Style(1 / 3, stroke="#1f4e9c"),  # thin lines of the graphical solution
    "locus": Style(1 / 3, "dashed", stroke="#1f4e9c"),  # a locus that gives no solution
    "centre": Style(1 / 3, "dashdot"),  # axes, centre lines, paths
    "thin": Style(1 / 3),  # solid thin lines of a part's view (GOST 2.402: a gear's root circle)
    "extreme": Style(1 / 3, "twodot"),  # extreme positions of links
    "dimension": Style(1 / 3, fill="#000000"),  # dimension and leader lines, their arrowheads
    "result": Style(2 / 3, stroke="#b01c1c", fill="#b01c1c"),  # what the construction finds
    "vector": Style(1 / 2, fill="#000000"),  # plan vectors and their arrowheads
    "link": Style(1.0),  # links of the mechanism, main solid line
    "joint": Style(1 / 2, fill="#ffffff"),  # revolute joints: circles over the links
    "point": Style(1 / 3, fill="#000000"),  # marked points: small filled dots
    "frame": Style(1.0),  # the frame and the title block's thick lines
    "frame_thin": Style(1 / 3),  # the title block's thin lines
    "label": Style(0.0, fill="#000000"),  # lettering on the drawing
    "title": Style(0.0, fill="#000000"),  # lettering in the title block and tables
}

#: Dash parameters (mm): GOST 2.303 ranges, with the length we aim for inside each.
DASHED = (2.0, 4.0, 8.0, 1.5)  # min, target, max dash; gap
DASHDOT = (5.0, 12.0, 30.0, 1.5, 0.5)  # min, target, max dash; gap either side of the dot; dot
TWODOT = (5.0, 12.0, 30.0, 1.3, 0.5)
#: ISO 128-20's line elements for an English sheet, at the narrow line of ISO 128-24's line group
#: 0.7 (d = 0.35 mm): dash 12d, long dash 24d, space 3d, dot 0.5d; the dash is still fitted to
#: each line (ISO 128-20: lines start and end with a dash, and cross at dashes) within
#: 0.7-1.4 times its length.
ISO_D = 0.35
ISO_DASHED = (8.5 * ISO_D, 12 * ISO_D, 17 * ISO_D, 3 * ISO_D)
ISO_DASHDOT = (17 * ISO_D, 24 * ISO_D, 34 * ISO_D, 3 * ISO_D, 0.5 * ISO_D)
ISO_TWODOT = ISO_DASHDOT


def patterns(
    lang: Lang | None = None,
) -> tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]]:
    """(dashed, dash-dot, two-dot) dash parameters of ``lang`` (default: the language being
    drawn): GOST 2.303 in Russian, ISO 128-20 in English."""
    if (lang or current()) == "ru":
        return DASHED, DASHDOT, TWODOT
    return ISO_DASHED, ISO_DASHDOT, ISO_TWODOT


#: ISO 128-20's narrow line is half the wide one (line group 0.7: 0.35 and 0.7 mm).
ISO_NARROW = 1 / 2


def for_language(st: Style, lang: str) -> Style:
    """A role's style on a sheet drawn in ``lang``: an English sheet draws GOST's thin lines
    (S/3) as ISO 128's narrow lines (S/2); a Russian one keeps them."""
    if lang == "ru" or not 0.0 < st.weight < ISO_NARROW:
        return st
    return replace(st, weight=ISO_NARROW)


def style(role: str) -> Style:
    """The style of a role; an unknown role is a programming error (``KeyError`` names it)."""
    try:
        return STYLES[role]
    except KeyError:
        raise KeyError(f"unknown sheet role {role!r}; roles are {', '.join(STYLES)}") from None


def _gap_pattern(line: LineType) -> tuple[tuple[float, ...], float, float, float]:
    """(the gap's own pattern between two dashes, its length, dash min, dash target)."""
    dashed, dashdot, twodot = patterns()
    if line == "dashed":
        lo, target, _hi, gap = dashed
        return (gap,), gap, lo, target
    lo, target, _hi, s, dot = dashdot if line == "dashdot" else twodot
    dots = 1 if line == "dashdot" else 2
    pat: tuple[float, ...] = (s,) + (dot, s) * dots
    return pat, sum(pat), lo, target


def _count(length: float, gap: float, lo: float, target: float, least: int, step: int) -> int:
    """The number of dashes nearest the target dash length that keeps every dash ≥ ``lo``;
    at least ``least`` (stepping by ``step`` to keep the parity); 0 when not even that fits."""
    n = max(least, round((length + gap) / (target + gap)))
    if (n - least) % step:
        n -= 1
    while n >= least and (length - (n - 1) * gap) / n < lo:
        n -= step
    return n if n >= least else 0


def fit_open(line: LineType, length: float) -> Dash | None:
    """The dash pattern for an open line of ``length`` mm that starts and ends with a dash.

    ``None`` for a solid line, or for a line too short to hold two dashes of GOST length (drawn
    solid, as GOST allows for short centre lines).
    """
    if line == "solid" or length <= 0.0:
        return None
    gap_pat, gap, lo, target = _gap_pattern(line)
    n = _count(length, gap, lo, target, 2, 1)
    if n == 0:
        return None
    return Dash(((length - (n - 1) * gap) / n, *gap_pat))


def fit_closed(line: LineType, length: float) -> Dash | None:
    """The dash pattern for a closed line (a circle) of perimeter ``length`` mm.

    A whole number of periods (at least two) fits the perimeter, and the offset centres a gap on
    the start point, so the pattern is symmetric about it.
    """
    if line == "solid" or length <= 0.0:
        return None
    gap_pat, gap, lo, target = _gap_pattern(line)
    n = max(2, round(length / (target + gap)))
    while n >= 2 and length / n - gap < lo:
        n -= 1
    if n < 2:
        return None
    dash = length / n - gap
    return Dash((dash, *gap_pat), offset=dash + gap / 2.0)


def fit_centre_line(line: LineType, half: float) -> Dash | None:
    """The pattern for a centre line of length 2·``half`` whose middle falls inside a dash.

    An odd number of dashes (at least three), the middle one centred on the centre, so that two
    such lines cross at a dash (GOST 2.303). ``None`` when three dashes do not fit.
    """
    if line == "solid" or half <= 0.0:
        return None
    gap_pat, gap, lo, target = _gap_pattern(line)
    n = _count(2.0 * half, gap, lo, target, 3, 2)
    if n == 0:
        return None
    return Dash(((2.0 * half - (n - 1) * gap) / n, *gap_pat))


def arc_length(r: float, sweep: float) -> float:
    """Length of an arc of radius ``r`` and angle ``sweep`` (rad)."""
    return abs(r * sweep)


def circle_length(r: float) -> float:
    return 2.0 * math.pi * r
