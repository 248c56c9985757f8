"""2013-6 · Six-bar synthesis by the coefficient of velocity change K ("circle through B0B1").

Crank 1 (O1A, l1), connecting rod 2 (AB, l2), rocker 3 (O2B, l3), link 4 (BC, l4), slider 5 (C).

Frame (problems.md): O2 = (0, 0); the slider path is horizontal at y = l3; at mid-stroke the rocker
is vertical, B = (0, l3), C = (l4, l3). The extreme positions are C0 = (l4 − H/2, l3) and
C1 = (l4 + H/2, l3); B0 and B1 are where the rocker's circle meets the circles of radius l4 about
C0 and C1, on the branch of the mid position (left of the directed line O2 → C).

The seed's construction: θ = 180°·(K − 1)/(K + 1); the perpendicular to B0B1 at B0 meets the ray
from B1 at 90° − θ to B1B0 in O; the circle Γ through O, B0, B1 has OB1 as a diameter, and every
inscribed angle on B0B1 from its arc through O equals θ. Its mirror image Γ′ over B0B1 gives the
other arc that sees B0B1 under θ. O1 lies on a line parallel to the path at distance e.

Choices settled here (they change no published number):
- O is taken on the side of B0B1 where the rocker's pivot O2 lies (the ray from B1 turns towards
  O2); Γ′ covers the other side, so the set of solutions does not depend on this choice.
- The candidates are ordered by line (y = l3 − e first), then by x ascending; the seed's solution
  is the leftmost candidate on y = l3 − e.
- l1 = |O1B1 − O1B0| / 2 and l2 = (O1B1 + O1B0) / 2: the shorter of the two distances is the
  folded dead centre (crank and rod overlapping), the longer the extended one. For the seed's
  solution O1B1 > O1B0, which is the seed's formula.
- The check by analysis runs the six-bar assembled in the mode that passes through B1 at the
  extended dead centre, with C to the right of B (as in the mid position).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from geomcad.construction import Construction, Where, left_of
from geomcad.errors import ConstructionError, NoIntersection, ParameterError
from geomcad.geom import Line, Vec, angle_arcs, mirror_circle
from geomcad.kinematics import SixBar, branch_sign, grashof_crank_rocker
from geomcad.problem import (
    Build,
    ParamValue,
)
from geomcad.units import to_deg

from .kin_2013_6 import Analysis, analyse

#: The position the kinematic analysis is made at (a choice that changes no published number,
#: the same for every variant): the crank turns ccw at ω1 = 10 rad/s and stands 60° past its
#: position at the slider's left extreme.
ANALYSIS_OMEGA1 = 10.0
ANALYSIS_TURN = math.radians(60.0)


#: The operations of the steps O1 and H_check, which errors name as the protocol does.
O1_OP = "leftmost point of the θ-arcs on y = l3 − e"
H_CHECK_OP = "stroke of C over a full crank turn"

NOTES = [
    "seed formula slip: it writes AB = OB1 − O1A where it means AB = O1B1 − O1A; its numbers "
    "(89,5 − 13 = 76,5 мм) use O1B1, so no published value is affected",
]


@dataclass(frozen=True)
class Candidate:
    """One solution: the crank centre O1 and the four-bar it gives."""

    O1: Vec
    O1B0: float
    O1B1: float
    l1: float
    l2: float
    crank_rocker: bool
    line: int  # 0: y = l3 − e, 1: y = l3 + e
    arc: str  # "Γ" or "Γ'"

    def as_result(self) -> dict[str, Any]:
        return {
            "O1": [self.O1.x, self.O1.y],
            "O1B0": self.O1B0,
            "O1B1": self.O1B1,
            "l1": self.l1,
            "l2": self.l2,
            "crank_rocker": self.crank_rocker,
        }


@dataclass(frozen=True)
class Geometry:
    """Everything the sheet needs besides the recorded steps."""

    H: float
    K: float
    l3: float
    l4: float
    e: float
    theta: float
    candidates: tuple[Candidate, ...]
    chosen: Candidate
    mechanism: SixBar
    phi_min: float  # crank angle at the slider's left extreme
    phi_max: float
    analysis: Analysis  # the plans at φ1 and the slider's diagrams (the kinematics sheet)


def _check_params(p: Mapping[str, ParamValue]) -> tuple[float, float, float, float, float]:
    H, K, l3, l4, e = (float(p[n]) for n in ("H", "K", "l3", "l4", "e"))
    if K >= 3.0:
        raise ParameterError(
            "K",
            K,
            "must be < 3: at K ≥ 3, θ ≥ 90° and the ray from B1 at 90° − θ turns away "
            "from the perpendicular at B0, so the construction has no point O",
        )
    # C0 must be reachable from the rocker's circle: |O2C0| ≤ l3 + l4 (and ≥ |l3 − l4|)
    far = math.hypot(l4 + H / 2.0, l3)
    if far >= l3 + l4:
        raise ParameterError(
            "H",
            H,
            f"too large for l3 = {l3:g} m and l4 = {l4:g} m: at C1 the links BC and O2B "
            f"cannot close (|O2C1| = {far:.6g} m ≥ l3 + l4)",
        )
    return H, K, l3, l4, e


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """Run the seed's graphical synthesis as a recorded construction, then check it by analysis."""
    H, K, l3, l4, e = _check_params(p)
    c = Construction("2013-6: six-bar synthesis by K (circle through B0B1)")

    O2 = c.point("O2", (0.0, 0.0), role="given", note="rocker pivot")
    path = c.line("path", Vec(0.0, l3), (1.0, 0.0), "slider path y = l3", role="given")
    c.point("B", (0.0, l3), role="link", op="mid position: rocker vertical, B = (0, l3)")
    C = c.point("C", (l4, l3), role="link", op="mid position: C = B + (l4, 0) on the path")
    C0 = c.point("C0", C - Vec(H / 2.0, 0.0), role="given", op="C − H/2 along the path",
                 kind="stroke_end", args={"p": C, "sign": "–", "h": H / 2.0})  # fmt: skip
    C1 = c.point("C1", C + Vec(H / 2.0, 0.0), role="given", op="C + H/2 along the path",
                 kind="stroke_end", args={"p": C, "sign": "+", "h": H / 2.0})  # fmt: skip
    k3 = c.circle("k3", O2, l3, role="aux", r_name="l3", note="path of B")
    kC0 = c.circle("kC0", C0, l4, role="hidden", r_name="l4")
    kC1 = c.circle("kC1", C1, l4, role="hidden", r_name="l4")
    B0 = c.intersect(
        "B0",
        k3,
        kC0,
        left_of(O2, C0, "O2→C0 (the mid position's branch)"),
        role="result",
        op="circle(O2, l3) ∩ circle(C0, l4)",
        kind="extreme_joint",
        args={"o": O2, "r": "l3", "c": C0, "l": "l4"},
    )
    B1 = c.intersect(
        "B1",
        k3,
        kC1,
        left_of(O2, C1, "O2→C1 (the mid position's branch)"),
        role="result",
        op="circle(O2, l3) ∩ circle(C1, l4)",
        kind="extreme_joint",
        args={"o": O2, "r": "l3", "c": C1, "l": "l4"},
    )
    theta = math.pi * (K - 1.0) / (K + 1.0)
    c.value("θ", theta, "180°·(K − 1)/(K + 1), in radians", kind="theta_k",
            args={"K": K, "deg": to_deg(theta)})  # fmt: skip
    chord = c.line_through("B0B1", B0, B1)
    n0 = c.perpendicular("n0", chord, B0, note="perpendicular to B0B1 at B0")
    # the ray from B1 turns towards O2's side of the chord (left of B1→B0 when O2 is there)
    toward_o2 = 1.0 if Line.through(B1, B0).side(O2) > 0.0 else -1.0
    ray = c.ray_at_angle(
        "r1",
        B1,
        B0,
        toward_o2 * (math.pi / 2.0 - theta),
        "90° – θ",
        note="towards O2's side of B0B1",
    )
    O_ = c.intersect("O", n0, ray, role="construction")
    gamma = c.circle_through("Γ", O_, B0, B1, note="OB1 is a diameter: ∠OB0B1 = 90°")
    gamma_m = c.record(
        "Γ'",
        "mirror of Γ over B0B1",
        mirror_circle(gamma, chord),
        (gamma, chord),
        note="the other arc that sees B0B1 under θ",
        kind="mirror",
        args={"a": gamma, "line": chord},
    )
    # the loci of O1 drawn: the arcs of Γ and Γ′ that see B0B1 under θ (their other arcs, of
    # 180° − θ, hug the chord and carry no solution)
    c.run(
        "θ-arcs",
        "the arcs of Γ and Γ′ that see B0B1 under θ",
        lambda: angle_arcs(B0, B1, theta),
        (B0, B1),
        kind="locus_arcs",
        args={"a": "Γ", "b": "Γ'", "chord": chord, "angle": "θ"},
    )
    o_side = chord.side(O_)

    def on_theta_arc(circle_is_mirror: bool) -> Where:
        # Γ's θ-arc is on O's side of the chord, Γ′'s on the other side
        sign = -o_side if circle_is_mirror else o_side
        side_text = "the side opposite O" if circle_is_mirror else "O's side"
        return Where(
            lambda q: chord.side(q) * sign > 0.0,
            f"on the arc that sees B0B1 under θ ({side_text} of B0B1)",
        )

    lines = tuple(
        c.parallel(
            f"m{tag}",
            path,
            offset=sign * e,
            op=f"line ∥ path at e, y = l3 {tag} e",
            kind="offset_line",
            args={"sign": text, "e": e},
        )
        for tag, sign, text in (("−", -1.0, "–"), ("+", 1.0, "+"))
    )
    cands: list[Candidate] = []
    for li, (m_line, tag) in enumerate(zip(lines, ("−", "+"), strict=True)):
        found: list[tuple[Vec, str]] = []
        for circ, arc_name, mirrored in ((gamma, "Γ", False), (gamma_m, "Γ'", True)):
            pts = c.intersections(
                f"{arc_name}∩m{tag}",
                circ,
                m_line,
                on_theta_arc(mirrored),
                role="hidden",
                allow_empty=True,
            )
            found += [(q, arc_name) for q in pts]
        for q, arc_name in sorted(found, key=lambda t: t[0].x):
            cands.append(_candidate(q, B0, B1, O2, l3, li, arc_name))

    lower = [cd for cd in cands if cd.line == 0]
    if not lower:
        y_lo, y_hi = _theta_arcs_y_range(B0, B1, theta)
        e_lo, e_hi = max(0.0, l3 - y_hi), l3 - y_lo
        reach = (
            f"e must lie between {e_lo:.6g} and {e_hi:.6g} m"
            if e_hi > e_lo
            else "no e > 0 reaches them"
        )
        raise NoIntersection(
            f"O1 = {O1_OP}",
            f"the line y = l3 − e = {l3 - e:.6g} m misses the arcs that see B0B1 under θ "
            f"(they span y = {y_lo:.6g} … {y_hi:.6g} m); for this H and K, {reach}",
        )
    chosen = lower[0]
    O1 = c.point("O1", chosen.O1, role="result", op=O1_OP, kind="pick_centre",
                 args={"n": len(cands)})  # fmt: skip
    for i, cd in enumerate(cands):
        if cd is not chosen:
            c.point(f"O1({i + 1})", cd.O1, role="aux", op=f"solution {i + 1} on {cd.arc}")
    o1b0 = c.value("O1B0", chosen.O1B0, "|O1B0|", (O1, B0))
    o1b1 = c.value("O1B1", chosen.O1B1, "|O1B1|", (O1, B1))
    # the dead centres: the longer distance is the extended one (crank and rod in line)
    far, near = (
        (("O1B1", o1b1), ("O1B0", o1b0)) if o1b1 >= o1b0 else (("O1B0", o1b0), ("O1B1", o1b1))
    )
    ends = {"a": far[0], "b": near[0], "va": far[1], "vb": near[1]}
    l1 = c.value("l1", chosen.l1, "|O1B1 − O1B0| / 2", kind="half_difference",
                 args={**ends, "v": chosen.l1})  # fmt: skip
    l2 = c.value("l2", chosen.l2, "(O1B1 + O1B0) / 2", kind="half_sum",
                 args={**ends, "v": chosen.l2})  # fmt: skip

    notes = list(NOTES)
    mech: SixBar | None = None
    phi_min = phi_max = math.nan
    results: dict[str, Any] = {
        "theta_deg": to_deg(theta),
        "O1B0": o1b0,
        "O1B1": o1b1,
        "l1": l1,
        "l2": l2,
    }
    if not chosen.crank_rocker:
        raise ConstructionError(
            f"H_check = {H_CHECK_OP}",
            f"the four-bar O1ABO2 of the chosen solution (l1 = {l1:.6g}, l2 = {l2:.6g}, "
            f"l3 = {l3:.6g}, O1O2 = {chosen.O1.norm:.6g} m) is not a crank-rocker, so its crank "
            "cannot make a full turn",
        )
    mech = _mechanism(chosen, B0, B1, O2, l3, l4)
    h_check, k_check, phi_min, phi_max = mech.stroke_and_k()
    c.value("H_check", h_check, H_CHECK_OP, kind="check_stroke", args={"H": h_check})
    c.value("K_check", k_check, "ratio of the crank angles between C's extremes",
            kind="check_turn", args={"H": h_check, "K": k_check})  # fmt: skip
    results["H_check"] = h_check
    results["K_check"] = k_check
    results["solutions"] = [cd.as_result() for cd in cands]
    if not math.isclose(h_check, H, rel_tol=1e-6) or not math.isclose(k_check, K, rel_tol=1e-6):
        notes.append(
            f"the synthesized six-bar gives H = {h_check:.6g} m and K = {k_check:.6g}, not the "
            f"requested H = {H:g} m and K = {K:g}: the slider does not reverse at the rocker's "
            "dead centres"
        )
    analysis = analyse(mech, phi_min + ANALYSIS_TURN, ANALYSIS_OMEGA1, (phi_min, phi_max))
    geo = Geometry(H, K, l3, l4, e, theta, tuple(cands), chosen, mech, phi_min, phi_max, analysis)
    return Build(results, c, notes, data=geo)


