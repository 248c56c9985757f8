"""2013-6's kinematic-analysis sheet (``2013-6-kinematics``), A2 landscape, and the six-bar's
scheme that both 2013-6 sheets draw.

Top: the synthesized six-bar at the crank angle φ1 at a GOST scale, and its acceleration plan
(pole π). Bottom: the slider's displacement s, velocity v and acceleration a over a crank turn,
from the sweep, with φ1 marked and the plans' values at φ1 as dots on the curves (they must lie
on them); beside them the velocity plan (pole p) and the values read off the plans beside the
analytic ones. Each vector equation is drawn as its two lines meeting; a vector shorter than two
arrowheads is drawn as its end point only, named in a note under its plan.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.sheet import (
    Drawing,
    Scale,
    Sheet,
    TitleBlock,
    Viewport,
    fmt_number,
    gost_scale_to_fit,
    start,
)
from geomcad.sheet.drawing import ARROW_LEN
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.model import Polyline
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.plans import LINE_OVER_MM, draw_plan, markup_of, plan_scale
from geomcad.sheet.scale import ScaleStyle
from geomcad.sheet.scheme import draw_scheme
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.structure import Link, Mechanism, prismatic, revolute

if TYPE_CHECKING:
    from geomcad.problem import Solution

    from .kin_2013_6 import Analysis

WORDS = Words(__package__, "sheets_2013_6_kin")

#: The views on the A3 sheet (mm: x0, y0, x1, y1): the mechanism, the velocity plan and the
#: acceleration plan side by side on top; the diagrams and the tables below.
MECH_VIEW = (24.0, 24.0, 165.0, 126.0)
PANEL = (168.0, 24.0)  # the values read off the plans, then the links' ω and ε
APLAN_VIEW = (258.0, 24.0, 414.0, 126.0)
VPLAN_VIEW = (232.0, 134.0, 414.0, 194.0)
EQUATIONS = (232.0, 198.0, 182.0)  # x, y, width of the plans' vector equations
NOTE_H = 7.0  # room under a plan for its note on short vectors
GRAPH_X = (44.0, 216.0)  # the φ axis from 0 to 2π
GRAPH_SPAN = (134.0, 290.0)  # the diagrams' rows share this height (mm, top to bottom)
GRAPH_PAD = 15.0  # each row's room beyond its curve: the arrow, the symbol, the tick values
#: How far (m) the guide is drawn either side of the slider, as a share of l4.
GUIDE_EXT = 0.3
#: A vector shorter than this (mm) is drawn as its end point (it would be all arrowhead).
SHORT_MM = 2.0 * ARROW_LEN


def num(x: float, digits: int = 6) -> str:
    """A number in the language being drawn."""
    return fmt_number(x, current(), digits)


def factor(k: Scale) -> str:
    """A scale factor as the language being drawn writes it."""
    return k.label(ScaleStyle(lang=current()))


def mechanism(pts: Mapping[str, Vec], along: Vec) -> Mechanism:
    """The six-bar as a structure (GOST 2.770 numbering) in the position ``pts`` (O1, A, B, O2,
    C): crank 1, rod 2, rocker 3, link 4, slider 5 on the frame 0's guide along ``along``."""
    O1, A, B, O2, C = (pts[n] for n in ("O1", "A", "B", "O2", "C"))
    return Mechanism(
        links=tuple(Link(str(i)) for i in range(1, 6)),
        pairs=(
            revolute("O1", "0", "1", O1),
            revolute("A", "1", "2", A),
            revolute("B", "2", "3", B),
            revolute("B4", "3", "4", B),
            revolute("O2", "3", "0", O2),
            revolute("C", "4", "5", C),
            prismatic("C5", "5", "0", C, along),
        ),
    )


