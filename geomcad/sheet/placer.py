"""The one label placer of every sheet: candidate positions scored against an index of the ink.

When a sheet is finished (:meth:`geomcad.sheet.drawing.Drawing.finish`) the centre line of every
drawn item — polylines, circles, arcs; filled shapes as areas — goes into one shapely ``STRtree``
(:class:`Index`), and every text already on the sheet into another. A label then tries positions
around its anchor: the eight compass directions, the middles of the free sectors between the
lines that leave the anchor (the normals of a line for a label on a line), and the caller's
preferred direction, each at several gaps. Each position is scored by

- the lines that cross its box (grown by half a line's width), those through its middle, and
  those within :data:`PAD` of it; the cheapest few positions also by the area of ink (each line
  buffered by half its own width) inside the box, the measure the layout checker uses;
- the texts it overlaps (all but forbidden);
- its distance to the anchor, and whether another label's point lies nearer to it than its own;

and the cheapest position inside the field (the frame less the title block and графа 26) wins.
The labels with the fewest free positions are placed first, then each is placed again once with
all the others in place. A dimension's text tries its own candidates (along its dimension line)
against the same index, and so do optional texts (a diagram's tick values), left out where a
line crosses them.

Speed: every label's candidates are measured together (one query of the ink for the boxes of all
labels, and a box's crossing and middle tests only against the lines its padded box meets); while
the labels are placed, the placed ones are upright rectangles, compared with each candidate in
numpy, not through a text index rebuilt after every label.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import shapely
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry import box as sbox
from shapely.strtree import STRtree

from geomcad import tol
from geomcad.sheet.frame import Frame, reserved
from geomcad.sheet.model import XY, ArcItem, CircleItem, Item, Polyline, Sheet, TextItem
from geomcad.sheet.style import MAIN_LINE, fit_open, style
from geomcad.sheet.text import box, metrics, parse

#: The clearance a label keeps from lines and other texts (mm).
PAD = 0.4
#: Gaps (mm) between a label's box and its anchor (beyond the anchor's own ``clear`` radius).
GAPS = (0.5, 1.0, 1.7, 2.5, 3.4, 4.5, 6.0, 8.0, 10.5)
#: The eight compass directions on the paper (y down), the customary ones first.
DIRECTIONS: tuple[tuple[float, float], ...] = (
    (1, -1), (-1, -1), (1, 1), (-1, 1), (1, 0), (-1, 0), (0, -1), (0, 1),
)  # fmt: skip
#: A direction within 22.5° of an axis centres the box across it.
ALIGN = math.sin(math.radians(22.5))
#: A box grown by this much (about half a main line's width) meets the centre lines that cross it.
HALF = 0.3
#: Costs: a line crossed, a line through the middle of the box, a line within PAD, a text
#: overlapped.
W_LINE = 15.0
W_MIDDLE = 10.0
W_NEAR = 2.0
W_TEXT = 200.0
#: The cheapest REFINE positions of a label also pay W_INK for each mm² of ink inside its box
#: (less 0.25 mm all round); the others pay W_LINE more.
REFINE = 24
W_INK = 10.0
#: A mm of distance to the anchor, and each mm beyond FAR_MM (or 3 mm beyond a label's clear
#: radius, if that is more).
W_DIST = 0.6
W_FAR = 2.5
FAR_MM = 5.0
#: A label nearer another label's point than its own, per mm (up to 2 mm).
W_AMBIGUOUS = 3.0
#: Each further anchor (``others``) tried costs this much more.
W_OTHER = 0.5
#: Ink inside a box below this area (mm²) is touching, not crossing.
AREA_EPS = 0.02
#: A position this cheap is free (no line, no text); the labels with fewest such go first.
FREE = 8.0
#: A label that asks to keep clear of lines (:attr:`LabelRequest.keep`, a drawing of links on
#: a forces sheet: a letter touching a joint's circle, an arc or a hatch reads as part of it)
#: pays this for each line whose centre line comes within its ``keep`` of its box.
W_KEEP = 6.0
#: … for at most this many lines (a hatch's strokes are many lines: a letter beside the hatch
#: pays no more than beside a joint's circle and its link).
KEEP_LINES = 2
#: A label of a view that keeps its letters in its own cell (:attr:`LabelRequest.within`: a
#: plan in a grid of plans) pays this for a box that leaves the cell, and W_LINE more for each
#: mm it leaves it by (review 13: position 0's "p, o, e, f, s₃, d, g" stood in position 1's
#: plan, where the free side of its own cell was as near).
W_CELL = W_TEXT


@dataclass
class LabelRequest:
    """A label waiting to be placed next to ``anchor`` (sheet mm)."""

    anchor: XY
    markup: str
    height: float
    role: str
    prefer: tuple[float, float] | None
    clear: float  # the radius around the anchor the label keeps clear of (a joint's circle)
    id: str
    others: tuple[XY, ...] = ()  # further anchors to try, each at a small extra cost
    space: float = 0.0  # mm kept from other texts beyond PAD (labels that must read apart)
    keep: float = 0.0  # mm kept from every line's centre line where it can (W_KEEP a line)
    within: tuple[float, float, float, float] | None = None  # its view's cell (W_CELL outside)


@dataclass
class DimText:
    """A dimension's text waiting for its place: turned by ``angle`` (degrees, counter-clockwise
    on the paper) along the unit direction ``t``; ``candidates`` are the baseline starts to try,
    the preferred first; ``box`` its (width, rise, descent) in mm."""

    markup: str
    height: float
    angle: float
    t: tuple[float, float]
    candidates: tuple[XY, ...]
    box: tuple[float, float, float]


# -- geometry --------------------------------------------------------------------------------------


def text_outline(t: TextItem, pad: float = 0.0) -> Polygon:
    """The text's box on the paper (grown by ``pad``), turned by its angle about its baseline's
    start."""
    _, up, down = box(t.runs, t.height)
    return _turned_box(t.at, t.width, up, down, t.angle, pad)


def _turned_box(at: XY, w: float, up: float, down: float, angle: float, pad: float) -> Polygon:
    p = sbox(at[0] - pad, at[1] - up - pad, at[0] + w + pad, at[1] + down + pad)
    if angle:
        # counter-clockwise on the paper is clockwise in these y-down coordinates
        p = affinity.rotate(p, -angle, origin=at)
    return p


def _arc_points(it: ArcItem) -> list[XY]:
    # y is down on paper: a clockwise sweep (> 0) is an increasing atan2 angle
    a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
    n = max(8, int(abs(it.sweep) * it.r / 1.0) + 1)
    return [
        (
            it.c[0] + it.r * math.cos(a0 + it.sweep * i / n),
            it.c[1] + it.r * math.sin(a0 + it.sweep * i / n),
        )
        for i in range(n + 1)
    ]


def centre_line(it: Item) -> shapely.Geometry:
    """A drawn item's centre line (a filled shape: its area; a text: its box)."""
    if isinstance(it, TextItem):
        return text_outline(it)
    if isinstance(it, Polyline):
        pts = list(it.points)
        if it.fill and it.closed and len(pts) >= 3:
            return Polygon(pts)
        if it.closed:
            pts.append(pts[0])
        return LineString(pts) if len(pts) >= 2 else Point(pts[0])
    if isinstance(it, CircleItem):
        c = Point(it.c)
        return c.buffer(it.r) if it.fill else c.buffer(it.r).exterior
    return LineString(_arc_points(it))


