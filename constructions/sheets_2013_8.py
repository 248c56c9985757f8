"""2013-8's drawing sheet: the press and its flywheel, the load diagram with the work as its
area, and the energy balance.

A3 landscape. Left, top: the force–penetration diagram F(s), the triangle from F_max at s = 0 to
zero at s = h, its area (the work of one hole, E) hatched. Left, bottom: the energy balance of the
flywheel over two cycles, ΔT(t): each hole takes E at once, the motor gives it back at the power N
over the cycle, so the flywheel's kinetic energy swings by E between ω_max and ω_min. Right: the
given data, the results, the solution step by step, and under them the kinematic scheme of the
press (GOST 2.770, not to scale): the motor driving the flywheel by a belt, the crankshaft that
carries the flywheel, the connecting rod and the punch over the plate on its die.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.geom import Vec
from geomcad.sheet import Drawing, Scale, Sheet, TitleBlock, fmt_number, start
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.model import CircleItem, Polyline

from .p2013_8 import Data

if TYPE_CHECKING:
    from collections.abc import Mapping

    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_8")

#: Room for the load diagram's axes on the sheet (mm).
F_ROOM_MM = (190.0, 115.0)
#: Room for the energy balance's axes (mm).
T_ROOM_MM = (130.0, 86.0)
PANEL_X = 262.0
PANEL_W = 146.0
#: The press's scheme under the tables: its crankshaft's x (mm) and its enlargement.
SCHEME_X = 350.0
SCHEME_ZOOM = 1.3
KN = 1000.0


def f(x: float, digits: int = 4) -> str:
    return fmt_number(x, current(), digits)


def scales(sol: Solution) -> Mapping[str, float]:
    """The sheet's factor k_F (N/mm): the load diagram draws F in kN at the factor Axis.fit
    chooses for its room."""
    f_max = float(sol.data.F[0])
    return {"F": Axis.fit("F", WORDS("kN"), 0.0, f_max / KN, F_ROOM_MM[1]).k * KN}


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-8."""
    data: Data = sol.data
    tb = TitleBlock(title=WORDS("tb_title"), designation=WORDS("designation"), lang=current())
    d = start("A3", tb)
    d.text(WORDS("title"), (25.0, 13.0), 5.0)
    _load_diagram(d, data)
    _energy_balance(d, data)
    y = _panel(d, sol)
    _scheme(d, y)
    return [("", d.finish())]


def _load_diagram(d: Drawing, data: Data) -> None:
    h = float(data.s[-1])
    f_max = float(data.F[0]) / KN
    lang = current()
    gx = Axis.fit("s", WORDS("m"), 0.0, h, F_ROOM_MM[0])
    gx = gx.with_tick(nice_step(max(gx.hi, -gx.lo) / 6.0))
    gy = Axis.fit("F", WORDS("kN"), 0.0, f_max, F_ROOM_MM[1])
    top = 36.0
    at = (48.0, top + 7.0 + gy.mm(gy.hi))
    d.text(WORDS("load_title"), (25.0, 24.0), 3.5)
    g = Graph(d, gx, gy, at)
    g.factors((25.0, 31.0), lang)
    g.hatch(list(data.s), [x / KN for x in data.F])
    g.curve(list(data.s), [x / KN for x in data.F], "result")
    g.axes(lang)
    # the peak and the plate's thickness named inside the field, clear of the tick values
    _note(g, 0.0, f_max, f"F_{{max}} = {f(f_max)} {WORDS('kN')}", (8.0, 1.2))
    g.point(h, 0.0, "s = h", prefer=(0.0, -1.0))
    mid = g.p(h / 2.0, f_max / 2.0)
    d.text(f"E = F_{{max}}·h/2 = {f(data.E)} {WORDS('J')}", (mid[0] + 4.0, mid[1] - 3.0), 3.5)
    d.text(WORDS("area"), (mid[0] + 8.0, mid[1] + 2.5), 2.5)


def _note(
    g: Graph, x: float, y: float, markup: str, off: tuple[float, float], leader: bool = True
) -> None:
    """A marked data point named by a text at ``off`` (mm, y down) from it, inside the field
    where no tick value stands, with a thin leader to the text when it is set apart."""
    px, py = g.p(x, y)
    g.d.sheet.add(CircleItem((px, py), 0.6, "point", fill=True))
    if leader:
        g.d.sheet.add(Polyline(((px, py), (px + off[0] - 0.8, py + off[1] - 1.0)), "dimension"))
    g.d.text(markup, (px + off[0], py + off[1]), 2.5)


