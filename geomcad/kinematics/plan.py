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

import math
import re as _re
import sys
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
    #: the order of construction's kind and operands of the term (:func:`normal`,
    #: :func:`coriolis`; ``plan_term`` for a term given by its value)
    kind: str = "plan_term"
    args: tuple[tuple[str, str | float], ...] = ()


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
    #: the model line the unknown vector is perpendicular or parallel to, for the order of
    #: construction: a run of point names (``O1B``) or ``@word`` (``@guide``: a word of the
    #: sheet's table); "" = ``text`` without its sign and remark
    line: str = ""
    #: the unknown vector's label markup; "" = the relative vector of the point about ``start``
    #: (``V_{BA}``; ``a^τ_{BA}`` across a line, ``a^r_{BA}`` along one)
    unknown: str = ""


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

    Every step carries a ``kind`` and ``args`` for the order of construction (templates
    ``step.plan_*`` in ``geomcad/sheet/strings/<lang>/views.toml``): the plan's points, the
    known terms, the vector equations, the vectors read off and the angular velocities.
    :attr:`order` names the steps a sheet's order of construction lists (in recorded order),
    :attr:`values` the vectors read off the plan (``V_B = pb·μ_V``).
    """

    c: Construction
    kind: Kind
    suffix: str = ""
    points: dict[str, Vec] = field(default_factory=dict)
    lines: list[PlanLine] = field(default_factory=list)
    vectors: list[PlanVector] = field(default_factory=list)
    order: list[str] = field(default_factory=list)
    values: list[str] = field(default_factory=list)
    #: the step names of the fixed points (at the pole)
    at_pole: set[str] = field(default_factory=set)
    #: the points found by similarity: (a, b, point), the image triangle of a link's points
    images: list[tuple[str, str, str]] = field(default_factory=list)
    #: an acceleration plan's velocity plan: the size against which a relative velocity
    #: (of a Coriolis term) is rounding noise
    velocity: Plan | None = None
    #: the mechanism point of a plan point whose name is not its letter lower-cased (the image
    #: ``p2`` of point P of link 2, where p is the pole): plan name → mechanism name
    models: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        pole = self.pole
        self.points[pole] = self.c.point(
            pole,
            (0.0, 0.0),
            role="construction",
            op=f"the pole of the {_WHAT[self.kind]} plan",
            kind="plan_pole",
            args={"plan": f"@plan_{self.kind}"},
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

    def mark(self, point: str) -> str:
        """A plan point as label markup (``b3`` → ``b_{3}'`` on a suffixed plan)."""
        return point_markup(self.name(point))

    def origin(self, point: str) -> str:
        """A point to draw from, as markup: the pole for a fixed point (``o2`` → ``p``)."""
        name = self.name(point)
        return self.pole if name in self.at_pole else point_markup(name)

    def label_of(self, point: str) -> str:
        """The absolute vector of a plan point as label markup: ``b`` → ``V_B``, ``o2`` →
        ``a_{O2}`` on an acceleration plan."""
        return _sub(_SYMBOL[self.kind], self.model(point))

    def model(self, point: str) -> str:
        """The mechanism point a plan point stands for (:attr:`models`, else :func:`model_of`)."""
        return self.models.get(point.rstrip("'")) or model_of(point)

    def _noise(self, x: float) -> bool:
        """Whether a magnitude of plan units is rounding noise beside the plan's size (a
        vector that vanishes in this position: written 0, not 3·10^-17)."""
        size = max((p.norm for p in self.points.values()), default=0.0)
        return abs(x) <= NOISE * size

    @property
    def _unit(self) -> str:
        return f"@u_{self.kind}"

    def _add(
        self,
        point: str,
        value: Vec,
        op: str,
        kind: str,
        args: dict[str, str | float],
        listed: bool = True,
    ) -> Vec:
        name = self.name(point)
        args = {"pt": point_markup(name), "plan": f"@plan_{self.kind}", **args}
        v = self.c.point(name, value, role="construction", op=op, kind=kind, args=args)
        self.points[name] = v
        if listed:
            self.order.append(name)
        return v

    def _vec(
        self,
        tail: str,
        head: str,
        label: str,
        meaning: str,
        known: bool,
        kind: str = "plan_vector",
        args: dict[str, str | float] | None = None,
    ) -> str:
        t, h = self.name(tail), self.name(head)
        step = f"{t}{h}"
        value = self.points[h] - self.points[t]
        args = {
            "tail": self.origin(tail),
            "head": point_markup(h),
            "label": label,
            "mu": _MU[self.kind],
            "value": 0.0 if self._noise(value.norm) else value.norm,
            "unit": self._unit,
            **(args or {}),
        }
        self.c.record(
            step,
            f"vector {t} → {h} = {meaning}",
            value,
            (t, h),
            "construction",
            kind=kind,
            args=args,
        )
        self.vectors.append(PlanVector(step, t, h, label, meaning, known))
        return step

    # -- known points --------------------------------------------------------------------------
    def fixed(self, point: str) -> Vec:
        """A point of the frame (or of a link at rest): it lies at the pole."""
        self.at_pole.add(self.name(point))
        return self._add(
            point,
            Vec(0.0, 0.0),
            f"at the pole ({point} is fixed)",
            "plan_fixed",
            {"pole": self.pole, "vec": self.label_of(point)},
            listed=False,
        )

    def given(self, point: str, value: Vec, label: str, meaning: str = "") -> Vec:
        """A known vector from the pole (``pa = V_A``)."""
        args: dict[str, str | float] = {
            "pole": self.pole,
            "label": label,
            "value": value.norm,
            "unit": self._unit,
        }
        self._add(point, value, f"given {label}", "plan_given", args)
        self._vec(self.pole, point, label, meaning or label, True)
        return self[point]

    def same(self, point: str, as_: str, why: str, reason: str = "") -> Vec:
        """A point that coincides with another one (a translating link, a hinged block).
        ``reason`` says why in the order of construction: ``@translates`` (the link moves
        without turning), ``@hinge`` (one joint of two links), or another ``@word``."""
        eq = f"{self.label_of(point)} = {self.label_of(as_)}"
        args: dict[str, str | float] = {"as": self.mark(as_), "eq": eq}
        kind = "plan_same"
        if reason:
            kind, args["why"] = "plan_same_why", reason
        return self._add(
            point, self[as_], f"the same point as {self.name(as_)} ({why})", kind, args
        )

    def _turning(
        self, point: str, base: str, r: Vec, link: str | int, model: tuple[str, str]
    ) -> dict[str, str | float]:
        B, P = model if all(model) else (self.model(base), self.model(point))
        return {
            "base": self.origin(base),
            "w": _sub("ω", str(link)),
            "e": _sub("ε", str(link)),
            "l": _sub("l", f"{B}{P}"),
            "lv": r.norm,
            "line": f"{B}{P}",
            "from": P,
            "to": B,
            "unit": self._unit,
        }

    def rigid(
        self,
        point: str,
        base: str,
        base_pos: Vec,
        pos: Vec,
        omega: float,
        label: str,
        why: str,
        link: str | int = "",
        model: tuple[str, str] = ("", ""),
    ) -> Vec:
        """A point of a link that turns at ``omega``: V_P = V_base + ω × (P − base).
        ``link`` (its number) and ``model`` (the names of base and point on the mechanism)
        are for the order of construction."""
        r = pos - base_pos
        args = self._turning(point, base, r, link, model)
        args.update(label=label, omega=abs(omega), value=abs(omega) * r.norm)
        value = self[base] + Vec(-r.y, r.x) * omega
        self._add(point, value, f"{self.name(base)} + ω × r ({why})", "plan_rigid", args)
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
        link: str | int = "",
        model: tuple[str, str] = ("", ""),
    ) -> Vec:
        """A point of a link that turns at ``omega`` with ``eps`` on an acceleration plan:
        a_P = a_base + ε × r − ω²·r, r = P − base (the order of construction's ``link`` and
        ``model`` as in :meth:`rigid`)."""
        r = pos - base_pos
        value = self[base] + Vec(-r.y, r.x) * eps - r * (omega * omega)
        args = self._turning(point, base, r, link, model)
        args.update(
            label=label,
            omega=abs(omega),
            eps=abs(eps),
            an=omega * omega * r.norm,
            at=abs(eps) * r.norm,
        )
        kind = "plan_rigid_acc" if eps != 0.0 else "plan_rigid_acc_n"
        self._add(point, value, f"{self.name(base)} + ε × r − ω²·r ({why})", kind, args)
        self._vec(base, point, label, f"ε × r − ω²·r ({why})", True)
        return self[point]

    def image(
        self,
        point: str,
        a: str,
        b: str,
        A: Vec,
        B: Vec,
        P: Vec,
        label: str = "",
        why: str = "",
        model: tuple[str, str, str] = ("", "", ""),
    ) -> Vec:
        """The image of point P of a link whose points A and B are on the plan as ``a``, ``b``:
        the triangle abp is similar to ABP and turned the same way (the theorem of similarity).
        ``model`` names A, B and P on the mechanism, for the order of construction.

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
        names = model if all(model) else (self.model(a), self.model(b), self.model(point))
        args: dict[str, str | float] = {
            "a": self.mark(a),
            "b": self.mark(b),
            "A": names[0],
            "B": names[1],
            "P": names[2],
        }
        kind = "plan_image"
        own = self.models.get(point.rstrip("'"))
        if own and own != names[2]:
            own = ""
        if abs(AB.cross(r)) <= tol.REL_LENGTH * 1.0e3 * math.sqrt(L2) * max(
            r.norm, sys.float_info.min
        ):
            t = r.dot(AB) / L2  # P on line AB: its image on line ab at the same ratio
            kind = "plan_image_line" if t >= 0.0 else "plan_image_beyond"
            args["ratio"] = abs(t)
        if own:
            # a letter other than the point's own: the step says whose image it is
            kind += "_own"
            args["pole"] = _POLE["v"]  # the letter taken is the velocity plan's pole
            args["link"] = why.removeprefix("link ")
        self._add(point, value, op + (f" ({why})" if why else ""), kind, args)
        self.images.append((self.name(a), self.name(b), self.name(point)))
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

        The point's step (kind ``plan_solve``) carries the equation (``V_B = V_A + V_{BA} =
        V_{O2} + V_{BO2}``) and each side's line; each known term is a step of its own kind
        (``plan_normal``, ``plan_coriolis``).
        """
        name = self.name(point)
        lines: list[Line] = []
        args: dict[str, str | float] = {"pt": point_markup(name)}
        sums: list[str] = []
        for side_no, side in enumerate((first, second), start=1):
            tail = side.start
            parts = [] if tail == self.pole else [self.label_of(tail)]
            for term in side.terms:
                targs: dict[str, str | float] = {
                    "tail": self.origin(tail),
                    "pt": self.mark(term.head),
                    "unit": self._unit,
                }
                targs.update(term.args)
                targs.setdefault("label", term.label)
                targs.setdefault("value", term.value.norm)
                relv = targs.get("relv")
                vp = self.velocity
                if isinstance(relv, float) and vp is not None and vp._noise(relv):
                    targs.update(value=0.0, relv=0.0)  # no sliding in this position
                elif self._noise(term.value.norm):  # ω = 0 in this position
                    targs.update(value=0.0, omega=0.0)
                self._add(
                    term.head,
                    self[tail] + term.value,
                    f"{self.name(tail)} + {term.meaning}",
                    term.kind,
                    targs,
                )
                self._vec(tail, term.head, term.label, term.meaning, True)
                parts.append(f"+ {term.label}" if parts else term.label)
                tail = term.head
            d = side.direction.unit()
            if side.perpendicular:
                d = Vec(-d.y, d.x)
            step = f"{name}:{side_no}"
            through = self.name(tail)
            ref = side.line or _line_of(side.text)
            sign = "⊥" if side.perpendicular else "∥"
            largs = {"p": self.origin(tail), "s": sign, "l": ref}
            line = self.c.line(
                step,
                self[tail],
                d,
                f"line through {through} {side.text}",
                kind="plan_line",
                args=largs,
            )
            self.lines.append(PlanLine(step, through, line, side.text))
            lines.append(line)
            if tail != self.pole or parts:
                unknown = side.unknown or self._relative(point, side)
                parts.append(f"+ {unknown}" if parts else unknown)
                sums.append(" ".join(parts))
            args.update({f"p{side_no}": self.origin(tail), f"s{side_no}": sign})
            args[f"l{side_no}"] = ref
        args["eq"] = " = ".join([self.label_of(point), *sums])
        v = self.c.intersect(
            name,
            lines[0],
            lines[1],
            role="construction",
            kind="plan_solve",
            args=args,
        )
        self.points[name] = v
        self.order.append(name)
        return v

    def _relative(self, point: str, side: Side) -> str:
        P, S = self.model(point), self.model(side.start)
        if self.kind == "v":
            return _sub("V", P + S)
        return _sub("a^τ" if side.perpendicular else "a^r", P + S)

    def unknown(self, tail: str, head: str, label: str, meaning: str) -> Vec:
        """Record a vector the plan has found (``ab = V_BA``) and return it."""
        self.values.append(self._vec(tail, head, label, meaning, False, "plan_unknown"))
        return self.between(tail, head)

    def absolute(self, point: str, label: str, meaning: str = "") -> Vec:
        """Record the absolute vector pole → point (``pb = V_B``) and return it."""
        step = self._vec(self.pole, point, label, meaning or label, False, "plan_absolute")
        self.values.append(step)
        return self[point]

    # -- reading the plan ----------------------------------------------------------------------
    def omega(
        self,
        A: Vec,
        B: Vec,
        a: str,
        b: str,
        name: str = "",
        link: str | int = "",
        model: tuple[str, str] = ("", ""),
        rel: str = "",
    ) -> float:
        """The angular velocity (acceleration) of link AB read off the plan, ccw > 0; 0 where
        the vector read is rounding noise beside the plan's size (:data:`NOISE`).

        On a velocity plan: ω = (AB × ab)/AB², i.e. ω = |ab|/l_AB with the sense that turns
        AB towards ab. On an acceleration plan pass the tangential vector's ends: ε = a^τ/l.
        With ``name`` the value is recorded as a step (kind ``plan_omega``, ``plan_eps``) and
        listed in :attr:`order`; ``link`` (its number) and ``model`` (the names of A and B on
        the mechanism) are for its text, ``rel`` the label of the vector read (default: the
        relative vector of B about A, ``V_{BA}``, ``a^τ_{BA}``).
        """
        AB = B - A
        w = AB.cross(self.between(a, b)) / AB.dot(AB)
        length = AB.norm
        if self._noise(w * length):
            # the relative vector vanishes in this position (a dead or symmetric position):
            # ω (ε) is 0 to the plan's tolerance, not 4·10^-13, for every view and the JSON
            w = 0.0
        if name:
            MA, MB = model if all(model) else (self.model(a), self.model(b))
            shown = abs(w)
            rel = rel or (_sub("V", MB + MA) if self.kind == "v" else _sub("a^τ", MB + MA))
            sym = "ω" if self.kind == "v" else "ε"
            self.c.value(
                name,
                w,
                f"({MA}{MB} × {self.name(a)}{self.name(b)})/{MA}{MB}², ccw > 0",
                (self.name(a), self.name(b)),
                kind="plan_omega",
                args={
                    "w": _sub(sym, str(link)),
                    "rel": rel,
                    "relv": shown * length,
                    "l": _sub("l", MA + MB),
                    "lv": length,
                    "value": shown,
                    "unit": "@u_w" if self.kind == "v" else "@u_e",
                },
            )
            self.order.append(name)
        return w

    def extent(self) -> tuple[float, float, float, float]:
        """The plan's bounding box (x0, y0, x1, y1) in plan units, pole included."""
        xs = [p.x for p in self.points.values()]
        ys = [p.y for p in self.points.values()]
        return (min(xs), min(ys), max(xs), max(ys))


