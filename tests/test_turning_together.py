"""Links that turn together (issue 27, review 5: "ω2 = ω3 is printed as two identical
columns"): a block and the link it slides on have one ω and one ε by the group's kinematics;
the kinematic sheet's tables print one column headed "ω_{2} = ω_{3}" (ε likewise), a rule
from the linkage's structure, not from comparing values."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import _accel_positions, _tables, _turns, tabled_cells, together

ROOT = Path(__file__).resolve().parent
FILES = sorted(
    [
        *[p for p in (ROOT.parent / "examples").glob("*.toml") if "[frame]" in p.read_text()],
        *(ROOT / "linkages").glob("*.toml"),
    ]
)


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


def _links(head: str) -> list[int]:
    """The links a column's head names (``ω_{2} = ω_{3}, с^{-1}`` → [2, 3])."""
    return [int(sym.split("{")[1].rstrip("}")) for sym in head.split(", ")[0].split(" = ")]


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_links_turning_together_share_one_column(path: Path) -> None:
    """Every turning link but the crank is named in exactly one ω column and one ε column; links
    named in one column have equal ω and ε in every position (the rule is true); and two turning
    links whose ω and ε are equal in every position share a column (no two identical columns)."""
    s = _solved(path)
    lk = s.linkage
    accel = _accel_positions(s)
    omega, eps = _tables(s, accel)
    turning = {i for i in lk.moving_links if i != 1 and _turns(lk, i)}
    for table, symbol, positions, attr in (
        (omega, "ω", s.drawn, "omega"),
        (eps, "ε", accel, "eps"),
    ):
        heads = [h for h in table.rows[0] if h.startswith(symbol + "_")]
        named = [i for h in heads for i in _links(h)]
        assert sorted(named) == sorted(turning), (path.stem, heads)
        for h in heads:
            ls = _links(h)
            for P in positions:
                vals = [getattr(P, attr)[i] for i in ls]
                scale = abs(lk.omega) ** (1 if attr == "omega" else 2)
                assert max(vals) - min(vals) <= 1e-6 * scale, (path.stem, h)
        column = {i: h for h in heads for i in _links(h)}
        for a in turning:
            for b in turning:
                if a < b and all(
                    math.isclose(P.omega[a], P.omega[b], abs_tol=1e-9 * abs(lk.omega))
                    for P in s.drawn
                ):
                    assert column[a] == column[b], (path.stem, a, b)


@pytest.mark.parametrize(
    ("name", "pair"),
    [("examples/shaper.toml", (2, 3)), ("examples/rocking-slider.toml", (3, 5))],
)
def test_a_block_and_its_link_are_one_column(name: str, pair: tuple[int, int]) -> None:
    """An RPR's block and slotted link, an RRP's slider and the moving link of its guide: one
    column "ω_{a} = ω_{b}", whose cell the other sheets find by either symbol."""
    s = _solved(ROOT.parent / name)
    a, b = pair
    assert together(s.linkage)[a] == pair
    omega, eps = _tables(s, _accel_positions(s))
    assert any(h.startswith(f"ω_{{{a}}} = ω_{{{b}}},") for h in omega.rows[0])
    assert any(h.startswith(f"ε_{{{a}}} = ε_{{{b}}},") for h in eps.rows[0])
    cells = tabled_cells(s, s.drawn[1])
    assert cells[f"ω_{{{a}}}"] == cells[f"ω_{{{b}}}"]


def test_links_on_a_fixed_guide_do_not_join() -> None:
    """A slider on a fixed guide turns with no link: a slider-crank has no joined column."""
    s = _solved(ROOT.parent / "examples" / "slider-crank.toml")
    assert together(s.linkage) == {}
    omega, _eps = _tables(s, _accel_positions(s))
    assert not any(" = " in h for h in omega.rows[0])
