"""Review 7's drafting rules (issue 27): a crank's detail view draws nothing beyond its own
circle (the oscillator's detail once drew its coupler stubs 1.9 crank lengths out, towards the
plans column); the numbers of one track never stand among another's."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import (
    NUMBER_H,
    TRACK_MARGIN_MM,
    _CrankDetail,
    _gap,
    _Mechanism,
    _text_box,
    detail_letter,
    kinematic_sheets,
    layout,
)
from geomcad.sheet.model import ArcItem, CircleItem, Polyline
from geomcad.sheet.views import detail_letters

ROOT = Path(__file__).resolve().parent
EXAMPLES = ROOT.parent / "examples"
#: Files whose kinematic sheet draws the crank on a detail view.
DETAILED = {
    "sixbar_oscillator": ROOT / "linkages_layout" / "sixbar_oscillator.toml",
    "crusher": EXAMPLES / "crusher.toml",
    "vertical_yoke_rocker": ROOT / "linkages_drafting" / "vertical_yoke_rocker.toml",
}
#: The detail's circle reaches no further than this many crank lengths round the pivot: it
#: holds the crank circle and its numbers, not the links beyond.
MOST_REACH = 1.5


@pytest.mark.parametrize("name", sorted(DETAILED))
def test_a_crank_detail_ends_at_its_circle(name: str) -> None:
    """Every line the crank's detail draws lies inside the detail's thin circle round the
    pivot, which reaches at most MOST_REACH crank lengths: the stubs of the links at the
    crank's joint end on it."""
    s = solve(parse(tomllib.loads(DETAILED[name].read_text(encoding="utf-8"))))
    lk = s.linkage
    sheet = kinematic_sheets(s, "x")[0][1]
    pls = [pl for pl in layout(s).sized[0].layout if isinstance(pl.view, _CrankDetail)]
    assert pls, "no crank detail on this file's sheet"
    pl = pls[0]
    assert pl.viewport is not None and pl.scale is not None
    c = pl.viewport.p(lk.frame[lk.pivot])
    crank = pl.scale.mm(lk.length)
    x0, y0, x1, y1 = pl.inner

    def within(q: tuple[float, float]) -> bool:
        return x0 <= q[0] <= x1 and y0 <= q[1] <= y1

    rings = [it.r for it in sheet.items if isinstance(it, CircleItem) and it.role == "thin"
             and math.dist(it.c, c) < 1e-6 and it.r > crank]  # fmt: skip
    assert rings, "the detail draws no circle of its own round the crank"
    r = max(rings)
    assert r <= MOST_REACH * crank + 1e-6
    lines = [it for it in sheet.items if isinstance(it, Polyline)
             and any(within(q) for q in it.points)]  # fmt: skip
    assert len(lines) >= len(s.drawn)  # the crank in its positions at least
    for it in lines:
        for q in it.points:
            assert math.dist(q, c) <= r + 0.05, (it.role, q, math.dist(q, c), r)


#: Files whose mechanism numbers several tracks near each other: review 7's yoke (its point E
#: on the guide through the crank's pivot), the six-bars, the slotted levers, the shaper.
TRACKED = {
    **{n: ROOT / "linkages_layout" / f"{n}.toml" for n in (
        "yoke_pump_double_slider", "sixbar_coupler_slider", "tangent_rocking_slider",
        "v_compressor", "sixbar_oscillator",
    )},
    **{n: EXAMPLES / f"{n}.toml" for n in ("shaper", "scotch-yoke", "rocking-slider")},
    "vertical_yoke_rocker": ROOT / "linkages_drafting" / "vertical_yoke_rocker.toml",
}  # fmt: skip


def _number_owners(name: str) -> list[tuple[str, tuple[float, float, float, float]]]:
    """Each position number on the mechanism's view with the track it numbers (by its anchor,
    or by its row's box) and its box."""
    s = solve(parse(tomllib.loads(TRACKED[name].read_text(encoding="utf-8"))))
    sheet = kinematic_sheets(s, "x")[0][1]
    pl = next(pl for pl in layout(s).sized[0].layout if isinstance(pl.view, _Mechanism))
    anchors = {id(t): at for t, at in sheet.anchors}
    a = pl.box
    out = []
    for t in sheet.texts():
        if not (t.role == "label" and t.text.isdigit() and t.height == NUMBER_H):
            continue
        if not (a[0] <= t.at[0] <= a[2] and a[1] <= t.at[1] <= a[3]):
            continue
        p = anchors.get(id(t))
        if p is not None:
            owner = next(k for k, pts in pl.view.tracks.items()
                         if any(math.dist(p, q) < 1e-6 for q in pts))  # fmt: skip
        else:
            rows = pl.view.rows.items()
            x, y = t.at
            owner = next(k for k, bs in rows for b in bs
                         if abs(b[0] - x) < 1e-6 and b[1] <= y <= b[3] + 1.0)  # fmt: skip
        out.append((owner, _text_box(t)))
    return out


