"""A view's insets of short forces (ESKD выносные элементы): two μ_F for a view at most.

A view (the mechanism with its loads, a group's free body, Zhukovsky's lever) draws every force
at its one μ_F (:func:`~geomcad.sheet.loads.view_scales`), so that a longer arrow is a larger
force everywhere in it. A force that would be shorter than VIEW_SHORT_MM there is drawn
instead in an inset: a thin circle round its point on the view, lettered beside the circle,
and just beside it in the view's box the point again with its short forces at the view's one
further μ_F, the same for all its insets (stated once under the view's caption, "выносные
элементы Б, В: μ_F = 2 Н/мм", or in each inset's caption where that line has no room), same
directions, no inset arrow longer than the view's own shortest; a force too short at that μ_F
too (and not under the view's HIDE_SHARE) is drawn in its inset as a direction arrow of the
fixed length VIEW_SHORT_MM, at no scale (the line under the caption names it: "G1, Ф1 —
стрелки 5 мм без масштаба"), no longer than any arrow drawn to scale. One inset per point: all the
short forces of a point (of points closer than the circle) in one inset, under one letter, at
ONE μ_F (:func:`one_scale_per_inset`; where one μ_F cannot draw a point's forces, an inset per
μ_F, two circles side by side round the point: twins). The
insets go where the view's box is free of what is drawn, the nearest such place to their
circle (within BESIDE_MAX_MM where the view has room there).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt
import shapely

from geomcad import tol
from geomcad.geom import Vec
from geomcad.sheet.drawing import JOINT_R, Drawing, Viewport
from geomcad.sheet.lang import Words
from geomcad.sheet.loads import (
    INSET_CAP_MM,
    TIER_LIMIT,
    ForceScales,
    _inside,
    chord_points,
    force,
)
from geomcad.sheet.model import ArcItem, CircleItem, Polyline, TextItem
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scale import Scale
from geomcad.sheet.symbols import HATCH_LEN, HATCH_STEP, STAND_DEPTH, STAND_HALF
from geomcad.sheet.text import box, parse

WORDS = Words(__package__, "linkage_forces")

#: The radius (mm) of the thin circle round a point whose short forces are in an inset.
MARK_R = 3.5
#: An inset's circle round a point inside a filled block larger than the circle (a knot's
#: slider, scheme.KNOT_SLIDER) runs this far (mm) past the block's corners: not hidden by it.
PAST_BLOCK_MM = 0.5
#: An inset's circle keeps this far (mm) from a moment's arc about the same point.
ARC_APART_MM = 2.0


def _past_blocks(items: Sequence[object], c: tuple[float, float]) -> float:
    """The radius (mm) about sheet point ``c`` that clears, by :data:`PAST_BLOCK_MM`, the
    corners of every filled block among ``items`` that holds ``c`` (0 where none does)."""
    out = 0.0
    for it in items:
        if not (isinstance(it, Polyline) and it.fill and it.closed and len(it.points) > 3):
            continue
        if _holds(it.points, c):
            out = max(out, max(math.dist(q, c) for q in it.points) + PAST_BLOCK_MM)
    return out


def _clear_radius(items: Sequence[object], c: tuple[float, float], r: float) -> float:
    """An inset's circle's radius about sheet point ``c``: ``r``, or past a filled block round
    the point (:func:`_past_blocks`), and then :data:`ARC_APART_MM` outside every arc about
    the same point it would come closer to (a moment's arc: two lines apart, not one)."""
    r = max(r, _past_blocks(items, c))
    arcs = sorted(it.r for it in items
                  if isinstance(it, ArcItem) and math.dist(it.c, c) < CIRCLES_APART_MM)  # fmt: skip
    for ra in arcs:
        if abs(ra - r) < ARC_APART_MM:
            r = ra + ARC_APART_MM
    return r


#: An inset's circle keeps this far (mm) off a support of the frame (a hinge's stand and
#: hatched ground, a guide's hatching: review 11's kulisa drew Ж's circle round S3 over O's
#: support; 1.3 mm off it read as on it, the base line's and the circle's widths between):
#: where its point is that near one, the circle is moved off the support …
SUPPORT_GAP_MM = 2.0
#: … its centre off its point, so far as its point stays this far (mm) inside it (a joint's
#: circle and a gap: the circle still reads as round its point).
POINT_INSIDE_MM = JOINT_R + 0.5
#: The step (mm) and the directions tried for that move.
SHIFT_STEP_MM = 0.25
SHIFT_TURNS = 24


def supports(items: Sequence[object]) -> list[shapely.Polygon]:
    """The outlines (sheet mm) of the frame's supports among ``items``: the convex hull of each
    run of hatching strokes (role ``ground``; strokes closer than two hatch steps, one run),
    with the stand over it where a hinge's is (its two lines from the joint, each of a stand's
    length, :func:`~geomcad.sheet.symbols.pivot`)."""
    strokes = [np.asarray(it.points, dtype=float) for it in items
               if isinstance(it, Polyline) and it.role == "ground"]  # fmt: skip
    leg = math.hypot(STAND_DEPTH, STAND_HALF)
    stands = [np.asarray(it.points, dtype=float) for it in items
              if isinstance(it, Polyline) and it.role == "link" and len(it.points) == 2
              and abs(math.dist(*it.points) - leg) <= tol.SHEET_MM]  # fmt: skip
    runs: list[list[npt.NDArray[np.float64]]] = []
    for st in strokes:
        near = [r for r in runs
                if min(float(np.hypot(*(st[0] - o[0]))) for o in r) < 2.0 * HATCH_STEP]  # fmt: skip
        runs = [r for r in runs if not any(r is n for n in near)]
        runs.append([st, *(x for r in near for x in r)])
    out: list[shapely.Polygon] = []
    for r in runs:
        pts = np.concatenate(r)
        lo, hi = pts.min(axis=0) - HATCH_LEN, pts.max(axis=0) + HATCH_LEN
        legs = [st for st in stands if ((st[1] >= lo) & (st[1] <= hi)).all()]
        out.append(shapely.MultiPoint(np.concatenate([pts, *legs])).convex_hull)
    return out


def off_supports(
    c: tuple[float, float], r: float, points: Sequence[tuple[float, float]],
    outlines: Sequence[shapely.Geometry],
    keep: Sequence[tuple[tuple[float, float], float]] = (),
) -> tuple[float, float]:  # fmt: skip
    """The centre of an inset's circle of radius ``r`` (sheet mm) round the ``points`` it
    marks: ``c``, or, where the circle would come within :data:`SUPPORT_GAP_MM` of a
    support's outline (:func:`supports`), the nearest centre that keeps it that far off every
    one with each point :data:`POINT_INSIDE_MM` inside it and the circle
    :data:`CIRCLES_APART_MM` off the circles ``keep`` ((centre, radius)); ``c`` where none
    does (a point on a guide: the circle round its block crosses the guide's hatching)."""

    def clear(q: tuple[float, float]) -> bool:
        at = shapely.Point(q)
        return all(o.distance(at) >= r + SUPPORT_GAP_MM for o in outlines)

    if not outlines or clear(c):
        return c
    turns = [2.0 * math.pi * i / SHIFT_TURNS for i in range(SHIFT_TURNS)]
    most = r - POINT_INSIDE_MM - max((math.dist(c, p) for p in points), default=0.0)
    t = SHIFT_STEP_MM
    while t <= most + tol.SHEET_MM:
        for a in turns:
            q = (c[0] + t * math.cos(a), c[1] + t * math.sin(a))
            inside = all(math.dist(q, p) <= r - POINT_INSIDE_MM for p in points)
            apart = all(math.dist(q, o) >= r + ro + CIRCLES_APART_MM for o, ro in keep)
            if inside and apart and clear(q):
                return q
        t += SHIFT_STEP_MM
    return c


def _holds(poly: Sequence[tuple[float, float]], c: tuple[float, float]) -> bool:
    """Whether the closed polygon ``poly`` holds the point ``c`` (crossings of a ray)."""
    inside = False
    for a, b in zip(poly, (*poly[1:], poly[0]), strict=True):
        if (a[1] > c[1]) != (b[1] > c[1]):
            x = a[0] + (c[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            inside ^= c[0] < x
    return inside


#: The forces of one place at two of the insets' μ_F that one μ_F cannot draw (its arrows
#: past INSET_ONE_MM) are two insets, their circles this far (mm) each side of the place and
#: as much larger: side by side round it, each lettered on its own side (within
#: TWIN_TURN_DEG of the way from the other circle's centre to its own).
TWIN_SHIFT_MM = 1.5
TWIN_TURN_DEG = 60.0
#: Two insets' circles on a view keep at least this far (mm) apart; closer, they are one.
CIRCLES_APART_MM = 1.0
#: An inset draws its points at least this far (mm) apart: one of points closer on the view
#: is an enlarged detail (its length scale stated in its caption).
INSET_APART_MM = 10.0
#: The cap height (mm) of an inset's caption and of its labels, and the letter's on the view.
CAPTION_H = 2.5
LETTER_H = 3.5
#: Room (mm) kept round an inset's arrows for their labels, and between an inset and what is
#: drawn (the raster's cell is CELL_MM).
LABEL_PAD = 6.0
KEEP_MM = 2.0
CELL_MM = 1.0
#: The gaps (mm) tried between an inset's circle and its letter: touching it, just outside,
#: or (where a line drawn round the point, a moment's arc, would run through the letter) a
#: little further out, each mm further costing _W_GAP.
LETTER_GAPS = (0.6, 1.6, 2.6, 4.0, 5.5, 7.0)
#: A letter further than this (mm) off its circle is tied to it by a thin leader (ESKD 2.305).
LEADER_FROM = 2.0
#: The directions (degrees, counter-clockwise from the right) tried for the letter round its
#: circle, the first preferred (up and to the right, as ESKD letters a detail).
LETTER_TURNS = (45, 90, 0, 135, 315, 180, 270, 225, 68, 22, 112, 338, 158, 292, 202, 248)
#: The cost of a cell of the letter's box on a line or a text, of one within a label still to
#: be placed (the placer moves that one), of each later direction tried, and of each mm of gap.
_W_INK, _W_PENDING, _W_TURN, _W_GAP = 10.0, 0.5, 0.2, 2.0
#: The cost of a cell of a letter's leader on a line (it crosses the lines at its point), and
#: of a cell of its box within a cell of one (a letter squeezed between the lines of a guide).
_W_LEAD, _W_NEAR = 2.0, 3.0
#: How far (mm) round a label still to be placed the letter counts it (its text's size).
PENDING_MM = 3.0
#: An inset's copy is placed just beside its circle: its box within this distance (mm) of the
#: circle's centre where the view has room there; each mm further costs _W_FAR (a tenth of a
#: cell of its box on what is drawn, within KEEP_MM of a line or a text), so that it goes
#: further only where it would lie on the drawing there.
BESIDE_MAX_MM = 12.0
_W_FAR = 1.0e3


@dataclass(frozen=True)
class Short:
    """A force drawn in an inset: at model point ``at``, ``F`` (N), its label and role, the
    index ``tier`` of its μ_F in the view's :class:`ForceScales`; ``point``: the name of the
    point it acts at ("" where it has none: the view's point there names it)."""

    at: Vec
    F: Vec
    label: str
    role: str
    tier: int
    point: str = ""


class Insets:
    """The insets of one view: :meth:`add` the short forces while drawing the view, then
    :meth:`draw` them (after everything else of the view, so that they go where it is free).
    ``points``: the view's named points (model), by name, to letter an inset's point."""

    def __init__(self, fs: ForceScales, points: Mapping[str, Vec]) -> None:
        self.fs = fs
        self.points = points
        self.shorts: list[Short] = []
        #: (letter, μ_F) of each inset drawn, in order
        self.drawn: list[tuple[str, Scale]] = []
        #: the short forces of each inset drawn, in order
        self.members: list[list[Short]] = []
        #: lines the view draws after its insets (a detail's circle): no inset over them
        self.reserved: list[CircleItem] = []

    def add(self, at: Vec, F: Vec, tier: int, label: str, role: str, point: str = "") -> None:
        self.shorts.append(Short(at, F, label, role, tier, point))

    @property
    def scale(self) -> Scale:
        """The one μ_F of the view's insets."""
        return self.fs.scales[-1]

    def fixed(self, s: Short) -> bool:
        """Whether ``s`` is a direction arrow of the fixed length ``fs.fixed``, at no scale."""
        return s.tier >= len(self.fs.scales)

    @property
    def marked(self) -> bool:
        """Whether the insets draw at two μ_F of their own (μF*, μF**): each force's label
        then carries its tier's mark."""
        return len(self.fs.scales) > 2

    def scale_text(self, shorts: list[Short] | None = None) -> str:
        """The insets' μ_F as stated (``μ_F = 2 Н/мм``; with two: ``μ_F* = 2, μ_F** =
        0,5 Н/мм``), of the forces ``shorts`` drawn to scale only where given (an inset's)."""
        from geomcad.sheet.compose import scale_text

        if not self.marked:
            return scale_text(self.scale)
        mine = self.shorts if shorts is None else shorts
        return self.fs.further([s.tier for s in mine if not self.fixed(s)])

    @property
    def scaled(self) -> bool:
        """Whether some inset draws a force at the insets' μ_F (not only direction arrows)."""
        return any(not self.fixed(s) for s in self.shorts)

    def fixed_names(self) -> list[str]:
        """The labels of the forces drawn as direction arrows, once each, in order."""
        return list(dict.fromkeys(s.label for s in self.shorts if self.fixed(s)))

    def groups(self, eps: float) -> list[tuple[Vec, list[Short]]]:
        """The short forces by their point (a point within ``eps`` model units of one taken
        before joins it): one inset each."""
        out: list[tuple[Vec, list[Short]]] = []
        for s in self.shorts:
            for q, ss in out:
                if any(s.at.dist(u.at) <= eps for u in ss) or s.at.dist(q) <= eps:
                    ss.append(s)
                    break
            else:
                out.append((s.at, [s]))
        return out

    def clusters(self, v: Viewport) -> list[tuple[Vec, list[Short], tuple[float, float], float]]:
        """The insets of the view ``v``: :meth:`groups` of points closer than a circle, then
        any two whose circles (sheet mm: the centre of their points' box, :data:`MARK_R`
        round the farthest) would come closer than :data:`CIRCLES_APART_MM` joined, until
        none do (review 9: the rocking cylinder's lever drew Ж1, И1, Г1 over each other):
        (point, its short forces, the circle's centre, its radius), one letter each."""
        out: list[tuple[Vec, list[Short]]] = [(q, list(ss)) for q, ss in
                                              self.groups(v.scale.model(2.0 * MARK_R))]  # fmt: skip

        def circle(ss: list[Short]) -> tuple[tuple[float, float], float]:
            ats = [v.p(s.at) for s in ss]
            xs, ys = [a[0] for a in ats], [a[1] for a in ats]
            c = ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0)
            r = MARK_R + max(math.dist(c, a) for a in ats)
            # twins (below) reach 2·TWIN_SHIFT_MM further on their sides: kept apart as such
            return c, r + (2.0 * TWIN_SHIFT_MM if len(tiers(ss)) > 1 else 0.0)

        def tiers(ss: list[Short]) -> list[int]:
            """The insets' μ_F (tiers) of a place's forces drawn to scale, finest last."""
            return sorted({s.tier for s in ss if not self.fixed(s)})

        joined = True
        while joined:
            joined = False
            rings = [circle(ss) for _, ss in out]
            for i, j in itertools.combinations(range(len(out)), 2):
                (ci, ri), (cj, rj) = rings[i], rings[j]
                if math.dist(ci, cj) < ri + rj + CIRCLES_APART_MM:
                    out[i] = (out[i][0], out[i][1] + out[j][1])
                    del out[j]
                    joined = True
                    break
        out2: list[tuple[Vec, list[Short], tuple[float, float], float]] = []
        for q, ss in out:
            ts = tiers(ss)
            if len(ts) < 2:
                out2.append((q, ss, *circle(ss)))
                continue
            # forces of two μ_F at one place (:func:`one_scale_per_inset` could not draw them
            # at one): an inset each, their circles side by side round it (twins), the
            # direction arrows with the finer
            c, r = circle(ss)
            r -= 2.0 * TWIN_SHIFT_MM
            for n, t in enumerate(ts):
                mine = [s for s in ss if s.tier == t or (self.fixed(s) and t == ts[-1])]
                side = -1.0 if n == 0 else 1.0
                out2.append((q, mine, (c[0] + side * TWIN_SHIFT_MM, c[1]), r + TWIN_SHIFT_MM))
        return out2

    def point_name(self, q: Vec, shorts: list[Short], eps: float) -> str:
        """The name an inset gives its point at ``q``: the points its loads ``shorts`` there
        act at, each once ("B, K": the slider's B and the block's K at one place; review 10
        named the block's loads "B"), else the view's point there (:meth:`name_of`)."""
        own = [s.point for s in shorts if s.at.dist(q) <= eps and s.point in self.points]
        return ", ".join(dict.fromkeys(own)) if own else self.name_of(q, eps)

    def name_of(self, q: Vec, eps: float) -> str:
        """The name of the view's point at ``q`` ("" where none is)."""
        return next((n for n, p in self.points.items() if p.dist(q) <= eps), "")

    def count(self, v: Viewport) -> int:
        """How many insets the view ``v`` draws (one per point)."""
        return len(self.clusters(v)) if self.shorts else 0

    def draw(
        self,
        d: Drawing,
        v: Viewport,
        field: tuple[float, float, float, float],
        start: int,
        letters: Iterator[str],
        each: bool = False,
    ) -> None:
        """The insets into ``field`` (sheet mm), clear of the items drawn since ``start`` (the
        view's first), each lettered from ``letters`` with a thin circle round its point on
        the view ``v`` and the letter just outside the circle where it is clearest; ``each``:
        every inset's caption states the μ_F too (the view's caption line does not)."""
        if not self.shorts:
            return
        eps = v.scale.model(0.8)
        free = _Free(d, start, field)
        for it in self.reserved:
            free.mark(it)
        marks: list[tuple[str, Vec, list[Short], tuple[float, float], TextItem]] = []
        # the circles and their letters first (each beside its own circle), then the insets
        rings = self.clusters(v)
        radii = [r for *_, r in rings]
        outlines = supports(d.sheet.items[start:])
        for i, (q, shorts, c, r) in enumerate(rings):
            letter = next(letters)
            tiers = [s.tier for s in shorts if not self.fixed(s)]
            self.drawn.append((letter, self.fs.scales[tiers[0]] if tiers else self.scale))
            self.members.append(shorts)
            # a twin (an inset of the other μ_F at the same place): its letter on its own side
            twin = next((o[2] for j, o in enumerate(rings) if j != i and o[0] is q), None)
            side = None if twin is None else (c[0] - twin[0], c[1] - twin[1])
            # past a block or an arc round the point, as far as the other circles leave room
            room = min((math.dist(c, o[2]) - radii[j] - CIRCLES_APART_MM
                        for j, o in enumerate(rings) if j != i), default=math.inf)  # fmt: skip
            radii[i] = max(r, min(_clear_radius(d.sheet.items[start:], c, r), room))
            others = [(o[2], radii[j]) for j, o in enumerate(rings) if j != i]
            c = off_supports(c, radii[i], [v.p(s.at) for s in shorts], outlines, others)
            rings[i] = (q, shorts, c, radii[i])
            circle = CircleItem(c, radii[i], "thin")
            d.sheet.add(circle)
            beside = free.letter(d, letter, c, radii[i], side)  # its own circle is not in its way
            free.mark(circle)
            marks.append((letter, q, shorts, c, beside))
        for letter, q, shorts, c, beside in marks:
            self._one(d, v, free, q, c, letter, shorts, eps, each, beside)

    def _one(
        self,
        d: Drawing,
        v: Viewport,
        free: _Free,
        q: Vec,
        p: tuple[float, float],
        letter: str,
        shorts: list[Short],
        eps: float,
        each: bool,
        beside: TextItem | None = None,
    ) -> None:
        from geomcad.sheet.compose import round_scale_down, scale_text

        sc = self.scale
        scaled = any(not self.fixed(s) for s in shorts)
        # points of the view closer than INSET_APART_MM (one inset's circle took them): the
        # inset enlarges them, at the coarsest step of the view's series that sets them that
        # far apart, stated in its caption (ESKD 2.305: "Ж1 (2:1)"; review 9: the rocking
        # cylinder's lever's insets round its pole, its arrows over each other)
        sl = v.scale
        paper = [v.p(s.at) for s in shorts]
        gaps = [g for a, b in itertools.combinations(paper, 2) if (g := math.dist(a, b)) > 0.8]
        if gaps and min(gaps) < INSET_APART_MM:
            raw = sl.k * min(gaps) / INSET_APART_MM
            sl = round_scale_down(raw, sl.q, "gost" if sl.q == "l" else "nice")
        parts = []
        if sl is not v.scale:
            parts.append(sl.ratio_text() or scale_text(sl))
        if each and scaled:
            parts.append(self.scale_text(shorts))
        caption = WORDS("inset", letter=letter, scale="; ".join(parts)) if parts else letter
        # each force at the insets' μ_F, or a direction arrow fs.fixed mm long
        ks = [self.fs.k_at(s.F.norm) for s in shorts]
        arrive = pushes([s.F for s in shorts])
        lengths = [s.F.norm / k for s, k in zip(shorts, ks, strict=True)]
        # paper mm from the point: the far ends of the arrows (leaving it, or arriving)
        # each force at its own point (a detail keeps the view's μ_l): offsets from q
        rel = [((s.at.x - q.x) / sl.k, (q.y - s.at.y) / sl.k) for s in shorts]
        starts = side_by_side([s.F for s in shorts], sc.k, lengths, arrive, rel)
        starts = [(o[0] + e[0], o[1] + e[1]) for o, e in zip(starts, rel, strict=True)]
        tips = [
            (o[0] + (-1.0 if a else 1.0) * s.F.x / k, o[1] + (1.0 if a else -1.0) * s.F.y / k)
            for o, a, s, k in zip(starts, arrive, shorts, ks, strict=True)
        ]
        tips += starts
        x0 = min(0.0, *(t[0] for t in tips)) - LABEL_PAD
        x1 = max(0.0, *(t[0] for t in tips)) + LABEL_PAD
        y0 = min(0.0, *(t[1] for t in tips)) - LABEL_PAD
        y1 = max(0.0, *(t[1] for t in tips)) + LABEL_PAD
        cap_h = CAPTION_H if parts else LETTER_H
        cap_w = box(parse(caption), cap_h)[0]
        cap = cap_h * 2.0
        w, h = max(x1 - x0, cap_w), (y1 - y0) + cap
        corner = free.place(w, h, p)
        # the point in the inset, its arrows' box under the caption; the caption under the
        # arrows instead where the place found is not free (a large inset in a full view) and
        # there it meets fewer of the lines, texts and insets drawn (review 15: the rocking
        # cylinder's lever set "Г2 (μV = …)" over the caption Ш1 of another inset)
        cx = corner[0] + (w - cap_w) / 2.0
        top = free._count(free.grid, cx, corner[1], cap_w, cap)
        low = free._count(free.grid, cx, corner[1] + (y1 - y0), cap_w, cap) if top else 0
        if low < top:
            at = (corner[0] + (w - (x1 - x0)) / 2.0 - x0, corner[1] - y0)
            cap_at = (cx, corner[1] + (y1 - y0) + cap - cap_h * 0.5)
        else:
            at = (corner[0] + (w - (x1 - x0)) / 2.0 - x0, corner[1] + cap - y0)
            cap_at = (cx, corner[1] + cap_h)
        # a caption that is the bare letter, set where it would meet the circle's own letter
        # (the copy just under its circle), is left out: that letter names the copy too
        if parts or beside is None or not _meets(beside, caption, cap_at, cap_h):
            d.text(caption, cap_at, cap_h)
        iv = Viewport(d, sl, q.x, q.y, at)
        pts: list[Vec] = []
        for s in shorts:
            if all(s.at.dist(u) > eps for u in pts):
                pts.append(s.at)
        for u in pts:
            iv.dot(u)
            name = self.point_name(u, shorts, eps)
            if name:
                iv.label(u, markup_of(name), CAPTION_H, clear=0.8)
        for o, e, a, s, k in zip(starts, rel, arrive, shorts, ks, strict=True):
            q2 = q + Vec(o[0], -o[1]) * sl.k
            if o != e:  # set beside the others on its line: a thin line to its point
                iv.seg(s.at, q2, "thin")
            mark = self.fs.mark(s.tier) if self.marked and not self.fixed(s) else ""
            force(iv, q2, s.F, k, s.label + mark, arrive=a, role=s.role, height=CAPTION_H)
        free.take(corner, w, h)

    def text(self) -> str:
        """The line under the view's caption that states its insets' one μ_F:
        ``выносные элементы Б, В: μ_F = 2 Н/мм`` ("" without insets)."""
        return self.line([letter for letter, _ in self.drawn])

    def line(self, letters: list[str]) -> str:
        """:meth:`text` for insets lettered ``letters`` (never the μ_F without them)."""
        if not letters or not self.scaled:
            return ""
        return WORDS("insets", items=f"{', '.join(letters)}: {self.scale_text()}")


#: Two forces at one point closer in direction than this (degrees) are set side by side.
SAME_LINE_DEG = 20.0
#: … this far apart (mm), across their line.
BESIDE_MM = 3.0


#: Two arrows drawn from one point on about the same side of it are set side by side where
#: their tips would be closer than this (mm): two 5-mm arrows 45° apart are mostly two
#: overlapping heads (review 8: Φ4 and G4 at s4 on the rocking cylinder's lever).
TIPS_APART_MM = 4.0


def side_by_side(
    forces: list[Vec], k: float, lengths: list[float] | None = None,
    arrive: list[bool] | None = None, at: list[tuple[float, float]] | None = None,
) -> list[tuple[float, float]]:  # fmt: skip
    """Where (paper mm from their point, y down) the arrows of ``forces`` drawn from one point
    at ``k`` N/mm (or ``lengths`` mm long; those of ``arrive`` arriving at the point, on the
    side of it opposite their sense) start: at the point, but an arrow on about the side of
    one before it (within :data:`SAME_LINE_DEG`, or within the angle at which the shorter
    one's tip would lie closer than :data:`TIPS_APART_MM` to the other's) set a multiple of
    :data:`BESIDE_MM` across its line, the nearest to the point (this side first) at which it
    keeps :data:`ARROWS_APART_MM` from every arrow before it, so that no arrow lies on
    another (G₅ and Φ₅ both down at d) nor ends on one (Φ₅ set beside G₅ onto R₀₅). ``at``:
    where (paper mm) each arrow's own point is, where they are not one point (an inset of
    points closer than its circle): the offsets are from it."""
    lengths = lengths or [F.norm / k for F in forces]
    arrive = arrive or [False] * len(forces)
    at = at or [(0.0, 0.0)] * len(forces)
    rays = [F.unit() * (-1.0 if a else 1.0) for F, a in zip(forces, arrive, strict=True)]
    out: list[tuple[float, float]] = []
    segs: list[tuple[tuple[float, float], tuple[float, float]]] = []
    for i, F in enumerate(forces):
        u, r, n = F.unit(), rays[i], lengths[i]

        def clashes(o: tuple[float, float], i: int = i, r: Vec = r, n: float = n) -> bool:
            a = (at[i][0] + o[0], at[i][1] + o[1])
            seg = (a, (a[0] + r.x * n, a[1] - r.y * n))
            for j, other in enumerate(segs):
                if o == out[j] == (0.0, 0.0) and at[i] == at[j]:  # from one point: by angle
                    if arrive[i] and arrive[j]:  # both heads at the point: they would meet
                        return True
                    half = TIPS_APART_MM / (2.0 * max(min(n, lengths[j]), tol.SHEET_MM))
                    turn = max(math.radians(SAME_LINE_DEG), 2.0 * math.asin(min(1.0, half)))
                    if rays[j].dot(r) > math.cos(turn):
                        return True
                elif _seg_dist(seg, other) < ARROWS_APART_MM:
                    return True
            return False

        steps = [0, *(m * sgn for m in range(1, len(forces) + 1) for sgn in (1, -1))]
        o = next(((u.y * BESIDE_MM * m, u.x * BESIDE_MM * m) for m in steps
                  if not clashes((u.y * BESIDE_MM * m, u.x * BESIDE_MM * m))),
                 (u.y * BESIDE_MM * len(forces), u.x * BESIDE_MM * len(forces)))  # fmt: skip
        o = (o[0] + 0.0, o[1] + 0.0)  # no -0.0: the point itself compares equal
        out.append(o)
        a = (at[i][0] + o[0], at[i][1] + o[1])
        segs.append((a, (a[0] + r.x * n, a[1] - r.y * n)))
    return out


#: An arrow set beside others keeps this far (mm) from each of them: two heads' widths and a gap.
ARROWS_APART_MM = 1.8


def _seg_dist(
    a: tuple[tuple[float, float], tuple[float, float]],
    b: tuple[tuple[float, float], tuple[float, float]],
) -> float:
    """The distance (mm) between two segments (0 where they cross)."""

    def pt(p: tuple[float, float], s: tuple[tuple[float, float], tuple[float, float]]) -> float:
        (x0, y0), (x1, y1) = s
        dx, dy = x1 - x0, y1 - y0
        n2 = dx * dx + dy * dy
        t = 0.0 if n2 <= 0.0 else max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / n2))
        return math.hypot(p[0] - x0 - t * dx, p[1] - y0 - t * dy)

    def side(p: tuple[float, float], s: tuple[tuple[float, float], tuple[float, float]]) -> float:
        (x0, y0), (x1, y1) = s
        return (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)

    if side(a[0], b) * side(a[1], b) < 0.0 and side(b[0], a) * side(b[1], a) < 0.0:
        return 0.0
    return min(pt(a[0], b), pt(a[1], b), pt(b[0], a), pt(b[1], a))


