"""Review 14 of issue 27, the kinematic sheet's drafting (items 5 and 8):

- a fixed guide's hatching is drawn clear of every link line of the positions drawn: the
  ellipsograph's bar and its twelve thin positions ran straight through both hatched walls of
  its ram's and its slide's guides (:func:`geomcad.sheet.scheme.guide_walls`);
- each acceleration plan has its own caption "План ускорений, φ1 = …" with its μa, right over
  it: "φ1 = 60°" stood alone at the top of its cell, 100 mm from the plan it named.
"""

from __future__ import annotations

import itertools
import tomllib
from pathlib import Path

import pytest
from shapely.geometry import LineString, Point
from shapely.strtree import STRtree

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import _arranged, kinematic_sheets
from geomcad.sheet.model import Polyline, Sheet, TextItem
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent
FILES = {
    # a bar between a horizontal slide and a vertical ram: it leaves each block sideways
    "ellipsograph": ROOT / "linkages_review14" / "ellipsograph_blanking_press.toml",
    # a centred slider-crank: the rod's positions run above and below the guide's axis
    "slider-crank": ROOT.parent / "examples" / "slider-crank.toml",
    # a coupler's cross slider
    "compressor": ROOT / "linkages_layout" / "compressor_coupler_cross_slider.toml",
}
#: A line within this (mm) of a hatch line's end touches it (its wall), it does not cross it.
TOUCH_MM = 0.05
#: A caption stands at most this far (mm) above the top of the plan it names.
CAPTION_GAP_MM = 12.0


@pytest.fixture(scope="module")
def drawn() -> dict[str, tuple[Solved, list[tuple[str, Sheet]]]]:
    out = {}
    for name, path in FILES.items():
        s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
        out[name] = (s, kinematic_sheets(s, "X"))
    return out


def _crossings(sheet: Sheet) -> list[str]:
    """Each link line (main or thin) crossing a hatch line of the frame's supports and guides."""
    hatch = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "ground"]
    tree = STRtree([LineString(h.points) for h in hatch])
    out = []
    for it in sheet.items:
        if not isinstance(it, Polyline) or it.role not in ("thin", "link"):
            continue
        pts = [*it.points, *(it.points[:1] if it.closed else ())]
        for a, b in itertools.pairwise(pts):
            seg = LineString([a, b])
            for j in tree.query(seg, predicate="crosses"):
                h = hatch[int(j)].points
                x = seg.intersection(LineString(h))
                # a hatch line's own wall ends it: touching, not crossed (an inclined guide's
                # wall may pass a hair past its hatch lines' ends)
                if min(x.distance(Point(h[0])), x.distance(Point(h[-1]))) > TOUCH_MM:
                    out.append(f"{it.role} {a}–{b} × hatch at {h[0]}")
    return out


@pytest.mark.parametrize("name", list(FILES))
def test_no_link_line_runs_through_a_hatching(
    drawn: dict[str, tuple[Solved, list[tuple[str, Sheet]]]], name: str
) -> None:
    sheet = drawn[name][1][0][1]
    assert any(isinstance(it, Polyline) and it.role == "ground" for it in sheet.items)
    crossed = _crossings(sheet)
    assert not crossed, crossed[:5]


@pytest.mark.parametrize("name", ["ellipsograph", "slider-crank"])
def test_each_acceleration_plan_is_captioned_right_over_it(
    drawn: dict[str, tuple[Solved, list[tuple[str, Sheet]]]], name: str
) -> None:
    s, sheets = drawn[name]
    texts = [it.text for _, sh in sheets for it in sh.items if isinstance(it, TextItem)]
    # no caption of a lone angle: every one names its plan (the markup's "φ_1" drawn "φ1")
    assert not [t for t in texts if t.startswith(("φ1 =", "φ_1 ="))], texts
    _lay, lays = _arranged(s)
    aplans = [pl for pl in lays[0] if isinstance(pl.view, PlanView) and pl.view.group == "a"]
    # (the force analysis' position's plan too where the sheet has room for it: review 17)
    assert len(aplans) == len(_lay.accel) >= len(s.accel_phis) > 0
    for pl in aplans:
        caption = pl.view.caption(pl.scale)
        assert caption.startswith("План ускорений, φ_1 = "), caption
        assert "μ_a" in caption, caption
        assert caption.replace("_", "") in texts, caption
        v = pl.viewport
        assert v is not None
        top = min(v.p(q)[1] for q in pl.view.plan.points.values())
        gap = top - (pl.box[1] + pl.view.title_height)
        assert gap <= CAPTION_GAP_MM, (caption, gap)
