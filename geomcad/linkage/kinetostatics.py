"""Kinetostatics of a linkage at one position, by Assur groups, and Zhukovsky's lever.

At constant ω1 (ε1 = 0) every moving link carries its weight, its inertia loads Ф = −m·a_S and
M_Ф = −J·ε (d'Alembert) and the file's loads (:mod:`geomcad.linkage.loads`). The reactions are
found as the subject teaches, **from the last group to the crank**, each class-II group cut out
with its neighbours' reactions (the loads that later groups put on its links included):

- **RRR** (links a: E1–J, b: E2–J): the tangential components R^τ at E1 and E2 from the moment
  equations of each link about the inner joint J, ΣM_J = 0; the normal components (along E1J,
  E2J) from the group's force polygon R^τ_1 + ΣF_a + ΣF_b + R^τ_2 + R^n_2 + R^n_1 = 0, closed by
  the two lines of known direction; the inner reaction from link a's polygon;
- **RRP** (rod a: E–J, slider b on a guide of link g): R^τ at E from the rod's ΣM_J = 0; the
  guide's reaction N (normal to the slide) and R^n (along EJ) from the group's polygon
  R^τ + ΣF_a + ΣF_b + N + R^n = 0; the inner reaction from the slider's polygon; N's point of
  application h along the slide from J by the slider's moment equation about J;
- **RPR** (block a at A, slotted link b turning at C): the block's moment equation about A puts
  the product h·N (N of b on a, normal to the slide, applied h along the slide from A); link b's
  ΣM_C = 0 then gives N; the reactions at A and C close the block's and link b's polygons;
- **PRP** (block a at A, yoke b on a fixed guide): the yoke's polygon ΣF_b + N_ab + N_0b = 0 is
  closed by the two normals (to the slot and to the guide); the reaction at A closes the block's
  polygon; the points of N_ab and N_0b from the block's and the yoke's moment equations;
- **the crank**: R_01 closes its polygon, and the balancing moment M_bal (the moment the motor
  applies to the crank) is its moment equation about the pivot.

Each step is recorded in the position's :class:`~geomcad.construction.Construction` (``--trace``),
the polygons through :func:`geomcad.forces.force_polygon`.

**Zhukovsky's lever**: the velocity plan turned 90° counter-clockwise (pole p, the image of a
point P at V_P turned), every load moved to its point's image, a moment M on link i as a couple of
forces on the image of a segment of the link; the lever's moment equation about the pole gives
the balancing force at the crank's joint's image, hence M_bal_lever. A force F at an image
turned from V has the moment (V turned) × F = −F·V about the pole, so the lever's equation is
the equation of powers: M_bal_lever = −ΣP/ω1 over the same loads, inertia loads included.
"""

from __future__ import annotations

import math
import sys
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from geomcad import tol
from geomcad.construction import Construction
from geomcad.forces import ForcePolygon, Known, PlanVector, Term, Unknown, force_polygon
from geomcad.geom import Vec
from geomcad.linkage.cycle import Cycle
from geomcad.linkage.loads import (
    Range,
    centre_name,
    centre_vec,
    force_value,
    moment_value,
    ranges,
    slider_group,
    stroke_sign,
)
from geomcad.linkage.model import Group, Linkage, Load
from geomcad.linkage.plans import Position, plan_name

LoadKind = Literal["weight", "inertia", "given", "reaction"]

#: The kinds of the steps the order of the kinetostatic analysis lists (:attr:`Forces.order`):
#: the loads, each group cut out (from the last), its equations of moments, its polygons, the
#: points of the sliding pairs' reactions, the crank's balancing moment and Zhukovsky's lever.
ORDER_KINDS = frozenset(
    {
        "weight",
        "inertia_force",
        "inertia_moment",
        "given_force",
        "given_moment",
        "given_sum",
        "given_moment_sum",
        "group",
        "tangential",
        "slot_normal",
        "force_polygon",
        "polygon_closing",
        "slide_arm",
        "slide_couple",
        "slide_far",
        "crank",
        "balancing_moment",
        "zhukovsky",
        "lever_check",
    }
)


def _part(
    name: str, key: str | int, many: Counter[str | int], terms: dict[str | int, list[str]]
) -> str:
    """A load's name in the order: ``name`` where its point (link) carries it alone, else
    ``name`` with its number among that point's loads as a superscript (``F_{B}^{(2)}``), kept
    in ``terms`` for the sum stated after them."""
    if many[key] < 2:
        terms.setdefault(key, []).append(name)
        return name
    part = f"{name}^{{({len(terms.get(key, ())) + 1})}}"
    terms.setdefault(key, []).append(part)
    return part


