"""A slotted link (the RPR group's rocker) is drawn through every point it carries: a point
beyond its pivot is joined to the pivot by an arm (review 8: a rocking cylinder's arm
CE, beyond the pivot C, was drawn nowhere, its E and link 4 hanging free; a second slotted
lever's centre of mass S5 beyond its pivot floated detached)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad import tol
from geomcad.geom import Vec
from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import link_bodies

FILES = sorted((Path(__file__).resolve().parent / "linkages_arms").glob("*.toml"))


def _distance(q: Vec, a: Vec, b: Vec) -> float:
    """The distance from ``q`` to the segment ``ab`` (a point where ``a`` is ``b``)."""
    d = b - a
    if d.dot(d) == 0.0:
        return (q - a).norm
    t = max(0.0, min(1.0, (q - a).dot(d) / d.dot(d)))
    return (a + d * t - q).norm


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_every_point_of_a_slotted_link_is_on_its_body(path: Path) -> None:
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    lk = s.linkage
    slotted = [g.links[1] for g in lk.groups if g.kind == "RPR"]
    assert slotted, "the file has a slotted link"
    beyond = 0
    for P in s.drawn:
        bodies = link_bodies(lk, P)
        for link in slotted:
            g = lk.group_of(link)
            assert g is not None
            C, d = P.pos[g.pivot], P.slide[link]
            for n in lk.points_on(link):
                q = P.pos[n]
                beyond += (q - C).dot(d) < 0.0
                near = min(
                    _distance(q, a, b)
                    for body in bodies[str(link)]
                    for a, b in zip(body.points, body.points[1:], strict=False)
                )
                assert near <= tol.DERIVED * lk.length, (n, P.phi, near)
    assert beyond, "a point of the slotted link lies beyond its pivot (the case of the rule)"
