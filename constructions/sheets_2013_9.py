"""2013-9's drawing sheets.

Main sheet (A3): the valve mechanism at the state, then split into disc 1 and rod 2, each with
every force and moment on it at the force scale μ_F, the inertia loads included (d'Alembert); the
given data, the results at the state and the equation of motion on the right. A load is drawn on
its line of action outside its body: the rod's inertia force Ф_2 and the damper's force act along
the rod's axis and its crossbar's verticals, so they are drawn beyond the crosshead and the
crossbar, not on them.

Sheet ``motion`` (A3): φ(t) and φ'(t) from rest at φ = 0 (solve_ivp) across the field, the table
of the motion at eleven instants, the integration and the derivation of the equation of motion.

Every word comes from ``strings/<lang>/sheets_2013_9.toml``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from geomcad import tol
from geomcad.geom import Vec
from geomcad.sheet import Drawing, Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.loads import damper, ground, moment, spring
from geomcad.sheet.scale import gost_scale_to_fit, nice_factor

from .dyn_common import Where, draw_loads, f, load, mu, short_note, small
from .p2013_9 import ROD, Data

if TYPE_CHECKING:
    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_9")

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
#: A load drawn beyond its body keeps this gap (mm) from the body's outline.
GAP_MM = 3.0
#: The motion sheet: the graphs' left edge and width, the right column's left edge (mm).
GRAPH_X, GRAPH_W, RIGHT_X = 45.0, 200.0, 262.0


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


def _title(sol: Solution, key: str, no: int) -> TitleBlock:
    return TitleBlock(
        title=WORDS(key),
        designation=WORDS("designation", no=no),
        sheet_no=no,
        sheets=2,
        scale=k_l(float(sol.params["r"])).ratio_text() if no == 1 else "",
        lang=current(),
    )


def _unit(u: str) -> str:
    """A unit's symbol in the language being drawn."""
    return WORDS(f"u_{u}")


def _main(sol: Solution) -> Sheet:
    data: Data = sol.data
    r = data.r
    k = k_l(r)
    k_F = sol.scales["F"]
    d = start("A3", _title(sol, "tb_main", 1))
    d.text(WORDS("head_main"), (25.0, 13.0), 5.0)
    d.text(
        WORDS(
            "state",
            phi=f(math.degrees(data.phi)),
            dphi=f(data.dphi),
            ddphi=f(data.ddphi),
            t=f(float(sol.params["t"])),
            mu_l=mu(k),
            ratio=k.ratio_text(),
            k_F=f(k_F),
        ),
        (25.0, 24.5),
        3.5,
    )
    # O's height: the scheme's support, or the rod's crossbar with the spring's push arriving
    # from above, whichever reaches higher, under the views' heads
    spring_mm = float(sol.results["F_spring"]) / k_F if data.x > 0.0 else 0.0
    rise = max(k.mm((ROD.ground + 0.15) * r), k.mm(data.x + ROD.top * r) + spring_mm + 4.0)
    oy = VIEW_TOP + rise
    views = [d.viewport(k, (0.0, 0.0), (x, oy)) for x in VIEW_X]
    for v, head in zip(views, ("view_scheme", "view_disc", "view_rod"), strict=True):
        d.text(WORDS(head), (v.at[0] - 30.0, 32.0), 3.5)
    _scheme(views[0], data)
    _disc(views[1], data, k_F)
    _rod(views[2], data, k_F)
    y = d.paragraph(
        WORDS("rod_motion", x=f(data.x), xd=f(data.xd), xdd=f(data.xdd)), 25.0, 238.0, 200.0, 2.5
    )
    d.paragraph(WORDS("forces_at_mu", note=short_note(k_F)), 25.0, y + 1.0, 200.0, 2.5)
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


def phi_arc_radius(data: Data, k: Scale) -> float:
    """The radius (model units) of the arc that marks φ: it ends on OA, 1 mm clear of the
    crosshead's outline and outside the moment's arrow at O, as large as that allows (at most
    0.9·r, so that A's joint stays clear)."""
    r, phi = data.r, data.phi
    lo = k.model(9.0)  # outside M(t)'s arrow about O (5 mm) with its head
    gap = k.model(1.0)
    below = data.x - ROD.frame * r - gap  # the crosshead's lower edge, less the gap
    above = data.x + ROD.frame * r + gap
    for i in range(36, 0, -1):
        rho = r * i / 40.0
        if rho < lo:
            break
        if not (below < rho * math.sin(phi) < above):
            return rho
    return lo


