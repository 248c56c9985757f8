"""Review 14: a forces sheet whose pinned arrangement leaves a view no room once its plans'
details are reckoned again must not fail the file's build ("parameter layout = 'План сил группы
(4, 5)': has no room on the sheet", and no sheet of the file written): that arrangement is
passed over (:func:`linkage_forces._pin_try`, :func:`linkage_forces._enlarged`) and another,
or the search's own sheet, taken."""

from __future__ import annotations

from pathlib import Path

import geomcad
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.views import Polygon

PUMP = Path(__file__).parent / "linkages_review14" / "pump-inclined-kulisa.toml"


def test_pump_forces_sheet_is_laid_out() -> None:
    s = geomcad.solve(str(PUMP)).data
    _tree, z = lf.force_layout(s)
    # laid out, every view placed (it overflows its A1 by 2,8 mm: named in round 13's note)
    assert z.fmt == "A1"
    titles = {pl.view.title for pl in z.layout}
    assert "План сил группы (4, 5)" in titles
    assert sum(isinstance(pl.view, Polygon) for pl in z.layout) == 5
