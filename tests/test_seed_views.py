"""General views appended for the seed sheets (geomcad.sheet.leaders, stacked, …): each on
data of its own, not on a seed problem."""

from __future__ import annotations

import math

import numpy as np
import pytest

from geomcad.geom import Vec
from geomcad.sheet import Scale, TitleBlock, Viewport, start
from geomcad.sheet.compose import Field, Row, arrange, compose
from geomcad.sheet.leaders import angle_with_leader, crossed, ink
from geomcad.sheet.model import Polyline, TextItem
from geomcad.sheet.stacked import ROW_PAD_MM, Stacked, StackedDiagrams, row_factors


def test_a_segment_crosses_a_box_only_where_it_runs_through_it() -> None:
    segs = np.array([[0.0, 0.0, 10.0, 10.0]])
    assert crossed(segs, (4.0, 4.0, 6.0, 6.0))
    assert not crossed(segs, (6.0, 0.0, 9.0, 3.0))
    assert not crossed(np.zeros((0, 4)), (0.0, 0.0, 1.0, 1.0))


def test_an_angles_value_stands_clear_of_every_line_drawn_round_it() -> None:
    d = start("A4", TitleBlock(title="t", designation="d"))
    v = d.viewport(Scale(0.01, "l"), (0.0, 0.0), (100.0, 150.0))
    o = Vec(0.0, 0.0)
    # a fan of links crowding the angle's arc
    for a in range(0, 91, 10):
        v.seg(o, Vec.polar(0.4, math.radians(a)), "link")
    first = len(d.sheet.items)
    angle_with_leader(v, o, Vec(1.0, 0.0), Vec(0.0, 1.0), "90°", 8.0)
    texts = [it for it in d.sheet.items[first:] if isinstance(it, TextItem)]
    assert [t.text for t in texts] == ["90°"]
    t = texts[0]
    links = ink([it for it in d.sheet.items[:first] if isinstance(it, Polyline)])
    # the text's box (at its base line, 2.5 mm high) crosses no link
    x, y = t.at
    assert not crossed(links, (x, y - 2.5, x + 4.0, y))


def test_row_factors_fill_the_height_with_the_largest_least_row() -> None:
    ranges = [0.1, 2.0, 40.0]
    ks = row_factors(ranges, 150.0)
    heights = [r / k for r, k in zip(ranges, ks, strict=True)]
    assert sum(heights) <= 150.0 - ROW_PAD_MM * len(ranges)
    # no finer factor of the smallest row fits with the others
    i = int(np.argmin(heights))
    finer = list(ks)
    finer[i] = ks[i] / 2.0
    assert sum(r / k for r, k in zip(ranges, finer, strict=True)) > 150.0 - ROW_PAD_MM * 3


def test_stacked_diagrams_draw_one_row_per_curve_with_the_mark_on_each() -> None:
    xs = np.linspace(0.0, 2.0 * math.pi, 73)
    rows = [Stacked("S", "м", np.sin(xs), math.sin(1.0)),
            Stacked("V", "м/с", np.cos(xs), math.cos(1.0), "p")]  # fmt: skip
    view = StackedDiagrams("φ", "рад", 0.0, 2.0 * math.pi, xs, rows, 1.0, heading="h")
    d = start("A3", TitleBlock(title="t", designation="d"))
    first = len(d.sheet.items)
    compose(d, Row(view), layout=arrange(Row(view), Field.of_format("A3")))
    items = d.finish().items[first:]
    texts = [it.text for it in items if isinstance(it, TextItem)]
    assert "h" in texts and "p" in texts
    marks = [it for it in items if isinstance(it, Polyline)
             and it.role == "construction" and len(it.points) == 2
             and it.points[0][0] == it.points[1][0]]  # fmt: skip
    assert len({round(m.points[0][0], 6) for m in marks}) == 1  # one abscissa down both rows
    assert len(marks) >= 2


def test_the_title_blocks_room_is_the_forms_box_with_the_fields_margin() -> None:
    from geomcad.sheet.compose import FIELD_MARGIN
    from geomcad.sheet.form import title_block_room
    from geomcad.sheet.frame import TB_HEIGHT, TB_WIDTH

    assert title_block_room("A3") == (TB_WIDTH + FIELD_MARGIN, TB_HEIGHT + FIELD_MARGIN)
    assert title_block_room("A1") == title_block_room("A3")


