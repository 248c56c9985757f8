"""The kinematic and dynamics sheets' composition, review 7 (issue 27): one μ_V for a file's
velocity plans, wherever they stand; the crank's detail view as the last resort, never larger
than the mechanism; on the dynamics sheet, the ω1 diagram the height of its box and no axis's
name on a drawn line."""

from __future__ import annotations

import functools
import itertools
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import TitleBlock
from geomcad.sheet.compose import Placed, compose
from geomcad.sheet.linkage import (
    CRANK_MM,
    PA_MM,
    _CrankDetail,
    _Mechanism,
    _segment_to_box,
    _text_box,
    detail_letter,
    fit,
    kinematic_sheets,
    layout,
    sheet_formats,
)
from geomcad.sheet.linkage_forces import AXIS_NAME_H, NAME_CLEAR_MM, _sheet3
from geomcad.sheet.model import Polyline, Sheet
from geomcad.sheet.views import Diagram, PlanView

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


DYNAMICS_FILES = {
    "yoke_pump_double_slider": ROOT / "linkages_layout" / "yoke_pump_double_slider.toml",
    "tangent_rocking_slider": ROOT / "linkages_layout" / "tangent_rocking_slider.toml",
    "sixbar_coupler_slider": ROOT / "linkages_layout" / "sixbar_coupler_slider.toml",
    "shaper": ROOT.parent / "examples" / "shaper.toml",
}


@functools.cache
def _dynamics(name: str) -> tuple[Sheet, list[Placed]]:
    """The dynamics sheet of a file as :func:`force_sheets` draws it, and its views' places."""
    s = _solved(DYNAMICS_FILES[name])
    fw = analyse(s).flywheel
    assert fw is not None
    tree, z = fit(lambda h: (_sheet3(s, fw, h), {}), sheet_formats(s.linkage))
    d = z.start(TitleBlock(title="x", designation="x"))
    compose(d, tree, layout=z.layout)
    return d.finish(), list(z.layout)


@pytest.mark.parametrize("name", sorted(DYNAMICS_FILES))
def test_the_omega_diagram_takes_the_height_of_its_box(name: str) -> None:
    """Review 7: tangent's ω1 diagram was 60 mm high with 4 ticks in a taller box (its
    factor rounded coarse, its range padded by a quarter each side). Its ω axis runs the height
    of the box's room for the drawing."""
    _, places = _dynamics(name)
    (pl,) = [p for p in places if isinstance(p.view, Diagram) and p.view.y.symbol == "ω_1"]
    gr = pl.view.graph
    assert gr is not None
    y0, y1 = pl.inner[1], pl.inner[3]
    room = (y1 - y0) - Diagram.BELOW - Diagram.ABOVE
    assert gr.y.mm(gr.y.hi - gr.y.lo) >= room - 1e-6
    # the curve between ω_min and ω_max takes at least half of it
    fw = analyse(_solved(DYNAMICS_FILES[name])).flywheel
    assert fw is not None
    assert gr.y.mm(fw.omega_max - fw.omega_min) >= 0.5 * room


@pytest.mark.parametrize("name", sorted(DYNAMICS_FILES))
def test_no_axis_name_on_a_drawn_line(name: str) -> None:
    """Review 7: the yoke's "I_пр, кг·м²" by its arrow stood 1,2 mm under Wittenbauer's ω_max
    tangent, read as on it. An axis's name (3,5 mm) keeps NAME_CLEAR_MM and more from every
    curve and construction line of the sheet."""
    sheet, _ = _dynamics(name)
    lines = [it for it in sheet.items if isinstance(it, Polyline)
             and it.role in ("construction", "result")]  # fmt: skip
    for t in sheet.texts():
        if t.role != "label" or t.height < AXIS_NAME_H - 1e-9 or "," not in t.text:
            continue  # the axes' names: "symbol, unit"
        b = _text_box(t)
        gap = min(
            _segment_to_box(p, q, b) for pl in lines for p, q in itertools.pairwise(pl.points)
        )
        assert gap > 1.5 * NAME_CLEAR_MM, (t.text, gap)


@pytest.mark.parametrize("name", sorted(DETAIL_FILES))
def test_the_detail_letter_on_the_mechanism_is_crossed_by_no_line(name: str) -> None:
    """Review 7 (after the oscillator's mechanism grew to 1:2,5): its coupler AB ran through
    the letter "Б" marking the crank's detail, set up and to the right of the ring whatever
    was drawn there. The letter takes the first diagonal that no line crosses."""
    s = _solved(DETAIL_FILES[name])
    sheet = kinematic_sheets(s)[0][1]
    letter = detail_letter(s)
    (mark,) = [t for t in sheet.texts() if t.text == letter and t.role == "label"]
    b = _text_box(mark)
    lines = [it.points for it in sheet.items if isinstance(it, Polyline)]
    segments = [pq for pts in lines for pq in itertools.pairwise(pts)]
    # the letter's own shelf, 0,8 mm under its baseline, aside
    crossing = [
        (p, q) for p, q in segments
        if _segment_to_box(p, q, b) <= 0.0
        and not (abs(p[1] - q[1]) < 1e-9 and abs(p[1] - mark.at[1] - 0.8) < 1e-6)
    ]  # fmt: skip
    assert not crossing
