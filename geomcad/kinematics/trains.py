"""Gear trains: fixed-axis, planetary and compound-planetary ratios, exact, and the velocity plan.

Notation (the Russian school's): u_ab = ω_a/ω_b; u_ab^(H) is the ratio with the carrier H held
(ω_a − ω_H)/(ω_b − ω_H); u_aH^(b) the ratio to the carrier with b held. Willis' method turns the
whole train by −ω_H, so that the carrier stands still and the train has fixed axes:
u_aH^(b) = 1 − u_ab^(H).

One mesh with both axes fixed on carrier H gives (ω_a − ω_H)/(ω_b − ω_H) = −z_b/z_a for an external
pair and +z_b/z_a for an internal one (a pinion inside a ring). Ratios are exact
:class:`fractions.Fraction` values; tooth counts are whole numbers.

Coaxiality: two meshes that join the same pair of axes have equal centre distances,
m(z_a + z_b)/2 for an external pair and m(z_ring − z_pinion)/2 for an internal one (one module);
a missing tooth count follows, and must be a whole number ≥ 1.

The check: the mesh equations z_a(ω_a − ω_H) ± z_b(ω_b − ω_H) = 0, one per mesh, in the absolute
angular velocities of all links, solved exactly (:func:`solve_speeds`).

The graphical method (Smirnov's plan of linear velocities, :func:`velocity_plan`): the points of
every link on the radial line through the axes move perpendicular to it, with speeds
v(y) = ω·(y − y_0): a straight line in the plane (v, y). The radii go on a vertical axis; a point
shared by two links (a bearing, the pitch point of a mesh) has one velocity, so each link's line
passes through two known velocity ends; the fixed link's line is the axis v = 0. The slope dv/dy
of a link's line is its angular velocity. The angle diagram (:func:`ray_plan`) draws from one
pole a ray parallel to each link's line; the rays cut a line at distance H from the pole in
intercepts H·ω, so their ratios are the ratios of the train.

Every step the plan and the diagram record carries its kind and operands for the order of
construction (templates ``step.<kind>`` in geomcad/sheet/strings/<lang>/views.toml): the radii
laid off (``train_radii``), the points at rest (``train_rest``), the velocity taken
(``train_start``), each link's velocity line through two ends (``train_line``) and the points found
on it (``train_point``), the pole and the rays of the angle diagram (``ray_pole``,
``ray_parallel``, ``ray_cut``) and the diagram as a whole (``ray_plan``); the links are named as
the sheets name them (:func:`link_markup`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

from geomcad.construction import Construction
from geomcad.errors import ConstructionError, DegenerateInput, ParameterError
from geomcad.geom import Line, Vec


@dataclass(frozen=True)
class Mesh:
    """Gears ``a`` and ``b`` in mesh: the links they belong to, their tooth counts, whether the
    pair is internal (the gear with more teeth is then the ring), and ``carrier``: the link on
    which both their axes are fixed (the frame for a fixed-axis pair)."""

    a: str
    z_a: int
    b: str
    z_b: int
    carrier: str
    internal: bool = False

    def __post_init__(self) -> None:
        for name, z in ((self.a, self.z_a), (self.b, self.z_b)):
            if isinstance(z, bool) or int(z) != z or z < 1:
                raise ParameterError(f"z of {name}", z, "a tooth count must be a whole number ≥ 1")
        if self.internal and self.z_a == self.z_b:
            raise ParameterError(
                f"z of {self.b}",
                self.z_b,
                f"an internal pair needs a ring with more teeth than its pinion ({self.z_a})",
            )

    @property
    def name(self) -> str:
        return f"{self.a}–{self.b}"

    def ratio(self) -> Fraction:
        """u_ab^(H) = (ω_a − ω_H)/(ω_b − ω_H): −z_b/z_a external, +z_b/z_a internal."""
        u = Fraction(self.z_b, self.z_a)
        return u if self.internal else -u

    def centre_distance(self) -> Fraction:
        """The centre distance in modules: (z_a + z_b)/2 external, |z_b − z_a|/2 internal."""
        if self.internal:
            return Fraction(abs(self.z_b - self.z_a), 2)
        return Fraction(self.z_a + self.z_b, 2)

    def equation(self) -> dict[str, Fraction]:
        """The mesh equation as coefficients of the absolute ω's, = 0:
        z_a·ω_a ± z_b·ω_b − (z_a ± z_b)·ω_H (+ external, − internal)."""
        sign = -1 if self.internal else 1
        coeffs: dict[str, Fraction] = {}
        for link, k in (
            (self.a, Fraction(self.z_a)),
            (self.b, Fraction(sign * self.z_b)),
            (self.carrier, -Fraction(self.z_a + sign * self.z_b)),
        ):
            coeffs[link] = coeffs.get(link, Fraction(0)) + k
        return {k: v for k, v in coeffs.items() if v != 0}


def chain_ratio(meshes: Sequence[Mesh]) -> Fraction:
    """The ratio of gears in series, each pair on axes fixed on its carrier: the product of the
    meshes' ratios (a fixed-axis train when every carrier is the frame)."""
    u = Fraction(1)
    for mesh in meshes:
        u *= mesh.ratio()
    return u


