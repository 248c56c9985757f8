"""A view's insets of short forces (ESKD выносные элементы): one μ_F for the view itself.

A view (the mechanism with its loads, a group's free body, Zhukovsky's lever) draws every force
at its one μ_F (:func:`~geomcad.sheet.loads.view_scales`), so that a longer arrow is a larger
force everywhere in it. A force that would be shorter than two arrowheads there is drawn
instead in an inset: a thin circle round its point on the view, lettered, and elsewhere in the
view's box the point again with its short forces at their own finer μ_F (stated in the inset's
caption, "Б (μ_F = 2 Н/мм)"), same directions, each inset at one μ_F. The insets go where the
view's box is free of what is drawn, the nearest such place to their point.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from geomcad.geom import Vec
from geomcad.sheet.drawing import SHORT_MM, Drawing, Viewport
from geomcad.sheet.lang import Words
from geomcad.sheet.loads import ForceScales, chord_points, force, inset_bands
from geomcad.sheet.model import ArcItem, CircleItem, Polyline, TextItem
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scale import Scale
from geomcad.sheet.text import box, parse

WORDS = Words(__package__, "linkage_forces")

#: The radius (mm) of the thin circle round a point whose short forces are in an inset.
MARK_R = 3.5
#: The cap height (mm) of an inset's caption and of its labels, and the letter's on the view.
CAPTION_H = 2.5
LETTER_H = 3.5
#: Room (mm) kept round an inset's arrows for their labels, and between an inset and what is
#: drawn (the raster's cell is CELL_MM).
LABEL_PAD = 6.0
KEEP_MM = 2.0
CELL_MM = 1.0


@dataclass(frozen=True)
class Short:
    """A force drawn in an inset: at model point ``at``, ``F`` (N), its label and role, the
    index ``tier`` of its μ_F in the view's :class:`ForceScales`."""

    at: Vec
    F: Vec
    label: str
    role: str
    tier: int


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

    def add(self, at: Vec, F: Vec, tier: int, label: str, role: str) -> None:
        self.shorts.append(Short(at, F, label, role, tier))

    def groups(self, eps: float) -> list[tuple[Vec, list[tuple[Scale, list[Short]]]]]:
        """The short forces by their point (points within ``eps`` model units are one), and at
        each point by the μ_F of its insets (:func:`~geomcad.sheet.loads.inset_bands`, the
        coarsest first): one inset each, as few at a point as its forces allow."""
        out: list[tuple[Vec, list[Short]]] = []
        for s in self.shorts:
            for q, ss in out:
                if s.at.dist(q) <= eps:
                    ss.append(s)
                    break
            else:
                out.append((s.at, [s]))
        res = []
        for q, ss in out:
            bands = inset_bands([s.F.norm for s in ss])[::-1]
            by: list[tuple[Scale, list[Short]]] = [(sc, []) for sc in bands]
            for s in ss:
                i = next(i for i, (sc, _) in enumerate(by) if s.F.norm / sc.k >= SHORT_MM * 0.999)
                by[i][1].append(s)
            res.append((q, [b for b in by if b[1]]))
        return res

    def name_of(self, q: Vec, eps: float) -> str:
        """The name of the view's point at ``q`` ("" where none is)."""
        return next((n for n, p in self.points.items() if p.dist(q) <= eps), "")

    def draw(
        self,
        d: Drawing,
        v: Viewport,
        field: tuple[float, float, float, float],
        start: int,
        letters: Iterator[str],
    ) -> None:
        """The insets into ``field`` (sheet mm), clear of the items drawn since ``start`` (the
        view's first), each lettered from ``letters`` with a thin circle round its point on
        the view ``v``."""
        if not self.shorts:
            return
        eps = v.scale.model(0.8)
        free = _Free(d, start, field)
        for q, tiers in self.groups(v.scale.model(2.0 * MARK_R)):
            p = v.p(q)
            mine: list[str] = []
            for sc, shorts in tiers:
                letter = next(letters)
                mine.append(letter)
                self.drawn.append((letter, sc))
                self._one(d, v, free, q, p, letter, sc, shorts, eps)
            # one thin circle round the points of the insets (centred on them)
            ats = [v.p(s.at) for _, ss in tiers for s in ss]
            xs, ys = [a[0] for a in ats], [a[1] for a in ats]
            c = ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0)
            r = MARK_R + max(math.dist(c, a) for a in ats)
            d.sheet.add(CircleItem(c, r, "thin"))
            # the letter by the circle (anchored on it, up and to the right where free)
            # (or by another point of the circle, where that one is clearer of the lines)
            edge = (c[0] + r * math.sqrt(0.5), c[1] - r * math.sqrt(0.5))
            turns = [math.radians(a) for a in range(0, 360, 45) if a != 45]
            round_ = tuple((c[0] + r * math.cos(t), c[1] - r * math.sin(t)) for t in turns)
            d.label(edge, ", ".join(mine), LETTER_H, prefer=(0.7, -0.7), clear=0.5, others=round_)

    def _one(
        self,
        d: Drawing,
        v: Viewport,
        free: _Free,
        q: Vec,
        p: tuple[float, float],
        letter: str,
        sc: Scale,
        shorts: list[Short],
        eps: float,
    ) -> None:
        from geomcad.sheet.compose import scale_text

        caption = WORDS("inset", letter=letter, scale=scale_text(sc))
        starts = side_by_side([s.F for s in shorts], sc.k)
        arrive = pushes([s.F for s in shorts])
        # paper mm from the point: the far ends of the arrows (leaving it, or arriving)
        # each force at its own point (a detail keeps the view's μ_l): offsets from q
        rel = [((s.at.x - q.x) / v.scale.k, (q.y - s.at.y) / v.scale.k) for s in shorts]
        starts = [(o[0] + e[0], o[1] + e[1]) for o, e in zip(starts, rel, strict=True)]
        tips = [
            (o[0] + (-1.0 if a else 1.0) * s.F.x / sc.k, o[1] + (1.0 if a else -1.0) * s.F.y / sc.k)
            for o, a, s in zip(starts, arrive, shorts, strict=True)
        ]
        tips += starts
        x0 = min(0.0, *(t[0] for t in tips)) - LABEL_PAD
        x1 = max(0.0, *(t[0] for t in tips)) + LABEL_PAD
        y0 = min(0.0, *(t[1] for t in tips)) - LABEL_PAD
        y1 = max(0.0, *(t[1] for t in tips)) + LABEL_PAD
        cap_w = box(parse(caption), CAPTION_H)[0]
        cap = CAPTION_H * 2.0
        w, h = max(x1 - x0, cap_w), (y1 - y0) + cap
        corner = free.place(w, h, p)
        # the point in the inset, its arrows' box under the caption
        at = (corner[0] + (w - (x1 - x0)) / 2.0 - x0, corner[1] + cap - y0)
        d.text(caption, (corner[0] + (w - cap_w) / 2.0, corner[1] + CAPTION_H), CAPTION_H)
        iv = Viewport(d, v.scale, q.x, q.y, at)
        pts: list[Vec] = []
        for s in shorts:
            if all(s.at.dist(u) > eps for u in pts):
                pts.append(s.at)
        for u in pts:
            iv.dot(u)
            name = self.name_of(u, eps)
            if name:
                iv.label(u, markup_of(name), CAPTION_H, clear=0.8)
        for o, e, a, s in zip(starts, rel, arrive, shorts, strict=True):
            q2 = q + Vec(o[0], -o[1]) * v.scale.k
            if o != e:  # set beside the others on its line: a thin line to its point
                iv.seg(s.at, q2, "thin")
            force(iv, q2, s.F, sc.k, s.label, arrive=a, role=s.role, height=CAPTION_H)
        free.take(corner, w, h)

    def text(self) -> str:
        """The line under the view's caption that states the insets' μ_F:
        ``выносные элементы Б, В: μ_F = 2 Н/мм; Г: μ_F = 0,2 Н/мм`` ("" without insets)."""
        from geomcad.sheet.compose import scale_text

        by: dict[str, list[str]] = {}
        for letter, sc in self.drawn:
            by.setdefault(scale_text(sc), []).append(letter)
        if not by:
            return ""
        items = "; ".join(f"{', '.join(ls)}: {t}" for t, ls in by.items())
        return WORDS("insets", items=items)


