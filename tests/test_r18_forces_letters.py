"""Review 17 on the forces sheets: the centres of mass S_i that weights and inertia forces act
at are lettered on the mechanism and on each group's free body ("в точке S_5" of the order of
the analysis names a point of the drawing); a scale's ratio is written with the Cyrillic М of
«масштаб» ("(М 1:4)"), not a Latin M that prints the same."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def crusher() -> list[TextItem]:
    from geomcad.sheet import linkage_forces as lf

    lk = parse(tomllib.loads((ROOT / "examples" / "crusher.toml").read_text("utf-8")))
    sheet = lf.force_sheets(solve(lk), "x")[0][1]
    return [it for it in sheet.items if isinstance(it, TextItem)]


def _text(t: TextItem) -> str:
    return "".join(r.text for r in t.runs)


def test_each_centre_of_mass_is_lettered_on_the_mechanism_and_its_group(
    crusher: list[TextItem],
) -> None:
    # links 2…5 carry masses with centres in the middle of their joints: each S_i lettered on
    # the mechanism and on its group's free body; the crank has no mass in this file
    counts = {f"S{i}": sum(_text(t) == f"S{i}" for t in crusher) for i in range(1, 6)}
    assert counts == {"S1": 0, "S2": 2, "S3": 2, "S4": 2, "S5": 2}, counts


def test_a_scales_ratio_is_written_with_the_cyrillic_em(crusher: list[TextItem]) -> None:
    ratios = [_text(t) for t in crusher if ":" in _text(t) and "(" in _text(t)]
    assert any("(\u041c 1:" in r for r in ratios), ratios
    assert not any("(M " in r for r in ratios), ratios
