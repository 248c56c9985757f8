"""Force polygons, the three-force theorem and moments, as graphical steps.

A body in (kinetostatic) equilibrium has ΣF = 0: its forces, laid off head to tail at a scale
k_F (N/mm) in the order the equation is written, form a closed polygon. When two of the forces are
known only by their lines of action, the polygon is closed graphically: lay off the known vectors
from the pole, draw a line parallel to the first unknown through the end of the chain and one
parallel to the second unknown through the pole; where they meet is the polygon's missing vertex,
and the two closing sides are the unknown forces, magnitude and sense.

A body under three non-parallel forces has their lines meet in one point (the three-force
theorem): two known lines fix that point, and the third force's line passes through it.

The plan's coordinates are the forces' components in newtons (the plan's own frame: the pole at
``pole``); a sheet places the plan at its scale k_F.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from geomcad import tol
from geomcad.construction import Construction, fmt
from geomcad.errors import DegenerateInput, ParallelLines
from geomcad.geom import Line, PointLike, Vec, line_line, vec


@dataclass(frozen=True, slots=True)
class Known:
    """A force of the equation whose vector is known (N, components in the model's frame)."""

    name: str
    force: Vec


@dataclass(frozen=True, slots=True)
class Unknown:
    """A force known only by the direction of its line of action (either sense will do: the
    polygon's closure gives the magnitude with its sign along ``direction``)."""

    name: str
    direction: Vec


Term = Known | Unknown


@dataclass(frozen=True, slots=True)
class PlanVector:
    """One side of a force polygon: the vector ``name`` from ``tail`` to ``head`` (plan, N)."""

    name: str
    tail: Vec
    head: Vec

    def __str__(self) -> str:
        return f"{self.name} from {fmt(self.tail)} to {fmt(self.head)}, |{self.name}| = " + (
            f"{self.magnitude:.6f}"
        )

    @property
    def force(self) -> Vec:
        return self.head - self.tail

    @property
    def magnitude(self) -> float:
        return self.force.norm


@dataclass(frozen=True)
class ForcePolygon:
    """A closed force polygon: the pole, the vectors head to tail in the order of ΣF = 0, and
    the signed magnitudes found for the unknowns along their given directions (> 0: the sense
    assumed, < 0: the opposite one)."""

    pole: Vec
    vectors: tuple[PlanVector, ...]
    solved: tuple[tuple[str, float], ...]

    def __str__(self) -> str:
        return f"{' → '.join(self.names)} from {fmt(self.pole)}, |ΣF| = {self.closure:.3g}"

    def __getitem__(self, name: str) -> PlanVector:
        for v in self.vectors:
            if v.name == name:
                return v
        raise KeyError(f"no vector {name!r} in the polygon ({', '.join(self.names)})")

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(v.name for v in self.vectors)

    def signed(self, name: str) -> float:
        """The signed magnitude of unknown ``name`` along the direction it was given."""
        return dict(self.solved)[name]

    @property
    def closure(self) -> float:
        """|ΣF| of the polygon's vectors: zero, up to rounding, for a closed polygon (N)."""
        total = Vec(0.0, 0.0)
        for v in self.vectors:
            total = total + v.force
        return total.norm

    def diagonal(self, first: str, last: str, name: str) -> PlanVector:
        """The partial sum of the vectors from ``first`` to ``last`` (consecutive in the
        polygon) as the diagonal from the tail of ``first`` to the head of ``last``."""
        return PlanVector(name, self[first].tail, self[last].head)


def _split(terms: Sequence[Term]) -> tuple[int, int]:
    idx = [i for i, t in enumerate(terms) if isinstance(t, Unknown)]
    if len(idx) != 2:
        raise DegenerateInput(
            "force polygon",
            f"closing a polygon finds exactly two unknown magnitudes, not {len(idx)}",
        )
    return idx[0], idx[1]


def _sum(terms: Sequence[Term]) -> Vec:
    total = Vec(0.0, 0.0)
    for t in terms:
        if isinstance(t, Known):
            total = total + t.force
    return total


def closing_lines(terms: Sequence[Term], pole: PointLike = (0.0, 0.0)) -> tuple[Line, Line]:
    """The two lines whose meeting point closes the polygon: parallel to the first unknown
    through the end of the chain of known vectors that precede and follow it, and parallel to
    the second unknown through the point from which the known vectors after it lead back to the
    pole. With the unknowns last, these are the lines through the chain's end and the pole."""
    i, j = _split(terms)
    o = vec(pole)
    u1, u2 = (terms[k] for k in (i, j))
    assert isinstance(u1, Unknown) and isinstance(u2, Unknown)
    start1 = o + _sum(terms[:i]) + _sum(terms[i + 1 : j])
    start2 = o - _sum(terms[j + 1 :])
    return Line.of(start1, u1.direction), Line.of(start2, u2.direction)


def _assemble(terms: Sequence[Term], pole: Vec, z: Vec) -> ForcePolygon:
    """The polygon's vectors once the closing vertex ``z`` (tail of the second unknown) is
    known."""
    i, j = _split(terms)
    l1, l2 = closing_lines(terms, pole)
    a = l1.param(z)  # along the first unknown's direction, from the chain's end
    b = -l2.param(z)  # the second unknown runs from z to the line's start
    size = {i: a, j: b}
    vectors: list[PlanVector] = []
    at = pole
    solved: list[tuple[str, float]] = []
    for k, t in enumerate(terms):
        if isinstance(t, Known):
            f = t.force
        else:
            f = t.direction.unit() * size[k]
            solved.append((t.name, size[k]))
        vectors.append(PlanVector(t.name, at, at + f))
        at = at + f
    # the last head is the pole again (exactly, up to rounding)
    return ForcePolygon(pole, tuple(vectors), tuple(solved))


def close_polygon(terms: Sequence[Term], pole: PointLike = (0.0, 0.0)) -> ForcePolygon:
    """Close the force polygon of ΣF = 0 written in the order of ``terms`` (exactly two of them
    :class:`Unknown`). Raises :class:`ParallelLines` when the unknowns' lines are parallel
    (their magnitudes are then not fixed by ΣF = 0 alone).

    >>> p = close_polygon([Known("G", Vec(0, -10)), Unknown("R1", Vec(1, 1)),
    ...                    Unknown("R2", Vec(-1, 1))])
    >>> round(p.signed("R1"), 6), round(p.signed("R2"), 6), round(p.closure, 9)
    (7.071068, 7.071068, 0.0)
    """
    l1, l2 = closing_lines(terms, pole)
    meet = line_line(l1, l2)
    if not meet:
        raise ParallelLines("force polygon", "the two unknown forces are parallel")
    return _assemble(terms, vec(pole), meet[0])


def force_polygon(
    c: Construction,
    name: str,
    terms: Sequence[Term],
    pole: PointLike = (0.0, 0.0),
    equation: str = "",
    words: Mapping[str, str] | None = None,
) -> ForcePolygon:
    """Close the force polygon of ``terms`` as recorded steps of ``c``.

    Records: the two closing lines (``name: ∥ U``), their intersection (``name: closing
    vertex``; a :class:`ParallelLines` error names it), every side of the polygon as a segment
    (``name: F``), the signed magnitude of each unknown (``name: |U|``, a value) and the polygon
    itself (``name``, of kind ``force_polygon`` for the order of construction: its operands the
    equation ``eq`` as label markup, the unknowns ``a``, ``b`` and their magnitudes ``Fa``,
    ``Fb``). ``equation`` is ΣF = 0 in words, for the protocol; ``words`` gives the terms'
    names as label markup where they are not (``R_32`` → ``R_{32}``).
    """
    o = vec(pole)
    l1, l2 = closing_lines(terms, o)
    i, j = _split(terms)
    n1, n2 = terms[i].name, terms[j].name
    eq = equation or " + ".join(t.name for t in terms) + " = 0"
    c.record(f"{name}: ∥ {n1}", f"line ∥ {n1} through the end of the known vectors", l1)
    c.record(f"{name}: ∥ {n2}", f"line ∥ {n2} through the start of the known vectors", l2)
    z = c.intersect(
        f"{name}: closing vertex",
        l1,
        l2,
        op=f"line ∥ {n1} ∩ line ∥ {n2} (closing {eq})",
    )
    poly = _assemble(terms, o, z)
    for v in poly.vectors:
        c.record(f"{name}: {v.name}", f"plan vector {v.name}", v, role="hidden")
    for n, value in poly.solved:
        c.value(f"{name}: |{n}|", value, f"closing side of {name}, signed along the assumed sense")
    mark = dict(words or {})
    names = [mark.get(t.name, t.name) for t in terms]
    # a magnitude at the level of rounding (a force the equation makes zero) is written as 0
    size = max((v.force.norm for v in poly.vectors), default=0.0)
    solved = {n: (0.0 if abs(x) <= tol.REL_LENGTH * size else x) for n, x in poly.solved}
    return c.record(
        name,
        f"force polygon {eq}, head to tail from the pole",
        poly,
        role="hidden",
        kind="force_polygon",
        args={
            "eq": " + ".join(names) + " = 0",
            "a": mark.get(n1, n1),
            "b": mark.get(n2, n2),
            "Fa": abs(solved[n1]),
            "Fb": abs(solved[n2]),
        },
    )


def three_force_point(line1: Line, line2: Line) -> Vec:
    """The three-force theorem: the point where the lines of two of three forces in equilibrium
    meet; the third force's line passes through it. Parallel lines are :class:`ParallelLines`."""
    meet = line_line(line1, line2)
    if not meet:
        raise ParallelLines(
            "three-force theorem", "the two lines are parallel, so they fix no point of concurrency"
        )
    return meet[0]


def moment(about: PointLike, line: Line, magnitude: float) -> float:
    """The moment (N·m, ccw > 0) about a point of a force of signed ``magnitude`` along the
    directed ``line``."""
    return (line.p - vec(about)).cross(line.d) * magnitude


def inclination_to_horizontal(direction: PointLike) -> float:
    """The acute angle (rad, in [0, π/2]) between a line of the given direction and the
    horizontal."""
    d = vec(direction)
    if d.norm == 0.0 or not math.isfinite(d.norm):
        raise DegenerateInput("inclination", "a zero vector has no direction")
    return math.atan2(abs(d.y), abs(d.x))
