"""Each link is drawn through the joints it carries, in the principal position and in every thin
one (review 9: a bell-crank's arm CE drawn in no thin position, link 4 hanging on free points E;
a crosshead's arm to F drawn in no thin position), and a point no other link carries (a centre of
mass) is no corner of the outline where it lies within PLATE_NEAR of the joints' outline (the
bell-crank drawn C–S3–E–B with S3 inside the triangle CBE; the crosshead's arm kinked at S3)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from shapely.geometry import MultiPoint, Point
from test_slotted_link_arms import _distance

from geomcad import tol
from geomcad.linkage import parse
from geomcad.linkage.model import Linkage
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import PLATE_NEAR, link_bodies

ROOT = Path(__file__).resolve().parent
FILES = [
    *sorted((ROOT / "linkages_outlines").glob("*.toml")),
    *sorted((ROOT / "linkages_arms").glob("*.toml")),
    *sorted((ROOT / "linkages_layout").glob("*.toml")),
    *(ROOT.parent / "examples" / f"{n}.toml" for n in ("shaper", "sixbar-2013-6", "crusher")),
]


def _joints(lk: Linkage, link: int) -> list[str]:
    """The points of ``link`` that are pairs: its own joints and the points other links carry."""
    others = {n for m in lk.moving_links if m != link for n in lk.link_points(m)}
    return [n for n in lk.points_on(link) if n in lk.link_points(link) or n in others]


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_every_joint_is_on_its_links_outline(path: Path) -> None:
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    lk = s.linkage
    for P in s.drawn:
        for axes in (False, True):
            bodies = link_bodies(lk, P, axes=axes)
            for link in lk.moving_links:
                segs = [
                    (a, b)
                    for body in bodies.get(str(link), [])
                    for a, b in zip(
                        body.points,
                        [*body.points[1:], *body.points[:1]] if body.closed else body.points[1:],
                        strict=False,
                    )
                ]
                g = lk.group_of(link)
                yoke = g is not None and g.kind == "PRP" and link == g.links[1]
                if lk.has_slide(link) and not yoke:
                    continue  # a block, a slotted link: their own rules (test_slotted_link_arms)
                for n in _joints(lk, link):
                    if yoke and g is not None and n in lk.link_points(link):
                        continue  # the yoke's own pairs are its slot and rod
                    q = P.pos[n]
                    near = min((_distance(q, a, b) for a, b in segs), default=float("inf"))
                    assert near <= tol.DERIVED * max(1.0, lk.length), (link, n, axes, P.phi)


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_a_centre_near_its_joints_is_no_corner(path: Path) -> None:
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    lk = s.linkage
    carried: dict[str, int] = {}
    for m in lk.moving_links:
        for n in lk.points_on(m):
            carried[n] = carried.get(n, 0) + 1
    for P in s.drawn:
        bodies = link_bodies(lk, P)
        for link in lk.moving_links:
            joints = [P.pos[n] for n in _joints(lk, link)]
            if len(joints) < 2:
                continue
            size = max(a.dist(b) for a in joints for b in joints)
            hull = MultiPoint([(q.x, q.y) for q in joints]).convex_hull
            corners = [q for body in bodies.get(str(link), []) for q in body.points]
            for p in lk.points:
                if p.link != link or carried.get(p.name, 0) != 1 or p.name in _joints(lk, link):
                    continue
                q = P.pos[p.name]
                if hull.distance(Point(q.x, q.y)) <= PLATE_NEAR * size * (1.0 - 1e-9):
                    assert all(q.dist(c) > tol.DERIVED * max(1.0, q.norm) for c in corners), (
                        link, p.name, P.phi,
                    )  # fmt: skip
