"""Composing a sheet: views packed into the field by general rules, each at the largest scale of
its series that fits (issue 14: no hand-placed view positions).

A sheet is a tree of :class:`Row`, :class:`Column` and :class:`Grid` nodes whose leaves are
views (:class:`View`; the views that draw themselves from the model are in
:mod:`geomcad.sheet.views`). A view is one of three kinds:

- **scaled** — it has a natural extent in model units (:meth:`View.extent`: metres for a
  mechanism, m/s for a velocity plan, N for a force polygon) and is drawn through one
  :class:`~geomcad.sheet.drawing.Viewport` at one scale: the largest of its series that fits its
  box. The series are GOST 2.302's ratios for lengths (``"gost"``: k_l = 0.0025 m/mm is 1:2.5),
  or the factors 1, 2, 2.5, 4, 5 × 10^n (``"nice"``: plans, forces). Views with the same
  ``group`` share one scale (every velocity plan of a sheet one μ_V): the coarsest their boxes
  need;
- **fixed** — it has a natural size in mm (:meth:`View.natural`: a table, a block of text) and
  keeps it;
- **stretch** — it fills whatever box it gets, at least its minimum and best its preferred size
  (:meth:`View.stretch`: a diagram, whose two axes take their own factors).

:func:`arrange` packs the tree into the field — the frame less the title block and графа 26 —
and :func:`compose` also draws it: each view's title with its μ on its box's top edge, then the
view through its :class:`Placed` (box, inner box, scale, viewport). Where the tree leaves the
split of a row or a column open (``weights=None``), the split is chosen by a small search that
maximises first the smallest *fill* of the flexible views (the share of its box a view's drawing
covers: no view at a small scale beside a large empty area), then the share of the field used.
Fixed views get exactly their natural length along a split; the rest is shared. A box that runs
into the title block or графа 26 is cut back to the larger of its parts clear of them.

>>> from geomcad.sheet.frame import TitleBlock
>>> from geomcad.sheet import start
>>> d = start("A3", TitleBlock("t", "d"))
>>> a = Figure((0.0, 0.0, 0.4, 0.2), lambda v: None, title="A")
>>> b = Figure((0.0, 0.0, 0.1, 0.3), lambda v: None, title="B")
>>> lay = compose(d, Row(a, b))
>>> lay[a].scale.ratio_text(), lay[b].scale.ratio_text()
('1:2', '1:2')
"""

from __future__ import annotations

import bisect
import functools
import gc
import itertools
import math
import operator
import typing
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Literal

from geomcad import tol
from geomcad.errors import ParameterError
from geomcad.sheet.drawing import Drawing, Viewport
from geomcad.sheet.frame import Frame
from geomcad.sheet.lang import current
from geomcad.sheet.scale import GOST_RATIOS, NICE, PLAN_NICE, Quantity, Scale, ScaleStyle
from geomcad.sheet.scale import WORDS as SCALE_WORDS
from geomcad.sheet.text import balanced, break_points, parse
from geomcad.sheet.text import box as text_box

#: A rectangle on the sheet: x0, y0 (top), x1, y1 (bottom), mm.
Box = tuple[float, float, float, float]
#: A model rectangle: x0, y0, x1, y1 in model units, y up.
Extent = tuple[float, float, float, float]
#: The scale series of a scaled view.
Series = Literal["gost", "nice", "plan", "free"]
Kind = Literal["scaled", "fixed", "stretch"]

#: The gap between neighbouring boxes (mm).
GAP = 4.0
#: The margin kept between the field and the frame (mm).
FIELD_MARGIN = 3.0
#: A title line's room: its cap height times this, plus :data:`TITLE_GAP`.
TITLE_LEAD = 1.5
TITLE_GAP = 1.5
#: A title wider than its box is broken into lines (at most this many) this many cap heights
#: apart (GOST 2.304, type B: 17/10 h); their room counts in the layout.
TITLE_SPACING = 1.7
TITLE_LINES = 3
#: What a vector shorter than two arrowheads costs the search, against log(drawn area): a view
#: drawn 1.4 times larger (twice the area) is worth about two more short vectors.
SHORT_COST = 0.35
#: The search's score lost per millimetre of room a view lacks for the scale a rule asks of it
#: (its ``most_k``): a view drawn at half its area costs 1.4 at weight 2, a rule 10 mm short 10.
RULE_COST = 100.0
#: A content narrower than this share of its larger side counts as this wide (a plan along a
#: line still needs room for its labels).
THIN = 0.15


#: The GOST 2.302 ratios as length factors k (m/mm), smallest first.
_GOST_K = tuple(sorted(float(Fraction(1, 1000) / g) for g in GOST_RATIOS))


@functools.lru_cache(maxsize=4096)
def round_scale(raw: float, q: Quantity, series: Series) -> Scale:
    """The smallest factor of ``series`` that is at least ``raw`` (model units per mm): the
    largest drawing of the series that fits.

    ``"gost"`` takes GOST 2.302's ratios (for lengths; ``raw`` in m/mm); ``"nice"`` the
    mantissas 1, 2, 2.5, 4, 5; ``"plan"`` 1, 2, 5; ``"free"`` (a drawing not to scale, whose
    scale is not written) ``raw`` itself, to two significant digits.
    """
    if not (0.0 < raw < math.inf):
        raise ParameterError(f"k_{q}", raw, "a scale factor must be finite and positive")
    if series == "free":
        e = math.floor(math.log10(raw)) - 1
        return Scale(math.ceil(raw / 10.0**e * (1 - tol.REL_LENGTH)) * 10.0**e, q)
    if series == "gost":
        # k = 1/1000 m per mm of a ratio r: the smallest k ≥ raw is the largest r ≤ 1/(1000 raw)
        for k in _GOST_K:
            if k >= raw * (1 - tol.REL_LENGTH):
                return Scale(k, q)
        raise ParameterError(f"k_{q}", raw, "too large for the sheet even at 1:500")
    mantissas = NICE if series == "nice" else PLAN_NICE
    e = math.floor(math.log10(raw))
    for exp in (e - 1, e, e + 1):
        for m in mantissas:
            k = m * 10.0**exp
            if k >= raw * (1 - tol.REL_LENGTH):
                return Scale(k, q)
    return Scale(10.0 ** (e + 2), q)  # pragma: no cover - 10^(e+1) ≥ raw always


def round_scale_down(raw: float, q: Quantity, series: Series) -> Scale:
    """The largest factor of ``series`` that is at most ``raw`` (model units per mm): the
    smallest drawing of the series that still keeps a length a rule asks for (a crank 30 mm
    long at k = l/30). ``"free"`` gives ``raw`` itself."""
    up = round_scale(raw, q, series)
    if series == "free" or up.k <= raw * (1 + tol.REL_LENGTH):
        return up
    # the series' steps are at most 2.5 apart (5 → 10, 1:2.5 → 1:5 … 1:40 → 1:100 at most)
    k = round_scale(up.k / 2.6, q, series).k
    while True:
        nxt = round_scale(k * (1 + 2 * tol.REL_LENGTH), q, series).k
        if nxt > raw * (1 + tol.REL_LENGTH):
            return Scale(k, q)
        k = nxt


# --- views --------------------------------------------------------------------------------------


