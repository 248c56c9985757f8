"""A slider's guide that belongs to a moving link is drawn as that link: the scotch yoke's
link 3 (its slot through block 2, its rod in the frame's guide), never block 2 in a guide
hatched as the frame; the yoke's point E lettered where it coincides with A."""

from __future__ import annotations

import itertools
import math
import tomllib
from pathlib import Path

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import SLOT_HALF_MM, _principal, kinematic_sheets, layout
from geomcad.sheet.model import Polyline, TextItem
from geomcad.sheet.symbols import SLIDER_SIZE

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _yoke() -> Solved:
    data = tomllib.loads((EXAMPLES / "scotch-yoke.toml").read_text(encoding="utf-8"))
    return solve(parse(data))


def _near(q: tuple[float, float], pts: tuple[tuple[float, float], ...], mm: float) -> bool:
    """Whether a segment of the polyline ``pts`` passes within ``mm`` of ``q``."""
    for a, b in itertools.pairwise(pts):
        ab = (b[0] - a[0], b[1] - a[1])
        L2 = ab[0] ** 2 + ab[1] ** 2 or 1.0
        t = max(0.0, min(1.0, ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / L2))
        if math.dist(q, (a[0] + t * ab[0], a[1] + t * ab[1])) <= mm:
            return True
    return False


def test_the_yoke_is_drawn_as_its_link_and_the_frame_guide_clear_of_the_block() -> None:
    s = _yoke()
    P0, _ = _principal(s)
    A, E = P0.pos["A"], P0.pos["E"]
    assert A.dist(E) < 1e-9  # the file's principal position: block and yoke point coincide
    sheet = kinematic_sheets(s)[0][1]
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    a = v.p(A)
    slot = v.paper_dir(P0.slide[2])
    # link 3's slot drawn as a slot (GOST 2.770): a closed main-line outline round A, its two
    # sides along the slot either side of the block, both ways well past it
    half = SLOT_HALF_MM
    outlines = []
    for it in sheet.items:
        if not (isinstance(it, Polyline) and it.role == "link" and it.closed):
            continue
        along = [(p[0] - a[0]) * slot[0] + (p[1] - a[1]) * slot[1] for p in it.points]
        across = [(p[0] - a[0]) * slot[1] - (p[1] - a[1]) * slot[0] for p in it.points]
        if (
            min(along) < -6.0
            and max(along) > 6.0
            and all(abs(abs(c) - half) < 0.05 for c in across)
        ):
            outlines.append(it)
    assert outlines, "the yoke's slot through block 2 is not drawn as a slot"
    assert half > SLIDER_SIZE[1] / 2.0  # the block fits between the slot's sides
    # no single main line along the slot through the block (a slot is not one line)
    lines = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "link"]
    assert not [
        it
        for it in lines
        if not it.closed
        and _near(a, it.points, 0.5)
        and any(
            abs((p[0] - a[0]) * slot[1] - (p[1] - a[1]) * slot[0]) < 0.5 and math.dist(p, a) > 6.0
            for p in it.points
        )
    ], "the slot is drawn as one line"
    # no frame hatching at the block: the yoke's guide on the frame is elsewhere on its rod
    ground = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "ground"]
    assert not any(_near(a, it.points, 8.0) for it in ground), "block 2 sits in a frame guide"
    assert ground, "the yoke's guide on the frame is not drawn"
    # E lettered (with A: they coincide), beside the block and the slot (the yoke numbers its
    # positions on the guide in a row next to them)
    texts = [
        "".join(r.text for r in it.runs)
        for it in sheet.items
        if isinstance(it, TextItem) and math.dist((it.at[0] + it.width / 2.0, it.at[1]), a) < 12.0
    ]
    assert any("E" in t.split(", ") for t in texts), texts


def test_the_yokes_frame_guide_is_hatched_over_the_rods_travel() -> None:
    """The fixed guide the yoke's rod slides in is hatched (both sides) over at least the rod's
    travel along it (the span of E's positions), not a short bushing, and clear of the slot in
    every position."""
    s = _yoke()
    sheet = kinematic_sheets(s)[0][1]
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    d = v.paper_dir((1.0, 0.0))  # the file's guide: through O at 0°
    o = v.p((0.0, 0.0))
    es = [v.p(P.pos["E"]) for P in s.drawn]
    ts = [(q[0] - o[0]) * d[0] + (q[1] - o[1]) * d[1] for q in es]
    travel = max(ts) - min(ts)
    assert travel > 20.0
    ground = [  # the frame's hatching less the crank's support at O
        it
        for it in sheet.items
        if isinstance(it, Polyline)
        and it.role == "ground"
        and all(math.dist(p, o) > 10.0 for p in it.points)
    ]
    spans: dict[int, list[float]] = {}
    for it in ground:
        for p in it.points:
            off = (p[0] - o[0]) * d[1] - (p[1] - o[1]) * d[0]
            if 2.0 < abs(off) < 8.0:  # the hatched lines either side of the rod
                spans.setdefault(1 if off > 0 else -1, []).append(
                    (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1]
                )
    assert set(spans) == {1, -1}, "the guide is not hatched on both sides"
    for side in spans.values():
        assert max(side) - min(side) >= travel, (max(side) - min(side), travel)
        # clear of the yoke's slot: the guide ends short of the leftmost slot position
        assert max(side) < min(ts) - SLOT_HALF_MM or min(side) > max(ts) + SLOT_HALF_MM