def ink(it: Item, fmt: str) -> shapely.Geometry:
    """The ink of a drawn line: its centre line buffered by half its width (a filled shape as it
    is)."""
    g = centre_line(it)
    if isinstance(g, Polygon):
        return g
    half = style(it.role).weight * MAIN_LINE.get(fmt, 0.7) / 2.0
    return g.buffer(max(half, 0.05), quad_segs=2)


# -- the index -------------------------------------------------------------------------------------


@dataclass
class _Boxes:
    """Candidate boxes of a text: each ``core`` box, ``padded`` by :data:`PAD`, and, for the
    rows asked (:meth:`grown_middle`), the box ``grown`` by :data:`HALF` and its ``middle``
    (less a quarter of its height all round). Upright boxes keep their baseline starts and
    sizes (``at``; ``size``: width, rise, depth per row) and make those two only for the rows
    that need them; turned ones have all four made."""

    core: npt.NDArray[np.object_]
    padded: npt.NDArray[np.object_]
    grown: npt.NDArray[np.object_] | None = None
    middle: npt.NDArray[np.object_] | None = None
    at: npt.NDArray[np.float64] | None = None
    size: npt.NDArray[np.float64] | None = None

    @classmethod
    def turned(cls, ats: Sequence[XY], w: float, up: float, down: float, angle: float) -> _Boxes:
        """The boxes of a text turned by ``angle`` with its baseline starting at each of
        ``ats``."""
        q = min(w, up + down) / 4.0
        core, grown, padded, middle = (
            np.array([_turned_box(a, w, up, down, angle, g) for a in ats], dtype=object)
            for g in (0.0, HALF, PAD, -q)
        )
        return cls(core, padded, grown, middle)

    @classmethod
    def upright(cls, at: npt.NDArray[np.float64], size: npt.NDArray[np.float64]) -> _Boxes:
        """The boxes of upright texts with their baselines starting at the rows of ``at`` and
        the sizes (width, rise, depth) of the rows of ``size``."""
        x, y = at[:, 0], at[:, 1]
        w, up, down = size[:, 0], size[:, 1], size[:, 2]
        core, padded = (shapely.box(x - g, y - up - g, x + w + g, y + down + g) for g in (0.0, PAD))
        return cls(core, padded, at=at, size=size)

    def grown_middle(
        self, rows: npt.NDArray[np.int64]
    ) -> tuple[npt.NDArray[np.object_], npt.NDArray[np.object_]]:
        """The grown boxes and the middles of ``rows``."""
        if self.grown is not None and self.middle is not None:
            return self.grown[rows], self.middle[rows]
        assert self.at is not None and self.size is not None
        x, y = self.at[rows, 0], self.at[rows, 1]
        w, up, down = self.size[rows, 0], self.size[rows, 1], self.size[rows, 2]
        q = np.minimum(w, up + down) / 4.0
        grown, middle = (
            shapely.box(x - g, y - up - g, x + w + g, y + down + g) for g in (HALF, -q)
        )
        return grown, middle


