"""The six-bar's sweep: against the scalar construction, numerical differentiation, variants at
once, a continuous assembly branch, dead positions that name their step, and 2013-6's stroke and
K read off a full turn.

Tolerances of the differentiation tests: the five-point central difference
f' ≈ (−f(x+2h) + 8f(x+h) − 8f(x−h) + f(x−2h)) / 12h has truncation error h⁴·|f⁽⁵⁾|/30 and
rounding error about 1.5·ε·|f|/h. With h = 1e-3 rad and the six-bar's sizes (links 0.06 … 0.4 m,
derivatives per radian of the same order) that is about 3e-14 m and 2e-13 m, some 1e-12 of the
largest velocity or acceleration (measured: 5e-13 … 3e-12). The tests allow 1e-9 of the largest
value: a margin of about a thousand, while a wrong or missing term (a normal acceleration
ω²·l ≈ 0.1 of the largest) would exceed it by eight orders of magnitude.
"""

from __future__ import annotations

import dataclasses
import doctest
import math
from collections.abc import Callable

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geomcad
from geomcad.errors import ConstructionError, DegenerateInput, NoIntersection, ParameterError
from geomcad.geom import Circle, Line, Vec, circle_circle, line_circle
from geomcad.kinematics import (
    BLOCK,
    SixBar,
    SweepResult,
    angular_velocity,
    rrp_acceleration,
    rrp_velocity,
    rrr_acceleration,
    rrr_velocity,
)
from geomcad.kinematics.sixbar import STEP_B, STEP_C, STEP_VB, STEP_VC

H_DIFF = 1e-3
REL = 1e-9
Variant = Callable[[SixBar], SixBar]
TURN = np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)


@pytest.fixture(scope="module")
def seed() -> SixBar:
    mech = geomcad.solve("2013-6").data.mechanism
    assert isinstance(mech, SixBar)
    return mech


def tilted(m: SixBar) -> SixBar:
    """The seed's six-bar with an inclined guide and the other assembly branch of C."""
    return dataclasses.replace(
        m, guide_p=Vec(0.05, 0.32), guide_d=Vec(math.cos(0.3), math.sin(0.3)), branch_C=-1
    )


def mirrored(m: SixBar) -> SixBar:
    """The seed's six-bar reflected in the x-axis: B on the other side of A → O2."""
    return dataclasses.replace(
        m,
        O1=Vec(m.O1.x, -m.O1.y),
        O2=Vec(m.O2.x, -m.O2.y),
        guide_p=Vec(m.guide_p.x, -m.guide_p.y),
        branch_B=-m.branch_B,
    )


def d5(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, h: float = H_DIFF) -> np.ndarray:
    """The five-point central difference of f at x (f returns an array per angle array)."""
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h)


def assert_close(got: np.ndarray, want: np.ndarray, rel: float = REL) -> None:
    scale = float(np.max(np.abs(want)))
    assert float(np.max(np.abs(got - want))) <= rel * scale, (
        float(np.max(np.abs(got - want))),
        scale,
    )


# --- the scalar construction, one position at a time ------------------------------------------


def scalar_position(m: SixBar, phi: float) -> tuple[Vec, ...]:
    """A, B, C and their velocities at ω1 = 1 by geomcad.geom's intersections and the vector
    equations of the velocity plan, in plain floats."""
    a = m.O1 + Vec.polar(m.l1, phi)
    pts = circle_circle(Circle(a, m.l2), Circle(m.O2, m.l3))
    b = pts[0] if m.branch_B > 0 or len(pts) == 1 else pts[1]  # left of A → O2 first
    d = m.guide_d.unit()
    cs = line_circle(Line(m.guide_p, d), Circle(b, m.l4))
    c = cs[-1] if m.branch_C > 0 else cs[0]  # ascending along d
    va = (a - m.O1).perp()
    # V_B = V_A + V_BA (⊥ AB) = V_BO2 (⊥ O2B): (B − A)·V_B = (B − A)·V_A, (B − O2)·V_B = 0
    e1, e2 = b - a, b - m.O2
    det = e1.cross(e2)
    r1 = e1.dot(va)
    vb = Vec(r1 * e2.y, -r1 * e2.x) / det
    # V_C = V_B + V_CB (⊥ CB), V_C ∥ d: (C − B)·V_C = (C − B)·V_B
    e = c - b
    vc = d * (e.dot(vb) / e.dot(d))
    return a, b, c, va, vb, vc


