"""2013-6's drawing sheet: the six-bar in its mid and extreme positions and the whole synthesis.

A3 landscape. Left: the construction at k_l (the seed's 0.005 m/mm, 1:5, when it fits; else the
largest GOST scale that does): the rocker's arc, the extreme positions C0, C1 and B0, B1, the
chord B0B1, the perpendicular at B0 and the ray at 90° − θ meeting in O, the θ-circle Γ through
O, B0, B1 and its mirror image Γ′ (their arcs that see B0B1 under θ solid, the others dashed),
the lines at e from the path, every solution O1, and the seed's solution built out: the crank's
dead-centre positions O1A0B0 and O1A1B1, the crank circle, the linkage in its mid position, and
the dimensions O1B0 and O1B1. Right: the given data, the results beside the seed's, and all
solutions.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from geomcad.construction import Construction
from geomcad.geom import Arc, Circle, Line, Vec, angle_arcs, circle_circle
from geomcad.kinematics import branch_sign
from geomcad.sheet import Drawing, Scale, Sheet, TitleBlock, Viewport, fmt_number, start
from geomcad.sheet.scale import gost_scale_to_fit

from .sheets_2013_6_kin import kinematics_sheet
from .spec_2013_6 import SEED_K_L

if TYPE_CHECKING:
    from geomcad.problem import Solution

    from .p2013_6 import Geometry

#: The field the mechanism is drawn in on the sheet (mm: x0, y0, x1, y1), left of the tables.
VIEW = (24.0, 24.0, 256.0, 290.0)

#: The rocker's arc is drawn this far (rad) beyond B's swing.
SWING_PAD = 0.25

PANEL_X = 262.0


def extent(geo: Geometry, c: Construction) -> tuple[float, float, float, float]:
    """The model box the sheet draws (x0, y0, x1, y1): the θ-circles, the mechanism and every
    solution."""
    l3, l4 = geo.l3, geo.l4
    xs: list[float] = [-l3, l3]
    ys: list[float] = [-0.05 * l3]
    for circ in (c["Γ"], c["Γ′"]):
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


def scales(sol: Solution) -> Mapping[str, float]:
    """k_l of the sheet: for the seed's data the seed's 0.005 m/mm (1:5), so that its drawing
    and ours can be laid side by side; otherwise the largest GOST 2.302 scale at which the
    drawing fits the field."""
    x0, y0, x1, y1 = extent(sol.data, sol.construction)
    w, h = x1 - x0, y1 - y0
    room_w, room_h = VIEW[2] - VIEW[0], VIEW[3] - VIEW[1]
    if sol.is_seed and w / SEED_K_L <= room_w and h / SEED_K_L <= room_h:
        return {"l": SEED_K_L}
    return {"l": gost_scale_to_fit(w, h, room_w, room_h).k}


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The sheets of 2013-6: the synthesis, and the kinematic analysis of its six-bar."""
    return [main_sheet(sol), kinematics_sheet(sol)]


def main_sheet(sol: Solution) -> tuple[str, Sheet]:
    """The main sheet of 2013-6."""
    geo = sol.data
    c = sol.construction
    k = Scale(sol.scales["l"], "l")
    tb = TitleBlock(
        title="Синтез шестизвенного механизма по коэффициенту K",
        designation="ТММ.2013-6.01",
        scale=k.ratio_text(),
    )
    d = start("A3", tb)
    x0, y0, x1, y1 = extent(geo, c)
    cx, cy = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    at = ((VIEW[0] + VIEW[2]) / 2.0, (VIEW[1] + 8.0 + VIEW[3]) / 2.0)
    v = d.viewport(k, (cx, cy), at)
    d.text("Синтез механизма по K (метод окружности через B_0B_1)", (VIEW[0] + 2.0, 13.0), 5.0)
    d.text(f"{k.label()}   (M {k.ratio_text() or '—'})", (VIEW[0] + 2.0, 20.0), 3.5)

    _construction(v, geo, c)
    _mechanism(v, geo, c)
    _panel(d, sol, k)
    return ("", d.finish())


