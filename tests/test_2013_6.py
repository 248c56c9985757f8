"""2013-6: the seed's values, exact geometry checked independently, variants, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import geomcad
from geomcad.errors import ConstructionError, NoIntersection, ParameterError

REL = 1e-9
SEED = {"H": 0.2, "K": 1.3, "l3": 0.3, "l4": 0.3, "e": 0.3}


def independent(H: float, K: float, l3: float, l4: float, e: float) -> list[tuple[float, float]]:
    """The candidates O1 found without the kernel: B0, B1 by the law of cosines, then the points
    of the lines y = l3 ∓ e that see B0B1 under θ, as roots of the seen angle along each line."""
    theta = math.pi * (K - 1) / (K + 1)

    def b_of(cx: float) -> np.ndarray:
        d = math.hypot(cx, l3)
        alpha = math.acos((l3 * l3 + d * d - l4 * l4) / (2 * l3 * d))
        base = math.atan2(l3, cx)
        return l3 * np.array([math.cos(base + alpha), math.sin(base + alpha)])  # left of O2→C

    b0, b1 = b_of(l4 - H / 2), b_of(l4 + H / 2)
    out = []
    for y in (l3 - e, l3 + e):

        def seen(x: float, y: float = y) -> float:
            u, v = b0 - (x, y), b1 - (x, y)
            return math.atan2(abs(u[0] * v[1] - u[1] * v[0]), float(u @ v)) - theta

        xs = np.linspace(-5.0, 5.0, 20001)
        f = np.array([seen(x) for x in xs])
        roots = [
            brentq(seen, xs[i], xs[i + 1], xtol=1e-15) for i in np.nonzero(np.diff(np.sign(f)))[0]
        ]
        out += [(x, y) for x in sorted(roots)]
    return out


def test_seed_values_within_drawing_precision() -> None:
    sol = geomcad.solve("2013-6")
    for row in sol.seed_report():
        assert row["agrees"], row
    # 0.5 mm at the seed's k_l = 0.005 m/mm
    assert abs(sol.results["O1B1"] - 89.5 * 0.005) <= 0.5 * 0.005
    assert abs(sol.results["O1B0"] - 63.5 * 0.005) <= 0.5 * 0.005
    assert abs(sol.results["theta_deg"] - 23.5) <= 0.05


def test_exact_values_against_an_independent_solution() -> None:
    sol = geomcad.solve("2013-6")
    cands = independent(**SEED)
    got = [tuple(s["O1"]) for s in sol.results["solutions"]]
    assert len(got) == len(cands) == 4
    for (x, y), (gx, gy) in zip(cands, got, strict=True):
        assert gx == pytest.approx(x, rel=REL, abs=1e-12) and gy == pytest.approx(y, abs=1e-12)
    r = sol.results
    assert r["theta_deg"] == pytest.approx(180 * 0.3 / 2.3, rel=REL)
    assert r["O1B0"] == pytest.approx(0.31838270291557713, rel=REL)
    assert r["O1B1"] == pytest.approx(0.44668086493066156, rel=REL)
    assert r["l1"] == pytest.approx((r["O1B1"] - r["O1B0"]) / 2, rel=REL)
    assert r["l2"] == pytest.approx((r["O1B1"] + r["O1B0"]) / 2, rel=REL)
    assert r["solutions"][0]["O1"] == [r["solutions"][0]["O1"][0], 0.0]
    assert all(s["crank_rocker"] for s in r["solutions"])


def test_check_by_analysis_reproduces_stroke_and_k() -> None:
    r = geomcad.solve("2013-6").results
    assert r["H_check"] == pytest.approx(0.2, rel=REL)
    assert r["K_check"] == pytest.approx(1.3, rel=REL)


@pytest.mark.parametrize(
    "params",
    [
        {"K": 1.4, "H": 0.15, "e": 0.25},
        {"K": 1.15, "H": 0.25, "l3": 0.35, "l4": 0.4, "e": 0.2},
        {"K": 1.6, "H": 0.1, "l3": 0.25, "l4": 0.5, "e": 0.1},
    ],
)
def test_variants_match_the_independent_solution(params: dict[str, float]) -> None:
    p = {**SEED, **params}
    sol = geomcad.solve("2013-6", **params)
    assert sol.seed == {} and sol.diff == {}
    cands = independent(**p)
    got = [tuple(s["O1"]) for s in sol.results["solutions"]]
    assert len(got) == len(cands)
    for (x, _), (gx, _) in zip(cands, got, strict=True):
        assert gx == pytest.approx(x, rel=REL, abs=1e-12)
    assert sol.results["O1B0"] == pytest.approx(math.dist(cands[0], _b(p, -1)), rel=REL)


def _b(p: dict[str, float], side: int) -> tuple[float, float]:
    cx = p["l4"] + side * p["H"] / 2
    d = math.hypot(cx, p["l3"])
    alpha = math.acos((p["l3"] ** 2 + d * d - p["l4"] ** 2) / (2 * p["l3"] * d))
    base = math.atan2(p["l3"], cx)
    return (p["l3"] * math.cos(base + alpha), p["l3"] * math.sin(base + alpha))


@pytest.mark.parametrize("k", [0.5, 2.0, 7.5])
def test_results_scale_with_the_mechanism(k: float) -> None:
    """Rescaling every length rescales every length result and leaves the angles alone."""
    a = geomcad.solve("2013-6").results
    b = geomcad.solve("2013-6", **{n: v * k for n, v in SEED.items() if n != "K"}).results
    for name in ("O1B0", "O1B1", "l1", "l2", "H_check"):
        assert b[name] == pytest.approx(a[name] * k, rel=REL)
    assert b["theta_deg"] == pytest.approx(a["theta_deg"], rel=REL)
    assert b["K_check"] == pytest.approx(a["K_check"], rel=REL)


def test_every_solution_sees_b0b1_under_theta() -> None:
    sol = geomcad.solve("2013-6")
    c = sol.construction
    b0, b1 = c["B0"], c["B1"]
    theta = math.radians(sol.results["theta_deg"])
    for s in sol.results["solutions"]:
        o = np.array(s["O1"])
        u, v = np.array(tuple(b0)) - o, np.array(tuple(b1)) - o
        seen = math.atan2(abs(u[0] * v[1] - u[1] * v[0]), float(u @ v))
        assert seen == pytest.approx(theta, rel=REL)


def test_the_check_reports_a_synthesis_that_misses_its_stroke() -> None:
    sol = geomcad.solve(
        "2013-6",
        H=0.1761659143404782,
        K=2.308716046061097,
        l3=0.4598713078539125,
        l4=0.10904649182023587,
        e=0.12850327675004805,
    )
    assert sol.results["K_check"] < 2.0
    assert any("does not reverse" in n for n in sol.notes)


def test_notes_name_the_seed_formula_slip() -> None:
    assert any("OB1" in n for n in geomcad.solve("2013-6").notes)


BAD = [
    ({"K": 0.8}, ParameterError, r"parameter K = 0\.8: must be > 1"),
    ({"K": 1.0}, ParameterError, r"parameter K = 1\.0: must be > 1"),
    ({"K": 3.0}, ParameterError, r"parameter K = 3\.0: must be < 3"),
    ({"H": -0.1}, ParameterError, r"parameter H = -0\.1: must be > 0"),
    ({"l3": 0.0}, ParameterError, r"parameter l3 = 0\.0: must be > 0"),
    ({"e": 0.0}, ParameterError, r"parameter e = 0\.0: must be > 0"),
    ({"H": 1.0}, ParameterError, r"parameter H = 1\.0: too large .* cannot close"),
    (
        {"e": 2.0},
        NoIntersection,
        r'step "O1 = leftmost point of the θ-arcs on y = l3 − e": the line',
    ),
    ({"K": 1.4, "H": 0.15}, NoIntersection, r"misses the arcs .* e must lie between 0 and 0\.289"),
    ({"K": "x"}, ParameterError, r"parameter K = 'x': must be a number"),
    ({"K": float("nan")}, ParameterError, r"must be a finite number"),
    ({"Q": 1.0}, ParameterError, r"parameter Q .*no such parameter"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve("2013-6", **params)


def test_errors_are_value_errors_and_construction_errors_name_a_step() -> None:
    with pytest.raises(ValueError):
        geomcad.solve("2013-6", K=0.5)
    with pytest.raises(ConstructionError) as info:
        geomcad.solve("2013-6", e=2.0)
    assert info.value.step.startswith("O1 = ")
