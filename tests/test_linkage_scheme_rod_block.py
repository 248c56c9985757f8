"""A rod jointed to a slider block reaches the block's joint circle (GOST 2.770): its line is
not cut at the block's edge by the block's white fill."""

from __future__ import annotations

import itertools
import math
import tomllib
from pathlib import Path

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _principal, kinematic_sheets, layout
from geomcad.sheet.model import CircleItem, Polyline
from geomcad.sheet.style import MAIN_LINE, STYLES
from geomcad.sheet.symbols import JOINT_R, SLIDER_SIZE

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ORDER = list(STYLES)  # the layers in drawing order


def _dist(q: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    ab = (b[0] - a[0], b[1] - a[1])
    L2 = ab[0] ** 2 + ab[1] ** 2 or 1.0
    t = max(0.0, min(1.0, ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / L2))
    return math.dist(q, (a[0] + t * ab[0], a[1] + t * ab[1]))


def test_the_rod_runs_over_the_block_to_its_joint_circle() -> None:
    data = tomllib.loads((EXAMPLES / "slider-crank.toml").read_text(encoding="utf-8"))
    s = solve(parse(data))
    P0, _ = _principal(s)
    sheet = kinematic_sheets(s)[0][1]
    v = layout(s).sized[0].layout[layout(s).mech].viewport
    assert v is not None
    a, b = v.p(P0.pos["A"]), v.p(P0.pos["B"])
    d = math.dist(a, b)
    u = ((a[0] - b[0]) / d, (a[1] - b[1]) / d)
    # a point of the rod inside the block, between the joint circle and the block's edge
    r = JOINT_R + 0.5
    assert r < SLIDER_SIZE[1] / 2.0
    q = (b[0] + u[0] * r, b[1] + u[1] * r)
    items = sheet.items
    fills = [
        i
        for i, it in enumerate(items)
        if isinstance(it, Polyline) and it.fill and it.closed and len(it.points) == 4
        and math.dist(b, (sum(p[0] for p in it.points) / 4, sum(p[1] for p in it.points) / 4))
        < 0.05
    ]  # fmt: skip
    assert fills, "no block drawn at B"
    fill = fills[-1]
    layer = ORDER.index(items[fill].role)
    S = MAIN_LINE.get(sheet.format, 0.7)

    def over(i: int) -> bool:  # drawn over the fill: a later layer, or later in its layer
        k = ORDER.index(items[i].role)
        return k > layer or (k == layer and i > fill)

    inked = [
        it
        for i, it in enumerate(items)
        if isinstance(it, Polyline) and over(i) and not it.fill
        and any(
            _dist(q, p, e) <= STYLES[it.role].weight * S / 2.0 + 1e-6
            for p, e in itertools.pairwise((*it.points, *it.points[: int(it.closed)]))
        )
    ]  # fmt: skip
    assert inked, "the rod stops at the block's edge: its line is hidden under the block's fill"
    # the joint circle is still drawn over the rod's end
    assert any(
        isinstance(it, CircleItem) and it.fill and math.dist(it.c, b) < 0.05 and it.r == JOINT_R
        for it in items
    )
