"""The mechanism's scheme in its twelve positions as a teacher drafts it (issue 27, review 6
item 8): every moving point's track numbered (only a centre of mass that is nothing more is
not: tests/test_scheme_tracks.py); a rigid coupler triangle whole in the principal position
only, its thin positions one side; a link's number clear of the position numbers of its own
digits and its leader clear of every position's number."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import linkage as L
from geomcad.sheet.linkage import NUMBER_H, _Mechanism, kinematic_sheets, layout, link_bodies
from geomcad.sheet.model import Polyline, Sheet

ROOT = Path(__file__).resolve().parent
FILES = {
    "v_engine": ROOT / "linkages_positions" / "v_engine.toml",
    "coupler_slider": ROOT / "linkages_positions" / "coupler_slider.toml",
    "sixbar-slider": ROOT / "linkages" / "sixbar-slider.toml",
    **{n: ROOT.parent / "examples" / f"{n}.toml"
       for n in ("sixbar-2013-6", "shaper", "four-bar", "crusher", "scotch-yoke")},
}  # fmt: skip
#: what a link's number keeps from a position's number of its own digits (mm)
SAME_MM = getattr(L, "LINK_SAME_MM", 15.0)


def _solved(name: str) -> Solved:
    return solve(parse(tomllib.loads(FILES[name].read_text(encoding="utf-8"))))


def _drawn(s: Solved) -> tuple[Sheet, _Mechanism, tuple[float, float, float, float]]:
    sheet = kinematic_sheets(s, "x")[0][1]
    pl = next(pl for pl in layout(s).sized[0].layout if isinstance(pl.view, _Mechanism))
    assert isinstance(pl.view, _Mechanism)
    return sheet, pl.view, pl.box


@pytest.mark.parametrize("name", ["v_engine", "coupler_slider"])
def test_every_moving_joint_is_numbered_in_every_position(name: str) -> None:
    """The second cylinder's piston B of a V engine, a crank-rocker's B: each position's
    number at its own point (review 6: v_compressor's B stood in twelve places unnumbered)."""
    s = _solved(name)
    lk = s.linkage
    joints = {lk.joint, lk.output, *(g.joint for g in lk.groups if g.joint)}
    assert joints <= set(L.numbered_tracks(lk))
    sheet, mech, _ = _drawn(s)
    for j in joints - {lk.joint}:
        pts = mech.tracks[j]
        nums = [t for t in sheet.texts() if t.role == "label" and t.text.isdigit()
                and t.height == NUMBER_H]  # fmt: skip
        anchors = {id(t): at for t, at in sheet.anchors}
        # a number standing by its point (anchored there), or in a row off a crowd of them
        got = [t.text for t in nums
               if (id(t) in anchors and any(math.dist(anchors[id(t)], q) < 1e-6 for q in pts))
               or any(max(abs(u - w) for u, w in zip(L._text_box(t)[:3], b[:3], strict=True))
                      < 1e-6 for b in mech.rows.get(j, []))]  # fmt: skip
        assert sorted(got, key=int) == [str(k) for k in range(len(s.drawn))], j


def test_a_coupler_triangle_is_whole_in_the_principal_position_only() -> None:
    """The coupler ABK (a group hung on K): the thin positions draw its side AB and an arm to K
    from the nearer of A and B (review 9: link 4 hung on free points K), the principal one the
    whole triangle (twelve triangles once wove a web)."""
    s = _solved("coupler_slider")
    lk = s.linkage

    def at(*names: str) -> set[tuple[float, float]]:
        return {(round(P.pos[n].x, 12), round(P.pos[n].y, 12)) for n in names}

    for P in s.drawn:
        side, arm = link_bodies(lk, P, axes=True)["2"]
        assert len(side.points) == 2 and not side.closed and len(arm.points) == 2
        assert {(round(q.x, 12), round(q.y, 12)) for q in side.points} == at("A", "B")
        near = min("AB", key=lambda n: P.pos[n].dist(P.pos["K"]))
        assert {(round(q.x, 12), round(q.y, 12)) for q in arm.points} == at(near, "K")
        (whole,) = link_bodies(lk, P)["2"]
        assert whole.closed and len(whole.points) == 3


def test_a_link_with_its_joints_on_one_line_is_drawn_through_them_all() -> None:
    """The press's rocker C–B–E (E beyond B on CB): a thin position runs from C to E."""
    s = _solved("sixbar-slider")
    lk = s.linkage
    for P in s.drawn:
        (thin,) = link_bodies(lk, P, axes=True)["3"]
        ends = {(round(q.x, 9), round(q.y, 9)) for q in thin.points}
        assert ends == {(round(P.pos[n].x, 9), round(P.pos[n].y, 9)) for n in ("C", "E")}


def _link_numbers(
    sheet: Sheet, area: tuple[float, float, float, float]
) -> tuple[list[tuple[str, L.Box, tuple[float, float]]], list[tuple[str, L.Box]], list[Polyline]]:
    """The links' numbers (text, box, the point each names), the positions' numbers (text, box)
    and the leaders (thin two-point lines) in the view's ``area``."""

    def inside(p: tuple[float, float]) -> bool:
        return area[0] <= p[0] <= area[2] and area[1] <= p[1] <= area[3]

    anchors = {id(t): at for t, at in sheet.anchors}
    texts = [t for t in sheet.texts() if t.role == "label" and t.text.isdigit() and inside(t.at)]
    links = [(t.text, L._text_box(t), anchors[id(t)]) for t in texts
             if t.height > NUMBER_H and id(t) in anchors]  # fmt: skip
    numbers = [(t.text, L._text_box(t)) for t in texts if t.height == NUMBER_H]
    leaders = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "dimension"
               and len(it.points) == 2 and inside(it.points[0])]  # fmt: skip
    return links, numbers, leaders


