"""Cams (geomcad.kinematics.motion_laws, geomcad.kinematics.cams): the motion laws against
numerical differentiation and their boundary conditions, exact envelope invariants of the profile
by inversion, the involute of S = aφ, roller offsets against shapely, cusp and undercut errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from geomcad.errors import ConstructionError, ParameterError
from geomcad.kinematics.cams import (
    Follower,
    at_angles,
    cam_profile,
    follow,
    invert,
    rho_min,
    velocity_plan,
)
from geomcad.kinematics.motion_laws import (
    ALL_LAWS,
    LAWS,
    CamProgram,
    Phase,
    normalised,
    standard_program,
)

REL = 1e-9
H = 0.04

# -- the laws -------------------------------------------------------------------------------------

#: Each law's s′ and s″ at u = 0 and u = 1 (right value at 0, left value at 1), written out here.
ENDS = {
    "linear": ((1.0, 0.0), (1.0, 0.0)),
    "constant_acceleration": ((0.0, 4.0), (0.0, -4.0)),
    "harmonic": ((0.0, math.pi**2 / 2), (0.0, -(math.pi**2) / 2)),
    "cycloidal": ((0.0, 0.0), (0.0, 0.0)),
    "poly345": ((0.0, 0.0), (0.0, 0.0)),
    "modified_trapezoid": ((0.0, 0.0), (0.0, 0.0)),
}


@pytest.mark.parametrize("law", ALL_LAWS)
def test_laws_start_at_0_end_at_1_and_have_their_end_derivatives(law: str) -> None:
    s, ds, dds = normalised(law, [0.0, 1.0])
    assert s[0] == pytest.approx(0.0, abs=1e-15) and s[1] == pytest.approx(1.0, abs=1e-15)
    (d0, a0), (d1, a1) = ENDS[law]
    assert ds[0] == pytest.approx(d0, abs=1e-12) and ds[1] == pytest.approx(d1, abs=1e-12)
    assert dds[0] == pytest.approx(a0, abs=1e-12) and dds[1] == pytest.approx(a1, abs=1e-12)


@pytest.mark.parametrize("law", ALL_LAWS)
def test_laws_derivatives_match_numerical_differentiation(law: str) -> None:
    u = np.linspace(0.01, 0.99, 99)
    u = u[np.abs(u - 0.5) > 0.02]  # away from the constant-acceleration law's break
    h = 1e-5
    s_p, ds_p, _ = normalised(law, u + h)
    s_m, ds_m, _ = normalised(law, u - h)
    _, ds, dds = normalised(law, u)
    np.testing.assert_allclose((s_p - s_m) / (2 * h), ds, atol=1e-8)
    np.testing.assert_allclose((ds_p - ds_m) / (2 * h), dds, atol=1e-6)


@pytest.mark.parametrize("law", ALL_LAWS)
def test_mean_velocity_analogue_is_h_over_phi(law: str) -> None:
    """∫S′dφ over the rise is H: the mean of s′ over [0, 1] is 1 (trapezoids, fine grid)."""
    u = np.linspace(0.0, 1.0, 200001)
    _, ds, _ = normalised(law, u)
    assert float(np.sum((ds[1:] + ds[:-1]) / 2) * (u[1] - u[0])) == pytest.approx(1.0, abs=1e-9)


@pytest.mark.parametrize("law", LAWS)
def test_program_scales_the_law_and_returns_by_it(law: str) -> None:
    rise, dwell, ret = 2.0, 0.5, 1.5
    prog = standard_program(H, rise, law, dwell, ret)
    assert prog.total == pytest.approx(2 * math.pi)  # completed by the lower dwell
    phi = np.linspace(0.0, 2 * math.pi, 2001)
    m = prog.motion(phi)
    u = np.clip(phi / rise, 0, 1)
    s, ds, _ = normalised(law, u)
    on_rise = phi < rise
    np.testing.assert_allclose(m.S[on_rise], H * s[on_rise], atol=1e-15)
    np.testing.assert_allclose(m.S1[on_rise], H / rise * ds[on_rise], atol=1e-15)
    on_dwell = (phi >= rise) & (phi < rise + dwell)
    assert np.all(m.S[on_dwell] == H) and np.all(m.S1[on_dwell] == 0.0)
    on_ret = (phi > rise + dwell) & (phi < rise + dwell + ret)
    ur = (phi[on_ret] - rise - dwell) / ret
    sr, dsr, ddsr = normalised(law, ur)
    np.testing.assert_allclose(m.S[on_ret], H * (1 - sr), atol=1e-15)
    np.testing.assert_allclose(m.S1[on_ret], -H / ret * dsr, atol=1e-15)
    np.testing.assert_allclose(m.S2[on_ret], -H / ret**2 * ddsr, atol=1e-12)
    assert np.all(m.S[phi > rise + dwell + ret] == 0.0)


def test_one_sided_values_at_a_jump() -> None:
    prog = standard_program(H, math.pi)
    a = H / math.pi
    right = prog.motion([0.0, math.pi], "right")
    left = prog.motion([0.0, math.pi], "left")
    assert list(left.S1) == [0.0, pytest.approx(a)]
    assert list(right.S1) == [pytest.approx(a), 0.0]
    half = standard_program(H, 2.0, "constant_acceleration")
    assert half.motion([1.0], "left").S2[0] == pytest.approx(4 * H / 4.0)
    assert half.motion([1.0], "right").S2[0] == pytest.approx(-4 * H / 4.0)
    assert list(half.breaks()) == [0.0, 1.0, 2.0]


@pytest.mark.parametrize(
    ("phases", "words"),
    [
        ([Phase("return", 1.0)], "a return must start at S = H"),
        ([Phase("rise", 1.0), Phase("rise", 1.0)], "a rise must start at S = 0"),
        ([Phase("rise", 0.0)], "must be > 0"),
        ([Phase("rise", 4.0), Phase("return", 3.0)], "more than a full turn"),
        ([Phase("rise", 1.0, "spline")], "law"),
    ],
)
def test_bad_programs(phases: list[Phase], words: str) -> None:
    with pytest.raises(ParameterError, match=words):
        CamProgram.of(H, phases)
    with pytest.raises(ParameterError, match="stroke"):
        CamProgram.of(-1.0, [Phase("rise", 1.0)])


# -- the flat-faced follower ----------------------------------------------------------------------

laws_smooth = st.sampled_from(["constant_acceleration", "harmonic", "cycloidal", "poly345"])


def _face_normal(phi: np.ndarray, sigma: int) -> np.ndarray:
    return invert(np.stack([np.zeros_like(phi), np.ones_like(phi)], axis=-1), phi, sigma)


@settings(max_examples=40, deadline=None)
@given(
    law=laws_smooth,
    rise=st.floats(1.5, 3.5),
    ret=st.floats(1.5, 2.5),
    r0=st.floats(0.13, 0.2),  # above every law's cusp limit r0 > −min(S + S″)
    sigma=st.sampled_from([1, -1]),
)
def test_flat_face_envelope_invariants(
    law: str, rise: float, ret: float, r0: float, sigma: int
) -> None:
    """Each profile point lies on its face line, and the face touches the profile there: the
    profile's tangent (central differences) is ⊥ the face's normal."""
    prog = standard_program(H, rise, law, 0.2, ret)
    f = Follower("flat", r0, 0.0, 0.0, sigma)
    prof = cam_profile(prog, f, closed=True)
    n = _face_normal(prof.phi, sigma)
    # on the face line p·n = r0 + S
    np.testing.assert_allclose(np.sum(prof.contact * n, axis=1), r0 + prof.S, atol=1e-15)
    # the face line touches: d(contact)/dφ ⊥ n, at interior points of each phase
    phi = np.linspace(0.05, 2 * math.pi - 0.05, 400)
    phi = phi[np.min(np.abs(phi[:, None] - prog.breaks()[None, :]), axis=1) > 2e-4]
    h = 1e-6
    plus = follow(prog.motion(phi + h), f).contact
    minus = follow(prog.motion(phi - h), f).contact
    tangent = (plus - minus) / (2 * h)
    cos = np.sum(tangent * _face_normal(phi, sigma), axis=1) / np.maximum(
        np.linalg.norm(tangent, axis=1), 1e-300
    )
    assert np.max(np.abs(cos)) < 1e-6
    # the normal the profile reports is the face's
    np.testing.assert_allclose(prof.normal, n, atol=1e-15)


@pytest.mark.parametrize("sigma", [1, -1])
@pytest.mark.parametrize(("r0", "a_mm"), [(0.04, 40 / math.pi), (0.03, 20.0), (0.1, 7.0)])
def test_linear_law_flat_face_profile_is_an_involute(sigma: int, r0: float, a_mm: float) -> None:
    """For S = aφ the envelope is the involute of the circle of radius a: at every point the
    polar angle θ and inv α = tan α − α (cos α = a/r) satisfy θ + σ·inv α = const, and the
    radius of curvature is the unwound string, r0 + S."""
    a = a_mm / 1000
    phi_rise = H / a
    prog = standard_program(H, phi_rise)
    f = Follower("flat", r0, 0.0, 0.0, sigma)
    prof = cam_profile(prog, f, 0.0, phi_rise * 0.9)
    smooth = ~prof.corner & (prof.S1 > 0)
    p = prof.contact[smooth]
    r = np.hypot(p[:, 0], p[:, 1])
    alpha = np.arccos(a / r)
    theta = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    invariant = theta + sigma * (np.tan(alpha) - alpha)
    assert np.ptp(invariant) < 1e-12
    np.testing.assert_allclose(prof.rho[smooth], r0 + prof.S[smooth], rtol=1e-12)
    # every normal is tangent to the circle of radius a (the involute's base circle)
    n = prof.normal[smooth]
    cross = p[:, 0] * n[:, 1] - p[:, 1] * n[:, 0]
    np.testing.assert_allclose(np.abs(cross), a, rtol=1e-12)


def test_linear_law_starts_with_a_straight_piece_of_the_face() -> None:
    """At φ = 0 S′ jumps from 0 to a: the profile runs a along the face line y = r0 from the
    base circle's top (0, r0) to (a, r0), where the involute starts."""
    a = H / math.pi
    prof = cam_profile(standard_program(H, math.pi), Follower("flat", 0.04), 0.0, math.pi / 2)
    assert tuple(prof.contact[0]) == (0.0, 0.04)
    flat = prof.contact[prof.corner]
    assert np.all(flat[:, 1] == 0.04) and np.all((flat[:, 0] > 0) & (flat[:, 0] < a))
    first = int(np.argmax(~prof.corner[1:])) + 1
    assert prof.contact[first] == pytest.approx([a, 0.04], abs=1e-15)
    assert rho_min(standard_program(H, math.pi), prof) == pytest.approx(0.04, rel=REL)


