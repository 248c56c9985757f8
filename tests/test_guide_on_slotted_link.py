"""A guide carried by an RPR's slotted link runs on to its slider (review 6: the tangent
mechanism's link 3 was drawn from C to K only, and the slide 5 at D stood on nothing)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad import tol
from geomcad.geom import Vec
from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import link_bodies

FILE = Path(__file__).parent / "linkages_layout" / "tangent_rocking_slider.toml"


def _distance(q: Vec, a: Vec, b: Vec) -> float:
    d = b - a
    t = max(0.0, min(1.0, (q - a).dot(d) / d.dot(d)))
    return (a + d * t - q).norm


@pytest.mark.parametrize("axes", [False, True], ids=["principal", "thin"])
def test_the_slotted_link_carries_its_guide_to_the_slider(axes: bool) -> None:
    s = solve(parse(tomllib.loads(FILE.read_text(encoding="utf-8"))))
    lk = s.linkage
    guided = [g for g in lk.groups if g.kind == "RRP" and g.guide is not None]
    slotted = {g.links[1] for g in lk.groups if g.kind == "RPR"}
    carried = [g for g in guided if g.guide is not None and g.guide.link in slotted]
    assert carried, "the file's RRP slides on the RPR's slotted link"
    for P in s.drawn:
        bodies = link_bodies(lk, P, axes=axes)
        for g in carried:
            assert g.guide is not None
            link, D = g.guide.link, P.pos[g.joint]
            near = min(
                _distance(D, a, b)
                for body in bodies[str(link)]
                for a, b in zip(body.points, body.points[1:], strict=False)
            )
            assert near <= tol.DERIVED * lk.length, (P.phi, near)