@pytest.mark.parametrize("variant", [lambda m: m, tilted, mirrored], ids=["seed", "tilt", "mirror"])
def test_sweep_equals_the_scalar_construction(seed: SixBar, variant: Variant) -> None:
    m = variant(seed)
    phi = np.linspace(0.0, 2.0 * math.pi, 25)
    r = m.sweep(phi)
    for i, x in enumerate(phi):
        want = scalar_position(m, float(x))
        got = (r.A[i], r.B[i], r.C[i], r.V_A[i], r.V_B[i], r.V_C[i])
        for name, g, w in zip(("A", "B", "C", "V_A", "V_B", "V_C"), got, want, strict=True):
            size = max(m.l1, m.l2, m.l3, m.l4, w.norm)
            assert math.dist(g, w) <= REL * size, (name, i, g, w)
        assert r.s[i] == pytest.approx((want[2] - m.guide_p).dot(m.guide_d.unit()), abs=REL)
        assert r.v[i] == pytest.approx(want[5].dot(m.guide_d.unit()), abs=REL * want[5].norm)


def test_sweep_agrees_with_the_dyad_functions(seed: SixBar) -> None:
    m = tilted(seed)
    r = m.sweep(TURN, 2.0)
    zero = np.zeros(2)
    vb = rrr_velocity(r.A, r.V_A, m.O2.array(), zero, r.B)
    vc = rrp_velocity(r.B, r.V_B, r.C, m.guide_d.unit().array())
    assert_close(r.V_B, vb, 1e-12)
    assert_close(r.V_C, vc, 1e-12)


def test_result_layout(seed: SixBar) -> None:
    r = seed.sweep(TURN)
    assert isinstance(r, SweepResult)
    for arr in (r.A, r.B, r.C, r.V_A, r.V_B, r.V_C):
        assert arr.shape == (TURN.size, 2) and arr.dtype == np.float64
        assert arr[:, 0].flags.c_contiguous
    assert r.s.shape == r.v.shape == r.phi.shape == TURN.shape
    a, b, c = seed.positions(TURN)
    assert np.array_equal(a, r.A) and np.array_equal(b, r.B) and np.array_equal(c, r.C)
    assert np.array_equal(seed.slider_s(TURN), r.s)
    assert np.array_equal(seed.slider_v(TURN), r.v)
    assert seed.sweep(0.5).A.shape == (1, 2)
    assert seed.sweep(np.array([])).A.shape == (0, 2)


@pytest.mark.parametrize("block", [1, 7, 64, 719, BLOCK])
def test_blocks_do_not_change_the_numbers(seed: SixBar, block: int) -> None:
    ref = seed.sweep(TURN, 1.5)
    r = seed.sweep(TURN, 1.5, block=block)
    for f in dataclasses.fields(SweepResult):
        assert np.array_equal(getattr(r, f.name), getattr(ref, f.name)), f.name


# --- numerical differentiation ------------------------------------------------------------------


@pytest.mark.parametrize("variant", [lambda m: m, tilted, mirrored], ids=["seed", "tilt", "mirror"])
def test_velocities_are_the_derivatives_of_the_positions(seed: SixBar, variant: Variant) -> None:
    m = variant(seed)
    omega1 = 2.5
    v = m.velocities(TURN, omega1)
    for i in range(3):
        num = d5(lambda x, i=i: m.positions(x)[i], TURN) * omega1
        assert_close(v[i], num)
    assert_close(m.slider_v(TURN, omega1), d5(m.slider_s, TURN) * omega1)


@pytest.mark.parametrize("variant", [lambda m: m, tilted, mirrored], ids=["seed", "tilt", "mirror"])
@pytest.mark.parametrize(("omega1", "eps1"), [(1.0, 0.0), (3.0, 0.0), (-2.0, 7.0)])
def test_accelerations_are_the_derivatives_of_the_velocities(
    seed: SixBar, variant: Variant, omega1: float, eps1: float
) -> None:
    """Along φ(t) with φ' = ω1 and ω1' = ε1: a = ∂V/∂φ·ω1 + ∂V/∂ω1·ε1, and V ∝ ω1."""
    m = variant(seed)
    acc = m.accelerations(TURN, omega1, eps1)
    vel = m.velocities(TURN, omega1)
    for i in range(3):
        dv = d5(lambda x, i=i: m.velocities(x, omega1)[i], TURN)
        assert_close(acc[i], dv * omega1 + vel[i] / omega1 * eps1)
    ds = d5(lambda x: m.slider_v(x, omega1), TURN)
    sv = m.slider_v(TURN, omega1)
    assert_close(m.slider_a(TURN, omega1, eps1), ds * omega1 + sv / omega1 * eps1)


