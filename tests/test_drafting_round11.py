"""Review 11's drafting (issue 27, fix 6 and fix 7's drafting leftovers): a cut-out group (or
the crank) on the forces sheet is cut free of the frame, so its frame joints show the joint and
the reaction R_0j, not the frame's hatched support or guide."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from test_drafting_round9 import FILES, _linkage

from geomcad.linkage.solution import solve
from geomcad.sheet.model import CircleItem

#: Files with a revolute and a prismatic pair on the frame in their cut-out groups (a rocker's
#: pivot C, a slider's guide), each group and the crank checked.
CUT = ["slider_rocker_rpr", "shaper", "crank_rocker_inclined_slide"]


def _free_bodies(name: str, monkeypatch: pytest.MonkeyPatch) -> list[tuple[Any, Any, list[Any]]]:
    """The forces sheet's cut-out groups and crank of ``name``: (view, its viewport, the items
    it drew)."""
    from geomcad.sheet import linkage_forces as lf

    rec: list[tuple[Any, Any, list[Any]]] = []
    links = lf._FreeBody.links

    def rec_links(self: Any, d: Any, at: Any) -> None:
        start = len(d.sheet.items)
        links(self, d, at)
        rec.append((self, at.viewport, list(d.sheet.items[start:])))

    monkeypatch.setattr(lf._FreeBody, "links", rec_links)
    lf.force_sheets(solve(_linkage(name)))
    return rec


@pytest.mark.parametrize("name", [n for n in CUT if n in FILES])
def test_a_cut_out_group_shows_no_support_of_the_frame(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """No cut-out group nor the crank draws the frame's hatching (a hinge's hatched support or
    a guide's hatched lines: review 11 found them at C and D of the groups), and each revolute
    on the frame keeps its joint circle (where the reaction R_0j acts)."""
    from geomcad.linkage.solution import scheme

    bodies = _free_bodies(name, monkeypatch)
    assert bodies, name
    hinges = 0
    for view, v, items in bodies:
        hatch = [it for it in items if getattr(it, "role", None) == "ground"]
        assert not hatch, (name, view.title, len(hatch))
        full = scheme(view.lk, view.P)
        own = {str(i) for i in view.gf.links}
        circles = [it.c for it in items if isinstance(it, CircleItem) and it.role == "joint"]
        for p in full.pairs:
            if p.kind == "R" and full.frame in p.links and own & set(p.links):
                hinges += 1
                c = v.p(p.at)
                assert any(np.hypot(x - c[0], y - c[1]) < 0.05 for x, y in circles), (
                    name, view.title, p.name)  # fmt: skip
    assert hinges, name
