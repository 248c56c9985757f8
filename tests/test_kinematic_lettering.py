"""The kinematic sheets' lettering (issue 27, review 5 item 10): the tables and the order take
3.5 mm (GOST 2.304) wherever the views keep their rules' scales with it, and a sheet with no one
scale of lengths writes a dash in its title block's Масштаб."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import formats
from geomcad.sheet.compose import Field, arrange
from geomcad.sheet.linkage import (
    NO_SCALE,
    SMALL_TEXT_H,
    TEXT_H,
    _trees,
    _views,
    kinematic_sheets,
    layout,
)
from geomcad.sheet.views import Table

ROOT = Path(__file__).resolve().parent


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("name", ["four-bar", "shaper"])
def test_the_tables_take_the_larger_text_where_the_views_keep_their_scales(name: str) -> None:
    """Where the first sheet's tables are 2.5 mm, the same sheet with 3.5 mm text on its format
    would draw a view below the scale its rule wants; where they are 3.5 mm, every view keeps
    it (the four-bar's tables once stood at 2.5 mm beside a blank field)."""
    s = _solved(ROOT.parent / "examples" / f"{name}.toml")
    lay = layout(s)
    tables = [v for v in _views(lay.trees[0]) if isinstance(v, Table)]
    assert tables
    heights = {t.height for t in tables}
    assert len(heights) == 1
    (h,) = heights
    z = lay.sized[0]
    trees, _mech, _second, wants = _trees(s, lay.accel, TEXT_H, False, (False, False), False)
    big = arrange(trees[0], Field.of_format(z.fmt, z.landscape))
    mine = {v: k for v, k in wants.items() if v in _views(trees[0])}
    kept = big.fits and formats.meets(big, mine)
    if h == SMALL_TEXT_H:
        assert not kept
    if name == "four-bar":
        assert h == TEXT_H and kept


def test_a_plans_sheet_writes_a_dash_for_its_scale() -> None:
    """The velocity plans' sheet has no one scale of lengths (each plan at μ_V): its Масштаб
    reads "—", never an empty cell; the first sheet keeps the mechanism's scale."""
    s = _solved(ROOT / "linkages_layout" / "tall_rod_press.toml")  # the compressor's now fit
    sheets = kinematic_sheets(s, "x")
    assert [k for k, _ in sheets] == ["", "plans"]
    first, plans = sheets[0][1].block, sheets[1][1].block
    assert first is not None and plans is not None
    assert first.scale.startswith("1:") or first.scale.endswith(":1")
    assert plans.scale == NO_SCALE == "\u2014"