def _construction(v: Viewport, geo: Any, c: Any) -> None:
    B0, B1, Op, O2 = c["B0"], c["B1"], c["O"], c["O2"]
    theta = geo.theta
    # the rocker's arc and the slider's path
    swing = Arc(Circle(O2, geo.l3), B1.angle - SWING_PAD, B0.angle + SWING_PAD)
    v.arc(swing, "centre")
    ends = [c["C0"], c["C1"], c["B"], *(cd.O1 for cd in geo.candidates if cd.line == 1)]
    v.line_over(c["path"], ends, "centre", over=12.0)
    # B0B1, the perpendicular at B0 and the ray from B1 at 90° − θ, meeting in O
    v.seg(B0, B1, "construction")
    v.seg(B0, Op, "construction")
    v.seg(B1, Op, "construction")
    _right_angle(v, B0, B1, Op)
    v.dim_angle(B1, B0, Op, "90° – θ", r_mm=14.0, height=2.5)
    v.dot(Op, "result")
    v.label(Op, "O", prefer=(-1.0, -1.0))
    # the θ-circle Γ and its mirror Γ′: θ-arcs solid, the arcs of 180° − θ dashed
    left, right = angle_arcs(B0, B1, theta)
    chord = Line.through(B0, B1)
    for arc in (left, right):
        v.arc(arc, "construction")
        v.arc(Arc(arc.circle, arc.end, arc.start), "locus")
    gamma, gamma_m = c["Γ"], c["Γ′"]
    v.dot(gamma.c, "construction")
    for circ, name in ((gamma, "Γ"), (gamma_m, "Γ'")):
        # the label sits on the θ-arc, at its point furthest from the chord
        side = 1.0 if chord.side(circ.c) > 0.0 else -1.0
        far = circ.c + chord.normal * (side * circ.r)
        v.label(far, name, prefer=(0.0, side))
    # the lines at e from the path, and every solution
    for line_no, (step, tag) in enumerate((("m−", "–"), ("m+", "+"))):
        m = c[step]
        pts = [*(cd.O1 for cd in geo.candidates if cd.line == line_no), m.p]
        v.line_over(m, pts, "construction", over=14.0)
        far_end = Vec(max(q.x for q in pts), m.p.y)
        v.label(far_end, f"y = l_3 {tag} e", height=2.5, prefer=(1.0, 1.0), clear=12.0)
    for i, cd in enumerate(geo.candidates):
        if cd is geo.chosen:
            continue
        v.dot(cd.O1, "result")
        v.label(cd.O1, f"O_1^{{({i + 1})}}", height=3.5)


def _right_angle(v: Viewport, vertex: Vec, a: Vec, b: Vec, size_mm: float = 3.0) -> None:
    """The right-angle mark at ``vertex`` between the directions to a and b."""
    s = v.scale.model(size_mm)
    ua, ub = (a - vertex).unit() * s, (b - vertex).unit() * s
    v.polyline([vertex + ua, vertex + ua + ub, vertex + ub], "construction")


def _mechanism(v: Viewport, geo: Any, c: Any) -> None:
    O2, B, C, B0, B1, C0, C1 = (c[n] for n in ("O2", "B", "C", "B0", "B1", "C0", "C1"))
    ch = geo.chosen
    O1 = ch.O1
    mech = geo.mechanism
    # the crank pin at the dead centres: at the folded one (the nearer B) A lies on the far
    # side of O1, at the extended one between O1 and B
    folded = B0 if ch.O1B0 <= ch.O1B1 else B1
    A0, A1 = (O1 + (Bx - O1).unit() * (-ch.l1 if Bx is folded else ch.l1) for Bx in (B0, B1))
    # the seed's solution: O1B0 and O1B1, the angle θ between them, the crank circle
    v.seg(O1, B0, "result")
    v.seg(O1, B1, "result")
    v.dim_angle(O1, B0, B1, "θ", r_mm=22.0)
    v.circle(O1, ch.l1, "centre")
    # extreme positions (two-dot lines)
    for Bx, Cx, Ax in ((B0, C0, A0), (B1, C1, A1)):
        v.seg(O2, Bx, "extreme")
        v.seg(Bx, Cx, "extreme")
        v.seg(Ax, Bx, "extreme")
        v.seg(O1, Ax, "extreme")
        v.dot(Ax)
    # the mid position: A from circle(O1, l1) ∩ circle(B, l2) on the mechanism's branch
    A = _mid_A(O1, ch.l1, ch.l2, B, O2, mech.branch_B)
    v.seg(O1, A, "link")
    v.seg(A, B, "link")
    v.seg(O2, B, "link")
    v.seg(B, C, "link")
    v.guide(Vec(C0.x - 0.06 * geo.l4, geo.l3), Vec(C1.x + 0.06 * geo.l4, geo.l3), (0.0, -1.0))
    for q in (C0, C1):
        v.slider(q, role="extreme")
    v.slider(C)
    for q in (A, B, B0, B1):
        v.joint(q)
    v.pivot(O2)
    v.pivot(O1)
    # labels, then the dimensions of the result
    v.label(O2, "O_2", prefer=(1.0, -1.0), clear=4.0)
    # O1's label below its support, clear of the crank pins A, A0, A1 around it
    v.label(O1, "O_1", prefer=(1.0, -1.0), clear=6.0)
    v.label(A, "A", prefer=(-1.0, 1.0))
    v.label(B, "B", prefer=(1.0, 1.0))
    v.label(C, "C", prefer=(0.0, 1.0), clear=4.0)
    v.label(C0, "C_0", prefer=(0.0, 1.0), clear=4.0)
    v.label(C1, "C_1", prefer=(0.0, 1.0), clear=4.0)
    v.label(B0, "B_0", prefer=(-1.0, 1.0))
    v.label(B1, "B_1", prefer=(1.0, 1.0))
    for Ax, name in ((A0, "A_0"), (A1, "A_1")):
        out = (Ax - O1).unit()  # outside the crank circle, away from O1's label
        v.label(Ax, name, height=2.5, prefer=(out.x, out.y))
    mm = 1000.0
    v.dim_linear(O1, B0, f"O_1B_0 = {fmt_number(ch.O1B0 * mm, digits=4)}", offset=12.0, height=2.5)
    v.dim_linear(O1, B1, f"O_1B_1 = {fmt_number(ch.O1B1 * mm, digits=4)}", offset=-12.0, height=2.5)


