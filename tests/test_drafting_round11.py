"""Review 11's drafting (issue 27, fix 6 and fix 7's drafting leftovers): a cut-out group (or
the crank) on the forces sheet is cut free of the frame, so its frame joints show the joint and
the reaction R_0j, not the frame's hatched support or guide."""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np
import pytest
from test_drafting_round9 import FILES, _linkage

from geomcad.linkage.solution import solve
from geomcad.sheet.model import CircleItem, Polyline

#: Files with a revolute and a prismatic pair on the frame in their cut-out groups (a rocker's
#: pivot C, a slider's guide), each group and the crank checked.
CUT = ["slider_rocker_rpr", "shaper", "crank_rocker_inclined_slide"]


def _free_bodies(name: str, monkeypatch: pytest.MonkeyPatch) -> list[tuple[Any, Any, list[Any]]]:
    """The forces sheet's cut-out groups and crank of ``name``: (view, its viewport, the items
    it drew)."""
    from geomcad.sheet import linkage_forces as lf

    rec: list[tuple[Any, Any, list[Any]]] = []
    links = lf._FreeBody.links

    def rec_links(self: Any, d: Any, at: Any) -> None:
        start = len(d.sheet.items)
        links(self, d, at)
        rec.append((self, at.viewport, list(d.sheet.items[start:])))

    monkeypatch.setattr(lf._FreeBody, "links", rec_links)
    lf.force_sheets(solve(_linkage(name)))
    return rec


@pytest.mark.parametrize("name", [n for n in CUT if n in FILES])
def test_a_cut_out_group_shows_no_support_of_the_frame(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """No cut-out group nor the crank draws the frame's hatching (a hinge's hatched support or
    a guide's hatched lines: review 11 found them at C and D of the groups), and each revolute
    on the frame keeps its joint circle (where the reaction R_0j acts)."""
    from geomcad.linkage.solution import scheme

    bodies = _free_bodies(name, monkeypatch)
    assert bodies, name
    hinges = 0
    for view, v, items in bodies:
        hatch = [it for it in items if getattr(it, "role", None) == "ground"]
        assert not hatch, (name, view.title, len(hatch))
        full = scheme(view.lk, view.P)
        own = {str(i) for i in view.gf.links}
        circles = [it.c for it in items if isinstance(it, CircleItem) and it.role == "joint"]
        for p in full.pairs:
            if p.kind == "R" and full.frame in p.links and own & set(p.links):
                hinges += 1
                c = v.p(p.at)
                assert any(np.hypot(x - c[0], y - c[1]) < 0.05 for x, y in circles), (
                    name, view.title, p.name)  # fmt: skip
    assert hinges, name


# -- a detail's circle off the frame's supports -----------------------------------------------


def _ring_gap(c: tuple[float, float], r: float, a: Any, b: Any) -> float:
    """How near (mm) the circle (c, r) comes to the segment a–b (0 where it crosses it)."""
    t = np.linspace(0.0, 1.0, 200)[:, None]
    pts = np.asarray(a, float) + t * (np.asarray(b, float) - np.asarray(a, float))
    d = np.hypot(pts[:, 0] - c[0], pts[:, 1] - c[1]) - r
    return 0.0 if d.min() <= 0.0 <= d.max() else float(np.abs(d).min())


def test_the_inset_circle_is_moved_off_a_hinge_support() -> None:
    """An inset's circle round a point near a frame hinge's support keeps SUPPORT_GAP_MM off
    its stand and hatching, its point still POINT_INSIDE_MM inside it; one far from it stays
    round its point."""
    from geomcad.sheet import symbols
    from geomcad.sheet.insets import MARK_R, POINT_INSIDE_MM, SUPPORT_GAP_MM, off_supports, supports
    from geomcad.sheet.model import Sheet

    sheet = Sheet(420.0, 297.0, "A3", "t")
    symbols.pivot(sheet, (100.0, 100.0), (0.0, 1.0))  # the stand down, its ground at y 105
    outlines = supports(sheet.items)
    assert len(outlines) == 1
    p = (104.0, 111.5)  # 4.5 mm under the hatching: a circle of MARK_R round it comes 1 mm near
    c = off_supports(p, MARK_R, [p], outlines)
    assert c != p
    assert math.dist(c, p) <= MARK_R - POINT_INSIDE_MM + 1e-9
    lines = [it.points for it in sheet.items if isinstance(it, Polyline) and it.role != "joint"]
    gap = min(_ring_gap(c, MARK_R, a, b) for pts in lines for a, b in itertools.pairwise(pts))
    assert gap >= SUPPORT_GAP_MM - 1e-6, gap
    far = (140.0, 140.0)
    assert off_supports(far, MARK_R, [far], outlines) == far


def test_no_inset_circle_on_the_kulisa_hinge_support(monkeypatch: pytest.MonkeyPatch) -> None:
    """On kulisa_inclined_ram's forces sheet (review 11: Ж's circle round S3 on O's support),
    no inset circle off a slider comes within 2 mm of a hinge's stand or hatching."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.symbols import STAND_DEPTH, STAND_HALF

    sheet = lf.force_sheets(solve(_linkage("kulisa_inclined_ram")))[0][1]
    leg = math.hypot(STAND_DEPTH, STAND_HALF)
    support = [it.points for it in sheet.items if isinstance(it, Polyline) and (
        it.role == "ground" or (it.role == "link" and len(it.points) == 2
                                and abs(math.dist(*it.points) - leg) < 1e-6))]  # fmt: skip
    blocks = [np.asarray(it.points) for it in sheet.items if isinstance(it, Polyline)
              and it.fill and it.closed and len(it.points) == 4]  # fmt: skip
    rings = [it for it in sheet.items
             if isinstance(it, CircleItem) and it.role == "thin" and it.r < 6.0
             and not any(np.hypot(*(b.mean(axis=0) - it.c)) < 3.0 for b in blocks)]  # fmt: skip
    assert rings
    near = [(it.c, round(g, 2)) for it in rings
            if (g := min(_ring_gap(it.c, it.r, a, b) for a, b in support)) < 2.0]  # fmt: skip
    assert not near, near


# -- no thin line through a label --------------------------------------------------------------


@pytest.mark.parametrize("name", ["kulisa_inclined_ram", "sixbar_coupler_slider"])
def test_no_thin_line_runs_through_a_label(name: str) -> None:
    """On the kinematic sheet no thin line (the twelve positions' lines, paths, centre lines,
    construction, hatching) runs through a label: it is broken at the label's box (review 11:
    thin lines through "9", "11", "S5"; on main kulisa's "S3" and sixbar_coupler_slider's "B"
    were crossed). The measure is the layout checker's: the label's box less 0.25 mm all round
    meets the line's ink over more than AREA_EPS mm²."""
    from layout import AREA_EPS, stroke, text_poly

    from geomcad.sheet.linkage import kinematic_sheets
    from geomcad.sheet.model import TextItem
    from geomcad.sheet.placer import BROKEN_ROLES

    sheet = next(sh for _, sh in kinematic_sheets(solve(_linkage(name))))
    thin = [it for it in sheet.items if isinstance(it, Polyline) and it.role in BROKEN_ROLES]
    inks = [stroke(it, sheet.format) for it in thin]
    bad = []
    for t in sheet.items:
        if isinstance(t, TextItem) and t.role == "label":
            p = text_poly(t).buffer(-0.25)
            if p.is_empty:
                continue
            bad += [t.text for g in inks if g.intersects(p) and g.intersection(p).area > AREA_EPS]
    assert not bad, (name, bad)