def test_slider_analogues(seed: SixBar) -> None:
    """With ω1 = 1, ε1 = 0: S' = dS/dφ and S'' = d²S/dφ²."""
    s2 = (
        -seed.slider_s(TURN + 2 * H_DIFF)
        + 16 * seed.slider_s(TURN + H_DIFF)
        - 30 * seed.slider_s(TURN)
        + 16 * seed.slider_s(TURN - H_DIFF)
        - seed.slider_s(TURN - 2 * H_DIFF)
    ) / (12 * H_DIFF**2)
    # the second difference loses one more power of h to rounding: 4ε|S|/h² ≈ 3e-10 m
    assert_close(seed.slider_a(TURN), s2, 1e-7)


@pytest.mark.parametrize("variant", [lambda m: m, tilted, mirrored], ids=["seed", "tilt", "mirror"])
def test_angular_velocities_and_accelerations(seed: SixBar, variant: Variant) -> None:
    m = variant(seed)
    omega1, eps1 = 4.0, -3.0
    w = m.omegas(TURN, omega1)
    e = m.epsilons(TURN, omega1, eps1)
    # the link BC keeps its length, so ω4 is also read off the positions: the angle of CB
    r = m.sweep(TURN)

    def ang(x: np.ndarray, p: int, q: int) -> np.ndarray:
        pts = m.positions(x)
        return np.unwrap(np.arctan2(*(pts[q] - pts[p]).T[::-1]))

    assert_close(w[0], d5(lambda x: ang(x, 0, 1), TURN) * omega1)
    assert_close(w[2], d5(lambda x: ang(x, 1, 2), TURN) * omega1)
    rocker = d5(lambda x: np.unwrap(np.arctan2(*(m.positions(x)[1] - m.O2.array()).T[::-1])), TURN)
    assert_close(w[1], rocker * omega1)
    for i in range(3):
        dw = d5(lambda x, i=i: m.omegas(x, omega1)[i], TURN)
        assert_close(e[i], dw * omega1 + w[i] / omega1 * eps1)
    # signs: ω = V_QP / l_PQ turning counter-clockwise about P
    assert_close(w[0], angular_velocity(r.A, r.V_A, r.B, r.V_B) * omega1, 1e-12)


def test_acceleration_plans_close() -> None:
    """The dyad accelerations satisfy both vector equations: the projections on each link."""
    rng = np.random.default_rng(3)
    p1, p2, b = rng.normal(size=(3, 50, 2))
    v1, v2, a1, a2, vb_free = rng.normal(size=(5, 50, 2))
    vb = rrr_velocity(p1, v1, p2, v2, b)
    ab = rrr_acceleration(p1, v1, a1, p2, v2, a2, b, vb)
    for p, v, a in ((p1, v1, a1), (p2, v2, a2)):
        e, u = b - p, vb - v
        # a_B − a_P = a^n + a^τ with (b − p)·(a_B − a_P) = −|V_BP|²
        lhs = np.einsum("ij,ij->i", e, ab - a)
        assert np.allclose(lhs, -np.einsum("ij,ij->i", u, u), rtol=1e-9, atol=1e-9)
    d = np.tile([0.6, 0.8], (50, 1))
    vc = rrp_velocity(p1, vb_free, b, d)
    ac = rrp_acceleration(p1, vb_free, a1, b, vc, d)
    assert np.allclose(ac[:, 0] * d[:, 1] - ac[:, 1] * d[:, 0], 0.0, atol=1e-12)
    e, u = b - p1, vc - vb_free
    lhs = np.einsum("ij,ij->i", e, ac - a1)
    assert np.allclose(lhs, -np.einsum("ij,ij->i", u, u), rtol=1e-9, atol=1e-9)


