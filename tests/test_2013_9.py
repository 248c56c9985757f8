"""2013-9: the valve mechanism. The reduced model against the check formulas, the Lagrange
equation against an independent force balance, the seed's wrong final line, the motion from rest
against an independent integration and the energy method, variants, bad input, the sheets."""

from __future__ import annotations

import math

import numpy as np
import pytest
from layout import labels, layout_problems
from scipy.integrate import solve_ivp

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, ParameterError

PID = "2013-9"
REL = 1e-12
DEFAULTS = {
    "J": 0.05, "m": 2.0, "r": 0.05, "c": 4000.0, "k": 20.0, "M0": 2.0, "M1": 0.0, "Omega": 0.0,
    "t": 0.0, "phi_deg": 30.0, "phi_dot": 10.0, "T": 0.5,
}  # fmt: skip


def check(p: dict[str, float]) -> dict[str, float]:
    """problems.md's formulas at the state, and the rod's force balance by hand."""
    J, m, r, c, k = p["J"], p["m"], p["r"], p["c"], p["k"]
    phi, w, t = math.radians(p["phi_deg"]), p["phi_dot"], p["t"]
    M = p["M0"] + p["M1"] * math.sin(p["Omega"] * t)
    j = J + m * r * r * math.cos(phi) ** 2
    dj = -m * r * r * math.sin(2 * phi)
    mp = M - 0.5 * c * r * r * math.sin(2 * phi) - k * r * r * math.cos(phi) ** 2 * w
    dd = (mp - 0.5 * dj * w * w) / j
    x, xd = r * math.sin(phi), r * math.cos(phi) * w
    xdd = r * math.cos(phi) * dd - r * math.sin(phi) * w * w
    return {
        "J_pr": j,
        "dJ_pr": dj,
        "M_pr": mp,
        "phi_ddot": dd,
        # the rod: m·x'' = N − c·x − k·x' (the pin's push N along the rod's axis)
        "N_pin": abs(m * xdd + c * x + k * xd),
        "F_spring": abs(c * x),
        "F_damper": abs(k * xd),
        "F_inertia_rod": abs(m * xdd),
        "M_inertia_disc": abs(J * dd),
    }


def rhs(p: dict[str, float]):  # type: ignore[no-untyped-def]
    """The corrected final line, written out by hand, as a first-order system."""
    J, m, r, c, k = p["J"], p["m"], p["r"], p["c"], p["k"]

    def f(t: float, y: np.ndarray) -> list[float]:
        phi, w = y
        M = p["M0"] + p["M1"] * math.sin(p["Omega"] * t)
        lhs_j = J + m * r * r * math.cos(phi) ** 2
        rest = (
            M
            - 0.5 * c * r * r * math.sin(2 * phi)
            - k * r * r * math.cos(phi) ** 2 * w
            + 0.5 * m * r * r * math.sin(2 * phi) * w * w
        )
        return [w, rest / lhs_j]

    return f


def test_state_against_the_check_formulas() -> None:
    r = geomcad.solve(PID).results
    for name, value in check(DEFAULTS).items():
        assert r[name] == pytest.approx(value, rel=REL, abs=1e-15), name
    assert r["J_pr"] == pytest.approx(0.05375, rel=REL)
    assert r["dJ_pr"] == pytest.approx(-0.005 * math.sqrt(3) / 2, rel=REL)
    assert r["M_pr"] < 0 and r["phi_ddot"] < 0


def test_lagrange_equation_against_the_force_balance() -> None:
    """Disc and rod in equilibrium with their d'Alembert loads need no balancing moment when
    φ'' comes from the equation of motion, and the disc's own moment balance holds:
    M − J·φ'' − R_12·r·cos φ = 0."""
    sol = geomcad.solve(PID)
    R = sol.data.reactions
    r = sol.results
    assert abs(R.moment("M_b")) < 1e-12 * r["N_pin"] * 0.05
    phi = math.radians(30.0)
    n = R.magnitudes["R_{12}"]
    assert 2.0 - 0.05 * r["phi_ddot"] - n * 0.05 * math.cos(phi) == pytest.approx(0.0, abs=1e-12)
    assert R.force("R_{01}").y == pytest.approx(n, rel=REL)  # the bearing carries the pin's push
    assert abs(R.magnitudes["R_{02}"]) < 1e-12 * n


def test_seed_final_line_is_wrong() -> None:
    """The seed's last line, J·φ'' − m·r²·½·sin 2φ·φ'²/2 + m·r²·cos²φ·φ' = M_пр, solved for φ'',
    is not the equation of motion: it disagrees at the state, and a motion it drives does not
    keep the energy balance dE/dt = ΣN (here without spring and damper: E = const)."""
    p = DEFAULTS
    J, m, r = p["J"], p["m"], p["r"]
    phi, w = math.radians(p["phi_deg"]), p["phi_dot"]
    mp = check(p)["M_pr"]
    seed_dd = (mp + m * r * r * 0.5 * math.sin(2 * phi) * w * w / 2 - m * r * r * math.cos(phi) ** 2
               * w) / J  # fmt: skip
    ours = geomcad.solve(PID).results["phi_ddot"]
    assert abs(seed_dd - ours) > 1.0

    def energy_drift(seed: bool) -> float:
        def f(t: float, y: np.ndarray) -> list[float]:
            ph, om = y
            if seed:
                dd = (m * r * r * 0.25 * math.sin(2 * ph) * om * om
                      - m * r * r * math.cos(ph) ** 2 * om) / J  # fmt: skip
            else:
                dd = (0.5 * m * r * r * math.sin(2 * ph) * om * om) / (
                    J + m * r * r * math.cos(ph) ** 2
                )
            return [om, dd]

        s = solve_ivp(f, (0, 1.0), [0.0, 10.0], rtol=1e-11, atol=1e-12)
        ph, om = s.y[:, -1]
        e0 = 0.5 * (J + m * r * r) * 100.0
        return abs(0.5 * (J + m * r * r * math.cos(ph) ** 2) * om * om - e0) / e0

    assert energy_drift(seed=False) < 1e-8
    assert energy_drift(seed=True) > 0.1
    notes = " ".join(geomcad.solve(PID).notes)
    assert "spurious /2" in notes and "m·r²·cos²φ·φ' must be m·r²·cos²φ·φ''" in notes
    assert "φ'³" in notes and "−c·x·x'" in notes


