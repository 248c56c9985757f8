"""The kinematic sheet of a linkage file (A2 or A1 by its content), composed for any mechanism.

The sheet is one tree of views (:mod:`geomcad.sheet.compose`), whatever the mechanism: the
mechanism in all its numbered positions and the velocity plan of every position in a grid (on a
second sheet when there are more than :data:`PLANS_ON_SHEET`) above; the output's diagrams
s(φ), v(φ), a(φ) (the exact curves of the sweep, and the graphical derivatives by chords through
the numbered positions), the acceleration plans of two positions and the tables of ω and ε below.
The layout chooses the splits and each view's scale: a GOST 2.302 ratio for the mechanism, one
factor 1, 2, 2.5, 4, 5 × 10^n for all velocity plans and one for the acceleration plans, so
every vector is drawn at the stated μ. Its words come from ``strings/<lang>/linkage.toml``.

The format is chosen by the content (:mod:`geomcad.sheet.formats`): the smaller of
:data:`SIZES` on which the crank is drawn at least :data:`CRANK_MM` long and the velocity plans'
crank vector pa at least :data:`PA_MM` (a file with few positions, a small mechanism: A2), else
A1; a file's ``[sheet] format`` overrides it. Where the largest format's arrangement breaks
either rule, the search seeks the rules' scales (:func:`~geomcad.sheet.compose.View`'s
``most_k``): on one sheet, else with the velocity plans on a sheet of their own, else with the
crank on its detail view, the last resort (:func:`_rules_hold`). Tables, orders and notes are
written :data:`TEXT_H` high on A2 and A1 (2.5 mm, GOST 2.304's least, on a smaller format the
file asks for), the views' titles 5 mm.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import numpy.typing as npt
from shapely.geometry import MultiPoint, Point

from geomcad import tol
from geomcad.construction.recorder import Step
from geomcad.errors import ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.linkage.model import Group, Linkage
from geomcad.linkage.plans import Position, construct
from geomcad.linkage.solution import Solved, scheme
from geomcad.linkage.sweep import output_coordinate, prp_frame, rocker_angle, sweep
from geomcad.sheet import Drawing, Sheet, TitleBlock, fmt_number, formats
from geomcad.sheet.compose import (
    Choice,
    Column,
    Field,
    Grid,
    Node,
    Placed,
    Row,
    Tree,
    View,
    arrange,
    compose,
    round_scale_down,
)
from geomcad.sheet.compose import (
    Layout as Arranged,
)
from geomcad.sheet.drawing import SHORT_MM, Viewport
from geomcad.sheet.form import title_block_spacer
from geomcad.sheet.frame import FORMATS, name_fits, text_at
from geomcad.sheet.graph import nice_step_below
from geomcad.sheet.lang import Words, current, per_language
from geomcad.sheet.loads import clear_turn
from geomcad.sheet.model import ArcItem, CircleItem, Polyline, TextItem
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.placer import break_round, break_under_labels, clip_to_circle, within_hull
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scale import Scale, angle_places, column_places, fmt_column, fmt_fixed
from geomcad.sheet.scheme import Body, draw_scheme, is_block
from geomcad.sheet.symbols import HATCH_LEN, JOINT_R, SLIDER_SIZE, STAND_DEPTH, STAND_HALF
from geomcad.sheet.text import box, parse
from geomcad.sheet.views import AxisSpec, Curve, Diagram, PlanView, Steps, Table, Text

WORDS = Words(__package__, "linkage")

#: The formats a linkage file's sheets take by their content, smallest first (a course
#: project's sheets: A1, or A2 where the views reach their scales on it).
SIZES: tuple[str, ...] = ("A2", "A1")
#: The crank's least length on the mechanism's drawing (mm): the format is the smallest on which
#: the mechanism is drawn at a GOST scale giving it this much.
CRANK_MM = 30.0
#: The velocity plans' crank vector pa (V_A = ω1·l_OA) at least this long (mm), likewise.
PA_MM = 40.0
#: The cap height of tables, orders and notes on A2 and A1 (mm; GOST 2.304); on a smaller
#: format a file asks for, :data:`SMALL_TEXT_H`.
TEXT_H = 3.5
SMALL_TEXT_H = 2.5
#: How much of the layout search's score (Σ weight·log(drawn area)) the larger text may cost
#: the views on the largest format before the text is written :data:`SMALL_TEXT_H` high.
TEXT_COST = 1.0
#: The title block's Масштаб on a sheet with no one scale of lengths (ESKD: a dash).
NO_SCALE = "\u2014"
#: The views' titles (mm).
TITLE_H = 5.0
#: At most this many velocity plans share the first sheet with the mechanism.
PLANS_ON_SHEET = 12
#: The width of the order of construction and of the notes (mm), for 2.5 mm text; wider in
#: proportion to the square root of a larger text's height.
ORDER_W = 190.0
#: After the search, the mechanism is tried at up to this many finer GOST steps, one at a time,
#: each kept where every sheet still fits with the size rules and the diagrams' spans (a step
#: costs one more search: two keep a build within a few seconds).
FINER_STEPS = 2
#: Samples of the exact diagrams over a turn.
DIAGRAM_SAMPLES = 361


def _deg(phi: float, s: Solved) -> str:
    """A crank angle (degrees) with the one count of decimals of the sheets' angles."""
    return fmt_fixed(_wrap_deg(phi), _places(s), current())


def _wrap_deg(phi: float) -> float:
    d = math.degrees(phi) % 360.0
    return 0.0 if abs(d - 360.0) <= tol.TURN_START else d


def _places(s: Solved) -> int:
    """The decimals of every crank angle on the linkage's sheets (titles and tables)."""
    return angle_places([_wrap_deg(phi) for phi in (*(P.phi for P in s.drawn), *s.accel_phis)])


def sheet_formats(lk: Linkage) -> tuple[str, ...]:
    """The formats the file's sheets may take: its ``[sheet] format`` (checked: one of
    :data:`geomcad.sheet.formats.SIZES`), else :data:`SIZES`."""
    fmt = lk.sheet.get("format") if lk.sheet else None
    return SIZES if fmt is None else (formats.check(fmt, "sheet.format"),)


def text_height(fmts: Sequence[str]) -> float:
    """The cap height of tables, orders and notes on sheets of ``fmts``: :data:`TEXT_H` on A2
    and A1, else :data:`SMALL_TEXT_H`."""
    return TEXT_H if all(f in ("A2", "A1", "A0") for f in fmts) else SMALL_TEXT_H


def _on(tree: Tree, wants: Mapping[View, float], fmt: str) -> tuple[Tree, formats.Sized] | None:
    """``tree`` arranged on ``fmt`` in landscape (A4 upright), as a course project's sheets are,
    the search seeking the wanted scales (as :func:`geomcad.sheet.formats.choose` does); a
    :class:`Choice`'s arrangements one by one, the best kept (a quicker test of a format than
    their joint search); ``None`` where a view finds no room at all."""
    for v, k in wants.items():
        v.readable = max(v.readable, k * v.readable_mm)
    fmt, land = next(formats.candidates((fmt,)))
    field = Field.of_format(fmt, land)
    if not formats.may_reach(tree, wants, field):
        return None  # no arrangement reaches the wanted scales: the search would say no
    best: tuple[Tree, formats.Sized] | None = None
    for alt in _alternatives(tree):
        try:
            lay = arrange(alt, field)
        except ParameterError:
            continue
        if best is None or lay.score > best[1].layout.score:
            best = alt, formats.Sized(fmt, land, lay)
    return best


def fit(
    make: Callable[[float], tuple[Tree, Mapping[View, float]]],
    fmts: Sequence[str],
    readable: bool = False,
    each: bool = False,
) -> tuple[Tree, formats.Sized]:
    """The tree ``make(h)`` builds, its tables and texts written ``h`` high, and its format: the
    smallest of ``fmts`` (in landscape) on which it fits with the scales it wants
    (:func:`geomcad.sheet.formats.meets`), its text :func:`text_height` high, else
    :data:`SMALL_TEXT_H` (GOST 2.304's least) where only the text keeps it from fitting. On the
    largest format every view is drawn as large as it can be (the wanted scales no longer
    weigh in the search: they only decide whether a smaller format will do), and the text is
    :data:`SMALL_TEXT_H` high where the larger text would cost the views more than
    :data:`TEXT_COST` of the search's score (Σ weight·log(drawn area): a mechanism drawn at
    1:4 instead of 1:2.5 costs about 1.9). ``make`` builds new views each time (the search
    marks the views it arranges). The largest format's arrangement is the joint search of a
    :class:`Choice` (it finds better splits than its arrangements one by one). ``readable``:
    the larger text wherever the views keep their wanted scales with it, whatever it costs
    them beyond (a kinematic sheet's tables and order read at 3.5 mm where the crank and pa
    keep their rules' lengths: the blank field is the text's to take). ``each``: where the joint
    search on the largest format misses the wanted scales, a :class:`Choice`'s arrangements also
    one by one, the best kept (the joint search starts them all from the same splits, and a
    tall mechanism's arrangement beside its diagrams, that alone keeps the crank's rule, lost
    to one at half its scale)."""
    order = sorted(fmts, key=lambda f: FORMATS[f][0] * FORMATS[f][1])
    for fmt in order[:-1]:
        for h in dict.fromkeys((text_height((fmt,)), SMALL_TEXT_H)):
            tree, wants = make(h)
            on = _on(tree, wants, fmt)
            if on is None:
                break
            tree, z = on
            reached = formats.meets(z.layout, wants)
            if z.layout.fits and reached:
                return tree, z
            if not reached:
                break  # smaller text does not bring the views to their scales
    tried: list[tuple[Tree, formats.Sized]] = []
    kept: list[bool] = []
    for h in dict.fromkeys((text_height(order[-1:]), SMALL_TEXT_H)):
        tree, wants = make(h)
        fmt, land = next(formats.candidates(order[-1:]))
        field = Field.of_format(fmt, land)
        lay = arrange(tree, field)
        if each and wants and not formats.meets(lay, wants):
            for alt in _alternatives(tree)[1:] if isinstance(tree, Choice) else ():
                try:
                    alone = arrange(alt, field)
                except ParameterError:
                    continue
                if alone.score > lay.score:
                    tree, lay = alt, alone
        tried.append((tree, formats.Sized(fmt, land, lay)))
        kept.append(bool(wants) and formats.meets(tried[-1][1].layout, wants))
    # the larger text where it fits and costs the views at most TEXT_COST of the search's score
    # (``readable``: or keeps them at their wanted scales)
    big, small = tried[0][1].layout, tried[-1][1].layout
    # (``readable``: not where the smaller text alone gives the diagrams their plots' height)
    lifts = kept[-1] and _plot_low(big) and not _plot_low(small)
    if big.fits and (
        not small.fits
        or big.score[1] >= small.score[1] - TEXT_COST
        or (readable and kept[0] and not lifts)
    ):
        return tried[0]
    return tried[-1] if small.fits else tried[0]


def _plot_low(lay: Arranged) -> bool:
    """Whether an output diagram of the arrangement draws its plot lower than
    :data:`DIAGRAM_PLOT_MM`."""
    return any(
        pl.inner[3] - pl.inner[1] - pl.view.BELOW - pl.view.ABOVE < DIAGRAM_PLOT_MM - tol.SHEET_MM
        for pl in lay
        if isinstance(pl.view, _OutputDiagram)
    )


def order_width(h: float) -> float:
    """The width of an order of construction or a note written ``h`` high (mm)."""
    return round(ORDER_W * math.sqrt(h / SMALL_TEXT_H))


@dataclass(frozen=True)
class Layout:
    """The views of a linkage's kinematic sheets, their trees and scales."""

    k_l: Scale
    k_v: Scale
    k_a: Scale
    second: bool  # the velocity plans go on a second sheet
    accel: tuple[Position, ...]
    trees: tuple[Tree, ...]  # one per sheet
    mech: View  # the mechanism's view (on the first sheet)
    sized: tuple[formats.Sized, ...] = ()  # each sheet's format and arrangement
    #: the output's diagrams in equal heights; else their split searched, as the equal one
    #: drew a curve shorter than DIAGRAM_SPAN_LEAST_MM (these its curves' heights, mm) or the
    #: mechanism at a coarser scale
    balanced: bool = True
    squeezed: tuple[float, ...] = ()
    #: the diagrams' boxes keep DIAGRAM_SPAN_MM (else the crank's rule took the room, and
    #: only DIAGRAM_SPAN_LEAST_MM is sought)
    spans: bool = True


def centres(lk: Linkage, P: Position, plan: Plan) -> dict[str, tuple[str, str]]:
    """The images of the links' centres of mass that ``plan`` (P's velocity or acceleration
    plan) draws beside its own points (:class:`PlanView`'s ``centres``): of each link with a
    mass whose centre is the middle of its two joints (linkages.md) and is no point of the
    plan, ``s2`` the middle of the joints' images ab by similarity, with its vector from the
    pole (V_S2 = ps2·μ_V, a_S2 = πs2′·μ_a: the forces sheet's inertia forces are read off
    them; review 17, "s_i on no plan")."""
    out: dict[str, tuple[str, str]] = {}
    for link in lk.moving_links:
        m = lk.masses.get(link)
        joints = lk.link_points(link)
        if m is None or m.mass <= 0.0 or lk.centre(link) or len(joints) != 2:
            continue
        names = dict(P.handles.get(link, []))
        if not all(j in names for j in joints):
            continue
        a, b = (plan.name(names[j]) for j in joints)
        name = plan.name(f"s{link}")
        if a in plan.points and b in plan.points and name not in plan.points:
            out[name] = (a, b)
    return out


def _accel_positions(s: Solved) -> tuple[Position, ...]:
    """The positions of the kinematic sheet's acceleration plans: those of ``s.accel_phis``
    (the file's first two ``phi``, else the largest output accelerations, linkages.md), then
    the force analysis' position where the file gives masses or loads and it is none of them
    (review 17: "the inertia forces rest on an a_S that no plan shows"; its plan gives the
    forces sheet's a_Si = πs_i′·μ_a)."""
    lk = s.linkage
    out = [
        next((P for P in s.drawn if abs(P.phi - phi) <= tol.ANGLE), None) or construct(lk, phi)
        for phi in s.accel_phis
    ]
    if lk.masses or lk.loads:
        P0, _ = _principal(s)
        turn = 2.0 * math.pi
        if all(
            P is not P0 and min((P.phi - P0.phi) % turn, (P0.phi - P.phi) % turn) > tol.ANGLE
            for P in out
        ):
            out.append(P0)
    return tuple(out)


def _trees(
    s: Solved, accel: Sequence[Position], h: float = TEXT_H, enlarge: bool = False,
    rules: tuple[bool, bool] = (False, False), apart: bool = False, balanced: bool = True,
    k_v: float = 0.0, mech_k: float = 0.0, seek_k: float = 0.0, spans: bool = True,
) -> tuple[tuple[Tree, ...], _Mechanism, bool, dict[View, float]]:  # fmt: skip
    """The sheets' view trees (see the module's docstring), tables and orders written ``h``
    high, and the scales (model units per mm) the format is chosen to reach: the mechanism's
    and the velocity plans'. ``enlarge``: the crank in its positions enlarged beside the
    mechanism (:class:`_CrankDetail`), where the mechanism's scale leaves it short. ``rules``
    (the crank's, pa's): the search on every format seeks that rule's scale (the coarsest of
    its series that keeps it: a view's ``most_k``), its room missing counted as a cost.
    ``apart``: the velocity plans on a sheet of their own (as with more than
    :data:`PLANS_ON_SHEET` positions). ``balanced``: the output's s, v and a diagrams in boxes
    of one height, else the search splits their column. ``k_v`` ((m/s)/mm, 0: none): the
    velocity plans' scale on their own sheet, at which the velocity plan of an acceleration
    plan's position that is not a numbered one is drawn beside it (one μ_V for a file's
    velocity plans). ``mech_k`` (m/mm, 0: none): with the crank's detail, the scale the
    mechanism reached without it, which its search still seeks. ``seek_k`` (m/mm, 0: none):
    without the detail, a finer scale the mechanism's search seeks (:data:`FINER_STEPS`).
    ``spans``: each output diagram at least as high as draws its curve :data:`DIAGRAM_SPAN_MM`
    high (:meth:`_OutputDiagram.stretch`), else :data:`DIAGRAM_H`."""
    lk = s.linkage
    n = len(s.drawn)
    second = apart or n > PLANS_ON_SHEET
    mech = _Mechanism(s)
    crank: _CrankDetail | None = None
    if enlarge:
        crank = _CrankDetail(s, detail_letter(s))
        mech.detail = crank.letter

    def mech_node() -> Tree:  # the mechanism, and its crank enlarged beside it
        return mech if crank is None else Row(mech, crank)

    # vectors shorter than two arrowheads are drawn as their lettered end point (a note says so)
    vviews = [
        PlanView(P.vp, title=WORDS("position", i=i, phi=_deg(P.phi, s)), group="v",
                 centres=centres(lk, P, P.vp),
                 show_scale=False, weight=2.0, min_mm=SHORT_MM)
        for i, P in enumerate(s.drawn)
    ]  # fmt: skip
    # on their own sheet, the plans in cells fitted to each column's and row's largest plan
    # (review 8: the rocking cylinder's twelve, long in one position and tall in another,
    # fitted no A2 in equal cells at pa = 77 mm and took an A1 68 % blank)
    vplans = Grid(*vviews, title=WORDS("vplans"), group="v", title_height=TITLE_H, fitted=second)
    detail = accel[0] if accel else s.drawn[0]
    cells: list[View | Node] = []
    aviews: list[PlanView] = []
    for P in accel:
        # each acceleration plan captioned by itself, with its μa, and drawn right under its
        # caption (review 14: "φ1 = 60°" alone at its cell's top, 100 mm from its plan)
        ap = _TopPlan(P.ap, title=WORDS("aplan", phi=_deg(P.phi, s)), group="a", weight=2.0,
                      centres=centres(lk, P, P.ap),
                      min_mm=SHORT_MM)  # fmt: skip
        # πa′ = ω1²·l at least PA_MM, as pa (review 6: sixbar's was 27 mm in a 250 mm column)
        ap.most_k = round_scale_down(lk.omega**2 * lk.length / PA_MM, "a", ap.series).k
        aviews.append(ap)
        if any(P is Q for Q in s.drawn):
            cells.append(ap)
            continue
        # a position of an acceleration plan that is not a numbered one: its velocity plan
        # beside its acceleration plan (every plan's position has both, linkages.md)
        vp = _TopPlan(P.vp, title=WORDS("vplan_detail", phi=_deg(P.phi, s)), group="v",
                      centres=centres(lk, P, P.vp),
                      weight=2.0, min_mm=SHORT_MM, least_k=k_v)  # fmt: skip
        cells.append(Row(vp, ap))
    # a section holding a position's velocity plan beside its acceleration plan is titled by
    # both (review 9: "Планы ускорений" over the velocity plan of a `phi` position)
    both = any(isinstance(c, Row) for c in cells)
    aplans: Tree = Grid(*cells, title=WORDS("vaplans" if both else "aplans"), group="a",
                        title_height=TITLE_H)  # fmt: skip
    # s, v and a share the column's height (review 6: whitworth's s took 250 mm, v and a 60)
    graphs = _diagrams(s, spans)
    diagrams = Column(
        Text([_through(s)], height=h), *graphs, title=WORDS("diagrams"), title_height=TITLE_H,
        weights=(1.0,) * (len(graphs) + 1) if balanced else None,
    )  # fmt: skip
    width = order_width(h)
    notes: list[View] = [_Note(WORDS("short", mm=fmt_number(SHORT_MM)), h)]
    if _along_guide(s, s.drawn[:1]) is not None:  # a slider's signed V, a: which way is +
        notes.append(Text(paragraph=WORDS("out_sign", p=lk.output), width=width, height=h))
    tabled = _tables(s, accel, h)
    tables = Column(*tabled, *notes)
    # the velocity plan's steps, then the acceleration plan's
    names = [detail.vp.pole, *detail.vp.order, detail.ap.pole, *detail.ap.order]
    steps = [detail.c.step(n) for n in names]
    order = Steps(
        steps,
        width,
        only=names,
        given=_as_tabled(steps, detail, [(tabled[0], s.drawn), (tabled[1], accel)]),
        height=h,
        title=_order_title(s, detail),
        title_height=TITLE_H,
    )
    wants: dict[View, float] = {mech: lk.length / CRANK_MM}
    if crank is not None:  # the detail reaches the crank's length the mechanism cannot
        del wants[mech]
        wants[crank] = lk.length / CRANK_MM
    for view in vviews:  # one scale for them all: each needs its room at it
        wants[view] = abs(lk.omega) * lk.length / PA_MM
    # πa′ too: a smaller format is taken only where it keeps it (an A2 offered by an arrangement
    # that draws the slotted lever's crank at its rule drew πa′ 25 mm)
    for view in aviews:
        wants[view] = lk.omega**2 * lk.length / PA_MM
    if crank is not None and mech_k > 0.0:
        mech.most_k = mech_k  # the detail takes free room, not the mechanism's
    if rules[0]:
        cv: View = mech if crank is None else crank
        cv.most_k = round_scale_down(lk.length / CRANK_MM, "l", cv.series).k
    if crank is None and seek_k > 0.0 and not 0.0 < mech.most_k <= seek_k:
        mech.most_k = wants[mech] = seek_k
    if rules[1]:
        for view in vviews:
            view.most_k = round_scale_down(wants[view], view.quantity, view.series).k
    if second:
        # the tables and the order in a column of the field's height beside the rest: the
        # mechanism (and its crank's detail) over the diagrams and the acceleration plans
        # (review 8: under a row with that column, 350 mm tall, the mechanism's row kept
        # 155 mm and drew the oscillator at 1:2,5 beside its detail on a sheet 51 % blank)
        beside = Row(Column(mech_node(), Row(diagrams, aplans)), Column(tables, order))
        # the tables and the order between the diagrams and the acceleration plans, clear of
        # the title block's corner, which cuts a scaled plan's box but would cut their column
        # short (review 9: the sine drive's 1:1 mechanism left 281 mm under it, the column
        # needs 273 and the corner left it 226: 1:2 beside a detail of the crank instead)
        first: Tree = Column(mech_node(), Row(diagrams, Column(tables, order), aplans))
        if apart and n <= PLANS_ON_SHEET:
            # the plans moved to their own sheet for their size: a tall mechanism may take
            # the first sheet's whole height
            first = Choice(
                first,
                Row(mech_node(), Column(diagrams, Row(aplans, Column(tables, order)))),
                Row(Column(mech_node(), diagrams), aplans, Column(tables, order)),
                beside,
                # the diagrams beside a tall mechanism, the rest in a row under both (review
                # 9: the rocking cylinder's 1:1 mechanism, 330 mm tall, left its diagrams'
                # column 246 mm and their plots 41 mm; beside it they are 81 mm)
                Column(Row(mech_node(), diagrams), Row(aplans, tables, order)),
            )
        else:
            first = Choice(first, beside)
        # the plans' sheet: its grid over the whole field, or above the title block's height
        # (review 7: tangent's last plan, tall, in the cell the title block cuts drew all
        # twelve at pa = 39 mm; a row of cells clear of it keeps pa at its rule)
        # or in rows each as wide as its own plans need (review 10: tangent's plans 9 and 10
        # widened two columns of the aligned grid, which fitted no A2 at pa = 40 mm; the A1
        # taken was 68 % blank)
        shelves = Grid(*vviews, title=WORDS("vplans"), group="v", title_height=TITLE_H,
                       fitted=True, rows_own=True)  # fmt: skip
        plans_sheet = Choice(
            vplans, Column(vplans, title_block_spacer()),
            shelves, Column(shelves, title_block_spacer()),
        )  # fmt: skip
        return (first, plans_sheet), mech, True, wants
    sheet = Choice(
        Column(Row(mech_node(), vplans), Row(diagrams, aplans, Column(tables, order))),
        Row(Column(mech_node(), diagrams), Column(vplans, Row(aplans, Column(tables, order)))),
        Column(Row(mech_node(), vplans), Row(diagrams, aplans), Row(tables, order)),
    )
    return (sheet,), mech, False, wants