# --- variants at once ---------------------------------------------------------------------------


def test_parameter_sets_broadcast_like_a_loop(seed: SixBar) -> None:
    rng = np.random.default_rng(7)
    n = 300
    l1 = seed.l1 * rng.uniform(0.8, 1.2, n)
    l2 = seed.l2 * rng.uniform(0.97, 1.03, n)
    l4 = seed.l4 * rng.uniform(0.9, 1.5, n)
    o2 = seed.O2.array() + rng.uniform(-0.01, 0.01, (n, 2))
    ang = rng.uniform(-0.2, 0.2, n)
    gd = np.stack([np.cos(ang), np.sin(ang)], axis=-1) * rng.uniform(0.5, 2.0, (n, 1))
    phi = rng.uniform(0.0, 2.0 * math.pi, n)
    omega1 = rng.uniform(-5.0, 5.0, n)
    r = seed.sweep(phi, omega1, l1=l1, l2=l2, l4=l4, O2=o2, guide_d=gd, block=64)
    assert r.A.shape == (n, 2)
    for i in range(n):
        m = dataclasses.replace(
            seed, l1=l1[i], l2=l2[i], l4=l4[i], O2=Vec(*o2[i]), guide_d=Vec(*gd[i])
        )
        one = m.sweep(phi[i], omega1[i])
        for f in dataclasses.fields(SweepResult):
            got, want = getattr(r, f.name)[i], getattr(one, f.name)[0]
            assert np.allclose(got, want, rtol=1e-13, atol=1e-15), (f.name, i)


def test_one_angle_many_variants_and_many_angles_one_variant(seed: SixBar) -> None:
    l3 = np.linspace(0.29, 0.31, 11)
    r = seed.sweep(0.7, l3=l3)
    assert r.A.shape == (11, 2) and np.all(r.phi == 0.7)
    assert np.allclose(np.hypot(*(r.B - seed.O2.array()).T), l3, rtol=1e-14)
    # a dimension given as a number still overrides the mechanism's
    a = seed.sweep(TURN, l4=0.35)
    assert np.allclose(np.hypot(*(a.C - a.B).T), 0.35, rtol=1e-14)


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"l1": -0.1}, ParameterError, "l1"),
        ({"l2": np.array([0.38, 0.0, 0.38])}, ParameterError, "l2"),
        ({"l3": np.full(4, 0.3)}, ParameterError, "broadcast"),
        ({"O2": np.zeros((3, 3))}, ParameterError, "O2"),
        ({"guide_d": (0.0, 0.0)}, DegenerateInput, "guide direction"),
        ({"block": 0}, ParameterError, "block"),
    ],
)
def test_bad_sweep_input(seed: SixBar, kwargs: dict[str, object], error: type, words: str) -> None:
    with pytest.raises(error, match=words):
        seed.sweep(np.array([0.1, 0.2, 0.3]), **kwargs)  # type: ignore[arg-type]


def test_non_finite_angles_are_a_parameter_error(seed: SixBar) -> None:
    with (
        pytest.raises(ParameterError, match="crank angle must be finite"),
        np.errstate(invalid="ignore"),
    ):
        seed.sweep(np.array([0.0, math.nan, 1.0]))
    with pytest.raises(ParameterError, match="omega1"):
        seed.sweep(TURN, math.inf)


# --- the assembly branch ------------------------------------------------------------------------


@pytest.mark.parametrize("variant", [lambda m: m, tilted, mirrored], ids=["seed", "tilt", "mirror"])
def test_the_branch_is_continuous_over_a_turn(seed: SixBar, variant: Variant) -> None:
    m = variant(seed)
    phi = np.linspace(0.0, 2.0 * math.pi, 7201)
    r = m.sweep(phi)
    dphi = phi[1] - phi[0]
    for p, v in ((r.A, r.V_A), (r.B, r.V_B), (r.C, r.V_C)):
        steps = np.hypot(*np.diff(p, axis=0).T)
        # no step longer than the joint's own motion over it (a jump to the other assembly
        # mode would be of the order of a link length)
        assert np.all(steps <= 1.01 * np.max(np.hypot(*v.T)) * dphi)
    # B on one side of A → O2 and C on one side of B's foot on the guide, all turn long
    u, w = m.O2.array() - r.A, r.B - r.A
    side_b = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]
    assert np.all(np.sign(side_b) == m.branch_B)
    side_c = (r.C - r.B) @ m.guide_d.unit().array()
    assert np.all(np.sign(side_c) == m.branch_C)
    # the turn closes on itself
    assert np.allclose(r.B[0], r.B[-1], atol=1e-12) and np.allclose(r.C[0], r.C[-1], atol=1e-12)


