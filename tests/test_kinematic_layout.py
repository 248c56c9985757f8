"""The kinematic sheet's composition (review 6, issue 27): the output's s, v and a diagrams
share their column's height, and every acceleration plan keeps the size rule of the velocity
plans, πa′ = ω1²·l_OA at least PA_MM long."""

from __future__ import annotations

from pathlib import Path

import pytest

import geomcad
from geomcad.sheet.linkage import DIAGRAM_SPAN_LEAST_MM, DIAGRAM_SPAN_MM, PA_MM, _arranged
from geomcad.sheet.views import Diagram, PlanView

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
LINKAGES = [
    p
    for p in sorted(EXAMPLES.glob("*.toml"))
    if "[drive]" in p.read_text(encoding="utf-8")
    and ("[[group]]" in p.read_text(encoding="utf-8") or "[synthesis]" in p.read_text("utf-8"))
]
#: review 6's unseen six-bar (its acceleration plans off the numbered positions) and one of ours
SIXBARS = [
    Path(__file__).parent / "linkages_layout" / name
    for name in ("sixbar_coupler_slider.toml", "sixbar_vertical_slide.toml")
]


@pytest.mark.parametrize("path", LINKAGES + SIXBARS, ids=lambda p: p.stem)
def test_output_diagrams_share_their_height(path: Path) -> None:
    """Review 6: whitworth's s diagram took 250 mm of its column while v and a kept their
    least 60 mm; the crusher's were 73, 90 and 98 mm, the slider-crank's 107, 119 and 154.
    Where equal boxes would draw a curve under DIAGRAM_SPAN_LEAST_MM (its μ rounded coarse), or cost
    the mechanism its scale beside plans on their own sheet, the search splits the column
    instead, and says so."""
    s = geomcad.solve(str(path)).data
    lay, lays = _arranged(s)
    placed = [pl for z in lays for pl in z if isinstance(pl.view, Diagram)]
    assert len(placed) == 3
    heights = [pl.box[3] - pl.box[1] for pl in placed]
    if lay.balanced:
        assert max(heights) - min(heights) < 0.5, heights
    else:  # a curve too low at equal heights, or the mechanism finer with the plans apart
        assert len(lay.squeezed) == 3
        least = DIAGRAM_SPAN_MM if lay.spans else DIAGRAM_SPAN_LEAST_MM
        assert min(lay.squeezed) < least or lay.second, lay.squeezed


@pytest.mark.parametrize("path", LINKAGES + SIXBARS, ids=lambda p: p.stem)
def test_acceleration_plans_keep_the_size_rule(path: Path) -> None:
    """Review 6: sixbar_coupler_slider's πa′ was 27 mm in a 250 mm column. The crank's
    acceleration ω1²·l_OA is drawn at least PA_MM long, as pa on the velocity plans."""
    s = geomcad.solve(str(path)).data
    lk = s.linkage
    plans = [
        pl
        for lay in _arranged(s)[1]
        for pl in lay
        if isinstance(pl.view, PlanView) and pl.view.group == "a"
    ]
    assert plans
    for pl in plans:
        assert pl.scale is not None
        assert pl.scale.mm(lk.omega**2 * lk.length) >= PA_MM - 1e-6, pl.view.title


LAYOUT_FILES = sorted((Path(__file__).parent / "linkages_layout").glob("*.toml"))


@pytest.mark.parametrize("path", LINKAGES + LAYOUT_FILES, ids=lambda p: p.stem)
def test_plans_sheet_keeps_pa(path: Path) -> None:
    """Review 7: tangent's velocity plans on their own A1 drew pa = 39 mm (the tall last plan
    in the cell the title block cuts set the grid's μ_V). The plans' sheet is the size rule's
    last resort: wherever the plans go on a sheet of their own, pa = ω1·l_OA at μ_V is at
    least PA_MM, and the sheet fits."""
    s = geomcad.solve(str(path)).data
    lk = s.linkage
    lay, lays = _arranged(s)
    if not lay.second:
        return
    plans = [pl for pl in lays[-1] if isinstance(pl.view, PlanView)]
    assert len(plans) == len(s.drawn) and lays[-1].fits
    for pl in plans:
        assert pl.scale is not None
        assert pl.scale.mm(abs(lk.omega) * lk.length) >= PA_MM - 1e-6, pl.view.title