def willis(u_ab_h: Fraction) -> Fraction:
    """u_aH^(b) = 1 − u_ab^(H): the ratio to the carrier when b is held (Willis)."""
    return 1 - u_ab_h


def mobility(n: int, lower: int, higher: int) -> int:
    """Chebyshev's formula for a plane mechanism: W = 3n − 2p_l − p_h (n moving links, p_l lower
    and p_h higher pairs)."""
    return 3 * n - 2 * lower - higher


def coaxial_count(
    step: str, distance: Fraction, z_other: int, internal: bool, ring_unknown: bool = False
) -> int:
    """The tooth count a coaxiality condition gives: the gear that meshes with ``z_other`` at the
    centre distance ``distance`` (in modules).

    External: z = 2a − z_other; internal with the unknown as the ring: z = 2a + z_other; internal
    with the unknown as the pinion: z = z_other − 2a. A count that is not a whole number ≥ 1 is a
    :class:`ConstructionError` naming ``step``.
    """
    two_a = 2 * distance
    if not internal:
        z = two_a - z_other
    elif ring_unknown:
        z = two_a + z_other
    else:
        z = z_other - two_a
    if z.denominator != 1 or z < 1:
        raise ConstructionError(
            step, f"it gives {z} teeth: a tooth count must be a whole number ≥ 1"
        )
    return int(z)


class Speeds(dict[str, Fraction]):
    """Angular velocities by link, exact; printed as ``ω_1 = 1, ω_2-5 = 155/731, …``."""

    def __str__(self) -> str:
        return ", ".join(f"ω_{k} = {v}" for k, v in self.items())


def solve_speeds(meshes: Sequence[Mesh], known: Mapping[str, Fraction | int]) -> Speeds:
    """Every link's absolute angular velocity from the mesh equations (exact, Gauss–Jordan on
    fractions), given the ``known`` ones (the frame's 0 and the input's ω).

    The system must determine every link exactly once: a train with W ≠ the number of inputs, or
    a singular system, is a :class:`ConstructionError`.
    """
    links: list[str] = []
    for mesh in meshes:
        for link in (mesh.a, mesh.b, mesh.carrier):
            if link not in links:
                links.append(link)
    unknown = [k for k in links if k not in known]
    rows: list[list[Fraction]] = []
    for mesh in meshes:
        eq = mesh.equation()
        rhs = -sum((Fraction(known[k]) * v for k, v in eq.items() if k in known), Fraction(0))
        rows.append([eq.get(k, Fraction(0)) for k in unknown] + [rhs])
    n = len(unknown)
    if len(rows) != n:
        raise ConstructionError(
            "mesh equations",
            f"{len(rows)} equations for {n} unknown angular velocities ({', '.join(unknown)}): "
            "the train is not determined by the given inputs",
        )
    for col in range(n):
        pivot = next((i for i in range(col, n) if rows[i][col] != 0), None)
        if pivot is None:
            raise ConstructionError(
                "mesh equations",
                f"the equations do not determine ω of {unknown[col]} (singular system)",
            )
        rows[col], rows[pivot] = rows[pivot], rows[col]
        p = rows[col][col]
        rows[col] = [v / p for v in rows[col]]
        for i in range(n):
            if i != col and rows[i][col] != 0:
                f = rows[i][col]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[col], strict=True)]
    out = Speeds({k: Fraction(v) for k, v in known.items()})
    out.update({k: rows[i][n] for i, k in enumerate(unknown)})
    return out