#: A magnitude at most this share of the plan's size is written 0 in the order of construction.
NOISE = tol.DERIVED

_SYMBOL = {"v": "V", "a": "a"}
_MU = {"v": "μ_V", "a": "μ_a"}


def point_markup(name: str) -> str:
    """A plan point's step name as label markup: ``b3`` → ``b_{3}``, ``n_BA'`` → ``n_{BA}'``,
    ``p_P`` → ``p_{P}``; ``b``, ``π`` as they are."""
    m = _re.fullmatch(r"([^\d_']+)_?([^']*)('*)", name)
    if m is None or not m.group(2):
        return name
    base, sub, prime = m.groups()
    return f"{base}_{{{sub}}}{prime}"


def model_of(point: str) -> str:
    """The mechanism point a plan point stands for: ``b3`` → ``B3``, ``p_P`` → ``P``."""
    base = point.rstrip("'")
    return (base[2:] if base.startswith("p_") else base).upper()


def _sub(head: str, sub: str) -> str:
    """``head`` with subscript ``sub`` as markup (``V``, ``BA`` → ``V_{BA}``; none: ``head``)."""
    return f"{head}_{{{sub}}}" if sub else head


def _line_of(text: str) -> str:
    """The line a side's words name: ``⊥ O1B (V_B3 about O1)`` → ``O1B``."""
    return text.split("(")[0].strip().lstrip("⊥∥ ").strip()


