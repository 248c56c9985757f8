"""The force plans, their details and the μ_F tiers of a linkage file's forces sheet (issue 27):
a plan drawn large, its short vectors laid off as one run and shown in details of one level
beside it, at most three μ_F per view (two where two can draw every force), and forces along
one line at one point of Zhukovsky's lever drawn end to end."""

from __future__ import annotations

import itertools
import math
import re
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.forces import ForcePolygon, PlanVector
from geomcad.geom import Vec
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import solve
from geomcad.sheet import start
from geomcad.sheet.compose import compose
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.frame import TitleBlock
from geomcad.sheet.linkage_forces import POLY_MM, force_position, load_sides
from geomcad.sheet.loads import MOST_TIERS, NEGLIGIBLE, TIER_LIMIT, force_tiers
from geomcad.sheet.model import CircleItem, Polyline, TextItem
from geomcad.sheet.scale import nice_below
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.sheet.views import (
    DETAIL_LEAST,
    DETAIL_MAX_MM,
    LISTED_MM,
    Polygon,
    detail_spots,
    is_sliver,
    plan_details,
    regroup,
    short_runs,
)

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TESTS = Path(__file__).resolve().parent / "linkages"
LINKAGES = [
    p
    for p in sorted(EXAMPLES.glob("*.toml"))
    if "[drive]" in p.read_text(encoding="utf-8") and "[[group]]" in p.read_text(encoding="utf-8")
]


def chain(mags: list[float], names: list[str], turn: float = 1.1) -> list[PlanVector]:
    """Vectors of the magnitudes ``mags`` head to tail from the origin, each turned ``turn``
    rad from the one before."""
    out, q = [], Vec(0.0, 0.0)
    for i, (F, name) in enumerate(zip(mags, names, strict=True)):
        nxt = q + Vec(math.cos(i * turn), math.sin(i * turn)) * F
        out.append(PlanVector(name, q, nxt))
        q = nxt
    return out


def group_polygon() -> ForcePolygon:
    """A group's polygon as the kinetostatics builds it: R^τ_12 first, the loads in the order
    of their links (short ones between long ones), then the two unknowns closing it."""
    known = chain([30.0, 5000.0, 40.0, 4000.0, 60.0, 3000.0],
                  ["R^τ_{12}", "F_{B}", "G_{2}", "Ф_{2}", "G_{3}", "Ф_{3}"])  # fmt: skip
    end = known[-1].head
    corner = Vec(end.x, 0.0)
    vs = [*known, PlanVector("R_{03}", end, corner), PlanVector("R^n_{12}", corner, Vec(0, 0))]
    return ForcePolygon(Vec(0.0, 0.0), tuple(vs), (("R_{03}", 1.0), ("R^n_{12}", 1.0)))


def test_regroup_lays_the_short_loads_off_as_one_run() -> None:
    """The known loads take the order that makes the short vectors one run; the unknowns and
    a reaction's component keep their places, every vector keeps its force, the polygon
    closes, and one detail shows the run."""
    poly = group_polygon()
    k = 5000.0 / 110.0
    assert len(short_runs(poly.vectors, SHORT_MM * k)) == 3  # R^τ+… , G_2, G_3 apart
    new = regroup(poly, k)
    assert len(short_runs(new.vectors, SHORT_MM * k)) == 1
    assert new.vectors[0].name == "R^τ_{12}"
    assert [pv.name for pv in new.vectors[-2:]] == ["R_{03}", "R^n_{12}"]
    assert sorted(new.names) == sorted(poly.names)
    for pv in new.vectors:
        assert (pv.force - poly[pv.name].force).norm <= 1e-9 * 5000.0
    for a, b in itertools.pairwise([*new.vectors, new.vectors[0]]):
        assert (a.head - b.tail).norm <= 1e-9 * 5000.0  # head to tail, closed
    assert len(plan_details(new, k, iter("БВГД"))) == 1
    # a polygon whose short vectors are one run already keeps its order
    assert regroup(new, k) is new


