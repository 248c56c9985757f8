"""The mechanism view's numbered positions and symbols as a teacher reads them (issue 27, review
3): every position's own number next to its point (a crowd's numbers in a row with leaders, never
a shared "4–8"; a slider's numbers beyond its hatched guide), the frame's guide hatched over the
slider's travel, no mark hidden inside a block, and a crank the mechanism's scale leaves short
enlarged on a detail view at a stated μ_l (ESKD 2.305)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

from layout import findings, layout_problems

from geomcad.geom import Vec
from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, scheme, solve
from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.drawing import Drawing, Viewport
from geomcad.sheet.linkage import (
    CRANK_MM,
    DETAIL_BELOW,
    GUIDE_CLEAR_MM,
    _CrankDetail,
    _principal,
    _views,
    detail_letter,
    kinematic_sheets,
    layout,
    position_numbers,
)
from geomcad.sheet.model import CircleItem, Polyline, Sheet, TextItem
from geomcad.sheet.scheme import WALL_MIN_MM
from geomcad.sheet.symbols import SLIDER_SIZE

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _solved(name: str) -> Solved:
    data = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    return solve(parse(data))


def _viewport(s: Solved) -> Viewport:
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    return v


def _centre(t: TextItem) -> tuple[float, float]:
    return (t.at[0] + t.width / 2.0, t.at[1] - t.height / 2.0)


def _numbers(sheet: Sheet) -> dict[int, list[TextItem]]:
    out: dict[int, list[TextItem]] = {}
    for t in sheet.texts():
        if t.role == "label" and t.text.isdigit():
            out.setdefault(int(t.text), []).append(t)
    return out


def _seg_dist(q: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    ab = (b[0] - a[0], b[1] - a[1])
    L2 = ab[0] ** 2 + ab[1] ** 2 or 1.0
    t = max(0.0, min(1.0, ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / L2))
    return math.dist(q, (a[0] + t * ab[0], a[1] + t * ab[1]))


def _box_dist(q: tuple[float, float], t: TextItem) -> float:
    """The distance (mm) from a point to a text's box."""
    x0, x1 = t.at[0], t.at[0] + t.width
    y0, y1 = t.at[1] - t.height, t.at[1] + 0.3 * t.height
    dx = max(x0 - q[0], 0.0, q[0] - x1)
    dy = max(y0 - q[1], 0.0, q[1] - y1)
    return math.hypot(dx, dy)


def _crowd(n: int = 9) -> tuple[list[Vec], list[Vec]]:
    """A rocker's point near its extreme: n positions within about 4 mm at 1:1 (model m), the
    first half running one way, the rest back."""
    pts, vels = [], []
    for i in range(n):
        a = math.radians(60.0 + 3.0 * math.sin(math.pi * i / (n - 1)))
        pts.append(Vec(0.08 * math.cos(a), 0.08 * math.sin(a)))
        sense = 1.0 if i < n // 2 else -1.0
        vels.append(Vec(-math.sin(a), math.cos(a)) * sense)
    return pts, vels


def test_a_crowds_numbers_stand_in_a_row_each_with_a_leader_to_its_point() -> None:
    pts, vels = _crowd()
    d: Drawing = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.001, "l"), (0.0, 0.0), (200.0, 200.0))
    for q in pts:
        v.dot(q)
    position_numbers(v, pts, vels, Vec(0.0, 0.0))
    sheet = d.finish()
    nums = _numbers(sheet)
    # every position its own number, once, none shared ("4–8") or listed
    assert sorted(nums) == list(range(len(pts)))
    assert all(len(ts) == 1 for ts in nums.values())
    assert not [t.text for t in sheet.texts() if "\u2013" in t.text or "," in t.text]
    assert layout_problems(sheet) == []
    leaders = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "dimension"]
    for i, (t,) in nums.items():
        p = v.p(pts[i])
        # a leader from next to its own point to next to its own number
        assert any(
            math.dist(it.points[0], p) < 1.0 and _box_dist(it.points[-1], t) < 1.0 for it in leaders
        ), f"position {i}: no leader from its point to its number"
    # the leaders do not cross (the numbers stand in the order of their points)
    segs = [(it.points[0], it.points[-1]) for it in leaders]
    for k, (a, b) in enumerate(segs):
        for c, e in segs[k + 1 :]:
            assert not _crosses(a, b, c, e)


