"""The step recorder: a graphical solution as a list of named, exact steps.

Every step runs its geometric operation itself and stores its name, the operation in words, the
names of its inputs, the result, the result's role on the drawing and an optional note. The
answers of a problem are recorded results; the sheet draws and labels the steps; an error names
the step that failed.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, TypeVar

from geomcad.construction.branch import Any_, Index, Rule
from geomcad.construction.guard import is_numeric, watch, why
from geomcad.errors import ConstructionError, NoIntersection, ParallelLines
from geomcad.geom import (
    Arc,
    Circle,
    Line,
    PointLike,
    Ray,
    Segment,
    Vec,
    angle_arcs,
    circle_circle,
    circle_through,
    line_circle,
    line_line,
    parallel,
    perpendicular,
    ray_at_angle,
    vec,
)

T = TypeVar("T")
Obj = Line | Circle

#: Roles a step can have on the drawing. ``hidden`` steps are recorded but not drawn.
ROLES = ("given", "construction", "result", "link", "extreme", "aux", "hidden")


@dataclass(frozen=True)
class Step:
    """One recorded step: ``name = op`` with its result and drawing role."""

    index: int
    name: str
    op: str
    inputs: tuple[str, ...]
    result: Any
    role: str
    note: str = ""
    rule: str = ""
    #: what the step does, for the order of construction: a template key (``intersection``,
    #: ``circle``, a problem's own ``cross``); "" for a step no template describes
    kind: str = ""
    #: the template's operands: object names (``B0B1``) or numbers, by the template's field names
    args: tuple[tuple[str, str | float], ...] = ()

    @property
    def title(self) -> str:
        """The step as it is named in errors and in the protocol: ``name = op``."""
        return f"{self.name} = {self.op}"


def fmt(value: Any) -> str:
    """A step result in words for the protocol."""
    if isinstance(value, Vec):
        return f"({value.x:.6f}, {value.y:.6f})"
    if isinstance(value, Line):
        return f"line through {fmt(value.p)} at {math.degrees(value.d.angle):.6f}°"
    if isinstance(value, Ray):
        return f"ray from {fmt(value.origin)} at {math.degrees(value.d.angle):.6f}°"
    if isinstance(value, Segment):
        return f"segment {fmt(value.a)}–{fmt(value.b)}, length {value.length:.6f}"
    if isinstance(value, Circle):
        return f"circle centre {fmt(value.c)}, r = {value.r:.6f}"
    if isinstance(value, Arc):
        start, sweep = math.degrees(value.start), math.degrees(value.sweep)
        return f"arc of {fmt(value.circle)} from {start:.3f}° ccw {sweep:.3f}°"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, float):
        return f"{value:.9g}"
    if isinstance(value, tuple):
        return "[" + "; ".join(fmt(v) for v in value) + "]" if value else "none"
    return str(value)


def _kind(obj: object) -> str:
    return {Line: "line", Circle: "circle", Ray: "ray", Segment: "segment"}.get(type(obj), "object")


class Construction:
    """A recorded graphical construction.

    >>> from geomcad.geom import Circle
    >>> c = Construction("demo")
    >>> A = c.point("A", (0, 0))
    >>> k = c.circle("k", A, 1.0)
    >>> m = c.circle("m", c.point("B", (1, 0)), 1.0)
    >>> P = c.intersect("P", k, m)
    >>> c["P"] == P
    True
    >>> print(c.trace().splitlines()[-1])
    5. P = circle k ∩ circle m, point 1 in the kernel's order → (0.500000, 0.866025)
    """

    def __init__(self, title: str) -> None:
        self.title = title
        self.steps: list[Step] = []
        self._by_name: dict[str, Step] = {}
        self._names: dict[Any, str] = {}
        watch(self)

    # -- bookkeeping ---------------------------------------------------------------------------
    def __getitem__(self, name: str) -> Any:
        return self._by_name[name].result

    def __contains__(self, name: str) -> bool:
        return name in self._by_name

    def __iter__(self) -> Iterator[Step]:
        return iter(self.steps)

    def step(self, name: str) -> Step:
        """The recorded step called ``name``."""
        return self._by_name[name]

    def name_of(self, obj: object) -> str:
        """The name a recorded object was given, or its value in words."""
        try:
            return self._names.get(obj, fmt(obj))
        except TypeError:  # unhashable
            return fmt(obj)

    def record(
        self,
        name: str,
        op: str,
        result: T,
        inputs: Sequence[object] = (),
        role: str = "construction",
        note: str = "",
        rule: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> T:
        """Store a step whose result was computed by the caller; return the result.

        ``kind`` and ``args`` say what the step does in a structured form, for the order of
        construction a sheet writes from the steps (a template per kind and language); an
        argument that is a recorded object is stored by its name, a number as a float."""
        if role not in ROLES:
            raise ValueError(f"unknown role {role!r}; roles are {', '.join(ROLES)}")
        if name in self._by_name:
            raise ValueError(f"step name {name!r} is used twice in {self.title}")
        s = Step(
            len(self.steps) + 1,
            name,
            op,
            tuple(i if isinstance(i, str) else self.name_of(i) for i in inputs),
            result,
            role,
            note,
            rule,
            kind,
            self._args(args or {}),
        )
        self.steps.append(s)
        self._by_name[name] = s
        with contextlib.suppress(TypeError):  # unhashable results keep no name
            self._names.setdefault(result, name)
        return result

    def _args(self, args: Mapping[str, object]) -> tuple[tuple[str, str | float], ...]:
        out: list[tuple[str, str | float]] = []
        for k, v in args.items():
            if isinstance(v, bool) or not isinstance(v, (int, float, str)):
                out.append((k, self.name_of(v)))
            else:
                out.append((k, v if isinstance(v, str) else float(v)))
        return tuple(out)

    def run(
        self,
        name: str,
        op: str,
        fn: Callable[[], T],
        inputs: Sequence[object] = (),
        role: str = "construction",
        note: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> T:
        """Run ``fn`` as step ``name``; renames a :class:`ConstructionError` to the step."""
        title = f"{name} = {op}"
        try:
            result = fn()
        except ConstructionError as exc:
            raise type(exc)(title, exc.why) from None
        except Exception as exc:
            if not is_numeric(exc):
                raise
            raise ConstructionError(title, why(exc)) from exc
        return self.record(name, op, result, inputs, role, note, kind=kind, args=args)

    # -- the verbs -----------------------------------------------------------------------------
    # Each verb records its kind and operands (``kind``/``args`` of :class:`Step`); a caller that
    # words its own operation (``op``) says what it is by its own ``kind`` and ``args``.
    def point(
        self,
        name: str,
        p: PointLike,
        role: str = "given",
        note: str = "",
        op: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> Vec:
        """A given (or computed-elsewhere) point."""
        v = vec(p)
        kind = kind or ("" if op else "given")
        return self.record(name, op or "given", v, (), role, note, kind=kind, args=args)

    def value(
        self,
        name: str,
        x: float,
        op: str,
        inputs: Sequence[object] = (),
        note: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> float:
        """A number the construction measures or computes (a length, an angle)."""
        return self.record(name, op, float(x), inputs, "hidden", note, kind=kind, args=args)

    def segment(
        self, name: str, a: Vec, b: Vec, role: str = "construction", note: str = ""
    ) -> Segment:
        """The segment between two recorded points."""
        return self.record(
            name,
            f"segment {self.name_of(a)}{self.name_of(b)}",
            Segment(a, b),
            (a, b),
            role,
            note,
            kind="segment",
            args={"a": a, "b": b},
        )

    def line_through(
        self, name: str, a: Vec, b: Vec, role: str = "construction", note: str = ""
    ) -> Line:
        """The line through two points, directed from a to b."""
        op = f"line {self.name_of(a)}{self.name_of(b)}"
        return self.run(
            name,
            op,
            lambda: Line.through(a, b),
            (a, b),
            role,
            note,
            kind="line",
            args={"a": a, "b": b},
        )

    def line(
        self,
        name: str,
        p: Vec,
        direction: PointLike,
        op: str,
        role: str = "construction",
        note: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> Line:
        """A line through ``p`` along ``direction``, described by ``op``."""
        return self.run(
            name, op, lambda: Line.of(p, direction), (p,), role, note, kind=kind, args=args
        )

    def circle(
        self,
        name: str,
        centre: Vec,
        r: float,
        role: str = "construction",
        note: str = "",
        r_name: str = "",
    ) -> Circle:
        """The circle about a recorded centre (its radius named ``r_name`` in the words)."""
        op = f"circle({self.name_of(centre)}, {r_name or fmt(float(r))})"
        return self.run(
            name,
            op,
            lambda: Circle(centre, float(r)),
            (centre,),
            role,
            note,
            kind="circle",
            args={"c": centre, "r": r_name or float(r)},
        )

    def perpendicular(
        self, name: str, line: Line, through: Vec, role: str = "construction", note: str = ""
    ) -> Line:
        """The perpendicular to a line through a point."""
        op = f"perpendicular to {self.name_of(line)} at {self.name_of(through)}"
        return self.record(
            name,
            op,
            perpendicular(line, through),
            (line, through),
            role,
            note,
            kind="perpendicular",
            args={"line": line, "p": through},
        )

    def parallel(
        self,
        name: str,
        line: Line,
        through: Vec | None = None,
        offset: float = 0.0,
        role: str = "construction",
        note: str = "",
        op: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> Line:
        """The parallel to a line through a point, or at a signed offset (left > 0)."""
        where = f"through {self.name_of(through)}" if through is not None else f"at {fmt(offset)}"
        if not kind:
            kind = "parallel" if through is not None else "parallel_at"
            args = {"line": line, "p": through} if through is not None else {"line": line}
            if through is None:
                args["d"] = abs(offset)
        op = op or f"parallel to {self.name_of(line)} {where}"
        return self.record(
            name,
            op,
            parallel(line, through, offset),
            (line,),
            role,
            note,
            kind=kind,
            args=args,
        )

    def ray_at_angle(
        self,
        name: str,
        origin: Vec,
        toward: Vec,
        angle: float,
        angle_text: str = "",
        role: str = "construction",
        note: str = "",
    ) -> Line:
        """The line from ``origin`` at ``angle`` (ccw > 0) to the direction origin → toward."""
        a = angle_text or f"{math.degrees(angle):.6g}°"
        o, t = self.name_of(origin), self.name_of(toward)
        op = f"ray from {o} at {a} to {o}{t}"
        return self.run(
            name,
            op,
            lambda: ray_at_angle(origin, toward, angle),
            (origin, toward),
            role,
            note,
            kind="ray",
            args={"o": origin, "t": toward, "angle": angle_text or f"{math.degrees(angle):.4g}°"},
        )

    def circle_through(
        self, name: str, a: Vec, b: Vec, c: Vec, role: str = "construction", note: str = ""
    ) -> Circle:
        """The circle through three recorded points."""
        op = f"circle({self.name_of(a)}, {self.name_of(b)}, {self.name_of(c)})"
        return self.run(
            name,
            op,
            lambda: circle_through(a, b, c),
            (a, b, c),
            role,
            note,
            kind="circle3",
            args={"a": a, "b": b, "c": c},
        )

    def angle_arcs(
        self,
        name: str,
        a: Vec,
        b: Vec,
        angle: float,
        angle_text: str = "",
        role: str = "construction",
        note: str = "",
    ) -> tuple[Arc, Arc]:
        """The two arcs that see chord ab under ``angle``: (left of a → b, right)."""
        a_t = angle_text or f"{math.degrees(angle):.6g}°"
        op = f"arcs seeing {self.name_of(a)}{self.name_of(b)} under {a_t}"
        return self.run(
            name,
            op,
            lambda: angle_arcs(a, b, angle),
            (a, b),
            role,
            note,
            kind="arcs",
            args={"a": a, "b": b, "angle": angle_text or f"{math.degrees(angle):.4g}°"},
        )

    def intersections(
        self,
        name: str,
        o1: Obj,
        o2: Obj,
        rule: Rule | None = None,
        role: str = "construction",
        note: str = "",
        op: str = "",
        allow_empty: bool = False,
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> tuple[Vec, ...]:
        """All intersection points of two objects that ``rule`` keeps (kernel order by default).

        An empty result is :class:`NoIntersection` (or :class:`ParallelLines`) naming the step,
        unless ``allow_empty``.
        """
        rule = rule or Any_()
        op, kept = self._meet(name, o1, o2, rule, op, allow_empty)
        kind, args = (kind, args) if kind else ("intersection", {"a": o1, "b": o2})
        return self.record(name, op, kept, (o1, o2), role, note, rule.text, kind, args)

    def intersect(
        self,
        name: str,
        o1: Obj,
        o2: Obj,
        rule: Rule | None = None,
        role: str = "construction",
        note: str = "",
        op: str = "",
        kind: str = "",
        args: Mapping[str, object] | None = None,
    ) -> Vec:
        """The one intersection point of two objects that ``rule`` picks (the first it keeps)."""
        rule = rule or Index(0)
        op, kept = self._meet(name, o1, o2, rule, op, False)
        kind, args = (kind, args) if kind else ("intersection", {"a": o1, "b": o2})
        return self.record(name, op, kept[0], (o1, o2), role, note, rule.text, kind, args)

    def _meet(
        self, name: str, o1: Obj, o2: Obj, rule: Rule, op: str, allow_empty: bool
    ) -> tuple[str, tuple[Vec, ...]]:
        op = op or f"{_kind(o1)} {self.name_of(o1)} ∩ {_kind(o2)} {self.name_of(o2)}"
        title = f"{name} = {op}"
        try:
            raw = _intersect(o1, o2)
        except ConstructionError as exc:
            raise type(exc)(title, exc.why) from None
        except Exception as exc:
            if not is_numeric(exc):
                raise
            raise ConstructionError(title, why(exc)) from exc
        kept = rule.keep(raw)
        if not kept and not allow_empty:
            if isinstance(o1, Line) and isinstance(o2, Line):
                raise ParallelLines(title, "the lines are parallel")
            if not raw:
                raise NoIntersection(title, _miss(o1, o2))
            raise NoIntersection(title, f"no intersection point is {rule.text}")
        return op, kept

    # -- the protocol --------------------------------------------------------------------------
    def trace(self) -> str:
        """The construction protocol: one line per step, ``n. name = op, rule → result — note``."""
        lines = [f"Construction: {self.title}"]
        for s in self.steps:
            rule = f", {s.rule}" if s.rule else ""
            note = f" — {s.note}" if s.note else ""
            lines.append(f"{s.index}. {s.name} = {s.op}{rule} → {fmt(s.result)}{note}")
        return "\n".join(lines)


def _intersect(o1: Obj, o2: Obj) -> tuple[Vec, ...]:
    if isinstance(o1, Line) and isinstance(o2, Line):
        return line_line(o1, o2)
    if isinstance(o1, Line) and isinstance(o2, Circle):
        return line_circle(o1, o2)
    if isinstance(o1, Circle) and isinstance(o2, Line):
        return line_circle(o2, o1)
    if isinstance(o1, Circle) and isinstance(o2, Circle):
        return circle_circle(o1, o2)
    raise TypeError(f"cannot intersect {type(o1).__name__} with {type(o2).__name__}")


def _miss(o1: Obj, o2: Obj) -> str:
    if isinstance(o1, Circle) and isinstance(o2, Circle):
        d = o1.c.dist(o2.c)
        return (
            f"the circles do not meet: their centres are {d:.6g} apart, "
            f"their radii {o1.r:.6g} and {o2.r:.6g}"
        )
    circle = o1 if isinstance(o1, Circle) else o2
    line = o2 if isinstance(o1, Circle) else o1
    if isinstance(circle, Circle) and isinstance(line, Line):
        h = abs(line.side(circle.c))
        return (
            f"the line misses the circle: it passes {h:.6g} from the centre, "
            f"the radius is {circle.r:.6g}"
        )
    return "the objects do not meet"
