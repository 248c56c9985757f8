"""The kinematic and dynamics sheets' composition, review 7 (issue 27): one μ_V for a file's
velocity plans, wherever they stand; the crank's detail view as the last resort, never larger
than the mechanism."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import CRANK_MM, PA_MM, _CrankDetail, _Mechanism, layout
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent
#: Files that list ``phi`` off the numbered positions: their velocity plans stand beside the
#: acceleration plans on the first sheet (the press's and this round's own file also have a
#: sheet of velocity plans).
PHI_FILES = {
    "press_offset_long_rod": ROOT / "linkages_layout" / "press_offset_long_rod.toml",
    "sixbar_coupler_slider": ROOT / "linkages_layout" / "sixbar_coupler_slider.toml",
    "rocker_sixteen_phi": ROOT / "linkages_phi" / "rocker_sixteen_phi.toml",
    "four-bar": ROOT.parent / "examples" / "four-bar.toml",
}


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("name", sorted(PHI_FILES))
def test_one_velocity_scale_for_all_the_files_velocity_plans(name: str) -> None:
    """Review 7: the press's two ``phi`` velocity plans were drawn at μ_V = 0,004 (pa = 188 mm,
    a plan 135 × 170 mm) on the kinematic sheet, its plans sheet at μ_V = 0,01. Every velocity
    plan of a file, on whichever sheet, is drawn at one μ_V, pa at least PA_MM."""
    s = _solved(PHI_FILES[name])
    lk = s.linkage
    lay = layout(s)
    vplans = [
        pl for z in lay.sized for pl in z.layout
        if isinstance(pl.view, PlanView) and pl.view.group == "v" and pl.scale is not None
    ]  # fmt: skip
    assert len(vplans) >= len(s.drawn) + 2
    assert {pl.scale.k for pl in vplans if pl.scale is not None} == {lay.k_v.k}
    assert lay.k_v.mm(abs(lk.omega) * lk.length) >= PA_MM - 1e-9


DETAIL_FILES = {
    "sixbar_oscillator": ROOT / "linkages_layout" / "sixbar_oscillator.toml",
    "crusher": ROOT.parent / "examples" / "crusher.toml",
}


@pytest.mark.parametrize("name", sorted(DETAIL_FILES))
def test_the_crank_detail_never_outgrows_the_mechanism(name: str) -> None:
    """Review 7: the oscillator's mechanism was drawn at 1:4 (crank 12,5 mm, about 145 × 100 mm)
    in a corner beside its crank's 1:1 detail (190 × 190 mm), where 1:2 fits the sheet. The
    crank's detail is the last resort (no arrangement keeps the crank CRANK_MM long at the
    mechanism's own scale) and takes free room: the mechanism, the sheet's main view, stays
    the larger drawing."""
    s = _solved(DETAIL_FILES[name])
    lay = layout(s)
    drawn = {}
    for pl in lay.sized[0].layout:
        if isinstance(pl.view, _Mechanism | _CrankDetail) and pl.scale is not None:
            x0, y0, x1, y1 = pl.view.extent()
            drawn[type(pl.view)] = pl.scale.mm(x1 - x0) * pl.scale.mm(y1 - y0)
    assert _CrankDetail in drawn  # no arrangement holds the crank at the mechanism's scale
    assert drawn[_Mechanism] >= drawn[_CrankDetail]
    crank = max(pl.scale.mm(s.linkage.length) for pl in lay.sized[0].layout
                if isinstance(pl.view, _CrankDetail) and pl.scale is not None)  # fmt: skip
    assert crank >= CRANK_MM - 1e-9