def pushes(forces: list[Vec]) -> list[bool]:
    """Which of ``forces`` at one point are drawn arriving at it: one of about the opposite
    sense of a force before it (within :data:`SAME_LINE_DEG`), so that no two arrows leave
    the point tail to tail (they would read as one double-headed arrow)."""
    cos = math.cos(math.radians(SAME_LINE_DEG))
    return [any(G.unit().dot(F.unit()) < -cos for G in forces[:i]) for i, F in enumerate(forces)]


class _Free:
    """Where a view's box (sheet mm) is free of its drawing: a raster of CELL_MM cells, those
    within KEEP_MM of a line or a text, or within LABEL_PAD of a label to be placed, taken."""

    def __init__(self, d: Drawing, start: int, field: tuple[float, float, float, float]) -> None:
        self.field = field
        x0, y0, x1, y1 = field
        self.nx = max(1, int((x1 - x0) / CELL_MM))
        self.ny = max(1, int((y1 - y0) / CELL_MM))
        grid = np.zeros((self.ny, self.nx), dtype=bool)
        for it in d.sheet.items[start:]:
            if isinstance(it, TextItem):
                self._rect(grid, it.at[0], it.at[1] - it.height, it.width, it.height * 1.3)
                continue
            if not isinstance(it, Polyline | CircleItem | ArcItem):
                continue
            pts = chord_points(it)
            for a, b in itertools.pairwise(pts):
                n = max(2, int(math.dist(a, b) / (CELL_MM / 2.0)) + 1)
                xs = np.linspace(a[0], b[0], n)
                ys = np.linspace(a[1], b[1], n)
                self._mark(grid, xs, ys)
            if isinstance(it, Polyline) and it.fill and it.closed and len(it.points) > 3:
                self._fill(grid, np.array(it.points, dtype=float))  # a slider's block
        #: the cells of the lines and texts drawn (the letters' raster), and those within
        #: PENDING_MM of a label still to be placed
        self.ink = grid
        self.pending = np.zeros_like(grid)
        self.grid = _grow(grid, math.ceil(KEEP_MM / CELL_MM))
        for rq in d.pending:  # the labels still to be placed take room round their points
            self._rect(self.grid, rq.anchor[0] - LABEL_PAD, rq.anchor[1] - LABEL_PAD,
                       2 * LABEL_PAD, 2 * LABEL_PAD)  # fmt: skip
            self._rect(self.pending, rq.anchor[0] - PENDING_MM, rq.anchor[1] - PENDING_MM,
                       2 * PENDING_MM, 2 * PENDING_MM)  # fmt: skip

    def _fill(self, grid: npt.NDArray[np.bool_], poly: npt.NDArray[np.float64]) -> None:
        """The cells whose centres lie inside the closed outline ``poly`` (k, 2), taken."""
        x0, y0 = poly.min(axis=0)
        x1, y1 = poly.max(axis=0)
        xs = np.arange(x0, x1 + CELL_MM, CELL_MM / 2.0)
        ys = np.arange(y0, y1 + CELL_MM, CELL_MM / 2.0)
        gx, gy = np.meshgrid(xs, ys)
        pts = np.column_stack([gx.ravel(), gy.ravel()])
        ins = _inside(pts, [poly])
        self._mark(grid, pts[ins, 0], pts[ins, 1])

    def mark(self, it: Polyline | CircleItem | ArcItem) -> None:
        """A line drawn since: its cells taken (and those within KEEP_MM for the insets)."""
        mine = np.zeros_like(self.ink)
        for a, b in itertools.pairwise(chord_points(it)):
            n = max(2, int(math.dist(a, b) / (CELL_MM / 2.0)) + 1)
            self._mark(mine, np.linspace(a[0], b[0], n), np.linspace(a[1], b[1], n))
        self.ink |= mine
        self.grid |= _grow(mine, math.ceil(KEEP_MM / CELL_MM))

    def letter(
        self, d: Drawing, letter: str, c: tuple[float, float], r: float,
        side: tuple[float, float] | None = None,
    ) -> TextItem:  # fmt: skip
        """The letter of an inset beside its circle (centre ``c``, radius ``r``, sheet mm):
        its box one of :data:`LETTER_GAPS` outside the circle in one of the directions
        :data:`LETTER_TURNS`, where it covers fewest lines and texts drawn (and labels still to
        be placed), the nearest and first such place; its cells taken. ``side``: a twin's
        (sheet mm, away from the other circle round its point): only the directions within
        TWIN_TURN_DEG of it, so that the letter is nearer its own circle."""
        w, up, down = box(parse(letter), LETTER_H)
        hw, hh = w / 2.0, (up + down) / 2.0
        XY = tuple[float, float]
        best: tuple[float, XY, tuple[XY, XY] | None] | None = None
        near = _grow(self.ink, 1)
        for gap in LETTER_GAPS:
            for i, deg in enumerate(LETTER_TURNS):
                t = math.radians(deg)
                u = (math.cos(t), -math.sin(t))
                if side is not None and u[0] * side[0] + u[1] * side[1] < math.cos(
                    math.radians(TWIN_TURN_DEG)
                ) * math.hypot(*side):
                    continue
                # the box's centre along u where its nearest point is ``gap`` off the circle
                lo, hi = 0.0, r + gap + hw + hh
                for _ in range(30):
                    m = (lo + hi) / 2.0
                    dx = max(abs(u[0] * m) - hw, 0.0)
                    dy = max(abs(u[1] * m) - hh, 0.0)
                    if math.hypot(dx, dy) < r + gap:
                        lo = m
                    else:
                        hi = m
                x, y = c[0] + u[0] * hi - hw, c[1] + u[1] * hi - hh
                a = (c[0] + u[0] * r, c[1] + u[1] * r)
                b = (c[0] + u[0] * (r + gap), c[1] + u[1] * (r + gap))
                lead = self._on_ink(a, b) if gap > LEADER_FROM else 0
                cost = (
                    _W_INK * self._count(self.ink, x, y, w, 2.0 * hh)
                    + _W_NEAR * self._count(near, x, y, w, 2.0 * hh)
                    + _W_LEAD * lead
                    + _W_PENDING * self._count(self.pending, x, y, w, 2.0 * hh)
                    + _W_TURN * i
                    + _W_GAP * gap
                )
                if best is None or cost < best[0]:
                    best = (cost, (x, y), (a, b) if gap > LEADER_FROM else None)
        assert best is not None
        x, y = best[1]
        if best[2] is not None:  # the leader from the circle to the letter
            leader = Polyline(best[2], "thin")
            d.sheet.add(leader)
            self.mark(leader)
        item = d.text(letter, (x, y + up), LETTER_H)
        self._rect(self.ink, x, y, w, 2.0 * hh)
        self._rect(self.grid, x - KEEP_MM, y - KEEP_MM, w + 2 * KEEP_MM, 2.0 * hh + 2 * KEEP_MM)
        return item

    def _on_ink(self, a: tuple[float, float], b: tuple[float, float]) -> int:
        """How many cells of a leader from ``a`` to ``b`` (sheet mm) are on lines or texts."""
        n = max(2, int(math.dist(a, b) / (CELL_MM / 2.0)) + 1)
        i = ((np.linspace(a[1], b[1], n) - self.field[1]) / CELL_MM).astype(int)
        j = ((np.linspace(a[0], b[0], n) - self.field[0]) / CELL_MM).astype(int)
        ok = (i >= 0) & (i < self.ny) & (j >= 0) & (j < self.nx)
        return len({(int(p), int(q)) for p, q in zip(i[ok], j[ok], strict=True) if self.ink[p, q]})

    def _count(self, grid: npt.NDArray[np.bool_], x: float, y: float, w: float, h: float) -> int:
        """How many cells of ``grid`` the rectangle (sheet mm) covers, a cell outside the
        field (another view's) counted as covered."""
        i0, j0 = int((y - self.field[1]) / CELL_MM), int((x - self.field[0]) / CELL_MM)
        i1 = math.ceil((y + h - self.field[1]) / CELL_MM)
        j1 = math.ceil((x + w - self.field[0]) / CELL_MM)
        inside = grid[max(0, i0) : max(0, min(self.ny, i1)), max(0, j0) : max(0, min(self.nx, j1))]
        return int(inside.sum()) + (i1 - i0) * (j1 - j0) - inside.size

    def _mark(self, grid: npt.NDArray[np.bool_], xs: npt.NDArray[np.float64],
              ys: npt.NDArray[np.float64]) -> None:  # fmt: skip
        i = ((ys - self.field[1]) / CELL_MM).astype(int)
        j = ((xs - self.field[0]) / CELL_MM).astype(int)
        ok = (i >= 0) & (i < self.ny) & (j >= 0) & (j < self.nx)
        grid[i[ok], j[ok]] = True

    def _rect(self, grid: npt.NDArray[np.bool_], x: float, y: float, w: float, h: float) -> None:
        i0 = max(0, int((y - self.field[1]) / CELL_MM))
        i1 = min(self.ny, math.ceil((y + h - self.field[1]) / CELL_MM))
        j0 = max(0, int((x - self.field[0]) / CELL_MM))
        j1 = min(self.nx, math.ceil((x + w - self.field[0]) / CELL_MM))
        if i0 < i1 and j0 < j1:
            grid[i0:i1, j0:j1] = True

    def place(self, w: float, h: float, near: tuple[float, float]) -> tuple[float, float]:
        """The top-left corner (sheet mm) of a free w × h rectangle in the field nearest to
        ``near`` (an inset just beside its circle, within :data:`BESIDE_MAX_MM` of its centre
        where a free place is: one further costs :data:`_W_FAR` taken cells a mm); where none
        is free, the one that covers the fewest taken cells."""
        # an inset larger than the field is sought as large as the field (it runs over the
        # field's edge, never over another inset)
        cw = max(1, min(math.ceil(w / CELL_MM), self.nx - 1))
        ch = max(1, min(math.ceil(h / CELL_MM), self.ny - 1))
        s = np.zeros((self.ny + 1, self.nx + 1))
        s[1:, 1:] = self.grid.cumsum(0).cumsum(1)
        taken = s[ch:, cw:] - s[:-ch, cw:] - s[ch:, :-cw] + s[:-ch, :-cw]
        ii, jj = np.mgrid[0 : taken.shape[0], 0 : taken.shape[1]]
        cx = self.field[0] + (jj + cw / 2.0) * CELL_MM
        cy = self.field[1] + (ii + ch / 2.0) * CELL_MM
        # the distance from ``near`` to the rectangle's nearest point: one BESIDE_MAX_MM off
        # at most costs that much, one further as much as its cells taken besides
        dx = np.maximum(np.abs(cx - near[0]) - cw * CELL_MM / 2.0, 0.0)
        dy = np.maximum(np.abs(cy - near[1]) - ch * CELL_MM / 2.0, 0.0)
        dist = np.hypot(dx, dy)
        cost = taken * 1.0e4 + dist + np.maximum(dist - BESIDE_MAX_MM, 0.0) * _W_FAR
        k = int(np.argmin(cost))
        i, j = divmod(k, taken.shape[1])
        return self.field[0] + j * CELL_MM, self.field[1] + i * CELL_MM

    def take(self, corner: tuple[float, float], w: float, h: float) -> None:
        self._rect(self.grid, corner[0] - KEEP_MM, corner[1] - KEEP_MM,
                   w + 2 * KEEP_MM, h + 2 * KEEP_MM)  # fmt: skip