#: A sliding pair's reaction lies at most this many crank lengths from its joint; beyond, the
#: normal force is about zero and the pair carries a couple (see :class:`Reaction`).
ARM_MAX = 1.0e3
#: ... and at most this many times the mechanism's reach at the position (the largest distance
#: between two of its points): a point farther off lies on no drawing of the link (review 11: a
#: guide bar's 0.34 N weight reaction 2.8 m off a 0.1 m mechanism drew its free body at 1:15);
#: beyond, the reaction is drawn at its joint with the pair's couple, the same equivalent system.
REACH_MAX = 2.0


@dataclass(frozen=True)
class Applied:
    """A load on a link: a force ``force`` (N) at ``at`` (its velocity ``velocity``), or a
    moment ``moment`` (N·m, ccw > 0; ``force`` None). ``point`` names the mechanism point it
    acts at ("" for a computed point)."""

    name: str
    link: int
    kind: LoadKind
    force: Vec | None = None
    at: Vec | None = None
    moment: float = 0.0
    point: str = ""
    velocity: Vec | None = None


@dataclass(frozen=True)
class Reaction:
    """The force of link ``of`` on link ``on`` in their pair at ``joint`` (N), applied at
    ``at``; ``sliding``: a sliding pair's reaction, normal to the slide (``h`` m along the slide
    from ``joint``), else a revolute's through its axis. Where the normal force is (nearly) zero
    and the slide must still carry a moment, the force stays at the joint and the pair's
    ``couple`` (N·m, of ``of`` on ``on``) carries it."""

    name: str
    of: int
    on: int
    force: Vec
    at: Vec
    joint: str
    sliding: bool = False
    h: float = 0.0
    couple: float = 0.0

    @property
    def key(self) -> tuple[int, int]:
        return (min(self.of, self.on), max(self.of, self.on))

    def on_lower(self) -> Vec:
        """The force of the lower-numbered link on the higher one (the ``R_i_j`` of results)."""
        return self.force if self.of < self.on else -self.force


@dataclass
class GroupForces:
    """One group's (or the crank's, ``group`` None) free body: the loads on its links (their
    own and the later groups' reactions), the reactions found, the polygons drawn."""

    group: Group | None
    links: tuple[int, ...]
    loads: dict[int, list[Applied]]
    reactions: list[Reaction] = field(default_factory=list)
    polygons: list[tuple[str, ForcePolygon]] = field(default_factory=list)


@dataclass(frozen=True)
class LeverItem:
    """One load on Zhukovsky's lever: its force at the image ``image`` (the turned velocity of
    its point), its arm about the pole and its moment (the couples of a moment load too);
    ``link`` carries it at the mechanism point ``point`` (``C2``: the point of link 2 at C;
    "" for a couple's computed point)."""

    name: str
    force: Vec
    image: Vec
    moment: float
    link: int = 0
    point: str = ""


@dataclass
class Lever:
    """Zhukovsky's lever: the images (turned plan, m/s) of the mechanism's points, the loads on
    it, the balancing force at the crank's joint's image (⊥ the crank) and M_bal_lever."""

    images: dict[str, Vec]
    items: list[LeverItem]
    F_bal: Vec
    M_bal: float
    power: float  # ΣP over the same loads (W)


@dataclass
class Forces:
    """The kinetostatics of one position: the loads on each link, the groups (last to first,
    then the crank), every reaction, M_bal and the lever."""

    phi: float
    c: Construction
    loads: dict[int, list[Applied]]
    groups: list[GroupForces]
    reactions: list[Reaction]
    M_bal: float
    lever: Lever

    def R(self, i: int, j: int) -> Vec:
        """R_i_j: the force of link i on link j (summed over their pairs)."""
        total = Vec(0.0, 0.0)
        found = False
        for r in self.reactions:
            if r.key == (min(i, j), max(i, j)):
                found = True
                f = r.on_lower()
                total = total + (f if i < j else -f)
        if not found:
            raise KeyError(f"links {i} and {j} form no pair")
        return total

    @property
    def order(self) -> list[str]:
        """The names of the steps of the order of the analysis, in their recorded order."""
        return [s.name for s in self.c.steps if s.kind in ORDER_KINDS]

    @property
    def pairs(self) -> list[tuple[int, int]]:
        return sorted({r.key for r in self.reactions})


# --- loads --------------------------------------------------------------------------------


def output_velocity_at(lk: Linkage, P: Position) -> float:
    """The output's velocity at position P: a slider's along its guide, a rocker's ω."""
    if lk.rocker:
        return P.omega[lk.rocker]
    return P.v_rel[lk.output]


