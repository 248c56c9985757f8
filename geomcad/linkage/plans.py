"""A linkage at one crank angle: its position constructed, its velocity and acceleration plans.

Every step is recorded in one :class:`~geomcad.construction.Construction` (``--trace`` prints
it): the position of each joint by an exact construction (circle ∩ circle for an RRR, circle ∩
guide for an RRP, the slide line through the slider for an RPR, slot ∩ guide for a PRP), then
the velocity plan (pole p) and the acceleration plan (pole π) group by group from their vector
equations (:mod:`geomcad.kinematics.plan`). The values of :class:`Position` are read off those
plans: the plan on the sheet is the solution.

Plan points take the lower-case name of their point (``b``; ``b'`` on the acceleration plan); the
point of a link that coincides with a block's joint takes the link's number (``a3``: the point of
link 3 under A); a point whose lower-case name is the pole's (``p``) is written ``p_P``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from geomcad import tol
from geomcad.construction import Construction, Index
from geomcad.geom import Line, Vec
from geomcad.kinematics.plan import (
    Plan,
    Side,
    Term,
    acceleration_plan,
    coriolis,
    normal,
    velocity_plan,
)
from geomcad.linkage.model import Group, Linkage, PointDef
from geomcad.linkage.sweep import rpr_direction


def plan_name(point: str, taken: frozenset[str] = frozenset(), link: int = 0) -> str:
    """The plan point of a mechanism point: ``B`` → ``b``. Where the lower-case letter is the
    pole's (p) or a mechanism point's own name (``taken``), the letter with the number of the
    point's ``link`` as its index, as the images of a slider's coincident points are written
    (P of link 2 → ``p2``, drawn p₂; its step says whose image it is); ``p_P`` where that is
    taken too (or the point is the frame's)."""
    low = point.lower()
    if low not in ("p", "π") and low not in taken:
        return low
    indexed = f"{low}{link}"
    if link > 0 and not low[-1:].isdigit() and indexed not in {t.lower() for t in taken}:
        return indexed
    return f"p_{point}"


def _sub(name: str) -> str:
    """Label markup: a name's trailing digits as a subscript (``S2`` → ``S_{2}``)."""
    head = name.rstrip("0123456789")
    tail = name[len(head) :]
    return f"{head}_{{{tail}}}" if tail and head else name


@dataclass
class Position:
    """The linkage at crank angle ``phi`` (rad): the construction, both plans, and the values read
    off them (SI units; points keyed by name, links by number; sliding pairs by the block's
    joint: ``v_rel`` signed along the slide, ``a_cor`` the Coriolis vector)."""

    phi: float
    c: Construction
    vp: Plan
    ap: Plan
    pos: dict[str, Vec] = field(default_factory=dict)
    vel: dict[str, Vec] = field(default_factory=dict)
    acc: dict[str, Vec] = field(default_factory=dict)
    omega: dict[int, float] = field(default_factory=dict)
    eps: dict[int, float] = field(default_factory=dict)
    slide: dict[int, Vec] = field(default_factory=dict)
    v_rel: dict[str, float] = field(default_factory=dict)
    a_cor: dict[str, Vec] = field(default_factory=dict)
    #: per link, its points on the plans: (mechanism point, plan point) pairs
    handles: dict[int, list[tuple[str, str]]] = field(default_factory=dict)
    #: the guide line of each RRP/PRP group and the slide line of each RPR group, by group index
    lines: dict[int, Line] = field(default_factory=dict)
    #: the mechanism's point names, which plan points must not take
    taken: frozenset[str] = frozenset()
    #: the link of each mechanism point (0: the frame's)
    owner: dict[str, int] = field(default_factory=dict)

    def pn(self, point: str) -> str:
        """The plan point of a mechanism point (:func:`plan_name`)."""
        name = plan_name(point, self.taken, self.owner.get(point, 0))
        if name != point.lower():
            self.vp.models[name] = self.ap.models[name] = point
        return name


def construct(lk: Linkage, phi: float, title: str = "") -> Position:
    """Construct the linkage at crank angle ``phi`` (rad) with its plans (module docstring)."""
    deg = math.degrees(phi) % 360.0
    c = Construction(title or f"{lk.title}, φ1 = {deg:.6g}°")
    frame = {name: c.point(name, p, op="a frame point") for name, p in lk.frame.items()}
    vp = velocity_plan(c)
    P = Position(phi, c, vp, acceleration_plan(c, velocity=vp))
    P.taken = frozenset(lk.owner)
    P.owner = dict(lk.owner)
    P.pos.update(frame)
    _crank(lk, P)
    _points(lk, P, 1)
    for g in lk.groups:
        {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp}[g.kind](lk, g, P)
        for link in g.links:
            _points(lk, P, link)
    return P


def _on_plans(P: Position, point: str) -> str:
    """The plan point of ``point``, adding a frame point at both poles when first needed."""
    n = P.pn(point)
    if P.vp.name(n) not in P.vp.points:
        P.vp.fixed(n)
        P.ap.fixed(n)
        P.vel[point] = Vec(0.0, 0.0)
        P.acc[point] = Vec(0.0, 0.0)
    return n


def _crank(lk: Linkage, P: Position) -> None:
    O1 = P.pos[lk.pivot]
    A = O1 + Vec.polar(lk.length, P.phi)
    P.pos[lk.joint] = P.c.point(
        lk.joint,
        A,
        role="link",
        op=f"{lk.pivot} + l_{lk.pivot}{lk.joint} = {lk.length:g} m "
        f"at φ1 = {math.degrees(P.phi) % 360:.6g}°",
    )
    o = _on_plans(P, lk.pivot)
    a = P.pn(lk.joint)
    w1 = lk.omega
    nm = f"{lk.joint}{lk.pivot}"
    model = (lk.pivot, lk.joint)
    why = f"ω1 × {lk.pivot}{lk.joint}"
    P.vel[lk.joint] = P.vp.rigid(a, o, O1, A, w1, f"V_{{{lk.joint}}}", why, 1, model)
    # a_A = a^n_AO1 = ω1²·l from A to O1 (the crank turns evenly: ε1 = 0)
    P.acc[lk.joint] = P.ap.rigid_acc(a, o, O1, A, w1, 0.0, f"a^n_{{{nm}}}", why, 1, model)
    P.omega[1], P.eps[1] = w1, 0.0
    P.handles[1] = [(lk.pivot, o), (lk.joint, a)]


def _points(lk: Linkage, P: Position, link: int) -> None:
    for p in lk.points:
        if p.link == link:
            _point(P, p)


def _point(P: Position, p: PointDef) -> None:
    F = P.pos[p.frm]
    u = P.slide[p.link] if p.slide else (P.pos[p.toward] - F).unit()
    pos = F + u * p.along + u.perp() * p.left
    how = "the slide's direction" if p.slide else f"{p.frm}{p.toward}"
    P.pos[p.name] = P.c.point(
        p.name,
        pos,
        role="link",
        op=f"{p.along:g} m from {p.frm} along {how}, {p.left:g} m to its left",
    )
    n = P.pn(p.name)
    handles = P.handles[p.link]
    (A, a), far = handles[0], None
    for B, b in handles[1:]:
        if P.pos[A].dist(P.pos[B]) > tol.REL_LENGTH * 1.0e3 * max(P.pos[A].norm, 1.0):
            far = (B, b)
            break
    why = f"link {p.link}"
    if far is not None:
        B, b = far
        m3 = (A, B, p.name)
        P.vel[p.name] = P.vp.image(n, a, b, P.pos[A], P.pos[B], pos, why=why, model=m3)
        P.acc[p.name] = P.ap.image(n, a, b, P.pos[A], P.pos[B], pos, why=why, model=m3)
    else:
        w, e = P.omega[p.link], P.eps[p.link]
        label = f"{p.name}{A}"
        m2 = (A, p.name)
        P.vel[p.name] = P.vp.rigid(n, a, P.pos[A], pos, w, f"V_{{{label}}}", why, p.link, m2)
        P.acc[p.name] = P.ap.rigid_acc(n, a, P.pos[A], pos, w, e, f"a_{{{label}}}", why, p.link, m2)
    handles.append((p.name, n))


def _rrr(lk: Linkage, g: Group, P: Position) -> None:
    c = P.c
    (E1, E2), (l1, l2), J = g.ends, g.lengths, g.joint
    k1 = c.circle(f"k_{J}{E1}", P.pos[E1], l1, r_name=f"l_{E1}{J} = {l1:g}")
    k2 = c.circle(f"k_{J}{E2}", P.pos[E2], l2, r_name=f"l_{E2}{J} = {l2:g}")
    side = "left" if g.branch > 0 else "right"
    B = c.intersect(
        J,
        k1,
        k2,
        rule=Index(0 if g.branch > 0 else 1),
        role="link",
        note=f"{g.key}, assembly {side}: {J} on the {side} of {E1}{E2}",
    )
    P.pos[J] = B
    e1, e2, j = _on_plans(P, E1), _on_plans(P, E2), P.pn(J)
    A1, A2 = P.pos[E1], P.pos[E2]
    vp, ap = P.vp, P.ap
    vp.solve(
        j,
        Side(e1, B - A1, f"⊥ {E1}{J}", perpendicular=True),
        Side(e2, B - A2, f"⊥ {E2}{J}", perpendicular=True),
    )
    vp.unknown(e1, j, f"V_{{{J}{E1}}}", f"V_{J}{E1} ⊥ {E1}{J}")
    vp.unknown(e2, j, f"V_{{{J}{E2}}}", f"V_{J}{E2} ⊥ {E2}{J}")
    P.vel[J] = vp.absolute(j, f"V_{{{J}}}")
    a, b = g.links
    P.omega[a] = vp.omega(A1, B, e1, j, f"ω{a}", a, (E1, J))
    P.omega[b] = vp.omega(A2, B, e2, j, f"ω{b}", b, (E2, J))
    n1 = normal(
        P.omega[a], B, A1, f"n_{J}{E1}", f"a^n_{{{J}{E1}}}", f"a^n_{J}{E1} ∥ {J}{E1}", a, (J, E1)
    )
    n2 = normal(
        P.omega[b], B, A2, f"n_{J}{E2}", f"a^n_{{{J}{E2}}}", f"a^n_{J}{E2} ∥ {J}{E2}", b, (J, E2)
    )
    ap.solve(
        j,
        Side(e1, B - A1, f"⊥ {E1}{J}", perpendicular=True, terms=(n1,)),
        Side(e2, B - A2, f"⊥ {E2}{J}", perpendicular=True, terms=(n2,)),
    )
    ap.unknown(n1.head, j, f"a^τ_{{{J}{E1}}}", f"a^τ_{J}{E1} ⊥ {E1}{J}")
    ap.unknown(n2.head, j, f"a^τ_{{{J}{E2}}}", f"a^τ_{J}{E2} ⊥ {E2}{J}")
    P.acc[J] = ap.absolute(j, f"a_{{{J}}}")
    P.eps[a] = ap.omega(A1, B, e1, j, f"ε{a}", a, (E1, J))
    P.eps[b] = ap.omega(A2, B, e2, j, f"ε{b}", b, (E2, J))
    P.handles[a] = [(E1, e1), (J, j)]
    P.handles[b] = [(E2, e2), (J, j)]


def _coincident(P: Position, link: int, point: str, name: str) -> tuple[Vec, Vec]:
    """The velocity and acceleration of the point of ``link`` under ``point``, put on the plans
    as ``name`` (by similarity, or ω × r where the link has one plan point)."""
    pos = P.pos[point]
    handles = P.handles[link]
    (A, a) = handles[0]
    for B, b in handles[1:]:
        if P.pos[A].dist(P.pos[B]) > tol.REL_LENGTH * 1.0e3 * max(P.pos[A].norm, 1.0):
            why = f"the point of link {link} under {point}"
            m3 = (A, B, f"{point}{link}")
            return (
                P.vp.image(name, a, b, P.pos[A], P.pos[B], pos, why=why, model=m3),
                P.ap.image(name, a, b, P.pos[A], P.pos[B], pos, why=why, model=m3),
            )
    w, e = P.omega[link], P.eps[link]
    why = f"the point of link {link} under {point}"
    m2 = (A, f"{point}{link}")
    return (
        P.vp.rigid(name, a, P.pos[A], pos, w, f"V_{{{point}{link}{A}}}", why, link, m2),
        P.ap.rigid_acc(name, a, P.pos[A], pos, w, e, f"a_{{{point}{link}{A}}}", why, link, m2),
    )


def _rrp(lk: Linkage, g: Group, P: Position) -> None:
    c = P.c
    gd = g.guide
    assert gd is not None
    E, J = g.ends[0], g.joint
    (rod_l,) = g.lengths
    if gd.fixed:
        q, d = gd.through, gd.direction
        op = f"the guide through ({q.x:g}, {q.y:g}) at {math.degrees(gd.angle):g}°"
    else:
        F, T = P.pos[gd.frm], P.pos[gd.toward]
        d = (T - F).unit()
        q = F + d.perp() * gd.offset
        op = f"the guide on link {gd.link}: ∥ {gd.frm}{gd.toward}, {gd.offset:g} m to its left"
    guide = c.line(f"guide_{J}", q, d, op, role="aux")
    P.lines[g.index] = guide
    k = c.circle(f"k_{J}{E}", P.pos[E], rod_l, r_name=f"l_{E}{J} = {rod_l:g}")
    way = "forward" if g.branch > 0 else "backward"
    D = c.intersect(
        J,
        guide,
        k,
        rule=Index(1 if g.branch > 0 else 0),
        role="link",
        note=f"{g.key}, assembly {way}: {J} {'ahead of' if g.branch > 0 else 'behind'} {E}'s foot",
    )
    P.pos[J] = D
    B = P.pos[E]
    rod, slider = g.links
    P.slide[slider] = d
    e, j = _on_plans(P, E), P.pn(J)
    vp, ap = P.vp, P.ap
    if gd.fixed:
        wg = eg = 0.0
        jg = jga = vp.pole  # the guide's points are at rest: at the poles
        jga = ap.pole
    else:
        jg = f"{j}{gd.link}"
        _coincident(P, gd.link, J, jg)
        jga = jg
        wg, eg = P.omega[gd.link], P.eps[gd.link]
    along = "@guide" if gd.fixed else f"{gd.frm}{gd.toward}"
    vp.solve(
        j,
        Side(e, D - B, f"⊥ {E}{J}", perpendicular=True),
        Side(jg, d, "∥ the guide", line=along),
    )
    vp.unknown(e, j, f"V_{{{J}{E}}}", f"V_{J}{E} ⊥ {E}{J}")
    V_rel = vp.between(jg, j)
    if not gd.fixed:
        vp.unknown(jg, j, f"V_{{{J}{J}{gd.link}}}", f"V_{J}{J}{gd.link} ∥ the guide")
    P.vel[J] = vp.absolute(j, f"V_{{{J}}}")
    P.v_rel[J] = V_rel.dot(d)
    P.omega[rod] = vp.omega(B, D, e, j, f"ω{rod}", rod, (E, J))
    P.omega[slider] = wg
    nr = normal(
        P.omega[rod], D, B, f"n_{J}{E}", f"a^n_{{{J}{E}}}", f"a^n_{J}{E} ∥ {J}{E}", rod, (J, E)
    )
    terms: tuple[Term, ...] = ()
    if not gd.fixed:
        k_term = coriolis(
            wg,
            V_rel,
            f"k_{J}",
            f"a^k_{{{J}{J}{gd.link}}}",
            f"a^k = 2ω{gd.link} × V_rel",
            gd.link,
            f"V_{{{J}{J}{gd.link}}}",
        )
        terms = (k_term,)
        P.a_cor[J] = k_term.value
    else:
        P.a_cor[J] = Vec(0.0, 0.0)
    ap.solve(
        j,
        Side(e, D - B, f"⊥ {E}{J}", perpendicular=True, terms=(nr,)),
        Side(jga, d, "∥ the guide", terms=terms, line=along),
    )
    ap.unknown(nr.head, j, f"a^τ_{{{J}{E}}}", f"a^τ_{J}{E} ⊥ {E}{J}")
    P.acc[J] = ap.absolute(j, f"a_{{{J}}}")
    P.eps[rod] = ap.omega(B, D, e, j, f"ε{rod}", rod, (E, J))
    P.eps[slider] = eg
    P.handles[rod] = [(E, e), (J, j)]
    P.handles[slider] = [(J, j)]


def _rpr(lk: Linkage, g: Group, P: Position) -> None:
    import numpy as np

    c = P.c
    S, C = g.slider, g.pivot
    A, Cp = P.pos[S], P.pos[C]
    step = f"{g.key}: slide line through {S}"
    arr = rpr_direction(
        np.array([[A.x, A.y]]), np.array([[Cp.x, Cp.y]]), g.offset, step, np.array([P.phi])
    )
    d = Vec(float(arr[0, 0]), float(arr[0, 1]))
    if g.offset == 0.0:
        op = f"line {C}{S} (the slide line through the pivot)"
    else:
        side = "right" if g.offset > 0 else "left"
        op = f"line through {S} tangent to circle({C}, {abs(g.offset):g}), {C} on its {side}"
    line = c.line(f"slide_{S}", A, d, op, role="aux")
    P.lines[g.index] = line
    block, rocker = g.links
    P.slide[block] = d
    P.slide[rocker] = d
    s, cn = _on_plans(P, S), _on_plans(P, C)
    s3 = f"{s}{rocker}"
    vp, ap = P.vp, P.ap
    r = A - Cp
    along = f"{C}{S}" if g.offset == 0.0 else "@slide"
    vp.solve(
        s3,
        Side(cn, r, f"⊥ {C}{S}", perpendicular=True),
        Side(s, d, "∥ the slide", line=along),
    )
    vp.unknown(cn, s3, f"V_{{{S}{rocker}{C}}}", f"V_{S}{rocker}{C} ⊥ {C}{S}")
    vp.unknown(s3, s, f"V_{{{S}{S}{rocker}}}", f"V_{S}{S}{rocker} ∥ the slide")
    V_rel = vp.between(s3, s)
    s3m = f"{S}{rocker}"
    w3 = vp.omega(Cp, A, cn, s3, f"ω{rocker}", rocker, (C, s3m))
    P.omega[block] = P.omega[rocker] = w3
    P.v_rel[S] = V_rel.dot(d)
    k_term = coriolis(w3, V_rel, f"k_{S}", f"a^k_{{{S}{S}{rocker}}}", f"a^k = 2ω{rocker} × V_rel")
    P.a_cor[S] = k_term.value
    # the Coriolis term of S3 about the block: 2ω3 × V_S3S = −a^k_SS3
    minus_k = coriolis(
        w3,
        -V_rel,
        k_term.head,
        f"a^k_{{{s3m}{S}}}",
        f"a^k_{s3m}{S} = 2ω{rocker} × V_{s3m}{S}",
        rocker,
        f"V_{{{s3m}{S}}}",
    )
    nr = normal(
        w3,
        A,
        Cp,
        f"n_{S}{rocker}{C}",
        f"a^n_{{{S}{rocker}{C}}}",
        f"a^n_{S}{rocker}{C} ∥ {S}{C}",
        rocker,
        (s3m, C),
    )
    ap.solve(
        s3,
        Side(cn, r, f"⊥ {C}{S}", perpendicular=True, terms=(nr,)),
        Side(s, d, "∥ the slide", terms=(minus_k,), line=along),
    )
    ap.unknown(nr.head, s3, f"a^τ_{{{S}{rocker}{C}}}", f"a^τ ⊥ {C}{S}")
    e3 = ap.omega(Cp, A, cn, s3, f"ε{rocker}", rocker, (C, s3m))
    P.eps[block] = P.eps[rocker] = e3
    P.handles[block] = [(S, s)]
    P.handles[rocker] = [(C, cn), (S, s3)]


def _prp(lk: Linkage, g: Group, P: Position) -> None:
    c = P.c
    gd = g.guide
    assert gd is not None
    S, J = g.slider, g.joint
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    guide = c.line(
        f"guide_{J}",
        gd.through,
        gdir,
        f"the guide through ({gd.through.x:g}, {gd.through.y:g}) at {math.degrees(gd.angle):g}°",
        role="aux",
    )
    slot = c.line(
        f"slot_{S}",
        P.pos[S],
        sdir,
        f"the slot through {S} at {math.degrees(g.slot_angle):g}° to the guide",
        role="aux",
    )
    P.lines[g.index] = guide
    E = c.intersect(J, slot, guide, role="link", note=f"{g.key}: the yoke's reference point")
    P.pos[J] = E
    block, yoke = g.links
    P.slide[block] = P.slide[yoke] = sdir
    s, j = _on_plans(P, S), P.pn(J)
    vp, ap = P.vp, P.ap
    guide_side = Side(vp.pole, gdir, "∥ the guide", line="@guide")
    slot_side = Side(s, sdir, "∥ the slot", line="@slot")
    vp.solve(j, guide_side, slot_side)
    P.vel[J] = vp.absolute(j, f"V_{{{J}}}")
    vp.unknown(j, s, f"V_{{{S}{S}{yoke}}}", f"V_{S}{S}{yoke} ∥ the slot")
    ap.solve(j, replace(guide_side, start=ap.pole), slot_side)
    P.acc[J] = ap.absolute(j, f"a_{{{J}}}")
    ap.unknown(j, s, f"a^r_{{{S}{S}{yoke}}}", "a^r ∥ the slot")
    for link in g.links:
        P.omega[link] = P.eps[link] = 0.0
    P.v_rel[S] = vp.between(j, s).dot(sdir)
    P.v_rel[J] = P.vel[J].dot(gdir)
    P.a_cor[S] = P.a_cor[J] = Vec(0.0, 0.0)
    P.handles[block] = [(S, s)]
    P.handles[yoke] = [(J, j), (S, j)]
