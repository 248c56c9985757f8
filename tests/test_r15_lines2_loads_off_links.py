"""Round 15 (lines2): review 14's loads on their lines of action, with review 9's rule that an
arrow keeps off the links. A load along its own link (a crank's centripetal Φ₁ on OA, a
slider's load along its rod, a weight on a near-vertical link) is drawn on its own line of
action, never on a parallel beside it with an elbow, and never under the link's ink: slid
along its line past the link's end, or arriving at a slider's block from the free side of its
guide's axis (the view's top margin under its caption is room for it).

The loaded mechanisms of four files whose loads lie along their links are built once: every
arrow lies on its line of action through its point (within 0,1 mm) and its arrow itself runs
along no link (review 9's measure) wherever some place on that line inside the view's field
allows it. On main these loads were drawn beside their lines (an elbow back to the point),
and on round 14's branch some lay on their links (v_compressor's Φ₁ on its crank,
tangent_rocking_slider's F_D on its rod for 20 mm)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from test_drafting_round9 import ALONG_MAX_MM, _loaded_in, along_links, blocks, forced
from test_free_bodies import _bodies, _dist, _lines

NAMES = ["v_compressor", "rocking_cylinder_rocker", "tangent_rocking_slider", "crusher"]

#: A load's arrow this near (mm) the line through its point (its line of action) is on it.
ON_LINE_MM = 0.1


@pytest.fixture(scope="module")
def loaded() -> dict[str, Any]:
    """Each file's forces sheet, its loaded mechanism's loads (label, point, tail, tip) and
    the field of their arrows, built once."""
    mp = pytest.MonkeyPatch()
    try:
        return {n: _loaded_in(n, mp) for n in NAMES}
    finally:
        mp.undo()


def _off_line(p: Any, tail: Any, tip: Any) -> float:
    """How far (mm) ``p`` lies from the line through the arrow tail → tip."""
    length = math.dist(tail, tip)
    ux, uy = (tip[0] - tail[0]) / length, (tip[1] - tail[1]) / length
    return abs((p[0] - tail[0]) * uy - (p[1] - tail[1]) * ux)


@pytest.mark.parametrize("name", NAMES)
def test_every_load_is_on_its_line_of_action(name: str, loaded: dict[str, Any]) -> None:
    """No elbow, no parallel offset: each arrow's line passes through its point."""
    _, drawn, _ = loaded[name]
    assert drawn
    off = [(lab, round(_off_line(p, a, b), 2)) for lab, p, a, b in drawn
           if _off_line(p, a, b) > ON_LINE_MM]  # fmt: skip
    assert not off, (name, off)


@pytest.mark.parametrize("name", NAMES)
def test_no_load_arrow_lies_on_a_link_where_its_line_has_room(
    name: str, loaded: dict[str, Any]
) -> None:
    """The arrow itself (its line of action back to its point aside) runs along a link by no
    more than ALONG_MAX_MM wherever some place of it on its line of action inside the view's
    field, clear of the other arrows, the hatches and the blocks, does so (round 14's branch:
    v_compressor's Φ₁ 5,8 mm on its crank, rocking_cylinder_rocker's Φ₁ 5,8 mm on its crank,
    tangent_rocking_slider's F_D 20,5 mm on its rod, the crusher's G₂ 10 mm on its link)."""
    sheet, drawn, field = loaded[name]
    links = _lines(sheet.items, {"link"})
    ground = _lines(sheet.items, {"ground"})
    solids = blocks(sheet.items)
    bad = []
    for i, (lab, p, tail, tip) in enumerate(drawn):
        on = along_links(tail, tail, tip, links)
        if on <= ALONG_MAX_MM:
            continue
        others = [(a, b) for j, (_, _, a, b) in enumerate(drawn) if j != i]
        _, bare = forced(p, tail, tip, field, links + ground + others, solids)
        if not bare:
            bad.append((lab, round(on, 1)))
    assert not bad, (name, bad)


def test_a_slider_load_arrives_at_its_block_from_the_free_side_of_its_guide(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The piston compressor's F_B (test_free_bodies.COMPRESSOR: the rod almost along the
    cylinder's axis) on the free body of group (2, 3): on the guide's axis through B and off
    the rod — it arrives at the block's face from above, in the view's top margin under its
    caption (main: 5 mm beside the axis with an elbow; round 14's branch: 20 mm down the
    rod)."""
    _, bodies = _bodies("compressor", monkeypatch)
    (group,) = [b for b in bodies if tuple(b["gf"].links) == (2, 3)]
    b_pt = group["joints"]["B"]
    links = _lines(group["items"], {"link", "joint"})
    found = 0
    for tail, tip in group["vectors"]:
        if _off_line(b_pt, tail, tip) > ON_LINE_MM or abs(tip[0] - tail[0]) > 0.01:
            continue
        found += 1
        import numpy as np

        length = math.dist(tail, tip)
        t = np.arange(0.0, length, 0.1)
        u = np.subtract(tip, tail) / length
        q = np.asarray(tail) + t[:, None] * u
        far = np.hypot(*(q - np.asarray(b_pt)).T) > 2.0
        on_link = (_dist(q, links) < 0.8) & far
        assert on_link.sum() * 0.1 <= 2.0, (tail, tip)
        assert max(tail[1], tip[1]) <= b_pt[1], (tail, tip, b_pt)  # above B: the free side
    assert found == 1, group["vectors"]


def test_the_load_field_reaches_over_the_drawing_under_the_caption() -> None:
    """The loads' field (:func:`~geomcad.sheet.linkage_forces._load_field`) is the arrows'
    field with the view's top margin, LABEL_ROOM_MM under the caption kept for a label."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.compose import Placed

    class _V:
        margin = 24.0

    at = Placed(_V(), (10.0, 20.0, 200.0, 300.0), (34.0, 56.75, 176.0, 276.0), None)  # type: ignore[arg-type]
    x0, y0, x1, y1 = lf._load_field(at)
    assert (x0, x1, y1) == (10.0, 200.0, 300.0)
    assert y0 == pytest.approx(56.75 - 24.0 + lf.LABEL_ROOM_MM)
    assert lf._field(at)[1] == 56.75
