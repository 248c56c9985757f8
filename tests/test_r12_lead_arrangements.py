"""The forces sheet's search also offers the mechanism the field's height at the left edge with
the groups, the lever and the polygons beside it (review 12: the slotter's plans 27-54 mm in
104 x 93 mm cells under its mechanism, its lever in a 387 x 287 mm box with a 320 x 130 mm
drawing; the tangent rocking slider's groups at 1:4 beside its mechanism at 1:2)."""

from __future__ import annotations

from pathlib import Path

import geomcad
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.views import Polygon

HERE = Path(__file__).resolve().parent


def _layout(path: Path):  # type: ignore[no-untyped-def]
    s = geomcad.solve(str(path)).data
    _tree, z = lf.force_layout(s)
    return s, z.layout


def test_the_slotters_plans_read_and_its_crank_is_long() -> None:
    s, lay = _layout(HERE / "linkages_review12" / "slotter_whitworth_ram.toml")
    longest = []
    for pl in lay:
        v = pl.view
        if isinstance(v, Polygon) and pl.scale is not None:
            k = v.drawn_k(pl.scale.k)
            longest.append(max(pv.magnitude for poly, _ in v.layers for pv in poly.vectors) / k)
    # the largest plan (group (4, 5), F_D = 5420 N) drawn at least PLAN_READ_MM long: 27 mm before
    assert max(longest) >= lf.PLAN_READ_MM, longest
    main, own = lf._l_scales(lay)
    assert main == own
    assert s.linkage.length / main >= 50.0 * (1.0 - 1e-9)  # 1:2 (44 mm at 1:2,5 before)


def test_the_tangent_slider_groups_at_the_mechanisms_scale() -> None:
    _s, lay = _layout(HERE / "linkages_layout" / "tangent_rocking_slider.toml")
    main, own = lf._l_scales(lay)
    assert main == own, (main, own)  # 1:2 and 1:4 before