class View:
    """Something the layout places (see the module's docstring).

    Subclasses override :meth:`extent` (scaled), :meth:`natural` (fixed) or :meth:`stretch`
    (stretch), and :meth:`draw`. ``title`` is label markup drawn on the box's top edge, followed
    by the scale's label unless ``show_scale`` is False (a view of a titled :class:`Grid` shows
    the common scale in the grid's title instead). ``group`` names a scale group (views of one
    group share one scale); ``quantity`` and ``series`` say what the scale measures and how it
    is rounded. ``margin`` (mm) is kept clear round the drawing for its labels and symbols;
    ``readable`` (model units) is the shortest length that must be read on the drawing (a
    vector), drawn at least ``readable_mm`` long when the field allows it. ``weight`` is the
    view's share in the search for the splits (a view of weight 2 counts as two). ``least_k``
    (model units per mm): the scale is never finer than this (a scale the task fixes).
    ``most_k`` (model units per mm, 0: none): a scale a rule asks for at least (a crank 30 mm
    long): where the cell is too small to draw the view at it, each millimetre missing costs
    :data:`RULE_COST` of the search's score (a measure the search can follow split by split,
    where the rounded scale moves in steps; what must fit still comes first).
    """

    def __init__(
        self,
        *,
        title: str = "",
        group: str = "",
        quantity: Quantity = "l",
        series: Series = "gost",
        margin: float = 4.0,
        title_height: float = 3.5,
        show_scale: bool = True,
        readable: float = 0.0,
        readable_mm: float = 7.0,
        weight: float = 1.0,
        least_k: float = 0.0,
        most_k: float = 0.0,
    ) -> None:
        self.title = title
        self.group = group
        self.quantity: Quantity = quantity
        self.series: Series = series
        self.margin = margin
        self.title_height = title_height
        self.show_scale = show_scale
        self.readable = readable
        self.readable_mm = readable_mm
        self.weight = weight
        self.least_k = least_k
        self.most_k = most_k
        self._title_w: float | None = None
        #: the lines the title takes (more than one where it is wider than its box)
        self.title_lines = 1
        #: the lines its note under the caption takes in its box (:meth:`note_lines_in`)
        self.note_lines = 1
        self._memo: dict[object, Any] = {}

    def note_lines_in(self, width: float) -> int:
        """The lines a note under the caption takes in a box ``width`` mm wide (0: none; a
        force plan's line naming what its details cannot show is broken like a caption)."""
        return 0

    @property
    def kind(self) -> Kind:
        """scaled, fixed or stretch (see the module's docstring)."""
        if _ext(self) is not None:
            return "scaled"
        if _nat(self) is not None:
            return "fixed"
        return "stretch"

    def extent(self) -> Extent | None:
        """The model rectangle the view draws (scaled views), else None."""
        return None

    def natural(self) -> tuple[float, float] | None:
        """The size (mm) of a fixed view's drawing, else None."""
        return None

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """A stretch view's least and preferred (width, height) in mm."""
        return (40.0, 30.0), (120.0, 80.0)

    def lengths(self) -> Sequence[float]:
        """The model lengths of the vectors a scaled view draws (a plan's, a polygon's): the
        search counts those that would come out shorter than ``readable_mm`` (two arrowheads)
        and prefers a scale that leaves fewer of them."""
        return ()

    def used(self, w: float, h: float) -> tuple[float, float]:
        """The size (mm) a stretch view really draws in a room of w × h (its factors may be
        rounded): by default as much as it prefers."""
        pw, ph = self.stretch()[1]
        return min(w, pw), min(h, ph)

    def title_room(self) -> float:
        """The height (mm) of the title's lines above the drawing (0 without a title)."""
        return _title_room(self.title, self.title_height, self.title_lines)

    def caption(self, scale: Scale | None) -> str:
        """The title as drawn: the title, then the scale's label (and a length scale's GOST
        ratio), e.g. ``План скоростей, μ_V = 0,02 (м/с)/мм``."""
        if scale is None or not self.show_scale or not self.title:
            return self.title
        return f"{self.title}, {scale_text(scale)}"

    def draw(self, d: Drawing, at: Placed) -> None:
        """Draw the view into its place (the title is already drawn)."""


def scale_text(scale: Scale, style: ScaleStyle | None = None) -> str:
    """A scale's label as the title of a view shows it, in the language being drawn:
    ``μ_l = 0,0025 м/мм (М 1:2,5)`` (a Cyrillic М), ``μ_l = 0.0025 m/mm (1:2.5)``."""
    lang = current()
    text = scale.label(style or ScaleStyle(lang=lang))
    ratio = scale.ratio_text()
    if lang != "ru":
        ratio = ratio.replace(",", ".")
    # "(М 1:2,5)" with the Cyrillic М of «масштаб» (the Latin M prints the same but is
    # another letter); "(1:2.5)" in English
    return f"{text} ({SCALE_WORDS('ratio', ratio=ratio)})" if ratio else text


class Figure(View):
    """A scaled view drawn by a function: ``draw_fn(viewport)`` draws the model rectangle
    ``box`` (model units, y up) through the viewport the layout gives it. The general view for
    a construction no other view knows (a problem's own figure). Keywords as :class:`View`."""

    def __init__(self, box: Extent, draw_fn: Callable[[Viewport], None], **kw: Any) -> None:
        super().__init__(**kw)
        self.box = box
        self.draw_fn = draw_fn

    def extent(self) -> Extent | None:
        return self.box

    def draw(self, d: Drawing, at: Placed) -> None:
        assert at.viewport is not None
        self.draw_fn(at.viewport)


class Spacer(View):
    """A fixed empty box of ``size`` mm (room kept free)."""

    def __init__(self, size: tuple[float, float]) -> None:
        super().__init__(margin=0.0)
        self.size = size

    def natural(self) -> tuple[float, float] | None:
        return self.size


# --- the tree -----------------------------------------------------------------------------------


class Node:
    """A split of a box among its children (see :class:`Row`, :class:`Column`)."""

    def __init__(
        self,
        *items: View | Node,
        weights: Sequence[float] | None = None,
        gap: float = GAP,
        title: str = "",
        title_height: float = 5.0,
        group: str = "",
    ) -> None:
        if not items:
            raise ValueError(f"{type(self).__name__} needs at least one item")
        if weights is not None and (
            len(weights) != len(items) or any(not (w > 0.0) for w in weights)
        ):
            raise ValueError("weights: one positive weight per item")
        self.items = tuple(items)
        self.weights = tuple(weights) if weights is not None else None
        self.gap = gap
        self.title = title
        self.title_height = title_height
        #: The scale group whose scale the title shows (default: the first view's).
        self.group = group
        self._title_w: float | None = None
        #: the lines the title takes (more than one where it is wider than its box)
        self.title_lines = 1
        self._natural: tuple[float, float] | Literal[False] | None = False
        self._fixed: dict[bool, tuple[dict[int, float], list[int]]] = {}

    def views(self) -> Iterator[View]:
        for it in self.items:
            if isinstance(it, View):
                yield it
            else:
                yield from it.views()

    def title_room(self) -> float:
        return _title_room(self.title, self.title_height, self.title_lines)


class Row(Node):
    """Items side by side, left to right."""


class Column(Node):
    """Items one under another, top to bottom."""


class Grid(Node):
    """Alike items in equal cells, row by row, in the arrangement (columns × rows) that draws
    them the largest; ``cols`` fixes the number of columns. ``fitted`` (views of one scale
    group): each column as wide and each row as high as its largest drawing needs at their one
    scale, not equal cells (the velocity plans of a turn, long in one position and tall in
    another: review 8's rocking cylinder's twelve plans fitted no A2 in equal cells).
    ``rows_own`` (with ``fitted``): each row's cells as wide as that row's own drawings need,
    not as their columns' widest (review 10: tangent's plans 9 and 10, 161 and 143 mm wide at
    pa = 40 mm, widened two whole columns and the twelve fitted no A2)."""

    def __init__(
        self,
        *items: View | Node,
        cols: int | None = None,
        gap: float = GAP,
        title: str = "",
        title_height: float = 5.0,
        group: str = "",
        fitted: bool = False,
        rows_own: bool = False,
    ) -> None:
        super().__init__(*items, gap=gap, title=title, title_height=title_height, group=group)
        self.cols = cols
        self.fitted = fitted
        self.rows_own = rows_own


class Choice(Node):
    """Alternative arrangements of the same views: the layout takes the one that scores best
    (e.g. the plans beside the mechanism, or under it)."""

    def __init__(self, *items: View | Node) -> None:
        super().__init__(*items, gap=0.0)

    def views(self) -> Iterator[View]:
        seen: set[int] = set()
        for v in super().views():
            if id(v) not in seen:
                seen.add(id(v))
                yield v


Tree = View | Node


# --- the field ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class Field:
    """The rectangle views go in and the boxes inside it that belong to the form."""

    box: Box
    obstacles: tuple[Box, ...]

    @staticmethod
    def of(frame: Frame, margin: float = FIELD_MARGIN) -> Field:
        """The field of a frame: inside it by ``margin``, the title block and графа 26 kept
        free (with ``margin`` round them)."""
        from geomcad.sheet.frame import G26_HEIGHT, G26_WIDTH

        b = (frame.left + margin, frame.top + margin, frame.right - margin, frame.bottom - margin)
        tb = (frame.tb_left - margin, frame.tb_top - margin, frame.right, frame.bottom)
        right, below = frame.left + G26_WIDTH + margin, frame.top + G26_HEIGHT + margin
        g26 = (frame.left, frame.top, right, below)
        return Field(b, (tb, g26))

    @staticmethod
    def of_format(fmt: str, landscape: bool = True) -> Field:
        """The field of a sheet format (for scales computed without drawing)."""
        from geomcad.sheet.frame import LEFT_MARGIN, MARGIN, TB_HEIGHT, TB_WIDTH, paper

        w, h = paper(fmt, landscape)
        right, bottom = w - MARGIN, h - MARGIN
        return Field.of(
            Frame(LEFT_MARGIN, MARGIN, right, bottom, right - TB_WIDTH, bottom - TB_HEIGHT)
        )


# --- the result ---------------------------------------------------------------------------------


@dataclass
class Placed:
    """Where a view went: its ``box`` (sheet mm), the ``inner`` box its drawing is centred in
    (below the title, inside the margin), its ``scale`` and ``viewport`` (scaled views)."""

    view: View
    box: Box
    inner: Box
    scale: Scale | None = None
    viewport: Viewport | None = None

    @property
    def size(self) -> tuple[float, float]:
        return self.inner[2] - self.inner[0], self.inner[3] - self.inner[1]


