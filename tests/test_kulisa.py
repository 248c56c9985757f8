"""kulisa-23110713: the course work. Every result of the report, the exact values against the
check formulas, the energy method against solve_ivp, the Lagrange equation against the
kinetostatics, the balancing force two ways, the report's errata, variants, bad input, sheets."""

from __future__ import annotations

import math

import pytest
from layout import labels, layout_problems

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, ParameterError

PID = "kulisa-23110713"
REL = 1e-12
DEFAULTS = {
    "m1": 80.0, "R1": 0.36, "OA": 0.24, "m2": 20.0, "m3": 25.0, "R3": 0.12, "r3": 0.05,
    "rho3": 0.04, "M": 34.0, "phi_deg": 150.0, "phi0_deg": 0.0,
}  # fmt: skip


def check(p: dict[str, float]) -> dict[str, float]:
    """problems.md's formulas, and the reactions from the flywheel's own balance."""
    I1 = p["m1"] * p["R1"] ** 2 / 2
    kk = p["R3"] / (p["R3"] + p["r3"])
    B = p["m2"] + p["m3"] * (p["R3"] ** 2 + p["rho3"] ** 2) / (p["R3"] + p["r3"]) ** 2
    B *= p["OA"] ** 2
    phi, phi0 = math.radians(p["phi_deg"]), math.radians(p["phi0_deg"])
    i_pr = I1 + B * math.sin(phi) ** 2
    dI = B * math.sin(2 * phi)
    w = math.sqrt(2 * p["M"] * (phi - phi0) / i_pr)
    eps = (p["M"] - 0.5 * dI * w * w) / i_pr
    # the flywheel: M − I1·ε − OA·sin φ·N_x = 0, and its bearing takes −N_x
    n = (p["M"] - I1 * eps) / (p["OA"] * math.sin(phi))
    return {
        "I_pr_A": I1,
        "I_pr_B": B,
        "I_pr": i_pr,
        "dI_pr": dI,
        "omega1": w,
        "eps1": eps,
        "N_A": abs(n),
        "X_O": abs(n),
        "Y_O": 0.0,
        "F_x": abs(p["M"] / (kk * p["OA"] * math.sin(phi))),
    }


def test_the_reports_values() -> None:
    sol = geomcad.solve(PID)
    rows = {r["name"]: r for r in sol.seed_report()}
    for name in ("I_pr_A", "I_pr_B", "I_pr", "dI_pr", "omega1", "Y_O", "F_x"):
        assert rows[name]["class"] == "rounded" and rows[name]["agrees"], rows[name]
    r = sol.results
    assert round(r["I_pr"], 2) == 5.67 and round(r["dI_pr"], 3) == -1.688
    assert round(r["omega1"], 2) == 5.60 and round(r["F_x"], 1) == 401.4
    assert round(r["I_pr_A"], 3) == 5.184 and round(r["I_pr_B"], 3) == 1.949
    assert round(r["I_pr_B"] / 2, 3) == 0.975  # the report's 0,975·sin 2φ·φ'²
    assert r["Y_O"] == 0.0


def test_exact_values_against_the_check_formulas() -> None:
    r = geomcad.solve(PID).results
    for name, value in check(DEFAULTS).items():
        assert r[name] == pytest.approx(value, rel=1e-11, abs=1e-12), name


def test_erratum_eps1_comes_from_rounded_intermediates() -> None:
    """ε1 = 10,66 is (34 + 0,844·5,60²)/5,67 = 10,665; the exact 10,6668 rounds to 10,67."""
    sol = geomcad.solve(PID)
    assert sol.problem.seed["eps1"].kind == "erratum"
    assert round(sol.results["eps1"], 2) == 10.67
    assert pytest.approx(10.665, abs=5e-4) == (34 + 0.844 * 5.60**2) / 5.67
    assert any(n.startswith("erratum eps1") for n in sol.notes)