# --- dead positions and positions a dyad cannot reach --------------------------------------------


def test_a_dyad_that_cannot_close_names_its_step(seed: SixBar) -> None:
    # a crank too long for the coupler and rocker: B cannot be assembled over part of the turn
    m = dataclasses.replace(seed, l1=0.2)
    with pytest.raises(NoIntersection) as info:
        m.sweep(TURN)
    assert info.value.step == STEP_B
    assert "circles do not meet" in str(info.value) and "position index" in str(info.value)
    i = int(str(info.value).split("position index ")[1].split(",")[0])
    m.sweep(TURN[:i])  # every position before the reported one assembles
    # the slider's guide out of reach of BC
    far = dataclasses.replace(seed, guide_p=Vec(0.0, 1.0))
    with pytest.raises(NoIntersection, match="line misses the circle") as info:
        far.positions(TURN)
    assert info.value.step == STEP_C


def test_the_index_counts_across_blocks(seed: SixBar) -> None:
    m = dataclasses.replace(seed, l1=0.2)
    msgs = set()
    for block in (5, 64, BLOCK):
        with pytest.raises(NoIntersection) as info:
            m.sweep(TURN, block=block)
        msgs.add(str(info.value))
    assert len(msgs) == 1


def test_dead_position_of_the_rrr_dyad() -> None:
    # at φ = 0, A = (1, 0) and O2 = (3, 0) are l2 − l3 = 2 apart: AB and O2B overlap
    m = SixBar(Vec(0.0, 0.0), 1.0, 3.0, Vec(3.0, 0.0), 1.0, 5.0, Vec(0.0, 0.5), Vec(1.0, 0.0), 1, 1)
    _, b, _ = m.positions(np.array([0.5, 0.0]))
    assert np.array_equal(b[1], [4.0, 0.0])
    with pytest.raises(NoIntersection, match="dead position") as info:
        m.velocities(np.array([0.5, 0.0]))
    assert info.value.step == STEP_VB and "position index 1" in str(info.value)
    with pytest.raises(NoIntersection) as info:
        m.accelerations(np.array([0.0]))
    assert info.value.step == STEP_VB  # the velocity plan's dead position, checked first


def test_dead_position_of_the_rrp_dyad(seed: SixBar) -> None:
    # the guide at l4 from B: circle(B, l4) touches it, the rod BC is perpendicular to it
    phi0 = np.array([1.0])
    b = seed.positions(phi0)[1][0]
    m = dataclasses.replace(seed, guide_p=Vec(0.0, b[1] - seed.l4))
    _, _, c = m.positions(phi0)
    assert c[0] == pytest.approx([b[0], b[1] - seed.l4], abs=1e-15)
    with pytest.raises(NoIntersection, match="perpendicular to the guide") as info:
        m.slider_v(phi0)
    assert info.value.step == STEP_VC
    assert isinstance(info.value, ConstructionError)


# --- 2013-6: the synthesized six-bar over a turn -------------------------------------------------