def applied_loads(
    lk: Linkage,
    P: Position,
    rng: dict[str, Range],
    c: Construction,
    cyc: Cycle | None = None,
) -> dict[int, list[Applied]]:
    """The given loads of every moving link at position P: weights, inertia loads and the
    file's loads (module docstring of :mod:`geomcad.linkage.loads`), recorded in ``c``."""
    out: dict[int, list[Applied]] = {i: [] for i in lk.moving_links}
    g = lk.gravity
    for i in lk.moving_links:
        m = lk.masses.get(i)
        if m is None:
            continue
        S = centre_vec(lk, i, P.pos)
        VS = centre_vec(lk, i, P.vel)
        aS = centre_vec(lk, i, P.acc)
        sn = centre_name(lk, i)
        pt = lk.centre(i)
        if m.mass > 0.0 and g > 0.0:
            G = c.record(
                f"G_{i}",
                f"the weight of link {i}: m·g = {m.mass:g}·{g:g} N, down, at {sn}",
                Vec(0.0, -m.mass * g),
                role="hidden",
                kind="weight",
                args={
                    "F": f"G_{{{i}}}",
                    "i": i,
                    "m": m.mass,
                    "g": g,
                    "value": m.mass * g,
                    "at": sn,
                },
            )
            out[i].append(Applied(f"G_{{{i}}}", i, "weight", G, S, 0.0, pt, VS))
        if m.mass > 0.0 and aS.norm > 0.0:
            F = c.record(
                f"Ф_{i}",
                f"the inertia force of link {i}: −m·a_{sn} at {sn}",
                aS * -m.mass,
                role="hidden",
                kind="inertia_force",
                args={
                    "F": f"Ф_{{{i}}}",
                    "i": i,
                    "a": f"a_{{{sn}}}",
                    "m": m.mass,
                    "av": aS.norm,
                    "value": m.mass * aS.norm,
                    "at": sn,
                },
            )
            out[i].append(Applied(f"Ф_{{{i}}}", i, "inertia", F, S, 0.0, pt, VS))
        eps = P.eps[i]
        if m.J > 0.0 and eps != 0.0:
            M = c.value(
                f"M_Ф{i}",
                -m.J * eps,
                f"the inertia moment of link {i}: −J·ε{i}",
                kind="inertia_moment",
                args={
                    "M": f"M_{{Ф{i}}}",
                    "i": i,
                    "e": f"ε_{{{i}}}",
                    "J": m.J,
                    "ev": eps,
                    "value": -m.J * eps,
                },
            )
            out[i].append(Applied(f"M_{{Ф{i}}}", i, "inertia", None, None, M))
    # the file's loads: several on one point (one link) act together, as their sum
    moving = None
    if cyc is not None:
        v_out = output_velocity_at(lk, P)
        moving = stroke_sign(lk, cyc, np.array([P.phi]), np.array([v_out]))
    forces: dict[str, Vec] = {}
    moments: dict[int, float] = {}
    # a point (a link) that carries several loads: each named with its number among them
    # (F_B^(1), F_B^(2)), their sum F_B stated after them (review 7: two "F_B" of 10 820 and
    # 250 Н in the order beside one F_B = 11 070 Н in the table and on the drawing)
    acting: list[tuple[Load, float]] = []
    for ld in lk.loads:
        if ld.point:
            grp = slider_group(lk, ld.point)
            line = P.lines[grp.index]
            s = (P.pos[ld.point] - line.p).dot(line.d)
            v = P.v_rel[ld.point]
            f = float(force_value(lk, ld, rng[ld.point], np.array([s]), np.array([v]), moving)[0])
            if f != 0.0:
                acting.append((ld, f))
        else:
            mv = float(moment_value(ld, np.array([P.omega[ld.link]]), moving)[0])
            if not (ld.on_stroke and mv == 0.0):
                acting.append((ld, mv))
    many = Counter(ld.point if ld.point else ld.link for ld, _ in acting)
    terms: dict[str | int, list[str]] = {}
    for ld, f in acting:
        if ld.point:
            line = P.lines[slider_group(lk, ld.point).index]
            s = (P.pos[ld.point] - line.p).dot(line.d)
            r = rng[ld.point]
            s_w = s - r.s_min if lk.working == "forward" else r.s_max - s
            name = _part(f"F_{{{ld.point}}}", ld.point, many, terms)
            F = c.record(
                f"F_{ld.index}",
                f"load {ld.index} on {ld.point}: {ld.value:g} N·shape(s/H) along the guide, "
                f"against V; s = {s_w:.6g} m from the working stroke's start, H = {r.H:.6g} m",
                line.d * f,
                role="hidden",
                kind="given_force",
                args={"F": name, "at": ld.point, "value": abs(f)},
            )
            forces[ld.point] = forces.get(ld.point, Vec(0.0, 0.0)) + F
        else:
            what = (
                f"|M| against ω{ld.link} on the {ld.stroke} stroke"
                if ld.on_stroke
                else "a constant moment"
            )
            name = _part(f"M_{{{ld.link}}}", ld.link, many, terms)
            c.value(
                f"M_{ld.index}",
                f,
                f"load {ld.index}: a moment on link {ld.link}, {what}",
                kind="given_moment",
                args={"M": name, "link": ld.link, "value": f},
            )
            moments[ld.link] = moments.get(ld.link, 0.0) + f
    for point, F in forces.items():
        if len(terms.get(point, ())) > 1:
            c.value(
                f"F_{point}_sum",
                F.norm,
                f"the loads on {point} act together: their sum",
                kind="given_sum",
                args={"F": f"F_{{{point}}}", "terms": " + ".join(terms[point]),
                      "at": point, "value": F.norm},
            )  # fmt: skip
    for link, M in moments.items():
        if len(terms.get(link, ())) > 1:
            c.value(
                f"M_{link}_sum",
                M,
                f"the moment loads on link {link} act together: their sum",
                kind="given_moment_sum",
                args={"M": f"M_{{{link}}}", "terms": " + ".join(terms[link]),
                      "link": link, "value": M},
            )  # fmt: skip
    for point, F in forces.items():
        link = lk.owner[point]
        out[link].append(
            Applied(f"F_{{{point}}}", link, "given", F, P.pos[point], 0.0, point, P.vel[point])
        )
    for link, total in moments.items():
        out[link].append(Applied(f"M_{{{link}}}", link, "given", None, None, total))
    return out


