"""Views that draw themselves from the model, for :mod:`geomcad.sheet.compose` to place.

- :class:`Scheme` — the kinematic scheme of a :class:`~geomcad.structure.Mechanism` (GOST 2.770:
  supports hatched, joints, blocks; every link numbered), through
  :func:`~geomcad.sheet.scheme.draw_scheme`;
- :class:`PlanView` — a velocity or acceleration plan (:class:`~geomcad.kinematics.plan.Plan`);
- :class:`Polygon` — one or more force polygons in one viewport, and :func:`draw_polygon`, the
  one force-polygon drawer (each vector head to tail, labelled beside its middle outside the
  polygon, the vectors found in the result role, those shorter than two arrowheads drawn as a
  point with their label);
- :class:`Diagram` — a diagram (:class:`~geomcad.sheet.graph.Graph`) with its curves, each axis
  at its own factor, filling its box;
- :class:`Table` — a ruled table of rows, or of values with their units
  (:meth:`Table.of_values`, :meth:`Table.of_specs` from a problem's parameter or result specs);
- :class:`Text` — lines or a paragraph of text;
- :class:`Steps` — the order of construction, generated from a recorded construction's steps
  through the per-language templates of ``strings/<lang>/views.toml`` (one template per kind of
  step; the step's role decides whether it is listed).

Every view's words come from the tables of :mod:`geomcad.sheet.lang`; numbers are written by
:func:`~geomcad.sheet.scale.fmt_number` in the language being drawn.
"""

from __future__ import annotations

import functools
import itertools
import math
import re
import sys
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal, Protocol

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.construction import Construction
from geomcad.construction.recorder import Step
from geomcad.forces import ForcePolygon, PlanVector
from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.sheet.compose import (
    TITLE_GAP,
    TITLE_LEAD,
    TITLE_SPACING,
    Extent,
    Placed,
    View,
    scale_text,
    text_width,
    title_text_lines,
)
from geomcad.sheet.drawing import (
    ARROW_LEN,
    LINE_SPACING,
    SHORT_MM,
    Drawing,
    Viewport,
    number_columns,
    number_parts,
)
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.model import Polyline
from geomcad.sheet.plans import LINE_OVER_MM, markup_of, plan_lines, with_centres
from geomcad.sheet.scale import FIGURES, Scale, ScaleStyle, fmt_number, nice_below, nice_factor
from geomcad.sheet.scheme import Body, draw_scheme
from geomcad.sheet.text import balanced, break_points, metrics, wrap, wrap_balanced
from geomcad.structure import Mechanism
from geomcad.units import to_display

WORDS = Words(__package__, "views")


def num(x: float, digits: int = FIGURES) -> str:
    """A number to ``digits`` significant figures in the language being drawn."""
    return fmt_number(x, current(), digits)


def factor(k: Scale) -> str:
    """A scale factor as the language being drawn writes it (``μ_l = 0,005 м/мм``)."""
    return k.label(ScaleStyle(lang=current()))


def _bbox(pts: Iterable[Vec]) -> Extent:
    ps = list(pts)
    xs = [q.x for q in ps]
    ys = [q.y for q in ps]
    return (min(xs), min(ys), max(xs), max(ys))


def extent_of(pts: Iterable[Vec], pad: float = 0.0) -> Extent:
    """A figure's extent: the model box of ``pts`` grown by ``pad`` (model units) on every side
    (room for the supports, arrows and labels drawn round the points)."""
    x0, y0, x1, y1 = _bbox(pts)
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


# --- the scheme -----------------------------------------------------------------------------------


class Scheme(View):
    """The kinematic scheme of ``mech`` at a GOST 2.302 scale; every link is numbered.

    ``bodies``, ``highlight``, ``pair_labels``, ``link_labels``, ``ghosts``, ``supports`` are
    :func:`~geomcad.sheet.scheme.draw_scheme`'s; ``extra(viewport)`` draws more on the same
    viewport (loads, paths, positions); ``also`` are further model points the drawing covers.
    Keywords as :class:`~geomcad.sheet.compose.View` (default margin: room for a support).
    """

    def __init__(
        self,
        mech: Mechanism,
        bodies: Mapping[str, Sequence[Body]] | None = None,
        highlight: Sequence[str] = (),
        pair_labels: Mapping[str, str] | None = None,
        link_labels: Mapping[str, Vec] | None = None,
        ghosts: Sequence[str] = (),
        extra: Callable[[Viewport], None] | None = None,
        also: Iterable[Vec] = (),
        label_height: float = 3.5,
        supports: Mapping[str, tuple[float, float]] | None = None,
        **kw: Any,
    ) -> None:
        kw.setdefault("margin", 9.0)
        super().__init__(**kw)
        self.mech = mech
        self.bodies = bodies
        self.highlight = tuple(highlight)
        self.pair_labels = pair_labels
        self.link_labels = link_labels
        self.ghosts = tuple(ghosts)
        self.extra = extra
        self.label_height = label_height
        self.supports = supports
        pts = [p.at for p in mech.pairs]
        pts += [c for p in mech.pairs for c in (p.centre_a, p.centre_b) if c is not None]
        for bs in (bodies or {}).values():
            for b in bs:
                pts += list(b.points)
        pts += list(also)
        self._ext = _bbox(pts)

    def extent(self) -> Extent | None:
        return self._ext

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        draw_scheme(
            v,
            self.mech,
            bodies=self.bodies,
            highlight=self.highlight,
            pair_labels=self.pair_labels,
            link_labels=self.link_labels,
            label_height=self.label_height,
            ghosts=self.ghosts,
            supports=self.supports,
        )
        if self.extra is not None:
            self.extra(v)


# --- plans ----------------------------------------------------------------------------------------


class PlanView(View):
    """A velocity (``plan.kind`` "v") or acceleration ("a") plan at a factor 1, 2, 2.5, 4,
    5 × 10^n; all plans of one ``group`` share one factor. ``title`` defaults to the plan's
    kind in words ("План скоростей"); ``extra(viewport)`` draws more on it; a vector shorter
    than ``min_mm`` on the paper is drawn without its arrow, the construction lines run on
    ``over_mm`` past their points (as :func:`plan_lines`)."""

    def __init__(
        self,
        plan: Plan,
        extra: Callable[[Viewport], None] | None = None,
        min_mm: float = 0.5,
        over_mm: float = LINE_OVER_MM,
        centres: Mapping[str, tuple[str, str]] | None = None,
        **kw: Any,
    ) -> None:
        kw.setdefault("title", WORDS(f"plan_{plan.kind}"))
        kw.setdefault("quantity", plan.kind)
        kw.setdefault("series", "nice")
        kw.setdefault("margin", LINE_OVER_MM)
        super().__init__(**kw)
        self.plan = plan
        #: the plan as drawn: with the images of the links' centres of mass ``centres`` (their
        #: names: each the middle of two plan points, :func:`with_centres`)
        self.shown = with_centres(plan, centres or {})
        self.centres = tuple(centres or ())
        self.extra = extra
        self.min_mm = min_mm
        self.over_mm = over_mm

    def extent(self) -> Extent | None:
        return self.shown.extent()

    def lengths(self) -> Sequence[float]:
        pts = self.plan.points
        return [(pts[v.head] - pts[v.tail]).norm for v in self.plan.vectors]

    def draw(self, d: Drawing, at: Placed) -> None:
        """The plan in its cell, its letters kept inside the cell where they can (review 13:
        position 0's letters stood in position 1's plan on a grid of plans)."""
        assert at.viewport is not None
        at.viewport.within = at.box
        plan_lines(at.viewport, self.shown, self.min_mm, self.over_mm, self.centres)
        if self.extra is not None:
            self.extra(at.viewport)


# --- force polygons -------------------------------------------------------------------------------


def _outward(poly: ForcePolygon, a: Vec, b: Vec, inward: bool) -> tuple[float, float]:
    """The normal of side ab pointing away from the polygon's centroid (or towards it)."""
    pts = [pv.tail for pv in poly.vectors]
    c = Vec(sum(q.x for q in pts) / len(pts), sum(q.y for q in pts) / len(pts))
    n = (b - a).perp()
    if n.norm == 0.0:
        return (1.0, 0.0)
    if n.dot((a + b) * 0.5 - c) < 0.0:
        n = -n
    if inward:
        n = -n
    u = n.unit()
    return (u.x, u.y)


def draw_polygon(
    v: Viewport,
    poly: ForcePolygon,
    names: Mapping[str, str] | None = None,
    role: str = "vector",
    found: Iterable[str] | None = None,
    inward: Iterable[str] = (),
    height: float = 2.5,
    details: Sequence[Detail] = (),
    thin: bool = False,
    omit: Iterable[str] = (),
    lines: Iterable[str] = (),
    bound: tuple[float, float, float, float] | None = None,
) -> list[str]:
    """Draw ``poly`` through ``v`` at the viewport's μ_F: each vector head to tail, labelled
    beside its middle (``names`` maps a vector's name to label markup; default: the name),
    outside the polygon (inside for the names in ``inward``); the vectors ``found`` (default:
    the polygon's solved unknowns, or its closing vector) in the result role, the others in
    ``role``. The runs of ``details`` are drawn thin, circled and lettered (ESKD выносной
    элемент; :func:`draw_detail` draws them enlarged). ``thin``: the polygon lies along one
    line (two opposite reactions): its vectors are drawn side by side :data:`OFFSET_MM` apart,
    joined by thin lines, as a textbook draws them (a sliver's two long opposite ones
    :data:`SLIVER_LANE_MM` apart, :func:`_pair_lanes`). Never
    a dot: a vector outside every detail is an arrow however short; those in ``omit`` (a
    negligible share of the polygon, named under its caption) are not drawn; those in ``lines``
    (too short even for a detail, named under its caption) are drawn as lines. Returns the names
    of the vectors left shorter than two arrowheads."""
    if found is None:
        known = {n for n, _ in poly.solved}
        found = known or ({poly.vectors[-1].name} if poly.vectors else set())
    found = set(found)
    inward = set(inward)
    in_detail = {n for dt in details for n in dt.run} | set(lines)
    # a reaction is an arrow of the plan at its μ_F, however short, where a detail shows it
    # enlarged too (review 14: the gang saw's crank plan had R₄₁, 16 750 N, only in its detail)
    main = main_arrows(poly)
    zero = _zero(poly)
    omit = set(omit)
    # a resultant along its long component (the other too short to part them): one line
    twins = twin_resultants(poly, v.scale.k)
    # a sliver's two long opposite vectors: side by side a sliver's lane apart, the loads'
    # chain (in its detail) between them (review 12, fix 2: one line read as two superposed
    # arrows; review 9, fix 4: a 2,5 mm lane read as one smudged twin line)
    pair = sliver_pair(poly, in_detail | omit)
    paired = {pv.name for pv in pair} if pair else set()
    shift = (
        _shifts(v, poly, in_detail | paired)
        if thin
        else lanes(v.scale.k, _lane_vectors(poly, in_detail | paired, omit | set(twins)))
    )
    if pair:
        shift.update(_pair_lanes(pair, v.scale.k))
    short: list[str] = []
    drawn = [pv for pv in poly.vectors if pv.magnitude > zero and pv.name not in omit]
    res = [(r, c) for r, c in resultants(poly) if r.name not in twins]
    also = {comp: r for r, comp in twins.items()}
    # a component is labelled outside the triangle it makes with its resultant
    away: dict[str, Vec] = {}
    for r, _ in res:
        for pv in drawn:
            m = _COMPONENT.fullmatch(pv.name)
            if m is not None and m[1] + m[2] == r.name:
                at_tail = min((q - r.tail).norm for q in (pv.tail, pv.head)) <= zero
                away[pv.name] = r.head if at_tail else r.tail
    for i, pv in enumerate(drawn):
        s = shift.get(pv.name, Vec(0.0, 0.0))
        nxt = drawn[(i + 1) % len(drawn)]
        s2 = shift.get(nxt.name, Vec(0.0, 0.0))
        if (s - s2).norm > 0.0:  # the vectors side by side joined where they meet
            v.seg(pv.head + s, nxt.tail + s2, "construction")
        tail, head = pv.tail + s, pv.head + s
        text = (names or {}).get(pv.name, pv.name)
        if pv.name in also:  # its resultant drawn over it: "Rⁿ₃₄ ≈ R₃₄"
            text = f"{text} ≈ {(names or {}).get(also[pv.name], also[pv.name])}"
        if pv.name in in_detail and pv.name not in main:
            # its line keeps the chain whole (its arrow, named, is drawn in its detail: the
            # circle round it is clear of labels)
            v.seg(tail, head, "construction")
            continue
        else:
            if v.mm(pv.magnitude) < SHORT_MM and pv.name not in in_detail:
                short.append(pv.name)
            v.arrow(tail, head, "result" if pv.name in found else role)
        if s.norm > 0.0:
            prefer = (s.unit().x, s.unit().y)
        elif pv.name in away:
            n = (pv.head - pv.tail).perp().unit()
            n = -n if n.dot(away[pv.name] - pv.tail) > 0.0 else n
            prefer = (n.x, n.y)
        else:
            prefer = _outward(poly, pv.tail, pv.head, pv.name in inward)
        v.label((tail + head) * 0.5, text, height, prefer=prefer, clear=0.5)
    for r, corner in res:
        # a reaction found by its components: their resultant closes them, the label on the
        # side away from the components' corner, a third of the way along (clear of the
        # label of a long component drawn next to it)
        s = shift.get(r.name, Vec(0.0, 0.0))
        if s.norm > 0.0:  # beside a component along its line, tied to its ends
            v.seg(r.tail, r.tail + s, "construction")
            v.seg(r.head, r.head + s, "construction")
            r = PlanVector(r.name, r.tail + s, r.head + s)
            corner = corner + s
        else:
            # its ends go with its components' where lanes moved them (review 13: rocker_
            # centres' R_12 ended between R^τ_12 and G_2 set apart at their vertex)
            ends = _component_shifts(r, drawn, shift, zero)
            r = PlanVector(r.name, r.tail + ends[0], r.head + ends[1])
        # (its components may be in a detail: the reaction itself is an arrow of the plan)
        v.arrow(r.tail, r.head, "result")
        n = (r.head - r.tail).perp().unit()
        if n.dot(corner - r.tail) > 0.0:
            n = -n
        prefer = (n.x, n.y)
        if v.mm(abs(n.dot(corner - r.tail))) < SHORT_MM:
            # a component too short to tell the side: the label outside the polygon (not
            # inside it, by the head of another vector: R_12 by R_43's)
            prefer = _outward(poly, r.tail, r.head, False)
        v.label(r.tail + (r.head - r.tail) * 0.3, (names or {}).get(r.name, r.name), height,
                prefer=prefer, clear=0.5)  # fmt: skip
    sides = [(v.p(pv.tail + shift.get(pv.name, Vec(0.0, 0.0))),
              v.p(pv.head + shift.get(pv.name, Vec(0.0, 0.0)))) for pv in drawn]  # fmt: skip
    sides += [(v.p(r.tail + shift.get(r.name, Vec(0.0, 0.0))),
               v.p(r.head + shift.get(r.name, Vec(0.0, 0.0)))) for r, _ in res]  # fmt: skip
    segs = sides + _slot_sides(v, details)
    for centre, radius, letters in detail_spots(v, poly, [dt for dt in details if dt.host is None]):
        taken = [mark_detail(v, centre, radius, letters, segs=segs, bound=bound)]
        # one detail level (review 12, item 1): the details that show what a detail's μ_F
        # leaves short are taken from the same spot of the plan, side by side with it, their
        # letters on the same circle (never a circle on a detail)
        own = set(letters.split(", "))
        for dt in details:
            if dt.host is not None and root_of(dt).letter in own:
                taken.append(mark_detail(v, centre, radius, dt.letter, segs=segs, bound=bound,
                                         circle=False, taken=taken))  # fmt: skip
    v.dot(poly.pole)
    return short


