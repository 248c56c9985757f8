"""2013-2's drawing sheet: the cam profile by inversion, the S(φ) graph and the velocity plan.

A3 landscape. Left: the profile at k_l (the seed's 2:1 when it fits; else the largest GOST scale
that does) with the base circle, the follower turned back to each division point (its axis and its
face, or its tip, or its roller), the profile, and the radius vectors r_i dimensioned; below it
the follower's law S(φ) with the ordinates of the division points. Right: the mechanism at the
middle division point with the velocity plan Bb₁b₂ and the similar triangle OBB′ (OB′ = BC = S′),
the given data, the results beside the seed's, and the notes.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from geomcad import tol
from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.cams import CamProfile, evert
from geomcad.kinematics.motion_laws import LAW_TITLES_RU
from geomcad.sheet import (
    Drawing,
    Scale,
    Sheet,
    TitleBlock,
    Viewport,
    fmt_number,
    gost_scale_to_fit,
    nice_factor,
    start,
)
from geomcad.sheet.graph import Axis, Graph

if TYPE_CHECKING:
    from geomcad.problem import Solution

from .p2013_2 import VIEW

MM = 1000.0
#: The mechanism scheme with the velocity plan (sheet mm: x0, y0, x1, y1).
SCHEME = (258.0, 19.0, 410.0, 122.0)
#: The laws' short names for the data table.
LAW_SHORT_RU = {
    "linear": "S = aφ",
    "constant_acceleration": "равноуск.",
    "harmonic": "косинус.",
    "cycloidal": "синус.",
    "poly345": "3-4-5",
}
#: Division points closer than this on the paper (mm) are not all labelled.
LABEL_APART = 5.0
#: The follower's stem on the scheme is at least this long on the paper (mm).
STEM_MM = 10.0
#: The lowest baseline the right-hand panel may use (the title block starts at y = 237).
BOTTOM = 234.0
#: The width (mm) kept for the velocity plan at the scheme's right.
PLAN_ROOM = 46.0
#: The S(φ) graph: the data origin's x and the bottom of the axis; its room (mm).
GRAPH = (34.0, 278.0, 180.0, 48.0)
PANEL_X = 258.0
PANEL_W = 152.0
#: Rows a results table shows at most (the first, the last and evenly spaced ones between).
MAX_ROWS = 7
#: The face lines run this far (paper mm) past the contact point and the follower's axis.
FACE_OVER = 6.0


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-2."""
    k = Scale(sol.scales["l"], "l")
    tb = TitleBlock(
        title="Профиль кулачка по закону движения толкателя",
        designation="ТММ.2013-2.01",
        scale=k.ratio_text(),
    )
    d = start("A3", tb)
    d.text("Профиль кулачка (метод обращения движения)", (VIEW[0], 13.0), 5.0)
    d.text(f"{k.label()}   (M {k.ratio_text() or '—'})", (VIEW[0], 20.0), 3.5)
    _profile_view(d, sol, k)
    _graph(d, sol)
    _scheme(d, sol)
    _panel(d, sol, k)
    return [("", d.finish())]


# -- the profile by inversion ----------------------------------------------------------------------


