"""2013-5: the seed's values, the exact ratio, the seed's errata, the check by the mesh equations,
the graphical ratio equal to Willis', optional tooth counts, bad input, and the sheet."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
from geomcad_constructions import p2013_5, spec_2013_5
from hypothesis import given, settings
from hypothesis import strategies as st

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, ParameterError


def willis_by_hand(z1: int, z2: int, z3: int, z5: int, z6: int) -> Fraction:
    """u_1H2 from the seed's chain, written out afresh with the coaxial z4 and z7."""
    z4, z7 = z2 - z1 - z3, z5 + 2 * z6
    u13 = Fraction(z2, z1) * (1 + Fraction(z7, z5)) * Fraction(-z3, z4)
    return 1 - u13


def test_seed_values_within_their_precision_except_the_erratum() -> None:
    sol = geomcad.solve("2013-5")
    rows = {r["name"]: r for r in sol.seed_report()}
    assert {n for n, r in rows.items() if r["class"] == "erratum"} == {"u1H2"}
    for name, row in rows.items():
        if name != "u1H2":
            assert row["agrees"], row


def test_exact_values() -> None:
    r = geomcad.solve("2013-5").results
    assert r["W"] == 1 and r["z4"] == 20 and r["z7"] == 74
    assert all(isinstance(r[n], int) for n in ("W", "z4", "z7"))
    assert r["u12"] == 5.0 and r["u43"] == -3.0
    assert r["u5H1_7"] == pytest.approx(48 / 11, rel=1e-15)
    assert r["u13_H2"] == pytest.approx(-720 / 11, rel=1e-15)
    assert r["u1H2"] == pytest.approx(731 / 11, rel=1e-15)
    assert r["u1H2_fraction"] == [731, 11]
    assert Fraction(*r["u1H2_fraction"]) == willis_by_hand(20, 100, 60, 22, 26)


def test_seed_erratum_u1h2_multiplies_a_rounded_ratio() -> None:
    """The seed rounds u_5H1^(7) = 1 + 74/22 to 4,364 and then gets 1 + 5·4,364·3 = 66,46; the
    exact 1 + 5·(48/11)·3 = 731/11 = 66,4545… prints as 66,45."""
    assert round(1 + 74 / 22, 3) == 4.364
    assert round(1 + 5 * 4.364 * 3, 2) == 66.46
    assert round(731 / 11, 2) == 66.45
    sol = geomcad.solve("2013-5")
    assert sol.diff["u1H2"] == pytest.approx(731 / 11 - 66.46, abs=1e-12)
    note = next(n for n in sol.notes if n.startswith("erratum u1H2:"))
    assert "731/11" in note and "4,364" in note


def test_seed_erratum_the_coaxiality_condition_for_z4_is_misprinted() -> None:
    """The seed prints z1 − z2 = z4 + z3; taken literally, 20 − 100 = z4 + 60 gives z4 = −140,
    no gear. The centre distances m(z2 − z1)/2 (internal 1–2) and m(z3 + z4)/2 (external 4–3)
    must agree: z2 − z1 = z3 + z4, which gives the seed's own z4 = 20."""
    assert 20 - 100 - 60 == -140
    assert 100 - 20 - 60 == 20
    assert spec_2013_5.SEED_Z4_FORMULA == "z1 − z2 = z4 + z3"
    assert spec_2013_5.CORRECT_Z4_FORMULA == "z2 − z1 = z3 + z4"
    sol = geomcad.solve("2013-5")
    assert any("misprint" in n and "z2 − z1 = z3 + z4" in n for n in sol.notes)
    assert sol.construction.step("a_12").result == 40.0