def test_a_rows_number_moves_off_a_line_that_crosses_it() -> None:
    """Lines drawn across a crowd's row (other positions of the links): each number moves to
    the nearest place no line crosses, still joined to its point by a leader."""
    pts, vels = _crowd()
    d: Drawing = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.001, "l"), (0.0, 0.0), (200.0, 200.0))
    for q in pts:
        v.dot(q)
    # lines fanning out across both sides of the crowd, where the rows would stand
    for k in range(-2, 3):
        a = math.radians(61.5 + 2.5 * k)
        u = Vec(math.cos(a), math.sin(a))
        v.seg(u * 0.06, u * 0.11, "thin")
    position_numbers(v, pts, vels, Vec(0.0, 0.0))
    sheet = d.finish()
    nums = _numbers(sheet)
    assert sorted(nums) == list(range(len(pts)))
    assert not [f for f in findings(sheet) if f.kind in ("tick-label", "label-line")]
    assert layout_problems(sheet) == []


def _crosses(a: tuple[float, float], b: tuple[float, float], c: tuple[float, float],
             e: tuple[float, float]) -> bool:  # fmt: skip
    def orient(p: tuple[float, float], q: tuple[float, float], r: tuple[float, float]) -> float:
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    one = orient(a, b, c) * orient(a, b, e) < -1e-9
    return one and orient(c, e, a) * orient(c, e, b) < -1e-9


