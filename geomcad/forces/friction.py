"""Friction in revolute joints: the friction circle and the lines of action it fixes.

In a revolute joint with friction coefficient f, the reaction R_ij of link i on link j does not
pass through the joint's centre. It touches the **friction circle** of radius ρ = r·sin φ, where
r = d/2 is the pin's radius and φ = arctan f the friction angle, on the side where its moment
about the centre opposes the rotation of j relative to i:

    M_O(R_ij) = −sign(ω_ji)·ρ·|R_ij|.

A joint whose links do not turn relative to each other (ω_ji = 0) carries no friction moment, and
its reaction passes through the centre, as it does when f = 0.

``sense`` below is always sign(ω_ji): +1 when the link the reaction acts on turns
counter-clockwise relative to the link that exerts it, −1 clockwise, 0 not at all.

- :func:`friction_circle` — the circle of a joint, from the pin diameter, f and the sense;
- :func:`two_force_line` — the line of action of a weightless two-force member: the internal or
  external common tangent of its end joints' friction circles, and its inclination to the link;
- :func:`tangent_reaction` — the tangent from a point (where two other forces meet) to a friction
  circle, on the side that opposes the relative rotation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from geomcad import tol
from geomcad.construction import fmt
from geomcad.errors import DegenerateInput, NoIntersection, ParameterError
from geomcad.geom import Circle, Line, PointLike, Vec, common_tangents, tangents_from, vec

SENSES = (-1, 0, 1)


def friction_angle(f: float) -> float:
    """The friction angle φ = arctan f (rad); f ≥ 0."""
    if not (math.isfinite(f) and f >= 0.0):
        raise ParameterError("f", f, "a friction coefficient must be a finite number ≥ 0")
    return math.atan(f)


def friction_radius(d: float, f: float) -> float:
    """The friction-circle radius ρ = (d/2)·sin(arctan f) of a pin of diameter ``d`` (m)."""
    if not (math.isfinite(d) and d > 0.0):
        raise ParameterError("d", d, "a pin diameter must be a finite number > 0")
    return 0.5 * d * math.sin(friction_angle(f))


@dataclass(frozen=True, slots=True)
class FrictionCircle:
    """The friction circle of a joint: centre ``c``, radius ``rho`` (m), the pin radius ``r``
    and the ``sense`` of the relative rotation of the link the considered reaction acts on.

    ``name`` is the joint's letter, for errors and labels.
    """

    c: Vec
    rho: float
    sense: int
    r: float = 0.0
    name: str = ""

    def __str__(self) -> str:
        turn = {1: "ccw", -1: "cw", 0: "no"}[self.sense]
        return (
            f"friction circle centre {fmt(self.c)}, ρ = {fmt(self.rho)}, opposing {turn} "
            "relative rotation"
        )

    @property
    def arm(self) -> float:
        """The moment arm of the reaction about the centre: ρ when the links turn relative to
        each other, 0 when they do not (or f = 0)."""
        return self.rho if self.sense else 0.0

    @property
    def circle(self) -> Circle:
        """The friction circle as a geometric circle; a zero arm is :class:`DegenerateInput`."""
        if self.arm <= 0.0:
            raise DegenerateInput(
                f"friction circle {self.name}".strip(),
                "it is a point: the reaction passes through the centre",
            )
        return Circle(self.c, self.arm)

    def moment_arm(self, line: Line) -> float:
        """The signed moment about the centre of a unit force along the directed ``line``
        (> 0 counter-clockwise)."""
        return (line.p - self.c).cross(line.d)

    def opposes(self, line: Line) -> bool:
        """True when a force along the directed ``line`` touches this circle and its moment about
        the centre is −sense·ρ, i.e. it opposes the relative rotation."""
        scale = max(self.arm, self.r, tol.length_eps(1.0))
        return abs(self.moment_arm(line) + self.sense * self.arm) <= tol.TANGENT * scale

    def reaction_line(self, direction: PointLike) -> Line:
        """The line of a reaction with the given direction (and sense): tangent to the circle on
        the side where its moment opposes the relative rotation, through the centre if the arm
        is zero. The moment of a force along u through c + n is n × u, so the line passes
        through c + sense·ρ·u⊥ (u⊥ is u turned +90°), where the moment is −sense·ρ."""
        u = vec(direction).unit()
        return Line(self.c + u.perp() * (self.sense * self.arm), u)


def friction_circle(
    centre: PointLike, d: float, f: float, sense: int, name: str = ""
) -> FrictionCircle:
    """The friction circle of a revolute joint.

    ``centre``: the joint's centre; ``d``: the pin diameter (m); ``f``: the friction
    coefficient (≥ 0); ``sense``: sign(ω_ji), the relative rotation of the link the reaction acts
    on with respect to the link that exerts it (+1 ccw, −1 cw, 0 none).

    >>> fc = friction_circle((0, 0), 0.032, 0.3, -1, "B")
    >>> round(fc.rho, 7)
    0.0045976
    """
    if sense not in SENSES:
        raise ParameterError("sense", sense, "must be +1 (ccw), −1 (cw) or 0 (no rotation)")
    return FrictionCircle(vec(centre), friction_radius(d, f), int(sense), 0.5 * d, name)


@dataclass(frozen=True, slots=True)
class TwoForceLine:
    """The line of action of a weightless two-force member between joints a and b.

    ``line`` passes through the contact points and is directed as the force that acts on the
    member at a (away from b in tension, towards b in compression); the force at b is opposite.
    ``kind`` is "internal" (the line crosses between the centres), "external", or "centre line"
    (no friction moment at either end). ``touch_a`` and ``touch_b`` are the contact points (the
    centres where the arm is zero). ``alpha`` is the signed angle (ccw > 0, rad) from the
    direction a → b to the line taken from a's side to b's; its size is the inclination to the
    link, arcsin((ρ_a ± ρ_b)/|ab|).
    """

    line: Line
    kind: str
    touch_a: Vec
    touch_b: Vec
    alpha: float

    def __str__(self) -> str:
        return (
            f"{self.kind}{' common tangent' if self.kind in ('internal', 'external') else ''} "
            f"through {fmt(self.touch_a)} and {fmt(self.touch_b)}, "
            f"at {math.degrees(self.alpha):.6f}° to the link"
        )

    @property
    def inclination(self) -> float:
        """The angle between the line of action and the link's centre line (rad, ≥ 0)."""
        return abs(self.alpha)


