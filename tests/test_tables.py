"""The data and results tables written from the specs (issue 14): ``Param``/``ResultSpec`` say
their symbol, display unit and significant figures once, ``Table.of_specs`` writes them in the
language being drawn."""

from __future__ import annotations

import pytest

from geomcad.problem import Param, ResultSpec
from geomcad.registry import get, problem_ids
from geomcad.sheet.lang import language
from geomcad.sheet.views import Table
from geomcad.units import DISPLAY, to_display

PARAMS = (
    Param("m", 0.01, "module", "m", gt=0.0, display="mm"),
    Param("alpha_deg", 20.0, "profile angle", "deg"),
    Param("z", 40, "teeth", "1", integer=True),
    Param("law", "linear", "law", choices=("linear", "harmonic")),
)
RESULTS = (
    ResultSpec("F_max", "N", "largest force", "F", display="kN"),
    ResultSpec("omega1", "rad/s", "crank speed"),
    ResultSpec("r_D", "m", "radius", digits=2),
    ResultSpec("u13_H2", "1", "ratio", symbol="u_{13}^{(H2)}"),
    ResultSpec("r", "m", "radii at the division points"),
)
VALUES = {"F_max": 282743.3, "omega1": 157.0796, "r_D": 0.2056, "u13_H2": -65.45, "r": [0.1]}


def test_a_spec_writes_its_symbol_display_unit_and_figures_in_each_language() -> None:
    with language("ru"):
        t = Table.of_specs(RESULTS, VALUES)
        assert t.rows == [
            ["Величина", "Значение", "Ед."],
            ["F_{max}", "282,7", "кН"],
            ["ω_1", "157,1", "рад/с"],
            ["r_D", "0,21", "м"],
            ["u_{13}^{(H2)}", "–65,45", ""],
        ]  # the list result "r" is a table of its own
    with language("en"):
        t = Table.of_specs(RESULTS, VALUES, style="value")
        assert t.rows[1:3] == [["F_{max}", "282.7 kN"], ["ω_1", "157.1 rad/s"]]


def test_the_data_are_headed_parameter_integers_whole_choices_as_words() -> None:
    values = {"m": 0.01, "alpha_deg": 20.0, "z": 40, "law": "S = aφ"}
    with language("ru"):
        t = Table.of_specs(PARAMS, values, style="value")
        assert t.rows == [
            ["Параметр", "Значение"],
            ["m", "10 мм"],
            ["α", "20°"],  # no space before the degree sign
            ["z", "40"],
            ["law", "S = aφ"],
        ]
        t = Table.of_specs(PARAMS[:3], values, style="label", labels={"z": "z_1"})
        assert t.rows[1:] == [["m, мм", "10"], ["α, °", "20"], ["z_1", "40"]]
        t = Table.of_specs(PARAMS[:3], values, style="equation", pairs=2, head=["a", "b"])
        assert t.rows == [["a", "b"], ["m = 10 мм", "z = 40"], ["α = 20°", ""]]  # down, then on


def test_pairs_transpose_and_an_extra_column() -> None:
    values = {"m": 0.01, "alpha_deg": 20.0, "z": 40}
    with language("en"):
        t = Table.of_specs(PARAMS[:3], values, style="label", transpose=True)
        assert t.rows == [["m, mm", "α, °", "z"], ["10", "20", "40"]]
        t = Table.of_specs(
            RESULTS[:2], VALUES, style="value", pairs=2, extra=("on the plan", lambda s, x: s.unit)
        )
        assert t.rows == [
            ["Quantity", "Value", "on the plan"] * 2,
            ["F_{max}", "282.7 kN", "N", "ω_1", "157.1 rad/s", "rad/s"],
        ]


def test_a_display_unit_is_checked_against_the_si_unit() -> None:
    assert to_display(0.0025, "m", "mm") == 2.5
    assert to_display(37600.0, "N", "kN") == 37.6
    assert to_display(2.0, "m", "") == 2.0
    with language("ru"):  # an integer in another unit is converted too
        assert Table.of_specs(RESULTS[:1], {"F_max": 1500}).rows[1] == ["F_{max}", "1,5", "кН"]
    with pytest.raises(ValueError, match="cannot write a quantity in 'N' in 'mm'"):
        ResultSpec("F", "N", "force", display="mm")
    with pytest.raises(ValueError, match="F"):
        Param("F", 1.0, "force", "N", display="kJ")
    for display, (si, _) in DISPLAY.items():
        assert to_display(1.0, si, display) > 0.0


@pytest.mark.parametrize("pid", problem_ids())
def test_every_spec_has_a_unit_the_tables_write(pid: str) -> None:
    """Each problem's parameters and results write their unit in both languages (a unit the
    views' words do not know would be written as its SI key)."""
    from geomcad.sheet.views import WORDS

    problem = get(pid)
    for spec in (*problem.params, *problem.results):
        unit = spec.display or spec.unit
        if unit in ("1", ""):
            continue
        for lang in ("ru", "en"):
            assert f"unit.{unit}" in WORDS.table(lang), (pid, spec.name, unit)


def test_a_series_table_heads_each_column_with_its_symbol_and_display_unit() -> None:
    phi = ResultSpec("phi", "rad", "angles", symbol="φ_i", display="deg")
    S = ResultSpec("S", "m", "displacements", symbol="S_i", display="mm")
    with language("ru"):
        t = Table.of_series([(phi, [0.0, 0.3926990817]), (S, [0.0, 0.005])], index=("i", "01"))
    assert t.rows == [["i", "φ_i, °", "S_i, мм"], ["0", "0", "0"], ["1", "22,5", "5"]]


def test_a_table_filled_to_a_width_keeps_its_columns_in_proportion() -> None:
    narrow = Table([["a", "bb"], ["1", "22"]])
    wide = Table([["a", "bb"], ["1", "22"]], fill=3.0 * sum(narrow.widths))
    assert wide.widths == pytest.approx([3.0 * w for w in narrow.widths])
    assert Table([["a", "bb"]], fill=1.0).widths == narrow.widths  # never narrower


def test_groups_side_by_side_read_down_or_across() -> None:
    """Five entries in two groups of columns: read down the first group, then the next (the
    default), or along the rows (``across``); a blank pair fills the last row either way."""
    from geomcad.sheet.views import side_by_side

    entries = [[f"q{i}", str(i)] for i in range(1, 6)]
    down = side_by_side(entries, 2)
    assert [r[0::2] for r in down] == [["q1", "q4"], ["q2", "q5"], ["q3", ""]]
    across = side_by_side(entries, 2, across=True)
    assert [r[0::2] for r in across] == [["q1", "q2"], ["q3", "q4"], ["q5", ""]]
    t = Table.of_entries(entries, ("Нагрузка", "Значение"), pairs=2, across=True)
    assert t.rows[0] == ["Нагрузка", "Значение"] * 2
    assert t.rows[1:] == across
    assert Table.of_entries(entries, ("a", "b"), pairs=2).rows[1:] == down
