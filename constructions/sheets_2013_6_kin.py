"""2013-6's kinematic-analysis sheet (``2013-6-kinematics``), A2 landscape.

Top: the synthesized six-bar at the crank angle φ1 at a GOST scale, its velocity plan (pole p)
and its acceleration plan (pole π), each vector equation drawn as its two lines meeting. Bottom:
the slider's displacement s, velocity v and acceleration a over a crank turn, from the sweep, with
φ1 marked and the plans' values at φ1 as dots on the curves (they must lie on them). Right: the
values read off the plans beside the sweep's, and the order of the plans.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad.sheet import Sheet, TitleBlock, Viewport, fmt_number, gost_scale_to_fit, start
from geomcad.sheet.graph import Axis, Graph
from geomcad.sheet.lang import Words
from geomcad.sheet.model import Polyline
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.plans import draw_plan, plan_scale

if TYPE_CHECKING:
    from geomcad.problem import Solution

    from .kin_2013_6 import Analysis

WORDS = Words(__package__, "sheets_2013_6_kin")

MECH_VIEW = (26.0, 30.0, 246.0, 196.0)
VPLAN_VIEW = (256.0, 24.0, 416.0, 196.0)
APLAN_VIEW = (426.0, 24.0, 586.0, 196.0)
GRAPH_X = (44.0, 374.0)  # the φ axis from 0 to 2π
GRAPH_ROWS = ((206.0, 262.0), (274.0, 334.0), (346.0, 406.0))  # (top, bottom) of s, v, a
PANEL = (400.0, 212.0)


def kinematics_sheet(sol: Solution) -> tuple[str, Sheet]:
    geo = sol.data
    m = geo.mechanism
    an: Analysis = geo.analysis
    c = an.c
    pts = [c[n] for n in ("O1", "O2", "A", "B", "C")]
    xs, ys = [q.x for q in pts], [q.y for q in pts]
    pad = 0.25 * m.l3
    w, h = max(xs) - min(xs) + 2 * pad, max(ys) - min(ys) + 2 * pad
    room_w, room_h = MECH_VIEW[2] - MECH_VIEW[0], MECH_VIEW[3] - MECH_VIEW[1] - 10.0
    k = gost_scale_to_fit(w, h, room_w, room_h)
    kv = plan_scale(an.vp, VPLAN_VIEW[2] - VPLAN_VIEW[0], VPLAN_VIEW[3] - VPLAN_VIEW[1] - 14.0)
    ka = plan_scale(an.ap, APLAN_VIEW[2] - APLAN_VIEW[0], APLAN_VIEW[3] - APLAN_VIEW[1] - 14.0)
    tb = TitleBlock(
        title="Кинематический анализ шестизвенного механизма",
        designation="ТММ.2013-6.02",
        scale=k.ratio_text(),
    )
    d = start("A2", tb)
    phi1_deg = fmt_number(math.degrees(an.phi1), digits=4)
    d.text(f"Механизм в положении φ_1 = {phi1_deg}°", (MECH_VIEW[0] + 2.0, 13.0), 5.0)
    d.text(f"{k.label()}   (M {k.ratio_text()})", (MECH_VIEW[0] + 2.0, 20.0), 3.5)
    at = ((MECH_VIEW[0] + MECH_VIEW[2]) / 2.0, (MECH_VIEW[1] + 10.0 + MECH_VIEW[3]) / 2.0)
    v = d.viewport(k, ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0), at)
    _mechanism(v, c, m, an)
    draw_plan(d, an.vp, kv, VPLAN_VIEW)
    draw_plan(d, an.ap, ka, APLAN_VIEW)
    _diagrams(d, an, m)
    _panel(d, an, m, kv.k, ka.k)
    return ("kinematics", d.finish())


def _mechanism(v: Viewport, c: Any, m: Any, an: Analysis) -> None:
    O1, O2, A, B, C = (c[n] for n in ("O1", "O2", "A", "B", "C"))
    d = m.guide_d.unit()
    ext = v.scale.model(30.0)
    v.circle(O1, m.l1, "centre")
    v.line_over(c["path"], [C - d * ext, C + d * ext], "centre")
    v.guide(C - d * ext, C + d * ext, (0.0, -1.0))
    for a, b in ((O1, A), (A, B), (O2, B), (B, C)):
        v.seg(a, b, "link")
    v.slider(C, d)
    for q in (A, B):
        v.joint(q)
    v.pivot(O1)
    v.pivot(O2)
    a1 = math.degrees(an.phi1) + 25.0  # ω1's arrow spans 90° just past the crank
    v.turn(O1, an.omega1, a1 if an.omega1 > 0 else a1 + 90.0, "ω_1", r_mm=7.0, sweep_deg=90.0)
    for q, name, pref in (
        (O1, "O_1", (-1.0, -1.0)),
        (O2, "O_2", (1.0, -1.0)),
        (A, "A", (-1.0, 1.0)),
        (B, "B", (1.0, 1.0)),
        (C, "C", (0.0, 1.0)),
    ):
        v.label(q, name, prefer=pref, clear=4.0)
    for q, n in (
        (O1 + (A - O1) * 0.5, "1"),
        (A + (B - A) * 0.5, "2"),
        (O2 + (B - O2) * 0.5, "3"),
        (B + (C - B) * 0.5, "4"),
    ):
        v.label(q, n, 3.5, clear=0.8)


def _diagrams(d: Any, an: Analysis, m: Any) -> None:
    """s(φ), v(φ), a(φ) stacked, one φ axis scale, φ1 marked, the plans' values as dots."""
    room = GRAPH_X[1] - GRAPH_X[0]
    x_axis = Axis.fit("φ", "рад", 0.0, 2.0 * math.pi, room)
    g_dir = m.guide_d.unit()
    phi1 = an.phi1 % (2.0 * math.pi)
    s_at = float(np.interp(phi1, an.phi, an.s))
    curves = (
        ("S", "м", an.s, s_at, ""),
        ("V_C", "м/с", an.v, an.vp["c"].dot(g_dir), "по плану"),
        ("a_C", "м/с²", an.a, an.ap["c"].dot(g_dir), "по плану"),
    )
    d.text(
        "Диаграммы перемещения, скорости и ускорения ползуна за оборот кривошипа "
        f"(ω_1 = {fmt_number(an.omega1, digits=4)} рад/с; S – от левого крайнего положения)",
        (GRAPH_X[0] - 16.0, GRAPH_ROWS[0][0] - 1.0),
        3.5,
    )
    for (sym, unit, ys, at_phi1, mark), (top, bottom) in zip(curves, GRAPH_ROWS, strict=True):
        lo, hi = min(float(np.min(ys)), 0.0), max(float(np.max(ys)), 0.0)
        y_axis = Axis.fit(sym, unit, lo, hi, bottom - top - 14.0, name=sym.split("_")[0])
        zero_y = top + 10.0 + y_axis.mm(y_axis.hi)
        g = Graph(d, x_axis, y_axis, (GRAPH_X[0], zero_y))
        g.axes(tick_labels=True)
        g.curve(an.phi, ys, "result")
        x1, _ = g.p(phi1, 0.0)
        d.sheet.add(Polyline(((x1, top + 8.0), (x1, bottom)), "construction"))
        g.point(phi1, float(at_phi1), mark)
        g.factors((GRAPH_X[1] - 90.0, top + 6.0))


