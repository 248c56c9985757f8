"""Review 14, item 4 (the dynamics diagrams) and item 8 (axes): on the dynamics sheet the
diagrams M_пр(φ), A(φ), ΔT(φ), I_пр(φ) are drawn at about one height, M_пр (the one the
student integrates) at least as tall as the others (the walkbeam's M_пр was 29 mm beside a
92 mm A(φ)); an axis whose values do not start at 0 (ω1 about its mean) is broken by a zigzag
by its origin; the ω1(φ) diagram's φ axis carries the numbered positions as the others do."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.linkage.analysis import analyse
from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet import start
from geomcad.sheet.frame import TitleBlock
from geomcad.sheet.graph import Axis, Graph
from geomcad.sheet.model import Polyline, Sheet, TextItem
from geomcad.sheet.views import MARK_H, Diagram

HERE = Path(__file__).parent
FILES = ["linkages_review14/walkbeam.toml", "linkages_review14/ellipsograph_blanking_press.toml"]


def _dynamics(path: Path) -> dict[str, Any]:
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    fw = analyse(s).flywheel
    assert fw is not None
    tree, z = lf.fit(lambda h: (lf._sheet3(s, fw, h), {}), lf.sheet_formats(s.linkage))
    d = z.start(lf._title(s.linkage, "x", "x", 3, 3))
    lf.compose(d, tree, layout=z.layout)
    sheet = d.finish()
    diagrams: list[Diagram] = []
    for v in tree.views():
        inner = getattr(v, "diagrams", None)
        diagrams += list(inner) if inner is not None else [v] if isinstance(v, Diagram) else []
    drawn = {dg.y.name: dg for dg in diagrams if dg.graph is not None}
    return {"sheet": sheet, "diagrams": drawn, "n": len(fw.phis)}


@pytest.fixture(scope="module", params=FILES)
def dyn(request: pytest.FixtureRequest) -> dict[str, Any]:
    return _dynamics(HERE / request.param)


def _height(dg: Diagram) -> float:
    assert dg.graph is not None
    box = dg.graph.box
    return box[3] - box[1]


def test_m_pr_is_at_least_as_tall_as_each_other_diagram(dyn: dict[str, Any]) -> None:
    dg = dyn["diagrams"]
    m = _height(dg["M"])
    for name in ("A", "T", "I"):
        assert m >= _height(dg[name]) - 0.1, (name, m, _height(dg[name]))


def test_the_four_diagrams_are_drawn_at_about_one_height(dyn: dict[str, Any]) -> None:
    """Within the nice factors' step (1, 2, 2.5, 4, 5 × 10^n: at most 2 apart)."""
    hs = [_height(dyn["diagrams"][n]) for n in ("M", "A", "T", "I")]
    assert min(hs) >= 0.5 * max(hs), hs


def _zigzags(sheet: Sheet, at: tuple[float, float]) -> list[Polyline]:
    return [
        it
        for it in sheet.items
        if isinstance(it, Polyline)
        and len(it.points) >= 4
        and abs(it.points[0][0] - at[0]) < 1e-6
        and abs(it.points[0][1] - at[1]) < 1e-6
        and max(abs(p[0] - at[0]) for p in it.points) > 0.5
    ]


def test_the_omega_axis_not_starting_at_0_is_broken(dyn: dict[str, Any]) -> None:
    g = dyn["diagrams"]["ω"].graph
    assert g.y.lo > 0.0
    assert _zigzags(dyn["sheet"], g.at)


def test_the_omega_phi_axis_carries_the_position_numbers(dyn: dict[str, Any]) -> None:
    g = dyn["diagrams"]["ω"].graph
    x0, _, x1, _ = g.box
    under = {
        it.text
        for it in dyn["sheet"].items
        if isinstance(it, TextItem) and it.height == MARK_H
        and x0 - 3.0 <= it.at[0] <= x1 + 3.0 and g.at[1] < it.at[1] < g.at[1] + 15.0
    }  # fmt: skip
    assert {str(k) for k in range(0, dyn["n"], 2)} <= under


def test_a_graph_through_zero_has_no_break() -> None:
    """The rule is the axis's range, not the diagram: an axis through 0 is not broken, an
    axis from 4 to 5 is."""
    for lo, broken in ((0.0, False), (4.0, True)):
        d = start("A3", TitleBlock("t", "x"))
        sheet = d.sheet
        ax = Axis.fit("φ", "град", 0.0, 360.0, 120.0)
        ay = Axis.fit("ω", "с", lo, lo + 1.0, 60.0)
        g = Graph(d, ax, ay, (100.0, 200.0))
        g.axes()
        assert bool(_zigzags(sheet, g.at)) is broken
