"""Review 13 of issue 27: a hub (a joint of the frame where the links of every position meet)
is drawn once, clean: on the kinematic sheet the other positions' thin lines end short of the
joint's circle and of its support (the slotter's crank hub, twelve positions' lines through
its joint, stand and hatching, read as a knot)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from shapely.geometry import LineString, Point

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import kinematic_sheets
from geomcad.sheet.model import CircleItem, Polyline, Sheet
from geomcad.sheet.symbols import JOINT_R, STAND_DEPTH, STAND_HALF

ROOT = Path(__file__).resolve().parent
FILES = [
    ROOT / "linkages_review12" / "slotter_whitworth_ram.toml",
    ROOT.parent / "examples" / "four-bar.toml",
]
#: The ring round a hub's joint circle (mm) that no thin line enters.
RING = 0.9


def _hubs(sheet: Sheet) -> list[tuple[tuple[float, float], list[tuple[float, float]]]]:
    """The joints of the frame drawn with a support: (centre, the stand's two leg ends)."""
    leg = math.hypot(STAND_DEPTH, STAND_HALF)
    out = []
    for c in sheet.items:
        if not (isinstance(c, CircleItem) and abs(c.r - JOINT_R) < 1e-6):
            continue
        legs = [
            it.points[1] for it in sheet.items
            if isinstance(it, Polyline) and len(it.points) == 2 and it.role == "link"
            and math.dist(it.points[0], c.c) < 1e-6
            and abs(math.dist(*it.points) - leg) < 1e-6
        ]  # fmt: skip
        if len(legs) == 2:
            out.append((c.c, legs))
    return out


@pytest.fixture(scope="module")
def sheets() -> dict[str, Sheet]:
    out = {}
    for p in FILES:
        s = solve(parse(tomllib.loads(p.read_text(encoding="utf-8"))))
        out[p.stem] = kinematic_sheets(s, "X")[0][1]
    return out


@pytest.mark.parametrize("name", [p.stem for p in FILES])
def test_no_thin_line_enters_a_hubs_ring_or_its_stand(sheets: dict[str, Sheet], name: str) -> None:
    sheet = sheets[name]
    hubs = _hubs(sheet)
    assert hubs  # the crank's pivot at least
    thin = [LineString(it.points) for it in sheet.items
            if isinstance(it, Polyline) and it.role == "thin" and len(it.points) >= 2]  # fmt: skip
    assert len(thin) >= 11  # the other positions' links
    for c, (a, b) in hubs:
        ring = Point(c).buffer(JOINT_R + RING)
        stand = LineString([a, c, b]).convex_hull  # the triangle of the stand
        hits = [t for t in thin if t.intersects(ring) or t.intersects(stand.buffer(-0.3))]
        assert not hits, (c, len(hits))
