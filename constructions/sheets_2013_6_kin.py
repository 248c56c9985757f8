"""2013-6's kinematic-analysis sheet (``2013-6-kinematics``), A3 landscape composed by
geomcad.sheet.compose (no view placed by hand), and the six-bar's scheme that both 2013-6
sheets draw.

Top: the synthesized six-bar at the crank angle φ1 at a GOST scale, and its acceleration plan
(pole π), the values read off the plans between them. Bottom: the slider's displacement s,
velocity v and acceleration a over a crank turn, from the sweep, with φ1 marked and the plans'
values at φ1 as dots on the curves (they must lie on them); beside them the velocity plan (pole
p) and the plans' vector equations. Each vector equation is drawn as its two lines meeting; a
vector shorter than two arrowheads is drawn as its end point only, named in a note under its
plan (a text view whose words follow the plan's factor, as the values table's lengths do).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.compose import (
    GAP,
    Column,
    Field,
    Figure,
    Row,
    Spacer,
    View,
    compose,
)
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.frame import TB_HEIGHT
from geomcad.sheet.lang import Words, current
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scheme import draw_scheme
from geomcad.sheet.settle import factor_of, settle
from geomcad.sheet.short import short_vectors
from geomcad.sheet.stacked import Stacked, StackedDiagrams
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.sheet.views import PlanView, Steps, Table, Text, extent_of, num
from geomcad.structure import Link, Mechanism, prismatic, revolute

if TYPE_CHECKING:
    from geomcad.construction import Construction
    from geomcad.kinematics.sixbar import SixBar
    from geomcad.problem import Solution

    from .kin_2013_6 import Analysis
    from .p2013_6 import Geometry

WORDS = Words(__package__, "sheets_2013_6_kin")

#: The sheet's format.
FORMAT = "A3"
#: Room (mm) under a plan for its note on short vectors before the plan's factor is known.
NOTE_H = 11.0
#: The splits of the top row (the mechanism, the tables, the acceleration plan; None: the
#: layout's choice) and of the bottom row (the diagrams, the velocity plan over the equations:
#: the diagrams a little wider, so that the φ axis takes 0.04 rad/mm).
TOP_W = None
BOTTOM_W = (1.0, 0.9)
#: Room (mm) kept round a plan, and how far its construction lines run on past their points
#: (PLAN_OVER, less than the usual LINE_OVER_MM: within the margin and the field's).
PLAN_MARGIN = 4.0
PLAN_OVER = 6.0
#: Width (mm) of the plans' vector equations.
EQUATIONS_W = 150.0
#: How far (m) the guide is drawn either side of the slider, as a share of l4.
GUIDE_EXT = 0.3
#: A vector shorter than this (mm) is drawn as its end point (it would be all arrowhead).


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
    # the slider's number by its block's top edge (3 mm: the block's half height)
    numbers["5"] = pts["C"] + along.unit().perp() * v.scale.model(3.0)
    draw_scheme(v, mech, pair_labels={}, link_labels=numbers)
    for name, (pref, clear) in labels.items():
        v.label(pts[name], markup_of(name), prefer=pref, clear=clear)


class _Kin:
    """The kinematics sheet's views and their arrangement. The values table gives the plans'
    vectors in mm at the plans' factors, which the arrangement chooses: the tree is arranged
    until the factors it was built with are the ones it gets."""

    def __init__(self, sol: Solution[Geometry]) -> None:
        geo = sol.data
        m = geo.mechanism
        an: Analysis = geo.analysis
        c = an.c
        pts = [c[n] for n in ("O1", "O2", "A", "B", "C")]
        # the mechanism's box: its joints, the crank's circle, the guide past C, with room for
        # the supports and labels
        ext = GUIDE_EXT * m.l4
        round_crank = [m.O1 - Vec(m.l1, m.l1), m.O1 + Vec(m.l1, m.l1)]
        box = extent_of([*pts, *round_crank, c["C"] + Vec(ext, 0.0)], 0.04 * m.l3)
        self.mech = Figure(box, lambda v: _mechanism(v, c, m, an), weight=2.0,
                           title=WORDS("title", phi=num(math.degrees(an.phi1), 4)))  # fmt: skip
        self.vplan = PlanView(
            an.vp,
            min_mm=SHORT_MM,
            title=WORDS("vplan"),
            series="plan",
            margin=PLAN_MARGIN,
            over_mm=PLAN_OVER,
        )
        self.aplan = PlanView(
            an.ap,
            min_mm=SHORT_MM,
            title=WORDS("aplan"),
            series="plan",
            margin=PLAN_MARGIN,
            over_mm=PLAN_OVER,
        )
        self.diagrams = _diagrams(an, m)
        # the order of construction of each plan, under the plan (ω and ε read off the plans
        # are in the links' table: on an A3 their lines would halve the plans' scales)
        vorder, aorder = ([n for n in p.order if c.step(n).kind != "plan_omega"]
                          for p in (an.vp, an.ap))  # fmt: skip
        self.vorder = Steps(c, EQUATIONS_W, only=vorder, title=WORDS("vorder"))
        self.aorder = Steps(c, EQUATIONS_W, only=aorder, title=WORDS("aorder"))
        self.an, self.m = an, m
        s = settle(
            lambda k: (self._tree(*k), None),
            lambda lay, _: (factor_of(lay, self.vplan), factor_of(lay, self.aplan)),
            (0.0, 0.0),
            Field.of_format(FORMAT),
        )
        self.tree, self.layout = s.tree, s.layout

    def _tree(self, kv: float, ka: float) -> Column:
        panel = Column(*_panel(self.an, self.m, kv, ka))
        anote, vnote = _short_note(self.an.ap, ka), _short_note(self.an.vp, kv)
        top = Row(self.mech, panel, Column(self.aplan, *anote, self.aorder), weights=TOP_W)
        # the title block under the right-hand column
        right = Column(self.vplan, *vnote, self.vorder, Spacer((10.0, TB_HEIGHT - GAP)))
        return Column(top, Row(self.diagrams, right, weights=BOTTOM_W))


def kinematics_sheet(sol: Solution[Geometry]) -> tuple[str, Sheet]:
    kin = _Kin(sol)
    lay = kin.layout
    k = lay[kin.mech].scale
    assert k is not None
    tb = TitleBlock(
        title=WORDS("tb_title"),
        designation=WORDS("designation"),
        scale=k.ratio_text(),
        lang=current(),
    )
    d = start(FORMAT, tb)
    compose(d, kin.tree, layout=lay)
    return ("kinematics", d.finish())


def _short_note(plan: Plan, k: float) -> tuple[View, ...]:
    """The note under a plan drawn at the factor ``k``: the vectors drawn as points because
    they are shorter than two arrowheads, each with its value and length (none when every
    vector is an arrow, or ``k`` is not known yet, 0: its room)."""
    # the room is kept when no vector is short, so that whether a note is there does not swing
    # the plans' factors from one arrangement to the next
    if k == 0.0:
        return (Spacer((10.0, NOTE_H)),)
    unit = WORDS("unit_v" if plan.kind == "v" else "unit_a")
    nb = "\u00a0"  # a value, its unit and its length in mm stay on one line
    short = [f"{s.vector.label}{nb}={nb}{num(s.value, 3)}{nb}{unit} "
             f"({num(s.mm, 2)}{nb}{WORDS('mm')})"
             for s in short_vectors(plan, Scale(k, plan.kind))]  # fmt: skip
    if not short:
        return (Spacer((10.0, NOTE_H)),)
    text = WORDS("short", vectors="; ".join(short), mm=num(SHORT_MM, 2))
    return (Text(paragraph=text, width=EQUATIONS_W),)


def _mechanism(v: Viewport, c: Construction, m: SixBar, an: Analysis) -> None:
    O1, C = c["O1"], c["C"]
    d = m.guide_d.unit()
    ext = GUIDE_EXT * m.l4
    v.circle(O1, m.l1, "centre")
    v.line_over(c["path"], [C - d * ext, C + d * ext], "centre")
    pts = {n: c[n] for n in ("O1", "A", "B", "O2", "C")}
    # each point's name: (preferred direction, clearance mm), hand-set clear of its joint and
    # support (C: past the slider's block)
    labels = {
        "O1": ((-1.0, -1.0), 4.0),
        "O2": ((1.0, -1.0), 4.0),
        "A": ((-1.0, 1.0), 4.0),
        "B": ((1.0, 1.0), 4.0),
        "C": ((1.0, 0.0), 4.7),
    }
    six_bar(v, pts, d, labels)
    # ω1's arrow spans 90° just past the crank, outside A's path (inside it the crank's number,
    # the support and O1's name have the room): 25° ahead of the crank, 4 mm outside A's path
    a1 = math.degrees(an.phi1) + 25.0
    r_w = v.scale.mm(m.l1) + 4.0
    v.turn(O1, an.omega1, a1 if an.omega1 > 0 else a1 + 90.0, "ω_1", r_mm=r_w, sweep_deg=90.0)


def _diagrams(an: Analysis, m: SixBar) -> StackedDiagrams:
    """s(φ), v(φ), a(φ) of the slider over a crank turn, φ1 marked, the plans' values as
    dots."""
    g_dir = m.guide_d.unit()
    mark = WORDS("by_plan")
    phi1 = an.phi1 % (2.0 * math.pi)
    rows = (
        Stacked("S", WORDS("m"), an.s, float(np.interp(phi1, an.phi, an.s))),
        Stacked("V_C", WORDS("m_s"), an.v, an.vp["c"].dot(g_dir), mark),
        Stacked("a_C", WORDS("m_s2"), an.a, an.ap["c"].dot(g_dir), mark),
    )
    return StackedDiagrams("φ", WORDS("rad"), 0.0, 2.0 * math.pi, an.phi, rows, phi1,
                           heading=WORDS("diagrams_2", w=num(an.omega1, 4)),
                           title=WORDS("diagrams"), weight=2.0)  # fmt: skip


def _panel(an: Analysis, m: SixBar, kv: float, ka: float) -> tuple[View, ...]:
    """Values read off the plans beside the analytic ones (their lengths on the plans at the
    factors kv, ka; none yet when 0), and the links' ω and ε."""
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
    for name, val, kk, check in vals:
        rows.append([name, num(val, 4), num(abs(val) / kk, 4) if kk else "0000", num(check, 4)])
    # its columns as wide as their words plus 3 mm, not the general table's 3.4 mm: those
    # 1.6 mm across the four columns are what the mechanism needs beside it for 1:5 (else 1:10)
    widths = [max(text_box(parse(row[i]), 2.5)[0] for row in rows) + 3.0 for i in range(4)]
    values = Table(rows, widths=widths, row_h=5.0, title=WORDS("values"))
    # the links' angular velocities and accelerations under it
    rows = [[WORDS("link"), "ω, " + WORDS("rad_s"), "ε, " + WORDS("rad_s2")]]
    for i in range(3):
        rows.append([str(i + 2), num(an.omegas[i], 4), num(an.epsilons[i], 4)])
    omegas = Table(rows, widths=(14.0, 30.0, 30.0), row_h=5.0, title=WORDS("omegas"))
    signs = Text(paragraph=WORDS("signs"), width=sum(widths))
    return values, omegas, signs


def motion(sol: Solution[Geometry], frames: int) -> Frames:
    """The synthesized six-bar over one crank turn from the kinematics sheet's position (60°
    past C's left extreme), at ω1 of the analysis: the joints, C on its guide, the paths of A, B
    and C, and the velocity plan (pa, pb, pc)."""
    from .p2013_6 import ANALYSIS_OMEGA1, ANALYSIS_TURN

    geo = sol.data
    mech = geo.mechanism
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
