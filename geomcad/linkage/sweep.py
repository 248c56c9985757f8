"""Positions, velocities and accelerations of a linkage over whole arrays of crank angles.

A linkage file's mechanism is compiled once into a plan (:class:`geomcad.kinematics.chain.Chain`:
the crank, then each group in the file's order with the named points of its links) and swept by
the one kernel of :mod:`geomcad.kinematics.chain`, every group kind from its own vector equations
(those of the plans, :mod:`geomcad.linkage.plans`, which the tests hold to the same numbers),
Coriolis terms included, the assembly mode of each group fixed for the whole sweep.

:class:`State` shows every point as an ``(N, 2)`` float array, link ω and ε as ``(N,)``. A
position where a group cannot close, or a dead position, raises
:class:`~geomcad.errors.NoIntersection` naming the group and the first crank angle where it
happens.
"""

from __future__ import annotations

import weakref

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import NoIntersection
from geomcad.kinematics.chain import (
    BLOCK,
    RPR,
    RRP,
    RRR,
    Chain,
    Crank,
    FixedGuide,
    MovingGuide,
    Point,
    State,
    Step,
    run,
)
from geomcad.kinematics.chain import (
    PRP as PRPStep,
)
from geomcad.linkage.model import Group, Linkage

Arr = npt.NDArray[np.float64]

__all__ = [
    "BLOCK",
    "State",
    "guide_line",
    "output_coordinate",
    "output_velocity",
    "plan",
    "prp_frame",
    "rocker_angle",
    "rpr_direction",
    "sweep",
]

#: Compiled plans of the linkages swept lately, by identity.
_PLANS: dict[int, tuple[weakref.ref[Linkage], Chain]] = {}
_PLANS_MAX = 64


def plan(lk: Linkage) -> Chain:
    """The linkage as the kernel's plan: frame points, the crank, then each group followed by
    the ``[[point]]`` points of its links (compiled once per linkage object)."""
    hit = _PLANS.get(id(lk))
    if hit is not None and hit[0]() is lk:
        return hit[1]
    steps: list[Step] = []
    on = {link: [p for p in lk.points if p.link == link] for link in lk.moving_links}

    def points(link: int) -> None:
        steps.extend(
            Point(p.name, p.link, p.frm, "" if p.slide else p.toward, p.along, p.left)
            for p in on.get(link, ())
        )

    points(1)
    for g in lk.groups:
        steps.append(_step(g))
        for link in g.links:
            points(link)
    chain = Chain(
        {k: (v.x, v.y) for k, v in lk.frame.items()},
        Crank(lk.pivot, lk.joint, lk.length, lk.omega),
        tuple(steps),
    )
    if len(_PLANS) >= _PLANS_MAX:
        _PLANS.clear()
    _PLANS[id(lk)] = (weakref.ref(lk), chain)
    return chain


def _step(g: Group) -> Step:
    dead = f"{g.key}: velocity plan point {g.joint.lower()}"
    if g.kind == "RRR":
        (e0, e1), (l1, l2) = g.ends, g.lengths
        step = f"{g.key}: {g.joint} = circle({e0}, {l1:g}) ∩ circle({e1}, {l2:g})"
        return RRR(g.joint, (e0, e1), (l1, l2), g.branch, g.links, step, dead)
    gd = g.guide
    if g.kind == "RRP":
        assert gd is not None
        (length,) = g.lengths
        guide: FixedGuide | MovingGuide
        if gd.fixed:
            d = gd.direction
            guide = FixedGuide((gd.through.x, gd.through.y), (d.x, d.y))
        else:
            guide = MovingGuide(gd.frm, gd.toward, gd.offset, gd.link)
        step = f"{g.key}: {g.joint} = circle({g.ends[0]}, {length:g}) ∩ guide"
        return RRP(
            g.joint, g.ends[0], length, g.branch, g.links, guide, step, dead, f"{g.key}: guide"
        )
    if g.kind == "RPR":
        return RPR(g.slider, g.pivot, g.offset, g.links, f"{g.key}: slide line through {g.slider}")
    assert gd is not None
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    return PRPStep(
        g.joint,
        g.slider,
        (gd.through.x, gd.through.y),
        (gdir.x, gdir.y),
        (sdir.x, sdir.y),
        g.links,
    )


