"""2013-1: the W counts against the seed, the zero-velocity positions against the check formula
and a numerical derivative, variants, counts alone, bad input, the sheet."""

from __future__ import annotations

import math

import numpy as np
import pytest
from geomcad_constructions.p2013_1 import pusher_speed_ratio, slot_path_point
from layout import inside, item_box, overlapping_texts, text_box

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, NoIntersection, ParallelLines, ParameterError
from geomcad.sheet import Scale
from geomcad.sheet.model import TextItem
from geomcad.structure import mobility, remove_local_mobilities, replace_higher_pairs

PID = "2013-1"
SEED = {"e": 0.1, "psi_deg": 90.0, "h": -0.05, "theta1_deg": 0.0}
REL = 1e-9


def check_formula(e: float, psi_deg: float, h: float) -> list[float]:
    """θ1 = ψ ± arccos(h/e), in [0, 360), ascending, a double root once."""
    a = math.degrees(math.acos(h / e))
    return sorted({(psi_deg + s * a) % 360.0 for s in (1.0, -1.0)})


def pusher_position(theta1: np.ndarray, e: float, psi: float, h: float) -> np.ndarray:
    """The coordinate of M along the path, found without the library: solve the two line
    equations p·n1 = e, p·nψ = h as a 2×2 system per position."""
    out = []
    for t in theta1:
        a = np.array([[-math.sin(t), math.cos(t)], [-math.sin(psi), math.cos(psi)]])
        p = np.linalg.solve(a, np.array([e, h]))
        out.append(p @ np.array([math.cos(psi), math.sin(psi)]))
    return np.array(out)


def numeric_sign_changes(e: float, psi_deg: float, h: float, n: int = 7200) -> list[float]:
    """θ1 (deg) where the numerical derivative of M's path coordinate changes sign."""
    psi = math.radians(psi_deg)
    step = 2 * math.pi / n
    t = psi + (np.arange(n + 1) + 0.5) * step
    dt = 1e-6
    v = (pusher_position(t + dt, e, psi, h) - pusher_position(t - dt, e, psi, h)) / (2 * dt)
    idx = np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]
    return sorted(math.degrees(t[i] + step / 2) % 360.0 for i in idx)


# -- the seed ----------------------------------------------------------------------------------


def test_seed_counts() -> None:
    r = geomcad.solve(PID).results
    assert r["W_formal"] == 2
    assert r["W_local"] == 1
    assert r["W_true"] == 1
    assert r["W_after_replacement"] == 2
    assert r["W_after_seed"] == 1
    for k in ("W_formal", "W_local", "W_true", "W_after_replacement", "W_after_seed"):
        assert isinstance(r[k], int)


def test_seed_values_agree_except_the_erratum() -> None:
    sol = geomcad.solve(PID)
    rows = {row["name"]: row for row in sol.seed_report()}
    assert rows["W_formal"]["agrees"] and rows["W_formal"]["diff"] == 0
    assert rows["W_after_seed"]["agrees"] and rows["W_after_seed"]["diff"] == 0
    assert rows["W_after_replacement"]["class"] == "erratum"


def test_seed_erratum_w_after_replacement_counts_without_the_roller() -> None:
    """The seed's "after" count 3·7 − 2·10 = 1 drops the roller's spin that its "before" count
    3·7 − 2·9 − 1 = 2 keeps; the standard replacement gives 3·8 − 2·11 = 2, W unchanged."""
    sol = geomcad.solve(PID)
    assert sol.seed["W_after_replacement"] == 1.0
    assert sol.diff["W_after_replacement"] == 1.0
    assert sol.results["W_after_replacement"] == sol.results["W_formal"] == 2
    assert sol.results["W_after_seed"] == sol.results["W_true"] == 1
    notes = " ".join(sol.notes)
    assert "erratum W_after_replacement" in notes
    assert "3·8 − 2·11 = 2" in notes and "local mobility" in notes


