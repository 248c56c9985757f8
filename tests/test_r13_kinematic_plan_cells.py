"""Review 13 of issue 27: on a grid of velocity plans each plan's letters stand inside its own
cell (sine_crosshead_rocker's position 0, a plan as narrow as one line, wrote
"p, o, e, f, s₃, d, g" 21 mm into position 1's cell, and position 6 likewise into 7's): the
placer pays :data:`geomcad.sheet.placer.W_CELL` for a label of a plan that leaves the plan's
cell (:attr:`geomcad.sheet.drawing.Viewport.within`)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _arranged, kinematic_sheets
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent
FILES = [
    ROOT / "linkages_layout" / "sine_crosshead_rocker.toml",
    ROOT / "linkages_layout" / "kulisa_inclined_ram.toml",
]


def _strays(path: Path) -> tuple[int, list[tuple[str, float]]]:
    """How many labels name a point of a plan, and those whose box leaves that plan's cell
    (the smallest placed plan box holding the point) by more than 0.5 mm: (text, mm out)."""
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    sheets = kinematic_sheets(s, "X")
    lays = _arranged(s)[1]
    n, out = 0, []
    for (_, sheet), lay in zip(sheets, lays, strict=True):
        boxes = [pl.box for pl in lay if isinstance(pl.view, PlanView)]
        for item, (ax, ay) in sheet.anchors:
            own = [b for b in boxes if b[0] <= ax <= b[2] and b[1] <= ay <= b[3]]
            if not own:
                continue
            n += 1
            b = min(own, key=lambda b: (b[2] - b[0]) * (b[3] - b[1]))
            x0, y0 = item.at[0], item.at[1] - item.height
            x1, y1 = item.at[0] + item.width, item.at[1] + 0.3 * item.height
            past = max(b[0] - x0, b[1] - y0, x1 - b[2], y1 - b[3])
            if past > 0.5:
                out.append((item.text, round(past, 1)))
    return n, out


@pytest.fixture(scope="module")
def strays() -> dict[str, tuple[int, list[tuple[str, float]]]]:
    return {p.stem: _strays(p) for p in FILES}


@pytest.mark.parametrize("name", [p.stem for p in FILES])
def test_each_plans_letters_stand_in_its_own_cell(
    strays: dict[str, tuple[int, list[tuple[str, float]]]], name: str
) -> None:
    n, out = strays[name]
    assert n >= 12  # every plan's letters were found
    assert out == []
