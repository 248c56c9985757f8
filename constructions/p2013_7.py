"""2013-7 · Centrifugal governor with friction circles ("force polygons with friction circles").

The governor turns slowly faster from rest; find the shaft's angular velocity ω in the position
shown, with friction f in its six revolute joints (pins of diameter d).

Frame (problems.md): the shaft 7 is the y axis; the right half is drawn. The shaft's collar
carries the joints G and H at x = ∓l_GH/2, y = 0. Arm 6 is the straight rod H-F-D hanging down and
outwards at θ from the vertical: F = H + l_FH·(sin θ, −cos θ), the ball D = H + l_DH·(sin θ,
−cos θ), which turns at r_D = l_GH/2 + l_DH·sin θ. Link 3 (BF, weightless) runs from F down to the
pivot B = (l_AB/2, y_B) of the sleeve 2 (mass m2), which hangs on links 3 and 4 and slides on the
shaft without friction; A, E, C mirror B, F, D.

The seed's solution, recorded step by step:

1. The relative rotations, from the velocity analysis of the position (θ̇ > 0 while the balls
   rise, ``direction`` = +1; θ̇ < 0 when the governor slowly slows down, ``direction`` = −1): the
   sleeve translates (ω2 = 0), the arm turns at ω6 = θ̇, link 3 at ω3 from V_F = V_B + ω3 × BF
   with V_B vertical.
2. ρ = (d/2)·sin(arctan f), the friction circles at B, F and H, each with the sense of the
   relative rotation that its reaction must oppose: ω_32 at B and ω_36 at F (reactions on link 3),
   ω_67 at H (the reaction R_76 on the arm).
3. Link 3 is a weightless two-force member in tension (the sleeve hangs on it): its line of
   action is the common tangent of the circles at B and F whose moments oppose both rotations,
   the internal one here (ω_32 and ω_36 turn the same way), inclined by α = arcsin(2ρ/l_BF) to BF.
4. Body 2 is held by G_2 and the two symmetric reactions R_32, R_42: its force triangle, closed
   on their lines, gives R_32 (the seed's m2·g/2 = R_32·cos(45° + α)). Their lines meet on the
   shaft's axis, which the weight's line is: the three forces are concurrent.
5. Arm 6 (d'Alembert) carries R_36 = R_32 along link 3's line, the ball's weight G_6 and its
   inertia force Ф_6 = F_i = m·r_D·ω², both through D, and R_76 at H. P = G_6 + R_36 acts through
   Q, where the lines of G_6 and R_36 meet; P's line meets the line of F_i (the horizontal through
   D) in K, and by the three-force theorem R_76 passes through K, tangent to the friction circle
   at H on the side whose moment opposes ω_67. The sense of R_76, which picks the tangent, is the
   one the same polygon has without friction (R_76 through H's centre).
6. The force polygon G_6 + R_36 + F_i + R_76 = 0, closed on the lines of F_i and R_76, gives
   F_i; then ω = √(F_i/(m·r_D)). The same construction with f = 0 gives ``omega_no_friction``.

Choices settled here (problems.md leaves them to the construction): B is the lower of the two
points of the vertical x = l_AB/2 at l_BF from F (the sleeve hangs below the arm's joint F); β is
the acute angle between R_76's line and the horizontal. Bad input: masses, lengths, d and g must
be > 0, f ≥ 0, 0° < θ < 90°, ``direction`` ±1, and link 3 must reach from B's vertical to F; a
construction that fails names its step: friction circles at B and F that overlap (no internal
tangent), self-locking of the sleeve (link 3's line of action at 90° or more to the vertical),
self-locking of the arm (the polygon closes with F_i ≤ 0: friction alone holds it), and K within
the friction circle at H.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from geomcad.construction import Construction, Where
from geomcad.errors import ConstructionError, ParameterError
from geomcad.forces import (
    ForcePolygon,
    FrictionCircle,
    Known,
    TwoForceLine,
    Unknown,
    close_polygon,
    force_polygon,
    friction_circle,
    friction_radius,
    inclination_to_horizontal,
    tangent_reaction,
    two_force_line,
)
from geomcad.geom import Line, Vec, mirror
from geomcad.problem import (
    Build,
    ParamValue,
)
from geomcad.units import deg, to_deg


@dataclass(frozen=True)
class Forces:
    """One run of the force analysis (with the given f, or with f = 0)."""

    f: float
    rho: float
    fc_B: FrictionCircle
    fc_F: FrictionCircle
    fc_H: FrictionCircle
    link3: TwoForceLine
    u32: Vec  # direction of R_32 (link 3 on the sleeve, at B)
    tri2: ForcePolygon  # G_2 + R_32 + R_42 = 0
    T2: Vec  # where the lines of R_32 and R_42 meet (on the axis)
    Q: Vec  # where the lines of R_36 and G_6 meet
    P_line: Line
    K: Vec
    R76_line: Line
    poly6: ForcePolygon  # G_6 + R_36 + F_i + R_76 = 0
    R32: float
    P: float
    F_i: float
    R76: float
    alpha: float
    beta: float
    omega: float


@dataclass(frozen=True)
class Geometry:
    """The governor's position and both force analyses, for the sheet and the tests."""

    A: Vec
    B: Vec
    F: Vec
    D: Vec
    H: Vec
    G: Vec
    theta: float
    omega3_per_omega6: float
    m2: float
    m_ball: float
    g: float
    d: float
    direction: int
    run: Forces
    free: Forces


