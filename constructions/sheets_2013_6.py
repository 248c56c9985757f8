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

import itertools
import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad.construction import Construction
from geomcad.geom import Arc, Circle, Vec, circle_circle
from geomcad.kinematics import branch_sign
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Layout,
    Node,
    Row,
    View,
    arrange,
    compose,
)
from geomcad.sheet.lang import Words, current
from geomcad.sheet.model import ArcItem, CircleItem, Polyline
from geomcad.sheet.replay import replay
from geomcad.sheet.scheme import GUIDE_HALF
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
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
        k = 0.0
        for _ in range(3):
            self.tree = Row(self.view, Column(*_panel(sol, k)))
            self.layout: Layout = arrange(self.tree, Field.of_format("A3"))
            got = self.layout[self.view].scale
            assert got is not None
            if got.k == k:
                break
            k = got.k
        self.k = k


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
    # the angle at B1 last, when every line it must keep clear of is drawn
    _angle_with_leader(v, c["B1"], c["B0"], c["O"], "90° – θ", 12.0)


def _construction(v: Viewport, geo: Geometry, c: Construction) -> None:
    B0, B1, Op, O2 = c["B0"], c["B1"], c["O"], c["O2"]
    # the rocker's arc and the slider's path
    swing = Arc(Circle(O2, geo.l3), B1.angle - SWING_PAD, B0.angle + SWING_PAD)
    v.arc(swing, "centre")
    # the path's centre line where no link runs along it: left of B0, and past C1's block
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


def _ink(items: Sequence[Any]) -> np.ndarray:
    """The drawn lines of ``items`` as paper segments (x1, y1, x2, y2): polylines by their
    sides, circles and arcs by chords of at most about 1.5 mm."""
    out: list[tuple[float, float, float, float]] = []
    for it in items:
        if isinstance(it, Polyline):
            pts = [*it.points, *([it.points[0]] if it.closed else [])]
            out += [(*a, *b) for a, b in itertools.pairwise(pts)]
        elif isinstance(it, CircleItem | ArcItem):
            if isinstance(it, CircleItem):
                a0, sweep = 0.0, 2.0 * math.pi
            else:
                a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
                sweep = it.sweep
            n = max(8, int(abs(sweep) * it.r / 1.5) + 1)
            t = a0 + np.linspace(0.0, sweep, n + 1)
            xs, ys = it.c[0] + it.r * np.cos(t), it.c[1] + it.r * np.sin(t)
            out += [(xs[i], ys[i], xs[i + 1], ys[i + 1]) for i in range(n)]
    return np.array(out, dtype=np.float64).reshape(-1, 4)


def _crossed(segs: np.ndarray, b: tuple[float, float, float, float]) -> bool:
    """Whether a segment crosses or lies in the box b = (x0, y0, x1, y1) (Liang–Barsky, all
    segments at once)."""
    if segs.size == 0:
        return False
    x1, y1, x2, y2 = segs.T
    dx, dy = x2 - x1, y2 - y1
    t0, t1 = np.zeros_like(x1), np.ones_like(x1)
    ok = np.ones(x1.shape, dtype=bool)
    for p, q in ((-dx, x1 - b[0]), (dx, b[2] - x1), (-dy, y1 - b[1]), (dy, b[3] - y1)):
        zero = p == 0.0
        ok &= ~(zero & (q < 0.0))
        r = q / np.where(zero, 1.0, p)
        t0 = np.where(~zero & (p < 0.0), np.maximum(t0, r), t0)
        t1 = np.where(~zero & (p > 0.0), np.minimum(t1, r), t1)
    return bool(np.any(ok & (t0 <= t1)))