def test_erratum_reactions_come_from_the_rounded_eps1() -> None:
    """N_A = X_O = 177,2 is (34 − 5,184·10,66)/(0,24·sin 150°); the exact ε1 gives 177,47."""
    sol = geomcad.solve(PID)
    assert pytest.approx(-177.2, abs=0.05) == (34 - 5.184 * 10.66) / (0.24 * 0.5)
    assert sol.results["N_A"] == pytest.approx(177.472, abs=5e-4)
    for name in ("N_A", "X_O"):
        assert sol.problem.seed[name].kind == "erratum"
        assert any(n.startswith(f"erratum {name}") for n in sol.notes)


def test_erratum_printed_inertia_formula() -> None:
    """The printed m3·((R3 + ρ3)/(r3 + R3))² is not the kinetic energy's m3·(R3² + ρ3²)/(r3 + R3)²:
    the report's own 1,949 comes from the second; the first would give B = 2,428."""
    p = DEFAULTS
    printed = (p["m2"] + p["m3"] * ((p["R3"] + p["rho3"]) / (p["r3"] + p["R3"])) ** 2) * 0.24**2
    r = geomcad.solve(PID).results
    assert printed == pytest.approx(2.428, abs=5e-4)
    assert abs(printed - 1.949) > 0.4 and round(r["I_pr_B"], 3) == 1.949
    assert any("((R3 + ρ3)/(r3 + R3))²" in n for n in geomcad.solve(PID).notes)


def test_erratum_sign_of_x_C3() -> None:
    """The roller's centre moves with the yoke (same sign of velocity), so
    x_C3 = x_C30 + k·OA·cos φ, not the report's x_C30 − k·OA·cos φ."""
    from geomcad_constructions.p_kulisa import layout, mechanism

    sol = geomcad.solve(PID)
    lay = layout(0.36, 0.24, 0.12, 0.05)
    _, y_fn, roller_fn = mechanism(80, 0.36, 0.24, 20, 25, 0.12, 0.05, 0.04, 34, lay)
    for phi in (0.3, 1.0, 2.5, 4.0, 5.5):
        v2, vc = float(y_fn(phi).body.vx), float(roller_fn(phi).vx)
        assert v2 * vc > 0.0
        x_c3 = float(roller_fn(phi).x)
        k = 0.12 / 0.17
        assert x_c3 == pytest.approx(lay.x_C30 + k * 0.24 * math.cos(phi), rel=REL)
    assert any("x_C3" in n and "wrong sign" in n for n in sol.notes)


def test_energy_method_against_solve_ivp() -> None:
    from geomcad.dynamics import time_by_energy

    sol = geomcad.solve(PID)
    r = sol.results
    assert r["omega_ode"] == pytest.approx(r["omega1"], rel=1e-9)
    assert r["t_reach"] == pytest.approx(
        time_by_energy(sol.data.model, 0.0, math.radians(150.0)), rel=1e-9
    )
    assert any("DOP853" in n for n in sol.notes)


def test_lagrange_equation_against_the_kinetostatics() -> None:
    """With ε1 from the equation of motion the three bodies are in equilibrium with their
    inertia loads and no balancing moment; the yoke and roller's own balance gives the same N_A:
    N_A = [m2 + m3·(R3² + ρ3²)/(R3 + r3)²]·a2 with a2 = −OA·(ε·sin φ + ω²·cos φ)."""
    sol = geomcad.solve(PID)
    R = sol.data.dynamic
    r = sol.results
    assert abs(R.moment("M_b")) < 1e-12 * 34.0
    phi = math.radians(150.0)
    a2 = -0.24 * (r["eps1"] * math.sin(phi) + r["omega1"] ** 2 * math.cos(phi))
    m_red = 20.0 + 25.0 * (0.12**2 + 0.04**2) / 0.17**2
    assert R.magnitudes["N_A"] == pytest.approx(m_red * a2, rel=1e-12)
    assert r["N_A"] == pytest.approx(abs(m_red * a2), rel=1e-12)


def test_balancing_force_by_equal_power_and_by_kinetostatics() -> None:
    sol = geomcad.solve(PID)
    assert sol.data.F_x_kinetostatic == pytest.approx(sol.results["F_x"], rel=1e-12)
    assert sol.results["F_x"] == pytest.approx(34 / (0.12 / 0.17 * 0.24 * 0.5), rel=REL)