class _TopPlan(PlanView):
    """A plan drawn right under its own caption (:func:`_under_title`), not centred in a cell
    the layout may have made much taller than the plan: an acceleration plan and the velocity
    plan beside it, in cells as tall as the taller of the two."""

    def draw(self, d: Drawing, at: Placed) -> None:
        ext = self.shown.extent()
        if ext is not None and at.scale is not None:
            _under_title(d, at, ext)
        super().draw(d, at)


class _Note(Text):
    """The note on plan vectors drawn as points: its room is kept in the layout, its words
    drawn only where a plan has such a vector at the scales arranged (:attr:`shown`)."""

    def __init__(self, text: str, h: float) -> None:
        super().__init__(paragraph=text, width=order_width(h), height=h)
        self.shown = True

    def draw(self, d: Drawing, at: Placed) -> None:
        if self.shown:
            super().draw(d, at)


def _order_title(s: Solved, P: Position) -> str:
    """The order's title: the position's angle, and its number where its velocity plan is one
    of the numbered ones."""
    i = next((i for i, Q in enumerate(s.drawn) if Q is P), None)
    if i is None:
        return WORDS("order", phi=_deg(P.phi, s))
    return WORDS("order_at", i=i, phi=_deg(P.phi, s))


def _short(s: Solved, accel: Sequence[Position], lays: Sequence[Arranged]) -> bool:
    """Whether a plan vector comes out shorter than two arrowheads at the arranged scales."""
    k_v, k_a = lays[-1].scale("v"), lays[0].scale("a")
    plans = [(P.vp, k_v) for P in [*s.drawn, *accel]] + [(P.ap, k_a) for P in accel]
    return any(
        k.mm((plan.points[v.head] - plan.points[v.tail]).norm) < SHORT_MM
        for plan, k in plans
        for v in plan.vectors
    )


def layout(s: Solved) -> Layout:
    """Every view of the kinematic sheets and its scale (see the module's docstring)."""
    return _arranged(s)[0]


@per_language
def _arranged(s: Solved) -> tuple[Layout, tuple[Arranged, ...]]:
    """The arrangement of the sheets, once per solution and language (the build asks for the
    scales and its draw for the sheets: the search runs once). Each sheet takes the smallest
    format of the file's on which its views reach the scales :func:`_trees` wants. The output's
    diagrams keep their curves :data:`DIAGRAM_SPAN_MM` high as a least size of their boxes,
    except where that costs the mechanism the crank's rule at its own scale (the crank's
    detail, or a rule missed, where the arrangement without it keeps them): the crank's rule
    outranks the diagrams' (round 2: sixbar-slider's tall mechanism keeps 1:2 beside them)."""
    accel = _accel_positions(s)
    lay, views, share = _arranged_with(s, accel)
    two = accel[: len(s.accel_phis)]
    kept = not _detailed(lay) and share >= 1.0 - tol.REL_LENGTH and not _plot_low(views[0])
    if len(two) < len(accel) and not kept:
        # the force analysis' acceleration plan (:func:`_accel_positions`) where the sheet
        # keeps its rules with it as without it: never at the cost of the crank's detail, of
        # a size rule or of the diagrams' plots (review 17 asked for the plan; the layouts of
        # sixbar-slider and press_offset_long_rod had no room for it); with every rule kept
        # (``kept``) the sheet without it can be no better, and is not laid out
        lay2, views2, share2 = _arranged_with(s, two)
        if (
            (_detailed(lay) and not _detailed(lay2))
            or share2 > share + tol.REL_LENGTH
            or (_plot_low(views[0]) and not _plot_low(views2[0]))
        ):
            return lay2, views2
    return lay, views


def _arranged_with(
    s: Solved, accel: Sequence[Position]
) -> tuple[Layout, tuple[Arranged, ...], float]:
    """:func:`_arranged` with the acceleration plans of ``accel``, and how far it keeps the
    size rules (:func:`_rules_share`)."""
    lay, views, share = _arrange(s, accel, True)
    if _detailed(lay) or share < 1.0 - tol.REL_LENGTH:
        lay2, views2, share2 = _arrange(s, accel, False)
        if (_detailed(lay) and not _detailed(lay2)) or share2 > share + tol.REL_LENGTH:
            return lay2, views2, share2
    return lay, views, share


def _detailed(lay: Layout) -> bool:
    """Whether the layout draws the crank on its detail view."""
    return isinstance(lay.mech, _Mechanism) and lay.mech.detail is not None


def _arrange(
    s: Solved, accel: Sequence[Position], spans: bool
) -> tuple[Layout, tuple[Arranged, ...], float]:
    """:func:`_arranged` with the acceleration plans of ``accel``, with or without the
    diagrams' span as their least size, and how far it keeps the size rules
    (:func:`_rules_share`)."""
    fmts = sheet_formats(s.linkage)
    made: list[tuple[tuple[Tree, ...], _Mechanism, bool, dict[View, float]]] = []
    detail, rules, apart, balanced = False, (False, False), False, True
    plans_k = 0.0  # the velocity plans' scale on their own sheet, once it is arranged
    mech_k = 0.0  # the mechanism's finest scale without its crank's detail, once tried
    seek_k = 0.0  # a finer scale the mechanism's search seeks (FINER_STEPS)

    def make(i: int) -> Callable[[float], tuple[Tree, Mapping[View, float]]]:
        def tree(h: float) -> tuple[Tree, Mapping[View, float]]:
            made.append(
                _trees(s, accel, h, detail, rules, apart, balanced, plans_k, mech_k, seek_k, spans)
            )
            t, _, _, wants = made[-1]
            return t[i], {v: k for v, k in wants.items() if v in _views(t[i])}

        return tree

    def made_of(t0: Tree) -> tuple[tuple[Tree, ...], _Mechanism, bool, dict[View, float]]:
        return next(m for m in made if any(t0 is t for t in (m[0][0], *_alternatives(m[0][0]))))

    def attempt() -> tuple[list[tuple[Tree, formats.Sized]], _Mechanism, bool]:
        nonlocal plans_k
        made.clear()
        plans_k, plans = 0.0, None
        if apart or len(s.drawn) > PLANS_ON_SHEET:
            # the velocity plans' own sheet first: a plan beside an acceleration plan on the
            # first sheet takes its μ_V (review 7: the press's were drawn at μ_V = 0,004 with
            # pa = 188 mm beside the plans sheet's 0,01)
            plans = fit(make(1), fmts, True, rules[0])
            plans_k = plans[1].layout.scale("v").k
        first = fit(make(0), fmts, readable=True, each=rules[0] or seek_k > 0.0)
        trees_all, mech, second, _ = made_of(first[0])
        fitted = [first] + ([plans] if plans is not None else [])
        fitted += [fit(make(i), fmts, True, rules[0]) for i in range(len(fitted), len(trees_all))]
        return fitted, mech, second

    def attempt_seeking(k: float) -> tuple[list[tuple[Tree, formats.Sized]], _Mechanism, bool]:
        nonlocal seek_k
        seek_k = k
        try:
            return attempt()
        finally:
            seek_k = 0.0

    fitted, mech, second = attempt()
    k_first = _mech_k((fitted, mech, second))
    if fitted[0][1].layout.fits and math.isfinite(k_first):
        mech_k = k_first
    if k_first * CRANK_MM * DETAIL_BELOW > s.linkage.length > 0.0 and not any(
        _crank_may_keep(s, accel, fmts, sep, spans) for sep in (False, True)
    ):
        # the long links set the mechanism's scale and leave the crank short, and no
        # arrangement draws the mechanism at the crank's rule: the crank with its numbered
        # positions enlarged beside it (ESKD 2.305's detail view)
        detail = True
        fitted, mech, second = attempt()
    if not _rules_hold(s, fitted):
        # the search seeks the rules' scales (the crank CRANK_MM long, pa PA_MM): on one
        # sheet, else with the velocity plans on a sheet of their own (the mechanism keeps its
        # rule on the larger room), else with the crank on its detail view (the last resort: a
        # coarse mechanism on a smaller format); where none holds them, the one that comes
        # nearest to them (a pa of 39 mm with the crank at its rule beats the unruled
        # arrangement's crank of 16 mm and pa of 20 mm)
        rules = (True, True)
        # the crank's rule at the mechanism's own scale first, on one sheet or with the
        # velocity plans apart; its detail view only where neither holds it (review 7: the
        # oscillator's mechanism at 1:4 beside a 1:1 detail)
        tries = dict.fromkeys(((False, False), (False, True), (True, False), (True, True)))
        chosen = (detail, apart)
        near = _rules_share(s, fitted)
        for enlarge, sep in tries:
            if sep and len(s.drawn) > PLANS_ON_SHEET:
                continue  # the plans are on their own sheet already
            if not enlarge and not _crank_may_keep(s, accel, fmts, sep, spans):
                continue  # no arrangement draws the mechanism at the crank's rule: its detail
            detail, apart = enlarge, sep
            tried = attempt()
            if not enlarge and tried[0][0][1].layout.fits and math.isfinite(_mech_k(tried)):
                # the finest scale the mechanism reached without the detail: with it, the
                # mechanism seeks that scale still (the detail takes free room, not the
                # mechanism's)
                mech_k = min(mech_k or math.inf, _mech_k(tried))
            if _rules_hold(s, tried[0]):
                fitted, mech, second = tried
                chosen = (detail, apart)
                break
            if (share := _rules_share(s, tried[0])) > near:
                fitted, mech, second = tried
                chosen = (detail, apart)
                near = share
        detail, apart = chosen
    # the search's split of the diagrams' column, on the arrangement chosen, where the equal
    # heights leave a curve too low (its μ rounded coarse), or may cost the mechanism its
    # scale: with the velocity plans on a sheet of their own, the column shares the first
    # sheet with the mechanism (a test file's 1:1 became 1:2). Taken where it helps and keeps
    # the size rules as well.
    squeezed = _spans(fitted)
    floor = DIAGRAM_SPAN_MM if spans else DIAGRAM_SPAN_LEAST_MM
    low = min(squeezed, default=floor) < floor - tol.SHEET_MM
    if low or second:
        balanced = False
        tried = attempt()
        finer = _mech_k(tried) < _mech_k((fitted, mech, second)) * (1.0 - tol.REL_LENGTH)
        if (low or finer) and _rules_share(s, tried[0]) >= _rules_share(s, fitted) - tol.REL_LENGTH:
            fitted, mech, second = tried
        else:
            balanced = True
    # the mechanism at the next finer GOST step while the sheets still fit with the size rules
    # and the diagrams' spans kept (review 11: the kulisa drawn 1:4 on an A1 49 % blank, where
    # its mechanism, tables and diagrams fit at 1:2,5): the search, scoring every view's
    # drawn area, settles on splits that leave the field blank rather than grow one view
    for _ in range(FINER_STEPS):
        k_now = _mech_k((fitted, mech, second))
        if detail or not math.isfinite(k_now):
            break
        seek = round_scale_down(k_now * (1.0 - 2.0 * tol.REL_LENGTH), "l", mech.series).k
        tried = attempt_seeking(seek)
        if not (
            _mech_k(tried) <= seek * (1.0 + tol.REL_LENGTH)
            and all(z.layout.fits for _, z in tried[0])
            and [z.fmt for _, z in tried[0]] == [z.fmt for _, z in fitted]
            and _rules_share(s, tried[0]) >= _rules_share(s, fitted) - tol.REL_LENGTH
            and min(_spans(tried[0]), default=floor) >= floor - tol.SHEET_MM
        ):
            break
        fitted, mech, second = tried
    trees = tuple(t for t, _ in fitted)
    sized = tuple(z for _, z in fitted)
    lays = tuple(z.layout for z in sized)
    short = _short(s, accel, lays)
    for tree in trees:  # the note, where a plan needs it
        for view in _views(tree):
            if isinstance(view, _Note):
                view.shown = short
    k_v = lays[-1].scale("v")
    out = Layout(lays[0][mech].scale or Scale(1.0), k_v, lays[0].scale("a"), second, tuple(accel),
                 trees, mech, sized, balanced, squeezed, spans)  # fmt: skip
    return out, lays, _rules_share(s, fitted)


def _crank_may_keep(
    s: Solved, accel: Sequence[Position], fmts: Sequence[str], apart: bool, spans: bool = True
) -> bool:
    """A necessary test before the search (:func:`geomcad.sheet.formats.may_reach`): whether
    the first sheet, on the largest of ``fmts``, has room for the mechanism at the crank's
    rule (:data:`CRANK_MM`) with the other views at their least sizes, without the crank's
    detail view (a crusher's 0,9 m mechanism at 1:1 has none)."""
    trees, mech, _, _ = _trees(s, accel, SMALL_TEXT_H, rules=(True, True), apart=apart, spans=spans)
    k = round_scale_down(s.linkage.length / CRANK_MM, "l", mech.series).k
    largest = max(fmts, key=lambda f: FORMATS[f][0] * FORMATS[f][1])
    fmt, land = next(formats.candidates((largest,)))
    return formats.may_reach(trees[0], {mech: k}, Field.of_format(fmt, land))


def _mech_k(arranged: tuple[Sequence[tuple[Tree, formats.Sized]], View, bool]) -> float:
    """The mechanism's length factor (m/mm) in an arrangement (inf where it has none)."""
    scale = arranged[0][0][1].layout[arranged[1]].scale
    return math.inf if scale is None else scale.k


def _spans(fitted: Sequence[tuple[Tree, formats.Sized]]) -> tuple[float, ...]:
    """The heights (mm) at which the output's diagrams draw their curves, as arranged."""
    out = []
    for _, z in fitted:
        for pl in z.layout:
            if isinstance(pl.view, Diagram):
                x0, y0, x1, y1 = pl.inner
                ay = pl.view.axes(x1 - x0, y1 - y0)[1]
                ys = [float(np.max(c.ys)) for c in pl.view.curves]
                lo = [float(np.min(c.ys)) for c in pl.view.curves]
                out.append(ay.mm(max(ys) - min(lo)))
    return tuple(out)


def _rules_hold(s: Solved, fitted: Sequence[tuple[Tree, formats.Sized]]) -> bool:
    """Whether every sheet of the arrangement fits and keeps the size rules: the crank at
    least :data:`CRANK_MM` long on the mechanism or on its detail view, pa at least
    :data:`PA_MM`."""
    return _rules_share(s, fitted) >= 1.0 - tol.REL_LENGTH


def _rules_share(s: Solved, fitted: Sequence[tuple[Tree, formats.Sized]]) -> float:
    """How far the arrangement keeps the size rules: the smaller of the crank's length (on
    the mechanism or on its detail view) over :data:`CRANK_MM` and pa over :data:`PA_MM`, at
    most 1 (both kept); 0 where a sheet does not fit."""
    lk = s.linkage
    lays = [z.layout for _, z in fitted]
    if not all(lay.fits for lay in lays):
        return 0.0
    crank = 0.0
    for pl in lays[0]:
        if isinstance(pl.view, _Mechanism | _CrankDetail) and pl.scale is not None:
            crank = max(crank, pl.scale.mm(lk.length))
    pa = lays[-1].scale("v").mm(abs(lk.omega) * lk.length)
    return min(crank / CRANK_MM, pa / PA_MM, 1.0)


