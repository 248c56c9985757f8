"""Diagrams (geomcad.sheet.graph): nice factors, axes that hold their range, ticks through zero."""

from __future__ import annotations

import itertools
import math

import pytest

from geomcad.errors import ParameterError
from geomcad.sheet import TitleBlock, start
from geomcad.sheet.graph import Axis, Graph, nice_step


@pytest.mark.parametrize(
    ("raw", "step"), [(0.013, 0.02), (0.02, 0.02), (0.021, 0.025), (3.1, 4.0), (4.5, 5.0), (7, 10)]
)
def test_nice_step(raw: float, step: float) -> None:
    assert nice_step(raw) == pytest.approx(step, rel=1e-12)


def test_axis_fits_its_room_and_ticks_pass_zero() -> None:
    ax = Axis.fit("S", "м", -0.03, 0.11, 70.0)
    assert ax.mm(ax.hi - ax.lo) <= 70.0
    assert ax.mm(ax.hi - ax.lo) > 70.0 / 2.5  # the next nice factor down would not fit
    ticks = ax.ticks()
    assert 0.0 in ticks
    assert all(ax.lo <= t <= ax.hi for t in ticks)
    assert ax.factor_text() == "μ_{S} = 0,002 м/мм"


def test_constant_range_and_bad_range() -> None:
    ax = Axis.fit("J", "кг·м²", 2.0, 2.0, 50.0)
    assert ax.lo == -2.0 and ax.hi == 2.0
    with pytest.raises(ParameterError, match="axis S hi"):
        Axis.fit("S", "м", 0.0, math.nan, 50.0)


def test_graph_places_data_at_scale() -> None:
    d = start("A4", TitleBlock(title="t", designation="x"), landscape=False)
    g = Graph(
        d,
        Axis.fit("φ", "рад", 0.0, 2 * math.pi, 140.0),
        Axis.fit("S", "м", 0, 0.1, 50),
        (40.0, 120.0),
    )
    x, y = g.p(1.0, 0.05)
    assert x == pytest.approx(40.0 + 1.0 / g.x.k)
    assert y == pytest.approx(120.0 - 0.05 / g.y.k)
    g.axes()
    g.curve([0.0, 1.0, 2.0], [0.0, 0.05, 0.02])
    with pytest.raises(ValueError, match="not finite"):
        g.curve([0.0, 1.0], [0.0, math.inf])


def test_ordinate_runs_from_the_axis_to_the_point_and_is_labelled() -> None:
    d = start("A4", TitleBlock(title="t", designation="x"), landscape=False)
    g = Graph(d, Axis.fit("φ", "рад", 0.0, 3.0, 120.0), Axis.fit("S", "м", 0, 0.04, 40), (40, 150))
    n = len(d.sheet.items)
    g.ordinate(1.5, 0.02, "3")
    line = d.sheet.items[n]
    assert line.points == (g.p(1.5, 0.0), g.p(1.5, 0.02))  # type: ignore[attr-defined]
    g.ordinate(0.0, 0.0, "0")  # a point on the axis: no line, only its number
    assert len(d.sheet.items) == n + 1
    sheet = d.finish()
    assert {t.text for t in sheet.texts()} >= {"3", "0"}


def test_table_without_a_header_has_only_thin_rules() -> None:
    d = start("A4", TitleBlock(title="t", designation="x"), landscape=False)
    n = len(d.sheet.items)
    d.table(30.0, 30.0, (10.0, 10.0), [["a", "1"], ["b", "2"]], header=False)
    assert all(it.role != "frame" for it in d.sheet.items[n:])
    d.table(30.0, 60.0, (10.0, 10.0), [["a", "1"], ["b", "2"]])
    assert any(it.role == "frame" for it in d.sheet.items[n:])


def test_x_tick_values_never_run_into_each_other() -> None:
    d = start("A4", TitleBlock(title="t", designation="x"), landscape=False)
    n = len(d.sheet.items)
    g = Graph(
        d, Axis.fit("φ", "рад", 0.0, 0.0877, 180.0), Axis.fit("S", "м", 0, 2.0, 40), (30, 150)
    )
    g.axes()
    values = [it for it in d.sheet.items[n:] if getattr(it, "text", "").startswith("0,")]
    values = [t for t in values if abs(t.at[1] - (150 + 1.5 + 2.5 + 0.8)) < 1e-9]
    assert len(values) >= 3
    for a, b in itertools.pairwise(values):
        assert a.at[0] + a.width + 1.0 <= b.at[0] + 1e-9


def test_tick_values_stay_clear_of_the_curves() -> None:
    """A curve that swings through zero never crosses a tick value: the values are written at
    the plot's bottom and left edges; a line drawn through one (a position's marker) takes it
    off when the sheet is finished, its tick stays."""
    from layout import findings

    from geomcad.sheet.model import Polyline

    d = start("A3", TitleBlock(title="t", designation="x"))
    xs = [i * 2.0 * math.pi / 96 for i in range(97)]
    ys = [math.sin(3.0 * x) for x in xs]
    g = Graph(d, Axis.fit("φ", "рад", 0.0, 2.0 * math.pi, 200.0), Axis.fit("V", "м/с", -1, 1, 80),
              (60.0, 140.0))  # fmt: skip
    g.axes()
    g.curve(xs, ys)
    x1, _ = g.p(1.2, 0.0)
    d.sheet.add(Polyline(((x1, 90.0), (x1, 200.0)), "construction"))
    sheet = d.finish()
    values = [t for t in sheet.texts() if t.text.replace(",", "").replace("–", "").isdigit()]
    bottom = g.box[3]
    row = [t for t in values if t.at[0] > 60.0]  # the x axis's values (the y axis's are left)
    assert row and all(t.at[1] > bottom for t in row)  # under the plot, not at zero
    assert "1,2" not in {t.text for t in values}  # crossed by the marker: left out
    assert {"0,8", "1,6"} <= {t.text for t in row}
    assert not [f for f in findings(sheet) if f.kind in ("tick-label", "label-line")]
