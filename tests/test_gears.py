"""Involute gears (geomcad.kinematics.gears): the involute, generation by the rack, undercut and
pointed tips, and the workshop measurements both ways, against textbook values and independent
formulas."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geomcad.errors import ConstructionError, ParameterError
from geomcad.kinematics.gears import (
    GOST_13755,
    BasicRack,
    SpurGear,
    half_angle_of,
    inv,
    inv_inverse,
    involute,
    shift_from_chord,
    shift_from_span,
)

A20 = math.radians(20.0)


def eta_involute(g: SpurGear, radius: np.ndarray) -> np.ndarray:
    """Half the angular tooth thickness on the involute at radius R, written out afresh."""
    a_y = np.arccos(g.d_b / (2.0 * radius))
    s = math.pi * g.m / 2 + 2 * g.x * g.m * math.tan(g.alpha)
    return s / g.d + (math.tan(g.alpha) - g.alpha) - (np.tan(a_y) - a_y)


# -- the involute function ------------------------------------------------------------------------


def test_inv_of_20_degrees() -> None:
    assert inv(A20) == pytest.approx(0.014904383867336446, rel=1e-15)


@given(st.floats(min_value=0.02, max_value=1.5))
def test_inv_inverse_undoes_inv(alpha: float) -> None:
    """On pressure angles of gears (tan α − α loses digits to cancellation below ~1°)."""
    assert inv_inverse(inv(alpha)) == pytest.approx(alpha, rel=1e-11)


@pytest.mark.parametrize("bad", [-0.1, math.inf, math.nan])
def test_inv_inverse_rejects_a_negative_or_infinite_value(bad: float) -> None:
    with pytest.raises(ParameterError, match="inv α"):
        inv_inverse(bad)


def test_involute_points_have_the_polar_angle_inv_alpha() -> None:
    r_b, start = 0.05, 0.3
    t = np.linspace(0.0, 1.2, 50)
    p = involute(r_b, t, start)
    radius = np.hypot(p[:, 0], p[:, 1])
    assert np.allclose(radius, r_b * np.sqrt(1 + t * t), rtol=1e-14)
    alpha = np.arctan(t)
    assert np.allclose(np.arctan2(p[:, 1], p[:, 0]), start + np.tan(alpha) - alpha, atol=1e-14)


# -- sizes, thickness, textbook values ------------------------------------------------------------


def test_sizes_of_a_standard_gear() -> None:
    g = SpurGear(0.01, 40)
    assert g.d == pytest.approx(0.4)
    assert g.d_b == pytest.approx(0.4 * math.cos(A20))
    assert g.tip_diameter == pytest.approx(0.42)
    assert g.d_f == pytest.approx(0.375)
    assert g.s == pytest.approx(math.pi * 0.01 / 2)
    assert g.thickness(g.d) == pytest.approx(g.s, rel=1e-14)


def test_textbook_span_and_chord_values() -> None:
    """GOST 16532 tables, m = 1, x = 0: W over 3 teeth of z = 20 is 7,6604; the constant chord is
    1,3870 at 0,7476; the chordal thickness at the pitch circle is z·sin(90°/z)."""
    g = SpurGear(1.0, 20)
    assert g.span(3) == pytest.approx(7.6604, abs=5e-5)
    assert g.span_teeth() == 3
    cc = g.constant_chord()
    assert cc.s_bar == pytest.approx(1.3870, abs=5e-5)
    assert cc.h_bar == pytest.approx(0.7476, abs=5e-5)
    ch = g.chord()
    assert ch.s_bar == pytest.approx(20 * math.sin(math.radians(90 / 20)), rel=1e-14)
    assert ch.h_bar == pytest.approx(1 + 10 * (1 - math.cos(math.radians(90 / 20))), rel=1e-14)


@pytest.mark.parametrize(("z", "x", "undercut"), [(10, 0.0, True), (17, 0.0, True),
                                                  (18, 0.0, False), (10, 0.42, False)])  # fmt: skip
def test_undercut_below_x_min(z: int, x: float, undercut: bool) -> None:
    g = SpurGear(0.002, z, x)
    assert g.x_min == pytest.approx(1 - z * math.sin(A20) ** 2 / 2)
    assert g.undercut is undercut


def test_pointed_tip_is_an_error_naming_the_check() -> None:
    g = SpurGear(0.002, 12, 1.2)
    assert g.s_a < 0
    with pytest.raises(ConstructionError, match='step "pointed tip": the flanks meet at d = '):
        g.check()
    assert g.half_angle(g.pointed_diameter()) == pytest.approx(0.0, abs=1e-14)


def test_a_rack_too_steep_for_its_tooth_is_rejected() -> None:
    with pytest.raises(ParameterError, match="pointed at this profile angle"):
        BasicRack(alpha=math.radians(35.0)).check("alpha_deg")
    assert BasicRack(alpha=math.radians(25.0)).fillet() < GOST_13755.rho_f


# -- generation by the rack -----------------------------------------------------------------------


GEARS = [(0.01, 40, 0.42842139889997904, 0.42), (0.004, 10, 0.0, None), (0.002, 80, -0.5, None),
         (0.02, 25, 0.8, None), (0.003, 13, 0.3, None), (0.005, 30, 0.0, None)]  # fmt: skip


@pytest.mark.parametrize(("m", "z", "x", "d_a"), GEARS)
def test_the_generated_flank_lies_on_the_exact_involute(
    m: float, z: int, x: float, d_a: float | None
) -> None:
    g = SpurGear(m, z, x, d_a=d_a)
    fl = g.flank(300)
    radius = np.hypot(fl.involute[:, 0], fl.involute[:, 1])
    assert np.max(np.abs(half_angle_of(fl.involute) - eta_involute(g, radius))) < 1e-13
    assert radius.max() == pytest.approx(g.r_a, rel=1e-12)
    assert radius.min() == pytest.approx(g.limit_diameter() / 2, rel=1e-12)


@pytest.mark.parametrize(("m", "z", "x", "d_a"), GEARS)
def test_each_generated_point_is_a_point_of_contact_with_the_rack(
    m: float, z: int, x: float, d_a: float | None
) -> None:
    """Turned forward by its φ, an involute point lies on the rack's flank at that position, and
    the flank's normal there passes through the pitch point (the meshing condition)."""
    g = SpurGear(m, z, x, d_a=d_a)
    fl = g.flank(100)
    phi = fl.involute_phi
    c, s = np.cos(phi), np.sin(phi)
    px = c * fl.involute[:, 0] - s * fl.involute[:, 1]
    py = s * fl.involute[:, 0] + c * fl.involute[:, 1]
    a, r = g.alpha, g.r
    c0 = math.pi * m / 4 + (r + x * m) * math.tan(a)
    on_flank = px + py * math.tan(a) - (c0 - r * phi)
    assert np.max(np.abs(on_flank)) < 1e-12 * r
    normal_misses_p = (px - 0.0) * math.sin(a) - (py - r) * math.cos(a)
    assert np.max(np.abs(normal_misses_p)) < 1e-12 * r