def six_bar(
    v: Viewport,
    pts: Mapping[str, Vec],
    along: Vec,
    labels: Mapping[str, tuple[tuple[float, float], float]],
    number_at: Mapping[str, float] | None = None,
) -> None:
    """The six-bar's scheme in one position, the one scheme view of both 2013-6 sheets: the
    structure drawn by :func:`geomcad.sheet.scheme.draw_scheme` (GOST 2.770: supports turned
    away from their links, the slider on its guide, every link numbered; link n's number at
    the share ``number_at[n]`` of its length, the middle by default), and the points named as
    ``labels`` asks (name → (preferred direction, clearance mm))."""
    mech = mechanism(pts, along)
    ends = {"1": ("O1", "A"), "2": ("A", "B"), "3": ("O2", "B"), "4": ("B", "C")}
    at = {"1": 0.5, "2": 0.5, "3": 0.5, "4": 0.5, **(number_at or {})}
    numbers = {n: pts[a] + (pts[b] - pts[a]) * at[n] for n, (a, b) in ends.items()}
    # the slider's number by its block's top edge
    numbers["5"] = pts["C"] + along.unit().perp() * v.scale.model(3.0)
    draw_scheme(v, mech, pair_labels={}, link_labels=numbers)
    for name, (pref, clear) in labels.items():
        v.label(pts[name], markup_of(name), prefer=pref, clear=clear)


def kinematics_sheet(sol: Solution) -> tuple[str, Sheet]:
    geo = sol.data
    m = geo.mechanism
    an: Analysis = geo.analysis
    c = an.c
    pts = [c[n] for n in ("O1", "O2", "A", "B", "C")]
    # the mechanism's box: its joints, the crank's circle, the guide 30 mm past C (about 0.15 m
    # at the scales that fit), with room for the supports and labels
    ext = GUIDE_EXT * m.l4
    xs = [q.x for q in pts] + [m.O1.x - m.l1, m.O1.x + m.l1, c["C"].x + ext]
    ys = [q.y for q in pts] + [m.O1.y - m.l1, m.O1.y + m.l1]
    pad = 0.04 * m.l3
    w, h = max(xs) - min(xs) + 2 * pad, max(ys) - min(ys) + 2 * pad
    room_w, room_h = MECH_VIEW[2] - MECH_VIEW[0], MECH_VIEW[3] - MECH_VIEW[1] - 10.0
    k = gost_scale_to_fit(w, h, room_w, room_h)
    kv, ka = (
        plan_scale(plan, box[2] - box[0] - 2.0 * LINE_OVER_MM, box[3] - box[1] - 8.0 - NOTE_H)
        for plan, box in ((an.vp, VPLAN_VIEW), (an.ap, APLAN_VIEW))
    )
    tb = TitleBlock(
        title=WORDS("tb_title"),
        designation=WORDS("designation"),
        scale=k.ratio_text(),
        lang=current(),
    )
    d = start("A3", tb)
    d.text(WORDS("title", phi=num(math.degrees(an.phi1), 4)), (MECH_VIEW[0] + 2.0, 13.0), 5.0)
    d.text(f"{factor(k)}   (M {k.ratio_text()})", (MECH_VIEW[0] + 2.0, 20.0), 3.5)
    at = ((MECH_VIEW[0] + MECH_VIEW[2]) / 2.0, (MECH_VIEW[1] + 10.0 + MECH_VIEW[3]) / 2.0)
    v = d.viewport(k, ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0), at)
    _mechanism(v, c, m, an)
    lang = current()
    for plan, scale, box in ((an.vp, kv, VPLAN_VIEW), (an.ap, ka, APLAN_VIEW)):
        title = f"{WORDS('vplan' if plan.kind == 'v' else 'aplan')}, {factor(scale)}"
        inner = (box[0], box[1], box[2], box[3] - NOTE_H)
        draw_plan(d, plan, scale, inner, lang, title=title, min_mm=SHORT_MM)
        _short_note(d, plan, scale, box)
    _diagrams(d, an, m)
    _panel(d, an, m, kv.k, ka.k)
    x, y, width = EQUATIONS
    y = d.text(WORDS("equations"), (x, y + 3.5), 3.5).at[1] + 2.0
    for i in range(1, 5):
        y = d.paragraph(f"{i}. {WORDS(f'eq_{i}')}", x, y, width, 2.5, indent=4.0) + 0.4
    return ("kinematics", d.finish())