def test_details_are_at_one_scale_and_name_what_it_leaves_short() -> None:
    """A run of forces over three decades (review 7, item 4: plans with details at
    4 / 0,5 / 0,05 / 1 N/mm; review 14, fix 2: the knuckle press's six details at three more
    μ_F round one vertex): the details taken from the plan are all at ONE stated μ_F, at
    least DETAIL_LEAST times the polygon's, with the longest at most DETAIL_MAX_MM; none is
    taken from a detail. Every vector is an arrow at a μ_F the plan states, at least one
    arrowhead (LISTED_MM) long in a detail, but those the details' μ_F draws shorter than
    that: lines in the detail, named with their values on a line under the caption (review 9
    drew them in a second tier of details); each circle carries one letter."""
    vs = chain([5000.0, 3.0, 40.0, 400.0, 7.0], ["F0", "F1", "F2", "F3", "F4"])
    vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
    p = Polygon(poly, detail=True)
    d = start("A3", TitleBlock("t", "d"))
    lay = compose(d, p)
    sheet = d.finish()
    k = lay[p].scale.k
    assert p.details and len({dt.letter for dt in p.details}) == len(p.details)
    assert all(dt.tier == 1 and dt.host is None for dt in p.details)
    assert len({dt.k for dt in p.details}) == 1
    kd = p.details[0].k
    assert kd * DETAIL_LEAST <= k * (1.0 + 1e-9)
    drawn = p.layers[-1][0]
    runs = [n for dt in p.details for n in dt.run]
    assert len(runs) == len(set(runs))  # each short vector in exactly one detail
    listed = {n for dt in p.details for n in dt.listed} | set(p.lined)
    for dt in p.details:
        assert max(drawn[n].magnitude for n in dt.run) / dt.k <= DETAIL_MAX_MM
        for n in dt.run:
            assert (drawn[n].magnitude / dt.k < LISTED_MM) == (n in dt.listed), (dt.letter, n)
    assert listed == {"F1"}  # 3 N at the details' μ_F: the one vector a span of 10³ leaves
    notes = [t.text for t in sheet.texts() if "не показан" in t.text]
    assert len(notes) == 1 and "F" in notes[0]
    arrows = [(math.dist(t, h), sc.k) for t, h, sc in sheet.scaled]
    assert {sc for _, sc in arrows} <= {k, kd}
    assert min(mm for mm, sc in arrows if sc == kd) >= LISTED_MM * (1.0 - 1e-9)
    for pv in poly.vectors:
        if pv.name not in listed:
            assert any(math.isclose(mm * s, pv.magnitude, rel_tol=1e-6) for mm, s in arrows), pv
    captions = [t.text for t in sheet.texts() if "(μ" in t.text]
    assert len(captions) == len(p.details)
    v = lay[p].viewport
    assert v is not None
    spots = detail_spots(v, drawn, p.details)
    assert len(spots) == len(p.details)
    assert not any(", " in letters for _, _, letters in spots)
    circles = [it for it in sheet.items if isinstance(it, CircleItem) and not it.fill]
    assert len(circles) == len(p.details)


def test_runs_at_one_spot_of_the_plan_are_one_detail_with_one_letter() -> None:
    """Two runs of short vectors whose circles on the plan would overlap (a long vector
    between them barely two arrowheads long) are one detail, the vector between them
    included, lettered with one letter (review 7: one circle lettered "П1, Ш1, Э1"); runs
    far apart stay two details at one μ_F."""
    from geomcad.sheet.views import short_runs

    k = 50.0
    for between, spots in ((360.0, 1), (1500.0, 2)):
        vs = chain([5000.0, 340.0, between, 340.0, 3000.0], ["F0", "F1", "F2", "F3", "F4"])
        vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
        poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
        assert short_runs(poly.vectors, SHORT_MM * k) == [["F1"], ["F3"]]
        details = plan_details(poly, k, iter("БГД"))
        assert len(details) == spots and len({dt.k for dt in details}) == 1
        if spots == 1:
            assert details[0].run == ("F1", "F2", "F3") and details[0].letter == "Б"