#: A reaction's name (R_{12}, R_{1,12}), not a component's (R^n_{12}: :data:`_COMPONENT`).
_REACTION = re.compile(r"R_.+")


def main_arrows(poly: ForcePolygon) -> set[str]:
    """The vectors of ``poly`` drawn as arrows of the plan at its own μ_F however short, also
    where a detail shows them enlarged: its reactions (R₁₂; those it finds, which close it,
    and those of other links laid off as known loads), and the resultants of its split
    reactions (R₁₂ of R^n₁₂, R^τ₁₂, drawn in :func:`draw_polygon` whatever its length). A
    teacher reads the plan's equation on the plan: a reaction only in a detail leaves the
    polygon unclosed on the plan (review 14, fix 2: the gang saw's crank plan, R₄₁ only in
    its detail; the knuckle press's R₀₅). Only loads (G, Φ, F) and a split reaction's
    components are drawn only in a detail."""
    return {pv.name for pv in poly.vectors if _REACTION.fullmatch(pv.name)}


def _component_shifts(
    r: PlanVector, drawn: Sequence[PlanVector], shift: Mapping[str, Vec], zero: float
) -> tuple[Vec, Vec]:
    """The shifts of a resultant's tail and head: those of its component that starts at its
    tail and of the one that ends at its head (none where lanes left them)."""
    none = Vec(0.0, 0.0)
    parts = [pv for pv in drawn if _resultant_of(pv.name) == r.name]
    tail = next((shift.get(pv.name, none) for pv in parts if (pv.tail - r.tail).norm <= zero),
                none)  # fmt: skip
    head = next((shift.get(pv.name, none) for pv in parts if (pv.head - r.head).norm <= zero),
                none)  # fmt: skip
    return tail, head


def _pair_lanes(pair: tuple[PlanVector, PlanVector], k: float) -> dict[str, Vec]:
    """The sideways shifts (model units, at μ_F ``k``) that draw a sliver's two long opposite
    vectors side by side :data:`SLIVER_LANE_MM` apart across the first's line, each on the side
    of the other that it lies on in the plan (the loads' chain between them), centred where
    they were."""
    a, b = pair
    n = (a.head - a.tail).unit().perp()
    mid = (b.tail + b.head) * 0.5
    side = 1.0 if n.dot(mid - a.tail) >= 0.0 else -1.0
    half = n * (side * SLIVER_LANE_MM * k / 2.0)
    return {a.name: -half, b.name: half}


#: A reaction's component: R^n_{12}, R^τ_{12} (its resultant R_{12}).
_COMPONENT = re.compile(r"(.+)\^(?:n|τ|t)(_.+)")


def sliver_pair(
    poly: ForcePolygon, hidden: Iterable[str] = ()
) -> tuple[PlanVector, PlanVector] | None:
    """The two long vectors of a sliver plan (:func:`is_sliver`: a two-force member's R₁₂,
    R₃₂, or a link's two reactions with small loads between) that a plan draws side by side:
    the only two of its vectors drawn as arrows (the others ``hidden``: in its details, drawn
    as lines or left out), running opposite ways (within :data:`LANE_ANGLE`); ``None`` where
    there are no such two (a plan with a split reaction's components, or a load drawn large)."""
    if not is_sliver(poly) or resultants(poly):
        return None
    hidden = set(hidden)
    zero = _zero(poly)
    rest = [pv for pv in poly.vectors if pv.magnitude > zero and pv.name not in hidden]
    if len(rest) != 2:
        return None
    a, b = rest
    if (a.head - a.tail).unit().dot((b.head - b.tail).unit()) > -math.cos(LANE_ANGLE):
        return None
    return a, b


def sliver_loads(poly: ForcePolygon) -> float:
    """The magnitude under which a sliver plan's vectors go into its detail: all but its two
    long opposite ones (:func:`sliver_pair`), however long they would be drawn, so that the
    two are drawn side by side and the loads between them close the gap in the detail at a
    stated μ_F (review 9, fix 4: R₁₂ and R₃₂ of watt2's link 2 drawn side by side about the
    7.6 mm arrow of G₂); 0 where the plan is no such sliver."""
    zero = _zero(poly)
    vs = sorted((pv for pv in poly.vectors if pv.magnitude > zero), key=lambda pv: -pv.magnitude)
    if len(vs) < 3 or sliver_pair(poly, [pv.name for pv in vs[2:]]) is None:
        return 0.0
    return vs[2].magnitude * (1.0 + tol.REL_LENGTH)


def twin_resultants(poly: ForcePolygon, k: float) -> dict[str, str]:
    """The resultants of ``poly``'s split reactions (:func:`resultants`) that, drawn at μ_F
    ``k``, would run as a twin line along their long component: the other component is
    shorter than two arrowheads (drawn in a detail), so the two lines part by less than that
    over the whole plan. A plan draws the one line, named with both ("Rⁿ₃₄ ≈ R₃₄"). By the
    resultant's name, its long component's."""
    out: dict[str, str] = {}
    for r, _ in resultants(poly):
        parts = [pv for pv in poly.vectors if _resultant_of(pv.name) == r.name]
        if len(parts) != 2:
            continue
        small, big = sorted(parts, key=lambda pv: pv.magnitude)
        if small.magnitude / k < SHORT_MM:
            out[r.name] = big.name
    return out


def _resultant_of(name: str) -> str | None:
    """The name of the resultant whose component ``name`` is (R^n_{12} → R_{12}), or None."""
    m = _COMPONENT.fullmatch(name)
    return None if m is None else m[1] + m[2]


def resultants(poly: ForcePolygon) -> list[tuple[PlanVector, Vec]]:
    """The resultants of the reactions ``poly`` has split into two components (R^n_{12} and
    R^τ_{12} → R_{12}), each with the corner where its components meet: the vector closing
    the components, from the tail of the one to the head of the other that follows it in the
    chain (else laid off from the tail of the first by their sum). A component of zero length
    leaves none (the other is the reaction)."""
    zero = _zero(poly)
    parts: dict[str, list[PlanVector]] = {}
    for pv in poly.vectors:
        m = _COMPONENT.fullmatch(pv.name)
        if m is not None:
            parts.setdefault(m[1] + m[2], []).append(pv)
    out = []
    for name, ps in parts.items():
        if len(ps) != 2 or min(pv.magnitude for pv in ps) <= zero:
            continue
        a, b = ps
        if (b.head - a.tail).norm <= zero < (a.head - b.tail).norm:
            a, b = b, a  # b's head meets a's tail: the chain runs b → a
        if (a.head - b.tail).norm <= zero:
            out.append((PlanVector(name, a.tail, b.head), a.head))
        else:
            out.append((PlanVector(name, a.tail, a.head + (b.head - b.tail)), a.head))
    return out


def _zero(poly: ForcePolygon) -> float:
    """A vector of a polygon under this magnitude is round-off of a zero one (not drawn)."""
    return tol.DERIVED * max((pv.magnitude for pv in poly.vectors), default=0.0)


def _shifts(v: Viewport, poly: ForcePolygon, skip: Iterable[str] = ()) -> dict[str, Vec]:
    """The sideways shifts (model units) of a thin polygon's vectors: each next one
    :data:`OFFSET_MM` further across the line of the longest, the set centred on it."""
    skip = set(skip)
    zero = _zero(poly)
    vs = [pv for pv in poly.vectors if pv.magnitude > zero and pv.name not in skip]
    if len(vs) < 2:
        return {}
    big = max(vs, key=lambda pv: pv.magnitude)
    n = (big.head - big.tail).unit().perp()
    step = OFFSET_MM * v.scale.k
    return {pv.name: n * ((i - (len(vs) - 1) / 2.0) * step) for i, pv in enumerate(vs)}


def _lane_vectors(
    poly: ForcePolygon, skip: Iterable[str] = (), omit: Iterable[str] = ()
) -> list[PlanVector]:
    """The vectors of ``poly`` drawn as arrows (not zero, not in a detail, not left out) and
    the resultants of its split reactions: those that may lie along one another."""
    gone = set(skip) | set(omit)
    zero = _zero(poly)
    vs = [pv for pv in poly.vectors if pv.magnitude > zero and pv.name not in gone]
    return vs + [r for r, _ in resultants(poly) if r.name not in gone]


def along(a: PlanVector, b: PlanVector, k: float, near_mm: float = 1.2) -> float:
    """How long (mm, drawn at μ_F ``k``) vectors ``a`` and ``b`` run along one another: within
    :data:`LANE_ANGLE` of each other and ``near_mm`` (:data:`THIN_MM`) of one line (one drawn
    over the other); 0 where they only meet at an end or run apart."""
    return _along(a, b, k, near_mm)[0]


def _along(a: PlanVector, b: PlanVector, k: float, near_mm: float) -> tuple[float, Vec]:
    """:func:`along`, and the middle (model point on ``a``) of the part they run along."""
    none = (0.0, a.tail)
    la, lb = a.magnitude, b.magnitude
    if la <= 0.0 or lb <= 0.0:
        return none
    u, w = (a.head - a.tail).unit(), (b.head - b.tail).unit()
    if abs(u.cross(w)) > math.sin(LANE_ANGLE) and not one_line(a, b, k):
        return none
    # b's ends along a's line (t) and across it (d); d is linear in t along b
    t0, t1 = u.dot(b.tail - a.tail), u.dot(b.head - a.tail)
    d0, d1 = u.cross(b.tail - a.tail), u.cross(b.head - a.tail)
    if t1 < t0:
        t0, t1, d0, d1 = t1, t0, d1, d0
    lo, hi = max(t0, 0.0), min(t1, la)
    if hi <= lo:
        return none
    near = near_mm * k

    def d(t: float) -> float:
        return d0 if t1 == t0 else d0 + (d1 - d0) * (t - t0) / (t1 - t0)

    da, db = d(lo), d(hi)
    if not (abs(da) < near and abs(db) < near):
        if da == db:
            return none
        # the part of [lo, hi] where |d| < near
        ta, tb = (lo + (x - da) * (hi - lo) / (db - da) for x in (-near, near))
        lo, hi = max(min(ta, tb), lo), min(max(ta, tb), hi)
        if hi <= lo:
            return none
    # the spot where they come nearest (two sides of a thin triangle at its sharp vertex: set a
    # lane apart there, they part further along), a lane's overlap in from that end so the side
    # each lies on is read; two parallel ones at the middle
    mid = (lo + hi) / 2.0
    near_lo, near_hi = abs(d(lo)), abs(d(hi))
    if abs(near_lo - near_hi) <= tol.DERIVED * max(near_lo, near_hi, near):
        return (hi - lo) / k, a.tail + u * mid
    inset = min(LANE_OVERLAP_MM * k, (hi - lo) / 2.0)
    at = lo + inset if near_lo < near_hi else hi - inset
    return (hi - lo) / k, a.tail + u * at


def one_line(a: PlanVector, b: PlanVector, k: float) -> bool:
    """Whether two sides of a plan, drawn at μ_F ``k``, read as one line whatever the angle
    between them: the shorter stays within :data:`SLIVER_LANE_MM` of the longer's line over
    the whole of their common run (narrower than a sliver drawn in lanes), and they run
    within a lane (:data:`OFFSET_MM`) of one another longer than two arrowheads
    (:data:`SHORT_MM`: an arrowhead at their sharp vertex merges into the other line). The
    angle at which two sides part so is the one at which their lengths make them readable:
    about 9° for a 46 mm side (review 13: the gang saw's link 4, R₁₄ and R₅₄ at 8,8° read as
    one line), :data:`LANE_ANGLE` for a side twice :data:`SLIVER_MM`, never over
    asin(OFFSET_MM / SHORT_MM), 21°, for a short one."""
    if a.magnitude < b.magnitude:
        a, b = b, a
    la = a.magnitude
    if la <= 0.0 or b.magnitude <= 0.0:
        return False
    u = (a.head - a.tail).unit()
    t0, t1 = u.dot(b.tail - a.tail), u.dot(b.head - a.tail)
    d0, d1 = u.cross(b.tail - a.tail), u.cross(b.head - a.tail)
    if t1 < t0:
        t0, t1, d0, d1 = t1, t0, d1, d0
    lo, hi = max(t0, 0.0), min(t1, la)
    if hi <= lo or t1 == t0:
        return False

    def d(t: float) -> float:
        return d0 + (d1 - d0) * (t - t0) / (t1 - t0)

    if max(abs(d(lo)), abs(d(hi))) >= SLIVER_LANE_MM * k:
        return False
    # the part of the common run where they are within a lane of one another
    lane = OFFSET_MM * k
    da, db = d(lo), d(hi)
    if da == db:
        near = hi - lo if abs(da) < lane else 0.0
    else:
        ta, tb = (lo + (x - da) * (hi - lo) / (db - da) for x in (-lane, lane))
        near = max(0.0, min(max(ta, tb), hi) - max(min(ta, tb), lo))
    return near > SHORT_MM * k


def lanes(k: float, vectors: Sequence[PlanVector]) -> dict[str, Vec]:
    """The sideways shifts (model units) that draw side by side, :data:`OFFSET_MM` apart on the
    paper at μ_F ``k``, the vectors of a plan that would run along one another (over
    :data:`LANE_OVERLAP_MM`, :func:`along`): each set of such vectors in lanes across the line
    of its longest, the fewest lanes (vectors that only meet end to end share one), in the
    order they lie across it, centred where they run along one another; those still along one
    another once moved (two sides of a thin triangle that meet at a small angle) moved apart
    again (:data:`LANE_PASSES`). A vector along no other is not moved."""
    out = _lanes(k, vectors, OFFSET_MM)
    zero = Vec(0.0, 0.0)
    for _ in range(LANE_PASSES):
        moved = [
            PlanVector(pv.name, pv.tail + out.get(pv.name, zero), pv.head + out.get(pv.name, zero))
            for pv in vectors
        ]
        more = _lanes(k, moved, THIN_MM)
        if not more:
            break
        for name, sv in more.items():
            out[name] = out.get(name, zero) + sv
    return out


