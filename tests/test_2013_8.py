"""2013-8: the punch press. The seed's values, the exact ones against the check formulas, the
restored energy formula, the seed's J from rounded speeds, variants, bad input, the sheet."""

from __future__ import annotations

import math

import pytest
from layout import labels, layout_problems

import geomcad
from geomcad.cli import main
from geomcad.errors import ParameterError

PID = "2013-8"
REL = 1e-12


def check(d: float, h: float, tau: float, n: float, delta: float, z: float) -> dict[str, float]:
    """problems.md's check formulas."""
    f_max = math.pi * d * h * tau
    E = f_max * h / 2.0
    w_max = math.pi * n / 30.0
    w_min = w_max * (2.0 - delta) / (2.0 + delta)
    return {
        "F_max": f_max,
        "E": E,
        "N": E * z,
        "omega_max": w_max,
        "omega_min": w_min,
        "J": 2.0 * E / (w_max**2 - w_min**2),
    }


def test_seed_values_within_their_rounding() -> None:
    sol = geomcad.solve(PID)
    rows = {r["name"]: r for r in sol.seed_report()}
    for name in ("F_max", "N", "omega_max", "omega_min"):
        assert rows[name]["class"] == "rounded" and rows[name]["agrees"], rows[name]
    r = sol.results
    assert abs(r["F_max"] / 1000 - 282.7) <= 0.05
    assert abs(r["N"] - 4241) <= 0.5
    assert abs(r["omega_max"] - 157) <= 0.5 and abs(r["omega_min"] - 142) <= 0.5


def test_exact_values_against_the_check_formulas() -> None:
    r = geomcad.solve(PID).results
    for name, value in check(0.05, 0.03, 6e7, 1500, 0.1, 1).items():
        assert r[name] == pytest.approx(value, rel=REL), name
    assert r["F_max"] == pytest.approx(282743.338823, rel=1e-11)
    assert r["E"] == pytest.approx(4241.150082, rel=1e-9)
    assert r["omega_min"] == pytest.approx(r["omega_max"] * 19 / 21, rel=REL)
    assert r["J"] == pytest.approx(2 * 4241.150082 * 441 / (80 * 2500 * math.pi**2), rel=1e-9)


def test_restored_energy_formula_is_the_load_diagrams_area() -> None:
    """The seed lost E's formula: the area of the triangle F(s) from F_max to 0 over h."""
    sol = geomcad.solve(PID)
    s, F = sol.construction["F(s)"]
    assert list(s) == [0.0, 0.03] and F[0] == sol.results["F_max"] and F[-1] == 0.0
    assert sol.results["E"] == pytest.approx(sol.results["F_max"] * 0.03 / 2, rel=REL)
    assert sol.results["N"] == pytest.approx(4241, abs=0.5)  # the seed's N = E/t holds
    assert any("restored" in n and "F_max·h/2" in n for n in sol.notes)


def test_erratum_seed_J_comes_from_rounded_speeds() -> None:
    """The seed's 1,89 is 2·4241/(157² − 142²) = 1,891; the exact speeds give 1,8951 ≈ 1,90."""
    sol = geomcad.solve(PID)
    assert pytest.approx(1.89, abs=0.005) == 2 * 4241 / (157**2 - 142**2)
    assert sol.problem.seed["J"].kind == "erratum"
    assert abs(sol.results["J"] - 1.89) > 0.005
    assert round(sol.results["J"], 2) == 1.90
    assert any(n.startswith("erratum J") and "rounded speeds" in n for n in sol.notes)


@pytest.mark.parametrize(
    "params",
    [
        {"d_hole": 0.02, "h_plate": 0.01, "delta": 0.05},
        {"n_rpm": 3000, "holes_per_s": 2.5, "tau": 3e8},
        {"delta": 1.5},
    ],
)
def test_variants(params: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **params)
    assert sol.seed == {} and sol.diff == {}
    p = {"d_hole": 0.05, "h_plate": 0.03, "tau": 6e7, "n_rpm": 1500, "delta": 0.1,
         "holes_per_s": 1, **params}  # fmt: skip
    for name, value in check(*(float(p[k]) for k in p)).items():
        assert sol.results[name] == pytest.approx(value, rel=REL), name
    assert not layout_problems(sol.sheets()[0][1])


BAD = [
    ({"delta": 0.0}, ParameterError, r"delta = 0\.0: .*must be > 0 .*infinite flywheel"),
    ({"delta": 2.0}, ParameterError, r"delta = 2\.0: δ must be < 2"),
    ({"delta": 5.0}, ParameterError, r"ω_min ≤ 0"),
    ({"delta": -0.1}, ParameterError, r"delta = -0\.1"),
    ({"n_rpm": 0.0}, ParameterError, r"n_rpm = 0\.0: must be > 0"),
    ({"h_plate": -0.01}, ParameterError, r"h_plate"),
    ({"holes_per_s": 0}, ParameterError, r"holes_per_s"),
    ({"tau": "x"}, ParameterError, r"must be a number"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


@pytest.mark.parametrize(
    ("setting", "words"),
    [("delta=0", "delta"), ("delta=2", "δ must be < 2"), ("n_rpm=-5", "n_rpm")],
)
def test_bad_input_through_the_cli(
    capsys: pytest.CaptureFixture[str], setting: str, words: str
) -> None:
    code = main(["solve", PID, "--set", setting])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {PID}: ") and words in lines[0]


def test_the_sheet() -> None:
    ((name, sheet),) = geomcad.solve(PID).sheets()
    assert name == ""
    assert not layout_problems(sheet)
    assert {"s = h", "ω = ωmax", "1", "2", "3", "маховик", "двигатель"} <= labels(sheet)
    texts = " ".join(t.text for t in sheet.texts())
    assert "E = Fmax·h/2 = 4241 Дж" in texts
    assert "Fmax = 282,7 кН" in texts and "ω = ωmin" in texts
    assert "μF = 4 кН/мм" in texts  # the load diagram's force scale (under графа 26)


def test_speeds_are_not_written_as_tick_values() -> None:
    """ω_max and ω_min name the energy diagram's top and foot inside its field: no such text
    stands left of the ΔT axis or under the t axis, where the tick values are."""
    sheet = geomcad.solve(PID).sheets()[0][1]
    texts = sheet.texts()
    ticks = [t for t in texts if t.text in ("0,2", "4000")]
    t_row = max(t.at[1] for t in ticks if t.text == "0,2")  # the lower graph's x tick values
    y_col = max(t.at[0] + t.width for t in ticks if t.text == "4000")
    for t in texts:
        if t.text.startswith("ω = "):
            assert t.at[0] > y_col and t.at[1] < t_row - 2.0, t


def test_the_solution_is_written_from_the_recorded_steps() -> None:
    """The sheet's "Решение" lists the recorded steps through their kinds' templates: one
    numbered line per step, each value the recorded one; a variant's values follow."""
    from geomcad.sheet.scale import fmt_number

    sol = geomcad.solve(PID, delta=0.05)
    texts = [t.text for t in sol.sheets()[0][1].texts() if t.height <= 2.5]  # not view titles
    numbered = [t for t in texts if t[:3] in {f"{i}. " for i in range(1, 10)}]
    assert [t[:2] for t in numbered] == ["1.", "2.", "3.", "4.", "5.", "6."]
    J = fmt_number(sol.construction["J"], "ru", 4)
    assert numbered[-1].endswith(f"J = 2E/(ωmax2 – ωmin2) = {J} кг·м².")
    assert fmt_number(geomcad.solve(PID).results["J"], "ru", 4) != J