def test_radius_vectors_are_the_seeds_formula() -> None:
    prog = standard_program(H, math.pi)
    f = Follower("flat", 0.04)
    phis = np.arange(5) * math.pi / 8
    div = at_angles(prog, f, phis, math.pi / 2)
    a = H / math.pi
    np.testing.assert_allclose(div.radius, np.hypot(0.04 + a * phis, a), rtol=1e-14)


def test_cw_profile_is_the_mirror_image() -> None:
    prog = standard_program(H, 2.5, "cycloidal", 0.3, 2.0)
    ccw = cam_profile(prog, Follower("flat", 0.06, sigma=1), closed=True)
    cw = cam_profile(prog, Follower("flat", 0.06, sigma=-1), closed=True)
    np.testing.assert_allclose(cw.contact[:, 0], -ccw.contact[:, 0], atol=1e-15)
    np.testing.assert_allclose(cw.contact[:, 1], ccw.contact[:, 1], atol=1e-15)


@pytest.mark.parametrize("k", [0.1, 3.0, 25.0])
def test_profile_scales_with_the_cam(k: float) -> None:
    prog = standard_program(H, 2.5, "poly345", 0.3, 2.0)
    big = standard_program(H * k, 2.5, "poly345", 0.3, 2.0)
    for follower in (
        Follower("flat", 0.05),
        Follower("knife", 0.05, 0.01),
        Follower("roller", 0.05, 0.01, 0.01),
    ):
        scaled = Follower(follower.kind, follower.r0 * k, follower.e * k, follower.r_roller * k)
        a = cam_profile(prog, follower, closed=True)
        b = cam_profile(big, scaled, closed=True)
        np.testing.assert_allclose(b.contact, a.contact * k, rtol=1e-12, atol=1e-15 * k)
        np.testing.assert_allclose(b.pressure, a.pressure, atol=1e-12)
        assert rho_min(big, b) == pytest.approx(rho_min(prog, a) * k, rel=1e-7)