def _sum(loads: Iterable[Applied]) -> Vec:
    total = Vec(0.0, 0.0)
    for ld in loads:
        if ld.force is not None:
            total = total + ld.force
    return total


def _moment(loads: Iterable[Applied], about: Vec) -> float:
    total = 0.0
    for ld in loads:
        if ld.force is not None and ld.at is not None:
            total += (ld.at - about).cross(ld.force)
        else:
            total += ld.moment
    return total


def _knowns(loads: Iterable[Applied]) -> list[Known]:
    return [Known(ld.name, ld.force) for ld in loads if ld.force is not None]


def _closing(
    c: Construction, gf: GroupForces, name: str, knowns: list[Known], unknown: str, eq: str
) -> Vec:
    """A polygon with one unknown vector: the closing side from the chain's end to the pole
    (kept with the group's polygons)."""
    at = Vec(0.0, 0.0)
    vectors: list[PlanVector] = []
    for k in knowns:
        vectors.append(PlanVector(k.name, at, at + k.force))
        at = at + k.force
    vectors.append(PlanVector(unknown, at, Vec(0.0, 0.0)))
    poly = ForcePolygon(Vec(0.0, 0.0), tuple(vectors), ())
    c.record(
        name,
        f"force polygon {eq}, closed by {unknown}",
        poly,
        role="hidden",
        kind="polygon_closing",
        args={"eq": eq, "F": unknown, "value": at.norm},
    )
    gf.polygons.append((name, poly))
    return -at


# --- groups -------------------------------------------------------------------------------


def _clean(x: float, scale: float) -> float:
    """``x`` for the order of the analysis: 0 where it is at the level of rounding of ``scale``."""
    return 0.0 if abs(x) <= tol.REL_LENGTH * scale else x


def _tangential(o: int, link: int, E: str, J: str, M: float, length: float) -> dict[str, object]:
    """The operands of a tangential component found by a link's ΣM_J = 0 (kind ``tangential``)."""
    return {
        "R": f"R^τ_{{{o}{link}}}",
        "link": link,
        "J": J,
        "l": f"l_{{{E}{J}}}",
        "M": M,
        "lv": length,
        "value": M / length,
    }


def reaction_name(i: int, j: int) -> str:
    """The reaction of link ``i`` on link ``j``: R_ij (R_i,j past link 9)."""
    return f"R_{{{i}{j}}}" if i < 10 and j < 10 else f"R_{{{i},{j}}}"