def test_a_negligible_vector_is_named_under_the_caption_not_detailed() -> None:
    """A plan's vector under NEGLIGIBLE of its largest would need a detail at an absurd μ_F
    (the review's 0.025 N/mm): it is in no detail, not drawn, and named on a line under the
    plan's caption; a short vector above that share is still drawn in a detail at its μ_F, and
    a polygon without the rule details both."""
    vs = chain([5000.0, 2.0, 40.0, 3000.0], ["F0", "F1", "F2", "F3"])
    vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
    assert 2.0 < NEGLIGIBLE * 5000.0 < 40.0
    plain = Polygon(poly, detail=True)
    assert {n for dt in plain.details for n in dt.run} >= {"F1", "F2"}
    p = Polygon(poly, detail=True, negligible=(NEGLIGIBLE, lambda ns: "left out: " + ", ".join(ns)))
    assert p.omitted == ["F1"] and p.note == "left out: F1"
    d = start("A3", TitleBlock("t", "d"))
    lay = compose(d, p)
    sheet = d.finish()
    runs = {n for dt in p.details for n in dt.run}
    assert "F1" not in runs and "F2" in runs
    assert min(dt.k for dt in p.details) > 2.0 / SHORT_MM  # no detail at the absurd μ_F
    arrows = [(math.dist(t, h), sc.k) for t, h, sc in sheet.scaled]
    drawn = [mm * k for mm, k in arrows]
    assert not any(math.isclose(F, 2.0, rel_tol=1e-6) for F in drawn)
    assert any(math.isclose(F, 40.0, rel_tol=1e-6) for F in drawn)
    # the note on its line under the caption, inside the view's box, above the drawing
    notes = [t for t in sheet.texts() if t.text == "left out: F1"]
    assert len(notes) == 1
    box, inner = lay[p].box, lay[p].inner
    assert box[1] < notes[0].at[1] <= inner[1] and box[0] <= notes[0].at[0] < box[2]


def test_a_plan_placed_coarser_than_its_details_were_reckoned_at_spills() -> None:
    """A plan's extent holds its details as reckoned at its reference μ_F; placed at a coarser
    μ_F in a box that scales that extent, its details (the same size in mm, and more of them)
    would reach out of the box into the captions round it: :meth:`Polygon.spill` says by how
    much (the forces sheet then reckons them again at that μ_F), and 0 where it fits."""
    vs = chain([5000.0, 30.0, 400.0, 3000.0], ["F0", "F1", "F2", "F3"])
    vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
    k = 40.0
    p = Polygon(poly, detail=True, ref=(k, (300.0, 300.0)))
    x0, y0, x1, y1 = p.extent() or (0.0, 0.0, 0.0, 0.0)
    assert p.details
    for kk in (k, 4.0 * k):
        inner = (0.0, 0.0, (x1 - x0) / kk, (y1 - y0) / kk)
        spill = p.spill(kk, inner)
        assert spill <= 1e-6 if kk == k else spill > 5.0, (kk, spill)
    assert Polygon(poly).spill(4.0 * k, (0.0, 0.0, 1.0, 1.0)) == 0.0  # no details: none


def test_a_run_too_large_for_its_bound_is_one_detail_its_short_vectors_named() -> None:
    """A run whose detail at its μ_F would outgrow its plan (as the crusher's group (2, 3):
    G_2, G_3, Ф_3 and R^τ_12 one under the other, here over two decades) is one detail within
    the bound at one μ_F (not cut into pieces at several: review 7, item 4); the vectors of it
    then shorter than one arrowhead, and only those, are named with their values under the
    plan's caption: the plan's one detail μ_F has no detail of its own (round 14: review 9's
    tiers gave the knuckle press six details at three more μ_F round one vertex)."""
    from geomcad.sheet.views import LISTED_MM, STUB_MM

    vs = chain([5000.0, 470.0, 40.0, 196.0, 588.0, 3000.0],
               ["F0", "F1", "F2", "F3", "F4", "F5"], turn=0.15)  # fmt: skip
    vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
    k, bound = 100.0, 62.0
    details = plan_details(poly, k, iter("БГДЖИЛ"), bound=bound)
    assert len(details) == 1 and details[0].host is None
    dt = details[0]
    assert sorted(dt.run) == ["F1", "F2", "F3", "F4"]
    box = dt.box
    assert max(box[2] - box[0], box[3] - box[1]) / dt.k <= bound - 2.0 * STUB_MM + 1e-9
    short = {n for n in dt.run if poly[n].magnitude / dt.k < LISTED_MM}
    assert short and set(dt.listed) == short
    # the finest factor of the series within the bound: the next finer outgrows it
    finer = nice_below(dt.k * 0.999, 1.0).k
    assert max(box[2] - box[0], box[3] - box[1]) / finer > bound - 2.0 * STUB_MM


