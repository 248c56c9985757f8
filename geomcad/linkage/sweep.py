"""Positions, velocities and accelerations of a linkage over whole arrays of crank angles.

One kernel for any linkage file: the crank, then each group in the file's order, each kind solved
from its own vector equations in closed form over numpy arrays (every position at once), with the
assembly mode fixed for the whole sweep. The equations are those of the plans
(:mod:`geomcad.linkage.plans`), which the tests hold to the same numbers:

- crank: V_A = ω1 × OA, a_A = a^n_AO (ε1 = 0);
- RRR: V_B = V_P1 + V_BP1 (⊥ BP1) = V_P2 + V_BP2 (⊥ BP2), and likewise with a^n + a^τ;
- RRP: V_D = V_B + V_DB (⊥ DB) = V_Dg + V_rel (∥ guide), where D_g is the point of the guide's
  link g under D; a_D = a_Dg + a^k + a^r with a^k = 2ω_g × V_rel (none on a fixed guide);
- RPR: V_A = V_A3 + V_rel (∥ slide), V_A3 = V_C + ω3 × CA; a_A = a_A3 + a^k + a^r,
  a^k = 2ω3 × V_rel; the block turns with link 3;
- PRP: the yoke translates along the guide, V_A = V_E + V_rel (∥ slot), neither link turns.

Every point is an ``(N, 2)`` array; link ω and ε are ``(N,)``. A position where a group cannot
close, or a dead position, raises :class:`~geomcad.errors.NoIntersection` naming the group and the
first crank angle where it happens.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import NoIntersection
from geomcad.kinematics.dyads import cross, dot, perp
from geomcad.linkage.model import Group, Linkage, PointDef

Arr = npt.NDArray[np.float64]

#: The sweep's velocities and accelerations: none, velocities, or both.
Order = int


@dataclass
class State:
    """Positions (``pos``), velocities (``vel``) and accelerations (``acc``) of every point,
    ``(N, 2)`` each, ω and ε of every moving link, the unit slide direction of each link that
    has one (``slide``), and for each sliding pair, keyed by the block's joint, the relative
    velocity along the slide (signed, ``v_rel``) and the Coriolis acceleration (signed, along
    the slide's left normal, ``a_cor``)."""

    phi: Arr
    omega1: float
    pos: dict[str, Arr] = field(default_factory=dict)
    vel: dict[str, Arr] = field(default_factory=dict)
    acc: dict[str, Arr] = field(default_factory=dict)
    omega: dict[int, Arr] = field(default_factory=dict)
    eps: dict[int, Arr] = field(default_factory=dict)
    slide: dict[int, Arr] = field(default_factory=dict)
    v_rel: dict[str, Arr] = field(default_factory=dict)
    a_cor: dict[str, Arr] = field(default_factory=dict)


def _raise(step: str, bad: npt.NDArray[np.bool_], phi: Arr, why: str) -> None:
    if np.any(bad):
        i = int(np.argmax(bad))
        deg = math.degrees(float(phi[i])) % 360.0
        raise NoIntersection(step, f"{why} at the crank angle φ = {deg:.6g}°")


def _unit(v: Arr) -> Arr:
    return np.asarray(v / np.sqrt(dot(v, v))[..., None], dtype=np.float64)


def _solve2(c1: Arr, c2: Arr, rhs: Arr) -> tuple[Arr, Arr]:
    """x, y with x·c1 + y·c2 = rhs, row by row (Cramer's rule)."""
    det = cross(c1, c2)
    return cross(rhs, c2) / det, cross(c1, rhs) / det


def sweep(lk: Linkage, phi: npt.ArrayLike, order: Order = 2) -> State:
    """The linkage at the crank angles ``phi`` (rad): positions, and with ``order`` ≥ 1
    velocities, with ``order`` 2 accelerations too, at the file's constant ω1."""
    ph = np.atleast_1d(np.asarray(phi, dtype=np.float64))
    n = ph.shape[0]
    s = State(ph, lk.omega)
    zeros = np.zeros((n, 2))
    for name, p in lk.frame.items():
        s.pos[name] = np.broadcast_to(np.array([p.x, p.y]), (n, 2))
        s.vel[name] = zeros
        s.acc[name] = zeros
    w1 = lk.omega
    O1 = lk.frame[lk.pivot]
    r = lk.length * np.stack([np.cos(ph), np.sin(ph)], axis=-1)
    s.pos[lk.joint] = np.array([O1.x, O1.y]) + r
    s.omega[1] = np.full(n, w1)
    s.eps[1] = np.zeros(n)
    if order >= 1:
        s.vel[lk.joint] = w1 * perp(r)
    if order >= 2:
        s.acc[lk.joint] = -(w1 * w1) * r
    _points_of(lk, s, 1, order)
    for g in lk.groups:
        _GROUP[g.kind](lk, g, s, order)
        for link in g.links:
            _points_of(lk, s, link, order)
    return s


def _points_of(lk: Linkage, s: State, link: int, order: Order) -> None:
    for p in lk.points:
        if p.link == link:
            point(s, p, order)


def point(s: State, p: PointDef, order: Order) -> None:
    """A ``[[point]]`` of a solved link: P = F + along·u + left·u⊥; V_P = V_F + ω × FP;
    a_P = a_F + ε × FP − ω²·FP."""
    F = s.pos[p.frm]
    u = s.slide[p.link] if p.slide else _unit(s.pos[p.toward] - F)
    r = u * p.along + perp(u) * p.left
    s.pos[p.name] = F + r
    if order >= 1:
        w = s.omega[p.link][..., None]
        s.vel[p.name] = s.vel[p.frm] + w * perp(r)
    if order >= 2:
        w = s.omega[p.link][..., None]
        e = s.eps[p.link][..., None]
        s.acc[p.name] = s.acc[p.frm] + e * perp(r) - (w * w) * r


def _ang(p: Arr, vp: Arr, q: Arr, vq: Arr) -> Arr:
    e = q - p
    return np.asarray(cross(e, vq - vp) / dot(e, e), dtype=np.float64)


def _rrr(lk: Linkage, g: Group, s: State, order: Order) -> None:
    P1, P2 = s.pos[g.ends[0]], s.pos[g.ends[1]]
    l1, l2 = g.lengths
    dv = P2 - P1
    d2 = dot(dv, dv)
    d = np.sqrt(d2)
    _raise(
        g.key,
        d <= tol.REL_LENGTH * (l1 + l2),
        s.phi,
        f"the ends {g.ends[0]} and {g.ends[1]} coincide",
    )
    a = (l1 * l1 - l2 * l2 + d2) / (2.0 * d)
    h2 = l1 * l1 - a * a
    _raise(
        f"{g.key}: {g.joint} = circle({g.ends[0]}, {l1:g}) ∩ circle({g.ends[1]}, {l2:g})",
        ~(h2 >= -tol.TANGENT * max(l1, l2) ** 2),
        s.phi,
        "the group cannot close: the circles do not meet",
    )
    u = dv / d[..., None]
    B = P1 + u * a[..., None] + perp(u) * (g.branch * np.sqrt(np.maximum(h2, 0.0)))[..., None]
    s.pos[g.joint] = B
    if order < 1:
        return
    V1, V2 = s.vel[g.ends[0]], s.vel[g.ends[1]]
    e1, e2 = B - P1, B - P2
    det = cross(e1, e2)
    _raise(
        f"{g.key}: velocity plan point {g.joint.lower()}",
        np.abs(det) <= tol.ANGLE * l1 * l2,
        s.phi,
        "a dead position: the group's links are collinear",
    )
    VB = np.stack(_solve_dot(e1, e2, dot(e1, V1), dot(e2, V2), det), axis=-1)
    s.vel[g.joint] = VB
    a_, b_ = g.links
    s.omega[a_] = _ang(P1, V1, B, VB)
    s.omega[b_] = _ang(P2, V2, B, VB)
    if order < 2:
        return
    A1, A2 = s.acc[g.ends[0]], s.acc[g.ends[1]]
    u1, u2 = VB - V1, VB - V2
    aB = np.stack(
        _solve_dot(e1, e2, dot(e1, A1) - dot(u1, u1), dot(e2, A2) - dot(u2, u2), det), axis=-1
    )
    s.acc[g.joint] = aB
    s.eps[a_] = _ang(P1, A1, B, aB)
    s.eps[b_] = _ang(P2, A2, B, aB)


def _solve_dot(e1: Arr, e2: Arr, r1: Arr, r2: Arr, det: Arr) -> tuple[Arr, Arr]:
    """x with e1·x = r1 and e2·x = r2, row by row."""
    return (r1 * e2[..., 1] - r2 * e1[..., 1]) / det, (e1[..., 0] * r2 - e2[..., 0] * r1) / det


def guide_line(lk: Linkage, g: Group, s: State) -> tuple[Arr, Arr]:
    """The guide of an RRP/PRP group in every position: a point q on it and its unit
    direction d (a guide on a moving link: from → toward, shifted ``offset`` to the left)."""
    gd = g.guide
    assert gd is not None
    n = s.phi.shape[0]
    if gd.fixed:
        gdir = gd.direction
        return (
            np.broadcast_to(np.array([gd.through.x, gd.through.y]), (n, 2)),
            np.broadcast_to(np.array([gdir.x, gdir.y]), (n, 2)),
        )
    F, T = s.pos[gd.frm], s.pos[gd.toward]
    _raise(
        f"{g.key}: guide",
        dot(T - F, T - F) <= (tol.REL_LENGTH * lk.length) ** 2,
        s.phi,
        f"the guide's points {gd.frm} and {gd.toward} coincide",
    )
    d = _unit(T - F)
    return F + perp(d) * gd.offset, d


def _rrp(lk: Linkage, g: Group, s: State, order: Order) -> None:
    gd = g.guide
    assert gd is not None
    B = s.pos[g.ends[0]]
    (length,) = g.lengths
    q, d = guide_line(lk, g, s)
    t0 = dot(B - q, d)
    h = cross(d, B - q)
    w2 = length * length - h * h
    _raise(
        f"{g.key}: {g.joint} = circle({g.ends[0]}, {length:g}) ∩ guide",
        ~(w2 >= -tol.TANGENT * length * length),
        s.phi,
        "the group cannot close: the guide misses the circle",
    )
    D = q + d * (t0 + g.branch * np.sqrt(np.maximum(w2, 0.0)))[..., None]
    s.pos[g.joint] = D
    rod, slider = g.links
    s.slide[slider] = d
    if order < 1:
        return
    n = s.phi.shape[0]
    wg = s.omega[gd.link] if not gd.fixed else np.zeros(n)
    VB = s.vel[g.ends[0]]
    if gd.fixed:
        VDg = np.zeros((n, 2))
    else:
        rF = D - s.pos[gd.frm]
        VDg = s.vel[gd.frm] + wg[..., None] * perp(rF)
    e = D - B
    den = dot(e, d)
    _raise(
        f"{g.key}: velocity plan point {g.joint.lower()}",
        np.abs(den) <= tol.ANGLE * length,
        s.phi,
        "a dead position: the rod is perpendicular to the guide",
    )
    vr = dot(e, VB - VDg) / den
    VD = VDg + d * vr[..., None]
    s.vel[g.joint] = VD
    s.omega[rod] = _ang(B, VB, D, VD)
    s.omega[slider] = wg
    s.v_rel[g.joint] = vr
    s.a_cor[g.joint] = 2.0 * wg * vr
    if order < 2:
        return
    aB = s.acc[g.ends[0]]
    if gd.fixed:
        aDg = np.zeros((n, 2))
        eg = np.zeros(n)
    else:
        eg = s.eps[gd.link]
        aDg = s.acc[gd.frm] + eg[..., None] * perp(rF) - (wg * wg)[..., None] * rF
    acor = perp(d) * (2.0 * wg * vr)[..., None]
    u = VD - VB
    ar = (dot(e, aB - aDg - acor) - dot(u, u)) / den
    aD = aDg + acor + d * ar[..., None]
    s.acc[g.joint] = aD
    s.eps[rod] = _ang(B, aB, D, aD)
    s.eps[slider] = eg


def rpr_direction(A: Arr, C: Arr, offset: float, step: str, phi: Arr) -> Arr:
    """The slide line's unit direction of an RPR group: through A, ``offset`` to the left of C
    looking from C towards A, directed from C's foot to A."""
    r = A - C
    L2 = dot(r, r)
    t2 = L2 - offset * offset
    _raise(
        step,
        ~(t2 > tol.REL_LENGTH * L2),
        phi,
        f"the slider comes within the offset {abs(offset):g} m of the pivot",
    )
    t = np.sqrt(t2)
    return np.asarray((r * t[..., None] - perp(r) * offset) / L2[..., None], dtype=np.float64)


def _rpr(lk: Linkage, g: Group, s: State, order: Order) -> None:
    A, C = s.pos[g.slider], s.pos[g.pivot]
    d = rpr_direction(A, C, g.offset, f"{g.key}: slide line through {g.slider}", s.phi)
    block, rocker = g.links
    s.slide[block] = d
    s.slide[rocker] = d
    if order < 1:
        return
    r = A - C
    VA, VC = s.vel[g.slider], s.vel[g.pivot]
    w3, vr = _solve2(perp(r), d, VA - VC)
    s.omega[block] = w3
    s.omega[rocker] = w3
    s.v_rel[g.slider] = vr
    s.a_cor[g.slider] = 2.0 * w3 * vr
    if order < 2:
        return
    aA, aC = s.acc[g.slider], s.acc[g.pivot]
    rhs = aA - aC + (w3 * w3)[..., None] * r - perp(d) * (2.0 * w3 * vr)[..., None]
    e3, _ = _solve2(perp(r), d, rhs)
    s.eps[block] = e3
    s.eps[rocker] = e3


def prp_frame(g: Group) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A PRP group's guide point, guide direction and slot direction (unit vectors)."""
    gd = g.guide
    assert gd is not None
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    return (
        np.array([gd.through.x, gd.through.y]),
        np.array([gdir.x, gdir.y]),
        np.array([sdir.x, sdir.y]),
    )


def _prp(lk: Linkage, g: Group, s: State, order: Order) -> None:
    q, gv, sv = prp_frame(g)
    n = s.phi.shape[0]
    G = np.broadcast_to(gv, (n, 2))
    S = np.broadcast_to(sv, (n, 2))
    A = s.pos[g.slider]
    t, _ = _solve2(G, S, A - q)
    s.pos[g.joint] = q + G * t[..., None]
    block, yoke = g.links
    s.slide[block] = S
    s.slide[yoke] = S
    if order < 1:
        return
    v, w = _solve2(G, S, s.vel[g.slider])
    s.vel[g.joint] = G * v[..., None]
    for link in g.links:
        s.omega[link] = np.zeros(n)
    s.v_rel[g.slider] = w
    s.a_cor[g.slider] = np.zeros(n)
    s.v_rel[g.joint] = v
    s.a_cor[g.joint] = np.zeros(n)
    if order < 2:
        return
    a, _ = _solve2(G, S, s.acc[g.slider])
    s.acc[g.joint] = G * a[..., None]
    for link in g.links:
        s.eps[link] = np.zeros(n)


_GROUP = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp}


def output_coordinate(lk: Linkage, s: State) -> Arr | None:
    """s of the output slider along its guide (m), or ``None`` when the output is no slider."""
    g = lk.output_guide
    if g is None:
        return None
    P = s.pos[lk.output]
    q, d = (
        guide_line(lk, g, s)
        if g.kind == "RRP"
        else (np.broadcast_to(prp_frame(g)[0], P.shape), np.broadcast_to(prp_frame(g)[1], P.shape))
    )
    return np.asarray(dot(P - q, d), dtype=np.float64)


def output_velocity(lk: Linkage, s: State) -> Arr | None:
    """ds/dt of the output slider along its guide (its relative velocity on a moving guide)."""
    g = lk.output_guide
    if g is None:
        return None
    return s.v_rel[lk.output]
