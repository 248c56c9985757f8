"""Review 12's kinematic and plans sheets' crowding (issue 27, fix-list item 5).

- A yoke's rod (the yarn traverse's guide bar 5) was drawn ≈55 mm past the end of its hatched
  guide: its guide now covers the rod's end in every position (GUIDE_HOLD).
- Position numbers stacked ("4 3", "2 5 1" on the sewing machine's E and M, "6 7 5 8" on the
  yarn traverse's E) and tangled with their leaders (the bloom shear's S5): every number of the
  mechanism view keeps NUMBER_APART_MM from every other and no line runs through it.
- The slotter's s-diagram drawn 26 mm high at μ_s = 0,01 м/мм in a 44 mm room (30 mm empty
  under it): the output's diagrams share their column by their curves (fill_diagrams), each
  curve at least FILL_SHARE of its room, none drawn smaller than the layout gave it.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad import tol
from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.lang import language
from geomcad.sheet.linkage import (
    GUIDE_HOLD,
    INK_GROW_MM,
    NUMBER_APART_MM,
    NUMBER_H,
    _arranged,
    _CrankDetail,
    _gap,
    _Ink,
    _Mechanism,
    _OutputDiagram,
    fill_diagrams,
    kinematic_sheets,
    link_bodies,
    yoke,
)
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).parent
YOKED = [
    p
    for p in [
        ROOT / "linkages_review11" / "yarn_guide_traverse.toml",
        *sorted((ROOT / "linkages_layout").glob("*.toml")),
        *sorted((ROOT / "linkages_review12").glob("*.toml")),
    ]
    if '"PRP"' in p.read_text(encoding="utf-8")
]


def _solved(path: Path):  # type: ignore[no-untyped-def]
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("path", YOKED, ids=lambda p: p.stem)
def test_a_yoke_rod_ends_inside_its_guide_in_every_position(path: Path) -> None:
    """Every drawn position's rod of a PRP yoke ends on its hatched guide, and holds in it at
    least GUIDE_HOLD of the rod's travel (never barely touching its near end)."""
    s = _solved(path)
    lk = s.linkage
    groups = [g for g in lk.groups if g.kind == "PRP" and g.guide is not None]
    if not groups:
        pytest.skip("no yoke on a guide")
    for g in groups:
        assert g.guide is not None
        yk, d = yoke(lk, g), g.guide.direction
        g0, g1 = (yk.guide - d * yk.half).dot(d), (yk.guide + d * yk.half).dot(d)
        ends = []
        for P in s.drawn:
            rod = link_bodies(lk, P)[str(g.links[1])][0]
            end = max(rod.points, key=lambda q: abs((q - P.pos[g.joint]).dot(d)))
            t = end.dot(d)
            slack = tol.SAME_PLACE * lk.length
            assert g0 - slack <= t <= g1 + slack, (t, g0, g1)
            ends.append(t)
        travel = max(ends) - min(ends)
        hold = min(abs(t - (g0 if yk.rod > 0 else g1)) for t in ends)
        assert hold >= GUIDE_HOLD * travel - tol.SAME_PLACE * lk.length, (hold, travel)


CROWDED = [
    ROOT / "linkages_review12" / "needle_takeup_sewing.toml",
    ROOT / "linkages_review12" / "bloom_shear_swing_knife.toml",
    ROOT / "linkages_review11" / "yarn_guide_traverse.toml",
]


def _digits_box(t: TextItem) -> tuple[float, float, float, float]:
    """A number's ink: its advance width, from its baseline up its cap height (digits have no
    descent)."""
    return (t.at[0], t.at[1] - t.height, t.at[0] + t.width, t.at[1])


