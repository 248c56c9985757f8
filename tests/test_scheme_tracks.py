"""The mechanism's scheme numbers its tracks apart (issue 27, review 5 item 8): a centre of mass
that is nothing more is not numbered (its path is drawn and dotted); every position's number
stands nearer its own point than any point or number of another track; a link's number keeps
clear of the position numbers in a row or a column of them."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import linkage as L
from geomcad.sheet.linkage import (
    NUMBER_H,
    SHARE_MM,
    TRACK_MARGIN_MM,
    _Mechanism,
    _text_box,
    kinematic_sheets,
    layout,
    numbered_tracks,
)
from geomcad.sheet.model import Sheet

ROOT = Path(__file__).resolve().parent
TRACKS = ROOT / "linkages_tracks"
FILES = {
    **{p.stem: p for p in sorted(TRACKS.glob("*.toml"))},
    **{n: ROOT.parent / "examples" / f"{n}.toml" for n in ("four-bar", "rocking-slider")},
    "crank_rocker_mload": ROOT / "linkages" / "crank_rocker_mload.toml",
}


def _solved(name: str) -> Solved:
    return solve(parse(tomllib.loads(FILES[name].read_text(encoding="utf-8"))))


def _drawn(s: Solved) -> tuple[Sheet, _Mechanism]:
    sheet = kinematic_sheets(s, "x")[0][1]
    mech = next(pl.view for pl in layout(s).sized[0].layout if isinstance(pl.view, _Mechanism))
    assert isinstance(mech, _Mechanism)
    return sheet, mech


def _numbers(sheet: Sheet, mech: _Mechanism) -> list[tuple[str, str, tuple[float, float]]]:
    """Every single position number on the scheme: (its track, its text, its point)."""
    out = []
    for t, at in sheet.anchors:
        if t.role != "label" or not t.text.isdigit() or t.height != NUMBER_H:
            continue
        name = next((k for k, pts in mech.tracks.items()
                     if any(math.dist(at, q) < 1e-6 for q in pts)), None)  # fmt: skip
        if name is not None:
            out.append((name, t.text, at))
    return out


def test_a_centre_of_mass_alone_is_not_numbered() -> None:
    """S2 and S3 are centres of mass and nothing more: not numbered; the coupler point K and
    the joints are; where the centre is the output (the kulisa's S3) it is numbered."""
    s = _solved("rocker_centres")
    assert numbered_tracks(s.linkage) == ("A", "B", "K")
    sheet, mech = _drawn(s)
    assert set(mech.tracks) == {"A", "B", "K"}
    assert {n for n, _, _ in _numbers(sheet, mech)} <= {"A", "B", "K"}
    assert numbered_tracks(_solved("rocking_kulisa_moment").linkage) == ("A", "S3")


@pytest.mark.parametrize(
    "name", ["rocking_kulisa_moment", "rocker_centres", "four-bar", "crank_rocker_mload"]
)
def test_a_position_number_stands_nearer_its_own_point_than_another_track(name: str) -> None:
    """Each number's box is nearer its own point, by TRACK_MARGIN_MM, than any point or number
    of another track (review 4's rocking kulisa once set the crank circle's "9" beside S3's)."""
    s = _solved(name)
    sheet, mech = _drawn(s)
    nums = _numbers(sheet, mech)
    assert len(nums) >= 10
    boxes = {(n, txt, at): _text_box(t) for t, at in sheet.anchors for n, txt, a2 in nums
             if a2 == at and t.text == txt and t.height == NUMBER_H}  # fmt: skip
    rows = [(k, b) for k, bs in mech.rows.items() for b in bs]
    for (name_, txt, at), b in boxes.items():
        own = L._to_box(at, b)
        foreign = [L._to_box(q, b) for k, pts in mech.tracks.items() if k != name_ for q in pts
                   if math.dist(q, at) >= SHARE_MM]  # fmt: skip
        foreign += [L._gap(b, c) for (k, _, _), c in boxes.items() if k != name_]
        foreign += [L._gap(b, c) for k, c in rows if k != name_]
        assert min(foreign, default=math.inf) >= own + TRACK_MARGIN_MM - 1e-9, (name_, txt)


@pytest.mark.parametrize("name", ["rocking-slider", "crank_rocker_mload", "rocker_centres"])
def test_a_links_number_stands_off_a_column_of_numbers(name: str) -> None:
    """A link's number keeps LINK_CLEAR_MM from every position's number, LINK_ALONG times that
    in a row beside it or in a column over it (a vertical guide's numbers: the sixbar's "5"
    once stood between D's "4" and "5")."""
    s = _solved(name)
    sheet, mech = _drawn(s)
    area = next(pl.box for pl in layout(s).sized[0].layout if pl.view is mech)
    texts = [t for t in sheet.texts() if t.role == "label" and t.text.isdigit()
             and area[0] <= t.at[0] <= area[2] and area[1] <= t.at[1] <= area[3]]  # fmt: skip
    links = [t for t in texts if t.height > NUMBER_H]
    numbers = [_text_box(t) for t in texts if t.height == NUMBER_H]
    assert links and numbers
    for lt in links:
        b = _text_box(lt)
        assert all(L._apart(b, n) >= L.LINK_CLEAR_MM - 1e-9 for n in numbers), lt.text


def test_an_offset_slots_arm_is_drawn_in_the_principal_position_only() -> None:
    """The thin positions' slots start at their feet on the offset's circle, with no arm from
    the pivot (twelve arms once melted into one blot at C); the principal position keeps its
    arm C–foot."""
    from geomcad.sheet.linkage import link_bodies

    s = _solved("rocking_kulisa_moment")
    lk = s.linkage
    C = lk.frame["C"]
    (g,) = lk.groups
    e = abs(g.offset)
    assert e > 0.0
    for P in s.drawn:
        (thin,) = link_bodies(lk, P, axes=True)["3"]
        assert min(q.dist(C) for q in thin.points) >= e * (1.0 - 1e-9)  # from its foot on
        assert any(abs(q.dist(C) - e) <= 1e-9 * e for q in thin.points)
        # (then S3, 0,02 m beside the slot, on its arm square to it: review 17)
        main, *_ = link_bodies(lk, P)["3"]
        assert any(q.dist(C) <= 1e-12 for q in main.points)  # the arm from the pivot
