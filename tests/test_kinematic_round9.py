"""The kinematic sheets after review 9 (issue 27): the mechanism grows before its crank is
drawn on a detail view."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import (
    CRANK_MM,
    _accel_positions,
    _arranged,
    _crank_may_keep,
    _CrankDetail,
    _Mechanism,
    sheet_formats,
)

ROOT = Path(__file__).resolve().parent
FILES = sorted((ROOT / "linkages_layout").glob("*.toml")) + [
    ROOT.parent / "examples" / f"{n}.toml" for n in ("crusher", "shaper", "sixbar-2013-6")
]


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_crank_detail_only_where_the_mechanism_has_no_room_at_the_cranks_rule(
    path: Path,
) -> None:
    """Review 9: the sine drive's mechanism at 1:2 (crank 22.5 mm) beside a 1:1 detail of its
    crank, on an A1 44 % blank, where the field has room for the whole mechanism at 1:1 under
    which the diagrams, the tables and the acceleration plans still fit (the tables' column
    was offered only in the title block's corner, whose 55 mm it lost). Where the first sheet
    draws the crank's detail, the necessary test finds no room for the mechanism at the
    crank's rule with the other views at their least, whichever sheet the velocity plans are
    on; elsewhere the mechanism itself draws the crank CRANK_MM long."""
    s = _solved(path)
    lk = s.linkage
    _, lays = _arranged(s)
    detail = any(isinstance(pl.view, _CrankDetail) for pl in lays[0])
    if detail:
        accel = _accel_positions(s)
        fmts = sheet_formats(lk)
        assert not any(_crank_may_keep(s, accel, fmts, apart) for apart in (False, True))
        return
    mech = next(pl for pl in lays[0] if isinstance(pl.view, _Mechanism))
    assert mech.scale is not None
    assert mech.scale.mm(lk.length) >= CRANK_MM - 1e-9, path.stem
