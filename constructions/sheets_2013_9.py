"""2013-9's drawing sheets.

Main sheet (A3): the valve mechanism at the state, then split into disc 1 and rod 2, each with
every force and moment on it at the force scale μ_F, the inertia loads included (d'Alembert); the
given data, the results at the state and the equation of motion on the right.

Sheet ``motion`` (A3): φ(t) and φ'(t) from rest at φ = 0 (solve_ivp), the derivation of the
equation of motion and the slips of the seed's solution.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad import tol
from geomcad.geom import Vec
from geomcad.sheet import Drawing, Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.graph import Axis, Graph
from geomcad.sheet.loads import damper, ground, moment, spring
from geomcad.sheet.scale import gost_scale_to_fit, nice_factor

from .dyn_common import Where, draw_loads, f, short_note, small
from .p2013_9 import ROD, Data

if TYPE_CHECKING:
    from geomcad.problem import Solution

PANEL_X = 262.0
PANEL_W = 146.0
#: The three views' centres along x and the top of the drawings on the sheet (mm).
VIEW_X = (64.0, 140.0, 212.0)
VIEW_TOP = 44.0
#: Room for the drawing of one view (mm): width, height.
VIEW_ROOM = (70.0, 180.0)
DISC = 1.3  # the disc's drawn radius, in units of r


#: Force arrows on the sheet: the largest force gets at most this many mm.
FORCE_ROOM_MM = 40.0


def scales(sol: Solution) -> dict[str, float]:
    """The sheet's μ_F (N/mm): the largest force at most FORCE_ROOM_MM long."""
    res = sol.results
    biggest = max(res["N_pin"], res["F_spring"], res["F_damper"], res["F_inertia_rod"])
    return {"F": nice_factor(biggest, FORCE_ROOM_MM, "F").k if biggest > 0.0 else 1.0}