def _meets(mark: TextItem, text: str, at: tuple[float, float], h: float) -> bool:
    """Whether ``text`` set at ``at`` (baseline's left end), ``h`` high, meets the box of the
    text ``mark`` (a circle's letter) or comes within :data:`KEEP_MM` of it."""
    w, up, down = box(parse(text), h)
    mw, mup, mdown = box(mark.runs, mark.height)
    return (
        at[0] - KEEP_MM < mark.at[0] + mw
        and mark.at[0] - KEEP_MM < at[0] + w
        and at[1] - up - KEEP_MM < mark.at[1] + mdown
        and mark.at[1] - mup - KEEP_MM < at[1] + down
    )


def _grow(grid: npt.NDArray[np.bool_], n: int) -> npt.NDArray[np.bool_]:
    """The taken cells and those within ``n`` cells of them (a square neighbourhood)."""
    out = grid.copy()
    for _ in range(n):
        g = out.copy()
        g[1:, :] |= out[:-1, :]
        g[:-1, :] |= out[1:, :]
        g[:, 1:] |= out[:, :-1]
        g[:, :-1] |= out[:, 1:]
        out = g
    return out


#: The longest arrow (mm) of an inset whose forces one μ_F draws though they were at two (the
#: finer: its larger forces drawn longer than the insets' cap): a further μ_F's arrows reach
#: TIER_LIMIT times their room (loads.force_tiers); longer, the place's forces are two insets
#: (twins, TWIN_SHIFT_MM), each at one μ_F.
INSET_ONE_MM = TIER_LIMIT * INSET_CAP_MM


