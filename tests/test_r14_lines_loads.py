"""Review 14 (items 3 and 5 of its fix list): a load is drawn on its line of action through its
point, never on a parallel beside it with an elbow back to the point (the walkbeam's F_D left D
with a 10 mm jog and ran under its guide; the clipper's F_N the same), nor along an outline (the
walkbeam's lever drew G5 down its side pd for 49 mm): where the body is in the way it arrives at
its point from the other side, or slides along its own line.

Every force arrow of the forces sheets of the two files is recorded as it is drawn
(:func:`geomcad.sheet.loads.force`), with the point it acts at."""

from __future__ import annotations

import itertools
import math
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.geom import Vec
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.model import Polyline

HERE = Path(__file__).parent
FILES = {
    "walkbeam": HERE / "linkages_review14" / "walkbeam.toml",
    "clipper": HERE / "linkages_review13" / "clipper_fork_knife.toml",
}
#: An arrow this far (mm) off its point's line is off its line of action.
OFF_MM = 0.1
#: More than this (mm) of an arrow within 1 mm and 10° of a drawn outline runs along it.
ALONG_MM = 3.0
#: The roles of what a load may run on or beside: arrows, thin lines of action, axes, text.
FREE_ROLES = {"vector", "result", "thin", "centre", "frame", "frame_thin", "title", "label"}


@pytest.fixture(scope="module")
def drawn() -> dict[str, list[dict[str, Any]]]:
    out: dict[str, list[dict[str, Any]]] = {}
    real = lf.force
    for key, path in FILES.items():
        rec: list[dict[str, Any]] = []

        def spy(v: Any, at: Any, F: Vec, *args: Any, rec: list[Any] = rec, **kw: Any) -> Any:
            p = v.p(at)
            ends = real(v, at, F, *args, **kw)
            if ends is not None:
                lever = kw.get("clear") is None
                rec.append({"p": p, "ends": ends, "sheet": v.sheet, "lever": lever})
            return ends

        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(lf, "force", spy)
            lf.force_sheets(geomcad.solve(str(path)).data)
        out[key] = rec
    return out


def _off(r: dict[str, Any]) -> float:
    (ax, ay), (bx, by) = r["ends"]
    n = math.hypot(bx - ax, by - ay)
    px, py = r["p"]
    return abs((px - ax) * (by - ay) - (py - ay) * (bx - ax)) / n


def _along(r: dict[str, Any]) -> float:
    """How much (mm) of the arrow lies within 1 mm and 10° of a drawn outline."""
    (ax, ay), (bx, by) = r["ends"]
    n = math.hypot(bx - ax, by - ay)
    u = ((bx - ax) / n, (by - ay) / n)
    steps = max(2, int(n / 0.25))
    hit = [False] * steps
    for it in r["sheet"].items:
        if not isinstance(it, Polyline) or it.role in FREE_ROLES or it.fill:
            continue
        pts = [*it.points, it.points[0]] if it.closed else list(it.points)
        for a, b in itertools.pairwise(pts):
            s = math.dist(a, b)
            if s <= 0.0:
                continue
            w = ((b[0] - a[0]) / s, (b[1] - a[1]) / s)
            if abs(u[0] * w[1] - u[1] * w[0]) > math.sin(math.radians(10.0)):
                continue
            for i in range(steps):
                t = (i + 0.5) / steps * n
                q = (ax + u[0] * t - a[0], ay + u[1] * t - a[1])
                r_ = q[0] * w[0] + q[1] * w[1]
                if -0.2 <= r_ <= s + 0.2 and abs(q[0] * w[1] - q[1] * w[0]) < 1.0:
                    hit[i] = True
    return sum(hit) * n / steps


@pytest.mark.parametrize("key", sorted(FILES))
def test_every_load_on_its_line_of_action(drawn: dict[str, list[dict[str, Any]]], key: str) -> None:
    """Each arrow's line passes through its point (within OFF_MM): no parallel offset."""
    rec = drawn[key]
    assert rec
    off = [(round(_off(r), 2), r["ends"]) for r in rec if _off(r) > OFF_MM]
    assert not off, off


@pytest.mark.xfail(
    strict=True,
    reason="round 15: the lever's size first. G5 drawn from above d (off pd) runs out of the "
    "lever's margin at 0,002 (m/s)/mm, and load_sides then keeps it leaving along pd rather "
    "than hold the lever at 0,0025 (the side rule had shrunk 6 of 35 levers, the crusher's "
    "0,004 -> 0,01); a lever μ_F or a slide that draws it off pd within the box is next",
)
def test_lever_loads_off_its_sides(drawn: dict[str, list[dict[str, Any]]]) -> None:
    """No arrow of the walkbeam's lever runs along a side of it (G5 was down pd for 49 mm)."""
    lever = [r for r in drawn["walkbeam"] if r["lever"]]
    assert lever
    along = [(round(_along(r), 1), r["ends"]) for r in lever if _along(r) > ALONG_MM]
    assert not along, along


def test_clipper_load_leaves_its_point_outside_its_link(
    drawn: dict[str, list[dict[str, Any]]],
) -> None:
    """The clipper's F_N, whose line runs along its knife bar on one side of N: on that line,
    on the bar's other side, not hidden under the bar nor beside it."""
    mech = [r for r in drawn["clipper"] if not r["lever"]]
    bad = [(round(_off(r), 2), round(_along(r), 1), r["ends"]) for r in mech
           if _off(r) > OFF_MM or _along(r) > ALONG_MM]  # fmt: skip
    assert not bad, bad


def test_load_sides_turns_a_load_off_a_side() -> None:
    """A load at q pointing along a side from q is drawn arriving at q from the other side;
    one along a side through q on both sides slides along its own line off the side."""
    k = 0.01
    q, F = Vec(0.0, 0.0), Vec(0.0, -10.0)
    down = [(Vec(0.0, 0.0), Vec(0.0, -0.5))]  # a side from q down, 50 mm
    loads = [(q, F, "G", "vector")]
    assert lf.load_sides(loads, k, [20.0], lines=down) == [(True, q)]
    assert lf.load_sides(loads, k, [20.0]) == [(False, q)]
    both = [(Vec(0.0, 0.3), Vec(0.0, -0.3))]  # a side through q, 30 mm each way
    ((arrive, start),) = lf.load_sides(loads, k, [20.0], lines=both)
    run = F.unit() * (20.0 * k)
    tail = start - run if arrive else start
    assert lf.side_run(tail, run, k, both) <= lf.SIDE_RUN_MM
    assert abs(start.x) < 1e-12  # on its own line through q
