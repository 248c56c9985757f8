"""Review 7's drafting rules (issue 27): a crank's detail view draws nothing beyond its own
circle (the oscillator's detail once drew its coupler stubs 1.9 crank lengths out, towards the
plans column)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _CrankDetail, kinematic_sheets, layout
from geomcad.sheet.model import CircleItem, Polyline

ROOT = Path(__file__).resolve().parent
EXAMPLES = ROOT.parent / "examples"
#: Files whose kinematic sheet draws the crank on a detail view.
DETAILED = {
    "sixbar_oscillator": ROOT / "linkages_layout" / "sixbar_oscillator.toml",
    "crusher": EXAMPLES / "crusher.toml",
}
#: The detail's circle reaches no further than this many crank lengths round the pivot: it
#: holds the crank circle and its numbers, not the links beyond.
MOST_REACH = 1.5


@pytest.mark.parametrize("name", sorted(DETAILED))
def test_a_crank_detail_ends_at_its_circle(name: str) -> None:
    """Every line the crank's detail draws lies inside the detail's thin circle round the
    pivot, which reaches at most MOST_REACH crank lengths: the stubs of the links at the
    crank's joint end on it."""
    s = solve(parse(tomllib.loads(DETAILED[name].read_text(encoding="utf-8"))))
    lk = s.linkage
    sheet = kinematic_sheets(s, "x")[0][1]
    pls = [pl for pl in layout(s).sized[0].layout if isinstance(pl.view, _CrankDetail)]
    assert pls, "no crank detail on this file's sheet"
    pl = pls[0]
    assert pl.viewport is not None and pl.scale is not None
    c = pl.viewport.p(lk.frame[lk.pivot])
    crank = pl.scale.mm(lk.length)
    x0, y0, x1, y1 = pl.inner

    def within(q: tuple[float, float]) -> bool:
        return x0 <= q[0] <= x1 and y0 <= q[1] <= y1

    rings = [it.r for it in sheet.items if isinstance(it, CircleItem) and it.role == "thin"
             and math.dist(it.c, c) < 1e-6 and it.r > crank]  # fmt: skip
    assert rings, "the detail draws no circle of its own round the crank"
    r = max(rings)
    assert r <= MOST_REACH * crank + 1e-6
    lines = [it for it in sheet.items if isinstance(it, Polyline)
             and any(within(q) for q in it.points)]  # fmt: skip
    assert len(lines) >= len(s.drawn)  # the crank in its positions at least
    for it in lines:
        for q in it.points:
            assert math.dist(q, c) <= r + 0.05, (it.role, q, math.dist(q, c), r)
