"""Velocity and acceleration plans (geomcad.kinematics.plan) against numerical differentiation of
positions: a four-bar with a coupler point (image by similarity) and a crank with a slotted rocker
(Coriolis); a dead position names its step."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geomcad.construction import Construction
from geomcad.errors import DegenerateInput, ParallelLines
from geomcad.geom import Vec
from geomcad.kinematics.dyads import rrr
from geomcad.kinematics.plan import (
    Side,
    acceleration_plan,
    coriolis,
    normal,
    velocity_plan,
)
from geomcad.sheet.plans import markup_of, plan_scale

L1, L2, L3, O2 = 0.1, 0.35, 0.3, Vec(0.3, 0.0)
W1 = 12.0  # rad/s, ccw


def fourbar(phi: float) -> tuple[Vec, Vec]:
    a = np.array([[L1 * math.cos(phi), L1 * math.sin(phi)]])
    b = rrr(a, L2, O2.array()[None, :], L3, 1)
    return Vec(*a[0]), Vec(*b[0])


def coupler(A: Vec, B: Vec) -> Vec:
    """A coupler point E: 0.6 along AB and 0.1 m to its left."""
    u = (B - A).unit()
    return A + u * (0.6 * L2) + u.perp() * 0.1


def derivatives(f, t: float, h: float) -> tuple[np.ndarray, np.ndarray]:  # type: ignore[no-untyped-def]
    p = [np.asarray(f(t + k * h)) for k in (-2, -1, 0, 1, 2)]
    v = (p[0] - 8 * p[1] + 8 * p[3] - p[4]) / (12 * h)
    a = (-p[0] + 16 * p[1] - 30 * p[2] + 16 * p[3] - p[4]) / (12 * h * h)
    return v, a


def build_fourbar(phi: float):  # type: ignore[no-untyped-def]
    A, B = fourbar(phi)
    E = coupler(A, B)
    c = Construction("four-bar")
    vp = velocity_plan(c)
    vp.fixed("o1")
    vp.fixed("o2")
    vp.given("a", (A * W1).perp(), "V_A")
    vp.solve("b", Side("a", B - A, "⊥ AB", True), Side("o2", B - O2, "⊥ O2B", True))
    vp.image("e", "a", "b", A, B, E)
    w2 = vp.omega(A, B, "a", "b")
    w3 = vp.omega(O2, B, "o2", "b")
    ap = acceleration_plan(c)
    ap.fixed("o2")
    ap.given("a", A * (-W1 * W1), "a_A")
    ap.solve(
        "b",
        Side("a", B - A, "⊥ AB", True, (normal(w2, B, A, "n_BA", "a^n_{BA}", "ω2²·AB, B → A"),)),
        Side("o2", B - O2, "⊥ O2B", True, (normal(w3, B, O2, "n_BO2", "a^n_{BO2}", "ω3²·O2B"),)),
    )
    ap.image("e", "a", "b", A, B, E)
    return A, B, E, vp, ap, w2, w3


@settings(max_examples=25, deadline=None)
@given(st.floats(0.0, 2 * math.pi))
def test_fourbar_plans_match_differentiation(phi: float) -> None:
    *_, vp, ap, _, _ = build_fourbar(phi)
    h = 1e-3 / W1

    def pos(t: float) -> list[float]:
        a, b = fourbar(phi + W1 * t)
        return [*b, *coupler(a, b)]

    v, a = derivatives(pos, 0.0, h)
    for got, exp in ((vp["b"], v[:2]), (vp["e"], v[2:]), (ap["b"], a[:2]), (ap["e"], a[2:])):
        scale = max(np.linalg.norm(exp), 1.0)
        assert np.allclose(got.array(), exp, atol=1e-6 * scale), (got, exp)


def test_images_are_similar_to_their_links() -> None:
    A, B, E, vp, ap, *_ = build_fourbar(0.7)
    for plan in (vp, ap):
        ab, ae = plan.between("a", "b"), plan.between("a", "e")
        AB, AE = B - A, E - A
        # the same complex ratio: |ae|/|ab| = |AE|/|AB| and the same turn from ab to ae
        assert ae.norm / ab.norm == pytest.approx(AE.norm / AB.norm, rel=1e-12)
        turn = math.atan2(ab.cross(ae), ab.dot(ae))
        assert turn == pytest.approx(math.atan2(AB.cross(AE), AB.dot(AE)), abs=1e-12)


def test_normal_components_point_from_b_to_a_and_steps_are_named() -> None:
    A, B, _, vp, ap, w2, _ = build_fourbar(1.1)
    n = ap.between("a", "n_BA")
    assert n.unit().dot((A - B).unit()) == pytest.approx(1.0, rel=1e-12)
    assert n.norm == pytest.approx(w2 * w2 * A.dist(B), rel=1e-12)
    names = {s.name for s in vp.c}
    assert {"pa", "pb" if "pb" in names else "b", "b:1", "b:2", "πa'", "a'n_BA'", "b'"} <= names


def test_dead_position_names_the_step() -> None:
    # crank and coupler folded onto one line with the rocker: ⊥ AB ∥ ⊥ O2B
    c = Construction("dead")
    vp = velocity_plan(c)
    vp.fixed("o2")
    A, B = Vec(0.1, 0.0), Vec(0.3, 0.0)
    vp.given("a", Vec(0.5, 1.0), "V_A")
    with pytest.raises(ParallelLines) as info:
        vp.solve("b", Side("a", B - A, "⊥ AB", True), Side("o2", B - Vec(0.5, 0.0), "⊥ O2B", True))
    assert info.value.step.startswith("b = line b:1 ∩ line b:2")
    assert "parallel" in str(info.value)
    # with V_A ⊥ AB the two lines coincide: the plan cannot fix b either
    c2 = Construction("dead, coincident")
    vp2 = velocity_plan(c2)
    vp2.fixed("o2")
    vp2.given("a", Vec(0.0, 1.0), "V_A")
    with pytest.raises(DegenerateInput, match=r'step "b = line b:1 ∩ line b:2": the two lines'):
        vp2.solve("b", Side("a", B - A, "⊥ AB", True), Side("o2", B - Vec(0.5, 0.0), "⊥", True))


def slotted(phi: float) -> tuple[Vec, Vec]:
    """Crank O1A (0.1 m) with a block sliding in a rocker through O3 = (0, −0.25)."""
    return Vec(0.1 * math.cos(phi), 0.1 * math.sin(phi)), Vec(0.0, -0.25)


@pytest.mark.parametrize("phi", [0.3, 1.4, 2.9, 4.0, 5.5])
def test_coriolis_on_a_slotted_rocker_matches_differentiation(phi: float) -> None:
    A, O3 = slotted(phi)
    c = Construction("slotted rocker")
    vp = velocity_plan(c)
    vp.fixed("o3")
    vp.given("a2", (A * W1).perp(), "V_A2")
    vp.solve("a3", Side("a2", A - O3, "∥ O3A"), Side("o3", A - O3, "⊥ O3A", True))
    w3 = vp.omega(O3, A, "o3", "a3")
    v_rel = vp.between("a2", "a3")
    ap = acceleration_plan(c)
    ap.fixed("o3")
    ap.given("a2", A * (-W1 * W1), "a_A2")
    ap.solve(
        "a3",
        Side("a2", A - O3, "∥ O3A", False, (coriolis(w3, v_rel, "k", "a^k", "2ω3 × V_A3A2"),)),
        Side("o3", A - O3, "⊥ O3A", True, (normal(w3, A, O3, "n", "a^n", "ω3²·O3A"),)),
    )
    h = 1e-3 / W1

    def theta(t: float) -> float:
        a, o = slotted(phi + W1 * t)
        return math.atan2(a.y - o.y, a.x - o.x)

    (w,), (e,) = derivatives(lambda t: [theta(t)], 0.0, h)
    assert w3 == pytest.approx(w, rel=1e-7)
    r = A - O3
    expect = r.perp() * e - r * (w * w)  # the rocker's point under A
    assert np.allclose(ap["a3"].array(), expect.array(), atol=1e-5 * expect.norm)
    assert ap.omega(O3, A, "o3", "a3") == pytest.approx(e, rel=1e-5)


def test_plan_scale_and_markup() -> None:
    *_, vp, _, _, _ = build_fourbar(0.5)
    k = plan_scale(vp, 100.0, 80.0)
    x0, y0, x1, y1 = vp.extent()
    assert (x1 - x0) / k.k <= 100.0 and (y1 - y0) / k.k <= 80.0
    assert (x1 - x0) / k.k > 40.0 or (y1 - y0) / k.k > 32.0  # the plan fills its field
    assert markup_of("b3") == "b_3"
    assert markup_of("n_BA'") == "n_{BA}'"
    assert markup_of("c4'") == "c_4'"
    assert markup_of("p") == "p"
