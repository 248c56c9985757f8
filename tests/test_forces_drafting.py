"""The drawings of links on a linkage file's forces sheet (issue 27, round 2): the loaded
mechanism and the groups cut out. An arrow moved along its line of action carries that line
back to its point thin; the mechanism's arrows follow the free bodies' rules (no head in a
hatch or a block, no two arrows tail to tail); their letters keep clear of the lines; and the
order of the analysis writes each plan's equation in the order the plan lays its terms off."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
import shapely
from test_free_bodies import NAMES, _dist, _lines, _linkage

from geomcad.linkage.solution import solve
from geomcad.sheet.drawing import ARROW_LEN
from geomcad.sheet.loads import AT_POINT_MM, line_of_action
from geomcad.sheet.model import XY, Polyline, Sheet, TextItem


def _views(name: str, monkeypatch: pytest.MonkeyPatch) -> tuple[Sheet, list[dict[str, Any]]]:
    """The forces sheet of ``name`` and what each drawing of links drew on it (the last
    arrangement's): its kind, items, arrows, the forces placed by their clearance (the sheet
    point of application, tail, tip) and the anchors of the labels it asked for."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.drawing import Drawing

    rec: list[dict[str, Any]] = []
    draw = lf._Forces.draw
    force = lf.force
    label = Drawing.label

    def rec_force(v: Any, at: Any, F: Any, *a: Any, **kw: Any) -> Any:
        out = force(v, at, F, *a, **kw)
        if rec and rec[-1]["open"] and kw.get("clear") is not None and out is not None:
            rec[-1]["moved"].append((v.p(at), *out))
        return out

    def rec_label(d: Drawing, anchor: XY, *a: Any, **kw: Any) -> None:
        if rec and rec[-1]["open"]:
            rec[-1]["labels"].append(anchor)
        label(d, anchor, *a, **kw)

    def rec_draw(self: Any, d: Any, at: Any) -> None:
        i, j = len(d.sheet.items), len(d.sheet.vectors)
        kind = "mech" if isinstance(self, lf._Loaded) else "body"
        rec.append({"kind": kind, "moved": [], "labels": [], "open": True})
        draw(self, d, at)
        rec[-1].update(open=False, items=d.sheet.items[i:], vectors=d.sheet.vectors[j:])

    monkeypatch.setattr(lf._Forces, "draw", rec_draw)
    monkeypatch.setattr(lf, "force", rec_force)
    monkeypatch.setattr(Drawing, "label", rec_label)
    s = solve(_linkage(name))
    sheet = lf.force_sheets(s, name)[0][1]
    n = 1 + len(lf.force_position(s)[1].groups)
    return sheet, rec[-n:]


def test_the_line_of_action_back_to_the_point() -> None:
    """An arrow that reaches its point (or runs past it) draws no line; one moved along its
    line of action draws the thin line from its nearer end to the point."""
    sheet = Sheet(100.0, 100.0, "A4", "")
    assert line_of_action(sheet, (0.0, 0.0), (0.0, 0.0), (10.0, 0.0)) is None
    assert line_of_action(sheet, (5.0, 0.0), (0.0, 0.0), (10.0, 0.0)) is None
    assert line_of_action(sheet, (11.0, 0.0), (0.0, 0.0), (10.0, 0.0)) is None  # at its head
    line = line_of_action(sheet, (-20.0, 0.0), (0.0, 0.0), (10.0, 0.0))
    assert line is not None and line.points == ((0.0, 0.0), (-20.0, 0.0))
    assert line.role == "thin" and sheet.items == [line]
    line = line_of_action(sheet, (0.0, 30.0), (0.0, 0.0), (0.0, 10.0))
    assert line is not None and line.points == ((0.0, 10.0), (0.0, 30.0))


