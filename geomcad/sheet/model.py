"""The backend-neutral drawing model: a sheet of paper and the items on it, in sheet millimetres.

Coordinates are paper millimetres from the sheet's top-left corner, x to the right and y DOWN
(the SVG convention, so one SVG user unit is one millimetre). Model coordinates (y up) are turned
into these once, by a :class:`~geomcad.sheet.viewport.Viewport`.

Items are small frozen records. Each carries a ``role`` (its layer and line style, see
:mod:`geomcad.sheet.style`) and, for a dashed role, the dash pattern already fitted to its length,
so a backend only replays them. Nothing here writes files.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal, TypeAlias

if TYPE_CHECKING:
    from geomcad.sheet.frame import TitleBlock
    from geomcad.sheet.scale import Scale

XY: TypeAlias = tuple[float, float]
Shift = Literal["base", "sub", "sup"]


@dataclass(frozen=True, slots=True)
class Dash:
    """A fitted dash pattern: ``array`` in mm (dash, gap, dash, gap …) and the start ``offset``."""

    array: tuple[float, ...]
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class Polyline:
    """An open or closed chain of straight segments. ``fill`` fills a closed one (arrowheads)."""

    points: tuple[XY, ...]
    role: str
    closed: bool = False
    fill: bool = False
    dash: Dash | None = None


@dataclass(frozen=True, slots=True)
class CircleItem:
    """A full circle of centre ``c`` and radius ``r`` (mm). ``fill`` fills it (a joint's dot)."""

    c: XY
    r: float
    role: str
    fill: bool = False
    dash: Dash | None = None


@dataclass(frozen=True, slots=True)
class ArcItem:
    """A circular arc from ``start`` to ``end`` (points on the circle), centre ``c``, radius ``r``.

    ``sweep`` is the arc's angle in radians, > 0 clockwise as seen on the paper (the SVG
    sweep-flag 1). A model arc turning counter-clockwise keeps its look on the paper, so its
    sweep here is negative.
    """

    c: XY
    r: float
    start: XY
    end: XY
    sweep: float
    role: str
    dash: Dash | None = None


@dataclass(frozen=True, slots=True)
class Run:
    """A piece of a label's text with one baseline shift (a subscript, a superscript)."""

    text: str
    shift: Shift = "base"


@dataclass(frozen=True, slots=True)
class TextItem:
    """A line of text whose left end of the baseline is at ``at`` (mm).

    ``height`` is the GOST cap height (mm); ``font_size`` the matching em size, measured from the
    font. ``width`` is the text's advance width in mm, as the backends will set it. ``angle`` turns
    the text about ``at`` (degrees, counter-clockwise as seen on the paper): a dimension's text
    along a slanted dimension line, графа 26 turned 180°. ``stretch``: the text's width factor
    (below 1: condensed about ``at``, a title-block name too wide for its графа at GOST's least
    height, never set smaller); ``width`` is the condensed width.
    """

    at: XY
    runs: tuple[Run, ...]
    height: float
    font_size: float
    width: float
    role: str
    id: str = ""
    angle: float = 0.0
    stretch: float = 1.0

    @property
    def text(self) -> str:
        return "".join(r.text for r in self.runs)


Item: TypeAlias = Polyline | CircleItem | ArcItem | TextItem


@dataclass
class Sheet:
    """A drawing sheet: its paper size, its items in drawing order, and its title-block data.

    ``items`` is appended to by the frame, the viewports and the construction's drawing code; a
    backend groups them by role (one layer per role) and keeps their order inside a layer.
    """

    width: float
    height: float
    format: str
    title: str
    items: list[Item] = field(default_factory=list)
    #: The title block waiting to be filled (:func:`geomcad.sheet.frame.fill_title_blocks`).
    block: TitleBlock | None = None
    #: Every placed label with the point it names, and every vector (tail, tip), in sheet mm:
    #: what the layout checker measures.
    anchors: list[tuple[TextItem, XY]] = field(default_factory=list)
    vectors: list[tuple[XY, XY]] = field(default_factory=list)
    #: Every vector drawn through a viewport of a plan or a polygon, with the scale it was drawn
    #: at (``Scale`` of v, a or F): the checker finds that scale stated on the sheet.
    scaled: list[tuple[XY, XY, Scale]] = field(default_factory=list)
    #: The language the sheet is drawn in (``ru``: GOST line widths; ``en``: ISO 128's).
    lang: str = "ru"

    def add(self, item: Item) -> None:
        self.items.append(item)

    def texts(self) -> list[TextItem]:
        """Every text item, for tests and for label placement."""
        return [i for i in self.items if isinstance(i, TextItem)]

    def _repr_svg_(self) -> str | None:
        """The sheet as SVG, for Jupyter; ``None`` (no picture) until a backend is set.

        The sheet layer cannot import the render layer above it, so the backend registers
        itself (:func:`set_svg_writer`): importing :mod:`geomcad.notebook` does, and so does
        getting sheets through ``Solution.sheets()``.
        """
        return None if _svg_writer is None else _svg_writer(self)


_svg_writer: Callable[[Sheet], str] | None = None


def set_svg_writer(writer: Callable[[Sheet], str] | None) -> None:
    """Set the function that draws a sheet as SVG text for :meth:`Sheet._repr_svg_`."""
    global _svg_writer
    _svg_writer = writer