def two_force_line(a: FrictionCircle, b: FrictionCircle, tension: bool = True) -> TwoForceLine:
    """The line of action of a two-force member whose end joints have the friction circles a, b.

    The forces at the two ends are equal and opposite and share one line, which must touch both
    circles on the sides that oppose the relative rotations. With the same sense at both ends the
    circles lie on opposite sides of the line (the internal common tangent), with opposite senses
    on the same side (the external one); of the two tangents of that kind, the one whose moments
    oppose both rotations is taken. ``tension`` says which way the force acts (on the member at a:
    away from b in tension). A zero arm reduces a circle to its centre.

    Raises :class:`NoIntersection` when the circles overlap so that the required tangent does not
    exist, :class:`DegenerateInput` when the joints coincide.
    """
    if a.c.dist(b.c) <= tol.length_eps(max(a.c.norm, b.c.norm, a.r, b.r, 1.0)):
        raise DegenerateInput("two-force member", "its two joints coincide")
    ab = b.c - a.c
    toward_a = 1.0 if tension else -1.0  # the force on the member at a, along b → a in tension
    kind = "internal" if a.sense * b.sense > 0 else "external"
    candidates: list[tuple[Vec, Vec]] = []
    if a.arm > 0.0 and b.arm > 0.0:
        if kind == "internal" and a.arm + b.arm >= ab.norm * (1.0 - tol.TANGENT):
            na, nb = a.name or "a", b.name or "b"
            raise NoIntersection(
                "two-force member",
                f"the friction circles of {na} and {nb} overlap (ρ_{na} + ρ_{nb} = "
                f"{a.arm + b.arm:.6g} m ≥ {na}{nb} = {ab.norm:.6g} m): they have no internal "
                "common tangent",
            )
        candidates = [(s.a, s.b) for s in common_tangents(a.circle, b.circle, kind)]
    elif a.arm > 0.0:
        candidates = [(t, b.c) for t in tangents_from(b.c, a.circle)]
        kind = "tangent from b"
    elif b.arm > 0.0:
        candidates = [(a.c, t) for t in tangents_from(a.c, b.circle)]
        kind = "tangent from a"
    else:
        candidates = [(a.c, b.c)]
        kind = "centre line"
    for ta, tb in candidates:
        along = (ta - tb) * toward_a
        if along.norm == 0.0:
            continue
        at_a = Line(ta, along.unit())
        at_b = Line(tb, -at_a.d)
        if a.opposes(at_a) and b.opposes(at_b):
            ray = tb - ta
            alpha = math.atan2(ab.cross(ray), ab.dot(ray))
            return TwoForceLine(at_a, kind, ta, tb, alpha)
    raise NoIntersection(
        "two-force member",
        f"no common tangent of the friction circles of {a.name or 'a'} and {b.name or 'b'} "
        "opposes both relative rotations (they overlap)",
    )


