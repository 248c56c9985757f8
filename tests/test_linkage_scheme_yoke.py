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
from geomcad.sheet.linkage import _principal, kinematic_sheets, layout
from geomcad.sheet.model import Polyline, TextItem

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
    # link 3's slot: a main line through A along the slot, both ways past the block
    lines = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "link"]
    through = [
        it
        for it in lines
        if not it.closed
        and _near(a, it.points, 0.5)
        and any(
            abs((p[0] - a[0]) * slot[1] - (p[1] - a[1]) * slot[0]) < 0.5 and math.dist(p, a) > 6.0
            for p in it.points
        )
    ]
    assert through, "the yoke's slot through block 2 is not drawn"
    # no frame hatching at the block: the yoke's guide on the frame is elsewhere on its rod
    ground = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "ground"]
    assert not any(_near(a, it.points, 8.0) for it in ground), "block 2 sits in a frame guide"
    assert ground, "the yoke's guide on the frame is not drawn"
    # E lettered (with A: they coincide)
    texts = [
        "".join(r.text for r in it.runs)
        for it in sheet.items
        if isinstance(it, TextItem) and math.dist((it.at[0] + it.width / 2.0, it.at[1]), a) < 10.0
    ]
    assert any("E" in t.split(", ") for t in texts), texts