class Index:
    """The sheet's ink and texts for overlap queries, and its free field."""

    def __init__(self, sheet: Sheet, frame: Frame) -> None:
        lines = [it for it in sheet.items if not isinstance(it, TextItem)]
        #: centre lines (filled shapes as areas)
        self.lines = np.array([centre_line(it) for it in lines], dtype=object)
        self._items = lines
        self._fmt = sheet.format
        self._ink: dict[int, shapely.Geometry] = {}
        self.filled = shapely.get_type_id(self.lines) == shapely.GeometryType.POLYGON
        self.tree = STRtree(self.lines)
        self.texts: list[Polygon] = [text_outline(t) for t in sheet.texts()]
        self._text_tree: STRtree | None = None
        self._text_arr = np.array([], dtype=object)
        self.frame = frame
        self.forms = reserved(sheet.width, sheet.height)

    def ink_inside(self, boxes: npt.NDArray[np.object_]) -> npt.NDArray[np.float64]:
        """The area (mm²) of ink inside each box: the exact measure, for a few boxes."""
        out = np.zeros(len(boxes))
        i, j = self.tree.query(boxes, predicate="intersects")
        if len(i):
            inks = np.array([self._ink_of(b) for b in j.tolist()], dtype=object)
            # each box's areas summed in the tree's order, as one box at a time would
            np.add.at(out, i, shapely.area(shapely.intersection(inks, boxes[i])))
        return out

    def _ink_of(self, b: int) -> shapely.Geometry:
        g = self._ink.get(b)
        if g is None:
            g = self._ink[b] = ink(self._items[b], self._fmt)
        return g

    def add_text(self, p: Polygon) -> None:
        self.texts.append(p)
        self._text_tree = None

    def _tt(self) -> STRtree:
        if self._text_tree is None:
            self._text_arr = np.array(self.texts, dtype=object)
            self._text_tree = STRtree(self._text_arr)
        return self._text_tree

    def text_hits(self, padded: npt.NDArray[np.object_]) -> npt.NDArray[np.int64]:
        """How many texts each box overlaps (by more than :data:`AREA_EPS`)."""
        n = len(padded)
        if not self.texts:
            return np.zeros(n, dtype=np.int64)
        tt = self._tt().query(padded, predicate="intersects")
        if not tt.shape[1]:
            return np.zeros(n, dtype=np.int64)
        area = shapely.area(shapely.intersection(padded[tt[0]], self._text_arr[tt[1]]))
        return np.bincount(tt[0][area > AREA_EPS], minlength=n)

    def text_cost(self, padded: npt.NDArray[np.object_]) -> npt.NDArray[np.float64]:
        """W_TEXT for each box that overlaps a text."""
        return W_TEXT * self.text_hits(padded).astype(np.float64)

    def outside(self, cands: npt.NDArray[np.object_]) -> npt.NDArray[np.bool_]:
        """Which boxes leave the field: the frame (less 0.5 mm) or onto a box of the form."""
        x0, y0, x1, y1 = shapely.bounds(cands).T
        f, m = self.frame, 0.5
        out: npt.NDArray[np.bool_] = (
            (x0 < f.left + m) | (y0 < f.top + m) | (x1 > f.right - m) | (y1 > f.bottom - m)
        )
        for a0, b0, a1, b1 in self.forms:
            out |= (x0 < a1 + m) & (a0 - m < x1) & (y0 < b1 + m) & (b0 - m < y1)
        return out

    def cost(self, boxes: _Boxes, texts: bool = True) -> npt.NDArray[np.float64]:
        """The overlap cost of each box: lines crossed, lines through its middle, lines near,
        texts overlapped (unless not ``texts``), and leaving the field."""
        core, padded = boxes.core, boxes.padded
        n = len(core)
        out = np.zeros(n)
        # a line crosses a box whose outline grown by a line's half width its centre line meets;
        # one through the box's middle (its core less a quarter of its height all round) is worse
        # than one that cuts a corner. The grown box and the middle lie inside the padded one, so
        # the lines they meet are among the padded box's: one tree query, then those pairs.
        i, j = self.tree.query(padded, predicate="intersects")
        rows, back = np.unique(i, return_inverse=True)
        grown, middle = boxes.grown_middle(rows)
        lines = self.lines[j]
        crossed = np.bincount(i[shapely.intersects(grown[back], lines)], minlength=n)
        near = np.bincount(i, minlength=n)
        out += W_LINE * crossed + W_NEAR * np.maximum(near - crossed, 0)
        out += W_MIDDLE * np.bincount(i[shapely.intersects(middle[back], lines)], minlength=n)
        if texts:
            out += self.text_cost(padded)
        out[self.outside(core)] += 1e6
        return out