def test_seed_counts_come_from_the_model() -> None:
    geo = geomcad.solve(PID).data
    mb = geo.mob_before
    assert (mb.n, mb.p5, mb.p4, mb.w_local, mb.redundant) == (7, 9, 1, 1, 0)
    centre = mb.local[0].centre
    assert mb.local[0].link == "6" and centre is not None
    assert centre.dist(geo.points["M"]) < 1e-12
    ma = geo.mob_after
    assert (ma.n, ma.p5, ma.p4, ma.formal, ma.w_local) == (8, 11, 0, 2, 1)
    ms = geo.mob_seed
    assert (ms.n, ms.p5, ms.p4, ms.formal, ms.w_local) == (7, 10, 0, 1, 0)
    # the two routes to a mechanism without the roller agree
    other = remove_local_mobilities(replace_higher_pairs(geo.before).mechanism).mechanism
    mo = mobility(other)
    assert (mo.n, mo.p5, mo.formal) == (7, 10, 1)


def test_seed_assur_groups() -> None:
    dec = geomcad.solve(PID).data.decomposition
    assert [p.link for p in dec.primary] == ["2"]
    got = [(g.links, g.group_class, g.order, g.kind) for g in dec.groups]
    assert got == [(("1", "3"), 2, 2, "RRR"), (("7", "6"), 2, 2, "PRP"), (("4", "5"), 2, 2, "RRR")]
    assert dec.mechanism_class == 2


def test_seed_zero_positions_and_speed() -> None:
    r = geomcad.solve(PID).results
    assert r["zero_theta1_deg"] == pytest.approx([210.0, 330.0], abs=1e-9)
    # at θ1 = 0 the slot y = 0.1 crosses the path x = 0.05; turning it counter-clockwise about O
    # lifts that crossing: V_T = ω1·0.05
    assert r["VT_over_omega1"] == pytest.approx(0.05, rel=REL)


# -- the kinematics against independent checks -------------------------------------------------

VARIANTS = [
    SEED,
    {"e": 0.1, "psi_deg": 90.0, "h": 0.05, "theta1_deg": 20.0},
    {"e": 0.25, "psi_deg": 30.0, "h": -0.1, "theta1_deg": 100.0},
    {"e": 0.08, "psi_deg": -70.0, "h": 0.0, "theta1_deg": 45.0},
    {"e": -0.12, "psi_deg": 200.0, "h": 0.07, "theta1_deg": 10.0},
    {"e": 0.3, "psi_deg": 0.0, "h": 0.299, "theta1_deg": 80.0},
]


@pytest.mark.parametrize("p", VARIANTS, ids=lambda p: ",".join(f"{k}={v}" for k, v in p.items()))
def test_zero_positions_match_the_check_formula(p: dict[str, float]) -> None:
    r = geomcad.solve(PID, **p).results
    assert r["zero_theta1_deg"] == pytest.approx(
        check_formula(p["e"], p["psi_deg"], p["h"]), abs=1e-9
    )
    assert all(0.0 <= t < 360.0 for t in r["zero_theta1_deg"])
    assert r["zero_theta1_deg"] == sorted(r["zero_theta1_deg"])


@pytest.mark.parametrize("p", VARIANTS, ids=lambda p: ",".join(f"{k}={v}" for k, v in p.items()))
def test_zero_positions_are_where_a_numerical_derivative_changes_sign(p: dict[str, float]) -> None:
    r = geomcad.solve(PID, **p).results
    numeric = numeric_sign_changes(p["e"], p["psi_deg"], p["h"])
    assert len(numeric) == len(r["zero_theta1_deg"])
    step = 360.0 / 7200
    for got, want in zip(r["zero_theta1_deg"], numeric, strict=True):
        assert abs(math.remainder(got - want, 360.0)) <= step