def _short_note(d: Drawing, plan: Plan, scale: Scale, box: tuple[float, ...]) -> None:
    """Under a plan: the vectors drawn as points because they are shorter than two
    arrowheads, each with its value and length."""
    short = []
    for vec in plan.vectors:
        value = (plan.points[vec.head] - plan.points[vec.tail]).norm
        mm = scale.mm(value)
        if 0.0 < mm < SHORT_MM:
            unit = WORDS("unit_v" if plan.kind == "v" else "unit_a")
            short.append(f"{vec.label} = {num(value, 3)} {unit} ({num(mm, 2)} {WORDS('mm')})")
    if short:
        text = WORDS("short", vectors="; ".join(short), mm=num(SHORT_MM, 2))
        d.paragraph(text, box[0], box[3] - NOTE_H + 3.0, box[2] - box[0], 2.5)


def _mechanism(v: Viewport, c: Any, m: Any, an: Analysis) -> None:
    O1, C = c["O1"], c["C"]
    d = m.guide_d.unit()
    ext = GUIDE_EXT * m.l4
    v.circle(O1, m.l1, "centre")
    v.line_over(c["path"], [C - d * ext, C + d * ext], "centre")
    pts = {n: c[n] for n in ("O1", "A", "B", "O2", "C")}
    labels = {
        "O1": ((-1.0, -1.0), 4.0),
        "O2": ((1.0, -1.0), 4.0),
        "A": ((-1.0, 1.0), 4.0),
        "B": ((1.0, 1.0), 4.0),
        "C": ((1.0, 0.0), 4.7),
    }
    six_bar(v, pts, d, labels)
    a1 = math.degrees(an.phi1) + 25.0  # ω1's arrow spans 90° just past the crank
    v.turn(O1, an.omega1, a1 if an.omega1 > 0 else a1 + 90.0, "ω_1", r_mm=11.0, sweep_deg=90.0)


def _diagrams(d: Drawing, an: Analysis, m: Any) -> None:
    """s(φ), v(φ), a(φ) stacked, one φ axis scale, φ1 marked, the plans' values as dots."""
    lang = current()
    room = GRAPH_X[1] - GRAPH_X[0]
    x_axis = Axis.fit("φ", WORDS("rad"), 0.0, 2.0 * math.pi, room)
    g_dir = m.guide_d.unit()
    phi1 = an.phi1 % (2.0 * math.pi)
    s_at = float(np.interp(phi1, an.phi, an.s))
    mark = WORDS("by_plan")
    curves = (
        ("S", WORDS("m"), an.s, s_at, ""),
        ("V_C", WORDS("m_s"), an.v, an.vp["c"].dot(g_dir), mark),
        ("a_C", WORDS("m_s2"), an.a, an.ap["c"].dot(g_dir), mark),
    )
    top = GRAPH_SPAN[0]
    d.text(WORDS("diagrams"), (GRAPH_X[0] - 18.0, top - 6.0), 3.5)
    d.text(WORDS("diagrams_2", w=num(an.omega1, 4)), (GRAPH_X[0] - 18.0, top - 1.5), 2.5)
    spans = [(min(float(np.min(c[2])), 0.0), max(float(np.max(c[2])), 0.0)) for c in curves]
    factors = _row_factors([hi - lo for lo, hi in spans])
    for (sym, unit, ys, at_phi1, label), (lo, hi), k in zip(curves, spans, factors, strict=True):
        y_axis = Axis(sym, unit, lo, hi, k, sym.split("_")[0])
        bottom = top + GRAPH_PAD + (hi - lo) / k
        zero_y = top + 9.0 + y_axis.mm(y_axis.hi)
        g = Graph(d, x_axis, y_axis, (GRAPH_X[0], zero_y))
        g.axes(lang, tick_labels=True)
        g.curve(an.phi, ys, "result")
        # φ1 marked from the top of the field down to the axis or the point (not through the
        # tick values under the axis)
        x1, y_axis0 = g.p(phi1, 0.0)
        y_pt = g.p(phi1, float(at_phi1))[1]
        d.sheet.add(Polyline(((x1, top + 8.0), (x1, max(y_axis0, y_pt))), "construction"))
        g.point(phi1, float(at_phi1), label)
        g.factors((GRAPH_X[0] + 26.0, top + 4.0), lang)
        top = bottom


