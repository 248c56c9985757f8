"""Velocity and acceleration plans built from vector equations, as recorded constructions.

TMM finds a mechanism's velocities by drawing a **plan**: from a pole p, each point's velocity is
a vector pb, and each vector equation such as

    V_B = V_A + V_BA (⊥ AB)  =  V_O2 + V_BO2 (⊥ O2B)

is solved by drawing two lines of known direction, one through the end of each known part, and
intersecting them. Accelerations are done the same way on a second plan (pole π), where the known
parts are the normal components ω²·l (from B towards A) and the Coriolis components 2ω × V_rel,
and the unknown ones are tangential (⊥ the link) or relative (∥ the guide).

A :class:`Plan` keeps its points in plan units (m/s, m/s²) with the pole at the origin, records
every point, line and vector as a named step of a :class:`~geomcad.construction.Construction`, and
remembers what to draw: the construction lines (:attr:`Plan.lines`) and the vectors
(:attr:`Plan.vectors`). The plan on the sheet therefore *is* the solution.

    >>> from geomcad.construction import Construction
    >>> from geomcad.geom import Vec
    >>> c = Construction("four-bar")
    >>> A, B, O2 = Vec(0.0, 0.1), Vec(0.3, 0.2), Vec(0.4, 0.0)
    >>> vp = velocity_plan(c)
    >>> a = vp.given("a", Vec(-1.0, 0.0), "V_A")
    >>> o2 = vp.fixed("o2")
    >>> b = vp.solve("b", Side("a", B - A, "⊥ AB", perpendicular=True),
    ...              Side("o2", B - O2, "⊥ O2B", perpendicular=True))
    >>> round(vp.omega(A, B, "a", "b"), 6)
    -1.428571
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import DegenerateInput
from geomcad.geom import Line, Vec

Kind = Literal["v", "a"]

_POLE = {"v": "p", "a": "π"}
_WHAT = {"v": "velocity", "a": "acceleration"}


@dataclass(frozen=True)
class Term:
    """A known vector of a vector equation: its value in plan units, the name of the plan point
    at its head (a step name, e.g. ``n_BA``), its label markup (``a^n_{BA}``) and its meaning."""

    value: Vec
    head: str
    label: str
    meaning: str


@dataclass(frozen=True)
class Side:
    """One side of a vector equation: start at plan point ``start``, add the known ``terms``
    head to tail, then an unknown vector along (or, with ``perpendicular``, at right angles to)
    the model direction ``direction``; ``text`` says which (``⊥ AB``, ``∥ O1B``)."""

    start: str
    direction: Vec
    text: str
    perpendicular: bool = False
    terms: tuple[Term, ...] = ()


@dataclass(frozen=True)
class PlanLine:
    """A construction line of the plan: through plan point ``through`` along ``line``."""

    step: str
    through: str
    line: Line
    text: str


@dataclass(frozen=True)
class PlanVector:
    """A vector of the plan from point ``tail`` to point ``head`` (both plan point names)."""

    step: str
    tail: str
    head: str
    label: str
    meaning: str
    known: bool


@dataclass
class Plan:
    """A velocity (``kind`` ``v``) or acceleration (``a``) plan being built in ``c``.

    ``suffix`` is appended to every step name of the plan's points (``b'`` on an acceleration
    plan drawn beside a velocity plan), so that both can live in one construction.
    """

    c: Construction
    kind: Kind
    suffix: str = ""
    points: dict[str, Vec] = field(default_factory=dict)
    lines: list[PlanLine] = field(default_factory=list)
    vectors: list[PlanVector] = field(default_factory=list)

    def __post_init__(self) -> None:
        pole = self.pole
        self.points[pole] = self.c.point(
            pole, (0.0, 0.0), role="construction", op=f"the pole of the {_WHAT[self.kind]} plan"
        )

    # -- names -----------------------------------------------------------------------------
    @property
    def pole(self) -> str:
        return _POLE[self.kind]

    def name(self, point: str) -> str:
        """The step name of a plan point (the pole keeps its own)."""
        return point if point == self.pole else point + self.suffix

    def __getitem__(self, point: str) -> Vec:
        """A plan point (m/s or m/s² from the pole)."""
        return self.points[self.name(point)]

    def vector(self, point: str) -> Vec:
        """The absolute velocity (acceleration) of a point: pole → point."""
        return self[point]

    def between(self, tail: str, head: str) -> Vec:
        """A relative velocity (acceleration): the plan vector from ``tail`` to ``head``."""
        return self[head] - self[tail]

    def _add(self, point: str, value: Vec, op: str) -> Vec:
        name = self.name(point)
        v = self.c.point(name, value, role="construction", op=op)
        self.points[name] = v
        return v

    def _vec(self, tail: str, head: str, label: str, meaning: str, known: bool) -> None:
        t, h = self.name(tail), self.name(head)
        step = f"{t}{h}"
        value = self.points[h] - self.points[t]
        self.c.record(step, f"vector {t} → {h} = {meaning}", value, (t, h), "construction")
        self.vectors.append(PlanVector(step, t, h, label, meaning, known))

    # -- known points --------------------------------------------------------------------------
    def fixed(self, point: str) -> Vec:
        """A point of the frame (or of a link at rest): it lies at the pole."""
        return self._add(point, Vec(0.0, 0.0), f"at the pole ({point} is fixed)")

    def given(self, point: str, value: Vec, label: str, meaning: str = "") -> Vec:
        """A known vector from the pole (``pa = V_A``)."""
        self._add(point, value, f"given {label}")
        self._vec(self.pole, point, label, meaning or label, True)
        return self[point]

    def same(self, point: str, as_: str, why: str) -> Vec:
        """A point that coincides with another one (a translating link, a hinged block)."""
        return self._add(point, self[as_], f"= {self.name(as_)} ({why})")

    def rigid(
        self, point: str, base: str, base_pos: Vec, pos: Vec, omega: float, label: str, why: str
    ) -> Vec:
        """A point of a link that turns at ``omega``: V_P = V_base + ω × (P − base)."""
        r = pos - base_pos
        self._add(point, self[base] + Vec(-r.y, r.x) * omega, f"{self.name(base)} + ω × r ({why})")
        self._vec(base, point, label, f"ω × r ({why})", True)
        return self[point]

    def rigid_acc(
        self,
        point: str,
        base: str,
        base_pos: Vec,
        pos: Vec,
        omega: float,
        eps: float,
        label: str,
        why: str,
    ) -> Vec:
        """A point of a link that turns at ``omega`` with ``eps`` on an acceleration plan:
        a_P = a_base + ε × r − ω²·r, r = P − base."""
        r = pos - base_pos
        value = self[base] + Vec(-r.y, r.x) * eps - r * (omega * omega)
        self._add(point, value, f"{self.name(base)} + ε × r − ω²·r ({why})")
        self._vec(base, point, label, f"ε × r − ω²·r ({why})", True)
        return self[point]

    def image(
        self, point: str, a: str, b: str, A: Vec, B: Vec, P: Vec, label: str = "", why: str = ""
    ) -> Vec:
        """The image of point P of a link whose points A and B are on the plan as ``a``, ``b``:
        the triangle abp is similar to ABP and turned the same way (the theorem of similarity).

        Raises :class:`DegenerateInput` when A and B coincide.
        """
        ab, AB = self.between(a, b), B - A
        L2 = AB.dot(AB)
        if (tol.REL_LENGTH * max(A.norm, B.norm, 1.0)) ** 2 >= L2:
            raise DegenerateInput(f"{self.name(point)} = image of {point}", "A and B coincide")
        # the complex ratio ab / AB maps the link onto its image
        re = (ab.x * AB.x + ab.y * AB.y) / L2
        im = (ab.y * AB.x - ab.x * AB.y) / L2
        r = P - A
        value = self[a] + Vec(re * r.x - im * r.y, re * r.y + im * r.x)
        op = f"image of {point}: triangle {self.name(a)}{self.name(b)}{self.name(point)} ~ link"
        self._add(point, value, op + (f" ({why})" if why else ""))
        if label:
            self._vec(a, point, label, why or label, True)
        return self[point]

    # -- vector equations ------------------------------------------------------------------
    def solve(self, point: str, first: Side, second: Side) -> Vec:
        """The plan point of a vector equation with two unknown magnitudes.

        Each side starts at a known plan point, adds its known terms head to tail (each a
        recorded point and vector), and draws the line of its unknown vector through the end;
        the two lines meet in the new point. Parallel lines (a dead position, a guide along the
        link) raise :class:`~geomcad.errors.ParallelLines` naming the step.
        """
        name = self.name(point)
        lines: list[Line] = []
        for side_no, side in enumerate((first, second), start=1):
            tail = side.start
            for term in side.terms:
                self._add(term.head, self[tail] + term.value, f"{self.name(tail)} + {term.meaning}")
                self._vec(tail, term.head, term.label, term.meaning, True)
                tail = term.head
            d = side.direction.unit()
            if side.perpendicular:
                d = Vec(-d.y, d.x)
            step = f"{name}:{side_no}"
            through = self.name(tail)
            line = self.c.line(step, self[tail], d, f"line through {through} {side.text}")
            self.lines.append(PlanLine(step, through, line, side.text))
            lines.append(line)
        v = self.c.intersect(name, lines[0], lines[1], role="construction")
        self.points[name] = v
        return v

    def unknown(self, tail: str, head: str, label: str, meaning: str) -> Vec:
        """Record a vector the plan has found (``ab = V_BA``) and return it."""
        self._vec(tail, head, label, meaning, False)
        return self.between(tail, head)

    def absolute(self, point: str, label: str, meaning: str = "") -> Vec:
        """Record the absolute vector pole → point (``pb = V_B``) and return it."""
        self._vec(self.pole, point, label, meaning or label, False)
        return self[point]

    # -- reading the plan ----------------------------------------------------------------------
    def omega(self, A: Vec, B: Vec, a: str, b: str) -> float:
        """The angular velocity (acceleration) of link AB read off the plan, ccw > 0.

        On a velocity plan: ω = (AB × ab)/AB², i.e. ω = |ab|/l_AB with the sense that turns
        AB towards ab. On an acceleration plan pass the tangential vector's ends: ε = a^τ/l.
        """
        AB = B - A
        return AB.cross(self.between(a, b)) / AB.dot(AB)

    def extent(self) -> tuple[float, float, float, float]:
        """The plan's bounding box (x0, y0, x1, y1) in plan units, pole included."""
        xs = [p.x for p in self.points.values()]
        ys = [p.y for p in self.points.values()]
        return (min(xs), min(ys), max(xs), max(ys))


def velocity_plan(c: Construction, suffix: str = "") -> Plan:
    """A new velocity plan in ``c``, pole p at the origin."""
    return Plan(c, "v", suffix)


def acceleration_plan(c: Construction, suffix: str = "'") -> Plan:
    """A new acceleration plan in ``c``, pole π at the origin; its points are named ``b'``."""
    return Plan(c, "a", suffix)


def normal(omega: float, B: Vec, A: Vec, head: str, label: str, meaning: str) -> Term:
    """The normal acceleration of B about A: ω²·l_AB, directed from B to A."""
    return Term((A - B) * (omega * omega), head, label, meaning)


def coriolis(omega: float, v_rel: Vec, head: str, label: str, meaning: str) -> Term:
    """The Coriolis acceleration 2ω × V_rel: V_rel turned 90° in the sense of ω, times 2|ω|."""
    return Term(Vec(-v_rel.y, v_rel.x) * (2.0 * omega), head, label, meaning)
