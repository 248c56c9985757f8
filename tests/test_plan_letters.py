"""The letters of the velocity and acceleration plans (issue 27, review 5: "a / s2 crowd in
positions 3 and 9", whitworth's positions 2, 6, 10): letters of distinct points at nearly one
place are written as one list ("a, s_2"), so no two plan letters' boxes overlap."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.geom import Vec
from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import kinematic_sheets
from geomcad.sheet.model import TextItem
from geomcad.sheet.placer import text_outline
from geomcad.sheet.plans import NEAR_POINT_MM, _near
from geomcad.sheet.scale import Scale

ROOT = Path(__file__).resolve().parent
#: Two letters' boxes keep at least twice this apart (mm).
GAP = 0.3


def _plan_letters(items: list[tuple[TextItem, object]]) -> list[tuple[str, TextItem]]:
    """The sheet's plan letters: its labels in lower case (the plans' points, p, π) — the
    mechanism's points are capitals, its positions digits."""
    out = []
    for item, _anchor in items:
        text = "".join(r.text for r in item.runs)
        if text[:1].islower() or text[:1] == "π":
            out.append((text, item))
    return out


@pytest.mark.parametrize(
    "path",
    [
        ROOT / "linkages" / "near_points.toml",
        ROOT / "linkages" / "compressor.toml",
        ROOT / "linkages" / "sixbar-slider.toml",
        ROOT.parent / "examples" / "shaper.toml",
        ROOT.parent / "examples" / "four-bar.toml",
    ],
    ids=lambda p: p.stem,
)
def test_no_two_plan_letters_overlap(path: Path) -> None:
    """On every kinematic sheet, no two plan letters' boxes (grown by :data:`GAP`) overlap:
    near_points.toml's rod carries S2 and M near A, whose images crowd where ω2 is small."""
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    for name, sheet in kinematic_sheets(s, "x"):
        letters = _plan_letters(list(sheet.anchors))
        assert letters
        boxes = [text_outline(t, GAP) for _, t in letters]
        clash = [
            (letters[i][0], letters[j][0])
            for i in range(len(boxes))
            for j in range(i)
            if boxes[i].intersection(boxes[j]).area > 0.0
        ]
        assert not clash, (path.stem, name, clash)


def test_near_points_are_one_list_in_a_chain() -> None:
    """Points closer than :data:`NEAR_POINT_MM` on the paper, in a chain, share one list in the
    plan's order; a point further off keeps its own letter."""
    scale = Scale(0.001, "v")  # 1 mm on the paper = 0.001 model units
    step = NEAR_POINT_MM * 0.9 * 0.001
    pts = {
        "p": Vec(0.0, 0.0),
        "a": Vec(0.05, 0.0),
        "s2": Vec(0.05 + step, 0.0),
        "b": Vec(0.05 + 2 * step, 0.0),
        "c": Vec(0.05 + 2 * step + 2 * NEAR_POINT_MM * 0.001, 0.0),
    }
    assert _near(pts, scale) == [["p"], ["a", "s2", "b"], ["c"]]
