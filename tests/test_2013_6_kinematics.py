"""2013-6's kinematic analysis: the plans at φ1 against the vectorized sweep, the diagrams over a
turn against numerical differentiation, and the analysis sheet."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from geomcad_constructions.kin_2013_6 import analyse

import geomcad
from geomcad.errors import ConstructionError

PID = "2013-6"


@pytest.mark.parametrize(
    ("params", "phi1_deg", "omega1"),
    [({}, None, None), ({}, 200.0, -4.0), ({"K": 1.4, "H": 0.15, "e": 0.25}, 10.0, 7.0)],
)
def test_plans_equal_the_sweep_at_phi1(
    params: dict[str, float], phi1_deg: float | None, omega1: float | None
) -> None:
    sol = geomcad.solve(PID, **params)
    an, m = sol.data.analysis, sol.data.mechanism
    if phi1_deg is not None and omega1 is not None:
        an = analyse(m, math.radians(phi1_deg), omega1)
    phi = np.array([an.phi1])
    r = m.sweep(phi, an.omega1)
    acc = m.accelerations(phi, an.omega1)
    c = an.c
    for name, arr in (("A", r.A), ("B", r.B), ("C", r.C)):
        assert np.allclose(c[name].array(), arr[0], rtol=0, atol=1e-12), name
    scale_v = abs(an.omega1) * m.l1
    for name, arr in (("a", r.V_A), ("b", r.V_B), ("c", r.V_C)):
        assert np.allclose(an.vp[name].array(), arr[0], rtol=0, atol=1e-9 * scale_v), name
    scale_a = an.omega1**2 * m.l1
    for name, arr in zip(("a", "b", "c"), acc, strict=True):
        assert np.allclose(an.ap[name].array(), arr[0], rtol=0, atol=1e-9 * scale_a), name
    w = m.omegas(phi, an.omega1)
    e = m.epsilons(phi, an.omega1)
    assert np.allclose(an.omegas, [x[0] for x in w], rtol=1e-9)
    assert np.allclose(an.epsilons, [x[0] for x in e], rtol=1e-9, atol=1e-9 * an.omega1**2)


def test_acceleration_plan_vectors_have_their_directions() -> None:
    sol = geomcad.solve(PID)
    an = sol.data.analysis
    c, ap = an.c, an.ap
    A, B, C, O2 = (c[n] for n in ("A", "B", "C", "O2"))
    assert abs(ap.between("n_BA", "b").dot(B - A)) <= 1e-12  # a^τ_BA ⊥ AB
    assert abs(ap.between("n_BO2", "b").dot(B - O2)) <= 1e-12  # a^τ_BO2 ⊥ O2B
    assert abs(ap.between("n_CB", "c").dot(C - B)) <= 1e-12  # a^τ_CB ⊥ BC
    assert ap.between("a", "n_BA").unit().dot((A - B).unit()) == pytest.approx(1.0)  # B → A
    assert abs(ap["c"].cross(sol.data.mechanism.guide_d)) <= 1e-12  # a_C ∥ the path


def test_diagrams_match_differentiation() -> None:
    an = geomcad.solve(PID).data.analysis
    dphi = an.phi[1] - an.phi[0]
    # v = ds/dt = ω1·ds/dφ, a = ω1²·d²s/dφ² (ε1 = 0), central differences inside the turn
    v_num = np.gradient(an.s, dphi) * an.omega1
    a_num = np.gradient(np.gradient(an.s, dphi), dphi) * an.omega1**2
    inner = slice(3, -3)
    assert np.allclose(an.v[inner], v_num[inner], atol=2e-4 * np.max(np.abs(an.v)))
    assert np.allclose(an.a[inner], a_num[inner], atol=2e-3 * np.max(np.abs(an.a)))
    # s is measured from the left extreme: it spans exactly the stroke
    assert np.min(an.s) >= -1e-9
    assert 0.2 - 1e-5 <= np.max(an.s) <= 0.2 + 1e-9  # sampled every 0.5°


def test_the_kinematics_sheet_is_built() -> None:
    sol = geomcad.solve(PID)
    names = [n for n, _ in sol.sheets()]
    assert names == ["", "kinematics"]
    sheet = sol.sheets()[1][1]
    text = " ".join("".join(r.text for r in t.runs) for t in sheet.texts())
    assert "План скоростей" in text and "План ускорений" in text
    assert re.search(r"План скоростей, μV = \d+(,\d+)? \(м/с\)/мм", text)
    assert re.search(r"План ускорений, μa = \d+(,\d+)? \(м/с²\)/мм", text)


def test_the_analysis_position_is_60_degrees_past_the_left_extreme() -> None:
    sol = geomcad.solve(PID)
    an = sol.data.analysis
    assert an.phi1 == pytest.approx(sol.data.phi_min + math.radians(60.0), rel=1e-12)
    assert an.omega1 == 10.0


def test_a_position_where_the_dyad_cannot_close_names_the_step() -> None:
    from dataclasses import replace

    m = geomcad.solve(PID).data.mechanism
    an = analyse(m, 1.0, 1.0)
    # the slider's path moved 2·l4 away from B: circle(B, l4) cannot reach it
    bad = replace(m, guide_p=an.c["B"] + m.guide_d.perp() * (2.0 * m.l4))
    with pytest.raises(ConstructionError) as info:
        analyse(bad, 1.0, 1.0)
    assert info.value.step == "C = circle(B, l4) ∩ path"
    assert "misses" in str(info.value) or "no intersection" in str(info.value)
    # and a coupler too short to reach the rocker's circle
    with pytest.raises(ConstructionError, match=r'step "B = circle\(A, l2\) ∩ circle\(O2, l3\)"'):
        analyse(replace(m, l2=0.01), 1.0, 1.0)


def test_short_vector_notes_follow_the_plans_factors() -> None:
    """Under each plan the note names exactly the vectors shorter than two arrowheads at the
    factor the plan is drawn at, each with its length there (a text view of the layout)."""
    from geomcad_constructions.sheets_2013_6_kin import _Kin

    from geomcad.sheet import Scale
    from geomcad.sheet.lang import language
    from geomcad.sheet.settle import factor_of
    from geomcad.sheet.short import short_vectors
    from geomcad.sheet.views import num

    sol = geomcad.solve("2013-6")
    with language("ru"):
        kin = _Kin(sol)
        sheet = dict(sol.sheets())["kinematics"]
    text = " ".join(t.text for t in sheet.texts())
    total = 0
    for plan, view in ((kin.an.vp, kin.vplan), (kin.an.ap, kin.aplan)):
        shorts = short_vectors(plan, Scale(factor_of(kin.layout, view), plan.kind))
        total += len(shorts)
        for s in shorts:
            assert f"({num(s.mm, 2)}\u00a0мм)" in text, s.vector.label
    assert total > 0 and text.count("\u00a0мм)") == total
