"""2013-6's kinematic analysis: the synthesized six-bar at one crank position, by plans.

At the crank angle φ1 (from +x, ccw) and the crank speed ω1 (ccw > 0, ε1 = 0):
- positions by construction: A on the crank circle; B = circle(A, l2) ∩ circle(O2, l3) on the
  assembly branch the mechanism runs on; C = circle(B, l4) ∩ the slider's path on its branch;
- the velocity plan: pa = ω1 × O1A; V_B = V_A + V_BA (⊥ AB) = V_O2 + V_BO2 (⊥ O2B);
  V_C = V_B + V_CB (⊥ BC), V_C ∥ the path; ω2, ω3, ω4 read off the plan;
- the acceleration plan: πa' = ω1²·l1 from A towards O1; a_B = a_A + a^n_BA + a^τ_BA (⊥ AB) =
  a^n_BO2 + a^τ_BO2 (⊥ O2B); a_C = a_B + a^n_CB + a^τ_CB (⊥ BC), a_C ∥ the path.

The sweep over a whole turn (:meth:`SixBar.sweep`, :meth:`SixBar.slider_a`) gives the slider's
s(φ), v(φ) and a(φ), and checks the plans: their values at φ1 lie on the curves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from geomcad.construction import Construction, Where
from geomcad.geom import Vec
from geomcad.kinematics import SixBar, branch_sign
from geomcad.kinematics.plan import Plan, Side, acceleration_plan, normal, velocity_plan

#: Crank angles per turn for the diagrams.
DIAGRAM_SAMPLES = 721


@dataclass(frozen=True)
class Analysis:
    """The recorded analysis at φ1 and the slider's diagrams over a turn."""

    c: Construction
    vp: Plan
    ap: Plan
    phi1: float
    omega1: float
    omegas: tuple[float, float, float]  # ω2, ω3, ω4 (ccw > 0)
    epsilons: tuple[float, float, float]  # ε2, ε3, ε4
    phi: np.ndarray  # crank angles over a turn (rad, from φ1's zero)
    s: np.ndarray  # slider displacement from its left extreme (m)
    v: np.ndarray  # slider velocity along the path (m/s)
    a: np.ndarray  # slider acceleration along the path (m/s²)
    s_min: float  # the path coordinate of the left extreme


def analyse(
    m: SixBar, phi1: float, omega1: float, extremes: tuple[float, float] | None = None
) -> Analysis:
    """The plans at φ1 and the diagrams over a turn for six-bar ``m``; ``extremes`` are the
    crank angles of the slider's extreme positions when the caller has them already (else they
    are found by :meth:`SixBar.stroke_and_k`)."""
    c = Construction(f"2013-6: kinematic analysis at φ1 = {math.degrees(phi1):.6g}°")
    O1 = c.point("O1", m.O1, note="crank pivot")
    O2 = c.point("O2", m.O2, note="rocker pivot")
    A = c.point("A", O1 + Vec.polar(m.l1, phi1), op="O1 + l1·(cos φ1, sin φ1)", role="link")
    kA = c.circle("kA", A, m.l2, role="hidden", r_name="l2")
    k3 = c.circle("k3", O2, m.l3, role="hidden", r_name="l3")
    B = c.intersect(
        "B",
        kA,
        k3,
        Where(lambda q: branch_sign(A, O2, q) == m.branch_B, "on the mechanism's branch"),
        role="link",
        op="circle(A, l2) ∩ circle(O2, l3)",
    )
    d = m.guide_d.unit()
    path = c.line("path", m.guide_p, d, "the slider's path", role="given")
    kB = c.circle("kB", B, m.l4, role="hidden", r_name="l4")
    foot = path.foot(B)
    C = c.intersect(
        "C",
        kB,
        path,
        Where(lambda q: (q - foot).dot(d) * m.branch_C > 0.0, "on the mechanism's branch"),
        role="link",
        op="circle(B, l4) ∩ path",
    )
    # the velocity plan
    vp = velocity_plan(c)
    vp.fixed("o1")
    vp.fixed("o2")
    vp.rigid("a", "o1", O1, A, omega1, "V_A", "V_A = ω1 × O1A, ⊥ O1A", 1, ("O1", "A"))
    vp.solve("b", Side("a", B - A, "⊥ AB", True), Side("o2", B - O2, "⊥ O2B", True))
    vp.absolute("b", "V_B", "V_B ⊥ O2B")
    vp.unknown("a", "b", "V_{BA}", "V_BA ⊥ AB")
    vp.solve("c", Side("b", C - B, "⊥ BC", True), Side("p", d, "∥ the path", line="@guide"))
    vp.absolute("c", "V_C", "V_C ∥ the path")
    vp.unknown("b", "c", "V_{CB}", "V_CB ⊥ BC")
    w2 = vp.omega(A, B, "a", "b", "ω2", 2, ("A", "B"))
    w3 = vp.omega(O2, B, "o2", "b", "ω3", 3, ("O2", "B"))
    w4 = vp.omega(B, C, "b", "c", "ω4", 4, ("B", "C"))
    # the acceleration plan
    ap = acceleration_plan(c, velocity=vp)
    ap.fixed("o1")
    ap.fixed("o2")
    # a_A = ω1²·l1, from A to O1 (ε1 = 0)
    ap.rigid_acc("a", "o1", O1, A, omega1, 0.0, "a_A", "a_A = ω1²·l1", 1, ("O1", "A"))
    n_ba = normal(w2, B, A, "n_BA", "a^n_{BA}", "ω2²·l2, B → A", 2, ("B", "A"))
    n_bo2 = normal(w3, B, O2, "n_BO2", "a^n_{BO2}", "ω3²·l3, B → O2", 3, ("B", "O2"))
    ap.solve(
        "b",
        Side("a", B - A, "⊥ AB", True, (n_ba,)),
        Side("o2", B - O2, "⊥ O2B", True, (n_bo2,)),
    )
    ap.absolute("b", "a_B")
    ap.unknown("n_BA", "b", "a^τ_{BA}", "a^τ_BA ⊥ AB")
    ap.unknown("n_BO2", "b", "a^τ_{BO2}", "a^τ_BO2 ⊥ O2B")
    n_cb = normal(w4, C, B, "n_CB", "a^n_{CB}", "ω4²·l4, C → B", 4, ("C", "B"))
    ap.solve(
        "c",
        Side("b", C - B, "⊥ BC", True, (n_cb,)),
        Side("π", d, "∥ the path", line="@guide"),
    )
    ap.absolute("c", "a_C")
    ap.unknown("n_CB", "c", "a^τ_{CB}", "a^τ_CB ⊥ BC")
    e2 = ap.omega(A, B, "a", "b", "ε2", 2, ("A", "B"))
    e3 = ap.omega(O2, B, "o2", "b", "ε3", 3, ("O2", "B"))
    e4 = ap.omega(B, C, "b", "c", "ε4", 4, ("B", "C"))
    # the slider's diagrams over a turn, from φ1's zero: s from the left extreme
    phi = np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES)
    r = m.sweep(phi, omega1)
    s = np.asarray(r.s, dtype=np.float64)
    if extremes is None:
        extremes = m.stroke_and_k()[2:]
    s_min = float(np.min(m.slider_s(np.array(extremes))))
    acc = m.slider_a(phi, omega1)
    return Analysis(
        c, vp, ap, phi1, omega1, (w2, w3, w4), (e2, e3, e4), phi, s - s_min, r.v, acc, s_min
    )
