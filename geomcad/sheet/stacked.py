"""Diagrams stacked over one abscissa: s(φ), v(φ), a(φ) of a mechanism's output, one under
the other in the box the layout gives them, at one factor of the abscissa (μ_φ), each row at
its own nice factor, chosen together so that the rows fill the height with the largest least
row. One abscissa value (the plans' position φ1) is marked down every row, and each row's
value there (read off the plans) is a dot on its curve, which it must lie on.

Appended for the seed sheets (2013-6's kinematics sheet); it takes any curves.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from geomcad.sheet.compose import Placed, View
from geomcad.sheet.drawing import Drawing
from geomcad.sheet.graph import Axis, Graph, nice_steps
from geomcad.sheet.lang import current
from geomcad.sheet.model import Polyline

#: Room (mm) left of the abscissa's origin for the tick values and the symbols, and right of
#: its end for the arrow and its symbol.
LEFT_MM = 20.0
RIGHT_MM = 20.0
#: Each row's room (mm) beyond its curve: the arrow, the symbol, the tick values.
ROW_PAD_MM = 15.0
#: Room (mm) over the rows for the heading.
HEAD_MM = 4.0
#: A row's axis lies this far (mm) under its top plus its curve's height over zero; the mark
#: runs down from this far (mm) under the row's top; the factors are written this far (mm)
#: right of the origin and under the row's top.
AXIS_DROP_MM = 9.0
MARK_DROP_MM = 8.0
FACTORS_AT_MM = (26.0, 4.0)
#: Text height (mm) of the heading and the factors.
TEXT_MM = 2.5
#: Finer nice factors a row may take, tried together.
CHOICES = 6


@dataclass(frozen=True)
class Stacked:
    """One row: the ordinate's ``symbol`` and ``unit`` (markup), its values ``ys`` over the
    view's abscissa, its value ``at_mark`` at the marked abscissa and the dot's label."""

    symbol: str
    unit: str
    ys: npt.ArrayLike
    at_mark: float
    label: str = ""


def row_factors(ranges: Sequence[float], span: float, pad: float = ROW_PAD_MM) -> list[float]:
    """The rows' factors (nice, units per mm): of the few finest each range allows, the
    choice whose curves, stacked with their rows' room ``pad``, fill ``span`` mm with the
    largest least height."""
    total = span - pad * len(ranges)
    options = [nice_steps((r if r > 0.0 else 1.0) / max(total, 1.0), CHOICES) for r in ranges]
    best: tuple[tuple[float, float], list[float]] | None = None
    for combo in itertools.product(*options):
        h = [(r if r > 0.0 else 1.0) / k for r, k in zip(ranges, combo, strict=True)]
        if best is None or (sum(h) <= total and (min(h), sum(h)) > best[0]):
            best = ((min(h), sum(h)) if sum(h) <= total else (-1.0, 0.0), list(combo))
    assert best is not None, "at least one choice"
    return best[1]


class StackedDiagrams(View):
    """Rows of curves over one abscissa ``xs`` from ``lo`` to ``hi`` (its ``symbol`` and
    ``unit``), the abscissa ``mark`` marked down every row, ``heading`` written over them."""

    def __init__(
        self,
        symbol: str,
        unit: str,
        lo: float,
        hi: float,
        xs: npt.ArrayLike,
        rows: Sequence[Stacked],
        mark: float,
        heading: str = "",
        least: tuple[float, float] = (150.0, 120.0),
        prefer: tuple[float, float] = (240.0, 170.0),
        **kw: Any,
    ) -> None:
        kw.setdefault("margin", 0.0)
        super().__init__(**kw)
        self.symbol, self.unit, self.lo, self.hi = symbol, unit, lo, hi
        self.xs, self.rows, self.mark, self.heading = xs, list(rows), mark, heading
        self.least, self.prefer = least, prefer

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        return self.least, self.prefer

    def used(self, w: float, h: float) -> tuple[float, float]:
        """The width the abscissa really takes at its rounded factor, and all the height."""
        room = w - LEFT_MM - RIGHT_MM
        if room <= 1.0:
            return 0.0, 0.0
        k = Axis.fit(self.symbol, "", self.lo, self.hi, room).k
        return (self.hi - self.lo) / k + LEFT_MM + RIGHT_MM, h

    def draw(self, d: Drawing, at: Placed) -> None:
        lang = current()
        x0, y0, x1, y1 = at.inner
        gx = (x0 + LEFT_MM, x1 - RIGHT_MM)
        x_axis = Axis.fit(self.symbol, self.unit, self.lo, self.hi, gx[1] - gx[0])
        if self.heading:
            d.text(self.heading, (x0, y0 + TEXT_MM), TEXT_MM)
        top = y0 + HEAD_MM
        spans = [(min(float(np.min(r.ys)), 0.0), max(float(np.max(r.ys)), 0.0)) for r in self.rows]
        factors = row_factors([hi - lo for lo, hi in spans], y1 - top)
        for row, (lo, hi), k in zip(self.rows, spans, factors, strict=True):
            y_axis = Axis(row.symbol, row.unit, lo, hi, k, row.symbol.split("_")[0])
            bottom = top + ROW_PAD_MM + (hi - lo) / k
            zero_y = top + AXIS_DROP_MM + y_axis.mm(y_axis.hi)
            g = Graph(d, x_axis, y_axis, (gx[0], zero_y))
            g.axes(lang, tick_labels=True)
            g.curve(self.xs, row.ys, "result")
            # the mark from the top of the field down to the axis or the point (not through
            # the tick values under the axis)
            xm, y_axis0 = g.p(self.mark, 0.0)
            y_pt = g.p(self.mark, float(row.at_mark))[1]
            d.sheet.add(
                Polyline(((xm, top + MARK_DROP_MM), (xm, max(y_axis0, y_pt))), "construction")
            )
            g.point(self.mark, float(row.at_mark), row.label)
            g.factors((gx[0] + FACTORS_AT_MM[0], top + FACTORS_AT_MM[1]), lang)
            top = bottom
