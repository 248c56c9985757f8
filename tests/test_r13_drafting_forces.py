"""Round 13, drafting (review 13, item 5, forces part): force plans and Zhukovsky's lever.

1. Two sides of a force plan that read as one line are drawn side by side in lanes whatever the
   angle between them: the shorter stays within a sliver's lane (views.SLIVER_LANE_MM) of the
   longer's line over their common run and they run within a lane (OFFSET_MM) of one another
   longer than two arrowheads (views.one_line). The gang saw's link 4: R₁₄ (67 mm) and R₅₄
   (46 mm) at 8,8° met at the pole as one line; drawn so they are more than a lane apart there.
   Two short sides at a wide angle, or two long ones whose far ends part widely, are left alone.
2. A plan's sides do not cross where an order of its known loads exists that does not: a
   crossing near the end of a long side is a crossing unless a short side's run (a detail's
   circle) goes on from that end (stephenson_coupler_rocker's group (2, 3): R₄₂ crossed R^n₁₂
   5 mm short of its head, Ф₂ crossing back; views.crossings did not count it).
3. The lever's point letters stay at their points (the layout checker's ANCHOR_MAX) and clear
   of lines: the shaper's pole "p, o, c" was pushed 6,8 mm off by the twin inset circles round
   it (5 mm)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import pytest
from layout import ANCHOR_MAX, AREA_EPS, block_part, is_bar_of, stroke, text_poly
from plan_overlap import plan_arrows
from shapely.geometry import Point

from geomcad.forces import ForcePolygon, PlanVector
from geomcad.geom import Vec
from geomcad.sheet import views
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parent.parent
GANG_SAW = ROOT / "tests" / "linkages_review13" / "gang_saw_frame_feed.toml"
STEPHENSON = ROOT / "tests" / "linkages_layout" / "stephenson_coupler_rocker.toml"
SHAPER = ROOT / "examples" / "shaper.toml"


def _chain(pole: Vec, loads: list[tuple[str, Vec]]) -> list[PlanVector]:
    out, tail = [], pole
    for n, F in loads:
        out.append(PlanVector(n, tail, tail + F))
        tail = out[-1].head
    return out


def _polar(length: float, deg: float) -> Vec:
    a = math.radians(deg)
    return Vec(length * math.cos(a), length * math.sin(a))


def _gap_at_vertex(a: PlanVector, b: PlanVector, sa: Vec, sb: Vec) -> float:
    """The distance (model units) between a's tail and b's head once shifted (their vertex)."""
    return ((a.tail + sa) - (b.head + sb)).norm


# --- 1. near-parallel sides in lanes ---------------------------------------------------------


def test_a_thin_triangle_at_nine_degrees_is_drawn_in_lanes() -> None:
    """R₁₄ 67 mm, Ф₄ 21 mm, R₅₄ 46 mm back to the pole at 8,8° from R₁₄ (the gang saw's link
    4 at 1 mm a unit): the two long sides are moved apart, more than a lane apart at the pole."""
    r14 = _polar(67.0, 32.2)
    r54_dir = _polar(46.3, 23.4 + 180.0)
    phi = -(r14 + r54_dir)
    vs = _chain(Vec(0.0, 0.0), [("R_{14}", r14), ("Ф_{4}", phi), ("R_{54}", r54_dir)])
    assert views.one_line(vs[0], vs[2], 1.0)
    shift = views.lanes(1.0, vs)
    assert "R_{14}" in shift or "R_{54}" in shift
    zero = Vec(0.0, 0.0)
    gap = _gap_at_vertex(vs[0], vs[2], shift.get("R_{14}", zero), shift.get("R_{54}", zero))
    assert gap > views.OFFSET_MM


@pytest.mark.parametrize(
    ("long_mm", "short_mm", "deg", "laned"),
    [
        (67.0, 46.3, 8.8, True),  # the gang saw's link 4
        (40.0, 30.0, 12.0, True),  # far ends 6,2 mm apart, within a lane over 12 mm
        (200.0, 150.0, 8.0, False),  # long sides: their far ends 21 mm apart, readable
        (20.0, 15.0, 28.0, False),  # a short wide wedge: within a lane over 5 mm only
        (100.0, 80.0, 3.0, True),  # under LANE_ANGLE, as before
    ],
)
def test_the_angle_that_reads_as_one_line_depends_on_the_lengths(
    long_mm: float, short_mm: float, deg: float, laned: bool
) -> None:
    """Two sides from one vertex: laned where the shorter's far end is within a sliver's
    lane of the longer's line and they run within a lane longer than two arrowheads."""
    a = PlanVector("a", Vec(0.0, 0.0), _polar(long_mm, 0.0))
    b = PlanVector("b", _polar(short_mm, deg), Vec(0.0, 0.0))
    assert bool(views.lanes(1.0, [a, b])) is laned