@dataclass
class Layout:
    """The placed views of a sheet, by view; :meth:`scale` gives a group's scale."""

    placed: dict[int, Placed] = field(default_factory=dict)
    titles: list[tuple[Box, Node]] = field(default_factory=list)
    groups: dict[str, Scale] = field(default_factory=dict)
    #: the search's score of this arrangement: (−overflow in mm, Σ weight·log(drawn area))
    score: tuple[float, ...] = ()
    #: the lines of each title broken to its box (by id of the view or node), as laid out
    title_lines: dict[int, int] = field(default_factory=dict)

    @property
    def fits(self) -> bool:
        """True when nothing overflows: every fixed view and title fits its box, every stretch
        view has its least size and every ``readable`` length its millimetres."""
        return not self.score or self.score[0] >= 0.0

    def __getitem__(self, view: View) -> Placed:
        return self.placed[id(view)]

    def __iter__(self) -> Iterator[Placed]:
        return iter(self.placed.values())

    def scale(self, group: str) -> Scale:
        """The one scale of a scale group."""
        return self.groups[group]

    def fill(self) -> float:
        """The smallest fill of the flexible views (see the module's docstring)."""
        fills = _fills(self)
        return min(fills) if fills else 1.0


# --- the layout ---------------------------------------------------------------------------------


def _ext(v: View) -> Extent | None:
    """The view's extent, asked once."""
    if "ext" not in v._memo:
        v._memo["ext"] = v.extent()
    return v._memo["ext"]  # type: ignore[no-any-return]


def _nat(v: View) -> tuple[float, float] | None:
    """The view's natural size, asked once."""
    if "nat" not in v._memo:
        v._memo["nat"] = v.natural()
    return v._memo["nat"]  # type: ignore[no-any-return]


def _group(v: View) -> str:
    return v.group or f"#{id(v)}"


def _cut(cell: Box, obstacles: Sequence[Box]) -> list[Box]:
    """The parts of ``cell`` clear of the obstacles: for each obstacle it meets, the cell cut
    back on one side (the four ways); the cell itself when it meets none."""
    out = [cell]
    for o in obstacles:
        nxt: list[Box] = []
        for c in out:
            if not (c[0] < o[2] and o[0] < c[2] and c[1] < o[3] and o[1] < c[3]):
                nxt.append(c)
                continue
            for part in (
                (c[0], c[1], min(c[2], o[0]), c[3]),
                (max(c[0], o[2]), c[1], c[2], c[3]),
                (c[0], c[1], c[2], min(c[3], o[1])),
                (c[0], max(c[1], o[3]), c[2], c[3]),
            ):
                if part[2] - part[0] > 1.0 and part[3] - part[1] > 1.0:
                    nxt.append(part)
        out = nxt or [(cell[0], cell[1], cell[0], cell[1])]
    return out


def _room(v: View, cell: Box) -> tuple[float, float]:
    """The room (mm) a view's drawing has in ``cell``."""
    w = cell[2] - cell[0] - 2.0 * v.margin
    h = cell[3] - cell[1] - v.title_room() - 2.0 * v.margin
    return w, h


def _content(ext: Extent) -> tuple[float, float]:
    w, h = ext[2] - ext[0], ext[3] - ext[1]
    big = max(w, h)
    if big <= 0.0:
        return 0.0, 0.0
    return max(w, THIN * big), max(h, THIN * big)


def _raw_k(v: View, cell: Box) -> float:
    """The continuous scale at which the view's extent just fits the cell (inf: no room), never
    finer than the view's ``least_k``."""
    ext = _ext(v)
    assert ext is not None
    w, h = _room(v, cell)
    cw, ch = ext[2] - ext[0], ext[3] - ext[1]
    if w <= 1.0 or h <= 1.0:
        return math.inf
    need = max(cw / w, ch / h, v.least_k)
    return need if need > 0.0 else 0.0


#: A laid-out subtree: its views with their leaves, in the order of the tree, and its titled
#: nodes' boxes. The search joins its subtrees' parts (tuples: a memoised part is shared).
_Part = tuple[tuple[tuple["View", "_Leaf"], ...], tuple[tuple[Box, "Node"], ...]]


def _place(v: View, cell: Box, obstacles: tuple[Box, ...]) -> _Leaf:
    """The view's leaf in ``cell``: the part of the cell clear of the obstacles where it does
    best (computed once per view and cell)."""
    return _Info(v, obstacles).place(cell)


class _Info:
    """What the search needs of a view that no cell changes (asked once per search), and the
    view's leaves on this field (by cell, kept on the view: another search of the same field
    finds them)."""

    __slots__ = (
        "content",
        "ext_h",
        "ext_w",
        "group",
        "kind",
        "least",
        "least_k",
        "leaves",
        "lengths",
        "margin",
        "most_k",
        "nat",
        "obst",
        "prefer",
        "sized",
        "spacer",
        "title_room",
        "title_w",
        "view",
    )

    def __init__(self, v: View, obstacles: tuple[Box, ...]) -> None:
        self.view = v
        self.kind = kind = v.kind
        self.group = _group(v)
        self.title_w = _title_width(v)
        self.title_room = v.title_room()
        self.margin = v.margin
        self.nat = _nat(v)
        self.spacer = isinstance(v, Spacer)
        self.least, self.prefer = v.stretch() if kind == "stretch" else ((0.0, 0.0), (0.0, 0.0))
        ext = _ext(v)
        self.ext_w, self.ext_h = (ext[2] - ext[0], ext[3] - ext[1]) if ext else (0.0, 0.0)
        self.least_k = v.least_k
        self.most_k = v.most_k
        self.content = _content(ext) if ext is not None and kind == "scaled" else (0.0, 0.0)
        lengths = v._memo.get("lengths")
        if lengths is None:
            lengths = v._memo["lengths"] = tuple(sorted(v.lengths())) if kind == "scaled" else ()
        self.lengths: tuple[float, ...] = lengths
        self.obst = obstacles
        self.leaves: dict[Box, _Leaf] = v._memo.setdefault(("leaves", obstacles), {})
        self.sized: dict[tuple[float, float], tuple[float, float, float]]
        self.sized = v._memo.setdefault("sized", {})

    def place(self, cell: Box) -> _Leaf:
        """The leaf in ``cell`` (see :func:`_place`)."""
        leaf = self.leaves.get(cell)
        if leaf is None:
            x0, y0, x1, y1 = cell
            for o in self.obst:
                if x0 < o[2] and o[0] < x1 and y0 < o[3] and o[1] < y1:
                    break
            else:  # clear of the form's boxes: the cell itself (as _cut gives it)
                leaf = self.leaves[cell] = self.leaf(cell)
                return leaf
            parts = _cut(cell, self.obst)
            best = (
                parts[0]
                if len(parts) == 1
                else max(
                    parts,
                    key=lambda c: (round(self.score(c), 9), (c[2] - c[0]) * (c[3] - c[1])),
                )
            )
            leaf = self.leaves[cell] = self.leaf(best)
        return leaf

    def leaf(self, cell: Box) -> _Leaf:
        """The view's leaf in exactly ``cell``: what it needs depends on the cell's size only
        (asked once per size)."""
        size = (cell[2] - cell[0], cell[3] - cell[1])
        known = self.sized.get(size)
        if known is None:
            known = self.sized[size] = self.needs(*size)
        bad, raw_k, area = known
        return _Leaf(cell, self.kind, self.group, bad, raw_k, self.content, area, self.lengths)

    def needs(self, width: float, height: float) -> tuple[float, float, float]:
        """The overflow, the raw scale and the drawn area (stretch) of the view in a cell of
        ``width`` × ``height`` (the arithmetic of :func:`_room`, :func:`_raw_k`,
        :func:`_stretch_fill`)."""
        kind = self.kind
        bad = max(0.0, self.title_w - width)
        w = width - 2.0 * self.margin
        h = height - self.title_room - 2.0 * self.margin
        raw_k, area = 0.0, 0.0
        if kind == "fixed":
            # (a spacer keeps room free of views: the form's boxes may fill it)
            if not self.spacer:
                nat = self.nat
                assert nat is not None
                bad += max(0.0, nat[0] - w) + max(0.0, nat[1] - h)
        elif kind == "stretch":
            lw, lh = self.least
            # a stretch view narrower or lower than its least is as bad as a fixed one
            bad += max(0.0, lw - w) + max(0.0, lh - h)
            if self.fill(w, h) > 0.0:
                uw, uh = self.view.used(w, h)
                area = max(uw, 0.0) * max(uh, 0.0)
        else:
            raw_k = self.raw_k(w, h)
            if self.most_k > 0.0:  # the room the rule's scale needs, as a negative area
                k = self.most_k
                area = -(max(0.0, self.ext_w / k - w) + max(0.0, self.ext_h / k - h))
        return bad, raw_k, area

    def room(self, cell: Box) -> tuple[float, float]:
        """:func:`_room`."""
        return (
            cell[2] - cell[0] - 2.0 * self.margin,
            cell[3] - cell[1] - self.title_room - 2.0 * self.margin,
        )

    def raw_k(self, w: float, h: float) -> float:
        """:func:`_raw_k` in a room of w × h."""
        if w <= 1.0 or h <= 1.0:
            return math.inf
        need = max(self.ext_w / w, self.ext_h / h, self.least_k)
        return need if need > 0.0 else 0.0

    def fill(self, w: float, h: float) -> float:
        """:func:`_stretch_fill` in a room of w × h."""
        lw, lh = self.least
        pw, ph = self.prefer
        if w < lw or h < lh:
            return -1.0 + min(w / lw, h / lh) * 0.5
        return min(1.0, w / pw) * min(1.0, h / ph)

    def score(self, cell: Box) -> float:
        """:func:`_leaf_score`."""
        kind = self.kind
        w, h = self.room(cell)
        if kind == "fixed":
            nat = self.nat
            assert nat is not None
            fits = nat[0] <= w + tol.SHEET_MM and nat[1] <= h + tol.SHEET_MM
            return (1.0 if fits else -1.0) * (cell[2] - cell[0]) * (cell[3] - cell[1])
        if kind == "stretch":
            return self.fill(w, h)
        k = self.raw_k(w, h)
        if k == 0.0:
            return 1.0
        if not math.isfinite(k):
            return -1.0
        return 1.0 / k