def _alternatives(tree: Tree) -> tuple[Tree, ...]:
    """A :class:`Choice`'s arrangements; any other tree is its own one."""
    return tree.items if isinstance(tree, Choice) else (tree,)


def _views(tree: Tree) -> list[View]:
    return [tree] if isinstance(tree, View) else list(tree.views())


def sheet_scales(s: Solved) -> dict[str, float]:
    """The scale of each drawn quantity (for ``verify``): k_l, k_v, k_a."""
    lay = layout(s)
    return {"l": lay.k_l.k, "v": lay.k_v.k, "a": lay.k_a.k}


def kinematic_sheets(s: Solved, stem: str = "") -> list[tuple[str, Sheet]]:
    """The kinematic sheet (and, with many positions, a second sheet of velocity plans)."""
    lk = s.linkage
    lay, lays = _arranged(s)
    count = len(lay.trees)
    designation = WORDS("designation", stem=stem or WORDS("stem"))
    d = lay.sized[0].start(_title(lk, WORDS("kinematics"), designation, None, 1, count))
    fill_diagrams(lays[0])
    compose(d, lay.trees[0], layout=lays[0])
    if d.sheet.block is not None:
        d.sheet.block = replace(d.sheet.block, scale=lay.k_l.ratio_text())
    first = d.finish(breaks=False)
    for pl in lays[0]:  # a link's number never reads as a position's
        if isinstance(pl.view, _Mechanism | _CrankDetail):
            if isinstance(pl.view, _Mechanism):
                keep_tracks_apart(first, pl.box, pl.view.tracks, pl.view.rows)
            keep_link_numbers_clear(first, pl.box)
    break_under_labels(first)  # the labels where they stay
    out: list[tuple[str, Sheet]] = [("", first)]
    if lay.second:
        d2 = lay.sized[1].start(_title(lk, WORDS("vplans_sheet"), designation, None, 2, count))
        compose(d2, lay.trees[1], layout=lays[1])
        out.append(("plans", d2.finish()))
    return out


def _title(
    lk: Linkage, what: str, designation: str, k: Scale | None, no: int, count: int
) -> TitleBlock:
    return TitleBlock(
        title=sheet_name(lk, what),
        designation=designation,
        # a sheet with no one scale (the velocity plans' sheet, each plan at μ_V) says so:
        # a dash, never an empty cell
        scale=k.ratio_text() if k is not None else NO_SCALE,
        sheet_no=no,
        sheets=count,
        lang=current(),
    )


#: Letters of another script than the language's: a file's title in them stays off its sheets
#: (Cyrillic on an English sheet).
_FOREIGN = {"en": re.compile(f"[{chr(0x400)}-{chr(0x4FF)}]")}


def sheet_name(lk: Linkage, what: str) -> str:
    """A sheet's name in its title block: what it draws and the file's title ("Силовой
    анализ. Шестизвенный механизм вертикального пресса"), or what it draws alone where the
    title is not in the sheet's language or the two do not fit the name's cell at any GOST
    height (:func:`~geomcad.sheet.frame.name_fits`)."""
    name = file_title(lk)
    full = f"{what}. {name}"
    return full if name and name_fits(full, current()) else what


def file_title(lk: Linkage) -> str:
    """The file's title, where it is written in the language being drawn ("" on an English
    sheet for a Russian title: the title is the user's words, not a table's)."""
    foreign = _FOREIGN.get(current())
    return "" if foreign is not None and foreign.search(lk.title) else lk.title


def _through(s: Solved) -> str:
    lk = s.linkage
    n = _divisions(s)
    del lk
    through = WORDS("through_positions", last=n - 1)
    phi0 = _deg(s.drawn[0].phi, s)
    return WORDS("diagrams_note", through=through, phi0=phi0)


def _divisions(s: Solved) -> int:
    return len(s.drawn)


# --- the mechanism ----------------------------------------------------------------------------


def _principal(s: Solved) -> tuple[Position, int | None]:
    """The position drawn in main lines and its number (``None``: not a numbered one): the
    force analysis' position where the file gives masses or loads, else position 0."""
    lk = s.linkage
    if lk.masses or lk.loads:
        from geomcad.linkage.analysis import analyse

        a = analyse(s)
        if a.force_position is not None:
            return a.force_position, a.force_index
    return s.drawn[0], 0


#: A yoke's slot on the mechanism view: its sides this far (mm) either side of its axis, clear
#: of the block that slides in it (GOST 2.770's slotted link).
SLOT_HALF_MM = SLIDER_SIZE[1] / 2.0 + 0.5
#: Points nearer than this fraction of the crank's length are at one place (one label).
_SAME = tol.SAME_PLACE
#: A slotted link runs on past its block by this fraction of the block's distance from the pivot.
SLOT_PAST = 1.15


#: A point no other link carries (a centre of mass) is a corner of its link's outline where it lies
#: farther than this fraction of the link's size outside the outline of the link's joints; nearer,
#: it is drawn as its dot on the link (a crosshead's centre of mass 1.5 % off its arm was a kink).
PLATE_NEAR = 0.05


def _plate_corners(joints: Sequence[Vec], aside: Sequence[Vec]) -> list[Vec]:
    """Those of ``aside`` that lie farther than PLATE_NEAR of the joints' size outside the convex
    outline of ``joints`` (shapely's convex hull: a segment for two joints)."""
    if len(joints) < 2:
        return list(aside)
    size = max(a.dist(b) for a, b in itertools.combinations(joints, 2))
    hull = MultiPoint([(q.x, q.y) for q in joints]).convex_hull
    out: list[Vec] = []
    for q in aside:
        far = hull.distance(Point(q.x, q.y)) > PLATE_NEAR * size
        if far and not any(q.dist(u) <= tol.DERIVED * max(1.0, q.norm) for u in out):
            out.append(q)
    return out


def link_bodies(
    lk: Linkage, P: Position, links: Sequence[int] | None = None, slot_half: float = 0.0,
    axes: bool = False,
) -> dict[str, list[Body]]:  # fmt: skip
    """Each link's body in position P through all its points: a slotted link along its slide,
    past the block; a PRP yoke with its slot through the block; a link carrying a guide with
    the guide run on to its slider. ``links``: those to draw (default: every moving link).
    ``slot_half`` (model units): a yoke's slot drawn as a slot, the outline of its two sides
    this far either side of its axis (the block slides between them), its rod from the slot's
    side; 0: the slot as its axis line. ``axes``: each link through its pairs only, a point
    no other link carries (a coupler point M, a centre of mass) left out, a link of three or
    more joints drawn as one side, between its first two (its own in its group): a thin
    position's drawing, where the coupler's triangle in every position would weave a web (the
    points' paths and numbers show it); an offset slot without its arm from the pivot (the arms of
    every position would melt into one blot at the pivot: the slots touch the offset's
    circle, drawn once); a joint beyond the first two (a bell-crank's arm CE that link 4 hangs
    on) joined to the nearer of them by an arm. In the main position a point no other link
    carries (a centre of mass, a traced point) is a corner of the link's outline only where it
    lies farther than PLATE_NEAR of the link's size outside the outline of its joints (review 9:
    a bell-crank drawn C–S3–E with its centre of mass a corner; a coupler A–S2–B–M)."""
    out: dict[str, list[Body]] = {}
    carried: dict[str, int] = {}
    for link in lk.moving_links:
        for n in lk.points_on(link):
            carried[n] = carried.get(n, 0) + 1
    lone = {p.name for p in lk.points if carried.get(p.name, 0) == 1}
    for link in lk.moving_links if links is None else links:
        uniq: list[Vec] = []
        aside: list[Vec] = []
        for n in lk.points_on(link):
            q = P.pos[n]
            if n in lone and len([m for m in lk.points_on(link) if m not in lone]) >= 2:
                aside.append(q)
                continue
            if not any(q.dist(u) <= tol.DERIVED * max(1.0, q.norm) for u in uniq):
                uniq.append(q)
        if not axes and aside:
            uniq += _plate_corners(uniq, aside)
        g = lk.group_of(link)
        if g is not None and g.kind == "RPR" and link == g.links[1]:
            d = P.slide[link]
            C = P.pos[g.pivot]
            # to the farthest of its points, or a little past the block where the block is
            # farther (a slot runs on past its block; a link ends at its last joint)
            far = max(
                [(P.pos[n] - C).dot(d) for n in lk.points_on(link)]
                + [(P.pos[g.slider] - C).dot(d) * SLOT_PAST]
            )
            foot = C + d.perp() * g.offset
            if not g.offset:
                out[str(link)] = [Body.of([C, C + d * far])]
            elif axes:  # a thin position: its slot alone, tangent to the offset's circle
                out[str(link)] = [Body.of([foot, foot + d * far])]
            else:
                out[str(link)] = [Body.of([C, foot, foot + d * far])]
            # a point beyond the pivot (an arm the slot does not reach: review 8, a rocking
            # cylinder's arm CE drawn nowhere, its E hanging free) joined to the pivot by an arm
            # of the same link; in a thin position only where another link hangs on it
            for n in lk.points_on(link):
                q = P.pos[n]
                if (q - C).dot(d) < -tol.DERIVED * max(1.0, q.norm) and not (axes and n in lone):
                    out[str(link)].append(Body.of([C, q]))
                    continue
                # a point of the link off its slot (review 17: a planer's B set "from C toward
                # A" on an offset slot, 0,015 m beside it, drawn free of link 3 with link 4 hung
                # on it): joined to the slot by an arm square to it; a point no other link
                # carries only in the main position and where it lies farther than PLATE_NEAR
                # of the slot's length from it (a centre of mass 1 mm off is on the slot)
                at = foot + d * (q - foot).dot(d)
                off = q.dist(at)
                near = PLATE_NEAR * far if n in lone else tol.DERIVED * max(1.0, q.norm)
                if n != g.pivot and off > near and not (axes and n in lone):
                    out[str(link)].append(Body.of([at, q]))
        elif len(uniq) == 2:
            out[str(link)] = [Body.of(uniq)]
        elif len(uniq) > 2 and axes:
            # a thin position of a rigid triangle (a coupler ABE with a group hung on E): one
            # side, between the link's own joints in its group; the other points' paths and
            # numbers show them (twelve whole triangles once wove a web over the view). Points
            # on one line (a rocker CBE with E beyond B): the line through them all.
            u = (uniq[1] - uniq[0]).unit()
            if all(abs(u.cross(q - uniq[0])) <= tol.DERIVED * max(1.0, q.norm) for q in uniq):
                ends = sorted(uniq, key=lambda q: u.dot(q - uniq[0]))
                out[str(link)] = [Body.of([ends[0], ends[-1]])]
            else:
                # every further joint on an arm from the nearer of the two (review 9: a
                # bell-crank's E, link 4 hung on it, drawn free of its C in every thin position)
                arms = [Body.of([min(uniq[:2], key=q.dist), q]) for q in uniq[2:]]
                out[str(link)] = [Body.of(uniq[:2]), *arms]
        elif len(uniq) > 2:
            cx = sum(q.x for q in uniq) / len(uniq)
            cy = sum(q.y for q in uniq) / len(uniq)
            ring = sorted(uniq, key=lambda q: math.atan2(q.y - cy, q.x - cx))
            out[str(link)] = [Body.of(ring, closed=True)]
        if g is not None and g.kind == "PRP" and link == g.links[1] and g.guide is not None:
            # the yoke: its rod along the fixed guide (first: the link's number goes there) and
            # its slot across it, over the block's whole travel, in every position alike
            yk = yoke(lk, g)
            E, d = P.pos[g.joint], g.guide.direction
            u = P.slide[g.links[0]]
            if slot_half > 0.0:
                w = u.perp() * slot_half
                e0, e1 = E + u * yk.slot[0], E + u * yk.slot[1]
                slot = Body.of([e0 + w, e1 + w, e1 - w, e0 - w], closed=True)
                side = slot_half / max(abs(d.cross(u)), 0.2)  # the slot's side along the rod
                rod = Body.of([E + d * math.copysign(side, yk.rod), E + d * yk.rod])
            else:
                slot = Body.of([E + u * yk.slot[0], E + u * yk.slot[1]])
                rod = Body.of([E, E + d * yk.rod])
            # the yoke's own outline where it reaches a point off its rod and slot (a crosshead's
            # arm to the joint F a rocker hangs on: review 9, drawn nowhere in the thin positions)
            rod_slot = [(E + u * yk.slot[0], E + u * yk.slot[1]), (E, E + d * yk.rod)]
            off = any(
                min(_to_segment((q.x, q.y), (p.x, p.y), (r.x, r.y)) for p, r in rod_slot)
                > tol.DERIVED * max(1.0, q.norm)
                for q in uniq
            )
            out[str(link)] = [rod, slot, *(out.get(str(link), []) if off else [])]
        # a guide on this link runs on to the slider it carries
        for g2 in lk.groups:
            gd = g2.guide
            if g2.kind == "RRP" and gd is not None and gd.link == link:
                line = P.lines[g2.index]
                t = [(P.pos[n] - line.p).dot(line.d) for n in (gd.frm, gd.toward, g2.joint)]
                out.setdefault(str(link), []).append(Body.of([line.at(min(t)), line.at(max(t))]))
                if gd.offset:
                    out[str(link)].append(Body.of([P.pos[gd.frm], line.p]))
    return out


@dataclass(frozen=True)
class Yoke:
    """How a PRP group's yoke is drawn: ``rod`` (model units, signed along the guide's
    direction) from its point on the guide to the rod's end, ``slot`` the slot's two ends
    (signed along the slot's direction from the yoke's point on the guide): over the block's
    travel in the slot and on to the guide, never past them (review 11: the yarn traverse's
    bar, its block all below the guide, drawn as far above it), ``guide`` the middle of the
    fixed guide (the frame's, the same in every position) the rod
    slides in, clear of the yoke's travel on the side away from the crank's pivot, and
    ``half`` the guide's half length: over the rod's end in every position (the rod's travel
    and its hold, :data:`GUIDE_HOLD`), so that the rod never runs out past its guide."""

    rod: float
    slot: tuple[float, float]
    guide: Vec
    half: float = 0.0


_YOKES: dict[int, tuple[Linkage, dict[int, Yoke]]] = {}
#: A yoke's rod keeps this share of its travel inside its guide where it stands farthest from
#: it (the guide drawn that much longer than the travel, and the scheme's hatching runs
#: :data:`~geomcad.sheet.scheme.GUIDE_HALF` past either end): a rod whose end only touched the
#: guide's near end would read as run out of it. Review 13: half its travel (0.5) hatched the
#: clipper's guide 225 mm for a 140 mm stroke, "far beyond it"; 0.1 drew it 137 mm, but then
#: the sine crosshead rocker's forces sheet went to 1:2 with its crank 22.5 mm and no detail
#: (the forces layout does not yet draw the crank's detail wherever it goes finer): 0.5 kept
#: until it does (round 13).
GUIDE_HOLD = 0.5


def yoke(lk: Linkage, g: Group) -> Yoke:
    """The yoke of the PRP group ``g`` (:class:`Yoke`), from the linkage's whole turn."""
    held = _YOKES.get(id(lk))
    if held is None or held[0] is not lk:
        held = (lk, {})
        _YOKES.clear()
        _YOKES[id(lk)] = held
    if g.index not in held[1]:
        assert g.guide is not None
        st = sweep(lk, np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES), order=0)
        q, d = g.guide.through, g.guide.direction
        E, A = np.asarray(st.pos[g.joint]), np.asarray(st.pos[g.slider])
        t = (E - [q.x, q.y]) @ [d.x, d.y]
        t0, t1 = float(t.min()), float(t.max())
        side = -1.0 if (lk.frame[lk.pivot] - q).dot(d) >= 0.5 * (t0 + t1) else 1.0
        # the guide this far past the yoke's travel, as long as the rod's travel and the
        # rod's hold in it (GUIDE_HOLD): the rod's end, drawn to the guide's far end where
        # the yoke stands nearest the guide, stays in the hatched guide in every position
        # (review 12: the yarn traverse's bar drawn ≈55 mm past its guide)
        clear, travel = 0.5 * lk.length, t1 - t0
        half = 0.5 * travel * (1.0 + GUIDE_HOLD)
        near = t1 if side > 0.0 else t0  # the yoke's place nearest the guide
        tg = near + side * (clear + half)
        rod = side * (clear + 2.0 * half)
        # the block's place in the slot, signed along the slot (the yoke translates: one
        # direction in every position), and the slot on past it at either end it travels to
        w = np.asarray(st.slide[g.links[0]])
        r = ((A - E) * w).sum(axis=1)
        r0, r1 = float(r.min()), float(r.max())
        past = (SLOT_PAST - 1.0) * max(abs(r0), abs(r1), lk.length)
        slot = (min(r0 - past, 0.0), max(r1 + past, 0.0))
        held[1][g.index] = Yoke(rod, slot, q + d * tg, half)
    return held[1][g.index]


def frame_guides(lk: Linkage) -> dict[str, Vec]:
    """Where the scheme draws the frame's guide of each yoke (``draw_scheme``'s ``guides``)."""
    return {
        f"{g.joint}:{g.links[1]}": yoke(lk, g).guide
        for g in lk.groups
        if g.kind == "PRP" and g.guide is not None
    }


def _mechanism_extent(s: Solved) -> tuple[float, float, float, float]:
    """The model box of everything the mechanism view draws: every position's points and link
    bodies, the crank circle and the traced paths, with a little room round them."""
    lk = s.linkage
    pts: list[Vec] = []
    for P in (*s.drawn, _principal(s)[0]):
        pts += list(P.pos.values())
        for bodies in link_bodies(lk, P).values():
            for b in bodies:
                pts += list(b.points)
    O1 = lk.frame[lk.pivot]
    pts += [O1 + Vec(lk.length, lk.length), O1 - Vec(lk.length, lk.length)]
    for path in _paths(lk, traced_joints(lk)).values():
        pts += path
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    x0, y0, x1, y1 = min(xs), min(ys), max(xs), max(ys)
    pad = 0.04 * max(x1 - x0, y1 - y0, lk.length)
    return x0 - pad, y0 - pad, x1 + pad, y1 + pad


def _paths(lk: Linkage, joints: Sequence[str] = ()) -> dict[str, list[Vec]]:
    """The paths of the named points and of the groups' ``joints`` over a turn (sampled by
    the sweep)."""
    phi = np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES)
    st = sweep(lk, phi, order=0)
    names = dict.fromkeys((*(p.name for p in lk.points), *joints))
    return {n: [Vec(float(a), float(b)) for a, b in st.pos[n]] for n in names}


def one_pass(path: Sequence[Vec]) -> list[Vec]:
    """A point's path over a turn as it is drawn: where it runs over one curve forth and back
    (a rocker's joint on its arc: review 17, its dash-dot line drawn twice, the two passes' dashes
    out of step, printed as a solid thin line), that curve once, between the two points where it
    turns back (:data:`~geomcad.tol.RETRACED_AREA`); any other path as it is."""
    pts = list(path)
    if len(pts) < 4:
        return pts
    segs = [b - a for a, b in itertools.pairwise(pts)]
    length = sum(s.norm for s in segs)
    area = 0.5 * abs(sum(a.cross(b) for a, b in itertools.pairwise([*pts, pts[0]])))
    if length <= 0.0 or area > tol.RETRACED_AREA * length * length:
        return pts
    live = [i for i, s in enumerate(segs) if s.norm > tol.DERIVED * length]
    turns = [j for i, j in itertools.pairwise([*live, live[0]]) if segs[i].dot(segs[j]) < 0.0]
    if len(turns) != 2:
        return pts
    i, j = sorted(turns)
    # segment j starts at point j: the turning points are points i and j
    return pts[i : j + 1]