def test_check_by_the_mesh_equations() -> None:
    sol = geomcad.solve("2013-5")
    w = sol.data.omega_exact
    assert w[p2013_5.SUN] == Fraction(731, 11)
    assert w[p2013_5.H2] == 1
    assert w[p2013_5.FRAME] == 0
    # each mesh equation holds exactly
    z = {"1": 20, "2": 100, "3": 60, "4": 20, "5": 22, "6": 26, "7": 74}
    S, B, P, H1, H2 = (w[k] for k in ("1", "2-5", "6", "H1-4", "H2-7"))
    assert z["1"] * (S - H2) - z["2"] * (B - H2) == 0  # internal 1–2 on H2
    assert z["5"] * (B - H1) + z["6"] * (P - H1) == 0  # external 5–6 on H1
    assert z["6"] * (P - H1) - z["7"] * (H2 - H1) == 0  # internal 6–7 on H1
    assert z["4"] * (H1 - H2) + z["3"] * (0 - H2) == 0  # external 4–3 on H2


def test_the_graphical_ratio_equals_willis() -> None:
    sol = geomcad.solve("2013-5")
    c = sol.construction
    assert c["u1H2 (plan)"] == pytest.approx(731 / 11, rel=1e-12)
    assert c["u1H2 (angle diagram)"] == pytest.approx(731 / 11, rel=1e-12)
    plan = sol.data.plan
    for link, exact in sol.data.omega_exact.items():
        assert plan.omega[link] == pytest.approx(float(exact), rel=1e-12, abs=1e-15)
    assert plan.order == ("H2-7", "H1-4", "6", "2-5", "1")


@settings(max_examples=40, deadline=None)
@given(
    z1=st.integers(12, 40),
    z3=st.integers(12, 60),
    gap=st.integers(1, 40),
    z5=st.integers(12, 50),
    z6=st.integers(12, 50),
)
def test_variants_graphical_equals_willis_equals_mesh_equations(
    z1: int, z3: int, gap: int, z5: int, z6: int
) -> None:
    z2 = z1 + z3 + gap  # so that z4 = gap ≥ 1
    sol = geomcad.solve("2013-5", z1=z1, z2=z2, z3=z3, z5=z5, z6=z6)
    exact = willis_by_hand(z1, z2, z3, z5, z6)
    r = sol.results
    assert Fraction(*r["u1H2_fraction"]) == exact
    assert r["z4"] == gap and r["z7"] == z5 + 2 * z6
    assert sol.data.omega_exact[p2013_5.SUN] == exact
    assert sol.construction["u1H2 (plan)"] == pytest.approx(float(exact), rel=1e-10)
    assert sol.construction["u1H2 (angle diagram)"] == pytest.approx(float(exact), rel=1e-10)
    assert sol.seed == {}


def test_optional_counts_given_explicitly() -> None:
    sol = geomcad.solve("2013-5", z4=20, z7=74)
    assert sol.results["u1H2_fraction"] == [731, 11]
    assert sol.params["z4"] == 20
    assert sol.construction.step("z4").op.startswith("given")
    # None means "not given": the seed's data again
    assert geomcad.solve("2013-5", z4=None).is_seed


