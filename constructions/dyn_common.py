"""Drawing helpers shared by the dynamics sheets (2013-9, kulisa-23110713): loads on free-body
diagrams at a force scale, with their values."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from geomcad import tol
from geomcad.geom import Vec
from geomcad.sheet import Viewport, fmt_number
from geomcad.sheet.drawing import ARROW_LEN
from geomcad.sheet.loads import force, moment

ORIGIN = Vec(0.0, 0.0)

#: A force arrow shorter than this (mm) is drawn this long, so that its head shows.
#: A force shorter than this at μ_F (two arrowheads) cannot be read as an arrow: it is drawn as
#: a point with its label, and the sheet says so (SHEETS.md).
SHORT_MM = 2.0 * ARROW_LEN


def f(x: float, digits: int = 4) -> str:
    """A number for a sheet (decimal comma), ``digits`` significant digits."""
    return fmt_number(x, digits=digits)


def small(x: float, scale: float, unit: str = "") -> str:
    """A quantity that should vanish: its value, or "|…| < 10^{–9}·scale" when it is round-off
    (so that the sheet does not print noise that differs from machine to machine)."""
    bound = tol.DERIVED * abs(scale)
    if abs(x) <= bound:
        return f"|·| < {fmt_number(bound, digits=1)}{(' ' + unit) if unit else ''}"
    return f"{f(x, 3)}{(' ' + unit) if unit else ''}"


def short_note(k_F: float) -> str:
    """The sheet's words for the forces drawn as points."""
    return (
        f"силы короче {f(SHORT_MM)} мм при μ_F = {f(k_F)} Н/мм показаны точкой, "
        "их значения – у точки и в таблице"
    )


@dataclass(frozen=True)
class Where:
    """How a load is drawn: its label, the point it is drawn at (None: where it acts), whether
    the arrow arrives there, a preferred label direction, a moment's radius and start angle."""

    label: str
    at: Vec | None = None
    arrive: bool = False
    prefer: tuple[float, float] | None = None
    radius: float = 8.0
    start_deg: float = -35.0


def draw_loads(
    v: Viewport,
    reactions: Any,
    k_F: float,
    body: str,
    where: dict[str, Where],
    centre: Vec = ORIGIN,
) -> None:
    """Every solved load on ``body``: forces at their points exactly at k_F (one shorter than
    :data:`SHORT_MM` as a point with its label), moments about their points; the balancing
    check moment and round-off forces are left out."""
    biggest = max(
        (a.force.norm for lds in reactions.loads.values() for a in lds if a.force),
        default=0.0,
    )
    for ld in reactions.loads[body]:
        if ld.kind == "balancing":
            continue
        w = where.get(ld.name, Where(ld.name))
        if ld.force is not None:
            if ld.force.norm <= tol.DERIVED * biggest:
                continue
            text = f"{w.label} = {f(ld.force.norm)} Н"
            if ld.force.norm / k_F < SHORT_MM:
                v.dot(w.at or ld.at)
                v.label(w.at or ld.at, f"{text} (·)", 2.5, prefer=w.prefer, clear=1.0)
                continue
            force(v, w.at or ld.at, ld.force, k_F, text, w.arrive,
                  role="result", height=2.5, prefer=w.prefer)  # fmt: skip
        elif abs(ld.moment) > 0.0:
            text = f"{w.label} = {f(abs(ld.moment))} Н·м"
            moment(v, w.at or centre, ld.moment, w.radius, text, role="result",
                   start=math.radians(w.start_deg), height=2.5)  # fmt: skip
