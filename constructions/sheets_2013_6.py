"""2013-6's drawing sheet: the six-bar in its mid and extreme positions and the whole synthesis.

A3 landscape, composed by geomcad.sheet.compose (no view placed by hand). Left: the
construction at k_l (for the seed's data the seed's 0.005 m/mm, 1:5; else the largest GOST
scale its place allows): the rocker's arc, the extreme positions C0, C1 and B0, B1, the
chord B0B1, the perpendicular at B0 and the ray at 90° − θ meeting in O, the θ-circle Γ through
O, B0, B1 and its mirror image Γ′ (only their arcs that see B0B1 under θ: the others hug the chord),
the lines at e from the path, every solution O1, and the seed's solution built out: the crank's
dead-centre positions O1A0B0 and O1A1B1, the crank circle, the linkage in its mid position, and
the dimensions O1B0 and O1B1. The synthesis (B0, B1, the chord, the perpendicular n0 and the ray
r1, O, the θ-arcs, the lines at e and the other solutions) is the recorded construction replayed
by its steps' roles (geomcad.sheet.replay); the mechanism, the angles and the dimensions are
drawn here. Right: the given data beside the results, all solutions and the order of
construction written from the recorded steps (:data:`ORDER`, templates in
strings/<lang>/sheets_2013_6.toml).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from geomcad.construction import Construction
from geomcad.geom import Arc, Circle, Vec, circle_circle
from geomcad.kinematics import branch_sign
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Node,
    Row,
    View,
    compose,
)
from geomcad.sheet.lang import Words, current
from geomcad.sheet.leaders import angle_with_leader
from geomcad.sheet.replay import replay
from geomcad.sheet.scheme import GUIDE_HALF
from geomcad.sheet.settle import factor_of, settle
from geomcad.sheet.views import Steps, Table, Text, factor, num

from .sheets_2013_6_kin import kinematics_sheet, six_bar
from .spec_2013_6 import PARAMS, RESULTS, SEED_K_L

if TYPE_CHECKING:
    from geomcad.problem import Solution

    from .p2013_6 import Geometry

WORDS = Words(__package__, "sheets_2013_6")

#: The rocker's arc is drawn this far (rad) beyond B's swing.
SWING_PAD = 0.25

#: Width (mm) of the order of construction's text.
ORDER_W = 146.0

#: The steps the order of construction lists, in their recorded order (geomcad/sheet/views.py
#: Steps; the kinds' templates are in strings/<lang>/sheets_2013_6.toml and views.toml).
ORDER = ("C0", "C1", "B0", "B1", "θ", "n0", "r1", "O", "Γ", "θ-arcs", "m−", "m+", "O1",
         "l1", "l2", "K_check")  # fmt: skip


def extent(geo: Geometry, c: Construction) -> tuple[float, float, float, float]:
    """The model box the sheet draws (x0, y0, x1, y1): the θ-circles, the mechanism and every
    solution."""
    l3, l4 = geo.l3, geo.l4
    xs: list[float] = [-l3, l3]
    ys: list[float] = [-0.05 * l3]
    for circ in (c["Γ"], c["Γ'"]):
        xs += [circ.c.x - circ.r, circ.c.x + circ.r]
        ys += [circ.c.y - circ.r, circ.c.y + circ.r]
    for q in [
        *(c[n] for n in ("O2", "C0", "C1", "B0", "B1", "O")),
        *(cd.O1 for cd in geo.candidates),
    ]:
        xs.append(q.x)
        ys.append(q.y)
    xs.append(c["C1"].x + 0.1 * l4)
    return min(xs), min(ys), max(xs), max(ys)


class _Main:
    """The main sheet's views and their arrangement. The results give O1B0, O1B1 in mm at the
    mechanism's scale, which the arrangement chooses: arranged until the scale it was built
    with is the one it gets."""

    def __init__(self, sol: Solution[Geometry]) -> None:
        geo, c = sol.data, sol.construction
        # for the seed's data the seed's 1:5, so that its drawing and ours can be laid side by
        # side (O1B0, O1B1 are measured on it)
        least = SEED_K_L if sol.is_seed else 0.0
        self.view = Figure(extent(geo, c), lambda v: _drawing(v, geo, c), weight=2.0,
                           title=WORDS("title"), least_k=least)  # fmt: skip
        s = settle(
            lambda k: (Row(self.view, Column(*_panel(sol, k))), None),
            lambda lay, _: factor_of(lay, self.view),
            0.0,
            Field.of_format("A3"),
        )
        self.tree, self.layout, self.k = s.tree, s.layout, s.key


def scales(sol: Solution[Geometry]) -> Mapping[str, float]:
    """k_l of the sheet: the largest GOST 2.302 scale at which the drawing fits its place on
    the composed sheet (for the seed's data the seed's 0.005 m/mm, 1:5)."""
    return {"l": _Main(sol).k}


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The sheets of 2013-6: the synthesis, and the kinematic analysis of its six-bar."""
    return [main_sheet(sol), kinematics_sheet(sol)]


