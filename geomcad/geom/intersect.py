"""Closed-form intersections. Each returns a tuple of 0, 1 or 2 points in a documented order.

===================  ===========================  ==========================================
function             cases                        order of the points
===================  ===========================  ==========================================
line_line            () parallel, (P,) crossing   —
line_circle          () miss, (P,) tangent,       ascending along the line's direction
                     (P, Q) secant
circle_circle        () apart / nested /          first the point on the LEFT of the directed
                     concentric, (P,) touching,   line from the first centre to the second,
                     (P, Q) crossing              then the one on the right
===================  ===========================  ==========================================

"No intersection" is an empty tuple, never an exception; coincident input (the same line twice,
the same circle twice) is :class:`~geomcad.errors.DegenerateInput`, because it has infinitely
many common points.
"""

from __future__ import annotations

import math

from geomcad import tol
from geomcad.errors import DegenerateInput
from geomcad.geom.primitives import Circle, Line, Vec


def _scale(*values: float) -> float:
    return max((abs(v) for v in values), default=1.0) or 1.0


def line_line(l1: Line, l2: Line) -> tuple[Vec, ...]:
    """The common point of two lines: ``()`` when parallel, ``(P,)`` otherwise.

    Raises :class:`DegenerateInput` when the lines coincide.

    >>> line_line(Line.of((0, 0), (1, 0)), Line.of((2, -1), (0, 1)))
    (Vec(x=2.0, y=0.0),)
    """
    sin = l1.d.cross(l2.d)  # the directions are unit vectors, so this is sin of the angle
    if abs(sin) <= tol.ANGLE:
        scale = _scale(l1.p.x, l1.p.y, l2.p.x, l2.p.y)
        if abs(l1.side(l2.p)) <= tol.length_eps(scale):
            raise DegenerateInput("line ∩ line", "the two lines coincide")
        return ()
    t = (l2.p - l1.p).cross(l2.d) / sin
    return (l1.at(t),)


def line_circle(line: Line, circle: Circle) -> tuple[Vec, ...]:
    """The common points of a line and a circle, ascending along the line's direction.

    >>> line_circle(Line.of((-5, 0), (1, 0)), Circle.of((0, 0), 1))
    (Vec(x=-1.0, y=0.0), Vec(x=1.0, y=0.0))
    """
    t0 = line.param(circle.c)
    foot = line.at(t0)
    h = abs(line.side(circle.c))
    r = circle.r
    if h > r * (1.0 + tol.TANGENT):
        return ()
    if abs(h - r) <= tol.TANGENT * r:
        return (foot,)
    half = math.sqrt((r - h) * (r + h))
    return (line.at(t0 - half), line.at(t0 + half))


def circle_circle(c1: Circle, c2: Circle) -> tuple[Vec, ...]:
    """The common points of two circles: the one left of c1.c → c2.c first.

    Raises :class:`DegenerateInput` when the circles coincide.

    >>> circle_circle(Circle.of((0, 0), 1), Circle.of((1, 0), 1))[0].y > 0
    True
    """
    dv = c2.c - c1.c
    d = dv.norm
    scale = max(c1.r, c2.r, d)
    if d <= tol.length_eps(scale):
        if abs(c1.r - c2.r) <= tol.length_eps(scale):
            raise DegenerateInput("circle ∩ circle", "the two circles coincide")
        return ()
    outer = d - (c1.r + c2.r)
    inner = abs(c1.r - c2.r) - d
    if outer > tol.TANGENT * scale or inner > tol.TANGENT * scale:
        return ()
    u = dv / d
    a = (c1.r * c1.r - c2.r * c2.r + d * d) / (2.0 * d)
    m = c1.c + u * a
    if abs(outer) <= tol.TANGENT * scale or abs(inner) <= tol.TANGENT * scale:
        return (m,)
    h = math.sqrt(max(c1.r * c1.r - a * a, 0.0))
    n = u.perp()
    return (m + n * h, m - n * h)
