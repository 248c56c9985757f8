"""The composition layer (issue 14): views packed into the field at their series' largest scale,
the views that draw themselves, and the kinematic symbols in their local frame."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from layout import layout_problems

from geomcad.construction import Construction
from geomcad.errors import ParameterError
from geomcad.forces.polygon import ForcePolygon, PlanVector
from geomcad.geom import Vec
from geomcad.problem import Param
from geomcad.sheet import TitleBlock, start
from geomcad.sheet.compose import (
    Choice,
    Column,
    Field,
    Figure,
    Grid,
    Row,
    arrange,
    compose,
    round_scale,
)
from geomcad.sheet.frame import reserved
from geomcad.sheet.lang import language
from geomcad.sheet.model import CircleItem, Polyline
from geomcad.sheet.scale import Scale
from geomcad.sheet.symbols import Local, block
from geomcad.sheet.views import WORDS as WORDS_VIEWS
from geomcad.sheet.views import AxisSpec, Curve, Diagram, Polygon, Steps, Table, step_text


def _fig(w: float, h: float, **kw: object) -> Figure:
    return Figure((0.0, 0.0, w, h), lambda v: None, **kw)  # type: ignore[arg-type]


def _overlap(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 and b[1] < a[3] - 1e-9


@pytest.mark.parametrize(
    ("raw", "series", "k"),
    [(0.0023, "gost", 0.0025), (0.0026, "gost", 0.004), (0.03, "nice", 0.04),
     (0.03, "plan", 0.05), (0.04, "nice", 0.04), (0.7404, "free", 0.75), (0.02, "free", 0.02)],
)  # fmt: skip
def test_round_scale_takes_the_largest_drawing_of_the_series(
    raw: float, series: str, k: float
) -> None:
    assert round_scale(raw, "l", series).k == pytest.approx(k)  # type: ignore[arg-type]


def test_text_paragraphs_begin_on_new_lines_their_rest_indented() -> None:
    from geomcad.sheet.views import Text

    t = Text(paragraphs=["1. " + "word " * 30, "2. short"], width=60.0, indent=4.0)
    assert len(t.lines) >= 3 and t.lines[-1] == "2. short"
    assert t.shifts[0] == 0.0 and t.shifts[1] == 4.0 and t.shifts[-1] == 0.0


def test_round_scale_refuses_no_room() -> None:
    with pytest.raises(ParameterError):
        round_scale(float("inf"), "l", "gost")


def test_views_fill_the_field_without_overlap() -> None:
    """Boxes stay in the field, clear of each other, of the title block and of графа 26; the
    drawings fit their boxes at the chosen scales; a scale group shares one scale."""
    views = [_fig(0.5, 0.3, title="A", weight=2.0)]
    plans = [_fig(1.0 + i, 0.5, quantity="v", series="nice", group="v") for i in range(5)]
    table = Table([["a", "b"], ["1", "2"]], title="T")
    tree = Column(Row(views[0], Grid(*plans, title="plans")), Row(_fig(0.2, 0.2), table))
    field = Field.of_format("A1")
    lay = arrange(tree, field)
    boxes = [pl.box for pl in lay]
    for a, b in itertools.combinations(boxes, 2):
        assert not _overlap(a, b)
    for bx in boxes:
        assert field.box[0] <= bx[0] and bx[2] <= field.box[2] + 1e-9
        assert all(not _overlap(bx, r) for r in reserved(841.0, 594.0))
    for pl in lay:
        ext = pl.view.extent()
        if ext is not None:
            assert pl.scale is not None
            assert pl.scale.mm(ext[2] - ext[0]) <= pl.size[0] + 1e-6
            assert pl.scale.mm(ext[3] - ext[1]) <= pl.size[1] + 1e-6
    assert len({lay[p].scale for p in plans}) == 1
    nat = table.natural()
    assert nat is not None
    assert lay[table].size[0] >= nat[0] - 1e-6 and lay[table].size[1] >= nat[1] - 1e-6


def test_a_view_alone_is_drawn_larger_than_beside_another() -> None:
    field = Field.of_format("A3")
    a = _fig(0.3, 0.2)
    alone = arrange(a, field)[a].scale
    b = _fig(0.3, 0.2)
    beside = arrange(Row(a, b), field)[a].scale
    assert alone is not None and beside is not None and alone.k < beside.k


def test_the_split_follows_the_drawings() -> None:
    """A tall narrow view beside a wide one gets a narrow box: no large empty room beside a
    small drawing (the smallest fill stays high)."""
    wide, tall = _fig(0.8, 0.3), _fig(0.1, 0.5)
    lay = arrange(Row(wide, tall), Field.of_format("A2"))
    assert lay[tall].box[2] - lay[tall].box[0] < lay[wide].box[2] - lay[wide].box[0]
    assert lay.fill() > 0.35


def test_choice_takes_the_better_arrangement() -> None:
    a, b = _fig(0.8, 0.1), _fig(0.8, 0.1)
    side, under = Row(a, b), Column(a, b)
    lay = arrange(Choice(side, under), Field.of_format("A3"))
    assert lay[a].box[2] - lay[a].box[0] > 300.0  # two long views one under the other


def test_composed_sheet_passes_the_layout_checker() -> None:
    d = start("A3", TitleBlock("t", "d"))
    c = Construction("t")
    A = c.point("A", (0.0, 0.0))
    B = c.point("B", (0.1, 0.0))
    k = c.circle("k", A, 0.08)
    m = c.circle("m", B, 0.06)
    c.intersect("C", k, m)
    poly = ForcePolygon(
        Vec(0.0, 0.0),
        (
            PlanVector("F", Vec(0.0, 0.0), Vec(100.0, 0.0)),
            PlanVector("G", Vec(100.0, 0.0), Vec(100.0, 1.0)),
            PlanVector("R", Vec(100.0, 1.0), Vec(0.0, 0.0)),
        ),
        (("R", 100.0),),
    )
    pv = Polygon(poly, title="Forces")
    x = np.linspace(0.0, 360.0, 50)
    dia = Diagram(AxisSpec("φ", "°", "φ", 0.0, 360.0, 60.0), AxisSpec("S", "m", "S"),
                  [Curve(x, np.sin(np.radians(x)))], title="S")  # fmt: skip
    steps = Steps(c, width=90.0)
    table = Table.of_specs([Param("l_AB", 0.1, "AB", "m")], {"l_AB": 0.1})
    lay = compose(d, Row(Column(pv, dia), Column(table, steps)))
    sheet = d.finish()
    assert layout_problems(sheet) == []
    assert pv.points == ["G"]  # 1 N at μ_F ≥ 1 N/mm is shorter than two arrowheads
    assert lay[pv].scale is not None and lay[pv].scale.q == "F"
    texts = {t.text for t in sheet.texts()}
    assert "lAB" in texts  # the spec's name as markup, l_{AB}
    assert any(t.endswith("радиусом 0,08") for t in texts)


def test_order_of_construction_from_the_steps_in_each_language() -> None:
    c = Construction("t")
    A = c.point("A", (0.0, 0.0))
    B1 = c.point("B1", (1.0, 0.0))
    k = c.circle("k", A, 1.0)
    ln = c.line_through("AB", A, B1)
    c.intersect("C", k, ln)
    step = c.step("C")
    with language("ru"):
        assert step_text(step) == "C — точка пересечения k и AB"
    with language("en"):
        assert step_text(step) == "C: the intersection of k and AB"
        assert step_text(c.step("k")).startswith("k: the circle about A")
    listed = Steps(c, width=200.0).lines
    assert [t.split(" ")[0] for t in listed] == ["1.", "2.", "3."]  # the givens are not listed


def test_symbols_draw_in_their_local_frame() -> None:
    f = Local.along((10.0, 10.0), (0.0, -2.0))  # x up the paper
    assert f.p(1.0, 0.0) == pytest.approx((10.0, 9.0))
    assert f.p(0.0, 1.0) == pytest.approx((9.0, 10.0))  # y: x turned ccw on the paper
    d = start("A4", TitleBlock("t", "d"))
    n = len(d.sheet.items)
    block(d.sheet, (50.0, 50.0), (1.0, 0.0), with_joint=False)
    new = d.sheet.items[n:]
    assert not any(isinstance(it, CircleItem) for it in new)
    assert all(isinstance(it, Polyline) and it.closed for it in new)
    v = d.viewport(Scale(0.001), (0.0, 0.0), (100.0, 100.0))
    assert v.paper_dir((0.0, 1.0)) == (0.0, -1.0)


def test_linkage_sheet_states_the_scales_verify_reads() -> None:
    """The scales a linkage file's build reports (for verify) are the ones its sheet draws."""
    from pathlib import Path

    from geomcad import documents
    from geomcad.sheet.scale import fmt_number

    path = Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml"
    sol = documents.solve(str(path))
    texts = " | ".join(t.text for t in sol.sheets()[0][1].texts())
    assert f"μV = {fmt_number(sol.scales['v'])} (м/с)/мм" in texts
    assert f"μa = {fmt_number(sol.scales['a'])} (м/с²)/мм" in texts
    assert f"μl = {fmt_number(sol.scales['l'])} м/мм" in texts