@pytest.mark.parametrize("path", CROWDED, ids=lambda p: p.stem)
def test_position_numbers_stand_apart_and_off_the_lines(path: Path) -> None:
    """On the mechanism view (and its crank's detail), no two position numbers nearer than
    NUMBER_APART_MM, and no line (a link, a path, a leader) within INK_GROW_MM of a number."""
    s = _solved(path)
    with language("ru"):
        _, lays = _arranged(s)
        sheet = kinematic_sheets(s)[0][1]
    views = [pl.box for pl in lays[0] if isinstance(pl.view, _Mechanism | _CrankDetail)]
    nums = [
        t
        for t in sheet.items
        if isinstance(t, TextItem)
        and t.role == "label"
        and t.text.isdigit()
        and abs(t.height - NUMBER_H) <= tol.SHEET_MM
        and any(b[0] <= t.at[0] <= b[2] and b[1] <= t.at[1] <= b[3] for b in views)
    ]
    assert len(nums) >= len(s.drawn)
    boxes = [_digits_box(t) for t in nums]
    near = [
        (nums[i].text, nums[j].text, round(_gap(boxes[i], boxes[j]), 2))
        for i in range(len(nums))
        for j in range(i + 1, len(nums))
        if _gap(boxes[i], boxes[j]) < NUMBER_APART_MM - tol.SHEET_MM
    ]
    assert not near, near
    ink = _Ink(sheet)
    on = [t.text for t, b in zip(nums, boxes, strict=True) if ink.crossed([b], INK_GROW_MM)]
    assert not on, on


DIAGRAMMED = [
    *sorted((ROOT / "linkages_review12").glob("*.toml")),
    ROOT / "linkages_review11" / "yarn_guide_traverse.toml",
    *sorted((ROOT / "linkages_layout").glob("*.toml")),
]
#: The least share of its plot's room an output diagram's curve fills (review 12's item 5).
FILL_SHARE = 0.6


def _curves(arranged) -> list[tuple[float, float]]:  # type: ignore[no-untyped-def]
    """Each output diagram's (curve's height, plot's room) in mm, top to bottom."""
    out = []
    for pl in sorted(
        (p for p in arranged if isinstance(p.view, _OutputDiagram)), key=lambda p: p.box[1]
    ):
        dg = pl.view
        w, h = pl.inner[2] - pl.inner[0], pl.inner[3] - pl.inner[1]
        _, ay = dg.axes(w, h)
        out.append((ay.mm(ay.hi - ay.lo), h - dg.BELOW - dg.ABOVE))
    return out


@pytest.mark.parametrize("path", DIAGRAMMED, ids=lambda p: p.stem)
def test_the_output_diagrams_fill_their_band(path: Path) -> None:
    """After fill_diagrams every output diagram's curve fills at least FILL_SHARE of its plot's
    room, none is drawn lower than the layout drew it, the column's band is kept (its top and
    bottom), and a second call changes nothing."""
    s = _solved(path)
    with language("ru"):
        _, lays = _arranged(s)
        placed = [p for p in lays[0] if isinstance(p.view, _OutputDiagram)]
        top, bottom = min(p.box[1] for p in placed), max(p.box[3] for p in placed)
        before = _curves(lays[0])
        fill_diagrams(lays[0])
        after = _curves(lays[0])
        fill_diagrams(lays[0])
        again = _curves(lays[0])
    for (c1, r1), (c2, r2) in zip(after, again, strict=True):
        assert c2 == pytest.approx(c1, abs=tol.LAYOUT_BEATEN_MM)
        assert r2 == pytest.approx(r1, abs=tol.LAYOUT_BEATEN_MM)
    placed = [p for p in lays[0] if isinstance(p.view, _OutputDiagram)]
    assert min(p.box[1] for p in placed) == pytest.approx(top, abs=tol.SHEET_MM)
    assert max(p.box[3] for p in placed) <= bottom + tol.LAYOUT_BEATEN_MM
    for (c0, _), (c1, room) in zip(before, after, strict=True):
        assert c1 >= c0 - tol.LAYOUT_BEATEN_MM
        assert c1 >= FILL_SHARE * room, (c1, room, after)