BAD = [
    ({"z4": 21}, ParameterError, r"parameter z4 = 21: breaks coaxiality: .* z2 − z1 − z3 = 20"),
    ({"z7": 70}, ParameterError, r"parameter z7 = 70: breaks coaxiality: .* z7 = z5 \+ 2·z6 = 74"),
    ({"z3": 90, "z4": 5}, ParameterError, r"z4 = 5: breaks coaxiality: .* = -10, which no gear"),
    ({"z3": 90}, ConstructionError, r'step "z4 = z2 − z1 − z3 \(coaxiality .*\)": it gives -10'),
    ({"z3": 80}, ConstructionError, r'step "z4 = .*": it gives 0 teeth'),
    ({"z4": 0}, ParameterError, r"parameter z4 = 0: must be ≥ 1"),
    ({"z4": -20}, ParameterError, r"parameter z4 = -20: must be ≥ 1"),
    ({"z4": 2.5}, ParameterError, r"parameter z4 = 2\.5: must be a whole number"),
    ({"z1": 0}, ParameterError, r"parameter z1 = 0: must be ≥ 1"),
    ({"z6": 0}, ParameterError, r"parameter z6 = 0: must be ≥ 1"),
    ({"z2": 20}, ParameterError, r"parameter z2 = 20: the ring 2 .* more teeth than z1 = 20"),
    ({"m": 0.0}, ParameterError, r"parameter m = 0\.0: must be > 0"),
    ({"z5": "a"}, ParameterError, r"parameter z5 = 'a': must be a number"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve("2013-5", **params)


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_cli(
    params: dict[str, object], exc: type, words: str, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = ["solve", "2013-5", "--json"]
    for k, v in params.items():
        argv += ["--set", f"{k}={v}"]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: 2013-5: "), err
    if exc is ParameterError:
        assert f"parameter {next(iter(params))}" in lines[0] or "parameter" in lines[0]


def test_solve_json_keeps_counts_as_integers(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["solve", "2013-5", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["results"]["u1H2_fraction"] == [731, 11]
    assert data["results"]["z4"] == 20 and isinstance(data["results"]["z4"], int)
    assert "z4" not in data["params"]
    assert data["seed"]["u1H2"] == 66.46


def test_the_sheet_has_the_scheme_the_plan_and_the_angle_diagram() -> None:
    sol = geomcad.solve("2013-5")
    ((_, sheet),) = sol.sheets()
    texts = [t.text for t in sheet.texts()]
    assert "1:2" in texts
    assert any("План линейных скоростей" in t for t in texts)
    # the quotient of the printed segments, to 3 figures: 166,1/2,5 = 66,44 → 66,4
    assert any(t.startswith("u1H2 = ω1/ωH2 = 166,1/2,5 = 66,4") for t in texts)
    assert not any("66,4545" in t for t in texts)
    # velocities shorter than two arrowheads are points, named in a note
    assert any("b, f" in t for t in texts)
    for name in ("a", "b", "c", "d", "e", "f", "o", "S"):
        assert name in texts
    assert sol.scales == {"l": 0.002, "v": 0.025}


@pytest.mark.parametrize(
    "params",
    [{}, {"z1": 18, "z2": 90, "z3": 48, "z5": 20, "z6": 30, "m": 0.003},
     {"z1": 30, "z2": 60, "z3": 12, "z5": 40, "z6": 12}, {"z1": 12, "z2": 140, "z3": 100,
     "z5": 15, "z6": 60, "m": 0.001}],
    ids=["seed", "v1", "v2", "v3"],
)  # fmt: skip
def test_sheet_layout(params: dict[str, float]) -> None:
    """No text on another, everything inside the frame and off the title block, the scheme and
    the plans left of the tables."""
    from layout import layout_problems

    sol = geomcad.solve("2013-5", **params)
    ((_, sheet),) = sol.sheets()
    problems = layout_problems(sheet, drawing_right=260.0)
    assert not problems, "\n".join(problems)


def test_optional_parameters_of_the_problem_machinery() -> None:
    """Param(optional=True) has the default None: absent from the defaults and from the values
    build() receives unless given; None through the API means "not given"."""
    from geomcad.problem import Param

    problem = spec_2013_5.PROBLEM
    assert "z4" not in problem.defaults and "z7" not in problem.defaults
    assert problem.param("z4").optional and problem.param("z4").default is None
    with pytest.raises(ValueError, match="optional parameter has the default None"):
        Param("q", None, "no default, not optional")
    with pytest.raises(ValueError, match="optional parameter has the default None"):
        Param("q", 3, "a default, yet optional", optional=True)
    assert geomcad.solve("2013-5", z4=None, z7=None).params == problem.defaults


def test_the_readable_report_says_which_counts_were_derived(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["solve", "2013-5"]) == 0
    out = capsys.readouterr().out
    assert "z4: not set (derived by the problem)" in out
    assert "z4 = 20" in out
    assert main(["solve", "2013-5", "--set", "z4=20"]) == 0
    out = capsys.readouterr().out
    assert "z4 = 20   (set; default derived by the problem)" in out