def test_a_stretch_view_keeps_its_least_and_fixed_children_stay_in_their_box() -> None:
    """The search does not squeeze a diagram below its least size for a larger figure, and a
    column of tables taller than its box is cut back at the box's end (it counts as not
    fitting), not laid past it."""
    dg = Diagram(AxisSpec("x", "m"), AxisSpec("y", "N"), [Curve([0, 1, 2], [0, 1, 0])],
                 least=(150.0, 60.0), prefer=(200.0, 80.0))  # fmt: skip
    big = _fig(1.0, 1.0, weight=4.0)
    lay = arrange(Row(dg, big), Field.of_format("A3"))
    assert lay[dg].box[2] - lay[dg].box[0] >= 150.0
    tall = [Table([["a", "b"]] * 12, title=f"T{i}") for i in range(4)]
    field = Field.of_format("A4")
    lay = arrange(Row(_fig(0.1, 0.1), Column(*tall)), field)
    assert all(lay[t].box[3] <= field.box[3] + 1e-9 for t in tall)


def test_least_k_keeps_a_scale_the_task_fixes() -> None:
    """A view's ``least_k`` holds its scale at or above it even where a finer one fits."""
    free, held = _fig(0.1, 0.1), _fig(0.1, 0.1, least_k=0.005)
    lay = arrange(Row(free, held), Field.of_format("A3"))
    assert lay[free].scale is not None and lay[free].scale.k < 0.005
    assert lay[held].scale is not None and lay[held].scale.k == pytest.approx(0.005)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_order_of_construction_writes_every_step_of_a_general_kind(lang: str) -> None:
    """Every recorded step of a general kind (the recorder's verbs) gives a line the sheet can
    draw in either language, whatever its names (spaces, colons, signs the font lacks); a step
    of no kind is refused, naming the step, rather than written in the recorder's English."""
    import geomcad
    from geomcad.construction import recorder

    general = {k.removeprefix("step.") for k in WORDS_VIEWS.table() if k.startswith("step.")}
    seen = set()
    with language(lang):
        for pid in geomcad.problem_ids():
            for step in geomcad.solve(pid).construction:
                if step.kind in general:
                    seen.add(step.kind)
                    (first, *_rest) = Steps([step], width=160.0, only=[step.name]).lines
                    assert first.startswith("1. ") and "{" not in first.replace("_{", "")
        bare = recorder.Step(1, "X", "something in English", (), None, "construction")
        with pytest.raises(ValueError, match="step 'X = something in English': no template"):
            step_text(bare)
    assert {"given", "intersection", "circle", "perpendicular"} <= seen