def _check_params(p: Mapping[str, ParamValue]) -> dict[str, float]:
    v = {name: float(x) for name, x in p.items()}  # every parameter of 2013-7 is a number
    if v["direction"] not in (1.0, -1.0):
        raise ParameterError(
            "direction",
            p["direction"],
            "must be +1 (slowly accelerating) or −1 (slowly slowing down)",
        )
    theta = deg(v["theta_deg"])
    reach = v["l_GH"] / 2.0 + v["l_FH"] * math.sin(theta) - v["l_AB"] / 2.0
    if abs(reach) >= v["l_BF"]:
        raise ParameterError(
            "l_BF",
            v["l_BF"],
            f"too short: link 3 must reach from B's vertical x = l_AB/2 to F, "
            f"{abs(reach):.6g} m across",
        )
    return v


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """The seed's graphical solution as recorded steps, with friction and again with f = 0."""
    v = _check_params(p)
    c = Construction("2013-7: centrifugal governor, force polygons with friction circles")
    theta = deg(v["theta_deg"])
    direction = int(v["direction"])

    # --- the position -------------------------------------------------------------------------
    H = c.point("H", (v["l_GH"] / 2.0, 0.0), op="collar joint, (l_GH/2, 0)")
    G = c.point("G", (-v["l_GH"] / 2.0, 0.0), op="collar joint, (−l_GH/2, 0)")
    e6 = Vec(math.sin(theta), -math.cos(theta))
    arm = c.line("HD", H, e6, "arm 6 from H at θ to the vertical, down and outwards", role="link")
    F = c.point("F", arm.at(v["l_FH"]), role="link", op="on HD at l_FH from H")
    D = c.point("D", arm.at(v["l_DH"]), role="link", op="on HD at l_DH from H (the ball)")
    vert_B = c.line(
        "x = l_AB/2", Vec(v["l_AB"] / 2.0, 0.0), (0.0, -1.0), "vertical of the sleeve's pivot B"
    )
    kF = c.circle("k_BF", F, v["l_BF"], role="hidden", r_name="l_BF")
    B = c.intersect(
        "B",
        vert_B,
        kF,
        Where(lambda q: q.y < F.y, "below F (the sleeve hangs under the arm)"),
        role="link",
        op="line x = l_AB/2 ∩ circle(F, l_BF)",
    )
    axis = Line(Vec(0.0, 0.0), Vec(0.0, 1.0))
    A = c.point("A", mirror(B, axis), role="link", op="mirror of B over the shaft's axis")

    # --- 1. relative rotations: V_F = ω6 × HF = V_B + ω3 × BF, V_B vertical ---------------------
    hf, bf = F - H, F - B
    w3 = c.value(
        "ω_3/ω_6",
        hf.y / bf.y,  # x-components: −ω6·(F − H)_y = −ω3·(F − B)_y
        "from V_F = V_B + ω_3 × BF with V_B vertical (per unit ω_6)",
        (H, F, B),
        kind="velocity_ratio",
        args={
            "w": "ω_3/ω_6",
            "eq": "V_F = ω_6 × HF = V_B + ω_3 × BF",
            "ratio": "(y_F – y_H)/(y_F – y_B)",
            "value": hf.y / bf.y,
        },
    )
    w6 = float(direction)  # θ̇'s sign: the arm turns ccw while the balls rise (right half)
    senses = {
        "B": _sign(w3 * w6),  # ω_32 = ω_3 − ω_2, ω_2 = 0 (the sleeve translates)
        "F": _sign(w3 * w6 - w6),  # ω_36 = ω_3 − ω_6
        "H": _sign(w6),  # ω_67 = ω_6 − ω_7, the collar does not turn in the plane
    }
    for joint, what, expr in (
        ("B", "ω_32", "ω_3 – ω_2 = ω_3"),
        ("F", "ω_36", "ω_3 – ω_6"),
        ("H", "ω_67", "ω_6 – ω_7 = ω_6"),
    ):
        c.value(
            f"sense {what}",
            float(senses[joint]),
            f"sign of {what} (+1 ccw, −1 cw)",
            kind="sense",
            args={
                "w": _markup(what),
                "expr": expr,
                "turn": {1: "@ccw", -1: "@cw", 0: "@still"}[senses[joint]],
            },
        )

    run = _forces(c, v, B, F, D, H, senses, v["f"], "")
    free = _forces(c, v, B, F, D, H, senses, 0.0, "f=0: ")

    r_D = D.x
    results: dict[str, Any] = {
        "rho": run.rho,
        "alpha_deg": to_deg(run.alpha),
        "R32": run.R32,
        "P": run.P,
        "beta_deg": to_deg(run.beta),
        "F_i": run.F_i,
        "r_D": r_D,
        "omega": run.omega,
        "omega_no_friction": free.omega,
    }
    notes: list[str] = []
    if direction < 0:
        notes.append(
            "direction −1: the governor slowly slows down, the balls sink and every friction "
            "moment turns the other way"
        )
    geo = Geometry(
        A, B, F, D, H, G, theta, w3, v["m2"], v["m_ball"], v["g"], v["d"], direction, run, free
    )
    return Build(results, c, notes, data=geo)