def main_sheet(sol: Solution[Geometry]) -> tuple[str, Sheet]:
    """The main sheet of 2013-6."""
    m = _Main(sol)
    k = Scale(m.k, "l")
    tb = TitleBlock(
        title=WORDS("tb_title"),
        designation=WORDS("designation"),
        scale=k.ratio_text(),
        lang=current(),
    )
    d = start("A3", tb)
    compose(d, m.tree, layout=m.layout)
    return ("", d.finish())


def _drawing(v: Viewport, geo: Geometry, c: Construction) -> None:
    _construction(v, geo, c)
    _mechanism(v, geo, c)
    # the angle at B1 last, when every line it must keep clear of is drawn; its arc 12 mm round
    # B1 (hand-set: outside B1's joint and name, the value goes where the leader finds room)
    angle_with_leader(v, c["B1"], c["B0"], c["O"], "90° – θ", 12.0)


def _construction(v: Viewport, geo: Geometry, c: Construction) -> None:
    B0, B1, Op, O2 = c["B0"], c["B1"], c["O"], c["O2"]
    # the rocker's arc and the slider's path
    swing = Arc(Circle(O2, geo.l3), B1.angle - SWING_PAD, B0.angle + SWING_PAD)
    v.arc(swing, "centre")
    # the path's centre line where no link runs along it: left of B0, and past C1's block
    # (hand-set paper mm: 12 past the outermost point, stopped 4 short of B0's joint, resumed
    # 8 past C1's block and at least 10 long; GOST 2.303's axes run 2–5 mm past a contour)
    xs = [q.x for q in (c["C0"], c["C1"], c["B"], *(cd.O1 for cd in geo.candidates))]
    y = geo.l3
    left, right = min(xs) - v.scale.model(12.0), max(xs) + v.scale.model(12.0)
    if B0.x - v.scale.model(4.0) > left:
        v.seg(Vec(left, y), Vec(B0.x - v.scale.model(4.0), y), "centre")
    stub = c["C1"].x + v.scale.model(8.0)
    v.seg(Vec(stub, y), Vec(max(right, stub + v.scale.model(10.0)), y), "centre")
    # the synthesis as recorded, by its steps' roles (geomcad.sheet.replay): the chord B0B1,
    # the perpendicular at B0 and the ray from B1 at 90° − θ meeting in O, the θ-arcs of Γ and
    # Γ' (their arcs of 180° − θ hug the chord and carry no solution), the lines at e from the
    # path and every other solution; the chosen O1 and B0, B1 with the mechanism
    others = [s.name for s in c if s.name.startswith("O1(")]
    # the θ-arcs in the order recorded (left of B0 → B1 first), each named by its circle
    arcs = c["θ-arcs"]
    names = tuple("Γ" if a.circle.c.dist(c["Γ"].c) < a.circle.c.dist(c["Γ'"].c) else "Γ'"
                  for a in arcs)  # fmt: skip
    replay(
        v,
        c,
        ("B0", "B1", "B0B1", "n0", "r1", "O", "θ-arcs", "m−", "m+", *others),
        labels={
            "B0": "B_0",
            "B1": "B_1",
            "θ-arcs": names,
            "n0": "n_0",
            "r1": "r_1",
            "m−": "y = l_3 – e",
            "m+": "y = l_3 + e",
            **{n: f"O_1^{{({n[3:-1]})}}" for n in others},
        },
        prefer={
            "B0": (-1.0, 1.0),
            "B1": (1.0, 1.0),
            "O": (-1.0, -1.0),
            "m−": (-1.0, 1.0),
            "m+": (-1.0, 1.0),
        },
        over={"m−": 14.0, "m+": 14.0, "B0B1": 0.0, "n0": 0.0, "r1": 0.0},
        along={"m−": 1.0, "m+": 1.0, "r1": 0.8},
        box=extent(geo, c),
    )
    v.right_angle(B0, B1, Op)
    v.dot(c["Γ"].c, "construction")