def test_an_enlarged_joints_reaction_touches_its_friction_circle_and_rho_is_free() -> None:
    from geomcad.forces import FrictionCircle
    from geomcad.geom import Line
    from geomcad.sheet.friction import FrictionJoint, free_angle
    from geomcad.sheet.model import ArcItem, CircleItem

    # ρ's direction is the one farthest from every taken direction
    a = free_angle([Vec(1.0, 0.0), Vec(0.0, 1.0), Vec(-1.0, 0.0)])
    assert abs(math.remainder(a - math.radians(270.0), 2.0 * math.pi)) < 1e-9
    fc = FrictionCircle(Vec(0.0, 0.0), rho=0.002, sense=1, r=0.01, name="B")
    line = Line(Vec(0.0, 0.002), Vec(1.0, 0.0))  # tangent to the friction circle
    view = FrictionJoint(fc, [Vec(0.05, 0.05)], line, Vec(1.0, 0.0), "R", "ω", 0.02, "B")
    d = start("A3", TitleBlock(title="t", designation="d"))
    first = len(d.sheet.items)
    compose(d, Row(view), layout=arrange(Row(view), Field.of_format("A3")))
    items = d.finish().items[first:]
    circles = sorted(it.r for it in items if isinstance(it, CircleItem) and it.r > 1.0)
    k = circles[-1] / 0.01  # the pin's paper radius over its model radius
    assert circles[-2] == pytest.approx(0.002 * k)  # ρ drawn to scale
    texts = [it.text for it in items if isinstance(it, TextItem)]
    assert {"R", "ρ", "ω", "B"} <= set(texts)
    assert any(isinstance(it, ArcItem) for it in items)  # the rotation's curved arrow


def test_a_press_scheme_is_not_to_scale_and_names_its_parts() -> None:
    from geomcad.sheet.drives import Press, PressScheme

    names = {"flywheel": "fw", "motor": "mo", "plate": "pl", "die": "di"}
    view = PressScheme(names)
    assert view.extent() == Press().box
    d = start("A3", TitleBlock(title="t", designation="d"))
    first = len(d.sheet.items)
    compose(d, Row(view), layout=arrange(Row(view), Field.of_format("A3")))
    texts = {it.text for it in d.finish().items[first:] if isinstance(it, TextItem)}
    assert {"fw", "mo", "pl", "di", "1", "2", "3", "ω"} <= texts
    assert not any("1:" in t or ":1" in t for t in texts)  # no scale shown


def test_a_point_set_off_is_joined_to_its_text_by_a_leader() -> None:
    from geomcad.sheet.graph import Axis, Graph
    from geomcad.sheet.graph_notes import set_off

    d = start("A3", TitleBlock(title="t", designation="d"))
    g = Graph(d, Axis("x", "", 0.0, 10.0, 0.1), Axis("y", "", 0.0, 10.0, 0.1), (50.0, 150.0))
    first = len(d.sheet.items)
    set_off(g, 5.0, 5.0, "P", (8.0, 1.2))
    set_off(g, 2.0, 2.0, "Q", (3.0, -1.4), leader=False)
    items = d.sheet.items[first:]
    leaders = [it for it in items if isinstance(it, Polyline)]
    assert len(leaders) == 1 and leaders[0].points[0] == g.p(5.0, 5.0)
    texts = {it.text: it.at for it in items if isinstance(it, TextItem)}
    px, py = g.p(5.0, 5.0)
    assert texts["P"] == (px + 8.0, py + 1.2)


def test_the_title_blocks_spacer_is_as_tall_as_its_room() -> None:
    from geomcad.sheet.form import title_block_room, title_block_spacer

    assert title_block_spacer("A2").natural() == (10.0, title_block_room("A2")[1])


