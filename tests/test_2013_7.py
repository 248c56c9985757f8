"""2013-7 (centrifugal governor with friction circles): the seed's values at drawing precision,
the exact values against an independent solution, the construction's invariants (tangency,
concurrency, closure, the moment balance about H), f = 0, direction −1, bad input, the sheet."""

from __future__ import annotations

import itertools
import json
import math
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from layout import layout_problems
from scipy.optimize import brentq

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, NoIntersection, ParameterError
from geomcad.forces import moment
from geomcad.geom import Line, Vec
from geomcad.sheet import Scale
from geomcad.sheet.model import CircleItem, Polyline, Sheet

PID = "2013-7"
REL = 1e-9
SEED = {
    "m2": 10.0,
    "m_ball": 1.0,
    "f": 0.3,
    "d": 0.032,
    "l_AB": 0.1,
    "l_GH": 0.1,
    "l_FH": 0.15,
    "l_DH": 0.22,
    "l_BF": 0.15,
    "theta_deg": 45.0,
    "g": 9.81,
    "direction": 1,
}
LENGTHS = ("d", "l_AB", "l_GH", "l_FH", "l_DH", "l_BF")


def independent(**changes: float) -> dict[str, float]:
    """The governor solved without geomcad's geometry: the relative rotations by numerical
    differentiation of the linkage, link 3's line from the two moment conditions
    (F − B) × u = (s_B + s_F)·ρ, and F_i from the moment equation about H, in which R_76's
    moment is −s_H·ρ·|R_76| (a root of one scalar equation, brentq)."""
    p = {**SEED, **changes}
    th = math.radians(p["theta_deg"])
    rho = p["d"] / 2 * math.sin(math.atan(p["f"]))
    g, mb, m2 = p["g"], p["m_ball"], p["m2"]

    def linkage(t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        H = np.array([p["l_GH"] / 2, 0.0])
        e = np.array([math.sin(t), -math.cos(t)])
        F, D = H + p["l_FH"] * e, H + p["l_DH"] * e
        dx = F[0] - p["l_AB"] / 2
        B = np.array([p["l_AB"] / 2, F[1] - math.sqrt(p["l_BF"] ** 2 - dx * dx)])
        return H, F, D, B

    def psi3(t: float) -> float:
        _, F, _, B = linkage(t)
        return math.atan2(F[1] - B[1], F[0] - B[0])

    h = 1e-6
    w3 = (psi3(th + h) - psi3(th - h)) / (2 * h)  # ω_3 per unit θ̇; ω_6 = θ̇
    s = p["direction"]
    s_B, s_F, s_H = np.sign(w3 * s), np.sign((w3 - 1) * s), np.sign(s)
    H, F, D, B = linkage(th)
    L = float(np.linalg.norm(F - B))
    e_bf = (F - B) / L
    psi = math.asin((s_B + s_F) * rho / L)  # the line's turn from BF
    u = np.array(
        [e_bf[0] * math.cos(psi) - e_bf[1] * math.sin(psi),
         e_bf[0] * math.sin(psi) + e_bf[1] * math.cos(psi)]
    )  # fmt: skip
    perp = np.array([-u[1], u[0]])
    X = B - s_B * rho * perp  # a point of link 3's line
    T = m2 * g / (2 * u[1])  # tension: 2·T·u_y = m2·g
    R36 = -T * u  # link 3 pulls the arm from F towards B
    G6 = np.array([0.0, -mb * g])

    def cross(a: np.ndarray, b: np.ndarray) -> float:
        return float(a[0] * b[1] - a[1] * b[0])

    def residual(fi: float) -> float:
        R76 = -(R36 + G6 + np.array([fi, 0.0]))
        m = cross(X - H, R36) + cross(D - H, G6 + np.array([fi, 0.0]))
        return m - s_H * rho * float(np.linalg.norm(R76))

    fi = brentq(residual, 1e-9, 1e5, xtol=1e-14, rtol=1e-15)
    R76 = -(R36 + G6 + np.array([fi, 0.0]))
    return {
        "rho": rho,
        "alpha_deg": abs(math.degrees(psi)),
        "R32": T,
        "P": float(np.linalg.norm(R36 + G6)),
        "beta_deg": math.degrees(math.atan2(abs(R76[1]), abs(R76[0]))),
        "F_i": fi,
        "r_D": float(D[0]),
        "omega": math.sqrt(fi / (mb * D[0])),
        "R76": float(np.linalg.norm(R76)),
    }


# -- the seed ----------------------------------------------------------------------------------


def test_seed_values_within_drawing_precision() -> None:
    sol = geomcad.solve(PID)
    for row in sol.seed_report():
        assert row["agrees"], row
    r = sol.results
    # measured off the seed's plan at k_F = 1 N/mm: 0.5 mm is 0.5 N; the angle to 0.5°
    assert abs(r["P"] - 80.8) <= 0.5
    assert abs(r["F_i"] - 85.1) <= 0.5
    assert abs(r["beta_deg"] - 63.2) <= 0.5
    # printed after rounding: half a unit of the last digit
    assert abs(r["rho"] - 0.0046) <= 0.00005
    assert abs(r["alpha_deg"] - 3.5) <= 0.05
    assert abs(r["R32"] - 74) <= 0.5
    assert abs(r["r_D"] - 0.206) <= 0.0005


def test_seed_classes() -> None:
    seed = geomcad.solve(PID).problem.seed
    kinds = {k: v.kind for k, v in seed.items()}
    assert kinds == {
        "rho": "rounded",
        "alpha_deg": "rounded",
        "R32": "rounded",
        "P": "measured",
        "beta_deg": "measured",
        "F_i": "measured",
        "r_D": "rounded",
        "omega": "measured",
    }
    assert seed["P"].tol == seed["F_i"].tol == 0.5  # 0.5 mm at k_F = 1 N/mm
    # ω = √(F_i/0,206) carries F_i's 0.5 N, the rounding of 0,206 and its own to 0.1 rad/s
    w = math.sqrt(85.1 / 0.206)
    assert seed["omega"].tol == pytest.approx(0.5 * w / (2 * 85.1) + 0.0005 * w / 0.412 + 0.05)


def test_seed_arithmetic_is_consistent_so_there_is_no_erratum() -> None:
    """The seed's own numbers follow from each other: φ, ρ, sin α, R_32 and ω."""
    assert math.degrees(math.atan(0.3)) == pytest.approx(16.7, abs=0.05)
    assert 0.5 * 0.032 * math.sin(math.radians(16.7)) == pytest.approx(0.0046, abs=0.00005)
    sin_alpha = 2 * 0.0046 / 0.15
    assert sin_alpha == pytest.approx(0.06133, abs=0.000005)
    assert math.degrees(math.asin(0.06133)) == pytest.approx(3.5, abs=0.05)
    assert 10 * 9.81 / (2 * math.cos(math.radians(48.5))) == pytest.approx(74, abs=0.5)
    assert 1 * (0.1 / 2 + 0.22 * math.sin(math.radians(45))) == pytest.approx(0.206, abs=0.0005)
    assert math.sqrt(85.1 / 0.206) == pytest.approx(20.3, abs=0.05)
    sol = geomcad.solve(PID)
    assert not any(n.startswith("erratum") for n in sol.notes)
    assert sol.notes == []


def test_exact_seed_values() -> None:
    r = geomcad.solve(PID).results
    assert r["rho"] == pytest.approx(0.016 * 0.3 / math.sqrt(1.09), rel=REL)
    assert r["alpha_deg"] == pytest.approx(math.degrees(math.asin(2 * r["rho"] / 0.15)), rel=REL)
    up = math.radians(45 + r["alpha_deg"])
    assert r["R32"] == pytest.approx(10 * 9.81 / (2 * math.cos(up)), rel=REL)
    assert r["r_D"] == pytest.approx(0.05 + 0.22 / math.sqrt(2), rel=REL)
    assert r["P"] == pytest.approx(80.87849373232068, rel=REL)
    assert r["beta_deg"] == pytest.approx(63.19305719561119, rel=REL)
    assert r["F_i"] == pytest.approx(85.21046923849974, rel=REL)
    assert r["omega"] == pytest.approx(20.359798958671046, rel=REL)
    assert r["omega_no_friction"] == pytest.approx(19.315875324772392, rel=REL)


VARIANTS: list[dict[str, float]] = [
    {},
    {"direction": -1},
    {"f": 0.15, "d": 0.05},
    {"theta_deg": 30.0},
    {"theta_deg": 60.0, "direction": -1},
    {"l_AB": 0.16, "l_BF": 0.2, "m2": 4.0, "m_ball": 2.5},
    {"l_AB": 0.4},  # B outside F: link 3 leans inwards
    {"d": 0.2, "f": 0.5},
    {"g": 1.62, "l_DH": 0.3, "l_FH": 0.1},
]


@pytest.mark.parametrize(
    "changes", VARIANTS, ids=lambda c: ",".join(f"{k}={v}" for k, v in c.items()) or "seed"
)
def test_exact_values_against_an_independent_solution(changes: dict[str, float]) -> None:
    got = geomcad.solve(PID, **changes).results
    want = independent(**changes)
    for name in ("rho", "alpha_deg", "R32", "P", "beta_deg", "F_i", "r_D", "omega"):
        assert got[name] == pytest.approx(want[name], rel=REL, abs=1e-12), name
    free = independent(**{**changes, "f": 0.0})
    assert got["omega_no_friction"] == pytest.approx(free["omega"], rel=REL)


@settings(max_examples=60, deadline=None)
@given(
    st.floats(20.0, 70.0),
    st.floats(0.0, 0.5),
    st.floats(0.01, 0.05),
    st.sampled_from((1, -1)),
    st.floats(0.5, 20.0),
)
def test_well_conditioned_variants_match_the_independent_solution(
    theta: float, f: float, d: float, direction: int, m2: float
) -> None:
    changes = {"theta_deg": theta, "f": f, "d": d, "direction": direction, "m2": m2}
    sol = geomcad.solve(PID, **changes)
    want = independent(**changes)
    for name in ("R32", "P", "F_i", "omega"):
        assert sol.results[name] == pytest.approx(want[name], rel=1e-8), name
    run = sol.data.run
    assert run.poly6.closure <= 1e-12 * (run.F_i + run.R76)
    assert abs(run.R76_line.side(sol.data.H)) == pytest.approx(run.rho, abs=1e-15)
    # friction raises ω when speeding up and lowers it when slowing down (round-off at f → 0)
    gain = (sol.results["omega"] - sol.results["omega_no_friction"]) * direction
    assert gain >= -1e-12 * sol.results["omega_no_friction"]


# -- invariants of the construction ------------------------------------------------------------


@pytest.fixture(scope="module", params=[1, -1], ids=["accelerating", "slowing"])
def solved(request: pytest.FixtureRequest) -> Any:
    return geomcad.solve(PID, direction=request.param)


def test_reaction_lines_touch_their_friction_circles(solved: Any) -> None:
    run = solved.data.run
    rho = solved.results["rho"]
    line3 = run.link3.line
    for centre in (solved.data.B, solved.data.F):
        assert abs(line3.side(centre)) == pytest.approx(rho, abs=1e-15)
    assert abs(run.R76_line.side(solved.data.H)) == pytest.approx(rho, abs=1e-15)
    # the internal tangent crosses BF: B and F lie on opposite sides of link 3's line
    assert line3.side(solved.data.B) * line3.side(solved.data.F) < 0


def test_moments_oppose_the_relative_rotations(solved: Any) -> None:
    """At B the reaction on link 3 opposes ω_32, at F it opposes ω_36, at H R_76 opposes ω_67:
    each has the moment −sign(ω)·ρ·|R| about its joint."""
    run, geo = solved.data.run, solved.data
    rho, s = solved.results["rho"], geo.direction
    # the linkage turns: θ̇ = s, ω_3 = θ̇·(ω_3/ω_6) < 0 for s > 0
    w3 = geo.omega3_per_omega6 * s
    assert geo.omega3_per_omega6 < 0
    at_B = Line(run.link3.touch_a, run.link3.line.d)  # force of 2 on 3, at B
    at_F = Line(run.link3.touch_b, -run.link3.line.d)  # force of 6 on 3, at F
    assert moment(geo.B, at_B, 1.0) == pytest.approx(-np.sign(w3) * rho, abs=1e-15)
    assert moment(geo.F, at_F, 1.0) == pytest.approx(-np.sign(w3 - s) * rho, abs=1e-15)
    assert moment(geo.H, run.R76_line, 1.0) == pytest.approx(-s * rho, abs=1e-15)


def test_three_forces_are_concurrent(solved: Any) -> None:
    run, geo = solved.data.run, solved.data
    K, Q, T2 = run.K, run.Q, run.T2
    # arm 6: P, F_i and R_76 meet in K
    assert abs(run.P_line.side(K)) <= 1e-15
    assert K.y == pytest.approx(geo.D.y, abs=1e-15)  # F_i's line: the horizontal through D
    assert abs(run.R76_line.side(K)) <= 1e-15
    # P = G_6 + R_36 acts through Q, where R_36's line meets G_6's (the vertical through D)
    assert abs(run.link3.line.side(Q)) <= 1e-15 and Q.x == pytest.approx(geo.D.x, abs=1e-15)
    p_vec = run.poly6.diagonal("G_6", "R_36", "P").force
    assert abs(p_vec.unit().cross(run.P_line.d)) <= 1e-12
    # the sleeve: R_32, R_42 and G_2 (along the shaft's axis) meet on the axis
    assert T2.x == pytest.approx(0.0, abs=1e-15)
    assert abs(Line(run.link3.touch_a, run.u32).side(T2)) <= 1e-15


def test_force_polygons_close_head_to_tail(solved: Any) -> None:
    run = solved.data.run
    for poly, scale in ((run.tri2, run.R32), (run.poly6, run.F_i + run.R76)):
        assert poly.closure <= 1e-12 * scale
        assert poly.vectors[0].tail == poly.pole
        for a, b in itertools.pairwise(poly.vectors):
            assert a.head == b.tail
    assert run.tri2.names == ("G_2", "R_32", "R_42")
    assert run.poly6.names == ("G_6", "R_36", "F_i", "R_76")
    assert run.poly6["R_36"].magnitude == pytest.approx(run.R32, rel=1e-14)
    assert run.poly6["F_i"].force.y == 0.0 and run.poly6["F_i"].force.x > 0
    assert run.poly6.diagonal("G_6", "R_36", "P").magnitude == pytest.approx(run.P, rel=1e-14)
    m = solved.data
    assert run.poly6["G_6"].force.y == pytest.approx(-m.m_ball * m.g, rel=1e-15)
    assert run.tri2["G_2"].force.y == pytest.approx(-m.m2 * m.g, rel=1e-15)


def test_moment_balance_about_H_matches_the_construction(solved: Any) -> None:
    """ΣM_H = 0 for arm 6: R_36 along link 3's line, G_6 and F_i through D, and R_76, whose
    moment is the friction moment −ρ·|R_76| opposing ω_67."""
    run, geo = solved.data.run, solved.data
    H, D = geo.H, geo.D
    m36 = moment(H, run.link3.line, run.R32)
    m_g6 = moment(H, Line(D, Vec(0.0, -1.0)), geo.m_ball * geo.g)
    m_fi = moment(H, Line(D, Vec(1.0, 0.0)), run.F_i)
    m76 = moment(H, run.R76_line, run.R76)
    assert m76 == pytest.approx(-geo.direction * run.rho * run.R76, rel=1e-12)
    assert m36 + m_g6 + m_fi + m76 == pytest.approx(0.0, abs=1e-12 * abs(m_fi))
    r76 = run.R76
    assert r76 == pytest.approx(independent(direction=geo.direction)["R76"], rel=REL)


def test_the_trace_lists_the_seed_steps() -> None:
    trace = geomcad.solve(PID).trace()
    for words in (
        "ρ_B = friction circle of B",
        "l_3 = line of action of link 3: the common tangent",
        "plan 2 = force polygon G_2 + R_32 + R_42 = 0",
        "Q = line of R_36 ∩ line of G_6",
        "K = line of P ∩ line of F_i",
        "line R_76 = tangent from K to the friction circle at H",
        "plan 6 = force polygon G_6 + R_36 + F_i + R_76 = 0",
        "f=0: K = ",
    ):
        assert words in trace, words


# -- f = 0, direction −1, scaling --------------------------------------------------------------


def test_no_friction_reduces_to_the_frictionless_construction() -> None:
    r0 = geomcad.solve(PID, f=0.0).results
    assert r0["rho"] == 0.0 and r0["alpha_deg"] == 0.0
    # link 3 along BF, at 45° to the vertical: m2·g/2 = R_32·cos 45°
    assert r0["R32"] == pytest.approx(10 * 9.81 / (2 * math.cos(math.pi / 4)), rel=REL)
    # moments about H without friction: F_i·(H_y − D_y) = G_6·(D_x − H_x) − M_H(R_36)
    h = 0.15 / math.sqrt(2)
    arm = 0.22 / math.sqrt(2)
    r36 = r0["R32"]
    m36 = (h * -r36 / math.sqrt(2)) - (-h) * (-r36 / math.sqrt(2))  # (F − H) × R_36
    fi0 = (9.81 * arm - m36) / arm
    assert r0["F_i"] == pytest.approx(fi0, rel=REL)
    assert r0["omega"] == pytest.approx(math.sqrt(fi0 / (0.05 + arm)), rel=REL)
    assert r0["omega"] == r0["omega_no_friction"]
    assert geomcad.solve(PID).results["omega_no_friction"] == pytest.approx(r0["omega"], rel=1e-14)


def test_small_friction_tends_to_the_frictionless_result() -> None:
    w0 = geomcad.solve(PID, f=0.0).results["omega"]
    for f in (1e-3, 1e-5):
        up = geomcad.solve(PID, f=f).results["omega"]
        down = geomcad.solve(PID, f=f, direction=-1).results["omega"]
        assert down < w0 < up
        assert up - w0 == pytest.approx(w0 - down, rel=0.05)  # friction shifts ω both ways alike
        assert up - w0 < 20 * f * w0


def test_slowing_down_gives_a_lower_omega() -> None:
    up = geomcad.solve(PID).results
    down = geomcad.solve(PID, direction=-1)
    assert down.results["omega"] < up["omega_no_friction"] < up["omega"]
    assert down.results["R32"] < up["R32"]  # link 3's line turns towards the vertical
    assert down.results["omega_no_friction"] == up["omega_no_friction"]
    assert any("direction −1" in n for n in down.notes)
    assert down.seed == {} and down.diff == {}
    # without friction the direction does not matter
    a = geomcad.solve(PID, f=0.0).results
    b = geomcad.solve(PID, f=0.0, direction=-1).results
    assert a == b


@pytest.mark.parametrize("k", [0.5, 3.0])
def test_results_scale_with_the_governor(k: float) -> None:
    a = geomcad.solve(PID).results
    b = geomcad.solve(PID, **{n: SEED[n] * k for n in LENGTHS}).results
    for name in ("R32", "P", "F_i"):
        assert b[name] == pytest.approx(a[name], rel=REL)  # forces do not change
    for name in ("alpha_deg", "beta_deg"):
        assert b[name] == pytest.approx(a[name], rel=REL)
    assert b["rho"] == pytest.approx(a["rho"] * k, rel=REL)
    assert b["omega"] == pytest.approx(a["omega"] / math.sqrt(k), rel=REL)
    c = geomcad.solve(PID, m2=10 * k, m_ball=k).results
    assert c["F_i"] == pytest.approx(a["F_i"] * k, rel=REL)
    assert c["omega"] == pytest.approx(a["omega"], rel=REL)


# -- bad input ---------------------------------------------------------------------------------

BAD: list[tuple[dict[str, Any], type, str]] = [
    ({"m2": -10.0}, ParameterError, r"parameter m2 = -10\.0: must be > 0 kg"),
    ({"m2": 0.0}, ParameterError, r"parameter m2 = 0\.0: must be > 0"),
    ({"m_ball": -1.0}, ParameterError, r"parameter m_ball = -1\.0: must be > 0"),
    ({"f": -0.3}, ParameterError, r"parameter f = -0\.3: must be ≥ 0"),
    ({"d": 0.0}, ParameterError, r"parameter d = 0\.0: must be > 0 m"),
    ({"l_BF": -0.15}, ParameterError, r"parameter l_BF = -0\.15: must be > 0"),
    ({"l_DH": 0.0}, ParameterError, r"parameter l_DH = 0\.0"),
    ({"g": 0.0}, ParameterError, r"parameter g = 0\.0"),
    ({"theta_deg": 0.0}, ParameterError, r"parameter theta_deg = 0\.0: must be > 0 deg"),
    ({"theta_deg": 90.0}, ParameterError, r"parameter theta_deg = 90\.0: must be < 90 deg"),
    ({"direction": 0}, ParameterError, r"parameter direction = 0: must be \+1 .* or −1"),
    ({"direction": 2}, ParameterError, r"parameter direction = 2"),
    ({"direction": 0.5}, ParameterError, r"parameter direction = 0\.5: must be a whole number"),
    ({"l_BF": 0.1}, ParameterError, r"parameter l_BF = 0\.1: too short: link 3 must reach"),
    ({"m2": float("nan")}, ParameterError, r"parameter m2 = nan: must be a finite number"),
    ({"mass": 1.0}, ParameterError, r"parameter mass .*no such parameter"),
    # friction circles at B and F that overlap: 2ρ ≥ l_BF, no internal common tangent
    ({"d": 0.6}, NoIntersection, r'step "l_3 = line of action of link 3.*overlap \(ρ_B \+ ρ_F'),
    ({"d": 0.6, "direction": -1}, NoIntersection, r"friction circles of B and F overlap"),
    # the sleeve self-locks: link 3's line at 90° or more to the vertical
    ({"d": 0.4}, ConstructionError, r"self-locking: link 3's line of action makes 95\.0\d°"),
    ({"theta_deg": 87.0}, ConstructionError, r"self-locking: link 3's line .* cannot hold"),
    # the arm self-locks: F_i ≤ 0, friction alone holds the balls up while slowing down
    (
        {"d": 0.5, "direction": -1},
        ConstructionError,
        r'"plan 6: closing vertex = [^"]*": self-locking',
    ),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD, ids=[str(p) for p, _, _ in BAD])
def test_bad_input_through_the_api(params: dict[str, Any], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


CLI_BAD = [
    (["--set", "m2=-10"], ["parameter m2 = -10.0", "> 0"]),
    (["--set", "f=-1"], ["parameter f", "≥ 0"]),
    (["--set", "direction=0"], ["parameter direction = 0", "+1"]),
    (["--set", "direction=1.5"], ["direction", "whole number"]),
    (["--set", "direction=up"], ["direction", "whole number"]),
    (["--set", "d=0.6"], ['step "l_3 = line of action of link 3', "overlap"]),
    (["--set", "d=0.4"], ["self-locking", "cannot hold the sleeve"]),
    (["--set", "d=0.5", "--set", "direction=-1"], ['"plan 6: closing vertex = ', "F_i"]),
    (["--set", "l_BF=0.1"], ["l_BF", "too short"]),
    (["--set", "theta_deg=90"], ["theta_deg", "< 90"]),
]


@pytest.mark.parametrize(("argv", "words"), CLI_BAD, ids=[" ".join(a) for a, _ in CLI_BAD])
def test_bad_input_through_the_cli(
    capsys: pytest.CaptureFixture[str], argv: list[str], words: list[str]
) -> None:
    for extra in ([], ["--json"]):
        code = main(["solve", PID, *argv, *extra])
        out, err = capsys.readouterr()
        assert code == 2 and out == ""
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"error: {PID}: "), err
        assert "Traceback" not in err
        for w in words:
            assert w in lines[0], (w, err)


# -- the interface -----------------------------------------------------------------------------


def test_solve_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["solve", PID, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["params"]["direction"] == 1 and isinstance(data["params"]["direction"], int)
    assert set(data["results"]) == {
        "rho", "alpha_deg", "R32", "P", "beta_deg", "F_i", "r_D", "omega", "omega_no_friction"
    }  # fmt: skip
    assert data["seed"] == {
        "rho": 0.0046,
        "alpha_deg": 3.5,
        "R32": 74.0,
        "P": 80.8,
        "beta_deg": 63.2,
        "F_i": 85.1,
        "r_D": 0.206,
        "omega": 20.3,
    }
    assert data["diff"]["F_i"] == pytest.approx(data["results"]["F_i"] - 85.1, abs=1e-12)
    assert data["notes"] == []
    assert main(["solve", PID, "--set", "direction=-1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["params"]["direction"] == -1 and data["seed"] == {}


def test_verify_the_seeds_readings(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["verify", PID, "--json", "--measured", "P=80.8", "--measured", "F_i=85.1",
            "--measured", "beta_deg=63.2", "--measured", "omega=20.3"]  # fmt: skip
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["ok"] is True
    by = {i["name"]: i for i in data["items"]}
    assert by["F_i"]["precision"] == pytest.approx(0.5)  # 0.5 mm on the plan at k_F = 1 N/mm
    assert by["F_i"]["deviation_mm"] == pytest.approx(85.1 - by["F_i"]["exact"], abs=1e-12)
    assert by["beta_deg"]["precision"] == 0.5
    assert main(["verify", PID, "--measured", "F_i=87"]) == 1
    capsys.readouterr()


# -- the sheet ---------------------------------------------------------------------------------


def check_layout(sheet: Sheet) -> None:
    """No two texts overlap; everything drawn lies inside the frame and off the title block."""
    problems = layout_problems(sheet)
    assert not problems, "\n".join(problems)


@pytest.fixture(scope="module")
def seed_sheet() -> Sheet:
    ((name, sheet),) = geomcad.solve(PID).sheets()
    assert name == ""
    return sheet


def test_sheet_layout_and_scales(seed_sheet: Sheet) -> None:
    assert (seed_sheet.format, seed_sheet.width, seed_sheet.height) == ("A3", 420.0, 297.0)
    check_layout(seed_sheet)
    words = [t.text for t in seed_sheet.texts()]
    # the layout step's scales: the mechanism 1:2.5, the plans at 1 N/mm, the joints enlarged
    assert "1:2,5" in words  # the title block's scale
    assert any("μl = 0,0025 м/мм" in w and "М 1:2,5" in w for w in words)
    assert "План сил звена 6, μF = 1 Н/мм" in words
    assert "План сил звена 2, μF = 1 Н/мм" in words
    assert sum(w.startswith("Шарнир ") for w in words) == 3
    kj = Scale(geomcad.solve(PID).scales["j"], "l")
    assert kj.k < 0.0025  # larger than the mechanism's 1:2.5
    assert any(w.startswith("Шарниры") and f"(М {kj.ratio_text()})" in w for w in words)


def test_sheet_labels_name_the_points_and_forces(seed_sheet: Sheet) -> None:
    labels = {t.text for t in seed_sheet.texts() if t.role == "label"}
    for name in ("H", "F", "B", "D", "Q", "K", "G6", "Ф6", "R36", "R32", "R42", "R76", "G2", "P",
                 "ρ", "ω32", "ω36", "ω67", "f = 0"):  # fmt: skip
        assert name in labels, name
    assert any(t.startswith("β = 63,2") for t in labels)


def test_sheet_is_true_to_scale(seed_sheet: Sheet) -> None:
    sol = geomcad.solve(PID)
    kl, kf = sol.scales["l"], sol.scales["F"]
    assert (kl, kf) == (0.0025, 1.0)
    run = sol.data.run
    # the friction circles at B, F, H on the mechanism drawing: radius ρ/k_l, centres k_l apart
    small = [it for it in seed_sheet.items if isinstance(it, CircleItem)
             and it.role == "construction" and it.r == pytest.approx(run.rho / kl)]  # fmt: skip
    assert len(small) == 3
    (b, f, h) = (it.c for it in small)
    assert math.dist(b, f) * kl == pytest.approx(0.15, rel=1e-9)
    assert math.dist(f, h) * kl == pytest.approx(0.15, rel=1e-9)
    # the insets at k_j: ρ/k_j and the pin d/2/k_j
    kj = sol.scales["j"]
    big = [it.r for it in seed_sheet.items if isinstance(it, CircleItem)]
    assert big.count(pytest.approx(run.rho / kj)) == 3
    assert big.count(pytest.approx(0.016 / kj)) == 3
    # P on the plan of arm 6: the result arrow from the pole, P/k_F long to its head's tip
    shafts = [it for it in seed_sheet.items if isinstance(it, Polyline) and it.role == "result"
              and not it.closed and len(it.points) == 2]  # fmt: skip
    heads = [it for it in seed_sheet.items if isinstance(it, Polyline) and it.role == "result"
             and it.closed]  # fmt: skip
    lengths = [math.dist(s.points[0], hd.points[0]) for s in shafts for hd in heads]
    assert any(abs(x - run.P / kf) < 1e-9 for x in lengths)


@pytest.mark.parametrize(
    "changes",
    [
        {"direction": -1},
        {"f": 0.0},
        {"d": 0.2},
        {"theta_deg": 30.0},
        {"l_DH": 0.5, "l_FH": 0.3, "l_BF": 0.3, "m2": 50.0, "l_AB": 0.2},
    ],
    ids=["slowing", "no-friction", "large-pins", "theta-30", "large"],
)
def test_variant_sheets(changes: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **changes)
    kl, kf = Scale(sol.scales["l"], "l"), Scale(sol.scales["F"], "F")
    assert kl.ratio_text(), f"k_l = {kl.k} is not a GOST 2.302 scale"
    mant = kf.k / 10 ** math.floor(math.log10(kf.k))
    assert any(mant == pytest.approx(m) for m in (1, 2, 2.5, 4, 5))
    ((_, sheet),) = sol.sheets()
    check_layout(sheet)
    words = [t.text for t in sheet.texts()]
    assert kl.ratio_text() in words


# -- the order of construction, written from the recorded steps --------------------------------


def _order_lines(sheet: Sheet) -> list[str]:
    """The numbered lines of the sheet's order of construction (their first lines)."""
    return [t.text for t in sheet.texts() if t.role == "title" and t.text[:1].isdigit()
            and ". " in t.text[:4]]  # fmt: skip


@pytest.mark.parametrize(
    ("changes", "lang"),
    [({}, "ru"), ({}, "en"), ({"f": 0.0}, "ru"), ({"direction": -1}, "en")],
    ids=["seed-ru", "seed-en", "no-friction", "slowing-en"],
)
def test_the_order_is_written_from_the_recorded_steps(changes: dict[str, float], lang: str) -> None:
    from geomcad_constructions.sheets_2013_7 import ORDER, ORDER_NO_FRICTION, WORDS, order_steps

    from geomcad.sheet.lang import language
    from geomcad.sheet.views import num

    sol = geomcad.solve(PID, **changes)
    with language(lang):
        ((_, sheet),) = sol.sheets()
        rho = num(sol.results["rho"] * 1000.0)
        omega = num(sol.results["omega"])
        R32 = num(sol.results["R32"])
    names = ORDER if sol.results["rho"] > 0.0 else ORDER_NO_FRICTION
    steps = order_steps(sol)
    # one numbered line per listed step, each a recorded step with its kind
    assert [s.name for s in steps] == list(names)
    assert all(s.kind for s in steps)
    lines = _order_lines(sheet)
    assert [ln.split(". ", 1)[0] for ln in lines] == [str(i) for i in range(1, len(names) + 1)]
    text = " ".join(t.text for t in sheet.texts() if t.role == "title")
    # the values a student writes there are the recorded ones, in the language drawn
    assert f"= {omega} " in text
    assert f"R32 = {R32} " in text
    if sol.results["rho"] > 0.0:
        assert f"= {rho} " in text
        assert sol.construction.step("α").kind == "two_force_internal"
    else:
        assert "BF" in text
    # no hand-written order is left in the words
    assert not [k for k in WORDS.table() if k.startswith("step_")]


def test_mechanism_forces_are_drawn_at_the_stated_mu_F(seed_sheet: Sheet) -> None:
    """Each force on the half-governor is an arrow |F|/μ_F long at the μ_F its caption states,
    the weight G_6 (under two arrowheads at it) at the stated larger μ_F*, its label starred."""
    sol = geomcad.solve(PID)
    run, k_F = sol.data.run, sol.scales["F_mech"]
    words = [t.text for t in seed_sheet.texts()]
    assert k_F == 5.0
    # the caption, on one line or broken into lines within its box (compose._draw_title)
    caption = " ".join(w for w in words if w.startswith("Правая половина") or "μF = 5" in w)
    assert caption.startswith("Правая половина") and caption.endswith("μF = 5 Н/мм")
    assert "μF* = 0,5 Н/мм" in words
    mags = {
        "G_6": (9.81, 0.5),
        "F_i": (run.F_i, k_F),
        "R_76": (run.R76, k_F),
        "R_32": (run.R32, k_F),
        "R_36": (run.R32, k_F),
    }  # link 3 is a two-force link
    vec = [it for it in seed_sheet.items if isinstance(it, Polyline) and it.role == "vector"]
    shafts = [it for it in vec if not it.closed and len(it.points) == 2]
    heads = [it for it in vec if it.closed]
    lengths = [math.dist(s.points[0], hd.points[0]) for s in shafts for hd in heads]
    for name, (F, k) in mags.items():
        assert any(abs(x - F / k) < 1e-9 for x in lengths), name
    labels = {t.text for t in seed_sheet.texts() if t.role == "label"}
    assert "G6*" in labels and "Ф6" in labels