def _profile_view(d: Drawing, sol: Solution, k: Scale) -> None:
    geo = sol.data
    f = geo.follower
    prof, div = geo.profile, geo.divisions
    x0, y0, x1, y1 = geo.extent
    at = ((VIEW[0] + VIEW[2]) / 2.0, (VIEW[1] + 6.0 + VIEW[3]) / 2.0)
    v = d.viewport(k, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at)
    o = Vec(0.0, 0.0)
    # the theoretical profile's base circle r0 (for a roller its prime circle, dash-dot, and the
    # working profile's base circle r0 − r_roller)
    v.circle(o, f.r0, "centre" if f.kind == "roller" else "construction")
    if f.kind == "roller":
        v.circle(o, f.base_radius, "construction")
    v.centre_cross(o, 6.0)
    over = k.model(FACE_OVER)
    n = len(div.phi)
    if n > 1 and math.isclose(float(div.phi[-1] - div.phi[0]), 2.0 * math.pi):
        n -= 1  # the last point of a full turn is the first one again
    shown = _labelled(v, div, n)
    for i in range(n):
        turn = -f.sigma * float(div.phi[i])
        up = Vec(0.0, 1.0).rotated(turn)
        across = Vec(1.0, 0.0).rotated(turn)
        C = Vec(*div.pitch[i])
        B = Vec(*div.contact[i])
        # the follower's axis turned back by φ_i (for the flat face the line through O along
        # the motion, on which C_i lies), from O or its foot on the circle of radius e to past C_i
        foot = across * f.e if f.kind != "flat" else o
        tip = C + up * over
        v.seg(foot, tip, "construction")
        if i in shown:
            v.label(tip, str(i), height=2.5, prefer=(up.x, up.y), clear=0.5)
        if f.kind == "flat":
            t_b = (B - C).dot(across)
            lo, hi = min(0.0, t_b) - over, max(0.0, t_b) + over
            v.seg(C + across * lo, C + across * hi, "construction")
        elif f.kind == "roller":
            v.circle(C, f.r_roller, "construction")
        v.dot(C, "point")
        v.arrow(o, B, "result")
        if i in shown:
            v.label(B, f"B_{{{i}}}", height=2.5, prefer=(up.x, up.y))
    if f.kind != "flat" and f.e != 0.0:
        v.circle(o, abs(f.e), "centre")
    if f.kind == "roller":
        v.polyline(list(prof.pitch), "centre", closed=geo.closed)
    v.polyline(list(prof.contact), "link", closed=geo.closed)
    v.label(o, "O", prefer=(-1.0, -1.0), clear=1.0)
    # the inversion: the follower turns about O against the cam's rotation
    _turn_arrow(v, 0.55 * f.r0, 125.0, 165.0, -f.sigma, "–ω")
    # the radius vectors, dimensioned as radii: the line from o, its arrow at B_i, the value
    for i in sorted(shown):
        B = Vec(*div.contact[i])
        text = f"r_{{{i}}} = {fmt_number(float(div.radius[i]) * MM, digits=4)}"
        spots = tuple(v.p(B * t) for t in (0.6, 0.8, 0.5, 0.9, 0.4))
        d.label(v.p(B * 0.7), text, 2.5, others=spots)
    # the angle of one interval, between the last two axes
    if n >= 2:
        a0 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-2]))
        a1 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-1]))
        dphi = math.degrees(float(div.phi[-1] - div.phi[-2]))
        v.dim_angle(o, a0, a1, f"{fmt_number(dphi, digits=4)}°", r_mm=k.mm(f.r0) * 0.55,
                    height=2.5)  # fmt: skip


def _labelled(v: Viewport, div: CamProfile, n: int) -> set[int]:
    """The division points that get labels: every ``_label_step``-th one, and of those only
    points at least LABEL_APART mm on the paper from the ones already taken (the last one is
    preferred to its neighbour)."""
    step = _label_step(n)
    want = [i for i in range(n) if i % step == 0 or i == n - 1]
    taken: list[int] = []
    for i in [want[-1], *want[:-1]] if len(want) > 1 else want:
        q = v.p(div.contact[i])
        if all(math.dist(q, v.p(div.contact[j])) >= LABEL_APART for j in taken):
            taken.append(i)
    return set(taken)


def _label_step(n: int) -> int:
    """Label every point up to 13 of them, else every second, third …"""
    return max(1, math.ceil(n / 13))


# -- the law S(φ) ----------------------------------------------------------------------------------


def _graph(d: Drawing, sol: Solution) -> None:
    geo = sol.data
    prog = geo.program
    end = 2.0 * math.pi if geo.closed else prog.total
    x_at, y_at, room_w, room_h = GRAPH
    gx = Axis.fit("φ", "рад", 0.0, end, room_w)
    gy = Axis.fit("S", "м", 0.0, prog.H, room_h)
    g = Graph(d, gx, gy, (x_at, y_at))
    phi = np.linspace(0.0, end, 721)
    g.axes(tick_labels=True)
    g.curve(phi.tolist(), prog.motion(phi).S.tolist(), "link")
    div = geo.divisions
    n = len(div.phi)
    step = _label_step(n)
    for i in range(n):
        g.ordinate(float(div.phi[i]), float(div.S[i]), str(i) if i % step == 0 else "")
    top = g.box[1]
    d.text(
        f"Закон движения толкателя S(φ): {LAW_TITLES_RU[str(sol.params['law'])]}",
        (x_at - 6.0, top - 12.0),
        3.5,
    )
    g.factors((x_at + room_w * 0.45, top - 5.0))


# -- the scheme and the velocity plan --------------------------------------------------------------


