"""2013-8's drawing sheet: the load diagram with the work as its area, and the energy balance.

A3 landscape. Left, top: the force–penetration diagram F(s), the triangle from F_max at s = 0 to
zero at s = h, its area (the work of one hole, E) hatched. Left, bottom: the energy balance of the
flywheel over two cycles, ΔT(t): each hole takes E at once, the motor gives it back at the power N
over the cycle, so the flywheel's kinetic energy swings by E between ω_max and ω_min. Right: the
given data, the results beside the seed's, the solution step by step, the restored formula and the
seed's erratum.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.sheet import Drawing, Sheet, TitleBlock, fmt_number, start
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.lang import Words

from .p2013_8 import Data

if TYPE_CHECKING:
    from collections.abc import Mapping

    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_8")

#: Room for the load diagram's axes on the sheet (mm).
F_ROOM_MM = (150.0, 85.0)
PANEL_X = 262.0
PANEL_W = 146.0
KN = 1000.0


def f(x: float, digits: int = 4) -> str:
    return fmt_number(x, digits=digits)


def scales(sol: Solution) -> Mapping[str, float]:
    """The sheet's factor k_F (N/mm): the load diagram draws F in kN at the factor Axis.fit
    chooses for its room."""
    f_max = float(sol.data.F[0])
    return {"F": Axis.fit("F", WORDS("kN"), 0.0, f_max / KN, F_ROOM_MM[1]).k * KN}


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-8."""
    data: Data = sol.data
    tb = TitleBlock(
        title="Пресс: работа пробивки и маховик",
        designation="ТММ.2013-8.01",
    )
    d = start("A3", tb)
    d.text("Диаграмма нагрузки пресса и энергетический баланс маховика", (25.0, 13.0), 5.0)
    _load_diagram(d, data, sol)
    _energy_balance(d, data)
    _panel(d, sol, data)
    return [("", d.finish())]


def _load_diagram(d: Drawing, data: Data, sol: Solution) -> None:
    h = float(data.s[-1])
    f_max = float(data.F[0]) / KN
    gx = Axis.fit("s", "м", 0.0, h, F_ROOM_MM[0])
    gx = gx.with_tick(nice_step(max(gx.hi, -gx.lo) / 6.0))
    gy = Axis.fit("F", "кН", 0.0, f_max, F_ROOM_MM[1])
    top = 38.0
    at = (48.0, top + 7.0 + gy.mm(gy.hi))
    d.text(
        "1. Диаграмма нагрузки F(s) (сила пробивки по мере внедрения пуансона)", (25.0, 24.0), 3.5
    )
    g = Graph(d, gx, gy, at)
    g.factors((25.0, 31.0))
    g.hatch(list(data.s), [x / KN for x in data.F])
    g.curve(list(data.s), [x / KN for x in data.F], "result")
    g.axes()
    g.point(0.0, f_max, "F_{max}", prefer=(1.0, -1.0))
    g.point(h, 0.0, "h", prefer=(1.0, -1.0))
    mid = g.p(h / 2.0, f_max / 2.0)
    d.text(f"E = F_{{max}}·h/2 = {f(data.E)} Дж", (mid[0] + 4.0, mid[1] - 3.0), 3.5)
    d.text("(площадь под графиком)", (mid[0] + 8.0, mid[1] + 2.5), 2.5)