def test_the_checker_finds_a_vector_at_a_scale_the_sheet_does_not_state() -> None:
    """A plan's vector drawn through a viewport whose μ no text states is a layout problem;
    stated (as the views' titles write it), it is not."""
    d = start("A4", TitleBlock("t", "d"))
    v = d.viewport(Scale(0.02, "v"), (0.0, 0.0), (60.0, 100.0))
    v.arrow((0.0, 0.0), (1.0, 0.5), "vector")
    sheet = d.finish()
    assert any("not at a stated μ" in p for p in layout_problems(sheet))
    d = start("A4", TitleBlock("t", "d"))
    v = d.viewport(Scale(0.02, "v"), (0.0, 0.0), (60.0, 100.0))
    v.arrow((0.0, 0.0), (1.0, 0.5), "vector")
    d.text("План скоростей, μ_V = 0,02 (м/с)/мм", (60.0, 40.0), 3.5)
    d.text("μ_V = 0,05 (м/с)/мм", (60.0, 50.0), 3.5)  # another μ does not count
    assert layout_problems(d.finish()) == []


def test_least_room_is_necessary_for_the_wanted_scales() -> None:
    """Where no least size of a tree fits a field (formats.may_reach is False), the search's
    arrangement there does not draw the wanted views at their scales; and the test does say
    False for some of these trees (it saves searches) and True for others."""
    from geomcad.sheet.compose import Choice, Field, Grid, Row, Spacer, arrange, least_room
    from geomcad.sheet.formats import may_reach, meets

    said = set()
    for fmt, k, cols in itertools.product(("A4", "A3", "A2"), (0.001, 0.002, 0.004), (None, 2)):
        mech = Figure((0.0, 0.0, 0.5, 0.3), lambda v: None, title="M")
        plans = [Figure((0.0, 0.0, 0.2, 0.2), lambda v: None, title=f"P{i}") for i in range(4)]
        table = Spacer((120.0, 60.0))
        tree = Choice(
            Row(mech, Grid(*plans, cols=cols)),
            Column(Row(mech, table), Grid(*plans, cols=cols)),
        )
        wants = {mech: k, plans[0]: 2 * k}
        field = Field.of_format(fmt, fmt != "A4")
        ok = may_reach(tree, wants, field)
        said.add(ok)
        assert least_room(tree, wants)
        if not ok:
            for v, kk in wants.items():
                v.readable = kk * v.readable_mm
            try:
                lay = arrange(tree, field)
            except ParameterError:
                continue
            assert not meets(lay, wants), (fmt, k, cols)
    assert said == {True, False}