def _scheme(d: Drawing, sol: Solution) -> None:
    """The mechanism at the middle division point, in the fixed frame: the cam, the follower, the
    triangle OBB′ (and C); beside it the velocity plan pb₁b₂ at its own factor."""
    geo = sol.data
    f = geo.follower
    plan = geo.plan
    phi = plan.phi
    cam = evert(geo.profile.contact, np.full(len(geo.profile.phi), phi), f.sigma)
    width = float(np.max(np.abs(geo.profile.S1))) + 0.2 * f.r0
    h = float(plan.B.y)
    x0, y0, x1, y1 = SCHEME
    room_w, room_h = x1 - x0 - PLAN_ROOM - 8.0, y1 - y0
    stem = 0.25 * f.r0
    for _ in range(2):  # the stem is at least STEM_MM long on the paper
        xs = [*cam[:, 0], -f.r0, f.r0, -width, width]
        ys = [*cam[:, 1], -f.r0, h + stem]
        w_m, h_m = max(xs) - min(xs), max(ys) - min(ys)
        kl = gost_scale_to_fit(w_m, h_m, room_w, room_h)
        stem = max(0.25 * f.r0, kl.model(STEM_MM))
    left = x0 + 2.0 + (room_w - kl.mm(w_m)) / 2.0
    v = d.viewport(kl, (min(xs), (max(ys) + min(ys)) / 2.0), (left, (y0 + y1) / 2.0))
    o = Vec(0.0, 0.0)
    # the cam: its built profile and the base circle, turned to φ
    v.circle(o, f.base_radius, "construction")
    v.polyline(list(cam), "link", closed=geo.closed)
    Bp, C, B = plan.B_prime, plan.C, plan.B
    away = -1.0 if Bp.x >= 0.0 else 1.0
    v.pivot(o, down=(away, -1.0))
    _omega_arrow(v, max(f.r0 * 0.35, kl.model(13.0)), f.sigma, away)
    # the follower: flat face (or knife, roller), stem, guides
    top = Vec(f.e, h + stem)
    if f.kind == "flat":
        v.seg(Vec(-width, h), Vec(width, h), "link")
        v.seg(Vec(f.e, h), top, "link")
    elif f.kind == "roller":
        v.circle(B, f.r_roller, "link")
        v.seg(B, top, "link")
        v.joint(B)
    else:
        v.seg(B, top, "link")
    g_lo, g_hi = Vec(f.e, h + stem * 0.45), Vec(f.e, h + stem * 0.95)
    v.guide(g_lo, g_hi, (1.0, 0.0))
    v.guide(g_lo, g_hi, (-1.0, 0.0))
    # the triangle OBB′ similar to the plan, and C (BC = OB′ = S′)
    v.seg(o, B, "construction")
    v.seg(B, Bp, "construction")
    v.seg(o, Bp, "construction")
    if f.kind == "flat":
        v.seg(o, C, "construction")
    _right_angle(v, Bp, o, B)
    for q in (o, B, Bp):
        v.dot(q, "point")
    v.label(o, "O", prefer=(-away, 1.0), clear=1.5)
    v.label(B, "B", prefer=(-away, 1.0))
    v.label(Bp, "B'", prefer=(-away, -1.0))
    if f.kind == "flat":
        v.label(C, "C", prefer=(away, -1.0))
    if abs(plan.S1) > 0.0:
        v.dim_linear(o, Bp, "S'", offset=-3.0 if Bp.x > 0 else 3.0, height=2.5)
    # the velocity plan: pb1 = V_B1 ⊥ OB, pb2 = V_B2 along the motion, b1b2 = V_B2B1
    pts = [Vec(0.0, 0.0), plan.V_B1, plan.V_B2]
    pw = max(q.x for q in pts) - min(q.x for q in pts)
    ph = max(q.y for q in pts) - min(q.y for q in pts)
    p_room_w, p_room_h = PLAN_ROOM - 6.0, 0.45 * (y1 - y0)
    kv = nice_factor(max(pw * p_room_h / p_room_w, ph, plan.V_B1.norm * 0.1), p_room_h, "v")
    px = x1 - 4.0 - kv.mm(max(q.x for q in pts))
    py = y0 + 10.0 + kv.mm(max(q.y for q in pts))
    pv = d.viewport(kv, (0.0, 0.0), (px, py))
    pole = Vec(0.0, 0.0)
    b1, b2 = plan.V_B1, plan.V_B2
    pv.arrow(pole, b1, "vector")
    if b2.norm > 0.0:
        pv.arrow(pole, b2, "vector")
    if (b2 - b1).norm > 0.0:
        pv.arrow(b1, b2, "vector")
    pv.dot(pole, "point")
    pv.label(pole, "p", height=3.5, prefer=(1.0, -1.0))
    pv.label(b1, "b_1", height=3.5, prefer=(-1.0, 0.0))
    pv.label(b2, "b_2", height=3.5, prefer=(1.0, 1.0))
    low = max(pv.p(q)[1] for q in pts) + 9.0
    d.text("План скоростей", (x1 - PLAN_ROOM + 2.0, low), 3.5)
    d.text(f"{kv.label()}", (x1 - PLAN_ROOM + 2.0, low + 4.5), 2.5)
    d.text("(ω = 1 рад/с)", (x1 - PLAN_ROOM + 2.0, low + 8.5), 2.5)
    k_i = geo.plan_index
    d.text(
        f"Механизм при φ_{{{k_i}}} = {fmt_number(math.degrees(phi), digits=4)}° и план скоростей",
        (x0, y0 - 7.0),
        3.5,
    )
    d.text(
        f"{kl.label()} (M {kl.ratio_text()});  ΔOBB' подобен плану pb_1b_2, "
        + ("OB' = BC = S'" if f.kind == "flat" else "OB' = S'"),
        (x0, y0 - 2.5),
        2.5,
    )


