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


def _axis_values(sheet_texts: list[tuple[str, float, float]], x: float) -> list[str]:
    return [t for t, tx, _ in sheet_texts if abs(tx - x) < 1e-6]


@pytest.mark.parametrize(
    ("lo", "hi", "room"), [(0.0, 0.023, 115.0), (13.3, 14.7, 140.0), (-27.0, 1.2, 70.0),
                           (0.0, 9.04, 60.0), (-0.3, 2.5e-4, 50.0)]
)  # fmt: skip
def test_one_decimal_count_per_axis(lo: float, hi: float, room: float) -> None:
    """Every value written along an axis has its axis's decimals (0,016 and 0,020, never 0,02
    beside 0,016; 14,0 beside 14,1): those of the tick step, the same for every tick."""
    d = start("A3", TitleBlock(title="t", designation="x"))
    ay = Axis.fit("S", "м", lo, hi, room)
    n = len(d.sheet.items)
    g = Graph(d, Axis.fit("φ", "град", 0.0, 360.0, 180.0).with_tick(30.0), ay, (60.0, 200.0))
    g.axes()
    left = min(g.at[0], g.box[0]) - 1.5 - 0.8
    texts = [it for it in d.sheet.items[n:] if isinstance(getattr(it, "text", None), str)]
    ys = [t.text for t in texts if abs(t.at[0] + t.width - left) < 1e-6 or t.at[0] < left - 1.0]
    ys = [t for t in ys if any(c.isdigit() for c in t) and t != "0"]
    assert len(ys) >= 3
    decimals = {len(t.split(",")[1]) if "," in t else 0 for t in ys}
    assert len(decimals) == 1, ys
    step = ay.ticks()[1] - ay.ticks()[0]
    (places,) = decimals
    assert abs(step - round(step, places)) <= 1e-9 * step  # every tick written exactly
    assert places == 0 or abs(step - round(step, places - 1)) > 1e-9 * step  # no more


def test_zero_is_written_where_the_x_values_stand_on_the_bottom_edge() -> None:
    """ΔT's "0" on Wittenbauer's diagram: where the plot runs below the I axis (its values on
    the bottom edge), the y axis writes its zero; where the x values stand on the zero axis,
    it does not (the origin)."""
    for lo, zero in ((-27.0, True), (0.0, False)):
        d = start("A3", TitleBlock(title="t", designation="x"))
        n = len(d.sheet.items)
        g = Graph(d, Axis.fit("I", "кг·м²", 0.0, 0.023, 115.0),
                  Axis.fit("ΔT", "Дж", lo, 1.2 if lo else 27.0, 70.0), (60.0, 100.0))  # fmt: skip
        g.axes()
        texts = [it for it in d.sheet.items[n:] if getattr(it, "text", None) == "0"]
        at_zero = [t for t in texts if abs(t.at[1] - (100.0 + 2.5 / 2.0)) < 1e-6]
        assert bool(at_zero) is zero