# -- knife-edge and roller ------------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(
    law=st.sampled_from(LAWS),
    e=st.floats(-0.02, 0.02),
    sigma=st.sampled_from([1, -1]),
)
def test_knife_pressure_angle_and_normal(law: str, e: float, sigma: int) -> None:
    """The knife's tip runs on the profile; the pressure angle is the textbook
    tan α = (S′ − σe)/(s0 + S), and the normal is ⊥ the path's numerical tangent."""
    prog = standard_program(H, 2.0, law, 0.4, 2.0)
    f = Follower("knife", 0.05, e, 0.0, sigma)
    prof = cam_profile(prog, f, closed=True)
    s0 = math.sqrt(0.05**2 - e**2)
    np.testing.assert_allclose(prof.contact, prof.pitch, atol=0)
    np.testing.assert_allclose(
        np.tan(prof.pressure), (sigma * prof.S1 - e) / (s0 + prof.S), rtol=1e-9, atol=1e-12
    )
    fixed = invert(prof.contact, -prof.phi, sigma)  # back to the fixed frame
    np.testing.assert_allclose(fixed[:, 0], e, atol=1e-15)
    np.testing.assert_allclose(fixed[:, 1], s0 + prof.S, atol=1e-15)
    phi = np.linspace(0.1, 6.1, 300)
    phi = phi[np.min(np.abs(phi[:, None] - prog.breaks()[None, :]), axis=1) > 2e-4]
    h = 1e-6
    t = (follow(prog.motion(phi + h), f).contact - follow(prog.motion(phi - h), f).contact) / (
        2 * h
    )
    n = follow(prog.motion(phi), f).normal
    cos = np.sum(t * n, axis=1) / np.linalg.norm(t, axis=1)
    assert np.max(np.abs(cos)) < 1e-6