def _under_title(d: Drawing, at: Placed, ext: tuple[float, float, float, float]) -> Viewport:
    """The view's viewport moved up so that its drawing (model ``ext``) stands right under its
    title, centred across (the layout centres it in its box: a tall box left the title far
    above a drawing ruled by its width); kept in ``at`` for whoever reads the view's place."""
    v = at.viewport
    assert v is not None and at.scale is not None
    cx, cy = (ext[0] + ext[2]) / 2.0, (ext[1] + ext[3]) / 2.0
    h = at.scale.mm(ext[3] - ext[1])
    top = min(at.inner[1] + h / 2.0, (at.inner[1] + at.inner[3]) / 2.0)
    at.viewport = d.viewport(at.scale, (cx, cy), ((at.inner[0] + at.inner[2]) / 2.0, top))
    return at.viewport


class _Mechanism(View):
    """The mechanism in all its numbered positions: the principal one (:func:`_principal`) in
    main lines with its scheme's symbols, the others in thin lines, the crank circle and the
    paths of the named points."""

    def __init__(self, s: Solved) -> None:
        # the main lines' position named in the title where it is none of the numbered ones
        # (``[forces] phi``), as the forces sheet names it, not read as a numbered one beside it
        P0, k0 = _principal(s)
        deg = math.degrees(P0.phi) % 360.0
        phi = fmt_fixed(deg, angle_places([deg]), current())
        last = len(s.drawn) - 1
        super().__init__(
            title=WORDS("mech", last=last) if k0 is not None else WORDS("mech_phi", last=last,
                                                                         phi=phi),
            title_height=5.0, margin=6.0, weight=2.0,
        )  # fmt: skip
        self.s = s
        self._ext = _mechanism_extent(s)
        #: the letter of the crank's detail view (:class:`_CrankDetail`), where there is one
        self.detail: str | None = None
        #: each numbered track's points as drawn (paper mm), for :func:`keep_tracks_apart`
        self.tracks: dict[str, list[tuple[float, float]]] = {}
        #: the boxes of each track's numbers set in rows (paper mm)
        self.rows: dict[str, list[Box]] = {}

    def extent(self) -> tuple[float, float, float, float]:
        return self._ext

    def draw(self, d: Drawing, at: Placed) -> None:
        v = _under_title(d, at, self._ext)
        s = self.s
        lk = s.linkage
        v.circle(lk.frame[lk.pivot], lk.length, "centre")
        for path in _paths(lk, traced_joints(lk)).values():
            v.polyline(one_pass(path), "centre")
        for g in lk.groups:  # an offset slot's circle: the thin positions' slots touch it
            if g.kind == "RPR" and g.offset:
                _offset_arc(v, g, s.drawn)
        # every other position in thin lines, numbered at the crank's joint and the output; the
        # principal one (the force analysis' position, else position 0) in main lines
        P0, k0 = _principal(s)
        thin = len(d.sheet.items)
        swept: list[tuple[Vec, ...]] = []  # the thin positions' lines, the guides clear of them
        for i, P in enumerate(s.drawn):
            if i != k0:
                for bs in link_bodies(lk, P, axes=True).values():
                    for b in bs:
                        v.polyline(b.points, "thin", closed=b.closed)
                        swept.append(b.points + ((b.points[0],) if b.closed else ()))
        thin_end = len(d.sheet.items)
        labels: dict[str, str] = {}
        mech = scheme(lk, P0)  # the pairs where the principal position has them
        bodies = link_bodies(lk, P0, slot_half=v.scale.model(SLOT_HALF_MM))
        first: dict[str, str] = {}  # the names of the points at one place, on its first pair
        for pair in mech.pairs:
            name = pair.name.split(":")[0]
            if name not in P0.pos:
                continue
            there = next((k for k in first if P0.pos[k].dist(P0.pos[name]) <= _SAME * lk.length),
                      None)  # fmt: skip
            if there is None:
                first[name], labels[pair.name] = pair.name, name
            elif name not in labels[first[there]].split(", "):
                labels[first[there]] += f", {name}"  # a yoke's E on the block's A: "A, E"
        guides = frame_guides(lk)
        travel = {  # a slider's guide on the frame drawn over its travel in the positions drawn
            pair.name: [P.pos[pair.name.split(":")[0]] for P in s.drawn]
            for pair in mech.pairs
            if pair.kind == "P" and mech.frame in pair.links and pair.name not in guides
            and pair.name.split(":")[0] in P0.pos
        }  # fmt: skip
        guided = {name.split(":")[0] for name in travel}
        for g in lk.groups:  # a yoke's guide over its rod's travel
            if g.kind == "PRP" and g.guide is not None:
                yk, gd = yoke(lk, g), g.guide.direction
                travel[f"{g.joint}:{g.links[1]}"] = [yk.guide - gd * yk.half,
                                                     yk.guide + gd * yk.half]  # fmt: skip
        blocks = [
            (v.p(pair.at), v.paper_dir(pair.axis))
            for pair in mech.pairs
            if pair.kind == "P" and pair.axis is not None
            and any(is_block(mech, k) and k not in bodies for k in pair.links)
        ]  # fmt: skip
        # the crank's joint, the output and every named point whose path is traced
        traced = list(dict.fromkeys((lk.joint, lk.output, *(p.name for p in lk.points),
                                     *numbered_tracks(lk))))  # fmt: skip
        for name in traced:
            for P in s.drawn:
                if not any(_in_block(v.p(P.pos[name]), c, u) for c, u in blocks):
                    v.dot(P.pos[name])
        lettered = {n for t in labels.values() for n in t.split(", ")}  # "B, K": K lettered
        marked = {k: ", ".join(markup_of(n) for n in t.split(", ")) for k, t in labels.items()}
        numbers: dict[str, Vec] = {}
        for g in lk.groups:  # a yoke's number on its rod between the slot and the guide
            if g.kind == "PRP" and g.guide is not None:
                yk, gd = yoke(lk, g), g.guide.direction
                near = yk.guide - gd * math.copysign(yk.half, yk.rod)
                numbers[str(g.links[1])] = (P0.pos[g.joint] + near) * 0.5
        symbols_from = len(d.sheet.items)
        draw_scheme(v, mech, bodies=bodies, pair_labels=marked, label_height=3.5,
                    guides=guides, travel=travel, link_space=LINK_SPACE,
                    link_labels=numbers, letter_space=LETTER_SPACE, swept=swept)  # fmt: skip
        hubs = [v.p(p.at) for p in mech.pairs if p.kind == "R" and mech.frame in p.links]
        zones = hub_zones(d.sheet.items[symbols_from:], hubs)
        break_round(d.sheet, thin, thin_end, zones)
        # no letter on a hub's joint and support (its cleared ring is a letter's free room)
        d.occupied += [z.buffer(-HUB_CLEAR_MM) for z in zones]
        for p in lk.points:
            if p.name not in lettered:
                v.dot(P0.pos[p.name])
                v.label(P0.pos[p.name], markup_of(p.name), 3.5, clear=1.0, space=LETTER_SPACE)
        omega_arrow(v, lk, P0)
        # the positions numbered last, clear of every line drawn
        numbered: list[Vec] = []
        taken: list[Box] = []
        done: list[list[tuple[float, float]]] = []  # the tracks numbered, as drawn
        for name in numbered_tracks(lk):
            pts = [P.pos[name] for P in s.drawn]
            if name == lk.joint and self.detail is not None:
                mark_detail(v, lk.frame[lk.pivot], lk.length, self.detail)
                done.append([v.p(q) for q in pts])  # its circle is still the crank's zone
                continue  # the crank's positions are numbered on its detail view
            self.tracks[name] = [v.p(q) for q in pts]
            if _in_zone(self.tracks[name], done) and _read_elsewhere(lk, name):
                continue
            done.append(self.tracks[name])
            vels = [P.vel[name] for P in s.drawn]
            clear = GUIDE_CLEAR_MM if name in guided else 0.0
            rowed = len(taken)
            position_numbers(v, pts, vels, lk.frame[lk.pivot], numbered, clear, taken)
            self.rows[name] = taken[rowed:]
            numbered = pts


#: A hub (a joint of the frame where the links of every position meet) is drawn once, clean:
#: the other positions' thin lines end this far (mm) from its joint's circle and from its
#: support's stand and hatching (review 13: the slotter's crank hub, twelve positions' lines
#: through its joint and support, read as a knot).
HUB_CLEAR_MM = 1.0


def hub_zones(symbols: Sequence[Any], hubs: Sequence[tuple[float, float]]) -> list[Any]:
    """The zones (shapely, paper mm) that the thin lines keep out of round each hub (a joint
    of the frame, paper mm): its joint's circle and its support (the stand's two legs from the
    joint among ``symbols``, the scheme's items, their ground line and its hatching) grown by
    :data:`HUB_CLEAR_MM`."""
    zones = []
    leg = math.hypot(STAND_DEPTH, STAND_HALF)
    for c in hubs:
        pts = [c]
        legs = [
            it.points[1] for it in symbols
            if isinstance(it, Polyline) and len(it.points) == 2 and it.role == "link"
            and math.dist(it.points[0], c) <= tol.SHEET_MM
            and abs(math.dist(it.points[0], it.points[1]) - leg) <= tol.SHEET_MM
        ]  # fmt: skip
        if len(legs) == 2:  # the ground line 1.5 mm past the legs, hatched HATCH_LEN under it
            (ax, ay), (bx, by) = legs
            n = math.dist(legs[0], legs[1])
            ux, uy = (ax - bx) / n, (ay - by) / n
            mx, my = (ax + bx) / 2.0 - c[0], (ay + by) / 2.0 - c[1]
            m = math.hypot(mx, my)
            dx, dy = mx / m, my / m
            for (x, y), sgn in ((legs[0], 1.0), (legs[1], -1.0)):
                ex, ey = (
                    x + sgn * ux * (1.5 + 0.6 * HATCH_LEN),
                    y + sgn * uy * (1.5 + 0.6 * HATCH_LEN),
                )
                pts += [(ex, ey), (ex + dx * HATCH_LEN, ey + dy * HATCH_LEN)]
        zone = MultiPoint(pts).convex_hull.buffer(HUB_CLEAR_MM)
        zones.append(zone.union(Point(c).buffer(JOINT_R + HUB_CLEAR_MM)))
    return zones


#: On the mechanism in its positions, a point's letter keeps this much (mm) further than usual
#: from other texts: from the position numbers round it (placed before it), nearer, a number
#: beside it reads as its index ("D⁷") and a row of them ending at it as one text with it ("4 5B";
#: review 8). Not GOST 2.304's whole word space (0.6 h, 2.1 mm): that much more drove the placer
#: to set sixbar_coupler_slider's D on its guide's axis; 1.0–1.25 left crank_rocker_inclined's D
#: on the hatching.
LETTER_SPACE = 1.5
#: A track's numbering zone: the hull of its points grown by this much (mm), where its numbers
#: stand (:func:`position_numbers` sets them within a row's depth of their points).
ZONE_MM = 5.0
#: A track whose points lie within this (mm) of one line is degenerate: its point runs to and
#: fro along a segment (a yoke's point on its guide).
LINE_MM = 0.5


def _in_zone(track: Sequence[tuple[float, float]], done: Sequence[Sequence[tuple[float, float]]]
             ) -> bool:  # fmt: skip
    """Whether ``track`` (paper points) is degenerate (:data:`LINE_MM`) and lies within the
    numbering zone (:data:`ZONE_MM`) of one of the tracks ``done``: its numbers could only
    stand among that track's (review 7: a yoke's point E on its guide through the crank's
    pivot, numbered "9 3", "4 8", "5 7 6" inside the crank circle among its numbers)."""
    xy = np.asarray(track, dtype=float)
    if len(xy) < 2:
        return False
    i, j = np.unravel_index(np.argmax(((xy[:, None] - xy[None]) ** 2).sum(axis=2)), (len(xy),) * 2)
    u = xy[j] - xy[i]
    span = float(np.hypot(*u))
    if span > 0.0:
        d = xy - xy[i]
        off = np.abs(u[0] * d[:, 1] - u[1] * d[:, 0]) / span
        if float(off.max()) > LINE_MM:
            return False
    return any(within_hull(track, other, ZONE_MM) for other in done if len(other) >= 3)


def _read_elsewhere(lk: Linkage, name: str) -> bool:
    """Whether the positions of the link that carries ``name`` are numbered at another of its
    points (a yoke's arm end F for its point E on the guide)."""
    link = lk.owner.get(name)
    return link is not None and any(
        k != name and lk.owner.get(k) == link for k in numbered_tracks(lk)
    )


def numbered_tracks(lk: Linkage) -> tuple[str, ...]:
    """The points whose positions the mechanism's view numbers: every moving point (the
    crank's joint, the output, each group's joint, every named point), but a centre of mass
    that is nothing more (no group hangs on it, no load acts at it): its path is drawn and
    dotted, its letter stands at the principal position, and its positions follow from its
    link's, which are numbered; numbers of its own would only stand among the joints' ones
    (S3's "9", "10" beside the crank circle's). A group's joint is numbered as a named point
    is (review 6: a V compressor's second piston B once stood in twelve unnumbered places)."""
    centres = {m.centre for m in lk.masses.values()}
    hung = {q for g in lk.groups for q in g.known} | {ld.point for ld in lk.loads if ld.point}
    joints = (g.joint for g in lk.groups if g.joint)
    return tuple(
        name
        for name in dict.fromkeys((lk.joint, lk.output, *(p.name for p in lk.points), *joints))
        if name in (lk.joint, lk.output) or name not in centres or name in hung
    )


def traced_joints(lk: Linkage) -> tuple[str, ...]:
    """The groups' joints whose paths the mechanism's view draws (as a named point's): every
    numbered joint but the output, the crank's joint (its circle is drawn) and a slider's
    joint on the frame's guide (its path is the guide's axis, drawn with the guide)."""
    named = {p.name for p in lk.points}
    on_frame = {
        g.joint
        for g in lk.groups
        if g.kind == "PRP" or (g.kind == "RRP" and g.guide is not None and g.guide.fixed)
    }
    return tuple(
        n
        for n in numbered_tracks(lk)
        if n not in (lk.joint, lk.output) and n not in named and n not in on_frame
    )


#: The offset's arc runs this far (degrees) past the outermost feet of the slots.
OFFSET_ARC_PAST_DEG = 8.0


def _offset_arc(v: Viewport, g: Group, drawn: Sequence[Position]) -> None:
    """The circle of an RPR group's slot offset e round its pivot, which every position's slot
    touches at its foot, drawn thin over the feet of the positions ``drawn`` (the arc they
    span, a little past the outermost; the whole circle where the slot turns round)."""
    link = g.links[1]
    C = drawn[0].pos[g.pivot]
    feet = sorted(
        math.atan2(f.y, f.x) % (2.0 * math.pi)
        for f in (P.slide[link].perp() * g.offset for P in drawn)
    )
    gaps = [(b - a, a) for a, b in itertools.pairwise([*feet, feet[0] + 2.0 * math.pi])]
    gap, at = max(gaps)
    past = math.radians(OFFSET_ARC_PAST_DEG)
    if gap <= 2.0 * past:
        v.circle(C, abs(g.offset), "thin")
        return
    a0 = at + gap - past  # the arc runs from the far side of the largest gap round to its start
    sweep = 2.0 * math.pi - gap + 2.0 * past
    n = max(8, int(math.degrees(sweep) / 3.0))
    r = abs(g.offset)
    v.polyline(
        [C + Vec(math.cos(a0 + sweep * k / n), math.sin(a0 + sweep * k / n)) * r
         for k in range(n + 1)],
        "thin",
    )  # fmt: skip


#: The crank is drawn enlarged on a detail view of its own at once where the mechanism's scale
#: draws it shorter than this share of :data:`CRANK_MM` and no arrangement has room for the
#: mechanism at the crank's rule (:func:`_crank_may_keep`): the detail then shows it at least
#: twice as large. Otherwise the search seeks the rule at the mechanism's own scale first, the
#: detail being the last resort; beside its detail the mechanism keeps the scale it reached
#: without it (review 7: the oscillator's 1:2,5 became 1:4 beside its 1:1 detail).
DETAIL_BELOW = 0.5
#: The crank's detail: its box reaches this many crank lengths round the pivot …
DETAIL_REACH = 1.9
#: … its drawing this many, to the detail's circle (the crank circle, its numbers and ω1
#: inside it; the stubs of the links at the crank's joint end on it; review 7: the oscillator's
#: stubs ran 45 mm past the crank circle towards the plans, read as an unclipped drawing).
DETAIL_CIRCLE = 1.4
#: On the mechanism, the detail's circle round the crank: this much (mm) beyond the crank's
#: circle; its leader and shelf (mm).
DETAIL_RING_MM, DETAIL_LEADER_MM, DETAIL_SHELF_MM = 3.0, 6.0, 5.0
#: The detail's letter keeps this much (mm) from every line, circle, dot and text drawn before
#: it, its leader as long as one of these (mm) to find such a place.
LETTER_CLEAR_MM = 1.0
DETAIL_LEADERS = (DETAIL_LEADER_MM, 1.5 * DETAIL_LEADER_MM, 2.0 * DETAIL_LEADER_MM)


def detail_letter(s: Solved) -> str:
    """The letter of the crank's detail view: the first of the sheet's language's letters (the
    word table's ``detail_letters``; GOST 2.316-2008, 4.17: not Ё З Й О Ч Х Ъ Ы Ь) that neither
    is nor looks like (``detail_like``) the name of a point of the mechanism (Б where the
    crank's joint is A)."""
    names = {*s.linkage.frame, *s.drawn[0].pos}
    letters, like = WORDS("detail_letters"), WORDS("detail_like")
    return next(c for c, k in zip(letters, like, strict=True) if k not in names and c not in names)