def test_a_detail_s_slot_never_hangs_on_its_letter() -> None:
    """The layout reckons a plan with its details before the sheet letters them; drawn with
    the letters the sheet gives (narrower or wider, with a number or not: the merged sheet's
    "И1" for "Ш1" that put a detail left of its plan and the plan out of its box), each
    detail takes the slot reckoned, so the whole keeps the size the layout checked."""
    vs = chain([5000.0, 3.0, 40.0, 400.0, 7.0, 20.0], ["F0", "F1", "F2", "F3", "F4", "F5"])
    vs.append(PlanVector("R", vs[-1].head, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vs), ())
    p = Polygon(poly, detail=True)
    k = p.k_ref
    for room in (None, (140.0 * k, 100.0 * k)):
        got = []
        for letters in ("W" * 9, "ИЛПЭ", ["Ш1", "Ж12", "Ю7", "Л1"], ["Ш99", "Ж99", "Ю99", "Ш98"]):
            details, _, ext = p._with_details(k, iter(letters), room)
            assert details
            got.append(([dt.slot for dt in details], ext))
        assert all(g == got[0] for g in got), room


@pytest.mark.parametrize(
    ("forces", "room", "tiers"),
    [
        ([100.0, 60.0, 40.0], 24.0, 1),
        ([1000.0, 300.0, 20.0, 10.0], 24.0, 2),  # 1000 N 25 mm at μ_F*, not a third tier
        ([120.0, 88.3, 58.9, 32.2], 24.0, 1),  # one μ_F, the largest 30 mm (not 24 + μ_F*)
        ([1e5, 1e4, 1e3, 100.0, 10.0, 1.0], 24.0, MOST_TIERS),  # five decades: never four
        ([1e4, 3000.0, 400.0, 50.0, 12.0], 24.0, MOST_TIERS),  # four bands: two joined
    ],
)
def test_force_tiers_are_few_and_never_leave_a_force_short(
    forces: list[float], room: float, tiers: int
) -> None:
    fs = force_tiers([*forces, 1e-14], room)
    assert len(fs.scales) == tiers
    assert [sc.k for sc in fs.scales] == sorted((sc.k for sc in fs.scales), reverse=True)
    assert fs.tier(1e-14) is None  # round-off of a zero force
    # left out only where a fourth μ_F would be needed, and only a negligible share
    assert fs.negligible < NEGLIGIBLE * max(forces)
    assert (fs.negligible > 0.0) == (min(forces) < NEGLIGIBLE * max(forces))
    for F in forces:
        tier = fs.tier(F)
        if fs.negligible >= F:
            assert tier is None
            continue
        assert tier is not None
        mm = F / fs.scales[tier].k
        assert mm >= SHORT_MM * (1.0 - 1e-9), (F, mm)
        if tiers < MOST_TIERS:
            assert mm <= TIER_LIMIT * room * (1.0 + 1e-9), (F, mm)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_forces_sheet_plans_are_large_and_tiers_few(path: Path) -> None:
    """On every example's forces sheet: each force plan's longest vector at least POLY_MM
    long (the search seeks PLAN_SEEK_MM; the groups' shared μ_l may leave a plan's cell
    less; a sliver, R01 = −R21, is drawn short: test_plan_lanes), no view with more than
    MOST_TIERS μ_F (at most two stars in a label), and every detail's caption right by its
    drawing."""
    s = solve(geomcad.solve(str(path)).data.linkage)
    if analyse(s).forces is None:
        pytest.skip("no force analysis")
    sheet = dict(geomcad.solve(str(path)).sheets())["forces"]
    arrows = [(math.dist(t, h), sc.k) for t, h, sc in sheet.scaled if sc.q == "F"]
    _, f, _ = force_position(s)
    for gf in f.groups:
        for name, poly in gf.polygons:
            if is_sliver(poly):
                continue
            big = max(pv.magnitude for pv in poly.vectors)
            at = [mm for mm, k in arrows if math.isclose(mm * k, big, rel_tol=1e-6)]
            assert at and max(at) >= POLY_MM, (name, at)
    stars = [len(m) for t in sheet.texts() for m in re.findall(r"\*+", t.text)]
    assert max(stars, default=0) <= MOST_TIERS - 1