def _theta_arcs_y_range(B0: Vec, B1: Vec, theta: float) -> tuple[float, float]:
    """The lowest and highest y on the two arcs that see B0B1 under θ (their end points count)."""
    ys = [B0.y, B1.y]
    for arc in angle_arcs(B0, B1, theta):
        for q in (arc.circle.c + Vec(0.0, arc.circle.r), arc.circle.c - Vec(0.0, arc.circle.r)):
            if arc.contains(q):
                ys.append(q.y)
    return min(ys), max(ys)


def _candidate(q: Vec, B0: Vec, B1: Vec, O2: Vec, l3: float, line: int, arc: str) -> Candidate:
    d0, d1 = q.dist(B0), q.dist(B1)
    l1, l2 = abs(d1 - d0) / 2.0, (d1 + d0) / 2.0
    return Candidate(q, d0, d1, l1, l2, grashof_crank_rocker(l1, l2, l3, q.dist(O2)), line, arc)


def _mechanism(cd: Candidate, B0: Vec, B1: Vec, O2: Vec, l3: float, l4: float) -> SixBar:
    """The six-bar of a solution, assembled through the extended dead centre."""
    b_ext = B1 if cd.O1B1 >= cd.O1B0 else B0
    a_ext = cd.O1 + (b_ext - cd.O1).unit() * cd.l1
    return SixBar(
        cd.O1,
        cd.l1,
        cd.l2,
        O2,
        l3,
        l4,
        Vec(0.0, l3),
        Vec(1.0, 0.0),
        branch_sign(a_ext, O2, b_ext),
        1,
    )