def _energy_balance(d: Drawing, data: Data) -> None:
    T, E = data.cycle, data.E
    lang = current()
    gx = Axis.fit("t", WORDS("s"), 0.0, 2.2 * T, T_ROOM_MM[0])
    gy = Axis.fit("ΔT", WORDS("J"), 0.0, E, T_ROOM_MM[1])
    y_title = 172.0
    d.text(WORDS("balance_title"), (25.0, y_title), 3.5)
    at = (48.0, y_title + 18.0 + gy.mm(E))
    g = Graph(d, gx, gy, at)
    g.factors((25.0, y_title + 7.0), lang)
    # each hole takes E at once (t = 0, T); the motor returns it at the power N over the cycle
    ts = [0.0, 0.0, T, T, 2.0 * T]
    dts = [E, 0.0, data.N * T, 0.0, data.N * T]
    g.hatch([0.0, T], [0.0, data.N * T])
    g.curve(ts, dts, "result")
    g.axes(lang)
    g.curve([0.0, 2.1 * T], [E, E], "centre")
    g.span_y(2.1 * T, 0.0, E, f"E = {f(E)} {WORDS('J')}")
    # the speeds named at the top and the foot of the drop, inside the field, as "ω = ω_max",
    # so that they cannot be read as tick values
    g.point(T, E, "ω = ω_{max}", prefer=(1.0, -1.0), height=3.5)
    _note(g, T, 0.0, "ω = ω_{min}", (3.0, -1.4), leader=False)
    # what the diagram says, beside it
    x_note = 48.0 + T_ROOM_MM[0] + 24.0
    y = y_title + 24.0
    for key in ("balance_1", "balance_2", "balance_3"):
        y = d.paragraph(WORDS(key, T=f(T), N=f(data.N)), x_note, y, 255.0 - x_note, 2.5) + 0.6


def _panel(d: Drawing, sol: Solution) -> float:
    """The tables and the solution on the right; returns the y (mm) where they end."""
    p, r = sol.params, sol.results
    x, y = PANEL_X, 10.0
    d.text(WORDS("data"), (x, y + 3.5), 3.5)
    rows = [[WORDS("param"), WORDS("value")]]
    for name, label, unit in (
        ("d_hole", "d", WORDS("m")),
        ("h_plate", "h", WORDS("m")),
        ("tau", "τ", WORDS("Pa")),
        ("n_rpm", "n", WORDS("rpm")),
        ("delta", "δ", ""),
        ("holes_per_s", "z", WORDS("holes_per_s")),
    ):
        rows.append([label, f"{f(float(p[name]))} {unit}".strip()])
    _, hh = d.table(x, y + 6.0, (30.0, 40.0), rows)
    d.text(WORDS("results"), (x + 76.0, y + 3.5), 3.5)
    rows = [[WORDS("quantity"), WORDS("value")]]
    for name, label, unit, scale in (
        ("F_max", "F_{max}", WORDS("kN"), KN),
        ("E", "E", WORDS("J"), 1.0),
        ("N", "N", WORDS("W"), 1.0),
        ("omega_max", "ω_{max}", WORDS("rad_s"), 1.0),
        ("omega_min", "ω_{min}", WORDS("rad_s"), 1.0),
        ("J", "J", WORDS("kgm2"), 1.0),
    ):
        rows.append([label, f"{f(float(r[name]) / scale)} {unit}"])
    _, hr = d.table(x + 76.0, y + 6.0, (30.0, 40.0), rows)
    y += 6.0 + max(hh, hr) + 6.0
    y = d.text(WORDS("solution"), (x, y + 3.5), 3.5).at[1] + 2.0
    steps = [
        WORDS("step_1", F=f(r["F_max"] / KN)),
        WORDS("step_2", E=f(r["E"])),
        WORDS("step_3", N=f(r["N"])),
        WORDS("step_4", w=f(r["omega_max"])),
        WORDS("step_5", w=f(r["omega_min"])),
        WORDS("step_6", J=f(r["J"])),
    ]
    for i, step in enumerate(steps):
        y = d.paragraph(f"{i + 1}. {step}", x, y, PANEL_W, 2.5, indent=4.0) + 0.6
    return y