def _panel(d: Any, an: Analysis, m: Any, kv: float, ka: float) -> None:
    """Values read off the plans beside the sweep's, and the order of the plans."""
    x, y = PANEL
    g_dir = m.guide_d.unit()
    phi = np.array([an.phi1])
    r = m.sweep(phi, an.omega1)
    aa, ab, ac = (q[0] for q in m.accelerations(phi, an.omega1))
    rows = [["Величина", "По плану", "На плане, мм", "По функциям положения"]]
    vals = (
        ("V_A", an.vp["a"].norm, kv, float(np.hypot(*r.V_A[0]))),
        ("V_B", an.vp["b"].norm, kv, float(np.hypot(*r.V_B[0]))),
        ("V_C", an.vp["c"].dot(g_dir), kv, float(r.v[0])),
        ("a_A", an.ap["a"].norm, ka, float(np.hypot(*aa))),
        ("a_B", an.ap["b"].norm, ka, float(np.hypot(*ab))),
        ("a_C", an.ap["c"].dot(g_dir), ka, float(ac @ m.guide_d.unit().array())),
    )
    d.text("Значения в положении φ_1 (V_C, a_C – проекции на направляющую)", (x, y + 3.5), 3.5)
    for name, val, kk, check in vals:
        rows.append(
            [
                name,
                fmt_number(val, digits=5),
                fmt_number(abs(val) / kk, digits=4),
                fmt_number(check, digits=5),
            ]
        )
    for i, (wn, wv) in enumerate(zip(("ω_2", "ω_3", "ω_4"), an.omegas, strict=True)):
        rows.append([wn, fmt_number(wv, digits=5), "", ""])
        rows.append([("ε_2", "ε_3", "ε_4")[i], fmt_number(an.epsilons[i], digits=5), "", ""])
    _, h = d.table(x, y + 6.0, (24.0, 40.0, 30.0, 40.0), rows, row_h=5.0)
    y += 6.0 + h + 3.0
    d.text("ω, ε – против часовой стрелки > 0; V, a – в м/с, м/с²; ω – рад/с; ε – рад/с²",
           (x, y + 2.5), 2.5)  # fmt: skip


def motion(sol: Solution, frames: int) -> Frames:
    """The synthesized six-bar over one crank turn from the kinematics sheet's position (60°
    past C's left extreme), at ω1 of the analysis: the joints, C on its guide, the paths of A, B
    and C, and the velocity plan (pa, pb, pc)."""
    from .p2013_6 import ANALYSIS_OMEGA1, ANALYSIS_TURN

    geo = sol.data
    mech = geo.mechanism
    assert mech is not None, "build refuses a solution that is not a crank-rocker"
    r = mech.sweep(turn(frames, geo.phi_min + ANALYSIS_TURN, ANALYSIS_OMEGA1), ANALYSIS_OMEGA1)
    fixed = {"O1": mech.O1, "O2": mech.O2}
    points = {k: np.tile([v.x, v.y], (frames, 1)) for k, v in fixed.items()}
    points |= {"A": r.A, "B": r.B, "C": r.C}
    cx = r.C[:, 0]
    reach = 0.15 * float(cx.max() - cx.min()) + geo.l4 * 0.1
    y = mech.guide_p.y
    return Frames(
        title=WORDS("motion_title", id=sol.problem.id),
        phi=r.phi,
        points=points,
        links=(("O1", "A"), ("A", "B"), ("O2", "B"), ("B", "C")),
        fixed=("O1", "O2"),
        traced=("A", "B", "C"),
        sliders={"C": (mech.guide_d.x, mech.guide_d.y)},
        guides=(((float(cx.min()) - reach, y), (float(cx.max()) + reach, y)),),
        velocities={"A": r.V_A, "B": r.V_B, "C": r.V_C},
        plan_edges=(("A", "B"), ("B", "C")),
        omega1=ANALYSIS_OMEGA1,
    )
