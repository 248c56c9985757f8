"""A point's path that runs over one curve forth and back is drawn once (review 17: a rocker's
joint C traced over the whole turn drew its dash-dot arc twice, the two passes' dashes out of
step, printed as a solid thin line); a path that encloses an area (a coupler point's) as it is."""

from __future__ import annotations

import itertools
import math
import tomllib
from pathlib import Path

from geomcad.geom import Vec
from geomcad.linkage import parse
from geomcad.sheet.linkage import _paths, one_pass, traced_joints

ROOT = Path(__file__).resolve().parent.parent


def test_an_arc_forth_and_back_is_one_pass_between_its_ends() -> None:
    # ψ = 0,6·sin φ over a turn: the arc from −0,6 to 0,6 rad, twice
    pts = [Vec(math.cos(0.6 * math.sin(t)), math.sin(0.6 * math.sin(t)))
           for t in (2.0 * math.pi * i / 360 for i in range(361))]  # fmt: skip
    arc = one_pass(pts)
    ends = sorted(math.atan2(q.y, q.x) for q in (arc[0], arc[-1]))
    assert math.isclose(ends[0], -0.6, abs_tol=1e-4) and math.isclose(ends[1], 0.6, abs_tol=1e-4)
    turn = [math.atan2(q.y, q.x) for q in arc]
    steps = [b - a for a, b in itertools.pairwise(turn)]
    assert all(s > 0.0 for s in steps) or all(s < 0.0 for s in steps)  # one way, once


def test_a_loop_and_a_circle_are_kept_whole() -> None:
    circle = [Vec(math.cos(t), math.sin(t)) for t in (2 * math.pi * i / 100 for i in range(101))]
    assert one_pass(circle) == circle


def test_the_files_rocker_joints_are_arcs_coupler_points_loops() -> None:
    lk = parse(tomllib.loads((ROOT / "examples" / "sixbar-2013-6.toml").read_text("utf-8")))
    paths = _paths(lk, traced_joints(lk))
    drawn = {n: one_pass(p) for n, p in paths.items()}
    assert any(len(drawn[n]) < len(p) for n, p in paths.items())  # B on its rocker
    for n, p in paths.items():
        if len(drawn[n]) < len(p):
            # every point of the full path lies on the one pass drawn (within a sample step)
            step = max(a.dist(b) for a, b in itertools.pairwise(p))
            assert all(min(q.dist(r) for r in drawn[n]) <= step for q in p), n
