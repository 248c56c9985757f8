"""Review 9's drafting (issue 27, fixes 3 and 9): the loads of a loaded mechanism are drawn off
the link outlines (an arrow slid along its line of action, or beside it, never along a link nor
tied to its point by a line of action that runs along one), and ω1's arc crosses no link."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from test_free_bodies import _dist, _lines

from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.loads import AT_POINT_MM
from geomcad.sheet.model import XY, Polyline

ROOT = Path(__file__).resolve().parent
FILES = {
    p.stem: p
    for p in [
        *(ROOT.parent / "examples").glob("*.toml"),
        *(ROOT / "linkages_layout").glob("*.toml"),
        *(ROOT / "linkages_review9").glob("*.toml"),
    ]
    if "[drive]" in p.read_text("utf-8")
}
FORCES = sorted(k for k, p in FILES.items() if "mass" in p.read_text("utf-8"))

#: A line that runs with an arrow (within 15°) this near it reads as the arrow drawn along it …
ALONG_GAP_MM = 2.5
ALONG_DEG = 15.0
#: … and an arrow with its line of action back to its point may do so over this much (mm).
ALONG_MAX_MM = 3.0
#: ω1's arc keeps this far (mm) between its centre line and a link's: half a link's 0.7 mm line,
#: half the arc's and 0.5 mm of paper.
ARC_GAP_MM = 1.0


def _linkage(name: str) -> Any:
    return parse(tomllib.loads(FILES[name].read_text("utf-8")))


def along_links(p: XY, tail: XY, tip: XY, links: list[tuple[XY, XY]]) -> float:
    """How much (mm) of an arrow (tail → tip) for a load at sheet point ``p``, with the thin line
    of action from its nearer end back to ``p``, runs within ALONG_GAP_MM of a link's line that
    runs within ALONG_DEG of it; the part within AT_POINT_MM of ``p`` (the joint) aside."""
    length = math.dist(tail, tip)
    u = np.subtract(tip, tail) / length
    s = float(np.dot(np.subtract(p, tail), u))
    lo, hi = min(0.0, s), max(length, s)
    t = np.arange(lo, hi, 0.25) + 0.125
    q = np.asarray(tail) + t[:, None] * u
    q = q[np.hypot(*(q - np.asarray(p)).T) > AT_POINT_MM]
    par = [
        (a, b)
        for a, b in links
        if math.dist(a, b) > 0.0
        and abs(u[0] * (b[1] - a[1]) - u[1] * (b[0] - a[0])) / math.dist(a, b)
        <= math.sin(math.radians(ALONG_DEG))
    ]
    return float(np.count_nonzero(_dist(q, par) < ALONG_GAP_MM) * 0.25) if len(q) else 0.0


def test_the_measure_sees_an_arrow_along_a_link_and_one_tied_along_it() -> None:
    link = [((0.0, 0.0), (40.0, 0.0))]
    assert along_links((20.0, 0.0), (20.0, 0.0), (30.0, 0.0), link) > 5.0  # on the link
    assert along_links((20.0, 0.0), (20.0, 2.0), (30.0, 2.0), link) > 5.0  # 2 mm beside it
    assert along_links((20.0, 0.0), (45.0, 0.0), (60.0, 0.0), link) > 5.0  # tied along it
    assert along_links((20.0, 0.0), (20.0, 0.0), (20.0, 15.0), link) == 0.0  # across it
    assert along_links((40.0, 0.0), (45.0, 0.0), (60.0, 0.0), link) < 1.0  # past its end


def _loaded(name: str, monkeypatch: pytest.MonkeyPatch) -> tuple[Any, list[Any]]:
    """The forces sheet of ``name`` and the loads its loaded mechanism drew: (label, sheet
    point of application, tail, tip)."""
    sheet, drawn, _ = _loaded_in(name, monkeypatch)
    return sheet, drawn


def _loaded_in(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> tuple[Any, list[Any], tuple[float, float, float, float]]:
    """:func:`_loaded` and the field (sheet mm) the loaded mechanism's arrows are drawn in
    (``linkage_forces._load_field``)."""
    from geomcad.sheet import linkage_forces as lf

    rec: list[Any] = []
    fields: list[tuple[float, float, float, float]] = []
    force, links = lf.force, lf._Loaded.links
    on: list[bool] = [False]

    def rec_force(v: Any, at: Any, F: Any, *a: Any, **kw: Any) -> Any:
        out = force(v, at, F, *a, **kw)
        if on[0] and out is not None:
            rec.append((a[1] if len(a) > 1 else "", v.p(at), *out))
        return out

    def rec_links(self: Any, d: Any, at: Any) -> None:
        rec.clear()
        fields.append(lf._load_field(at))
        on[0] = True
        links(self, d, at)
        on[0] = False

    monkeypatch.setattr(lf, "force", rec_force)
    monkeypatch.setattr(lf._Loaded, "links", rec_links)
    sheet = lf.force_sheets(solve(_linkage(name)))[0][1]
    return sheet, list(rec), fields[-1]


def places(p: XY, tail: XY, tip: XY, field: tuple[float, float, float, float]) -> list[Any]:
    """Every place (tail, tip) of the arrow tail → tip on its line of action through ``p``
    (slid by 0.5 mm steps, up to 300 mm past ``p`` either way) that keeps inside ``field``."""
    length = math.dist(tail, tip)
    u = np.subtract(tip, tail) / length
    x0, y0, x1, y1 = field
    out = []
    for s in np.arange(-length - 300.0, 300.0, 0.5):
        a = np.asarray(p) + s * u
        b = a + length * u
        if all(x0 <= q[0] <= x1 and y0 <= q[1] <= y1 for q in (a, b)):
            out.append(((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))))
    return out


def blocks(items: list[Any]) -> list[Any]:
    """The filled shapes of ``items`` that are no arrowheads (sliders' blocks), as polygons."""
    import shapely.geometry as sg

    solid = [it for it in items if isinstance(it, Polyline) and it.fill and it.closed]
    return [sg.Polygon(it.points) for it in solid if len(it.points) > 3]


def in_block(p: XY, tail: XY, tip: XY, solids: list[Any]) -> bool:
    """Whether the arrow tail → tip enters one of ``solids`` away from its point ``p``
    (beyond AT_POINT_MM of it): it would be drawn through a slider's block."""
    import shapely.geometry as sg

    length = math.dist(tail, tip)
    u = np.subtract(tip, tail) / length
    q = np.asarray(tail) + (np.arange(0.0, length, 0.25) + 0.125)[:, None] * u
    q = q[np.hypot(*(q - np.asarray(p)).T) > AT_POINT_MM]
    return any(b.contains(sg.Point(x, y)) for b in solids for x, y in q)


def forced(
    p: XY, tail: XY, tip: XY, field: Any, lines: list[tuple[XY, XY]], solids: Any = ()
) -> tuple[bool, bool]:
    """Whether the two rules cannot both hold for a load at ``p`` drawn tail → tip: (every
    place of it on its line of action inside ``field`` runs, arrow and line of action back to
    ``p``, along one of ``lines`` over more than ALONG_MAX_MM, or through one of ``solids``;
    every place runs along them or through one even without its line of action, the arrow
    itself)."""
    spots = [(a, b) for a, b in places(p, tail, tip, field) if not in_block(p, a, b, list(solids))]
    tied = all(along_links(p, a, b, lines) > ALONG_MAX_MM for a, b in spots)
    bare = all(along_links(a, a, b, lines) > ALONG_MAX_MM for a, b in spots)
    return tied, bare


@pytest.mark.parametrize("name", FORCES)
def test_the_loads_of_the_loaded_mechanism_keep_off_the_links(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """No load arrow of the loaded mechanism, with its line of action back to its point, runs
    along a link outline (within ALONG_GAP_MM, within ALONG_DEG) over more than ALONG_MAX_MM
    (review 9: the compressor's Φ1 tied along its crank and slid 25 mm past A, Φ3 2 mm under
    its rod MB).

    Since review 14 a load is drawn on its own line of action (never on a parallel beside it
    with an elbow: the walkbeam's F_D 10 mm under its guide). One exemption, measured
    (:func:`forced`): a load whose every place on its line of action inside the view's field
    runs, with its line of action back to its point, along a link, a hatch line or another
    load's arrow over more than ALONG_MAX_MM, or through a slider's block — its line of
    action is its link's (a crank's centripetal Φ₁ on OA, a slider's load on its rod) or
    crosses a link at its point at less than ALONG_DEG (a weight on a near-vertical link
    through its centre of mass) — may run along a link by its line of action; its arrow
    itself must still keep off the links (no more than ALONG_MAX_MM on one) wherever some
    place inside the field allows that (slid along its line past the link's end, its thin line
    of action under the link)."""
    sheet, drawn, field = _loaded_in(name, monkeypatch)
    links = _lines(sheet.items, {"link"})
    ground = _lines(sheet.items, {"ground"})
    solids = blocks(sheet.items)
    assert drawn
    bad = []
    for i, (lab, p, tail, tip) in enumerate(drawn):
        m = along_links(p, tail, tip, links)
        if m <= ALONG_MAX_MM:
            continue
        others = [(a, b) for j, (_, _, a, b) in enumerate(drawn) if j != i]
        tied, bare = forced(p, tail, tip, field, links + ground + others, solids)
        if tied and (bare or along_links(tail, tail, tip, links) <= ALONG_MAX_MM):
            continue
        bad.append((lab, round(m, 1)))
    assert not bad, (name, bad)


def test_forced_sees_a_load_along_its_own_link() -> None:
    """The exemption's measure: a load on the line of its link, the link across the whole
    field, is forced (every place runs along it); beside the link, or with room past the
    link's end in the field, it is not."""
    link = [((0.0, 0.0), (100.0, 0.0))]
    field = (0.0, -50.0, 100.0, 50.0)
    assert forced((50.0, 0.0), (50.0, 0.0), (60.0, 0.0), field, link) == (True, True)
    assert forced((50.0, 10.0), (50.0, 10.0), (60.0, 10.0), field, link) == (False, False)
    wide = (0.0, -50.0, 150.0, 50.0)  # room past the link's end: the arrow itself off it
    assert forced((50.0, 0.0), (50.0, 0.0), (60.0, 0.0), wide, link) == (True, False)
    # a link across the load's line at 5 degrees through its point: forced, the arrow free
    slant = [
        ((0.0, -50.0 * math.tan(math.radians(5.0))), (100.0, 50.0 * math.tan(math.radians(5.0))))
    ]
    assert forced((50.0, 0.0), (50.0, 0.0), (60.0, 0.0), field, slant) == (True, False)
    # room past the link's end, but through a block there: forced
    import shapely.geometry as sg

    block = [sg.box(100.0, -5.0, 150.0, 5.0)]
    assert forced((50.0, 0.0), (50.0, 0.0), (60.0, 0.0), wide, link, block) == (True, True)


def _omega_arcs(sheet_of: Any, monkeypatch: pytest.MonkeyPatch) -> tuple[Any, list[Any]]:
    from geomcad.sheet.drawing import Viewport

    arcs: list[Any] = []
    turn = Viewport.turn

    def rec_turn(
        v: Any, centre: Any, sense: float, start: float, markup: str = "",
        r_mm: float = 9.0, sweep_deg: float = 100.0, *a: Any, **kw: Any,
    ) -> None:  # fmt: skip
        if markup == "ω_1":
            a0 = math.radians(start)
            a1 = a0 + math.copysign(math.radians(sweep_deg), sense)
            arcs.append((v.sheet, v.p(centre), r_mm, min(a0, a1), max(a0, a1)))
        turn(v, centre, sense, start, markup, r_mm, sweep_deg, *a, **kw)

    monkeypatch.setattr(Viewport, "turn", rec_turn)
    return sheet_of(), arcs


@pytest.mark.parametrize("name", sorted(FILES))
def test_omega_arcs_cross_no_link(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """ω1's arc on every mechanism view (the kinematic sheet's and the loaded mechanism's)
    keeps ARC_GAP_MM between its centre line and a link's (review 9: the compressor's ran
    0.44 mm from rod 2's: the inks of a 0.7 mm link and a thin arc touched)."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.linkage import kinematic_sheets

    def build() -> list[Any]:
        s = solve(_linkage(name))
        out = [sh for _, sh in kinematic_sheets(s)]
        if name in FORCES:
            out.append(lf.force_sheets(s)[0][1])
        return out

    _, arcs = _omega_arcs(build, monkeypatch)
    assert arcs
    for sheet, c, r, a0, a1 in arcs:
        a = np.linspace(a0, a1, 200)
        q = np.column_stack([c[0] + r * np.cos(a), c[1] - r * np.sin(a)])
        near = float(_dist(q, _lines(sheet.items, {"link"})).min())
        assert near >= ARC_GAP_MM, (name, c, r, near)


def test_a_caption_beside_grafa_26_stays_one_line_clear_of_it() -> None:
    """A view set just right of графа 26 whose caption is wider than the view's box prints it
    on one line under графа 26 where the blank paper there holds it, clear of графа 26's box
    (review 9: sine-plans' "Положение 0, φ1 = 180°" broke onto two lines beside it)."""
    from geomcad.sheet.frame import reserved
    from geomcad.sheet.linkage import kinematic_sheets
    from geomcad.sheet.placer import text_outline

    sheets = dict(kinematic_sheets(solve(_linkage("sine_crosshead_rocker"))))
    sheet = sheets["plans"]
    texts = [it for it in sheet.items if getattr(it, "runs", None) and it.angle == 0.0]
    captions = [t.text for t in texts if t.text.startswith(WORDS_POSITION)]
    assert len(captions) >= 12
    assert all("φ" in c for c in captions), captions  # none broken after "Положение"
    g26 = reserved(sheet.width, sheet.height)[1]
    import shapely.geometry as sg

    box = sg.box(*g26)
    assert not any(text_outline(t).intersects(box) for t in texts), "a text over графа 26"


WORDS_POSITION = "Положение"