def mark_detail(v: Viewport, pivot: Vec, r: float, letter: str) -> None:
    """The crank's detail marked on the mechanism (ESKD 2.305): a thin circle round the crank's
    circle (radius ``r`` about ``pivot``), a leader from it up and to the right to a shelf
    carrying the detail's ``letter``: the first of the diagonals (up and to the right first)
    and of the leader's lengths (:data:`DETAIL_LEADERS`) where the letter keeps
    :data:`LETTER_CLEAR_MM` from everything drawn before it (a line, a circle, a joint's dot,
    a text), else the one where the fewest are that near (review 7: the oscillator's coupler
    AB crossed its "Б"; review 8: its "Г" stood on the dot of Φ1's point)."""
    ring = v.mm(r) + DETAIL_RING_MM
    c = v.p(pivot)
    segments: list[tuple[tuple[float, float], tuple[float, float]]] = []
    boxes: list[Box] = []
    for it in v.sheet.items:
        if isinstance(it, Polyline):
            segments += itertools.pairwise((*it.points, *it.points[:1]) if it.closed else it.points)
        elif isinstance(it, CircleItem | ArcItem):
            if it.r <= 2.0 * LETTER_CLEAR_MM:  # a joint, a dot: its box
                boxes.append((it.c[0] - it.r, it.c[1] - it.r, it.c[0] + it.r, it.c[1] + it.r))
            else:  # a circle (an arc: its whole circle, to spare), as a polygon
                n = max(12, int(2.0 * math.pi * it.r / 2.0))
                ring_pts = [(it.c[0] + it.r * math.cos(2.0 * math.pi * k / n),
                             it.c[1] + it.r * math.sin(2.0 * math.pi * k / n))
                            for k in range(n + 1)]  # fmt: skip
                segments += itertools.pairwise(ring_pts)
        elif isinstance(it, TextItem) and not it.angle:
            boxes.append(_text_box(it))
    v.sheet.add(CircleItem(c, ring, "thin"))
    w = box(parse(letter), TITLE_H)[0]
    g = LETTER_CLEAR_MM
    best: tuple[int, tuple[tuple[float, float], ...], tuple[float, float]] | None = None
    for lead, deg in itertools.product(DETAIL_LEADERS, (45.0, 135.0, -45.0, -135.0)):
        u = (math.cos(math.radians(deg)), -math.sin(math.radians(deg)))
        a = (c[0] + u[0] * ring, c[1] + u[1] * ring)
        b = (a[0] + u[0] * lead, a[1] + u[1] * lead)
        e = (b[0] + math.copysign(DETAIL_SHELF_MM, u[0]), b[1])
        at = (min(b[0], e[0]) + 0.8, b[1] - 0.8)
        lbox = (at[0] - g, at[1] - TITLE_H - g, at[0] + w + g, at[1] + g)
        hits = sum(_segment_to_box(p, q, lbox) <= 0.0 for p, q in segments)
        hits += sum(_gap(lbox, o) <= 0.0 for o in boxes)
        if best is None or hits < best[0]:
            best = (hits, (a, b, e), at)
        if hits == 0:
            break
    assert best is not None
    v.sheet.add(Polyline(best[1], "thin"))
    text_at(v.sheet, letter, best[2], TITLE_H, role="label")


class _CrankDetail(View):
    """The crank in its numbered positions enlarged (ESKD 2.305's detail view, titled by its
    letter and its own μ_l): the crank's circle and its positions numbered, the crank in the
    principal position in main lines with its support, the others thin, the links at the
    crank's joint as stubs, ω1. Drawn where the long links set the mechanism's scale and leave
    the crank under :data:`CRANK_MM` there. ``only``: the crank in that one position alone,
    unnumbered, reaching ``reach`` crank lengths round the pivot (the forces sheet's detail)."""

    def __init__(
        self, s: Solved, letter: str, only: Position | None = None, reach: float = DETAIL_REACH
    ) -> None:
        super().__init__(
            title=WORDS("crank_detail", letter=letter, last=len(s.drawn) - 1), group="crank",
            title_height=5.0, margin=6.0, weight=0.5,
        )  # fmt: skip
        self.s = s
        self.letter = letter
        self.only = only
        lk = s.linkage
        #: how far (m) round the pivot the detail reaches
        self.reach = reach * lk.length
        O1, r = lk.frame[lk.pivot], self.reach
        self._ext = (O1.x - r, O1.y - r, O1.x + r, O1.y + r)

    def extent(self) -> tuple[float, float, float, float]:
        return self._ext

    def draw(self, d: Drawing, at: Placed) -> None:
        v = _under_title(d, at, self._ext)
        s = self.s
        lk = s.linkage
        O1 = lk.frame[lk.pivot]
        reach = min(self.reach, DETAIL_CIRCLE * lk.length)
        start = len(d.sheet.items)
        P0, k0 = _principal(s) if self.only is None else (self.only, 0)
        drawn = s.drawn if self.only is None else [self.only]
        v.circle(O1, lk.length, "centre")
        for i, P in enumerate(drawn):
            A = P.pos[lk.joint]
            role = "link" if i == k0 else "thin"
            v.seg(O1, A, role)
            # the links at the crank's joint, as far as the detail reaches
            for q in _neighbours(lk, P, lk.joint):
                u = (q - A).unit()
                t = _ray_to_circle(A - O1, u, reach)
                v.seg(A, A + u * t, role)
        if self.only is None:
            pts = [P.pos[lk.joint] for P in s.drawn]
            for q in pts:
                v.dot(q)
            position_numbers(v, pts, [P.vel[lk.joint] for P in s.drawn], O1)
        v.pivot(O1, _support_down(lk, P0))
        v.joint(P0.pos[lk.joint])
        v.label(O1, markup_of(lk.pivot), 3.5, clear=2.0)
        v.label(P0.pos[lk.joint], markup_of(lk.joint), 3.5, clear=2.0)
        v.label((O1 + P0.pos[lk.joint]) * 0.5, "1", 3.5, clear=1.0, space=LINK_SPACE)
        omega_arrow(v, lk, P0)
        # the detail's content ends at its circle (drawn thin where it shows the numbered
        # positions; the forces sheet's detail adds the crank's loads after it)
        sheet = d.sheet
        kept = clip_to_circle(sheet.items[start:], v.p(O1), v.mm(reach))
        gone = {id(it) for it in sheet.items[start:]} - {id(it) for it in kept}
        sheet.items[start:] = kept
        sheet.anchors = [(t, q) for t, q in sheet.anchors if id(t) not in gone]
        if self.only is None:
            v.circle(O1, reach, "thin")


def _neighbours(lk: Linkage, P: Position, joint: str) -> list[Vec]:
    """The points of position P that the links at ``joint`` (other than the crank) run to."""
    out: list[Vec] = []
    A = P.pos[joint]
    for link in lk.moving_links:
        names = list(lk.points_on(link))
        if joint not in names or link == 1:
            continue
        for n in names:
            q = P.pos[n]
            if n != joint and q.dist(A) > tol.DERIVED * max(1.0, A.norm):
                out.append(q)
                break
    return out


def _ray_to_circle(p: Vec, u: Vec, r: float) -> float:
    """How far along the unit ``u`` from ``p`` (relative to the circle's centre) the circle of
    radius ``r`` is (0 where ``p`` lies outside it)."""
    b = p.dot(u)
    c = p.dot(p) - r * r
    disc = b * b - c
    return max(0.0, -b + math.sqrt(disc)) if disc >= 0.0 else 0.0


def _support_down(lk: Linkage, P: Position) -> tuple[float, float]:
    """The crank's support on the detail: pointing away from the crank (down where it leaves
    room)."""
    a = P.pos[lk.joint] - lk.frame[lk.pivot]
    return (0.0, -1.0) if a.y >= -0.5 * a.norm else (0.0, 1.0)


#: A position of one point that falls within this (mm on the drawing) of the same position of a
#: point numbered before is numbered once (a scotch yoke's slider at the crank's extremes).
SHARE_MM = 2.5
#: Two position numbers stand at least this far apart (mm): nearer, "4 3" or "6 7 5 8" read as
#: one number (review 12: the sewing machine's E and M, the yarn traverse's E at 0.8–1.2 mm).
NUMBER_APART_MM = 1.5
#: The numbers of the positions are written this high (mm; GOST 2.304's least) and kept this
#: much further than other labels from each other (mm), so that two numbers never read as one.
NUMBER_H = 2.5
NUMBER_SPACE = NUMBER_APART_MM
#: The links' numbers (3.5 mm) keep this much further (mm) from other texts, so that a link's
#: number never reads as a position's.
LINK_SPACE = 2.6
#: Positions of one point on one side of its path nearer each other than this (mm) are a crowd:
#: their numbers cannot each stand beside their own point, so they stand in a row off the path,
#: each joined to its point by a leader.
CROWD_MM = 5.0
#: A row's numbers stand this far (mm) off the outermost point of their crowd, this far apart
#: (NUMBER_APART_MM, and a little for the font's side bearings measured in their boxes).
ROW_OFF_MM, ROW_GAP_MM = 2.2, NUMBER_APART_MM + 0.1
#: A crowd's row stands at least this share of its numbers' largest shift along it off the
#: crowd, so that no leader runs flatter than about 55° to the row.
ROW_STEEP = 0.7
#: A row's number that a drawn line crosses moves out from its row in steps of this much (mm),
#: at most this many, to the first place no line crosses (joined to its point by a leader); a
#: line within INK_GROW_MM of a number's box crosses it.
ROW_STEP_MM, ROW_STEPS, INK_GROW_MM = 0.8, 16, 0.3
#: The moves a row's number may make (outward, along the row; in ROW_STEP_MM), nearest first.
_ROW_MOVES = sorted(
    ((o, a) for o in range(ROW_STEPS + 1) for a in range(-6, 7)),
    key=lambda m: (math.hypot(m[0], 1.5 * m[1]), abs(m[1]), m[1]),
)
#: A number shifted along its row more than this (mm) from straight across its point gets a
#: leader even off a crowd (a slider's number beyond its hatched guide).
ROW_SHIFT_MM = 0.8
#: A leader starts this far (mm) from its point (clear of the dot) and stops this far short of
#: its number's box.
LEADER_FROM_MM, LEADER_TO_MM = 0.6, 0.4

Box = tuple[float, float, float, float]
#: The room (mm) a slider's numbers keep from its path: its hatched guide (GOST 2.770) on either
#: side of the block.
GUIDE_CLEAR_MM = SLIDER_SIZE[1] / 2.0 + 0.6 + HATCH_LEN + 0.3


def _in_block(q: tuple[float, float], c: tuple[float, float], u: tuple[float, float]) -> bool:
    """Whether the paper point ``q`` falls inside a slider block drawn at ``c`` along ``u``
    (:data:`~geomcad.sheet.symbols.SLIDER_SIZE`): a mark there would be hidden in the block."""
    dx, dy = q[0] - c[0], q[1] - c[1]
    a = abs(dx * u[0] + dy * u[1])
    b = abs(-dx * u[1] + dy * u[0])
    return a <= SLIDER_SIZE[0] / 2.0 and b <= SLIDER_SIZE[1] / 2.0


def position_numbers(
    v: Viewport,
    pts: Sequence[Vec],
    vels: Sequence[Vec],
    pivot: Vec,
    numbered: Sequence[Vec] = (),
    clear: float = 0.0,
    taken: list[Box] | None = None,
) -> None:
    """Number the positions ``pts`` of one point on its path (``vels``: its velocities there),
    as a drawing of the mechanism in its positions does: the point's letter stands once (at the
    principal position, by the scheme), each position gets its own number next to its point.

    A number is set off the path across it: on the outer side (away from the centre of the
    circle through the positions; on a line, away from the crank's ``pivot``) where the point
    runs one way round, on the inner side where it runs back (a rocker's or a slider's return
    stroke), so that a position of the return stroke that falls on one of the working stroke is
    numbered on the other side. A number standing alone is placed by the sheet's label placer
    clear of the lines and the other labels. Positions on one side nearer each other than
    :data:`CROWD_MM` are a crowd (a slider near its dead point, a rocker at its extreme): their
    numbers stand in a row off the crowd, in the order of their points along it, each joined to
    its point by a thin leader, never a shared "4–8". ``clear`` (mm): room the numbers keep from
    the path (a slider's hatched guide): every number then stands in its side's row beyond it.
    ``taken``: the boxes (paper mm) of the rows numbered before in this view, pushed clear of.
    ``numbered``: the same positions of a point numbered before; where this point's position
    falls on that one's (a scotch yoke's slider at the crank's extremes), its number stands
    once."""
    keep = [
        i
        for i, q in enumerate(pts)
        if not (i < len(numbered) and v.mm((q - numbered[i]).norm) < SHARE_MM)
    ]
    if not keep:
        return
    centre = _centre_of(pts)
    line_n = Vec(0.0, 0.0)
    if centre is None:  # along a line: across it, on the side away from the pivot
        t = max((q - pts[0] for q in pts), key=lambda d: d.norm)
        line_n = Vec(-t.y, t.x)
        if line_n.x * (pts[0].x - pivot.x) + line_n.y * (pts[0].y - pivot.y) < 0.0:
            line_n = Vec(t.y, -t.x)
    normal: dict[int, Vec] = {}
    runs: dict[int, float] = {}
    for i in keep:
        n = line_n if centre is None else pts[i] - centre
        t = Vec(-n.y, n.x)  # counter-clockwise round the centre
        normal[i] = n.unit() if n.norm > 0.0 else n
        runs[i] = vels[i].x * t.x + vels[i].y * t.y
    # the sense most positions run in (a crank's whole turn, a rocker's working stroke) outside
    ahead = sum(math.copysign(1.0, r) for r in runs.values() if r) >= 0.0
    out: dict[int, tuple[float, float]] = {}  # each number's side, a paper direction
    for i in keep:
        side = -1.0 if runs[i] and (runs[i] > 0.0) != ahead else 1.0
        out[i] = v.paper_dir(normal[i] * side)
    paper = {i: v.p(pts[i]) for i in keep}
    # the crowds: positions within CROWD_MM of each other (single linkage); on a slider's
    # guide (``clear``), each stroke's positions a row on its own side
    crowd = {i: i for i in keep}

    def root(i: int) -> int:
        while crowd[i] != i:
            i = crowd[i]
        return i

    for a, b in itertools.combinations(keep, 2):
        if clear > 0.0:
            near = out[a][0] * out[b][0] + out[a][1] * out[b][1] > 0.0
        else:
            near = math.dist(paper[a], paper[b]) < CROWD_MM
        if near:
            crowd[root(b)] = root(a)
    members: dict[int, list[int]] = {}
    for i in keep:
        members.setdefault(root(i), []).append(i)
    held = taken if taken is not None else []
    for g in members.values():
        if clear <= 0.0 and len(g) == 1:
            i = g[0]
            v.label(pts[i], str(i), NUMBER_H, prefer=(out[i][0], -out[i][1]), clear=1.0,
                    space=NUMBER_SPACE)  # fmt: skip
            continue
        # the row's side: the crowd's mean side of its path, else the other where fewer lines
        # cross it (a crowd at a rocker's extreme, its links on one side)
        sx, sy = sum(out[i][0] for i in g), sum(out[i][1] for i in g)
        if math.hypot(sx, sy) < 0.5 * len(g):  # both strokes: the path's outer side
            o = v.paper_dir(normal[g[0]])
            sx, sy = o[0], o[1]
        ln = math.hypot(sx, sy) or 1.0
        mean = (sx / ln, sy / ln)
        sides = [mean] if clear > 0.0 else [mean, (-mean[0], -mean[1])]
        _number_row(v, g, paper, sides, clear, held, leaders=clear <= 0.0)


def _number_row(
    v: Viewport,
    g: Sequence[int],
    paper: Mapping[int, tuple[float, float]],
    sides: Sequence[tuple[float, float]],
    clear: float,
    taken: list[Box],
    leaders: bool,
) -> None:
    """The numbers of the positions ``g`` in a row off their points (paper ``paper``): the row
    runs across the first of the paper directions ``sides`` that crosses the fewest drawn lines
    (a crowd's two sides of its path), :data:`ROW_OFF_MM` beyond its outermost point (and
    ``clear``), each number as near straight across its point as the numbers' widths let it,
    pushed out past the rows ``taken``; a number a drawn line crosses moved to the nearest place
    no line crosses (:data:`_ROW_MOVES`); a number joined to its point by a leader where the row
    is a crowd's (``leaders``), or it was moved, or it stands shifted along the row."""
    ink = _Ink(v.sheet)
    best: tuple[float, dict[int, Box], dict[int, float], tuple[float, float]] | None = None
    for k, n in enumerate(sides):
        boxes, shifts = _row_boxes(g, paper, n, clear, taken)
        cost = ink.crossed(list(boxes.values())) + 0.5 * k
        if best is None or cost < best[0]:
            best = cost, boxes, shifts, n
    assert best is not None
    _, boxes, shifts, n = best
    sheet = v.sheet
    leads: list[tuple[tuple[float, float], tuple[float, float]]] = []  # (point, number) drawn
    for i in g:
        # a number a line crosses moves to the nearest place no line crosses: further out and
        # a little along its row (never onto a number); else it stays where fewest cross it
        b = boxes[i]
        best_at: tuple[int, float, Box] | None = None
        for out_k, along_k in _ROW_MOVES:
            dx = n[0] * out_k * ROW_STEP_MM - n[1] * along_k * ROW_STEP_MM
            dy = n[1] * out_k * ROW_STEP_MM + n[0] * along_k * ROW_STEP_MM
            cand = (b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy)
            if any(_overlaps(cand, o) for o in taken):
                continue
            # its leader never runs through a number set before (review 12: the bloom shear's
            # S5, position 9's leader through position 3's number)
            if _through_text(paper[i], cand, taken):
                continue
            # nor across the leader of a number set before from another point (review 12: the
            # bloom shear's S5, the leaders of 10 and 2 crossed under D; two leaders from points
            # nearer than LEADER_FROM_MM start off them at one place and part, never cross)
            led = leaders or out_k or along_k or shifts[i] > ROW_SHIFT_MM
            mid = ((cand[0] + cand[2]) / 2.0, (cand[1] + cand[3]) / 2.0)
            if led and any(
                math.dist(p, paper[i]) > LEADER_FROM_MM and _cross(p, c, paper[i], mid)
                for p, c in leads
            ):
                continue
            hits = ink.crossed([cand])
            if best_at is None or hits < best_at[0]:
                best_at = hits, math.hypot(out_k, along_k), cand
            if not hits:
                break
        moved = best_at is not None and best_at[1] > 0.0
        if best_at is not None:
            boxes[i] = best_at[2]
        up = box(parse(str(i)), NUMBER_H)[1]
        text_at(sheet, str(i), (boxes[i][0], boxes[i][1] + up), NUMBER_H, role="label")
        taken.append(boxes[i])
        if leaders or moved or shifts[i] > ROW_SHIFT_MM:
            drawn = len(sheet.items)
            _leader(sheet, paper[i], boxes[i])
            ink.add(sheet.items[drawn:])  # the next numbers keep off it too
            leads.append((paper[i], ((boxes[i][0] + boxes[i][2]) / 2.0,
                                     (boxes[i][1] + boxes[i][3]) / 2.0)))  # fmt: skip


def _row_boxes(
    g: Sequence[int],
    paper: Mapping[int, tuple[float, float]],
    n: tuple[float, float],
    clear: float,
    taken: Sequence[Box],
) -> tuple[dict[int, Box], dict[int, float]]:
    """The boxes of a row of the numbers of ``g`` on the side ``n`` (a paper unit vector) of
    their points, and how far (mm) each stands shifted along the row from straight across its
    point."""
    t = (-n[1], n[0])
    sizes = {i: box(parse(str(i)), NUMBER_H) for i in g}
    along = {i: abs(t[0]) * sizes[i][0] + abs(t[1]) * (sizes[i][1] + sizes[i][2]) for i in g}
    across = {i: abs(n[0]) * sizes[i][0] + abs(n[1]) * (sizes[i][1] + sizes[i][2]) for i in g}
    order = sorted(g, key=lambda i: paper[i][0] * t[0] + paper[i][1] * t[1])
    want = [paper[i][0] * t[0] + paper[i][1] * t[1] for i in order]
    # the numbers' centres along the row: as near their points as their widths allow (runs of
    # touching numbers centred on their points' mean)
    runs_: list[list[int]] = []
    for k in range(len(order)):
        runs_.append([k])
        while len(runs_) > 1:
            a, b = runs_[-2], runs_[-1]
            ca, cb = _run_at(a, order, want, along), _run_at(b, order, want, along)
            end_a = ca + sum(along[order[k2]] + ROW_GAP_MM for k2 in a) - ROW_GAP_MM
            if end_a + ROW_GAP_MM <= cb:
                break
            runs_[-2:] = [a + b]
    at: dict[int, float] = {}
    for r in runs_:
        x = _run_at(r, order, want, along)
        for k in r:
            i = order[k]
            at[i] = x + along[i] / 2.0
            x += along[i] + ROW_GAP_MM
    shifts = {i: abs(at[i] - (paper[i][0] * t[0] + paper[i][1] * t[1])) for i in g}
    # far enough out that the leaders to the numbers shifted most stay steep (a leader run
    # nearly along the row would pass under its neighbours)
    off = max(ROW_OFF_MM, ROW_STEEP * max(shifts.values())) if len(g) > 1 else ROW_OFF_MM
    depth = max(paper[i][0] * n[0] + paper[i][1] * n[1] for i in g) + off + clear
    for _ in range(12):  # out past the rows numbered before
        boxes = {i: _row_box(t, n, at[i], depth, sizes[i], across[i]) for i in g}
        if not any(_overlaps(b, o) for b in boxes.values() for o in taken):
            break
        depth += NUMBER_H
    return boxes, shifts


