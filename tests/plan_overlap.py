"""The superposition measure of a forces sheet's plans (review 12, fix 2): on the paper, per
force plan (its arrows at its μ_F, not its details'), no two arrows drawn over one another and
no razor-thin pair of long arrows."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

XY = tuple[float, float]
Seg = tuple[XY, XY]
#: Two arrows are drawn over one another where they run within this (mm: a line width or two)
#: of one another …
OVER_MM = 0.7
#: … within this angle …
OVER_ANGLE = math.radians(5.0)
#: … over more than this share of the shorter's length.
OVER_SHARE = 0.2
#: Two arrows longer than this (mm) …
LONG_MM = 50.0
#: … at an angle under this …
THIN_ANGLE = math.radians(5.0)
#: … come no nearer than this (mm) over their common run (a thin triangle's two long sides meet
#: at its sharp vertex: read as one line there).
THIN_GAP_MM = 1.5


def _unit(s: Seg) -> tuple[float, float, float]:
    (ax, ay), (bx, by) = s
    n = math.hypot(bx - ax, by - ay)
    return (bx - ax) / n, (by - ay) / n, n


def _run(a: Seg, b: Seg, near: float) -> float:
    """How long (mm) b runs within ``near`` of a's line, over a's extent (b's part)."""
    ux, uy, la = _unit(a)
    ax, ay = a[0]
    t = [ux * (q[0] - ax) + uy * (q[1] - ay) for q in b]
    d = [ux * (q[1] - ay) - uy * (q[0] - ax) for q in b]
    if t[1] < t[0]:
        t, d = t[::-1], d[::-1]
    lo, hi = max(t[0], 0.0), min(t[1], la)
    if hi <= lo:
        return 0.0
    steps = 40
    run = 0.0
    for i in range(steps):
        x = lo + (hi - lo) * (i + 0.5) / steps
        dx = d[0] if t[1] == t[0] else d[0] + (d[1] - d[0]) * (x - t[0]) / (t[1] - t[0])
        if abs(dx) < near:
            run += (hi - lo) / steps
    return run


def _angle(a: Seg, b: Seg) -> float:
    ux, uy, _ = _unit(a)
    wx, wy, _ = _unit(b)
    return math.asin(min(abs(ux * wy - uy * wx), 1.0))


def superposed(arrows: Sequence[Seg]) -> list[tuple[int, int, float]]:
    """Pairs of arrows drawn over one another: (i, j, shared share of the shorter)."""
    out = []
    for i, a in enumerate(arrows):
        for j in range(i + 1, len(arrows)):
            b = arrows[j]
            if _angle(a, b) > OVER_ANGLE:
                continue
            la, lb = math.dist(*a), math.dist(*b)
            run = max(_run(a, b, OVER_MM), _run(b, a, OVER_MM))
            if run > OVER_SHARE * min(la, lb):
                out.append((i, j, run / min(la, lb)))
    return out


def razor_thin(arrows: Sequence[Seg]) -> list[tuple[int, int, float]]:
    """Pairs of arrows longer than LONG_MM at an angle under THIN_ANGLE that come nearer than
    THIN_GAP_MM over their common run: (i, j, angle in degrees)."""
    out = []
    for i, a in enumerate(arrows):
        for j in range(i + 1, len(arrows)):
            b = arrows[j]
            if min(math.dist(*a), math.dist(*b)) < LONG_MM or _angle(a, b) > THIN_ANGLE:
                continue
            if max(_run(a, b, THIN_GAP_MM), _run(b, a, THIN_GAP_MM)) > 0.0:
                out.append((i, j, math.degrees(_angle(a, b))))
    return out


def plan_arrows(path: Path, monkeypatch: Any) -> dict[str, list[Seg]]:
    """Each force plan's arrows (paper mm) at its own μ_F on the file's forces sheet, by the
    plan's title (its details' arrows, at their finer μ_F, left out)."""
    import geomcad
    from geomcad.sheet import views

    rec: dict[str, list[Seg]] = {}
    draw = views.Polygon.draw

    def rec_draw(self: views.Polygon, d: Any, at: Any) -> None:
        j = len(d.sheet.scaled)
        draw(self, d, at)
        k = at.viewport.scale.k
        rec[self.title] = [(a, b) for a, b, sc in d.sheet.scaled[j:] if sc.k == k]

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    sheets = dict(geomcad.solve(str(path)).sheets())
    assert "forces" in sheets
    return rec
