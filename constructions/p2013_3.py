"""2013-3 · Mechanism with a cross: the velocity plan.

Links: 1 translates along O1O2 and carries A and B; block 2 is hinged to link 1 at B and slides in
the slotted rocker 3 (pivot O1, slot along B–O1–C); the cross 4 slides with two perpendicular
slides on link 3 (along O1C) and on link 5 (along O2C); link 5 rocks about O2 and carries the
moment M.

Frame (problems.md): O1 = (0, 0), O2 = (l_O1O2, 0); A = (−2·l_AB·cos α, 0) on the far side of O1;
triangle O1AB is isosceles with base angles α (O1B = AB), B below O1O2; C is the foot of the
perpendicular from O2 on the slot line (∠O1CO2 = 90°), above O1O2, on the other side of O1 from B.

The velocity plan, as the seed draws it:
- pa = V_A; link 1 translates, so b1 = a, and block 2 is hinged there, so b2 = b1;
- V_B3 = V_B2 + V_B3B2 (∥ O1B) = V_O1 + V_B3O1 (⊥ O1B): two lines meet in b3; ω3 = pb3/l_O1B;
- c3 is the image of C on link 3 (o1, b3, c3 on one line, pc3/pb3 = O1C/O1B, c3 opposite b3);
- the cross slides on 3 and on 5 at a fixed right angle, so links 3, 4 and 5 turn together:
  ω5 = ω3, and pc5 = ω5 × O2C (⊥ O2C);
- V_C4 = V_C3 + V_C4C3 (∥ O1C) = V_C5 + V_C4C5 (∥ O2C): two lines meet in c4.

The power balance on link 1 gives the force equivalent to M: F_red·|v_A| = |M·ω5|.

Choices settled here (they change no published number): ``v_A`` is signed along +x (towards O2)
and must not be zero; ``M`` may have either sign (its sense is drawn); every result is a
magnitude, as problems.md's "Signs" rule asks.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from geomcad.construction import Construction, right_of
from geomcad.errors import ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan, Side, velocity_plan
from geomcad.problem import Build, ParamValue
from geomcad.structure import Link, Mechanism, Pair


@dataclass(frozen=True)
class Geometry:
    """The solved model besides the recorded steps: the given motion and load, and the plan."""

    v_A: float
    M: float
    l_AB: float
    plan: Plan
    #: The mechanism as links and pairs in the given position (its scheme is drawn from it).
    mechanism: Mechanism


def _check(p: Mapping[str, ParamValue]) -> tuple[float, float, float, float, float]:
    v_a, l_ab, l12, m, alpha_deg = (
        float(p[n]) for n in ("v_A", "l_AB", "l_O1O2", "M", "alpha_deg")
    )
    if v_a == 0.0:
        raise ParameterError("v_A", v_a, "must not be zero: a mechanism at rest has no plan")
    return v_a, l_ab, l12, m, math.radians(alpha_deg)


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """The positions by construction, then the velocity plan from its vector equations."""
    v_a, l_ab, l12, m, alpha = _check(p)
    c = Construction("2013-3: mechanism with a cross, velocity plan")
    O1 = c.point("O1", (0.0, 0.0), note="pivot of the slotted link 3")
    O2 = c.point("O2", (l12, 0.0), note="pivot of link 5")
    A = c.point(
        "A", (-2.0 * l_ab * math.cos(alpha), 0.0), op="on O1O2 beyond O1, O1A = 2·l_AB·cos α"
    )
    kA = c.circle("kA", A, l_ab, role="hidden", r_name="l_AB")
    kO1 = c.circle("kO1", O1, l_ab, role="hidden", r_name="l_AB", note="O1B = AB")
    B = c.intersect(
        "B", kA, kO1, right_of(A, O1, "A→O1 (B below O1O2)"), role="link",
        op="circle(A, l_AB) ∩ circle(O1, l_AB)",
    )  # fmt: skip
    slot = c.line_through("slot", B, O1, note="the slot of link 3, B–O1–C")
    n5 = c.perpendicular("O2C", slot, O2, note="the cross keeps O2C ⊥ O1C")
    C = c.intersect("C", slot, n5, role="link", op="slot ∩ perpendicular from O2")
    c.value("l_O1B", O1.dist(B), "|O1B|", (O1, B))
    c.value("l_O1C", O1.dist(C), "|O1C|", (O1, C))
    c.value("l_O2C", O2.dist(C), "|O2C|", (O2, C))

    vp = velocity_plan(c)
    vp.fixed("o1")
    vp.fixed("o2")
    vp.given("a", Vec(v_a, 0.0), "V_A", "V_A ∥ O1O2 (link 1 translates)")
    vp.same("b1", "a", "link 1 translates: V_B1 = V_A", "@translates")
    vp.same("b2", "b1", "block 2 is hinged to link 1 at B: V_B2 = V_B1", "@hinge")
    vp.solve(
        "b3",
        Side("b2", O1 - B, "∥ O1B (V_B3B2 along the slot)"),
        Side("o1", B - O1, "⊥ O1B (V_B3 about O1)", perpendicular=True),
    )
    v_b3 = vp.absolute("b3", "V_{B3}", "V_B3 ⊥ O1B")
    v_b3b2 = vp.unknown("b2", "b3", "V_{B3B2}", "V_B3B2 ∥ O1B")
    omega3 = vp.omega(O1, B, "o1", "b3", "ω3", 3, ("O1", "B"), rel="V_{B3}")
    vp.image("c3", "o1", "b3", O1, B, C, why="C on link 3: o1b3c3 ~ O1BC", model=("O1", "B", "C"))
    v_c3 = vp.absolute("c3", "V_{C3}", "V_C3 ⊥ O1C")
    omega5 = c.value(
        "ω5",
        omega3,
        "equal to ω3: the cross slides on links 3 and 5 at a fixed right angle",
        kind="cross_omega",
        args={"w": "ω_5", "of": "ω_3", "value": abs(omega3)},
    )
    vp.order.append("ω5")
    vp.rigid("c5", "p", O2, C, omega5, "V_{C5}", "V_C5 = ω5 × O2C, ⊥ O2C", 5, ("O2", "C"))
    v_c5 = vp["c5"]
    vp.solve(
        "c4",
        Side("c3", C - O1, "∥ O1C (V_C4C3: the cross slides on link 3)"),
        Side("c5", C - O2, "∥ O2C (V_C4C5: the cross slides on link 5)"),
    )
    v_c4 = vp.absolute("c4", "V_{C4}", "V_C4 of the cross's centre")
    vp.unknown("c3", "c4", "V_{C4C3}", "V_C4C3 ∥ O1C")
    vp.unknown("c5", "c4", "V_{C4C5}", "V_C4C5 ∥ O2C")
    f_red = c.value(
        "F_red",
        abs(m * omega5) / abs(v_a),
        "|M·ω5| / |v_A| (equal power)",
        kind="reduced_force",
        args={"M": abs(m), "w": abs(omega5), "v": abs(v_a), "value": abs(m * omega5) / abs(v_a)},
    )

    results: dict[str, Any] = {
        "V_B3": v_b3.norm,
        "V_B3B2": v_b3b2.norm,
        "omega3": abs(omega3),
        "V_C3": v_c3.norm,
        "omega5": abs(omega5),
        "V_C5": v_c5.norm,
        "V_C4": v_c4.norm,
        "F_red": f_red,
    }
    return Build(results, c, [], {}, Geometry(v_a, m, l_ab, vp, mechanism(c)))


def mechanism(c: Construction) -> Mechanism:
    """The mechanism with a cross as links and pairs (GOST 2.770's symbols come from them):
    1 slides on the frame at A and carries B; block 2, hinged to 1 at B, slides in the slot of
    the rocker 3 (pivot O1); the cross 4 slides on 3 and on 5 at C; 5 turns about O2."""
    O1, O2, A, B, C = (c[n] for n in ("O1", "O2", "A", "B", "C"))
    u3, u5 = (C - B).unit(), (C - O2).unit()
    pairs = (
        Pair("A", "P", "0", "1", A, Vec(1.0, 0.0)),
        Pair("B", "R", "1", "2", B),
        Pair("B'", "P", "2", "3", B, u3),
        Pair("O1", "R", "3", "0", O1),
        Pair("C", "P", "3", "4", C, u3),
        Pair("C'", "P", "4", "5", C, u5),
        Pair("O2", "R", "5", "0", O2),
    )
    return Mechanism(tuple(Link(str(i)) for i in range(1, 6)), pairs)