def _scheme(v: Viewport, data: Data) -> None:
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
    rho = phi_arc_radius(data, v.scale)
    v.dim_angle((0.0, 0.0), (rho, 0.0), A, "φ", r_mm=v.mm(rho), height=2.5)
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
    # the links' numbers (GOST 2.770): the disc 1, the rod 2; the frame 0 at its supports
    v.label(Vec.polar(DISC * r, math.radians(-60.0)), "1", 3.5, prefer=(1.0, -1.0), clear=1.5)
    v.label((0.0, 0.5 * (x + ROD.frame * r + g0)), "2", 3.5, prefer=(1.0, 0.0), clear=1.5)


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
            "M_Phi1": Where(WORDS("M_in1"), radius=9.5, start_deg=-20.0),
            "R_{01}": Where("R_{01}", prefer=(-1.0, 0.0)),
            "R_{12}": Where("R_{21}", prefer=(1.0, 0.0)),
        },
    )


def _rod(v: Viewport, data: Data, k_F: float) -> None:
    """The rod with its loads, each on its line of action outside the rod: the pin's push R_12
    arrives at A from below the crosshead, the spring's push at the crossbar's end from above;
    Ф_2 (along the axis) and the damper's force (along the crossbar's right vertical), drawn as
    points where they are short, sit on their lines beyond the crosshead and the crossbar."""
    r, x, phi = data.r, data.x, data.phi
    A = Vec(r * math.cos(phi), x)
    _crosshead(v, data)
    v.dot(A)
    v.label(A, "A", 3.5, prefer=(1.0, -1.0))
    gm = Vec(0.0, 0.5 * sum(ROD.guide) * r)
    v.dot(gm)
    gap = v.scale.model(GAP_MM)
    top = x + ROD.top * r
    under = x - ROD.frame * r - gap  # below the crosshead
    over = top + gap  # above the crossbar
    R = data.reactions

    def up(name: str) -> bool:
        F = load(R, "2", name)
        return F is not None and F.y > 0.0

    draw_loads(
        v,
        R,
        k_F,
        "2",
        {
            "R_{12}": Where("R_{12}", arrive=True, prefer=(1.0, 0.0)),
            # Phi_2 acts along the axis: drawn below the crosshead pushing up, or above the
            # crossbar pushing down
            "Phi_2": Where(
                WORDS("Phi2"),
                at=Vec(0.0, x - ROD.frame * r) if up("Phi_2") else Vec(0.0, top),
                arrive=True,
                prefer=(-1.0, 0.0),
                short_at=Vec(0.0, under) if up("Phi_2") else Vec(0.0, over),
            ),
            "F_spring": Where(
                WORDS("F_spring"),
                at=Vec(-ROD.bar_half * r, top),
                arrive=not up("F_spring"),
                prefer=(-1.0, 0.0),
                short_at=Vec(-ROD.bar_half * r, over),
            ),
            "F_damper": Where(
                WORDS("F_damper"),
                at=Vec(ROD.bar_half * r, top),
                arrive=not up("F_damper"),
                prefer=(1.0, 0.0),
                short_at=Vec(ROD.bar_half * r, over),
            ),
            "M_{02}": Where("M_{02}", at=gm, radius=5.0, start_deg=150.0),
        },
    )


def _zero(x: float, scale: float) -> float:
    """|x|, or 0 when it is round-off against ``scale``."""
    return 0.0 if abs(x) <= tol.DERIVED * max(abs(scale), 1.0) else abs(x)