def velocity_plan(c: Construction, suffix: str = "") -> Plan:
    """A new velocity plan in ``c``, pole p at the origin."""
    return Plan(c, "v", suffix)


def acceleration_plan(c: Construction, suffix: str = "'", velocity: Plan | None = None) -> Plan:
    """A new acceleration plan in ``c``, pole π at the origin; its points are named ``b'``.
    ``velocity``: the velocity plan of the same position (for the order of construction)."""
    return Plan(c, "a", suffix, velocity=velocity)


def normal(
    omega: float,
    B: Vec,
    A: Vec,
    head: str,
    label: str,
    meaning: str,
    link: str | int = "",
    model: tuple[str, str] = ("", ""),
) -> Term:
    """The normal acceleration of B about A: ω²·l_AB, directed from B to A. ``link`` (its
    number) and ``model`` (the names of B and A on the mechanism) are for the order of
    construction (kind ``plan_normal``; without ``model``: ``plan_term``)."""
    value = (A - B) * (omega * omega)
    if not all(model):
        return Term(value, head, label, meaning)
    P, Q = model
    args: tuple[tuple[str, str | float], ...] = (
        ("w", _sub("ω", str(link))),
        ("omega", abs(omega)),
        ("l", _sub("l", Q + P)),
        ("lv", (A - B).norm),
        ("from", P),
        ("to", Q),
    )
    return Term(value, head, label, meaning, "plan_normal", args)


def coriolis(
    omega: float,
    v_rel: Vec,
    head: str,
    label: str,
    meaning: str,
    link: str | int = "",
    rel: str = "",
) -> Term:
    """The Coriolis acceleration 2ω × V_rel: V_rel turned 90° in the sense of ω, times 2|ω|.
    ``link`` (the number of the link that carries the guide) and ``rel`` (the label markup of
    V_rel) are for the order of construction (kind ``plan_coriolis``; without ``rel``:
    ``plan_term``)."""
    value = Vec(-v_rel.y, v_rel.x) * (2.0 * omega)
    if not rel:
        return Term(value, head, label, meaning)
    args: tuple[tuple[str, str | float], ...] = (
        ("w", _sub("ω", str(link))),
        ("omega", abs(omega)),
        ("rel", rel),
        ("relv", v_rel.norm),
        ("sense", "@ccw" if omega > 0.0 else "@cw"),
    )
    return Term(value, head, label, meaning, "plan_coriolis", args)