def _omega_arrow(v: Viewport, r: float, sigma: int, side: float) -> None:
    """The cam's sense of rotation: an arc about O below it, on ``side`` (±1 in x), with an
    arrowhead, labelled ω."""
    a0, a1 = (200.0, 290.0) if side <= 0.0 else (250.0, 340.0)
    _turn_arrow(v, r, a0, a1, sigma, "ω")


def _turn_arrow(v: Viewport, r: float, a0_deg: float, a1_deg: float, sense: int, text: str) -> None:
    """An arc about O from a0 to a1 (degrees, counter-clockwise) with an arrowhead at the end the
    ``sense`` (+1 counter-clockwise) points to, and its label."""
    a0, a1 = math.radians(a0_deg), math.radians(a1_deg)
    v.arc(Arc(Circle(Vec(0.0, 0.0), r), a0, a1), "dimension")
    end, before = (a1, a1 - 0.15) if sense > 0 else (a0, a0 + 0.15)
    v.arrow(Vec.polar(r, before), Vec.polar(r, end), "dimension")
    mid = (a0 + a1) / 2.0
    v.label(Vec.polar(r, mid), text, height=3.5, prefer=(math.cos(mid), math.sin(mid)), clear=0.5)


def _right_angle(v: Viewport, vertex: Vec, a: Vec, b: Vec, size_mm: float = 2.5) -> None:
    s = v.scale.model(size_mm)
    if (a - vertex).norm == 0.0 or (b - vertex).norm == 0.0:
        return
    ua, ub = (a - vertex).unit() * s, (b - vertex).unit() * s
    v.polyline([vertex + ua, vertex + ua + ub, vertex + ub], "construction")


# -- tables ----------------------------------------------------------------------------------------


def _rows(n: int) -> list[int]:
    """The division points a table shows: all of them, or MAX_ROWS spread evenly."""
    if n <= MAX_ROWS:
        return list(range(n))
    idx = np.unique(np.round(np.linspace(0, n - 1, MAX_ROWS)).astype(int))
    return [int(i) for i in idx]


def _clean(x: float, size: float) -> float:
    """A value that is zero up to rounding (sin π …) printed as 0."""
    return 0.0 if abs(x) <= tol.DERIVED * size else x