def test_motion_from_rest_against_an_independent_integration() -> None:
    sol = geomcad.solve(PID)
    ref = solve_ivp(rhs(DEFAULTS), (0.0, 0.5), [0.0, 0.0], method="Radau", rtol=1e-11,
                    atol=1e-13)  # fmt: skip
    assert sol.results["phi_T"] == pytest.approx(ref.y[0, -1], rel=1e-7, abs=1e-10)
    assert sol.results["omega_T"] == pytest.approx(ref.y[1, -1], rel=1e-7, abs=1e-9)
    assert any("DOP853" in n and "rtol = 1e-11" in n for n in sol.notes)


def test_energy_method_against_solve_ivp_without_damping() -> None:
    """k = 0 and a constant M: the kinetic-energy theorem gives φ' at any φ the motion passes."""
    from geomcad.dynamics import omega_by_energy, work

    sol = geomcad.solve(PID, k=0.0, T=0.08)
    tr = sol.data.motion
    from geomcad_constructions.p2013_9 import model_of

    model, _ = model_of(0.05, 2.0, 0.05, 4000.0, 0.0, lambda t: 2.0 + 0.0 * np.asarray(t), True)
    phi, w = tr.at(0.08)
    assert w > 0
    assert omega_by_energy(model, 0.0, phi) == pytest.approx(w, rel=1e-8)
    assert work(model, 0.0, phi) == pytest.approx(
        2.0 * phi - 0.5 * 4000.0 * 0.05**2 * math.sin(phi) ** 2, rel=1e-12
    )


@pytest.mark.parametrize(
    "params",
    [
        {"phi_deg": 120.0, "phi_dot": -5.0},
        {"r": 0.12, "m": 5.0, "J": 0.3},
        {"M1": 3.0, "Omega": 20.0, "t": 0.1, "T": 2.0},
        {"c": 0.0, "k": 0.0},
        {"phi_deg": 90.0},
    ],
)
def test_variants(params: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **params)
    p = {**DEFAULTS, **params}
    for name, value in check(p).items():
        assert sol.results[name] == pytest.approx(value, rel=1e-10, abs=1e-12), name
    ref = solve_ivp(rhs(p), (0.0, p["T"]), [0.0, 0.0], method="Radau", rtol=1e-11, atol=1e-13)
    assert sol.results["phi_T"] == pytest.approx(ref.y[0, -1], rel=1e-6, abs=1e-9)
    assert abs(sol.data.reactions.moment("M_b")) < 1e-9 * max(1.0, sol.results["N_pin"])
    for _, sheet in sol.sheets():
        assert not layout_problems(sheet)


BAD = [
    ({"J": 0.0}, ConstructionError, r'step "J_pr,min = .*zero at φ = 90°'),
    ({"J": 0.0, "m": 0.0}, ConstructionError, r"zero at φ = 0°"),
    ({"m": -2.0}, ParameterError, r"parameter m = -2\.0: the rod's mass cannot be negative"),
    ({"J": -0.1}, ParameterError, r"parameter J = -0\.1: the disc's moment of inertia cannot"),
    ({"c": -1.0}, ParameterError, r"spring stiffness cannot be negative"),
    ({"k": -1.0}, ParameterError, r"damping constant cannot be negative"),
    ({"r": 0.0}, ParameterError, r"parameter r = 0\.0: must be > 0"),
    ({"T": 0.0}, ParameterError, r"parameter T = 0\.0: must be > 0"),
    ({"phi_dot": math.inf}, ParameterError, r"finite"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


@pytest.mark.parametrize(
    ("setting", "words"),
    [("J=0", 'step "J_pr,min'), ("m=-1", "mass cannot be negative"), ("r=0", "parameter r")],
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
    assert [n for n, _ in sheets] == ["", "motion"]
    for _, sheet in sheets:
        assert not layout_problems(sheet)
    main_sheet = sheets[0][1]
    words = labels(main_sheet)
    for start in ("R01 = ", "R21 = ", "R12 = ", "Fупр = ", "Fд = ", "Ф2 = ", "MФ1 = ", "M(t) = ",
                  "M02 = "):  # fmt: skip
        assert any(w.replace("*", "").startswith(start) for w in words), start
    assert not any(w.startswith("Mb") for w in words)  # the check moment is not a load
    assert "|·|" not in " ".join(t.text for t in main_sheet.texts())
    # the stacked diagrams share one μ_t, so their t ticks line up
    motion = sheets[1][1]
    mu_t = {t.text.split(";")[-1].strip() for t in motion.texts() if t.text.startswith("μ")}
    assert len(mu_t) == 1 and next(iter(mu_t)).startswith("μt = ")
