"""geomcad.forces: friction circles, two-force lines, tangent reactions, the three-force theorem
and force polygons, checked against independent formulas and invariants."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geomcad.construction import Construction
from geomcad.errors import DegenerateInput, NoIntersection, ParallelLines, ParameterError
from geomcad.forces import (
    Known,
    Unknown,
    close_polygon,
    force_polygon,
    friction_angle,
    friction_circle,
    friction_radius,
    inclination_to_horizontal,
    moment,
    tangent_reaction,
    three_force_point,
    two_force_line,
)
from geomcad.geom import Line, Vec

ABS = 1e-12

coord = st.floats(-1.0, 1.0, allow_nan=False)
sense = st.sampled_from((-1, 1))
pin = st.floats(0.005, 0.05)
coef = st.floats(0.01, 2.0)


# -- the friction circle ---------------------------------------------------------------------------


@pytest.mark.parametrize(("d", "f"), [(0.032, 0.3), (0.05, 0.1), (0.01, 1.0), (0.02, 5.0)])
def test_friction_radius_is_r_sin_phi(d: float, f: float) -> None:
    assert friction_angle(f) == pytest.approx(math.atan(f), abs=ABS)
    assert friction_radius(d, f) == pytest.approx(d / 2 * f / math.sqrt(1 + f * f), rel=1e-14)


def test_the_seed_friction_circle() -> None:
    # the seed: φ = arctg 0,3 = 16,7°, ρ = 0,5·0,032·sin 16,7° = 0,0046 м
    assert math.degrees(friction_angle(0.3)) == pytest.approx(16.7, abs=0.05)
    assert friction_radius(0.032, 0.3) == pytest.approx(0.0046, abs=0.00005)


def test_no_friction_gives_a_point() -> None:
    fc = friction_circle((1.0, 2.0), 0.03, 0.0, 1, "A")
    assert fc.rho == 0.0 and fc.arm == 0.0
    with pytest.raises(DegenerateInput, match="friction circle A"):
        _ = fc.circle
    # no relative rotation: no friction moment either
    assert friction_circle((0, 0), 0.03, 0.3, 0).arm == 0.0


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: friction_radius(0.03, -0.1), r"parameter f = -0\.1: .*≥ 0"),
        (lambda: friction_radius(0.0, 0.3), r"parameter d = 0\.0: .*> 0"),
        (lambda: friction_radius(float("nan"), 0.3), r"parameter d"),
        (lambda: friction_radius(0.03, float("inf")), r"parameter f"),
        (lambda: friction_circle((0, 0), 0.03, 0.3, 2), r"parameter sense = 2"),
    ],
)
def test_bad_friction_input(call: object, words: str) -> None:
    with pytest.raises(ParameterError, match=words):
        call()  # type: ignore[operator]


@given(coord, coord, pin, coef, sense, st.floats(0.0, 2 * math.pi))
def test_reaction_line_opposes_the_relative_rotation(
    x: float, y: float, d: float, f: float, s: int, angle: float
) -> None:
    fc = friction_circle((x, y), d, f, s)
    line = fc.reaction_line(Vec.polar(1.0, angle))
    # it touches the circle, and its moment about the centre is −sense·ρ per newton
    assert abs(line.side(fc.c)) == pytest.approx(fc.rho, abs=ABS)
    assert moment(fc.c, line, 1.0) == pytest.approx(-s * fc.rho, abs=ABS)
    assert fc.opposes(line)
    assert not fc.opposes(Line(line.p, -line.d))


# -- two-force members ---------------------------------------------------------------------------


@settings(max_examples=300)
@given(coord, coord, coord, coord, pin, pin, coef, sense, sense, st.booleans())
def test_two_force_line_touches_both_circles_and_opposes_both_rotations(
    ax: float,
    ay: float,
    bx: float,
    by: float,
    da: float,
    db: float,
    f: float,
    sa: int,
    sb: int,
    tension: bool,
) -> None:
    a = friction_circle((ax, ay), da, f, sa, "a")
    b = friction_circle((bx, by), db, f, sb, "b")
    length = a.c.dist(b.c)
    assume(length > 1.5 * (a.rho + b.rho) + 1e-3)
    t = two_force_line(a, b, tension)
    line = t.line
    at_b = Line(t.touch_b, -line.d)
    # tangency: each centre is ρ from the line, at the contact point
    assert abs(line.side(a.c)) == pytest.approx(a.rho, abs=1e-12)
    assert abs(line.side(b.c)) == pytest.approx(b.rho, abs=1e-12)
    assert t.touch_a.dist(a.c) == pytest.approx(a.rho, abs=1e-12)
    assert t.touch_b.dist(b.c) == pytest.approx(b.rho, abs=1e-12)
    assert abs(line.side(t.touch_b)) <= 1e-12
    # the force on the member at a: away from b in tension, towards it in compression
    assert line.d.dot(a.c - b.c) * (1 if tension else -1) > 0
    # each end's moment opposes its relative rotation
    assert moment(a.c, line, 1.0) == pytest.approx(-sa * a.rho, abs=1e-12)
    assert moment(b.c, at_b, 1.0) == pytest.approx(-sb * b.rho, abs=1e-12)
    # the same senses: internal; opposite: external; and |sin α| = |s_a ρ_a + s_b ρ_b| / |ab|
    assert t.kind == ("internal" if sa == sb else "external")
    sides = line.side(a.c) * line.side(b.c)
    assert (sides < 0) == (sa == sb)
    assert math.sin(t.inclination) == pytest.approx(abs(sa * a.rho + sb * b.rho) / length, abs=1e-9)


def test_two_force_line_of_the_seed_link() -> None:
    """Link 3 of 2013-7: B below F at 45°, both joints turning clockwise relative to link 3's
    neighbours; the internal tangent, α = arcsin(2ρ/BF) = 3,5°, turned away from the vertical."""
    h = 0.15 / math.sqrt(2)
    F = Vec(0.05 + h, -h)
    B = Vec(0.05, F.y - h)
    t = two_force_line(
        friction_circle(B, 0.032, 0.3, -1, "B"), friction_circle(F, 0.032, 0.3, -1, "F")
    )
    rho = friction_radius(0.032, 0.3)
    assert t.kind == "internal"
    assert t.inclination == pytest.approx(math.asin(2 * rho / 0.15), rel=1e-12)
    assert math.degrees(t.inclination) == pytest.approx(3.5, abs=0.05)
    # the force on link 3 at B points down and away from F: 45° + α from the downward vertical
    assert math.degrees(math.atan2(-t.line.d.x, -t.line.d.y)) == pytest.approx(
        45 + math.degrees(t.inclination), abs=1e-9
    )
    # the line passes through the middle of BF (equal circles, internal tangent)
    assert abs(t.line.side((B + F) * 0.5)) <= 1e-15


def test_two_force_line_without_friction_is_the_centre_line() -> None:
    a = friction_circle((0, 0), 0.03, 0.0, -1)
    b = friction_circle((1, 1), 0.03, 0.0, 1)
    t = two_force_line(a, b)
    assert t.kind == "centre line" and t.alpha == 0.0
    assert t.touch_a == a.c and t.touch_b == b.c


def test_two_force_line_with_one_idle_joint_is_a_tangent_from_its_centre() -> None:
    a = friction_circle((0, 0), 0.04, 0.3, 0)  # no relative rotation at a
    b = friction_circle((0.5, 0), 0.04, 0.3, 1)
    t = two_force_line(a, b, tension=False)
    assert t.touch_a == a.c
    assert abs(t.line.side(b.c)) == pytest.approx(b.rho, abs=1e-15)
    assert moment(b.c, Line(t.touch_b, -t.line.d), 1.0) == pytest.approx(-b.rho, abs=1e-15)
    t2 = two_force_line(b, a, tension=False)
    assert t2.touch_b == a.c


def test_overlapping_friction_circles_have_no_internal_tangent() -> None:
    a = friction_circle((0, 0), 0.6, 0.3, -1, "B")
    b = friction_circle((0.15, 0), 0.6, 0.3, -1, "F")
    with pytest.raises(NoIntersection, match=r"friction circles of B and F overlap"):
        two_force_line(a, b)
    # with opposite senses the external tangent still exists
    c = friction_circle((0.15, 0), 0.6, 0.3, 1, "F")
    assert two_force_line(a, c).kind == "external"


def test_coincident_joints_are_degenerate() -> None:
    a = friction_circle((0, 0), 0.03, 0.3, 1)
    with pytest.raises(DegenerateInput, match="coincide"):
        two_force_line(a, a)


# -- a tangent from a point ------------------------------------------------------------------------


@settings(max_examples=300)
@given(coord, coord, coord, coord, pin, coef, sense, st.floats(0.0, 2 * math.pi))
def test_tangent_reaction_passes_the_point_and_opposes_the_rotation(
    px: float, py: float, cx: float, cy: float, d: float, f: float, s: int, hint_angle: float
) -> None:
    fc = friction_circle((cx, cy), d, f, s, "H")
    p = Vec(px, py)
    assume(p.dist(fc.c) > 2 * fc.rho + 1e-3)
    hint = Vec.polar(1.0, hint_angle)
    assume(abs(hint.dot((fc.c - p).unit())) > 0.2)  # a hint that says which way the force acts
    line = tangent_reaction(p, fc, hint)
    assert line.p == p
    assert abs(line.side(fc.c)) == pytest.approx(fc.rho, abs=1e-12)
    # the sense: towards the joint or away from it, as the hint says
    assert line.d.dot(fc.c - p) * hint.dot(fc.c - p) > 0
    assert moment(fc.c, line, 1.0) == pytest.approx(-s * fc.rho, abs=1e-12)


def test_tangent_reaction_from_inside_the_circle_is_an_error() -> None:
    fc = friction_circle((0, 0), 0.1, 1.0, 1, "H")
    with pytest.raises(NoIntersection, match="within the friction circle of H"):
        tangent_reaction((0.01, 0.0), fc, (1.0, 0.0))


def test_tangent_reaction_from_a_point_on_the_circle() -> None:
    fc = friction_circle((0, 0), 0.1, 1.0, 1, "H")
    on = Vec(fc.rho, 0.0)
    line = tangent_reaction(on, fc, (0.0, -1.0))  # down on the right: clockwise, opposes ccw
    assert line.p == on and line.d.y < 0 and fc.opposes(line)
    with pytest.raises(NoIntersection, match="would help the relative rotation"):
        tangent_reaction(on, fc, (0.0, 1.0))


def test_tangent_reaction_without_friction_runs_through_the_centre() -> None:
    fc = friction_circle((1, 1), 0.1, 0.0, 1)
    line = tangent_reaction((0, 0), fc, (-1.0, -1.0))
    assert line.d.x < 0 and abs(line.side((1, 1))) <= 1e-15
    with pytest.raises(DegenerateInput, match="centre"):
        tangent_reaction((1, 1), fc, (1.0, 0.0))
    with pytest.raises(DegenerateInput, match="neither towards nor away"):
        tangent_reaction((0, 0), fc, (1.0, -1.0))


# -- the three-force theorem and moments ---------------------------------------------------------


def test_three_force_point_lies_on_both_lines() -> None:
    l1 = Line.of((0, 0), (1, 2))
    l2 = Line.of((3, 0), (-1, 1))
    k = three_force_point(l1, l2)
    assert abs(l1.side(k)) <= 1e-15 and abs(l2.side(k)) <= 1e-15
    with pytest.raises(ParallelLines, match="parallel"):
        three_force_point(l1, Line.of((5, 5), (2, 4)))


def test_moment_and_inclination() -> None:
    # 10 N along +x, 2 m above the point: clockwise, −20 N·m
    assert moment((0, 0), Line.of((7, 2), (1, 0)), 10.0) == pytest.approx(-20.0)
    assert math.degrees(inclination_to_horizontal((-1, math.sqrt(3)))) == pytest.approx(60.0)
    assert inclination_to_horizontal((0, -1)) == pytest.approx(math.pi / 2)
    with pytest.raises(DegenerateInput):
        inclination_to_horizontal((0, 0))


# -- force polygons -----------------------------------------------------------------------------


def test_symmetric_triangle_of_the_seed_sleeve() -> None:
    """G_2 + R_32 + R_42 = 0 with R_32, R_42 at 45° + α to the vertical: the seed's
    m2·g/2 = R_32·cos(45° + α)."""
    alpha = math.asin(2 * friction_radius(0.032, 0.3) / 0.15)
    up = math.radians(45) + alpha
    p = close_polygon(
        [
            Known("G_2", Vec(0, -98.1)),
            Unknown("R_32", Vec(math.sin(up), math.cos(up))),
            Unknown("R_42", Vec(-math.sin(up), math.cos(up))),
        ]
    )
    assert p.signed("R_32") == pytest.approx(98.1 / (2 * math.cos(up)), rel=1e-13)
    assert p.signed("R_32") == pytest.approx(74.0, abs=0.5)
    assert p.closure <= 1e-12
    assert p.vectors[-1].head.dist(p.pole) <= 1e-12
    assert p.names == ("G_2", "R_32", "R_42")


def test_unknown_sense_comes_out_negative() -> None:
    p = close_polygon([Known("G", Vec(0, -10)), Unknown("A", Vec(0, -1)), Unknown("B", Vec(1, 0))])
    assert p.signed("A") == pytest.approx(-10.0) and p.signed("B") == pytest.approx(0.0, abs=1e-15)
    assert p["A"].force.y == pytest.approx(10.0)


@settings(max_examples=300)
@given(
    st.lists(st.tuples(st.floats(-100, 100), st.floats(-100, 100)), min_size=1, max_size=5),
    st.floats(0, 2 * math.pi),
    st.floats(0, 2 * math.pi),
    st.integers(0, 5),
    st.integers(0, 5),
)
def test_any_polygon_closes_head_to_tail(
    knowns: list[tuple[float, float]], a1: float, a2: float, i: int, j: int
) -> None:
    assume(abs(math.sin(a2 - a1)) > 0.05)
    terms: list[Known | Unknown] = [Known(f"F{k}", Vec(x, y)) for k, (x, y) in enumerate(knowns)]
    i, j = sorted((min(i, len(terms)), min(j, len(terms))))
    terms.insert(i, Unknown("U1", Vec.polar(1.0, a1)))
    terms.insert(j + 1, Unknown("U2", Vec.polar(1.0, a2)))
    pole = Vec(3.0, -2.0)
    p = close_polygon(terms, pole)
    scale = 1.0 + sum(math.hypot(x, y) for x, y in knowns)
    assert p.closure <= 1e-12 * scale
    assert p.vectors[0].tail == pole
    for prev, nxt in zip(p.vectors, p.vectors[1:], strict=False):
        assert prev.head == nxt.tail
    assert p.vectors[-1].head.dist(pole) <= 1e-12 * scale
    for t, v in zip(terms, p.vectors, strict=True):
        assert v.name == t.name
        if isinstance(t, Known):
            assert v.force.dist(t.force) <= 1e-12 * scale
        else:
            assert abs(v.force.cross(t.direction)) <= 1e-12 * scale


def test_polygon_needs_two_unknowns_that_are_not_parallel() -> None:
    with pytest.raises(DegenerateInput, match="exactly two unknown"):
        close_polygon([Known("G", Vec(0, -1)), Unknown("A", Vec(1, 0))])
    with pytest.raises(ParallelLines, match="parallel"):
        close_polygon([Known("G", Vec(0, -1)), Unknown("A", Vec(1, 0)), Unknown("B", Vec(-2, 0))])


def test_recorded_polygon_names_its_steps() -> None:
    c = Construction("t")
    terms = [Known("G", Vec(0, -10)), Known("R", Vec(-3, -4)), Unknown("F", Vec(1, 0)),
             Unknown("S", Vec(-1, 2))]  # fmt: skip
    p = force_polygon(c, "plan", terms)
    assert c["plan"] is p
    for name in ("plan: ∥ F", "plan: ∥ S", "plan: closing vertex", "plan: G", "plan: |F|"):
        assert name in c
    assert c["plan: |F|"] == p.signed("F")
    assert "G + R + F + S = 0" in c.trace()
    diag = p.diagonal("G", "R", "P")
    assert diag.force.dist(Vec(-3, -14)) <= 1e-15
    bad = [Known("G", Vec(0, -1)), Unknown("A", Vec(1, 0)), Unknown("B", Vec(1, 0))]
    with pytest.raises(ParallelLines, match=r'step "plan2: closing vertex = line ∥ A ∩ line ∥ B'):
        force_polygon(c, "plan2", bad)
    with pytest.raises(KeyError, match="no vector 'X'"):
        _ = p["X"]