def one_scale_per_inset(
    fs: ForceScales, arrows: Sequence[tuple[Vec, Vec]], v: Viewport
) -> ForceScales:
    """The view's force scales ``fs`` with each of its insets at ONE μ_F (review 12: the
    needle's inset Г held Φ5* and G5**, two stated μ in one detail): the forces ``arrows``
    (point, force; model) short at the view's own μ_F, by the insets the view ``v`` draws
    (:meth:`Insets.clusters`); where one inset's forces are at two of the insets' μ_F, all of
    them at the finer (:attr:`ForceScales.pinned`: the larger of them drawn longer, none
    shorter than it was) where that draws none past :data:`INSET_ONE_MM` (else the place
    is two insets, twins, one per μ_F), until no more join; then a μ_F that no force is
    drawn at any more is not stated (the view states at most as many as before)."""
    if len(fs.scales) < 3:
        return fs  # one inset μ_F at most: every inset at it
    pinned: dict[float, int] = {}
    while True:
        cur = replace(fs, pinned=tuple(pinned.items()))
        ins = Insets(cur, {})
        for at, F in arrows:
            t = cur.tier(F.norm)
            if t is not None and 0 < t < len(cur.scales):
                ins.add(at, F, t, "", "")
        more = False
        places: dict[int, list[Short]] = {}  # an inset's forces, a twin's joined
        for q, shorts, _, _ in ins.clusters(v) if ins.shorts else []:
            places.setdefault(id(q), []).extend(shorts)
        for shorts in places.values():
            tiers = {s.tier for s in shorts}
            fine = cur.scales[max(tiers)].k if len(tiers) > 1 else 0.0
            if fine and max(s.F.norm for s in shorts) / fine <= INSET_ONE_MM:
                for s in shorts:
                    if s.tier != max(tiers):
                        pinned[s.F.norm] = max(tiers)
                        more = True
        if not more:
            break
    if not pinned:
        return fs
    cur = replace(fs, pinned=tuple(pinned.items()))
    used = {cur.tier(F.norm) for _, F in arrows} | {0}
    keep = [i for i in range(len(fs.scales)) if i in used]
    if len(keep) == len(fs.scales):
        return cur
    index = {i: n for n, i in enumerate(keep)}
    scales = tuple(fs.scales[i] for i in keep)
    return replace(fs, scales=scales, pinned=tuple((F, index[t]) for F, t in pinned.items()))