def _panel(d: Drawing, sol: Solution, k: Scale) -> None:
    p, r, geo = sol.params, sol.results, sol.data
    x, y = PANEL_X, 125.0
    d.text("Исходные данные", (x, y + 3.5), 3.5)
    law = str(p["law"])
    kinds = {"flat": "плоский", "knife": "острый", "roller": "роликовый"}
    mm = MM
    rise, dwell, ret = (fmt_number(float(p[n]), digits=4) for n in ("phi_rise_deg",
                        "phi_dwell_deg", "phi_return_deg"))  # fmt: skip
    step_deg = fmt_number(math.degrees(geo.span) / int(p["n_div"]), digits=3)
    e_mm, rr_mm = (fmt_number(float(p[n]) * mm, digits=4) for n in ("e", "r_roller"))
    offsets = f"{e_mm} / {rr_mm} мм"
    r0_mm = fmt_number(float(p["r0"]) * mm, digits=4)
    rows = [
        ["H", f"{fmt_number(float(p['H']) * mm, digits=4)} мм", "φ_у", f"{rise}°", "закон",
         LAW_SHORT_RU[law]],
        ["r_{min}", f"{r0_mm} мм", "φ_д / φ_с", f"{dwell}° / {ret}°",
         "толкатель", kinds[str(p["follower"])]],
        ["интерв.", f"{p['n_div']} × {step_deg}°",
         "ω", "против час." if int(p["omega_sign"]) > 0 else "по час.", "e / r_{рол}",
         offsets],
    ]  # fmt: skip
    widths = (13.0, 25.0, 15.0, 29.0, 20.0, 30.0)
    _, h = d.table(x, y + 5.0, widths, rows, row_h=5.0, header=False)
    y += 5.0 + h + 5.0
    d.text("Результаты (мм)", (x, y + 3.5), 3.5)
    head = ["i", "φ_i, °", "S_i", "S'_i", "r_i"]
    rows = [head]
    n = len(r["phi"])
    for i in _rows(n):
        rows.append(
            [
                str(i),
                fmt_number(math.degrees(float(r["phi"][i])), digits=4),
                fmt_number(_clean(float(r["S"][i]), geo.program.H) * mm, digits=4),
                fmt_number(_clean(float(geo.divisions.S1[i]), geo.program.H) * mm, digits=4),
                fmt_number(float(r["r"][i]) * mm, digits=4),
            ]
        )
    rows.append(["a", "", "", "", fmt_number(float(r["a"]) * mm, digits=4)])
    r_widths = (14.0, 26.0, 26.0, 26.0, 30.0)
    _, h = d.table(x, y + 5.0, r_widths, rows, row_h=4.5)
    y += 5.0 + h + 1.5
    rho = float(r["rho_min"]) * mm
    alpha = float(r["pressure_angle_max_deg"])
    summary = (
        f"a = H/φ_у;  ρ_{{min}} = {fmt_number(rho, digits=5)} мм;  "
        f"α_{{max}} = {fmt_number(alpha, digits=4)}°."
    )
    for text in [summary, *_notes_ru(sol)]:
        y = d.paragraph(text, x, y, PANEL_W, 2.5) + 0.6
    order = _order_ru(sol)
    if y + 7.0 + 4.5 * len(order) <= BOTTOM:
        y = d.text("Порядок построения", (x, y + 5.0), 3.5).at[1] + 1.2
        for i, step in enumerate(order):
            y = d.paragraph(f"{i + 1}. {step}", x, y, PANEL_W, 2.5, indent=4.0) + 0.2


def _order_ru(sol: Solution) -> list[str]:
    """The construction by inversion, step by step (one line each)."""
    kind = sol.data.follower.kind
    lay = "r_{min} + S_i" if kind == "flat" else "s_0 + S_i"
    what = {
        "flat": "через C_i – тарелки перпендикулярно осям, B_i в S'_i от оси",
        "knife": "B_i = C_i – положения острия",
        "roller": "C_i – центры ролика, B_i – по нормали на r_{рол}",
    }[kind]
    last = {
        "flat": "профиль – огибающая тарелок",
        "knife": "профиль – кривая через B_i",
        "roller": "профиль – эквидистанта центрового",
    }[kind]
    return [
        "оси толкателя 0, 1, 2 … повёрнуты вокруг O на φ_i против вращения кулачка (–ω);",
        f"на осях отложены {lay} (точки C_i); {what};",
        f"{last}; радиус-векторы r_i = OB_i.",
    ]


def _notes_ru(sol: Solution) -> list[str]:
    """The sheet's notes: the radius formula, what happens at a jump of S′."""
    geo = sol.data
    f = geo.follower
    out: list[str] = []
    if f.kind == "flat":
        out.append(
            "r_i^2 = (r_{min} + S_i)^2 + S'_i^2: точка касания B отстоит от оси толкателя на "
            "BC = OB' = S' (ΔOBB' подобен плану pb_1b_2)."
        )
    prof = geo.profile
    if np.any(prof.corner) and f.kind == "flat" and sol.params["law"] == "linear":
        a = float(sol.results["a"]) * MM
        out.append(
            f"При φ = 0 S' скачком растёт от 0 до a = {fmt_number(a, digits=4)} мм (жёсткий "
            "удар): профиль начинается отрезком прямой длиной a, касательным к окружности r_{min}, "
            "далее – эвольвента окружности радиуса a."
        )
    return out
