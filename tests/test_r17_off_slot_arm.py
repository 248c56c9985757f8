"""A point of a slotted link off its slot is joined to it (review 17: a planer's B, set "from
C toward A" on a slot offset 0,015 m from its pivot, lay beside the slot; link 3 was drawn to
B's foot on the slot and B, with link 4 hung on it, floated free of it on the kinematic sheet,
the forces sheet's mechanism and group (2, 3))."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from test_slotted_link_arms import _distance

from geomcad import tol
from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import link_bodies

FILE = Path(__file__).resolve().parent / "linkages_review17" / "planer_offset_kulisa.toml"


@pytest.mark.parametrize("axes", [False, True], ids=["main", "thin"])
def test_a_joint_beside_an_offset_slot_is_on_its_link(axes: bool) -> None:
    s = solve(parse(tomllib.loads(FILE.read_text(encoding="utf-8"))))
    lk = s.linkage
    (g,) = [g for g in lk.groups if g.kind == "RPR"]
    link = g.links[1]
    # B carries link 4 and lies off the slot (the case of the rule)
    B = s.drawn[0].pos["B"]
    C, d = s.drawn[0].pos[g.pivot], s.drawn[0].slide[link]
    foot = C + d.perp() * g.offset
    assert abs((B - foot).cross(d)) > 1e-3
    for P in s.drawn:
        bodies = link_bodies(lk, P, axes=axes)[str(link)]
        for n in lk.points_on(link):
            if n == "S3" or (axes and n == g.pivot):
                # a centre of mass no other link carries (the rule's other case); a thin
                # position's slot starts at its foot on the offset's circle
                continue
            q = P.pos[n]
            near = min(
                _distance(q, a, b)
                for body in bodies
                for a, b in zip(body.points, body.points[1:], strict=False)
            )
            assert near <= tol.DERIVED * lk.length, (n, P.phi, near)
