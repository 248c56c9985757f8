"""Branch rules: how a construction step chooses among the points an intersection yields.

Each rule filters and orders the kernel's candidates and describes itself in words, so that the
protocol says which branch was taken and an empty result says what was asked for. A mechanism
never jumps to the other assembly branch silently: the rule is always explicit.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from geomcad.geom import Arc, Line, PointLike, Vec, vec


class Rule:
    """Base of the branch rules: ``keep`` filters and orders, ``text`` describes the choice."""

    text: str = "any"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        return points


@dataclass(frozen=True)
class Any_(Rule):
    """Keep every point, in the kernel's documented order."""

    text: str = "in the kernel's order"


@dataclass(frozen=True)
class Index(Rule):
    """The kernel's i-th point (see the ordering table in :mod:`geomcad.geom.intersect`)."""

    i: int

    @property
    def text(self) -> str:  # type: ignore[override]
        return f"point {self.i + 1} in the kernel's order"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        return (points[self.i],) if len(points) > self.i else ()


@dataclass(frozen=True)
class LeftOf(Rule):
    """Points strictly on the left of the directed line a → b (``names`` label it in words)."""

    a: Vec
    b: Vec
    names: str = "the line"

    @property
    def text(self) -> str:  # type: ignore[override]
        return f"left of {self.names}"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        line = Line.through(self.a, self.b)
        return tuple(p for p in points if line.side(p) > 0.0)


@dataclass(frozen=True)
class RightOf(Rule):
    """Points strictly on the right of the directed line a → b."""

    a: Vec
    b: Vec
    names: str = "the line"

    @property
    def text(self) -> str:  # type: ignore[override]
        return f"right of {self.names}"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        line = Line.through(self.a, self.b)
        return tuple(p for p in points if line.side(p) < 0.0)


@dataclass(frozen=True)
class Nearest(Rule):
    """Every point, nearest to ``to`` first."""

    to: Vec
    names: str = "the reference point"

    @property
    def text(self) -> str:  # type: ignore[override]
        return f"nearest to {self.names}"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        return tuple(sorted(points, key=lambda p: p.dist(self.to)))


@dataclass(frozen=True)
class OnArc(Rule):
    """Points that lie on ``arc`` (not on the rest of its circle)."""

    arc: Arc
    names: str = "the arc"

    @property
    def text(self) -> str:  # type: ignore[override]
        return f"on {self.names}"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        return tuple(p for p in points if self.arc.contains(p))


@dataclass(frozen=True)
class Where(Rule):
    """Points for which ``predicate`` holds; ``text`` says what it means."""

    predicate: Callable[[Vec], bool]
    text: str = "satisfying the condition"

    def keep(self, points: tuple[Vec, ...]) -> tuple[Vec, ...]:
        return tuple(p for p in points if self.predicate(p))


def left_of(a: PointLike, b: PointLike, names: str = "the line") -> LeftOf:
    """Rule: the point on the left of the directed line a → b."""
    return LeftOf(vec(a), vec(b), names)


def right_of(a: PointLike, b: PointLike, names: str = "the line") -> RightOf:
    """Rule: the point on the right of the directed line a → b."""
    return RightOf(vec(a), vec(b), names)


def nearest(to: PointLike, names: str = "the reference point") -> Nearest:
    """Rule: the point nearest to ``to``."""
    return Nearest(vec(to), names)
