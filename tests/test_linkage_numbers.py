"""How a linkage file's sheets write their numbers (issue 27, point 9): a slider's V, a in
the kinematics tables signed as on its v(φ), a(φ) diagrams; one count of decimals per column
of one quantity; one unit per quantity on the force sheet (table and order of calculation);
every crank angle of a sheet with one count of decimals."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from geomcad.linkage import parse, synthesis
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.lang import language
from geomcad.sheet.scale import angle_places, fmt_fixed

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
KINEMATIC = sorted(
    p.name
    for p in EXAMPLES.glob("*.toml")
    if "drive" in (d := tomllib.loads(p.read_text(encoding="utf-8"))) or synthesis.is_synthesis(d)
)


def _solved(name: str) -> Solved:
    data = tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))
    if synthesis.is_synthesis(data):
        data = synthesis.synthesize(data).linkage
    return solve(parse(data))


def _value(cell: str) -> float:
    return float(cell.replace("\u2013", "-").replace("\u202f", "").replace(",", "."))


def _decimals(cell: str) -> int:
    return len(cell.split(",", 1)[1]) if "," in cell else 0


def test_an_angle_is_written_with_the_sheets_one_count_of_decimals() -> None:
    assert angle_places([0.0, 30.0, 330.0]) == 0
    assert angle_places([3.749, 92.51, 30.0]) == 1
    with language("ru"):
        assert fmt_fixed(3.749, 1) == "3,7"
        assert fmt_fixed(45.0, 1) == "45,0"
        assert fmt_fixed(-0.01, 1) == "0,0"
        assert fmt_fixed(11130.4, 0) == "11\u202f130"


def test_a_sliders_velocity_in_the_table_is_signed_as_on_its_diagram() -> None:
    """slider-crank's V_B: negative on the return stroke, each value's sign that of the v(φ)
    diagram at its position, its magnitude the point's speed."""
    from geomcad.sheet.linkage import _accel_positions, _diagrams, _tables

    s = _solved("slider-crank.toml")
    lk = s.linkage
    with language("ru"):
        table = _tables(s, _accel_positions(s))[0]
        v_diagram = _diagrams(s)[1]
    head, *rows = table.rows
    col = next(i for i, h in enumerate(head) if h.startswith("V_"))
    v = [_value(r[col]) for r in rows]
    assert min(v) < 0.0 < max(v), f"V_B unsigned: {v}"
    exact = v_diagram.curves[0]
    xs, ys = np.asarray(exact.xs), np.asarray(exact.ys)
    n = len(s.drawn)
    for k, (P, vk) in enumerate(zip(s.drawn, v, strict=True)):
        speed = P.vel[lk.output].norm
        assert abs(abs(vk) - speed) <= 0.01 * max(speed, 1.0)
        on_diagram = float(np.interp(360.0 * k / n, xs, ys))
        if abs(on_diagram) > 0.05 * abs(lk.omega) * lk.length:
            assert vk * on_diagram > 0.0, f"position {k}: table {vk}, diagram {on_diagram}"


@pytest.mark.parametrize("name", KINEMATIC)
def test_every_kinematics_column_has_one_count_of_decimals(name: str) -> None:
    from geomcad.sheet.linkage import _accel_positions, _places, _tables

    s = _solved(name)
    with language("ru"):
        tables = _tables(s, _accel_positions(s))
    places = _places(s)
    for t in tables:
        head, *rows = t.rows
        for c, h in enumerate(head):
            counts = {_decimals(r[c]) for r in rows}
            assert len(counts) == 1, f"{name}: column {h!r} mixes decimals: {[r[c] for r in rows]}"
            if h.startswith("φ"):
                assert counts == {places}, f"{name}: the angles' decimals are not the sheet's"


def test_every_crank_angle_of_a_sheet_has_one_count_of_decimals() -> None:
    """four-bar: its positions from 33.75° in steps of 30° (3.749° beside 92.51° before)."""
    from geomcad.sheet.linkage import kinematic_sheets

    s = _solved("four-bar.toml")
    with language("ru"):
        sheets = kinematic_sheets(s, "four-bar")
    angles = [
        m.group(1)
        for _, sheet in sheets
        for t in sheet.texts()
        for m in re.finditer(r"φ_?1 = ([\d,\u2013]+)°", t.text)
    ]
    assert len(angles) >= len(s.drawn)
    assert len({_decimals(a) for a in angles}) == 1, angles
    assert any(a.startswith("3,") for a in angles)


def test_the_force_sheet_writes_each_quantity_in_one_unit_with_one_count_of_decimals() -> None:
    """crusher: the table's forces in the order's Н (not кН beside its Н), its moments in Н·м,
    each quantity's numbers with one count of decimals."""
    from geomcad.sheet.linkage_forces import _table2, force_position, force_sheets

    s = _solved("crusher.toml")
    with language("ru"):
        table = _table2(force_position(s)[1], 2.5)
        sheet = force_sheets(s)[0][1]
    by_unit: dict[str, list[str]] = {}
    for _, value, unit in table.rows[1:]:
        by_unit.setdefault(unit, []).append(value)
    assert set(by_unit) == {"Н", "Н·м"}, set(by_unit)
    for unit, values in by_unit.items():
        # each value (a load of its own) to 4 significant figures, as the order writes it,
        # the column aligned on its decimal comma (issue 27: 88,29 never 88 beside 2200)
        for v in values:
            digits = v.replace("\u2013", "").replace("\u202f", "").replace(",", "")
            assert v == "0" or len(digits.lstrip("0")) >= 4, f"{unit}: {values}"
    texts = " ".join(t.text for t in sheet.texts())
    assert "кН" not in texts
    assert max(_value(v) for v in by_unit["Н"]) >= 1.0e4  # where the table wrote кН before
