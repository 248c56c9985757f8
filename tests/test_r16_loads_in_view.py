"""A load arrow stays in its view (issue 27): a load along its own link slid past the link's
end on its line of action pays more for each mm outside the view's box than for one along a link
(``loads._W_BOX``), so that it never runs onto another view or past the frame. A sweep of the
force positions found the clipper's F_N at positions 6 and 9 slid 40 mm past the knife bar's end,
over the sheet's frame; the checker's rules (tests/layout.py) hold there now."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from layout import layout_problems

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage_forces as lf

CLIPPER = Path(__file__).resolve().parent / "linkages_review13" / "clipper_fork_knife.toml"


@pytest.mark.parametrize("position", [6, 9])
def test_a_load_slid_along_its_link_stays_in_its_view(position: int) -> None:
    data = tomllib.loads(CLIPPER.read_text("utf-8"))
    data["forces"] = {**data.get("forces", {}), "position": position}
    data["forces"].pop("phi", None)
    sheets = lf.force_sheets(solve(parse(data)), "x")
    sheet = sheets[0][1]
    assert layout_problems(sheet) == []