def _curvature_numeric(prog: CamProgram, f: Follower, phi: np.ndarray) -> np.ndarray:
    """The pitch curve's signed radius of curvature from finite differences of its points."""
    h = 1e-4
    p0 = follow(prog.motion(phi), f).pitch
    pp = follow(prog.motion(phi + h), f).pitch
    pm = follow(prog.motion(phi - h), f).pitch
    d1 = (pp - pm) / (2 * h)
    d2 = (pp - 2 * p0 + pm) / h**2
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    return np.asarray(-f.sigma * np.linalg.norm(d1, axis=1) ** 3 / cross)


@pytest.mark.parametrize("sigma", [1, -1])
@pytest.mark.parametrize("law", ["harmonic", "cycloidal", "poly345"])
def test_pitch_curvature_matches_finite_differences(law: str, sigma: int) -> None:
    prog = standard_program(H, 2.0, law, 0.4, 2.0)
    f = Follower("roller", 0.05, 0.012, 0.01, sigma)
    phi = np.linspace(0.2, 1.8, 9)
    exact = follow(prog.motion(phi), f).rho_pitch
    np.testing.assert_allclose(exact, _curvature_numeric(prog, f, phi), rtol=1e-5)


@pytest.mark.parametrize("sigma", [1, -1])
@pytest.mark.parametrize("law", ["harmonic", "cycloidal", "poly345", "constant_acceleration"])
def test_roller_profile_is_the_exact_inner_offset(law: str, sigma: int) -> None:
    """Every roller profile point is r_r from its pitch point along the pitch curve's normal, and
    the whole profile agrees with shapely's inner buffer of the pitch curve."""
    prog = standard_program(H, 2.2, law, 0.4, 2.0)
    r_r = 0.012
    f = Follower("roller", 0.05, 0.008, r_r, sigma)
    prof = cam_profile(prog, f, closed=True, step=math.radians(0.25))
    d = np.linalg.norm(prof.pitch - prof.contact, axis=1)
    np.testing.assert_allclose(d, r_r, rtol=1e-12)
    np.testing.assert_allclose(prof.rho, prof.rho_pitch - r_r, rtol=1e-12)
    pitch = Polygon(prof.pitch)
    buffered = pitch.buffer(-r_r, quad_segs=64)
    ours = Polygon(prof.contact)
    assert ours.is_valid
    assert ours.hausdorff_distance(buffered) < 2e-6
    assert abs(ours.area - buffered.area) / ours.area < 1e-5