def _given(d: Drawing, sol: Solution, x: float, y: float) -> float:
    """The given data as a table from (x, y top); returns the y below it and its gap."""
    p = sol.params
    d.text(WORDS("given"), (x, y + 3.5), 3.5)
    items = [
        ("J", "J", "kgm2"), ("m", "m", "kg"), ("r", "r", "m"), ("c", "c", "N_m"),
        ("k", "k", "Ns_m"), ("M0", "M_0", "Nm"), ("M1", "M_1", "Nm"), ("Omega", "Ω", "rad_s"),
        ("t", "t", "s"), ("phi_deg", "φ", "deg"), ("phi_dot", "φ'", "rad_s"), ("T", "T", "s"),
    ]  # fmt: skip
    cells = [f"{lab} = {f(float(p[n]), 6)}{'' if u == 'deg' else ' '}{_unit(u)}"
             for n, lab, u in items]  # fmt: skip
    rows = [[WORDS("param"), "M(t) = M_0 + M_1·sin Ωt"]]
    rows += [[cells[i], cells[i + 1]] for i in range(0, len(cells), 2)]
    _, h = d.table(x, y + 6.0, (73.0, 73.0), rows)
    return y + 6.0 + h + 6.0


def _panel_main(d: Drawing, sol: Solution, data: Data) -> None:
    res = sol.results
    x, y = PANEL_X, 10.0
    y = _given(d, sol, x, y)
    d.text(WORDS("results_state"), (x, y + 3.5), 3.5)
    R = data.reactions
    qty, val = WORDS("quantity"), WORDS("value")
    rows = [[qty, val, qty, val]]
    n, nm = _unit("N"), _unit("Nm")
    pairs = [
        (WORDS("J_pr"), f"{f(res['J_pr'], 4)} {_unit('kgm2')}"),
        (WORDS("dJ_pr"), f"{f(res['dJ_pr'], 4)} {_unit('kgm2')}"),
        (WORDS("M_pr"), f"{f(res['M_pr'], 4)} {nm}"),
        ("φ''", f"{f(res['phi_ddot'], 4)} {_unit('rad_s2')}"),
        ("R_{12} = R_{21}", f"{f(res['N_pin'], 4)} {n}"),
        ("R_{01}", f"{f(R.force('R_{01}').norm, 4)} {n}"),
        (f"{WORDS('F_spring')} = c|x|", f"{f(res['F_spring'], 4)} {n}"),
        (f"{WORDS('F_damper')} = k|x'|", f"{f(res['F_damper'], 4)} {n}"),
        (f"{WORDS('Phi2')} = m|x''|", f"{f(res['F_inertia_rod'], 4)} {n}"),
        (f"{WORDS('M_in1')} = J|φ''|", f"{f(res['M_inertia_disc'], 4)} {nm}"),
        ("M_{02}", f"{f(abs(R.moment('M_{02}')), 4)} {nm}"),
        ("R_{02}", f"{f(_zero(R.magnitudes['R_{02}'], res['N_pin']), 3)} {n}"),
    ]
    for i in range(0, len(pairs), 2):
        rows.append([pairs[i][0], pairs[i][1], pairs[i + 1][0], pairs[i + 1][1]])
    _, h = d.table(x, y + 6.0, (29.0, 44.0, 29.0, 44.0), rows)
    y += 6.0 + h + 5.0
    y = d.text(WORDS("eq_head"), (x, y + 3.5), 3.5).at[1] + 2.0
    for key in ("eq_1", "eq_2", "eq_3", "eq_4"):
        y = d.paragraph(WORDS(key), x, y, PANEL_W, 2.5, indent=4.0) + 0.6
    y += 3.0
    y = d.text(WORDS("loads_head"), (x, y + 3.5), 3.5).at[1] + 2.0
    mb = R.moment("M_b")
    notes = (
        WORDS("loads_1"),
        WORDS("loads_2"),
        WORDS("loads_3", mb=small(mb, data.M_t or 1.0, nm)),
    )
    for ln in notes:
        y = d.paragraph(f"– {ln}", x, y, PANEL_W, 2.5, indent=3.0) + 0.6


#: The title block's top-left corner on an A3 sheet (mm): nothing of a graph may reach into it.
BLOCK = (230.0, 232.0)


