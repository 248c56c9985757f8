"""2013-7's drawing sheet: the half-governor with its friction circles and reaction lines, the
joints enlarged, and the force plans of the sleeve and of the arm.

A3 landscape.
- Top left: the right half of the governor at k_l (the seed's 0.002 m/mm, 1:2, when it fits;
  else the largest GOST scale that does), with the friction circles at B, F and H drawn to scale,
  link 3's line of action (their common tangent), the lines of G_6 and F_i through D, the point Q
  where R_36's line meets G_6's, P's line through Q, the point K where it meets F_i's line, and
  R_76's line from K tangent to the friction circle at H; the forces on the arm and the sleeve as
  arrows; the angle β.
- Bottom left: the joints B, F, H enlarged (at the largest GOST scale that shows the friction
  circle at most 24 mm across), each with the friction circle, the pin, the links' centre lines,
  the reaction touching the circle and the relative rotation it opposes.
- Middle: the force triangle of the sleeve 2 (G_2 + R_32 + R_42 = 0) and the force polygon of arm
  6 (G_6 + R_36 + F_i + R_76 = 0, with P = G_6 + R_36) at k_F, the frictionless polygon dashed.
- Right: the given data, the results beside the seed's, the order of construction.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from geomcad.forces import ForcePolygon, FrictionCircle
from geomcad.geom import Circle, Line, Vec, line_circle
from geomcad.sheet import Drawing, Scale, Sheet, TitleBlock, Viewport, fmt_number, start
from geomcad.sheet.scale import GOST_RATIOS, gost_scale_to_fit, nice_factor

if TYPE_CHECKING:
    from geomcad.problem import Solution

from .p2013_7 import Forces, Geometry
from .spec_2013_7 import SEED_K_F, SEED_K_L

#: Sheet regions (mm). The mechanism's room starts at MECH_AT; the force plan of arm 6 and the
#: order of construction are in the middle column; the sleeve's plan, the tables and the notes on
#: the right; the enlarged joints along the bottom, left of the title block.
MECH_AT = (24.0, 26.0)
MID_X = 163.0
PLAN6_AT = (164.0, 30.0)
STEPS_AT = (163.0, 104.0, 95.0)  # x, y, width
PLAN2_AT = (264.0, 24.0)
GIVEN_AT = (326.0, 10.0)
RIGHT_X = 264.0
INSETS = (22.0, 176.0, 228.0, 290.0)  # x0, y0, x1, y1
#: Force arrows on the mechanism drawing are this long (mm); they show lines and senses only.
ARROW_MM = 14.0
#: An inset shows its friction circle at most this many mm across.
INSET_CIRCLE_MM = 24.0


def scales(sol: Solution) -> dict[str, float]:
    """The sheet's k_l and k_F (for ``verify`` and the drawing): the seed's 1:2 and 1 N/mm for
    its data where they fit, else the largest that fit the sheet's rooms."""
    geo: Geometry = sol.data
    box = extent(geo)
    return {"l": sheet_k_l(box, sol.is_seed), "F": sheet_k_F(geo.run, geo.free, sol.is_seed)}


def extent(geo: Geometry) -> tuple[float, ...]:
    """The model box of the mechanism drawing: the shaft, the half-governor with its ball, Q and
    K, with a margin for the force arrows and labels."""
    run = geo.run
    rb = ball_radius(geo.D.dist(geo.H))
    B, F, D, H = geo.B, geo.F, geo.D, geo.H
    pts = [B, F, H, run.Q, run.K, Vec(0.0, 0.0), Vec(0.0, B.y), D + Vec(rb, rb), D - Vec(rb, rb)]
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    pad = 0.08 * max(max(xs) - min(xs), max(ys) - min(ys))
    return min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad


def ball_radius(l_DH: float) -> float:
    """The radius the ball D is drawn with (the problem gives none): 6 % of the arm HD."""
    return 0.06 * l_DH


#: The room (mm: width, height) of the mechanism drawing and of the two force plans on the sheet.
MECH_ROOM = (134.0, 140.0)
PLAN2_ROOM = (56.0, 100.0)
PLAN6_ROOM = (92.0, 72.0)


def sheet_k_l(box: tuple[float, ...], seed_data: bool) -> float:
    """k_l of the sheet: the seed's 0.002 m/mm (1:2) for its data when the drawing fits,
    otherwise the largest GOST 2.302 scale at which it fits its field."""
    w, h = box[2] - box[0], box[3] - box[1]
    room_w, room_h = MECH_ROOM
    if seed_data and w / SEED_K_L <= room_w and h / SEED_K_L <= room_h:
        return SEED_K_L
    return gost_scale_to_fit(w, h, room_w, room_h).k


