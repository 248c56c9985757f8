"""A linkage solved: its structure, its cycle and its plans at the asked crank angles.

:func:`solve` is what ``geomcad solve FILE.toml`` computes; :func:`results` words it as the
``results`` of linkages.md (every value at a position read off that position's plans).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad import tol
from geomcad.errors import ConstructionError
from geomcad.geom import Vec
from geomcad.linkage.cycle import Cycle, cycle, numbered, stroke_middles
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import Position, construct
from geomcad.linkage.sweep import sweep
from geomcad.structure import Mechanism, chebyshev, mobility
from geomcad.structure.model import Link, Pair, prismatic, revolute

#: Crank angles at which a whole turn is checked before the plans are constructed.
TURN_SAMPLES = 720


@dataclass(frozen=True)
class Solved:
    """The linkage, its structural scheme at the first position, W, its cycle (``None``
    without a slider output), the crank angles of the results' positions with their
    constructions, and the two positions whose acceleration plans go on the sheet."""

    linkage: Linkage
    scheme: Mechanism
    W: int
    cycle: Cycle | None
    positions: tuple[Position, ...]
    accel_phis: tuple[float, ...]
    #: the numbered positions 0 … N−1 (``positions = N``, default 12), always solved and drawn;
    #: the same objects as ``positions`` when the file lists no ``phi``
    drawn: tuple[Position, ...] = ()

    @property
    def numbered(self) -> bool:
        """True when the positions are the file's ``positions = N`` numbering."""
        return self.linkage.phi is None


def scheme(lk: Linkage, P: Position) -> Mechanism:
    """The structural scheme (links and pairs) of the linkage in position ``P``."""
    own = lk.owner
    links = tuple(Link(str(i)) for i in lk.moving_links)
    pairs: list[Pair] = [revolute(lk.pivot, "0", "1", P.pos[lk.pivot])]
    for g in lk.groups:
        a, b = (str(i) for i in g.links)
        if g.kind == "RRR":
            e1, e2 = g.ends
            pairs += [
                revolute(f"{e1}:{a}", str(own[e1]), a, P.pos[e1]),
                revolute(g.joint, a, b, P.pos[g.joint]),
                revolute(f"{e2}:{b}", str(own[e2]), b, P.pos[e2]),
            ]
        elif g.kind == "RRP":
            assert g.guide is not None
            e = g.ends[0]
            pairs += [
                revolute(f"{e}:{a}", str(own[e]), a, P.pos[e]),
                revolute(g.joint, a, b, P.pos[g.joint]),
                prismatic(
                    f"{g.joint}:{b}", b, str(g.guide.link), P.pos[g.joint], P.slide[g.links[1]]
                ),
            ]
        elif g.kind == "RPR":
            pairs += [
                revolute(f"{g.slider}:{a}", str(own[g.slider]), a, P.pos[g.slider]),
                prismatic(f"{g.slider}:{a}{b}", a, b, P.pos[g.slider], P.slide[g.links[0]]),
                revolute(f"{g.pivot}:{b}", b, str(own[g.pivot]), P.pos[g.pivot]),
            ]
        else:
            assert g.guide is not None
            pairs += [
                revolute(f"{g.slider}:{a}", str(own[g.slider]), a, P.pos[g.slider]),
                prismatic(f"{g.slider}:{a}{b}", a, b, P.pos[g.slider], P.slide[g.links[0]]),
                prismatic(f"{g.joint}:{b}", b, "0", P.pos[g.joint], g.guide.direction),
            ]
    return Mechanism(links, tuple(pairs))


