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

from typing import TYPE_CHECKING

from geomcad.sheet import Sheet, TitleBlock, start
from geomcad.sheet.compose import Column, Field, Layout, Row, arrange, compose
from geomcad.sheet.drives import PressScheme
from geomcad.sheet.graph import Graph, nice_step
from geomcad.sheet.graph_notes import set_off
from geomcad.sheet.lang import Words, current
from geomcad.sheet.views import AxisSpec, Curve, Diagram, Steps, Table, Text, num

from .p2013_8 import Data
from .spec_2013_8 import PARAMS, RESULTS

if TYPE_CHECKING:
    from collections.abc import Mapping

    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_8")

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
        names = {k: WORDS(k) for k in ("flywheel", "motor", "plate", "die")}
        scheme = PressScheme(names, title=WORDS("scheme_title"), margin=6.0)
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
        # the peak and the plate's thickness named inside the field, clear of the tick values;
        # hand-set offset (mm): right of the peak and just under it, where the label keeps off
        # the axis's title above it (an earlier placement ran it into the title)
        set_off(g, 0.0, f_max, f"F_{{max}} = {num(f_max)} {WORDS('kN')}", (8.0, 1.2))
        g.point(h, 0.0, "s = h", prefer=(0.0, -1.0))
        # the work written on the hatched triangle's hypotenuse, hand-set (mm) from its middle
        # outward: inside the area the hatching would run through it
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
        set_off(g, T, 0.0, "ω = ω_{min}", (3.0, -1.4), leader=False)

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