def plan_box(poly: ForcePolygon) -> tuple[float, float, float, float]:
    """The plan extent (N) of a force polygon: xmin, ymin, xmax, ymax of its vertices."""
    xs = [q.x for vv in poly.vectors for q in (vv.tail, vv.head)]
    ys = [q.y for vv in poly.vectors for q in (vv.tail, vv.head)]
    return min(xs), min(ys), max(xs), max(ys)


def sheet_k_F(run: Forces, free: Forces, seed_data: bool) -> float:
    """k_F of the force plans: the seed's 1 N/mm for its data when both plans fit their room,
    otherwise the smallest factor 1, 2, 2.5, 4 or 5 × 10^n at which they do. The plan of arm 6
    also carries the frictionless polygon, drawn from the same pole."""
    need = 0.0
    for polys, room in (((run.tri2,), PLAN2_ROOM), ((run.poly6, free.poly6), PLAN6_ROOM)):
        boxes = [plan_box(pp) for pp in polys]
        w = max(b[2] for b in boxes) - min(b[0] for b in boxes)
        h = max(b[3] for b in boxes) - min(b[1] for b in boxes)
        need = max(need, w / room[0], h / room[1])  # N per mm
    if seed_data and need <= SEED_K_F:
        return SEED_K_F
    return nice_factor(need, 1.0, "F").k


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-7."""
    geo = sol.data
    kl = Scale(sol.scales["l"], "l")
    kf = Scale(sol.scales["F"], "F")
    tb = TitleBlock(
        title="Силовой расчёт центробежного регулятора с учётом трения",
        designation="ТММ.2013-7.01",
        scale=kl.ratio_text(),
    )
    d = start("A3", tb)
    d.text("Центробежный регулятор: круги трения и планы сил", (MECH_AT[0], 13.0), 5.0)
    d.text(
        f"Правая половина, {kl.label()}   (M {kl.ratio_text() or '—'})",
        (MECH_AT[0], 25.0),
        3.5,
    )
    _mechanism(d, geo, kl)
    _insets(d, geo, kl)
    _plans(d, geo, kf)
    _panel(d, sol)
    return [("", d.finish())]


# -- the mechanism --------------------------------------------------------------------------------


def _mechanism(d: Drawing, geo: Any, k: Scale) -> None:
    run = geo.run
    x0, y0, x1, y1 = extent(geo)
    at = (MECH_AT[0] + MECH_ROOM[0] / 2.0, MECH_AT[1] + MECH_ROOM[1] / 2.0)
    v = d.viewport(k, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at)
    B, F, D, H = geo.B, geo.F, geo.D, geo.H
    S = Vec(0.0, B.y)  # the sleeve's centre on the shaft
    over = k.model(4.0)
    # the shaft 7 and its axis, the collar, the sleeve 2 (a slider on the shaft)
    top, bottom = Vec(0.0, y1 - over), Vec(0.0, y0 + over)
    v.seg(top, bottom, "link")
    v.seg(top + Vec(0.0, over), bottom - Vec(0.0, over), "centre")
    v.seg(Vec(0.0, 0.0), H, "link")
    v.seg(S, B, "link")
    v.slider(S, (0.0, 1.0))
    # arm 6 with the ball D, link 3
    v.seg(H, D, "link")
    v.seg(B, F, "link")
    v.circle(D, ball_radius(geo.D.dist(H)), "link")
    for q in (B, F, H):
        v.joint(q)
    # the friction circles, to scale
    for fc in (run.fc_B, run.fc_F, run.fc_H):
        if fc.arm > 0.0:
            v.circle(fc.c, fc.arm, "construction")
    # the lines of action: link 3's (the common tangent), G_6's and F_i's through D, P's, R_76's
    ends3 = [run.link3.touch_a, run.link3.touch_b, run.Q]
    v.line_over(run.link3.line, ends3, "result", over=6.0)
    v.seg(D, run.Q, "construction")
    # F_i's line from D to K and on past K, where the angle β is marked
    past = k.model(17.0) * (1.0 if run.K.x >= D.x else -1.0)
    v.seg(D, Vec(run.K.x + past, D.y), "construction")
    v.line_over(run.P_line, [run.Q, run.K], "construction", over=8.0)
    t76 = run.R76_line.foot(H)
    v.line_over(run.R76_line, [run.K, t76], "result", over=8.0)
    for q in (run.Q, run.K):
        v.dot(q, "result")
    # the forces, drawn along their lines at a fixed length (senses, not magnitudes)
    m = k.model(ARROW_MM)
    u36 = run.link3.line.d
    _force(v, D, D + Vec(0.0, -m), "G_6", (1.0, -1.0))
    _force(v, D, D + Vec(m, 0.0), "Ф_6", (1.0, 1.0))
    _force(v, run.link3.touch_b, run.link3.touch_b + u36 * m, "R_{36}", (1.0, -1.0))
    _force(v, run.link3.touch_a, run.link3.touch_a + run.u32 * m, "R_{32}", (-1.0, 1.0))
    u76 = run.R76_line.d
    _force(v, t76, t76 + u76 * m, "R_{76}", (-1.0, 1.0))
    # the angle β between R_76's line and the horizontal, at K
    left = run.K + Vec(-1.0 if u76.x < 0.0 else 1.0, 0.0) * k.model(16.0)
    up = run.K + (u76 if u76.y > 0.0 else -u76) * k.model(16.0)
    v.dim_angle(run.K, left, up, f"β = {fmt_number(math.degrees(run.beta), digits=3)}°", 13.0, 2.5)
    # labels
    v.label(H, "H", prefer=(1.0, 1.0), clear=3.0)
    v.label(F, "F", prefer=(1.0, 0.0), clear=3.0)
    v.label(B, "B", prefer=(1.0, -1.0), clear=3.0)
    v.label(D, "D", prefer=(1.0, -1.0), clear=k.mm(ball_radius(geo.D.dist(H))) + 1.0)
    v.label(run.Q, "Q", prefer=(1.0, 0.0))
    v.label(run.K, "K", prefer=(0.0, -1.0), clear=2.0)
    v.label(S, "2", prefer=(-1.0, -1.0), clear=5.0)
    v.label(top, "7", prefer=(1.0, 0.0))


def _force(v: Viewport, tail: Vec, head: Vec, name: str, prefer: tuple[float, float]) -> None:
    v.arrow(tail, head, "vector")
    v.label(head, name, prefer=prefer, clear=0.5)


# -- the enlarged joints --------------------------------------------------------------------------


def inset_scale(rho: float, d: float, room_mm: float) -> Scale | None:
    """The GOST 2.302 scale of the joint insets: the largest at which the friction circle is at
    most INSET_CIRCLE_MM across and the pin fits the inset; ``None`` when there is no friction
    circle (f = 0)."""
    if rho <= 0.0:
        return None
    fits = [
        g
        for g in GOST_RATIOS
        if 2.0 * rho * 1000.0 * float(g) <= INSET_CIRCLE_MM and d * 1000.0 * float(g) <= room_mm
    ]
    g = fits[-1] if fits else GOST_RATIOS[0]
    return Scale(float(Fraction(1, 1000) / g), "l")


def _insets(d: Drawing, geo: Any, kl: Scale) -> None:
    run = geo.run
    x0, y0, x1, y1 = INSETS
    w = (x1 - x0) / 3.0
    room = min(w, y1 - y0 - 8.0) - 4.0  # the pin must fit the inset
    ks = inset_scale(run.rho, geo.d, room)
    if ks is None or ks.k >= kl.k:
        why = (
            "f = 0: круги трения вырождаются в точки, реакции проходят через центры шарниров."
            if ks is None
            else "Круги трения достаточно велики на основном чертеже; выносные элементы не нужны."
        )
        d.paragraph(why, x0, y0 + 4.0, x1 - x0, 3.5)
        return
    S = Vec(0.0, geo.B.y)
    u76 = run.R76_line.d
    joints = (
        (run.fc_B, [geo.F, S], run.link3.line, run.u32, "R_{32}", -1, "ω_{23}"),
        (run.fc_F, [geo.B, geo.H, geo.D], run.link3.line, run.link3.line.d, "R_{36}", -1, "ω_{63}"),
        (run.fc_H, [Vec(0.0, 0.0), geo.D], run.R76_line, u76, "R_{76}", 1, "ω_{67}"),
    )
    for i, (fc, towards, line, force, fname, flip, wname) in enumerate(joints):
        box = (x0 + i * w, y0, x0 + (i + 1) * w, y1)
        _inset(d, ks, box, fc, towards, line, force, fname, flip * fc.sense, wname, geo.d)


def _inset(
    d: Drawing,
    k: Scale,
    box: tuple[float, float, float, float],
    fc: FrictionCircle,
    towards: list[Vec],
    line: Line,
    force: Vec,
    fname: str,
    sense: int,
    wname: str,
    pin_d: float,
) -> None:
    """One enlarged joint: its friction circle, pin, links, the reaction and the rotation it
    opposes (``sense`` of the rotation of the link the reaction acts on, relative to the other).
    The title sits over the box, the joint in the middle of the rest."""
    bx0, by0, bx1, by1 = box
    centre_at = ((bx0 + bx1) / 2.0, (by0 + 8.0 + by1) / 2.0)
    top = centre_at[1] - max(k.mm(pin_d / 2.0), k.mm(fc.arm) + 12.0)
    d.text(f"Шарнир {fc.name}  (M {k.ratio_text()})", (bx0 + 2.0, max(by0 + 3.5, top - 3.0)), 3.5)
    v = d.viewport(k, fc.c, centre_at)
    reach = k.model(min(bx1 - bx0, by1 - by0 - 8.0) / 2.0 - 1.0)
    J = fc.c
    # the links' centre lines through the joint, the pin, the friction circle
    dirs = [(q - J).unit() for q in towards]
    for u in dirs:
        v.seg(J, J + u * reach, "centre")
    v.circle(J, pin_d / 2.0, "dimension")
    v.circle(J, fc.arm, "construction")
    v.dot(J)
    # the reaction's line inside the inset, and the reaction from its point of contact
    chord = line_circle(line, Circle(J, reach))
    touch = line.foot(J)
    if len(chord) == 2:
        v.seg(chord[0], chord[1], "result")
    u = force.unit()
    tip = touch + u * k.model(16.0)
    v.arrow(touch, tip, "vector")
    v.dot(touch, "result")
    v.label(tip, fname, prefer=(u.x, u.y), clear=0.5)
    # ρ: a radius of the friction circle in a free direction
    taken = [*dirs, (touch - J).unit(), u, -u]
    a_rho = _free_angle(taken)
    v.seg(J, J + Vec.polar(fc.arm, a_rho), "dimension")
    v.label(
        J + Vec.polar(fc.arm, a_rho), "ρ", height=2.5, prefer=(math.cos(a_rho), math.sin(a_rho))
    )
    # the relative rotation the reaction opposes, as a curved arrow outside the pin
    a_w = _free_angle([*taken, Vec.polar(1.0, a_rho)])
    r_w = (
        (fc.arm + pin_d / 2.0) / 2.0
        if k.mm(pin_d / 2.0 - fc.arm) > 8.0
        else pin_d / 2.0 + k.model(3.0)
    )
    _turn_arrow(v, J, r_w, a_w, sense)
    v.label(J + Vec.polar(r_w, a_w), wname, height=2.5, prefer=(math.cos(a_w), math.sin(a_w)))


def _free_angle(taken: list[Vec]) -> float:
    """The direction (rad) farthest, in angle, from every direction in ``taken``."""
    angles = [t.angle for t in taken]
    best, best_gap = 0.0, -1.0
    for i in range(72):
        a = i * math.pi / 36.0
        gap = min(abs(math.remainder(a - b, 2.0 * math.pi)) for b in angles)
        if gap > best_gap:
            best, best_gap = a, gap
    return best


def _turn_arrow(v: Viewport, c: Vec, r: float, mid: float, sense: int) -> None:
    """A curved arrow of radius r about c, 70° long, centred on the direction ``mid``, turning
    counter-clockwise for sense +1 and clockwise for −1."""
    half = math.radians(35.0)
    s = 1.0 if sense >= 0 else -1.0
    n = 24
    pts = [c + Vec.polar(r, mid - s * half + s * 2.0 * half * i / n) for i in range(n + 1)]
    v.polyline(pts[:-1], "dimension")
    v.arrow(pts[-3], pts[-1], "dimension")


# -- the force plans ------------------------------------------------------------------------------


def _plans(d: Drawing, geo: Any, k: Scale) -> None:
    run, free = geo.run, geo.free
    x, y = PLAN2_AT
    d.text("План сил звена 2,", (x, y - 9.0), 3.5)
    d.text(k.label(), (x, y - 3.0), 3.5)
    v2 = _plan_view(d, k, [run.tri2], (x, y), PLAN2_ROOM)
    _polygon(v2, run.tri2, {"G_2": "G_2", "R_32": "R_{32}", "R_42": "R_{42}"}, "vector")
    x, y = PLAN6_AT
    d.text(f"План сил звена 6, {k.label()}", (x - 1.0, y - 5.0), 3.5)
    v6 = _plan_view(d, k, [run.poly6, free.poly6], (x, y), PLAN6_ROOM)
    names = {"G_6": "G_6", "R_36": "R_{36}", "F_i": "Ф_6", "R_76": "R_{76}"}
    # the frictionless polygon first, dashed, under the one with friction (G_6 is common)
    if run.rho > 0.0:
        for vec_ in free.poly6.vectors:
            if vec_.name != "G_6":
                v6.seg(vec_.tail, vec_.head, "locus")
    # P = G_6 + R_36 runs beside R_36: P's label goes outside, R_36's inside the polygon
    _polygon(v6, run.poly6, names, "vector", inward=("R_36",))
    p = run.poly6.diagonal("G_6", "R_36", "P")
    v6.arrow(p.tail, p.head, "result")
    v6.label(_mid(p.tail, p.head), "P", prefer=_outward(run.poly6, p.tail, p.head))
    if run.rho > 0.0:
        fi0 = free.poly6["F_i"]
        v6.label(fi0.head, "f = 0", height=2.5, prefer=(1.0, -1.0))


def _plan_view(
    d: Drawing, k: Scale, polys: list[ForcePolygon], corner: tuple[float, float], room: Any
) -> Viewport:
    boxes = [plan_box(p) for p in polys]
    bx0 = min(b[0] for b in boxes)
    by0 = min(b[1] for b in boxes)
    bx1 = max(b[2] for b in boxes)
    by1 = max(b[3] for b in boxes)
    at = (corner[0] + room[0] / 2.0, corner[1] + room[1] / 2.0)
    return d.viewport(k, ((bx0 + bx1) / 2.0, (by0 + by1) / 2.0), at)


def _mid(a: Vec, b: Vec) -> Vec:
    return (a + b) * 0.5


def _outward(poly: ForcePolygon, a: Vec, b: Vec, inward: bool = False) -> tuple[float, float]:
    """The normal of side ab pointing away from the polygon's centroid (or towards it)."""
    pts = [vv.tail for vv in poly.vectors]
    cx = sum(q.x for q in pts) / len(pts)
    cy = sum(q.y for q in pts) / len(pts)
    n = (b - a).perp()
    if n.dot(_mid(a, b) - Vec(cx, cy)) < 0.0:
        n = -n
    if inward:
        n = -n
    u = n.unit()
    return (u.x, u.y)