def _lanes(k: float, vectors: Sequence[PlanVector], near_mm: float) -> dict[str, Vec]:
    """:func:`lanes`' one pass: the vectors within ``near_mm`` of one another over
    :data:`LANE_OVERLAP_MM` are the sets moved into lanes."""
    vs = list(vectors)
    n = len(vs)
    # (those nearer than a lane's width count: moved into lanes, none lands on another)
    over: dict[tuple[int, int], Vec] = {}
    # the pairs at an angle over LANE_ANGLE that read as one line (:func:`one_line`)
    wide: set[tuple[int, int]] = set()
    for i in range(n):
        for j in range(i + 1, n):
            run, spot = _along(vs[i], vs[j], k, near_mm)
            if run > LANE_OVERLAP_MM:
                over[i, j] = spot
                u, w = (vs[i].head - vs[i].tail).unit(), (vs[j].head - vs[j].tail).unit()
                if abs(u.cross(w)) > math.sin(LANE_ANGLE):
                    wide.add((i, j))
    if not over:
        return {}
    root = list(range(n))

    def find(i: int) -> int:
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i

    for i, j in over:
        root[find(i)] = find(j)
    sets: dict[int, list[int]] = {}
    for i in range(n):
        sets.setdefault(find(i), []).append(i)
    out: dict[str, Vec] = {}
    for members in sets.values():
        if len(members) < 2:
            continue
        big = vs[max(members, key=lambda i: vs[i].magnitude)]
        across = (big.head - big.tail).unit().perp()
        # each across the line where they run along one another (two that meet at a small
        # angle apart there, not at their middles)
        spots = [m for (i, j), m in over.items() if i in members]
        c = Vec(sum(q.x for q in spots) / len(spots), sum(q.y for q in spots) / len(spots))
        at: dict[int, float] = {}
        for i in members:
            pv = vs[i]
            w = pv.head - pv.tail
            t = min(max(w.dot(c - pv.tail) / w.dot(w), 0.0), 1.0)
            at[i] = across.dot(pv.tail + w * t - big.tail)
        apart = any(p in wide for p in over if p[0] in members)
        lane: dict[int, int] = {}
        for i in sorted(members, key=lambda i: (at[i], i)):
            taken = {lane[j] for j in lane if (min(i, j), max(i, j)) in over}
            lane[i] = next(x for x in range(n) if x not in taken)
        # a lane moves as one (vectors end to end in it stay joined), the lanes in the order
        # they lie across, OFFSET_MM apart, centred where they were. Sides that meet at a
        # wider angle (:func:`one_line`) meet at their vertices, wherever those are along the
        # set (a thin triangle's two sharp ones at either end of its long side): each lane is
        # moved by its place across, the lanes a lane and a line's clearance (half
        # SLIVER_LANE_MM) apart at every vertex (review 13: the gang saw's link 4, R_54's
        # arrowhead on R_14 at 2 mm; sixbar_coupler_slider's link 2, R_12 and R_32 on R_42)
        step = SLIVER_LANE_MM / 2.0 if apart else OFFSET_MM
        count = max(lane.values()) + 1
        if apart:
            # the side each lies on read where they have parted, at their middles (two that
            # cut one another near their vertex, v_compressor's R_21 and R_01 through the
            # pole's detail, are set on the sides they part to, uncrossed)
            for i in members:
                at[i] = across.dot((vs[i].tail + vs[i].head) * 0.5 - big.tail)
        where = [sum(at[i] for i in members if lane[i] == x) / sum(lane[i] == x for i in members)
                 for x in range(count)]  # fmt: skip
        rank = {x: r for r, x in enumerate(sorted(range(count), key=lambda x: where[x]))}
        mid = sum(where) / count
        for i in members:
            place = (rank[lane[i]] - (count - 1) / 2.0) * step * k
            move = place if apart else mid + place - where[lane[i]]
            if move != 0.0:
                out[vs[i].name] = across * move
    return out


def is_sliver(poly: ForcePolygon) -> bool:
    """Whether the polygon is a sliver: no wider across the line of its longest vector than
    :data:`SLIVER_SHARE` of that vector (a two-force member's R₀₁ = −R₂₁, a link's two
    reactions with a small weight between): drawn large it shows two long lines over one
    another and nothing more, so a sheet draws it no longer than :data:`SLIVER_MM`."""
    spread = _across(poly)
    if spread is None:
        return False
    across, big = spread
    return max(across) - min(across) <= SLIVER_SHARE * big


def is_thin(poly: ForcePolygon, k: float) -> bool:
    """Whether the polygon, drawn at μ_F ``k``, lies within :data:`THIN_MM` of the line of its
    longest vector (its vectors would be drawn over one another)."""
    spread = _across(poly)
    if spread is None:
        return False
    return max(abs(c) for c in spread[0]) / k < THIN_MM


def _across(poly: ForcePolygon) -> tuple[list[float], float] | None:
    """The signed distances (plan units) of the ends of the polygon's drawn vectors from the
    line of its longest vector, and that vector's magnitude; ``None`` where fewer than two
    vectors are drawn."""
    zero = _zero(poly)
    vs = [pv for pv in poly.vectors if pv.magnitude > zero]
    if len(vs) < 2:
        return None
    big = max(vs, key=lambda pv: pv.magnitude)
    u = (big.head - big.tail).unit()
    return [u.cross(q - big.tail) for pv in vs for q in (pv.tail, pv.head)], big.magnitude


def detail_spots(
    v: Viewport, poly: ForcePolygon, details: Sequence[Detail]
) -> list[tuple[tuple[float, float], float, str]]:
    """The circles (centre and radius on the paper, letters) that mark the details' runs on
    the polygon drawn through ``v``: one per detail, or one round the runs of details whose
    circles would overlap (a run cut into two details), lettered with both ("Б, В")."""
    out: list[tuple[list[tuple[float, float]], str]] = []
    for dt in details:
        pts = [v.p(q) for n in dt.run for q in (poly[n].tail, poly[n].head)]
        for i, (other, letters) in enumerate(out):
            c0, r0 = _circle(other)
            c1, r1 = _circle(pts)
            if math.dist(c0, c1) < r0 + r1 + 1.0:
                out[i] = ([*other, *pts], f"{letters}, {dt.letter}")
                break
        else:
            out.append((pts, dt.letter))
    return [(*_circle(pts), letters) for pts, letters in out]


def _circle(pts: Sequence[tuple[float, float]]) -> tuple[tuple[float, float], float]:
    cx = (min(q[0] for q in pts) + max(q[0] for q in pts)) / 2.0
    cy = (min(q[1] for q in pts) + max(q[1] for q in pts)) / 2.0
    r = max(DETAIL_CIRCLE_MM, *(math.hypot(q[0] - cx, q[1] - cy) + 1.5 for q in pts))
    return (cx, cy), r


def mark_detail(
    v: Viewport,
    c: tuple[float, float],
    r: float,
    letter: str,
    segs: Sequence[tuple[tuple[float, float], tuple[float, float]]] = (),
    bound: tuple[float, float, float, float] | None = None,
    circle: bool = True,
    taken: Sequence[tuple[float, float]] = (),
) -> tuple[float, float]:
    """Circle (thin) the spot of radius ``r`` mm round ``c`` (paper) and letter it on a short
    leader (ESKD выносной элемент): of the eight ways round the circle (up-right first), the
    one whose letter is farthest from the polygon's sides ``segs`` (paper), among those that
    keep the letter inside the view's ``bound`` (paper) where any does (CI: sixbar_coupler's
    "Ю1" 1 mm into the next plan's box). ``circle`` False: the circle is drawn already, one
    more letter on a leader of its own, none of the ways ``taken`` by its other letters nor
    next to them where another is free. Returns the way taken."""
    cx, cy = c
    k = v.scale.k
    if circle:
        v.circle(Vec(v.ox + (cx - v.at[0]) * k, v.oy - (cy - v.at[1]) * k), r * k,
                 "construction")  # fmt: skip
    ways = [(math.cos(math.radians(a)), -math.sin(math.radians(a))) for a in range(45, 405, 45)]
    if taken:
        # a way and its neighbours (45° on) are the letter's room: the next letter beyond
        near = [w for w in ways if all(w[0] * t[0] + w[1] * t[1] < WAY_NEAR for t in taken)]
        free = [w for w in ways if all(math.dist(w, t) > tol.REL_LENGTH for t in taken)]
        ways = near or free or ways
    half = text_width(letter, 3.5) / 2.0 + 1.0

    def middle(u: tuple[float, float]) -> tuple[float, float]:
        return (cx + u[0] * (r + 5.5), cy + u[1] * (r + 5.5))  # about the letter's middle

    def inside(u: tuple[float, float]) -> bool:
        if bound is None:
            return True
        (x, y), (x0, y0, x1, y1) = middle(u), bound
        return x0 <= x - half and x + half <= x1 and y0 <= y - 3.0 and y + 3.0 <= y1

    ways = [w for w in ways if inside(w)] or ways

    def clearance(u: tuple[float, float]) -> float:
        return min((_seg_dist(middle(u), a, b) for a, b in segs), default=math.inf)

    u = max(ways, key=lambda w: min(clearance(w), 6.0))  # 6 mm clear is clear enough
    edge = (cx + r * u[0], cy + r * u[1])
    leader = (edge[0] + 4.2 * u[0], edge[1] + 4.2 * u[1])
    v.sheet.add(Polyline((edge, leader), "construction"))
    v.d.label(leader, letter, 3.5, prefer=u, clear=0.5)
    return u


#: Two letters on one detail circle take ways round it whose cosine is under this (more than
#: 45° apart: two neighbouring ways put two letters 3.5 mm high side by side, touching).
WAY_NEAR = math.cos(math.radians(60.0))


def root_of(dt: Detail) -> Detail:
    """The detail taken from the plan whose spot ``dt`` shows at a finer μ_F (``dt`` itself
    where it is one)."""
    while dt.host is not None:
        dt = dt.host
    return dt


