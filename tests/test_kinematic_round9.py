"""The kinematic sheets after review 9 (issue 27): the mechanism grows before its crank is
drawn on a detail view; the output's diagrams take their plots' height where the sheet has
room."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.compose import Field, arrange
from geomcad.sheet.linkage import (
    CRANK_MM,
    DIAGRAM_PLOT_MM,
    PA_MM,
    _accel_positions,
    _alternatives,
    _arranged,
    _CrankDetail,
    _Mechanism,
    _trees,
    text_height,
)
from geomcad.sheet.views import Diagram

ROOT = Path(__file__).resolve().parent
FILES = sorted((ROOT / "linkages_layout").glob("*.toml")) + [
    ROOT.parent / "examples" / f"{n}.toml" for n in ("crusher", "shaper", "sixbar-2013-6")
]


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_crank_detail_only_where_no_arrangement_draws_the_mechanism_at_the_cranks_rule(
    path: Path,
) -> None:
    """Where the first sheet draws the crank's detail, no arrangement of the same sheet
    without it (the rules sought, on its format, its text height, its plans' sheet) fits
    with the mechanism itself at the crank's rule; elsewhere the mechanism draws the crank
    CRANK_MM long."""
    s = _solved(path)
    lk = s.linkage
    lay, lays = _arranged(s)
    mech = next(pl for pl in lays[0] if isinstance(pl.view, _Mechanism))
    assert mech.scale is not None
    if not any(isinstance(pl.view, _CrankDetail) for pl in lays[0]):
        assert mech.scale.mm(lk.length) >= CRANK_MM - 1e-9, path.stem
        return
    z = lay.sized[0]
    trees, view, _, _ = _trees(
        s, _accel_positions(s), text_height((z.fmt,)), False, (True, True), lay.second,
        lay.balanced, lay.k_v.k,
    )  # fmt: skip
    field = Field.of_format(z.fmt, z.landscape)
    for alt in _alternatives(trees[0]):
        got = arrange(alt, field)
        scale = got[view].scale
        assert not (got.fits and scale is not None and scale.mm(lk.length) >= CRANK_MM), path.stem


def test_the_sine_drive_is_drawn_at_its_cranks_rule_without_a_detail() -> None:
    """Review 9: the sine drive's mechanism at 1:2 (crank 22.5 mm) beside a 1:1 detail of its
    crank, on an A1 44 % blank, where the field has room for the whole mechanism at 1:1 with
    the diagrams, the tables and the acceleration plans under it (the tables' column was
    offered only in the title block's corner, which cut it 55 mm short)."""
    s = _solved(ROOT / "linkages_layout" / "sine_crosshead_rocker.toml")
    lay, lays = _arranged(s)
    assert not any(isinstance(pl.view, _CrankDetail) for pl in lays[0])
    assert lay.k_l.mm(s.linkage.length) >= CRANK_MM - 1e-9
    assert all(z.layout.fits for z in lay.sized)


#: Files whose output diagrams were squeezed to 41 mm plots under a mechanism that kept its
#: rule (review 9: the rocking cylinder's ψ, ω, ε 35–45 mm high), which an arrangement of
#: the same views draws at least DIAGRAM_PLOT_MM high, the rules kept.
ROOMY = ("rocking_cylinder_rocker", "compressor_coupler_cross_slider", "press_offset_long_rod")


@pytest.mark.parametrize("name", ROOMY)
def test_the_output_diagrams_take_their_plots_height_where_the_sheet_has_room(name: str) -> None:
    s = _solved(ROOT / "linkages_layout" / f"{name}.toml")
    lk = s.linkage
    lay, lays = _arranged(s)
    plots = [
        pl.inner[3] - pl.inner[1] - pl.view.BELOW - pl.view.ABOVE
        for pl in lays[0]
        if isinstance(pl.view, Diagram)
    ]
    assert len(plots) == 3
    assert min(plots) >= DIAGRAM_PLOT_MM - 1e-6, plots
    # the size rules still hold
    crank = max(
        pl.scale.mm(lk.length)
        for pl in lays[0]
        if isinstance(pl.view, _Mechanism | _CrankDetail) and pl.scale is not None
    )
    assert crank >= CRANK_MM - 1e-9
    assert lay.k_v.mm(abs(lk.omega) * lk.length) >= PA_MM - 1e-9
    assert all(z.layout.fits for z in lay.sized)
