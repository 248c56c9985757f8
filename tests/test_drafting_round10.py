"""Review 10's drafting (issue 27, fixes 3, 5 and 8): a slider on the frame's guide carrying a
block that slides on a moving link at its own point (a knot) drawn so that neither hides the
other, every guide of the frame with its axis, detail circles and moment arcs clear of filled
blocks and of each other, and no load arrow across a link outline where sliding it along its
line of action (its tail or its head at its point) would avoid it."""

from __future__ import annotations

import itertools
import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from test_drafting_round9 import ALONG_MAX_MM, FILES, FORCES, _loaded, along_links
from test_free_bodies import _lines

from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.loads import AT_POINT_MM
from geomcad.sheet.model import XY, Polyline
from geomcad.sheet.scheme import GUIDE_HALF, draw_scheme


def crossings(p: XY, tail: XY, tip: XY, links: list[tuple[XY, XY]]) -> int:
    """How many link lines the arrow tail → tip crosses, away from its point of application
    ``p`` (within AT_POINT_MM of it the arrow meets its own body's joint)."""
    n = 0
    a, b = np.asarray(tail, float), np.asarray(tip, float)
    for c, d in links:
        c_, d_ = np.asarray(c, float), np.asarray(d, float)
        r, s = b - a, d_ - c_
        den = r[0] * s[1] - r[1] * s[0]
        if abs(den) < 1e-12:
            continue
        t = ((c_[0] - a[0]) * s[1] - (c_[1] - a[1]) * s[0]) / den
        w = ((c_[0] - a[0]) * r[1] - (c_[1] - a[1]) * r[0]) / den
        if 0.0 < t < 1.0 and 0.0 < w < 1.0:
            x = a + t * r
            if math.dist((float(x[0]), float(x[1])), p) > AT_POINT_MM:
                n += 1
    return n


def avoidable(p: XY, tail: XY, tip: XY, links: list[tuple[XY, XY]]) -> bool:
    """Whether the arrow crosses a link although one with its tail or its head at ``p`` (the
    same length and direction) crosses none and runs along none (review 9's rule,
    :func:`test_drafting_round9.along_links`: an arrow with its head or tail at its point that
    runs along its link over more than ALONG_MAX_MM avoids no crossing, it draws the load
    along an outline instead: sine_crosshead_rocker's G₅ across the link at G, since review
    14 on its line of action, which near S₅ runs within ALONG_GAP_MM of its own rocker DG)."""
    if crossings(p, tail, tip, links) == 0:
        return False
    u = np.subtract(tip, tail)
    leave = (p, (p[0] + float(u[0]), p[1] + float(u[1])))
    arrive = ((p[0] - float(u[0]), p[1] - float(u[1])), p)
    return any(crossings(p, *alt, links) == 0 and along_links(p, *alt, links) <= ALONG_MAX_MM
               for alt in (leave, arrive))  # fmt: skip


def test_the_crossing_measure() -> None:
    link = [((0.0, 0.0), (0.0, 40.0))]
    assert crossings((10.0, 20.0), (10.0, 20.0), (-10.0, 20.0), link) == 1
    assert crossings((10.0, 20.0), (10.0, 20.0), (30.0, 20.0), link) == 0
    assert avoidable((10.0, 20.0), (10.0, 20.0), (-10.0, 20.0), link)  # tail at p: leaves clear
    # the way that crosses nothing runs along a link: not avoidable (review 9's rule)
    # (a link from the point along the arrow's line the other way: arriving runs along it)
    rod = [*link, ((10.0, 20.0), (40.0, 20.0))]
    assert not avoidable((10.0, 20.0), (10.0, 20.0), (-10.0, 20.0), rod)
    # a point between two links: either way crosses one, not avoidable
    two = [*link, ((25.0, 0.0), (25.0, 40.0))]
    assert not avoidable((10.0, 20.0), (10.0, 20.0), (-10.0, 20.0), two)


#: Files whose loaded mechanism still draws a load across a link where a slide would avoid it
#: (none since review 14: rocking_cylinder_rocker's Φ₁, once beside its crank across the
#: cylinder's rod, is slid along its own line past O).
CROSSING: set[str] = set()