class _Solver:
    def __init__(self, lk: Linkage, P: Position, c: Construction) -> None:
        self.lk, self.P, self.c = lk, P, c
        pts = list(P.pos.values())
        reach = max(((p - q).norm for p in pts for q in pts), default=0.0)
        #: the farthest a sliding pair's reaction lies from its joint (m)
        self.arm_max = ARM_MAX * lk.length
        if reach > 0.0:
            self.arm_max = min(self.arm_max, REACH_MAX * reach)
        self.reactions: list[Reaction] = []

    def _react(
        self,
        gf: GroupForces,
        of: int,
        on: int,
        F: Vec,
        at: Vec,
        joint: str,
        on_loads: dict[int, list[Applied]],
        sliding: bool = False,
        h: float = 0.0,
        couple: float = 0.0,
    ) -> None:
        """Record the force of ``of`` on ``on``; its opposite goes on ``of``'s loads (an
        earlier link) unless ``of`` is in the group or the frame."""
        r = Reaction(reaction_name(of, on), of, on, F, at, joint, sliding, h, couple)
        gf.reactions.append(r)
        self.reactions.append(r)
        self.c.record(
            f"{r.name} at {joint}" + (f" ({of}→{on})" if sliding else ""),
            f"the force of link {of} on link {on}"
            + (f", normal to the slide, {h:.6g} m along it from {joint}" if sliding else "")
            + (f", and a couple {couple:.6g} N·m" if couple else ""),
            F,
            role="hidden",
        )
        if of != 0 and of not in gf.links:
            vel = self._velocity(of, at)
            on_loads[of].append(
                Applied(
                    reaction_name(on, of),
                    of,
                    "reaction",
                    -F,
                    at,
                    0.0,
                    joint if h == 0.0 else "",
                    vel,
                )
            )
            if couple:
                on_loads[of].append(Applied(f"M_{{{on}{of}}}", of, "reaction", None, None, -couple))

    def _velocity(self, link: int, at: Vec) -> Vec:
        """The velocity of the point of ``link`` at ``at`` (rigid body)."""
        P = self.P
        base = self.lk.link_points(link)[0]
        return P.vel[base] + (at - P.pos[base]).perp() * P.omega[link]

    def rrr(self, g: Group, gf: GroupForces, loads: dict[int, list[Applied]]) -> None:
        c, P, own = self.c, self.P, self.lk.owner
        a, b = g.links
        (E1, E2), J = g.ends, g.joint
        pJ = P.pos[J]
        La, Lb = gf.loads[a], gf.loads[b]
        out: list[tuple[Vec, Vec, float]] = []
        for E, L, link, length in ((E1, La, a, g.lengths[0]), (E2, Lb, b, g.lengths[1])):
            u = (pJ - P.pos[E]).unit()
            t = u.perp()
            M = _moment(L, pJ)
            # (E − J) × (Rτ·t) = −l·Rτ  ⇒  Rτ = M_J(loads)/l
            Rt = c.value(
                f"{g.key}: R^τ_{own[E]}{link}",
                M / length,
                f"ΣM_{J}(link {link}) = 0: R^τ·l_{E}{J} = ΣM_{J} of its loads = {M:.6g} N·m",
                kind="tangential",
                args=_tangential(own[E], link, E, J, M, length),
            )
            out.append((u, t, Rt))
        (u1, t1, Rt1), (u2, t2, Rt2) = out
        o1, o2 = own[E1], own[E2]
        terms: list[Term] = [
            Known(f"R^τ_{{{o1}{a}}}", t1 * Rt1),
            *_knowns(La),
            *_knowns(Lb),
            Known(f"R^τ_{{{o2}{b}}}", t2 * Rt2),
            Unknown(f"R^n_{{{o2}{b}}}", u2),
            Unknown(f"R^n_{{{o1}{a}}}", u1),
        ]
        poly = force_polygon(c, f"{g.key}: force polygon", terms)
        gf.polygons.append((f"{g.key}: force polygon", poly))
        R1 = t1 * Rt1 + u1 * poly.signed(f"R^n_{{{o1}{a}}}")
        R2 = t2 * Rt2 + u2 * poly.signed(f"R^n_{{{o2}{b}}}")
        Rba = _closing(
            c,
            gf,
            f"{g.key}: polygon of link {a}",
            [Known(reaction_name(o1, a), R1), *_knowns(La)],
            reaction_name(b, a),
            f"{reaction_name(o1, a)} + ΣF_{a} + {reaction_name(b, a)} = 0",
        )
        self._react(gf, o1, a, R1, P.pos[E1], E1, loads)
        self._react(gf, o2, b, R2, P.pos[E2], E2, loads)
        self._react(gf, b, a, Rba, pJ, J, loads)

    def rrp(self, g: Group, gf: GroupForces, loads: dict[int, list[Applied]]) -> None:
        c, P, own = self.c, self.P, self.lk.owner
        assert g.guide is not None
        a, b = g.links
        E, J = g.ends[0], g.joint
        pJ, pE = P.pos[J], P.pos[E]
        La, Lb = gf.loads[a], gf.loads[b]
        d = P.slide[b]
        n_dir = d.perp()
        u = (pJ - pE).unit()
        t = u.perp()
        M = _moment(La, pJ)
        Rt = c.value(
            f"{g.key}: R^τ_{own[E]}{a}",
            M / g.lengths[0],
            f"ΣM_{J}(link {a}) = 0: R^τ·l_{E}{J} = ΣM_{J} of its loads = {M:.6g} N·m",
            kind="tangential",
            args=_tangential(own[E], a, E, J, M, g.lengths[0]),
        )
        o, gl = own[E], g.guide.link
        terms: list[Term] = [
            Known(f"R^τ_{{{o}{a}}}", t * Rt),
            *_knowns(La),
            *_knowns(Lb),
            Unknown(reaction_name(gl, b), n_dir),
            Unknown(f"R^n_{{{o}{a}}}", u),
        ]
        poly = force_polygon(c, f"{g.key}: force polygon", terms)
        gf.polygons.append((f"{g.key}: force polygon", poly))
        n = poly.signed(reaction_name(gl, b))
        N = n_dir * n
        R = t * Rt + u * poly.signed(f"R^n_{{{o}{a}}}")
        Rab = _closing(
            c,
            gf,
            f"{g.key}: polygon of link {b}",
            [*_knowns(Lb), Known(reaction_name(gl, b), N)],
            reaction_name(a, b),
            f"ΣF_{b} + {reaction_name(gl, b)} + {reaction_name(a, b)} = 0",
        )
        # the slider about J: ΣM_J(loads) + h·n = 0
        Mb = _moment(Lb, pJ)
        h, m = self._arm(f"{g.key}: h_{gl}{b}", -Mb, n, J, b, reaction_name(gl, b))
        self._react(gf, o, a, R, pE, E, loads)
        self._react(gf, a, b, Rab, pJ, J, loads)
        self._react(gf, gl, b, N, pJ + d * h, J, loads, sliding=True, h=h, couple=m)

    def _arm(
        self, name: str, couple: float, n: float, joint: str, link: int, force: str = "N"
    ) -> tuple[float, float]:
        """h with h·n = couple: the point of a sliding pair's reaction along the slide, and no
        couple; where that point would lie farther than :data:`ARM_MAX` crank lengths (a normal
        force of about zero) or :data:`REACH_MAX` times the mechanism's reach (off any drawing
        of the link), h = 0 and the pair's couple."""
        if n != 0.0 and abs(couple) <= abs(n) * self.arm_max:
            h = couple / n
            self.c.value(
                name,
                h,
                f"ΣM_{joint}(link {link}) = 0: the reaction's point, h m along the slide from "
                f"{joint}",
                kind="slide_arm",
                args={"F": force, "J": joint, "link": link, "value": abs(h)},
            )
            return h, 0.0
        if n != 0.0 and abs(couple) <= abs(n) * ARM_MAX * self.lk.length:
            self.c.value(
                name + " (couple)",
                couple,
                f"ΣM_{joint}(link {link}) = 0: the reaction's point, {abs(couple / n):.4g} m "
                f"along the slide from {joint}, lies off the mechanism: the force at {joint} "
                "and the slide's couple",
                kind="slide_far",
                args={"F": force, "J": joint, "link": link, "value": couple, "h": abs(couple / n)},
            )
            return 0.0, couple
        self.c.value(
            name + " (couple)",
            couple,
            f"ΣM_{joint}(link {link}) = 0: the normal force is about zero, the slide carries a "
            "couple",
            kind="slide_couple",
            args={"F": force, "J": joint, "link": link, "value": couple},
        )
        return 0.0, couple

    def rpr(self, g: Group, gf: GroupForces, loads: dict[int, list[Applied]]) -> None:
        c, P, own = self.c, self.P, self.lk.owner
        a, b = g.links
        A, C = g.slider, g.pivot
        pA, pC = P.pos[A], P.pos[C]
        d = P.slide[a]
        n_dir = d.perp()
        La, Lb = gf.loads[a], gf.loads[b]
        MA = _moment(La, pA)  # the block about A: MA + h·n = 0 (N of b on a at A + h·d)
        MC = _moment(Lb, pC)
        arm = (pA - pC).dot(d)
        n = c.value(
            f"{g.key}: N_{b}{a}",
            (MC + MA) / arm,
            f"ΣM_{C}(link {b}) = 0 with the block's ΣM_{A} = 0: "
            f"N·{arm:.6g} m = ΣM_{C}(link {b}) + ΣM_{A}(block {a})",
            kind="slot_normal",
            args={
                "N": reaction_name(b, a),
                "a": a,
                "b": b,
                "A": A,
                "C": C,
                "M": (MC + MA) if arm > 0.0 else -(MC + MA),
                "arm": abs(arm),
                "value": (MC + MA) / arm,
            },
        )
        N = n_dir * n
        h, m = self._arm(f"{g.key}: h_{b}{a}", -MA, n, A, a, reaction_name(b, a))
        RC = _closing(
            c,
            gf,
            f"{g.key}: polygon of link {b}",
            [*_knowns(Lb), Known(reaction_name(a, b), -N)],
            reaction_name(own[C], b),
            f"ΣF_{b} + {reaction_name(a, b)} + {reaction_name(own[C], b)} = 0",
        )
        RA = _closing(
            c,
            gf,
            f"{g.key}: polygon of link {a}",
            [*_knowns(La), Known(reaction_name(b, a), N)],
            reaction_name(own[A], a),
            f"ΣF_{a} + {reaction_name(b, a)} + {reaction_name(own[A], a)} = 0",
        )
        self._react(gf, own[A], a, RA, pA, A, loads)
        self._react(gf, b, a, N, pA + d * h, A, loads, sliding=True, h=h, couple=m)
        self._react(gf, own[C], b, RC, pC, C, loads)

    def prp(self, g: Group, gf: GroupForces, loads: dict[int, list[Applied]]) -> None:
        c, P, own = self.c, self.P, self.lk.owner
        assert g.guide is not None
        a, b = g.links
        A, E = g.slider, g.joint
        pA, pE = P.pos[A], P.pos[E]
        sdir = P.slide[a]
        gdir = g.guide.direction
        La, Lb = gf.loads[a], gf.loads[b]
        terms: list[Term] = [
            *_knowns(Lb),
            Unknown(reaction_name(a, b), sdir.perp()),
            Unknown(reaction_name(0, b), gdir.perp()),
        ]
        poly = force_polygon(c, f"{g.key}: force polygon of link {b}", terms)
        gf.polygons.append((f"{g.key}: force polygon of link {b}", poly))
        Nab = sdir.perp() * poly.signed(reaction_name(a, b))  # of a on b
        N0b = gdir.perp() * poly.signed(reaction_name(0, b))
        RA = _closing(
            c,
            gf,
            f"{g.key}: polygon of link {a}",
            [*_knowns(La), Known(reaction_name(b, a), -Nab)],
            reaction_name(own[A], a),
            f"ΣF_{a} + {reaction_name(b, a)} + {reaction_name(own[A], a)} = 0",
        )
        # the block about A: ΣM_A + h1·n_ba = 0, N_ba = −N_ab along the slot's normal
        n_ba = -poly.signed(reaction_name(a, b))
        h1, m1 = self._arm(f"{g.key}: h_{b}{a}", -_moment(La, pA), n_ba, A, a, reaction_name(b, a))
        at1 = pA + sdir * h1
        # the yoke about E: ΣM_E(loads) + (at1 − E) × N_ab − m1 + h2·n_0b (+ m2) = 0
        Mb = _moment(Lb, pE) + (at1 - pE).cross(Nab) - m1
        h2, m2 = self._arm(
            f"{g.key}: h_0{b}", -Mb, poly.signed(reaction_name(0, b)), E, b, reaction_name(0, b)
        )
        self._react(gf, own[A], a, RA, pA, A, loads)
        self._react(gf, b, a, -Nab, at1, A, loads, sliding=True, h=h1, couple=m1)
        self._react(gf, 0, b, N0b, pE + gdir * h2, E, loads, sliding=True, h=h2, couple=m2)

    def moment_scale(self, *more: Vec) -> float:
        """The moments' scale (N·m) of the analysis: the largest reaction on the crank's arm (a
        moment within ``tol.REL_LENGTH`` of it is written as 0 in the order of the analysis)."""
        forces = [r.force.norm for r in self.reactions] + [F.norm for F in more]
        return max(forces, default=0.0) * self.lk.length

    def crank(self, gf: GroupForces) -> float:
        c, P, lk = self.c, self.P, self.lk
        pO = P.pos[lk.pivot]
        L1 = gf.loads[1]
        c.record(
            "crank",
            "the crank 1 with the reaction of link 2 and its own loads",
            (1,),
            role="hidden",
            kind="crank",
            args={"O": lk.pivot, "A": lk.joint},
        )
        R01 = _closing(
            c,
            gf,
            "crank: polygon of link 1",
            _knowns(L1),
            reaction_name(0, 1),
            f"ΣF_1 + {reaction_name(0, 1)} = 0",
        )
        M = c.value(
            "M_bal",
            -_moment(L1, pO),
            f"ΣM_{lk.pivot}(link 1) = 0: M_bal = −ΣM_{lk.pivot} of the loads on the crank",
            kind="balancing_moment",
            args={"O": lk.pivot, "value": _clean(-_moment(L1, pO), self.moment_scale(R01))},
        )
        self._react(gf, 0, 1, R01, pO, lk.pivot, {})
        return M