def _sign(x: float) -> int:
    return (x > 0.0) - (x < 0.0)


def _markup(name: str) -> str:
    """A protocol name (``R_32``, ``ω_67``) as label markup (``R_{32}``)."""
    return re.sub(r"_(\w{2,})", r"_{\1}", name)


def _forces(
    c: Construction,
    v: dict[str, float],
    B: Vec,
    F: Vec,
    D: Vec,
    H: Vec,
    senses: dict[str, int],
    f: float,
    pre: str,
) -> Forces:
    """Steps 2–6 of the seed's solution with friction coefficient ``f``; step names start with
    ``pre`` (the frictionless run repeats them)."""
    d = v["d"]
    rho = c.value(
        f"{pre}ρ",
        friction_radius(d, f),
        "(d/2)·sin(arctan f)",
        kind="friction_radius" if f > 0.0 else "no_friction",
        args={"d": d * 1000.0, "f": f, "rho": friction_radius(d, f) * 1000.0, "at": "B, F, H"},
    )
    fcs: dict[str, FrictionCircle] = {}
    for joint, centre, what in (("B", B, "ω_32"), ("F", F, "ω_36"), ("H", H, "ω_67")):
        fcs[joint] = c.record(
            f"{pre}ρ_{joint}",
            f"friction circle of {joint}, radius ρ, opposing {what}",
            friction_circle(centre, d, f, senses[joint], joint),
            (centre,),
            kind="friction_circle",
            args={"j": joint, "w": _markup(what)},
        )
    fc_B, fc_F, fc_H = fcs["B"], fcs["F"], fcs["H"]

    # --- 3. link 3: a two-force member in tension ------------------------------------------
    link3 = c.run(
        f"{pre}l_3",
        "line of action of link 3: the common tangent of the friction circles at B and F "
        "whose moments oppose ω_32 and ω_36",
        lambda: two_force_line(fc_B, fc_F, tension=True),
        (fc_B, fc_F),
    )
    # the order of construction writes the line by this step: the tangent of the kind the
    # senses of the relative rotations at its ends ask for, at α to the centre line
    alpha = c.value(
        f"{pre}α",
        abs(link3.alpha),
        "angle between link 3's line of action and BF",
        kind=f"two_force_{link3.kind.replace(' ', '_')}",
        args={
            "link": 3,
            "a": "B",
            "b": "F",
            "wa": "ω_{32}",
            "wb": "ω_{36}",
            "alpha": math.degrees(abs(link3.alpha)),
        },
    )
    u32 = -link3.line.d  # link 3 pulls the sleeve towards F
    if u32.y <= 0.0:
        up = math.degrees(math.acos(max(-1.0, min(1.0, u32.y))))
        raise ConstructionError(
            c.step(f"{pre}l_3").title,
            f"self-locking: link 3's line of action makes {up:.4g}° with the vertical (BF at "
            f"{math.degrees(math.acos(max(-1.0, min(1.0, (F - B).unit().y)))):.4g}°, turned by "
            f"α = {math.degrees(alpha):.4g}°), so its pull cannot hold the sleeve up",
        )

    # --- 4. body 2: G_2 + R_32 + R_42 = 0 ------------------------------------------------------
    axis = Line(Vec(0.0, 0.0), Vec(0.0, 1.0))
    u42 = Vec(-u32.x, u32.y)  # the mirror image of R_32 over the axis
    G2 = Vec(0.0, -v["m2"] * v["g"])
    tri2 = force_polygon(
        c,
        f"{pre}plan 2",
        [Known("G_2", G2), Unknown("R_32", u32), Unknown("R_42", u42)],
        equation="G_2 + R_32 + R_42 = 0",
        words={"G_2": "G_2", "R_32": "R_{32}", "R_42": "R_{42}"},
    )
    R32 = tri2.signed("R_32")
    if R32 <= 0.0:
        raise ConstructionError(
            c.step(f"{pre}plan 2: closing vertex").title,
            f"self-locking: the sleeve's polygon closes with R_32 = {R32:.6g} N ≤ 0",
        )
    c.value(f"{pre}R_32", R32, "|R_32| off the force triangle of body 2")
    line32 = Line(link3.touch_a, u32)
    line42 = Line(mirror(link3.touch_a, axis), u42)
    T2 = c.intersect(f"{pre}T_2", line32, line42, op="line of R_32 ∩ line of R_42 (on the axis)")

    # --- 5. arm 6: P = G_6 + R_36 through Q, K, the tangent at H -------------------------------
    u36 = link3.line.d  # R_36 = −R_63: link 3 pulls F towards B
    G6 = Vec(0.0, -v["m_ball"] * v["g"])
    line36 = c.record(f"{pre}line R_36", "link 3's line of action, directed as R_36", link3.line)
    line_g6 = c.line(f"{pre}line G_6", D, (0.0, -1.0), "vertical through D")
    line_fi = c.line(f"{pre}line F_i", D, (1.0, 0.0), "horizontal through D, outwards")
    Q = c.intersect(
        f"{pre}Q",
        line36,
        line_g6,
        op="line of R_36 ∩ line of G_6",
        kind="action_meet",
        args={"a": "R_{36}", "b": "G_6"},
    )
    P_vec = G6 + u36 * R32
    c.value(f"{pre}P", P_vec.norm, "|G_6 + R_36| off the plan", ())
    P_line = c.line(
        f"{pre}line P",
        Q,
        P_vec,
        "through Q parallel to P = G_6 + R_36",
        kind="resultant_line",
        args={"F": "P", "sum": "G_6 + R_{36}", "value": P_vec.norm, "p": "Q"},
    )
    K = c.intersect(
        f"{pre}K",
        P_line,
        line_fi,
        op="line of P ∩ line of F_i",
        kind="three_force",
        args={"a": "P", "b": "Ф_6", "c": "R_{76}", "link": 6},
    )
    # the sense of R_76: the polygon closed on the frictionless line KH
    estimate = close_polygon(
        [Known("P", P_vec), Unknown("F_i", Vec(1.0, 0.0)), Unknown("R_76", H - K)]
    )
    hint = (H - K) * estimate.signed("R_76")
    R76_line = c.run(
        f"{pre}line R_76",
        "tangent from K to the friction circle at H whose moment opposes ω_67",
        lambda: tangent_reaction(K, fc_H, hint),
        (K, fc_H),
        kind="tangent_reaction" if fc_H.arm > 0.0 else "centre_reaction",
        args={"F": "R_{76}", "p": "K", "j": "H", "w": "ω_{67}"},
    )

    # --- 6. the polygon of arm 6: G_6 + R_36 + F_i + R_76 = 0 ----------------------------------
    poly6 = force_polygon(
        c,
        f"{pre}plan 6",
        [
            Known("G_6", G6),
            Known("R_36", u36 * R32),
            Unknown("F_i", Vec(1.0, 0.0)),
            Unknown("R_76", R76_line.d),
        ],
        equation="G_6 + R_36 + F_i + R_76 = 0",
        words={"G_6": "G_6", "R_36": "R_{36}", "F_i": "Ф_6", "R_76": "R_{76}"},
    )
    F_i = poly6.signed("F_i")
    R76 = poly6.signed("R_76")
    if R76 <= 0.0:
        raise ConstructionError(
            c.step(f"{pre}plan 6: closing vertex").title,
            f"the polygon gives R_76 = {R76:.6g} N against the sense that chose its tangent: "
            "friction at H this large leaves no consistent reaction",
        )
    if F_i <= 0.0:
        word = "rise" if senses["H"] > 0 else "sink"
        raise ConstructionError(
            c.step(f"{pre}plan 6: closing vertex").title,
            f"self-locking: the polygon of arm 6 closes with F_i = {F_i:.6g} N ≤ 0, so friction "
            f"alone holds the arm and the balls do not {word} at any ω",
        )
    beta = c.value(
        f"{pre}β", inclination_to_horizontal(R76_line.d), "R_76's line to the horizontal"
    )
    r_D = D.x
    omega = c.value(
        f"{pre}ω",
        math.sqrt(F_i / (v["m_ball"] * r_D)),
        "√(F_i/(m·r_D))",
        kind="omega_inertia" if not pre else "omega_no_friction",
        args={"F": F_i, "m": v["m_ball"], "r": r_D, "value": math.sqrt(F_i / (v["m_ball"] * r_D))},
    )
    return Forces(
        f,
        rho,
        fc_B,
        fc_F,
        fc_H,
        link3,
        u32,
        tri2,
        T2,
        Q,
        P_line,
        K,
        R76_line,
        poly6,
        R32,
        P_vec.norm,
        F_i,
        R76,
        alpha,
        beta,
        omega,
    )
