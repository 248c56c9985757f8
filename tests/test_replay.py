"""geomcad.sheet.replay: a construction drawn by its steps' roles (issue 14), and the orders of
construction of 2013-5 and 2013-6 written from their recorded steps."""

from __future__ import annotations

import collections
import math

import pytest
from geomcad_constructions import sheets_2013_5, sheets_2013_6
from layout import layout_problems

import geomcad
from geomcad.construction import Construction
from geomcad.geom import Line, Vec, angle_arcs
from geomcad.sheet import TitleBlock, start
from geomcad.sheet.compose import Row, compose
from geomcad.sheet.lang import language
from geomcad.sheet.model import ArcItem, CircleItem, Polyline
from geomcad.sheet.replay import Replay, extent
from geomcad.sheet.views import Steps, step_text


def _toy() -> Construction:
    c = Construction("toy")
    A = c.point("A", (0.0, 0.0))
    B = c.point("B", (0.1, 0.0), role="result")
    C = c.point("C", (0.0, 0.08), role="construction")
    c.line_through("AB", A, B)  # construction: thin, over A and B
    c.circle("k", A, 0.05, role="result")
    c.segment("AC", A, C, role="link")
    c.segment("BC", B, C, role="extreme")
    c.circle("path", B, 0.02, role="aux")
    c.circle("hid", C, 0.5, role="hidden")
    c.run("arcs", "arcs", lambda: angle_arcs(A, B, math.radians(40.0)), kind="arcs")
    c.line("far", Vec(0.0, 0.04), (1.0, 0.0), "a line through no two points", kind="line")
    return c


def _drawn(c: Construction, **kw: object) -> tuple[list[object], list[str]]:
    d = start("A3", TitleBlock("t", "d"))
    view = Replay(c, **kw)  # type: ignore[arg-type]
    compose(d, Row(view))
    view_items: list[object] = list(d.sheet.items)
    labels = [r.markup for r in d.pending]
    sheet = d.finish()
    assert layout_problems(sheet) == []
    return view_items, labels


def test_a_replayed_construction_draws_each_step_by_its_role() -> None:
    c = _toy()
    items, labels = _drawn(c, labels={"arcs": ("Γ", "Γ'"), "far": "y = 0,04"})
    roles = collections.Counter(
        (type(it).__name__, it.role)  # type: ignore[attr-defined]
        for it in items
        if isinstance(it, Polyline | CircleItem | ArcItem)
    )
    # points: the given A as a dot, the result B marked, C (construction) as a dot
    assert roles[("CircleItem", "result")] == 2  # B's dot and the circle k
    assert roles[("CircleItem", "point")] == 2  # A and C
    assert roles[("CircleItem", "centre")] == 1  # the aux path
    assert roles[("Polyline", "link")] == 1  # AC
    assert roles[("Polyline", "extreme")] == 1  # BC in phantom lines
    assert roles[("Polyline", "construction")] == 2  # AB over A, B and the clipped line
    assert roles[("ArcItem", "construction")] == 2  # the two arcs
    # the hidden circle is not drawn (it would be a thin construction circle)
    assert roles[("CircleItem", "construction")] == 0
    # the points by their names, the curves only as asked
    assert sorted(labels) == sorted(["A", "B", "C", "Γ", "Γ'", "y = 0,04"])


def test_lines_run_over_their_points_and_are_clipped_to_the_extent() -> None:
    c = _toy()
    box = extent(c)
    # the arcs reach below and above the chord; the far line spans the box
    assert box[0] < 0.0 and box[2] > 0.1 and box[1] < 0.0 and box[3] > 0.08
    d = start("A3", TitleBlock("t", "d"))
    view = Replay(c, names=["AB", "far", "A", "B"], over=0.0)
    lay = compose(d, Row(view))
    vp = lay[view].viewport
    assert vp is not None
    segs = [it for it in d.sheet.items if isinstance(it, Polyline) and it.role == "construction"]
    ab = min(segs, key=lambda s: abs(s.points[0][1] - vp.p(Vec(0.0, 0.0))[1]))
    # AB from A to B exactly (over = 0), the far line across the extent of A, B (a flat box)
    assert ab.points[0] == pytest.approx(vp.p(Vec(0.0, 0.0)))
    assert ab.points[-1] == pytest.approx(vp.p(Vec(0.1, 0.0)))
    assert len(segs) == 1  # the far line misses the box of A and B: not drawn


def test_an_unknown_step_name_is_refused() -> None:
    with pytest.raises(ValueError, match="'nope'"):
        Replay(_toy(), names=["A", "nope"])


def test_2013_6_draws_its_synthesis_by_replay_and_passes_the_checker() -> None:
    sol = geomcad.solve("2013-6")
    _, sheet = sheets_2013_6.main_sheet(sol)
    assert layout_problems(sheet) == []
    arcs = [it for it in sheet.items if isinstance(it, ArcItem) and it.role == "construction"]
    # the θ-arcs of Γ and Γ' (313° each for θ = 23.5°), drawn from the recorded step
    big = [a for a in arcs if abs(a.sweep) > math.pi]
    assert len(big) == 2
    texts = {t.text for t in sheet.texts()}
    assert {"Γ", "Γ'", "y = l3 – e", "y = l3 + e", "O", "B0", "B1", "O1(2)", "O1(4)"} <= texts


def test_2013_6_order_is_its_steps() -> None:
    sol = geomcad.solve("2013-6")
    c = sol.construction
    for lang, theta in (("ru", "23,48°"), ("en", "23.48°")):
        with language(lang):
            order = Steps(c, 146.0, only=sheets_2013_6.ORDER, words=sheets_2013_6.WORDS)
            numbered = [t for t in order.lines if t.split(" ")[0].rstrip(".").isdigit()]
            assert len(numbered) == len(sheets_2013_6.ORDER)
            text = " ".join(order.lines)
            assert theta in text  # θ = 180°·(K − 1)/(K + 1), from the recorded value
            l1 = step_text(c.step("l1"), sheets_2013_6.WORDS)
            assert ("0,06415" if lang == "ru" else "0.06415") in l1
            assert "?" not in text  # every sign in the sheet font
    assert math.degrees(c["θ"]) == pytest.approx(sol.results["theta_deg"], abs=1e-12)


def test_2013_5_order_is_its_plan_steps_for_any_variant() -> None:
    for params in ({}, {"z1": 18, "z2": 96, "z3": 58}):
        sol = geomcad.solve("2013-5", **params)
        c = sol.construction
        names = sheets_2013_5.order_steps(c)
        # the radii, the points at rest, the start, one line per moving link and one point per
        # other level, the angle diagram and the ratio
        lines = [n for n in names if c.step(n).kind == "train_line"]
        assert len(lines) == 5
        assert names[0] == "radii" and names[-1] == "u1H2 (angle diagram)"
        with language("ru"):
            last = step_text(c.step(names[-1]), sheets_2013_5.WORDS)
            u = sol.results["u1H2"]
            assert f"{u:.4g}".replace(".", ",") in last
            order = Steps(c, 148.0, only=names, words=sheets_2013_5.WORDS)
            assert "?" not in " ".join(order.lines)


def test_train_line_kinds_name_the_links_as_the_sheet_does() -> None:
    c = geomcad.solve("2013-5").construction
    with language("en"):
        assert step_text(c.step("v(H2-7)")) == "the velocity line of link H_2–7 through o and b"
    assert isinstance(c["v(H2-7)"], Line)