def test_numbers_along_a_guide_stand_beyond_it_without_sharing() -> None:
    """A slider's positions on a straight guide (``clear``: the hatched guide's room): every
    number beyond the guide, its own, the working stroke on one side and the return on the
    other, straight across its point where the spacing allows."""
    n = 12
    pts = [Vec(0.04 * (1.0 - math.cos(2.0 * math.pi * i / n)), 0.0) for i in range(n)]
    vels = [Vec(math.sin(2.0 * math.pi * i / n) or 1.0, 0.0) for i in range(n)]
    d: Drawing = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.0005, "l"), (0.0, 0.0), (120.0, 150.0))
    position_numbers(v, pts, vels, Vec(-0.05, 0.0), clear=GUIDE_CLEAR_MM)
    sheet = d.finish()
    nums = _numbers(sheet)
    assert sorted(nums) == list(range(n))
    assert layout_problems(sheet) == []
    y = v.p(pts[0])[1]
    sides = {}
    for i, (t,) in nums.items():
        top, bottom = t.at[1] - t.height, t.at[1]
        gap = min(abs(top - y), abs(bottom - y))
        assert gap >= GUIDE_CLEAR_MM - 0.05 and not (top < y < bottom), (i, gap)
        sides[i] = 1 if top > y else -1
    forward = {sides[i] for i in range(1, n // 2)}
    back = {sides[i] for i in range(n // 2 + 1, n)}
    assert len(forward) == 1 and len(back) == 1 and forward != back


def test_a_sliders_guide_is_hatched_over_its_travel_on_both_sides() -> None:
    s = _solved("slider-crank")
    sheet = kinematic_sheets(s)[0][1]
    v = _viewport(s)
    P0, _ = _principal(s)
    mech = scheme(s.linkage, P0)
    (pair,) = [p for p in mech.pairs if p.kind == "P" and mech.frame in p.links]
    assert pair.axis is not None
    u = v.paper_dir(pair.axis)
    stops = [v.p(P.pos["B"]) for P in s.drawn]
    ref = stops[0]
    ts = [(q[0] - ref[0]) * u[0] + (q[1] - ref[1]) * u[1] for q in stops]
    assert max(ts) - min(ts) > 20.0
    spans: dict[int, list[float]] = {}
    for it in sheet.items:
        if not (isinstance(it, Polyline) and it.role == "ground"):
            continue
        for p in it.points:
            off = (p[0] - ref[0]) * u[1] - (p[1] - ref[1]) * u[0]
            if SLIDER_SIZE[1] / 2.0 <= abs(off) <= GUIDE_CLEAR_MM + 0.5:
                spans.setdefault(1 if off > 0 else -1, []).append(
                    (p[0] - ref[0]) * u[0] + (p[1] - ref[1]) * u[1]
                )
    assert set(spans) == {1, -1}, "the guide is not hatched on both sides"
    # round 14 (review 14, item 5): a wall is hatched only where no position's link line
    # crosses it, so the rod that sweeps both walls leaves a stub at least a slider long,
    # within the travel (scheme.guide_walls; tests/test_r14_kin_sheet.py holds the clearance)
    lo, hi = min(ts) - SLIDER_SIZE[0], max(ts) + SLIDER_SIZE[0]  # the travel (the crank's
    for side in spans.values():  # support on the axis lies beyond it)
        on = [t for t in side if lo <= t <= hi]
        assert on and max(on) - min(on) >= WALL_MIN_MM - 1e-9, (on, lo, hi)
    # no number stands in the guide or its hatching: B's numbers beyond it
    inside = []
    for ts_ in _numbers(sheet).values():
        for t in ts_:
            c = _centre(t)
            along = (c[0] - ref[0]) * u[0] + (c[1] - ref[1]) * u[1]
            off = abs((c[0] - ref[0]) * u[1] - (c[1] - ref[1]) * u[0])
            if min(ts) <= along <= max(ts) and off < GUIDE_CLEAR_MM + t.height / 2.0 - 0.1:
                inside.append(t.text)
    assert not inside, inside


def test_no_position_mark_is_hidden_inside_a_block() -> None:
    s = _solved("shaper")
    sheet = kinematic_sheets(s)[0][1]
    v = _viewport(s)
    P0, _ = _principal(s)
    mech = scheme(s.linkage, P0)
    blocks = [p for p in mech.pairs if p.kind == "P" and mech.frame in p.links]
    assert blocks
    dots = [it for it in sheet.items if isinstance(it, CircleItem) and it.role == "point"]
    for pair in blocks:
        assert pair.axis is not None
        c, u = v.p(pair.at), v.paper_dir(pair.axis)
        inside = [
            q.c
            for q in dots
            if abs((q.c[0] - c[0]) * u[0] + (q.c[1] - c[1]) * u[1]) < SLIDER_SIZE[0] / 2.0
            and abs((q.c[0] - c[0]) * u[1] - (q.c[1] - c[1]) * u[0]) < SLIDER_SIZE[1] / 2.0
        ]
        assert not inside, f"marks inside the block of {pair.name}: {inside}"
        # the positions that fall there are still numbered (beyond the guide)
        name = pair.name.split(":")[0]
        hidden = [
            i
            for i, P in enumerate(s.drawn)
            if abs(
                (v.p(P.pos[name])[0] - c[0]) * u[0] + (v.p(P.pos[name])[1] - c[1]) * u[1]
            ) < SLIDER_SIZE[0] / 2.0
        ]  # fmt: skip
        assert hidden
        nums = _numbers(sheet)
        for i in hidden:
            q = v.p(s.drawn[i].pos[name])
            assert any(_box_dist(q, t) < GUIDE_CLEAR_MM + 4.0 for t in nums.get(i, [])), i


def test_a_short_crank_is_enlarged_on_a_detail_view_at_a_stated_scale() -> None:
    """The crusher's long links set its scale (1:5) and leave its crank 8 mm: the crank is drawn
    again on a detail view lettered on the mechanism (a circle, a leader, a letter) at a GOST
    scale giving it at least CRANK_MM, numbered there 0 … 11; the mechanism keeps its own μ_l."""
    s = _solved("crusher")
    lk = s.linkage
    sheet = kinematic_sheets(s)[0][1]
    lay = layout(s)
    z = lay.sized[0].layout
    k_mech = z[lay.mech].scale
    assert k_mech is not None and k_mech.mm(lk.length) < DETAIL_BELOW * CRANK_MM
    details = [view for view in _views(lay.trees[0]) if isinstance(view, _CrankDetail)]
    assert len(details) == 1
    dv = z[details[0]].viewport
    assert dv is not None
    assert dv.scale.mm(lk.length) >= CRANK_MM - 1e-6
    assert dv.scale.ratio is not None  # a GOST 2.302 ratio
    letter = detail_letter(s)
    assert letter not in "АВЕКМНРСТУ"  # never like a Latin point name (the crank's A)
    texts = [t.text for t in sheet.texts()]
    # its title: the letter and its own μ_l, stated
    title = [t for t in texts if t.startswith(f"{letter}:")]
    assert title and dv.scale.ratio_text() in title[0], texts[:5]
    assert any(t == letter for t in texts)  # the letter on the mechanism's shelf
    # numbered there: every position of the crank's joint next to its point on the detail
    nums = _numbers(sheet)
    for i, P in enumerate(s.drawn):
        q = dv.p(P.pos[lk.joint])
        assert any(_box_dist(q, t) < 6.0 for t in nums.get(i, [])), f"A{i} unnumbered"
    # and not on the mechanism, where its numbers would jam
    v = _viewport(s)
    o = v.p(lk.frame[lk.pivot])
    ring = k_mech.mm(lk.length) + 1.0
    assert not [t.text for ts in nums.values() for t in ts if math.dist(_centre(t), o) < ring + 1.0]


def test_a_crank_long_enough_gets_no_detail() -> None:
    s = _solved("slider-crank")
    lay = layout(s)
    assert not [view for view in _views(lay.trees[0]) if isinstance(view, _CrankDetail)]
