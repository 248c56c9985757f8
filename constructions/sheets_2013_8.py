"""2013-8's drawing sheet: the press and its flywheel, the load diagram with the work as its
area, and the energy balance.

A3 landscape, composed by geomcad.sheet.compose (no view placed by hand). Left, top: the
force–penetration diagram F(s), the triangle from F_max at s = 0 to zero at s = h, its area (the
work of one hole, E) hatched. Left, bottom: the energy balance of the flywheel over two cycles,
ΔT(t): each hole takes E at once, the motor gives it back at the power N over the cycle, so the
flywheel's kinetic energy swings by E between ω_max and ω_min. Right: the heading, the given
data, the results, the solution step by step, what the energy balance says, and under them the
kinematic scheme of the press (GOST 2.770, not to scale): the motor driving the flywheel by a
belt, the crankshaft that carries the flywheel, the connecting rod and the punch over the plate
on its die.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.geom import Vec
from geomcad.sheet import Sheet, TitleBlock, start
from geomcad.sheet.compose import Column, Field, Figure, Layout, Row, arrange, compose
from geomcad.sheet.graph import Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.model import CircleItem, Polyline
from geomcad.sheet.views import AxisSpec, Curve, Diagram, Steps, Table, Text, num

from .p2013_8 import Data
from .spec_2013_8 import PARAMS, RESULTS

if TYPE_CHECKING:
    from collections.abc import Mapping

    from geomcad.problem import Solution
    from geomcad.sheet.drawing import Viewport

WORDS = Words(__package__, "sheets_2013_8")

#: The scheme's model: sheet millimetres of a drawing not to scale (flywheel rim, crank, rod).
RIM, CRANK, ROD = 19.0, 7.0, 30.0
#: The scheme's model box (x0, y0, x1, y1), round the motor, the flywheel and the die.
SCHEME_BOX = (-60.0, -55.0, 30.0, 27.0)
#: Width (mm) of the solution's text and of the notes beside the energy balance.
SOLUTION_W = 146.0
#: The recorded steps the solution lists, in their order.
SOLUTION = ("F_max", "E", "N", "ω_max", "ω_min", "J")
NOTE_W = SOLUTION_W
#: Width (mm) the sheet's heading wraps at (it heads the right-hand column).
HEADING_W = 170.0
KN = 1000.0


class _Sheet:
    """The sheet's views and their arrangement (one tree for the sheet and the scales hook)."""

    def __init__(self, sol: Solution[Data]) -> None:
        data = sol.data
        self.load = _load_diagram(data)
        self.balance = _energy_balance(data)
        # one sentence (the cycle and the motor's return of E), then its formula on a line
        keys = ("balance_1", "balance_2", "balance_3")
        w = [WORDS(k, T=num(data.cycle), N=num(data.N)) for k in keys]
        note = Text(paragraphs=[f"{w[0]} {w[1]}", w[2]], width=NOTE_W)
        given, results, solution = _panel(sol)
        # the press's scheme is not to scale: it takes whatever enlargement its place allows
        scheme = Figure(SCHEME_BOX, _scheme, title=WORDS("scheme_title"), show_scale=False,
                        series="free", margin=6.0)  # fmt: skip
        heading = Text(paragraph=WORDS("title"), width=HEADING_W, height=5.0)
        left = Column(self.load, self.balance, weights=(1.33, 1.0))
        right = Column(heading, Row(given, results), solution, note, scheme)
        self.tree = Row(left, right, weights=(0.52, 0.48))
        self.layout: Layout = arrange(self.tree, Field.of_format("A3"))


def _factor(view: Diagram, lay: Layout) -> float:
    """The y factor (units per mm) the diagram takes in its place."""
    x0, y0, x1, y1 = lay[view].inner
    return view.axes(x1 - x0, y1 - y0)[1].k


def scales(sol: Solution[Data]) -> Mapping[str, float]:
    """The sheet's factor k_F (N/mm): the load diagram draws F in kN at the factor its place
    on the composed sheet allows."""
    s = _Sheet(sol)
    return {"F": _factor(s.load, s.layout) * KN}