def kinetostatics(lk: Linkage, P: Position, cyc: Cycle | None = None) -> Forces:
    """The kinetostatics of position P (module docstring)."""
    deg = math.degrees(P.phi) % 360.0
    c = Construction(f"{lk.title}: kinetostatics at φ1 = {deg:.6g}°")
    rng = ranges(lk, cyc)
    given = applied_loads(lk, P, rng, c, cyc)
    loads = {i: list(v) for i, v in given.items()}
    sv = _Solver(lk, P, c)
    groups: list[GroupForces] = []
    for g in reversed(lk.groups):
        c.record(
            g.key,
            f"Assur group {g.kind} of links {g.links[0]}, {g.links[1]} cut out with the loads "
            "and the reactions of the links it is cut from",
            g.links,
            role="hidden",
            kind="group",
            args={"a": g.links[0], "b": g.links[1], "type": f"@{g.kind.lower()}"},
        )
        gf = GroupForces(g, g.links, {i: list(loads[i]) for i in g.links})
        {"RRR": sv.rrr, "RRP": sv.rrp, "RPR": sv.rpr, "PRP": sv.prp}[g.kind](g, gf, loads)
        groups.append(gf)
    gf1 = GroupForces(None, (1,), {1: list(loads[1])})
    M_bal = sv.crank(gf1)
    groups.append(gf1)
    scale = sv.moment_scale()
    lever = zhukovsky(lk, P, given, c, scale)
    # relative to M_bal, or to the moments of the analysis where M_bal is about zero (a dead
    # position, where the lever's plan collapses to its pole)
    floor = max(tol.DERIVED * scale, sys.float_info.min)
    off = abs(lever.M_bal - M_bal) / max(abs(M_bal), abs(lever.M_bal), floor)
    off *= 100.0
    c.value(
        "M_bal check",
        off,
        "Zhukovsky's lever against the force analysis: |M_bal_lever − M_bal|/|M_bal|, %",
        kind="lever_check",
        args={"a": _clean(M_bal, scale), "b": _clean(lever.M_bal, scale), "value": round(off, 2)},
    )
    return Forces(P.phi, c, given, groups, sv.reactions, M_bal, lever)


