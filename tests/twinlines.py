"""The twin-line check of a forces sheet's plans (review 9, fix 4): no two near-parallel lines
of a force plan closer than :data:`NEAR_MM` over more than :data:`RUN_MM` (two long lines a
fraction of a millimetre apart read as one smudged line; a plan draws such a pair as one line,
"R₃₂ = −R₁₂", or side by side at least a lane apart)."""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence

from geomcad.sheet.compose import compose
from geomcad.sheet.model import Polyline, Sheet
from geomcad.sheet.views import Polygon

XY = tuple[float, float]
Box = tuple[float, float, float, float]
#: Lines closer than this (mm) …
NEAR_MM = 1.0
#: … but not on one another (one line drawn twice, e.g. two arrows of one line), nor two sides
#: of the polygon meeting at a vertex (a thin triangle: one end of one on the other's line) …
SAME_MM = 0.05
#: (two sides meet where their lines cross this close (mm) to an end of each: an arrowhead)
MEET_MM = 4.0
#: … within this angle …
ANGLE = math.radians(4.0)
#: … along one another longer than this (mm) are a twin line (a detail's stub, the 4 mm end of
#: a long vector it joins, may meet the run's first vector at a small angle: a joint, not a
#: twin line; compressor's link 5, 1.3 mm apart over the stub's 4 mm).
RUN_MM = 5.0


def forces_sheet(s: object) -> tuple[Sheet, list[Box]]:
    """The forces sheet of solution ``s`` drawn as :func:`force_sheets` draws it, and the boxes
    (sheet mm) of its force plans."""
    from geomcad.sheet import linkage_forces as F

    tree, z = F.force_layout(s)  # type: ignore[arg-type]
    d = z.start(F._title(s.linkage, "forces", "X", 2, 2))  # type: ignore[attr-defined]
    compose(d, tree, layout=z.layout)
    boxes = [pl.box for pl in z.layout if isinstance(pl.view, Polygon)]
    return d.finish(), boxes


def sliver_boxes(s: object) -> list[Box]:
    """The boxes of the sliver plans of two long opposite vectors with small loads between
    (:func:`~geomcad.sheet.views.sliver_loads`; not a long vector balanced by two along its
    line, which are drawn side by side) of ``s``'s forces sheet, as :func:`forces_sheet` places
    them."""
    from geomcad.sheet import linkage_forces as F
    from geomcad.sheet.views import DETAIL_LEAST, DETAIL_MAX_MM, sliver_loads

    def paired(p: Polygon, k: float) -> bool:
        # (the loads in its detail, at least DETAIL_LEAST times larger, within DETAIL_MAX_MM)
        loads = sliver_loads(p.layers[-1][0])
        return 0.0 < loads * DETAIL_LEAST <= DETAIL_MAX_MM * p.drawn_k(k)

    _tree, z = F.force_layout(s)  # type: ignore[arg-type]
    return [pl.box for pl in z.layout if isinstance(pl.view, Polygon) and pl.scale is not None
            and paired(pl.view, pl.scale.k)]  # fmt: skip


def _segments(sheet: Sheet, box: Box) -> Iterator[tuple[XY, XY]]:
    x0, y0, x1, y1 = box
    for it in sheet.items:
        if not isinstance(it, Polyline) or it.fill or it.role in ("text", "frame"):
            continue
        pts = it.points
        for a, b in zip(pts, pts[1:] + ((pts[0],) if it.closed else ()), strict=False):
            if all(x0 <= p[0] <= x1 and y0 <= p[1] <= y1 for p in (a, b)):
                yield a, b


def _twin(a: tuple[XY, XY], b: tuple[XY, XY], near: float = NEAR_MM) -> float:
    """How long (mm) segments ``a`` and ``b`` run within NEAR_MM of one another, near-parallel
    and not on one line (0 where they do not)."""
    (ax, ay), (bx, by) = a
    la = math.hypot(bx - ax, by - ay)
    lb = math.hypot(b[1][0] - b[0][0], b[1][1] - b[0][1])
    if la < RUN_MM or lb < RUN_MM:
        return 0.0
    ux, uy = (bx - ax) / la, (by - ay) / la
    wx, wy = (b[1][0] - b[0][0]) / lb, (b[1][1] - b[0][1]) / lb
    if abs(ux * wy - uy * wx) > math.sin(ANGLE):
        return 0.0
    t = [ux * (q[0] - ax) + uy * (q[1] - ay) for q in b]
    d = [ux * (q[1] - ay) - uy * (q[0] - ax) for q in b]
    if _meet(t, d, la):
        return 0.0  # two sides meeting at a vertex: a thin triangle, as the plan is
    if t[1] < t[0]:
        t, d = t[::-1], d[::-1]
    lo, hi = max(t[0], 0.0), min(t[1], la)
    if hi - lo <= RUN_MM:
        return 0.0

    def across(x: float) -> float:
        return d[0] if t[1] == t[0] else d[0] + (d[1] - d[0]) * (x - t[0]) / (t[1] - t[0])

    steps = 20
    run = 0.0
    for i in range(steps):
        x = lo + (hi - lo) * (i + 0.5) / steps
        if SAME_MM < abs(across(x)) < near:
            run += (hi - lo) / steps
    return run


def _meet(t: list[float], d: list[float], la: float) -> bool:
    """Whether a segment (``t``, ``d``: its ends along and across a segment ``la`` long) and
    that segment are two sides meeting at their vertex: their lines cross within MEET_MM of an
    end of each (a side's line may stop an arrowhead short of its head)."""
    if abs(d[1] - d[0]) <= SAME_MM:
        return False  # parallel: side by side, never meeting
    x = t[0] - d[0] * (t[1] - t[0]) / (d[1] - d[0])  # where b's line crosses a's, along a
    return min(abs(x - t[0]), abs(x - t[1])) <= MEET_MM and min(abs(x), abs(x - la)) <= MEET_MM


def twin_lines(
    sheet: Sheet, boxes: Sequence[Box], near: float = NEAR_MM, least: float = RUN_MM
) -> list[tuple[Box, float, float]]:
    """The pairs of lines in the plans' ``boxes`` closer than ``near`` (mm) over more than
    ``least`` (mm): (box, their run in mm, their gap)."""
    out = []
    for box in boxes:
        segs = list(_segments(sheet, box))
        for i, a in enumerate(segs):
            for b in segs[i + 1 :]:
                run = _twin(a, b, near)
                if run > least:
                    mid = ((b[0][0] + b[1][0]) / 2.0, (b[0][1] + b[1][1]) / 2.0)
                    (ax, ay), (bx, by) = a
                    la = math.hypot(bx - ax, by - ay)
                    gap = abs((bx - ax) * (mid[1] - ay) - (by - ay) * (mid[0] - ax)) / la
                    out.append((box, run, gap))
    return out