def _reach(it: Any) -> list[tuple[float, float]]:
    """The corners (sheet mm) of what an item covers: a line's points, a circle's box, a
    text's box (its cap height above the baseline, a subscript below)."""
    if isinstance(it, Polyline):
        return [tuple(q) for q in it.points]
    if isinstance(it, CircleItem):
        return [(it.c[0] - it.r, it.c[1] - it.r), (it.c[0] + it.r, it.c[1] + it.r)]
    if isinstance(it, TextItem):
        w, up, down = text_box(it.runs, it.height)
        return [(it.at[0], it.at[1] - up), (it.at[0] + w, it.at[1] + down)]
    return []


@pytest.mark.parametrize("path", [*LINKAGES, *sorted(TESTS.glob("*.toml"))], ids=lambda p: p.stem)
def test_a_plan_and_its_details_keep_inside_its_box_under_its_caption(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """On the forces sheet of every example and test file, everything a force plan draws (its
    vectors, their names, the circles and letters of its details, the details and their
    captions) lies in the plan's box below its caption (the review's "И, Л" touching the caption
    of the plan below, a plan running through titles), the line naming what it leaves out
    under the caption (broken into lines where wider than the box: round 15); the boxes of the
    views never overlap, so it is clear of every title."""
    from geomcad.sheet import views

    rec: list[tuple[Polygon, Any, list[Any]]] = []
    draw = views.Polygon.draw

    def rec_draw(self: Polygon, d: Any, at: Any) -> None:
        i = len(d.sheet.items)
        draw(self, d, at)
        rec.append((self, at, d.sheet.items[i:]))

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    s = solve(geomcad.solve(str(path)).data.linkage)
    if analyse(s).forces is None:
        pytest.skip("no force analysis")
    dict(geomcad.solve(str(path)).sheets())
    assert rec
    for p, at, items in rec:
        x0, y0, x1, y1 = at.box
        below = y0 + p.title_room()
        for it in items:
            notes = [p.note, *p.listed_lines(x1 - x0)]  # broken into lines for the box
            notes = ["".join(r.text for r in parse(n)) for n in notes]
            top = y0 if isinstance(it, TextItem) and it.text in notes else below
            for x, y in _reach(it):
                assert x0 <= x <= x1 and top <= y <= y1, (path.stem, p.title, it)


def test_forces_at_one_lever_point_never_lie_over_one_another() -> None:
    """Two forces of one sense along one line at one point are drawn head to tail (the
    shorter from the tip of the longer), two of opposite senses back to back (both leave the
    point); a long force at the lever's edge pointing out of it, past the view's margin,
    arrives from inside it, and a force along it of the other sense then leaves the point from
    its tail."""
    b, c, a = Vec(0.3, 0.1), Vec(0.0, 0.2), Vec(0.0, 0.0)
    right, left, k = Vec(1500.0, 0.0), Vec(-200.0, 0.0), 0.01
    loads = [
        (b, right, "F_B", "vector"),
        (b, Vec(600.0, 20.0), "Ф_3", "vector"),  # nearly along F_B
        (c, right, "F_c", "vector"),
        (c, left, "Ф_c", "vector"),
        (a, right, "F_a", "vector"),
    ]
    lengths = [37.5, 15.0, 30.0, 10.0, 20.0]
    out = load_sides(loads, k, lengths)
    assert [arrive for arrive, _ in out] == [False] * 5
    assert out[1][1].dist(b + Vec(1.0, 0.0) * (37.5 * k)) <= 1e-12  # from F_B's tip
    assert [start for _, start in out[2:]] == [c, c, a]
    # F_B 60 mm long from b, at the right edge of the lever, runs 60 mm out of it: past a
    # margin of 40 mm it arrives from inside, within one of 70 mm it leaves as usual
    ext = (0.0, 0.0, 0.3, 0.2)
    pair = [(b, right, "F_B", "vector"), (b, left, "Ф_3", "vector")]
    out = load_sides(pair, k, [60.0, 20.0], ext, slack=40.0)
    assert out[0] == (True, b)
    assert out[1][0] is False and out[1][1].dist(b + Vec(-1.0, 0.0) * (60.0 * k)) <= 1e-12
    assert load_sides(pair[:1], k, [60.0], ext, slack=70.0) == [(False, b)]
    # one of its sense goes on from its tip: the point itself, where it arrives
    same = [(b, right, "F_B", "vector"), (b, Vec(600.0, 20.0), "Ф_3", "vector")]
    assert load_sides(same, k, [60.0, 20.0], ext, slack=40.0) == [(True, b), (False, b)]