def _angle_with_leader(
    v: Viewport, vertex: Vec, p1: Vec, p2: Vec, text: str, r_mm: float, height: float = 2.5
) -> None:
    """An angle's arc at ``vertex`` whose value stands where no line crosses it, as near the
    arc as that allows, joined to the arc's middle by a thin leader when it stands apart (the
    angle at B1 sits among the links and the construction, where no place beside it is free)."""
    v.dim_angle(vertex, p1, p2, text, r_mm=r_mm, height=height)
    mid = v.d.pending.pop().anchor  # the arc's middle; the value is placed here instead
    w, rise, down = text_box(parse(text), height)
    segs = _ink(v.sheet.items)
    links = _ink([it for it in v.sheet.items if it.role in ("link", "joint")])
    # the arc's points on the paper, its middle first (as dim_angle draws it)
    a1, a2 = (p1 - vertex).angle, (p2 - vertex).angle
    sweep = math.remainder(a2 - a1, 2.0 * math.pi)
    start, sweep = (a1, sweep) if sweep > 0 else (a2, -sweep)
    c = v.p(vertex)
    on_arc = [
        (c[0] + r_mm * math.cos(start + sweep * t), c[1] - r_mm * math.sin(start + sweep * t))
        for t in (0.5, 0.35, 0.65, 0.2, 0.8)
    ]
    # the dimensions' texts, placed at the finish, keep the places they would take now (the
    # first candidate that crosses no line): each as a disc round its text's middle
    # the dimensions' texts are placed at the finish, anywhere along their lines: every place
    # they may take is kept free (a disc round the text's middle at each candidate)
    dims = []
    for dt in v.d.dims:
        dw, rise = dt.box[0], dt.box[1]
        for at in dt.candidates:
            dims.append((at[0] + dt.t[0] * dw / 2.0, at[1] + dt.t[1] * dw / 2.0, rise + 1.0))

    def near_dim(x: float, y: float, pad: float) -> bool:
        return any(math.hypot(x - dx, y - dy) < rr + pad for dx, dy, rr in dims)

    best = None
    for r in (3.0, 5.0, 7.0, 9.0, 12.0, 15.0, 18.0, 22.0, 27.0, 33.0, 40.0):
        for p0 in on_arc:
            out = math.atan2(-(p0[1] - c[1]), p0[0] - c[0])  # outward through the arc
            for k in sorted(
                range(24), key=lambda k: abs(math.remainder(k * math.pi / 12.0 - out, 2 * math.pi))
            ):
                a = k * math.pi / 12.0
                cx, cy = p0[0] + r * math.cos(a), p0[1] - r * math.sin(a)
                box = (cx - w / 2.0 - 0.8, cy - rise / 2.0 - 0.8, cx + w / 2.0 + 0.8,
                       cy + rise / 2.0 + down + 0.8)  # fmt: skip
                if _crossed(segs, box) or near_dim(cx, cy, w / 2.0):
                    continue
                # the leader crosses no link (thin lines it may)
                steps = [(p0[0] + (cx - p0[0]) * t / 80.0, p0[1] + (cy - p0[1]) * t / 80.0)
                         for t in range(81)]  # fmt: skip
                if not any(_crossed(links, (x - 0.3, y - 0.3, x + 0.3, y + 0.3))
                           or near_dim(x, y, 0.5) for x, y in steps):  # fmt: skip
                    best, mid = (cx, cy), p0
                    break
            if best is not None:
                break
        if best is not None:
            break
    if best is None:  # nowhere free: beside the arc as the label placer would
        v.d.label(mid, text, height, clear=0.5)
        return
    cx, cy = best
    if math.dist(best, mid) > w / 2.0 + 2.0:
        # the leader from the arc to the nearer end of the text's underline
        end = (
            (cx - w / 2.0, cy + rise / 2.0 + 0.6)
            if mid[0] < cx
            else (cx + w / 2.0, cy + rise / 2.0 + 0.6)
        )
        v.sheet.add(Polyline((mid, end), "dimension"))
        v.sheet.add(Polyline(((cx - w / 2.0, end[1]), (cx + w / 2.0, end[1])), "dimension"))
    v.d.text(text, (cx - w / 2.0, cy + rise / 2.0), height)


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
        shown[name] = f"{num(float(r[name]), 4)} {m_} ({drawn} {WORDS('mm')}*)"
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
