"""Review 13 of issue 27: beside the crank's detail view the mechanism still takes the finest
GOST scale that fits the field (the knuckle coining press drew its mechanism at 1:2,5, the crank
22 mm, where 1:2 fitted; the vertical yoke's at 1:4 where 1:2 fitted): the search tries the
finer steps (:data:`geomcad.sheet.linkage.FINER_STEPS`) with the detail as without it, and the
crank keeps its rule on the detail."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import CRANK_MM, _CrankDetail, _Mechanism, layout

ROOT = Path(__file__).resolve().parent
FILES = {
    "knuckle_coining_press": ROOT / "linkages_review13" / "knuckle_coining_press.toml",
    "vertical_yoke_rocker": ROOT / "linkages_drafting" / "vertical_yoke_rocker.toml",
}


@pytest.mark.parametrize("name", sorted(FILES))
def test_beside_its_cranks_detail_the_mechanism_takes_a_finer_scale(name: str) -> None:
    s = solve(parse(tomllib.loads(FILES[name].read_text(encoding="utf-8"))))
    lay = layout(s)
    assert all(z.layout.fits for z in lay.sized)
    scales = {type(pl.view): pl.scale for pl in lay.sized[0].layout if pl.scale is not None}
    mech, detail = scales[_Mechanism], scales[_CrankDetail]
    assert mech.k <= 0.002 * (1.0 + 1e-9), mech.ratio_text()  # 1:2 or finer (main: 1:2,5, 1:4)
    assert detail.mm(s.linkage.length) >= CRANK_MM * (1.0 - 1e-9)