def solve(lk: Linkage) -> Solved:
    """Solve the linkage: its cycle, its numbered (and listed) positions, their plans."""
    # the whole turn first: a group that cannot close anywhere is named with its crank angle
    # (the angle the user can find, not the sweep's internal index)
    try:
        sweep(lk, np.linspace(0.0, 2.0 * math.pi, TURN_SAMPLES, endpoint=False), order=2)
    except ConstructionError as e:
        why = re.sub(
            r"first at position index \d+, at the crank angle", "first at the crank angle", e.why
        )
        raise type(e)(e.step, why) from None
    cyc = cycle(lk)
    if cyc is None and lk.rocker:
        from geomcad.errors import FileKeyError

        why = f"the output link {lk.rocker} turns fully (a crank): it has no strokes"
        bad = next((ld for ld in lk.loads if ld.on_stroke), None)
        if bad is not None:
            raise FileKeyError(f"load {bad.index}: stroke", bad.stroke, why)
        if lk.working_key:
            raise FileKeyError(lk.working_key, lk.working, why)
    drawn = tuple(construct(lk, phi) for phi in numbered(lk, cyc, lk.positions))
    positions = drawn if lk.phi is None else tuple(construct(lk, phi) for phi in lk.phi)
    m = scheme(lk, positions[0])
    W = chebyshev(m.n, m.p5, m.p4)
    mob = mobility(m)
    if W != 1 or mob.true != 1:
        raise ConstructionError(
            "structure",
            f"the mechanism has W = {W} (true mobility {mob.true}); a crank drives W = 1",
        )
    if lk.phi is not None:
        accel = tuple(lk.phi[:2])
    elif cyc is not None:
        accel = largest_accelerations(lk, cyc, drawn)
    else:
        accel = (drawn[0].phi, drawn[len(drawn) // 2].phi)
    return Solved(lk, m, W, cyc, positions, accel, drawn)


def output_acceleration(lk: Linkage, P: Position) -> float:
    """The output's acceleration at P: a slider's along its guide (relative to a moving
    guide's link), a rocker's ε."""
    if lk.rocker:
        return P.eps[lk.rocker]
    g = lk.output_guide
    assert g is not None
    if g.kind == "PRP":
        assert g.guide is not None
        return P.acc[lk.output].dot(g.guide.direction)
    d = P.slide[g.links[1]]
    a = P.acc[lk.output]
    gd = g.guide
    if gd is not None and not gd.fixed:
        r = P.pos[lk.output] - P.pos[gd.frm]
        w, e = P.omega[gd.link], P.eps[gd.link]
        a = a - P.acc[gd.frm] - Vec(-r.y, r.x) * e + r * (w * w)
    return a.dot(d)


def largest_accelerations(
    lk: Linkage, cyc: Cycle, drawn: tuple[Position, ...]
) -> tuple[float, ...]:
    """The crank angles of the acceleration plans by default: in each stroke (working, then
    idle) the first numbered position where |the output's acceleration| is largest (within
    :data:`~geomcad.tol.DERIVED` of the maximum, relative); a stroke with no numbered position
    inside it gives its middle.

    Where the output's strokes are mirror images (the working stroke takes half a turn and
    |the output's acceleration| at the turn ψ equals that at 2π − ψ in every numbered
    position: an axial slider-crank, a V engine's cylinders) the idle stroke's largest is the
    mirror of the working stroke's, and its plan would show nothing new (the same |a|, the
    same drawing turned over). The idle stroke's plan is then drawn where its output's
    acceleration is largest among the positions that are not that mirror: the other end of
    the stroke, where the acceleration has the other sign (review 6 item 7).

    Where the idle stroke's largest lies beside the working stroke's pick (within one step of
    the numbering or 45° of the crank's turn, the shorter way: two neighbours about the
    output's extreme, such as a rocker's positions 6 and 7, whose plans are nearly the same
    figure) the idle stroke's plan is drawn where its output's acceleration is largest among
    its positions farther than that from the working pick; a stroke with none keeps its
    largest (review 7 item 7). Files whose picks already differ keep them."""
    n = len(drawn)
    step = 2.0 * math.pi / n
    edge = tol.DERIVED
    working: list[int] = []
    idle: list[int] = []
    for k in range(n):
        turn = k * step  # the crank's turn from position 0, the working stroke's start
        if edge < turn < cyc.phi_working - edge:
            working.append(k)
        elif cyc.phi_working + edge < turn:
            idle.append(k)
    acc = {k: abs(output_acceleration(lk, drawn[k])) for k in (*working, *idle)}
    scale = max(acc.values(), default=0.0)
    mirrored = (
        bool(working)
        and abs(cyc.phi_working - math.pi) <= edge * math.pi
        and all(n - k in acc and abs(acc[k] - acc[n - k]) <= edge * scale for k in working)
    )
    mids = stroke_middles(lk, cyc)
    out: list[float] = []
    first: int | None = None
    near = max(step, math.pi / 4) * (1 + edge)  # picks this close show the same figure

    def apart(k: int, j: int) -> float:
        """The crank's turn between the numbered positions k and j, the shorter way."""
        d = abs(k - j) % n
        return min(d, n - d) * step

    for ks, mid in ((working, mids[0]), (idle, mids[1])):
        if first is not None and mirrored and len(ks) > 1:
            ks = [k for k in ks if k != n - first]  # not the mirror of the working stroke's
        if first is not None and ks:
            top = max(acc[k] for k in ks)
            best = next(k for k in ks if acc[k] >= top * (1 - edge))
            far = [k for k in ks if apart(k, first) > near]
            if apart(best, first) <= near and far:
                ks = far  # not beside the working stroke's pick (review 7 item 7)
        if not ks:
            out.append(mid)
            continue
        top = max(acc[k] for k in ks)
        pick = next(k for k in ks if acc[k] >= top * (1 - edge))
        first = pick if first is None else first
        out.append(drawn[pick].phi)
    return tuple(out)


def _xy(out: dict[str, Any], key: str, v: Vec) -> None:
    out[key] = math.hypot(v.x, v.y)
    out[f"{key}_x"] = v.x
    out[f"{key}_y"] = v.y


def moving_points(lk: Linkage) -> list[str]:
    """Every moving joint and named point, in the order they become known."""
    names = [lk.joint]
    for g in lk.groups:
        if g.joint:
            names.append(g.joint)
    names += [p.name for p in lk.points]
    order = {n: i for i, n in enumerate(lk.owner)}
    return sorted(dict.fromkeys(names), key=lambda n: order[n])


def position_results(lk: Linkage, P: Position) -> dict[str, Any]:
    """One object of ``results.positions``: everything read off position P's plans."""
    # the file's own angle back (30, not 29.999999999999996), within [0°, 360°)
    out: dict[str, Any] = {"phi_deg": round(math.degrees(P.phi) % 360.0, 10) % 360.0}
    for name in moving_points(lk):
        p = P.pos[name]
        out[f"x_{name}"] = p.x
        out[f"y_{name}"] = p.y
        _xy(out, f"V_{name}", P.vel[name])
        _xy(out, f"a_{name}", P.acc[name])
    for i in lk.moving_links:
        out[f"omega_{i}"] = P.omega[i]
    for i in lk.moving_links:
        out[f"eps_{i}"] = P.eps[i]
    for name, v in P.v_rel.items():
        out[f"V_rel_{name}"] = abs(v)
        out[f"a_cor_{name}"] = P.a_cor[name].norm
    return out


def results(s: Solved) -> dict[str, Any]:
    """The ``results`` object of ``solve --json`` (linkages.md)."""
    lk = s.linkage
    out: dict[str, Any] = {
        "W": s.W,
        "structure": [
            {"kind": g.kind, "links": list(g.links), "class": 2, "order": 2} for g in lk.groups
        ],
        "formula": formula(lk),
    }
    if s.cycle is not None:
        if lk.rocker:
            out["swing_deg"] = s.cycle.swing_deg
        else:
            out["stroke"] = s.cycle.stroke
        out["K"] = s.cycle.K
    out["positions"] = [position_results(lk, P) for P in s.positions]
    from geomcad.linkage.analysis import add_results  # forces and dynamics (issue 15)

    add_results(s, out)
    return out


def formula(lk: Linkage) -> str:
    """The structure formula: I(0,1) → II(2,3) → …"""
    parts = ["I(0,1)"] + [f"II({a},{b})" for a, b in (g.links for g in lk.groups)]
    return " → ".join(parts)