@pytest.fixture(scope="module")
def gang_saw_plans() -> dict[str, list[Any]]:
    mp = pytest.MonkeyPatch()
    try:
        return plan_arrows(GANG_SAW, mp)
    finally:
        mp.undo()


def _one_line_pairs(arrows: list[Any]) -> list[tuple[int, int, float]]:
    """Pairs of drawn arrows that read as one line (views.one_line at 1 mm a unit) and come
    nearer than a lane anywhere (not drawn side by side): (i, j, nearest mm)."""
    out = []
    pvs = [PlanVector(str(i), Vec(*a), Vec(*b)) for i, (a, b) in enumerate(arrows)]
    for i, a in enumerate(pvs):
        for j in range(i + 1, len(pvs)):
            b = pvs[j]
            if not views.one_line(a, b, 1.0):
                continue
            near = min(*(_seg_dist(p, b.tail, b.head) for p in (a.tail, a.head)),
                       *(_seg_dist(p, a.tail, a.head) for p in (b.tail, b.head)))  # fmt: skip
            if near < views.OFFSET_MM:
                out.append((i, j, near))
    return out


def _seg_dist(p: Vec, a: Vec, b: Vec) -> float:
    d = b - a
    t = 0.0 if d.norm == 0.0 else max(0.0, min(1.0, (p - a).dot(d) / d.dot(d)))
    return (p - (a + d * t)).norm


def test_the_gang_saw_link_4_plan_draws_its_long_sides_apart(
    gang_saw_plans: dict[str, list[Any]],
) -> None:
    plans = {t: a for t, a in gang_saw_plans.items() if "4" in t.split(",")[0]}
    assert plans
    bad = {t: _one_line_pairs(a) for t, a in gang_saw_plans.items() if _one_line_pairs(a)}
    assert bad == {}, bad


# --- 2. no crossing sides where an order does not cross ---------------------------------------


def _stephenson_group_23() -> ForcePolygon:
    """Stephenson's group (2, 3) as the kinetostatics laid it off (1 N a mm at its μ_F)."""
    loads = [("R^τ_{12}", Vec(16.0, -34.2)), ("R_{42}", Vec(64.2, 73.9)),
             ("Ф_{2}", Vec(25.2, -4.0)), ("Ф_{3}", Vec(9.3, -2.3)), ("G_{2}", Vec(0.0, -8.9)),
             ("G_{3}", Vec(0.0, -5.1)), ("R^τ_{03}", Vec(-3.4, 1.5))]  # fmt: skip
    vs = _chain(Vec(0.0, 0.0), loads)
    rn03 = PlanVector("R^n_{03}", vs[-1].head, Vec(128.5, 60.0))
    rn12 = PlanVector("R^n_{12}", rn03.head, Vec(0.0, 0.0))
    return ForcePolygon(Vec(0.0, 0.0), (*vs, rn03, rn12), (("R^n_{03}", 1.0), ("R^n_{12}", 1.0)))


def test_a_crossing_near_the_end_of_a_long_side_counts() -> None:
    """R₄₂ crosses R^n₁₂ 5 mm short of its head, where Ф₂ (25 mm, no detail) goes on: a
    crossing; regroup lays the known loads off in an order that does not cross."""
    poly = _stephenson_group_23()
    k = 1.0
    assert views.crossings(poly, views.SHORT_MM * k) >= 1
    new = views.regroup(poly, k)
    assert views.crossings(new, views.SHORT_MM * k) == 0
    assert sorted(new.names) == sorted(poly.names)
    assert (new.vectors[-1].head - new.pole).norm < 1e-9


def test_a_crossing_in_a_detail_circle_does_not_count() -> None:
    """Two long sides that cut one another within two arrowheads of an end where a run of
    short sides goes on (drawn enlarged in a detail, its circle round them) do not cross."""
    loads = [("A", Vec(100.0, 0.0)), ("s1", Vec(0.0, 3.0)), ("s2", Vec(-3.0, 0.0)),
             ("B", Vec(-60.0, -40.0))]  # fmt: skip
    vs = _chain(Vec(0.0, 0.0), loads)
    close = PlanVector("C", vs[-1].head, Vec(0.0, 0.0))
    poly = ForcePolygon(Vec(0.0, 0.0), (*vs, close), (("C", 1.0),))
    assert views.crossings(poly, views.SHORT_MM) == 0