def test_roller_rests_in_the_corner_where_s_prime_jumps_up() -> None:
    """Linear law, roller: at φ = 0 the profile has an arc of the roller circle about the pitch
    curve's corner (concave, radius r_r)."""
    prog = standard_program(H, math.pi)
    f = Follower("roller", 0.04, 0.005, 0.01)
    prof = cam_profile(prog, f, 0.0, math.pi / 2)
    arc = prof.contact[prof.corner]
    centre = prof.pitch[prof.corner]
    np.testing.assert_allclose(np.linalg.norm(arc - centre, axis=1), 0.01, rtol=1e-12)
    assert np.all(centre == centre[0])
    assert np.all(prof.rho[prof.corner] == -0.01)
    assert rho_min(prog, prof) == pytest.approx(0.01)


# -- errors ---------------------------------------------------------------------------------------


def test_base_circle_too_small_for_the_flat_face_is_a_cusp() -> None:
    prog = standard_program(H, 1.0, "harmonic", 0.0, 3.0)
    # ρ = r0 + S + S″ is least at the end of the rise: r0 + H − π²H/2
    need = math.pi**2 * H / 2 - H
    with pytest.raises(ConstructionError, match=r"cusp at φ = 57\.29.*r0 must exceed 0\.1573"):
        cam_profile(prog, Follower("flat", need * 0.95), closed=True)
    prof = cam_profile(prog, Follower("flat", need * 1.05), closed=True)
    assert rho_min(prog, prof) == pytest.approx(need * 0.05, rel=1e-6)


def test_roller_larger_than_the_pitch_curvature_is_undercut() -> None:
    """A harmonic rise straight into a return gives the pitch curve a nose of radius
    ρ = y²/(y − S″), y = r0 + H, S″ = −π²H/(2Φ²): a roller larger than that undercuts."""
    prog = standard_program(H, 1.0, "harmonic", 0.0, 1.0)
    y = 0.02 + H
    nose = y * y / (y + math.pi**2 * H / 2)
    ok = cam_profile(prog, Follower("roller", 0.02, 0.0, 0.9 * nose), closed=True)
    assert float(np.min(ok.rho_pitch[ok.rho_pitch > 0])) == pytest.approx(nose, rel=1e-9)
    assert rho_min(prog, ok) == pytest.approx(0.1 * nose, rel=1e-6)
    with pytest.raises(ConstructionError, match="undercut") as info:
        cam_profile(prog, Follower("roller", 0.02, 0.0, 1.1 * nose), closed=True)
    assert info.value.step.startswith("profile = inner offset of the pitch curve")
    assert f"ρ = {nose:.6g} m (at φ = 57.2958°)" in str(info.value)