def test_least_room_of_a_row() -> None:
    """A wanted view's drawing at its scale with margins and title, a fixed child's natural
    width and the gap along a row; the tallest child across it."""
    from geomcad.sheet.compose import GAP, Row, Spacer, least_room, natural_of

    a = Figure((0.0, 0.0, 0.2, 0.1), lambda v: None, title="A", margin=4.0)
    s = Spacer((50.0, 300.0))
    k = 0.002 * (1 + 1e-9)
    ((w, h),) = least_room(Row(a, s), {a: 0.002})
    nat = natural_of(s)
    assert nat is not None
    assert w == pytest.approx(0.2 / k + 8.0 + nat[0] + GAP, rel=1e-6)
    assert h == pytest.approx(0.1 / k + 8.0 + a.title_room(), rel=1e-6)


def test_a_title_wider_than_its_box_breaks_into_lines_whose_room_counts() -> None:
    """A view's (or a node's) title wider than the box it gets is written in lines within the
    box, never past it into the next view; the drawing starts under the last line; a short
    title stays on one line."""
    from geomcad.sheet.compose import TITLE_SPACING, text_width

    long = "Приведённые моменты, работы, приращение кинетической энергии, момент инерции"
    a = _fig(0.2, 0.3, title=long, quantity="v", series="nice", show_scale=False)
    b = _fig(0.2, 0.3, title="B", show_scale=False)
    node_title = "Диаграммы выходного звена и угловые скорости звеньев механизма по положениям"
    c = _fig(0.2, 0.1, show_scale=False)
    tree = Row(a, b, Column(c, title=node_title))
    d = start("A4", TitleBlock(title="t", designation="x"))
    lay = compose(d, tree, Field.of(d.frame))
    sheet = d.finish()
    box = lay[a].box
    assert text_width(long, a.title_height) > box[2] - box[0]  # it cannot stand on one line
    lines = [t for t in sheet.texts() if t.text in long and t.text != "B" and len(t.text) > 3]
    assert len(lines) >= 2 and " ".join(t.text for t in lines) == long
    assert all(box[0] - 1e-6 <= t.at[0] and t.at[0] + t.width <= box[2] + 1e-6 for t in lines)
    last = max(t.at[1] for t in lines)
    assert lay[a].inner[1] >= last  # the drawing under the title's last line
    assert a.title_lines == len(lines)
    assert lay[a].inner[1] - box[1] >= a.title_height * (1 + (len(lines) - 1) * TITLE_SPACING)
    assert b.title_lines == 1
    cell = next(cl for cl, node in lay.titles if node.title == node_title)
    parts = [t for t in sheet.texts() if t.text in node_title and len(t.text) > 3]
    assert len(parts) >= 2 and all(t.at[0] + t.width <= cell[2] + 1e-6 for t in parts)
    assert lay[c].box[1] >= max(t.at[1] for t in parts)
