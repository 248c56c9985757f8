"""Sheets 2 and 3 of a linkage file's course project: the force analysis and the flywheel.

:func:`force_sheets` returns them for the lead's list of linkage sheets, named ``forces`` and
``dynamics``:

- **sheet 2, the force analysis** at one position (the file's first ``phi``, or the numbered
  position nearest the middle of the working stroke): the mechanism with every load drawn (top
  left); each Assur group and the crank cut out, with their loads and the reactions found (top
  right); each group's force polygons at their μ_F (bottom middle); Zhukovsky's lever, the
  velocity plan turned 90° with the loads at their points' images (bottom left); the table of
  loads, reactions and the two M_bal (bottom right);
- **sheet 3, the dynamics**: M_pr(φ), the works A(φ) (the exact integral and the graphical one
  through the numbered positions), ΔT(φ) and I_pr(φ) (left), Wittenbauer's energy–mass diagram
  with its two tangents and the segment ab they cut (top right), ω(φ) of the steady cycle with
  the flywheel and the tables: under the diagram, or the tables beside it down the right edge
  with ω(φ) under both or under the diagram alone, as the layout's search finds the diagram
  drawn larger (the flywheel is found on it: it weighs 1.5 views in the search).

The sheets are trees of views (:mod:`geomcad.sheet.compose`): the layout chooses the splits
and each view's scale (the largest of its series that fits its box), and every vector is drawn at
the μ its view states. Each sheet takes the smallest format on which it fits
(:func:`geomcad.sheet.linkage.fit`: A2 or A1, or the file's ``[sheet] format``), its tables,
orders and notes 3.5 mm high on A2 and A1, its views' titles 5 mm. The force sheet's
composition (:func:`force_layout`, issue 27):

- one μ_l for the mechanism and its groups and crank cut out (one scale group, stated in every
  caption; the title block's Масштаб is the mechanism's), or, where the crank would then be
  shorter than :data:`~geomcad.sheet.linkage.CRANK_MM` or a smaller format would do, one μ_l of
  the groups' own, shared by all of them and at least half the mechanism's size; the crank cut
  out keeps the mechanism's μ_l where that draws it CRANK_MM long;
- the groups and the crank cut out beside the mechanism (or over the polygons) in one band
  packed by their sizes (:func:`_band`), or each group over its polygons; the table and the
  order beside the polygons, or down the right edge over the title block;
- the drawings of links never finer than :func:`links_scale` (the geometry alone: ω and the
  loads rescale none of them), the crank at least CRANK_MM long where the mechanism's sweep
  allows it (:data:`SWEEP_MAX_MM`); where the mechanism's μ_l still draws the crank short, the
  crank enlarged in a detail in the mechanism view's free room (:meth:`_Loaded.crank_detail`);
  the crank's length a constraint of the search (:data:`CRANK_WEIGHT`, :func:`_held`): a
  detail only where no arrangement on the largest format holds the mechanism's μ_l with it, and
  the crank cut out at its own μ_l where that takes less of the other views' room than its
  crank lost (review 7);
- once the search has chosen, on the largest format: the mechanism, its groups and its crank
  at ONE μ_l with the crank CRANK_MM long on it, pinned as a constraint in an arrangement of
  its own (every form offered whatever the mechanism's shape: the mechanism as a band across
  the top, or down the left edge the sheet's height, alone or over the lever, with the tables
  down the right edge or in a row under the groups, :func:`_pinned_tree`), where the search
  left them apart or the crank short (an instrument-size mechanism enlarged: the yarn
  traverse's 12 mm crank at 2,5:1, 30 mm); where no such arrangement holds them, the
  mechanism at its crank's rule and the groups at one coarser μ_l of their own; where the
  search kept the rule, the drawings of links one GOST step finer while every other view
  keeps its scale (review 10), the force plans coarser while each still reads
  (:data:`PLAN_READ_MM`, review 11: kulisa at 1:2,5, not 1:4);
- the smallest format on which, besides, every force polygon is :data:`POLY_MM` across: the
  views grow, and the groups take their own μ_l, before a larger format is taken; on the format
  taken the tables are 3.5 mm high where the drawings of links keep their scales with it.

The words come from ``strings/<lang>/linkage_forces.toml``.
"""

from __future__ import annotations

import contextvars
import itertools
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.construction.recorder import Step
from geomcad.errors import GeomcadError, ParameterError, SheetsFailed
from geomcad.forces import ForcePolygon
from geomcad.geom import Vec
from geomcad.linkage.analysis import analyse
from geomcad.linkage.dynamics import Flywheel
from geomcad.linkage.kinetostatics import (
    Applied,
    Forces,
    GroupForces,
    Lever,
    LeverItem,
    Reaction,
    reaction_name,
)
from geomcad.linkage.loads import centre_vec
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import Position
from geomcad.linkage.solution import Solved, scheme
from geomcad.sheet import Drawing, Sheet, TitleBlock, fmt_number, formats, symbols
from geomcad.sheet.compose import _GOST_K as GOST_K
from geomcad.sheet.compose import (
    GAP,
    TITLE_LEAD,
    TITLE_SPACING,
    Choice,
    Column,
    Field,
    Grid,
    Layout,
    Placed,
    Row,
    Series,
    Tree,
    View,
    arrange,
    compose,
    natural_of,
    round_scale,
    round_scale_down,
)
from geomcad.sheet.compose import _lines_width as lines_width
from geomcad.sheet.compose import _title_width as title_width
from geomcad.sheet.drawing import SHORT_MM, Viewport
from geomcad.sheet.frame import FORMATS, LEFT_MARGIN, MARGIN, reserved
from geomcad.sheet.graph import (
    ARROW_OVER,
    FACTOR_PLACES,
    Axis,
    Graph,
    nice_steps,
    thousands_power,
)
from geomcad.sheet.insets import MARK_R, TWIN_SHIFT_MM, Insets, _seg_dist, one_scale_per_inset
from geomcad.sheet.lang import Words, current
from geomcad.sheet.linkage import (
    CRANK_MM,
    DETAIL_RING_MM,
    NO_SCALE,
    SMALL_TEXT_H,
    TEXT_COST,
    TEXT_H,
    TITLE_H,
    ZERO,
    _alternatives,
    _CrankDetail,
    _on,
    fit,
    frame_guides,
    link_bodies,
    mark_detail,
    omega_arrow,
    order_width,
    position_marks,
    row_height,
    sheet_formats,
    sheet_name,
    table_number,
    tabled_cells,
)
from geomcad.sheet.linkage import WORDS as KIN_WORDS
from geomcad.sheet.linkage import layout as kinematic_layout
from geomcad.sheet.loads import (
    AT_POINT_MM,
    NEGLIGIBLE,
    VIEW_NEGLIGIBLE,
    Clearance,
    ForceScales,
    _inside,
    force,
    line_of_action,
    moment,
    view_scales,
)
from geomcad.sheet.model import XY, CircleItem, TextItem
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scale import (
    ANGLE_PLACES,
    FIGURES,
    Scale,
    angle_places,
    fmt_column,
    fmt_fixed,
)
from geomcad.sheet.scheme import Body, draw_scheme
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse, wrap
from geomcad.sheet.views import (
    SLIVER_MM,
    AxisSpec,
    Curve,
    Diagram,
    Polygon,
    Steps,
    Table,
    Text,
    detail_letters,
    is_sliver,
)
from geomcad.structure import Mechanism
from geomcad.structure.model import Link

WORDS = Words(__package__, "linkage_forces")
#: The longest load arrow on a drawing of links (mm).
LOAD_MM = 24.0
#: The radius (mm) of M_ур's arc about the crank's pivot: clear of the support's stand and
#: hatching (symbols.STAND_DEPTH + HATCH_LEN) round the pivot.
M_BAL_MM = symbols.STAND_DEPTH + symbols.HATCH_LEN + 3.0
#: M_ур's arc spans this many degrees, its gap centred on the crank (:func:`m_bal_start`).
M_BAL_SWEEP_DEG = 250.0


def m_bal_start(lk: Linkage, P: Position, sense: float) -> float:
    """Where (model degrees) M_ур's arc about the crank's pivot starts, turning in the sense
    of ``sense``: its gap centred on the crank in position ``P``, so that the arc and its head
    never lie on the crank nor its number, and its label stands across the pivot from the crank
    (review 7: O, A, 1, 2, M_ур and ω1 cramped at the crank)."""
    a = P.pos[lk.joint] - lk.frame[lk.pivot]
    crank = math.degrees(math.atan2(a.y, a.x))
    return crank + math.copysign(0.5 * (360.0 - M_BAL_SWEEP_DEG), sense)


#: How far (mm) the labels of a drawing of links on the forces sheet keep from the centre
#: lines of its links, joints, hatching, arcs and arrows where they can (about half a mm of
#: paper between a letter and a main line's ink): no letter touching a joint's circle, an
#: arc or a hatch (:attr:`~geomcad.sheet.placer.LabelRequest.keep`).
LABEL_KEEP_MM = 1.0
#: The room (mm) an arrow's label takes past its tip.
LABEL_ROOM_MM = 6.0
#: The longest load arrow on Zhukovsky's lever (mm).
LEVER_LOAD_MM = 40.0
#: The paper (mm) the lever drawn larger than the layout drew it (:meth:`_Lever.grow`) keeps
#: free inside its box's edges.
LEVER_EDGE_MM = 2.0
#: The share of a view's larger drawn side that its longest load arrow may take where that is
#: more than its least room (LOAD_MM, LEVER_LOAD_MM): a view drawn large draws its forces long,
#: so that fewer of them are short there and drawn again in insets (:func:`arrow_room`).
ARROW_SHARE = 1.0 / 3.0


#: The share of a view's larger drawn side its longest load arrow may take where that draws a
#: force the view shows (the lever's P_ур, a free body's reaction) in the view itself rather
#: than only in an inset (:meth:`_ByScale.scales_at`).
KEEP_SHARE = 1.0


def arrow_room(least: float, margin: float, size: tuple[float, float]) -> float:
    """The room (mm) of the longest load arrow of a view drawn ``size`` (mm, without its
    margin): :data:`ARROW_SHARE` of its larger side, at least ``least``, at most ``margin`` and
    half its smaller side (an arrow at a point of the drawing, leaving it or arriving at it,
    then keeps inside the view's box)."""
    w, h = size
    return max(least, min(ARROW_SHARE * max(w, h), margin + 0.5 * min(w, h)))


class _ByScale:
    """A view's force scales as its drawn size makes them (:func:`arrow_room`): ``fs`` those of
    its least room until it is drawn (:meth:`scales_at` ``None``: the layout reserves its
    caption's line of insets from them; a larger room leaves out and draws short no more
    forces), :meth:`scales_at` those at a length scale, which :meth:`placed` makes the view's
    ``fs`` (and its ``omitted``, the forces ``_named`` it leaves out)."""

    fs: ForceScales
    margin: float
    omitted: list[str]
    _ext: tuple[float, float, float, float]
    _forces: list[float]
    _named: list[tuple[str, float]]
    _least: float
    #: the forces never left out (a free body's reactions, the lever's P_ур)
    _keep: tuple[float, ...] = ()
    #: the loads the file gives (F_B, a moment's pair of forces): never without a scale
    _given: tuple[float, ...] = ()
    #: whether :meth:`scales_at` draws the arrows longer, up to KEEP_SHARE, where that draws a
    #: force of ``_keep`` in the view rather than only in an inset (the lever: only once it is
    #: drawn as large as its box allows, :meth:`_Lever.grow`, a larger lever first)
    _keep_long: bool = True

    def arrows(self) -> list[tuple[Vec, Vec]]:
        """The forces the view draws as arrows (point, force; model units)."""
        raise NotImplementedError

    def scales_at(self, scale: Scale | None) -> ForceScales:
        """The view's force scales drawn at ``scale``: of the rooms up to its
        :func:`arrow_room`, the coarsest μ_F that leaves out fewest forces and then draws
        fewest in insets (a longer arrow in the view gives its insets more room,
        :func:`~geomcad.sheet.loads.view_scales`), where each of its arrows, drawn at its
        point (leaving it or arriving at it), keeps within the drawing's extent and margin
        (none over its top: the caption); where a force is still left out, a room up to
        :data:`ARROW_SHARE` of the view's larger side that leaves out fewer and keeps within
        them; else its least room's μ_F (``None``: those)."""
        memo: dict[float | None, ForceScales] = self.__dict__.setdefault("_by_scale", {})
        key = None if scale is None else scale.k
        if key in memo:
            return memo[key]
        least = memo.get(None) or view_scales(self._forces, self._least, self._keep, self._given)
        memo[None] = fs = least
        if scale is not None:
            x0, y0, x1, y1 = self._ext
            room = arrow_room(self._least, self.margin, (scale.mm(x1 - x0), scale.mm(y1 - y0)))
            m = self.margin * scale.k
            box = (x0 - m, y0 - m, x1 + m, y1)  # the caption over the drawing
            r = self._least
            fs = view_scales(self._forces, r, self._keep, self._given)
            while r < room:
                r = min(room, r * 1.25)
                at = view_scales(self._forces, r, self._keep, self._given)
                # as costly: the longer arrows (the view's room used, review 7 item 2)
                if (self._cost(at), at.k) < (self._cost(fs), fs.k) and self._fits(at, scale, box):
                    fs = at
            # a force still left out (a reaction of a free body): longer arrows, up to
            # ARROW_SHARE of the view's larger side, where they keep within its box
            far = ARROW_SHARE * max(scale.mm(x1 - x0), scale.mm(y1 - y0))
            while self._cost(fs)[0] and r < far:
                r = min(far, r * 1.25)
                at = view_scales(self._forces, r, self._keep, self._given)
                if self._cost(at)[0] < self._cost(fs)[0] and self._fits(at, scale, box):
                    fs = at
            # a force the view shows (the lever's P_ур, a free body's reaction) still drawn
            # only in an inset: longer arrows, up to KEEP_SHARE of the view's larger side,
            # where they keep within its box (review 15: the knuckle press's P_ур in inset
            # Л1 at a third μ_F, its lever showing F_D alone)
            most = KEEP_SHARE * max(scale.mm(x1 - x0), scale.mm(y1 - y0))
            while self._keep_long and self._cost(fs)[1] and r < most:
                r = min(most, r * 1.25)
                at = view_scales(self._forces, r, self._keep, self._given)
                if self._cost(at)[:2] < self._cost(fs)[:2] and self._fits(at, scale, box):
                    fs = at
        memo[key] = fs
        return fs

    def outline(self) -> list[tuple[Vec, Vec]]:
        """The lines of the links the view draws (model units): an arrow along one of them
        would be hidden by it (none: a view without links)."""
        return []

    def _fits(self, fs: ForceScales, scale: Scale, box: tuple[float, float, float, float]) -> bool:
        """Whether each arrow of the view at ``fs`` drawn at ``scale`` at its point, leaving
        it or arriving at it, keeps within ``box`` (model units): of the two, one that runs
        along none of the view's links (:meth:`outline`, :func:`side_run`) where one does (a
        load along its link leaves its point outside the link, on the side away from it,
        with the room it takes there: review 14, the clipper's F_N along its knife bar)."""
        lines = self.outline()
        for p, F in self.arrows():
            if fs.tier(F.norm) == 0:
                u = F * (scale.k / fs.k)
                ends = [p + u, p - u]
                if lines:
                    free = [e for e in ends
                            if side_run(e if e is ends[1] else p, u, scale.k, lines)
                            <= SIDE_RUN_MM + AT_POINT_MM]  # fmt: skip
                    ends = free or ends
                if not any(_within((e.x, e.y), box, 0.1 * scale.k) for e in ends):
                    return False
        return True

    def placed(self, at: Placed) -> ForceScales:
        """The view's ``fs`` where it is drawn (:meth:`scales_at` its scale), each of its
        insets at one μ_F (:func:`~geomcad.sheet.insets.one_scale_per_inset`)."""
        self.fs = self.scales_at(at.scale)
        if at.viewport is not None:
            self.fs = one_scale_per_inset(self.fs, self.arrows(), at.viewport)
        self.omitted = omitted_values(self.fs, self._named)
        return self.fs

    def further_room(self) -> float:
        """The room (mm) of the lines under the view's caption at its least room's scales,
        wrapped at its caption's width."""
        assert isinstance(self, View)  # a mixin of the views
        fs = self.scales_at(None)
        return further_room(fs, omitted_values(fs, self._named, True), title_width(self))

    def _shorts(self, fs: ForceScales) -> int:
        """How many of the view's forces ``fs`` draws in insets."""
        return sum(1 for F in self._forces if fs.tier(F) not in (0, None))

    def _cost(self, fs: ForceScales) -> tuple[int, int, int, int]:
        """How many of the view's forces ``fs`` draws to no scale (named, not drawn, or a
        direction arrow), how many of those it shows (``_keep``: the lever's P_ур, a free
        body's reactions) it draws only in insets, whether its insets' longest arrow outgrows
        the view's shortest (a reaction drawn past their cap), and how many it draws in
        insets."""
        left = sum(1 for F in self._forces
                   if fs.zero < F and (fs.tier(F) is None or fs.is_fixed(F)))  # fmt: skip
        kept = sum(1 for F in self._keep if fs.zero < F and fs.tier(F) not in (0, None))
        return left, kept, int(fs.over > 1.0 + tol.DERIVED), self._shorts(fs)


#: The least length (mm) of a force plan's longest vector (a course project draws its plans
#: 100–200 mm long): the sheet takes a larger format rather than draw them smaller.
PLAN_MM = 100.0
#: … and on the largest format, where nothing larger is left, the search's aim for it.
PLAN_SEEK_MM = 80.0
#: The width of the note under the table of loads (mm), for 2.5 mm text.
TABLE2_W = 60.0
#: The scale group of the force sheet's drawings of links: the mechanism, its groups, its crank.
L_GROUP = "l"
#: The scale group of the groups and the crank cut out where they cannot share the mechanism's.
GROUPS_L = "lg"
#: The arrangements of sheet 2 its layout searches (:func:`_sheet2`; one more where ``under``).
ARRANGEMENTS = 4
#: The scale group of the crank cut out where the mechanism's μ_l draws the crank shorter than
#: CRANK_MM: its own μ_l, stated in its caption, at which the crank is CRANK_MM long.
CRANK_L = "lc"
#: The weight of a millimetre the crank is drawn short of CRANK_MM on the mechanism (a group of
#: its own μ_l short of GROUPS_SHARE) in :func:`_held`'s search, against
#: a millimetre a force plan's longest vector falls short of its seek (:data:`PLAN_SEEK_MM`):
#: the size rule is a constraint, the plans' seek a wish (review 7: the yoke pump's crank at
#: 15 mm, 1:4, traded for plans 100 mm longer).
CRANK_WEIGHT = 20.0


def force_position(s: Solved) -> tuple[Position, Forces, int | None]:
    """The position drawn on sheet 2, its forces and its number (``None``: a ``[forces] phi``
    that is none of the numbered positions): the force analysis' position of
    :func:`~geomcad.linkage.analysis.analyse` (``[forces]``, else its default)."""
    a = analyse(s)
    assert a.force_position is not None and a.force_forces is not None
    return a.force_position, a.force_forces, a.force_index


def force_sheets(
    s: Solved,
    stem: str = "",
    first_no: int = 2,
    count: int = 0,
    failures: list[tuple[str, Exception]] | None = None,
) -> list[tuple[str, Sheet]]:
    """Sheet 2 (where the file gives masses or loads) and sheet 3 (with ``[dynamics]``),
    numbered from ``first_no`` of ``count`` sheets (0: these are the last ones).

    Each sheet is drawn on its own (review 14: the forces layout that failed cost a file all
    its sheets): with ``failures`` given, a sheet that raises a :class:`GeomcadError` is
    ``(name, None)`` in the list, keeping its number, and its error is appended to ``failures``;
    without, the error propagates."""
    a = analyse(s)
    mine = (a.forces is not None) + (a.flywheel is not None)
    count = count or first_no - 1 + mine
    designation = KIN_WORDS("designation", stem=stem or KIN_WORDS("stem"))
    out: list[tuple[str, Sheet]] = []
    no = first_no
    jobs: list[tuple[str, Callable[[int], Sheet]]] = []
    if a.forces is not None:
        jobs.append(("forces", lambda n: _forces_sheet(s, designation, n, count)))
    if a.flywheel is not None:
        flywheel = a.flywheel
        jobs.append(("dynamics", lambda n: _dynamics_sheet(s, flywheel, designation, n, count)))
    for name, job in jobs:
        try:
            out.append((name, job(no)))
        except GeomcadError as exc:
            if failures is None or not SheetsFailed.sheet_own(exc):
                raise
            failures.append((name, exc))
            out.append((name, None))  # type: ignore[arg-type]  # its place kept
        no += 1
    return out


def _forces_sheet(s: Solved, designation: str, no: int, count: int) -> Sheet:
    """Sheet 2: the loaded mechanism, its groups, the force plans and Zhukovsky's lever."""
    lk = s.linkage
    for grow in (True, False):
        tree, z = force_layout(s, grow)
        d = z.start(_title(lk, WORDS("forces"), designation, no, count))
        compose(d, tree, layout=z.layout)
        held = [pl.view.sheet_detail(d, pl) for pl in z.layout if isinstance(pl.view, _Loaded)]
        if all(held):
            break
        # the plans grown into the room the short crank's detail wanted (review 7: a 20 mm
        # crank and no detail): the sheet drawn again with the plans as laid out
    main = [pl.scale for pl in z.layout if isinstance(pl.view, _Loaded)]
    if d.sheet.block is not None and main and main[0] is not None:
        # the title block's Масштаб: the main view's, the loaded mechanism's
        d.sheet.block = replace(d.sheet.block, scale=main[0].ratio_text())
    return d.finish()


def _dynamics_sheet(s: Solved, flywheel: Flywheel, designation: str, no: int, count: int) -> Sheet:
    """Sheet 3: the flywheel by Wittenbauer's method."""
    lk = s.linkage
    tree, z = fit(lambda h: (_sheet3(s, flywheel, h), {}), sheet_formats(lk))
    # its diagrams have no length scale: "—" in the Масштаб cell, as on the velocity plans'
    # sheet (review 17: the cell left empty on the dynamics sheet alone)
    d = z.start(replace(_title(lk, WORDS("dynamics"), designation, no, count), scale=NO_SCALE))
    compose(d, tree, layout=z.layout)
    return d.finish()


#: The formats the forces layout falls back on (:func:`force_layout`), set while it does.
_FALLBACK: contextvars.ContextVar[tuple[str, ...] | None] = contextvars.ContextVar(
    "forces_fallback", default=None
)


def _formats(lk: Linkage) -> tuple[str, ...]:
    """The formats the forces sheet may take: the file's (:func:`sheet_formats`), or the
    larger one it falls back on (:func:`force_layout`)."""
    return _FALLBACK.get() or sheet_formats(lk)