#: Two forces at one point closer in direction than this (degrees) are set side by side.
SAME_LINE_DEG = 20.0
#: … this far apart (mm), across their line.
BESIDE_MM = 3.0


def side_by_side(forces: list[Vec], k: float) -> list[tuple[float, float]]:
    """Where (paper mm from their point, y down) the arrows of ``forces`` drawn from one point
    at ``k`` N/mm start: at the point, but a force of about the sense of a longer one before
    it (within :data:`SAME_LINE_DEG`) set :data:`BESIDE_MM` across its line for each such
    one, so that no arrow lies on another (G₅ and Φ₅ both down at d)."""
    cos = math.cos(math.radians(SAME_LINE_DEG))
    out: list[tuple[float, float]] = []
    for i, F in enumerate(forces):
        u = F.unit()
        n = sum(1 for G in forces[:i] if G.unit().dot(u) > cos)
        side = BESIDE_MM * n
        out.append((u.y * side, u.x * side) if n else (0.0, 0.0))
    return out


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
        self.grid = _grow(grid, math.ceil(KEEP_MM / CELL_MM))
        for rq in d.pending:  # the labels still to be placed take room round their points
            self._rect(self.grid, rq.anchor[0] - LABEL_PAD, rq.anchor[1] - LABEL_PAD,
                       2 * LABEL_PAD, 2 * LABEL_PAD)  # fmt: skip

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
        ``near``; where none is free, the one that covers the fewest taken cells."""
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
        dist = np.hypot(cx - near[0], cy - near[1])
        cost = taken * 1.0e4 + dist
        k = int(np.argmin(cost))
        i, j = divmod(k, taken.shape[1])
        return self.field[0] + j * CELL_MM, self.field[1] + i * CELL_MM

    def take(self, corner: tuple[float, float], w: float, h: float) -> None:
        self._rect(self.grid, corner[0] - KEEP_MM, corner[1] - KEEP_MM,
                   w + 2 * KEEP_MM, h + 2 * KEEP_MM)  # fmt: skip


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