def sweep(lk: Linkage, phi: npt.ArrayLike, order: int = 2) -> State:
    """The linkage at the crank angles ``phi`` (rad): positions, and with ``order`` ≥ 1
    velocities, with ``order`` 2 accelerations too, at the file's constant ω1."""
    return run(plan(lk), phi, order)


def guide_line(lk: Linkage, g: Group, s: State) -> tuple[Arr, Arr]:
    """The guide of an RRP/PRP group in every position: a point q on it and its unit
    direction d, ``(N, 2)`` each (a guide on a moving link: from → toward, shifted ``offset``
    to the left)."""
    gd = g.guide
    assert gd is not None
    n = s.phi.shape[0]
    if gd.fixed:
        d0 = gd.direction
        q = np.broadcast_to(np.array([gd.through.x, gd.through.y]), (n, 2))
        return q, np.broadcast_to(np.array([d0.x, d0.y]), (n, 2))
    d = s.slide[g.links[1]]
    q = s.pos[gd.frm] + gd.offset * np.stack([-d[:, 1], d[:, 0]], axis=-1)
    return np.asarray(q), d


def rpr_direction(A: Arr, C: Arr, offset: float, step: str, phi: Arr) -> Arr:
    """The slide line's unit direction of an RPR group, ``(N, 2)``: through A, ``offset`` to the
    left of C looking from C towards A, directed from C's foot to A: with r = A − C,
    d = r·(√(r² − o²) − i·o)/r² as a complex number."""
    r = np.asarray(A, dtype=np.float64) - np.asarray(C, dtype=np.float64)
    L2 = np.sum(r * r, axis=-1)
    t2 = L2 - offset * offset
    bad = ~(t2 > tol.REL_LENGTH * L2)
    if np.any(bad):
        i = int(np.argmax(bad))
        deg = np.degrees(float(np.atleast_1d(phi)[i])) % 360.0
        raise NoIntersection(
            step,
            f"the slider comes within the offset {abs(offset):g} m of the pivot"
            f" at the crank angle φ = {deg:.6g}°",
        )
    sq = np.sqrt(t2)
    d = np.stack(
        [r[..., 0] * sq + r[..., 1] * offset, r[..., 1] * sq - r[..., 0] * offset], axis=-1
    )
    return np.asarray(d / L2[..., None], dtype=np.float64)


def prp_frame(g: Group) -> tuple[Arr, Arr, Arr]:
    """A PRP group's guide point, guide direction and slot direction (unit vectors), ``(2,)``."""
    gd = g.guide
    assert gd is not None
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    q = np.array([gd.through.x, gd.through.y])
    return q, np.array([gdir.x, gdir.y]), np.array([sdir.x, sdir.y])


def rocker_angle(lk: Linkage, s: State) -> Arr:
    """The rocker output's angle ψ (rad, ccw > 0, in (−π, π]): an RRR link's direction from its
    frame pivot to its joint, an RPR link 3's slide line's direction."""
    link = lk.rocker
    if lk.has_slide(link):
        d = s.slide[link]
    else:
        pivot = lk.frame_pivot(link)
        other = next(p for p in lk.link_points(link) if p != pivot)
        d = s.pos[other] - s.pos[pivot]
    return np.asarray(np.arctan2(d[:, 1], d[:, 0]), dtype=np.float64)


def output_coordinate(lk: Linkage, s: State) -> Arr | None:
    """s of the output slider along its guide (m), or the rocker's angle ψ (rad, unwrapped
    along the sweep), or ``None`` when the output is neither."""
    if lk.rocker:
        return np.asarray(np.unwrap(rocker_angle(lk, s)), dtype=np.float64)
    g = lk.output_guide
    if g is None:
        return None
    if g.kind == "RRP":
        return s.along[lk.output]
    P = s.pos[lk.output]
    q0, d0, _ = prp_frame(g)
    return np.asarray((P - q0) @ d0)


def output_velocity(lk: Linkage, s: State) -> Arr | None:
    """ds/dt of the output slider along its guide (its relative velocity on a moving guide), or
    the rocker's ω."""
    if lk.rocker:
        return np.asarray(s.omega[lk.rocker], dtype=np.float64)
    g = lk.output_guide
    if g is None:
        return None
    return s.v_rel[lk.output]