@pytest.mark.parametrize(
    "params",
    [
        {"phi_deg": 60.0},
        {"phi_deg": 300.0, "phi0_deg": 30.0},
        {"OA": 0.1, "R1": 0.5, "m2": 5.0},
        {"phi_deg": 500.0},
        {"M": 2.0, "phi_deg": 90.0},
        {"r3": 0.0, "rho3": 0.0},
    ],
)
def test_variants(params: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **params)
    assert sol.seed == {} and sol.diff == {}
    p = {**DEFAULTS, **params}
    for name, value in check(p).items():
        assert sol.results[name] == pytest.approx(value, rel=1e-10, abs=1e-10), name
    assert sol.results["omega_ode"] == pytest.approx(sol.results["omega1"], rel=1e-9)
    assert abs(sol.data.dynamic.moment("M_b")) < 1e-10 * abs(p["M"])
    for _, sheet in sol.sheets():
        assert not layout_problems(sheet)


BAD = [
    ({"m1": 0.0}, ConstructionError, r'step "I_pr,min = .*zero at φ = 0°'),
    ({"m1": 0.0, "phi0_deg": 40.0}, ConstructionError, r"zero at φ = 180°"),
    ({"m2": -1.0}, ParameterError, r"parameter m2 = -1\.0: the yoke's mass cannot be negative"),
    ({"m3": -25.0}, ParameterError, r"parameter m3 = -25\.0: the roller's mass cannot"),
    ({"m1": -80.0}, ParameterError, r"parameter m1 = -80\.0: the flywheel's mass cannot"),
    ({"M": -5.0}, ConstructionError, r'step "ω1 = .*cannot bring the machine to φ = 150°'),
    ({"M": 0.0}, ConstructionError, r"cannot bring the machine"),
    (
        {"phi_deg": 180.0},
        ConstructionError,
        r'step "F_x = \|M·ω_q1/v_qC3\|: equal power of M and F_x": .*dead position',
    ),
    ({"phi_deg": 360.0}, ConstructionError, r"dead position"),
    ({"phi_deg": 0.0}, ParameterError, r"phi_deg = 0\.0: must be > phi0_deg"),
    ({"R1": 0.0}, ParameterError, r"parameter R1 = 0\.0: must be > 0"),
    ({"rho3": -0.01}, ParameterError, r"rho3"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


@pytest.mark.parametrize(
    ("setting", "words"),
    [
        ("m1=0", 'step "I_pr,min'),
        ("m2=-1", "mass cannot be negative"),
        ("M=-5", "cannot bring the machine"),
        ("phi_deg=180", "dead position"),
    ],
)
def test_bad_input_through_the_cli(
    capsys: pytest.CaptureFixture[str], setting: str, words: str
) -> None:
    code = main(["solve", PID, "--set", setting])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {PID}: ") and words in lines[0]
    assert "Traceback" not in err


def test_the_sheets() -> None:
    sheets = geomcad.solve(PID).sheets()
    assert [n for n, _ in sheets] == ["", "graphs", "fbd"]
    for _, sheet in sheets:
        assert not layout_problems(sheet)
    scheme, graphs, fbd = (s for _, s in sheets)
    assert {"VA", "VA2", "VC3", "P3", "A", "O", "C3", "ω1", "ω3"} <= labels(scheme)
    words = labels(fbd)
    for start in ("XO = ", "NA = ", "MФ1 = ", "Ф2 = ", "R32 = ", "R23 = ", "R03 = ", "Ф3 = ",
                  "MФ3 = ", "Fx = "):  # fmt: skip
        assert any(w.replace("*", "").startswith(start) for w in words), start
    texts = " ".join(t.text for t in graphs.texts())
    # the stacked diagrams share one μ_φ, so their φ ticks line up
    mu_phi = {t.text.split(";")[-1].strip() for t in graphs.texts() if t.text.startswith("μ")}
    assert len(mu_phi) == 1 and next(iter(mu_phi)).startswith("μφ = ")
    assert "|·|" not in " ".join(t.text for t in fbd.texts())
    # the audit (solver, the report's errata) is on the review sheet only
    assert "solve_ivp" not in texts and "Замечания к отчёту" not in texts
