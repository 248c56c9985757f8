"""A sliver force plan (review 9, fix 4): a plan whose two long vectors run opposite ways along
one line with small loads between them (a link's R₁₂ and R₃₂ with G₂ and Ф₂, a two-force
member's R₀₁ = −R₂₁) is drawn with its two long vectors side by side a sliver's lane
(views.SLIVER_LANE_MM) apart, the loads' chain between them closing the gap in the plan's
detail at its stated μ_F. Review 9 found them a lane (2.5 mm) apart: two long lines that read
as one smudged twin line (watt2's link 2 and crank, double_kulisa's links 2 and 4 and crank);
review 12 found them drawn as ONE line ("R₀₁ ≈ −R₂₁"): two superposed arrows (the bloom shear's
crank). And on no forces sheet do two near-parallel lines of a plan run closer than 1 mm
(tests/twinlines.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from twinlines import forces_sheet, sliver_boxes, twin_lines

import geomcad
from geomcad.sheet.views import OFFSET_MM

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent / "examples"


def _loaded(paths: list[Path]) -> list[Path]:
    return [p for p in paths
            if "[links." in (t := p.read_text(encoding="utf-8")) or "[[load]]" in t]  # fmt: skip


FILES = _loaded(sorted(EXAMPLES.glob("*.toml"))) + _loaded(
    sorted((HERE / "linkages_layout").glob("*.toml"))
)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_no_twin_lines_on_any_plan(path: Path) -> None:
    s = geomcad.solve(str(path)).data
    sheet, boxes = forces_sheet(s)
    # no two near-parallel lines of a plan closer than 1 mm over more than 5 mm
    assert twin_lines(sheet, boxes) == []
    # a sliver plan's two long vectors a sliver's lane apart: none of its lines runs beside
    # another within a lane's width (plus its strokes) over 10 mm
    twins = twin_lines(sheet, sliver_boxes(s), OFFSET_MM + 0.5, 10.0)
    assert twins == [], [(round(run, 1), round(gap, 2)) for _b, run, gap in twins]


#: Review 9's forces sheets whose plans the layout left smaller than their boxes hold.
GROWN = ["compressor_coupler_cross_slider", "rocking_cylinder_rocker", "sine_crosshead_rocker"]


@pytest.mark.parametrize("stem", GROWN)
def test_plans_as_large_as_their_boxes_hold(stem: str) -> None:
    """Review 9, fix 9: the forces sheets 44–54 % blank with plans of 25–60 mm. A plan is
    drawn at the finest μ_F of its series at which it, with its details planned again at that
    μ_F, keeps within its box: the next finer step would not (a sliver at its cap aside).
    Before, compressor's group (4, 5) was drawn at 10 N/mm, 49 mm long, where 5 N/mm (98 mm)
    fits its 96 × 156 mm box."""
    from geomcad.sheet import linkage_forces as F
    from geomcad.sheet.compose import round_scale_down
    from geomcad.sheet.views import Polygon

    s = geomcad.solve(str(HERE / "linkages_layout" / f"{stem}.toml")).data
    _tree, z = F.force_layout(s)
    plans = [pl for pl in z.layout if isinstance(pl.view, Polygon) and pl.scale is not None]
    assert plans
    for pl in plans:
        view = pl.view
        assert isinstance(view, Polygon) and pl.scale is not None
        if view.drawn_k(pl.scale.k) != pl.scale.k:
            continue  # a sliver at its cap
        finer = round_scale_down(pl.scale.k * 0.999, pl.scale.q, view.series).k
        if view.drawn_k(finer) != finer:
            continue
        w, h = pl.inner[2] - pl.inner[0], pl.inner[3] - pl.inner[1]
        if view.detail:
            _d, _t, ext = view._with_details(finer, iter("W" * 99), (w * finer, h * finer))
        else:
            ext = view.extent()
            assert ext is not None
        over = max((ext[2] - ext[0]) / finer - w, (ext[3] - ext[1]) / finer - h)
        assert over > 0.0, (view.title, pl.scale.k, finer)