@pytest.mark.parametrize("name", NAMES)
def test_a_moved_arrow_is_joined_to_its_point_by_its_line_of_action(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """On the mechanism and every group cut out, each arrow drawn off its point of application
    (moved along its line of action until clear) has a thin line on that line from its nearer
    end to the point: the force reads as acting there."""
    _, views = _views(name, monkeypatch)
    moved = 0
    for view in views:
        thin = [it for it in view["items"] if isinstance(it, Polyline) and it.role == "thin"]
        for p, tail, tip in view["moved"]:
            length = math.dist(tail, tip)
            u = np.subtract(tip, tail) / length
            s = float(np.dot(np.subtract(p, tail), u))
            if -AT_POINT_MM <= s <= length + AT_POINT_MM:
                continue
            moved += 1
            end = tail if s < 0.0 else tip
            assert any(
                _dist(np.array([p, end]), [(it.points[0], it.points[-1])]).max() < 1e-6
                for it in thin
            ), (name, view["kind"], p, tail, tip)
    if name == "shaper":
        assert moved >= 1  # Ф_4 on link 4 is moved off it


def _tail_to_tail(vectors: list[tuple[XY, XY]]) -> list[tuple[XY, XY, XY, XY]]:
    """Pairs of arrows on one line pointing away from each other with their tails within
    ARROW_LEN: they would read as one double-headed arrow."""
    out = []
    for (a0, a1), (b0, b1) in [(x, y) for i, x in enumerate(vectors) for y in vectors[i + 1 :]]:
        ua = np.subtract(a1, a0) / math.dist(a0, a1)
        ub = np.subtract(b1, b0) / math.dist(b0, b1)
        across = abs(float(np.cross(ua, np.subtract(b0, a0))))
        if float(np.dot(ua, ub)) < -0.99 and across < 1.0 and math.dist(a0, b0) < ARROW_LEN:
            out.append((a0, a1, b0, b1))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_the_loaded_mechanism_keeps_the_free_bodies_rules(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """On the loaded mechanism (as on the groups): no arrowhead in a hatch or on a slider's
    block or guide (away from its own point), no two arrows tail to tail."""
    _, views = _views(name, monkeypatch)
    for view in views:
        hatch = _lines(view["items"], {"ground"})
        links = _lines(view["items"], {"link"})
        assert view["vectors"], (name, view["kind"])
        for tail, tip in view["vectors"]:
            length = math.dist(tail, tip)
            u = np.subtract(tip, tail) / length
            t = np.arange(max(0.0, length - ARROW_LEN), length, 0.1)
            head = np.asarray(tail) + t[:, None] * u
            assert not (_dist(head, hatch) < 0.5).any(), (name, view["kind"], tail, tip)
            own = [p for p, a, b in view["moved"] if math.dist(a, tail) + math.dist(b, tip) < 1e-6]
            far = np.array([all(math.dist(q, p) > AT_POINT_MM for p in own) for q in head])
            assert not ((_dist(head, links) < 0.5) & far).any(), (name, view["kind"], tail, tip)
        assert not _tail_to_tail(view["vectors"]), (name, view["kind"])


#: The least paper (mm) between a letter of a drawing of links and the ink of a line.
LETTER_GAP_MM = 0.2


@pytest.mark.parametrize("name", NAMES)
def test_the_letters_of_the_drawings_of_links_keep_clear_of_their_lines(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every point letter and link number on the mechanism and the groups cut out (texts of
    one or two characters) keeps LETTER_GAP_MM of paper from the ink of every line: no letter
    touching a joint's circle, a moment's arc, a hatch or a block."""
    from geomcad.sheet.placer import ink, text_outline

    sheet, views = _views(name, monkeypatch)
    lines = [it for it in sheet.items if not isinstance(it, TextItem)]
    inks = [ink(it, sheet.format) for it in lines]
    tree = shapely.STRtree(inks)
    asked = [a for view in views for a in view["labels"]]
    for t, at in sheet.anchors:
        if len(t.text) > 2 or not any(math.dist(at, a) < 1e-9 for a in asked):
            continue
        b = text_outline(t)
        gap = min((b.distance(inks[j]) for j in tree.query(b.buffer(1.0))), default=1.0)
        assert gap >= LETTER_GAP_MM, (name, t.text, at, gap)


@pytest.mark.parametrize("name", NAMES)
def test_the_order_writes_each_plan_as_it_is_laid_off(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each force plan's equation in the order of the analysis lists its terms in the order
    the plan drawn lays them off (its known loads regrouped so that the short vectors run
    together): the recorded equation where the plan keeps the model's order."""
    from geomcad.forces import ForcePolygon
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet import views as vw

    drawn: list[ForcePolygon] = []
    # the steps of every order the layout search builds, and the one it draws (the search
    # tries sheets after the one it keeps: the last built is not always the one drawn)
    shown: list[list[Any]] = []
    pdraw, steps_init, sdraw = vw.Polygon.draw, lf.Steps.__init__, lf.Steps.draw

    def rec_draw(self: Any, d: Any, at: Any) -> None:
        drawn.append(self.layers[-1][0])
        pdraw(self, d, at)

    def rec_steps(self: Any, st: Any, *a: Any, **kw: Any) -> None:
        self.recorded = list(st)
        steps_init(self, st, *a, **kw)

    def rec_sdraw(self: Any, d: Any, at: Any) -> None:
        shown.append(self.recorded)
        sdraw(self, d, at)

    monkeypatch.setattr(vw.Polygon, "draw", rec_draw)
    monkeypatch.setattr(lf.Steps, "__init__", rec_steps)
    monkeypatch.setattr(lf.Steps, "draw", rec_sdraw)
    s = solve(_linkage(name))
    f = lf.force_position(s)[1]
    lf.force_sheets(s, name)
    order = shown[0]  # sheet 2's order (drawn before the dynamics sheet's)
    plans = {st.name: st for st in order if st.kind in ("force_polygon", "polygon_closing")}
    n = sum(len(gf.polygons) for gf in f.groups)
    assert len(plans) == n
    reordered = 0
    for poly in drawn[-n:]:
        names = [pv.name for pv in poly.vectors]
        (st,) = [st for st in plans.values() if sorted(pv.name for pv in st.result.vectors)
                 == sorted(names)]  # fmt: skip
        eq = str(dict(st.args)["eq"])
        if names == [pv.name for pv in st.result.vectors]:
            assert eq == lf.load_name(str(dict(f.c.step(st.name).args)["eq"]))
        else:
            reordered += 1
            assert eq == " + ".join(lf.load_name(x) for x in names) + " = 0", (name, eq, names)
    if name == "sixbar-2013-6":
        assert reordered >= 1  # its polygon of link 5 lays Ф_5, R_05 off first


def test_an_arrow_arriving_at_a_slider_stops_at_its_block() -> None:
    """A force arriving at a slider's joint ends at the block's outline, not under it (a
    filled block hides a head drawn inside it); the arrow that misses the block is as asked."""
    from geomcad.sheet import symbols
    from geomcad.sheet.loads import Clearance, _inside

    sheet = Sheet(200.0, 200.0, "A4", "")
    clear = Clearance(sheet, 0, (0.0, 0.0, 200.0, 200.0))
    symbols.block(sheet, (100.0, 100.0), (1.0, 0.0), size=(30.0, 30.0))  # a head fits inside
    (shape,) = clear.solids()
    tail, tip = clear.place((100.0, 100.0), (0.0, 1.0), 15.0, True)  # down onto the block
    head = np.array([tip, (tip[0], tip[1] - ARROW_LEN)])
    assert not _inside(head, [shape]).any(), tip
    assert tip[1] < 100.0 and math.isclose(tip[1] - tail[1], 15.0)
    assert _inside(np.array([(100.0, 100.0), (150.0, 100.0)]), [shape]).tolist() == [True, False]
    assert 100.0 - 15.0 - 4.0 <= tip[1] <= 100.0 - 15.0  # at the outline, not far from it