def tangent_reaction(point: PointLike, fc: FrictionCircle, along: PointLike) -> Line:
    """The line of a reaction through ``point`` tangent to the friction circle ``fc``.

    ``along`` gives the force's sense: whether it points from the point towards the joint
    (``along`` has a positive component along point → centre) or away from it; a frictionless
    estimate or the force polygon gives it. With that sense, the two tangents from the point
    have moments of opposite signs about the centre, and the one whose moment opposes the
    relative rotation is taken. The line is directed along the force. A zero arm gives the line
    through the centre.

    Raises :class:`NoIntersection` when the point lies inside the friction circle (no tangent),
    :class:`DegenerateInput` when ``along`` is square to point → centre (no sense).
    """
    p = vec(point)
    to_c = fc.c - p
    if to_c.norm == 0.0:
        raise DegenerateInput("reaction through a point", "the point is the joint's centre")
    touches = tangents_from(p, fc.circle) if fc.arm > 0.0 else ()
    if len(touches) == 1:  # the point is on the circle: the tangent there
        w = (p - fc.c).perp()
        w = w if w.dot(vec(along)) >= 0.0 else -w
        line = Line(p, w.unit())
        if fc.opposes(line):
            return line
        raise NoIntersection(
            "tangent to a friction circle",
            f"the point lies on the friction circle of {fc.name or 'the joint'}, on the side "
            "where the reaction would help the relative rotation",
        )
    toward = vec(along).dot(to_c.unit())
    if abs(toward) <= tol.ANGLE:
        raise DegenerateInput(
            "reaction through a point",
            "the given sense is square to the line from the point to the joint: it says "
            "neither towards nor away",
        )
    sigma = 1.0 if toward > 0.0 else -1.0  # the force points towards the joint, or away
    if fc.arm <= 0.0:
        return Line(p, to_c.unit() * sigma)
    if not touches:
        raise NoIntersection(
            "tangent to a friction circle",
            f"the point lies within the friction circle of {fc.name or 'the joint'} "
            f"({p.dist(fc.c):.6g} m from its centre, ρ = {fc.arm:.6g} m)",
        )
    for t in touches:
        line = Line(t, (t - p).unit() * sigma)
        if fc.opposes(line):
            return Line(p, line.d)
    raise NoIntersection(  # unreachable: with one sense the two tangents' moments differ in sign
        "tangent to a friction circle", "neither tangent opposes the relative rotation"
    )