def zhukovsky(
    lk: Linkage,
    P: Position,
    given: dict[int, list[Applied]],
    c: Construction,
    scale: float = 0.0,
) -> Lever:
    """Zhukovsky's lever of position P under the given loads (module docstring); ``scale``
    (N·m): moments below 1e-12 of it are written as 0 in the order of the analysis."""
    images = {name: v.perp() for name, v in P.vel.items()}
    for name, im in images.items():
        c.record(f"lever: {name.lower()}", f"image of {name}: V_{name} turned 90° ccw", im,
                 role="hidden")  # fmt: skip
    items: list[LeverItem] = []
    power = 0.0
    for link, lds in given.items():
        for ld in lds:
            if ld.force is not None:
                assert ld.velocity is not None
                im = ld.velocity.perp()
                m = im.cross(ld.force)
                pt = ld.point or (centre_name(lk, link) if ld.kind in ("weight", "inertia") else "")
                items.append(LeverItem(ld.name, ld.force, im, m, link, pt))
                power += ld.force.dot(ld.velocity)
            else:
                # the couple: ±F ⊥ a segment X–Y of the link at the images of X and Y (its
                # point farthest from X: the couple's arm as long as the link allows)
                w = P.omega[link]
                pts = lk.points_on(link)
                X = P.pos[pts[0]]
                far = max(pts[1:], key=lambda q: P.pos[q].dist(X), default="")
                # a block with one joint: its point coinciding with the farthest point of its
                # group's other link (c2 of block 2 on link 3 at C), lettered so
                g = lk.group_of(link)
                mates = [q for j in (g.links if g else ()) if j != link for q in lk.points_on(j)]
                mate = max(mates, key=lambda q: P.pos[q].dist(X), default="")
                if far and P.pos[far].dist(X) > 0.0:
                    u = P.pos[far] - X
                elif mate and P.pos[mate].dist(X) > 0.0:
                    u = P.pos[mate] - X
                    far = f"{mate}{link}"
                else:
                    far = ""
                    u = (P.slide[link] if link in P.slide else Vec(1.0, 0.0)) * lk.length
                F = u.perp() * (ld.moment / u.dot(u))
                vX = P.vel[pts[0]]
                vY = vX + u.perp() * w
                items.append(LeverItem(ld.name, F, vY.perp(), vY.perp().cross(F), link, far))
                items.append(LeverItem(ld.name, -F, vX.perp(), vX.perp().cross(-F), link, pts[0]))
                power += ld.moment * w
    for k, it in enumerate(items, start=1):
        c.value(
            f"lever: M_p({it.name}) {k}",
            it.moment,
            f"the moment about p of {it.name} at its image ({it.image.x:.6g}, {it.image.y:.6g})",
        )
    total = sum(it.moment for it in items)
    moments = any(ld.force is None for lds in given.values() for ld in lds)
    e = (P.pos[lk.joint] - P.pos[lk.pivot]).unit()
    # F_bal = f·e⊥ at the image of A: its lever moment is −ω1·l·f; the lever balances
    f = total / (lk.omega * lk.length)
    F_bal = e.perp() * f
    M = c.value(
        "M_bal_lever",
        f * lk.length,
        "Zhukovsky's lever: Σ moments about p of the loads at their images + that of the "
        "balancing force ⊥ OA at the image of the crank's joint = 0; M = F_bal·l_OA",
        kind="zhukovsky",
        args={
            # how the loads go onto the lever: forces only, or forces and moments (each
            # on its link's image, as the sheet draws it)
            "loads": "@lever_moments" if moments else "@lever_forces",
            "a": plan_name(lk.joint),
            "OA": f"{lk.pivot}{lk.joint}",
            "F": _clean(f * lk.length, scale) / lk.length,
            "l": lk.length,
            "value": _clean(f * lk.length, scale),
        },
    )
    return Lever(images, items, F_bal, M, power)