def test_2013_6_stroke_and_k_from_one_sweep_over_several_syntheses() -> None:
    """The seed's synthesis and three variants, each run through a full turn, all in one sweep
    over the stacked parameter sets: the slider's stroke is H and the ratio of the crank angles
    of its working and return strokes is K."""
    cases = [{}, {"K": 1.4, "H": 0.15, "e": 0.25}, {"K": 1.15, "H": 0.25, "l3": 0.35, "l4": 0.4}]
    cases.append({"K": 1.6, "H": 0.1, "l3": 0.25, "l4": 0.5, "e": 0.1})
    mechs = [geomcad.solve("2013-6", **c).data.mechanism for c in cases]
    n = 1 << 16
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    first = mechs[0]
    for m in mechs:  # the frame of problems.md: same O2, guide direction and branches
        assert (m.O2, m.guide_d, m.branch_B, m.branch_C) == (
            first.O2,
            first.guide_d,
            first.branch_B,
            first.branch_C,
        )

    def stack(name: str) -> np.ndarray:
        vals = [getattr(m, name) for m in mechs]
        rows = [tuple(v) if isinstance(v, Vec) else v for v in vals]
        return np.repeat(np.array(rows, dtype=float), n, axis=0)

    r = first.sweep(
        np.tile(phi, len(mechs)),
        O1=stack("O1"),
        l1=stack("l1"),
        l2=stack("l2"),
        l3=stack("l3"),
        l4=stack("l4"),
        guide_p=stack("guide_p"),
    )
    dphi = 2.0 * math.pi / n
    for k, (case, m) in enumerate(zip(cases, mechs, strict=True)):
        s = r.s[k * n : (k + 1) * n]
        H = case.get("H", 0.2)
        K = case.get("K", 1.3)
        # sampling misses an extreme by at most |S''|·Δφ²/8 < 1e-10 m
        assert s.max() - s.min() == pytest.approx(H, rel=1e-9)
        a = (phi[np.argmax(s)] - phi[np.argmin(s)]) % (2.0 * math.pi)
        k_sweep = max(a, 2 * math.pi - a) / min(a, 2 * math.pi - a)
        # each extreme's angle is known to Δφ/2
        assert k_sweep == pytest.approx(K, abs=4 * dphi)
        # and the exact check by analysis agrees with the sweep
        h_exact, k_exact, _, _ = m.stroke_and_k()
        assert h_exact == pytest.approx(H, rel=REL) and k_exact == pytest.approx(K, rel=REL)


# --- invariants ---------------------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(
    turn=st.floats(-math.pi, math.pi),
    k=st.floats(0.01, 100.0),
    shift=st.tuples(st.floats(-10.0, 10.0), st.floats(-10.0, 10.0)),
    omega1=st.floats(0.1, 50.0),
)
def test_moving_turning_and_rescaling_the_mechanism(
    seed: SixBar, turn: float, k: float, shift: tuple[float, float], omega1: float
) -> None:
    """Turned by γ about the origin, scaled by k and shifted: the positions follow, the
    velocities and accelerations turn and scale, the slider's s, v, a scale, ω and ε stay."""
    c, s = math.cos(turn), math.sin(turn)
    rot = np.array([[c, -s], [s, c]])
    t = np.array(shift)

    def move(p: Vec) -> Vec:
        return Vec(*(k * (rot @ p.array()) + t))

    m = dataclasses.replace(
        seed,
        O1=move(seed.O1),
        O2=move(seed.O2),
        guide_p=move(seed.guide_p),
        guide_d=Vec(*(rot @ seed.guide_d.array())),
        l1=k * seed.l1,
        l2=k * seed.l2,
        l3=k * seed.l3,
        l4=k * seed.l4,
    )
    phi = np.linspace(0.0, 2.0 * math.pi, 48, endpoint=False)
    a, b = seed.sweep(phi, omega1), m.sweep(phi + turn, omega1)
    size = k * max(seed.l2, 1.0)
    for p, q in ((a.A, b.A), (a.B, b.B), (a.C, b.C)):
        assert np.allclose(k * p @ rot.T + t, q, rtol=0, atol=1e-12 * (size + np.hypot(*t)))
    for p, q in ((a.V_A, b.V_A), (a.V_B, b.V_B), (a.V_C, b.V_C)):
        assert np.allclose(k * p @ rot.T, q, rtol=0, atol=1e-11 * k * omega1)
    assert np.allclose(k * a.s, b.s, rtol=0, atol=1e-11 * (size + np.hypot(*t)))
    assert np.allclose(k * a.v, b.v, rtol=0, atol=1e-11 * k * omega1)
    assert np.allclose(
        k * seed.slider_a(phi, omega1, 2.0),
        m.slider_a(phi + turn, omega1, 2.0),
        rtol=0,
        atol=1e-10 * k * omega1 * omega1,
    )
    for w, v in zip(seed.omegas(phi, omega1), m.omegas(phi + turn, omega1), strict=True):
        assert np.allclose(w, v, rtol=0, atol=1e-10 * omega1)


def test_the_docstring_examples_run() -> None:
    from geomcad.kinematics import dyads, sixbar

    for mod in (sixbar, dyads):
        failed, _ = doctest.testmod(mod)
        assert failed == 0