def test_a_velocity_is_drawn_at_its_factor_or_as_its_end_point_when_short() -> None:
    from geomcad.sheet.drawing import SHORT_MM
    from geomcad.sheet.model import CircleItem
    from geomcad.sheet.velocities import relative, tip, velocity

    d = start("A3", TitleBlock(title="t", designation="d"))
    v = d.viewport(Scale(0.01, "l"), (0.0, 0.0), (100.0, 150.0))
    a = Vec(0.1, 0.1)
    assert v.mm((tip(v, a, Vec(2.0, 0.0), 0.1) - a).norm) == pytest.approx(20.0)  # 2 m/s at 0.1
    first = len(d.sheet.items)
    velocity(v, a, Vec(2.0, 0.0), 0.1, "V")
    arrows = [it for it in d.sheet.items[first:] if isinstance(it, Polyline)]
    reach = max(q[0] for it in arrows for q in it.points)
    assert reach == pytest.approx(v.p(a)[0] + 20.0)
    first = len(d.sheet.items)
    slow = Vec(0.5 * SHORT_MM * 0.1, 0.0)  # half of two arrowheads on the paper
    velocity(v, a, slow, 0.1, "W")
    dots = [it for it in d.sheet.items[first:] if isinstance(it, CircleItem)]
    assert len(dots) == 1 and dots[0].c == pytest.approx(v.p(tip(v, a, slow, 0.1)))
    first = len(d.sheet.items)
    velocity(v, a, Vec(0.0, 0.0), 0.1, "0")
    relative(v, a, Vec(1.0, 0.0), Vec(1.0, 0.0), 0.1, "R")
    assert len(d.sheet.items) == first  # a point at rest, no relative velocity: nothing drawn


def test_a_views_drawn_extent_takes_in_what_it_draws_round_its_body() -> None:
    from geomcad.sheet.reach import drawn_extent

    box = (0.0, 0.0, 1.0, 1.0)

    def draw(v: Viewport) -> None:
        v.seg(Vec(0.5, 0.5), Vec(0.5, 0.5) + Vec(v.scale.model(30.0), 0.0), "vector")

    for k in (0.01, 0.02):
        got = drawn_extent(box, draw, Scale(k, "l"))
        assert got[:2] == pytest.approx(box[:2]) and got[3] == pytest.approx(box[3])
        assert got[2] == pytest.approx(max(1.0, 0.5 + 30.0 * k), abs=1e-3 * k + 1e-9)


def test_a_tree_is_built_again_until_its_scales_are_the_ones_it_gets() -> None:
    from geomcad.sheet.compose import Figure
    from geomcad.sheet.settle import factor_of, settle

    built: list[float] = []

    def build(k: float) -> tuple[Row, Figure]:
        built.append(k)
        # a view whose model grows with the scale it was built for (loads drawn at their μ)
        fig = Figure((0.0, 0.0, 1.0 + 10.0 * k, 1.0), lambda v: None)
        return Row(fig), fig

    s = settle(build, factor_of, 0.0, Field.of_format("A3"), rounds=6)
    assert built[0] == 0.0 and len(built) >= 2
    assert s.key == factor_of(s.layout, s.parts) == built[-1]  # settled: built with what it got
    once: list[float] = []
    settle(lambda k: (once.append(k), build(k))[1], factor_of, 0.0, Field.of_format("A3"), 1)
    assert once == [0.0]  # at most ``rounds`` builds


def test_a_plans_short_vectors_are_those_under_two_arrowheads_at_its_scale() -> None:
    import geomcad
    from geomcad.sheet.drawing import SHORT_MM
    from geomcad.sheet.short import short_vectors

    plan = geomcad.solve("kulisa-23110713").data.vplan
    lengths = [(plan.points[v.head] - plan.points[v.tail]).norm for v in plan.vectors]
    longest = max(lengths)
    every = short_vectors(plan, Scale(longest, "v"), zero=True)  # the longest 1 mm long
    assert len(every) == len(plan.vectors)
    k = Scale(longest / SHORT_MM * 0.999, "v")  # the longest just over two arrowheads
    got = short_vectors(plan, k, zero=True)
    assert all(s.mm < SHORT_MM for s in got)
    assert len(got) == sum(1 for x in lengths if k.mm(x) < SHORT_MM)
    assert all(s.mm > 0.0 for s in short_vectors(plan, Scale(longest, "v")))