def _mechanism(v: Viewport, geo: Geometry, c: Construction) -> None:
    O2, B, C, B0, B1, C0, C1 = (c[n] for n in ("O2", "B", "C", "B0", "B1", "C0", "C1"))
    ch = geo.chosen
    O1 = ch.O1
    mech = geo.mechanism
    # the crank pin at the dead centres: at the folded one (the nearer B) A lies on the far
    # side of O1, at the extended one between O1 and B
    folded = B0 if ch.O1B0 <= ch.O1B1 else B1
    A0, A1 = (O1 + (Bx - O1).unit() * (-ch.l1 if Bx is folded else ch.l1) for Bx in (B0, B1))
    # the seed's solution: O1B0 and O1B1, the angle θ between them, the crank circle. O1B0
    # and O1B1 are the crank and the rod at the dead centres (A0B0 runs through O1, A1 lies on
    # O1B1): extreme positions, drawn with them below in thin two-dot lines (GOST 2.770)
    # θ's arc 22 mm round O1 (hand-set: outside O1's support and name and the crank's number)
    v.dim_angle(O1, B0, B1, "θ", r_mm=22.0)
    v.circle(O1, ch.l1, "centre")
    # extreme positions (two-dot lines); the crank and the rod at a dead centre lie on one
    # line, drawn once: A·O1·B at the folded one (A beyond O1), O1·A·B at the extended one
    for Bx, Cx, Ax in ((B0, C0, A0), (B1, C1, A1)):
        v.seg(O2, Bx, "extreme")
        v.seg(Bx, Cx, "extreme")
        v.seg(Ax if Bx is folded else O1, Bx, "extreme")
        v.dot(Ax)
    for q in (C0, C1):
        v.slider(q, role="extreme")
    for q in (B0, B1):
        v.joint(q)
    # the mid position: A from circle(O1, l1) ∩ circle(B, l2) on the mechanism's branch, the
    # six-bar drawn as on the kinematics sheet
    A = _mid_A(O1, ch.l1, ch.l2, B, O2, mech.branch_B)
    # the guide under the whole stroke, on from the scheme's own guide at C (GUIDE_HALF mm
    # either side of it)
    half = v.scale.model(GUIDE_HALF)
    for a, b in ((C0.x - 0.06 * geo.l4, C.x - half), (C.x + half, C1.x + 0.06 * geo.l4)):
        if b > a:
            v.guide(Vec(a, geo.l3), Vec(b, geo.l3), (0.0, -1.0))
    # each point's name: (preferred direction, clearance mm), hand-set away from its links and
    # supports (O1, O2: beside the support's hatching; C: past the slider's block)
    labels = {
        "O2": ((1.0, -1.0), 4.0),
        "O1": ((1.0, -1.0), 4.5),
        "A": ((-1.0, 1.0), 1.5),
        "B": ((1.0, 1.0), 1.5),
        "C": ((1.0, 0.0), 4.7),
    }
    pts = {"O1": O1, "A": A, "B": B, "O2": O2, "C": C}
    # link 4's number on BC's own stretch between B and the nearer of B0, B1 ahead of it, where
    # no extreme position of BC runs beside it on that side (past B1 the line B1C1 is there)
    u = (C - B).unit()
    ahead = [(q - B).dot(u) for q in (B0, B1) if (q - B).dot(u) > 0.0]
    share = min([0.5, *(0.5 * a / B.dist(C) for a in ahead)])
    six_bar(v, pts, Vec(1.0, 0.0), labels, number_at={"4": share})
    for q, name in ((C0, "C_0"), (C1, "C_1")):
        v.label(q, name, prefer=(0.0, 1.0), clear=4.0)
    for Ax, name in ((A0, "A_0"), (A1, "A_1")):
        out = (Ax - O1).unit()  # outside the crank circle, away from O1's label
        v.label(Ax, name, height=2.5, prefer=(out.x, out.y))
    mm = 1000.0
    # O1B0's dimension on A's side of O1B0 (its other side holds O1B1 and θ), beyond the pin A
    # so that it never runs through the joint
    n = (B0 - O1).unit().perp()  # left of O1 → B0 in the model
    side_a = (A - O1).dot(n)
    # 12 mm from the line measured (GOST 2.307: at least 10 from the contour), and 6 mm beyond
    # the pin A where A lies farther out
    off = max(12.0, v.mm(abs(side_a)) + 6.0)
    offset = off if side_a > 0.0 else -off  # dim_linear's offset: left of a → b on the paper
    v.dim_linear(O1, B0, f"O_1B_0 = {num(ch.O1B0 * mm, 4)}", offset=offset, height=2.5)
    v.dim_linear(O1, B1, f"O_1B_1 = {num(ch.O1B1 * mm, 4)}", offset=-12.0, height=2.5)