@pytest.mark.parametrize("name", sorted(TRACKED))
def test_no_number_stands_among_another_tracks_numbers(name: str) -> None:
    """No position's number stands within TRACK_MARGIN_MM of a number of another track (the
    yoke's E numbered "9 3", "4 8", "5 7 6" inside the crank circle, its "1" 1.3 mm from the
    crank's "1"): a degenerate track inside another's numbering zone is left unnumbered where
    its link is numbered at another point."""
    owned = _number_owners(name)
    assert len({k for k, _ in owned}) >= 2
    for i, (k, b) in enumerate(owned):
        for m, c in owned[i + 1 :]:
            if k != m:
                assert _gap(b, c) >= TRACK_MARGIN_MM, (k, m, b, c)


@pytest.mark.parametrize(
    ("name", "numbered"),
    [("yoke_pump_double_slider", {"A", "F", "D"}), ("vertical_yoke_rocker", {"F", "B"})],
)
def test_a_degenerate_track_in_another_zone_is_not_numbered(name: str, numbered: set[str]) -> None:
    """A yoke's E (on its guide through the crank's pivot, inside the crank circle, numbered
    there or on the crank's detail) is dotted but not numbered; its link's positions are
    numbered at the arm's end F."""
    owned = {k for k, _ in _number_owners(name)}
    assert "E" not in owned and numbered <= owned


def test_a_detail_letter_never_reads_as_a_points_letter() -> None:
    """A detail is never lettered with a Cyrillic capital read as a point's Latin one: drawn
    alike (А–A, В–B, …) or differing by a stroke and read by the same name (Б–B, Д–D; review
    7: tangent's inset "Д" beside its point "D")."""
    letters = detail_letters(["A", "B", "D", "O"])
    first = [next(letters) for _ in range(6)]
    assert not {"А", "Б", "В", "Д", "О"} & {c[0] for c in first}
    s = solve(parse(tomllib.loads(TRACKED["sixbar_coupler_slider"].read_text(encoding="utf-8"))))
    assert detail_letter(s) not in ("А", "Б", "В", "Д")  # its points A, B, C, D, E


def test_the_tangent_forces_sheet_letters_no_detail_as_its_point_d() -> None:
    """On tangent_rocking_slider's forces sheet (a point D, insets lettered), no "Д"."""
    from geomcad.sheet.linkage_forces import force_sheets

    s = solve(parse(tomllib.loads(TRACKED["tangent_rocking_slider"].read_text(encoding="utf-8"))))
    assert "D" in s.drawn[0].pos
    texts = [t.text for _, sh in force_sheets(s, "x") for t in sh.texts()]
    assert "D" in texts
    assert not [t for t in texts if t == "Д" or t.startswith("Д ")]  # a detail's mark or title


def _on_arc(it: ArcItem, q: tuple[float, float]) -> bool:
    """Whether the paper direction from the arc's centre to ``q`` falls within the arc."""
    a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
    a = math.atan2(q[1] - it.c[1], q[0] - it.c[0])
    # ArcItem.sweep > 0 turns clockwise on the paper (y down: the angle grows)
    t = (a - a0) % (2.0 * math.pi) if it.sweep > 0 else (a0 - a) % (2.0 * math.pi)
    return t <= abs(it.sweep)


@pytest.mark.parametrize("name", ["sixbar_coupler_slider", "yoke_pump_double_slider"])
def test_m_bal_arc_never_crosses_the_crank(name: str) -> None:
    """On the forces sheet, M_ур's arc about the crank's pivot leaves its gap over the crank
    (review 7: its 250° arc crossed the crank and its number "1" on yoke's and sixbar's)."""
    from geomcad.sheet.linkage_forces import M_BAL_MM, force_sheets

    s = solve(parse(tomllib.loads(TRACKED[name].read_text(encoding="utf-8"))))
    sheet = dict(force_sheets(s, "x"))["forces"]
    arcs = [it for it in sheet.items if isinstance(it, ArcItem) and it.role == "result"
            and abs(it.r - M_BAL_MM) < 1e-6]  # fmt: skip
    assert arcs
    checked = 0
    for arc in arcs:
        for it in sheet.items:
            if not (isinstance(it, Polyline) and it.role == "link" and len(it.points) == 2):
                continue
            a, b = it.points
            if math.dist(a, arc.c) > 1e-3:
                a, b = b, a
            if math.dist(a, arc.c) > 1e-3 or math.dist(a, b) <= arc.r:
                continue
            checked += 1
            assert not _on_arc(arc, b), (arc, it.points)
    assert checked >= len(arcs)