def _scheme(d: Drawing, top: float) -> None:
    """The press's kinematic scheme (GOST 2.770), not to scale: the motor's pulley and the
    flywheel joined by a belt, the flywheel on the crankshaft 1 with the crank, the connecting rod
    2, the punch 3 in its guides, the plate on the die. Model units are sheet millimetres at
    SCHEME_ZOOM."""
    d.text(WORDS("scheme_title"), (PANEL_X, top + 6.0), 3.5)
    R, r1, l2 = 19.0, 7.0, 30.0  # flywheel rim, crank, rod
    O1 = Vec(0.0, 0.0)
    z = SCHEME_ZOOM
    v = d.viewport(Scale(1.0 / z, "l"), (0.0, 0.0), (SCHEME_X, top + 12.0 + (R + 6.0) * z))
    s = v.sheet
    # the motor on its foot, its pulley on the shaft
    Mo = Vec(-50.0, -4.0)
    rp = 4.0
    v.circle(Mo, 7.0, "construction")
    v.circle(Mo, rp, "link")
    v.seg(Mo, Mo + Vec(0.0, -9.0 - 3.1 / z), "link")
    v.guide(Mo + Vec(-6.0, -9.0 - 3.1 / z), Mo + Vec(6.0, -9.0 - 3.1 / z))
    # the belt: the outer common tangents of the pulley and the flywheel's rim
    dv = O1 - Mo
    u = dv.unit()
    n = u.perp()
    c = (R - rp) / dv.norm
    sn = math.sqrt(1.0 - c * c)
    for sg in (1.0, -1.0):
        w = u * (-c) + n * (sg * sn)
        v.seg(Mo + w * rp, O1 + w * R, "link")
    # the flywheel (its rim) on the crankshaft 1, the crank O1 A, the rod 2
    v.circle(O1, R, "link")
    v.circle(O1, R - 2.5, "link")
    phi = math.radians(-60.0)
    A = O1 + Vec.polar(r1, phi)
    B = Vec(0.0, A.y - math.sqrt(l2 * l2 - A.x * A.x))
    v.seg(O1, A, "link")
    v.seg(A, B, "link")
    # the punch 3: a slider at B between vertical guides, the punch below it down to the plate
    tip = B - Vec(0.0, 9.0)
    v.seg(B, tip, "link")
    v.slider(B, (0.0, 1.0))
    for side in (-1.0, 1.0):
        v.guide(B + Vec(0.0, -6.0), B + Vec(0.0, 6.0), (side, 0.0))
    # the plate over the die's two blocks (hatched), the die's hole under the punch
    py = tip.y
    plate = [Vec(-13.0, py), Vec(13.0, py), Vec(13.0, py - 2.5), Vec(-13.0, py - 2.5)]
    v.polyline(plate, "link", closed=True)
    for x0, x1 in ((-15.0, -2.5), (2.5, 15.0)):
        y0, y1 = py - 2.5, py - 8.0
        v.polyline([Vec(x0, y0), Vec(x1, y0), Vec(x1, y1), Vec(x0, y1)], "link", closed=True)
        for i in range(1, 6):
            xa = x0 + (x1 - x0) * i / 6.0
            s.add(Polyline((v.p(Vec(xa - 1.8, y1)), v.p(Vec(xa + 1.8, y0))), "ground"))
    v.joint(A)
    v.pivot(O1, (0.0, 1.0))
    v.turn(O1, 1.0, -25.0, "ω", r_mm=(R + 3.0) * z, sweep_deg=40.0)
    # the links' numbers and names
    v.label(O1 + (A - O1) * 0.5, "1", 3.5, prefer=(1.0, 0.3), clear=0.8)
    v.label(A + (B - A) * 0.5, "2", 3.5, prefer=(1.0, 0.0), clear=0.8)
    v.label(B + Vec(0.0, 4.5), "3", 3.5, prefer=(1.0, 0.0), clear=4.0)
    v.label(O1 + Vec(R * 0.71, R * 0.71), WORDS("flywheel"), 2.5, prefer=(1.0, 1.0), clear=1.0)
    v.label(Mo + Vec(0.0, 7.0), WORDS("motor"), 2.5, prefer=(0.0, 1.0), clear=1.0)
    v.label(Vec(13.0, py - 1.25), WORDS("plate"), 2.5, prefer=(1.0, 0.0), clear=1.0)
    v.label(Vec(15.0, py - 6.0), WORDS("die"), 2.5, prefer=(1.0, 0.0), clear=1.0)