def _crossing(a: Any, b: Any, end_mm: float = 1.0) -> tuple[float, float] | None:
    """Where two drawn arrows cut one another inside both (more than ``end_mm`` from their
    ends), else None."""
    (ax, ay), (bx, by) = a
    (cx, cy), (dx, dy) = b
    rx, ry, sx, sy = bx - ax, by - ay, dx - cx, dy - cy
    den = rx * sy - ry * sx
    if abs(den) < 1e-12:
        return None
    t = ((cx - ax) * sy - (cy - ay) * sx) / den
    u = ((cx - ax) * ry - (cy - ay) * rx) / den
    ea, eb = end_mm / math.hypot(rx, ry), end_mm / math.hypot(sx, sy)
    if ea < t < 1.0 - ea and eb < u < 1.0 - eb:
        return (ax + t * rx, ay + t * ry)
    return None


def test_stephenson_group_23_plan_does_not_cross_itself(monkeypatch: pytest.MonkeyPatch) -> None:
    """As drawn: no two arrows of the plan at its μ_F cross outside its details' circles
    (where a run of short sides, drawn enlarged in the detail, turns)."""
    from geomcad.sheet.model import CircleItem

    rec: dict[str, tuple[list[Any], list[CircleItem]]] = {}
    draw = views.Polygon.draw

    def rec_draw(self: views.Polygon, d: Any, at: Any) -> None:
        i, j = len(d.sheet.items), len(d.sheet.scaled)
        draw(self, d, at)
        k = at.viewport.scale.k
        arrows = [(a, b) for a, b, sc in d.sheet.scaled[j:] if sc.k == k]
        rings = [it for it in d.sheet.items[i:] if isinstance(it, CircleItem) and not it.fill]
        rec[self.title] = (arrows, rings)

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    import geomcad

    dict(geomcad.solve(str(STEPHENSON)).sheets())
    title = next(t for t in rec if "(2, 3)" in t)
    arrows, rings = rec[title]
    crossed = []
    for i in range(len(arrows)):
        for j in range(i + 1, len(arrows)):
            at = _crossing(arrows[i], arrows[j])
            if at is not None and not any(math.dist(at, c.c) < c.r for c in rings):
                crossed.append((i, j, at))
    assert crossed == [], (title, crossed)


# --- 3. the lever's letters at their points -------------------------------------------------


def test_ring_clearance_is_the_way_out_of_the_circles_round_a_point() -> None:
    from geomcad.sheet.linkage_forces import ring_clearance
    from geomcad.sheet.model import CircleItem

    twins = [CircleItem((-1.5, 0.0), 5.0, "thin"), CircleItem((1.5, 0.0), 5.0, "thin")]
    assert ring_clearance((0.0, 0.0), twins) == pytest.approx(math.sqrt(25.0 - 2.25), abs=0.05)
    assert ring_clearance((20.0, 0.0), twins) == 0.0


def test_the_shaper_lever_letters_stay_at_their_points() -> None:
    from geomcad.linkage import parse
    from geomcad.linkage.solution import solve
    from geomcad.sheet import linkage_forces as lf

    mp = pytest.MonkeyPatch()
    asked: list[Any] = []
    orig = lf._Lever.draw

    def lever(self: Any, d: Any, at: Any) -> Any:
        n0 = len(d.pending)
        out = orig(self, d, at)
        asked.extend((rq.anchor, rq.markup) for rq in d.pending[n0:])
        return out

    mp.setattr(lf._Lever, "draw", lever)
    try:
        lk = parse(tomllib.loads(SHAPER.read_text("utf-8")))
        sheet = lf.force_sheets(solve(lk), "x")[0][1]
    finally:
        mp.undo()
    points = {tuple(a) for a, m in asked if "," in m}
    assert points, "the shaper's lever letters a point with several names (p, o, c)"
    _form, drawn = block_part(sheet)
    lines = [it for it in drawn if not isinstance(it, TextItem)]
    far, crossed = [], []
    for t, anchor in sheet.anchors:
        if tuple(anchor) not in {tuple(a) for a, _ in asked}:
            continue
        d = text_poly(t).distance(Point(anchor))
        if d > ANCHOR_MAX:
            far.append((t.text, round(d, 1)))
        p = text_poly(t).buffer(-0.25)
        for it in lines:
            if stroke(it, sheet.format).intersection(p).area > AREA_EPS and not is_bar_of(it, t):
                crossed.append((t.text, it.role))
                break
    assert far == [], far
    assert crossed == [], crossed