# -- the graphical method ------------------------------------------------------------------------


@dataclass(frozen=True)
class PlanPoint:
    """A point on the radial line of the scheme: its name (A, B …), its radius ``y`` from the
    central axis (m, negative below it) and the links that share its velocity (the two gears of
    a mesh's pitch point; a link and its carrier at a bearing)."""

    name: str
    y: float
    links: tuple[str, ...]


@dataclass(frozen=True)
class VelocityPlan:
    """Smirnov's plan: each link's velocity line in the plane (v in m/s, y in m), each point's
    velocity end ``ends[name]`` = (v, y), and ω = dv/dy of every link, in the order the lines
    were found."""

    lines: dict[str, Line]
    ends: dict[str, Vec]
    omega: dict[str, float]
    order: tuple[str, ...]


def _slope(line: Line) -> float:
    """dv/dy of a plan line: the angular velocity of its link."""
    if line.d.y == 0.0:
        raise DegenerateInput("velocity line", "a link's velocity line is parallel to the v axis")
    return line.d.x / line.d.y


def link_markup(link: str) -> str:
    """A link's name as label markup for the order of construction: ``H2-7`` → ``H_2–7``,
    ``2-5`` → ``2–5`` (the sheet's names of the blocks)."""
    return re.sub(r"([A-Za-z])(\d)", r"\1_\2", link).replace("-", "–")


def _link_line(
    c: Construction, link: str, ends: Mapping[str, Vec], a: str, b: str, note: str
) -> Line:
    """Record the velocity line of ``link`` through the ends of its points ``a`` and ``b``."""
    pa, pb = ends[a], ends[b]
    return c.run(
        f"v({link})",
        f"line {a.lower()}{b.lower()}",
        lambda: Line.through(pa, pb),
        (pa, pb),
        note=note,
        kind="train_line",
        args={"link": link_markup(link), "a": a.lower(), "b": b.lower()},
    )