@pytest.mark.parametrize("p", VARIANTS, ids=lambda p: ",".join(f"{k}={v}" for k, v in p.items()))
def test_speed_ratio_is_the_derivative_of_the_pusher_position(p: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **p)
    e, h, psi = p["e"], p["h"], math.radians(p["psi_deg"])
    t = math.radians(p["theta1_deg"])
    dt = 1e-6
    s = pusher_position(np.array([t - dt, t + dt]), e, psi, h)
    numeric = (s[1] - s[0]) / (2 * dt)
    assert sol.results["VT_over_omega1"] == pytest.approx(numeric, rel=1e-6, abs=1e-9)
    # and the closed form (e·cos δ − h)/sin²δ, δ = θ1 − ψ
    d = t - psi
    assert sol.results["VT_over_omega1"] == pytest.approx(
        (e * math.cos(d) - h) / math.sin(d) ** 2, rel=REL
    )


def test_the_vectorized_plan_agrees_with_the_recorded_one() -> None:
    t = np.radians(np.arange(1.0, 360.0, 7.0))
    v = pusher_speed_ratio(t, 0.1, math.pi / 2, -0.05)
    for ti, vi in zip(t, v, strict=True):
        if math.isfinite(vi):
            got = geomcad.solve(PID, theta1_deg=math.degrees(ti)).results["VT_over_omega1"]
            assert got == pytest.approx(vi, rel=REL)
    m = slot_path_point(np.array([0.0]), 0.1, math.pi / 2, -0.05)
    assert m[0] == pytest.approx([0.05, 0.1])


def test_at_the_zero_position_the_plan_closes_at_the_pole() -> None:
    c = geomcad.solve(PID).construction
    assert c["m6*"].norm < 1e-12
    z = geomcad.solve(PID).data.zeros[geomcad.solve(PID).data.built]
    # ML ⊥ MO
    assert abs((z.L - z.M).dot(z.M)) < 1e-12
    assert z.M.norm == pytest.approx(0.1, rel=REL)


def test_a_path_tangent_to_the_circle_has_no_zero_position() -> None:
    """|h| = |e|: the tangent at the touching point is the path itself; nearby
    V_T/ω1 = (e·cos δ − e)/sin²δ → −e/2, so the speed never vanishes."""
    with pytest.raises(NoIntersection, match="touches the circle"):
        geomcad.solve(PID, h=-0.1)
    d = np.radians([0.1, -0.1, 0.01])
    v = pusher_speed_ratio(math.pi / 2 + d, 0.1, math.pi / 2, 0.1)
    assert v == pytest.approx([-0.05] * 3, rel=1e-4)


@pytest.mark.parametrize("k", [0.5, 3.0])
def test_results_scale_with_the_mechanism(k: float) -> None:
    a = geomcad.solve(PID).results
    b = geomcad.solve(PID, e=0.1 * k, h=-0.05 * k).results
    assert b["zero_theta1_deg"] == pytest.approx(a["zero_theta1_deg"], abs=1e-9)
    assert b["VT_over_omega1"] == pytest.approx(a["VT_over_omega1"] * k, rel=REL)
    assert b["W_true"] == a["W_true"]


def test_turning_everything_turns_the_zero_positions() -> None:
    a = geomcad.solve(PID).results["zero_theta1_deg"]
    b = geomcad.solve(PID, psi_deg=130.0, theta1_deg=40.0).results
    assert b["zero_theta1_deg"] == pytest.approx(sorted((x + 40.0) % 360 for x in a), abs=1e-9)
    assert b["VT_over_omega1"] == pytest.approx(0.05, rel=REL)


