"""No superposed or razor-thin force plans (issue 27, review 12, fix 2).

On the forces sheet, per force plan, measured on the arrows drawn at the plan's own μ_F
(tests/plan_overlap.py): no two arrows drawn over one another (within 0,7 mm of one another, at
an angle under 5°, over more than 20 % of the shorter's length: the bloom shear's crank plan was
R₀₁ and R₂₁, two 45 mm arrows on one line, "R₀₁ ≈ −R₂₁"; its link 4 R₃₄ and R₅₄), and no two
arrows longer than 50 mm at an angle under 5° nearer than 1,5 mm anywhere along their common run
(the bloom's link 2: R₃₂ and R₁₂, 176 and 156 mm at 1,5°, meeting at the sharp vertex of a thin
triangle; the stephenson's crank plan). A sliver's two long opposite vectors are drawn side by
side a sliver's lane apart (views.SLIVER_LANE_MM), two sides of a thin triangle a lane apart
where they come nearest (views.lanes), each joined to its neighbours by thin lines."""

from __future__ import annotations

from pathlib import Path

import pytest
from plan_overlap import plan_arrows, razor_thin, superposed

HERE = Path(__file__).resolve().parent
FILES = [
    HERE / "linkages_review12" / "bloom_shear_swing_knife.toml",
    HERE / "linkages_review12" / "needle_takeup_sewing.toml",
    HERE / "linkages_review12" / "slotter_whitworth_ram.toml",
    HERE / "linkages_layout" / "stephenson_coupler_rocker.toml",
    HERE / "linkages_layout" / "pumpjack_horsehead_unit.toml",
]


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_no_plan_draws_two_arrows_over_one_another(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    plans = plan_arrows(path, monkeypatch)
    assert plans
    over = {t: superposed(a) for t, a in plans.items() if superposed(a)}
    assert over == {}, over
    thin = {t: razor_thin(a) for t, a in plans.items() if razor_thin(a)}
    assert thin == {}, thin


def test_the_measure_sees_two_arrows_on_one_line() -> None:
    """The measure is not blind: two opposite 45 mm arrows on one line are superposed, two
    176 and 156 mm arrows from one vertex at 1,5° razor-thin; side by side 5 mm apart, neither."""
    import math

    a = ((0.0, 0.0), (45.0, 0.0))
    assert superposed([a, ((45.0, 0.3), (0.0, 0.3))])
    assert not superposed([a, ((45.0, 5.0), (0.0, 5.0))])
    t = math.radians(1.5)
    b = ((176.0, 0.0), (0.0, 0.0))
    c = ((0.0, 0.0), (156.0 * math.cos(t), 156.0 * math.sin(t)))
    assert razor_thin([b, c])
    lifted = ((0.0, 2.5), (156.0 * math.cos(t), 2.5 + 156.0 * math.sin(t)))
    assert not razor_thin([b, lifted])
