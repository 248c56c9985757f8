"""Review 11's kinematic sheets (issue 27, fix-list item 7).

- The yarn traverse's guide bar (a PRP yoke, its block all below the horizontal guide) was drawn
  as far above the guide as its block travels below it: the slot runs over the block's travel
  and on to the guide, never past them.
- Its s, v, a diagrams drew their curves 20–30 mm high: each output diagram's box is at least
  as high as draws its curve DIAGRAM_SPAN_MM high at its rounded μ (:func:`span_room`), where
  the crank's rule does not need the room.
- The kulisa's mechanism at 1:4 on an A1 half blank, where the sheet fits it at 1:2,5: after
  the search the mechanism is tried at the next finer GOST steps (FINER_STEPS).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad import tol
from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.graph import Axis, nice_step_below
from geomcad.sheet.linkage import (
    CRANK_MM,
    DIAGRAM_SPAN_LEAST_MM,
    DIAGRAM_SPAN_MM,
    Diagram,
    _arranged,
    _detailed,
    link_bodies,
    span_room,
)

ROOT = Path(__file__).parent
FILES = sorted((ROOT / "linkages_layout").glob("*.toml")) + sorted(
    (ROOT / "linkages_review11").glob("*.toml")
)


def _solved(path: Path):  # type: ignore[no-untyped-def]
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


def test_a_yoke_slot_ends_at_its_guide_where_the_block_stays_on_one_side() -> None:
    """The yarn traverse's block K stays below the bar's guide through E: every drawn slot
    lies on K's side of the guide (at most the guide's line itself), and covers K."""
    s = _solved(ROOT / "linkages_review11" / "yarn_guide_traverse.toml")
    lk = s.linkage
    g = next(g for g in lk.groups if g.kind == "PRP")
    assert g.guide is not None
    d = g.guide.direction
    for P in s.drawn:
        E, K = P.pos[g.joint], P.pos[g.slider]
        side = d.cross(K - E)
        assert abs(side) > 0.0
        for half in (0.0, 0.001):  # its axis line, and the slot drawn as a slot
            bodies = link_bodies(lk, P, slot_half=half)[str(g.links[1])]
            slot = bodies[1]
            far = [d.cross(q - E) * (1.0 if side > 0 else -1.0) for q in slot.points]
            assert min(far) >= -tol.SAME_PLACE * lk.length - half, far
            # the slot reaches past the block
            assert max(far) > abs(side), (far, side)


@pytest.mark.parametrize("span", [0.0302, 5.41, 1234.0, 0.7, 1.0, 2.0e-6])
@pytest.mark.parametrize("mm", [35.0, 50.0])
def test_span_room_draws_the_span_that_high(span: float, mm: float) -> None:
    """At the room span_room gives, the axis's rounded μ draws the span at least ``mm`` high
    and below twice that (the coarsest factor that does); a room 1 mm lower draws it lower."""
    room = span_room(span, mm)
    ax = Axis.fit("y", "", 0.0, span, room)
    assert mm - tol.SHEET_MM <= ax.mm(span) < 2.0 * mm
    assert abs(ax.k - nice_step_below(span / mm)) <= tol.DERIVED * ax.k
    lower = Axis.fit("y", "", 0.0, span, room - 1.0)
    assert lower.mm(span) < mm


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_output_diagrams_draw_their_curves_at_least_the_span(path: Path) -> None:
    """Every output diagram of the kinematic sheet draws its curve DIAGRAM_SPAN_MM high at
    least, except on a sheet whose crank's rule needed the room (DIAGRAM_SPAN_LEAST_MM there)."""
    s = _solved(path)
    lay, lays = _arranged(s)
    spans = []
    for pl in lays[0]:
        if isinstance(pl.view, Diagram):
            x0, y0, x1, y1 = pl.inner
            ay = pl.view.axes(x1 - x0, y1 - y0)[1]
            ys = [float(y) for c in pl.view.curves for y in c.ys]
            spans.append(ay.mm(max(ys) - min(ys)))
    assert len(spans) == 3
    least = DIAGRAM_SPAN_MM if lay.spans and not _detailed(lay) else DIAGRAM_SPAN_LEAST_MM
    assert min(spans) >= least - tol.SHEET_MM, (spans, lay.spans)


def test_the_kulisa_mechanism_takes_the_finer_scale_its_sheet_fits() -> None:
    """Review 11: kulisa_inclined_ram drawn 1:4 (crank 30 mm) on an A1 49 % blank; its sheet
    fits the mechanism at 1:2,5 with the size rules and the diagrams' spans kept."""
    s = _solved(ROOT / "linkages_layout" / "kulisa_inclined_ram.toml")
    lay, lays = _arranged(s)
    assert lay.k_l.ratio_text() == "1:2,5"
    assert lay.k_l.mm(s.linkage.length) >= CRANK_MM
    assert lay.sized[0].fmt == "A1"
    assert all(la.fits for la in lays)