def _row_factors(ranges: Sequence[float]) -> list[float]:
    """The diagrams' factors (nice, units per mm): of the few finest each range allows, the
    choice whose curves, stacked with their rows' room, fill GRAPH_SPAN with the largest least
    height."""
    total = GRAPH_SPAN[1] - GRAPH_SPAN[0] - GRAPH_PAD * len(ranges)
    options = []
    for r in ranges:
        r = r if r > 0.0 else 1.0
        ks = [nice_step(r / total)]
        while len(ks) < 6:
            ks.append(nice_step(ks[-1] * 1.001))
        options.append(ks)
    best: tuple[tuple[float, float], list[float]] | None = None
    for combo in itertools.product(*options):
        h = [(r if r > 0.0 else 1.0) / k for r, k in zip(ranges, combo, strict=True)]
        if sum(h) <= total and (best is None or (min(h), sum(h)) > best[0]):
            best = ((min(h), sum(h)), list(combo))
    assert best is not None, "the coarsest factors always fit"
    return best[1]


def _panel(d: Drawing, an: Analysis, m: Any, kv: float, ka: float) -> None:
    """Values read off the plans beside the analytic ones, and the links' ω and ε."""
    x, y = PANEL
    g_dir = m.guide_d.unit()
    phi = np.array([an.phi1])
    r = m.sweep(phi, an.omega1)
    aa, ab, ac = (q[0] for q in m.accelerations(phi, an.omega1))
    rows = [[WORDS("quantity"), WORDS("by_plan_col"), WORDS("on_plan_mm"), WORDS("analytic")]]
    vals = (
        ("V_A", an.vp["a"].norm, kv, float(np.hypot(*r.V_A[0]))),
        ("V_B", an.vp["b"].norm, kv, float(np.hypot(*r.V_B[0]))),
        ("V_C", an.vp["c"].dot(g_dir), kv, float(r.v[0])),
        ("a_A", an.ap["a"].norm, ka, float(np.hypot(*aa))),
        ("a_B", an.ap["b"].norm, ka, float(np.hypot(*ab))),
        ("a_C", an.ap["c"].dot(g_dir), ka, float(ac @ m.guide_d.unit().array())),
    )
    d.text(WORDS("values"), (x, y + 3.5), 3.5)
    for name, val, kk, check in vals:
        rows.append([name, num(val, 4), num(abs(val) / kk, 4), num(check, 4)])
    widths = [max(text_box(parse(row[i]), 2.5)[0] for row in rows) + 3.0 for i in range(4)]
    _, h = d.table(x, y + 6.0, widths, rows, row_h=5.0)
    # the links' angular velocities and accelerations under it
    y += 6.0 + h + 4.0
    rows = [[WORDS("link"), "ω, " + WORDS("rad_s"), "ε, " + WORDS("rad_s2")]]
    for i in range(3):
        rows.append([str(i + 2), num(an.omegas[i], 4), num(an.epsilons[i], 4)])
    d.text(WORDS("omegas"), (x, y + 3.5), 3.5)
    _, h = d.table(x, y + 6.0, (14.0, 30.0, 30.0), rows, row_h=5.0)
    y += 6.0 + h + 1.0
    d.paragraph(WORDS("signs"), x, y + 2.5, sum(widths), 2.5)


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
