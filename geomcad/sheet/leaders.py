"""Values set apart from what they name, with a leader: where a drawing is so crowded round an
angle's arc that no place beside it is free (an angle among the links and the construction),
the value goes to the nearest place that no drawn line crosses, joined to the arc by a thin
leader that crosses no link.

Appended for the seed sheets (2013-6's angle 90° − θ at B1); any viewport may use it.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from geomcad.geom import Vec
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.model import ArcItem, CircleItem, Polyline
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse

#: Arcs and circles are taken as chords of at most this length (mm).
CHORD_MM = 1.5
#: How far (mm) from the arc the value may go, nearest first.
LEADER_REACH_MM = (3.0, 5.0, 7.0, 9.0, 12.0, 15.0, 18.0, 22.0, 27.0, 33.0, 40.0)
#: Where on the arc (share of its sweep) the leader may start, the middle first.
ON_ARC = (0.5, 0.35, 0.65, 0.2, 0.8)
#: Directions tried from the arc (a full turn in this many steps, outward first).
DIRECTIONS = 24
#: The free room (mm) round the value's box and round the leader's path.
TEXT_CLEAR_MM = 0.8
PATH_CLEAR_MM = 0.3
#: Samples along the leader tested against the links.
PATH_SAMPLES = 80
#: Over this distance (mm) beyond the value's half width, the value is joined by a leader.
LEADER_FROM_MM = 2.0
#: The underline under the value, below its base line (mm).
UNDERLINE_MM = 0.6


def ink(items: Sequence[Any]) -> np.ndarray:
    """The drawn lines of ``items`` as paper segments (x1, y1, x2, y2): polylines by their
    sides, circles and arcs by chords of at most :data:`CHORD_MM`."""
    out: list[tuple[float, float, float, float]] = []
    for it in items:
        if isinstance(it, Polyline):
            pts = [*it.points, *([it.points[0]] if it.closed else [])]
            out += [(*a, *b) for a, b in itertools.pairwise(pts)]
        elif isinstance(it, CircleItem | ArcItem):
            if isinstance(it, CircleItem):
                a0, sweep = 0.0, 2.0 * math.pi
            else:
                a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
                sweep = it.sweep
            n = max(8, int(abs(sweep) * it.r / CHORD_MM) + 1)
            t = a0 + np.linspace(0.0, sweep, n + 1)
            xs, ys = it.c[0] + it.r * np.cos(t), it.c[1] + it.r * np.sin(t)
            out += [(xs[i], ys[i], xs[i + 1], ys[i + 1]) for i in range(n)]
    return np.array(out, dtype=np.float64).reshape(-1, 4)


def crossed(segs: np.ndarray, b: tuple[float, float, float, float]) -> bool:
    """Whether a segment crosses or lies in the box b = (x0, y0, x1, y1) (Liang–Barsky, all
    segments at once)."""
    if segs.size == 0:
        return False
    x1, y1, x2, y2 = segs.T
    dx, dy = x2 - x1, y2 - y1
    t0, t1 = np.zeros_like(x1), np.ones_like(x1)
    ok = np.ones(x1.shape, dtype=bool)
    for p, q in ((-dx, x1 - b[0]), (dx, b[2] - x1), (-dy, y1 - b[1]), (dy, b[3] - y1)):
        zero = p == 0.0
        ok &= ~(zero & (q < 0.0))
        r = q / np.where(zero, 1.0, p)
        t0 = np.where(~zero & (p < 0.0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (p > 0.0), np.minimum(t1, r), t1)
    return bool(np.any(ok & (t0 <= t1)))


def angle_with_leader(
    v: Viewport, vertex: Vec, p1: Vec, p2: Vec, text: str, r_mm: float, height: float = 2.5
) -> None:
    """An angle's arc at ``vertex`` (from ``p1`` to ``p2``, ``r_mm`` on the paper) whose value
    stands where no line crosses it, as near the arc as that allows, joined to the arc's
    middle by a thin leader when it stands apart. Call it when every line it must keep clear of
    is drawn; the dimensions' texts placed at the finish keep every place they may take."""
    v.dim_angle(vertex, p1, p2, text, r_mm=r_mm, height=height)
    mid = v.d.pending.pop().anchor  # the arc's middle; the value is placed here instead
    w, rise, down = text_box(parse(text), height)
    segs = ink(v.sheet.items)
    links = ink([it for it in v.sheet.items if it.role in ("link", "joint")])
    # the arc's points on the paper, its middle first (as dim_angle draws it)
    a1, a2 = (p1 - vertex).angle, (p2 - vertex).angle
    sweep = math.remainder(a2 - a1, 2.0 * math.pi)
    start, sweep = (a1, sweep) if sweep > 0 else (a2, -sweep)
    c = v.p(vertex)
    on_arc = [
        (c[0] + r_mm * math.cos(start + sweep * t), c[1] - r_mm * math.sin(start + sweep * t))
        for t in ON_ARC
    ]
    # the dimensions' texts are placed at the finish, anywhere along their lines: every place
    # they may take is kept free (a disc round the text's middle at each candidate)
    dims = []
    for dt in v.d.dims:
        dw, rise_d = dt.box[0], dt.box[1]
        for at in dt.candidates:
            dims.append((at[0] + dt.t[0] * dw / 2.0, at[1] + dt.t[1] * dw / 2.0, rise_d + 1.0))

    def near_dim(x: float, y: float, pad: float) -> bool:
        return any(math.hypot(x - dx, y - dy) < rr + pad for dx, dy, rr in dims)

    half = DIRECTIONS / 2.0
    cl, pc = TEXT_CLEAR_MM, PATH_CLEAR_MM
    best = None
    for r in LEADER_REACH_MM:
        for p0 in on_arc:
            out = math.atan2(-(p0[1] - c[1]), p0[0] - c[0])  # outward through the arc
            for k in sorted(
                range(DIRECTIONS),
                key=lambda k: abs(math.remainder(k * math.pi / half - out, 2 * math.pi)),
            ):
                a = k * math.pi / half
                cx, cy = p0[0] + r * math.cos(a), p0[1] - r * math.sin(a)
                box = (cx - w / 2.0 - cl, cy - rise / 2.0 - cl, cx + w / 2.0 + cl,
                       cy + rise / 2.0 + down + cl)  # fmt: skip
                if crossed(segs, box) or near_dim(cx, cy, w / 2.0):
                    continue
                # the leader crosses no link (thin lines it may)
                steps = [
                    (
                        p0[0] + (cx - p0[0]) * t / PATH_SAMPLES,
                        p0[1] + (cy - p0[1]) * t / PATH_SAMPLES,
                    )
                    for t in range(PATH_SAMPLES + 1)
                ]
                if not any(crossed(links, (x - pc, y - pc, x + pc, y + pc))
                           or near_dim(x, y, 0.5) for x, y in steps):  # fmt: skip
                    best, mid = (cx, cy), p0
                    break
            if best is not None:
                break
        if best is not None:
            break
    if best is None:  # nowhere free: beside the arc as the label placer would
        v.d.label(mid, text, height, clear=0.5)
        return
    cx, cy = best
    if math.dist(best, mid) > w / 2.0 + LEADER_FROM_MM:
        # the leader from the arc to the nearer end of the text's underline
        under = cy + rise / 2.0 + UNDERLINE_MM
        end = (cx - w / 2.0, under) if mid[0] < cx else (cx + w / 2.0, under)
        v.sheet.add(Polyline((mid, end), "dimension"))
        v.sheet.add(Polyline(((cx - w / 2.0, end[1]), (cx + w / 2.0, end[1])), "dimension"))
    v.d.text(text, (cx - w / 2.0, cy + rise / 2.0), height)
