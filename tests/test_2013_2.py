"""2013-2: the seed's radius vectors, exact values against independent formulas, variants (a full
turn, other laws, knife and roller followers, clockwise), bad input, and the sheet's layout."""

from __future__ import annotations

import itertools
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from layout import layout_problems

import geomcad
from geomcad.errors import ConstructionError, ParameterError
from geomcad.sheet.model import Polyline, Sheet
from geomcad.sheet.scale import Scale

PID = "2013-2"
MM = 1e-3
REL = 1e-9
SEED_R_MM = [41.98, 46.77, 51.6, 56.45, 61.34]
SEED_K_L = 0.0005  # 2:1

# -- the seed -------------------------------------------------------------------------------------


def test_seed_values_within_rounding_and_drawing_precision() -> None:
    sol = geomcad.solve(PID)
    rows = sol.seed_report()
    assert [r["name"] for r in rows] == ["a", "r.0", "r.1", "r.2", "r.3", "r.4"]
    assert all(r["agrees"] and r["class"] == "rounded" for r in rows), rows
    r = sol.results["r"]
    for exact, seed in zip(r, SEED_R_MM, strict=True):
        # printed to 0.01 mm (51,6 to 0.1 mm) …
        assert abs(exact - seed * MM) <= 0.05 * MM
        # … and well within drawing precision: 0.5 mm on the seed's 2:1 drawing
        assert abs(exact - seed * MM) <= 0.5 * SEED_K_L
    assert abs(sol.results["a"] - 12.73 * MM) <= 0.005 * MM


def test_exact_values_are_the_seeds_formula() -> None:
    r = geomcad.solve(PID).results
    a = 0.04 / math.pi
    phi = [i * math.pi / 8 for i in range(5)]
    assert r["phi"] == pytest.approx(phi, rel=REL)
    assert r["S"] == pytest.approx([a * p for p in phi], abs=1e-15)
    assert r["S"] == pytest.approx([0.0, 0.005, 0.01, 0.015, 0.02], abs=1e-15)
    assert r["a"] == pytest.approx(a, rel=REL)
    assert r["r"] == pytest.approx([math.hypot(0.04 + a * p, a) for p in phi], rel=1e-13)
    assert r["pressure_angle_max_deg"] == 0.0
    # the involute's smallest radius of curvature is its string at φ = 0+, r0
    assert r["rho_min"] == pytest.approx(0.04, rel=REL)


def test_profile_starts_on_the_base_circle_and_ends_at_b4() -> None:
    r = geomcad.solve(PID).results
    prof = np.array(r["profile"])
    assert prof.shape[1] == 2 and len(prof) > 150
    assert tuple(prof[0]) == (0.0, 0.04)  # the base circle's top, before the jump
    a = r["a"]
    assert prof[1:].tolist().count([a, 0.04]) == 1  # the involute starts a along the face
    radii = np.hypot(prof[:, 0], prof[:, 1])
    assert np.all(np.diff(radii) >= -1e-15)  # the radius grows along the rise
    assert radii[-1] == pytest.approx(r["r"][-1], rel=1e-14)
    assert prof[-1] == pytest.approx([0.06, -a], abs=1e-15)


def test_notes_explain_the_jump_at_phi_0_and_the_seeds_letters() -> None:
    notes = geomcad.solve(PID).notes
    jump = next(n for n in notes if n.startswith("at φ = 0°,"))
    assert "S′ jumps from 0 to 12.7324 mm" in jump and "rigid impact" in jump
    assert "straight piece of the face line" in jump and "41.98" in jump
    assert "involute of the circle of radius a" in jump
    assert any("seed notation" in n and "B′" in n for n in notes)
    # a variant without a jump has no such note
    assert not any(n.startswith("at φ") for n in geomcad.solve(PID, law="harmonic").notes)


def test_trace_names_the_inversion_steps() -> None:
    text = geomcad.solve(PID).trace()
    for step in ("axis_2 =", "face_2 = perpendicular to axis_2 at C_2", "B_2 = on face_2",
                 "r_2 = |OB_2|", "profile = envelope of the face lines", "OB′ ="):  # fmt: skip
        assert step in text, step


