"""Small frozen value objects: Vec (points and vectors), Line, Ray, Segment, Circle, Arc.

Equality is exact (``==`` compares the floats); tolerant comparison is :func:`almost_equal`.
Public functions accept loose point input (a ``Vec``, a tuple or a length-2 array) through
:func:`vec` and return geomcad types.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import SupportsFloat, TypeAlias

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import DegenerateInput


@dataclass(frozen=True, slots=True)
class Vec:
    """A point or a free vector in the plane (model units, y up)."""

    x: float
    y: float

    def __add__(self, o: Vec) -> Vec:
        return Vec(self.x + o.x, self.y + o.y)

    def __sub__(self, o: Vec) -> Vec:
        return Vec(self.x - o.x, self.y - o.y)

    def __mul__(self, k: float) -> Vec:
        return Vec(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> Vec:
        return Vec(self.x / k, self.y / k)

    def __neg__(self) -> Vec:
        return Vec(-self.x, -self.y)

    def __iter__(self) -> Iterator[float]:
        yield self.x
        yield self.y

    def dot(self, o: Vec) -> float:
        return self.x * o.x + self.y * o.y

    def cross(self, o: Vec) -> float:
        """z-component of self × o: > 0 when ``o`` turns counter-clockwise from ``self``."""
        return self.x * o.y - self.y * o.x

    @property
    def norm(self) -> float:
        return math.hypot(self.x, self.y)

    @property
    def angle(self) -> float:
        """Direction angle in radians, (−π, π], counter-clockwise from +x."""
        return math.atan2(self.y, self.x)

    def unit(self) -> Vec:
        """This vector scaled to length 1; a zero vector is :class:`DegenerateInput`."""
        n = self.norm
        if n == 0.0 or not math.isfinite(n):
            raise DegenerateInput("unit vector", "a zero or non-finite vector has no direction")
        return Vec(self.x / n, self.y / n)

    def perp(self) -> Vec:
        """This vector turned 90° counter-clockwise."""
        return Vec(-self.y, self.x)

    def rotated(self, angle: float) -> Vec:
        """This vector turned by ``angle`` radians counter-clockwise."""
        c, s = math.cos(angle), math.sin(angle)
        return Vec(c * self.x - s * self.y, s * self.x + c * self.y)

    def dist(self, o: Vec) -> float:
        return math.hypot(self.x - o.x, self.y - o.y)

    def array(self) -> npt.NDArray[np.float64]:
        return np.array([self.x, self.y], dtype=np.float64)

    @staticmethod
    def polar(r: float, angle: float) -> Vec:
        return Vec(r * math.cos(angle), r * math.sin(angle))


Point: TypeAlias = Vec
PointLike: TypeAlias = Vec | Sequence[SupportsFloat] | npt.NDArray[np.float64]


def vec(p: PointLike) -> Vec:
    """Loose point input (Vec, tuple, length-2 array) to a :class:`Vec` of floats."""
    if isinstance(p, Vec):
        return p
    x, y = (float(v) for v in p)
    return Vec(x, y)


def almost_equal(a: PointLike, b: PointLike, scale: float = 1.0) -> bool:
    """True when points ``a`` and ``b`` coincide within the length tolerance of ``scale``."""
    return vec(a).dist(vec(b)) <= tol.length_eps(scale)


@dataclass(frozen=True, slots=True)
class Line:
    """An infinite directed line through ``p`` with unit direction ``d``."""

    p: Vec
    d: Vec

    def __post_init__(self) -> None:
        if not math.isclose(self.d.norm, 1.0, rel_tol=tol.DERIVED):
            raise DegenerateInput("line", "the direction must be a unit vector (use Line.of)")

    @staticmethod
    def of(p: PointLike, direction: PointLike) -> Line:
        """The line through ``p`` along ``direction`` (any non-zero length)."""
        return Line(vec(p), vec(direction).unit())

    @staticmethod
    def through(a: PointLike, b: PointLike) -> Line:
        """The line through ``a`` and ``b``, directed from a to b."""
        a, b = vec(a), vec(b)
        if a == b:
            raise DegenerateInput("line through two points", "the points coincide")
        return Line(a, (b - a).unit())

    @staticmethod
    def at_angle(p: PointLike, angle: float) -> Line:
        """The line through ``p`` at ``angle`` radians from +x."""
        return Line(vec(p), Vec(math.cos(angle), math.sin(angle)))

    @property
    def normal(self) -> Vec:
        """The unit normal, the direction turned 90° counter-clockwise (points to the left)."""
        return self.d.perp()

    def at(self, t: float) -> Vec:
        """The point at signed distance ``t`` from ``p`` along the direction."""
        return self.p + self.d * t

    def param(self, q: PointLike) -> float:
        """The signed distance along the line from ``p`` to the foot of ``q``."""
        return (vec(q) - self.p).dot(self.d)

    def side(self, q: PointLike) -> float:
        """Signed distance of ``q`` from the line: > 0 on the left of the direction."""
        return self.d.cross(vec(q) - self.p)

    def foot(self, q: PointLike) -> Vec:
        """The foot of the perpendicular from ``q``."""
        return self.at(self.param(q))


@dataclass(frozen=True, slots=True)
class Ray:
    """A half-line from ``origin`` along the unit direction ``d``."""

    origin: Vec
    d: Vec

    @staticmethod
    def of(origin: PointLike, direction: PointLike) -> Ray:
        return Ray(vec(origin), vec(direction).unit())

    @property
    def line(self) -> Line:
        return Line(self.origin, self.d)


@dataclass(frozen=True, slots=True)
class Segment:
    """The segment from ``a`` to ``b``."""

    a: Vec
    b: Vec

    @staticmethod
    def of(a: PointLike, b: PointLike) -> Segment:
        return Segment(vec(a), vec(b))

    @property
    def length(self) -> float:
        return self.a.dist(self.b)

    @property
    def midpoint(self) -> Vec:
        return (self.a + self.b) * 0.5

    @property
    def line(self) -> Line:
        return Line.through(self.a, self.b)


@dataclass(frozen=True, slots=True)
class Circle:
    """The circle of centre ``c`` and radius ``r`` > 0."""

    c: Vec
    r: float

    def __post_init__(self) -> None:
        if not (self.r > 0.0 and math.isfinite(self.r)):
            raise DegenerateInput("circle", f"the radius must be positive and finite, not {self.r}")

    @staticmethod
    def of(c: PointLike, r: float) -> Circle:
        return Circle(vec(c), float(r))

    def at(self, angle: float) -> Vec:
        """The point of the circle at polar ``angle`` about the centre."""
        return self.c + Vec.polar(self.r, angle)

    def power(self, q: PointLike) -> float:
        """Signed distance of ``q`` from the circle: > 0 outside."""
        return vec(q).dist(self.c) - self.r


@dataclass(frozen=True, slots=True)
class Arc:
    """The arc of ``circle`` from angle ``start`` counter-clockwise to ``end`` (radians)."""

    circle: Circle
    start: float
    end: float

    @property
    def sweep(self) -> float:
        """Counter-clockwise sweep in (0, 2π]."""
        s = math.fmod(self.end - self.start, 2.0 * math.pi)
        return s + 2.0 * math.pi if s <= 0.0 else s

    def contains(self, q: PointLike) -> bool:
        """True when the polar angle of ``q`` about the centre lies on the arc."""
        a = math.fmod((vec(q) - self.circle.c).angle - self.start, 2.0 * math.pi)
        if a < 0.0:
            a += 2.0 * math.pi
        return a <= self.sweep + tol.ANGLE

    @property
    def start_point(self) -> Vec:
        return self.circle.at(self.start)

    @property
    def end_point(self) -> Vec:
        return self.circle.at(self.end)


Primitive: TypeAlias = Vec | Line | Ray | Segment | Circle | Arc