def _mid_A(O1: Vec, l1: float, l2: float, B: Vec, O2: Vec, branch: int) -> Vec:
    """The crank pin A with B at mid-stroke, on the assembly branch the mechanism runs on."""
    pts = circle_circle(Circle(O1, l1), Circle(B, l2))
    for q in pts:
        if branch_sign(q, O2, B) == branch:
            return q
    return pts[0]


def _panel(d: Drawing, sol: Solution, k: Scale) -> None:
    """The tables on the right: given data, results beside the seed's, every solution."""
    p = sol.params
    r = sol.results
    x, y = PANEL_X, 10.0
    d.text("Исходные данные", (x, y + 3.5), 3.5)
    rows = [["Параметр", "Значение"]]
    for name, label, unit in (
        ("H", "H", "м"),
        ("K", "K", ""),
        ("l3", "l_3", "м"),
        ("l4", "l_4", "м"),
        ("e", "e", "м"),
    ):
        rows.append([label, f"{fmt_number(float(p[name]))} {unit}".strip()])
    _, h = d.table(x, y + 6.0, (40.0, 40.0), rows)
    y += 6.0 + h + 6.0
    d.text("Результаты", (x, y + 3.5), 3.5)
    rows = [["Величина", "Значение"]]
    mmk = k.k
    for name, label, unit, scale in (
        ("theta_deg", "θ", "°", 1.0),
        ("O1B0", "O_1B_0", "мм*", mmk),
        ("O1B1", "O_1B_1", "мм*", mmk),
        ("l1", "l_1", "м", 1.0),
        ("l2", "l_2", "м", 1.0),
        ("H_check", "H (анализ)", "м", 1.0),
        ("K_check", "K (анализ)", "", 1.0),
    ):
        exact = float(r[name]) / scale
        rows.append([label, f"{fmt_number(exact, digits=4)} {unit}".strip()])
    _, h = d.table(x, y + 6.0, (40.0, 40.0), rows)
    y += 6.0 + h + 4.0
    d.text(f"* на чертеже, {k.label()}", (x, y + 2.5), 2.5)
    y += 8.0
    d.text("Все решения (O_1 на прямых y = l_3 ± e)", (x, y + 3.5), 3.5)
    rows = [["№", "O_1 (x; y), м", "l_1, м", "l_2, м", "кривош."]]
    for i, s in enumerate(r["solutions"]):
        ox, oy = s["O1"]
        rows.append(
            [
                str(i + 1),
                f"{fmt_number(ox, digits=4)}; {fmt_number(oy, digits=4)}",
                fmt_number(s["l1"], digits=4),
                fmt_number(s["l2"], digits=4),
                "да" if s["crank_rocker"] else "нет",
            ]
        )
    _, h = d.table(x, y + 6.0, (10.0, 48.0, 26.0, 26.0, 36.0), rows)
    y += 6.0 + h + 6.0
    y = d.text("Порядок построения", (x, y + 3.5), 3.5).at[1] + 2.0
    th = fmt_number(float(r["theta_deg"]), digits=4)
    steps = (
        "механизм в среднем положении O_2BC и в крайних O_2B_0C_0, O_2B_1C_1 (ход ползуна H);",
        f"θ = 180°·(K – 1)/(K + 1) = {th}°;",
        "перпендикуляр к B_0B_1 в точке B_0 и луч из B_1 под углом 90°\u00a0–\u00a0θ к B_1B_0 "
        "пересекаются в точке O;",
        "окружность Γ через O, B_0, B_1 (OB_1 – диаметр) и её зеркальный образ Γ' относительно "
        "B_0B_1: дуги, из которых хорда B_0B_1 видна под углом θ;",
        "прямые y\u00a0=\u00a0l_3\u00a0±\u00a0e пересекают эти дуги в точках O_1; решение "
        "задачи – левая точка на y\u00a0=\u00a0l_3\u00a0–\u00a0e;",
        "l_1 = (O_1B_1 – O_1B_0)/2, l_2 = (O_1B_1 + O_1B_0)/2;",
        f"проверка анализом за полный оборот кривошипа: H = "
        f"{fmt_number(float(r['H_check']), digits=4)} м, K = "
        f"{fmt_number(float(r['K_check']), digits=4)}.",
    )
    for i, step in enumerate(steps):
        y = d.paragraph(f"{i + 1}. {step}", x, y, 146.0, 2.5, indent=4.0) + 0.6