def k_l(r: float) -> Scale:
    """The largest GOST scale at which a view (the disc or the crosshead across, the support
    above to the disc's bottom) fits its room."""
    w, h = 2.0 * max(DISC, ROD.slot_half + ROD.frame) * r, (ROD.ground + DISC + 0.4) * r
    return gost_scale_to_fit(w, h, VIEW_ROOM[0], VIEW_ROOM[1])


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet (the parts and their loads) and the ``motion`` sheet."""
    return [("", _main(sol)), ("motion", _motion(sol))]


def _title(sol: Solution, title: str, no: int) -> TitleBlock:
    return TitleBlock(
        title=title,
        designation=f"ТММ.2013-9.0{no}",
        sheet_no=no,
        sheets=2,
        scale=k_l(float(sol.params["r"])).ratio_text() if no == 1 else "",
    )


def _main(sol: Solution) -> Sheet:
    data: Data = sol.data
    r = data.r
    k = k_l(r)
    k_F = sol.scales["F"]
    d = start("A3", _title(sol, "Механизм клапана: силы и моменты", 1))
    d.text("Механизм клапана: расчленение на диск и шток в заданном положении", (25.0, 13.0), 5.0)
    d.text(
        f"φ = {f(math.degrees(data.phi))}°, φ' = {f(data.dphi)} рад/с, φ'' = {f(data.ddphi)} "
        f"рад/с², t = {f(float(sol.params['t']))} с;   {k.label()} (M {k.ratio_text()});   "
        f"μ_F = {f(k_F)} Н/мм",
        (25.0, 24.5),
        3.5,
    )
    oy = VIEW_TOP + k.mm((ROD.ground + 0.15) * r)
    views = [d.viewport(k, (0.0, 0.0), (x, oy)) for x in VIEW_X]
    for v, head in zip(views, ("а) схема механизма", "б) диск 1", "в) шток 2"), strict=True):
        d.text(head, (v.at[0] - 30.0, 32.0), 3.5)
    _scheme(views[0], data, sol)
    _disc(views[1], data, k_F)
    _rod(views[2], data, k_F)
    d.text(
        f"Шток: x = r·sin φ = {f(data.x)} м, x' = r·cos φ·φ' = {f(data.xd)} м/с, "
        f"x'' = r·cos φ·φ'' – r·sin φ·φ'^2 = {f(data.xdd)} м/с².",
        (25.0, 244.0),
        2.5,
    )
    d.text(
        f"Силы – в масштабе μ_F; {short_note(k_F)}.",
        (25.0, 250.0),
        2.5,
    )
    _panel_main(d, sol, data)
    return d.finish()


def _crosshead(v: Viewport, data: Data, role: str = "link") -> None:
    """The rod: its slotted crosshead around y = x, its stem and its crossbar."""
    r, x = data.r, data.x
    sh, fr = ROD.slot_half * r, ROD.frame * r
    slot = 0.09 * r
    outer = [(-sh - fr, x - fr), (sh + fr, x - fr), (sh + fr, x + fr), (-sh - fr, x + fr)]
    v.polyline(outer, role, closed=True)
    v.polyline([(-sh, x - slot), (sh, x - slot), (sh, x + slot), (-sh, x + slot)], role,
               closed=True)  # fmt: skip
    top = x + ROD.top * r
    v.seg((0.0, x + fr), (0.0, top), role)
    v.seg((-ROD.bar_half * r, top), (ROD.bar_half * r, top), role)


def _scheme(v: Viewport, data: Data, sol: Solution) -> None:
    r, x, phi = data.r, data.x, data.phi
    A = Vec(r * math.cos(phi), r * math.sin(phi))
    v.circle((0.0, 0.0), DISC * r, "link")
    v.seg((0.0, 0.0), A, "link")
    _crosshead(v, data)
    # the fixed guide: two bushings either side of the stem
    g0, g1 = ROD.guide[0] * r, ROD.guide[1] * r
    gap = v.scale.model(1.2)
    for s in (-1.0, 1.0):
        ground(v, (s * gap, g0), (s * gap, g1), (s, 0.0))
    # the spring (left) and the damper (right) between the crossbar and the support
    top = x + ROD.top * r
    gy = ROD.ground * r
    b = ROD.bar_half * r
    spring(v, (-b, top), (-b, gy))
    damper(v, (b, top), (b, gy))
    ground(v, (-1.3 * b - 0.1 * r, gy), (1.3 * b + 0.1 * r, gy), (0.0, 1.0))
    v.pivot((0.0, 0.0))
    v.joint(A)
    v.dim_angle((0.0, 0.0), (DISC * r, 0.0), A, "φ", r_mm=0.9 * v.mm(DISC * r), height=2.5)
    v.seg((0.0, 0.0), (1.25 * DISC * r, 0.0), "centre")
    moment(v, (0.0, 0.0), data.M_t, 5.0, "M(t)", role="vector", start=math.radians(150.0))
    # the rod's coordinate x along its axis, from the spring's free position
    xs = -(DISC + 0.15) * r
    v.arrow((xs, 0.0), (xs, 1.3 * r), "dimension")
    v.label((xs, 1.3 * r), "x", 3.5, prefer=(-1.0, 0.0))
    v.label(A, "A", 3.5, prefer=(1.0, -1.0))
    v.label((0.0, 0.0), "O", 3.5, prefer=(-1.0, -1.0))
    v.label((-b, 0.5 * (top + gy)), "c", 3.5, prefer=(-1.0, 0.0), clear=3.0)
    v.label((b, 0.5 * (top + gy)), "k", 3.5, prefer=(1.0, 0.0), clear=3.5)


def _disc(v: Viewport, data: Data, k_F: float) -> None:
    r, phi = data.r, data.phi
    A = Vec(r * math.cos(phi), r * math.sin(phi))
    v.circle((0.0, 0.0), DISC * r, "link")
    v.seg((0.0, 0.0), A, "link")
    v.joint((0.0, 0.0))
    v.joint(A)
    v.label(A, "A", 3.5, prefer=(1.0, 1.0))
    v.label((0.0, 0.0), "O", 3.5, prefer=(-1.0, 1.0))
    draw_loads(
        v,
        data.reactions,
        k_F,
        "1",
        {
            "M(t)": Where("M(t)", radius=5.0, start_deg=200.0),
            "M_{Ф1}": Where("M_{Ф1}", radius=9.5, start_deg=-20.0),
            "R_{01}": Where("R_{01}", prefer=(-1.0, 0.0)),
            "R_{12}": Where("R_{21}", prefer=(1.0, 0.0)),
        },
    )


def _rod(v: Viewport, data: Data, k_F: float) -> None:
    r, x, phi = data.r, data.x, data.phi
    A = Vec(r * math.cos(phi), x)
    _crosshead(v, data)
    v.dot(A)
    v.label(A, "A", 3.5, prefer=(1.0, -1.0))
    gm = Vec(0.0, 0.5 * sum(ROD.guide) * r)
    v.dot(gm)
    draw_loads(
        v,
        data.reactions,
        k_F,
        "2",
        {
            "R_{12}": Where("R_{12}", prefer=(1.0, 0.0)),
            "Ф_2": Where("Ф_2", prefer=(-1.0, 0.0)),
            "F_{упр}": Where("F_{упр}", prefer=(-1.0, 0.0)),
            "F_д": Where("F_д", prefer=(1.0, 0.0)),
            "M_{02}": Where("M_{02}", at=gm, radius=5.0, start_deg=150.0),
        },
    )


def _zero(x: float, scale: float) -> float:
    """|x|, or 0 when it is round-off against ``scale``."""
    return 0.0 if abs(x) <= tol.DERIVED * max(abs(scale), 1.0) else abs(x)


def _panel_main(d: Drawing, sol: Solution, data: Data) -> None:
    p, res = sol.params, sol.results
    x, y = PANEL_X, 10.0
    d.text("Исходные данные", (x, y + 3.5), 3.5)
    items = [
        ("J", "J", "кг·м²"), ("m", "m", "кг"), ("r", "r", "м"), ("c", "c", "Н/м"),
        ("k", "k", "Н·с/м"), ("M0", "M_0", "Н·м"), ("M1", "M_1", "Н·м"), ("Omega", "Ω", "рад/с"),
        ("t", "t", "с"), ("phi_deg", "φ", "°"), ("phi_dot", "φ'", "рад/с"), ("T", "T", "с"),
    ]  # fmt: skip
    cells = [f"{lab} = {f(float(p[n]), 6)}{'' if u == '°' else ' '}{u}" for n, lab, u in items]
    rows = [["Параметр", "M(t) = M_0 + M_1·sin Ωt"]]
    rows += [[cells[i], cells[i + 1]] for i in range(0, len(cells), 2)]
    _, h = d.table(x, y + 6.0, (73.0, 73.0), rows)
    y += 6.0 + h + 6.0
    d.text("Результаты в заданном положении", (x, y + 3.5), 3.5)
    R = data.reactions
    rows = [["Величина", "Значение", "Величина", "Значение"]]
    pairs = [
        ("J_{пр}", f"{f(res['J_pr'], 6)} кг·м²"),
        ("dJ_{пр}/dφ", f"{f(res['dJ_pr'], 6)} кг·м²"),
        ("M_{пр}", f"{f(res['M_pr'], 6)} Н·м"),
        ("φ''", f"{f(res['phi_ddot'], 6)} рад/с²"),
        ("R_{12} = R_{21}", f"{f(res['N_pin'], 6)} Н"),
        ("R_{01}", f"{f(R.force('R_{01}').norm, 6)} Н"),
        ("F_{упр} = c|x|", f"{f(res['F_spring'], 6)} Н"),
        ("F_д = k|x'|", f"{f(res['F_damper'], 6)} Н"),
        ("Ф_2 = m|x''|", f"{f(res['F_inertia_rod'], 6)} Н"),
        ("M_{Ф1} = J|φ''|", f"{f(res['M_inertia_disc'], 6)} Н·м"),
        ("M_{02}", f"{f(abs(R.moment('M_{02}')), 6)} Н·м"),
        ("R_{02}", f"{f(_zero(R.magnitudes['R_{02}'], res['N_pin']), 3)} Н"),
    ]
    for i in range(0, len(pairs), 2):
        rows.append([pairs[i][0], pairs[i][1], pairs[i + 1][0], pairs[i + 1][1]])
    _, h = d.table(x, y + 6.0, (29.0, 44.0, 29.0, 44.0), rows)
    y += 6.0 + h + 5.0
    y = d.text("Уравнение движения", (x, y + 3.5), 3.5).at[1] + 2.0
    lines = (
        "J_{пр} = J + mr^2cos^2φ,  dJ_{пр}/dφ = –mr^2sin 2φ;",
        "M_{пр} = M(t) – ½cr^2sin 2φ – kr^2cos^2φ·φ' (по равенству мощностей);",
        "J_{пр}φ'' + ½(dJ_{пр}/dφ)φ'^2 = M_{пр}, т.е.",
        "(J + mr^2cos^2φ)φ'' – ½mr^2sin 2φ·φ'^2 = M(t) – ½cr^2sin 2φ – kr^2cos^2φ·φ'.",
    )
    for ln in lines:
        y = d.paragraph(ln, x, y, PANEL_W, 2.5, indent=4.0) + 0.6
    y += 3.0
    y = d.text("Силы на частях механизма", (x, y + 3.5), 3.5).at[1] + 2.0
    mb = R.moment("M_b")
    notes = (
        "R_{ij} – сила звена i на звено j (0 – стойка); Ф_2 = –m·x'' и M_{Ф1} = –J·φ'' – "
        "нагрузки инерции (принцип Даламбера), их направления зависят от знака φ'' (от M_{пр});",
        "шток: F_{упр} = –c·x, F_д = –k·x', R_{12} вдоль оси штока (паз гладкий), момент "
        "направляющей M_{02}; диск: M(t), M_{Ф1}, R_{21} = –R_{12}, R_{01} в опоре O;",
        f"проверка: равновесие диска с нагрузками инерции требует уравновешивающего момента "
        f"M_у = {small(mb, data.M_t or 1.0, 'Н·м')}, т.е. 0 – кинетостатика совпадает с "
        "уравнением движения.",
    )
    for ln in notes:
        y = d.paragraph(f"– {ln}", x, y, PANEL_W, 2.5, indent=3.0) + 0.6


def _motion(sol: Solution) -> Sheet:
    data: Data = sol.data
    tr = data.motion
    d = start("A3", _title(sol, "Механизм клапана: закон движения", 2))
    d.text("Движение из состояния покоя при φ = 0: φ(t) и φ'(t)", (25.0, 13.0), 5.0)
    T = tr.t_end
    ts = list(tr.t)
    gx = Axis.fit("t", "с", 0.0, T, 195.0)
    for i, (vals, sym, unit, y_head) in enumerate(
        ((list(tr.phi), "φ", "рад", 24.0), (list(tr.omega), "φ'", "рад/с", 134.0))
    ):
        gy = Axis.fit(sym, unit, min(0.0, min(vals)), max(0.0, max(vals)), 92.0)
        d.text(f"{i + 1}. {sym}(t)", (25.0, y_head), 3.5)
        at = (45.0, y_head + 18.0 + gy.mm(gy.hi))
        g = Graph(d, gx, gy, at)
        g.factors((25.0, y_head + 6.0))
        g.curve(ts, vals, "result")
        g.axes()
        g.point(T, vals[-1], f"{sym}(T) = {f(vals[-1])}", prefer=(1.0, -1.0))
    x, y = PANEL_X, 10.0
    res = sol.results
    y = d.text("Интегрирование уравнения движения", (x, y + 3.5), 3.5).at[1] + 2.0
    lines: tuple[str, ...] = (
        "J_{пр}(φ)φ'' + ½J'_{пр}(φ)φ'^2 = M_{пр}(φ, φ', t) как система для (φ, φ'), "
        "начальные условия φ(0) = 0, φ'(0) = 0;",
        "численное интегрирование (метод Рунге – Кутты);"
        if tr.method == "DOP853"
        else "численное интегрирование жёсткой системы (LSODA: методы Адамса и BDF);",
        f"φ(T) = {f(res['phi_T'])} рад, φ'(T) = {f(res['omega_T'])} рад/с при T = {f(T)} с.",
    )
    for ln in lines:
        y = d.paragraph(f"– {ln}", x, y, PANEL_W, 2.5, indent=3.0) + 0.6
    y += 4.0
    y = d.text("Вывод уравнения (dE/dt = ΣN)", (x, y + 3.5), 3.5).at[1] + 2.0
    lines = (
        "x = r sin φ, x' = r cos φ·φ', E = ½(J + mr^2cos^2φ)φ'^2;",
        "N(M) = M(t)φ', N(F_{упр}) = –cx·x' = –½cr^2sin 2φ·φ', N(F_д) = –kx'^2 = –kr^2cos^2φ·φ'^2;",
        "dE/dt = (J + mr^2cos^2φ)φ'φ'' – mr^2sin φ cos φ·φ'^3;",
        "после сокращения на φ': (J + mr^2cos^2φ)φ'' – ½mr^2sin 2φ·φ'^2 = M(t) – ½cr^2sin 2φ – "
        "kr^2cos^2φ·φ'.",
    )
    for ln in lines:
        y = d.paragraph(f"– {ln}", x, y, PANEL_W, 2.5, indent=3.0) + 0.6
    return d.finish()