class _Ink:
    """The lines drawn on a sheet so far as paper segments (polylines by their sides, circles
    and arcs by chords), for counting the lines that cross a number's box; ``roles``: only
    the lines of those roles."""

    def __init__(self, sheet: Sheet, roles: Collection[str] = ()) -> None:
        self.roles = roles
        self.segs = self._segments(sheet.items)

    def add(self, items: Sequence[object]) -> None:
        """The lines of ``items`` (drawn since) added."""
        self.segs = np.concatenate([self.segs, self._segments(items)])

    def _segments(self, items: Sequence[object]) -> np.ndarray:
        segs: list[tuple[float, float, float, float]] = []
        for it in items:
            if self.roles and getattr(it, "role", None) not in self.roles:
                continue
            if isinstance(it, Polyline):
                pts = (*it.points, *it.points[:1]) if it.closed else it.points
                segs += [(*a, *b) for a, b in itertools.pairwise(pts)]
            elif isinstance(it, CircleItem | ArcItem):
                a0, sweep = 0.0, 2.0 * math.pi
                if isinstance(it, ArcItem):
                    a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
                    sweep = it.sweep
                m = max(8, int(abs(sweep) * it.r) + 1)
                ts = [a0 + sweep * k / m for k in range(m + 1)]
                ring = [(it.c[0] + it.r * math.cos(t), it.c[1] + it.r * math.sin(t)) for t in ts]
                segs += [(*a, *b) for a, b in itertools.pairwise(ring)]
        return np.asarray(segs, dtype=float).reshape(-1, 4)

    def crossed(self, boxes: Sequence[Box], grow: float = INK_GROW_MM) -> int:
        """How many segments cross the ``boxes`` (paper mm, each grown by ``grow``), all told
        (Liang–Barsky's clipping of every segment against each box)."""
        if not len(self.segs) or not boxes:
            return 0
        x0, y0, x1, y1 = self.segs.T
        dx, dy = x1 - x0, y1 - y0
        total = 0
        for bx0, by0, bx1, by1 in boxes:
            bx0, by0, bx1, by1 = bx0 - grow, by0 - grow, bx1 + grow, by1 + grow
            near = (np.minimum(x0, x1) <= bx1) & (np.maximum(x0, x1) >= bx0)
            near &= (np.minimum(y0, y1) <= by1) & (np.maximum(y0, y1) >= by0)
            if not near.any():
                continue
            px, py, qx, qy = x0[near], y0[near], dx[near], dy[near]
            lo, hi = np.zeros_like(px), np.ones_like(px)
            ok = np.ones_like(px, dtype=bool)
            for pp, qq in ((-qx, px - bx0), (qx, bx1 - px), (-qy, py - by0), (qy, by1 - py)):
                par = pp == 0.0
                ok &= ~(par & (qq < 0.0))
                r = np.where(par, 0.0, qq / np.where(par, 1.0, pp))
                lo = np.where(~par & (pp < 0.0), np.maximum(lo, r), lo)
                hi = np.where(~par & (pp > 0.0), np.minimum(hi, r), hi)
            total += int(np.count_nonzero(ok & (lo <= hi)))
        return total


def _run_at(
    r: Sequence[int], order: Sequence[int], want: Sequence[float], along: Mapping[int, float]
) -> float:
    """Where a run of touching numbers starts along the row: its numbers' centres as near, on
    the mean, as they can be to their points."""
    x, offs = 0.0, []
    for k in r:
        offs.append(x + along[order[k]] / 2.0)
        x += along[order[k]] + ROW_GAP_MM
    return sum(want[k] - o for k, o in zip(r, offs, strict=True)) / len(r)


def _row_box(
    t: tuple[float, float],
    n: tuple[float, float],
    s: float,
    depth: float,
    size: tuple[float, float, float],
    across: float,
) -> Box:
    """The paper box of a number centred ``s`` along the row's direction ``t`` and with its
    near side ``depth`` along ``n``."""
    c = depth + across / 2.0
    cx, cy = t[0] * s + n[0] * c, t[1] * s + n[1] * c
    w, h = size[0], size[1] + size[2]
    return (cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0)


def _overlaps(a: Box, b: Box) -> bool:
    g = NUMBER_SPACE
    return a[0] < b[2] + g and b[0] < a[2] + g and a[1] < b[3] + g and b[1] < a[3] + g


#: A link's number (3.5 mm) keeps at least this much (mm) from every position's number, so
#: that the two never read as one ("5" beside B's "10 3 11 4"); moved round its point in
#: steps of LINK_STEP_MM up to LINK_REACH_MM, with a leader where it stands further than
#: LINK_LEADER_MM from its point.
LINK_CLEAR_MM, LINK_STEP_MM, LINK_REACH_MM, LINK_LEADER_MM = 5.0, 0.5, 20.0, 5.0
#: Texts side by side read as one line: a link's number keeps LINK_CLEAR_MM times this from a
#: position's number beside it in its line (a row of numbers is read along).
LINK_ALONG = 3.0
#: A link's number keeps this much (mm) from a position's number of the same digits (whitworth's
#: link "3" once stood among position 3's "3" at A and at B: three "3"s, one of them the link's).
LINK_SAME_MM = 15.0
#: A link's number looks this far (mm) for a place that keeps those rules too (a point's letter
#: only LINK_REACH_MM: it names the point it stands by).
LINK_NUMBER_REACH_MM = 30.0
#: The directions tried round the point, every 10°.
_LINK_DIRS = [(math.cos(math.radians(a)), math.sin(math.radians(a))) for a in range(0, 360, 10)]


def _text_box(t: TextItem) -> Box:
    return (t.at[0], t.at[1] - t.height, t.at[0] + t.width, t.at[1] + 0.3 * t.height)


def _gap(a: Box, b: Box, along: float = 1.0) -> float:
    """The distance (mm) between two boxes (0 where they overlap), their horizontal distance
    divided by ``along``."""
    dx, dy = max(a[0] - b[2], b[0] - a[2], 0.0), max(a[1] - b[3], b[1] - a[3], 0.0)
    return math.hypot(dx / along, dy)


def _apart(a: Box, b: Box) -> float:
    """How far (mm) a link's number ``a`` stands from a position's number ``b`` as read: in
    a row of numbers (beside it) or a column of them (over it, along a vertical guide), its
    distance along that line counts :data:`LINK_ALONG` times less."""
    return min(_gap(a, b, LINK_ALONG), _gap((a[1], a[0], a[3], a[2]), (b[1], b[0], b[3], b[2]),
                                            LINK_ALONG))  # fmt: skip