def _energy_balance(d: Drawing, data: Data) -> None:
    T, E = data.cycle, data.E
    gx = Axis.fit("t", "с", 0.0, 2.2 * T, 120.0)
    gy = Axis.fit("ΔT", "Дж", 0.0, E, 55.0)
    y_title = 150.0
    d.text(
        "2. Энергетический баланс: энергия маховика сверх наименьшей, ΔT = T – T_{min}",
        (25.0, y_title),
        3.5,
    )
    at = (48.0, y_title + 20.0 + gy.mm(E))
    g = Graph(d, gx, gy, at)
    g.factors((25.0, y_title + 7.0))
    # each hole takes E at once (t = 0, T); the motor returns it at the power N over the cycle
    ts = [0.0, 0.0, T, T, 2.0 * T]
    dts = [E, 0.0, data.N * T, 0.0, data.N * T]
    g.hatch([0.0, T], [0.0, data.N * T])
    g.curve(ts, dts, "result")
    g.axes()
    g.curve([0.0, 2.1 * T], [E, E], "centre")
    g.span_y(2.1 * T, 0.0, E, f"E = {f(E)} Дж")
    g.point(0.0, E, "ω_{max}", prefer=(1.0, -1.0))
    g.point(T, 0.0, "ω_{min}", prefer=(1.0, -1.0))
    y0 = at[1] + 16.0
    lines = (
        f"Пробивка (мгновенно) отнимает у маховика E, его скорость падает от ω_{{max}} до "
        f"ω_{{min}}; за цикл 1/z = {f(T)} с",
        f"двигатель мощностью N = {f(data.N)} Вт возвращает E (штриховка – работа двигателя "
        "за цикл):",
        "E = ½J(ω_{max}^2 – ω_{min}^2).",
    )
    for i, ln in enumerate(lines):
        d.text(ln, (25.0, y0 + i * 5.0), 2.5)


def _panel(d: Drawing, sol: Solution, data: Data) -> None:
    p, r = sol.params, sol.results
    x, y = PANEL_X, 10.0
    d.text("Исходные данные", (x, y + 3.5), 3.5)
    rows = [["Параметр", "Значение"]]
    for name, label, unit in (
        ("d_hole", "d", "м"),
        ("h_plate", "h", "м"),
        ("tau", "τ", "Па"),
        ("n_rpm", "n", "об/мин"),
        ("delta", "δ", ""),
        ("holes_per_s", "z", "отв./с"),
    ):
        rows.append([label, f"{f(float(p[name]))} {unit}".strip()])
    _, hh = d.table(x, y + 6.0, (40.0, 40.0), rows)
    y += 6.0 + hh + 6.0
    d.text("Результаты", (x, y + 3.5), 3.5)
    rows = [["Величина", "Значение"]]
    for name, label, unit, scale in (
        ("F_max", "F_{max}", "кН", KN),
        ("E", "E", "Дж", 1.0),
        ("N", "N", "Вт", 1.0),
        ("omega_max", "ω_{max}", "рад/с", 1.0),
        ("omega_min", "ω_{min}", "рад/с", 1.0),
        ("J", "J", "кг·м²", 1.0),
    ):
        rows.append([label, f"{f(float(r[name]) / scale)} {unit}"])
    _, hh = d.table(x, y + 6.0, (40.0, 46.0), rows)
    y += 6.0 + hh + 6.0
    y = d.text("Решение", (x, y + 3.5), 3.5).at[1] + 2.0
    steps = (
        f"F_{{max}} = π·d·h·τ = {f(r['F_max'] / KN)} кН (площадь среза π·d·h);",
        f"сила падает линейно от F_{{max}} до 0 на пути s = h, работа на одно отверстие – площадь "
        f"диаграммы: E = F_{{max}}·h/2 = {f(r['E'])} Дж;",
        f"N = E·z = {f(r['N'])} Вт;",
        f"ω_{{max}} = πn/30 = {f(r['omega_max'])} рад/с (номинальная скорость – наибольшая);",
        f"δ = (ω_{{max}} – ω_{{min}})/ω_{{ср}}, ω_{{ср}} = (ω_{{max}} + ω_{{min}})/2, отсюда "
        f"ω_{{min}} = ω_{{max}}(2 – δ)/(2 + δ) = {f(r['omega_min'])} рад/с;",
        f"½J(ω_{{max}}^2 – ω_{{min}}^2) = E, J = 2E/(ω_{{max}}^2 – ω_{{min}}^2) = "
        f"{f(r['J'])} кг·м².",
    )
    for i, step in enumerate(steps):
        y = d.paragraph(f"{i + 1}. {step}", x, y, PANEL_W, 2.5, indent=4.0) + 0.6
