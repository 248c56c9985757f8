"""Diagrams on a sheet: a quantity plotted against another, each axis at its own scale factor.

TMM draws kinematic and dynamic diagrams (S(φ), V(φ), a(φ), J_пр(φ), ω(φ), F(s) …) as graphs
whose axes carry scale factors the way plans do: μ_φ in rad/mm, μ_S in m/mm. An :class:`Axis` is
one such axis: its symbol, its unit, the range of values it must show and its factor (1, 2, 2.5, 4
or 5 × 10^n units per mm, the smallest that fits the room). A :class:`Graph` puts two axes on the
sheet with the data origin at a chosen sheet point, draws the axes with arrows, ticks and values,
and plots curves, points and hatched areas (work under a force curve).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import ParameterError
from geomcad.sheet.drawing import DOT_R, Drawing, _arrow, _head
from geomcad.sheet.lang import Lang, Words
from geomcad.sheet.model import XY, CircleItem, Polyline, Sheet
from geomcad.sheet.scale import NICE, fmt_fixed, fmt_number, nice_below
from geomcad.sheet.style import fit_open, style
from geomcad.sheet.text import box, parse

#: Ticks are spaced at least this far apart on the paper (mm).
#: The diagrams' words, per language.
WORDS = Words(__package__, "graph")
TICK_MIN_MM = 8.0
TICK_LEN = 1.5
#: Tick values along the x axis keep at least this gap between them (mm).
TICK_GAP_MM = 1.0
ARROW_OVER = 7.0  # the axis runs this far past the last value (mm), ending in an arrow
HATCH_STEP_MM = 2.0
#: The most decimals a tick's value is written with.
TICK_PLACES = 6
#: An axis whose tick step needs more decimals than this writes its values times a power of
#: ten, named by the axis (``J_пр·10^6, кг·м²``: 2, 4, 6 where 0,000002, 0,000004 …).
FACTOR_PLACES = 4


def nice_step(raw: float) -> float:
    """The smallest 1, 2, 2.5, 4 or 5 × 10^n that is ≥ ``raw`` (> 0)."""
    e = math.floor(math.log10(raw))
    for exp in (e, e + 1):
        for m in NICE:
            step = m * 10.0**exp
            if step >= raw * (1.0 - tol.DERIVED):
                return step
    return 10.0 ** (e + 2)


def nice_steps(raw: float, n: int) -> list[float]:
    """The ``n`` finest nice factors from :func:`nice_step` of ``raw`` up, each the next step of
    the series (its steps lie at least 1.25 apart, so 1.001 × a step is past it): the choices a
    curve's factor is tried at together with others' (stacked diagrams)."""
    ks = [nice_step(raw)]
    while len(ks) < n:
        ks.append(nice_step(ks[-1] * 1.001))
    return ks


def nice_step_below(raw: float) -> float:
    """The largest 1, 2, 2.5, 4 or 5 × 10^n that is ≤ ``raw`` (> 0): the coarsest factor that
    still draws ``raw`` units at least 1 mm (a curve's span at least its least height)."""
    return nice_below(raw, 1.0).k


def exact_places(step: float) -> int:
    """The decimals that write ``step`` (> 0) exactly, at most :data:`TICK_PLACES`."""
    return next(
        (d for d in range(TICK_PLACES) if abs(step - round(step, d)) <= tol.DERIVED * step),
        TICK_PLACES,
    )


def thousands_power(x: float) -> int:
    """The least multiple n of 3 with 10^n · ``x`` ≥ 1 (``x`` > 0): a small value written
    times 10^n (2,5·10⁻⁵ → 6, 25)."""
    return 3 * math.ceil(-math.log10(x) / 3.0 - tol.DERIVED)


@dataclass(frozen=True)
class Axis:
    """One axis of a diagram.

    ``symbol`` is label markup (``φ``, ``S``, ``J_{пр}``), ``unit`` the unit's text (``рад``,
    ``м``), ``name`` the factor's subscript (μ_name), ``lo``…``hi`` the values shown (lo ≤ 0 ≤ hi
    is not required: the axis line sits at 0 when 0 is in range, else at ``lo``) and ``k`` the
    factor in units per mm. ``tick`` fixes the tick step (e.g. 30 for degrees); 0 chooses a nice
    step at least :data:`TICK_MIN_MM` apart.
    """

    symbol: str
    unit: str
    lo: float
    hi: float
    k: float
    name: str = ""
    tick: float = 0.0

    @classmethod
    def fit(
        cls, symbol: str, unit: str, lo: float, hi: float, room_mm: float, name: str = ""
    ) -> Axis:
        """The axis whose nice factor puts ``lo``…``hi`` into ``room_mm`` millimetres.

        A range with no extent (all values equal) is shown as ±|value| (or ±1 when zero), so a
        constant quantity still gets a readable axis.
        """
        for what, x in (("lo", lo), ("hi", hi), ("room", room_mm)):
            if not math.isfinite(x):
                raise ParameterError(f"axis {symbol} {what}", x, "must be finite")
        if room_mm <= 0.0:
            raise ParameterError(f"axis {symbol} room", room_mm, "must be positive")
        lo, hi = min(lo, hi), max(lo, hi)
        if hi - lo <= 0.0:
            m = abs(hi) or 1.0
            lo, hi = -m, m
        return cls(symbol, unit, lo, hi, nice_step((hi - lo) / room_mm), name or symbol)

    @property
    def zero(self) -> float:
        """The value at which the other axis crosses this one."""
        return 0.0 if self.lo <= 0.0 <= self.hi else self.lo

    def mm(self, value: float) -> float:
        return value / self.k

    def with_tick(self, step: float) -> Axis:
        """The same axis with ticks every ``step`` units (> 0)."""
        if not (math.isfinite(step) and step > 0.0):
            raise ParameterError(f"axis {self.symbol} tick", step, "must be positive")
        return dataclasses.replace(self, tick=step)

    def ticks(self) -> list[float]:
        """Tick values: every ``tick`` units, or a nice step at least :data:`TICK_MIN_MM` apart;
        always through zero."""
        step = self.tick or nice_step(TICK_MIN_MM * self.k)
        first = math.ceil(self.lo / step - tol.DERIVED)
        last = math.floor(self.hi / step + tol.DERIVED)
        return [i * step for i in range(first, last + 1)]

    def places(self) -> int:
        """The decimals of every value written along the axis: those that write its tick step
        exactly (0,016 and 0,020, never 0,02 beside 0,016; 14,0 beside 14,1), at most
        :data:`TICK_PLACES`."""
        return exact_places(self.tick or nice_step(TICK_MIN_MM * self.k))

    def power(self) -> int:
        """The power of ten n the values along the axis are written times (10^n · value), a
        multiple of 3; 0 where the tick step needs at most :data:`FACTOR_PLACES` decimals."""
        step = self.tick or nice_step(TICK_MIN_MM * self.k)
        return 0 if self.places() <= FACTOR_PLACES else thousands_power(step)

    def tick_text(self, value: float, lang: Lang | None = None) -> str:
        """A tick's value as the axis writes it: :meth:`places` decimals (zero as "0"), or
        times 10^:meth:`power` with the decimals that writes its step exactly."""
        step = self.tick or nice_step(TICK_MIN_MM * self.k)
        if abs(value) <= tol.DERIVED * step:
            return "0"
        n = self.power()
        return fmt_fixed(value * 10.0**n, exact_places(step * 10.0**n), lang)

    def caption(self) -> str:
        """The axis' name by its arrow: ``symbol, unit``, the symbol times 10^:meth:`power`
        where its values are written so."""
        n = self.power()
        return f"{self.symbol}·10^{{{n}}}, {self.unit}" if n else f"{self.symbol}, {self.unit}"

    def factor_text(self, lang: Lang | None = None) -> str:
        """``μ_φ = 0,02 рад/мм`` (``lang``: default the language being drawn)."""
        per = WORDS("per_mm", lang)
        return f"μ_{{{self.name}}} = {fmt_number(self.k, lang)} {self.unit}/{per}"


#: An axis broken by the origin (its values not starting at 0): the zigzag begins this far
#: (mm) from the origin, is this long along the axis and swings this far either side of it.
BREAK_AT = 2.0
BREAK_LEN = 4.0
BREAK_SWING = 1.5


def _zigzag(s: Sheet, at: XY, along: XY) -> None:
    """The break mark of an axis: from the origin ``at`` along the unit direction ``along``
    a straight piece, then a zigzag across the axis (GOST 2.319's break of a scale that does
    not start at zero); the axis's arrow starts where it ends."""
    ux, uy = along
    nx, ny = -uy, ux
    q = BREAK_LEN / 4.0

    def pt(t: float, side: float) -> XY:
        return (at[0] + ux * t + nx * side, at[1] + uy * t + ny * side)

    pts = (pt(0.0, 0.0), pt(BREAK_AT, 0.0), pt(BREAK_AT + q, BREAK_SWING),
           pt(BREAK_AT + 3.0 * q, -BREAK_SWING), pt(BREAK_AT + BREAK_LEN, 0.0))  # fmt: skip
    s.add(Polyline(pts, "vector"))


class Graph:
    """A diagram: the data point (x0, y0) = (x.zero, y.zero) lands on sheet point ``at``."""

    def __init__(self, drawing: Drawing, x: Axis, y: Axis, at: XY) -> None:
        self.d = drawing
        self.x, self.y = x, y
        self.at = at

    def p(self, x: float, y: float) -> XY:
        """A data point on the sheet (y up in the data, down on the paper)."""
        return (
            self.at[0] + self.x.mm(x - self.x.zero),
            self.at[1] - self.y.mm(y - self.y.zero),
        )

    @property
    def box(self) -> tuple[float, float, float, float]:
        """The sheet rectangle the data range covers (x0, y0, x1, y1), y down."""
        a = self.p(self.x.lo, self.y.hi)
        b = self.p(self.x.hi, self.y.lo)
        return (a[0], a[1], b[0], b[1])

    def axes(self, lang: Lang | None = None, tick_labels: bool = True, height: float = 2.5) -> None:
        """Both axes with arrows and ticks, the tick values where no curve reaches them, and the
        axes' symbols and units placed by the label placer next to the arrows.

        The values of the x axis are written under the plot's bottom edge and those of the y
        axis left of its left edge, so that no curve can cross them: where the zero axis runs
        inside the plot (values below or left of zero), the edge gets a thin line with the same
        ticks, the zero axis keeps its ticks unlabelled. A value that another line drawn on the
        sheet crosses (a marker of a position) is left out when the sheet is finished.
        """
        x0, y0, x1, y1 = self.box
        ax, ay = self.at
        s = self.d.sheet
        # an axis whose values do not start at 0 (ω1 about its mean) is broken by a zigzag by
        # the origin (review 14: ω1's axis began at 4,04 with nothing to say so); no tick by it
        x_break, y_break = (not (a.lo <= 0.0 <= a.hi) for a in (self.x, self.y))
        cut = BREAK_AT + BREAK_LEN
        if x_break:
            _zigzag(s, (ax, ay), (1.0, 0.0))
        if y_break:
            _zigzag(s, (ax, ay), (0.0, -1.0))
        _arrow(s, (x0 - 2.0 if x0 < ax else ax + (cut if x_break else 0.0), ay),
               (x1 + ARROW_OVER, ay), "vector")  # fmt: skip
        _arrow(s, (ax, y1 + 2.0 if y1 > ay else ay - (cut if y_break else 0.0)),
               (ax, y0 - ARROW_OVER), "vector")  # fmt: skip
        # the rows of values: at the bottom and left edges (the zero axes when they are there)
        bottom = max(ay, y1)
        left = min(ax, x0)
        if bottom > ay + tol.DERIVED:
            s.add(Polyline(((x0, bottom), (x1, bottom)), "dimension"))
        if left < ax - tol.DERIVED:
            s.add(Polyline(((left, y0), (left, y1)), "dimension"))
        right_of_last = -math.inf  # the right edge of the last x value written
        for v in self.x.ticks():
            px, _ = self.p(v, self.y.zero)
            if x_break and px < ax + cut + TICK_GAP_MM:
                continue
            for yy in (ay,) if bottom == ay else (ay, bottom):
                s.add(Polyline(((px, yy), (px, yy + TICK_LEN)), "dimension"))
            text = self.x.tick_text(v, lang)
            half = box(parse(text), height)[0] / 2.0
            # a value that would run into the one before it is left out (its tick stays), and
            # so is zero (the origin, or the other axis runs through it)
            if tick_labels and v != self.x.zero and px - half >= right_of_last + TICK_GAP_MM:
                at = (px, bottom + TICK_LEN + height + 0.8)
                self.d.optional.append(self.d.text(text, at, height, anchor="centre"))
                right_of_last = px + half
        for v in self.y.ticks():
            _, py = self.p(self.x.zero, v)
            if y_break and py > ay - cut - TICK_GAP_MM:
                continue
            for xx in (ax,) if left == ax else (ax, left):
                s.add(Polyline(((xx - TICK_LEN, py), (xx, py)), "dimension"))
            # zero too where the x values stand on an edge of their own (ΔT's 0 on
            # Wittenbauer's diagram, its I_пр axis running through the plot)
            if tick_labels and (v != self.y.zero or bottom > ay + tol.DERIVED):
                at = (left - TICK_LEN - 0.8, py + height / 2.0)
                self.d.optional.append(
                    self.d.text(self.y.tick_text(v, lang), at, height, anchor="right")
                )
        # the symbols by the arrows' tips, placed clear of the curves drawn before the sheet is
        # finished
        self.d.label((x1 + ARROW_OVER, ay), self.x.caption(), 3.5,
                     prefer=(-1.0, 1.0), clear=0.5)  # fmt: skip
        self.d.label((ax, y0 - ARROW_OVER), self.y.caption(), 3.5,
                     prefer=(1.0, 0.3), clear=1.0)  # fmt: skip

    def factors(self, at: XY, lang: Lang | None = None, height: float = 2.5) -> None:
        """Both scale factors as one line of text with its baseline at ``at``."""
        self.d.text(f"{self.x.factor_text(lang)};  {self.y.factor_text(lang)}", at, height)

    def curve(self, xs: npt.ArrayLike, ys: npt.ArrayLike, role: str = "result") -> None:
        """A polyline through the data points; non-finite points are a programming error."""
        xa, ya = np.asarray(xs, dtype=np.float64), np.asarray(ys, dtype=np.float64)
        pts = tuple(self.p(float(a), float(b)) for a, b in zip(xa, ya, strict=True))
        if not all(math.isfinite(c) for q in pts for c in q):
            raise ValueError("a curve point is not finite")
        length = sum(math.dist(a, b) for a, b in itertools.pairwise(pts))
        self.d.sheet.add(Polyline(pts, role, dash=fit_open(style(role).line, length)))

    def hatch(self, xs: npt.ArrayLike, ys: npt.ArrayLike, role: str = "construction") -> None:
        """Vertical hatching between the x axis and the curve (an area such as a work)."""
        xs, ys = np.asarray(xs, dtype=np.float64), np.asarray(ys, dtype=np.float64)
        x0, x1 = float(xs[0]), float(xs[-1])
        n = max(2, int(abs(self.x.mm(x1 - x0)) / HATCH_STEP_MM))
        for i in range(1, n):
            x = x0 + (x1 - x0) * i / n
            y = float(np.interp(x, xs, ys) if xs[0] < xs[-1] else np.interp(x, xs[::-1], ys[::-1]))
            self.d.sheet.add(Polyline((self.p(x, self.y.zero), self.p(x, y)), role))

    def point(
        self,
        x: float,
        y: float,
        markup: str = "",
        role: str = "point",
        prefer: tuple[float, float] | None = None,
        height: float = 2.5,
    ) -> None:
        """A marked data point with an optional placed label (``prefer``: a paper direction to
        try first, y down)."""
        q = self.p(x, y)
        self.d.sheet.add(CircleItem(q, DOT_R, role, fill=True))
        if markup:
            self.d.label(q, markup, height, prefer=prefer, clear=DOT_R)

    def span_y(self, x: float, y0: float, y1: float, markup: str = "", height: float = 2.5) -> None:
        """A dimension along the y axis at data x: a line from y0 to y1 with arrowheads at both
        ends and a placed label (a swing such as ΔT_max − ΔT_min)."""
        a, b = self.p(x, y0), self.p(x, y1)
        if a == b:
            return
        self.d.sheet.add(Polyline((a, b), "dimension"))
        up = 1.0 if b[1] < a[1] else -1.0
        _head(self.d.sheet, b, (0.0, -up), "dimension")
        _head(self.d.sheet, a, (0.0, up), "dimension")
        if markup:
            mid = (a[0], (a[1] + b[1]) / 2.0)
            self.d.label(mid, markup, height, prefer=(1.0, 0.0), clear=0.5)

    def ordinate(
        self,
        x: float,
        y: float,
        markup: str = "",
        role: str = "construction",
        height: float = 2.5,
    ) -> None:
        """The ordinate of a data point: a thin line from the x axis to (x, y), and an optional
        label (a division point's number) placed by the point, above it where there is room."""
        foot = self.p(x, self.y.zero)
        top = self.p(x, y)
        if math.dist(foot, top) > 0.0:
            self.d.sheet.add(Polyline((foot, top), role))
        if markup:
            up = -1.0 if y >= self.y.zero else 1.0
            self.d.label(top, markup, height, prefer=(0.0, up), clear=DOT_R)
