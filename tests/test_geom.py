"""The geometry kernel: documented cases and orders, and invariants under hypothesis."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geomcad.errors import DegenerateInput
from geomcad.geom import (
    Circle,
    Line,
    Vec,
    angle_arcs,
    circle_circle,
    circle_on_diameter,
    circle_through,
    common_tangents,
    line_circle,
    line_line,
    mirror,
    perpendicular,
    ray_at_angle,
    rotate,
    tangents_from,
)

REL = 1e-9
coord = st.floats(-10.0, 10.0, allow_nan=False)
radius = st.floats(0.1, 10.0)
points = st.builds(Vec, coord, coord)
angles = st.floats(-math.pi, math.pi)


def on_circle(p: Vec, c: Circle, scale: float = 10.0) -> bool:
    return abs(p.dist(c.c) - c.r) <= REL * scale


def on_line(p: Vec, line: Line, scale: float = 10.0) -> bool:
    return abs(line.side(p)) <= REL * scale


# -- the table of cases -------------------------------------------------------------------------
def test_line_line_cases() -> None:
    x = Line.of((0, 0), (1, 0))
    assert line_line(x, Line.of((2, -1), (0, 1))) == (Vec(2.0, 0.0),)
    assert line_line(x, Line.of((0, 1), (1, 0))) == ()
    with pytest.raises(DegenerateInput, match="coincide"):
        line_line(x, Line.of((5, 0), (-1, 0)))


def test_line_circle_cases_and_order() -> None:
    c = Circle.of((0, 0), 1)
    assert line_circle(Line.of((-5, 2), (1, 0)), c) == ()
    assert line_circle(Line.of((-5, 1), (1, 0)), c) == (Vec(0.0, 1.0),)
    p, q = line_circle(Line.of((5, 0), (-1, 0)), c)  # ascending along the direction (−x)
    assert p == Vec(1.0, 0.0) and q == Vec(-1.0, 0.0)


def test_circle_circle_cases_and_order() -> None:
    a = Circle.of((0, 0), 1)
    assert circle_circle(a, Circle.of((3, 0), 1)) == ()  # apart
    assert circle_circle(a, Circle.of((0.1, 0), 0.2)) == ()  # nested
    assert circle_circle(a, Circle.of((0, 0), 2)) == ()  # concentric
    assert circle_circle(a, Circle.of((2, 0), 1)) == (Vec(1.0, 0.0),)  # touching outside
    assert circle_circle(a, Circle.of((0.5, 0), 0.5)) == (Vec(1.0, 0.0),)  # touching inside
    left, right = circle_circle(a, Circle.of((1, 0), 1))
    assert left.y > 0 > right.y  # left of the directed line of centres first
    left2, _ = circle_circle(Circle.of((1, 0), 1), a)
    assert left2.y < 0
    with pytest.raises(DegenerateInput):
        circle_circle(a, Circle.of((0, 0), 1))


def test_degenerate_primitives() -> None:
    with pytest.raises(DegenerateInput):
        Circle.of((0, 0), 0.0)
    with pytest.raises(DegenerateInput):
        Circle.of((0, 0), -1.0)
    with pytest.raises(DegenerateInput):
        Line.through((1, 1), (1, 1))
    with pytest.raises(DegenerateInput):
        circle_through((0, 0), (1, 1), (2, 2))
    with pytest.raises(DegenerateInput):
        angle_arcs((0, 0), (1, 0), 0.0)


def test_tangents_from_cases() -> None:
    c = Circle.of((0, 0), 3)
    assert tangents_from((1, 0), c) == ()
    assert tangents_from((3, 0), c) == (Vec(3.0, 0.0),)
    first, second = tangents_from((5, 0), c)
    assert first == Vec(1.8, -2.4) and second == Vec(1.8, 2.4)


def test_common_tangents_counts() -> None:
    a, b = Circle.of((0, 0), 1), Circle.of((5, 0), 2)
    assert len(common_tangents(a, b, "external")) == 2
    assert len(common_tangents(a, b, "internal")) == 2
    assert common_tangents(a, Circle.of((1.5, 0), 1), "internal") == ()  # overlapping
    assert len(common_tangents(a, Circle.of((2, 0), 1), "internal")) == 1  # touching
    assert common_tangents(a, Circle.of((0.1, 0), 0.2), "external") == ()  # nested


# -- invariants ---------------------------------------------------------------------------------
@settings(max_examples=200)
@given(points, radius, points, radius)
def test_circle_circle_points_lie_on_both(c1: Vec, r1: float, c2: Vec, r2: float) -> None:
    assume(c1.dist(c2) > 1e-3)
    a, b = Circle(c1, r1), Circle(c2, r2)
    pts = circle_circle(a, b)
    for p in pts:
        assert on_circle(p, a) and on_circle(p, b)
    d = c1.dist(c2)
    if abs(r1 - r2) + 1e-6 < d < r1 + r2 - 1e-6:
        assert len(pts) == 2
        assert Line.through(c1, c2).side(pts[0]) > 0 > Line.through(c1, c2).side(pts[1])


@settings(max_examples=200)
@given(points, angles, points, radius)
def test_line_circle_points_lie_on_both(p: Vec, ang: float, c: Vec, r: float) -> None:
    line = Line.at_angle(p, ang)
    circ = Circle(c, r)
    pts = line_circle(line, circ)
    for q in pts:
        assert on_circle(q, circ, 20.0) and on_line(q, line, 20.0)
    if len(pts) == 2:
        assert line.param(pts[0]) < line.param(pts[1])


@settings(max_examples=200)
@given(points, angles, points, angles)
def test_line_line_point_lies_on_both(p: Vec, a1: float, q: Vec, a2: float) -> None:
    assume(abs(math.sin(a1 - a2)) > 1e-3)
    l1, l2 = Line.at_angle(p, a1), Line.at_angle(q, a2)
    (x,) = line_line(l1, l2)
    scale = max(1.0, x.norm)
    assert on_line(x, l1, scale) and on_line(x, l2, scale)


@settings(max_examples=200)
@given(points, points, points)
def test_circle_through_three_points(a: Vec, b: Vec, c: Vec) -> None:
    area = abs((b - a).cross(c - a))
    assume(area > 0.5)
    k = circle_through(a, b, c)
    for p in (a, b, c):
        assert on_circle(p, k, max(10.0, k.r))


@settings(max_examples=200)
@given(points, points, radius)
def test_tangents_touch(p: Vec, c: Vec, r: float) -> None:
    circ = Circle(c, r)
    assume(p.dist(c) > r * 1.01)
    for t in tangents_from(p, circ):
        assert on_circle(t, circ, 20.0)
        assert abs((t - p).dot(t - c)) <= REL * 400.0  # radius ⊥ tangent


@settings(max_examples=200)
@given(points, radius, points, radius, st.sampled_from(["external", "internal"]))
def test_common_tangents_touch_both(c1: Vec, r1: float, c2: Vec, r2: float, kind: str) -> None:
    a, b = Circle(c1, r1), Circle(c2, r2)
    for seg in common_tangents(a, b, kind):
        assume(seg.length > 1e-6)
        line = seg.line
        assert abs(abs(line.side(c1)) - r1) <= REL * 40
        assert abs(abs(line.side(c2)) - r2) <= REL * 40
        same_side = line.side(c1) * line.side(c2) > 0
        assert same_side == (kind == "external")


@settings(max_examples=200)
@given(points, points, st.floats(0.05, math.pi - 0.05), st.floats(0.01, 0.99))
def test_angle_arcs_see_the_chord_under_the_angle(a: Vec, b: Vec, ang: float, f: float) -> None:
    assume(a.dist(b) > 0.1)
    left, right = angle_arcs(a, b, ang)
    chord = Line.through(a, b)
    for arc, sign in ((left, 1.0), (right, -1.0)):
        x = arc.circle.at(arc.start + f * arc.sweep)
        assert chord.side(x) * sign > 0
        seen = abs(math.atan2((a - x).cross(b - x), (a - x).dot(b - x)))
        assert math.isclose(seen, ang, rel_tol=1e-7)


@settings(max_examples=100)
@given(points, points, points, angles, points)
def test_constructions_commute_with_rotation(a: Vec, b: Vec, c: Vec, ang: float, o: Vec) -> None:
    """A rigid motion of the input moves the circle through three points the same way."""
    assume(abs((b - a).cross(c - a)) > 0.5)
    k = circle_through(a, b, c)
    k2 = circle_through(rotate(a, ang, o), rotate(b, ang, o), rotate(c, ang, o))
    assert rotate(k.c, ang, o).dist(k2.c) <= 1e-7 * max(1.0, k.r)
    assert math.isclose(k.r, k2.r, rel_tol=1e-7)


def test_thales_and_textbook_verbs() -> None:
    k = circle_on_diameter((0, 0), (2, 0))
    assert k.c == Vec(1.0, 0.0) and k.r == 1.0
    x = Line.of((0, 0), (1, 0))
    assert perpendicular(x, (3, 1)).d == Vec(-0.0, 1.0)
    assert mirror((1, 2), x) == Vec(1.0, -2.0)
    r = ray_at_angle((0, 0), (1, 0), math.pi / 2)
    assert abs(r.d.x) < 1e-15 and r.d.y == 1.0