# -- counts alone ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("counts", "want"),
    [
        ({"n": 3, "p5": 4, "p4": 0, "local": 0}, (1, 0, 1, 1, 1)),  # a four-bar
        ({"n": 3, "p5": 3, "p4": 1, "local": 1}, (2, 1, 1, 2, 1)),  # a cam with a roller
        ({"n": 5, "p5": 5, "p4": 4, "local": 0}, (1, 0, 1, 1, 1)),  # two planetary stages
        ({"n": 7, "p5": 9, "p4": 1, "local": 0}, (2, 0, 2, 2, 2)),
    ],
)
def test_counts_alone(counts: dict[str, int], want: tuple[int, ...]) -> None:
    sol = geomcad.solve(PID, **counts)
    r = sol.results
    got = tuple(
        r[k] for k in ("W_formal", "W_local", "W_true", "W_after_replacement", "W_after_seed")
    )
    assert got == want
    assert sol.seed == {}
    assert any("counts alone" in n for n in sol.notes)


# -- bad input ---------------------------------------------------------------------------------

BAD = [
    ({"n": 2, "p5": 3, "p4": 0, "local": 0}, ConstructionError, r"not a mechanism"),
    ({"n": 3, "p5": 4, "p4": 1, "local": 0}, ConstructionError, r"= 0 ≤ 0: not a mechanism"),
    ({"local": 3}, ConstructionError, r"W = 3·7 − 2·9 − 1 − 3 = -1 ≤ 0"),
    ({"n": 1, "p5": 0, "p4": 0, "local": 2}, ParameterError, r"parameter local = 2: must be ≤ n"),
    ({"h": 0.2}, NoIntersection, r'step "M\* = pusher path ∩ circle\(O, \|e\|\)": .*never'),
    ({"h": -0.11}, NoIntersection, r"farther than the slot's offset"),
    ({"theta1_deg": 90.0}, ParallelLines, r'step "M = slot ∩ pusher path": the slot .* parallel'),
    ({"theta1_deg": 270.0}, ParallelLines, r"parallel to the pusher path"),
    ({"psi_deg": 0.0}, ParallelLines, r"parallel to the pusher path"),
    ({"n": -1}, ParameterError, r"parameter n = -1: must be ≥ 0"),
    ({"p5": -2}, ParameterError, r"parameter p5 = -2: must be ≥ 0"),
    ({"p4": -1}, ParameterError, r"parameter p4 = -1: must be ≥ 0"),
    ({"local": -1}, ParameterError, r"parameter local = -1: must be ≥ 0"),
    ({"p4": 1.5}, ParameterError, r"whole number"),
    ({"e": 0.0}, ParameterError, r"parameter e = 0\.0: must not be 0"),
    ({"e": float("inf")}, ParameterError, r"finite"),
    ({"psi_deg": "x"}, ParameterError, r"must be a number"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


CLI_BAD = [
    (["--set", "n=2", "--set", "p5=3", "--set", "p4=0", "--set", "local=0"], ["not a mechanism"]),
    (["--set", "h=0.2"], ['step "M* = pusher path ∩ circle(O, |e|)"', "never"]),
    (["--set", "theta1_deg=90"], ['step "M = slot ∩ pusher path"', "parallel"]),
    (["--set", "n=-1"], ["parameter n = -1", "≥ 0"]),
    (["--set", "p5=-3"], ["parameter p5", "≥ 0"]),
    (["--set", "p4=0.5"], ["p4", "whole number"]),
    (["--set", "e=0"], ["parameter e", "must not be 0"]),
]


@pytest.mark.parametrize(("argv", "words"), CLI_BAD)
def test_bad_input_through_the_cli(
    capsys: pytest.CaptureFixture[str], argv: list[str], words: list[str]
) -> None:
    for cmd in (["solve", PID, *argv], ["solve", PID, *argv, "--json"], ["build", PID, *argv]):
        if cmd[0] == "build" and "--set" in cmd:
            continue  # build takes no parameters
        code = main(cmd)
        out, err = capsys.readouterr()
        assert code == 2 and out == ""
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"error: {PID}: "), err
        for w in words:
            assert w in lines[0], (w, err)


def test_solve_json(capsys: pytest.CaptureFixture[str]) -> None:
    import json

    assert main(["solve", PID, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["results"]["W_formal"] == 2 and out["seed"]["W_after_seed"] == 1.0
    assert out["results"]["zero_theta1_deg"] == pytest.approx([210.0, 330.0])


# -- the sheet ---------------------------------------------------------------------------------

A2_FRAME = (20.0, 5.0, 589.0, 415.0)
A2_BLOCK = (589.0 - 185.0, 415.0 - 55.0, 589.0, 415.0)


@pytest.mark.parametrize("p", VARIANTS, ids=lambda p: ",".join(f"{k}={v}" for k, v in p.items()))
def test_sheet_layout(p: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **p)
    ((name, sheet),) = sol.sheets()
    assert name == "" and sheet.format == "A2"
    for key in ("l", "l_pos"):
        assert Scale(sol.scales[key], "l").ratio_text(), f"k_{key} is not a GOST scale"
    assert not overlapping_texts(sheet.texts())
    block = [it for it in sheet.items if it.role in ("frame", "frame_thin", "title")]
    drawn = [it for it in sheet.items if it not in block]
    for it in drawn:
        b = item_box(it)
        assert inside(b, A2_FRAME, 1e-6), f"outside the frame: {it}"
        if not isinstance(it, TextItem):
            assert not (
                b[0] < A2_BLOCK[2]
                and A2_BLOCK[0] < b[2]
                and b[1] < A2_BLOCK[3]
                and A2_BLOCK[1] < b[3]
            ), it
    for t in sheet.texts():
        if t.role == "label":
            bb = text_box(t)
            assert not (bb[2] > A2_BLOCK[0] and bb[3] > A2_BLOCK[1]), t.text


def test_sheet_is_true_to_scale() -> None:
    """|OM*| on the dead-position drawing is |e| at its k_l."""
    sol = geomcad.solve(PID)
    k = sol.scales["l_pos"]
    ((_, sheet),) = sol.sheets()
    labels = {t.text for t in sheet.texts()}
    assert {"O", "M", "L", "p, m6", "m1"} <= labels
    assert Scale(k, "l").ratio_text() == "1:2"
    assert Scale(sol.scales["l"], "l").ratio_text() == "1:4"


def test_order_of_construction_is_the_recorded_steps() -> None:
    """The panel's order of construction is ORDER's steps through their kinds' templates, in
    both languages, with the recorded zero positions and V_T/ω1 written as a student writes
    them."""
    from geomcad_constructions.sheets_2013_1 import ORDER, WORDS

    from geomcad.sheet import views as V
    from geomcad.sheet.lang import language

    sol = geomcad.solve("2013-1")
    c = sol.construction
    assert all(c.step(n).kind for n in ORDER)
    for lang in ("ru", "en"):
        with language(lang):
            steps = V.Steps([c.step(n) for n in ORDER], 162.0, only=ORDER, words=WORDS)
            numbered = [t for t in steps.lines if t[:1].isdigit()]
            assert len(numbered) == len(ORDER)
            text = " ".join(steps.lines)
            for deg in sol.results["zero_theta1_deg"]:
                assert f"θ_1 = {V.num(deg)}°" in text
            # pm6 is a plan segment (mm): V_T = pm6·μ_V at ω1 = 1 rad/s, V_T/ω1 in metres
            vt = V.num(sol.results["VT_over_omega1"])
            assert f"pm_6·μ_V = {vt}" in text and f"V_T/ω_1 = {vt}" in text
            # the dead position first, then the plan at the given θ1
            assert text.index("M*") < text.index("pm_6·μ_V =")


def test_assur_kinds_in_the_sheets_letters() -> None:
    """The groups' kinds in the language's pair letters: ВВВ/ПВП on Russian sheets."""
    from geomcad.sheet.assur import group_kind
    from geomcad.sheet.lang import language

    with language("ru"):
        assert (group_kind("RRR"), group_kind("PRP")) == ("ВВВ", "ПВП")
    with language("en"):
        assert (group_kind("RRR"), group_kind("PRP")) == ("RRR", "PRP")
