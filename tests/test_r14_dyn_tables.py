"""Review 14, item 8: one count of decimals for the columns of one quantity and unit in a
table: the kinematic sheet's ω table wrote ω2, ω3 with 3 decimals beside ω4 with 4 (the
walkbeam), its ε table alike."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _tables

HERE = Path(__file__).parent
FILES = ["linkages_review14/walkbeam.toml", "linkages_layout/sixbar_oscillator.toml",
         "../examples/shaper.toml"]  # fmt: skip


def _decimals(cell: str) -> int:
    i = max(cell.find(","), cell.find("."))
    return 0 if i < 0 else len(cell) - i - 1


@pytest.fixture(scope="module", params=FILES)
def tables(request: pytest.FixtureRequest) -> list[list[list[str]]]:
    s = solve(parse(tomllib.loads((HERE / request.param).read_text(encoding="utf-8"))))
    return [t.rows for t in _tables(s, [s.drawn[0], s.drawn[len(s.drawn) // 2]])]


def test_the_columns_of_one_unit_share_their_decimals(tables: list[list[list[str]]]) -> None:
    for rows in tables:
        head, body = rows[0], rows[1:]
        # the angular quantities' columns (ω_i or ε_i, one unit per table)
        cols = [j for j, h in enumerate(head) if h.startswith(("ω", "ε"))]
        assert cols
        places = {_decimals(r[j]) for r in body for j in cols}
        assert len(places) == 1, (head, places, body[:2])