def test_roller_not_smaller_than_r0_undercuts_the_base_circle() -> None:
    prog = standard_program(H, math.pi)
    with pytest.raises(ConstructionError, match=r"r_roller = 0\.04 m is not smaller than r0"):
        cam_profile(prog, Follower("roller", 0.04, 0.0, 0.04), 0.0, math.pi / 2)


@pytest.mark.parametrize("kind", ["flat", "roller"])
def test_a_drop_of_s_prime_is_a_cusp_for_flat_and_roller(kind: str) -> None:
    prog = standard_program(H, math.pi, "linear", 0.0, math.pi / 2)
    f = Follower(kind, 0.04, 0.0, 0.01 if kind == "roller" else 0.0)
    with pytest.raises(ConstructionError, match=r"S′ drops .* at φ = 180°"):
        cam_profile(prog, f, closed=True)
    knife = cam_profile(prog, Follower("knife", 0.04), closed=True)
    assert np.any(knife.corner)


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("flat", 0.0), "r0"),
        (("flat", -0.01), "r0"),
        (("wheel", 0.04), "follower"),
        (("roller", 0.04, 0.0, 0.0), "r_roller"),
        (("knife", 0.04, 0.04), "e"),
        (("roller", 0.04, 0.04, 0.01), "e"),
    ],
)
def test_bad_followers(args: tuple[object, ...], words: str) -> None:
    with pytest.raises(ParameterError, match=words):
        Follower(*args)  # type: ignore[arg-type]
    with pytest.raises(ParameterError, match="omega_sign"):
        Follower("flat", 0.04, sigma=2)


# -- the velocity plan ----------------------------------------------------------------------------


@pytest.mark.parametrize("kind", ["flat", "knife", "roller"])
@pytest.mark.parametrize("sigma", [1, -1])
def test_velocity_plan_is_similar_to_obb_prime(kind: str, sigma: int) -> None:
    """V_B1 ⊥ OB, V_B2 along the motion, V_B2B1 along the face (the pitch curve's tangent);
    b₂b₁/BB′ = Bb₂/OB′ = Bb₁/OB = ω and OB′ = S′."""
    prog = standard_program(H, 2.0, "harmonic", 0.3, 2.0)
    f = Follower(kind, 0.05, 0.007 if kind != "flat" else 0.0, 0.01 if kind == "roller" else 0)
    f = Follower(f.kind, f.r0, f.e, f.r_roller, sigma)
    omega = 3.0
    for phi in (0.4, 1.1, 3.0, 4.0):
        pl = velocity_plan(prog, f, phi, omega)
        B, Bp = pl.B, pl.B_prime
        assert pl.V_B1.dot(B) == pytest.approx(0.0, abs=1e-15)
        assert pl.V_B2.x == 0.0
        assert Bp.norm == pytest.approx(abs(pl.S1), abs=1e-15)
        assert pl.V_B1.norm / B.norm == pytest.approx(omega, rel=REL)
        assert pl.V_B2.norm == pytest.approx(omega * abs(pl.S1), abs=1e-15)
        assert pl.V_B2B1.norm == pytest.approx(omega * (B - Bp).norm, rel=REL)
        # the relative velocity is along the profile's (pitch curve's) tangent at B
        n = follow(prog.motion([phi]), f).normal[0]
        n_fixed = invert(n, -phi, sigma)
        assert pl.V_B2B1.x * n_fixed[0] + pl.V_B2B1.y * n_fixed[1] == pytest.approx(0, abs=1e-15)
        if kind == "flat":
            assert pl.V_B2B1.y == pytest.approx(0.0, abs=1e-15)
            assert (B - pl.C).norm == pytest.approx(abs(pl.S1), abs=1e-15)
