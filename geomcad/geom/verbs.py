"""The textbook verbs of ruler-and-compass construction, as exact operations.

Names read like the steps of a graphical solution: ``perpendicular(line, through=p)``,
``circle_through(a, b, c)``, ``tangents_from(p, circle)``, ``angle_arcs(a, b, θ)``.
"""

from __future__ import annotations

import math

from geomcad import tol
from geomcad.errors import DegenerateInput
from geomcad.geom.primitives import Arc, Circle, Line, PointLike, Segment, Vec, vec


def perpendicular(line: Line, through: PointLike) -> Line:
    """The perpendicular to ``line`` through a point; its direction is the line's, turned +90°."""
    return Line(vec(through), line.normal)


def parallel(line: Line, through: PointLike | None = None, offset: float = 0.0) -> Line:
    """The parallel to ``line`` through a point, or at signed distance ``offset`` (left > 0)."""
    p = vec(through) if through is not None else line.p + line.normal * offset
    return Line(p, line.d)


def bisector(a: PointLike, b: PointLike) -> Line:
    """The perpendicular bisector of segment ab, directed to the left of a → b."""
    a, b = vec(a), vec(b)
    return perpendicular(Line.through(a, b), (a + b) * 0.5)


def angle_bisector(vertex: PointLike, p: PointLike, q: PointLike) -> Line:
    """The bisector of the angle p-vertex-q, directed into the angle."""
    v = vec(vertex)
    u1 = (vec(p) - v).unit()
    u2 = (vec(q) - v).unit()
    s = u1 + u2
    if s.norm <= tol.ANGLE:
        return Line(v, u1.perp())
    return Line(v, s.unit())


def ray_at_angle(origin: PointLike, toward: PointLike, angle: float) -> Line:
    """The line from ``origin`` at ``angle`` radians (counter-clockwise > 0) to origin → toward."""
    o = vec(origin)
    return Line(o, (vec(toward) - o).unit().rotated(angle))


def rotate(p: PointLike, angle: float, about: PointLike = (0.0, 0.0)) -> Vec:
    """The point turned by ``angle`` radians counter-clockwise about a centre."""
    c = vec(about)
    return c + (vec(p) - c).rotated(angle)


def scale(p: PointLike, k: float, about: PointLike = (0.0, 0.0)) -> Vec:
    """The point scaled by ``k`` from a centre (a homothety)."""
    c = vec(about)
    return c + (vec(p) - c) * k


def mirror(p: PointLike, line: Line) -> Vec:
    """The mirror image of a point over a line."""
    q = vec(p)
    return q - line.normal * (2.0 * line.side(q))


def mirror_circle(c: Circle, line: Line) -> Circle:
    """The mirror image of a circle over a line."""
    return Circle(mirror(c.c, line), c.r)


def circle_through(a: PointLike, b: PointLike, c: PointLike) -> Circle:
    """The circle through three points; collinear points are :class:`DegenerateInput`.

    >>> circle_through((1, 0), (0, 1), (-1, 0))
    Circle(c=Vec(x=0.0, y=0.0), r=1.0)
    """
    a, b, c = vec(a), vec(b), vec(c)
    ab, ac = b - a, c - a
    den = 2.0 * ab.cross(ac)
    size = max(ab.norm, ac.norm)
    if abs(den) <= tol.REL_LENGTH * size * size:
        raise DegenerateInput("circle through three points", "the points are collinear")
    ux = (ac.y * ab.dot(ab) - ab.y * ac.dot(ac)) / den
    uy = (ab.x * ac.dot(ac) - ac.x * ab.dot(ab)) / den
    centre = a + Vec(ux, uy)
    return Circle(centre, centre.dist(a))


def circle_on_diameter(a: PointLike, b: PointLike) -> Circle:
    """The circle on diameter ab (Thales: every point of it sees ab at 90°)."""
    a, b = vec(a), vec(b)
    if a == b:
        raise DegenerateInput("circle on a diameter", "the diameter's ends coincide")
    return Circle((a + b) * 0.5, a.dist(b) * 0.5)