class _Eval:
    """One candidate layout: its views' leaves (cells, scales' needs) and titled boxes, by
    view."""

    def __init__(self, part: _Part) -> None:
        self.items, titles = part
        self.titles = list(titles)
        self.views: dict[int, View] = {id(v): v for v, _ in self.items}
        self.leaves: dict[int, _Leaf] = {id(v): leaf for v, leaf in self.items}
        self.cells: dict[int, Box] = {id(v): leaf.cell for v, leaf in self.items}


class _Leaf:
    """What the search needs of a view in a cell, computed once per cell."""

    __slots__ = ("area", "bad", "cell", "content", "group", "kind", "lengths", "raw_k")

    def __init__(
        self,
        cell: Box,
        kind: Kind,
        group: str,
        bad: float,
        raw_k: float,
        content: tuple[float, float],
        area: float,
        lengths: tuple[float, ...] = (),
    ) -> None:
        self.cell = cell
        self.kind = kind
        self.group = group
        self.bad = bad  # mm a fixed view or a title overflows its cell
        self.raw_k = raw_k  # scaled: the continuous scale that fits
        self.content = content  # scaled: the content's model size (thin ones widened)
        # stretch: the area it really draws (mm²); scaled: less the room (mm) it lacks for its
        # most_k (a rule's scale)
        self.area = area
        self.lengths = lengths  # scaled: its vectors' lengths, sorted


def _leaf_score(v: View, cell: Box) -> float:
    """How well a view alone does in a cell (for choosing where a cut cell goes)."""
    kind = v.kind
    if kind == "fixed":
        nat = _nat(v)
        assert nat is not None
        w, h = _room(v, cell)
        fits = nat[0] <= w + tol.SHEET_MM and nat[1] <= h + tol.SHEET_MM
        return (1.0 if fits else -1.0) * (cell[2] - cell[0]) * (cell[3] - cell[1])
    if kind == "stretch":
        return _stretch_fill(v, cell)
    k = _raw_k(v, cell)
    if k == 0.0:
        return 1.0
    if not math.isfinite(k):
        return -1.0
    return 1.0 / k


def _stretch_fill(v: View, cell: Box) -> float:
    (lw, lh), (pw, ph) = v.stretch()
    w, h = _room(v, cell)
    if w < lw or h < lh:
        return -1.0 + min(w / lw, h / lh) * 0.5
    return min(1.0, w / pw) * min(1.0, h / ph)


def natural_of(t: Tree) -> tuple[float, float] | None:
    """The natural size (mm, margins and titles included) of a tree made of fixed views only,
    else None."""
    if isinstance(t, View):
        nat = _nat(t)
        if nat is None:
            return None
        return max(nat[0] + 2 * t.margin, _title_width(t)), nat[1] + 2 * t.margin + t.title_room()
    if t._natural is not False:
        return t._natural
    t._natural = _natural_node(t)
    return t._natural


def _natural_node(t: Node) -> tuple[float, float] | None:
    sizes = [natural_of(it) for it in t.items]
    if any(sz is None for sz in sizes):
        return None
    ws = [sz[0] for sz in sizes if sz is not None]
    hs = [sz[1] for sz in sizes if sz is not None]
    gaps = t.gap * (len(sizes) - 1)
    if isinstance(t, Row):
        return sum(ws) + gaps, max(hs) + t.title_room()
    if isinstance(t, Column):
        return max(ws), sum(hs) + gaps + t.title_room()
    return None  # a grid of fixed views shares its box


def _fixed(node: Node, horizontal: bool) -> tuple[dict[int, float], list[int]]:
    """The natural lengths along the split of a node's fixed children, by index, and the
    indices of the others (asked once per node)."""
    known = node._fixed.get(horizontal)
    if known is None:
        fixed: dict[int, float] = {}
        for i, it in enumerate(node.items):
            nat = natural_of(it)
            if nat is not None:
                fixed[i] = nat[0] if horizontal else nat[1]
        flex = [i for i in range(len(node.items)) if i not in fixed]
        known = node._fixed[horizontal] = (fixed, flex)
    return known


def _split(
    node: Node, box: Box, weights: Sequence[float], horizontal: bool
) -> list[tuple[Tree, Box]]:
    """The node's children's boxes: fixed children their natural length, the rest shared by
    ``weights``."""
    x0, y0, x1, y1 = box
    y0 += node.title_room()
    length = (x1 - x0) if horizontal else (y1 - y0)
    n = len(node.items)
    free = length - node.gap * (n - 1)
    fixed, flex = _fixed(node, horizontal)
    share = free - sum(fixed.values())
    total_w = sum(weights[i] for i in flex) or 1.0
    out = []
    pos = x0 if horizontal else y0
    for i, it in enumerate(node.items):
        ln = fixed[i] if i in fixed else max(share, 0.0) * weights[i] / total_w
        # fixed children that overrun the box are cut back at its end (and count as not
        # fitting), not laid past it
        end = min(pos + ln, x1 if horizontal else y1)
        cell = (pos, y0, end, y1) if horizontal else (x0, pos, x1, end)
        out.append((it, cell))
        pos += ln + node.gap
    return out