def sheets(sol: Solution[Data]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-8."""
    tb = TitleBlock(title=WORDS("tb_title"), designation=WORDS("designation"), lang=current())
    d = start("A3", tb)
    s = _Sheet(sol)
    compose(d, s.tree, layout=s.layout)
    return [("", d.finish())]


def _load_diagram(data: Data) -> Diagram:
    h = float(data.s[-1])
    f_max = float(data.F[0]) / KN
    ks = [x / KN for x in data.F]

    def extra(g: Graph) -> None:
        g.hatch(list(data.s), ks)
        g.curve(list(data.s), ks, "result")
        # the peak and the plate's thickness named inside the field, clear of the tick values
        _note(g, 0.0, f_max, f"F_{{max}} = {num(f_max)} {WORDS('kN')}", (8.0, 1.2))
        g.point(h, 0.0, "s = h", prefer=(0.0, -1.0))
        mid = g.p(h / 2.0, f_max / 2.0)
        g.d.text(f"E = F_{{max}}·h/2 = {num(data.E)} {WORDS('J')}", (mid[0] + 4.0, mid[1] - 3.0),
                 3.5)  # fmt: skip
        g.d.text(WORDS("area"), (mid[0] + 8.0, mid[1] + 2.5), 2.5)

    return Diagram(
        AxisSpec("s", WORDS("m"), lo=0.0, hi=h, tick=nice_step(h / 6.0)),
        AxisSpec("F", WORDS("kN"), lo=0.0, hi=f_max),
        [Curve(list(data.s), ks, "construction")],
        extra=extra, least=(120.0, 80.0), prefer=(200.0, 130.0), margin=0.0,
        title=WORDS("load_title"), weight=2.0,
    )  # fmt: skip


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


def _energy_balance(data: Data) -> Diagram:
    T, E = data.cycle, data.E
    # each hole takes E at once (t = 0, T); the motor returns it at the power N over the cycle
    ts = [0.0, 0.0, T, T, 2.0 * T]
    dts = [E, 0.0, data.N * T, 0.0, data.N * T]

    def extra(g: Graph) -> None:
        # the motor's work over a cycle is the rise of ΔT (an ordinate, in J), not an area
        g.curve(ts, dts, "result")
        g.curve([0.0, 2.1 * T], [E, E], "centre")
        g.span_y(2.1 * T, 0.0, E, f"E = {num(E)} {WORDS('J')}")
        # the speeds named at the top and the foot of the drop, inside the field, as
        # "ω = ω_max", so that they cannot be read as tick values
        g.point(T, E, "ω = ω_{max}", prefer=(1.0, -1.0), height=3.5)
        _note(g, T, 0.0, "ω = ω_{min}", (3.0, -1.4), leader=False)

    return Diagram(
        AxisSpec("t", WORDS("s"), lo=0.0, hi=2.2 * T),
        AxisSpec("ΔT", WORDS("J"), lo=0.0, hi=E),
        [Curve(ts, dts, "construction")],
        extra=extra, least=(100.0, 70.0), prefer=(150.0, 110.0), margin=0.0,
        title=WORDS("balance_title"),
    )  # fmt: skip


def _panel(sol: Solution[Data]) -> tuple[Table, Table, Steps]:
    """The given data, the results and the solution step by step."""
    p, r = sol.params, sol.results
    given = Table.of_specs(PARAMS, p, style="value", title=WORDS("data"))
    results = Table.of_specs(RESULTS, r, style="value", title=WORDS("results"))
    solution = Steps(sol.construction, SOLUTION_W, only=SOLUTION, words=WORDS,
                     title=WORDS("solution"))  # fmt: skip
    return given, results, solution


def _scheme(v: Viewport) -> None:
    """The press's kinematic scheme (GOST 2.770), not to scale: the motor's pulley and the
    flywheel joined by a belt, the flywheel on the crankshaft 1 with the crank, the connecting rod
    2, the punch 3 in its guides, the plate on the die. Model units are sheet millimetres, drawn
    at the enlargement its place allows."""
    R, r1, l2 = RIM, CRANK, ROD
    O1 = Vec(0.0, 0.0)
    z = 1.0 / v.scale.k
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