def _mid_A(O1: Vec, l1: float, l2: float, B: Vec, O2: Vec, branch: int) -> Vec:
    """The crank pin A with B at mid-stroke, on the assembly branch the mechanism runs on."""
    pts = circle_circle(Circle(O1, l1), Circle(B, l2))
    for q in pts:
        if branch_sign(q, O2, B) == branch:
            return q
    return pts[0]


def _panel(sol: Solution[Geometry], k: float) -> tuple[View | Node, ...]:
    """The tables on the right: given data, results (O1B0, O1B1 in mm at the factor k; none
    yet when 0), every solution, the order of construction."""
    p = sol.params
    r = sol.results
    m_ = WORDS("m")
    given = Table.of_specs(PARAMS, p, style="value", widths=(30.0, 36.0), title=WORDS("data"))
    shown = dict(r)
    for name in ("O1B0", "O1B1"):
        # the real length (as the drawing's dimension gives it, in mm there) and, marked, the
        # length on the drawing in mm at k, which the published solution measures
        drawn = num(float(r[name]) / k if k else 0.0, 4)
        shown[name] = f"{num(float(r[name]), 4)} {m_} ({drawn} {WORDS('mm')}^{{*}})"
    results = Table.of_specs(
        RESULTS, shown, labels={"H_check": WORDS("H_check"), "K_check": WORDS("K_check")},
        style="value", widths=(30.0, 46.0), title=WORDS("results"),
    )  # fmt: skip
    note = Text(lines=[WORDS("on_drawing", k=factor(Scale(k or 0.001, "l")))])
    rows = [["№", f"O_1 (x; y), {m_}", f"l_1, {m_}", f"l_2, {m_}", WORDS("crank")]]
    for i, s in enumerate(r["solutions"]):
        ox, oy = s["O1"]
        rows.append(
            [
                str(i + 1),
                f"{num(ox, 4)}; {num(oy, 4)}",
                num(s["l1"], 4),
                num(s["l2"], 4),
                WORDS("yes" if s["crank_rocker"] else "no"),
            ]
        )
    every = Table(rows, fill=ORDER_W, title=WORDS("all"))
    order = Steps(sol.construction, ORDER_W, only=ORDER, words=WORDS)
    # the data and the results side by side, so that the order of construction has its room
    return Row(given, Column(results, note)), every, order