def velocity_plan(
    c: Construction,
    points: Sequence[PlanPoint],
    fixed: str,
    start: str,
    start_point: str,
    v_start: float,
) -> VelocityPlan:
    """Draw Smirnov's plan as recorded steps in ``c``.

    The fixed link's line is the axis v = 0. The ``start`` link gets its line through its point
    shared with the fixed link (v = 0 there) and the velocity end (``v_start``, y) of
    ``start_point``. Then, repeatedly, a link with two points of known velocity at different
    radii gets its line through their ends, and each point on a link with a line gets its end
    where the horizontal at its radius meets that line. A link that never gets two known points
    is a :class:`ConstructionError` naming its step.
    """
    by_name = {p.name: p for p in points}
    links: list[str] = []
    for p in points:
        for link in p.links:
            if link not in links:
                links.append(link)
    lines: dict[str, Line] = {}
    ends: dict[str, Vec] = {}
    order: list[str] = []
    c.record(
        "radii",
        "the points' radii on one vertical",
        tuple(Vec(0.0, p.y) for p in points),
        role="hidden",
        kind="train_radii",
        args={"points": ", ".join(p.name for p in points)},
    )
    axis = c.line(
        f"v({fixed})",
        Vec(0.0, 0.0),
        (0.0, 1.0),
        f"axis v = 0: the fixed link {fixed}",
        "given",
        kind="train_axis",
        args={"link": link_markup(fixed)},
    )
    lines[fixed] = axis
    fixed_pts = [p for p in points if fixed in p.links and start in p.links]
    if not fixed_pts:
        raise ConstructionError(
            f"v({start})", f"the start link {start} has no point on the fixed link {fixed}"
        )
    sp = by_name[start_point]
    if start not in sp.links:
        raise ConstructionError(f"v({start})", f"{start_point} is not a point of {start}")
    for p in points:
        if fixed in p.links:
            ends[p.name] = c.point(
                p.name.lower(),
                (0.0, p.y),
                "construction",
                op="on v = 0",
                kind="train_rest",
                args={"p": p.name, "link": link_markup(fixed)},
            )
    anchor = fixed_pts[0]
    ends[sp.name] = c.point(
        sp.name.lower(),
        (v_start, sp.y),
        "construction",
        op=f"V_{sp.name} taken",
        kind="train_start",
        args={
            "p": sp.name,
            "link": link_markup(start),
            "r": sp.y - anchor.y,
            "w": v_start / (sp.y - anchor.y) if sp.y != anchor.y else 0.0,
            "v": v_start,
        },
    )
    lines[start] = _link_line(c, start, ends, anchor.name, sp.name, f"line of {start}")
    order.append(start)

    def spread() -> None:
        for p in points:
            if p.name in ends:
                continue
            for link in p.links:
                if link in lines:
                    level = c.line(
                        f"y_{p.name}",
                        Vec(0.0, p.y),
                        (1.0, 0.0),
                        f"horizontal at y_{p.name}",
                        kind="train_level",
                        args={"p": p.name},
                    )
                    ends[p.name] = c.intersect(
                        p.name.lower(),
                        lines[link],
                        level,
                        role="construction",
                        op=f"line of {link} ∩ horizontal at y_{p.name}",
                        kind="train_point",
                        args={"p": p.name, "link": link_markup(link)},
                    )
                    break

    spread()
    while len(lines) < len(links):
        progress = False
        for link in links:
            if link in lines:
                continue
            known = [p for p in points if link in p.links and p.name in ends]
            known.sort(key=lambda p: p.y)
            if len(known) >= 2 and known[-1].y != known[0].y:
                a, b = known[0].name, known[-1].name
                lines[link] = _link_line(
                    c, link, ends, a, b, f"line of {link} through {a.lower()} and {b.lower()}"
                )
                order.append(link)
                spread()
                progress = True
        if not progress:
            missing = [k for k in links if k not in lines]
            raise ConstructionError(
                f"v({missing[0]})",
                f"fewer than two points of known velocity on {', '.join(missing)}: the plan does "
                f"not close from {start}",
            )
    omega = {k: (0.0 if k == fixed else _slope(line)) for k, line in lines.items()}
    return VelocityPlan(lines, ends, omega, tuple(order))


@dataclass(frozen=True)
class RayPlan:
    """The angle diagram: pole ``S``, the line at distance ``H`` from it, and per link the end
    of its ray on that line (intercept H·ω along v)."""

    S: Vec
    H: float
    ends: dict[str, Vec]

    def omega(self, link: str) -> float:
        """ω of a link read off the diagram: its intercept / H."""
        return (self.ends[link].x - self.S.x) / self.H

    def ratio(self, a: str, b: str) -> float:
        """u_ab = ω_a/ω_b as the ratio of the two intercepts."""
        return (self.ends[a].x - self.S.x) / (self.ends[b].x - self.S.x)


def ray_plan(
    c: Construction, plan: VelocityPlan, S: Vec, H: float, links: Sequence[str]
) -> RayPlan:
    """Record the angle diagram: from pole S a ray parallel to each link's velocity line, cut by
    the horizontal at distance H above S (a ray with slope dv/dy = ω meets it at v = S.v + H·ω)."""
    if not (H > 0.0 and math.isfinite(H)):
        raise ParameterError("H", H, "the pole distance must be > 0")
    pole = c.point("S", S, "construction", op="pole of the angle diagram", kind="ray_pole")
    base = c.line("ω-line", S + Vec(0.0, H), (1.0, 0.0), "horizontal at H above S", kind="ray_base")
    ends: dict[str, Vec] = {}
    for link in links:
        ray = c.parallel(
            f"ray {link}",
            plan.lines[link],
            through=pole,
            note=f"∥ line of {link}",
            kind="ray_parallel",
            args={"link": link_markup(link)},
        )
        ends[link] = c.intersect(
            f"ω{link}",
            ray,
            base,
            role="construction",
            kind="ray_cut",
            args={"link": link_markup(link)},
        )
    c.record(
        "ω",
        "the rays' intercepts on the line at H: H·ω of each link",
        tuple(ends.values()),
        role="hidden",
        kind="ray_plan",
        args={"links": ", ".join(link_markup(k) for k in links)},
    )
    return RayPlan(S, H, ends)