def _through_text(p: tuple[float, float], b: Box, boxes: Sequence[Box]) -> bool:
    """Whether the line from ``p`` to the middle of ``b`` runs through one of ``boxes``
    (grown by :data:`INK_GROW_MM`; sampled every :data:`LINK_STEP_MM` / 2)."""
    cx, cy = (b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0
    n = max(2, int(math.dist(p, (cx, cy)) / (LINK_STEP_MM / 2.0)))
    g = INK_GROW_MM
    for k in range(1, n):
        x, y = p[0] + (cx - p[0]) * k / n, p[1] + (cy - p[1]) * k / n
        if any(o[0] - g <= x <= o[2] + g and o[1] - g <= y <= o[3] + g for o in boxes):
            return True
    return False


#: Beyond this distance (mm) from every place a label may move to, a text box neither stands
#: too near it (:data:`NUMBER_SPACE`) nor lies on its leader (:data:`INK_GROW_MM`).
_NEAR_MM = NUMBER_SPACE + 2.0 * INK_GROW_MM + 1.0


def _reach(p: tuple[float, float], r: float, w: float, h: float) -> Box:
    """A box (mm) holding every ``w`` × ``h`` place round ``p`` up to ``r`` from it (as the
    searches below try them; 1 mm to spare), and ``p``."""
    return (p[0] - r - w - 1.0, p[1] - r - h - 1.0, p[0] + r + w + 1.0, p[1] + r + h + 1.0)


def _segment_to_box(a: tuple[float, float], b: tuple[float, float], x: Box) -> float:
    """The distance (mm) from the segment ``a``–``b`` to the box ``x`` (0 where they meet)."""
    corners = ((x[0], x[1]), (x[2], x[1]), (x[2], x[3]), (x[0], x[3]))
    edges = list(itertools.pairwise((*corners, corners[0])))
    if _to_box(a, x) == 0.0 or any(_cross(a, b, c, d) for c, d in edges):
        return 0.0
    return min(_to_box(a, x), _to_box(b, x), *(_to_segment(c, a, b) for c in corners))


def _cross(
    a: tuple[float, float], b: tuple[float, float], c: tuple[float, float], d: tuple[float, float]
) -> bool:
    """Whether the segments a–b and c–d cross."""

    def side(p: tuple[float, float], q: tuple[float, float], r: tuple[float, float]) -> float:
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    return side(a, b, c) * side(a, b, d) <= 0.0 and side(c, d, a) * side(c, d, b) <= 0.0


def _to_segment(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """The distance from the point ``p`` to the segment ``a``–``b`` (in their units: mm on the
    paper, model units for a link's outline)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = dx * dx + dy * dy
    t = 0.0 if n == 0.0 else min(1.0, max(0.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / n))
    return math.dist(p, (a[0] + t * dx, a[1] + t * dy))


def _leader_off(
    p: tuple[float, float], q: tuple[float, float], boxes: Sequence[Box], enough: float
) -> float:
    """How near (mm) the segment ``p``–``q`` comes to the ``boxes``; any figure below
    ``enough`` as soon as one is found (the caller asks only whether it is that near)."""
    env = (min(p[0], q[0]), min(p[1], q[1]), max(p[0], q[0]), max(p[1], q[1]))
    out = math.inf
    for n in boxes:
        if _gap(env, n) >= out:
            continue
        out = min(out, _segment_to_box(p, q, n))
        if out < enough:
            break
    return out


#: Within this (mm) of a rule's limit the array test below is not trusted: the exact one decides.
_HAIR_MM = tol.SHEET_MM


def _tried_places(
    p: tuple[float, float], steps: int, w: float, h: float
) -> tuple[np.ndarray, np.ndarray]:
    """Every ``w`` × ``h`` place round ``p`` in the order the searches below try them (step by
    step of :data:`LINK_STEP_MM`, direction by direction of :data:`_LINK_DIRS`): their
    distances from ``p`` and their boxes (K × 4, paper mm)."""
    rs = np.repeat(np.arange(1, steps + 1) * LINK_STEP_MM, len(_LINK_DIRS))
    us = np.tile(np.asarray(_LINK_DIRS), (steps, 1))
    cxs, cys = p[0] + us[:, 0] * (rs + w / 2.0), p[1] + us[:, 1] * (rs + h / 2.0)
    return rs, np.stack([cxs - w / 2.0, cys - h / 2.0, cxs + w / 2.0, cys + h / 2.0], axis=1)


def _box_gaps(cs: np.ndarray, boxes: np.ndarray, along: float = 1.0) -> np.ndarray:
    """:func:`_gap` of each of the boxes ``cs`` (K × 4) to each of ``boxes`` (N × 4): K × N."""
    a = cs[:, None, :]
    dx = np.maximum(np.maximum(a[..., 0] - boxes[:, 2], boxes[:, 0] - a[..., 2]), 0.0)
    dy = np.maximum(np.maximum(a[..., 1] - boxes[:, 3], boxes[:, 1] - a[..., 3]), 0.0)
    out: np.ndarray = np.hypot(dx / along, dy)
    return out


def _too_near(
    cs: np.ndarray, boxes: Sequence[Box], limit: float, read: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """For each of the candidate boxes ``cs`` (K × 4, paper mm): whether it surely stands nearer
    than ``limit`` to one of ``boxes`` (:func:`_gap`, or :func:`_apart` where ``read``), and
    whether it may (within :data:`_HAIR_MM` of the limit: the caller asks the exact test). All
    K × len(``boxes``) distances at once, for the place searches below."""
    if not boxes:
        return np.zeros(len(cs), dtype=bool), np.zeros(len(cs), dtype=bool)
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    d = _box_gaps(cs, b)
    if read:  # _apart: along a row, or along a column (the boxes' axes swapped)
        d = np.minimum(
            _box_gaps(cs, b, LINK_ALONG),
            _box_gaps(cs[:, [1, 0, 3, 2]], b[:, [1, 0, 3, 2]], LINK_ALONG),
        )
    sure = np.asarray((d < limit - _HAIR_MM).any(axis=1))
    return sure, np.asarray(~sure & (np.abs(d - limit) <= _HAIR_MM).any(axis=1))


def keep_link_numbers_clear(sheet: Sheet, area: Box) -> None:
    """Each point's letter a thin position's line runs through (the crank's pivot among its
    twelve positions), and each link's number (a label of digits higher than
    :data:`NUMBER_H`) that stands nearer than :data:`LINK_CLEAR_MM` to a position's number
    (:data:`NUMBER_H` high; :data:`LINK_ALONG` times that beside it in its line), in ``area``
    (a view's box on the finished sheet), moves to the nearest place round the point it names
    that keeps that much from every number, clear of every other text and of every drawn
    line; a leader joins it to its point where it stands further than :data:`LINK_LEADER_MM`
    from it. Where no place within :data:`LINK_REACH_MM` does, it stays.

    A link's number also keeps :data:`LINK_SAME_MM` from a position's number of the same
    digits, and its leader keeps :data:`LINK_CLEAR_MM` from every position's number (a leader
    run among a row of numbers reads as one of theirs: the shaper's "5" once ran among B's)."""

    def inside(t: TextItem) -> bool:
        return area[0] <= t.at[0] <= area[2] and area[1] <= t.at[1] <= area[3]

    texts = [t for t in sheet.texts() if inside(t)]
    digits = [(t.text, _text_box(t)) for t in texts
              if t.role == "label" and t.text.isdigit() and t.height == NUMBER_H]  # fmt: skip
    numbers = [n for _, n in digits]
    anchors = {id(item): at for item, at in sheet.anchors}
    ink, thin = _Ink(sheet), _Ink(sheet, ("thin",))
    current = {id(o): _text_box(o) for o in texts}  # the boxes as moved so far
    for t in texts:
        if t.role != "label" or t.height <= NUMBER_H or id(t) not in anchors:
            continue
        b = _text_box(t)
        same = [n for txt, n in digits if txt == t.text]
        if t.text.isdigit():
            if all(_apart(b, n) >= LINK_CLEAR_MM for n in numbers) and all(
                _gap(b, n) >= LINK_SAME_MM for n in same
            ):
                continue
        elif not ("A" <= t.text[:1] <= "Z" and thin.crossed([b], 0.0)):
            continue  # a point's letter moves only where a thin position's line runs through it
        p = anchors[id(t)]
        w, h = b[2] - b[0], b[3] - b[1]
        reach = LINK_NUMBER_REACH_MM if t.text.isdigit() else LINK_REACH_MM
        r, steps = 0.0, round(reach / LINK_STEP_MM)
        # only the boxes near the places tried can refuse one (the rest, asked of each of
        # them, cost the sheet a tenth of a second)
        env = _reach(p, steps * LINK_STEP_MM, w, h)
        others = [bx for k, bx in current.items() if k != id(t) and _gap(env, bx) < _NEAR_MM]
        near = [n for n in numbers if _apart(env, n) < LINK_CLEAR_MM + 1.0]
        same = [n for n in same if _gap(env, n) < LINK_SAME_MM + 1.0] if t.text.isdigit() else []
        # the numbers its leader keeps clear of: near enough to matter, but not those at its
        # point itself (every leader starts there)
        lead = [n for n in numbers if LINK_CLEAR_MM <= _to_box(p, n) <
                steps * LINK_STEP_MM + w + h + LINK_CLEAR_MM]  # fmt: skip
        found: Box | None = None
        # the places that keep every rule first; then, where the number stands too near a
        # position's number as it is, those that let its leader pass nearer, then those that
        # stand nearer a number of its own digits (the rules of before)
        tiers = [(True, True)]
        if any(_apart(b, n) < LINK_CLEAR_MM for n in numbers) and t.text.isdigit():
            tiers += [(True, False), (False, False)]
        r_found = 0.0
        # every place tried, in the order tried (step by step, direction by direction), with the
        # rules of fixed boxes asked of all at once; the exact test only within a hair of a limit
        rs, cs = _tried_places(p, steps, w, h)
        inside_area = (area[0] <= cs[:, 0]) & (cs[:, 2] <= area[2])
        inside_area &= (area[1] <= cs[:, 1]) & (cs[:, 3] <= area[3])
        out_near, ask_near = _too_near(cs, near, LINK_CLEAR_MM, read=True)
        out_same, ask_same = _too_near(cs, same, LINK_SAME_MM)
        out_other, ask_other = _too_near(cs, others, NUMBER_SPACE)
        maybe = inside_area & ~out_near & ~out_other
        for keep_same, keep_lead in tiers:
            best = -1.0  # a relaxed tier: the place whose leader stands clearest of the numbers
            ok = maybe & ~out_same if keep_same else maybe
            for i in np.flatnonzero(ok).tolist():
                r = float(rs[i])
                ux, uy = _LINK_DIRS[i % len(_LINK_DIRS)]
                cx, cy = p[0] + ux * (r + w / 2.0), p[1] + uy * (r + h / 2.0)
                c = (cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0)
                if ask_near[i] and any(_apart(c, n) < LINK_CLEAR_MM for n in near):
                    continue
                if keep_same and ask_same[i] and any(_gap(c, n) < LINK_SAME_MM for n in same):
                    continue
                if ask_other[i] and any(_gap(c, o) < NUMBER_SPACE for o in others):
                    continue
                off = math.inf
                # what its leader must keep: LINK_CLEAR_MM, or (relaxed) more than the best
                need = LINK_CLEAR_MM if keep_lead else best + tol.SHEET_MM
                if r > LINK_LEADER_MM and t.text.isdigit():
                    mid = ((c[0] + c[2]) / 2.0, (c[1] + c[3]) / 2.0)
                    off = _leader_off(p, mid, lead, need)
                if off < need or (not keep_lead and off == need):
                    continue  # its leader would run among the positions' numbers
                if ink.crossed([c]):
                    continue
                if r > LINK_LEADER_MM and _through_text(p, c, others):
                    continue  # its leader would run through another text
                found, r_found, best = c, r, off
                if keep_lead:
                    break
            if found is not None:
                break
        if found is None:
            continue
        current[id(t)] = found
        _move_number(sheet, ink, t, found, p, r_found)


#: A position's number stands at least this much (mm) nearer its own point than any point or
#: number of another track (S3's "9" beside the crank circle's "9" reads as either); else it
#: moves round its point, as a link's number does (LINK_STEP_MM up to TRACK_REACH_MM).
TRACK_MARGIN_MM, TRACK_REACH_MM = 1.5, 12.0


def _to_box(p: tuple[float, float], b: Box) -> float:
    """The distance (mm) from the point ``p`` to the box ``b`` (0 inside it)."""
    return math.hypot(max(b[0] - p[0], p[0] - b[2], 0.0), max(b[1] - p[1], p[1] - b[3], 0.0))


def keep_tracks_apart(
    sheet: Sheet,
    area: Box,
    tracks: Mapping[str, Sequence[tuple[float, float]]],
    rows: Mapping[str, Sequence[Box]],
) -> None:
    """Each position's number in ``area`` (a view's box on the finished sheet) that stands
    nearer than :data:`TRACK_MARGIN_MM` beyond its own point to a point or a number of another
    of the ``tracks`` (each track's numbered points, paper mm) moves to the nearest place round
    its point where it does not, clear of every other text and of every drawn line, with a
    leader where it stands further than :data:`LINK_LEADER_MM` from its point: the numbers of
    two paths never interleave (a rocker's centre of mass numbered among the crank circle's
    numbers). ``rows``: each track's numbers set in rows (their boxes), which stay where they
    are. Where no place within :data:`TRACK_REACH_MM` does, it stays."""

    def track_of(p: tuple[float, float]) -> str | None:
        near = (k for k, pts in tracks.items() if any(math.dist(p, q) < tol.SHEET_MM for q in pts))
        return next(near, None)

    def inside(t: TextItem) -> bool:
        return area[0] <= t.at[0] <= area[2] and area[1] <= t.at[1] <= area[3]

    anchors = {id(item): at for item, at in sheet.anchors}
    texts = [t for t in sheet.texts() if inside(t)]
    numbers = [t for t in texts if t.role == "label" and t.text.isdigit()
               and t.height == NUMBER_H and id(t) in anchors]  # fmt: skip
    owner = {id(t): track_of(anchors[id(t)]) for t in numbers}
    current = {id(o): _text_box(o) for o in texts}
    ink = _Ink(sheet)
    for t in numbers:
        name = owner[id(t)]
        if name is None:
            continue
        p = anchors[id(t)]
        foreign_pts = [q for k, pts in tracks.items() if k != name for q in pts
                       if math.dist(q, p) >= SHARE_MM]  # fmt: skip
        foreign = [id(o) for o in numbers if owner[id(o)] not in (None, name)]
        foreign_rows = [b for k, bs in rows.items() if k != name for b in bs]

        def confused(
            c: Box,
            p: tuple[float, float] = p,
            pts: Sequence[tuple[float, float]] = foreign_pts,
            nums: Sequence[int] = foreign,
            boxes: Sequence[Box] = foreign_rows,
        ) -> bool:
            near = min(
                (
                    *(_to_box(q, c) for q in pts),
                    *(_gap(c, current[k]) for k in nums),
                    *(_gap(c, b) for b in boxes),
                ),
                default=math.inf,
            )
            return near < _to_box(p, c) + TRACK_MARGIN_MM

        b = current[id(t)]
        if not confused(b):
            continue
        w, h = b[2] - b[0], b[3] - b[1]
        steps = round(TRACK_REACH_MM / LINK_STEP_MM)
        # only what stands near the places tried can confuse one or refuse it: a point, a
        # number or a row further from all of them than any is from ``p`` never does
        env = _reach(p, steps * LINK_STEP_MM, w, h)
        far = math.hypot(env[2] - env[0], env[3] - env[1]) + TRACK_MARGIN_MM + 1.0
        pts_near = [q for q in foreign_pts if _to_box(q, env) < far]
        nums_near = [k for k in foreign if _gap(env, current[k]) < far]
        rows_near = [bx for bx in foreign_rows if _gap(env, bx) < far]
        others = [bx for k, bx in current.items() if k != id(t) and _gap(env, bx) < _NEAR_MM]
        found: Box | None = None
        r = 0.0
        crossed = ink.crossed([b])  # a place crossed by no more lines than its own
        # every place in the order tried, the fixed rules asked of all at once (the exact test
        # only within a hair of a limit)
        rs, cs = _tried_places(p, steps, w, h)
        inside_area = (area[0] <= cs[:, 0]) & (cs[:, 2] <= area[2])
        inside_area &= (area[1] <= cs[:, 1]) & (cs[:, 3] <= area[3])
        foes = [*(current[k] for k in nums_near), *rows_near]
        gaps = [_box_gaps(cs, np.asarray(foes, dtype=float).reshape(-1, 4))]
        if pts_near:
            q = np.asarray(pts_near, dtype=float)
            gaps.append(_box_gaps(cs, np.column_stack([q, q])))
        least = np.min(np.concatenate(gaps, axis=1), axis=1, initial=math.inf)
        lim = _box_gaps(cs, np.asarray([(*p, *p)], dtype=float))[:, 0] + TRACK_MARGIN_MM
        out_conf = least < lim - _HAIR_MM
        ask_conf = ~out_conf & (np.abs(least - lim) <= _HAIR_MM)
        out_other, ask_other = _too_near(cs, others, NUMBER_SPACE)
        for i in np.flatnonzero(inside_area & ~out_conf & ~out_other).tolist():
            r = float(rs[i])
            ux, uy = _LINK_DIRS[i % len(_LINK_DIRS)]
            cx, cy = p[0] + ux * (r + w / 2.0), p[1] + uy * (r + h / 2.0)
            c = (cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0)
            if ask_conf[i] and confused(c, p, pts_near, nums_near, rows_near):
                continue
            if ask_other[i] and any(_gap(c, o) < NUMBER_SPACE for o in others):
                continue
            if ink.crossed([c]) > crossed or (r > LINK_LEADER_MM and _through_text(p, c, others)):
                continue
            found = c
            break
        if found is None:
            continue
        current[id(t)] = found
        _move_number(sheet, ink, t, found, p, r)


def _move_number(
    sheet: Sheet, ink: _Ink, t: TextItem, found: Box, p: tuple[float, float], r: float
) -> None:
    """The number ``t`` moved into the box ``found`` (its anchor kept), with a leader from its
    point ``p`` where it stands ``r`` mm off, further than :data:`LINK_LEADER_MM`, added to
    the ``ink`` the searches test."""
    i = next(k for k, it in enumerate(sheet.items) if it is t)
    moved = replace(t, at=(found[0], found[3] - 0.3 * t.height))
    sheet.items[i] = moved
    sheet.anchors = [(moved if it is t else it, at) for it, at in sheet.anchors]
    if r > LINK_LEADER_MM:
        drawn = len(sheet.items)
        _leader(sheet, p, found)
        ink.add(sheet.items[drawn:])


def _leader(sheet: Sheet, p: tuple[float, float], b: Box) -> None:
    """A thin leader from point ``p`` (paper) to the box ``b`` of its number: from
    :data:`LEADER_FROM_MM` off the point to :data:`LEADER_TO_MM` short of the box."""
    cx, cy = (b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0
    dx, dy = cx - p[0], cy - p[1]
    d = math.hypot(dx, dy)
    if d == 0.0:
        return
    # where the line to the centre leaves the box, grown by LEADER_TO_MM
    hw, hh = (b[2] - b[0]) / 2.0 + LEADER_TO_MM, (b[3] - b[1]) / 2.0 + LEADER_TO_MM
    k = min(hw / abs(dx) if dx else math.inf, hh / abs(dy) if dy else math.inf)
    end = (cx - dx * k, cy - dy * k)
    if math.dist(p, end) <= LEADER_FROM_MM + 0.3:
        return
    u = (dx / d, dy / d)
    sheet.add(Polyline(((p[0] + u[0] * LEADER_FROM_MM, p[1] + u[1] * LEADER_FROM_MM), end),
                       "dimension"))  # fmt: skip


def _centre_of(pts: Sequence[Vec]) -> Vec | None:
    """The centre of the circle that best fits ``pts`` (least squares), or None where they lie
    on a line (or the circle is much larger than their spread: a nearly straight path)."""
    xy = np.array([(q.x, q.y) for q in pts], dtype=float)
    span = float(np.ptp(xy, axis=0).max()) if len(xy) else 0.0
    if len(xy) < 3 or span <= 0.0:
        return None
    c0 = xy.mean(axis=0)
    d = (xy - c0) / span
    a = np.column_stack([2.0 * d, np.ones(len(d))])
    sol, *_ = np.linalg.lstsq(a, (d**2).sum(axis=1), rcond=None)
    r2 = sol[2] + sol[0] ** 2 + sol[1] ** 2
    if not np.isfinite(sol).all() or abs(sol[0]) + abs(sol[1]) > 20.0 or r2 <= 0.0:
        return None
    resid = np.abs(np.hypot(*(d - sol[:2]).T) - math.sqrt(r2)).max()
    if resid > 0.05:  # not on one circle (a coupler curve): no centre to turn away from
        return None
    return Vec(float(c0[0] + sol[0] * span), float(c0[1] + sol[1] * span))


#: ω1's arrow: an arc of this fraction of the crank's drawn length, between the least and the
#: largest radius (mm: within a view's margin round the pivot), over this many degrees,
#: starting this many degrees past the crank (in its sense).
OMEGA_R, OMEGA_MIN_MM, OMEGA_MAX_MM, OMEGA_SWEEP_DEG, OMEGA_PAST_DEG = 0.6, 14.0, 18.0, 90.0, 25.0
#: … and, moved clear of what is drawn round the pivot, at least this radius (mm).
OMEGA_LEAST_MM = 9.0


def omega_arrow(v: Viewport, lk: Linkage, P: Position) -> None:
    """ω1 as an arc arrow about the crank's pivot, inside the path of the crank's joint (so
    that it stays in the view's box however long the crank is drawn) and just ahead of the
    crank in position ``P``, in the crank's sense of rotation, labelled ω_1."""
    pivot = lk.frame[lk.pivot]
    a = P.pos[lk.joint] - pivot
    crank = math.degrees(math.atan2(a.y, a.x))
    sense = 1.0 if lk.omega > 0 else -1.0
    start = crank + sense * OMEGA_PAST_DEG
    r_mm = min(max(OMEGA_R * v.scale.mm(lk.length), OMEGA_MIN_MM), OMEGA_MAX_MM)
    # clear of the links, the arrows and the letters drawn before it (review 9)
    start, r_mm = clear_turn(v.sheet, v.p(pivot), sense, start, r_mm, OMEGA_SWEEP_DEG,
                             (OMEGA_LEAST_MM, max(r_mm, OMEGA_MAX_MM)))  # fmt: skip
    v.turn(pivot, sense, start, "ω_1", r_mm=r_mm, sweep_deg=OMEGA_SWEEP_DEG)


# --- the diagrams -----------------------------------------------------------------------------


def _output_curves(
    s: Solved, psi: np.ndarray
) -> tuple[list[tuple[str, str, str]], np.ndarray, np.ndarray, np.ndarray]:
    """The output's coordinate and its first two time derivatives over the crank's turn ψ from
    position 0, with their (symbol, unit, factor name): a slider's s, v, a from the working
    stroke's start in the working direction, else the output link's angle ψ (from position 0,
    ccw > 0, rad), ω and ε."""
    lk = s.linkage
    sign = 1.0 if lk.omega > 0 else -1.0
    phi = s.drawn[0].phi + sign * psi
    st = sweep(lk, phi, order=2)
    g = lk.output_guide
    if g is not None and s.cycle is not None:
        coord = output_coordinate(lk, st)
        assert coord is not None
        fwd = 1.0 if lk.working == "forward" else -1.0
        # s is measured along the guide: a PRP's yoke runs on its fixed guide (its slide row is
        # the slot's direction, across which the yoke does not move), an RRP's slider along its
        # guide; on a moving guide s is the slider's place on it, and v, a its motion relative
        # to the guide's link (the slider's less that of the guide's point under it)
        sl = prp_frame(g)[1] if g.kind == "PRP" else st.slide[g.links[1]]
        vel, acc = st.vel[lk.output], st.acc[lk.output]
        gd = g.guide
        if g.kind == "RRP" and gd is not None and not gd.fixed:
            r = st.pos[lk.output] - st.pos[gd.frm]
            w, e = st.omega[gd.link][:, None], st.eps[gd.link][:, None]
            turn = np.stack([-r[:, 1], r[:, 0]], axis=1)
            vel = vel - st.vel[gd.frm] - w * turn
            acc = acc - st.acc[gd.frm] - e * turn + w * w * r
        s_m = fwd * (coord - (s.cycle.s_min if fwd > 0 else s.cycle.s_max))
        v_m = fwd * (vel * sl).sum(axis=1)
        a_m = fwd * (acc * sl).sum(axis=1)
        names = [("S", WORDS("m"), "s"), ("v", WORDS("m_s"), "v"), ("a", WORDS("m_s2"), "a")]
        return names, s_m, v_m, a_m
    link = lk.rocker or lk.owner[lk.output]
    if lk.rocker:
        ang = np.unwrap(rocker_angle(lk, st))
    else:
        base = next(p for p in lk.points_on(link) if p != lk.output)
        r = st.pos[lk.output] - st.pos[base]
        ang = np.unwrap(np.arctan2(r[:, 1], r[:, 0]))
    names = [
        (f"ψ_{{{link}}}", WORDS("rad"), "ψ"),
        (f"ω_{{{link}}}", WORDS("per_s"), "ω"),
        (f"ε_{{{link}}}", WORDS("per_s2"), "ε"),
    ]
    return names, ang - ang[0], st.omega[link], st.eps[link]


#: The least height (mm) of each of the output's diagrams on the kinematic sheet: its plot's
#: room (less the ticks' and the arrow's, :class:`~geomcad.sheet.views.Diagram`) draws the curve
#: at least :data:`DIAGRAM_SPAN_MM` high at the coarsest rounding of its μ (1, 2, 2.5, 4, 5 ×
#: 10^n), so that a tall column of plans beside the diagrams never squeezes one to a tick.
DIAGRAM_H = 60.0
#: The least height (mm) of a diagram's curve from its lowest to its highest point: each
#: output diagram's box is at least as high as the room at which its μ (rounded coarse to 1, 2,
#: 2.5, 4, 5 × 10^n) draws its curve this high (review 11: the yarn traverse's s, v, a were
#: 20–30 mm high in 63 mm boxes, read as squeezed; a teacher reads a diagram off a curve
#: about as tall as the crank's 60 mm circle).
DIAGRAM_SPAN_MM = 35.0
#: The least height (mm) of a diagram's curve on every sheet, the crank's rule's too: where the
#: equal boxes of DIAGRAM_H draw one lower, the search splits the column (review 5: a(φ) was
#: squeezed to 12 mm beside a column of plans).
DIAGRAM_SPAN_LEAST_MM = 25.0
#: The height (mm) of each output diagram's plot (its y axis's room) the layout seeks where the
#: sheet has room: lower, its drawn area counts in the search as if it shrank by the plot's
#: shortfall to the power :data:`DIAGRAM_PLOT_POWER` (review 9: the rocking cylinder's ψ, ω,
#: ε squeezed to 41 mm under a 1:1 mechanism with an arrangement beside it left untried).
DIAGRAM_PLOT_MM = 60.0
DIAGRAM_PLOT_POWER = 2.0


def span_room(span: float, mm: float) -> float:
    """The least plot height (mm) at which a diagram's axis (its factor the smallest of 1, 2,
    2.5, 4, 5 × 10^n that puts ``span`` into the room) draws ``span`` at least ``mm`` high: the
    span at the coarsest such factor not above span/mm (between mm and 2·mm); ``mm`` for no
    span (a constant, drawn ±|value|)."""
    if not span > 0.0:
        return mm
    return span / nice_step_below(span / mm)


class _OutputDiagram(Diagram):
    """An output's diagram on the kinematic sheet: a plot lower than :data:`DIAGRAM_PLOT_MM`
    counts in the layout's search as a smaller drawing (:meth:`used`), so the search gives
    the diagrams their height where it costs the other views less."""

    def __init__(self, *args: Any, spans: bool = True, **kw: Any) -> None:
        super().__init__(*args, **kw)
        self.spans = spans

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """With ``spans``, the least height that draws the curve :data:`DIAGRAM_SPAN_MM` high
        at least: the room at which the coarsest factor of the series not above
        span/DIAGRAM_SPAN_MM puts the span into the plot exactly (:func:`span_room`)."""
        (lw, lh), (pw, ph) = super().stretch()
        if not self.spans:
            return (lw, lh), (pw, ph)
        lo, hi = self._range(self.y, 1)
        need = self.BELOW + self.ABOVE + span_room(hi - lo, DIAGRAM_SPAN_MM)
        return (lw, max(lh, need)), (pw, max(ph, need))

    def used(self, w: float, h: float) -> tuple[float, float]:
        uw, uh = super().used(w, h)
        plot = h - self.BELOW - self.ABOVE
        if 0.0 < plot < DIAGRAM_PLOT_MM:
            uh *= (plot / DIAGRAM_PLOT_MM) ** DIAGRAM_PLOT_POWER
        return uw, uh


def fill_diagrams(arranged: Arranged) -> None:
    """The output's diagrams, one under another in their column, share its band by their
    curves: each box as high as its curve at its factor and its room over it, the factors
    made finer (1, 2, 2,5, 4, 5 × 10^n) where the band holds the finer curve, the one whose
    step costs least first, the height left over shared alike (review 12: the slotter's s
    drawn 26 mm high at μ_s = 0,01 м/мм in a 56 mm room, 30 mm empty under it, where the a
    diagram's room had 18 mm to spare: at 0,005 it draws 52 mm). The arrangement's boxes are
    set anew in place (a second call finds no finer step to take: it keeps them)."""
    placed = sorted((pl for pl in arranged if isinstance(pl.view, _OutputDiagram)),
                    key=lambda pl: pl.box[1])  # fmt: skip
    if len(placed) < 2 or any(
        abs(a.box[0] - b.box[0]) > tol.SHEET_MM or abs(a.box[2] - b.box[2]) > tol.SHEET_MM
        for a, b in itertools.pairwise(placed)
    ):
        return  # not one column
    spans: list[float] = []
    ks: list[float] = []
    over: list[float] = []  # each box's height less its curve's room
    for pl in placed:
        dg = pl.view
        assert isinstance(dg, _OutputDiagram)
        room = pl.inner[3] - pl.inner[1] - dg.BELOW - dg.ABOVE
        _, ay = dg.axes(pl.inner[2] - pl.inner[0], pl.inner[3] - pl.inner[1])
        if room <= 0.0 or dg.y.tick:
            return
        spans.append(ay.hi - ay.lo)
        ks.append(ay.k)
        over.append(pl.box[3] - pl.box[1] - room)
    heights = [pl.box[3] - pl.box[1] for pl in placed]
    spare = sum(heights) - sum(sp / k + o for sp, k, o in zip(spans, ks, over, strict=True))
    finer = [_finer(k) for k in ks]
    while True:
        steps = zip(spans, ks, finer, strict=True)
        cost, i = min((sp / f - sp / k, i) for i, (sp, k, f) in enumerate(steps))
        if cost > spare:
            break
        ks[i], finer[i] = finer[i], _finer(finer[i])
        spare -= cost
    share = max(spare, 0.0) / len(placed)
    y = placed[0].box[1]
    for k, (pl, sp, o) in enumerate(zip(placed, spans, over, strict=True)):
        h = sp / ks[k] + o + share
        top, bottom = pl.inner[1] - pl.box[1], pl.box[3] - pl.inner[3]
        box = (pl.box[0], y, pl.box[2], y + h)
        inner = (pl.inner[0], y + top, pl.inner[2], y + h - bottom)
        arranged.placed[id(pl.view)] = replace(pl, box=box, inner=inner)
        if k + 1 < len(placed):
            y += h + (placed[k + 1].box[1] - pl.box[3])


def _finer(k: float) -> float:
    """The next finer factor of the series 1, 2, 2,5, 4, 5 × 10^n below ``k`` (one of it)."""
    return nice_step_below(k * (1.0 - 4.0 * tol.REL_LENGTH))


def _diagrams(s: Solved, spans: bool = True) -> list[Diagram]:
    """The output's diagrams over a turn from position 0: the exact curves of the sweep, and
    the derivatives by chords through the numbered positions (graphical differentiation)."""
    lk = s.linkage
    psi = np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES)
    names, s_m, v_m, a_m = _output_curves(s, psi)
    n = _divisions(s)

    def s_of(at: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        # from position 0 (an angle's output counts from its first sample), then ``at`` in order
        return np.asarray(_output_curves(s, np.append(0.0, at))[1][1:], dtype=np.float64)

    psi_k, s_k, psi_v, v_ch, psi_a, a_ch = chord_derivatives(s_of, n, abs(lk.omega), REFINE_STEPS)
    rows = [(s_m, psi_k, s_k), (v_m, psi_v, v_ch), (a_m, psi_a, a_ch)]
    x = AxisSpec("φ", WORDS("deg"), "φ", 0.0, 360.0, 30.0)
    out: list[Diagram] = []
    for (sym, unit, name), (exact, gx, gy) in zip(names, rows, strict=True):
        curves = [
            Curve(np.degrees(psi), exact, "result"),
            Curve(np.degrees(gx), gy, "construction", points=True),
        ]
        out.append(_OutputDiagram(x, AxisSpec(sym, unit, name), curves, least=(120.0, DIAGRAM_H),
                                  prefer=(600.0, 160.0), marks=position_marks(n),
                                  spans=spans))  # fmt: skip
    return out


def chord_derivatives(
    s_of: Callable[[npt.NDArray[np.float64]], npt.NDArray[np.float64]],
    n: int,
    omega: float,
    refine: int = 0,
) -> tuple[npt.NDArray[np.float64], ...]:
    """The graphical differentiation by chords of a periodic s(ψ) over a cycle, ``s_of`` giving
    s at crank turns ψ from position 0, divided first at the ``n`` numbered positions; ``omega``
    the crank's |ω|. Each chord's slope is the derivative at its interval's middle, v = Δs/Δt,
    and so is each chord's of v's polyline: a at the middle between two of v's points.
    Where a's points change by more than :data:`REFINE_SHARE` of their range from a division
    point to the next, the intervals beside it are halved (the textbook's smaller intervals
    where the curve is steep), at most ``refine`` times. A numbered position between unequal
    intervals takes the chords of the shorter's length on its two sides (the longer one's
    chord drawn from the position), so that its a is the symmetric chord difference at the
    position itself; any other division point between unequal intervals has its a off it, at
    the middle. Both polylines cover the whole cycle: at ψ = 0 and 2π each takes the chord
    between its last and first points (the cycle repeats), so it ends where it starts.
    Returns (ψ_s, s, ψ_v, v, ψ_a, a)."""
    nodes = np.linspace(0.0, 2.0 * math.pi, n + 1)
    for level in range(refine + 1):
        s_k = s_of(nodes)
        dpsi = np.diff(nodes)
        v_mid = np.diff(s_k) / (dpsi / omega)
        x_mid = nodes[:-1] + dpsi / 2.0
        x_prev = np.concatenate([[x_mid[-1] - 2.0 * math.pi], x_mid[:-1]])
        v_prev = np.concatenate([v_mid[-1:], v_mid[:-1]])
        a_k = (v_mid - v_prev) / ((x_mid - x_prev) / omega)  # about the nodes 0 … m−1
        x_a = (x_prev + x_mid) / 2.0  # the middle between the two chords' middles
        span = float(a_k.max() - a_k.min())
        jump = np.abs(a_k - np.roll(a_k, -1)) > REFINE_SHARE * span  # node j to node j+1
        steep = jump | np.roll(jump, 1)
        if level == refine or not steep.any():
            break
        m = len(nodes) - 1
        halves = {(j - 1) % m for j in np.flatnonzero(steep)} | set(np.flatnonzero(steep))
        extra = [nodes[i] + dpsi[i] / 2.0 for i in sorted(halves)]
        nodes = np.sort(np.concatenate([nodes, extra]))
    step = 2.0 * math.pi / n
    before = np.roll(dpsi, 1)
    odd = np.flatnonzero(
        (np.abs(nodes[:-1] / step - np.round(nodes[:-1] / step)) * step <= tol.TURN_START)
        & (np.abs(dpsi - before) > tol.TURN_START)
    )
    if len(odd):  # numbered positions between unequal intervals: chords of the shorter's length
        at, h = nodes[odd], np.minimum(dpsi, before)[odd]
        s3 = s_of(np.stack([at - h, at, at + h], axis=1).ravel()).reshape(-1, 3).T
        a_k[odd] = (s3[0] - 2.0 * s3[1] + s3[2]) / (h / omega) ** 2
        x_a[odd] = at
    psi_v, v = _periodic(x_mid, v_mid)
    psi_a, a = _periodic(x_a, a_k)
    return nodes, s_k, psi_v, v, psi_a, a


#: A division point's neighbours are halved where a changes by more than this share of its
#: range from it to the next (see :func:`chord_derivatives`).
REFINE_SHARE = 1.0 / 3.0
#: At most this many halvings (a 30° interval down to 3.75°).
REFINE_STEPS = 3


def _periodic(
    x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Points of a cycle's derivative, sorted on [0, 2π), closed at 0 and 2π by the chord from
    the last point to the first (one cycle on)."""
    x = np.mod(x, 2.0 * math.pi)
    x[np.abs(x - 2.0 * math.pi) <= tol.TURN_START] = 0.0
    x[np.abs(x) <= tol.TURN_START] = 0.0
    o = np.argsort(x)
    x, y = x[o], y[o]
    t = (2.0 * math.pi - x[-1]) / (x[0] + 2.0 * math.pi - x[-1])
    y0 = y[-1] + t * (y[0] - y[-1])
    if x[0] == 0.0:  # a point at 0: it closes the cycle at 2π
        return np.append(x, 2.0 * math.pi), np.append(y, y[0])
    return np.concatenate([[0.0], x, [2.0 * math.pi]]), np.concatenate([[y0], y, [y0]])


def position_marks(n: int) -> list[tuple[float, str]]:
    """The numbered positions 0 … n−1 at their crank angles from position 0 (degrees), the
    marks under a diagram's φ axis."""
    return [(360.0 * k / n, str(k)) for k in range(n)]


# --- the tables -------------------------------------------------------------------------------


def _tables(s: Solved, accel: Sequence[Position], h: float = TEXT_H) -> list[Table]:
    """The angular velocities of the turning links in every position, and their angular
    accelerations (with the output's) in the positions of the acceleration plans, written ``h``
    high."""
    lk = s.linkage
    per_s, per_s2 = WORDS("per_s"), WORDS("per_s2")
    r = lk.rocker
    # a rocker output: its ω (its ε) first, in place of the output point's V (a)
    links = [i for i in lk.moving_links if i not in (1, r) and _turns(lk, i)]
    if r:
        out_v = f"ω_{{{r}}}, {per_s}"
        first = [_zeroed([P.omega[r] for P in s.drawn], abs(lk.omega))]
        out_a = f"ε_{{{r}}}, {per_s2}"
        first_a = [_zeroed([P.eps[r] for P in accel], lk.omega**2)]
    else:
        out_v = f"V_{{{lk.output}}}, {WORDS('m_s')}"
        scale_v = abs(lk.omega) * lk.length
        out_a = f"a_{{{lk.output}}}, {WORDS('m_s2')}"
        scale_a = lk.omega**2 * lk.length
        along_v, along_a = _along_guide(s, s.drawn), _along_guide(s, accel)
        # a slider's V, a: their projections on its guide, signed as on the v(φ), a(φ)
        # diagrams (a note under the tables says which way is +); else the point's speed
        first = [_zeroed(along_v[0] if along_v else
                         [P.vel[lk.output].norm for P in s.drawn], scale_v)]  # fmt: skip
        first_a = [_zeroed(along_a[1] if along_a else
                           [P.acc[lk.output].norm for P in accel], scale_a)]  # fmt: skip
    # links that turn together (a block and the link it slides on) share one column
    with_ = together(lk)
    if r:
        out_v = f"{_joined('ω', r, with_)}, {per_s}"
        out_a = f"{_joined('ε', r, with_)}, {per_s2}"
    links = [i for i in links if r not in with_.get(i, ())
             and min(j for j in with_.get(i, (i,)) if j in links) == i]  # fmt: skip
    head = ["№", "φ_1, °", out_v, *[f"{_joined('ω', i, with_)}, {per_s}" for i in links]]
    rows = [head, *_columns(
        [float(i) for i in range(len(s.drawn))],
        [math.degrees(P.phi) % 360 for P in s.drawn],
        *first,
        *[_zeroed([P.omega[j] for P in s.drawn], abs(lk.omega)) for j in links],
        angle=1,
        places=_places(s),
        shared=range(2 if r else 3, 3 + len(links)),
    )]  # fmt: skip
    head2 = ["φ_1, °", out_a, *[f"{_joined('ε', i, with_)}, {per_s2}" for i in links]]
    rows2 = [head2, *_columns(
        [math.degrees(P.phi) % 360 for P in accel],
        *first_a,
        *[_zeroed([P.eps[j] for P in accel], lk.omega**2) for j in links],
        angle=0,
        places=_places(s),
        shared=range(1 if r else 2, 2 + len(links)),
    )]  # fmt: skip
    row_h = row_height(h)
    return [
        Table(
            rows,
            title=WORDS("omega_table"),
            height=h,
            row_h=row_h,
            title_height=TITLE_H,
            center=True,
        ),
        Table(
            rows2,
            title=WORDS("eps_table"),
            height=h,
            row_h=row_h,
            title_height=TITLE_H,
            center=True,
        ),
    ]


def _as_tabled(
    steps: Sequence[Step], P: Position, tables: Sequence[tuple[Table, Sequence[Position]]]
) -> dict[str, dict[str, str]]:
    """The values of the steps as the sheet's tables print them in position ``P``, where a
    table has ``P``'s row (its rows after the header one per position of ``tables``' second)
    and a column headed by the value's symbol: one rounding per value on a sheet, the column's
    decimals. A step that reads off a link's ω or ε (kind ``plan_omega``: its ``w``, its
    magnitude ``value``) writes the cell's magnitude, and ``|ε_4|`` for its symbol where the
    cell is negative (the text's quotient of lengths is a magnitude, the table's value signed);
    a step that uses a link's ω (``w`` and its value ``omega``: a^n = ω²·l, 2ω·V) or gives a
    tabled quantity (``label`` and its ``value``: V_D, a_D) writes the same cell's magnitude."""
    cells = _cells(P, tables)
    minus = "\u2212\u2013-"
    out: dict[str, dict[str, str]] = {}
    for step in steps:
        args = dict(step.args)
        w, label = args.get("w"), args.get("label")
        given: dict[str, str] = {}
        if step.kind == "plan_omega" and isinstance(w, str) and w in cells:
            given["value"] = cells[w].lstrip(minus)
            if cells[w][:1] in minus:
                given["w"] = f"|{w}|"
        elif isinstance(w, str) and w in cells and "omega" in args:
            given["omega"] = cells[w].lstrip(minus)
        if isinstance(label, str) and label in cells and "value" in args:
            given["value"] = cells[label].lstrip(minus)
        if given:
            out[step.name] = given
    return out


def _cells(
    P: Position, tables: Sequence[tuple[Table, Sequence[Position]]], same: bool = False
) -> dict[str, str]:
    """Position ``P``'s cells of ``tables`` (their rows after the header one per position of
    ``tables``' second), by their column's symbol (``ε_{3}`` of ``ε_{3}, с^{-2}``); ``same``:
    a position at ``P``'s crank angle is ``P``'s, else only ``P`` itself."""

    def at(Q: Position) -> bool:
        return Q is P or (same and abs(math.remainder(Q.phi - P.phi, math.tau)) <= tol.ANGLE)

    cells: dict[str, str] = {}
    for table, positions in tables:
        row = next((i for i, Q in enumerate(positions) if at(Q)), None)
        if row is None:
            continue
        head, values = table.rows[0], table.rows[1 + row]
        for h, v in zip(head, values, strict=True):
            cells.update(dict.fromkeys(h.split(", ")[0].split(" = "), v))
    return cells


def together(lk: Linkage) -> dict[int, tuple[int, ...]]:
    """The moving links that turn together, by each of them: a block and the link it slides on
    (an RPR's two links, an RRP's slider and the moving link its guide is on) have one ω and one
    ε by the group's kinematics; each such set sorted, the same tuple for each of its links."""
    parent = {i: i for i in lk.moving_links}

    def root(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for g in lk.groups:
        pair: tuple[int, int] | None = None
        if g.kind == "RPR":
            pair = g.links
        elif g.kind == "RRP" and g.guide is not None and not g.guide.fixed:
            pair = (g.links[1], g.guide.link)
        if pair is not None and pair[0] in parent and pair[1] in parent:
            parent[root(pair[0])] = root(pair[1])
    sets: dict[int, list[int]] = {}
    for i in parent:
        sets.setdefault(root(i), []).append(i)
    return {i: tuple(sorted(m)) for m in sets.values() if len(m) > 1 for i in m}


def _joined(symbol: str, link: int, with_: Mapping[int, Sequence[int]]) -> str:
    """A column's symbol for ``link``: ``ω_{2} = ω_{3}`` where links turn together."""
    return " = ".join(f"{symbol}_{{{i}}}" for i in with_.get(link, (link,)))


def tabled_cells(s: Solved, P: Position) -> dict[str, str]:
    """The kinematic sheet's table cells of the position at ``P``'s crank angle, by their
    column's symbol (``ω_{2}``, ``ε_{3}``, ``a_{B}``): another sheet prints a value the
    kinematic sheet tables as its cell reads (one rounding per value in a set of sheets)."""
    # (the force analysis' position among the acceleration plans': its ε read as the
    # kinematic sheet tables it where that draws its plan, without running that layout)
    accel = _accel_positions(s)
    omega, eps = _tables(s, accel)
    return _cells(P, [(omega, s.drawn), (eps, accel)], same=True)


def _along_guide(
    s: Solved, positions: Sequence[Position]
) -> tuple[list[float], list[float]] | None:
    """A slider output's velocity and acceleration in ``positions`` as its v(φ), a(φ)
    diagrams give them (their projections on its guide, + in the working stroke's direction),
    or None for an output that has no such diagrams."""
    lk = s.linkage
    if lk.rocker or lk.output_guide is None or s.cycle is None or not positions:
        return None
    sign = 1.0 if lk.omega > 0 else -1.0
    psi = np.array([(sign * (P.phi - s.drawn[0].phi)) % (2.0 * math.pi) for P in positions])
    _, _, v, a = _output_curves(s, psi)
    return [float(x) for x in v], [float(x) for x in a]


def _zeroed(xs: Sequence[float], scale: float) -> list[float]:
    """Round-off of a zero (at most :data:`ZERO` of ``scale``, its quantity's size) as 0."""
    return [0.0 if abs(x) <= ZERO * scale else float(x) for x in xs]


def _columns(
    *cols: Sequence[float], angle: int = -1, places: int = 1, shared: Sequence[int] = ()
) -> list[list[str]]:
    """Table rows from columns of one quantity each, a column's numbers with the same count of
    decimals (:func:`~geomcad.sheet.scale.fmt_column`): 4 significant figures at its largest
    (the order of construction prints a value as its cell does); the columns ``shared`` (of
    one quantity and unit: ω2, ω3, ω4 in s⁻¹) one count of decimals together, 4 significant
    figures at their largest (review 14: ω2, ω3 with 3 decimals beside ω4 with 4); the crank
    angle (column ``angle``) with the sheets' ``places``."""
    n = len(cols)
    one = column_places([x for i in shared for x in cols[i]]) if shared else 0
    texts = [
        [fmt_fixed(x, places, current()) for x in c] if i == angle % n
        else [fmt_fixed(x, one, current()) for x in c] if i in shared
        else fmt_column(c, current())
        for i, c in enumerate(cols)
    ]  # fmt: skip
    return [list(r) for r in zip(*texts, strict=True)]


def row_height(h: float) -> float:
    """A table's row height for text ``h`` high: 6 mm for 2.5 mm, 8 mm for 3.5 mm."""
    return 2.0 * h + 1.0


def _turns(lk: Linkage, link: int) -> bool:
    """False for a link that cannot turn: a slider on a fixed guide, the links of a PRP."""
    g = lk.group_of(link)
    if g is None:
        return True
    if g.kind == "PRP":
        return False
    return not (g.kind == "RRP" and link == g.links[1] and g.guide is not None and g.guide.fixed)


#: Values below this fraction of their quantity's scale print as 0 (round-off of a zero).
ZERO = tol.DERIVED


def table_number(x: float, scale: float = 0.0, digits: int = 3, *, zeros: bool = False) -> str:
    """A table value to ``digits`` significant figures (``zeros``: its trailing zeros kept,
    :func:`~geomcad.sheet.scale.fmt_number`); round-off of a zero (at most :data:`ZERO` of
    ``scale``, the size of its quantity) as 0."""
    return "0" if abs(x) <= ZERO * scale else fmt_number(x, current(), digits, zeros=zeros)


# --- the moving mechanism ---------------------------------------------------------------------


def motion(s: Solved, frames: int) -> Frames:
    """The linkage over one crank turn from position 0 (:mod:`geomcad.sheet.motion`): every
    joint and point from the sweep, each link as the chain of its points, the sliders along
    their guides, the paths of the named points and the output, and the velocity plan with its
    relative velocities along each link."""
    lk = s.linkage
    phi = turn(frames, s.drawn[0].phi, 1.0 if lk.omega > 0 else -1.0)
    st = sweep(lk, phi, order=1)
    pos, vel = st.pos, st.vel
    names = [*lk.frame, *(n for n in lk.owner if n not in lk.frame)]
    points = {n: np.array(pos[n]) for n in names if n in pos}
    links: list[tuple[str, ...]] = []
    edges: list[tuple[str, str]] = []
    for link in lk.moving_links:
        on = [n for n in dict.fromkeys(lk.points_on(link)) if n in points]
        if len(on) >= 2:
            links.append(tuple(on))
            edges += [(on[0], q) for q in on[1:] if q in vel and on[0] in vel]
    sliders = {}
    guides = []
    for g in lk.groups:
        if g.kind in ("RRP", "PRP") and g.guide is not None:
            d = st.slide[g.links[1]][0]
            sliders[g.joint] = (float(d[0]), float(d[1]))
            if g.guide.fixed:
                P = points[g.joint]
                t = (P - np.array([g.guide.through.x, g.guide.through.y])) @ d
                q = np.array([g.guide.through.x, g.guide.through.y])
                reach = 0.15 * float(t.max() - t.min()) + 0.1 * lk.length
                a, b = q + d * (t.min() - reach), q + d * (t.max() + reach)
                guides.append(((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))))
    traced = tuple(dict.fromkeys((lk.joint, *(p.name for p in lk.points), lk.output)))
    return Frames(
        title=WORDS("motion", title=file_title(lk) or lk.title),
        phi=phi,
        points=points,
        links=tuple(links),
        fixed=tuple(lk.frame),
        traced=traced,
        sliders=sliders,
        guides=tuple(guides),
        velocities={n: np.array(vel[n]) for n in points if n in vel},
        plan_edges=tuple(dict.fromkeys(edges)),
        omega1=lk.omega,
    )