# -- labels ----------------------------------------------------------------------------------------


@dataclass
class _Candidates:
    at: npt.NDArray[np.float64]  # (n, 2) baseline starts
    core: npt.NDArray[np.object_]
    padded: npt.NDArray[np.object_]
    base: npt.NDArray[np.float64]  # the cost that does not depend on other labels' texts
    anchor: npt.NDArray[np.int64]  # which anchor (0: the request's own, i: others[i − 1])


def _free_directions(
    index: Index, anchors: Sequence[XY], radii: Sequence[float]
) -> list[list[tuple[float, float]]]:
    """For each anchor, the middles of the free sectors around it: where the ink crosses a
    circle of its radius about it, the widest gaps between the crossings first (a line through
    the anchor gives its two normals)."""
    out: list[list[tuple[float, float]]] = [[] for _ in anchors]
    if not len(anchors):
        return out
    rings = shapely.get_exterior_ring(
        shapely.buffer(shapely.points(np.array(anchors, dtype=np.float64)), radii, quad_segs=16)
    )
    ri, li = index.tree.query(rings, predicate="intersects")
    if not len(ri):
        return out
    edges = index.lines[li]
    filled = index.filled[li]
    edges[filled] = shapely.boundary(edges[filled])
    parts, pi = shapely.get_parts(shapely.intersection(rings[ri], edges), return_index=True)
    keep = ~shapely.is_empty(parts)
    xy = shapely.get_coordinates(shapely.centroid(parts[keep]))
    crossings: list[list[tuple[float, float]]] = [[] for _ in anchors]
    for k, (x, y) in zip(ri[pi[keep]].tolist(), xy.tolist(), strict=True):
        crossings[k].append((x, y))
    for k, pts in enumerate(crossings):
        if not pts:
            continue
        ax, ay = anchors[k]
        angles = sorted(math.atan2(y - ay, x - ax) for x, y in pts)
        gaps = []
        for i, a in enumerate(angles):
            b = angles[(i + 1) % len(angles)] + (2.0 * math.pi if i + 1 == len(angles) else 0.0)
            gaps.append((b - a, (a + b) / 2.0))
        gaps.sort(key=lambda g: -g[0])
        out[k] = [(math.cos(m), math.sin(m)) for width, m in gaps[:3] if width > math.radians(40.0)]
    return out