def _grid_cells(node: Grid, box: Box, cols: int) -> list[tuple[Tree, Box]]:
    x0, y0, x1, y1 = box
    y0 += node.title_room()
    n = len(node.items)
    rows = math.ceil(n / cols)
    ws = [(x1 - x0 - node.gap * (cols - 1)) / cols] * cols
    hs = [(y1 - y0 - node.gap * (rows - 1)) / rows] * rows
    fitted = _fitted_lengths(node, cols, x1 - x0, y1 - y0) if node.fitted else None
    if fitted is not None:
        ws, hs = fitted
    ys = [y0 + sum(hs[:r]) + r * node.gap for r in range(rows)]
    if fitted is not None and node.rows_own:
        out: list[tuple[Tree, Box]] = []
        for r in range(rows):
            row = list(range(r * cols, min(n, (r + 1) * cols)))
            own = _fitted_lengths(node, len(row), x1 - x0, y1 - y0, row)
            rws = own[0] if own is not None else ws[: len(row)]
            xr = x0
            for i, w in zip(row, rws, strict=True):
                out.append((node.items[i], (xr, ys[r], xr + w, ys[r] + hs[r])))
                xr += w + node.gap
        return out
    xs = [x0 + sum(ws[:c]) + c * node.gap for c in range(cols)]
    return [
        (
            it,
            (
                xs[i % cols],
                ys[i // cols],
                xs[i % cols] + ws[i % cols],
                ys[i // cols] + hs[i // cols],
            ),
        )
        for i, it in enumerate(node.items)
    ]


def _fitted_lengths(
    node: Grid, cols: int, width: float, height: float, only: Sequence[int] | None = None
) -> tuple[list[float], list[float]] | None:
    """A fitted grid's column widths and row heights (mm) in ``width`` × ``height``: each
    column's (row's) margins and titles, and a share of the rest in proportion to its largest
    drawing's model width (height), so that one scale draws every cell's drawing to its
    column's or row's limit; None (equal cells) where an item is no view with an extent or the
    fixed parts leave no room. ``only``: of these items alone (one row of a ``rows_own``
    grid)."""
    items = node.items if only is None else [node.items[i] for i in only]
    n = len(items)
    rows = math.ceil(n / cols)
    sizes = []
    for it in items:
        ext = _ext(it) if isinstance(it, View) else None
        if ext is None or not isinstance(it, View):
            return None
        sizes.append(
            (ext[2] - ext[0], ext[3] - ext[1], 2.0 * it.margin, 2.0 * it.margin + it.title_room())
        )
    cw = [max(sizes[i][0] for i in range(c, n, cols)) for c in range(cols)]
    cf = [max(sizes[i][2] for i in range(c, n, cols)) for c in range(cols)]
    rh = [max(sizes[i][1] for i in range(r * cols, min(n, (r + 1) * cols))) for r in range(rows)]
    rf = [max(sizes[i][3] for i in range(r * cols, min(n, (r + 1) * cols))) for r in range(rows)]
    free_w = width - node.gap * (cols - 1) - sum(cf)
    free_h = height - node.gap * (rows - 1) - sum(rf)
    if free_w <= 0.0 or free_h <= 0.0 or sum(cw) <= 0.0 or sum(rh) <= 0.0:
        return None
    return (
        [f + free_w * w / sum(cw) for f, w in zip(cf, cw, strict=True)],
        [f + free_h * h / sum(rh) for f, h in zip(rf, rh, strict=True)],
    )


def _getter(ids: Sequence[int]) -> Callable[[Mapping[int, object]], object]:
    """A function giving the tuple of a mapping's values at ``ids``."""
    if not ids:
        return lambda m: ()
    if len(ids) == 1:
        one = ids[0]
        return lambda m: (m[one],)
    return operator.itemgetter(*ids)


class _Beaten(Exception):
    """A layout's overflow so far is already past the best one's (:meth:`_Solver.evaluate`)."""


#: A layout laid out so far whose leaves overflow by this much (mm) more than the best one's
#: total overflow loses to it, whatever the rest adds (only overflow is added; :func:`_score`
#: compares it rounded to a millionth of a mm).
BEATEN = tol.LAYOUT_BEATEN_MM


class _Solver:
    """The search over the open splits (see the module's docstring)."""

    def __init__(self, tree: Tree, field_: Field) -> None:
        self.tree = tree
        self.field = field_
        self.nodes: list[Node] = []
        self._collect(tree)
        self.choice: dict[int, tuple[float, ...] | int] = {}
        for nd in self.nodes:
            if isinstance(nd, Choice):
                self.choice[id(nd)] = 0
            elif isinstance(nd, Grid):
                self.choice[id(nd)] = nd.cols or 1
            else:
                self.choice[id(nd)] = nd.weights or (1.0,) * len(nd.items)

        #: Each node's subtree's nodes, and the placements of subtrees already evaluated (by
        #: node, box and the subtree's choices): a search step changes one node, and the rest
        #: of the tree is replayed from here.
        self.sub: dict[int, list[int]] = {}
        self._subtree(tree)
        self.memo: dict[tuple[object, ...], _Part] = {}
        #: Each memoised part's overflow (Σ of its leaves' ``bad``), and the overflow of the
        #: layout being laid out so far against the most it may reach (:meth:`evaluate`).
        self.bads: dict[tuple[object, ...], float] = {}
        self._bad = 0.0
        self._most = math.inf
        self.options: dict[tuple[object, ...], list[tuple[float, ...] | int]] = {}
        self.scored: dict[object, tuple[_Part, tuple[float, ...]]] = {}
        #: Layouts scored (for the benchmark and the tests).
        self.evaluations = 0
        self._choices = [id(nd) for nd in self.nodes if isinstance(nd, Choice)]
        self._laid_ids: dict[tuple[object, ...], list[int]] = {}
        self._laid_getters: dict[tuple[object, ...], Callable[[Mapping[int, object]], object]] = {}
        self._sub_get = {i: _getter(ids) for i, ids in self.sub.items()}
        self.infos: dict[int, _Info] = {}
        self._splits: dict[int, Any] = {}
        #: Each node's children's cells, by node, box and the node's own choice.
        self._cells: dict[tuple[object, ...], list[tuple[Tree, Box]]] = {}

    def _collect(self, t: Tree) -> None:
        if isinstance(t, Node):
            self.nodes.append(t)
            for it in t.items:
                self._collect(it)

    def _subtree(self, t: Tree) -> list[int]:
        if isinstance(t, View):
            return []
        ids = [id(t)]
        for it in t.items:
            ids += self._subtree(it)
        self.sub[id(t)] = ids
        return ids

    def _options(self, nd: Node, fine: bool = False) -> list[tuple[float, ...] | int]:
        """A node's options: a Choice's items, a Grid's column counts, or the splits of a row
        or column: its flexible items' shares in coarse steps, or (``fine``) in quarter steps
        within half a coarse step of the current split."""
        if isinstance(nd, Choice):
            return list(range(len(nd.items)))
        if isinstance(nd, Grid):
            return [nd.cols] if nd.cols else list(range(1, len(nd.items) + 1))
        if nd.weights is not None:
            return [nd.weights]
        cur = self.choice[id(nd)]
        known = self.options.get((id(nd), fine, cur))
        if known is not None:  # the rounds come back to a node whose split has not moved
            return known
        n = len(nd.items)
        flex = [i for i, it in enumerate(nd.items) if natural_of(it) is None]
        out: list[tuple[float, ...] | int] = []
        if len(flex) <= 1:
            out.append((1.0,) * n)
            self.options[(id(nd), fine, cur)] = out
            return out
        coarse = {2: 12, 3: 8, 4: 6}.get(len(flex), 4)
        steps = coarse * (4 if fine else 1)
        assert isinstance(cur, tuple)
        total = sum(cur[i] for i in flex)
        share = [cur[i] / total for i in flex]
        near = 0.5 / coarse + tol.SHEET_MM
        # in fine steps, each part within half a coarse step of the current share: the first
        # parts' steps chosen from their own ranges, the last part checked
        ranges = [
            [c for c in range(1, steps) if not (fine and abs(c / steps - sh) > near)]
            for sh in share[:-1]
        ]
        for combo in itertools.product(*ranges):
            used = sum(combo)
            if used >= steps:
                continue
            last = steps - used
            if fine and abs(last / steps - share[-1]) > near:
                continue
            w = [1.0] * n
            for i, c in zip(flex, (*combo, last), strict=True):
                w[i] = float(c)
            out.append(tuple(w))
        self.options[(id(nd), fine, cur)] = out
        return out

    def run(self, t: Tree, box: Box) -> _Part:
        """The subtree laid out in ``box`` at the current choices (memoised)."""
        if isinstance(t, View):
            return ((t, self._info(t).place(box)),), ()
        key = (id(t), box, self._sub_get[id(t)](self.choice))
        part = self.memo.get(key)
        if part is None:
            start = self._bad
            part = self.memo[key] = self._run(t, box)
            self.bads[key] = self._bad - start
        else:
            self._bad += self.bads[key]
            if self._bad > self._most:
                raise _Beaten
        return part

    def _split(self, node: Node, box: Box, weights: tuple[float, ...]) -> list[tuple[Tree, Box]]:
        """:func:`_split` with what does not depend on the box asked once per node."""
        known = self._splits.get(id(node))
        if known is None:
            horizontal = isinstance(node, Row)
            fixed, flex = _fixed(node, horizontal)
            lens = tuple(fixed.get(i) for i in range(len(node.items)))
            gaps = node.gap * (len(node.items) - 1)
            known = (horizontal, node.title_room(), gaps, sum(fixed.values()), lens, flex)
            self._splits[id(node)] = known
        horizontal, top, gaps, fixed_sum, lens, flex = known
        x0, y0, x1, y1 = box
        y0 += top
        length = (x1 - x0) if horizontal else (y1 - y0)
        share = max(length - gaps - fixed_sum, 0.0)
        total_w = sum([weights[i] for i in flex]) or 1.0
        gap = node.gap
        out = []
        pos = x0 if horizontal else y0
        stop = x1 if horizontal else y1
        for it, fixed_len, wt in zip(node.items, lens, weights, strict=True):
            ln = fixed_len if fixed_len is not None else share * wt / total_w
            # fixed children that overrun the box are cut back at its end (and count as not
            # fitting), not laid past it
            end = pos + ln
            if end > stop:
                end = stop
            out.append((it, (pos, y0, end, y1) if horizontal else (x0, pos, x1, end)))
            pos += ln + gap
        return out

    def _info(self, v: View) -> _Info:
        info = self.infos.get(id(v))
        if info is None:
            info = self.infos[id(v)] = _Info(v, self.field.obstacles)
        return info

    def _run(self, t: Node, box: Box) -> _Part:
        titles: tuple[tuple[Box, Node], ...] = ((box, t),) if t.title else ()
        ch = self.choice[id(t)]
        if isinstance(t, Choice):
            assert isinstance(ch, int)
            items, inner = self.run(t.items[ch], box)
            return items, titles + inner
        cells_key = (id(t), box, ch)
        kids = self._cells.get(cells_key)
        if kids is None:
            if isinstance(t, Grid):
                assert isinstance(ch, int)
                kids = _grid_cells(t, box, ch)
            else:
                assert isinstance(ch, tuple)
                kids = self._split(t, box, ch)
            self._cells[cells_key] = kids
        out: list[tuple[View, _Leaf]] = []
        more_titles: list[tuple[Box, Node]] = list(titles)
        for it, cell in kids:
            if isinstance(it, View):
                leaf = self._info(it).place(cell)
                out.append((it, leaf))
                if leaf.bad:
                    self._bad += leaf.bad
                    if self._bad > self._most:
                        raise _Beaten
                continue
            more, inner = self.run(it, cell)
            out += more
            if inner:
                more_titles += inner
        return tuple(out), tuple(more_titles)

    def evaluate(self, floor: tuple[float, ...] | None = None) -> tuple[_Part, tuple[float, ...]]:
        """The layout of the current choices and its score; a set of choices the search
        comes back to (the next round's sweep of an unmoved node) is scored once. With a
        ``floor`` (the best score so far), a layout whose overflow alone already makes it
        worse is not scored: its score is given as the floor's overflow less one (it loses)."""
        key = self._laid_get(self.choice)
        done = self.scored.get(key)
        if done is None:
            # the overflow its leaves add up to as they are laid out: one already past the
            # floor's (by more than the score's rounding) ends the layout there, as _score
            # would end it
            self._bad, self._most = 0.0, math.inf if floor is None else BEATEN - floor[0]
            try:
                part = self.run(self.tree, self.field.box)
            except _Beaten:
                self.evaluations += 1
                assert floor is not None
                return ((), ()), (floor[0] - 1.0,)
            finally:
                self._most = math.inf
            sc = _score(part, floor)
            self.evaluations += 1
            if sc is None:
                assert floor is not None
                return part, (floor[0] - 1.0,)
            done = self.scored[key] = (part, sc)
        return done

    def _laid_get(self, choice: Mapping[int, object]) -> object:
        """The current choices of the nodes laid out, with the :class:`Choice` nodes' (the key
        of :attr:`scored`: two arrangements whose nodes' splits read alike are two layouts)."""
        which = tuple(choice[i] for i in self._choices)
        get = self._laid_getters.get(which)
        if get is None:
            get = self._laid_getters[which] = _getter(self._laid())
        return which, get(choice)

    def _laid(self) -> list[int]:
        """The ids of the nodes :meth:`_active` yields, found once per choice of the
        :class:`Choice` nodes (the only choices that change which nodes are laid out)."""
        which = tuple(self.choice[i] for i in self._choices)
        ids = self._laid_ids.get(which)
        if ids is None:
            ids = self._laid_ids[which] = [id(nd) for nd in self._active(self.tree)]
        return ids

    def _active(self, t: Tree) -> Iterator[Node]:
        """The nodes the current choices lay out (a :class:`Choice`'s other arrangements are
        not on the sheet: moving their splits changes nothing)."""
        if isinstance(t, Node):
            yield t
            ch = self.choice[id(t)]
            for it in [t.items[ch]] if isinstance(t, Choice) and isinstance(ch, int) else t.items:
                yield from self._active(it)

    def _descend(self) -> tuple[_Part, tuple[float, ...]]:
        """Coordinate search over the splits and grid shapes, the choices held: in coarse
        steps, then in fine steps near the coarse optimum. Only the nodes laid out are swept,
        in the order of :attr:`nodes` (a node that two arrangements share is swept twice).
        Three coarse rounds: with two, the shaper's forces sheet took another arrangement
        with its tables at 2.5 mm (a lower score)."""
        best_ev, best = self.evaluate()
        laid = {id(nd) for nd in self._active(self.tree)}
        for fine, rounds in ((False, 3), (True, 2)):
            for _ in range(rounds):
                improved = False
                for nd in self.nodes:
                    if (
                        id(nd) not in laid
                        or isinstance(nd, Choice)
                        or (fine and isinstance(nd, Grid))
                    ):
                        continue
                    opts = self._options(nd, fine)
                    if len(opts) <= 1:
                        continue
                    keep = self.choice[id(nd)]
                    for o in opts:
                        if o == keep:
                            continue
                        self.choice[id(nd)] = o
                        ev, sc = self.evaluate(best)
                        if sc > best:
                            best, best_ev, keep, improved = sc, ev, o, True
                    self.choice[id(nd)] = keep
                if not improved:
                    break
        return best_ev, best

    def solve(self) -> _Eval:
        """The best layout over every combination of the :class:`Choice` nodes' options."""
        choices = [nd for nd in self.nodes if isinstance(nd, Choice)]
        start = dict(self.choice)
        found: tuple[_Part, tuple[float, ...]] | None = None
        for combo in itertools.product(*(range(len(c.items)) for c in choices)):
            self.choice = dict(start)
            for c, i in zip(choices, combo, strict=True):
                self.choice[id(c)] = i
            ev, sc = self._descend()
            if found is None or sc > found[1]:
                found = (ev, sc)
        assert found is not None
        return _Eval(found[0])


def _scales(ev: _Eval) -> dict[str, Scale]:
    """Each group's scale: the coarsest any member's cell needs, rounded up in its series."""
    raw: dict[str, tuple[float, View]] = {}
    for key, v in ev.views.items():
        if v.kind != "scaled":
            continue
        k = _raw_k(v, ev.cells[key])
        g = _group(v)
        if g not in raw or k > raw[g][0]:
            raw[g] = (k, v)
    out = {}
    for g, (k, v) in raw.items():
        if not math.isfinite(k):
            raise ParameterError("layout", v.title or type(v).__name__, "has no room on the sheet")
        out[g] = round_scale(k, v.quantity, v.series) if k > 0.0 else Scale(1.0, v.quantity)
    return out


def _fill_of(v: View, cell: Box, k: float) -> float:
    ext = _ext(v)
    assert ext is not None
    cw, ch = _content(ext)
    area = (cell[2] - cell[0]) * (cell[3] - cell[1] - v.title_room())
    if area <= 0.0 or not math.isfinite(k) or k <= 0.0:
        return 0.0
    return (cw / k + 2 * v.margin) * (ch / k + 2 * v.margin) / area


def _title_width(v: View) -> float:
    """The width (mm) of a view's title with a typical scale label after it."""
    if not v.title:
        return 0.0
    if v._title_w is None:
        sample = Scale(0.0025, v.quantity) if v.kind == "scaled" else None
        v._title_w = _lines_width(v.caption(sample), v.title_height, v.title_lines)
    return v._title_w


def _node_title_width(node: Node) -> float:
    """The width (mm) of a node's title with a typical scale label after it."""
    if node._title_w is not None:
        return node._title_w
    text = node.title
    if node.group or any(v.group for v in node.views()):
        text += ", " + scale_text(Scale(0.0025, next(iter(node.views())).quantity))
    node._title_w = _lines_width(text, node.title_height, node.title_lines)
    return node._title_w


def _lines_width(text: str, height: float, lines: int) -> float:
    """The width (mm) of a title set in ``lines`` balanced lines (one: the whole line)."""
    if lines <= 1:
        return text_width(text, height)
    tokens = _title_tokens(text)
    return max(text_width(t, height) for t in balanced(tokens, min(lines, len(tokens)), height))


def _title_tokens(text: str) -> list[tuple[str, str]]:
    """The pieces a title may be broken between (:func:`break_points`), an equation and a
    number with its unit kept on one line (``δ = 0,04``, ``μ_l = 0,002 м/мм``), a short
    preposition with the word after it (``с маховиком``, never "по" at a line's end)."""
    out: list[tuple[str, str]] = []
    for t, j in break_points(text):
        prev = out[-1][0] if out else ""
        short = prev.isalpha() and prev.islower() and len(prev) <= 2
        last = prev.rsplit(" ", 1)[-1]  # the number of ``μ_l = 0,0025`` keeps its unit
        if out and (t == "=" or prev.endswith("=") or last[:1].isdigit() or short):
            out[-1] = (out[-1][0] + out[-1][1] + t, j)
        else:
            out.append((t, j))
    return out


@functools.lru_cache(maxsize=4096)
def _rounded(k: float, q: Quantity, series: Series) -> float:
    """The factor :func:`round_scale` gives (inf where it refuses ``k``)."""
    try:
        return round_scale(k, q, series).k
    except ParameterError:
        return math.inf


@typing.overload
def _score(part: _Part) -> tuple[float, ...]: ...
@typing.overload
def _score(part: _Part, floor: tuple[float, ...] | None) -> tuple[float, ...] | None: ...
def _score(part: _Part, floor: tuple[float, ...] | None = None) -> tuple[float, ...] | None:
    """(−infeasibility, Σ weight·log(drawn area)): larger is better. The sum of logarithms
    shares the field fairly: a view gains only where its drawing grows, so no view keeps a
    large box its drawing does not use while another could grow into it. With a ``floor``:
    None where the overflow of the boxes alone already scores below it (the rest of the
    infeasibility only adds)."""
    items, titles = part
    bad = sum([leaf.bad for _, leaf in items])
    for cell, node in titles:
        bad += max(0.0, _node_title_width(node) - (cell[2] - cell[0]))
    if floor is not None and -round(bad, 6) < floor[0]:
        return None
    raw: dict[str, float] = {}
    first: dict[str, View] = {}
    for v, leaf in items:
        if leaf.kind == "scaled":
            g = leaf.group
            k = leaf.raw_k
            if g in raw:
                if k > raw[g]:
                    raw[g] = k
            else:
                raw[g] = 0.0 if k < 0.0 else k
                first[g] = v
    rounded: dict[str, float] = {}
    for g, k in raw.items():
        if not math.isfinite(k):
            bad += 1000.0
            rounded[g] = math.inf
            continue
        v = first[g]
        r = rounded[g] = _rounded(k, v.quantity, v.series) if k > 0.0 else 1.0
        if r == math.inf:  # a candidate too small even for the smallest scale
            bad += 1000.0
    short = 0
    rule = 0.0
    small = tol.SHEET_AREA
    # the drawn area (mm²) of each flexible view at the rounded scales and at the raw ones, a
    # scale group counting once (the sum of its members'), a stretch view's as it really
    # draws; with each one's weight
    areas_r: dict[object, list[float]] = {}
    areas_c: dict[object, list[float]] = {}
    log = math.log
    inf = math.inf
    for v, leaf in items:
        kind = leaf.kind
        if kind == "fixed":
            continue
        if kind == "stretch":
            a = leaf.area
            a = a if a > small else small
            areas_r[v] = areas_c[v] = [a, v.weight]
            continue
        g = leaf.group
        k = rounded[g]
        if leaf.area < 0.0:
            rule -= leaf.area
        if k != math.inf:
            if v.readable > 0.0 and v.readable / k < v.readable_mm:
                bad += v.readable_mm - v.readable / k
            lengths = leaf.lengths
            if lengths:
                # drawn (over half a millimetre) yet shorter than two arrowheads
                short += bisect.bisect_left(lengths, v.readable_mm * k) - bisect.bisect_right(
                    lengths, 0.5 * k
                )
        cw, ch = leaf.content
        w = v.weight
        # (the rounded scales' areas, then the raw ones': written out twice, not as a loop
        # over the pair, the search's hottest lines)
        area = (cw / k) * (ch / k) if 0.0 < k < inf and cw > 0.0 else small
        area = area if area > small else small
        prev = areas_r.get(g)
        if prev is None:
            areas_r[g] = [0.0 + area, w if w > 0.0 else 0.0]
        else:
            prev[0] += area
            if w > prev[1]:
                prev[1] = w
        kk = raw[g]
        area = (cw / kk) * (ch / kk) if 0.0 < kk < inf and cw > 0.0 else small
        area = area if area > small else small
        prev = areas_c.get(g)
        if prev is None:
            areas_c[g] = [0.0 + area, w if w > 0.0 else 0.0]
        else:
            prev[0] += area
            if w > prev[1]:
                prev[1] = w
    score_r = sum([w * log(a) for a, w in areas_r.values()])
    score_c = sum([w * log(a) for a, w in areas_c.values()])
    return (-round(bad, 6), score_r + 0.1 * score_c - SHORT_COST * short - RULE_COST * rule)


def _fills(lay: Layout) -> list[float]:
    out: dict[str, float] = {}
    for pl in lay:
        v = pl.view
        if v.kind == "scaled" and pl.scale is not None:
            g = _group(v)
            out[g] = max(out.get(g, 0.0), _fill_of(v, pl.box, pl.scale.k))
        elif v.kind == "stretch":
            out[f"#{id(v)}"] = _stretch_fill(v, pl.box)
    return list(out.values())


def arrange(tree: Tree, field_: Field, _titles_broken: bool = False) -> Layout:
    """Pack ``tree`` into ``field_`` and choose every scale (no drawing; see the module's
    docstring). :class:`ParameterError` when a view has no room at all. A title wider than
    the box it gets is broken into lines and the tree laid out again with their room."""
    if not _titles_broken:
        _set_title_lines(tree, {})
        noted = [t for t in _titled(tree) if isinstance(t, View) and t.note_lines != 1]
        notes = {id(t) for t in noted}
        for t in noted:
            t.note_lines = 1
        if notes:
            _forget(tree, notes)
    # the search allocates many small tuples and no cycles: the cyclic collector, which would
    # scan the whole heap again and again meanwhile, waits till it is done
    collect = gc.isenabled()
    gc.disable()
    try:
        ev = _Solver(tree, field_).solve()
    finally:
        if collect:
            gc.enable()
    scales = _scales(ev)
    lay = Layout(
        titles=ev.titles,
        groups={g: s for g, s in scales.items()},
        score=_score((ev.items, tuple(ev.titles))),
    )
    for key, v in ev.views.items():
        cell = ev.cells[key]
        top = cell[1] + v.title_room()
        inner = (cell[0] + v.margin, top + v.margin, cell[2] - v.margin, cell[3] - v.margin)
        scale = scales.get(_group(v)) if v.kind == "scaled" else None
        lay.placed[key] = Placed(v, cell, inner, scale)
    if _break_titles(tree, lay, field_.obstacles):
        return arrange(tree, field_, _titles_broken=True)
    lay.title_lines = {id(t): t.title_lines for t in _titled(tree) if t.title_lines > 1}
    return lay


# --- titles broken into lines ---------------------------------------------------------------


def _title_room(title: str, height: float, lines: int) -> float:
    """The room (mm) of a title of ``lines`` lines at cap height ``height`` (0 without one)."""
    if not title:
        return 0.0
    return height * TITLE_LEAD + TITLE_GAP + (lines - 1) * height * TITLE_SPACING


def title_text_lines(text: str, width: float, height: float) -> list[str]:
    """A title as drawn in a box ``width`` mm wide: one line where it fits, else broken at
    spaces into lines of about equal width (at most :data:`TITLE_LINES`)."""
    if not text or text_width(text, height) <= width:
        return [text]
    tokens = _title_tokens(text)
    for n in range(2, min(TITLE_LINES, len(tokens)) + 1):
        lines = balanced(tokens, n, height)
        if max(text_width(ln, height) for ln in lines) <= width:
            return lines
    return [text]


def _titled(tree: Tree) -> Iterator[View | Node]:
    """The tree's views and nodes (each once), those with a title."""
    if tree.title:
        yield tree
    if isinstance(tree, Node):
        for it in tree.items:
            yield from _titled(it)


def _set_title_lines(tree: Tree, lines: Mapping[int, int], only_changed: bool = False) -> None:
    """Set the lines of every title of the tree (1 unless ``lines`` says otherwise), dropping
    what the layout remembered of the old room where a count changed: of every view, or,
    ``only_changed`` (the titles broken within one :func:`arrange`, nothing else about the
    views changed), of the views whose own count changed (a view's cells depend on its own
    title's room only; the nodes' natural sizes are always dropped)."""
    changed: set[int] = set()
    for t in _titled(tree):
        n = lines.get(id(t), 1)
        if n != t.title_lines:
            t.title_lines, t._title_w = n, None
            changed.add(id(t))
    if changed:
        _forget(tree, changed if only_changed else None)


def _forget(tree: Tree, views: set[int] | None = None) -> None:
    """Drop the layout's memory of boxes and natural sizes that counted the titles' room (of
    the views in ``views`` only, where given)."""
    if isinstance(tree, View):
        if views is None or id(tree) in views:
            for key in [k for k in tree._memo if k not in ("ext", "nat", "lengths")]:
                del tree._memo[key]
        return
    tree._natural, tree._fixed = False, {}
    for it in tree.items:
        _forget(it, views)


def _title_start(box: Box, height: float, obstacles: Sequence[Box]) -> float:
    """Where a title on ``box``'s top edge starts: the box's left edge, else just right of a
    box of the form its first line would run into (графа 26 in the top-left corner: as
    :meth:`~geomcad.sheet.drawing.Drawing.text` moves it), every line of it there."""
    x = box[0]
    for o in obstacles:
        if o[0] <= x < o[2] and o[1] < box[1] + height * TITLE_LEAD and box[1] < o[3]:
            x = o[2]
    return x


def _break_titles(tree: Tree, lay: Layout, obstacles: Sequence[Box] = ()) -> bool:
    """Give each title wider than its box in ``lay`` the lines it takes there (never fewer
    than it had; the width from where it starts, :func:`_title_start`: review 8's dynamics
    title moved past графа 26 was broken for its whole box and ran to the next view's title);
    whether any count grew (the tree is then laid out again)."""
    want: dict[int, int] = {}
    for pl in lay:
        v = pl.view
        if v.title:
            w = pl.box[2] - _title_start(pl.box, v.title_height, obstacles)
            want[id(v)] = len(title_text_lines(v.caption(pl.scale), w, v.title_height))
    for cell, node in lay.titles:
        text = _node_caption(node, lay)
        w = cell[2] - _title_start(cell, node.title_height, obstacles)
        want[id(node)] = len(title_text_lines(text, w, node.title_height))
    # a view's lines under its caption (a force plan's line naming what its details cannot
    # show) broken for its box like the caption
    notes: set[int] = set()
    for pl in lay:
        v = pl.view
        if (n := v.note_lines_in(pl.box[2] - pl.box[0])) > v.note_lines:
            v.note_lines = n
            notes.add(id(v))
    if notes:
        _forget(tree, notes)
    grown = {id(t): max(t.title_lines, want.get(id(t), 1)) for t in _titled(tree)}
    if all(grown[id(t)] == t.title_lines for t in _titled(tree)):
        return bool(notes)
    _set_title_lines(tree, grown, only_changed=True)
    return True


def _node_caption(node: Node, lay: Layout) -> str:
    """A node's title as drawn: with its scale group's scale where it shows one."""
    g = node.group or next((v.group for v in node.views() if v.group), "")
    if g and g in lay.groups:
        return f"{node.title}, {scale_text(lay.groups[g])}"
    return node.title


def compose(
    d: Drawing, tree: Tree, field_: Field | None = None, layout: Layout | None = None
) -> Layout:
    """Arrange ``tree`` in the drawing's field (:func:`arrange`; or take ``layout``, an
    arrangement of this same tree), then draw every title and every view; returns the layout
    (each view's box, scale and viewport)."""
    lay = layout or arrange(tree, field_ or Field.of(d.frame))
    _set_title_lines(tree, lay.title_lines)  # the room this layout gave the titles
    for cell, node in lay.titles:
        _draw_title(d, _node_caption(node, lay), cell, node.title_height, node.title_lines)
    boxes = [pl.box for pl in lay]
    for pl in lay:
        v = pl.view
        if v.title:
            _draw_title(d, v.caption(pl.scale), pl.box, v.title_height, v.title_lines, boxes)
        if pl.scale is not None:
            ext = _ext(v)
            assert ext is not None
            centre = ((ext[0] + ext[2]) / 2.0, (ext[1] + ext[3]) / 2.0)
            at = ((pl.inner[0] + pl.inner[2]) / 2.0, (pl.inner[1] + pl.inner[3]) / 2.0)
            pl.viewport = d.viewport(pl.scale, centre, at)
        v.draw(d, pl)
    return lay


def _draw_title(
    d: Drawing, text: str, box: Box, height: float, room: int, others: Sequence[Box] = ()
) -> None:
    """A title on its box's top edge (from :func:`_title_start`), broken into lines within
    the box's width where it is wider (at most the ``room`` lines the layout gave it); a box
    set beside графа 26 takes it on one line under графа 26 instead, run back left over the
    blank paper there, where that is clear of the ``others`` boxes and within its room."""
    from geomcad.sheet.drawing import RESERVED_GAP
    from geomcad.sheet.frame import reserved

    form = [(x0, y0, x1 + RESERVED_GAP, y1) for x0, y0, x1, y1 in
            reserved(d.sheet.width, d.sheet.height)]  # fmt: skip
    x = _title_start(box, height, form)
    lines = title_text_lines(text, box[2] - x, height)
    if len(lines) > room:
        lines = [text]
    if len(lines) > 1:
        one = _under_form(text, box, height, len(lines), form, others)
        if one is not None:
            d.text(text, one, height)
            return
    for i, line in enumerate(lines):
        d.text(line, (x, box[1] + height + i * height * TITLE_SPACING), height)


def _under_form(
    text: str, box: Box, height: float, lines: int, form: Sequence[Box], others: Sequence[Box]
) -> tuple[float, float] | None:
    """Where a title broken into ``lines`` lines beside графа 26 (its box set just right of
    a box of the form, ``form`` grown by the gap kept from it) stands on one line instead:
    under that box, ending a cap height before its own box's right edge, its baseline within
    the room of the lines (review 9: sine-plans' "Положение 0, φ1 = 180°" broke beside
    графа 26 over blank paper); ``None`` where no box of the form is there or the line would
    meet another box."""
    w = text_width(text, height)
    for o in form:
        if not (o[1] <= box[1] < o[3] and abs(box[0] - o[2]) <= tol.SHEET_MM):
            continue
        # a title's gap below графа 26, and a cap height before the next box's title
        y = o[3] + TITLE_GAP + height
        x = box[2] - height - w
        if y > box[1] + height + (lines - 1) * height * TITLE_SPACING + tol.SHEET_MM:
            return None
        line = (x, y - height, box[2] - height, y + 0.3 * height)
        if x < o[0] or any(
            b != box and line[0] < b[2] and b[0] < line[2] and line[1] < b[3] and b[1] < line[3]
            for b in others
        ):
            return None
        return x, y
    return None


def text_width(markup: str, height: float) -> float:
    """The width (mm) of a line of label markup at cap height ``height``."""
    return text_box(parse(markup), height)[0]


def least_room(tree: Tree, wants: Mapping[View, float]) -> list[tuple[float, float]]:
    """The sizes (mm; width, height) of which a box must have one, at least, for every view of
    ``wants`` to be drawn at its scale (model units per mm) or larger in ``tree``, whatever the
    search chooses: the wanted views at those scales with their margins and titles, the lengths
    a split always gives (its fixed children's natural lengths, its gaps, its title), a grid's
    equal cells in each of its shapes, either arrangement of a :class:`Choice`; everything else
    as small as it may get, the form's boxes ignored. A necessary test: where no size of the
    list fits a field, no arrangement there draws the wanted views at their scales."""
    return _pareto(_least(tree, wants))


def _pareto(sizes: Sequence[tuple[float, float]]) -> list[tuple[float, float]]:
    out: list[tuple[float, float]] = []
    for w, h in sorted(set(sizes)):
        if not out or h < out[-1][1]:
            out.append((w, h))
    return out


def _least(t: Tree, wants: Mapping[View, float]) -> list[tuple[float, float]]:
    if isinstance(t, View):
        k = wants.get(t)
        if k is None:
            return [(0.0, 0.0)]
        ext = _ext(t)
        assert ext is not None
        k *= 1.0 + tol.REL_LENGTH  # as formats.meets allows
        w = (ext[2] - ext[0]) / k + 2.0 * t.margin
        return [(w, (ext[3] - ext[1]) / k + 2.0 * t.margin + t.title_room())]
    if isinstance(t, Choice):
        return _pareto([sz for it in t.items for sz in _least(it, wants)])
    kids = [_least(it, wants) for it in t.items]
    top = t.title_room()
    if isinstance(t, Grid):
        n = len(t.items)
        out = []
        lw = [min(w for w, _ in kid) for kid in kids]
        lh = [min(h for _, h in kid) for kid in kids]
        for cols in [t.cols] if t.cols else range(1, n + 1):
            rows = math.ceil(n / cols)
            if t.fitted and t.rows_own:  # each row as its own children need
                cws = max(sum(lw[r * cols : (r + 1) * cols]) for r in range(rows))
                chs = sum(
                    max(lh[i] for i in range(r * cols, min(n, r * cols + cols)))
                    for r in range(rows)
                )
            elif t.fitted:  # each column (row) as its largest child needs
                cws = sum(max(lw[i] for i in range(c, n, cols)) for c in range(cols))
                chs = sum(
                    max(lh[i] for i in range(r * cols, min(n, r * cols + cols)))
                    for r in range(rows)
                )
            else:  # each cell holds one child: the largest least width and height of any child
                cws, chs = cols * max(lw), rows * max(lh)
            out.append((cws + t.gap * (cols - 1), chs + t.gap * (rows - 1) + top))
        return _pareto(out)
    horizontal = isinstance(t, Row)
    fixed, _ = _fixed(t, horizontal)
    acc = [(t.gap * (len(t.items) - 1), 0.0)]  # (along the split, across it)
    for i, kid in enumerate(kids):
        opts = [(w, h) if horizontal else (h, w) for w, h in kid]
        if i in fixed:  # a fixed child takes its natural length along the split, whatever
            opts = [(max(fixed[i], a), c) for a, c in opts]
        acc = _pareto([(a0 + a, max(c0, c)) for a0, c0 in acc for a, c in opts])
    if horizontal:
        return _pareto([(a, c + top) for a, c in acc])
    return _pareto([(c, a + top) for a, c in acc])