def fallback_formats(lk: Linkage) -> tuple[str, ...]:
    """The next larger format after the largest the file's sheets may take (A1 → A0), where
    there is one: the forces sheet's last resort before it fails (review 14). None where the
    file states its ``[sheet] format``: a format the student was given is kept, and a sheet
    with no room on it fails, naming the view (a course project on A1 is not handed in on A0)."""
    if lk.sheet and lk.sheet.get("format") is not None:
        return ()
    order = sorted(FORMATS, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    largest = max(sheet_formats(lk), key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    bigger = order[order.index(largest) + 1 :]
    return (bigger[0],) if bigger else ()


def force_layout(s: Solved, grow: bool = True) -> tuple[Tree, formats.Sized]:
    """Sheet 2's tree and its format and arrangement (:func:`_compose2`; for the size rules'
    bench and the tests: the scales and the format without drawing).

    A layout that finds no room for a view on the file's formats (``ParameterError`` "has no
    room on the sheet", review 14: the pump's plan of group (4, 5) at its position 4 cost the
    file all its sheets) falls back on the next larger format (:func:`fallback_formats`, A1 →
    A0) before it fails: a sheet larger than planned beats no sheet. ``grow``: the force plans
    grown into the field once laid out (:func:`_fit_and_grow_plans`)."""
    try:
        return _force_layout(s, grow)
    except ParameterError as exc:
        more = fallback_formats(s.linkage) if exc.name == "layout" else ()
        if not more:
            raise
        token = _FALLBACK.set(more)
        try:
            return _force_layout(s, grow)
        except ParameterError:
            raise exc from None
        finally:
            _FALLBACK.reset(token)


def _force_layout(s: Solved, grow: bool = True) -> tuple[Tree, formats.Sized]:
    """:func:`force_layout` on the formats :func:`_formats` gives."""
    P, forces, k = force_position(s)
    waived = sweep_mm(s, crank_scale(s.linkage).k) > SWEEP_MAX_MM
    # where the sweep waives the crank's length, the mechanism sought at the kinematic sheet's μ_l
    kin: float | None = kinematic_scale(s).k if waived else None
    found = _compose2(s, P, forces, k, _formats(s.linkage), kin=kin)
    if not found[1].layout.fits and kin is not None:
        # the kinematic sheet's μ_l keeps the sheet from fitting: the next coarser GOST steps
        # one by one, then the mechanism as large as the field draws it (a kinematic sheet at
        # 1:4 beside a forces sheet at 1:5, not at 1:10)
        for step in (*_coarser(kin), None):
            kin = step
            found = _compose2(s, P, forces, k, _formats(s.linkage), kin=kin)
            if found[1].layout.fits:
                break
    if not _crank_kept(found[1].layout):
        found = _held(s, P, forces, k, found, kin)
    lay = found[1].layout
    if _crank_short(lay):
        # the mechanism's μ_l draws the crank short (its detail enlarges it there): the crank
        # cut out at a μ_l of its own that draws it CRANK_MM long, on the same format, where
        # that fits
        shared = not any(isinstance(pl.view, _FreeBody) and pl.view.group == GROUPS_L
                         for pl in lay)  # fmt: skip
        fmts = _formats(s.linkage)
        largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
        under = isinstance(found[0], Choice) and len(found[0].items) > ARRANGEMENTS
        own, _kept = _final2(s, P, forces, k, found[1], shared, largest, kin, True, under)
        # its own μ_l may take other views' room: where it overflows by less than the crank
        # cut out was short (review 7: the oscillator's 20 mm crank, its 1:1 over A1 by a
        # plan's 1.8 mm vector)
        lost = -own[1].layout.score[0] if not own[1].layout.fits else 0.0
        # (never at the cost of the mechanism's own crank)
        kept = _crank_kept(own[1].layout) or not _crank_kept(lay)
        if (
            kept
            and not _crank_short(own[1].layout)
            and (not lay.fits or lost < _crank_shortfall(lay))
        ):
            found = own
    found = _rowed(s, P, forces, k, found, kin)
    found = _pinned(s, P, forces, k, found, kin)
    if grow:  # (not where the plans grown leave a short crank's detail no room)
        _fit_and_grow_plans(found[1].layout)
    for pl in found[1].layout:
        if isinstance(pl.view, _Lever):
            pl.view.grow(pl, found[1].layout)
        elif isinstance(pl.view, _FreeBody):
            pl.view.grow(pl)
    return found


def _fit_and_grow_plans(lay: Layout) -> None:
    """The force plans' cells fitted to their shapes (:func:`_fitted_plans`) and the plans
    grown into them (:func:`grow_plan`), the shapes taken at the μ_F each was placed at or
    at the next finer step of its series, whichever grows the plans more (the product of
    their growths; the first on a tie). A detail keeps its size in mm at any μ_F, so a plan
    whose details lie beside it at the μ_F placed may have them under it a step finer: the
    crusher's group (4, 5), 36 × 49 mm with its detail beside it at 200 N/mm, cut a row cell
    112 mm high, and stayed at 200 N/mm (its longest vector 47 mm) where a column cell held
    it at 100 N/mm."""
    plans = [pl for pl in lay if isinstance(pl.view, Polygon) and pl.scale is not None]
    was = [(pl.box, pl.inner, pl.scale) for pl in plans]

    def run(finer: bool) -> float:
        for pl, (box, inner, scale) in zip(plans, was, strict=True):
            pl.box, pl.inner, pl.scale = box, inner, scale
        _fitted_plans(lay, finer)
        for pl in plans:
            grow_plan(pl)
        return sum(math.log(sc.k / pl.scale.k) for pl, (_b, _i, sc) in zip(plans, was, strict=True)
                   if sc is not None and pl.scale is not None)  # fmt: skip

    grown = [run(False), run(True)]
    if grown[0] >= grown[1] - tol.REL_LENGTH:
        run(False)


def grow_plan(pl: Placed) -> None:
    """A force plan drawn at a finer μ_F of its series where its box holds it (review 9,
    fix 9: plans 25–60 mm in cells twice their size, the sheets 44–54 % blank): the layout
    reckoned its extent with its details' slots at its reference μ_F, and a detail keeps its
    size in mm at any μ_F, so at the μ_F placed the plan with its details, planned again as
    :meth:`Polygon.draw` plans them, may leave its box room for a finer step. Each finer step
    is tried while the whole keeps within the box it is centred in (a sliver stays capped:
    :attr:`Polygon.longest_mm`); the first that does not ends the search."""
    view = pl.view
    assert isinstance(view, Polygon)
    if pl.scale is None:
        return
    if view.drawn_k(pl.scale.k) != pl.scale.k:
        _grow_sliver(pl)
        return
    x0, y0, x1, y1 = pl.inner
    w, h = x1 - x0, y1 - y0
    best = pl.scale.k
    k = best
    for _ in range(GROW_STEPS):
        k = round_scale_down(k * (1.0 - 4.0 * tol.REL_LENGTH), pl.scale.q, view.series).k
        if view.drawn_k(k) != k:
            break  # a sliver at its cap
        if view.detail:
            _d, _t, ext = view._with_details(k, iter("W" * 99), (w * k, h * k))
        else:
            ext = view.extent() or (0.0, 0.0, 0.0, 0.0)
        if (ext[2] - ext[0]) / k > w + tol.SHEET_MM or (ext[3] - ext[1]) / k > h + tol.SHEET_MM:
            break
        best = k
    if best != pl.scale.k:
        pl.scale = Scale(best, pl.scale.q)
    if view.detail:  # the details as at the μ_F placed (drawn again so)
        view._with_details(pl.scale.k, iter("W" * 99), (w * pl.scale.k, h * pl.scale.k))


#: The finer steps of its series :func:`grow_plan` tries for a plan.
GROW_STEPS = 8

#: A sliver (:func:`views.is_sliver`, reckoned by the layout with its longest vector at most
#: SLIVER_MM) is drawn with it at most this long (mm) where its box holds it so, details and
#: all: the μ_F series' steps 5 → 10 and 1 → 2 left a 60 mm cap drawing 3458 N at 100 N/mm,
#: 35 mm in a 138 mm cell (review 11, item 2: the forces sheet's plans 30–50 mm, the field
#: half blank). The two long vectors stay one thin closed figure, the equality under it.
SLIVER_GROW_MM = 80.0


def _grow_sliver(pl: Placed) -> None:
    """A sliver placed at its cap drawn at the finer μ_F of its series that draws its longest
    vector at most SLIVER_GROW_MM long, where the whole, its details planned again at that
    μ_F as :meth:`Polygon.draw` plans them, keeps within the box it is centred in."""
    view = pl.view
    assert isinstance(view, Polygon) and pl.scale is not None
    x0, y0, x1, y1 = pl.inner
    w, h = x1 - x0, y1 - y0
    was = view.longest_mm
    view.longest_mm = SLIVER_GROW_MM
    k = view.drawn_k(pl.scale.k)
    if view.detail:
        _d, _t, ext = view._with_details(k, iter("W" * 99), (w * k, h * k))
    else:
        ext = view.extent() or (0.0, 0.0, 0.0, 0.0)
    if (ext[2] - ext[0]) / k > w + tol.SHEET_MM or (ext[3] - ext[1]) / k > h + tol.SHEET_MM:
        view.longest_mm = was


#: The growth :func:`_fitted_plans` seeks for the plans in their new cells, at most (a plan
#: drawn this many times its placed size), and the steps of its search.
FIT_GROW_MOST = 6.0
FIT_GROW_STEPS = 24
#: The slack (mm) a fitted cell keeps round the plan's reckoned need (the details are planned
#: again in it, :func:`grow_plan`).
FIT_SLACK_MM = 2.0


def _plan_need(pl: Placed, finer: bool = False) -> tuple[float, float, bool]:
    """The size (mm) of a force plan as placed, its details planned in its box at its μ_F,
    and whether it keeps that size at any μ_F (a sliver, drawn at its cap); ``finer``: its
    shape as planned at the next finer step of its series, drawn at the μ_F placed (the
    details, which keep their size in mm, then take less of it)."""
    view = pl.view
    assert isinstance(view, Polygon) and pl.scale is not None
    w, h = pl.size
    fixed = view.longest_mm > 0.0
    was = view.longest_mm
    if fixed:
        view.longest_mm = max(was, SLIVER_GROW_MM)
    k = view.drawn_k(pl.scale.k)
    if view.detail:
        kk = k
        if finer and not fixed:
            kk = round_scale_down(k * (1.0 - 4.0 * tol.REL_LENGTH), pl.scale.q, view.series).k
        _d, _t, ext = view._with_details(kk, iter("W" * 99), (w * kk, h * kk))
    else:
        ext = view.extent() or (0.0, 0.0, 0.0, 0.0)
    view.longest_mm = was
    return (ext[2] - ext[0]) / k, (ext[3] - ext[1]) / k, fixed


def _partitions(n: int) -> Iterator[list[int]]:
    """The ways to cut a run of ``n`` items into consecutive runs: the runs' lengths."""
    for cuts in itertools.product((False, True), repeat=max(n - 1, 0)):
        runs, run = [], 1
        for c in cuts:
            if c:
                runs.append(run)
                run = 1
            else:
                run += 1
        runs.append(run)
        yield runs


def _shared(sizes: Sequence[float], spare: float, grows: Sequence[bool]) -> list[float]:
    """``sizes`` with the ``spare`` room shared among them in proportion, only among those
    that ``grows`` (a plan that grows into it; a sliver keeps its size at its cap, and its
    cell would be left blank) where any does."""
    if not any(grows):
        grows = [True] * len(sizes)
    total = sum(sz for sz, g in zip(sizes, grows, strict=True) if g)
    return [sz + spare * sz / total if g else sz for sz, g in zip(sizes, grows, strict=True)]


def _fitted_plans(lay: Layout, finer: bool = False) -> None:
    """The force plans' cells fitted to the plans' own shapes (review 13, item 1: the plans
    shared a Grid of equal cells, a 116 × 6 mm sliver's cell as large as a square plan's, the
    square plans 54 mm long in 170 × 83 mm cells, the sheets 59–77 % blank). Once the layout
    has placed them, the region their Grid took (where no other view's box reaches into it)
    is cut again, the plans in their order, into rows (or columns) of cells each as large as
    its plan needs: the plans drawn the same number of times larger (a sliver, capped at its
    length, at its size), the largest that fits, every cell at least as wide as its caption;
    the spare room shared among the cells in proportion. The plans are then grown into them
    (:func:`grow_plan`). Nothing is drawn coarser: the cut is taken only where it holds every
    plan at its placed size."""
    plans = [pl for pl in lay if isinstance(pl.view, Polygon) and pl.scale is not None]
    if len(plans) < 2 or len(plans) > 8:
        return
    X0 = min(pl.box[0] for pl in plans)
    Y0 = min(pl.box[1] for pl in plans)
    X1 = max(pl.box[2] for pl in plans)
    Y1 = max(pl.box[3] for pl in plans)
    e = tol.SHEET_MM
    mine = {id(pl) for pl in plans}
    for pl in lay:
        if id(pl) in mine:
            continue
        b = pl.box
        if b[0] < X1 - e and b[2] > X0 + e and b[1] < Y1 - e and b[3] > Y0 + e:
            return  # the plans' boxes are not one region of their own
    needs = [_plan_need(pl, finer) for pl in plans]
    # a cell's frame round its plan: the margins, the caption's room over it
    pads = [
        (
            2.0 * pl.view.margin + FIT_SLACK_MM,
            pl.view.title_room() + 2.0 * pl.view.margin + FIT_SLACK_MM,
        )
        for pl in plans
    ]
    least_w = [title_width(pl.view) + FIT_SLACK_MM for pl in plans]
    W, H = X1 - X0, Y1 - Y0

    def cell(i: int, g: float) -> tuple[float, float]:
        nw, nh, fixed = needs[i]
        f = 1.0 if fixed else g
        return max(nw * f + pads[i][0], least_w[i]), nh * f + pads[i][1]

    def holds(runs: list[int], g: float, across: bool) -> bool:
        i = 0
        used = 0.0
        for r in runs:
            cells = [cell(j, g) for j in range(i, i + r)]
            i += r
            if across:  # rows: the widths side by side, the row as high as its highest
                if sum(c[0] for c in cells) + GAP * (r - 1) > W + e:
                    return False
                used += max(c[1] for c in cells)
            else:  # columns
                if sum(c[1] for c in cells) + GAP * (r - 1) > H + e:
                    return False
                used += max(c[0] for c in cells)
        return used + GAP * (len(runs) - 1) <= (H if across else W) + e

    best: tuple[float, list[int], bool] | None = None
    for runs in _partitions(len(plans)):
        for across in (True, False):
            if not holds(runs, 1.0, across):
                continue
            lo, hi = 1.0, FIT_GROW_MOST
            if holds(runs, hi, across):
                lo = hi
            for _ in range(FIT_GROW_STEPS):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if holds(runs, mid, across) else (lo, mid)
            if best is None or lo > best[0] * (1.0 + tol.REL_LENGTH):
                best = (lo, runs, across)
    if best is None:
        return
    g, runs, across = best
    # the cells at that growth, the spare room shared in proportion to their sizes
    i = 0
    lines = []
    for r in runs:
        lines.append([(j, cell(j, g)) for j in range(i, i + r)])
        i += r
    deep = [max(c[1] if across else c[0] for _j, c in ln) for ln in lines]
    spare = (H if across else W) - sum(deep) - GAP * (len(lines) - 1)
    deep = _shared(deep, spare, [any(not needs[j][2] for j, _c in ln) for ln in lines])
    at = Y0 if across else X0
    for ln, d in zip(lines, deep, strict=True):
        long = [c[0] if across else c[1] for _j, c in ln]
        room = (W if across else H) - sum(long) - GAP * (len(ln) - 1)
        long = _shared(long, room, [not needs[j][2] for j, _c in ln])
        pos = X0 if across else Y0
        for (j, _c), s in zip(ln, long, strict=True):
            box = (pos, at, pos + s, at + d) if across else (at, pos, at + d, pos + s)
            pl, v = plans[j], plans[j].view
            top = box[1] + v.title_room()
            pl.box = box
            pl.inner = (box[0] + v.margin, top + v.margin, box[2] - v.margin, box[3] - v.margin)
            pos += s + GAP
        at += d + GAP


def _rowed(
    s: Solved, P: Position, f: Forces, k: int | None, found: tuple[Tree, formats.Sized],
    kin: float | None,
) -> tuple[Tree, formats.Sized]:  # fmt: skip
    """Once the search has chosen: the arrangement of the drawings of links and the lever side
    by side over the polygons and the tables (``rowed``, :func:`_sheet2`), on the same format
    with the groups and the crank cut out at the μ_l they have, where it draws every view at
    least as large as the one found (no scale coarser), keeps the crank's and the groups'
    rules, its tables whole and its polygons' details in their boxes, and the search scores it
    higher (review 8: the press's mechanism 53 mm wide in a 251 mm box over the lever, its
    plans at 100 N/mm; side by side, two of its plans at 50 N/mm). Tried alone, after the
    search (a sixth arrangement in the joint search would cost every sheet's layout)."""
    lay = found[1].layout
    shared = not any(isinstance(pl.view, _FreeBody) and pl.view.group == GROUPS_L for pl in lay)
    own = any(isinstance(pl.view, _FreeBody) and pl.view.group == CRANK_L for pl in lay)
    under = isinstance(found[0], Choice) and len(found[0].items) > ARRANGEMENTS
    tree, _w = _sheet2(s, P, f, k, TEXT_H, None, shared, kin, own, under, rowed=True)
    last = len(_alternatives(tree)) - 1
    try:
        cand, _rules = _final2(s, P, f, k, found[1], shared, found[1].fmt, kin, own, under,
                               only=last, rowed=True)  # fmt: skip
    except ParameterError:
        # the row has no room for a view on this format (review 11: a 12 mm crank's groups
        # beside a rocker's long arm): the arrangement found stands
        return found
    got = cand[1].layout
    was = {(type(pl.view).__name__, pl.view.title): pl.scale.k for pl in lay if pl.scale}
    now = {(type(pl.view).__name__, pl.view.title): pl.scale.k for pl in got if pl.scale}
    larger = was.keys() == now.keys() and all(
        now[key] <= kk * (1.0 + tol.REL_LENGTH) for key, kk in was.items()
    )
    if (
        larger
        and got.score > lay.score
        and _crank_kept(got)
        and _groups_kept(got)
        and _whole(got)
        and not _spilt(got)
    ):
        return cand
    return found


def _pinned(
    s: Solved, P: Position, f: Forces, k: int | None, found: tuple[Tree, formats.Sized],
    kin: float | None,
) -> tuple[Tree, formats.Sized]:  # fmt: skip
    """Once the search has chosen, on the largest format: the mechanism, its groups and its
    crank at ONE μ_l with the crank at least CRANK_MM long on it, the μ_l pinned as a
    constraint (:func:`_sheet2`'s ``pin``), where the search left them apart (groups at 1:4
    beside a 1:2 mechanism, a crank cut out alone at 1:1) or the crank short (review 10: the
    slider-rocker's 20 mm crank at 1:2.5, the sine mechanism's 18 mm at 1:2.5 where a 1:1 band
    across the top holds 45 mm): the GOST steps from the coarsest that keeps the crank's rule,
    finer while one holds; and, where the search kept the rule, the views grown into the
    field: the next finer steps while the sheet holds every other view at a scale no coarser
    (review 10: kulisa at 1:4 on a 52 %-blank A1). A step is taken where the sheet fits with
    its tables whole, its plans' details in their boxes and the crank kept at the step; the
    first that fails ends the search (a finer one needs more room still)."""
    lk = s.linkage
    fmts = _formats(lk)
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    best = found
    lay = found[1].layout
    if found[1].fmt != largest:
        return found  # a smaller format holds the sheet with its rules: it is full enough
    main = [pl.scale.k for pl in lay if isinstance(pl.view, _Loaded) and pl.scale is not None]
    if not main:
        return found
    mk = main[0]
    e = 1.0 + tol.REL_LENGTH
    one = all(pl.scale.k <= mk * e and pl.scale.k >= mk / e for pl in lay
              if isinstance(pl.view, _FreeBody) and pl.scale is not None)  # fmt: skip
    kept = one and lk.length / mk >= CRANK_MM / e
    steps = sorted((g for g in GOST_K if lk.length / g >= CRANK_MM / e), reverse=True)
    if kept:
        steps = [g for g in steps if g < mk / e][:GROW_L_STEPS]
    field = Field.of_format(largest, True)
    room = (field.box[2] - field.box[0], field.box[3] - field.box[1])
    w, h = sweep_box(s)
    for pin in steps:
        if w / pin > room[0] or h / pin > room[1]:
            break  # the mechanism alone is larger than the field
        # one μ_l; where none holds, the groups at a coarser one of their own, at least
        # GROUPS_SHARE of the mechanism's size, said in their captions
        # (only where that lengthens the mechanism's crank: groups apart for groups apart
        # would only move the views)
        short = lk.length / mk < CRANK_MM / e
        own = [g for g in _coarser(pin) if pin / g >= GROUPS_SHARE / e] if short else []
        for pg in (pin, *own):
            got_one = _pin_try(s, P, f, k, kin, largest, field, pin, pg)
            # (the plans keep their μ_F: one step of their series coarser at most where the
            # rule is mended, none where the views only grow)
            # (or, where the views grow, coarser plans while each still reads: the larger
            # μ_l wins over larger plans down to PLAN_READ_MM, review 11: kulisa at 1:4)
            # (and where the search left the groups apart from a mechanism that keeps the
            # crank's rule, one μ_l outranks larger plans the same way: review 13, the gang
            # saw's groups at 1:15 beside its 1:10, the yarn traverse's at 2:1 beside 2,5:1)
            if got_one is not None and (
                short
                or _no_coarser(best[1].layout, got_one[1].layout, not kept)
                or (
                    (kept or not one)
                    and _no_coarser(best[1].layout, got_one[1].layout, plans=False, lever=not one)
                    and _plans_read(got_one[1].layout)
                )
            ):
                break
        else:
            break
        best, kept = got_one, True
        if pg != pin:
            break  # the groups apart: the mechanism grows no further
    if not kept and lk.length / mk < CRANK_MM * CRANK_FLOOR / e:
        # no step holds the crank's rule (review 11: a 12 mm crank wants 2,5:1, the traverse's
        # mechanism then takes the sheet's height; review 13: the coining press's 55 mm crank
        # wants 1:1, its 0,65 m stroke then twice the field's height): the finest step between
        # that keeps the sheet, the crank as long as the field lets it be (1:2 with the crank
        # enlarged in a detail, not the search's 1:10 with a 5,5 mm crank), also where the
        # sweep waives the crank's rule (the kinematic sheet's μ_l only a floor then: the
        # crusher at 1:4, not 1:5); only under CRANK_FLOOR of the rule (above, the crank's
        # detail reads it: at 1:2 the sine file's leaves its detail no room)
        first = steps[0] if steps else min(GOST_K)
        for pin in sorted(g for g in GOST_K if first * e < g < mk / e):
            if w / pin > room[0] or h / pin > room[1]:
                continue
            for pg in (pin, *[g for g in _coarser(pin) if pin / g >= GROUPS_SHARE / e]):
                got_one = _pin_try(s, P, f, k, kin, largest, field, pin, pg)
                if got_one is not None:
                    return got_one
    return _enlarged(s, P, f, k, kin, largest, field, best)


def _enlarged(
    s: Solved, P: Position, f: Forces, k: int | None, kin: float | None, fmt: str,
    field: Field, found: tuple[Tree, formats.Sized],
) -> tuple[Tree, formats.Sized]:  # fmt: skip
    """Where the sheet ``found`` draws the crank shorter than CRANK_MM on the mechanism and on
    the crank cut out both (no finer μ_l holds the mechanism: review 13, the knot's 50 mm crank
    at 1:2 beside a 1:1 that overflows A1): the same μ_l pinned (:func:`_pin_try`), the crank
    cut out enlarged at the μ_l that draws it CRANK_MM long, stated in its caption; ``found``
    where that does not fit."""
    lay = found[1].layout
    lk = s.linkage
    main = [pl.scale.k for pl in lay if isinstance(pl.view, _Loaded) and pl.scale is not None]
    if not main or lk.length / main[0] >= CRANK_MM * (1.0 - tol.REL_LENGTH):
        return found
    if not _crank_short(lay):
        return found
    groups = [pl.scale.k for pl in lay if isinstance(pl.view, _FreeBody)
              and pl.view.gf.group is not None and pl.scale is not None]  # fmt: skip
    got = _pin_try(s, P, f, k, kin, fmt, field, main[0], max([main[0], *groups]))
    if got is not None:
        return got
    # the pinned arrangements hold no sheet at that μ_l: the search's own arrangements with
    # the crank cut out at its own μ_l (:func:`_sheet2`'s ``crank_own``), where they keep the
    # mechanism's μ_l and every rule
    shared = not any(isinstance(pl.view, _FreeBody) and pl.view.group == GROUPS_L for pl in lay)
    under = isinstance(found[0], Choice) and len(found[0].items) > ARRANGEMENTS
    try:
        own, _kept = _final2(s, P, f, k, found[1], shared, fmt, kin, True, under)
    except ParameterError:
        return found  # the crank cut out at its own μ_l leaves a view no room
    now = own[1].layout
    again = [pl.scale.k for pl in now if isinstance(pl.view, _Loaded) and pl.scale is not None]
    if (
        now.fits
        and again
        and again[0] <= main[0] * (1.0 + tol.REL_LENGTH)
        and not _crank_short(now)
        and _groups_kept(now)
        and _whole(now)
        and not _spilt(now)
    ):
        return own
    return found


def _pin_try(
    s: Solved, P: Position, f: Forces, k: int | None, kin: float | None, fmt: str,
    field: Field, pin: float, pin_groups: float,
) -> tuple[Tree, formats.Sized] | None:  # fmt: skip
    """Sheet 2 with its drawings of links pinned (:func:`_pinned`) where it fits on ``fmt``
    with its tables whole, its plans' details in their boxes and the crank kept: of the
    arrangements of :func:`_pinned_tree`, each tried alone (the joint search would take the
    one that scores best with the pinned μ_l given up), the best that keeps them."""
    tree, _wants = _sheet2(s, P, f, k, TEXT_H, shared=True, kin=kin, pin=pin,
                           pin_groups=pin_groups)  # fmt: skip
    best: tuple[Tree, formats.Sized] | None = None
    for only, alt in enumerate(_alternatives(tree)):
        try:
            first = formats.Sized(fmt, True, arrange(alt, field))
        except ParameterError:
            continue  # a view finds no room at all
        try:
            cand, _rules = _final2(s, P, f, k, first, True, fmt, kin, pin=pin,
                                   pin_groups=pin_groups, only=only)  # fmt: skip
        except ParameterError:
            continue  # reckoned again at its plans' μ_F, a view finds no room: not this one
        got = cand[1].layout
        if (
            got.fits
            and _crank_kept(got)
            and _groups_kept(got)
            and _whole(got)
            and not _spilt(got)
            and (best is None or got.score > best[1].layout.score)
        ):
            best = cand
    return best


#: Where no GOST step holds the crank's rule, :func:`_pinned` pins the mechanism finer only
#: where the search drew its crank under this share of CRANK_MM (a 3 mm crank at 1:4), the
#: sweep waiving the rule or not (review 13: the coining press's 5,5 mm crank at 1:10);
#: above, the crank's detail reads it (the sine file's 18 mm crank and its 1:1 detail).
CRANK_FLOOR = 0.5
#: The finer GOST steps of the mechanism's μ_l :func:`_pinned` tries where the search kept
#: the crank's rule (the views grown into the field).
GROW_L_STEPS = 2


def _no_coarser(
    was: Layout, now: Layout, step: bool = False, plans: bool = True, lever: bool = False
) -> bool:
    """Whether ``now`` draws every view but the drawings of links at a scale no coarser than
    ``was`` does (the same views by kind and title); ``step``: a force plan at most one step of
    its series coarser; ``plans``: the force plans counted (else left out: :func:`_plans_read`
    judges them); ``lever``: Zhukovsky's lever at most one step of its series coarser (the
    price of one μ_l for the drawings of links, :func:`_pinned`)."""

    def scales(lay: Layout) -> dict[tuple[str, str], float]:
        links = (_Loaded, _FreeBody) if plans else (_Loaded, _FreeBody, Polygon)
        return {(type(pl.view).__name__, pl.view.title): pl.scale.k for pl in lay
                if pl.scale is not None and not isinstance(pl.view, links)}  # fmt: skip

    a, b = scales(was), scales(now)
    if step:
        a = {key: round_scale(kk * (1.0 + 4.0 * tol.REL_LENGTH), "F", "nice").k
             if key[0] == "Polygon" else kk for key, kk in a.items()}  # fmt: skip
    if lever:
        levers = {(type(pl.view).__name__, pl.view.title): pl for pl in was
                  if isinstance(pl.view, _Lever) and pl.scale is not None}  # fmt: skip
        for key, pl in levers.items():
            assert pl.scale is not None and isinstance(pl.view, _Lever)
            a[key] = round_scale(pl.scale.k * (1.0 + 4.0 * tol.REL_LENGTH), pl.scale.q,
                                 pl.view.series).k  # fmt: skip
    return a.keys() == b.keys() and all(b[key] <= kk * (1.0 + tol.REL_LENGTH)
                                        for key, kk in a.items())  # fmt: skip


#: The trade-off of the drawings of links against the force plans (fix-list 11, item 1):
#: where the search kept the crank's rule, the mechanism and its groups take the next finer
#: GOST step at the cost of coarser force plans while every plan's longest vector stays at
#: least this long (mm): half a course project's plan (:data:`PLAN_MM`), a polygon still read
#: at its own μ_F with its 7 mm arrows, the shorter ones in its details. Below it the plans
#: keep their μ_F and the links their step (kulisa at 1:2,5 with plans 55–103 mm, not at 1:4).
PLAN_READ_MM = 0.5 * PLAN_MM


def _plans_read(lay: Layout) -> bool:
    """Whether every force plan of ``lay`` but a sliver (capped at its own length,
    :attr:`Polygon.longest_mm`) draws its longest vector at least :data:`PLAN_READ_MM` long."""
    for pl in lay:
        v = pl.view
        if isinstance(v, Polygon) and pl.scale is not None and v.longest_mm <= 0.0:
            big = max((pv.magnitude for poly, _ in v.layers for pv in poly.vectors), default=0.0)
            if big / pl.scale.k < PLAN_READ_MM * (1.0 - tol.REL_LENGTH):
                return False
    return True


def _held(
    s: Solved, P: Position, f: Forces, k: int | None, found: tuple[Tree, formats.Sized],
    kin: float | None,
) -> tuple[Tree, formats.Sized]:  # fmt: skip
    """Where the search left the mechanism's crank shorter than its rule (the layout's score
    trades it against the plans' seek, :data:`PLAN_SEEK_MM`): the crank's length as a
    constraint (review 7: the yoke pump and the tangent rocking slider at 1:4 with a detail
    while half of the sheet was blank). On the largest format, every arrangement one by one
    (the one more of ``under`` too), the groups at the mechanism's μ_l, then at one μ_l of
    their own (at least :data:`GROUPS_SHARE` of its size); the first whose drawings keep the
    crank's length and the groups' share, its tables and texts whole in their boxes
    (:func:`_whole`), is taken. A detail then enlarges the crank only where no arrangement
    holds its scale. Where none does, once more with one arrangement more (``held``: the
    mechanism at its rule's scale with the tables and polygons beside it, the groups and the
    lever under it; review 8: the rocking cylinder's 55 mm crank at 1:1), that arrangement kept
    (the joint search would pass it over for a larger score, the crank short again)."""
    fmts = _formats(s.linkage)
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    for held in (False, True):
        for shared in (True, False):
            tree, wants = _sheet2(s, P, f, k, TEXT_H, shared=shared, kin=kin, under=True,
                                  weight=CRANK_WEIGHT, held=held)  # fmt: skip
            on = _on(tree, wants, largest)
            if on is None or not (_crank_kept(on[1].layout) and _groups_kept(on[1].layout)):
                continue
            only = next(i for i, alt in enumerate(_alternatives(tree)) if alt is on[0])
            kept, _rules = _final2(s, P, f, k, on[1], shared, largest, kin, under=True,
                                   weight=CRANK_WEIGHT, held=held,
                                   only=only if held else None)  # fmt: skip
            lay = kept[1].layout
            if _crank_kept(lay) and _groups_kept(lay) and _whole(lay):
                return kept
    return found


def _whole(lay: Layout) -> bool:
    """Whether every table and text of ``lay`` (its fixed views) keeps within its box: the
    crank's constraint (:func:`_held`) never takes their room."""
    e = tol.SHEET_MM
    for pl in lay:
        nat = pl.view.natural() if pl.view.kind == "fixed" else None
        if nat is not None and (nat[0] > pl.box[2] - pl.box[0] + e
                                or nat[1] > pl.box[3] - pl.box[1] + e):  # fmt: skip
            return False
    return True


def _crank_short(lay: Layout) -> bool:
    """Whether ``lay`` draws the crank cut out shorter than
    :data:`~geomcad.sheet.linkage.CRANK_MM`."""
    return _crank_shortfall(lay) > CRANK_MM * tol.REL_LENGTH


def _crank_shortfall(lay: Layout) -> float:
    """How much (mm) shorter than :data:`~geomcad.sheet.linkage.CRANK_MM` ``lay`` draws the
    crank cut out (0 where it keeps the rule)."""
    return max((CRANK_MM - pl.view.lk.length / pl.scale.k for pl in lay
                if isinstance(pl.view, _FreeBody) and pl.view.gf.group is None
                and pl.scale is not None), default=0.0)  # fmt: skip


def _compose2(
    s: Solved, P: Position, f: Forces, k: int | None, fmts: Sequence[str], kin: float | None = None
) -> tuple[Tree, formats.Sized]:
    """Sheet 2's tree and its format and arrangement.

    The format: the smallest of ``fmts`` on which the sheet fits with its crank
    :data:`~geomcad.sheet.linkage.CRANK_MM` long and its polygons :data:`POLY_MM` across
    (:func:`~geomcad.sheet.linkage.fit`), the groups and the crank cut out at the mechanism's
    μ_l; where that takes a larger format than the groups at one μ_l of their own would (or
    does not keep the crank's length), at their own μ_l: the views share less before a larger
    format is taken (issue 27). First the polygons alone (as large as the sheet draws them),
    then, on that format, with their details reckoned at the μ_F each got there (the details
    take the room the polygon leaves free where they can); the tables and texts
    :data:`~geomcad.sheet.linkage.TEXT_H` high where that fits on the format and draws the
    links at the scales the smaller text gives them (an A1 with room to spare never has its
    tables at 2.5 mm), or costs the views at most :data:`~geomcad.sheet.linkage.TEXT_COST`,
    else :data:`~geomcad.sheet.linkage.SMALL_TEXT_H`."""
    wants: list[dict[View, float]] = []

    def make(h: float, shared: bool, under: bool = False) -> tuple[Tree, dict[View, float]]:
        tree, w = _sheet2(s, P, f, k, h, shared=shared, kin=kin, under=under)
        wants.append(w)
        return tree, w

    def reached(z: formats.Sized) -> bool:
        lay = z.layout
        (w,) = [w for w in wants if all(id(v) in lay.placed for v in w)]
        return lay.fits and formats.meets(lay, w) and _crank_kept(lay) and _groups_kept(lay)

    def area(fmt: str) -> float:
        return FORMATS[fmt][0] * FORMATS[fmt][1]

    order = sorted(fmts, key=area)
    _tree, z = fit(lambda h: make(h, True), order)
    ok = reached(z)
    own: formats.Sized | None = None
    if not ok or z.fmt != order[0]:
        smaller = [fm for fm in order if area(fm) < area(z.fmt)] if ok else order
        if smaller:
            # (the format taken last in the list: fit tries the smaller ones with the scales
            # sought, as on any but the largest)
            _tree2, z2 = fit(lambda h: make(h, False), [*smaller, z.fmt] if ok else smaller)
            if (reached(z2) and (not ok or z2.fmt != z.fmt)) or (
                not ok and z2.layout.fits and _crank_kept(z2.layout)
            ):
                own = z2
    if own is None and not ok:
        # the largest format's search, every view as large as it draws it, left the rules
        # broken: its arrangements one by one, seeking the wanted scales (review 6: the
        # compressor's V at 1:1 beside its groups at 1:2, not all at 1:2 with a 22.5 mm crank)
        for h in (TEXT_H, SMALL_TEXT_H):
            on = _on(*make(h, False), order[-1])
            if on is not None and reached(on[1]):
                own = on[1]
                break
    if own is not None and (ok or _crank_kept(own.layout)):
        # the groups would leave the mechanism's μ_l: first one arrangement more that makes
        # room for them at it (review 6: the shaper's groups at 1:4 beside its mechanism at
        # 1:2.5), tried only here (a search over more arrangements costs every sheet's layout)
        # (on the groups' format, its arrangements one by one: a quicker test than their
        # joint search)
        for h in (TEXT_H, SMALL_TEXT_H):
            on = _on(*make(h, True, True), own.fmt)
            if on is not None and reached(on[1]):
                found, kept = _final2(s, P, f, k, on[1], True, order[-1], kin, under=True)
                if kept:
                    return found
                break
    if own is not None:
        found, kept = _final2(s, P, f, k, own, False, order[-1], kin)
        if kept or not ok:
            return found
    found, kept = _final2(s, P, f, k, z, True, order[-1], kin)
    larger = [fm for fm in order if area(fm) > area(z.fmt)]
    if kept or not larger:
        return found
    # the polygons' details leave the rules broken on this format: with the smaller text
    tree_s, wants_s = _sheet2(s, P, f, k, SMALL_TEXT_H, shared=True, kin=kin)
    on = _on(tree_s, wants_s, z.fmt)
    if on is not None and on[1].layout.fits and formats.meets(on[1].layout, wants_s):
        found, kept = _final2(s, P, f, k, on[1], True, order[-1], kin)
        if kept:
            return found
    # the polygons' details leave the rules broken on this format: the next larger one
    _tree, z3 = fit(lambda h: make(h, True), larger)
    return _final2(s, P, f, k, z3, True, order[-1], kin)[0]


def _final2(
    s: Solved, P: Position, f: Forces, k: int | None, z: formats.Sized, shared: bool,
    largest: str, kin: float | None = None, crank_own: bool = False, under: bool = False,
    weight: float = 1.0, held: bool = False, only: int | None = None, rowed: bool = False,
    pin: float | None = None, pin_groups: float = 0.0,
) -> tuple[tuple[Tree, formats.Sized], bool]:  # fmt: skip
    """Sheet 2 on the format of ``z`` with its polygons' details reckoned at the μ_F each got
    there (see :func:`_compose2`), and whether it keeps the rules (where it does not on a format
    smaller than the largest, the caller takes the larger format found first); the crank cut
    out at its own μ_l where ``crank_own``, one arrangement more where ``under`` (another
    where ``held``; :func:`_sheet2`), only the arrangement of index ``only`` where given."""
    refs = {pl.view.title: (pl.scale.k, _room(pl)) for pl in z.layout
            if isinstance(pl.view, Polygon) and pl.scale}  # fmt: skip
    field = Field.of_format(z.fmt, z.landscape)
    tried: list[tuple[Tree, formats.Sized]] = []
    rules: list[bool] = []
    good: list[bool] = []
    for h in (TEXT_H, SMALL_TEXT_H):
        tree, w = _sheet2(
            s, P, f, k, h, refs, shared, kin, crank_own, under, weight, held, rowed, pin, pin_groups
        )
        tree = tree if only is None else _alternatives(tree)[only]
        lay = arrange(tree, field)
        # a plan placed at a coarser μ_F than its details were reckoned at may not hold them
        # in its box (they would run into the captions round it): reckoned again at that μ_F
        spilt = _spilt(lay)
        if spilt:
            tree, w = _sheet2(s, P, f, k, h, {**refs, **spilt}, shared, kin, crank_own, under,
                              weight, held, rowed, pin, pin_groups)  # fmt: skip
            tree = tree if only is None else _alternatives(tree)[only]
            lay = arrange(tree, field)
        tried.append((tree, formats.Sized(z.fmt, z.landscape, lay)))
        # on a smaller format than the largest, its polygons POLY_MM across as it was chosen
        # for (their details take some of their room: where neither text keeps them, the
        # smaller)
        wanted = formats.meets(lay, w) or z.fmt == largest
        rules.append(_crank_kept(lay) and _groups_kept(lay) and wanted)
        good.append(lay.fits and rules[-1])
    big, small = (t[1].layout for t in tried)
    # the larger text where it keeps the rules and draws the links at the smaller text's
    # scales, or costs the views at most TEXT_COST of the search's score (as linkage.fit)
    if good[0] and (
        not good[1]
        or _l_scales(big) == _l_scales(small)
        or big.score[1] >= small.score[1] - TEXT_COST
    ):
        return tried[0], True
    if good[1] or small.fits:
        return tried[1], rules[1]
    # neither fits: the one that keeps the rules, then the lesser overflow, then the larger text
    i = max((0, 1), key=lambda j: (rules[j], tried[j][1].layout.score[0]))
    return tried[i], rules[i]


def _spilt(lay: Layout) -> dict[str, tuple[float, tuple[float, float]]]:
    """The force plans of ``lay`` whose details, planned at the μ_F each got, reach out of
    the boxes they are centred in past their margins (into the captions round them): their
    μ_F and size there (new references, as :func:`_final2`'s). A detail's slot holds its
    labels: one that runs into the margin but not past it is clear of the next caption."""
    return {pl.view.title: (pl.scale.k, _room(pl)) for pl in lay
            if isinstance(pl.view, Polygon) and pl.scale is not None
            and pl.view.spill(pl.scale.k, pl.inner) > 2.0 * pl.view.margin}  # fmt: skip


def _room(pl: Placed) -> tuple[float, float]:
    """A force plan's room in its box (mm) with the lines under its caption counted in: the
    plan drawn again with its details takes their share off (:meth:`Polygon.note_room`: the
    first pass draws none, the one with details may add one; the crusher's group (4, 5) plan
    planned its details into the 4.4 mm its new line took, at 100 N/mm, then drawn at 200)."""
    assert isinstance(pl.view, Polygon)
    return pl.size[0], pl.size[1] + pl.view.note_room()


def _l_scales(lay: Layout) -> tuple[float, float]:
    """The μ_l (m/mm) of the loaded mechanism and of the groups cut out."""
    main = [pl.scale.k for pl in lay if isinstance(pl.view, _Loaded) and pl.scale is not None]
    own = [pl.scale.k for pl in lay if isinstance(pl.view, _FreeBody) and pl.scale is not None]
    return (main[0] if main else 0.0), max(own, default=0.0)


#: The groups and the crank cut out at a μ_l of their own are drawn at least this share of
#: the mechanism's size (1:5 beside 1:2.5).
GROUPS_SHARE = 0.5


def _groups_kept(lay: Layout) -> bool:
    """Whether the groups cut out are drawn at least :data:`GROUPS_SHARE` of the mechanism's
    size (where they have a μ_l of their own)."""
    main = [pl.scale.k for pl in lay if isinstance(pl.view, _Loaded) and pl.scale is not None]
    own = [pl.scale.k for pl in lay if isinstance(pl.view, _FreeBody) and pl.scale is not None]
    return not main or all(main[0] / kk >= GROUPS_SHARE * (1.0 - tol.REL_LENGTH) for kk in own)


def _crank_kept(lay: Layout) -> bool:
    """Whether the layout draws the loaded mechanism's crank as long as it wants (its
    ``readable`` length at least ``readable_mm``; true where the sweep forbids that want)."""
    for pl in lay:
        v = pl.view
        if isinstance(v, _Loaded) and pl.scale is not None and v.readable > 0.0:
            return v.readable / pl.scale.k >= v.readable_mm * (1.0 - tol.REL_LENGTH)
    return True


def _title(lk: Linkage, what: str, designation: str, no: int, count: int) -> TitleBlock:
    return TitleBlock(
        title=sheet_name(lk, what),
        designation=designation,
        sheet_no=no,
        sheets=count,
        lang=current(),
    )


def _num(x: float, digits: int = FIGURES, scale: float = 0.0, *, zeros: bool = False) -> str:
    """A value to ``digits`` significant figures (:func:`~geomcad.sheet.scale.fmt_number`;
    ``zeros``: its trailing zeros kept); round-off of a zero (at most ``ZERO`` of ``scale``)
    as 0."""
    return table_number(x, scale, digits, zeros=zeros)


def _load(x: float, scale: float = 0.0) -> str:
    """A load, a reaction or M_ур as the forces sheet writes it wherever it is printed (the
    table of loads, the order of the analysis, the lever's title): one value of its own to
    :data:`~geomcad.sheet.scale.FIGURES` significant figures, its trailing zeros kept (89,00
    and 17,70 in the table and in the text alike); round-off of a zero (at most ``ZERO`` of
    ``scale``) as 0."""
    return _num(x, FIGURES, scale, zeros=True)


#: The operands of the order of the analysis that are its results (a load, a reaction, M_ур,
#: P_ур), written as the table of loads writes them (:func:`_load`), by the step's kind; a kind
#: not listed, its ``value``: not a lever arm in m (``slide_arm``), not a discrepancy in %.
RESULT_FIELDS: Mapping[str, tuple[str, ...]] = {
    "force_polygon": ("Fa", "Fb"),
    "zhukovsky": ("F", "value"),
    "lever_check": ("a", "b"),
    "slide_arm": (),
}


#: The operands of the order of the analysis that the kinematic sheet tables: an operand's
#: symbol (key) and its value (value), the link's ε of M_Ф = −J·ε (signed, as its table) and
#: the point's a of Ф = m·a (a magnitude).
KINEMATIC_FIELDS = {"e": "ev", "a": "av"}


def _as_loads(
    steps: Sequence[Step], cells: Mapping[str, str] | None = None
) -> dict[str, dict[str, str]]:
    """The result operands (:data:`RESULT_FIELDS`) of ``steps`` as :func:`_load` writes them,
    by step name: the order of the analysis prints a value as the table of loads does; and an
    ε or a that the kinematic sheet tables in this position (``cells``,
    :func:`~geomcad.sheet.linkage.tabled_cells`) as its cell reads (:data:`KINEMATIC_FIELDS`)."""
    out: dict[str, dict[str, str]] = {}
    for st in steps:
        keys = RESULT_FIELDS.get(st.kind, ("value",))
        args = dict(st.args)
        given = {
            k: _load(float(v))
            for k, v in st.args
            if k in keys and isinstance(v, float | int) and not isinstance(v, bool)
        }
        for sym, field in KINEMATIC_FIELDS.items():
            name = args.get(sym)
            if isinstance(name, str) and name in (cells or {}) and field in args:
                cell = (cells or {})[name]
                given[field] = cell if sym == "e" else cell.lstrip("\u2212\u2013-")
        out[st.name] = given
    return out


# --- sheet 2 ------------------------------------------------------------------------------


def _sheet2(
    s: Solved, P: Position, f: Forces, k: int | None, h: float,
    refs: Mapping[str, tuple[float, tuple[float, float]]] | None = None, shared: bool = True,
    kin: float | None = None, crank_own: bool = False, under: bool = False, weight: float = 1.0,
    held: bool = False, rowed: bool = False, pin: float | None = None, pin_groups: float = 0.0,
) -> tuple[Tree, dict[View, float]]:  # fmt: skip
    """Sheet 2's tree, its tables and texts ``h`` high, and the scales its views want. The
    force polygons are drawn with their details where ``refs`` gives their reference μ_F and
    room (mm; by their titles), else alone (for a first arrangement). The groups and the crank
    cut out are drawn at the mechanism's μ_l (``shared``), else at one μ_l of their own. Where
    the sweep waives the crank's length, the mechanism is sought at the kinematic sheet's μ_l
    (``kin``: where that fits). The crank cut out is drawn at a μ_l of its own that draws it
    CRANK_MM long where ``crank_own`` (where the mechanism's draws it short). ``under``: one
    arrangement more, the polygons under the mechanism and the groups over the lever (room
    for the groups at the mechanism's μ_l; tried only where the others leave it broken).
    ``weight``: a millimetre the crank (and a group of its own μ_l) falls short of its rule
    weighs that many of the plans' seek in the search (:data:`CRANK_WEIGHT`, :func:`_held`).
    ``held``: one arrangement more, the last, the mechanism with the tables and the polygons
    beside it and the groups and the lever under them (room for a mechanism at its crank's
    scale that takes a third of the sheet; tried only where the others leave the crank short).
    ``rowed``: one more, the last, the drawings of links and the lever side by side over the
    polygons and the tables in a row (tall narrow drawings: a press's vertical slider-crank;
    tried once the search has chosen, :func:`_rowed`). ``pin``: the mechanism, its groups and
    its crank at this one μ_l (m/mm), never finer, sought as a constraint, with one arrangement
    more, the last, the mechanism as a band across the top, the groups and the lever in a row
    under it, the polygons and the tables under those (:func:`_pinned`); ``pin_groups``: the
    groups and the crank cut out at this coarser μ_l of their own (0: at ``pin``)."""
    lk = s.linkage
    # the length scales from the geometry alone (a change of ω or of the loads rescales no
    # drawing of links): never finer than links_scale; the crank CRANK_MM long where the
    # mechanism's sweep allows it on the sheet
    k_l = links_scale(s).k
    deg = math.degrees(P.phi) % 360.0
    phi = fmt_fixed(deg, angle_places([deg]), current())
    title = WORDS("mech", k=k, phi=phi) if k is not None else WORDS("mech_phi", phi=phi)
    mech = _Loaded(lk, P, f, title)
    letters = detail_letters([*P.pos, *_FORCE_LETTERS, load_name(chr(0x424))])
    # the crank drawn short on the mechanism (where the format keeps no μ_l that draws it
    # CRANK_MM long) is drawn again in a detail (its letter taken where it is drawn)
    mech.solved = s
    if sweep_mm(s, crank_scale(lk).k) <= SWEEP_MAX_MM or pin is not None:
        mech.readable, mech.readable_mm = weight * lk.length, weight * CRANK_MM
    else:
        if kin is not None:
            # the sweep waives the crank's length: the mechanism no coarser than the kinematic
            # sheet draws it, where the format allows it (review 5: a crusher at 1:15 beside 1:5)
            mech.readable, mech.readable_mm = lk.length, lk.length / kin
        # the crank may come out short on it: its detail's letter, the first of the sheet's
        mech.detail = next(letters)
    bodies = [_FreeBody(lk, P, gf) for gf in f.groups]
    # one μ_l for the mechanism and its cut-out groups and crank (issue 27, point 7): one scale
    # group, the coarsest any of them needs, stated in every caption
    for v in (mech, *bodies):
        v.least_k = k_l
        v.group = L_GROUP if shared else GROUPS_L
    mech.group = L_GROUP
    # the crank cut out is at the mechanism's μ_l where that keeps the crank CRANK_MM long (a
    # small drawing, it costs the sheet little)
    for b in bodies:
        if b.gf.group is None and mech.readable > 0.0:
            b.group = L_GROUP
    # the search counts a scale group once, at its heaviest member's weight: the mechanism's
    # (2) and one for each drawing of links it draws at its scale, as each had on its own
    for b in bodies:
        if crank_own and b.gf.group is None:
            b.group, b.least_k = CRANK_L, crank_scale(lk).k
            b.readable, b.readable_mm = lk.length, CRANK_MM
    if pin is not None:
        # one μ_l for all the drawings of links, the crank on it CRANK_MM long or more
        for v in (mech, *bodies):
            v.group, v.least_k, v.most_k = L_GROUP, pin, pin
        if pin_groups > pin:
            # the groups apart, at one μ_l of their own; the crank cut out (a small drawing)
            # keeps the mechanism's, CRANK_MM long
            for b in bodies:
                b.group, b.least_k, b.most_k = GROUPS_L, pin_groups, pin_groups
                if b.gf.group is None:
                    b.group, b.least_k, b.most_k = CRANK_L, pin, pin
        if lk.length / pin < CRANK_MM * (1.0 - tol.REL_LENGTH):
            # the field holds no μ_l that draws the crank CRANK_MM long on the mechanism
            # (review 13: the coining press's 55 mm crank on a 0,65 m stroke at 1:2): the
            # crank cut out is its enlarged view, at the μ_l that draws it CRANK_MM long,
            # stated in its caption (never a crank read only at 27 mm, or at 5 mm)
            own = crank_scale(lk).k
            for b in bodies:
                if b.gf.group is None:
                    b.group, b.least_k, b.most_k = CRANK_L, own, own
        mech.readable, mech.readable_mm = lk.length, lk.length / pin
    mech.weight = 2.0 + sum(b.group == L_GROUP for b in bodies)
    if not shared:
        for b in bodies:
            if b.group == GROUPS_L:
                b.weight = 2.0
                # at least GROUPS_SHARE of the mechanism's size, never finer than k_l
                b.readable = weight * lk.length
                b.readable_mm = weight * GROUPS_SHARE * lk.length / k_l
    # each group's polygons under the group cut out (the crank's under the crank); a
    # polygon's vectors too short for its μ_F are drawn again, enlarged, in details at their
    # own stated μ_F beside it in its view (one letter each on the sheet). A plan leaves out
    # no term of its ΣF = 0, however small (review 11 item 5: slider_rocker_rpr's "G4 (менее
    # 0,1 %) не показана"): its details' tiers (DETAIL_TIERS, a span of 10⁴) reach the 0,1 %
    # the views leave out (NEGLIGIBLE), so each term is an arrow at a stated μ_F
    per_group = [
        [
            Polygon(
                poly,
                title=_poly_title(gf, name),
                margin=8.0,
                names={pv.name: load_name(pv.name) for pv in poly.vectors},
                detail=refs is not None,
                letters=letters,
                ref=(refs or {}).get(_poly_title(gf, name)),
            )
            for name, poly in gf.polygons
        ]
        for gf in f.groups
    ]
    polys = [p for ps in per_group for p in ps]
    groups = Row(*[Column(b, *ps) for b, ps in zip(bodies, per_group, strict=True)])
    lever = _Lever(lk, P, f)
    mech.letters = lever.letters = letters  # their insets lettered after the polygons' details
    for b in bodies:
        b.letters = letters
    table: Table | Column = _table2(f, h)
    if mech.short or lever.short or any(b.short for b in bodies):
        note = WORDS("short", mm=fmt_number(SHORT_MM))
        table = Column(table, Text(paragraph=note, width=TABLE2_W * h / 2.5, height=h))
    # the order's equation of each plan lists its terms as the plan lays them off
    drawn = {name: p.layers[-1][0] for gf, ps in zip(f.groups, per_group, strict=True)
             for (name, _), p in zip(gf.polygons, ps, strict=True)}  # fmt: skip
    steps = order_steps(f, drawn)
    order = Steps(steps, order_width(h) * 170.0 / 190.0, only=[st.name for st in steps],
                  words=WORDS, given=_as_loads(steps, tabled_cells(s, P)), height=h,
                  title=WORDS("order"), title_height=TITLE_H)  # fmt: skip
    right = Column(table, order)
    # the groups cut out beside the mechanism (or over the polygons) in one band packed by
    # their sizes, or each group over its polygons; the table and the order of the analysis
    # beside the polygons, or down the right edge over the title block
    k_b = max(k_l, max(sweep_box(s)) / SWEEP_MM)
    band = _band(bodies, k_b)
    if pin is not None:
        # the mechanism at the pinned μ_l: a wide flat one (a long guide, a long rod) as a band
        # across the top, a tall narrow one (a slotted lever, a press) down the left edge
        tree: Tree = _pinned_tree(s, mech, bodies, lever, polys, right, pin,
                                  max(pin, pin_groups))  # fmt: skip
    else:
        tree = _choice2(mech, band, lever, polys, right, groups, bodies, under, held, rowed)
    # the format: the smallest on which the crank is CRANK_MM long (where the sweep allows it),

    # every force polygon at least POLY_MM across and its longest vector at least PLAN_MM (a
    # course project draws its plans large): a format too small for that is passed over
    wants: dict[View, float] = {}
    for p in polys:
        big = max(pv.magnitude for poly, _ in p.layers for pv in poly.vectors)
        side = max(_side(p))
        want = max(big / PLAN_MM, side / POLY_MM)
        if is_sliver(p.layers[-1][0]):
            # a sliver (R01 = -R21) shows no more drawn long: at most SLIVER_MM in its cell
            p.longest_mm = SLIVER_MM
        if want > 0.0:
            wants[p] = want
        if big > 0.0 and pin is None:
            # and on the largest format the search seeks it (its longest vector PLAN_SEEK_MM;
            # with the μ_l pinned, the plans take what the drawings of links leave)
            p.readable = max(p.readable, big * p.readable_mm / PLAN_SEEK_MM)
    if mech.readable > 0.0:
        wants[mech] = mech.readable / mech.readable_mm
    return tree, wants


def _choice2(
    mech: View, band: Row, lever: View, polys: Sequence[View], right: Column, groups: Row,
    bodies: Sequence[View], under: bool, held: bool, rowed: bool,
) -> Choice:  # fmt: skip
    """The arrangements of sheet 2 its search chooses from (see :func:`_sheet2`)."""
    return Choice(
        Column(Row(mech, band), Row(lever, Grid(*polys), right)),
        Row(Column(mech, lever), Column(band, Row(Grid(*polys), right))),
        Column(Row(mech, lever, right), groups),
        Row(Column(mech, lever), Column(Grid(*bodies), Grid(*polys)), right),
        *([Row(Column(mech, Grid(*polys)), Column(band, lever), right)] if under else []),
        # the mechanism the field's height at the left edge, the groups, the lever and the
        # polygons in a column beside it (or the lever beside the polygons under the groups),
        # the tables at the right edge (review 12: the slotter's five plans 27-54 mm in 104 x 93
        # mm cells under its mechanism while its lever took 387 x 287 mm for a 320 x 130 mm
        # drawing; so its plans reach 108 mm, its mechanism 1:2 instead of 1:2,5)
        Row(mech, Column(band, lever, Grid(*polys)), right),
        Row(mech, Column(band, Row(lever, Grid(*polys))), right),
        # the mechanism at its rule's scale with the tables and the polygons beside it, the
        # groups and the lever under them (review 8: a 55 mm crank's mechanism at 1:1 holds
        # only so on A1; tried only where the others leave the crank short, :func:`_held`)
        *(
            [Column(Row(mech, Column(Row(*right.items), Grid(*polys))), Row(band, lever))]
            if held
            else []
        ),
        *([Column(Row(mech, band, lever), Row(Grid(*polys), Row(*right.items)))] if rowed else []),
    )


def _pinned_tree(
    s: Solved, mech: _Loaded, bodies: Sequence[_FreeBody], lever: View, polys: Sequence[View],
    right: Column, pin: float, pin_groups: float,
) -> Tree:  # fmt: skip
    """The arrangements of :func:`_pinned`'s sheet, its drawings of links at ``pin`` m/mm
    (:func:`_pin_try` tries each alone and keeps the best that holds its rules): the mechanism
    as a band across the top, the groups and the lever in a row under it, the polygons and the
    tables under those; or the mechanism down the left edge the field's height, either the
    groups and the lever beside it over the polygons and the tables down the right edge, or the
    groups and the lever over the polygons and the tables in a row. Every form is offered
    whatever the mechanism's shape (review 12: the yarn traverse's 297 x 325 mm mechanism at
    2,5:1 was given the band alone by its aspect, which has no room for the polygons under it,
    and fell to 2:1, its crank 24 mm; down the left edge it holds). The boxes of the mechanism
    and of the groups are given, as large as their drawings at ``pin`` (margins and captions
    included): the search shares only the rest among the lever and the polygons."""
    fmts = _formats(s.linkage)
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    field = Field.of_format(largest, True)
    fw, fh = field.box[2] - field.box[0], field.box[3] - field.box[1]
    mw, mh = _body_size(mech, pin)
    band = _band(bodies, pin_groups)
    bw, bh = _band_size(bodies, pin_groups)
    # across the top: under the band the groups over the polygons, the table beside the order
    # at the right edge (over the title block); the lever beside the mechanism where it leaves
    # room, else beside the polygons
    tables = Row(*right.items)
    rest = max(fh - mh - bh - 2.0 * GAP, 1.0)
    if fw - mw - GAP >= LEVER_SHARE * fw:  # the lever beside the mechanism
        top: Tree = Row(lever, mech, weights=[max(fw - mw - GAP, 1.0), mw])
        below = Column(band, Grid(*polys), weights=[bh, rest])
        th = mh
    else:  # the lever beside the polygons (the form's box in the field's corner above)
        top = mech
        th = mh + max((o[3] - field.box[1] for o in field.obstacles if o[1] <= field.box[1]),
                      default=0.0)  # fmt: skip
        rest = max(fh - th - bh - 2.0 * GAP, 1.0)
        below = Column(band, Row(lever, Grid(*polys)), weights=[bh, rest])
    across = Column(top, Row(below, tables), weights=[th, max(fh - th - GAP, 1.0)])
    # down the left edge: the groups and the lever over the polygons, the mechanism beside
    # them, the tables down the right edge
    rw = max((nat[0] for it in right.items if (nat := natural_of(it)) is not None), default=0.0)
    left = fw - mw - rw - 2.0 * GAP
    rest = max(fh - bh - GAP, 1.0)
    if bw <= BAND_SHARE * left:
        side = Column(Row(band, lever, weights=[bw, max(left - bw - GAP, 1.0)]), Grid(*polys),
                      weights=[bh, rest])  # fmt: skip
    else:
        side = Column(band, Row(lever, Grid(*polys)), weights=[bh, rest])
    beside = Row(side, mech, right, weights=[max(left, 1.0), mw, 1.0])
    # or the mechanism the sheet's height at the left edge and the tables in a row under the
    # groups, beside the polygons: the groups and the lever take the width the tables' column
    # left them (review 11: the yarn traverse's 12 mm crank at 2,5:1 with its groups at 2:1
    # holds only so on A1; down a right column its groups fell to 1:1 and the crank to 12 mm)
    wide = fw - mw - GAP
    upper = Row(band, lever, weights=[bw, max(wide - bw - GAP, 1.0)])
    under = Column(upper, Row(Grid(*polys), Row(*right.items)), weights=[bh, rest])
    # or the mechanism over the lever down the left edge, the groups over the polygons and
    # the tables beside it (review 12: the yarn traverse's groups at 2,5:1 take 506 mm in a
    # row, no room for the lever beside them)
    # (the mechanism's box the form's corner above it taken in: графа 26)
    th = mh + max((o[3] - field.box[1] for o in field.obstacles if o[1] <= field.box[1]
                   and o[0] <= field.box[0] + mw), default=0.0)  # fmt: skip
    column = Column(mech, lever, weights=[th, max(fh - th - GAP, 1.0)])
    # (the tables in a row their natural widths: the search gives the polygons the rest)
    tw = sum(nat[0] for it in right.items if (nat := natural_of(it)) is not None)
    tw += GAP * (len(right.items) - 1)
    low = Row(Grid(*polys), Row(*right.items), weights=[max(wide - tw - GAP, 1.0), tw])
    grouped = Column(band, low, weights=[bh, rest])
    return Choice(
        across,
        beside,
        Row(mech, under, weights=[mw, max(wide, 1.0)]),
        Row(column, grouped, weights=[mw, max(wide, 1.0)]),
    )


#: The room beside a mechanism drawn across the top (:func:`_pinned_tree`) takes the lever
#: where it is at least this share of the field's width.
LEVER_SHARE = 0.25
#: The groups cut out take at most this share of the width beside the lever
#: (:func:`_pinned_tree`); wider, the lever goes beside the polygons.
BAND_SHARE = 0.6


def _body_size(v: View, k: float) -> tuple[float, float]:
    """The box (mm) a drawing of links takes at ``k`` m/mm, its margins and caption in (the
    caption as it reads at ``k``, on one line: at 2,5:1 the needle's is 248 mm, its typical
    caption's 242 mm; it was set in two lines and took its drawing one step coarser)."""
    w, h = _side(v)
    said = lines_width(v.caption(Scale(k, "l")), v.title_height, 1)
    return (max(w / k + 2.0 * v.margin, title_width(v), said) + PIN_SLACK_MM,
            h / k + 2.0 * v.margin + v.title_room() + PIN_SLACK_MM)  # fmt: skip


#: What :func:`_pinned_tree` adds to a box it gives a drawing of links (mm): the layout's
#: rounding of its scale never takes it one GOST step coarser.
PIN_SLACK_MM = 2.0


def _band_size(bodies: Sequence[_FreeBody], k: float) -> tuple[float, float]:
    """The box (mm) :func:`_band` packs the groups and the crank cut out in at ``k``."""
    size = {id(b): _body_size(b, b.least_k if b.group == CRANK_L else k) for b in bodies}
    tall = max(bodies, key=lambda b: size[id(b)][1])
    rest = [b for b in bodies if b is not tall]
    if len(rest) > 1 and sum(size[id(b)][1] for b in rest) <= size[id(tall)][1]:
        return size[id(tall)][0] + GAP + max(size[id(b)][0] for b in rest), size[id(tall)][1]
    return (sum(size[id(b)][0] for b in bodies) + GAP * (len(bodies) - 1),
            max(size[id(b)][1] for b in bodies))  # fmt: skip


def _band(bodies: Sequence[_FreeBody], k: float) -> Row:
    """The groups and the crank cut out side by side, packed by their sizes at ``k`` m/mm
    (a crank at its own μ_l, :data:`CRANK_L`, at that; margins and captions included): the
    tallest, and beside it the others one under another where together they are no taller
    than it (a flat group and the crank beside a tall group), else all in a row; each cell as
    wide (high) as its drawing, where equal cells would leave the tall one small and the flat
    one empty, and at least as wide as its caption. The splits are given: the search spends
    nothing on them."""
    ks = {id(b): b.least_k if b.group == CRANK_L else k for b in bodies}
    size = {id(b): (max(_side(b)[0] / ks[id(b)] + 2.0 * b.margin, title_width(b)),
                    _side(b)[1] / ks[id(b)] + 2.0 * b.margin + b.title_room())
            for b in bodies}  # fmt: skip
    tall = max(bodies, key=lambda b: size[id(b)][1])
    rest = [b for b in bodies if b is not tall]
    if len(rest) > 1 and sum(size[id(b)][1] for b in rest) <= size[id(tall)][1]:
        col = Column(*rest, weights=[size[id(b)][1] for b in rest])
        return Row(tall, col, weights=[size[id(tall)][0], max(size[id(b)][0] for b in rest)])
    return Row(*bodies, weights=[size[id(b)][0] for b in bodies])


def _side(v: View) -> tuple[float, float]:
    ext = v.extent()
    assert ext is not None
    return ext[2] - ext[0], ext[3] - ext[1]


#: The letters of the forces and moments on a forces sheet, the balancing force's and the
#: centres of mass' (no detail is lettered with one; nor with the inertia force's, in the
#: language drawn).
_FORCE_LETTERS = ("F", "G", "M", "P", "R", "S")


#: A force polygon's larger side (mm) on the smallest format the force sheet may take.
POLY_MM = 60.0
#: The larger side (mm) of the box the mechanism sweeps over a turn that its drawing on the
#: force sheet is scaled up to (the finest GOST scale at which it is at most this): the main
#: view is large where the crank alone would leave it small (a long crank, short links).
SWEEP_MM = 200.0
#: Where the mechanism's sweep would be larger than this (mm) with its crank CRANK_MM long (a
#: crusher's short crank on long links), the crank's length is no rule of the layout.
SWEEP_MAX_MM = 400.0


def sweep_box(s: Solved) -> tuple[float, float]:
    """The width and height (m) of the box every named point of the mechanism sweeps over
    its numbered positions (the geometry alone: no ω, no load)."""
    pts = [q for P in s.drawn or s.positions for q in P.pos.values()]
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    return max(xs) - min(xs), max(ys) - min(ys)


def sweep_mm(s: Solved, k: float) -> float:
    """The larger side (mm) of the mechanism's sweep (:func:`sweep_box`) at ``k`` m/mm."""
    return max(sweep_box(s)) / k


def links_scale(s: Solved) -> Scale:
    """The finest length scale a drawing of the force sheet's links takes: the finer of
    :func:`crank_scale` and the finest GOST 2.302 scale at which the mechanism's sweep is at
    most :data:`SWEEP_MM` (from the dimensions alone, so that ω and the loads never rescale a
    drawing of links; the layout takes it where the sheet has room, a coarser one else)."""
    big = max(sweep_box(s))
    fits = [k for k in GOST_K if big / k <= SWEEP_MM * (1.0 + tol.REL_LENGTH)]
    sweep = min(fits) if fits else max(GOST_K)
    return Scale(min(crank_scale(s.linkage).k, sweep), "l")


def _coarser(k: float) -> tuple[float, ...]:
    """The GOST 2.302 reductions coarser than ``k`` (m/mm), the nearest first."""
    return tuple(g for g in GOST_K if g > k * (1.0 + tol.DERIVED))


def kinematic_scale(s: Solved) -> Scale:
    """The μ_l of the mechanism on the kinematic sheet (its layout, searched once per solution
    and language): the forces sheet's mechanism is drawn no coarser where the format allows."""
    return kinematic_layout(s).k_l


def crank_scale(lk: Linkage) -> Scale:
    """The finest length scale a drawing of the force sheet's links takes: the coarsest GOST
    2.302 scale at which the crank is still :data:`~geomcad.sheet.linkage.CRANK_MM` long (from
    the dimensions alone, so that ω and the loads never rescale a drawing of links)."""
    fits = [k for k in GOST_K if lk.length / k >= CRANK_MM * (1.0 - tol.REL_LENGTH)]
    return Scale(max(fits) if fits else min(GOST_K), "l")


def order_steps(f: Forces, drawn: Mapping[str, ForcePolygon] | None = None) -> list[Step]:
    """The steps of the order of the kinetostatic analysis (:attr:`Forces.order`: the loads,
    the groups from the last, the crank, Zhukovsky's lever), their operands in the language
    drawn (the inertia force's letter). ``drawn``: the force plans as the sheet lays them off,
    by their steps' names (a plan's known loads may be laid off in another order than the
    model's, :func:`~geomcad.sheet.views.regroup`): each plan's equation then lists its terms
    in that order, so that it reads along the plan (:func:`plan_equation`)."""
    out = []
    for name in f.order:
        st = f.c.step(name)
        poly = (drawn or {}).get(name)
        args = tuple(
            (k, load_name(plan_equation(st, poly) if k == "eq" and poly else a))
            if isinstance(a, str)
            else (k, a)
            for k, a in st.args
        )
        out.append(replace(st, args=args))
    return out


def plan_equation(st: Step, poly: ForcePolygon) -> str:
    """The equation ΣF = 0 of the force plan step ``st`` with its terms in the order the plan
    ``poly`` lays them off: the recorded one where the plan keeps the model's order (a sum
    ΣF_5 written as such), else each vector's name in the plan's order."""
    eq = str(dict(st.args)["eq"])
    recorded = st.result.vectors if isinstance(st.result, ForcePolygon) else ()
    names = [pv.name for pv in poly.vectors]
    if names == [pv.name for pv in recorded]:
        return eq
    return " + ".join(names) + " = 0"


def load_name(name: str) -> str:
    """A load's name (the model's: ``Ф_2`` for an inertia force, as the subject writes it) in
    the language being drawn: the inertia force's letter from the table (Greek Φ in English)."""
    return name.replace(chr(0x424), WORDS("inertia"))


def _poly_title(gf: GroupForces, name: str) -> str:
    if gf.group is None:
        return WORDS("poly_crank")
    if "polygon of link" in name:
        return WORDS("poly_link", link=name.rsplit(" ", 1)[-1])
    return WORDS("poly_group", links=", ".join(str(i) for i in gf.links))


def _bbox(pts: Sequence[Vec], minimum: float) -> tuple[float, float, float, float]:
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    pad = 0.05 * max(x1 - x0, y1 - y0, minimum)
    return x0 - pad, y0 - pad, x1 + pad, y1 + pad


def _force(
    v: Viewport, at: Vec, F: Vec, fs: ForceScales, label: str, arrive: bool = False,
    role: str = "vector", clear: Clearance | None = None, insets: Insets | None = None,
    point: str = "",
) -> None:  # fmt: skip
    """A force as an arrow at the view's μ_F, or, shorter than :data:`SHORT_MM` there, in the
    view's ``insets`` at a finer stated μ_F (:func:`~geomcad.sheet.loads.view_scales`); never
    a dot. A zero force, or a negligible one, draws nothing. ``clear``: on a drawing of links,
    the arrow goes where its line of action is clear of them
    (:class:`~geomcad.sheet.loads.Clearance`). ``point``: the name of the point it acts at
    (its inset names it)."""
    tier = fs.tier(F.norm)
    if tier is None:
        return
    if tier > 0 and insets is not None:
        insets.add(at, F, tier, label, role, point)
        return
    force(v, at, F, fs.k_at(F.norm), label + fs.mark(min(tier, len(fs.scales) - 1)),
          arrive=arrive, role=role, height=2.5, clear=clear)  # fmt: skip


#: The radius (mm) of a moment's arc about its point, and how much larger each further
#: moment's arc about the same point is (M_Φ3 and a given M_3 on one link: two arcs, not one).
MOMENT_MM = 6.0
MOMENT_STEP_MM = 3.0


def _draw_loads(
    v: Viewport, lk: Linkage, P: Position, loads: Sequence[Applied], fs: ForceScales, role: str,
    clear: Clearance | None = None, arcs: dict[tuple[float, float], int] | None = None,
    insets: Insets | None = None,
) -> None:  # fmt: skip
    """The loads: the moments first (their arcs, each point's further ones larger, counted in
    ``arcs``), then the forces, clear of the drawing and of each other with ``clear``."""
    arcs = {} if arcs is None else arcs
    for ld in loads:
        if ld.force is None and ld.moment != 0.0:
            c = centre_vec(lk, ld.link, P.pos)
            r = _moment_radius(v, c, arcs, clear)
            moment(v, c, ld.moment, r, load_name(ld.name), role, height=2.5)
    forces = [ld for ld in loads if ld.force is not None and ld.at is not None]
    if clear is not None:
        # the forces that are clear at their own points take them first; those that must be
        # moved along their lines of action (a load along its link) find room after them
        # (the larger first among those about as clear: the main load before a small weight)
        forces.sort(key=lambda ld: (_cost(v, ld, fs, clear) // CLEAR_BAND, -_norm(ld)))
    for ld in forces:
        assert ld.force is not None and ld.at is not None
        _force(v, ld.at, ld.force, fs, load_name(ld.name), role=role, clear=clear,
               insets=insets, point=ld.point)  # fmt: skip


#: Loads whose arrows are about as clear at their points (their costs,
#: :meth:`~geomcad.sheet.loads.Clearance.best`, in one band this wide) are drawn the larger
#: first: the main load takes the free place before a weight on the same line.
CLEAR_BAND = 10.0


def _given_loads(loads: Sequence[Applied]) -> list[Applied]:
    """The loads of ``loads`` that the file gives (F_B, M_3), not weights nor inertia."""
    return [ld for ld in loads if ld.kind == "given"]


def _given(loads: Sequence[Applied]) -> tuple[float, ...]:
    """The magnitudes (N) of the given forces of ``loads`` (never drawn without a scale)."""
    return tuple(ld.force.norm for ld in _given_loads(loads) if ld.force is not None)


def _norm(ld: Applied) -> float:
    return ld.force.norm if ld.force is not None else 0.0


def _cost(v: Viewport, ld: Applied, fs: ForceScales, clear: Clearance) -> float:
    """How far from clear at its own point a load's arrow is on the drawing so far
    (:meth:`~geomcad.sheet.loads.Clearance.best`)."""
    assert ld.force is not None and ld.at is not None
    tier = fs.tier(ld.force.norm)
    if tier is None:
        return 0.0
    F = ld.force
    u = (F.x / F.norm, -F.y / F.norm)
    return clear.best(v.p(ld.at), u, F.norm / fs.k_at(F.norm), False)[0]


def _moment_radius(
    v: Viewport, c: Vec, arcs: dict[tuple[float, float], int], clear: Clearance | None = None
) -> float:
    """The radius (mm) of the next moment's arc about model point ``c``: :data:`MOMENT_MM`,
    each further one about the same point (within 0.5 mm on the sheet) :data:`MOMENT_STEP_MM`
    larger; and at least :data:`MOMENT_PAST_MM` past the corners of a filled block round the
    point (``clear``'s solids: a knot's slider, which would hide the arc)."""
    x, y = v.p(c)
    key = next((q for q in arcs if math.hypot(q[0] - x, q[1] - y) < 0.5), (x, y))
    n = arcs.get(key, 0)
    arcs[key] = n + 1
    reach = [
        float(np.hypot(q[:, 0] - x, q[:, 1] - y).max())
        for q in (clear.solids() if clear is not None else [])
        if _inside(np.array([(x, y)]), [q])[0]
    ]
    return max([MOMENT_MM, *(r + MOMENT_PAST_MM for r in reach)]) + MOMENT_STEP_MM * n


#: A moment's arc runs this far (mm) past the corners of a filled block round its point.
MOMENT_PAST_MM = 0.5


#: The height (mm) of the line under a view's caption that states the further μ_F.
SCALES_H = 2.5


def further_room(fs: ForceScales, omitted: Sequence[str] = (), width: float = 0.0) -> float:
    """The room (mm) of the lines under a view's caption that state its insets' μ_F and the
    forces it draws to no scale (``omitted``: those it leaves out and those it draws as
    direction arrows, :func:`draw_insets`), those wrapped at ``width`` mm (the caption's: the
    view's box is never narrower) as a list of them would be; 0 where it has neither."""
    if not (fs.tiered or omitted):
        return 0.0
    omitted = _omitted_fit(omitted, width)
    lines = len(_omitted_lines(omitted, width)) if omitted and width > 0.0 else 1
    return (SCALES_H * TITLE_LEAD + (max(lines, 1) - 1) * SCALES_H * TITLE_SPACING
            + _stars_rise(fs))  # fmt: skip


def _stars_rise(fs: ForceScales) -> float:
    """How far (mm) the line under a view's caption rises over its cap height where it states
    two inset μ_F (their marks ``*``, ``**`` are superscripts): 0 with one."""
    return max(0.0, fs.further_rise(SCALES_H) - SCALES_H) if len(fs.scales) > 2 else 0.0


def _omitted_fit(omitted: Sequence[str], width: float) -> list[str]:
    """The forces left out as the line under a view's caption names them: with their values
    (``G_4 = 29,43 Н``) where that takes one line ``width`` mm wide, else by their names
    alone (the table of loads gives their values): a long list takes no second line of the
    view's room (review 7: the insets draw fewer forces, the lists grew)."""
    if width <= 0.0 or len(_omitted_lines(omitted, width)) <= 1:
        return list(omitted)
    return list(dict.fromkeys(o.split(" = ", 1)[0] for o in omitted))


def _omitted_text(omitted: Sequence[str]) -> str:
    """The words that name the forces a view leaves out as negligible, with their values."""
    key = "omitted_one" if len(omitted) == 1 else "omitted"
    return WORDS(key, share=fmt_number(VIEW_NEGLIGIBLE * 100.0), items=", ".join(omitted))


def _omitted_lines(omitted: Sequence[str], width: float) -> list[str]:
    """:func:`_omitted_text` in lines at most ``width`` mm wide (review 6: the lever's line ran
    across the next view's force plan)."""
    return wrap(_omitted_text(omitted), width, SCALES_H)


def omitted_values(
    fs: ForceScales, named: Sequence[tuple[str, float]], fixed: bool = False
) -> list[str]:
    """The forces ``named`` (name, N) that the view leaves out as negligible (``fixed``: and
    those it draws as direction arrows, to no scale), each with its value (``G_1 = 11,8 Н``),
    once each."""
    out = [f"{load_name(n)} = {_num(abs(F))} {WORDS('newton')}"
           for n, F in named if fs.zero < abs(F) <= fs.negligible
           or (fixed and fs.zero < abs(F) and fs.is_fixed(abs(F)))]  # fmt: skip
    return list(dict.fromkeys(out))


def draw_insets(
    d: Drawing, at: Placed, view: View, ins: Insets, start: int, omitted: Sequence[str]
) -> None:
    """The view's insets (:class:`~geomcad.sheet.insets.Insets`) where its box is free, then
    the lines under its caption that state their one μ_F, name the forces drawn as direction
    arrows ("G_1, Ф_1 — стрелки 5 мм без масштаба", else by the share they are under: "силы
    менее 1,7 % — …") and name the forces it leaves out,
    wrapped at the box's width into the lines its title's room holds (:func:`further_room`).
    Where they would need more lines, each inset's caption states its μ_F instead (never the
    μ_F without the letters of the insets it is of), and where they still would, the forces
    left out are named without the share they are under."""
    assert at.viewport is not None
    letters = getattr(view, "letters", None) or detail_letters()
    mine = [next(letters) for _ in range(ins.count(at.viewport))]
    parts = [ins.line(mine)] if mine and ins.scaled else []
    # the forces drawn as direction arrows: by name, or by their share where the names
    # would not fit
    names = ins.fixed_names()
    by_name = ""
    if names:
        key = "fixed_one" if len(names) == 1 else "fixed"
        by_name = WORDS(key, names=", ".join(names), mm=fmt_number(ins.fs.fixed))
        parts.append(by_name)
    omitted = _omitted_fit(omitted, title_width(view))
    if omitted:
        key = "omitted_one" if len(omitted) == 1 else "omitted"
        share = _share_text(getattr(view, "fs", ins.fs).limit or VIEW_NEGLIGIBLE)
        parts.append(WORDS(key, share=share, items=", ".join(omitted)))
    width = at.box[2] - at.box[0]
    # the lines reserved for them (:func:`further_room`): as many as a list of all the
    # forces drawn to no scale takes
    fs = getattr(view, "fs", ins.fs)
    unscaled = omitted_values(fs, getattr(view, "_named", ()), True)
    unscaled = _omitted_fit(unscaled, title_width(view))
    room = max(len(_omitted_lines(unscaled, title_width(view))) if unscaled else 1, 1)

    def fits() -> bool:
        return len(wrap(";  ".join(parts), width, SCALES_H)) <= room

    if names and not fits():
        # "силы менее N % — стрелки 5 мм без масштаба": N the largest such one's share
        big = max(getattr(view, "_forces", [0.0]))
        top = max(s.F.norm for s in ins.shorts if ins.fixed(s))
        i = 1 if mine and ins.scaled else 0
        parts[i] = WORDS("fixed_all", share=_share_text(top / big) if big > 0.0 else "",
                         mm=fmt_number(ins.fs.fixed))  # fmt: skip

    def bare() -> None:
        key = "omitted_bare_one" if len(omitted) == 1 else "omitted_bare"
        parts[-1] = WORDS(key, items=", ".join(omitted))

    # never the μ_F without the letters it is of (review 10: slider_rocker's group (4, 5)
    # stated "выносные элементы: μF = 1 Н/мм" beside its insets Я and Г1): where the line
    # has no room for them, each inset's caption states its letter's μ_F
    each = bool(mine) and ins.scaled and not fits()
    if each:
        parts = parts[1:]
        if names and parts[0] != by_name:
            short, parts[0] = parts[0], by_name  # by name where the line has room without
            if not fits():  # the insets' μ_F
                parts[0] = short
    if omitted and not fits():
        bare()
    ins.draw(d, at.viewport, _field(at), start, iter(mine), each)
    lines = wrap(";  ".join(parts), width, SCALES_H) if parts else []
    head = (view.title_lines - 1) * TITLE_SPACING  # a caption broken into lines
    top = at.box[1] + view.title_height * (TITLE_LEAD + head) + SCALES_H + _stars_rise(fs)
    for i, line in enumerate(lines):
        d.text(line, (at.box[0], top + i * SCALES_H * TITLE_SPACING), SCALES_H)


def _share_text(share: float) -> str:
    """A share of the largest force as the percentage the line of forces left out states:
    to two significant figures, rounded up past it (every force named is under it, the
    largest of them too)."""
    pct = share * 100.0
    e = math.floor(math.log10(pct)) - 1
    return fmt_number(math.ceil(pct / 10.0**e * (1.0 + tol.DERIVED)) * 10.0**e)


class _Forces(_ByScale, View):
    """A mechanism view with loads drawn at their own μ_F (``fs``: the view's μ_F, stated after
    the length scale in the caption, and those of its short forces, on a line under it) over
    the model box ``_ext``."""

    _ext: tuple[float, float, float, float]
    fs: ForceScales
    omitted: list[str]
    #: the sheet's detail letters, the insets' taken after the polygons' details
    letters: Iterator[str] | None = None

    def title_room(self) -> float:
        return super().title_room() + self.further_room()

    @property
    def kF(self) -> Scale:
        """The view's own μ_F."""
        return self.fs.scales[0]

    @property
    def short(self) -> bool:
        """Whether some forces are drawn at a second μ_F (the sheet explains the mark)."""
        return self.fs.tiered and not self.fs.insets

    def extent(self) -> tuple[float, float, float, float]:
        return self._ext

    def caption(self, scale: Scale | None) -> str:
        return f"{super().caption(scale)};  {self.scales_at(scale).caption()}"

    def draw(self, d: Drawing, at: Placed) -> None:
        """The drawing of links (:meth:`links`) at the force scales of its drawn size, its
        labels clear of its lines by :data:`LABEL_KEEP_MM` where they can."""
        self.placed(at)
        keep, d.keep = d.keep, LABEL_KEEP_MM
        try:
            self.links(d, at)
        finally:
            d.keep = keep

    def links(self, d: Drawing, at: Placed) -> None:
        raise NotImplementedError


class _Loaded(_Forces):
    """The mechanism in the force position with every load drawn at its μ_F."""

    def __init__(self, lk: Linkage, P: Position, f: Forces, title: str) -> None:
        super().__init__(title=title, title_height=5.0, margin=LOAD_MM, weight=2.0)
        self.lk, self.P, self.f = lk, P, f
        self.loads = [ld for lds in f.loads.values() for ld in lds]
        bodies = [q for bs in link_bodies(lk, P).values() for b in bs for q in b.points]
        self._ext = _bbox([*P.pos.values(), *bodies], lk.length)
        named = [(ld.name, ld.force.norm) for ld in self.loads
                 if ld.force is not None and ld.at is not None]  # fmt: skip
        self._forces, self._least, self._named = [F for _, F in named], LOAD_MM, named
        self._given = _given(self.loads)
        self.fs = view_scales(self._forces, LOAD_MM, given=self._given)
        self.omitted = omitted_values(self.fs, named)
        #: the solution and the letter of the crank's detail, where the crank may come out
        #: short (:meth:`crank_detail`); the detail's μ_l where one is drawn
        self.solved: Solved | None = None
        self.detail: str | None = None
        self.detail_scale: Scale | None = None

    def arrows(self) -> list[tuple[Vec, Vec]]:
        return [
            (ld.at, ld.force) for ld in self.loads if ld.force is not None and ld.at is not None
        ]

    def outline(self) -> list[tuple[Vec, Vec]]:
        return body_lines(link_bodies(self.lk, self.P))

    def links(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        start = len(d.sheet.items)
        lk, P = self.lk, self.P
        ins = Insets(self.fs, P.pos)
        clear = Clearance(d.sheet, len(d.sheet.items), _load_field(at), at.box)
        draw_scheme(v, scheme(lk, P), bodies=link_bodies(lk, P), pair_labels={},
                    label_height=3.5, guides=frame_guides(lk), guide_axes=True)  # fmt: skip
        places: dict[str, list[str]] = {}  # every named point, the frame's (O, C) too; the
        for name in P.pos:  # names of one place in one label ("B, K": a pin carrying a block)
            if name in lk.owner:
                there = next(
                    (k for k in places if P.pos[k].dist(P.pos[name]) <= tol.SAME_PLACE * lk.length),
                    name,
                )
                places.setdefault(there, []).append(name)
        for there, names in places.items():
            v.label(P.pos[there], ", ".join(markup_of(n) for n in names), 3.5, clear=1.0)
        label_centres(v, lk, P, self.loads, [P.pos[n] for n in places])
        # the moments, then the forces, each clear of the links and of the arrows before it
        _draw_loads(v, lk, P, self.loads, self.fs, "vector", clear, insets=ins)
        omega_arrow(v, lk, P)
        v.turn(P.pos[lk.pivot], self.f.M_bal, m_bal_start(lk, P, self.f.M_bal), WORDS("M_bal"),
               M_BAL_MM, M_BAL_SWEEP_DEG, "result", 2.5)  # fmt: skip
        self.crank_detail(d, at, Clearance(d.sheet, start, _field(at)))
        if self._sheet_detail_due(at):
            # the circle sheet_detail will draw round the crank: no inset over it
            r = max(lk.length, v.scale.k * M_BAL_MM)
            ins.reserved.append(CircleItem(v.p(lk.frame[lk.pivot]), v.mm(r) + DETAIL_RING_MM,
                                           "thin"))  # fmt: skip
        draw_insets(d, at, self, ins, start, self.omitted)

    def _sheet_detail_due(self, at: Placed) -> bool:
        """Whether :meth:`sheet_detail` may still mark the crank's detail on this view (after
        its insets are drawn)."""
        v = at.viewport
        return not (
            v is None
            or self.solved is None
            or self.detail_scale is not None
            or (self.detail is None and self.letters is None)
            or v.scale.mm(self.lk.length) >= CRANK_MM * (1.0 - tol.REL_LENGTH)
        )

    def crank_detail(self, d: Drawing, at: Placed, drawn: Clearance) -> None:
        """Where the view's μ_l draws the crank shorter than
        :data:`~geomcad.sheet.linkage.CRANK_MM` (the size rule itself): the crank enlarged in a
        detail (ESKD 2.305; the kinematic sheet's :class:`~geomcad.sheet.linkage._CrankDetail`
        in the force position), lettered by a circle round the crank, at the finest GOST scale
        that draws the crank at most 1.5 CRANK_MM long, at least CRANK_MM (finer than the
        view's; where GOST 2.302 has none in that span, the nearest longer), and finds room in
        the view's box clear of what it draws (``drawn``); the
        crank's loads and M_ур on it at the view's μ_F. Its letter is ``detail``, else the next
        of the sheet's ``letters`` (taken only where the detail is drawn). Nothing where no
        such room is left."""
        v, s = at.viewport, self.solved
        if v is None or s is None or (self.detail is None and self.letters is None):
            return
        if v.scale.mm(self.lk.length) >= CRANK_MM * (1.0 - tol.REL_LENGTH):
            return
        self._place_detail(d, at, drawn.segments(), _field(at))

    def sheet_detail(self, d: Drawing, at: Placed) -> bool:
        """Where the view's box left no room for :meth:`crank_detail` (review 7: a 20 mm crank
        at 1:2.5 and no detail): the detail in the sheet's free room, once every view is drawn,
        clear of all that is drawn on it, its texts and the form's boxes (ESKD 2.305: a detail
        lettered by its circle may stand anywhere on the sheet). Whether the sheet draws the
        crank as its rule wants (false: short, and no room for its detail)."""
        v = at.viewport
        if v is None or self.solved is None or self.detail_scale is not None:
            return True
        if self.detail is None and self.letters is None:
            return True
        if v.scale.mm(self.lk.length) >= CRANK_MM * (1.0 - tol.REL_LENGTH):
            return True
        sheet = d.sheet
        boxes = [*reserved(sheet.width, sheet.height)]
        for it in sheet.items:
            if isinstance(it, TextItem):
                (x, y), hh = it.at, it.height
                boxes.append((x, y - 1.3 * hh, x + it.width, y + 0.4 * hh))
        outline = [((x0, y0), (x1, y0)) for x0, y0, x1, _ in boxes]
        outline += [((x1, y0), (x1, y1)) for _, y0, x1, y1 in boxes]
        outline += [((x0, y1), (x1, y1)) for x0, _, x1, y1 in boxes]
        outline += [((x0, y0), (x0, y1)) for x0, y0, _, y1 in boxes]
        segs = np.concatenate(
            [Clearance(sheet, 0).segments(), np.array(outline, dtype=float).reshape(-1, 2, 2)]
        )
        field = (LEFT_MARGIN, MARGIN, sheet.width - MARGIN, sheet.height - MARGIN)
        self._place_detail(d, at, segs, field)
        return self.detail_scale is not None

    def _place_detail(
        self, d: Drawing, at: Placed, segs: npt.NDArray[np.float64],
        box: tuple[float, float, float, float],
    ) -> None:  # fmt: skip
        """The crank's detail (:meth:`crank_detail`) at the first of its scales for which
        ``box`` keeps room clear of ``segs``, nearest the crank's pivot; nothing where none."""
        v, s = at.viewport, self.solved
        assert v is not None and s is not None
        lk, P = self.lk, self.P
        # the crank's loads at the view's own μ_F (those too short there are in the view's
        # insets, :func:`draw_insets`, not drawn a second time here)
        loads = [ld for ld in self.f.loads.get(1, [])
                 if ld.force is None or self.fs.tier(ld.force.norm) == 0]  # fmt: skip
        arrows = [ld.force.norm / self.fs.k for ld in loads if ld.force is not None]
        O1 = lk.frame[lk.pivot]
        pivot = v.p(O1)
        for k in detail_scales(lk.length, v.scale.k):
            crank = lk.length / k
            half = max(CRANK_REACH * crank, M_BAL_MM + LABEL_ROOM_MM,
                       crank + max(arrows, default=0.0) + LABEL_ROOM_MM)  # fmt: skip
            w, h = 2.0 * half, 2.0 * half + DETAIL_TITLE_MM
            spot = free_spot(segs, box, (w, h), pivot, DETAIL_GAP_MM)
            if spot is None:
                continue
            x0, y0 = spot
            scale = Scale(k, "l")
            letter = self.detail
            if letter is None:
                assert self.letters is not None
                letter = self.detail = next(self.letters)
            det = _CrankDetail(s, letter, only=P, reach=CRANK_REACH)
            inner = (x0, y0 + DETAIL_TITLE_MM, x0 + w, y0 + h)
            pl = Placed(
                det, inner, inner, scale, d.viewport(scale, O1, (x0 + half, inner[1] + half))
            )
            clear = Clearance(d.sheet, len(d.sheet.items), inner)
            det.draw(d, pl)
            dv = pl.viewport
            assert dv is not None
            _draw_loads(dv, lk, P, loads, self.fs, "vector", clear)
            dv.turn(O1, self.f.M_bal, m_bal_start(lk, P, self.f.M_bal), WORDS("M_bal"), M_BAL_MM,
                    M_BAL_SWEEP_DEG, "result", 2.5)  # fmt: skip
            d.text(WORDS("crank_detail", letter=letter, scale=scale.ratio_text()),
                   (x0, y0 + TITLE_H), TITLE_H)  # fmt: skip
            # the circle round the crank and M_ур's arc about its pivot
            mark_detail(v, O1, max(lk.length, v.scale.k * M_BAL_MM), letter)
            self.detail_scale = scale
            return


def detail_scales(length: float, k_view: float) -> list[float]:
    """The GOST 2.302 μ_l (m/mm) a crank ``length`` (m) long drawn at ``k_view`` may take in
    its detail, in the order tried: those finer than ``k_view`` that draw it
    :data:`~geomcad.sheet.linkage.CRANK_MM` … 1.5 CRANK_MM long, the finest first; then, where
    the series has none in that span (a 50 mm crank: 1:1 draws it 50 mm, 1:2 25 mm; review 7's
    oscillator was left with no detail), the nearest that draws it longer."""
    fine = [k for k in GOST_K
            if k < k_view and length / k >= CRANK_MM * (1.0 - tol.REL_LENGTH)]  # fmt: skip
    span = sorted(k for k in fine if length / k <= 1.5 * CRANK_MM)
    return span or sorted(fine, reverse=True)[:1]


#: The room (mm) the layout keeps round a free body's drawing for its arrows (its margin);
#: :meth:`_FreeBody.grow` takes more where its box has it.
FREE_MARGIN = LOAD_MM * 0.75


class _FreeBody(_Forces):
    """An Assur group (or the crank) cut out, its joints lettered as on the mechanism, with its
    loads and the reactions of the links it is cut from (the external forces of its free body:
    R_12 of the crank on link 2, R_03 of the frame …; a reaction between the group's own links,
    found from one link's polygon, is internal and is not drawn here), each arrow clear of the
    links (:class:`~geomcad.sheet.loads.Clearance`)."""

    def __init__(self, lk: Linkage, P: Position, gf: GroupForces) -> None:
        links = gf.links
        title = WORDS("group", a=links[0], b=links[1]) if gf.group is not None else WORDS("crank")
        super().__init__(title=title, margin=FREE_MARGIN)
        self.lk, self.P, self.gf = lk, P, gf
        pts: list[Vec] = []
        for i in links:
            pts += [P.pos[n] for n in lk.points_on(i)]
            pts += [ld.at for ld in gf.loads[i] if ld.at is not None]
        pts += [r.at for r in gf.reactions]
        pts += [q for bs in link_bodies(lk, P, links).values() for b in bs for q in b.points]
        self._ext = _bbox(pts, lk.length * 0.5)
        named = [(ld.name, ld.force.norm) for i in links for ld in gf.loads[i]
                 if ld.force is not None]  # fmt: skip
        named += [(r.name, r.force.norm) for r in external(gf)]
        self._forces, self._least, self._named = [F for _, F in named], LOAD_MM, named
        self._keep = tuple(r.force.norm for r in external(gf))
        self._given = _given([ld for i in links for ld in gf.loads[i]])
        self.fs = view_scales(self._forces, LOAD_MM, self._keep, self._given)
        self.omitted = omitted_values(self.fs, named)

    def grow(self, pl: Placed) -> None:
        """The arrows' margin the room the view's box leaves round its drawing (centred in
        it), less a label's room past an arrow, where that is more than :data:`FREE_MARGIN`:
        a free body in a large box draws its forces longer, up to :func:`arrow_room` (review
        15: "μ_F as fine as fits"; the gang saw's group (4, 5) drew R05 10 mm in a box with
        room for 25 mm). Before its caption is drawn (it states the view's μ_F)."""
        self.margin = FREE_MARGIN
        self.__dict__.pop("_by_scale", None)
        if pl.scale is not None:
            x0, y0, x1, y1 = self._ext
            w, h = pl.size
            room = FREE_MARGIN + min(0.5 * (w - pl.scale.mm(x1 - x0)),
                                     0.5 * (h - pl.scale.mm(y1 - y0))) - LABEL_ROOM_MM  # fmt: skip
            self.margin = max(FREE_MARGIN, room)
            self.fs = self.scales_at(pl.scale)

    def arrows(self) -> list[tuple[Vec, Vec]]:
        gf = self.gf
        out = [(ld.at, ld.force) for i in gf.links for ld in gf.loads[i]
               if ld.force is not None and ld.at is not None]  # fmt: skip
        return out + [(r.at, r.force) for r in external(self.gf)]

    def outline(self) -> list[tuple[Vec, Vec]]:
        return body_lines(link_bodies(self.lk, self.P, self.gf.links))

    def links(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        start = len(d.sheet.items)
        lk, P, gf = self.lk, self.P, self.gf
        ins = Insets(self.fs, P.pos)
        links = gf.links
        full = scheme(lk, P)
        own = {str(i) for i in links}
        pairs = tuple(p for p in full.pairs if own & set(p.links))
        near = {x for p in pairs for x in p.links} - own - {full.frame}
        mech = Mechanism(tuple(Link(x) for x in sorted(own | near)), pairs, full.frame)
        clear = Clearance(d.sheet, len(d.sheet.items), _load_field(at), at.box)
        draw_scheme(v, mech, bodies=link_bodies(lk, P, links), pair_labels={},
                    ghosts=sorted(near), guides=frame_guides(lk), cut_free=True)  # fmt: skip
        for name in joint_names(lk, links):  # lettered as on the mechanism
            v.label(P.pos[name], markup_of(name), 3.5, clear=1.0)
        label_centres(v, lk, P, [ld for i in links for ld in gf.loads[i]],
                      [P.pos[n] for n in joint_names(lk, links)])  # fmt: skip
        arcs: dict[tuple[float, float], int] = {}
        for r in external(gf):
            if r.couple:
                label = f"M_{{{r.of}{r.on}}}"
                c = P.pos[r.joint]
                moment(v, c, r.couple, _moment_radius(v, c, arcs), label, "result", height=2.5)
        loads = [ld for i in links for ld in gf.loads[i]]
        _draw_loads(v, lk, P, [ld for ld in loads if ld.force is None], self.fs, "vector",
                    arcs=arcs)  # fmt: skip
        # the reactions found at their joints first, then the loads where they are clear
        for r in external(gf):
            _force(
                v, r.at, r.force, self.fs, load_name(r.name), True, "result", clear, ins, r.joint
            )
        _draw_loads(v, lk, P, [ld for ld in loads if ld.force is not None], self.fs, "vector",
                    clear, insets=ins)  # fmt: skip
        if gf.group is None:
            M = -sum(
                (ld.at - P.pos[lk.pivot]).cross(ld.force)
                if ld.force is not None and ld.at
                else ld.moment
                for ld in gf.loads[1]
            )
            v.turn(P.pos[lk.pivot], M, m_bal_start(lk, P, M), WORDS("M_bal"), M_BAL_MM,
                   M_BAL_SWEEP_DEG, "result", 2.5)  # fmt: skip
        draw_insets(d, at, self, ins, start, self.omitted)


def label_centres(
    v: Viewport, lk: Linkage, P: Position, loads: Sequence[Applied], named: Sequence[Vec]
) -> None:
    """Each centre of mass S_i a weight or an inertia force of ``loads`` acts at: a dot,
    lettered as the order of the analysis names it ("в точке S_5"), where it is the middle
    of its link's joints (a named point, ``named`` places, is lettered already)."""
    seen: set[int] = set()
    for ld in loads:
        if ld.kind not in ("weight", "inertia") or ld.link in seen or lk.centre(ld.link):
            continue
        seen.add(ld.link)
        q = centre_vec(lk, ld.link, P.pos)
        if any(q.dist(n) <= tol.SAME_PLACE * lk.length for n in named):
            continue
        v.dot(q)
        v.label(q, markup_of(f"S{ld.link}"), 3.5, clear=1.0)


#: The forces sheet's crank detail reaches this many crank lengths round the pivot (the crank,
#: the stubs of its links, ω1; M_ур's arc and the loads may reach further).
CRANK_REACH = 1.3
#: The room (mm) of the crank detail's title line over its drawing.
DETAIL_TITLE_MM = 8.0
#: How far (mm) the crank's detail keeps from what its view draws (the view's labels, placed
#: after, find room in it).
DETAIL_GAP_MM = 6.0
#: The cell (mm) of the grid the crank detail's place is sought on.
SPOT_MM = 2.0


def free_spot(
    segs: npt.NDArray[np.float64], box: tuple[float, float, float, float],
    size: tuple[float, float], near: tuple[float, float], gap: float,
) -> tuple[float, float] | None:  # fmt: skip
    """The top-left corner (sheet mm) of a rectangle ``size`` (w, h) inside ``box`` that keeps
    ``gap`` mm from every segment of ``segs`` (n, 2, 2; and inside the box by it), its centre
    nearest ``near``; ``None`` where there is none. The segments are sampled on a grid of
    :data:`SPOT_MM` cells; a summed-area table tests every corner at once."""
    x0, y0, x1, y1 = box
    nx, ny = int((x1 - x0) // SPOT_MM), int((y1 - y0) // SPOT_MM)
    cw, ch = (
        math.ceil((size[0] + 2.0 * gap) / SPOT_MM),
        math.ceil((size[1] + 2.0 * gap) / SPOT_MM),
    )
    if nx < cw or ny < ch:
        return None
    occ = np.zeros((ny, nx), dtype=np.int32)
    if len(segs):
        a, b = segs[:, 0, :], segs[:, 1, :]
        n = np.maximum(1, np.ceil(np.hypot(*(b - a).T) / (SPOT_MM / 2.0))).astype(int)
        t = np.concatenate([np.linspace(0.0, 1.0, m + 1) for m in n])
        i = np.repeat(np.arange(len(segs)), n + 1)
        pts = a[i] + (b[i] - a[i]) * t[:, None]
        cx = np.floor((pts[:, 0] - x0) / SPOT_MM).astype(int)
        cy = np.floor((pts[:, 1] - y0) / SPOT_MM).astype(int)
        ok = (cx >= 0) & (cx < nx) & (cy >= 0) & (cy < ny)
        occ[cy[ok], cx[ok]] = 1
    sat = np.zeros((ny + 1, nx + 1), dtype=np.int64)
    sat[1:, 1:] = occ.cumsum(0).cumsum(1)
    used = sat[ch:, cw:] - sat[:-ch, cw:] - sat[ch:, :-cw] + sat[:-ch, :-cw]
    free = np.argwhere(used == 0)
    if not len(free):
        return None
    corners = np.column_stack([x0 + free[:, 1] * SPOT_MM + gap, y0 + free[:, 0] * SPOT_MM + gap])
    centres = corners + np.array(size) / 2.0
    best = int(np.argmin(np.hypot(centres[:, 0] - near[0], centres[:, 1] - near[1])))
    return float(corners[best, 0]), float(corners[best, 1])


def body_lines(bodies: Mapping[str, Sequence[Body]]) -> list[tuple[Vec, Vec]]:
    """The straight pieces (model units) of the links' bodies (:func:`link_bodies`)."""
    out: list[tuple[Vec, Vec]] = []
    for bs in bodies.values():
        for b in bs:
            pts = [*b.points, b.points[0]] if b.closed else list(b.points)
            out += [(x, y) for x, y in itertools.pairwise(pts) if x != y]
    return out


def _field(at: Placed) -> tuple[float, float, float, float]:
    """Where a view's force arrows go: its box below its caption."""
    return at.box[0], at.inner[1], at.box[2], at.box[3]


def _load_field(at: Placed) -> tuple[float, float, float, float]:
    """Where the load arrows of a drawing of links go (:class:`Clearance`'s box): as
    :func:`_field`, and over the drawing up to :data:`LABEL_ROOM_MM` under its caption (the
    view's top margin, which :func:`_field` leaves to the drawing): a load along a slider's
    guide arrives at the block's face from above where the guide's axis runs up, outside the
    body on its line of action, rather than down its link (review 14:
    tangent_rocking_slider's F_D on its rod, the compressor's F_B down its connecting rod)."""
    x0, y0, x1, y1 = _field(at)
    caption = at.inner[1] - at.view.margin
    return x0, min(y0, caption + LABEL_ROOM_MM), x1, y1


def _within(p: tuple[float, float], box: tuple[float, float, float, float], e: float) -> bool:
    """Whether point ``p`` is in ``box`` to ``e`` (0.1 mm on the paper)."""
    return box[0] - e <= p[0] <= box[2] + e and box[1] - e <= p[1] <= box[3] + e


def external(gf: GroupForces) -> list[Reaction]:
    """The reactions on a group's (or the crank's) free body: those of the links it is cut
    from and of the frame on its links; a reaction between two of its own links (R_32 of an
    RRR) is internal to it."""
    return [r for r in gf.reactions if r.on in gf.links and r.of not in gf.links]


def joint_names(lk: Linkage, links: Sequence[int]) -> list[str]:
    """The lettered points of a cut-out group or the crank: every joint and point of its links
    (the frame's joints it hangs on, O and C, among them), each once."""
    return list(dict.fromkeys(n for i in links for n in lk.points_on(i)))


def polygon_points(poly: ForcePolygon) -> list[Vec]:
    """The polygon's vertices (for its extent)."""
    return [q for pv in poly.vectors for q in (pv.tail, pv.head)]


def lever_images(P: Position, lev: Lever) -> dict[str, Vec]:
    """The lettered points of Zhukovsky's lever by the plan's names: every point of the
    velocity plan turned 90° (the pole p, a sliding pair's a3 …), then every load's point off
    the plan (a centre of mass s2 …)."""
    out = {name: q.perp() for name, q in P.vp.points.items()}
    for it in lev.items:
        if it.point:
            out.setdefault(P.pn(it.point), it.image)
    return out


def lever_links(lk: Linkage, P: Position, lev: Lever) -> dict[int, list[str]]:
    """Each moving link's points on the lever (plan names): its points on the plans (its
    joints, its [[point]] points, the point of a sliding pair on it) and the points its loads
    act at; the image of the link is the figure they make, joined as on the velocity plan."""
    out: dict[int, list[str]] = {}
    for link in lk.moving_links:
        names = [n for _, n in P.handles.get(link, [])]
        names += [P.pn(it.point) for it in lev.items if it.link == link and it.point]
        out[link] = list(dict.fromkeys(names))
    return out


def figure_edges(pts: Sequence[Vec], eps: float) -> list[tuple[Vec, Vec]]:
    """The segments that draw the image of a link through its points ``pts``: its outline
    (the convex hull, with the points on an edge as the edge's vertices: a–s2–b, not a–b and
    s2–m) and a point inside it joined to every corner; points closer than ``eps`` are one."""
    uniq: list[Vec] = []
    for q in pts:
        if all(q.dist(u) > eps for u in uniq):
            uniq.append(q)
    if len(uniq) < 2:
        return []
    uniq.sort(key=lambda q: (q.x, q.y))

    def half(seq: Sequence[Vec]) -> list[Vec]:
        out: list[Vec] = []
        for q in seq:
            while len(out) >= 2 and (out[-1] - out[-2]).cross(q - out[-2]) <= 0.0:
                out.pop()
            out.append(q)
        return out

    lo, hi = half(uniq), half(uniq[::-1])
    corners = lo[:-1] + hi[:-1] if len(uniq) > 2 else uniq
    # all in line: the hull is the segment between the two extremes
    ring = len(corners) > 2
    edges: list[tuple[Vec, Vec]] = []
    on_edge: set[int] = set()
    sides = (
        list(zip(corners, corners[1:] + corners[:1], strict=True))
        if ring
        else [(uniq[0], uniq[-1])]
    )
    for a, b in sides:
        u = b - a
        n2 = u.dot(u)
        chain = []
        for i, q in enumerate(uniq):
            t = (q - a).dot(u) / n2
            if (
                -tol.DERIVED <= t <= 1.0 + tol.DERIVED
                and abs(u.cross(q - a)) / math.sqrt(n2) <= eps
            ):
                chain.append((t, q))
                on_edge.add(i)
        chain.sort(key=lambda tq: tq[0])
        edges += [(x, y) for (_, x), (_, y) in itertools.pairwise(chain)]
    for i, q in enumerate(uniq):
        if i not in on_edge:
            edges += [(c, q) for c in corners]
    return edges


#: Two forces at one point of the lever closer in direction than this (degrees) would be drawn
#: over one another: the second is drawn arriving at the point.
SAME_LINE_DEG = 20.0
#: A load's arrow within this angle (degrees) and distance (mm) of a side of the lever runs
#: along it; more than SIDE_RUN_MM of it so is a load drawn along an outline, which a teacher
#: returns (review 14: the walkbeam's G₅ down pd for 49 mm).
SIDE_DEG = 10.0
SIDE_MM = 1.0
SIDE_RUN_MM = 2.0
#: The slides (mm) past its point tried for a load along a side on both sides of its point.
SIDE_SLIDES_MM = tuple(float(g) for g in range(2, 302, 2))


def side_run(a: Vec, run: Vec, k: float, lines: Sequence[tuple[Vec, Vec]]) -> float:
    """How much (mm) of the arrow from model point ``a`` along ``run`` (model units) lies
    within :data:`SIDE_MM` and :data:`SIDE_DEG` of one of ``lines`` (model segments), at
    ``k`` model units per mm."""
    n_mm = run.norm / k
    if n_mm <= 0.0 or not lines:
        return 0.0
    segs = np.array([((p.x, p.y), (q.x, q.y)) for p, q in lines], dtype=float) / k
    ab = segs[:, 1] - segs[:, 0]
    n2 = (ab**2).sum(axis=1)
    u = (run.x / run.norm, run.y / run.norm)
    ok = n2 > 0.0
    sin = np.abs(ab[:, 0] * u[1] - ab[:, 1] * u[0]) / np.sqrt(np.where(ok, n2, 1.0))
    ok &= sin <= math.sin(math.radians(SIDE_DEG))
    if not ok.any():
        return 0.0
    segs, ab, n2 = segs[ok], ab[ok], n2[ok]
    m = max(2, int(n_mm / 0.25))
    t = (np.arange(m) + 0.5) / m * n_mm
    pts = np.column_stack([a.x / k + t * u[0], a.y / k + t * u[1]])
    w = np.clip(((pts[:, None, :] - segs[None, :, 0]) * ab[None]).sum(axis=2) / n2, 0.0, 1.0)
    foot = segs[None, :, 0] + w[..., None] * ab[None]
    d = np.linalg.norm(pts[:, None, :] - foot, axis=2)
    return float(np.count_nonzero((d < SIDE_MM).any(axis=1)) * n_mm / m)


def load_sides(
    loads: Sequence[tuple[Vec, Vec, str, str]],
    k: float,
    lengths: Sequence[float],
    ext: tuple[float, float, float, float] | None = None,
    slack: float = 0.0,
    lines: Sequence[tuple[Vec, Vec]] = (),
) -> list[tuple[bool, Vec]]:
    """How each load (point, force, …) of the lever is drawn: whether it arrives at its point
    (else leaves it), and from where (model units). A force along the line of a longer one at
    the same point and of its sense (within :data:`SAME_LINE_DEG`) goes on from that one's
    tip (Φ₃ after F_B at b); of opposite senses they leave the point
    back to back; a force that, ``lengths`` mm long, would run more than ``slack`` mm (the
    view's margin) past the view's extent ``ext`` (model units) arrives at its point where
    that keeps more of it over the drawing and no arrow there lies on that side. A force
    that would run along one of ``lines`` (the lever's sides, model units: within
    :data:`SIDE_DEG` and :data:`SIDE_MM` of one for more than :data:`SIDE_RUN_MM`) is drawn
    from the point's other side (arriving instead of leaving, or the reverse) where that runs
    along less of them (review 14: the walkbeam's G₅ down the side pd for 49 mm). ``k``: the
    view's scale (model units per mm; points within 0.8 mm on the paper are one)."""
    starts = [q for q, _, _, _ in loads]
    side: dict[int, bool] = {}
    cos = math.cos(math.radians(SAME_LINE_DEG))

    def past(q: Vec) -> float:
        if ext is None:
            return 0.0
        return max(ext[0] - q.x, q.x - ext[2], 0.0) + max(ext[1] - q.y, q.y - ext[3], 0.0)

    for i in sorted(range(len(loads)), key=lambda i: -lengths[i]):
        q, F = loads[i][0], loads[i][1]
        side[i] = False
        if F.norm == 0.0:
            continue
        u = F.unit()
        # on from the tip of the longer ones of its sense along its line there
        tips = [
            starts[j] + (Vec(0.0, 0.0) if side[j] else loads[j][1].unit() * (lengths[j] * k))
            for j in side
            if j != i and loads[j][1].norm > 0.0 and (loads[j][0] - q).norm / k < 0.8
            and loads[j][1].unit().dot(u) > cos
        ]  # fmt: skip
        if tips:
            starts[i] = max(tips, key=lambda t: (t - q).dot(u))
            continue
        # the rays from the point that the arrows drawn from it lie on
        rays = [
            (j, loads[j][1].unit() * (-1.0 if a else 1.0))
            for j, a in side.items()
            if j != i and starts[j] == loads[j][0] and loads[j][1].norm > 0.0
            and (loads[j][0] - q).norm / k < 0.8
        ]  # fmt: skip
        run = u * (lengths[i] * k)
        out = past(q + run)
        free_back = not any(r.dot(-u) > cos for _, r in rays)
        on_side = side_run(q, run, k, lines), side_run(q - run, run, k, lines)
        if (
            on_side[0] > SIDE_RUN_MM
            and on_side[1] < on_side[0]
            and free_back
            and past(q - run) <= max(slack * k, out)
        ):
            # along a side leaving the point: arriving at it from the other side, where that
            # keeps within the view's margin as far as leaving does (never at the cost of the
            # lever's size: the walkbeam's G5 from above held its lever at 0,0025 for 0,002)
            side[i] = True
            continue
        if out > slack * k and past(q - run) < out - 1.0 * k and free_back:
            # out of the view leaving it: arriving, along a side or not (a load along a side
            # beats a lever drawn smaller: the crusher's P_M5 held it at 0,01 for 0,004
            # (m/s)/mm)
            side[i] = True
            continue
        # leaving along an arrow that arrives there (of the opposite sense): from its tail
        ahead = [lengths[j] for j, r in rays if r.dot(u) > cos]
        if ahead:
            starts[i] = q + u * (max(ahead) * k)
            continue
        if min(on_side) > SIDE_RUN_MM and lines:
            # along a side on either side of its point (Φ₁ at s₁ on pa, the crank's
            # centripetal inertia): slid along its own line past the side's end, its thin
            # line of action (drawn over the side) tying it back
            def slid(g: float, q: Vec = q, u: Vec = u, run: Vec = run) -> tuple[Vec, Vec]:
                # the arrow's tail and its far end, g mm past its point (< 0: arriving)
                s0 = q + u * (g * k)
                return (s0, s0 + run) if g > 0.0 else (s0 - run, s0)

            tries = [(g, side_run(slid(g)[0], run, k, lines), abs(g))
                     for g in (x * sgn for x in SIDE_SLIDES_MM for sgn in (1.0, -1.0))]  # fmt: skip
            g, along, _ = min(tries, key=lambda t: (t[1] > SIDE_RUN_MM,
                              sum(past(e) for e in slid(t[0])), t[2]))  # fmt: skip
            if along <= SIDE_RUN_MM:
                side[i] = g < 0.0
                starts[i] = q + u * (g * k)
    return [(side[i], starts[i]) for i in range(len(loads))]


#: Two arrows of the lever, each with its label's room past its far end (LABEL_ROOM_MM), keep
#: this far (mm) apart where they act at different points: closer, one is slid along its line
#: of action (:func:`uncross`; review 10: kulisa's F_D and P_ур crossed near s4, their labels
#: side by side).
ARROWS_CLEAR_MM = 1.5
#: The slides (mm) tried past an arrow's point, beyond arriving at it or leaving it (tied back
#: to it by its thin line of action), each mm costing _W_SLIDE; an arrow over the view's edge
#: (its margin) costs _W_EDGE per mm.
SLIDES_MM = (4.0, 8.0, 12.0, 16.0, 24.0, 32.0)
_W_SLIDE, _W_EDGE = 0.05, 1.0
_Seg = tuple[tuple[float, float], tuple[float, float]]


def uncross(
    loads: Sequence[tuple[Vec, Vec, str, str]],
    k: float,
    lengths: Sequence[float],
    sides: Sequence[tuple[bool, Vec]],
    ext: tuple[float, float, float, float] | None = None,
    slack: float = 0.0,
    lines: Sequence[tuple[Vec, Vec]] = (),
) -> list[tuple[bool, Vec]]:
    """:func:`load_sides` (``sides``) with no two arrows of different points crossing or
    within :data:`ARROWS_CLEAR_MM` of each other, an arrow's label's room
    (:data:`LABEL_ROOM_MM` past its far end) counted with it: the longer arrows keep their
    places, and a shorter one that would meet one of them is slid along its line of action —
    arriving at its point instead of leaving it (or the other way), else past it by one of
    :data:`SLIDES_MM` (its thin line of action ties it back) — to the place that meets none
    and keeps most within the view's extent ``ext`` plus ``slack`` mm, the nearest first, and
    of those one that runs along none of ``lines`` (the lever's sides, :func:`side_run`)
    first. An arrow set on from another's tip (one line, one point) keeps its place. Model
    units, ``k`` model units per mm."""
    n = len(loads)
    out = list(sides)
    eps = 0.8 * k

    def foot(i: int, arrive: bool, start: Vec) -> _Seg:
        # the arrow and its label's room past its far end from its point, in mm
        run = loads[i][1].unit() * (lengths[i] * k * (-1.0 if arrive else 1.0))
        a, b = start, start + run
        q = loads[i][0]
        far, near = (a, b) if (a - q).norm > (b - q).norm else (b, a)
        room = far + (far - near).unit() * (LABEL_ROOM_MM * k) if (far - near).norm > 0 else far
        return ((near.x / k, near.y / k), (room.x / k, room.y / k))

    def past(seg: _Seg) -> float:
        if ext is None:
            return 0.0
        x0, y0, x1, y1 = (e / k for e in ext)
        return sum(max(x0 - slack - x, x - x1 - slack, 0.0) + max(y0 - slack - y, y - y1 - slack,
                   0.0) for x, y in seg)  # fmt: skip

    def meets(seg: _Seg, feet: Sequence[_Seg]) -> int:
        return sum(_seg_dist(seg, f) < ARROWS_CLEAR_MM for f in feet)

    placed: list[int] = []
    for i in sorted(range(n), key=lambda i: -lengths[i]):
        q, F = loads[i][0], loads[i][1]
        arrive, start = out[i]
        feet = [foot(j, *out[j]) for j in placed if (loads[j][0] - q).norm > eps]
        placed.append(i)
        if F.norm == 0.0 or not feet or (start - q).norm > eps or not meets(foot(i, *out[i]), feet):
            continue
        u = F.unit()
        tries = [(arrive, start, 0.0), (not arrive, q, 0.0)]
        for g in SLIDES_MM:
            tries.append((False, q + u * (g * k), g))  # leaving, past its point
            tries.append((True, q - u * (g * k), g))  # arriving, short of it

        def along(t: tuple[bool, Vec, float], i: int = i, u: Vec = u) -> bool:
            run = u * (lengths[i] * k)
            return side_run(t[1] - run if t[0] else t[1], run, k, lines) > SIDE_RUN_MM

        best = min(tries, key=lambda t: (meets(seg := foot(i, t[0], t[1]), feet), along(t),
                                         _W_EDGE * past(seg) + _W_SLIDE * t[2]))  # fmt: skip
        out[i] = (best[0], best[1])
    return out


#: The lever asks the layout for a μ_V that draws the images its loads act at this far (mm)
#: apart at least (its ``most_k``): two insets' circles round them side by side, their
#: letters between (review 9: the rocking cylinder's lever, drawn 80 × 60 mm, crowded its
#: insets Ж1, И1, Г1 round the pole) …
LEVER_APART_MM = 10.0
#: … where that draws the lever at most this large (mm); points closer than LEVER_ONE of its
#: size are one (an inset's circle takes them together).
LEVER_MOST_MM = 250.0
LEVER_ONE = 0.01


def lever_k(points: Sequence[Vec], ext: tuple[float, float, float, float], series: Series) -> float:
    """The μ_V (model units per mm) the lever asks of the layout (:data:`LEVER_APART_MM`):
    the coarsest of ``series`` that draws any two of ``points`` (the images its loads act at)
    that far apart, or its extent ``ext`` :data:`LEVER_MOST_MM` large where that is coarser;
    0 (none) for a lever of one point."""
    size = max(ext[2] - ext[0], ext[3] - ext[1])
    one: list[Vec] = []
    for q in points:
        if all(q.dist(u) > LEVER_ONE * size for u in one):
            one.append(q)
    gaps = [a.dist(b) for a, b in itertools.combinations(one, 2)]
    if not gaps or size <= 0.0:
        return 0.0
    k = max(min(gaps) / LEVER_APART_MM, size / LEVER_MOST_MM)
    return round_scale_down(k, "v", series).k


class _Lever(_ByScale, View):
    """Zhukovsky's lever: the velocity plan turned 90° with the loads at their points'
    images and the balancing force at the crank's joint."""

    letters: Iterator[str] | None = None

    def __init__(self, lk: Linkage, P: Position, f: Forces) -> None:
        lev = f.lever
        #: the forces drawn as arrows, and each moment's couple, drawn as the moment's arc
        #: on its link's image (:func:`lever_loads`)
        self.lever_forces, self.moments = lever_loads(f)
        forces = [it.force.norm for it in self.lever_forces] + [lev.F_bal.norm]
        self._forces, self._least, self._keep = forces, LEVER_LOAD_MM, (lev.F_bal.norm,)
        mine = {ld.name for lds in f.loads.values() for ld in _given_loads(lds)}
        self._given = tuple(it.force.norm for it in self.lever_forces if it.name in mine)
        self.fs = view_scales(forces, LEVER_LOAD_MM, self._keep, self._given)
        self.short = False
        self._keep_long = False  # (until :meth:`grow`)
        super().__init__(title=WORDS("lever"), title_height=5.0, quantity="v", series="nice",
                         margin=LEVER_LOAD_MM)  # fmt: skip
        self.lk, self.P, self.f = lk, P, f
        self._named = [(it.name, it.force.norm) for it in self.lever_forces]
        self.omitted = omitted_values(self.fs, self._named)
        pts = [Vec(0.0, 0.0), *lever_images(P, lev).values(), *(it.image for it in lev.items)]
        xs = [q.x for q in pts]
        ys = [q.y for q in pts]
        self._ext = (min(xs), min(ys), max(xs), max(ys))
        self.most_k = lever_k([q for q, _ in self.arrows()], self._ext, self.series)

    def _drawn_at(self, fs: ForceScales) -> set[str]:
        """The names of the points off the velocity plan the lever draws: those of the forces
        it draws (at ``fs``) and the ends of the links' images its moments are drawn on."""
        P = self.P
        at = {P.pn(it.point) for it in self.lever_forces
              if it.point and fs.tier(it.force.norm) is not None}  # fmt: skip
        return at | {P.pn(it.point) for m in self.moments for it in m.pair if it.point}

    def extent(self) -> tuple[float, float, float, float]:
        return self._ext

    def arrows(self) -> list[tuple[Vec, Vec]]:
        lev = self.f.lever
        return [(it.image, it.force) for it in self.lever_forces] + [
            (lev.images[self.lk.joint], lev.F_bal)
        ]

    def _sides(
        self, k: float, images: Mapping[str, Vec], fs: ForceScales | None = None, slide: bool = True
    ) -> tuple[Insets, list[tuple[Vec, Vec, str, str]], list[float], list[tuple[bool, Vec]]]:
        """The lever's insets (the forces short at ``fs``, the view's by default), the loads
        drawn in it, their lengths (mm) and how each is drawn (:func:`load_sides`, then
        :func:`uncross` where ``slide``) at scale ``k`` (model units per mm)."""
        fs = fs or self.fs
        lev = self.f.lever
        loads = [(it.image, it.force, load_name(it.name), "vector") for it in self.lever_forces]
        loads.append((lev.images[self.lk.joint], lev.F_bal, WORDS("P_bal"), "result"))
        points = [self.P.pn(it.point) if it.point else "" for it in self.lever_forces]
        points.append(self.P.pn(self.lk.joint))
        # the forces short at the view's μ_F go to its insets, the others are drawn here
        ins = Insets(fs, images)
        here = []
        for (q, F, name, role), point in zip(loads, points, strict=True):
            t = fs.tier(F.norm)
            if t is not None and t > 0:
                ins.add(q, F, t, name, role, point)
            elif t is not None:
                here.append((q, F, name, role))
        lengths = [F.norm / fs.k for _, F, _, _ in here]
        # an arrow leaves its point unless it would run out of the view (past its margin,
        # less a label's room) or along a side of the lever
        lines = self.lines(k, fs)
        sides = load_sides(here, k, lengths, self._ext, self.margin - LABEL_ROOM_MM, lines)
        if slide:
            sides = uncross(here, k, lengths, sides, self._ext, self.margin - LABEL_ROOM_MM,
                            lines)  # fmt: skip
        return ins, here, lengths, sides

    def lines(self, k: float, fs: ForceScales | None = None) -> list[tuple[Vec, Vec]]:
        """The lines the lever draws at ``k`` model units per mm (model units): the velocity
        plan's vectors turned 90° (those over 0.3 mm) and the sides of the links' images
        (:func:`figure_edges`) the plan does not draw already, at the points it draws
        (``fs``: the view's force scales, by which a point whose loads are all left out is
        not drawn)."""
        fs = fs or self.fs
        P, lev = self.P, self.f.lever
        drawn: list[tuple[Vec, Vec]] = []
        for vec in P.vp.vectors:
            a, b = P.vp.points[vec.tail].perp(), P.vp.points[vec.head].perp()
            if (b - a).norm / k > 0.3:
                drawn.append((a, b))
        images = lever_images(P, lev)
        # a point off the velocity plan whose loads are all left out (review 12: the bloom
        # shear's d4 of a force left out, 0,02 %) would be a point nothing on the sheet
        # explains: not drawn, nor its link's side to it
        drawn_at = self._drawn_at(fs)
        images = {n: q for n, q in images.items() if n in P.vp.points or n in drawn_at}
        for figure in lever_links(self.lk, P, lev).values():
            mine = [images[n] for n in figure if n in images]
            for x, y in figure_edges(mine, 0.3 * k):
                # a side the plan draws already (pa, a3a …) is not drawn twice
                if not any({x, y} == {a, b} for a, b in drawn):
                    drawn.append((x, y))
        return drawn

    def _fits(self, fs: ForceScales, scale: Scale, box: tuple[float, float, float, float]) -> bool:
        """As on a drawing of links, each arrow as :func:`load_sides` draws it (a force on from
        another's tip: the two together)."""
        # (the arrows at their points: the scale a slide of uncross would not change)
        _, here, lengths, sides = self._sides(scale.k, {}, fs, slide=False)
        for (_, F, _, _), (arrive, p), n in zip(here, sides, lengths, strict=True):
            if F.norm > 0.0:
                e = p + F.unit() * (scale.k * n * (-1.0 if arrive else 1.0))
                if not (
                    _within((p.x, p.y), box, 0.1 * scale.k)
                    and _within((e.x, e.y), box, 0.1 * scale.k)
                ):
                    return False
        return True

    def title_room(self) -> float:
        return super().title_room() + self.further_room()

    def grow(self, pl: Placed, lay: Layout) -> None:
        """:meth:`_grow`, then P_ур drawn in the lever rather than in an inset where longer
        arrows do that within its box (:meth:`_ByScale.scales_at`): the lever as large as its
        box allows first, its arrows as long as P_ур needs then."""
        self._keep_long = False
        self.__dict__.pop("_by_scale", None)
        try:
            self._grow(pl, lay)
        finally:
            self._keep_long = True
            self.__dict__.pop("_by_scale", None)
        if pl.scale is not None:
            self.fs = self.scales_at(pl.scale)

    def _grow(self, pl: Placed, lay: Layout) -> None:
        """The lever drawn larger in its box where its arrows allow: the layout reserves
        LEVER_LOAD_MM round it for its arrows whatever they are; here the finer steps of its
        series are tried, each with the margin its box leaves round the drawing, while the
        arrows drawn at that scale's μ_F (:meth:`scales_at`), their labels' room past them,
        keep within the box (no more forces left out, then none more in insets, than at the
        layout's scale)."""
        if pl.scale is None or self.group:
            return
        x0, y0, x1, y1 = self._ext
        top = pl.box[1] + self.title_room()
        rw, rh = pl.box[2] - pl.box[0] - 2.0 * LEVER_EDGE_MM, pl.box[3] - top - 2.0 * LEVER_EDGE_MM
        margin, scale, fs = self.margin, pl.scale, self.scales_at(pl.scale)
        cost = self._cost(fs)
        best: tuple[float, Scale] | None = None
        k = scale.k
        while True:
            k = round_scale_down(k * (1.0 - 4.0 * tol.REL_LENGTH), scale.q, self.series).k
            m = min(0.5 * (rw - (x1 - x0) / k), 0.5 * (rh - (y1 - y0) / k))
            if m < LABEL_ROOM_MM + LEVER_EDGE_MM:
                break
            at = Scale(k, scale.q)
            # the view's μ_F chosen for the room its arrows have short of their labels' room:
            # the same μ_F the drawing then takes (scales_at with this margin)
            self.margin = m - LABEL_ROOM_MM
            self.__dict__.pop("_by_scale", None)
            fs_at = self.scales_at(at)
            inner = (x0 - self.margin * k, y0 - self.margin * k,
                     x1 + self.margin * k, y1 + self.margin * k)  # fmt: skip
            if self._cost(fs_at) > cost or not self._fits(fs_at, at, inner):
                break
            best = (m, at)
        self.margin = margin
        self.__dict__.pop("_by_scale", None)
        if best is None:
            self.fs = fs
            return
        m, at = best
        self.margin = m - LABEL_ROOM_MM
        e = LEVER_EDGE_MM + m
        pl.inner = (pl.box[0] + e, top + e, pl.box[2] - e, pl.box[3] - e)
        pl.scale = at
        lay.groups[f"#{id(self)}"] = at
        self.fs = self.scales_at(at)

    def caption(self, scale: Scale | None) -> str:
        m = WORDS("m_bal", value=_load(self.f.lever.M_bal))
        return f"{super().caption(scale)};  {self.scales_at(scale).caption()};  {m}"

    def draw(self, d: Drawing, at: Placed) -> None:
        lev = self.f.lever
        self.placed(at)
        v = at.viewport
        assert v is not None
        start = len(d.sheet.items)
        kv = v.scale
        P, lev = self.P, self.f.lever
        for a, b in self.lines(kv.k):
            v.seg(a, b, "construction")
        images = lever_images(P, lev)
        drawn_at = self._drawn_at(self.fs)
        images = {n: q for n, q in images.items() if n in P.vp.points or n in drawn_at}
        groups: list[tuple[Vec, list[str]]] = []
        for name, im in images.items():
            for q, names in groups:
                if kv.mm(im.dist(q)) < 0.8:
                    names.append(markup_of(name))
                    break
            else:
                groups.append((im, [markup_of(name)]))
        asked = []
        for q, names in groups:
            v.dot(q)
            asked.append(len(d.pending))
            v.label(q, ", ".join(names), 2.5, clear=0.8)
        ins, here, lengths, sides = self._sides(kv.k, images)
        # the moments: each an arc on its link's image, in the sense of M·xy/l_XY, clear of
        # the lettered points (and their insets) where the image is long enough
        arcs: dict[tuple[float, float], int] = {}
        clear_of = [Vec(0.0, 0.0), *(q for q, _ in groups), *(sh.at for sh in ins.shorts)]
        for m in self.moments:
            if abs(m.value) > tol.DERIVED * max(abs(it.moment) for it in m.pair):
                q = m.at(kv.k, clear_of, MOMENT_MM)
                r = _moment_radius(v, q, arcs)
                if any(kv.mm(c.dist(q)) < 1.0 for c in clear_of):
                    r += INSET_ARC_MM
                moment(v, q, m.value, r, load_name(m.name), "vector", height=2.5)
                clear_of.append(q)
        segs = []
        for (_, F, _, _), (arrive, at_), n in zip(here, sides, lengths, strict=True):
            run = F.unit() * (kv.k * n) if F.norm > 0.0 else Vec(0.0, 0.0)
            segs.append((v.p(at_ - run), v.p(at_)) if arrive else (v.p(at_), v.p(at_ + run)))
        for i, ((q, F, name, role), (arrive, at_)) in enumerate(zip(here, sides, strict=True)):
            _force(v, at_, F, self.fs, name, arrive, role)
            # slid off its point (:func:`uncross`), not on from another arrow there: its
            # thin line of action ties it back
            p = v.p(q)
            on = [segs[j] for j, (p0, *_) in enumerate(here) if j != i and kv.mm(p0.dist(q)) < 0.8]
            if F.norm > 0.0 and not any(_seg_dist((p, p), e) < 1.0 for e in on):
                line_of_action(v.sheet, p, *segs[i])
        draw_insets(d, at, self, ins, start, self.omitted)
        # a point the insets' circles are drawn round (the pole p, o, c of the shaper) is
        # lettered outside them, next to their outline, not pushed off past the gaps the
        # placer tries beyond a joint's clearance (review 13: 'p, o, c' 6,8 mm off its point
        # under the twin circles of Ш and Ю, 5 mm round it); where the circles reach farther
        # than a label may stand off its point (a cluster's circle round several points), it
        # keeps its place by its point inside them
        rings = [it for it in d.sheet.items[start:] if isinstance(it, CircleItem) and not it.fill]
        for j in asked:
            rq = d.pending[j]
            out = ring_clearance(rq.anchor, rings)
            if out <= RING_LABEL_MM:
                rq.clear = max(rq.clear, out)


#: How much larger (mm) a moment's arc on the lever is round a point an inset is drawn at: past
#: the inset's circles (MARK_R, twins TWIN_SHIFT_MM apart) by 3 mm.
INSET_ARC_MM = MARK_R + TWIN_SHIFT_MM + 3.0 - MOMENT_MM

#: A moment's arc on the lever keeps this far (mm) past its radius from the lettered points
#: where it can (:meth:`LeverMoment.at`): tried at ARC_PLACES + 1 places along its link's
#: image from its middle out, then on the image's line past its ends, ARC_STEP_MM apart.
ARC_CLEAR_MM = 4.0
ARC_PLACES = 8
ARC_STEP_MM = 2.0

#: A lever's point is lettered outside the insets' circles round it where their outline is at
#: most this far (mm) from it: the label a gap (1 mm) past the outline stays within the 6 mm a
#: label stands off its point at most (the layout checker's ANCHOR_MAX).
RING_LABEL_MM = 5.0


def ring_clearance(q: XY, rings: Sequence[CircleItem], steps: int = 72) -> float:
    """How far (mm) from the point ``q`` (paper) a label must keep to stand outside the
    circles ``rings`` round it: the least distance, over the directions from ``q``, at which
    a ray leaves every circle that holds ``q`` (0 where none does)."""
    holding = [c for c in rings if math.dist(c.c, q) < c.r]
    if not holding:
        return 0.0
    least = math.inf
    for i in range(steps):
        a = 2.0 * math.pi * i / steps
        ux, uy = math.cos(a), math.sin(a)
        out = 0.0
        for c in holding:
            # the ray q + s·u leaves circle c at the larger root of |q + s·u − c| = r
            dx, dy = q[0] - c.c[0], q[1] - c.c[1]
            b = dx * ux + dy * uy
            out = max(out, -b + math.sqrt(b * b - (dx * dx + dy * dy - c.r * c.r)))
        least = min(least, out)
    return least


@dataclass(frozen=True)
class LeverMoment:
    """A moment load on Zhukovsky's lever: its name (``M_{Ф3}``), its couple's two forces
    ``pair`` (the model's :class:`LeverItem` s, at the images of two points of its link) and
    their moment about the pole, M·xy/l_XY on the lever (the sense its arc is drawn in)."""

    name: str
    pair: tuple[LeverItem, LeverItem]

    def at(self, k: float, clear_of: Sequence[Vec], r_mm: float) -> Vec:
        """Where its arc of radius ``r_mm`` is drawn at ``k`` model units per mm: on its
        link's image xy (the segment between its couple's images), at the place nearest the
        middle whose arc keeps :data:`ARC_CLEAR_MM` clear of the points ``clear_of`` (their
        letters and insets), else on the line of xy past its nearer end as little as does;
        where none does, the place farthest from them."""
        a, b = self.pair[0].image, self.pair[1].image
        ts = [0.5 + (0.5 if i % 2 else -0.5) * ((i + 1) // 2) / (ARC_PLACES // 2 + 1)
              for i in range(ARC_PLACES + 1)]  # fmt: skip
        # a short image: on its line past its ends (a moment is the same anywhere on its link)
        run = a.dist(b) / k
        if run > 0.0:
            steps = int((r_mm + ARC_CLEAR_MM) // ARC_STEP_MM) + 1
            for j in range(1, steps + 1):
                ts += [1.0 + j * ARC_STEP_MM / run, -j * ARC_STEP_MM / run]
        best, far = a + (b - a) * 0.5, -1.0
        for t in ts:
            q = a + (b - a) * t
            gap = min((q.dist(c) / k for c in clear_of), default=math.inf)
            if gap >= r_mm + ARC_CLEAR_MM:
                return q
            if gap > far:
                best, far = q, gap
        return best

    @property
    def value(self) -> float:
        return self.pair[0].moment + self.pair[1].moment


def lever_loads(f: Forces) -> tuple[list[LeverItem], list[LeverMoment]]:
    """The loads of the lever of ``f`` as the lever draws them: the forces, each an arrow at
    the image of its point; and the moments (M_Ф3, a given M_5), each on the image xy of
    its link as the moment M·xy/l_XY its couple (±M/l_XY ⊥ XY at X and Y, the model's
    two items) has about any point of the lever: an arc named by the moment, not two arrows
    at a further μ_F (review 17: the crusher's lever drew five couples, ten arrows, nine in
    insets at μ_F* and μ_F**)."""
    moments = {ld.name for lds in f.loads.values() for ld in lds if ld.force is None}
    forces = [it for it in f.lever.items if it.name not in moments]
    pairs: dict[tuple[str, int], list[LeverItem]] = {}
    for it in f.lever.items:
        if it.name in moments:
            pairs.setdefault((it.name, it.link), []).append(it)
    out = []
    for (name, _), its in pairs.items():
        assert len(its) == 2, (name, its)
        out.append(LeverMoment(name, (its[0], its[1])))
    return forces, out


def _table2(f: Forces, h: float) -> Table:
    forces: list[tuple[str, float, float]] = []  # (name, value, scale of round-off)
    moments: list[tuple[str, float]] = []
    order: list[tuple[str, int]] = []
    for lds in f.loads.values():
        for ld in lds:
            if ld.force is not None:
                forces.append((load_name(ld.name), ld.force.norm, 0.0))
                order.append(("F", len(forces) - 1))
            else:
                moments.append((load_name(ld.name), ld.moment))
                order.append(("M", len(moments) - 1))
    big = max(r.force.norm for r in f.reactions)
    for i, j in f.pairs:
        # a reaction between two moving links by both its names, R_23 = R_32: the drawings
        # name it by the link it acts on (link 2's polygon R_32, link 3's R_23; review 18)
        name = reaction_name(i, j) if i == 0 else f"{reaction_name(i, j)} = {reaction_name(j, i)}"
        forces.append((name, f.R(i, j).norm, big))
        order.append(("F", len(forces) - 1))
    for r in f.reactions:
        if r.couple:
            moments.append((f"M_{{{r.of}{r.on}}}", r.couple))
            order.append(("M", len(moments) - 1))
    moments.append((WORDS("m_bal_forces"), f.M_bal))
    moments.append((WORDS("m_bal_lever"), f.lever.M_bal))
    order += [("M", len(moments) - 2), ("M", len(moments) - 1)]
    # one unit per quantity on the sheet: N and N·m, as its order of calculation writes them;
    # each value (a load or a reaction of its own, not one quantity over positions) to 4
    # significant figures, as the order of the analysis writes it (G_2 = 88,29 in both, never
    # 88 beside 2200; M_Ф4 = 0,06814, never 0,1 beside 161,5), the column aligned on its
    # decimal comma; a value that is round-off against the largest of its kind as 0 (an ε
    # that vanishes in this position gives M_Φ = 10^-13 N·m, not a number to print)
    big_f = max((x for _, x, _ in forces), default=0.0)
    big_m = max((abs(m) for _, m in moments), default=0.0)
    f_text = [_load(x, max(sc, big_f)) for _, x, sc in forces]
    m_text = [_load(m, big_m) for _, m in moments]
    rows: list[tuple[str, float | str, str]] = []
    for kind, i in order:
        if kind == "F":
            rows.append((forces[i][0], f_text[i], "N"))
        else:
            rows.append((moments[i][0], m_text[i], "N·m"))
    return Table.of_values(rows, first=WORDS("load"), title=WORDS("loads"), center=True,
                           height=h, row_h=row_height(h), title_height=TITLE_H)  # fmt: skip


# --- sheet 3 ------------------------------------------------------------------------------


def _sheet3(s: Solved, fw: Flywheel, h: float) -> Tree:
    """Sheet 3's tree, its tables ``h`` high."""
    lk = s.linkage
    sign = 1.0 if lk.omega > 0 else -1.0
    psi = fw.psi
    deg = np.degrees(psi)
    n = len(fw.phis)
    psi_k = np.array([2.0 * math.pi * i / n for i in range(n + 1)])
    M_k = np.array([*fw.M_pr, fw.M_pr[0]])
    I_k = np.array([*fw.I_pr, fw.I_pr[0]])
    W = fw.dA - fw.M_drive * psi  # the loads' work, exact
    A_k = graphical_work(psi, W, psi_k)
    drive = fw.M_drive * psi
    J, Nm = WORDS("J"), WORDS("Nm")
    rows = [
        (WORDS("M_pr"), Nm, [(fw.dense.M_pr * sign, WORDS("M_pr")),
                             (np.full_like(psi, fw.M_drive), WORDS("M_dr"))], M_k * sign, "M"),
        ("A", J, [(-W, WORDS("A_res")), (drive, WORDS("A_dr"))], -A_k, "A"),
        ("ΔT", J, [(fw.dA, "")], A_k + fw.M_drive * psi_k, "T"),
        (WORDS("I_pr"), WORDS("kgm2"), [(fw.dense.I_pr, "")], I_k, "I"),
    ]  # fmt: skip
    x = AxisSpec("φ", WORDS("deg"), "φ", 0.0, 360.0, 30.0)
    graphs = []
    for sym, unit, curves, gy, name in rows:
        # a diagram of one curve is named by its axis; of more, each curve at its end
        cs = [
            Curve(_thin(deg), _thin(c), "result" if j == 0 else "construction",
                  label=lab if len(curves) > 1 else "")
            for j, (c, lab) in enumerate(curves)
        ]  # fmt: skip
        cs.append(Curve(np.degrees(psi_k), gy, "construction", points=True))
        graphs.append(_DynDiagram(x, AxisSpec(sym, unit, name), cs, least=(120.0, 45.0),
                                  prefer=(600.0, 150.0), marks=position_marks(n)))  # fmt: skip
    phi0 = math.degrees(fw.phis[0]) % 360.0  # the flywheel's ψ = 0: numbered position 0
    origin = WORDS(
        "phi_origin",
        phi0=fmt_fixed(phi0, angle_places([phi0, 360.0 / n]), current()),
        last=n - 1,
        step=fmt_fixed(360.0 / n, angle_places([360.0 / n]), current()),  # 30°, not 30,0°
    )
    note = Text(paragraph=origin, width=order_width(h), height=h)
    column = Column(note, _Stacked(graphs), title=WORDS("graphs"), title_height=TITLE_H)
    witt = _Wittenbauer(fw)
    omega = _omega(lk, fw)
    tables = Column(*_tables3(lk, fw, h))
    # Wittenbauer's diagram over ω(φ) and the tables, or beside the tables (its height no
    # longer the room the ω/table row leaves): the search takes the one that draws it larger
    return Choice(
        Row(column, Column(witt, Row(omega, tables))),
        Column(Row(column, witt), Row(omega, tables)),
        Row(column, Column(witt, omega), tables),
        Row(column, Column(Row(witt, tables), omega)),
    )


class _DynDiagram(Diagram):
    """A diagram of the dynamics sheet: its curves named at the axis captions' height (review
    14: M_дв and M_пр written small, stacked between the two lines at the diagram's end)."""

    LABEL_H = 3.5
    LABEL_GAP = 3.0 * LABEL_H


#: The finer-to-coarser nice factors each diagram of :class:`_Stacked` may take, tried together.
STACK_CHOICES = 7


def stack_factors(ranges: Sequence[float], room: float, first_tallest: bool = True) -> list[float]:
    """The y factors (nice, units per mm) of diagrams stacked in ``room`` mm of plot height,
    their values' ``ranges``: of the few finest each range allows, the choice whose plots fit
    ``room`` together with the largest least height, then the least spread of heights (one
    height), then the largest sum; with ``first_tallest``, where any choice allows it, the
    first diagram (M_пр, the one the student integrates) at least as tall as each other."""
    options = [nice_steps((r if r > 0.0 else 1.0) / max(room, 1.0), STACK_CHOICES) for r in ranges]
    best: tuple[tuple[float, ...], list[float]] | None = None
    for combo in itertools.product(*options):
        h = [(r if r > 0.0 else 1.0) / k for r, k in zip(ranges, combo, strict=True)]
        fits = sum(h) <= room * (1.0 + tol.DERIVED)
        tallest = not first_tallest or all(h[0] >= x * (1.0 - tol.DERIVED) for x in h[1:])
        key = (float(fits), float(tallest), min(h), min(h) - max(h), sum(h))
        if best is None or key > best[0]:
            best = (key, list(combo))
    assert best is not None, "at least one diagram"
    return best[1]


class _Stacked(View):
    """The dynamics sheet's diagrams one under another over one φ axis (one μ_φ), their y
    factors chosen together (:func:`stack_factors`) so that they are drawn at about one
    height, M_пр (the first) at least as tall as the others (review 14: the walkbeam's M_пр
    drew −431 … +145 N·m 29 mm high at μ_M = 20 N·m/mm over a 110 mm A(φ)). The room left
    over is shared out between them."""

    def __init__(self, diagrams: Sequence[Diagram], gap: float = GAP) -> None:
        super().__init__(margin=0.0, weight=float(len(diagrams)))
        self.diagrams = list(diagrams)
        self.gap = gap

    def _pad(self, dg: Diagram) -> float:
        return dg.BELOW + dg.ABOVE + 2.0 * dg.margin

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        sizes = [dg.stretch() for dg in self.diagrams]
        extra = self.gap * (len(sizes) - 1)
        return ((max(s[0][0] for s in sizes), sum(s[0][1] for s in sizes) + extra),
                (max(s[1][0] for s in sizes), sum(s[1][1] for s in sizes) + extra))  # fmt: skip

    def plots(self, h: float) -> tuple[list[float], float]:
        """Each diagram's plot height (mm) in a room ``h`` mm high, and the room left over
        under each (shared out equally)."""
        key = ("plots", round(h, 6))
        if key not in self._memo:
            room = h - self.gap * (len(self.diagrams) - 1) - sum(map(self._pad, self.diagrams))
            ranges = [dg._range(dg.y, 1) for dg in self.diagrams]
            spans = [hi - lo if hi > lo else 1.0 for lo, hi in ranges]
            ks = stack_factors(spans, max(room, 1.0))
            plots = [r / k for r, k in zip(spans, ks, strict=True)]
            self._memo[key] = plots, max(room - sum(plots), 0.0) / len(plots)
        return self._memo[key]  # type: ignore[no-any-return]

    def used(self, w: float, h: float) -> tuple[float, float]:
        if h <= sum(map(self._pad, self.diagrams)):
            return 0.0, 0.0
        plots, spare = self.plots(h)
        uw = max(dg.used(w - 2.0 * dg.margin, p + dg.BELOW + dg.ABOVE)[0] + 2.0 * dg.margin
                 for dg, p in zip(self.diagrams, plots, strict=True))  # fmt: skip
        return uw, h - spare * len(plots)

    def draw(self, d: Drawing, at: Placed) -> None:
        x0, y0, x1, y1 = at.inner
        plots, spare = self.plots(y1 - y0)
        top = y0
        for dg, p in zip(self.diagrams, plots, strict=True):
            # the box as tall as the plot at its factor (a box a hair taller keeps the
            # factor: the plot is range / factor exactly), the spare room under it
            m = dg.margin
            box = (x0, top, x1, top + p * (1.0 + tol.DERIVED) + self._pad(dg))
            dg.draw(d, Placed(dg, box, (box[0] + m, box[1] + m, box[2] - m, box[3] - m)))
            top = box[3] + spare + self.gap


def _nonzero(xs: Sequence[float], lang: str, digits: int = 4) -> list[str]:
    """A table column (:func:`fmt_column`) in which a value that is not 0 but negligible
    beside the column's largest (under :data:`~geomcad.sheet.loads.NEGLIGIBLE` of it), or would
    print as 0,000 at the column's decimals, is written to two significant figures instead,
    and asks the others for no further decimals (1,353 and 0,400 beside 0,00031, not
    1,35300)."""
    big = max((abs(x) for x in xs), default=0.0)
    tiny = [x != 0.0 and abs(x) < NEGLIGIBLE * big for x in xs]
    rest = iter(fmt_column([x for x, t in zip(xs, tiny, strict=True) if not t], lang, digits))
    out = [fmt_number(x, lang, 2) if t else next(rest) for x, t in zip(xs, tiny, strict=True)]
    return [
        fmt_number(x, lang, 2) if x != 0.0 and not any(c in "123456789" for c in t) else t
        for x, t in zip(xs, out, strict=True)
    ]


def graphical_work(
    psi: npt.NDArray[np.float64], W: npt.NDArray[np.float64], psi_k: npt.NDArray[np.float64]
) -> npt.NDArray[np.float64]:
    """The graphical integration of M_пр through the division points ``psi_k`` (from 0 to a
    full turn): each interval's M_пр replaced by its mean ordinate, the step of equal area
    under the curve (the textbook's rule), so that the integral's polyline passes through the
    work ``W`` of the curve (sampled at ``psi``) at every division point and, over the cycle,
    ends at its whole work A_ц: A_д = A_с there, and ΔT returns to 0."""
    return np.asarray(np.interp(psi_k, psi, W), dtype=np.float64)


#: At most about this many points of a curve are drawn.
CURVE_POINTS = 720


def _thin(y: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Every k-th sample of a dense curve, its last one kept."""
    k = max(1, len(y) // CURVE_POINTS)
    out = y[::k]
    return out if (len(y) - 1) % k == 0 else np.append(out, y[-1])


#: Wittenbauer's tangents are drawn at least this steep (degrees; the ω_min one, the flatter).
WITT_MIN_DEG = 5.0
#: ... unless that would draw the I_пр axis shorter than this (mm): then the axis is this long
#: (where the box has the room) and the tangents as steep as its scale makes them (review 10:
#: slider_rocker_rpr's I_пр ≤ 0,007 kg·m² beside ΔT over 270 J drew a 15 mm-wide sliver).
WITT_LEAST_MM = 60.0


class _Wittenbauer(View):
    """The energy–mass diagram ΔT(I_пр) with its two tangents at ψ_max, ψ_min and the segment
    ab they cut on the ΔT axis; both axes fitted to the box. The sheet's main construction (the
    flywheel is found on it): it weighs 1.5 views in the layout's search."""

    LEFT, BELOW, ABOVE, RIGHT = 22.0, 14.0, 10.0, 14.0

    def __init__(self, fw: Flywheel) -> None:
        super().__init__(title=WORDS("witt"), title_height=5.0, margin=2.0, weight=1.5)
        self.fw = fw

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        return (120.0, 100.0), (400.0, 400.0)

    def _axes(self, w: float, h: float) -> tuple[Axis, Axis]:
        fw = self.fw
        a, b = fw.segment
        k_max = 0.5 * fw.omega_max**2
        i_hi = float(fw.dense.I_pr.max())
        lo = float(min(fw.dA.min(), b, 0.0))
        hi = float(max(fw.dA.max(), a + k_max * i_hi, 0.0))
        ay = Axis.fit("ΔT", WORDS("J"), lo, hi, max(h - self.BELOW - self.ABOVE - 6.0, 1.0), "T")
        # the I_пр axis no longer than draws the ω_min tangent WITT_MIN_DEG steep (review 9: a
        # wide flat box drew the tangents at 2.2° and 1.9°, a strip no hand could construct)
        box = max(w - self.LEFT - self.RIGHT, 1.0)
        room = box
        slope = 0.5 * fw.omega_min**2
        if slope > 0.0 and i_hi > 0.0:
            steep = i_hi * slope / (math.tan(math.radians(WITT_MIN_DEG)) * ay.k)
            room = min(box, max(steep, 1.0))
        ax = Axis.fit(WORDS("I_pr"), WORDS("kgm2"), 0.0, i_hi, room, "I")
        least = min(WITT_LEAST_MM, box, ay.mm(ay.hi - ay.lo))  # never flatter than square
        for _ in range(3):  # the factor's rounding up may leave the axis short of `least`
            drawn = ax.mm(ax.hi - ax.lo)
            if drawn >= least or room >= box:
                break
            room = min(box, room * max(least, room) / max(drawn, 1.0))
            ax = Axis.fit(WORDS("I_pr"), WORDS("kgm2"), 0.0, i_hi, room, "I")
        return ax, ay

    def used(self, w: float, h: float) -> tuple[float, float]:
        if w <= self.LEFT + self.RIGHT or h <= self.BELOW + self.ABOVE + 6.0:
            return 0.0, 0.0
        ax, ay = self._axes(w, h)
        return (ax.mm(ax.hi - ax.lo) + self.LEFT + self.RIGHT,
                ay.mm(ay.hi - ay.lo) + self.BELOW + self.ABOVE + 6.0)  # fmt: skip

    def draw(self, d: Drawing, at: Placed) -> None:
        fw = self.fw
        x0, y0, x1, y1 = at.inner
        ax, ay = self._axes(x1 - x0, y1 - y0)
        a, b = fw.segment
        k_max, k_min = 0.5 * fw.omega_max**2, 0.5 * fw.omega_min**2
        i_hi = float(fw.dense.I_pr.max())
        tan_hi = k_max * ax.k / ay.k
        tan_lo = k_min * ax.k / ay.k
        angles = WORDS(
            "witt_angles",
            hi=fmt_fixed(math.degrees(math.atan(tan_hi)), ANGLE_PLACES, current()),
            lo=fmt_fixed(math.degrees(math.atan(tan_lo)), ANGLE_PLACES, current()),
        )
        # ab, the segment the tangents cut on the ΔT axis, is read in the heading: a label on
        # the axis itself would stand among its tick values
        ab = WORDS("ab", value=_num(a - b))
        # at the box's top right, as a diagram's factors (review 7: at its top left it ran on
        # from the title of the column beside it)
        d.text(f"{ay.factor_text(current())};  {ax.factor_text(current())};  {angles};  {ab}",
               (x1, y0 + 3.0), 2.5, anchor="right")  # fmt: skip
        gr = Graph(d, ax, ay, (x0 + self.LEFT, y0 + self.ABOVE + 6.0 + ay.mm(ay.hi - ay.zero)))
        gr.axes(current(), tick_labels=True)
        gr.curve(_thin(fw.dense.I_pr), _thin(fw.dA), "result")
        # the numbered positions' points on the curve, each with its number (review 17: the
        # curve "without 0 … 11" could not be read against the ΔT and I_пр diagrams it is
        # built from): I_пр of the position, ΔT of the dense curve at its ψ
        n = len(fw.phis)
        psi_k = np.array([2.0 * math.pi * i / n for i in range(n)])
        for i, (x, y) in enumerate(zip(fw.I_pr, np.interp(psi_k, fw.psi, fw.dA), strict=True)):
            gr.point(float(x), float(y), str(i))
        gr.point(0.0, a, "a", prefer=(-1.0, 0.0))
        gr.point(0.0, b, "b", prefer=(-1.0, 0.0))
        # each tangent named at its far end, clear of the axes, of a and b and of the curve
        # (a touching point near the ΔT axis leaves no room there); its touching point a dot
        for (yy, slope), (x, y), name in zip(((a, k_max), (b, k_min)), fw.touch,
                                             ("ω_{max}", "ω_{min}"), strict=True):  # fmt: skip
            x_end = min(i_hi, (ay.hi - yy) / slope) if slope > 0.0 else i_hi
            x_end = _clear_of_axis_name(gr, yy, slope, x_end, x)
            if x_end > 0.0:
                gr.curve([0.0, x_end], [yy, yy + slope * x_end], "construction")
                d.label(gr.p(x_end, yy + slope * x_end), name, 2.5, prefer=(1.0, 0.0))
            gr.point(x, y)


#: The height (mm) of an axis's symbol by its arrow (:meth:`geomcad.sheet.graph.Graph.axes`),
#: and the room (mm) a line keeps from it.
AXIS_NAME_H = 3.5
NAME_CLEAR_MM = 1.0


def _clear_of_axis_name(gr: Graph, y0: float, slope: float, x_end: float, touch: float) -> float:
    """Where a tangent y = y0 + slope·x drawn from the ΔT axis ends (I_пр units): at ``x_end``,
    or short of the I_пр axis's symbol by its arrow (written left of the tip, above the axis)
    where it would run through it, never short of its touching point ``touch`` (review 7: the
    yoke's ω_max tangent ran over "I_пр, кг·м²")."""
    name = f"{gr.x.symbol}, {gr.x.unit}"
    tip = gr.box[2] + ARROW_OVER
    left = tip - text_box(parse(name), AXIS_NAME_H)[0] - 2.0 * NAME_CLEAR_MM
    low, high = gr.at[1] + NAME_CLEAR_MM, gr.at[1] - AXIS_NAME_H - 2.0 * NAME_CLEAR_MM
    end = gr.p(x_end, y0 + slope * x_end)
    if end[0] <= left:
        return x_end
    x_left = gr.x.zero + (left - gr.at[0]) * gr.x.k
    at_left = gr.p(x_left, y0 + slope * x_left)[1]
    if max(at_left, end[1]) < high or min(at_left, end[1]) > low:
        return x_end  # above or below the name all along
    return max(x_left, touch)


#: The ω1 diagram's y range beyond ω_min … ω_max, each side, as a share of it.
OMEGA_PAD = 0.1


class _Filled(_DynDiagram):
    """A diagram whose y axis (through no zero: ω1 about its mean) is drawn the height of its
    box: its range widened about its middle to the whole room at the axis's factor (review 7:
    tangent's ω1 drew 60 mm with 4 ticks in a taller box, its factor rounded coarse). The
    layout's search sizes it by its curves, as any diagram (:meth:`used`)."""

    filled = False

    def axes(self, w: float, h: float) -> tuple[Axis, Axis]:
        ax, ay = super().axes(w, h)
        spare = max(h - self.BELOW - self.ABOVE, 1.0) * ay.k - (ay.hi - ay.lo)
        if self.filled and spare > 0.0:
            ay = replace(ay, lo=ay.lo - spare / 2.0, hi=ay.hi + spare / 2.0)
        return ax, ay

    def draw(self, d: Drawing, at: Placed) -> None:
        self.filled = True
        try:
            super().draw(d, at)
        finally:
            self.filled = False


def _omega(lk: Linkage, fw: Flywheel) -> Diagram:
    assert fw.omega_psi is not None and fw.omega_t is not None
    lo = float(min(fw.omega_t.min(), fw.omega_min))
    hi = float(max(fw.omega_t.max(), fw.omega_max))
    # room for ω_max's and ω_min's names over and under their lines; the axis then takes
    # the rest of its box (:class:`_Filled`), so a wider pad would only coarsen its μ
    pad = OMEGA_PAD * (hi - lo)
    delta = WORDS(
        "delta",
        given=_num(lk.dynamics.delta if lk.dynamics else 0.0, 3),
        achieved=_num(fw.delta_achieved, 4),
    )
    curves = [
        Curve(_thin(np.degrees(fw.omega_psi)), _thin(fw.omega_t), "result", label="ω_1"),
        Curve([0.0, 360.0], [fw.omega_max, fw.omega_max], "construction", label="ω_{max}"),
        Curve([0.0, 360.0], [fw.omega_min, fw.omega_min], "construction", label="ω_{min}"),
    ]
    # its φ axis as the other diagrams': ticks every 30° and the numbered positions under it
    # (review 14: ω1's axis had neither 0 nor the positions' numbers)
    return _Filled(
        AxisSpec("φ", WORDS("deg"), "φ", 0.0, 360.0, 30.0),
        AxisSpec("ω_1", WORDS("per_s"), "ω", lo - pad, hi + pad),
        curves,
        least=(120.0, 60.0),
        prefer=(400.0, 160.0),
        zero=False,
        marks=position_marks(len(fw.phis)),
        title=f"{WORDS('omega')}; {delta}",
    )


#: A column of I_пр whose largest value is under this (kg·m²) is written times a power of ten:
#: where its first figure stands past the decimals a diagram's axis writes without one.
TABLE_SMALL = 10.0 ** (1 - FACTOR_PLACES)


def _tables3(lk: Linkage, fw: Flywheel, h: float) -> list[View]:
    n = len(fw.phis)
    step = max(1, math.ceil(n / 12))
    si = max(abs(x) for x in fw.I_pr)
    # a column of tiny I_пр written times 10^n as its diagram's axis writes it (review 11: an
    # instrument's 0,00000236 кг·м²): I_пр·10^6 = 2,360
    n_i = thousands_power(si) if 0.0 < si < TABLE_SMALL else 0
    i_head = f"{WORDS('I_pr')}·10^{{{n_i}}}" if n_i else WORDS("I_pr")
    rows: list[list[str]] = [
        ["№", "φ_1, °", f"{i_head}, {WORDS('kgm2')}", f"{WORDS('M_pr')}, {WORDS('Nm')}"]
    ]
    sm = max(abs(x) for x in fw.M_pr)
    # M_пр in the diagram's convention (> 0 in the crank's sense of rotation: ΣP/|ω1|); each
    # column one count of decimals
    sign = 1.0 if lk.omega > 0 else -1.0
    idx = list(range(0, n, step))
    degs = [math.degrees(fw.phis[i]) % 360.0 for i in idx]
    cols = [
        [fmt_fixed(x, angle_places(degs), current()) for x in degs],
        _nonzero(
            [0.0 if abs(fw.I_pr[i]) <= ZERO * si else fw.I_pr[i] * 10.0**n_i for i in idx],
            current(),
            4,
        ),
        fmt_column(
            [0.0 if abs(fw.M_pr[i]) <= ZERO * sm else sign * fw.M_pr[i] for i in idx], current(), 4
        ),
    ]
    for j, i in enumerate(idx):
        rows.append([str(i), cols[0][j], cols[1][j], cols[2][j]])
    # the results to four significant figures each, trailing zeros kept (367,0 and 0,5105:
    # the column reads aligned on its decimal commas)
    res: list[tuple[str, float | str, str]] = [
        (WORDS("A_c"), fw.A_cycle, "J"),
        (WORDS("M_dr"), fw.M_drive, "N·m"),
        ("ω_{max}", fw.omega_max, "1/s"),
        ("ω_{min}", fw.omega_min, "1/s"),
        (WORDS("J_fw"), fw.J_flywheel, "kg·m²"),
    ]
    if fw.D > 0.0 and lk.dynamics is not None:
        kind = WORDS("disc") if lk.dynamics.flywheel == "disc" else WORDS("rim")
        res += [(f"D ({kind})", fw.D, "m"), ("b", fw.b, "m"), ("m", fw.mass, "kg")]
    res = [(n, fmt_number(float(v), current(), FIGURES, zeros=True), u) for n, v, u in res]
    row_h = row_height(h)
    table = Table(rows, title=WORDS("table3"), height=h, row_h=row_h, title_height=TITLE_H,
                  center=True)  # fmt: skip
    # a reduced moment of inertia of 0 explained under the table: the driven links stand still
    zeros = [str(i) for i in idx if abs(fw.I_pr[i]) <= ZERO * si]
    note = [Text(paragraph=WORDS("I_zero", at=", ".join(zeros)), width=table.span,
                 height=SMALL_TEXT_H)] if zeros else []  # fmt: skip
    return [
        table,
        *note,
        Table.of_values(res, header=False, title=WORDS("results3"), height=h, row_h=row_h,
                        title_height=TITLE_H),
    ]  # fmt: skip