@pytest.mark.parametrize(("m", "z", "x", "d_a"), GEARS)
def test_fillet_joins_the_involute_and_ends_on_the_root_circle(
    m: float, z: int, x: float, d_a: float | None
) -> None:
    g = SpurGear(m, z, x, d_a=d_a)
    fl = g.flank(200)
    root = np.hypot(*fl.fillet[-1])
    assert root == pytest.approx(g.d_f / 2, rel=1e-12)
    assert half_angle_of(fl.fillet[-1:])[0] == pytest.approx(fl.root_from, rel=1e-12)
    # without undercut the fillet leaves the involute tangentially at the limit circle; with
    # undercut it starts where it cuts the involute; either way the two curves meet there
    assert np.allclose(fl.fillet[0], fl.involute[-1], rtol=0, atol=1e-11 * g.r)
    radius = np.hypot(*fl.fillet[0])
    assert radius == pytest.approx(g.limit_diameter() / 2, rel=1e-12)
    assert half_angle_of(fl.fillet[:1])[0] == pytest.approx(
        float(eta_involute(g, np.array([radius]))[0]), abs=1e-12
    )
    if g.undercut:  # below the crossing the fillet is inside the involute: the tooth is undercut
        q = fl.fillet[len(fl.fillet) // 3]
        r_q = float(np.hypot(*q))
        if r_q > g.r_b:
            assert half_angle_of(q[None, :])[0] < eta_involute(g, np.array([r_q]))[0]


# -- measurements both ways -----------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    z=st.integers(min_value=12, max_value=120),
    x=st.floats(min_value=-0.3, max_value=0.8),
    where=st.floats(min_value=0.15, max_value=0.85),
)
def test_round_trip_chord_predicted_from_x_gives_x_back(z: int, x: float, where: float) -> None:
    g = SpurGear(0.004, z, x)
    if g.undercut or g.s_a < 0.2 * g.m:
        return
    d_lo, d_hi = g.limit_diameter(), g.tip_diameter
    ch = g.chord(d_lo + where * (d_hi - d_lo))
    back = shift_from_chord(g.m, z, g.tip_diameter, ch.s_bar, ch.h_bar)
    assert back.x == pytest.approx(x, abs=1e-11)
    assert back.d_y == pytest.approx(ch.d_y, rel=1e-13)
    assert back.s == pytest.approx(g.s, rel=1e-11)
    # and with the caliper's height jaw set to h̄, the chord reads s̄ again
    assert g.chord_at_height(ch.h_bar).s_bar == pytest.approx(ch.s_bar, rel=1e-11)