def _fit_graph(
    gx: Axis, sym: str, unit: str, ts: list[float], vals: list[float], y_head: float, room: float
) -> tuple[Axis, tuple[float, float]]:
    """The value axis of a graph under ``y_head`` with the largest height up to ``room`` at
    which its t axis, tick values and the curve keep out of the title block."""
    lo, hi = min(0.0, min(vals)), max(0.0, max(vals))
    while True:
        gy = Axis.fit(sym, unit, lo, hi, room)
        at = (GRAPH_X, y_head + 18.0 + gy.mm(gy.hi))
        right = [at[1] - gy.mm(v - gy.zero) for t, v in zip(ts, vals, strict=True)
                 if GRAPH_X + gx.mm(t) > BLOCK[0] - 2.0]  # fmt: skip
        low = max([at[1] + 12.0, *right])
        if low <= BLOCK[1] - 2.0 or room < 30.0:
            return gy, at
        room *= 0.8


def _motion(sol: Solution) -> Sheet:
    """φ(t) and φ'(t) on the left, one above the other on a common t axis, the derivation under
    them; on the right the integration, the table of the motion and the phase curve φ'(φ)."""
    data: Data = sol.data
    tr = data.motion
    lang = current()
    d = start("A3", _title(sol, "tb_motion", 2))
    d.text(WORDS("head_motion"), (25.0, 13.0), 5.0)
    T = tr.t_end
    ts = list(tr.t)
    gx = Axis.fit("t", _unit("s"), 0.0, T, GRAPH_W)
    gx = gx.with_tick(nice_step(T / 10.0))
    times = np.linspace(0.0, T, 11)
    state = tr.sol(times)
    # each graph: the head's y and the room (mm) of its curve's height
    for i, (vals, sym, unit, y_head, room) in enumerate(
        (
            (list(tr.phi), "φ", "rad", 24.0, 82.0),
            (list(tr.omega), "φ'", "rad_s", 136.0, 100.0),
        )
    ):
        gy, at = _fit_graph(gx, sym, _unit(unit), ts, vals, y_head, room)
        d.text(f"{i + 1}. {sym}(t)", (25.0, y_head), 3.5)
        g = Graph(d, gx, gy, at)
        g.factors((25.0, y_head + 6.0), lang)
        g.curve(ts, vals, "result")
        # the ordinates of the table's instants (those that stand on the t axis's upper side,
        # clear of its tick values)
        for tt, val in zip(times, state[i], strict=True):
            if val > 0.0:
                g.curve([tt, tt], [0.0, val], "construction")
        g.axes(lang)
        g.point(T, vals[-1], f"{sym}(T) = {f(vals[-1])}", prefer=(1.0, -1.0))
    x, y = RIGHT_X, 10.0
    width = 408.0 - RIGHT_X
    res = sol.results
    y = d.text(WORDS("int_head"), (x, y + 3.5), 3.5).at[1] + 2.0
    lines: tuple[str, ...] = (
        WORDS("int_1"),
        WORDS("int_rk") if tr.method == "DOP853" else WORDS("int_lsoda"),
        WORDS("int_3", phi=f(res["phi_T"]), omega=f(res["omega_T"]), T=f(T)),
    )
    for ln in lines:
        y = d.paragraph(f"– {ln}", x, y, width, 2.5, indent=3.0) + 0.6
    y += 4.0
    # the motion at eleven instants, from the dense solution
    d.text(WORDS("table_head"), (x, y + 3.5), 3.5)
    phis, omegas = state
    rows = [[f"t, {_unit('s')}", f"φ, {_unit('rad')}", f"φ, {_unit('deg')}",
             f"φ', {_unit('rad_s')}"]]  # fmt: skip
    for tt, ph, om in zip(times, phis, omegas, strict=True):
        rows.append([f(float(tt), 4), f(float(ph), 4), f(math.degrees(float(ph)), 4),
                     f(float(om), 4)])  # fmt: skip
    _, h = d.table(x, y + 6.0, (width / 4.0,) * 4, rows, row_h=7.0)
    y += 6.0 + h + 6.0
    y = d.text(WORDS("deriv_head"), (x, y + 3.5), 3.5).at[1] + 2.0
    for key in ("deriv_1", "deriv_2", "deriv_3", "deriv_4"):
        y = d.paragraph(f"– {WORDS(key)}", x, y, width, 2.5, indent=3.0) + 0.6
    _given(d, sol, x, y + 4.0)
    return d.finish()