def test_solve_json_has_list_seed_and_diff() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "geomcad", "solve", PID, "--json"],
        capture_output=True,
        text=True,
        encoding="utf-8",
        check=True,
    ).stdout
    data = json.loads(out)
    assert data["seed"]["r"] == pytest.approx([x * MM for x in SEED_R_MM], abs=1e-15)
    assert data["seed"]["a"] == pytest.approx(0.01273, abs=1e-15)
    for d, e, s in zip(data["diff"]["r"], data["results"]["r"], data["seed"]["r"], strict=True):
        assert d == pytest.approx(e - s, abs=1e-15)
    assert data["params"]["law"] == "linear" and data["params"]["n_div"] == 4


def test_verify_reads_radius_vectors_off_the_seeds_drawing() -> None:
    from geomcad.verify import verify

    report = verify(geomcad.solve(PID), {"r.2_mm": 103.2, "r.4_mm": "122,3"})
    assert report.ok
    assert report.items[0].exact == pytest.approx(geomcad.solve(PID).results["r"][2])
    assert not verify(geomcad.solve(PID), {"r.4_mm": 121.0}).ok


# -- variants -------------------------------------------------------------------------------------


def _law(name: str, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The laws written out independently (s, s′, s″ over u in [0, 1])."""
    if name == "harmonic":
        return (
            (1 - np.cos(np.pi * u)) / 2,
            np.pi / 2 * np.sin(np.pi * u),
            np.pi**2 / 2 * np.cos(np.pi * u),
        )
    if name == "cycloidal":
        t = 2 * np.pi * u
        return u - np.sin(t) / (2 * np.pi), 1 - np.cos(t), 2 * np.pi * np.sin(t)
    if name == "poly345":
        return (
            10 * u**3 - 15 * u**4 + 6 * u**5,
            30 * u**2 - 60 * u**3 + 30 * u**4,
            60 * u - 180 * u**2 + 120 * u**3,
        )
    raise AssertionError(name)


def _full_turn(law: str, H: float, rise: float, dwell: float, ret: float, phi: np.ndarray) -> tuple:
    S, S1, S2 = np.zeros_like(phi), np.zeros_like(phi), np.zeros_like(phi)
    up = phi < rise
    s, ds, dds = _law(law, phi[up] / rise)
    S[up], S1[up], S2[up] = H * s, H / rise * ds, H / rise**2 * dds
    top = (phi >= rise) & (phi < rise + dwell)
    S[top] = H
    down = (phi >= rise + dwell) & (phi < rise + dwell + ret)
    s, ds, dds = _law(law, (phi[down] - rise - dwell) / ret)
    S[down], S1[down], S2[down] = H * (1 - s), -H / ret * ds, -H / ret**2 * dds
    return S, S1, S2


FULL = {"law": "harmonic", "phi_dwell_deg": 30.0, "phi_return_deg": 150.0, "span_fraction": 1.0,
        "n_div": 12}  # fmt: skip


@pytest.mark.parametrize("law", ["harmonic", "cycloidal", "poly345"])
def test_full_turn_flat_face_against_independent_formulas(law: str) -> None:
    sol = geomcad.solve(PID, **{**FULL, "law": law})
    assert sol.seed == {} and sol.diff == {}
    r = sol.results
    rise, dwell, ret = math.radians(180), math.radians(30), math.radians(150)
    phi = np.array(r["phi"])
    assert phi == pytest.approx(np.arange(13) * math.pi / 6, rel=REL)
    S, S1, _ = _full_turn(law, 0.04, rise, dwell, ret, phi[:-1])
    np.testing.assert_allclose(r["S"][:-1], S, atol=1e-15)
    np.testing.assert_allclose(r["r"][:-1], np.hypot(0.04 + S, S1), rtol=1e-12)
    assert r["r"][-1] == pytest.approx(0.04, rel=1e-12)
    fine = np.linspace(0, 2 * math.pi, 400001)[:-1]
    S, _, S2 = _full_turn(law, 0.04, rise, dwell, ret, fine)
    assert r["rho_min"] == pytest.approx(float(np.min(0.04 + S + S2)), rel=1e-6)
    prof = np.array(r["profile"])
    assert np.hypot(prof[:, 0], prof[:, 1]).max() == pytest.approx(0.08, rel=1e-9)


def test_knife_with_offset_against_independent_formulas() -> None:
    e, law = 0.01, "cycloidal"
    sol = geomcad.solve(PID, follower="knife", e=e, law=law, n_div=6, span_fraction=1.0)
    r = sol.results
    phi = np.array(r["phi"])
    rise = math.pi
    s, ds, _ = _law(law, np.clip(phi / rise, 0, 1))
    S, S1 = 0.04 * s, 0.04 / rise * ds
    s0 = math.sqrt(0.04**2 - e**2)
    np.testing.assert_allclose(r["r"], np.hypot(e, s0 + S), rtol=1e-13)
    fine = np.linspace(0, rise, 200001)
    s, ds, _ = _law(law, fine / rise)
    alpha = np.degrees(np.abs(np.arctan2(0.04 / rise * ds - e, s0 + 0.04 * s)))
    assert r["pressure_angle_max_deg"] == pytest.approx(float(alpha.max()), abs=1e-6)
    assert np.max(np.abs(S1)) > 0


def test_roller_radius_vectors_are_the_offset_profile() -> None:
    e, r_r = 0.008, 0.012
    sol = geomcad.solve(PID, follower="roller", e=e, r_roller=r_r, law="poly345",
                        phi_rise_deg=120, phi_dwell_deg=60, phi_return_deg=120,
                        span_fraction=1.0, n_div=8)  # fmt: skip
    r = sol.results
    phi = np.array(r["phi"])
    rise, dwell, ret = (math.radians(x) for x in (120, 60, 120))
    S, S1, _ = _full_turn("poly345", 0.04, rise, dwell, ret, phi)
    s0 = math.sqrt(0.04**2 - e**2)
    q = np.stack([np.full_like(phi, e), s0 + S], axis=1)
    nu = np.stack([e - S1, s0 + S], axis=1)
    nu /= np.linalg.norm(nu, axis=1)[:, None]
    np.testing.assert_allclose(r["r"], np.linalg.norm(q - r_r * nu, axis=1), rtol=1e-12)
    # the working profile's base circle is r0 − r_roller (r0 is the pitch curve's)
    assert min(r["r"]) == pytest.approx(0.04 - r_r, rel=1e-12)
    assert r["rho_min"] > 0


def test_clockwise_cam_has_the_same_radii() -> None:
    ccw = geomcad.solve(PID).results
    cw = geomcad.solve(PID, omega_sign=-1).results
    assert cw["r"] == pytest.approx(ccw["r"], rel=1e-14)
    mirrored = np.array(cw["profile"]) * [-1.0, 1.0]
    np.testing.assert_allclose(mirrored, ccw["profile"], atol=1e-15)


@pytest.mark.parametrize("k", [0.25, 4.0])
def test_results_scale_with_the_cam(k: float) -> None:
    a = geomcad.solve(PID).results
    b = geomcad.solve(PID, H=0.04 * k, r0=0.04 * k).results
    for name in ("r", "S"):
        assert b[name] == pytest.approx([x * k for x in a[name]], rel=1e-12, abs=1e-15)
    assert b["rho_min"] == pytest.approx(a["rho_min"] * k, rel=REL)
    assert b["phi"] == a["phi"]


# -- bad input ------------------------------------------------------------------------------------

BAD = [
    ({"H": -0.04}, ParameterError, r"parameter H = -0\.04: must be > 0"),
    ({"H": 0.0}, ParameterError, r"parameter H = 0\.0: must be > 0"),
    ({"phi_rise_deg": 0.0}, ParameterError, r"parameter phi_rise_deg = 0\.0: must be > 0"),
    ({"phi_rise_deg": 400.0}, ParameterError, r"phi_rise_deg = 400\.0: must be ≤ 360"),
    ({"r0": 0.0}, ParameterError, r"parameter r0 = 0\.0: must be > 0"),
    ({"r0": -0.01}, ParameterError, r"parameter r0 = -0\.01: must be > 0"),
    ({"n_div": 0}, ParameterError, r"parameter n_div = 0: must be ≥ 1"),
    ({"n_div": 2.5}, ParameterError, r"n_div = 2\.5: must be a whole number"),
    ({"span_fraction": 0.0}, ParameterError, r"span_fraction = 0\.0: must be > 0"),
    ({"span_fraction": 1.5}, ParameterError, r"span_fraction = 1\.5: must be ≤ 1"),
    ({"omega_sign": 2}, ParameterError, r"omega_sign = 2: must be \+1 or −1"),
    ({"phi_return_deg": 200.0}, ParameterError, r"rise \+ dwell \+ return = 380° is more"),
    ({"law": "spline"}, ParameterError, r"law = 'spline': must be one of linear, constant_"),
    ({"follower": "mushroom"}, ParameterError, r"follower = 'mushroom': must be one of flat"),
    ({"follower": "roller"}, ParameterError, r"r_roller = 0\.0: a roller follower needs"),
    ({"follower": "knife", "e": 0.05}, ParameterError, r"parameter e = 0\.05: .*\|e\| < r0"),
    (
        {"follower": "roller", "r_roller": 0.039},
        ConstructionError,
        r'step "profile = inner offset of the pitch curve by r_roller .*": the roller radius '
        r"r_roller = 0\.039 m is not smaller than the pitch curve's smallest radius of curvature "
        r"ρ = 0\.03844",
    ),
    (
        {"follower": "roller", "r_roller": 0.05},
        ConstructionError,
        r"r_roller = 0\.05 m is not smaller than r0 = 0\.04 m",
    ),
    (
        {"law": "linear", "phi_return_deg": 180.0},
        ConstructionError,
        r'step "profile = envelope of the face lines.*": S′ drops from 0\.0127324 to -0\.0127324',
    ),
    (
        {"law": "harmonic", "phi_rise_deg": 60.0, "phi_return_deg": 60.0, "r0": 0.02},
        ConstructionError,
        r"the profile has a cusp at φ = .*the base circle is too small for this law",
    ),
    ({"H": "x"}, ParameterError, r"parameter H = 'x': must be a number"),
    ({"r0": float("inf")}, ParameterError, r"must be a finite number"),
    ({"Q": 1.0}, ParameterError, r"parameter Q .*no such parameter"),
]  # fmt: skip


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


def _cli(*argv: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "geomcad", *argv],
        capture_output=True,
        text=True,
        encoding="utf-8",
        timeout=120,
    )


CLI_BAD = [
    (["H=-0.04"], "parameter H = -0.04: must be > 0"),
    (["phi_rise_deg=0"], "parameter phi_rise_deg = 0.0: must be > 0"),
    (["r0=0"], "parameter r0 = 0.0: must be > 0"),
    (["law=spline"], "law = 'spline': must be one of"),
    (["follower=roller", "r_roller=0.039"],
     'step "profile = inner offset of the pitch curve by r_roller'),
    (["phi_return_deg=180"], 'step "profile = envelope of the face lines'),
    (["n_div=abc"], "n_div = 'abc': must be a whole number"),
]  # fmt: skip


@pytest.mark.parametrize(("sets", "words"), CLI_BAD)
def test_bad_input_through_the_cli(sets: list[str], words: str) -> None:
    argv = ["solve", PID, *itertools.chain.from_iterable(("--set", s) for s in sets), "--json"]
    res = _cli(*argv)
    assert res.returncode == 2
    assert res.stdout == ""
    lines = res.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {PID}: "), res.stderr
    assert words in lines[0]
    assert "Traceback" not in res.stderr


def test_errors_are_value_errors_and_name_the_step() -> None:
    with pytest.raises(ValueError):
        geomcad.solve(PID, r0=-1.0)
    with pytest.raises(ConstructionError) as info:
        geomcad.solve(PID, phi_return_deg=180.0)
    assert info.value.step.startswith("profile = envelope of the face lines (inversion)")


# -- the sheet ------------------------------------------------------------------------------------


def _check_layout(sheet: Sheet) -> None:
    problems = layout_problems(sheet)
    assert not problems, "\n".join(problems[:20])


def test_seed_sheet_is_a2_at_2_to_1_with_no_overlaps() -> None:
    """A2: the whole rise at the seed's 2:1 (the span thick, the rest of the rise thin)."""
    sol = geomcad.solve(PID)
    assert sol.scales["l"] == SEED_K_L
    ((name, sheet),) = sol.sheets()
    assert name == "" and sheet.format == "A2"
    _check_layout(sheet)
    assert "2:1" in [t.text for t in sheet.texts()]
    words = {t.text for t in sheet.texts()}
    for w in ("B0", "B4", "r0 = 41,98", "r4 = 61,34", "O", "B'", "b1", "b2", "p", "C"):
        assert w in words, w


def test_seed_sheet_radius_vectors_are_true_to_scale() -> None:
    sol = geomcad.solve(PID)
    k = sol.scales["l"]
    sheet = sol.sheets()[0][1]
    # the radius vectors r_i = OB_i: thin construction segments from O (no arrowheads), each
    # as long as r_i at k_l
    segs = [
        it.points
        for it in sheet.items
        if isinstance(it, Polyline) and it.role == "construction" and len(it.points) == 2
    ]
    found = []
    for r in sol.results["r"]:
        hits = [pts for pts in segs if math.dist(*pts) * k == pytest.approx(r, rel=1e-9)]
        assert hits, r
        found.append(hits[0][0])
    assert all(o == found[0] for o in found)


@pytest.mark.parametrize(
    "params",
    [
        FULL,
        {"follower": "knife", "e": 0.01, "omega_sign": -1, "law": "cycloidal", "n_div": 6,
         "span_fraction": 1.0},
        {"follower": "roller", "e": 0.008, "r_roller": 0.012, "law": "poly345",
         "phi_rise_deg": 120, "phi_dwell_deg": 60, "phi_return_deg": 120, "span_fraction": 1.0,
         "n_div": 8},
        {"H": 0.1, "r0": 0.15, "law": "constant_acceleration", "n_div": 30},
        {"H": 2.0, "phi_rise_deg": 5.0, "r0": 0.1, "n_div": 40, "span_fraction": 0.001,
         "law": "constant_acceleration", "follower": "roller", "e": 0.045, "r_roller": 0.0377,
         "omega_sign": -1},
    ],
    ids=["full-turn", "knife-cw", "roller", "large", "tiny-span"],
)  # fmt: skip
def test_variant_sheets_fit_at_a_gost_scale(params: dict[str, object]) -> None:
    sol = geomcad.solve(PID, **params)
    k = Scale(sol.scales["l"], "l")
    assert k.ratio_text(), f"k_l = {k.k} is not a GOST 2.302 scale"
    sheet = sol.sheets()[0][1]
    _check_layout(sheet)
    # every paragraph is drawn (a glyph missing from the font would have raised)
    assert any(t.text == "Порядок построения" for t in sheet.texts())


@pytest.mark.parametrize(
    "params",
    [{}, {"follower": "roller", "r_roller": 0.01, "e": 0.005}, {"follower": "knife"}],
    ids=["flat", "roller", "knife"],
)
def test_order_of_construction_is_the_recorded_steps(params: dict[str, object]) -> None:
    """The order of construction lists the recorded steps through their kinds' templates: one
    division's steps written for any index i ("for each φ_i"), then the profile and the velocity
    plan of geomcad.kinematics.plan, with the recorded values, in both languages."""
    from geomcad_constructions.sheets_2013_2 import WORDS, order_steps

    from geomcad.sheet import views as V
    from geomcad.sheet.lang import language

    sol = geomcad.solve("2013-2", **params)
    c = sol.construction
    steps = order_steps(sol)
    names = [s.name for s in steps]
    assert names[:2] == ["base", "Δφ"] and names[-6:] == ["B", "p", "b1", "b2", "pb2", "B′"]
    assert "profile" in names and all(s.kind for s in steps)
    # the division's steps are recorded for every φ_i; the order writes them once, with i
    each = [s for s in steps if dict(s.args).get("i") == "i"]
    assert len(each) == (4 if sol.params["follower"] == "flat" else 3)
    assert all(dict(c.step(s.name).args)["i"] == 1.0 for s in each)
    for lang in ("ru", "en"):
        with language(lang):
            view = V.Steps(steps, 280.0, only=names, height=2.5, words=WORDS)
            numbered = [t for t in view.lines if t[:1].isdigit()]
            assert len(numbered) == len(steps)
            text = " ".join(view.lines)
            assert "C_{i}" in text and "C_{1}" not in text
            v_b2 = c.step("pb2").result.norm
            assert f"= {V.num(v_b2)} " in text  # V_B2 = pb2·μ_V, read off the plan
            assert f"S' = {V.num(sol.data.plan.S1 * 1000.0)} " in text  # OB' = S', mm
