"""2013-3, the mechanism with a cross: the velocity plan against the seed, closed forms, and an
independent numerical differentiation of the positions."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geomcad
from geomcad.errors import ParameterError
from geomcad.geom import Vec

PID = "2013-3"


def positions(
    s: float, v_A: float, l_AB: float, l_O1O2: float, alpha_deg: float
) -> dict[str, np.ndarray]:
    """Independent positions after link 1 has moved by s along x: plain numpy, no plan."""
    a = math.radians(alpha_deg)
    A = np.array([-2 * l_AB * math.cos(a) + s, 0.0])
    B = np.array([-l_AB * math.cos(a) + s, -l_AB * math.sin(a)])
    u = -B / np.linalg.norm(B)  # slot direction B → O1 → C
    O2 = np.array([l_O1O2, 0.0])
    C = u * (O2 @ u)
    return {"A": A, "B": B, "C": C, "u": u, "O2": O2}


def by_differentiation(v_A: float = 1.0, l_AB: float = 0.1, l_O1O2: float = 0.2, M: float = 10.0,
                       alpha_deg: float = 60.0) -> dict[str, float]:  # fmt: skip
    """The velocities as time derivatives of the positions (central differences, h = 1e-6 m)."""
    h = 1e-6 * l_AB
    p = [positions(s, v_A, l_AB, l_O1O2, alpha_deg) for s in (-h, h)]
    dt = 2 * h / v_A  # link 1 moves at v_A
    th3 = [math.atan2(q["u"][1], q["u"][0]) for q in p]
    th5 = [math.atan2(*(q["C"] - q["O2"])[::-1]) for q in p]
    w3 = (th3[1] - th3[0]) / dt
    w5 = (th5[1] - th5[0]) / dt
    q0 = positions(0.0, v_A, l_AB, l_O1O2, alpha_deg)
    C = q0["C"]
    vc4 = (p[1]["C"] - p[0]["C"]) / dt
    vb3b2 = (np.linalg.norm(p[1]["B"]) - np.linalg.norm(p[0]["B"])) / dt
    return {
        "V_B3": abs(w3) * np.linalg.norm(q0["B"]),
        "V_B3B2": abs(vb3b2),
        "omega3": abs(w3),
        "V_C3": abs(w3) * np.linalg.norm(C),
        "omega5": abs(w5),
        "V_C5": abs(w5) * np.linalg.norm(C - q0["O2"]),
        "V_C4": float(np.linalg.norm(vc4)),
        "F_red": abs(M * w5 / v_A),
    }


def test_seed_values_within_their_rounding() -> None:
    sol = geomcad.solve(PID)
    rows = sol.seed_report()
    assert {r["name"] for r in rows} == set(sol.results)
    for row in rows:
        assert row["agrees"], row


def test_exact_values_in_closed_form() -> None:
    r = geomcad.solve(PID).results
    s3 = math.sqrt(3.0)
    expect = {"V_B3": s3 / 2, "V_B3B2": 0.5, "omega3": 5 * s3, "V_C3": s3 / 2, "omega5": 5 * s3,
              "V_C5": 1.5, "V_C4": s3, "F_red": 50 * s3}  # fmt: skip
    for k, v in expect.items():
        assert r[k] == pytest.approx(v, rel=1e-12), k


def test_plan_matches_numerical_differentiation_of_positions() -> None:
    r = geomcad.solve(PID).results
    for k, v in by_differentiation().items():
        assert r[k] == pytest.approx(v, rel=1e-6), k


@settings(max_examples=40, deadline=None)
@given(
    v_A=st.floats(0.1, 5.0) | st.floats(-5.0, -0.1),
    l_AB=st.floats(0.02, 0.5),
    l_O1O2=st.floats(0.05, 1.0),
    M=st.floats(-50.0, 50.0),
    alpha_deg=st.floats(5.0, 85.0),
)
def test_variants_match_differentiation_and_closed_forms(
    v_A: float, l_AB: float, l_O1O2: float, M: float, alpha_deg: float
) -> None:
    p = {"v_A": v_A, "l_AB": l_AB, "l_O1O2": l_O1O2, "M": M, "alpha_deg": alpha_deg}
    r = geomcad.solve(PID, **p).results
    num = by_differentiation(**p)
    for k, v in num.items():
        assert r[k] == pytest.approx(v, rel=1e-5, abs=1e-9), k
    a = math.radians(alpha_deg)
    w = abs(v_A) * math.sin(a) / l_AB
    assert r["V_B3"] == pytest.approx(abs(v_A) * math.sin(a), rel=1e-9)
    assert r["V_B3B2"] == pytest.approx(abs(v_A) * math.cos(a), rel=1e-9)
    assert r["omega3"] == pytest.approx(w, rel=1e-9)
    assert r["V_C5"] == pytest.approx(w * l_O1O2 * math.sin(a), rel=1e-9)
    assert r["V_C4"] == pytest.approx(math.hypot(r["V_C3"], r["V_C5"]), rel=1e-9)
    assert r["F_red"] == pytest.approx(abs(M) * w / abs(v_A), rel=1e-9, abs=1e-12)


def test_plan_vectors_have_their_directions_and_the_image_is_similar() -> None:
    sol = geomcad.solve(PID, alpha_deg=40.0, l_O1O2=0.35)
    c, vp = sol.construction, sol.data.plan
    O1, O2, B, C = (c[n] for n in ("O1", "O2", "B", "C"))
    slot = (C - O1).unit()
    tol = 1e-12
    assert abs(vp["b3"].dot(B - O1)) <= tol  # V_B3 ⊥ O1B
    assert abs(vp.between("b2", "b3").cross(slot)) <= tol  # V_B3B2 ∥ O1B
    assert abs(vp["c5"].dot(C - O2)) <= tol  # V_C5 ⊥ O2C
    assert abs(vp.between("c3", "c4").cross(slot)) <= tol  # V_C4C3 ∥ O1C
    assert abs(vp.between("c5", "c4").cross((C - O2).unit())) <= tol  # V_C4C5 ∥ O2C
    # the image o1 b3 c3 is similar to O1 B C, turned the same way
    ratio = vp["c3"].norm / vp["b3"].norm
    assert ratio == pytest.approx(O1.dist(C) / O1.dist(B), rel=1e-12)
    assert vp["c3"].dot(vp["b3"]) < 0  # C lies across O1 from B
    assert (B - O1).cross(C - O1) == pytest.approx(0.0, abs=1e-15)
    # the plan's angular velocity is the same from either point of link 3
    w_b = vp.omega(O1, B, "o1", "b3")
    w_c = vp.omega(O1, C, "o1", "c3")
    assert w_b == pytest.approx(w_c, rel=1e-12)


def test_every_plan_vector_is_a_named_step() -> None:
    sol = geomcad.solve(PID)
    names = [s.name for s in sol.construction]
    for step in ("pa", "pb3", "b2b3", "pc3", "pc5", "pc4", "c3c4", "c5c4", "b3", "c4"):
        assert step in names, step
    trace = sol.trace()
    assert "c4 = line c4:1 ∩ line c4:2" in trace


def test_results_are_invariant_under_rescaling() -> None:
    a = geomcad.solve(PID).results
    b = geomcad.solve(PID, l_AB=0.3, l_O1O2=0.6, v_A=3.0).results
    for k in ("V_B3", "V_B3B2", "V_C3", "V_C5", "V_C4"):
        assert b[k] == pytest.approx(3.0 * a[k], rel=1e-12)
    assert b["omega3"] == pytest.approx(a["omega3"], rel=1e-12)


BAD = [
    ({"alpha_deg": 0.0}, ParameterError, r"parameter alpha_deg = 0\.0: must be > 0"),
    ({"alpha_deg": 90.0}, ParameterError, r"parameter alpha_deg = 90\.0: must be < 90"),
    ({"alpha_deg": 120.0}, ParameterError, r"must be < 90"),
    ({"l_AB": -0.1}, ParameterError, r"parameter l_AB = -0\.1: must be > 0"),
    ({"l_O1O2": 0.0}, ParameterError, r"parameter l_O1O2 = 0\.0: must be > 0"),
    ({"v_A": 0.0}, ParameterError, r"parameter v_A = 0\.0: must not be zero"),
    ({"M": float("inf")}, ParameterError, r"must be a finite number"),
    ({"v_A": "fast"}, ParameterError, r"must be a number"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve(PID, **params)


@pytest.mark.parametrize("setting", ["alpha_deg=95", "v_A=0", "l_AB=-1", "nope=1"])
def test_bad_input_through_the_cli(setting: str) -> None:
    run = subprocess.run(
        [sys.executable, "-m", "geomcad", "solve", PID, "--set", setting, "--json"],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr.startswith("error: 2013-3: parameter ")
    assert len(run.stderr.strip().splitlines()) == 1
    assert "Traceback" not in run.stderr


def test_scales_are_gost_and_plan_factor_is_nice() -> None:
    sol = geomcad.solve(PID)
    # 1:2: the layout's largest that fits (the Spacer under the title block may lie under the form)
    assert sol.scales["l"] == pytest.approx(0.002)
    kv = sol.scales["v"]
    mant = kv / 10 ** math.floor(math.log10(kv))
    assert min(abs(mant - m) for m in (1.0, 2.0, 2.5, 4.0, 5.0)) < 1e-9


def test_plan_fits_its_field_and_vectors_end_on_points() -> None:
    from geomcad_constructions.sheets_2013_3 import _views

    from geomcad.sheet.compose import Field, arrange

    sol = geomcad.solve(PID, alpha_deg=25.0)
    vp, kv = sol.data.plan, sol.scales["v"]
    _tree, _scheme, plan = _views(sol)
    lay = arrange(_tree, Field.of_format("A3"))
    ix0, iy0, ix1, iy1 = lay[plan].inner
    x0, y0, x1, y1 = vp.extent()
    assert (x1 - x0) / kv <= ix1 - ix0 + 1e-9
    assert (y1 - y0) / kv <= iy1 - iy0 + 1e-9
    assert sol.sheets()  # draws without error for a variant
    assert Vec(0, 0) == vp["p"]


@pytest.mark.parametrize("v_A, M", [(1.0, 10.0), (-1.0, -10.0), (-1.0, 10.0), (1.0, -10.0)])
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_the_moment_and_omega_are_named_by_their_arcs(v_A: float, M: float, lang: str) -> None:
    """Whatever the signs of v_A and M (the variant v_A = −1, M = −10, α = 45° among them), M is
    named at O2 and ω3 at O1: each label within 3 mm of its arc's middle, over no other text."""
    import shapely
    from geomcad_constructions.sheets_2013_3 import sheets

    from geomcad.sheet.lang import language
    from geomcad.sheet.model import TextItem
    from geomcad.sheet.placer import text_outline

    sol = geomcad.solve(PID, v_A=v_A, M=M, alpha_deg=45.0)
    with language(lang):
        sheet = sheets(sol)[0][1]
    texts = [it for it in sheet.items if isinstance(it, TextItem)]
    for name in ("M", "ω3"):
        (item, anchor), *more = [(it, p) for it, p in sheet.anchors if it.text == name]
        assert not more
        box = text_outline(item)
        assert box.distance(shapely.Point(anchor)) <= 3.0
        assert not [t.text for t in texts if t is not item and text_outline(t).overlaps(box)]