def _seg_dist(q: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """The distance (mm) from point q to segment ab (paper)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n2 = dx * dx + dy * dy
    t = 0.0 if n2 == 0.0 else max(0.0, min(1.0, ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / n2))
    return math.hypot(q[0] - a[0] - t * dx, q[1] - a[1] - t * dy)


#: The least radius (mm) of the thin circle that marks a polygon's detail.
DETAIL_CIRCLE_MM = 3.0
#: A polygon's largest vector is drawn at most this long at its reference μ_F (mm), at which
#: the room of its details is reckoned for the layout.
POLY_MM = 110.0
#: A detail is drawn at the coarsest μ_F of the series that draws its shortest vector at
#: least this long (mm; an arrow of two arrowheads, readable), never a finer one …
DETAIL_MM = SHORT_MM
#: … and its longest at most this long (mm): a detail copy is not drawn several times longer
#: than its plan's own vectors (review 8, item 3: the oscillator's G4 = 24 N at 59 mm in a
#: detail beside G5 = 64 N at 16 mm in its plan); what it then draws too short is named under
#: the plan's caption (one level: no detail is taken from a detail). Review 9, item 1: at 30 mm
#: the details named the shaper's G4, Φ4, Rτ34 and a compressor's given F_B instead of drawing
#: them (the polygon not closed on the sheet): a detail is an enlarged view (ESKD 2.305), its
#: vectors may outgrow the plan's; a closed polygon comes first.
DETAIL_MAX_MM = 60.0
#: A detail enlarges the view it is taken from at least this many times (a detail barely
#: larger than its polygon is not worth its room).
DETAIL_LEAST = 4.0
#: A detail is drawn no larger (mm) than its plan, or than this where the plan is smaller.
DETAIL_BOUND_MM = 40.0
#: The lines of the long vectors a detail joins are drawn this long (mm).
STUB_MM = 4.0
#: The room (mm) round a detail's drawing for its labels, and its caption's height.
DETAIL_PAD_MM = 4.0
DETAIL_CAPTION_H = 2.5
#: The lines under a detail's caption are this many caption heights apart.
DETAIL_LINES = 1.8
#: How much (mm² of the polygon's view per mm) a detail's distance from the spot it enlarges
#: weighs against the size of the view (:func:`place_details`).
DETAIL_NEAR = 100.0
#: The gap (mm) between a polygon and its details.
DETAIL_GAP_MM = 4.0
#: A thin polygon's vectors are drawn side by side this far apart (mm) …
OFFSET_MM = 2.5
#: … a polygon is thin when all of it lies within this (mm) of its longest vector's line.
THIN_MM = 1.2
#: A plan no wider than this share of its longest vector is a sliver …
SLIVER_SHARE = 0.125
#: … drawn with its longest vector at most this long (mm; a μ_F of the series draws it at
#: least half as long): its long sides side by side. A two-force plan (R₁₂ = −R₃₂, or two
#: reactions with a small load between) shows nothing its length could: it is the equality
#: it states, and the table gives |R|. A ТММ teacher accepts it as the two vectors side by
#: side, joined at their ends into a closed narrow figure, with the equality written under it
#: and its own μ_F in its caption (|R| can still be measured); drawn 90–100 mm it was a twin
#: line across its cell (review 7, item 4), so 30–60 mm.
SLIVER_MM = 60.0
#: Two vectors of a plan within this angle of each other …
LANE_ANGLE = math.radians(5.0)
#: … that run within THIN_MM of one another longer than this (mm) are drawn side by side.
LANE_OVERLAP_MM = 3.0
#: The passes of :func:`lanes` that move apart again the vectors still along one another.
LANE_PASSES = 2
#: A sliver's two long opposite vectors are drawn side by side this far apart (mm): one line
#: read as two superposed arrows (review 12, fix 2), a lane (:data:`OFFSET_MM`) as one smudged
#: twin line (review 9, fix 4); each a lane and a line's clearance (:data:`THIN_MM`) from the
#: loads' chain left on the plan's line between them.
SLIVER_LANE_MM = 2.0 * (OFFSET_MM + THIN_MM)


#: The Cyrillic capitals that read as Latin ones (a detail lettered with one reads as a point):
#: those drawn alike, and Б, Д, which differ from B, D by a stroke and are read by the same
#: name (review 7: tangent's detail "Д" beside its point "D").
_LATIN_LIKE = {
    chr(0x410 + i): c
    for i, c in zip((0, 1, 2, 4, 5, 10, 12, 13, 14, 16, 17, 18, 19, 21), "ABBDEKMHOPCTYX",
                    strict=True)
}  # fmt: skip


def detail_letters(used: Iterable[str] = ()) -> Iterator[str]:
    """The letters of a sheet's details in the language drawn (ESKD: capitals, those that
    read as digits or as other letters left out), none that is, or is drawn as, the first
    letter of a name in ``used`` (the sheet's points and forces), so that a detail never reads
    as a point; past the last, the letters again with a number (Б1, Г1, …)."""
    taken = {n[0].upper() for n in used if n}
    base = [c for c in WORDS("detail_letters") if not {c, _LATIN_LIKE.get(c)} & taken]
    yield from base
    for i in range(1, 100):
        yield from (f"{c}{i}" for c in base)


def short_runs(
    vectors: Sequence[PlanVector], limit: float, closed: bool = True, floor: float = 0.0
) -> list[list[str]]:
    """The runs (head to tail; round the polygon when ``closed``) of the vectors shorter than
    ``limit`` (and longer than round-off of zero, and than ``floor``: those a polygon leaves
    out as negligible): each is drawn enlarged in one detail."""
    vs = list(vectors)
    zero = max(tol.DERIVED * max((pv.magnitude for pv in vs), default=0.0), floor)
    small = [zero < pv.magnitude < limit for pv in vs]
    if not any(small):
        return []
    long = [not s and pv.magnitude > zero for s, pv in zip(small, vs, strict=True)]
    start = long.index(True) if closed and any(long) else 0  # a run never wraps past a long one
    runs: list[list[str]] = []
    cur: list[str] = []
    for i in range(len(vs)):
        j = (start + i) % len(vs)
        if small[j]:
            cur.append(vs[j].name)
        elif long[j] and cur:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    return runs


def detail_scale(k: float, m: float) -> Scale:
    """The μ_F of a detail that enlarges a polygon drawn at ``k`` about ``m`` times: the
    largest factor 1, 2, 2.5, 4, 5 × 10^n at most k/m."""
    return nice_below(k / m, 1.0)


@dataclass
class Detail:
    """An enlarged detail of a force polygon (ESKD выносной элемент): its ``run`` of short
    vectors head to tail at its own μ_F ``k`` (stated in its caption with its ``letter``),
    with the lines of the long vectors it joins; one level: every vector of the run is an
    arrow in it. ``slot``: where it is drawn, in the polygon's units (its caption's room
    ``cap`` at the top)."""

    run: tuple[str, ...]
    k: float
    letter: str
    box: Extent
    slot: Extent = (0.0, 0.0, 0.0, 0.0)
    cap: float = 0.0
    #: the vectors up to this magnitude are left out (negligible): no line of them is joined
    floor: float = 0.0
    #: the vectors of the run shorter than two arrowheads at ``k`` that no finer detail
    #: shows (past :data:`DETAIL_TIERS`): drawn as lines, listed with their values under
    #: the detail's caption
    listed: tuple[str, ...] = ()
    #: the detail whose short vectors this one shows at a finer μ_F (drawn as lines in that
    #: one, no circle there: this one's letter is on the plan's circle of that one's spot,
    #: :func:`root_of`); None: the first detail of its spot of the plan
    host: Detail | None = None
    #: its tier: 1 taken from the plan at the plan's details' μ_F, 2 at the next finer one
    #: (from a detail of tier 1, or from the plan where tier 1 showed nothing of its run), …
    tier: int = 1


def detail_k(mags: Sequence[float], k: float) -> float:
    """The μ_F of a detail of vectors of magnitudes ``mags`` taken from a polygon drawn at
    ``k``: the coarsest factor 1, 2, 2.5, 4, 5 × 10^n that draws the shortest at least
    :data:`DETAIL_MM` long, and enlarges the polygon at least :data:`DETAIL_LEAST` times."""
    return min(nice_below(min(mags), DETAIL_MM).k, detail_scale(k, DETAIL_LEAST).k)


def plan_details(
    poly: ForcePolygon,
    k_ref: float,
    letters: Iterator[str],
    floor: float = 0.0,
    bound: float = 0.0,
    dropped: list[str] | None = None,
) -> list[Detail]:
    """The details of ``poly`` drawn at μ_F ``k_ref``: one per run of its vectors shorter
    than two arrowheads there (:func:`regroup` makes it one run where the polygon's order
    allows), all at ONE μ_F (:func:`details_k`), as a view's insets are at one (review 7:
    plans with details at 4 / 0,5 / 0,05 / 1 N/mm read as four drawings). A run is never cut
    into pieces (each circle on the plan marks one run, lettered with one letter).

    One μ_F of details per plan (:data:`DETAIL_TIERS` = 1; review 14, fix 2: the knuckle
    press's group (4, 5), a sliver with six details at three more μ_F round one vertex; review
    12, item 1: the slotter's Ц → Ш → Я): a teacher reads a plan as one polygon at its μ_F and
    its details at one finer μ_F, each taken from the plan (its circle there, one letter),
    never from a detail; a detail joins the lines of the vectors its run is chained to, so the
    run ends on the sheet where the plan continues. Every reaction of the plan is an arrow of
    the plan itself at the plan's μ_F (:func:`main_arrows`; drawn in its detail too), so the
    plan's equation closes on the plan; a run of reactions only, each at least
    :data:`LISTED_MM` long on the plan, makes no detail. In the details a vector is an arrow
    where it is at least :data:`LISTED_MM` (one arrowhead) long; the shorter ones (a run
    spanning more than :data:`DETAIL_MAX_MM` / :data:`LISTED_MM`, or a detail held to its
    plan's size: loads and R^τ components under about 1,5 % of the plan's largest over the
    round's 39 files) are lines in it, :attr:`Detail.listed`: named with their values under
    the plan's caption (review 9 wanted every term an arrow, which took up to three tiers of
    details; review 14 ranks one μ_F above the arrows of loads of a few newtons). A run whose
    every vector would be listed makes no detail: its vectors are added to ``dropped`` (drawn
    as lines on the plan, named under its caption; where ``dropped`` is None, it is a detail
    all the same). With more tiers (:data:`DETAIL_TIERS` over 1) the listed vectors of a tier
    are drawn again in a detail beside it at the next finer μ_F, lettered on the same circle
    of the plan. The vectors up to ``floor`` (negligible) are in none. ``bound`` (mm, 0:
    none): no detail is drawn larger than that (its plan's size: a detail never outgrows its
    plan), its joined lines included.

    A sliver's loads (:func:`sliver_loads`: the vectors between its two balanced forces,
    drawn as one line) are one run however long, where a detail holds them.
    """
    limit = SHORT_MM * k_ref
    loads = sliver_loads(poly)
    if loads * DETAIL_LEAST <= DETAIL_MAX_MM * k_ref:  # a detail of them holds them
        limit = max(limit, loads)
    runs = _one_spot(poly, short_runs(poly.vectors, limit, floor=floor), k_ref)
    # a run of reactions only, each an arrow at least one arrowhead long on the plan, is
    # read there (:func:`main_arrows`): no detail repeats it (review 14: the knuckle press's
    # group (4, 5), a detail of R₀₅ alone beside its arrow)
    main = main_arrows(poly)
    runs = [
        run
        for run in runs
        if not all(n in main and poly[n].magnitude >= LISTED_MM * k_ref for n in run)
    ]
    if not runs:
        return []
    zero = max(_zero(poly), floor)
    inset = {n for run in runs for n in run}
    # the shortest arrow of the drawing a tier's details are taken from (mm): item 6
    shortest = min((pv.magnitude / k_ref for pv in poly.vectors
                    if pv.magnitude > zero and pv.name not in inset), default=0.0)  # fmt: skip
    todo: list[tuple[list[str], Detail | None]] = [(run, None) for run in runs]
    k_from = k_ref
    out: list[Detail] = []
    for tier in range(DETAIL_TIERS):
        if not todo:
            break
        last = tier == DETAIL_TIERS - 1
        boxes = [_bbox(q for n in run for q in (poly[n].tail, poly[n].head)) for run, _ in todo]
        kd = details_k(
            [[poly[n].magnitude for n in run if poly[n].magnitude > zero] for run, _ in todo],
            [max(b[2] - b[0], b[3] - b[1]) for b in boxes],
            k_from,
            bound,
            shortest,
            last,
        )
        nxt: list[tuple[list[str], Detail | None]] = []
        made: list[Detail] = []
        for (run, host), box in zip(todo, boxes, strict=True):
            # as details_k reckons it; in the last tier's (one μ_F, the plan's only detail
            # scale) an arrow one arrowhead long is drawn (a plan's short arrow, not named)
            least = (LISTED_MM if last else SHORT_MM) * kd * (1.0 - tol.REL_LENGTH)
            short = [n for n in run if zero < poly[n].magnitude < least]
            every = sum(poly[n].magnitude > zero for n in run)
            if len(short) == every and not last:  # nothing to show here: finer, same spot
                nxt.append((run, host))
                continue
            if len(short) == every and dropped is not None and host is None:
                dropped += short
                continue
            dt = Detail(tuple(run), kd, next(letters), box, floor=floor, host=host, tier=tier + 1)
            made.append(dt)
            if last:
                # (a reaction is an arrow however short, in its detail as on the plan)
                dt.listed = tuple(n for n in short if n not in main_arrows(poly))
            else:
                nxt += [(sub, dt) for sub in _one_spot(poly, _sub_runs(poly, run, short), kd)]
        out += made
        shortest = min((poly[n].magnitude / kd for dt in made for n in dt.run
                        if poly[n].magnitude >= SHORT_MM * kd * (1.0 - tol.REL_LENGTH)),
                       default=0.0)  # fmt: skip
        k_from = kd
        todo = nxt
    return out


def _sub_runs(poly: ForcePolygon, run: Sequence[str], short: Sequence[str]) -> list[list[str]]:
    """The runs (consecutive in ``run``) of its vectors ``short``, broken by the others (not
    zero) between them."""
    zero = _zero(poly)
    out: list[list[str]] = []
    cur: list[str] = []
    for n in run:
        if n in short:
            cur.append(n)
        elif poly[n].magnitude > zero and cur:
            out.append(cur)
            cur = []
    if cur:
        out.append(cur)
    return out


#: A plan's details go at most this many tiers deep (a detail of a detail, …). One: a plan
#: is one polygon at its μ_F with its details at ONE finer μ_F, one circle per spot (review
#: 14, fix 2: the knuckle press's group (4, 5), a 40 mm sliver with six details at three
#: more μ_F, 500, 100 and 10 N/mm, round one vertex; the walkbeam's group (2, 3) at 20, 4
#: and 0,5 N/mm; review 12 had three tiers, review 7 four drawings). Each tier spans
#: DETAIL_MAX_MM / DETAIL_MM ≈ 8.6 times in magnitude (LISTED_MM in the last: 17 times); a
#: vector shorter than that below the detail's shortest arrow (mostly under 1 % of the
#: plan's largest) is a line in it, named with its value under the plan's caption.
DETAIL_TIERS = 1
#: In the last tier's details (the plan's one detail μ_F) a vector is an arrow where it is
#: drawn at least one arrowhead long (mm): a short arrow, as the plan draws its own short
#: vectors outside its details; shorter ones are lines, named under the caption.
LISTED_MM = ARROW_LEN


def _over(ext: Extent, room: tuple[float, float], k: float) -> float:
    """How far (mm at μ_F ``k``) the extent ``ext`` outgrows ``room`` (model units)."""
    return max(ext[2] - ext[0] - room[0], ext[3] - ext[1] - room[1], 0.0) / k


def _one_spot(poly: ForcePolygon, runs: list[list[str]], k: float) -> list[list[str]]:
    """The runs of ``poly`` drawn at μ_F ``k`` with those whose circles on the plan would
    overlap (:func:`detail_spots`) made one, the vectors between them included: one spot of
    the plan is one detail, lettered with one letter (review 7: a circle lettered "П1, Ш1,
    Э1")."""
    names = list(poly.names)
    n = len(names)

    def circle(run: Sequence[str]) -> tuple[tuple[float, float], float]:
        return _circle([(q.x / k, q.y / k) for x in run for q in (poly[x].tail, poly[x].head)])

    out: list[list[str]] = []
    for run in runs:
        if out:
            (c0, r0), (c1, r1) = circle(out[-1]), circle(run)
            if math.dist(c0, c1) < r0 + r1 + 1.0:
                i, j = names.index(out[-1][-1]), names.index(run[0])
                out[-1] = [*out[-1], *(names[(i + 1 + t) % n] for t in range((j - i - 1) % n)),
                           *run]  # fmt: skip
                continue
        out.append(list(run))
    return out


def details_k(
    mags: Sequence[Sequence[float]],
    sizes: Sequence[float],
    k_ref: float,
    bound: float = 0.0,
    shortest: float = 0.0,
    last: bool = False,
) -> float:
    """The one μ_F of a plan's details (runs of magnitudes ``mags``, each spanning ``sizes``
    in plan units) taken from the plan drawn at ``k_ref``: :func:`detail_k` of all their
    vectors (the shortest at least :data:`DETAIL_MM`, at least :data:`DETAIL_LEAST` times
    the plan), made coarser where a run would then draw its longest vector over
    :data:`DETAIL_MAX_MM`, or outgrow ``bound`` mm (0: none) with its joined lines: the
    finest factor 1, 2, 2.5, 4, 5 × 10^n that keeps every run within both. Where that leaves
    some too short, the μ_F is the coarsest that still draws the others :data:`DETAIL_MM`
    long (review 8, item 3, the crusher's G4 = 147 N drawn 29 mm at 5 N/mm because
    R^τ34 = 17 N would have wanted 2 N/mm; at 10 N/mm G4 is 15 mm, Ф4 9 mm); those too short
    are drawn in a detail of the detail (:func:`plan_details`). In the ``last`` tier (one
    detail μ_F per plan, :data:`DETAIL_TIERS`) none is: the μ_F is the finest within both
    limits where that draws more of them at least :data:`LISTED_MM` long (fewer are named
    under the caption) than the coarser one would.

    Order of lengths (review 9, item 6: crank_rocker's detail drew Φ4 = 25 N 12.5 mm beside
    the plan's G5 = 108 N at 10.8 mm): where the coarsest factor that draws the shortest
    vector :data:`DETAIL_MM` long draws the longest no longer than ``shortest`` (mm, the
    shortest arrow of the drawing the details are taken from; 0: none), it is that factor,
    however little it enlarges: a detail's arrows then keep the order of the plan's.
    Otherwise the detail is at the finer μ_F its caption states."""
    every = [m for run in mags for m in run]
    plain = nice_below(min(every), DETAIL_MM).k
    if 0.0 < max(every) / plain <= shortest * (1.0 + tol.REL_LENGTH):
        readable = kd = plain
    else:
        readable = kd = detail_k(every, k_ref)
    for run, size in zip(mags, sizes, strict=True):
        kd = max(kd, nice_factor(max(run), DETAIL_MAX_MM, "F").k)
        room = bound - 2.0 * STUB_MM
        if bound > 0.0 and room > 0.0 and size > 0.0:
            kd = max(kd, nice_factor(size, room, "F").k)
    if kd > readable * (1.0 + tol.REL_LENGTH):
        shown = [m for m in every if m >= DETAIL_MM * kd * (1.0 - tol.REL_LENGTH)]
        if shown:
            coarse = max(kd, detail_k(shown, k_ref))

            def listed(k: float) -> int:
                return sum(m < LISTED_MM * k * (1.0 - tol.REL_LENGTH) for m in every)

            # the last tier keeps the finer one only where it draws more of them as arrows
            # (a detail larger for nothing pushed the clipper's link 4 plan to 24 mm)
            if not last or listed(coarse) <= listed(kd):
                kd = coarse
    return kd


def regroup(poly: ForcePolygon, k: float) -> ForcePolygon:
    """:func:`_regroup`, remembered (a sheet's layout asks it again for each arrangement)."""
    return _regroup(poly, k)


@functools.lru_cache(maxsize=256)
def _regroup(poly: ForcePolygon, k: float) -> ForcePolygon:
    """The polygon with its known loads laid off in the order that makes its vectors shorter
    than two arrowheads at μ_F ``k`` one run, where it can (a polygon may take its known
    forces in any order: only the closing of its unknowns is fixed): the unknowns (or the
    closing vector), the components of a reaction split in two (their resultant closes
    them) stay where they are, the other vectors take their places by magnitude, rising or
    falling, whichever leaves fewer runs (the polygon's own order on a tie). Before the runs
    comes the polygon not crossing itself (:func:`crossings` of its sides two arrowheads
    long): where no order by magnitude keeps it one run and uncrossed, its loads are laid
    off in every order (:data:`REGROUP_ALL`, :data:`REGROUP_LONGS`). A crossing that stays
    is inherent to the forces (the unknowns' places are fixed). The same vectors head to
    tail from the same pole; the polygon closes as before."""
    fixed = {n for n, _ in poly.solved} or {poly.vectors[-1].name} if poly.vectors else set()
    free = [i for i, pv in enumerate(poly.vectors)
            if pv.name not in fixed and _COMPONENT.fullmatch(pv.name) is None]  # fmt: skip
    if len(free) < 2:
        return poly
    limit = SHORT_MM * k

    def laid(ordered: Sequence[PlanVector]) -> ForcePolygon:
        vs = list(poly.vectors)
        for i, pv in zip(free, ordered, strict=True):
            vs[i] = pv
        out: list[PlanVector] = []
        tail = poly.pole
        for pv in vs:
            out.append(PlanVector(pv.name, tail, tail + pv.force))
            tail = out[-1].head
        return ForcePolygon(poly.pole, tuple(out), poly.solved)

    def key(cand: ForcePolygon) -> tuple[int, int]:
        # a polygon whose long sides cross reads worse than one with one detail more
        return crossings(cand, limit), len(short_runs(cand.vectors, limit))

    best = (key(poly), poly)
    for down in (False, True):
        cand = laid(sorted((poly.vectors[i] for i in free), key=lambda pv: pv.magnitude,
                           reverse=down))  # fmt: skip
        if key(cand) < best[0]:
            best = (key(cand), cand)
    longs = [poly.vectors[i] for i in free if poly.vectors[i].magnitude >= limit]
    if best[0] <= (0, 1) or len(longs) > REGROUP_LONGS:
        return best[1]
    # its long sides cross, or its short ones are apart: its loads in every order (ГОСТ,
    # textbook: any order of the known forces), or, too many for that, the long ones in
    # every order with the short ones one run among them
    shorts = sorted((poly.vectors[i] for i in free if poly.vectors[i].magnitude < limit),
                    key=lambda pv: pv.magnitude)  # fmt: skip
    if len(free) <= REGROUP_ALL:
        orders: Iterable[Sequence[PlanVector]] = itertools.permutations(
            poly.vectors[i] for i in free
        )
    else:
        orders = (
            [*perm[:at], *shorts, *perm[at:]]
            for perm in itertools.permutations(longs)
            for at in range(len(perm) + 1)
        )
    for order in orders:
        cand = laid(order)
        if key(cand) < best[0]:
            best = (key(cand), cand)
    return best[1]


#: A polygon whose long sides cross has its loads laid off in every order where it has at
#: most this many of them …
REGROUP_ALL = 6
#: … else its long loads in every order (at most this many), its short ones one run.
REGROUP_LONGS = 5


def crossings(poly: ForcePolygon, least: float = 0.0) -> int:
    """How many times the polygon's sides (its vectors not zero) cross one another: pairs of
    sides, both at least ``least`` long, that are not neighbours in the chain and cut each
    other inside both. A crossing within ``least`` of an end where the chain goes on with a
    side shorter than ``least`` is in that run's detail circle (short sides join there) and
    is not counted; at an end between two long sides only a touch (:data:`TOUCH_SHARE` of
    ``least``) is not a crossing (review 13: stephenson's group (2, 3), R₄₂ over R^n₁₂ 5 mm
    short of its head, where Ф₂ turned back across it, read as crossed sides)."""
    zero = _zero(poly)
    vs = [pv for pv in poly.vectors if pv.magnitude > zero]
    sides = [(pv.tail, pv.head, pv.magnitude >= least) for pv in vs]
    n = len(sides)
    touch = TOUCH_SHARE * least

    def room(i: int, j: int) -> float:
        """How far from its end towards side j (i ± 1) a crossing of side i is not one."""
        return least if not sides[j % n][2] else touch

    out = 0
    for i in range(n):
        a, b, long_i = sides[i]
        for j in range(i + 2, n):
            if (i == 0 and j == n - 1) or not (long_i and sides[j][2]):
                continue  # the closing side meets the first at the pole
            c, d, _ = sides[j]
            den = (b - a).cross(d - c)
            if abs(den) <= zero * zero:
                continue  # parallel: lanes draw them apart
            t = (c - a).cross(d - c) / den
            u = (c - a).cross(b - a) / den
            la, lc = (b - a).norm, (d - c).norm
            e0 = max(tol.DERIVED, room(i, i - 1) / la)
            e1 = max(tol.DERIVED, room(i, i + 1) / la)
            f0 = max(tol.DERIVED, room(j, j - 1) / lc)
            f1 = max(tol.DERIVED, room(j, j + 1) / lc)
            if e0 < t < 1.0 - e1 and f0 < u < 1.0 - f1:
                out += 1
    return out


#: Two long sides that cut one another within this (mm on the paper) of the end where they
#: meet a long side only touch there; :func:`crossings` takes it as this share of its
#: ``least`` (two arrowheads, :data:`SHORT_MM`).
TOUCH_MM = 1.0
TOUCH_SHARE = TOUCH_MM / SHORT_MM


def place_details(
    poly: ForcePolygon,
    details: Sequence[Detail],
    k: float,
    ext: Extent,
    room: tuple[float, float] | None = None,
    names: Mapping[str, str] | None = None,
    noted: Iterable[str] = (),
) -> Extent:
    """Give each detail its slot beside the polygon's extent ``ext`` (model units; their room
    in mm at the polygon's μ_F ``k``), one after another: in a corner of the polygon's box
    clear of its sides, or beside, below or above the polygon or a detail placed before; the
    spot that keeps the whole within ``room`` (model units: the view's box), then smallest.
    Returns the extent of the polygon with its details."""
    flat = list(details)
    if not flat:
        return ext
    pad, cap = DETAIL_PAD_MM * k, (DETAIL_CAPTION_H * 1.5 + 1.5) * k
    sizes = []
    for dt in flat:
        kd = dt.k
        pts = [q for n in dt.run for q in (poly[n].tail, poly[n].head)]
        pts += [b for _, _, b in _stubs(poly, dt, kd)]
        dt.box = _bbox(pts)
        bw, bh = (dt.box[2] - dt.box[0]) * k / kd, (dt.box[3] - dt.box[1]) * k / kd
        # its caption as wide as with the widest letter the sheet may give it, so that the
        # slots (and whether the whole keeps within ``room``) never hang on the letters drawn
        lines = [
            _detail_caption(dt, Scale(kd, "F"), LETTER_ROOM),
            *_detail_listed(poly, dt, names, noted),
        ]
        w = max(bw + 2.0 * pad,
                *(text_width(t, DETAIL_CAPTION_H) * k for t in lines))  # fmt: skip
        dt.cap = cap + (len(lines) - 1) * DETAIL_CAPTION_H * DETAIL_LINES * k
        sizes.append((w, bh + 2.0 * pad + dt.cap))
    gap = DETAIL_GAP_MM * k
    x0, y0, x1, y1 = ext
    segs = [(pv.tail, pv.head) for pv in poly.vectors]
    segs += [(r.tail, r.head) for r, _ in resultants(poly)]
    placed: list[Extent] = []
    union = ext
    for dt, (w, h) in zip(flat, sizes, strict=True):
        at = ((dt.box[0] + dt.box[2]) / 2.0, (dt.box[1] + dt.box[3]) / 2.0)  # its run's spot
        best: tuple[float, float, float, Extent] | None = None
        anchors = [ext, *placed]
        spots = [(x0, y1 - h), (x1 - w, y1 - h), (x0, y0), (x1 - w, y0)]  # the box's corners
        # beside the whole so far (always clear of it)
        spots += [(union[2] + 1.5 * gap, union[3] - h), (union[0], union[1] - 1.5 * gap - h)]
        for ax0, ay0, ax1, ay1 in anchors:
            spots += [
                (ax1 + gap, ay1 - h), (ax1 + gap, ay0), (ax0 - gap - w, ay1 - h),
                (ax0 - gap - w, ay0), (ax0, ay0 - gap - h), (ax1 - w, ay0 - gap - h),
                (ax0, ay1 + gap), (ax1 - w, ay1 + gap),
            ]  # fmt: skip
        for bx, by in spots:
            slot = (bx, by, bx + w, by + h)
            if any(_crosses(a, b, slot, gap) for a, b in segs):
                continue
            if any(_overlap(slot, q, gap) for q in placed):
                continue
            u = (min(union[0], slot[0]), min(union[1], slot[1]),
                 max(union[2], slot[2]), max(union[3], slot[3]))  # fmt: skip
            uw, uh = u[2] - u[0], u[3] - u[1]
            over = 0.0 if room is None else max(uw - room[0], 0.0) + max(uh - room[1], 0.0)
            # the smallest whole, and the detail near the spot it enlarges: moving it
            # DETAIL_NEAR mm farther weighs as much as a square mm more of the whole
            far = math.dist(at, (bx + w / 2.0, by + h / 2.0))
            key = (over, uw * uh + DETAIL_NEAR * far * k, max(uw, uh))
            if best is None or key < best[:3]:
                best = (*key, slot)
        assert best is not None  # a spot beside the whole is always free
        dt.slot = best[3]
        placed.append(best[3])
        union = (min(union[0], dt.slot[0]), min(union[1], dt.slot[1]),
                 max(union[2], dt.slot[2]), max(union[3], dt.slot[3]))  # fmt: skip
    return union


def _overlap(a: Extent, b: Extent, gap: float) -> bool:
    """Whether two boxes come closer than ``gap``."""
    return a[0] < b[2] + gap and b[0] < a[2] + gap and a[1] < b[3] + gap and b[1] < a[3] + gap


def _crosses(a: Vec, b: Vec, box: Extent, clear: float) -> bool:
    """Whether segment ab comes within ``clear`` of the box (Liang–Barsky on the grown box)."""
    x0, y0, x1, y1 = box[0] - clear, box[1] - clear, box[2] + clear, box[3] + clear
    t0, t1 = 0.0, 1.0
    d = b - a
    for p, q in ((-d.x, a.x - x0), (d.x, x1 - a.x), (-d.y, a.y - y0), (d.y, y1 - a.y)):
        if p == 0.0:
            if q < 0.0:
                return False
        else:
            t = q / p
            if p < 0.0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return False
    return True


def _detail_caption(dt: Detail, sc: Scale, letter: str | None = None) -> str:
    """A detail's caption: its letter (or ``letter`` in its place) and μ_F."""
    return f"{dt.letter if letter is None else letter} ({scale_text(sc)})"


#: The room of a detail's letter in its caption: a letter at least as wide as any of
#: :func:`detail_letters` with a two-digit number (the detail is placed before it is lettered).
LETTER_ROOM = "W99"


def _detail_listed(
    poly: ForcePolygon,
    dt: Detail,
    names: Mapping[str, str] | None = None,
    noted: Iterable[str] = (),
) -> list[str]:
    """The line under a detail's caption that lists the vectors of its run too short to
    draw at its μ_F, with their values (none: no line; nor for those ``noted``, named under
    the plan's caption: :func:`listed_items`)."""
    left = [n for n in dt.listed if n not in set(noted)]
    if not left:
        return []
    return [WORDS("detail_listed", items=listed_items(poly, left, names), mm=num(LISTED_MM))]


def listed_items(
    poly: ForcePolygon, listed: Sequence[str], names: Mapping[str, str] | None = None
) -> str:
    """The vectors ``listed`` (too short to draw in a detail), each with its value."""
    unit = WORDS("unit.N")
    return ", ".join(f"{(names or {}).get(n, n)} = {num(poly[n].magnitude)} {unit}"
                     for n in listed)  # fmt: skip


def _stubs(poly: ForcePolygon, dt: Detail, kd: float) -> list[tuple[PlanVector, Vec, Vec]]:
    """The lines (vector, from, to; :data:`STUB_MM` long at the detail's μ_F ``kd``) of the
    long vectors a detail's run joins, before its first and after its last."""
    order = list(poly.names)
    zero = max(_zero(poly), dt.floor)
    i, j = order.index(dt.run[0]), order.index(dt.run[-1])
    n = len(order)
    before = next(poly.vectors[(i - s) % n] for s in range(1, n + 1)
                  if poly.vectors[(i - s) % n].magnitude > zero)  # fmt: skip
    after = next(poly.vectors[(j + s) % n] for s in range(1, n + 1)
                 if poly.vectors[(j + s) % n].magnitude > zero)  # fmt: skip
    out = []
    for pv, q, sign in ((before, poly[dt.run[0]].tail, -1.0), (after, poly[dt.run[-1]].head, 1.0)):
        if pv.name not in dt.run:
            out.append((pv, q, q + (pv.head - pv.tail).unit() * (sign * STUB_MM * kd)))
    return out


def draw_detail(
    v: Viewport,
    poly: ForcePolygon,
    dt: Detail,
    names: Mapping[str, str] | None = None,
    found: Iterable[str] = (),
    height: float = 2.5,
    others: Sequence[Detail] = (),
    noted: Iterable[str] = (),
) -> None:
    """Draw detail ``dt`` of ``poly`` in its slot of the polygon's viewport ``v``: its run at
    its μ_F, captioned with its letter and μ_F (and the vectors too short in it, but those
    ``noted`` under the plan's caption), the lines of the long vectors it joins (a
    vector in another of ``others``, the plan's details, lettered with that one's letter;
    the others unnamed: the plan names them). The runs of the details of ``others`` that
    show its short vectors at a finer μ_F (:attr:`Detail.host`) are lines in it: those
    details are taken from the same spot of the plan, lettered on its circle there (one
    detail level, review 12: never a circle on a detail)."""
    sc = Scale(dt.k, "F")
    sx0, sy0, sx1, sy1 = dt.slot
    names = names or {}
    found = set(found)
    top = v.p((sx0, sy1))
    lines = [_detail_caption(dt, sc), *_detail_listed(poly, dt, names, noted)]
    for i, line in enumerate(lines):
        v.d.text(line, (top[0], top[1] + DETAIL_CAPTION_H * (1.0 + DETAIL_LINES * i)),
                 DETAIL_CAPTION_H)  # fmt: skip
    at = v.p(((sx0 + sx1) / 2.0, (sy0 + sy1 - dt.cap) / 2.0))
    bx0, by0, bx1, by1 = dt.box
    sub = Viewport(v.d, sc, (bx0 + bx1) / 2.0, (by0 + by1) / 2.0, at)
    # the lines of the vectors it joins are not named again (a force appears once in a
    # plan: the plan names them by the circle): one drawn in another detail (a run cut in
    # two) is lettered with that detail's letter
    elsewhere = {n: d.letter for d in others if d is not dt for n in d.run}
    run = [poly[n] for n in dt.run if poly[n].magnitude > _zero(poly)]
    shift = lanes(sc.k, run)  # those along one another side by side, tied where they meet
    none = Vec(0.0, 0.0)
    for pv, a, b in _stubs(poly, dt, sc.k):
        # from the end of the run's first (or last) vector, where lanes moved it
        first = (a - poly[dt.run[0]].tail).norm <= (a - poly[dt.run[-1]].head).norm
        s = shift.get(run[0 if first else -1].name, none) if run else none
        sub.seg(a + s, b + s, "construction")
        if pv.name in elsewhere:
            sub.label(b + s, elsewhere[pv.name], height, clear=0.5)
    # the runs drawn again at a finer μ_F (the details beside it taken from its spot of the
    # plan, lettered on the plan's circle): lines here, never a circle on a detail
    subs = [d for d in others if d.host is dt]
    finer = {n for d in subs for n in d.run}
    for i, pv in enumerate(run):
        s = shift.get(pv.name, Vec(0.0, 0.0))
        if i + 1 < len(run) and (s - shift.get(run[i + 1].name, Vec(0.0, 0.0))).norm > 0.0:
            sub.seg(pv.head + s, run[i + 1].tail + shift.get(run[i + 1].name, Vec(0.0, 0.0)),
                    "construction")  # fmt: skip
        n = pv.name
        tail, head = pv.tail + s, pv.head + s
        if n in dt.listed or n in finer:  # too short at its μ_F: its line (listed, or finer)
            sub.seg(tail, head, "construction")
            continue
        sub.arrow(tail, head, "result" if n in found else "vector")
        prefer = (s.unit().x, s.unit().y) if s.norm > 0.0 else _outward(poly, tail, head, False)
        sub.label((tail + head) * 0.5, names.get(n, n), height, prefer=prefer, clear=0.5)


def _slot_sides(
    v: Viewport, details: Sequence[Detail]
) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The sides (paper) of the slots of ``details`` drawn through ``v``: a detail's letter is
    kept clear of them as of the polygon's sides (review 9: "П2" on its leader over the
    caption "П2 (μF = 4 Н/мм)" of the detail under the circle)."""
    out = []
    for dt in details:
        x0, y0, x1, y1 = dt.slot
        if x1 <= x0 or y1 <= y0:
            continue
        a, b, c, e = v.p((x0, y0)), v.p((x1, y0)), v.p((x1, y1)), v.p((x0, y1))
        out += [(a, b), (b, c), (c, e), (e, a)]
    return out


class Polygon(View):
    """Force polygons at one μ_F (a factor 1, 2, 2.5, 4, 5 × 10^n) in one viewport: the
    first in ``layers`` drawn first (a frictionless polygon dashed under the one with friction).
    Each layer is (polygon, role); ``names``, ``found``, ``inward`` as :func:`draw_polygon`.
    ``detail``: the last layer's known loads are laid off in the order that makes its vectors
    too short for the polygon's μ_F one run (:func:`regroup`), and those vectors are drawn
    enlarged in lettered :attr:`details` of one level in the same view, near the circle that
    marks them, in the room the polygon leaves free or beside it (each at its own μ_F,
    :func:`detail_k`, stated in its caption; letters from ``letters``); their room is reckoned
    at the μ_F of ``ref`` (default: the one that draws the largest vector at most
    :data:`POLY_MM` long), within its room (w, h mm) where they can, and they are planned
    again at the μ_F drawn, within the box drawn. A
    polygon along one line is drawn with its vectors side by side
    (:func:`draw_polygon`'s ``thin``). ``negligible`` (share, note): with details, the vectors
    of the last layer under that share of its largest (not zero) are neither drawn nor
    detailed (a detail of them would be at an absurd μ_F); the note (given their names) says
    so on a line under the caption (:attr:`omitted`)."""

    def __init__(
        self,
        *layers: ForcePolygon | tuple[ForcePolygon, str],
        names: Mapping[str, str] | None = None,
        found: Iterable[str] | None = None,
        inward: Iterable[str] = (),
        label_height: float = 2.5,
        detail: bool = False,
        letters: Iterator[str] | None = None,
        ref: tuple[float, tuple[float, float]] | None = None,
        negligible: tuple[float, Callable[[Sequence[str]], str]] | None = None,
        **kw: Any,
    ) -> None:
        kw.setdefault("title", WORDS("force_polygon"))
        kw.setdefault("quantity", "F")
        kw.setdefault("series", "nice")
        kw.setdefault("margin", 6.0)
        super().__init__(**kw)
        self.layers = [lay if isinstance(lay, tuple) else (lay, "vector") for lay in layers]
        self.names = names
        self.found = None if found is None else set(found)
        self.inward = tuple(inward)
        self.label_height = label_height
        self.points: list[str] = []
        self.details: list[Detail] = []
        self.thin = False
        self._ext = _bbox(
            q for poly, _ in self.layers for pv in poly.vectors for q in (pv.tail, pv.head)
        )
        self.detail = detail and bool(self.layers)
        self.letters = letters
        self.k_ref = 1.0
        #: the names of the last layer's vectors left out as negligible, the note naming them
        self.omitted: list[str] = []
        self.note = ""
        self.floor = 0.0
        #: the longest vector drawn at most this long (mm; 0: as placed): a sliver's cap
        self.longest_mm = 0.0
        #: whether the vectors too short in the details are named on a line under the
        #: caption (:attr:`noted`; where none was at the reference μ_F, under a detail's)
        self.listed_line = False
        self.noted: list[str] = []
        #: the vectors of runs too short even at the details' μ_F (no detail of them): lines
        self.lined: list[str] = []
        if self.detail and negligible is not None:
            vs = self.layers[-1][0].vectors
            big = max((pv.magnitude for pv in vs), default=0.0)
            zero = tol.DERIVED * big
            self.floor = negligible[0] * big
            self.omitted = [pv.name for pv in vs if zero < pv.magnitude <= self.floor]
            if self.omitted:
                self.note = negligible[1]([(names or {}).get(n, n) for n in self.omitted])
        if self.detail:
            # the room of the details as at the reference μ_F (they are planned again, and
            # lettered, at the μ_F the layout chooses)
            big = max((pv.magnitude for pv in self.layers[-1][0].vectors), default=0.0)
            if big > 0.0:
                k_ref, room = ref or (nice_factor(big, POLY_MM, "F").k, None)
                self.k_ref = k_ref
                # its known forces in the order that keeps its short vectors one run
                last, role = self.layers[-1]
                self.layers[-1] = (regroup(last, k_ref), role)

                # the room given is the box's less its caption (:meth:`note_room` not counted
                # off): the lines this plan adds under its caption take their share of it
                def within() -> tuple[float, float] | None:
                    if room is None:
                        return None
                    return room[0] * k_ref, max(room[1] - self.note_room(), 0.0) * k_ref

                self.details, self.thin, self._ext = self._with_details(k_ref, iter(_ANY), within())
                if self._lists(k_ref):
                    # what the details cannot show named under the plan, as a view names
                    # what its insets leave out (review 7, item 4): never a second scale
                    self.listed_line = True
                    self.details, self.thin, self._ext = self._with_details(
                        k_ref, iter(_ANY), within()
                    )

    def _lists(self, k_ref: float) -> bool:
        """Whether the plan's details leave vectors too short to draw (:attr:`Detail.listed`)
        at ``k_ref`` or at the coarser μ_F a layout may draw it at (up to :data:`LIST_SPAN`
        times): the line under the caption that names them is reserved before the layout."""
        poly = self.layers[-1][0]
        x0, y0, x1, y1 = _bbox(q for pv in poly.vectors for q in (pv.tail, pv.head))
        k = k_ref
        while k <= LIST_SPAN * k_ref * (1.0 + tol.REL_LENGTH):
            bound = max(max(x1 - x0, y1 - y0) / k, DETAIL_BOUND_MM)
            dropped: list[str] = []
            details = plan_details(poly, k, iter(_ANY), self.floor, bound, dropped)
            if dropped or any(dt.listed for dt in details):
                return True
            k = nice_factor(k * (1.0 + NICE_STEP), 1.0, "F").k
        return False

    def _with_details(
        self, k: float, letters: Iterator[str], room: tuple[float, float] | None = None
    ) -> tuple[list[Detail], bool, Extent]:
        """The details, thinness and extent (with the details' slots) of the polygon at
        μ_F ``k``. Where the details at their μ_F leave the whole larger than ``room`` and a
        coarser one fits them in the room the plan leaves free beside or under it, at that
        one (the vectors it makes too short are named under the caption): a detail never
        pushes its plan to a coarser μ_F than the plan's box holds (the crusher's group
        (4, 5): a detail of G4, Ф4 at 2,5 N/mm, 72 mm high, under a plan 99 mm high in a
        162 mm box; drawn at 4 N/mm it fits)."""
        poly = self.layers[-1][0]
        x0, y0, x1, y1 = _bbox(q for pv in poly.vectors for q in (pv.tail, pv.head))
        # a detail no larger than its plan as drawn (nor than DETAIL_BOUND_MM)
        bound = max(max(x1 - x0, y1 - y0) / k, DETAIL_BOUND_MM)
        thin = len(self.layers) == 1 and is_thin(poly, k)
        if thin:  # the room of the vectors side by side (their labels in the margin)
            grow = (len(poly.vectors) - 1) * OFFSET_MM / 2.0 * k
            x0, y0, x1, y1 = x0 - grow, y0 - grow, x1 + grow, y1 + grow
        for poly2, _ in self.layers[:-1]:
            b = _bbox(q for pv in poly2.vectors for q in (pv.tail, pv.head))
            x0, y0, x1, y1 = min(x0, b[0]), min(y0, b[1]), max(x1, b[2]), max(y1, b[3])
        plan = (x0, y0, x1, y1)
        if room is not None:
            _, ext = self._placed(k, iter(_ANY), bound, plan, room)
            lined = len(self.lined)
            # the room free beside or under the plan, less a detail's slot round its run
            free = max(room[0] - (x1 - x0), room[1] - (y1 - y0)) / k
            cap = DETAIL_CAPTION_H * 1.5 + 1.5 + DETAIL_CAPTION_H * DETAIL_LINES
            tight = free - 2.0 * DETAIL_PAD_MM - cap - DETAIL_GAP_MM
            if _over(ext, room, k) > 0.0 and 2.0 * STUB_MM + DETAIL_MM < tight < bound:
                _, ext2 = self._placed(k, iter(_ANY), tight, plan, room)
                # at the cost of a vector drawn only where the plan's one detail μ_F names
                # it (round 14: a plan drawn half as large for a 0,2 % vector's arrow); not
                # where it leaves a run with no detail (review 9, item 1: sixbar_coupler's
                # group (4, 5) named all four of its short vectors, no detail of them)
                kept = len(self.lined) <= lined
                if _over(ext2, room, k) < _over(ext, room, k) and kept:
                    bound = tight
        details, ext = self._placed(k, letters, bound, plan, room)
        return details, thin, ext

    def _placed(
        self,
        k: float,
        letters: Iterator[str],
        bound: float,
        plan: Extent,
        room: tuple[float, float] | None,
    ) -> tuple[list[Detail], Extent]:
        """The details of the polygon at μ_F ``k``, none larger than ``bound`` (mm), placed
        round its extent ``plan`` within ``room``, and the whole's extent."""
        poly = self.layers[-1][0]
        dropped: list[str] = []
        # a run with nothing to show makes no detail where the line under the caption is kept
        details = plan_details(poly, k, letters, self.floor, bound,
                               dropped if self.listed_line else None)  # fmt: skip
        self.noted = [n for dt in details for n in dt.listed] if self.listed_line else []
        self.lined = dropped
        ext = place_details(poly, details, k, plan, room, self.names, self.noted)
        return details, ext

    def extent(self) -> Extent | None:
        return self._ext

    def drawn_k(self, k: float) -> float:
        """The μ_F the polygon is drawn at where it is placed at ``k``: ``k``, or, where
        :attr:`longest_mm` caps it (a sliver: :func:`is_sliver`), the finest factor of the
        series that draws its longest vector no longer than that, as its caption states."""
        if self.longest_mm <= 0.0 or not (self.show_scale and self.title):
            return k
        big = max((pv.magnitude for poly, _ in self.layers for pv in poly.vectors), default=0.0)
        if big <= 0.0 or big / k <= self.longest_mm:
            return k
        return max(k, nice_factor(big, self.longest_mm, "F").k)

    def caption(self, scale: Scale | None) -> str:
        if scale is not None:
            scale = Scale(self.drawn_k(scale.k), scale.q)
        return super().caption(scale)

    def title_room(self) -> float:
        return super().title_room() + self.note_room()

    def note_room(self) -> float:
        """The height (mm) of the lines under the caption (the note of the vectors left out,
        the line naming what the details cannot show)."""
        lines = bool(self.note) + (self.note_lines if self.listed_line else 0)
        return NOTE_H * TITLE_LEAD * lines + NOTE_GAP if lines else 0.0

    def listed_lines(self, width: float) -> list[str]:
        """The line naming what the details cannot show, as drawn in a box ``width`` mm wide:
        with the vectors' values where it fits on one line, else without them (their values
        are in the table), broken at spaces into lines of about equal width where even that
        is wider than the box (review 14's sixbar-2013-6: 100 mm in an 85 mm box)."""
        if not (self.noted or self.lined):
            return []
        note = self._listed_note()
        if text_width(note, NOTE_H) > width:
            note = self._listed_note(values=False)
        return title_text_lines(note, width, NOTE_H)

    def note_lines_in(self, width: float) -> int:
        """How many lines the listed line takes in a box ``width`` mm wide (the layout gives
        it that room under the caption and lays the sheet out again where it grew)."""
        return len(self.listed_lines(width)) if self.listed_line else 0

    def spill(self, k: float, inner: Extent) -> float:
        """How far (mm) the polygon with its details, planned again at the μ_F ``k`` it is
        placed at (as :meth:`draw` does), would reach out of the box ``inner`` (sheet mm) it is
        centred in: 0 where it keeps within. Its extent was reckoned at the reference μ_F, and
        a detail keeps its size in mm at any μ_F: at a coarser one it takes more of the room."""
        if not self.detail:
            return 0.0
        k = self.drawn_k(k)
        w, h = inner[2] - inner[0], inner[3] - inner[1]
        _, _, ext = self._with_details(k, iter(_ANY), (w * k, h * k))
        return max((ext[2] - ext[0]) / k - w, (ext[3] - ext[1]) / k - h, 0.0)

    def lengths(self) -> Sequence[float]:
        out = []
        inset = {n for dt in self.details for n in dt.run} | set(self.omitted)
        for poly, _ in self.layers:
            out += [pv.magnitude for pv in poly.vectors if pv.name not in inset]
        for dt in self.details:
            # drawn |F|/k_d mm long in its detail: |F|·k_ref/k_d at the reference μ_F
            out += [self.layers[-1][0][n].magnitude * self.k_ref / dt.k for n in dt.run]
        return out

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        k = self.drawn_k(v.scale.k)
        short = k != v.scale.k
        if short:  # a sliver drawn short at the μ_F its caption states
            v = Viewport(d, Scale(k, v.scale.q), v.ox, v.oy, v.at)
            at.viewport = v
        if self.detail:
            # the details planned and placed again for the μ_F drawn (their run, their room
            # in mm), lettered in the order drawn, the whole centred in the box
            letters = self.letters if self.letters is not None else detail_letters()
            x0, y0, x1, y1 = at.inner
            room = ((x1 - x0) * v.scale.k, (y1 - y0) * v.scale.k)
            self.details, self.thin, ext = self._with_details(v.scale.k, letters, room)
            centre = ((ext[0] + ext[2]) / 2.0, (ext[1] + ext[3]) / 2.0)
            where = v.at
            half = (ext[3] - ext[1]) / v.scale.k / 2.0
            if short:  # drawn short: under its caption, not in the middle of its cell
                where = (v.at[0], min(v.at[1], y0 + half))
            if 2.0 * half > y1 - y0:  # taller than its cell: never over its own caption
                where = (v.at[0], y0 + half)
            v = Viewport(d, v.scale, centre[0], centre[1], where)
            at.viewport = v
        notes = [self.note] if self.note else []
        # what the details cannot show, on lines of its own
        notes += self.listed_lines(at.box[2] - at.box[0])
        lines = (self.title_lines - 1) * TITLE_SPACING
        for i, note in enumerate(notes):  # each on a line of its own under the caption
            top = at.box[1] + self.title_height * (TITLE_LEAD + lines) + NOTE_H + NOTE_GAP
            d.text(note, (at.box[0], top + i * NOTE_H * TITLE_LEAD), NOTE_H)
        for i, (poly, role) in enumerate(self.layers):
            last = i == len(self.layers) - 1
            self.points += draw_polygon(
                v, poly, self.names, role, self.found, self.inward, self.label_height,
                self.details if last else (), self.thin and last,
                self.omitted if last else (), self.lined if last else (), bound=at.box,
            )  # fmt: skip
        if self.details:
            poly = self.layers[-1][0]
            found = self.found if self.found is not None else {n for n, _ in poly.solved}
            for dt in self.details:
                draw_detail(v, poly, dt, self.names, found, self.label_height, self.details,
                            self.noted)  # fmt: skip

    def _listed_note(self, values: bool = True) -> str:
        """The line under the caption that names the vectors too short in the plan's
        details (at their one μ_F), with their ``values``, and the letters of their details."""
        poly = self.layers[-1][0]

        def items(names: Sequence[str]) -> str:
            if values:
                return listed_items(poly, names, self.names)
            return ", ".join((self.names or {}).get(n, n) for n in names)

        if self.lined:  # too short for a detail at the plan's one detail μ_F: lines on the plan
            return WORDS("plan_lined", mm=num(LISTED_MM), items=items([*self.noted, *self.lined]))
        letters = ", ".join(dt.letter for dt in self.details if dt.listed)
        many = sum(bool(dt.listed) for dt in self.details) > 1
        key = "plan_listed_many" if many else "plan_listed"
        if len(self.noted) == 1:
            key += "_one"
        return WORDS(key, letters=letters, mm=num(LISTED_MM), items=items(self.noted))


#: The μ_F a plan may be drawn at, as a multiple of its reference μ_F, whose details'
#: vectors too short to draw reserve their line under its caption (:meth:`Polygon._lists`) …
LIST_SPAN = 8.0
#: … tried factor by factor of the series (the next above k(1 + NICE_STEP)).
NICE_STEP = 0.01
#: The height (mm) of the line under a polygon's caption that names the vectors left out.
NOTE_H = 2.5
#: … set this much (mm) lower, clear of the caption's subscripts (μ_F).
NOTE_GAP = 0.6
#: The letters of the details while their room is reckoned (those drawn come from the sheet's).
_ANY = "W" * 99


# --- diagrams -------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Curve:
    """A curve of a diagram: data ``xs``, ``ys``, its role; ``points`` marks the samples;
    ``label`` (markup) names it at its end (by the label placer)."""

    xs: npt.ArrayLike
    ys: npt.ArrayLike
    role: str = "result"
    points: bool = False
    label: str = ""


@dataclass(frozen=True)
class AxisSpec:
    """An axis of a :class:`Diagram` before its factor is known: symbol and unit (markup), the
    factor's subscript, a fixed range (else the curves'), a fixed tick step."""

    symbol: str
    unit: str
    name: str = ""
    lo: float | None = None
    hi: float | None = None
    tick: float = 0.0


class Diagram(View):
    """A diagram y(x) filling its box: each axis takes the smallest factor 1, 2, 2.5, 4,
    5 × 10^n that puts its range into the room, and the factors are written at the box's top
    right. ``extra(graph)`` draws more on the graph (spans, hatching, labelled points).
    ``zero``: the y range always takes in 0 (else only the curves' range or the spec's)."""

    #: Room (mm) left of the y axis for its tick values, and under the x axis for its values
    #: and symbol, and above the y axis's arrow for its symbol.
    LEFT = 14.0
    BELOW = 12.0
    ABOVE = 10.0
    RIGHT = 12.0
    #: The height (mm) of a curve's name, and the least gap (mm) between two curves' ends
    #: at which each is named at its end.
    LABEL_H = 2.5
    LABEL_GAP = 6.0  # curves farther apart than this at their ends are named there

    def __init__(
        self,
        x: AxisSpec,
        y: AxisSpec,
        curves: Sequence[Curve],
        extra: Callable[[Graph], None] | None = None,
        least: tuple[float, float] = (80.0, 45.0),
        prefer: tuple[float, float] = (240.0, 110.0),
        zero: bool = True,
        marks: Sequence[tuple[float, str]] = (),
        **kw: Any,
    ) -> None:
        kw.setdefault("margin", 2.0)
        super().__init__(**kw)
        self.zero = zero
        #: (x, markup) written in a row under the x axis's values (the numbered positions)
        self.marks = list(marks)
        self.x, self.y = x, y
        self.curves = list(curves)
        self.extra = extra
        self.least, self.prefer = least, prefer
        self.graph: Graph | None = None

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        return self.least, self.prefer

    def title_room(self) -> float:
        """The title's line, and one more for the factors under a long title."""
        base = super().title_room()
        return base + 4.0 if self.title else base

    def _range(self, spec: AxisSpec, which: int) -> tuple[float, float]:
        key = f"range{which}"
        if key not in self._memo:
            self._memo[key] = self._range_of(spec, which)
        return self._memo[key]  # type: ignore[no-any-return]

    def _range_of(self, spec: AxisSpec, which: int) -> tuple[float, float]:
        vals = [np.asarray(c.xs if which == 0 else c.ys, dtype=np.float64) for c in self.curves]
        lo = spec.lo if spec.lo is not None else min(float(a.min()) for a in vals)
        hi = spec.hi if spec.hi is not None else max(float(a.max()) for a in vals)
        return (min(lo, 0.0), max(hi, 0.0)) if self.zero or which == 0 else (lo, hi)

    def axes(self, w: float, h: float) -> tuple[Axis, Axis]:
        """The two axes fitted to a room of w × h mm."""
        room_x = max(w - self.LEFT - self.RIGHT, 1.0)
        room_y = max(h - self.BELOW - self.ABOVE, 1.0)
        xlo, xhi = self._range(self.x, 0)
        ylo, yhi = self._range(self.y, 1)
        ax = Axis(
            self.x.symbol, self.x.unit, xlo, xhi,
            nice_step(max(xhi - xlo, sys.float_info.min) / room_x),
            self.x.name or self.x.symbol, self.x.tick,
        )  # fmt: skip
        ay = Axis.fit(self.y.symbol, self.y.unit, ylo, yhi, room_y, self.y.name)
        if self.y.tick:
            ay = ay.with_tick(self.y.tick)
        return ax, ay

    def used(self, w: float, h: float) -> tuple[float, float]:
        if w <= self.LEFT + self.RIGHT or h <= self.BELOW + self.ABOVE:
            return 0.0, 0.0
        ax, ay = self.axes(w, h)
        return (
            ax.mm(ax.hi - ax.lo) + self.LEFT + self.RIGHT,
            ay.mm(ay.hi - ay.lo) + self.BELOW + self.ABOVE,
        )

    def draw(self, d: Drawing, at: Placed) -> None:
        x0, y0, x1, y1 = at.inner
        ax, ay = self.axes(x1 - x0, y1 - y0)
        origin = (x0 + self.LEFT, y0 + self.ABOVE + ay.mm(ay.hi - ay.zero))
        gr = Graph(d, ax, ay, origin)
        gr.axes(current(), tick_labels=True)
        for c in self.curves:
            gr.curve(c.xs, c.ys, c.role)
            if c.points:
                for xx, yy in zip(np.asarray(c.xs), np.asarray(c.ys), strict=True):
                    gr.point(float(xx), float(yy))
        bottom = max(gr.at[1], gr.box[3]) + 1.5 + 2.5 + 0.8 + 1.2 + MARK_H
        right_of_last = -math.inf
        for xx, mark in self.marks:
            px = gr.p(xx, ay.zero)[0]
            half = text_width(mark, MARK_H) / 2.0
            if px - half >= right_of_last + 1.0:
                d.text(mark, (px, bottom), MARK_H, anchor="centre")
                right_of_last = px + half
        for c, (xx, yy), up in self._label_points(ay):
            d.label(gr.p(xx, yy), c.label, self.LABEL_H, prefer=(0.3, -1.0 if up else 1.0),
                    clear=0.5)  # fmt: skip
        # the factors: right of the title, or on a line of their own under a long title
        factors = f"{ay.factor_text(current())};  {ax.factor_text(current())}"
        right = min(at.box[2], x0 + self.used(x1 - x0, y1 - y0)[0])
        base = at.box[1] + self.title_height
        if (
            self.title
            and text_width(self.title, self.title_height) + text_width(factors, 2.5) + 5.0
            > right - at.box[0]
        ):
            base = at.box[1] + super().title_room() + 2.5
        d.text(factors, (right, base), 2.5, anchor="right")
        if self.extra is not None:
            self.extra(gr)
        self.graph = gr

    def _label_points(self, ay: Axis) -> list[tuple[Curve, tuple[float, float], bool]]:
        """Where each labelled curve is named: at its end, or, where other labelled curves
        end near it (a drive's work meeting the resistances' at the cycle's end), at the
        point of its last :data:`LABEL_SPAN` of x farthest (on the paper) from theirs; and
        whether above it (the side away from the nearest other curve)."""
        named = [c for c in self.curves if c.label]
        out = []
        for c in named:
            xs = np.asarray(c.xs, dtype=np.float64)
            ys = np.asarray(c.ys, dtype=np.float64)
            others = [o for o in named if o is not c]
            if not others:
                out.append((c, (float(xs[-1]), float(ys[-1])), True))
                continue
            span = LABEL_SPAN * (float(xs.max()) - float(xs.min()))
            k = np.flatnonzero(np.abs(xs - xs[-1]) <= span)
            diff = np.array(
                [
                    ys[k] - np.interp(xs[k], np.asarray(o.xs, dtype=np.float64),
                                      np.asarray(o.ys, dtype=np.float64))
                    for o in others
                ]
            )  # fmt: skip
            near = np.argmin(np.abs(diff), axis=0)
            signed = diff[near, np.arange(len(k))]
            gap = np.abs(signed)
            j = len(k) - 1 if ay.mm(float(gap[-1])) >= self.LABEL_GAP else int(np.argmax(gap))
            i = int(k[j])
            out.append((c, (float(xs[i]), float(ys[i])), bool(signed[j] >= 0.0)))
        return out


#: The height (mm) of a diagram's marks under its x axis (the numbered positions' numbers).
MARK_H = 3.5
#: A curve's name is written within this share of the x range from its end.
LABEL_SPAN = 0.2


# --- tables and text ------------------------------------------------------------------------------

#: Cell padding (mm) either side of a cell's text.
CELL_PAD = 1.2
#: A table's heading takes at most this many lines; a narrower table is widened to it.
HEADING_LINES = 3
#: A heading stands on one line over its table (running past the table's right edge, over the
#: room beside it) where the line is at most this many times the table's width: a drawing
#: office writes "Исходные данные" on one line over a narrow table, never broken in two.
HEADING_SPAN = 2.0


class Table(View):
    """A ruled table of ``rows`` of label markup (the first the header unless ``header`` is
    False), its columns as wide as their widest text (or ``widths``), widened in proportion
    to ``fill`` mm in all when that is wider (a table as wide as the one under it); ``center``:
    each column's numbers, aligned on their separator, as a block in its middle.

    Its ``title`` is its heading (GOST 2.105: above the table, from its left edge), on one
    line where that line is at most HEADING_SPAN times the table's width (the view is then as
    wide as its heading, the table under its left part), else broken into lines no wider than
    the table (a word longer than that widens the table); a heading the layout gives room for
    on one line is drawn on one line. A heading never runs past its view into the next view
    or the frame."""

    def __init__(
        self,
        rows: Sequence[Sequence[str]],
        widths: Sequence[float] | None = None,
        header: bool = True,
        height: float = 2.5,
        row_h: float = 6.0,
        fill: float = 0.0,
        center: bool = False,
        **kw: Any,
    ) -> None:
        kw.setdefault("margin", 1.0)
        heading = kw.pop("title", "")
        self.center = center
        super().__init__(**kw)
        self.rows = [list(r) for r in rows]
        self.header = header
        self.height = height
        self.row_h = row_h
        if widths is None:
            n = max(len(r) for r in self.rows)
            # numbers aligned on their separator take their widest whole and decimal parts
            body = self.rows[1:] if header else self.rows
            aligned = number_columns(body, height, n)
            widths = [
                max(
                    sum(aligned[i]),
                    *(
                        text_width(r[i], height)
                        for j, r in enumerate(self.rows)
                        if i < len(r) and (number_parts(r[i]) is None or (header and j == 0))
                    ),
                    0.0,
                )
                + 2 * CELL_PAD
                + 1.0
                for i in range(n)
            ]
        total = sum(widths)
        self.widths = [w * fill / total for w in widths] if 0.0 < total < fill else list(widths)
        #: the heading's lines (the view draws its heading itself, within its own width): one
        #: line where it costs little room, else at most HEADING_LINES of them, the table
        #: widened where its columns are narrower
        self.heading_line = heading
        one = text_width(heading, self.title_height) if heading else 0.0
        if one <= HEADING_SPAN * sum(self.widths):
            self.heading = [heading] if heading else []
        else:
            self.heading = wrap_balanced(heading, sum(self.widths), self.title_height)
        if len(self.heading) > HEADING_LINES:
            tokens = break_points(heading)
            n = min(HEADING_LINES, len(tokens))
            self.heading = balanced(tokens, n, self.title_height)
        wide = max((text_width(t, self.title_height) for t in self.heading), default=0.0)
        if wide > sum(self.widths) and len(self.heading) > 1:
            self.widths = [w * wide / sum(self.widths) for w in self.widths]
        #: the view's width: the table's, or its one-line heading's where that is wider
        self.span = max(sum(self.widths), wide)

    def heading_room(self) -> float:
        """The height (mm) of the heading's lines above the table (0 without a heading): as
        a view's one-line title, and a line spacing more for each further line."""
        if not self.heading:
            return 0.0
        h = self.title_height
        return h * TITLE_LEAD + TITLE_GAP + (len(self.heading) - 1) * h * LINE_SPACING

    def natural(self) -> tuple[float, float] | None:
        return self.span, self.heading_room() + self.row_h * len(self.rows)

    def draw(self, d: Drawing, at: Placed) -> None:
        x, y = at.inner[0], at.inner[1]
        h = self.title_height
        lines = self.heading
        if len(lines) > 1 and text_width(self.heading_line, h) <= at.inner[2] - x:
            # the layout gave the view room beside the table: the heading on one line, next
            # to the table as its last line would be
            lines = [""] * (len(lines) - 1) + [self.heading_line]
        for i, line in enumerate(lines):
            if line:
                d.text(line, (x, y + h + i * h * LINE_SPACING), h)
        d.table(x, y + self.heading_room(), self.widths, self.rows, self.height, self.row_h,
                self.header, self.center)  # fmt: skip

    @staticmethod
    def of_values(
        entries: Iterable[tuple[str, float | str, str]],
        digits: int = 4,
        first: str = "",
        **kw: Any,
    ) -> Table:
        """A table "quantity | value | unit" of (label markup, value, SI unit) entries; numbers
        to ``digits`` significant figures, a text value as it is; ``first`` heads the first
        column (default "Величина"); ``header=False``: no heading row."""
        head = [first or WORDS("quantity"), WORDS("value"), WORDS("unit")]
        rows = [
            [label, value if isinstance(value, str) else num(value, digits), unit_text(unit)]
            for label, value, unit in entries
        ]
        return Table([head, *rows] if kw.get("header", True) else rows, **kw)

    @staticmethod
    def of_specs(
        specs: Iterable[Spec],
        values: Mapping[str, Any],
        labels: Mapping[str, str] | None = None,
        digits: int | None = None,
        style: TableStyle = "column",
        pairs: int = 1,
        extra: tuple[str, Callable[[Spec, Any], str]] | None = None,
        first: str = "",
        head: Sequence[str] | None = None,
        transpose: bool = False,
        across: bool = False,
        **kw: Any,
    ) -> Table:
        """A table of the values of ``specs`` (a problem's ``Param`` or ``ResultSpec``) found in
        ``values``, each written as its spec says: its ``symbol`` (default: the name as markup,
        ``l_AB`` → ``l_{AB}``; ``labels`` maps a name to other markup, e.g. words of the
        sheet's language), its value in its ``display`` unit (default its SI ``unit``; a
        unit ``deg`` is written °) to its ``digits`` significant figures (``digits`` here
        overrides every spec's). An integer is written whole; a text value (a choice, or a
        value the sheet has written itself) as it is, without a unit; a list is left out.

        ``style``: ``"column"`` quantity | value | unit; ``"value"`` quantity | value with its
        unit; ``"label"`` "quantity, unit" | value; ``"equation"`` one cell "l_{AB} = 0,1 м".
        ``pairs`` > 1 sets that many groups of columns side by side (read down the first, then
        the next; ``across``: along the rows, left to right). ``extra = (heading, cell(spec,
        value))`` adds a column (e.g. a length on the
        plan). ``first`` is the first column's heading (default "Параметр" for a problem's
        ``Param``, else "Величина"); ``head`` replaces the whole heading row (every group's).
        ``transpose``: the quantities in a heading row, their values in the row under it (use
        with ``style="label"``).
        """
        specs = list(specs)
        entries: list[list[str]] = []
        for s in specs:
            if s.name not in values:
                continue
            x = values[s.name]
            if isinstance(x, list | tuple | dict):
                continue  # a list of values is a table of its own
            label = (labels or {}).get(s.name) or s.symbol or name_markup(s.name)
            shown = s.display or s.unit
            if isinstance(x, str):
                text, unit = x, ""
            elif isinstance(x, int) and not isinstance(x, bool) and shown == s.unit:
                text, unit = str(x), unit_text(shown)
            else:
                y = to_display(float(x), s.unit, shown)
                text, unit = num(y, digits or s.digits), unit_text(shown)
            if style == "column":
                row = [label, text, unit]
            elif style == "value":
                row = [label, with_unit(text, unit)]
            elif style == "label":
                row = [f"{label}, {unit}" if unit else label, text]
            else:
                row = [f"{label} = {with_unit(text, unit)}"]
            if extra is not None:
                row.append(extra[1](s, x))
            entries.append(row)
        n = max(1, pairs)
        if head is None:
            names = {"column": ("quantity", "value", "unit"), "value": ("quantity", "value"),
                     "label": ("quantity", "value"), "equation": ("quantity",)}[style]  # fmt: skip
            head = [WORDS(w) for w in names]
            given = bool(specs) and all(hasattr(s, "default") for s in specs)  # a problem's data
            head[0] = first or (WORDS("parameter") if given and style != "equation" else head[0])
            if extra is not None:
                head.append(extra[0])
            head = list(head) * n
        rows = [list(head), *side_by_side(entries, n, across)]
        if not kw.get("header", True):
            rows = rows[1:]
        if transpose:  # the quantities across, their values (and extra cells) under them
            rows = [list(col) for col in zip(*entries, strict=True)]
        return Table(rows, **kw)

    @staticmethod
    def of_entries(
        entries: Sequence[Sequence[str]],
        head: Sequence[str],
        pairs: int = 1,
        across: bool = False,
        **kw: Any,
    ) -> Table:
        """A table of ready-written entries (each a row's cells: ``(label, value)`` …) under
        the heading ``head`` of one group, set in ``pairs`` groups of columns side by side as
        :meth:`of_specs` sets them (read down, or with ``across`` along the rows)."""
        n = max(1, pairs)
        rows = [list(head) * n, *side_by_side([list(e) for e in entries], n, across)]
        return Table(rows if kw.get("header", True) else rows[1:], **kw)

    @staticmethod
    def of_series(
        columns: Sequence[tuple[Spec, Sequence[float]]],
        index: tuple[str, Sequence[str]] | None = None,
        digits: int | None = None,
        **kw: Any,
    ) -> Table:
        """A table of series (values at the division points, the positions …): a column per
        ``(spec, values)``, headed "symbol, unit" (its display unit), each value in that unit to
        the spec's ``digits`` (or ``digits``); ``index = (heading, cells)`` is a first column."""
        head = [index[0]] if index else []
        cells: list[list[str]] = [list(index[1])] if index else []
        for spec, values in columns:
            shown = spec.display or spec.unit
            unit = unit_text(shown)
            label = spec.symbol or name_markup(spec.name)
            head.append(f"{label}, {unit}" if unit else label)
            cells.append(
                [num(to_display(float(v), spec.unit, shown), digits or spec.digits) for v in values]
            )
        n = max((len(c) for c in cells), default=0)
        rows = [head] + [[c[i] if i < len(c) else "" for c in cells] for i in range(n)]
        return Table(rows, **kw)


def side_by_side(entries: Sequence[list[str]], n: int, across: bool = False) -> list[list[str]]:
    """``entries`` (rows of cells) in ``n`` groups of columns side by side: the first group
    read down, then the next; with ``across`` along the rows, left to right. Blank cells fill
    the last row."""
    per = -(-len(entries) // n)
    blank = [""] * len(entries[0]) if entries else []
    rows = []
    for i in range(per):
        line: list[str] = []
        for j in range(n):
            k = i * n + j if across else j * per + i
            line += entries[k] if k < len(entries) else blank
        rows.append(line)
    return rows


#: How :meth:`Table.of_specs` sets a value and its unit.
TableStyle = Literal["column", "value", "label", "equation"]


def with_unit(value: str, unit: str) -> str:
    """A value with its unit: ``0,15 м``, ``45°`` (no space before the degree sign)."""
    return value + unit if unit in ("°", "") else f"{value} {unit}"


class Spec(Protocol):
    """What :meth:`Table.of_specs` reads of a parameter's or a result's spec."""

    @property
    def name(self) -> str: ...
    @property
    def unit(self) -> str: ...
    @property
    def symbol(self) -> str: ...
    @property
    def display(self) -> str: ...
    @property
    def digits(self) -> int: ...


def unit_text(unit: str) -> str:
    """An SI unit as written on a sheet in the language being drawn (``"m"`` → ``м``); a unit
    the table does not know is written as it is; ``"1"`` is no unit."""
    table = WORDS.table()
    return table.get(f"unit.{unit}", "" if unit == "1" else unit)


def name_markup(name: str) -> str:
    """A parameter's or a step's name as label markup: ``l_AB`` → ``l_{AB}``, ``O1`` →
    ``O_1``, ``theta_deg`` → ``θ``, ``omega1`` → ``ω_1``.

    >>> name_markup("l_AB"), name_markup("O1"), name_markup("omega1"), name_markup("AB")
    ('l_{AB}', 'O_1', 'ω_1', 'AB')
    """
    base = name.removesuffix("_deg")
    greek = WORDS.table().get(f"greek.{base}")
    if greek:
        return greek
    m = re.fullmatch(r"([A-Za-z]+)_?([A-Za-z0-9]*)", base)
    if m and m.group(2) and (not m.group(1).isupper() or m.group(2).isdigit() or "_" in base):
        head, sub = m.groups()
        head = WORDS.table().get(f"greek.{head}", head)
        return f"{head}_{{{sub}}}" if len(sub) > 1 else f"{head}_{sub}"
    return markup_of(base)


class Text(View):
    """Lines of text (label markup), or one ``paragraph`` (or several, ``paragraphs``, each
    begun on a new line) wrapped to ``width`` mm, their later lines indented by ``indent``."""

    def __init__(
        self,
        lines: Sequence[str] = (),
        paragraph: str = "",
        width: float = 0.0,
        height: float = 2.5,
        indent: float = 0.0,
        paragraphs: Sequence[str] = (),
        **kw: Any,
    ) -> None:
        kw.setdefault("margin", 1.0)
        super().__init__(**kw)
        self.height = height
        self.indent = indent
        self.lines = list(lines)
        if paragraph:
            self.lines += wrap(paragraph, width, height, indent)
        #: x offsets (mm) of the lines: the continuation lines of ``paragraphs`` indented
        self.shifts = [0.0] * len(self.lines)
        for par in paragraphs:
            wrapped = wrap(par, width, height, indent)
            self.lines += wrapped
            self.shifts += [0.0] + [indent] * (len(wrapped) - 1)
        self.width = width or max((text_width(t, height) for t in self.lines), default=0.0)

    def natural(self) -> tuple[float, float] | None:
        lead = self.height * LINE_SPACING
        return self.width, self.height + max(len(self.lines) - 1, 0) * lead + 1.0

    def draw(self, d: Drawing, at: Placed) -> None:
        lead = self.height * LINE_SPACING
        for i, (t, dx) in enumerate(zip(self.lines, self.shifts, strict=True)):
            d.text(t, (at.inner[0] + dx, at.inner[1] + self.height + i * lead), self.height,
                   role="title")  # fmt: skip


# --- the order of construction -------------------------------------------------------------------

#: The kinds of step the templates know, each told by its operation's words (the recorder's).
#: Roles whose steps the order of construction lists.
LISTED = ("construction", "result", "link", "extreme")


def step_text(
    step: Step, words: Words | None = None, given: Mapping[str, str] | None = None
) -> str:
    """One step of the order of construction in the language being drawn: the template of its
    recorded kind (:attr:`Step.kind`), key ``step.<kind>``, looked up in ``words`` (a sheet's
    own table, for a problem's own kinds) and then in ``strings/<lang>/views.toml``, filled
    with the step's name (``{name}``) and operands (:attr:`Step.args`: names as label markup,
    numbers in the language drawn, ``@key`` the word ``word.key`` of the tables).

    A step without a kind, or whose kind no table knows, is an error naming the step: the
    order of construction is written from the recorded steps or not at all. ``given`` are
    fields already written (a value as a table of the sheet prints it, one rounding per value)."""
    key = f"step.{step.kind}"
    table = words.table() if words is not None else {}
    template = table.get(key) or WORDS.table().get(key)
    if not step.kind or template is None:
        raise ValueError(
            f"step {step.title!r}: no template for its kind {step.kind!r} "
            f"in the {current()} words (key {key!r})"
        )
    # an operand ``@key`` is a word: ``word.key`` of the sheet's table or of views.toml
    fields = {
        k: table.get(f"word.{v[1:]}") or WORDS(f"word.{v[1:]}")
        if isinstance(v, str) and v.startswith("@")
        else _arg(v)
        for k, v in step.args
    }
    fields["name"] = _arg(step.name)
    fields.update({k: v for k, v in (given or {}).items() if k in fields})
    try:
        return template.format(**fields)
    except (KeyError, IndexError) as exc:
        raise ValueError(f"step {step.title!r}: template {key!r} needs {exc}") from None


_POINTS = re.compile(r"(?:[A-Z][a-z]?\d*'*)+")


def _arg(v: str | float) -> str:
    """An operand as label markup: a number in the language drawn (4 significant figures);
    a symbol (``O1``, ``b3``, ``l_AB``) through :func:`name_markup`; a run of point names
    (``B0B1``, ``O1C``) with each point's digits as its subscript; markup (``{``) as it is."""
    if not isinstance(v, str):
        return num(v)
    if "{" in v:
        return _printable(v)
    if re.fullmatch(r"-?\d+(\.\d*)?(e-?\d+)?", v):
        return num(float(v))
    if re.fullmatch(r"[A-Za-z]\d+'*|[a-z]\d*'*|[A-Za-z]+_\w+", v):
        return name_markup(v)
    if _POINTS.fullmatch(v):
        return re.sub(r"([A-Z][a-z]?)(\d+)", lambda m: f"{m.group(1)}_{m.group(2)}", v)
    return _printable(v)


def _printable(text: str) -> str:
    """Recorded words with the signs the sheet font lacks written as words (``⊥``, ``∥``)."""
    w = metrics().widths
    for sign, key in (("⊥", "sign.perp"), ("∥", "sign.par"), ("∩", "sign.cap")):
        text = text.replace(sign, WORDS(key))
    # the minus sign and the prime the font lacks, as the sheets' own en dash and apostrophe
    text = text.replace("\u2212", "\u2013").replace("\u2032", "'")
    return "".join(c if ord(c) in w or c in "_{}^" else "?" for c in text)


class Steps(View):
    """The order of construction: the listed steps of ``construction`` (roles in
    :data:`LISTED`; ``only`` keeps these names, in their recorded order), numbered, each
    through its kind's template (:func:`step_text`; ``words`` holds a problem's own kinds;
    ``given``, by step name, fields already written) and wrapped to ``width`` mm."""

    def __init__(
        self,
        construction: Construction | Sequence[Step],
        width: float,
        only: Sequence[str] | None = None,
        height: float = 2.5,
        words: Words | None = None,
        given: Mapping[str, Mapping[str, str]] | None = None,
        **kw: Any,
    ) -> None:
        kw.setdefault("title", WORDS("order"))
        kw.setdefault("margin", 1.0)
        super().__init__(**kw)
        steps = list(construction)
        keep = [s for s in steps if (s.name in only if only is not None else s.role in LISTED)]
        self.height = height
        self.width = width
        self.lines: list[str] = []
        for i, s in enumerate(keep, 1):
            text = step_text(s, words, (given or {}).get(s.name))
            self.lines += wrap(f"{i}. {text}", width, height, indent=4.0)

    def natural(self) -> tuple[float, float] | None:
        lead = self.height * LINE_SPACING
        return self.width, self.height + max(len(self.lines) - 1, 0) * lead + 1.0

    def draw(self, d: Drawing, at: Placed) -> None:
        lead = self.height * LINE_SPACING
        for i, t in enumerate(self.lines):
            x = at.inner[0] + (0.0 if re.match(r"\d+\. ", t) else 4.0)
            d.text(t, (x, at.inner[1] + self.height + i * lead), self.height, role="title")