@pytest.mark.parametrize("name", ["sixbar-2013-6", "coupler_slider", "v_engine", "four-bar"])
def test_a_links_number_keeps_off_a_position_number_of_its_digits(name: str) -> None:
    """Link 1's "1" beside position 1's "1" reads as either (whitworth's link 3 once stood
    among position 3's "3" at A and at B)."""
    sheet, _, area = _drawn(_solved(name))
    links, numbers, _ = _link_numbers(sheet, area)
    assert links and numbers
    for text, b, _ in links:
        gaps = [L._gap(b, n) for t, n in numbers if t == text]
        assert min(gaps, default=math.inf) >= SAME_MM - 1e-9, text


@pytest.mark.parametrize("name", ["sixbar-2013-6", "v_engine", "crusher", "four-bar"])
def test_a_links_leader_keeps_off_the_position_numbers(name: str) -> None:
    """A link's number joined to its point by a leader: the leader keeps LINK_CLEAR_MM from
    every position's number but those at its point itself (a leader among a row of numbers
    reads as one of theirs: the shaper's "5" once ran among B's). Where no place within
    LINK_NUMBER_REACH_MM allows it (the shaper's ram, the coupler_slider's block 2) the
    leader stands as clear as it can: not asserted here."""
    sheet, _, area = _drawn(_solved(name))
    links, numbers, leaders = _link_numbers(sheet, area)
    for text, b, p in links:
        own = [ld for ld in leaders
               if L._to_box(ld.points[1], b) <= L.LEADER_TO_MM + 0.05
               and math.dist(ld.points[0], p) <= L.LEADER_FROM_MM + 0.05]  # fmt: skip
        for ld in own:
            a, e = ld.points
            for _, n in numbers:
                if L._to_box(p, n) >= L.LINK_CLEAR_MM:
                    assert _segment_to_box(a, e, n) >= L.LINK_CLEAR_MM - 1e-6, text


def _segment_to_box(
    a: tuple[float, float], b: tuple[float, float], x: tuple[float, float, float, float]
) -> float:
    """The distance from the segment a–b to the box x, sampled every 0.05 mm."""
    n = max(2, int(math.dist(a, b) / 0.05))
    return min(L._to_box((a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n), x)
               for k in range(n + 1))  # fmt: skip