def _polygon(
    v: Viewport,
    poly: ForcePolygon,
    names: dict[str, str],
    role: str,
    inward: tuple[str, ...] = (),
) -> None:
    """The polygon's vectors head to tail, each labelled beside its middle, outside the polygon
    (inside for the names in ``inward``)."""
    for vec_ in poly.vectors:
        v.arrow(vec_.tail, vec_.head, role)
        v.label(
            _mid(vec_.tail, vec_.head),
            names[vec_.name],
            prefer=_outward(poly, vec_.tail, vec_.head, vec_.name in inward),
            clear=0.5,
        )
    v.dot(poly.pole)


# -- the tables -----------------------------------------------------------------------------------


def _with_unit(value: str, unit: str) -> str:
    """A value with its unit: ``0,15 м``, ``45°`` (no space before the degree sign)."""
    return value + unit if unit in ("°", "") else f"{value} {unit}"


def _panel(d: Drawing, sol: Solution) -> None:
    p = sol.params
    r = sol.results
    geo = sol.data
    run, free = geo.run, geo.free
    # the given data, beside the sleeve's plan
    x, y = GIVEN_AT
    d.text("Исходные данные", (x, y + 3.5), 3.5)
    given = [
        ("m_2", fmt_number(float(p["m2"])), "кг"),
        ("m_ш", fmt_number(float(p["m_ball"])), "кг"),
        ("f", fmt_number(float(p["f"])), ""),
        ("d", fmt_number(float(p["d"])), "м"),
        ("AB", fmt_number(float(p["l_AB"])), "м"),
        ("GH", fmt_number(float(p["l_GH"])), "м"),
        ("FH", fmt_number(float(p["l_FH"])), "м"),
        ("DH", fmt_number(float(p["l_DH"])), "м"),
        ("BF", fmt_number(float(p["l_BF"])), "м"),
        ("θ", fmt_number(float(p["theta_deg"])), "°"),
        ("g", fmt_number(float(p["g"])), "м/с^2"),
        ("режим", "разгон" if int(p["direction"]) > 0 else "выбег", ""),
    ]
    half = (len(given) + 1) // 2
    rows = []
    for i in range(half):
        row: list[str] = []
        for j in (i, i + half):
            name, val, unit = given[j]
            row += [name, _with_unit(val, unit)]
        rows.append(row)
    head = ["Вел.", "Значение", "Вел.", "Значение"]
    _, h = d.table(x, y + 6.0, (14.0, 30.0, 14.0, 30.0), [head, *rows])
    y += 6.0 + h + 6.0
    # with and without friction
    d.text("С трением и без трения", (x, y + 3.5), 3.5)
    rows = [["", f"f = {fmt_number(run.f)}", "f = 0"]]
    for label, a, b, unit in (
        ("R_{32}", run.R32, free.R32, "Н"),
        ("P", run.P, free.P, "Н"),
        ("β", math.degrees(run.beta), math.degrees(free.beta), "°"),
        ("F_i", run.F_i, free.F_i, "Н"),
        ("ω", run.omega, free.omega, "рад/с"),
    ):
        rows.append(
            [
                label,
                _with_unit(fmt_number(a, digits=4), unit),
                _with_unit(fmt_number(b, digits=4), unit),
            ]
        )
    d.table(x, y + 6.0, (14.0, 37.0, 37.0), rows)
    # the results
    x, y = RIGHT_X, PLAN2_AT[1] + PLAN2_ROOM[1] + 4.0
    d.text("Результаты", (x, y + 3.5), 3.5)
    rows = [["Величина", "Значение"]]
    for name, label, unit in (
        ("rho", "ρ", "м"),
        ("alpha_deg", "α", "°"),
        ("R32", "R_{32}", "Н"),
        ("P", "P", "Н"),
        ("beta_deg", "β", "°"),
        ("F_i", "F_i = Ф_6", "Н"),
        ("r_D", "r_D", "м"),
        ("omega", "ω", "рад/с"),
        ("omega_no_friction", "ω (f = 0)", "рад/с"),
    ):
        rows.append([label, _with_unit(fmt_number(float(r[name]), digits=4), unit)])
    d.table(x, y + 6.0, (40.0, 60.0), rows)
    # the order of construction, under the arm's plan
    x, y, width = STEPS_AT
    y = d.text("Порядок построения", (x, y + 3.5), 3.5).at[1] + 2.0
    turn = {1: "против час. стрелки", -1: "по час. стрелке", 0: "нет"}
    mode = "разгон" if geo.direction > 0 else "выбег"
    kinds = {"internal": "внутренняя", "external": "внешняя"}
    friction = run.rho > 0.0
    if friction:
        circles = (
            f"ρ = 0,5d·sin(arctg f) = {fmt_number(run.rho * 1000.0, digits=4)} мм, круги "
            "трения в B, F, H;"
        )
        line3 = (
            f"линия звена 3 – {kinds.get(run.link3.kind, 'общая')} касательная к кругам B и "
            f"F, α = {fmt_number(math.degrees(run.alpha), digits=3)}° к BF;"
        )
        line76 = "R_{76} – касательная из K к кругу трения H, момент против ω_{67};"
    else:
        circles = "f = 0: кругов трения нет, реакции проходят через центры шарниров;"
        line3 = "линия звена 3 – BF;"
        line76 = "R_{76} – по прямой KH;"
    steps = (
        f"{mode}: ω_{{32}} {turn[run.fc_B.sense]}, ω_{{36}} {turn[run.fc_F.sense]}, "
        f"ω_{{67}} {turn[run.fc_H.sense]};",
        circles,
        line3,
        f"G_2 + R_{{32}} + R_{{42}} = 0: R_{{32}} = {fmt_number(run.R32, digits=4)} Н;",
        f"P = G_6 + R_{{36}} = {fmt_number(run.P, digits=4)} Н через точку Q; K – на линиях P "
        "и Ф_6;",
        line76,
        f"G_6 + R_{{36}} + Ф_6 + R_{{76}} = 0: F_i = {fmt_number(run.F_i, digits=4)} Н;",
        f"ω = (F_i/(m_ш·r_D))^{{1/2}} = {fmt_number(run.omega, digits=4)} рад/с"
        + (f" (f = 0: {fmt_number(free.omega, digits=4)})." if friction else "."),
    )
    for i, step in enumerate(steps):
        y = d.paragraph(f"{i + 1}. {step}", x, y, width, 2.5, indent=4.0) + 0.6