def tangents_from(p: PointLike, circle: Circle) -> tuple[Vec, ...]:
    """The points where the tangents from ``p`` touch ``circle``.

    ``()`` when p is inside, ``(p,)`` when p is on the circle, otherwise two points: first the
    one on the left of the directed line from p to the centre.
    """
    q = vec(p)
    dv = circle.c - q
    d = dv.norm
    r = circle.r
    if d < r * (1.0 - tol.TANGENT):
        return ()
    if abs(d - r) <= tol.TANGENT * r:
        return (q,)
    u = dv / d
    # the contact point T: angle at the centre between C→p and C→T is arccos(r/d)
    along = r * r / d
    across = r * math.sqrt((d - r) * (d + r)) / d
    foot = circle.c - u * along
    n = u.perp()
    return (foot + n * across, foot - n * across)


def common_tangents(c1: Circle, c2: Circle, kind: str = "external") -> tuple[Segment, ...]:
    """The common tangents of two circles, each as the segment from its contact with c1 to c2.

    ``kind`` is "external" (both circles on one side of the tangent) or "internal" (the tangent
    crosses between them). ``()`` when there is none (nested circles; overlapping circles for
    "internal"); a single touching tangent counts once. The tangent touching c1 on the LEFT of
    the directed line c1.c → c2.c comes first.
    """
    if kind not in ("external", "internal"):
        raise DegenerateInput("common tangents", f"kind must be external or internal, not {kind}")
    dv = c2.c - c1.c
    d = dv.norm
    if d <= tol.length_eps(max(c1.r, c2.r)):
        return ()
    s2 = 1.0 if kind == "external" else -1.0
    cos_b = (s2 * c2.r - c1.r) / d
    if abs(cos_b) > 1.0 + tol.TANGENT:
        return ()
    cos_b = max(-1.0, min(1.0, cos_b))
    sin_b = math.sqrt(max(0.0, 1.0 - cos_b * cos_b))
    u = dv / d
    out: list[Segment] = []
    for sb in (-sin_b, sin_b) if sin_b > tol.TANGENT else (0.0,):
        n = u * cos_b + u.perp() * sb  # unit normal; both centres on its + side (internal: c2 on −)
        t1 = c1.c - n * c1.r
        t2 = c2.c - n * (s2 * c2.r)
        out.append(Segment(t1, t2))
    return tuple(out)


def angle_arcs(a: PointLike, b: PointLike, angle: float) -> tuple[Arc, Arc]:
    """The two arcs of points X that see the chord ab under ``angle`` (∠aXb = angle, 0 < angle < π).

    Returns (the arc on the LEFT of a → b, the arc on the right); they are mirror images over ab.
    Each is the locus of the inscribed-angle theorem: radius |ab| / (2 sin angle), centre on the
    perpendicular bisector at |ab| / (2 tan angle) from the midpoint, on the arc's own side when
    angle < 90°. The chord's end points themselves are not on the arcs.
    """
    a, b = vec(a), vec(b)
    if not 0.0 < angle < math.pi:
        raise DegenerateInput(
            "arc seeing a chord under an angle", "the angle must be in (0°, 180°)"
        )
    if a == b:
        raise DegenerateInput("arc seeing a chord under an angle", "the chord's ends coincide")
    chord = b - a
    c = chord.norm
    m = (a + b) * 0.5
    n = chord.unit().perp()  # left normal
    radius = c / (2.0 * math.sin(angle))
    off = c / (2.0 * math.tan(angle))
    arcs: list[Arc] = []
    for side in (1.0, -1.0):
        centre = m + n * (side * off)
        circ = Circle(centre, radius)
        aa = (a - centre).angle
        ab_ = (b - centre).angle
        # the arc on this side runs counter-clockwise from b to a (left side) or a to b (right)
        arcs.append(Arc(circ, ab_, aa) if side > 0 else Arc(circ, aa, ab_))
    return arcs[0], arcs[1]