@pytest.mark.parametrize(
    "name",
    [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason="a load across a link"))
     if n in CROSSING else n for n in FORCES],
)  # fmt: skip
def test_no_load_crosses_a_link_where_sliding_it_avoids_that(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """No load arrow of the loaded mechanism crosses a link outline where the same arrow with
    its tail or its head at its point of application would cross none (review 10:
    stephenson_coupler_rocker's Φ2 across the coupler's side AM to S2)."""
    sheet, drawn = _loaded(name, monkeypatch)
    links = _lines(sheet.items, {"link"})
    bad = [lab for lab, p, tail, tip in drawn if avoidable(p, tail, tip, links)]
    assert not bad, (name, bad)


# -- the knot and the guides' axes ------------------------------------------------------------

DRAFTING = Path(__file__).resolve().parent / "linkages_drafting"
SCHEMES = {**FILES, **{p.stem: p for p in DRAFTING.glob("*.toml")}}


def _scheme(name: str) -> tuple[Any, Any, Any]:
    """The loaded mechanism's scheme of ``name`` drawn as the forces sheet draws it (at a
    crank of 30 mm): (sheet, viewport, mechanism)."""
    from geomcad.linkage.solution import scheme
    from geomcad.sheet.linkage import frame_guides, link_bodies

    lk = parse(tomllib.loads(SCHEMES[name].read_text("utf-8")))
    P = solve(lk).positions[0]
    d = start("A1", TitleBlock(title="t", designation="d"))
    v = Viewport(d, Scale(lk.length / 30.0), 300.0, 300.0, (420.0, 300.0))
    mech = scheme(lk, P)
    draw_scheme(v, mech, bodies=link_bodies(lk, P), pair_labels={}, guides=frame_guides(lk),
                guide_axes=True)  # fmt: skip
    return d.sheet, v, mech


def _slides(mech: Any) -> list[Any]:
    return [p for p in mech.pairs if p.kind == "P" and mech.frame in p.links]


@pytest.mark.parametrize("name", sorted(n for n in SCHEMES if "guide" in SCHEMES[n].read_text()))
def test_every_guide_of_the_frame_has_its_axis(name: str) -> None:
    """Every prismatic pair on the frame is drawn with its guide's axis: a centre (dash-dot)
    or thin line through the pair's point along the guide, reaching past the hatched guide's
    ends (review 10: slider_rocker_rpr's loaded mechanism drew the slider's guide hatched
    with no axis)."""
    sheet, v, mech = _scheme(name)
    lines = [it for it in sheet.items
             if isinstance(it, Polyline) and it.role in ("centre", "thin")]  # fmt: skip
    for p in _slides(mech):
        c, u = np.asarray(v.p(p.at)), np.asarray(v.paper_dir(p.axis))
        reach = 0.0
        for it in lines:
            for a, b in itertools.pairwise(it.points):
                ab = np.subtract(b, a)
                n = float(np.hypot(*ab))
                if n == 0.0 or abs(ab[0] * u[1] - ab[1] * u[0]) / n > 1e-6:
                    continue
                w = np.subtract(a, c)
                if abs(float(u[0] * w[1] - u[1] * w[0])) > 0.05:
                    continue
                reach = max(reach, *(abs(float(np.dot(np.subtract(q, c), u))) for q in (a, b)))
        assert reach > GUIDE_HALF, (name, p.name, reach)


def _blocks(sheet: Any) -> list[np.ndarray]:
    return [
        np.asarray(it.points)
        for it in sheet.items
        if isinstance(it, Polyline) and it.fill and it.closed and len(it.points) == 4
    ]


@pytest.mark.parametrize(
    "name", sorted(n for n in SCHEMES if "slider = " in SCHEMES[n].read_text())
)
def test_a_knot_draws_the_carried_block_inside_its_slider(name: str) -> None:
    """Where a slider on the frame's guide carries at its point a block sliding on a moving
    link (slider_rocker_rpr's B ≡ K), the carried block lies wholly inside the slider's outline
    and the slider shows beyond it along the guide at both ends: neither hides the other
    (review 10: two blocks of one size over each other, the slider's hidden)."""
    sheet, v, mech = _scheme(name)
    size = mech.size()
    knots = [
        (f, p)
        for f in _slides(mech)
        for p in mech.pairs
        if p.kind == "P" and mech.frame not in p.links and p.at.dist(f.at) <= size / 4096.0
    ]
    checked = 0
    for f, _ in knots:
        c = np.asarray(v.p(f.at))
        here = [b for b in _blocks(sheet) if np.hypot(*(b.mean(axis=0) - c)) < 0.05]
        if len(here) < 2:
            continue  # one block there: the other pair's link is a body (a yoke's slot)
        checked += 1
        outer, inner = sorted(here, key=lambda b: -float(np.ptp(b, axis=0).sum()))
        u = np.asarray(v.paper_dir(f.axis))
        n = np.array([-u[1], u[0]])
        o_u, o_n = np.abs((outer - c) @ u).max(), np.abs((outer - c) @ n).max()
        i_u, i_n = np.abs((inner - c) @ u).max(), np.abs((inner - c) @ n).max()
        assert i_n < o_n and i_u + 1.0 < o_u, (name, o_u, o_n, i_u, i_n)
    if name in ("slider_rocker_rpr", "knot_vertical_slide"):
        assert checked, name
    elif not checked:
        pytest.skip("no knot")


@pytest.mark.parametrize("name", ["slider_rocker_rpr", "knot_vertical_slide"])
def test_each_point_is_lettered_once_on_the_kinematic_mechanism(name: str) -> None:
    """On the kinematic sheet each capital point name of the mechanism is printed in one label
    ("B, K" for two names of one place: review 10 printed "B, K" and "K" at B)."""
    from geomcad.sheet.linkage import kinematic_sheets
    from geomcad.sheet.model import TextItem

    lk = parse(tomllib.loads(SCHEMES[name].read_text("utf-8")))
    sheet = next(sh for _, sh in kinematic_sheets(solve(lk)))
    names = {n for n in lk.owner if len(n) == 1 and n.isupper()}
    seen: dict[str, int] = {}
    for it in sheet.items:
        if isinstance(it, TextItem) and it.angle == 0.0:
            parts = [t.strip() for t in it.text.split(",")]
            if parts and all(t in names for t in parts):
                for t in parts:
                    seen[t] = seen.get(t, 0) + 1
    assert seen, name
    assert all(k == 1 for k in seen.values()), (name, seen)