@pytest.mark.parametrize(("z", "x"), [(20, 0.0), (40, 0.43), (80, -0.5), (12, 0.5)])
def test_round_trip_span_predicted_from_x_gives_x_back(z: int, x: float) -> None:
    g = SpurGear(0.003, z, x)
    k = g.span_teeth()
    assert shift_from_span(g.m, z, k, g.span(k)) == pytest.approx(x, abs=1e-12)


IMPOSSIBLE = [
    # (s_chord, h_chord), the error, its words — for m = 10 mm, z = 40, d_a = 420 mm
    ((0.13, 0.0091), ParameterError, r"s_chord = 0\.13: the chord's ends lie outside the tip"),
    ((0.05, 0.0091), ParameterError, r"s_chord = 0\.05: the chord spans .* angular pitch"),
    ((0.0181, 0.03), ParameterError, r"s_chord .* below the base circle .* must be ≥"),
    ((0.0181, 0.21), ParameterError, r"h_chord = 0\.21: the chordal height must lie between"),
    ((0.0, 0.0091), ParameterError, r"s_chord = 0\.0: the chordal thickness must be > 0"),
    ((0.032, 0.0199), ParameterError, r"s_chord .* (angular pitch|thicker|pitch)"),
    ((0.0181, 0.0001), ParameterError, r"s_chord .* outside the tip circle"),
    ((0.024, 0.0016), ConstructionError, r'step "limit circle": .* no involute flank'),
]


@pytest.mark.parametrize(("reading", "exc", "words"), IMPOSSIBLE)
def test_impossible_caliper_readings_are_refused(
    reading: tuple[float, float], exc: type, words: str
) -> None:
    with pytest.raises(exc, match=words):
        shift_from_chord(0.01, 40, 0.42, *reading)


def test_a_reading_on_a_pointed_tooth_is_refused() -> None:
    """A reading taken below the tip of a tooth whose flanks meet below the tip circle."""
    g = SpurGear(0.005, 12, 1.2, d_a=0.005 * (12 + 2 * 2.2))
    assert g.s_a < 0
    d_y = (g.limit_diameter() + g.pointed_diameter()) / 2
    ch = g.chord(d_y)
    with pytest.raises(ConstructionError, match='step "pointed tip": the flanks meet at d'):
        shift_from_chord(g.m, 12, g.tip_diameter, ch.s_bar, ch.h_bar)


@pytest.mark.parametrize("x", [0.0, 0.3, 0.8])
def test_a_chord_in_the_fillet_is_refused(x: float) -> None:
    """A chord whose ends lie on the generated fillet, not on the involute."""
    g = SpurGear(0.01, 40, x)
    q = g.flank(50).fillet[15]
    radius, eta = float(np.hypot(*q)), float(half_angle_of(q[None, :])[0])
    s_bar, h_bar = 2 * radius * math.sin(eta), g.r_a - radius * math.cos(eta)
    with pytest.raises(ConstructionError, match=r'step "chord on the flanks": .* the fillet'):
        shift_from_chord(0.01, 40, g.tip_diameter, s_bar, h_bar)


def test_a_span_touching_outside_the_involute_is_refused() -> None:
    with pytest.raises(ParameterError, match=r"W = .* over k = 12 teeth the jaws would touch"):
        g = SpurGear(0.003, 20)
        shift_from_span(0.003, 20, 12, g.span(12))
