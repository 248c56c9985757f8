"""Drawing rules the dynamics sheets (2013-9, kulisa-23110713) rely on: a curved arrow's head on
its arc at any radius, a table column with one count of decimals, a vanishing check value
written with its symbol and kept on one line, two moments about one point told apart."""

from __future__ import annotations

import math

import pytest

from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.drawing import ARROW_LEN, Viewport
from geomcad.sheet.free_body import facing, small
from geomcad.sheet.lang import language
from geomcad.sheet.loads import MOMENT_SWEEP
from geomcad.sheet.model import ArcItem, Polyline
from geomcad.sheet.scale import fmt_column
from geomcad.sheet.text import wrap


@pytest.mark.parametrize("r_mm", [5.0, 9.0, 20.0, 40.0])
@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_a_curved_arrows_shaft_reaches_its_head_at_any_radius(r_mm: float, sense: float) -> None:
    d = start("A4", TitleBlock(title="t", designation="d"))
    v = Viewport(d, Scale(1.0), 0.0, 0.0, (100.0, 150.0))
    first = len(d.sheet.items)
    v.turn((0.0, 0.0), sense, 30.0, "", r_mm=r_mm, sweep_deg=250.0)
    new = d.sheet.items[first:]
    (arc,) = (it for it in new if isinstance(it, ArcItem))
    (head,) = (it for it in new if isinstance(it, Polyline) and it.fill)
    tip = head.points[0]
    assert math.isclose(math.dist(tip, arc.c), r_mm, rel_tol=1e-9)
    # the shaft ends inside the head's length, not an arc's angle away from it
    assert math.dist(arc.end, tip) <= ARROW_LEN


def test_a_column_has_one_count_of_decimals() -> None:
    assert fmt_column([0.0, 1.83, 3.87, 9.078], "ru") == ["0,000", "1,830", "3,870", "9,078"]
    assert fmt_column([0.0, 0.05, 0.1, 0.5], "en") == ["0.00", "0.05", "0.10", "0.50"]
    assert fmt_column([0.0, 15.0, 360.0], "en") == ["0", "15", "360"]
    assert fmt_column([-1e-17, -0.1308, 2.525], "en") == ["0.000", "–0.131", "2.525"]


def test_a_vanishing_check_value_has_its_symbol_and_stays_on_one_line() -> None:
    with language("ru"):
        tiny = small(1e-12, 2.0, "Н·м", "M_у")
        big = small(0.5, 2.0, "Н·м", "M_у")
    assert "·|" not in tiny and tiny.startswith("|M_у|") and tiny.endswith("Н·м")
    assert big.replace("\u00a0", " ") == "M_у = 0,5 Н·м"
    text = f"проверка: момент {tiny}, т.е. 0 – кинетостатика совпадает с уравнением движения."
    for width in (40.0, 60.0, 80.0):
        assert any(tiny in line for line in wrap(text, width, 2.5))


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_two_moments_about_one_point_face_one_direction(sense: float) -> None:
    sweep = math.degrees(MOMENT_SWEEP)
    mid = facing(sense, 225.0) + sense * sweep / 2.0
    gap = facing(sense, 225.0, True) + sense * (sweep + (360.0 - sweep) / 2.0)
    assert math.isclose(mid % 360.0, 225.0) and math.isclose(gap % 360.0, 225.0)