def _boxes_around(
    anchor: XY, w: float, up: float, down: float, dirs: Sequence[tuple[float, float]], gap0: float
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """Baseline starts of a ``w`` × (up + down) box ``gap`` from the anchor along each direction:
    the box's nearest corner (or the middle of its nearest edge, for a direction within 22.5° of
    an axis) on the ray, the box beyond it; with each one's direction index (rows: each gap of
    :data:`GAPS`, each direction)."""
    h = up + down
    u: list[tuple[float, float, float, float]] = []
    for dx, dy in dirs:
        n = math.hypot(dx, dy)
        ux, uy = dx / n, dy / n
        sx = 1.0 if ux > ALIGN else -1.0 if ux < -ALIGN else 0.0
        sy = 1.0 if uy > ALIGN else -1.0 if uy < -ALIGN else 0.0
        u.append((ux, uy, sx * w / 2.0, sy * h / 2.0))
    ua = np.array(u, dtype=np.float64)
    g = (np.array(GAPS, dtype=np.float64) + gap0)[:, None]
    cx = anchor[0] + ua[:, 0] * g + ua[:, 2]
    cy = anchor[1] + ua[:, 1] * g + ua[:, 3]
    at = np.stack([cx - w / 2.0, cy - h / 2.0 + up], axis=-1).reshape(-1, 2)
    return at, np.tile(np.arange(len(u), dtype=np.int64), len(GAPS))


def _candidates(
    requests: Sequence[LabelRequest], index: Index, points: npt.NDArray[np.float64]
) -> list[_Candidates]:
    """Every request's candidate positions and their costs that do not depend on the other
    labels, all requests' boxes measured together (one query of the index for all of them)."""
    sizes = [box(parse(r.markup), r.height) for r in requests]
    anchors = [(ri, a) for ri, r in enumerate(requests) for a in (r.anchor, *r.others)]
    free = _free_directions(
        index, [a for _, a in anchors], [requests[ri].clear + 1.5 for ri, _ in anchors]
    )
    all_at: list[npt.NDArray[np.float64]] = []
    owner: list[npt.NDArray[np.int64]] = []
    anchor_of: list[npt.NDArray[np.int64]] = []
    order: list[npt.NDArray[np.float64]] = []
    ai = 0
    for ri, req in enumerate(requests):
        w, up, down = sizes[ri]
        for k in range(1 + len(req.others)):
            a = anchors[ai][1]
            dirs: list[tuple[float, float]] = []
            if req.prefer is not None:
                dirs.append(req.prefer)
            dirs += free[ai]
            ai += 1
            first = len(dirs)
            dirs += DIRECTIONS
            ats, dis = _boxes_around(a, w, up, down, dirs, req.clear)
            all_at.append(ats)
            owner.append(np.full(len(ats), ri, dtype=np.int64))
            anchor_of.append(np.full(len(ats), k, dtype=np.int64))
            order.append(np.where(dis < first, 0.05 * dis, 0.3 + 0.1 * (dis - first)))
    at = np.concatenate(all_at)
    who = np.concatenate(owner)
    which = np.concatenate(anchor_of)
    starts = np.searchsorted(who, np.arange(len(requests) + 1))
    boxes = _Boxes.upright(at, np.array(sizes, dtype=np.float64)[who])
    core = boxes.core
    clear = np.array([r.clear for r in requests], dtype=np.float64)[who]
    far = np.array([max(FAR_MM, r.clear + 3.0) for r in requests], dtype=np.float64)[who]
    used = np.array([a for _, a in anchors], dtype=np.float64)
    first_anchor = np.cumsum([0] + [1 + len(r.others) for r in requests])[:-1]
    own = shapely.points(used[first_anchor[who] + which])
    d = shapely.distance(core, own) - clear
    base = W_DIST * d + W_FAR * np.maximum(d + clear - far, 0.0)
    base += np.concatenate(order) + W_OTHER * which
    # nearer another label's point than its own: the label would name the wrong point. Only
    # the points within the box's distance to its own anchor count, so a pair is measured
    # exactly only where the point's distance to the box's rectangle (numpy) is not more
    if len(points):
        reach = d + clear
        bounds = shapely.bounds(core)
        ci: list[npt.NDArray[np.int64]] = []
        pj: list[npt.NDArray[np.int64]] = []
        for ri, req in enumerate(requests):
            r = np.hypot(points[:, 0] - req.anchor[0], points[:, 1] - req.anchor[1])
            near = np.flatnonzero(r < 25.0)
            near = near[~(r[near] < 1.0)]
            if not len(near):
                continue
            rows = np.arange(starts[ri], starts[ri + 1])
            b, p = bounds[rows][:, None, :], points[near][None, :, :]
            gx = np.maximum(np.maximum(b[..., 0] - p[..., 0], p[..., 0] - b[..., 2]), 0.0)
            gy = np.maximum(np.maximum(b[..., 1] - p[..., 1], p[..., 1] - b[..., 3]), 0.0)
            ii, jj = np.nonzero(np.hypot(gx, gy) <= reach[rows][:, None] + tol.SHEET_MM)
            ci.append(rows[ii])
            pj.append(near[jj])
        c_i = np.concatenate(ci) if ci else np.zeros(0, dtype=np.int64)
        p_j = np.concatenate(pj) if pj else np.zeros(0, dtype=np.int64)
        if len(c_i):
            dq = np.full(len(at), np.inf)
            np.minimum.at(dq, c_i, shapely.distance(core[c_i], shapely.points(points[p_j])))
            hit = np.isfinite(dq)
            base[hit] += W_AMBIGUOUS * np.clip(d[hit] + clear[hit] - dq[hit], 0.0, 2.0)
    base += index.cost(boxes, texts=False)
    keep = np.array([r.keep for r in requests], dtype=np.float64)[who]
    kept = np.flatnonzero(keep > 0.0)
    if len(kept):
        # the labels that keep clear of lines: each line near their box (its ink touching it)
        g = keep[kept][:, None] * np.array([-1.0, -1.0, 1.0, 1.0])
        wide = shapely.box(*(shapely.bounds(core[kept]) + g).T)
        ki, _ = index.tree.query(wide, predicate="intersects")
        base[kept] += W_KEEP * np.minimum(np.bincount(ki, minlength=len(kept)), KEEP_LINES)
    cell = np.array([r.within or (np.nan,) * 4 for r in requests], dtype=np.float64)[who]
    celled = np.flatnonzero(~np.isnan(cell[:, 0]))
    if len(celled):
        b, c = shapely.bounds(core[celled]), cell[celled]
        out = np.maximum(np.maximum(c[:, :2] - b[:, :2], b[:, 2:] - c[:, 2:]), 0.0).max(axis=1)
        base[celled] += np.where(out > tol.SHEET_MM, W_CELL + W_LINE * out, 0.0)
    # the cheapest few measured exactly: the ink inside each (a line through the letters
    # against one that grazes an edge); the others wait behind them
    best = np.concatenate(
        [s + np.argsort(base[s:e], kind="stable")[:REFINE] for s, e in itertools.pairwise(starts)]
    )
    inner = shapely.box(*(shapely.bounds(core[best]) + np.array([0.25, 0.25, -0.25, -0.25])).T)
    extra = np.full(len(base), W_LINE)
    extra[best] = W_INK * index.ink_inside(inner)
    base += extra
    padded = boxes.padded
    space = np.array([r.space for r in requests], dtype=np.float64)[who]
    if np.any(space > 0.0):
        padded = padded.copy()
        sp = np.flatnonzero(space > 0.0)
        g = (PAD + space[sp])[:, None] * np.array([-1.0, -1.0, 1.0, 1.0])
        padded[sp] = shapely.box(*(shapely.bounds(core[sp]) + g).T)
    return [
        _Candidates(at[s:e], core[s:e], padded[s:e], base[s:e], which[s:e])
        for s, e in itertools.pairwise(starts)
    ]


def _overlaps(
    boxes: npt.NDArray[np.float64], others: npt.NDArray[np.float64]
) -> npt.NDArray[np.int64]:
    """How many of the upright rectangles ``others`` (rows x0, y0, x1, y1) each of ``boxes``
    overlaps by more than :data:`AREA_EPS`."""
    if not len(others):
        return np.zeros(len(boxes), dtype=np.int64)
    b, o = boxes[:, None, :], others[None, :, :]
    dx = np.minimum(b[..., 2], o[..., 2]) - np.maximum(b[..., 0], o[..., 0])
    dy = np.minimum(b[..., 3], o[..., 3]) - np.maximum(b[..., 1], o[..., 1])
    area = np.maximum(dx, 0.0) * np.maximum(dy, 0.0)
    hits: npt.NDArray[np.int64] = np.count_nonzero(area > AREA_EPS, axis=1)
    return hits


def place_labels(sheet: Sheet, index: Index, requests: Sequence[LabelRequest]) -> None:
    """Place every request on the sheet: the most constrained first, then each once more with
    all the others in place; records each label with the point it names in ``sheet.anchors``."""
    if not requests:
        return
    points = np.array([r.anchor for r in requests], dtype=np.float64).reshape(-1, 2)
    cands = _candidates(requests, index, points)
    # the texts already on the sheet, once for every candidate; the labels' own boxes (upright
    # rectangles) are counted as they are placed
    hits = index.text_hits(np.concatenate([c.padded for c in cands]))
    cuts = np.cumsum([len(c.base) for c in cands])[:-1]
    fixed = np.split(hits, cuts)
    pads = [shapely.bounds(c.padded) for c in cands]
    hulls = np.array([(p[:, 0].min(), p[:, 1].min(), p[:, 2].max(), p[:, 3].max()) for p in pads])
    # the fewest free positions first (a label in a crowd before one in the open)
    free = [
        int(np.sum(c.base + W_TEXT * f.astype(np.float64) < FREE))
        for c, f in zip(cands, fixed, strict=True)
    ]
    order = sorted(range(len(requests)), key=lambda i: free[i])
    chosen: dict[int, int] = {}
    placed = np.zeros((len(requests), 4))
    on = np.zeros(len(requests), dtype=bool)
    for rnd in range(2):
        for i in order:
            c = cands[i]
            on[i] = False  # a label is placed again with the others in place, not itself
            h = hulls[i]
            near = on & (placed[:, 0] <= h[2]) & (h[0] <= placed[:, 2])
            near &= (placed[:, 1] <= h[3]) & (h[1] <= placed[:, 3])
            n = fixed[i] + _overlaps(pads[i], placed[near])
            total = c.base + W_TEXT * n.astype(np.float64)
            k = int(np.argmin(total))
            if rnd and total[chosen[i]] <= total[k] + tol.SHEET_MM:
                k = chosen[i]
            chosen[i] = k
            placed[i] = shapely.bounds(c.core[k])
            on[i] = True
    for i in order:
        index.add_text(cands[i].core[chosen[i]])
    fs_cache: dict[float, float] = {}
    for i, req in enumerate(requests):
        c = cands[i]
        k = chosen[i]
        runs = parse(req.markup)
        w, _, _ = box(runs, req.height)
        fs = fs_cache.setdefault(req.height, metrics().font_size(req.height))
        item = TextItem((float(c.at[k, 0]), float(c.at[k, 1])), runs, req.height, fs, w,
                        req.role, req.id)  # fmt: skip
        sheet.add(item)
        used = req.anchor if c.anchor[k] == 0 else req.others[c.anchor[k] - 1]
        sheet.anchors.append((item, used))


# -- dimension texts -------------------------------------------------------------------------------


def place_dims(sheet: Sheet, index: Index, dims: Sequence[DimText]) -> None:
    """Put each dimension's text at its first candidate clear of lines and texts (else the
    cheapest), through the same index."""
    if not dims:
        return
    for dim in dims:
        w, rise, down = dim.box
        boxes = _Boxes.turned(dim.candidates, w, rise, down, dim.angle)
        total = index.cost(boxes) + 0.01 * np.arange(len(dim.candidates))
        k = int(np.argmin(total))
        runs = parse(dim.markup)
        item = TextItem(dim.candidates[k], runs, dim.height, metrics().font_size(dim.height),
                        w, "label", angle=dim.angle)  # fmt: skip
        sheet.add(item)
        index.add_text(boxes.core[k])


def shrink_moved(sheet: Sheet, moved: Sequence[TextItem]) -> None:
    """Each text moved off графа 26 that now runs into another text is set at the next smaller
    GOST height (down to 2.5 mm) until it runs into none."""
    items = sheet.items
    for t in moved:
        i = next(k for k, it in enumerate(items) if it is t)
        others = [text_outline(o) for o in sheet.texts() if o is not t]
        tree = STRtree(np.array(others, dtype=object)) if others else None
        cur = t
        for h in (3.5, 2.5):
            p = text_outline(cur)
            clash = tree is not None and any(
                others[j].intersection(p).area > 0.0 for j in tree.query(p, predicate="intersects")
            )
            if not clash or h >= cur.height:
                break
            w, _, _ = box(cur.runs, h)
            cur = dataclasses.replace(cur, height=h, font_size=metrics().font_size(h), width=w)
        items[i] = cur


def drop_crossed(sheet: Sheet, index: Index, texts: Sequence[TextItem]) -> None:
    """Take off the sheet (and the index) each of ``texts`` that a drawn line crosses: a centre
    line meets its box less 0.25 mm all round, grown by :data:`HALF`."""
    if not texts:
        return
    inner = np.array([text_outline(t, HALF - 0.25) for t in texts], dtype=object)
    hit = index.tree.query(inner, predicate="intersects")[0]
    crossed = {id(texts[i]) for i in hit}
    if crossed:
        sheet.items[:] = [it for it in sheet.items if id(it) not in crossed]
        index.texts = [text_outline(t) for t in sheet.texts()]
        index._text_tree = None


#: The thin lines broken where they run through a label (GOST 2.316: a text on a drawing is
#: not crossed by lines; a thin line is interrupted at it, as hatching is at an inscription,
#: GOST 2.306): review 11 found thin lines of the twelve positions through the numbers "9",
#: "11" and the letter "S5". The main lines and the vectors are never broken (the placer keeps
#: labels off them where it can).
BROKEN_ROLES = frozenset({"thin", "construction", "centre", "extreme", "locus", "ground"})
#: The gap (mm) a broken line keeps from the label's box; a piece left shorter than it is
#: dropped (a crumb of a line, no line).
BREAK_PAD = 0.5


def break_under_labels(sheet: Sheet) -> None:
    """Break each open thin line of :data:`BROKEN_ROLES` that runs into a label's box (role
    ``label``) where it does: the line's parts outside the box grown by :data:`BREAK_PAD` are
    kept, each with its own dash pattern. A line wholly within the grown box (a bar over the
    label's letters) and one that only reaches the grown box (a leader to the label) are
    kept whole."""
    labels = [t for t in sheet.items if isinstance(t, TextItem) and t.role == "label"]
    if not labels:
        return
    own = [text_outline(t) for t in labels]
    grown = [text_outline(t, BREAK_PAD) for t in labels]
    tree = STRtree(np.array(own, dtype=object))
    out: list[Item] = []
    for it in sheet.items:
        if not (
            isinstance(it, Polyline) and it.role in BROKEN_ROLES and not it.closed
            and not it.fill and len(it.points) >= 2
        ):  # fmt: skip
            out.append(it)
            continue
        line = LineString(it.points)
        hit = [grown[j] for j in tree.query(line, predicate="intersects")
               if not grown[j].contains(line)]  # fmt: skip
        if not hit:
            out.append(it)
            continue
        rest = line.difference(shapely.union_all(hit))
        for part in getattr(rest, "geoms", [rest]):
            if isinstance(part, LineString) and part.length > BREAK_PAD:
                pts = tuple((float(x), float(y)) for x, y in part.coords)
                out.append(dataclasses.replace(
                    it, points=pts, dash=fit_open(style(it.role).line, part.length)))  # fmt: skip
    sheet.items[:] = out


def break_round(sheet: Sheet, first: int, last: int, zones: Sequence[shapely.Geometry]) -> None:
    """Break the lines among ``sheet.items[first:last]`` (polylines, open or closed, not filled)
    where they run into one of ``zones`` (paper mm): their parts outside the zones are kept,
    each an open line with its own dash pattern; the other items are left as they are."""
    if not zones:
        return
    zone = shapely.union_all(list(zones))
    out: list[Item] = list(sheet.items[:first])
    for it in sheet.items[first:last]:
        if not isinstance(it, Polyline) or it.fill or len(it.points) < 2:
            out.append(it)
            continue
        pts = (*it.points, it.points[0]) if it.closed else it.points
        line = LineString(pts)
        if not line.intersects(zone):
            out.append(it)
            continue
        rest = line.difference(zone)
        for part in getattr(rest, "geoms", [rest]):
            if isinstance(part, LineString) and part.length > BREAK_PAD:
                q = tuple((float(x), float(y)) for x, y in part.coords)
                dash = fit_open(style(it.role).line, part.length)
                out.append(dataclasses.replace(it, points=q, closed=False, dash=dash))
    out += sheet.items[last:]
    sheet.items[:] = out


def clip_to_circle(items: Sequence[Item], c: XY, r: float) -> list[Item]:
    """What of ``items`` (paper mm) lies inside the circle of centre ``c`` and radius ``r`` (a
    detail view's content ends at its circle, ESKD 2.305): an open line cut where it leaves the
    circle (each part inside a line of its own); a closed or filled shape, a circle or an arc
    kept whole where it reaches inside; a text where the middle of its box lies inside; the
    rest left out."""
    disc = Point(c).buffer(r, quad_segs=64)
    out: list[Item] = []
    for it in items:
        if isinstance(it, TextItem):
            if disc.contains(text_outline(it).centroid):
                out.append(it)
            continue
        line = centre_line(it)
        if disc.contains(line):
            out.append(it)
        elif not disc.intersects(line):
            continue
        elif isinstance(it, Polyline) and not it.closed and not it.fill:
            cut = line.intersection(disc)
            for part in getattr(cut, "geoms", [cut]):
                if isinstance(part, LineString) and not part.is_empty and part.length > 0.0:
                    pts = tuple((float(x), float(y)) for x, y in part.coords)
                    out.append(dataclasses.replace(it, points=pts))
        else:
            out.append(it)
    return out


def within_hull(pts: Sequence[XY], other: Sequence[XY], grow: float) -> bool:
    """Whether every one of the points ``pts`` lies within the convex hull of ``other`` grown
    by ``grow`` (paper mm)."""
    hull = shapely.MultiPoint([tuple(q) for q in other]).convex_hull.buffer(grow)
    return all(hull.covers(Point(q)) for q in pts)
