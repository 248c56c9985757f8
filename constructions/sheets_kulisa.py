"""kulisa-23110713's drawing sheets: what the student hands in.

- main sheet (composed by geomcad.sheet.compose): the mechanism at φ with the velocities of its
  points drawn at μ_V (V_A ⊥ OA, the yoke's V_A2 = V_A1 + V_A2A1, the roller's V_D = V_2 and
  V_C3 from its instantaneous centre P), the velocity plan, the given data and the results;
- ``graphs`` (composed): I_pr(φ) and ω1(φ) over a turn from rest (the kinetic-energy theorem as
  a curve, the solve_ivp integration as points) with their ordinates, the equation of motion,
  and the two methods side by side in a table;
- ``fbd`` (composed): the free-body diagrams of flywheel, yoke and roller with the reactions and
  the inertia loads at μ_F, and the mechanism balanced by the horizontal force F_x at the
  roller's axis; each view's extent takes in its loads' reach, measured at the layout's scale
  (the tree is rebuilt until the scales settle).

Every word comes from ``strings/<lang>/sheets_kulisa.toml``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad.dynamics.analogues import Array
from geomcad.geom import Arc, Circle, Vec
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Layout,
    Node,
    Row,
    Spacer,
    Tree,
    View,
    arrange,
    compose,
)
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.form import title_block_spacer
from geomcad.sheet.free_body import Where, draw_loads, facing, load, moment_of, short_note, small
from geomcad.sheet.graph import Graph
from geomcad.sheet.lang import Words, current
from geomcad.sheet.loads import force, ground, moment
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.reach import drawn_extent
from geomcad.sheet.scale import fmt_column, nice_factor
from geomcad.sheet.settle import settle
from geomcad.sheet.short import short_vectors
from geomcad.sheet.velocities import relative, tip, velocity
from geomcad.sheet.views import factor, num

from .p_kulisa import Data, mechanism, sweep, turns
from .spec_kulisa import PARAMS, PROBLEM, RESULTS

if TYPE_CHECKING:
    from geomcad.problem import Solution

#: The width (mm) of the main sheet's notes on the right.
PANEL_W = 118.0
SLOT_W = 0.08  # the slot's half-width and the yoke's bar height, in units of OA
SHEETS = 3


WORDS = Words(__package__, "sheets_kulisa")


def _tb(key: str, no: int, scale: str = "") -> TitleBlock:
    return TitleBlock(
        title=WORDS(key),
        designation=WORDS("designation", no=no),
        sheet_no=no,
        sheets=SHEETS,
        scale=scale,
        lang=current(),
    )


def _u(key: str) -> str:
    """A unit's symbol in the language being drawn."""
    return WORDS(f"u_{key}")


#: The largest reaction on the free-body sheet gets at most this many mm.
FORCE_ROOM_MM = 45.0
#: The largest velocity on the scheme gets at most this many mm.
VELOCITY_ROOM_MM = 36.0


def scales(sol: Solution[Data]) -> dict[str, float]:
    """The sheets' μ_F (the free-body diagrams) and μ_V (the velocities on the scheme)."""
    data = sol.data
    res = sol.results
    loads = [
        ld.force.norm
        for r in (data.dynamic, data.static)
        for lds in r.loads.values()
        for ld in lds
        if ld.force is not None
    ]
    biggest = max(res["N_A"], res["X_O"], res["Y_O"], res["F_x"], *loads)
    w_oa = data.omega * float(sol.params["OA"])
    return {
        "F": nice_factor(biggest, FORCE_ROOM_MM, "F").k,
        "v": nice_factor(w_oa, VELOCITY_ROOM_MM, "v").k,
    }


def sheets(sol: Solution[Data]) -> list[tuple[str, Sheet]]:
    """The main sheet and the sheets ``graphs`` and ``fbd``."""
    return [("", _main(sol)), ("graphs", _graphs(sol)), ("fbd", _fbd(sol))]


# -- geometry shared by the views --------------------------------------------------------------


def _p(sol: Solution[Data]) -> dict[str, float]:
    return {k: float(v) for k, v in sol.params.items()}


def _extent(sol: Solution[Data], data: Data) -> tuple[float, float, float, float]:
    """The mechanism's model box at φ: flywheel, slot, yoke bar, roller and its base."""
    p = _p(sol)
    R1, OA, R3, r3 = p["R1"], p["OA"], p["R3"], p["r3"]
    c3 = data.C3
    x0 = min(-R1, data.yoke.pin.point().x - 0.3 * OA)
    x1 = c3.x + 1.8 * R3
    y0 = min(-R1, -r3 - R3 - 0.1 * R3)
    y1 = max(R1, OA * (1.0 + 2.0 * SLOT_W))
    return x0, y0, x1, y1


def _flywheel(v: Viewport, sol: Solution[Data], data: Data, pivot: bool = True) -> None:
    p = _p(sol)
    A = data.yoke.pin.point()
    v.circle((0.0, 0.0), p["R1"], "link")
    v.seg((0.0, 0.0), A, "link")
    if pivot:
        v.pivot((0.0, 0.0))
    else:
        v.joint((0.0, 0.0))
    v.joint(A)


def bar_level(p: dict[str, float]) -> float:
    """The lower edge (model y) of the yoke's bar: above the roller's rim, which rises R3 − r3
    over the contact line y = 0, by one bar height, so that the bar runs clear of the flywheel's
    pivot O and of the roller's rim; a foot comes down from it to the contact D."""
    return p["R3"] - p["r3"] + SLOT_W * p["OA"]


def _yoke(v: Viewport, sol: Solution[Data], data: Data, guides: bool = True) -> None:
    """The yoke: a frame around the vertical slot through A, a bar from the frame to above the
    roller at bar_level, and a foot down to D = (x_C3, 0), where it bears on the roller's hub."""
    p = _p(sol)
    OA = p["OA"]
    A = data.yoke.pin.point()
    w = SLOT_W * OA
    top, bot = OA + 2.0 * w, -OA - 2.0 * w
    xa = A.x
    # the slot (inner) and the frame (outer)
    v.polyline([(xa - w, bot + w), (xa + w, bot + w), (xa + w, top - w), (xa - w, top - w)], "link",
               closed=True)  # fmt: skip
    v.polyline([(xa - 2 * w, bot), (xa + 2 * w, bot), (xa + 2 * w, top), (xa - 2 * w, top)], "link",
               closed=True)  # fmt: skip
    # the bar and its foot: one outline from the frame's right side round to the frame again
    y0 = bar_level(p)
    xd = data.C3.x
    v.polyline(
        [(xa + 2 * w, y0), (xd - w / 2, y0), (xd - w / 2, 0.0), (xd + w / 2, 0.0),
         (xd + w / 2, y0 + w), (xa + 2 * w, y0 + w)],
        "link",
    )  # fmt: skip
    if guides:
        # the bar's two guides over it, at a third and two thirds of its free length (a scheme:
        # the problem gives no guide positions)
        for gx in (0.35, 0.7):
            xg = xa + 2 * w + gx * (xd - xa - 2 * w)
            half = 0.08 * (xd - xa)
            ground(v, (xg - half, y0 + 1.5 * w), (xg + half, y0 + 1.5 * w), (0.0, 1.0))


def _roller(
    v: Viewport, sol: Solution[Data], data: Data, base: bool = True, foot: bool = True
) -> None:
    """The roller: its rim R3 (broken where the yoke's foot passes in front of it), its hub r3,
    its axis C3, and the base it rolls on."""
    p = _p(sol)
    R3, r3 = p["R3"], p["r3"]
    c3 = data.C3
    w = SLOT_W * p["OA"]
    if foot and w / 2.0 < R3:
        gap = math.asin(min(1.0, (w / 2.0) / R3)) + v.scale.model(0.6) / R3
        v.arc(Arc(Circle(c3, R3), math.pi / 2.0 + gap, math.pi / 2.0 - gap), "link")
    else:
        v.circle(c3, R3, "link")
    if r3 > 0.0:
        v.circle(c3, r3, "link")
    v.joint(c3)
    if base:
        yb = -r3 - R3
        ground(v, (c3.x - 1.6 * R3, yb), (c3.x + 1.6 * R3, yb), (0.0, -1.0))


def _numbers(v: Viewport, sol: Solution[Data], data: Data) -> None:
    """The links' numbers (GOST 2.770): flywheel 1, yoke 2, roller 3."""
    p = _p(sol)
    A = data.yoke.pin.point()
    w = SLOT_W * p["OA"]
    c3 = data.C3
    # each number at its link's outline where no other link runs: the flywheel's rim low right,
    # the yoke's frame low left, the roller's rim low right
    v.label(Vec.polar(p["R1"], math.radians(-60.0)), "1", prefer=(1.0, -1.0), clear=1.5)
    v.label((A.x - 2.0 * w, -0.8 * p["OA"]), "2", prefer=(-1.0, 0.0), clear=1.5)
    v.label(c3 + Vec.polar(p["R3"], math.radians(-40.0)), "3", prefer=(1.0, -1.0),
            clear=1.5)  # fmt: skip


# -- the main sheet ----------------------------------------------------------------------------


def _main(sol: Solution[Data]) -> Sheet:
    field = Field.of_format("A3")
    tree, views = _main_tree(sol, short=False)
    lay = arrange(tree, field)
    if _short(sol, lay[views["plan"]].scale):
        # the note on plan vectors drawn as points, and the layout again
        tree, views = _main_tree(sol, short=True)
        lay = arrange(tree, field)
    k = lay[views["scheme"]].scale
    assert k is not None
    d = start("A3", _tb("tb_main", 1, k.ratio_text()))
    compose(d, tree, layout=lay)
    return d.finish()


def _short(sol: Solution[Data], k: Scale | None) -> bool:
    """Whether a vector of the velocity plan at its scale ``k``, or a velocity on the scheme at
    its μ_V, comes out shorter than two arrowheads (drawn as its lettered end point)."""
    assert k is not None
    if short_vectors(sol.data.vplan, k, zero=True):
        return True
    va, v2, vc, _ = _plan_values(sol, sol.data)
    kv = sol.scales["v"]
    return any(0.0 < x.norm / kv < SHORT_MM for x in (va, v2, vc, v2 - va))


def _main_tree(sol: Solution[Data], short: bool) -> tuple[Node, dict[str, View]]:
    """The scheme with its velocities and the tables beside it; the velocity plan, its order of
    construction and the notes under them, the title block's corner kept free. ``short``: a
    note says that the plan's vectors shorter than two arrowheads are drawn as points."""
    data = sol.data
    # the model box holds the velocities drawn at μ_V (at most VELOCITY_ROOM_MM long)
    scheme = Figure(_extent(sol, data), lambda v: _scheme(v, sol, data),
                    title=WORDS("head_main"), margin=3.0, weight=3.0)  # fmt: skip
    tree, plan = _main_layout(sol, data, scheme, short)
    return tree, {"scheme": scheme, "plan": plan}


def _scheme(v: Viewport, sol: Solution[Data], data: Data) -> None:
    _flywheel(v, sol, data)
    _yoke(v, sol, data)
    _roller(v, sol, data)
    _numbers(v, sol, data)
    _velocities(v, sol, data)


def _main_layout(sol: Solution[Data], data: Data, scheme: View, short: bool) -> tuple[Node, View]:
    p = _p(sol)
    kv = Scale(sol.scales["v"], "v")
    state_line = WORDS("state", phi=num(p["phi_deg"]), omega=num(data.omega), mu_v=factor(kv))
    state = V.Text(lines=[state_line], height=3.5)
    plan, order = _plan(sol, data)
    tables, notes = _panel_main(sol, data, short)
    # the title block's box at the bottom right (with its margin): the notes go above it
    field = Field.of_format("A3")
    tb = field.obstacles[0]
    form = Spacer((field.box[2] - tb[0], field.box[3] - tb[1]))
    top = Row(Column(state, scheme), tables)
    return Column(top, Row(plan, order, Column(notes, form), gap=PLAN_GAP)), plan


def _plan_values(sol: Solution[Data], data: Data) -> tuple[Vec, Vec, Vec, float]:
    """V_A, V_2 (= V_A2 = V_D), V_C3 and ω3 read off the recorded velocity plan."""
    vp = data.vplan
    return vp.vector("a1"), vp.vector("a2"), vp.vector("c3"), float(sol.construction["ω3"])


def _velocities(v: Viewport, sol: Solution[Data], data: Data) -> None:
    """V_A ⊥ OA, V_A2 = V_A1 + V_A2A1 along x, V_D = V_2 at the contact, V_C3 from P; each from
    its point at μ_V, V_D along the contact line below the yoke's bar."""
    p = _p(sol)
    w = data.omega
    kv = sol.scales["v"]
    A = data.yoke.pin.point()
    c3 = data.C3
    D = Vec(c3.x, 0.0)
    P = Vec(c3.x, -p["r3"] - p["R3"])
    va, v2, vc, w3 = _plan_values(sol, data)
    velocity(v, A, va, kv, "V_A")
    velocity(v, A, v2, kv, "V_{A2}")
    # V_D named under its tip: the yoke's bar is over it
    velocity(v, D, v2, kv, "V_D = V_2", prefer=(0.0, -1.0))
    velocity(v, c3, vc, kv, "V_{C3}")
    # V_A2A1 along the slot: from V_A's tip to V_A2's tip
    relative(v, A, va, v2, kv, "V_{A2A1}")
    # the roller's velocities grow linearly from its instantaneous centre P
    if v2.norm > 0.0:
        v.seg(P, tip(v, D, v2, kv), "construction")
    v.dot(P)
    v.label(P, "P_3", 2.5, prefer=(1.0, -1.0))
    v.dot(D)
    v.label(D, "D", 2.5, prefer=(1.0, -1.0))
    v.label(A, "A", prefer=(-1.0, 1.0))
    v.label((0.0, 0.0), "O", prefer=(-1.0, -1.0))
    v.label(c3, "C_3", prefer=(1.0, -1.0))
    v.dot(data.C2)
    v.label(data.C2, "C_2", prefer=(0.0, -1.0))
    # ω1 and ω3 as curved arrows, the angle φ: hand-set where the links leave room, ω1 on a
    # 9 mm arc from 200° (left of O, clear of the crank and the yoke's bar), ω3 inside the
    # roller's rim from 110° (clear of the yoke's foot at the top)
    moment(v, (0.0, 0.0), w, 9.0, "ω_1", role="result", start=math.radians(200.0), height=2.5)
    moment(v, c3, w3, 0.55 * v.mm(p["R3"]), "ω_3", role="result", start=math.radians(110.0),
           height=2.5)  # fmt: skip
    v.seg((0.0, 0.0), (0.6 * p["R1"], 0.0), "centre")
    # the φ arc under the yoke's bar (2.5 mm under it) and outside ω1's arrow (at least 12 mm)
    r_phi = max(12.0, min(0.45 * v.mm(p["OA"]), v.mm(bar_level(p)) - 2.5))
    v.dim_angle((0.0, 0.0), (p["OA"], 0.0), A, "φ", r_mm=r_phi, height=2.5)


def _plan(sol: Solution[Data], data: Data) -> tuple[View, View]:
    """The velocity plan recorded by the problem (pa_1 = V_A1 ⊥ OA, a_1a_2 ∥ the slot, pa_2 ∥
    the guide, c_3 on pd by the roller's instantaneous centre) at the layout's μ_V, and its
    order of construction written from the plan's steps."""
    plan = V.PlanView(data.vplan, margin=5.0, min_mm=SHORT_MM)
    order = V.Steps(sol.construction, ORDER_W, only=data.plan_steps, words=WORDS)
    return plan, order


#: The gap (mm) between the velocity plan, its order of construction and the notes.
PLAN_GAP = 6.0

#: The width (mm) of the velocity plan's order of construction.
ORDER_W = 110.0


def _step_lines(sol: Solution[Data], *names: str) -> list[str]:
    """The texts of recorded steps (their kinds' templates in the language drawn)."""
    return [V.step_text(sol.construction.step(n), WORDS) for n in names]


def _notes(items: list[str], width: float) -> View:
    return V.Text(paragraphs=items, width=width)


def _results(sol: Solution[Data], names: tuple[str, ...], **kw: Any) -> V.Table:
    """The results ``names`` as a table "quantity | value"."""
    by = {s.name: s for s in RESULTS}
    labels = {"I_pr": WORDS("I_pr"), "dI_pr": WORDS("dI_pr"), "omega_ode": WORDS("omega_ode")}
    return V.Table.of_specs([by[n] for n in names], sol.results, labels=labels, style="value", **kw)


def _given(sol: Solution[Data]) -> View:
    # each cell says what it holds ("m_1 = 80 кг") under the table's title: a heading row
    # would only repeat one word over both columns
    return V.Table.of_specs(PARAMS, sol.params, style="equation", pairs=2, header=False,
                            fill=PANEL_W, title=WORDS("given"))  # fmt: skip


def _panel_main(sol: Solution[Data], data: Data, short: bool) -> tuple[Node, View]:
    """The tables of the given data, the velocities and the results, and the notes (with
    ``short``: on the plan's vectors drawn as points)."""
    va, v2, vc, w3 = _plan_values(sol, data)
    qty, val = WORDS("quantity"), WORDS("value")
    ms = _u("m_s")
    rows = [
        [qty, val, qty, val],
        ["V_A", f"{num(va.norm, 4)} {ms}", "V_2 = V_D", f"{num(v2.norm, 4)} {ms}"],
        ["V_{C3}", f"{num(vc.norm, 4)} {ms}", "ω_3", f"{num(abs(w3), 4)} {_u('rad_s')}"],
    ]
    vel = V.Table(rows, fill=PANEL_W, title=WORDS("velocities_head"))
    res = _results(
        sol, ("I_pr_A", "I_pr_B", "I_pr", "dI_pr", "omega1", "eps1", "t_reach", "omega_ode"),
        fill=PANEL_W, title=WORDS("results_head"),
    )  # fmt: skip
    notes = [WORDS("note_1"), WORDS("note_2")]
    if short:
        notes.append(WORDS("short_plan", mm=num(SHORT_MM)))
    return Column(_given(sol), vel, res), _notes(notes, NOTES_MAIN_W)


#: The width (mm) of the main sheet's notes (above the title block).
NOTES_MAIN_W = 180.0


# -- graphs --------------------------------------------------------------------------------------


def _graphs(sol: Solution[Data]) -> Sheet:
    """I_pr(φ) above ω1(φ) on the left (their ordinates at the tabulated positions), the equation
    of motion and a table of both every 15° on the right."""
    data = sol.data
    p = _p(sol)
    sw = sweep(data)
    phis_deg = np.degrees(sw["phi"])
    tick = 30.0 * turns(data)
    ode = _turn_ode(data)
    phi_deg = p["phi_deg"]
    i_pr, w1 = float(sol.results["I_pr"]), data.omega

    def extra_i(g: Graph) -> None:
        _ordinates(g, ode[0], data.model.J_pr(np.asarray(ode[0])))
        g.curve([phi_deg, phi_deg], [0.0, i_pr], "centre")
        g.point(phi_deg, i_pr, f"{WORDS('I_pr')} = {num(i_pr)}", prefer=(1.0, -1.0))

    def extra_w(g: Graph) -> None:
        _ordinates(g, ode[0], ode[1])
        for a, wv in zip(ode[0], ode[1], strict=True):
            g.point(float(np.degrees(a)), float(wv))
        g.curve([phi_deg, phi_deg], [0.0, w1], "centre")
        g.point(phi_deg, w1, f"ω_1 = {num(w1)}", prefer=(1.0, -1.0))

    d1 = V.Diagram(
        V.AxisSpec("φ", "°", tick=tick),
        V.AxisSpec(WORDS("I_pr"), _u("kgm2"), name="I"),
        [V.Curve(list(phis_deg), list(sw["I_pr"]))],
        extra=extra_i,
        title=WORDS("graph_1"),
        least=(150.0, 70.0),
        prefer=(230.0, 110.0),
    )
    d2 = V.Diagram(
        V.AxisSpec("φ", "°", tick=tick),
        V.AxisSpec("ω_1", _u("rad_s"), name="ω"),
        [V.Curve(list(phis_deg), list(sw["omega"]))],
        extra=extra_w,
        title=WORDS("graph_2"),
        least=(150.0, 70.0),
        prefer=(230.0, 110.0),
    )
    # both diagrams as wide (the lower one clear of the title block's corner): one μ_φ, their φ
    # ticks one above the other
    left = Column(Row(d1, Spacer((30.0, 10.0))), Row(d2, Spacer((30.0, 10.0))))  # 30 mm free
    tree = Row(left, _panel_graphs(sol, data, ode), weights=(0.6, 0.4))
    d = start("A3", _tb("tb_graphs", 2))
    compose(d, tree)
    return d.finish()


def _ordinates(g: Graph, phis: list[float], vals: Any) -> None:
    """The diagram's ordinates at the tabulated positions (thin lines from the φ axis)."""
    for a, val in zip(phis, vals, strict=True):
        if float(val) > 0.0:
            x = math.degrees(float(a))
            g.curve([x, x], [0.0, float(val)], "construction")


def _turn_ode(data: Data, n: int = 25) -> tuple[list[float], list[float]]:
    """ω1 by solve_ivp at n positions over the diagram's turns, on one motion from rest at φ0."""
    from geomcad.dynamics import reach

    phis = data.phi0 + np.linspace(0.0, 2.0 * math.pi * turns(data), n)[1:]
    arr = reach(data.model, data.phi0, float(phis[-1]))
    # the dense solution gives φ(t); invert it at the wanted φ by the monotone samples
    ts = np.linspace(0.0, arr.t, 4001)
    y = arr.trajectory.sol(ts)
    omegas = list(np.interp(phis, y[0], y[1]))
    return [data.phi0, *phis], [0.0, *omegas]


def _panel_graphs(sol: Solution[Data], data: Data, ode: tuple[list[float], list[float]]) -> Node:
    r = sol.results
    p = _p(sol)
    a_, b_ = float(r["I_pr_A"]), float(r["I_pr_B"])
    eq = _notes(
        [
            WORDS("eq_1"),
            WORDS("eq_2", a=num(a_, 4), b=num(b_, 4), half=num(b_ / 2.0, 4), M=num(p["M"], 4)),
            *_step_lines(sol, "ω1", "ε1"),
            WORDS("graph_2_note"),
        ],
        GRAPHS_PANEL_W,
    )
    eq.title = WORDS("eq_head")
    # I_pr and ω1 at the diagrams' points: the energy theorem beside the integration
    rows = [["φ, °", f"{WORDS('I_pr')}, {_u('kgm2')}", f"ω_1, {_u('rad_s')}",
             f"{WORDS('omega_ode')}, {_u('rad_s')}"]]  # fmt: skip
    phis = np.asarray(ode[0])
    i_pr = data.model.J_pr(phis)
    from geomcad.dynamics import omega_curve

    om = omega_curve(data.model, data.phi0, phis)
    # each column of one quantity with one count of decimals
    cols = [fmt_column([float(x) for x in xs], digits=dg)
            for xs, dg in ((np.degrees(phis), 5), (i_pr, 4), (om, 4), (ode[1], 4))]  # fmt: skip
    rows += [list(r) for r in zip(*cols, strict=True)]
    table = V.Table(rows, widths=(GRAPHS_PANEL_W / 4.0,) * 4, title=WORDS("table_head"))
    return Column(eq, table, title_block_spacer())


#: The width (mm) of the graphs sheet's right panel.
GRAPHS_PANEL_W = 146.0


# -- free-body diagrams --------------------------------------------------------------------------


Box = tuple[float, float, float, float]


def _fbd_boxes(sol: Solution[Data], data: Data) -> dict[str, Box]:
    """The model boxes of the four bodies: flywheel, yoke, roller, the whole mechanism."""
    p = _p(sol)
    R1, OA, R3 = p["R1"], p["OA"], p["R3"]
    A, c3 = data.yoke.pin.point(), data.C3
    w = SLOT_W * OA
    return {
        "1": (-R1, -R1, R1, R1),
        "2": (A.x - 2.0 * w, -OA - 2.0 * w, c3.x + w, OA + 2.0 * w),
        "3": (c3.x - R3, c3.y - R3, c3.x + R3, c3.y + R3),
        "all": _extent(sol, data),
    }


def _fbd_draw(sol: Solution[Data], data: Data) -> dict[str, Callable[[Viewport], None]]:
    """How each of the four views is drawn through the viewport the layout gives it."""
    p = _p(sol)
    k_F = sol.scales["F"]
    A = data.yoke.pin.point()
    c3 = data.C3
    D = Vec(c3.x, 0.0)
    P = Vec(c3.x, -p["r3"] - p["R3"])
    R = data.dynamic

    # a) the flywheel
    def flywheel(v1: Viewport) -> None:
        _flywheel(v1, sol, data, pivot=False)
        v1.label(A, "A", prefer=(-1.0, 1.0))
        v1.label((0.0, 0.0), "O", prefer=(-1.0, -1.0))
        # the two moments about O on radii far apart, the driving one's label in the inertia
        # moment's opening at the bottom
        draw_loads(v1, R, k_F, "1", {
            "M": Where("M", radius=7.0, start_deg=facing(moment_of(R, "1", "M"), 270.0)),
            "M_Phi1": Where(WORDS("M_Phi1"), radius=19.0,
                            start_deg=facing(moment_of(R, "1", "M_Phi1"), 270.0, True)),
            "R_{01}": Where("X_O", prefer=(0.0, 1.0)),
            "N_A": Where("N_A", prefer=(0.0, 1.0)),
        })  # fmt: skip

    # b) the yoke: the loads along the contact line y = 0 are drawn in the free space under the
    # bar (Ф_2 at C_2) and beyond the foot (R_32 at D), not along the bar's edge
    def yoke(v2: Viewport) -> None:
        _yoke(v2, sol, data, guides=False)
        v2.dot(data.C2)
        v2.label(data.C2, "C_2", prefer=(0.0, 1.0))
        v2.dot(D)
        v2.label(D, "D", prefer=(1.0, -1.0))
        v2.label(A, "A", prefer=(-1.0, 1.0))
        r32 = load(R, "2", "R_{32}")
        draw_loads(v2, R, k_F, "2", {
            # the pin's push arrives at A through the frame's outer side, clear of the bar
            "N_A": Where("N_A", arrive=True, prefer=(0.0, 1.0)),
            "Phi_2": Where(WORDS("Phi2"), prefer=(0.0, -1.0)),
            # pointing away from the bar: leaving D; pointing at it: arriving from beyond the foot
            "R_{32}": Where("R_{32}", arrive=r32 is not None and r32.x < 0.0, prefer=(0.0, -1.0)),
            # the guide's couple drawn in the free space under the bar, right of the frame
            "M_{02}": Where("M_{02}", at=Vec(data.C2.x, -0.45 * p["OA"]), radius=5.0,
                            start_deg=60.0),
        })  # fmt: skip

    # c) the roller, at its own (larger) scale: it is small beside the flywheel
    def roller(v3: Viewport) -> None:
        _roller(v3, sol, data, base=False, foot=False)
        for q, name, pref in ((D, "D", (-1.0, 1.0)), (P, "P", (-1.0, -1.0))):
            v3.dot(q)
            v3.label(q, name, prefer=pref)
        v3.label(c3, "C_3", prefer=(-1.0, -1.0))
        rim_mm, hub_mm = v3.mm(p["R3"]), v3.mm(p["r3"])
        # M_Φ3's arc 8 mm inside the rim where 6 mm clear of the hub, else 4 mm outside it
        r_m3 = rim_mm - 8.0 if rim_mm - 8.0 > hub_mm + 6.0 else rim_mm + 4.0
        gap = v3.scale.model(3.0)
        draw_loads(v3, R, k_F, "3", {
            "R_{32}": Where("R_{23}", prefer=(0.0, 1.0)),
            "R_{03}": Where("R_{03}", prefer=(1.0, -1.0), short_at=P - Vec(0.0, gap)),
            "Phi_3": Where(WORDS("Phi3"), prefer=(-1.0, 1.0)),
            # inside the rim, outside the hub where there is room between them
            "M_Phi3": Where(WORDS("M_Phi3"), radius=r_m3, start_deg=100.0),
        }, centre=c3)  # fmt: skip

    # d) the mechanism balanced by F_x at the roller's axis (no inertia loads)
    def balanced(v4: Viewport) -> None:
        _flywheel(v4, sol, data)
        _yoke(v4, sol, data)
        _roller(v4, sol, data)
        _numbers(v4, sol, data)
        v4.label((0.0, 0.0), "O", prefer=(-1.0, -1.0))
        v4.label(c3, "C_3", prefer=(0.0, -1.0))
        moment(v4, (0.0, 0.0), p["M"], 6.0, f"M = {num(abs(p['M']))} {_u('Nm')}", role="result",
               start=math.radians(160.0), height=2.5)  # fmt: skip
        fx = data.static.force("F_x")
        force(v4, c3, fx, k_F, f"F_x = {num(fx.norm)} {_u('N')}", role="result", height=2.5)

    return {"1": flywheel, "2": yoke, "3": roller, "all": balanced}


def _fbd_tree(sol: Solution[Data], k: Scale, k3: Scale) -> tuple[Node, dict[str, View]]:
    """The four views (a, b, d at one scale, the roller c at its own), their loads' reach
    measured at the scales k and k3, the heading and the panel; the layout chooses between the
    panel beside the top row and beside the whole."""
    data = sol.data
    boxes = _fbd_boxes(sol, data)
    draw = _fbd_draw(sol, data)
    views: dict[str, View] = {}
    # the loads' reach is measured, so the margins only keep the views apart
    for name, key in (("1", "view_1"), ("2", "view_2"), ("all", "view_4")):
        views[name] = Figure(drawn_extent(boxes[name], draw[name], k), draw[name], title=WORDS(key),
                             group="fbd", show_scale=False, margin=0.5, weight=3.0)  # fmt: skip
    views["3"] = Figure(drawn_extent(boxes["3"], draw["3"], k3), draw["3"], margin=0.5,
                        title=WORDS("view_3", ratio=k3.ratio_text()), show_scale=False)  # fmt: skip
    head = V.Text(lines=[WORDS("head_fbd")], height=5.0)
    state = Column(
        V.Text(lines=[WORDS("state_fbd", mu_l=factor(k), ratio=k.ratio_text(), eps=num(data.eps))],
               height=3.5),
        V.Text(paragraph=f"{short_note(sol.scales['F'], data.dynamic)}.", width=NOTES_W),
    )  # fmt: skip
    tables, notes = _panel_fbd(sol, data, NOTES_W)
    a, b, c, dd = views["1"], views["2"], views["3"], views["all"]
    # a and b at one scale: the row split as their model widths
    ab = Row(a, b, weights=[_width(v) for v in (a, b)])
    # the title block's height under the field's bottom (a box may lie over it)
    field = Field.of_format("A3")
    tb = Spacer((10.0, field.box[3] - field.obstacles[0][1]))
    # the tables beside the state line and the top row; the roller and the notes under them on
    # the left, the balanced mechanism above the title block
    tree = Column(
        head,
        Row(Column(state, ab), tables),
        Row(Column(c, notes), Column(dd, tb)),
    )
    return tree, views


def _width(v: View) -> float:
    box = v.extent()
    assert box is not None
    return box[2] - box[0]


def _fbd_scales(sol: Solution[Data]) -> tuple[Tree, dict[str, View], Layout]:
    """The tree rebuilt until its scales settle: the loads' arrows are drawn at μ_F, so the
    room a view needs depends on its length scale. It starts from 1:10 for the bodies and
    1:2.5 for the roller."""

    def got(lay: Layout, views: dict[str, View]) -> tuple[Scale, Scale]:
        k, k3 = lay[views["all"]].scale, lay[views["3"]].scale
        assert k is not None and k3 is not None
        return k, k3

    s = settle(
        lambda ks: _fbd_tree(sol, *ks),
        got,
        (Scale(0.01, "l"), Scale(0.0025, "l")),
        Field.of_format("A3"),
        rounds=FBD_ROUNDS,
        same=lambda a, b: (a[0].k, a[1].k) == (b[0].k, b[1].k),
    )
    return s.tree, s.parts, s.layout


#: Builds of the free-body sheet at most (its scales settle within them).
FBD_ROUNDS = 5


def _fbd(sol: Solution[Data]) -> Sheet:
    tree, views, lay = _fbd_scales(sol)
    k = lay[views["all"]].scale
    assert k is not None
    d = start("A3", _tb("tb_fbd", 3, k.ratio_text()))
    compose(d, tree, layout=lay)
    return d.finish()


#: The width (mm) of the free-body sheet's notes.
NOTES_W = 180.0

#: The names of the inertia loads on the free-body sheet's table, by the model's keys.
_INERTIA = {"M_Phi1": "M_Phi1", "Phi_2": "Phi2", "Phi_3": "Phi3", "M_Phi3": "M_Phi3"}


def _panel_fbd(sol: Solution[Data], data: Data, width: float = 140.0) -> tuple[Node, View]:
    """The tables of the loads, and the notes (``width`` mm wide)."""
    reactions = _results(sol, ("N_A", "X_O", "Y_O", "F_x"), widths=(50.0, 90.0), row_h=5.5,
                         title=WORDS("fbd_table_head"))  # fmt: skip
    R = data.dynamic
    n, nm = _u("N"), _u("Nm")
    vals = []
    for body in ("1", "2", "3"):
        for ld in R.loads[body]:
            if ld.kind == "inertia":
                val = ld.force.norm if ld.force is not None else abs(ld.moment)
                label = WORDS(_INERTIA[ld.name]) if ld.name in _INERTIA else ld.name
                vals.append((label, f"{num(val, 4)} {n if ld.force is not None else nm}"))
    vals.append(("R_{32} = R_{23}", f"{num(abs(R.magnitudes['R_{32}']), 4)} {n}"))
    vals.append(("R_{03}", f"{num(abs(R.magnitudes['R_{03}']), 4)} {n}"))
    vals.append(("M_{02}", f"{num(abs(R.moment('M_{02}')), 4)} {nm}"))
    # read along the rows: each body's loads side by side, in the order they act
    others = V.Table.of_entries(vals, (WORDS("load"), WORDS("value")), pairs=2, across=True,
                                widths=(28.0, 42.0, 28.0, 42.0), row_h=5.5,
                                title=WORDS("other_loads"))  # fmt: skip
    mb = R.moment("M_b")
    lines = (
        WORDS("fbd_1"),
        WORDS("fbd_2"),
        WORDS("fbd_3", mb=small(mb, float(sol.params["M"]), nm, WORDS("M_bal"))),
        " ".join(_step_lines(sol, "F_x", "|F_x| (kinetostatics)")),
    )
    notes = V.Text(paragraphs=[f"– {ln}" for ln in lines], width=width, indent=3.0)
    return Column(reactions, others), notes


# -- the animation ------------------------------------------------------------------------------


#: The slot's half length in units of OA (the animation's yoke).
SLOT_HALF = 1.25


def motion(solution: Solution[Data], frames: int) -> Frames:
    """The mechanism over one turn of the flywheel from the sheets' position φ, from the model's
    own motions (the yoke on its pin, the roller driven by the yoke), and the velocity plan at
    the constant ω1 the flywheel has at φ: pa (the pin), pc2 (the yoke), pc3 (the roller's axis);
    a c2 is the slip of the pin along the slot."""
    data = solution.data
    p = {k: float(v) for k, v in solution.params.items()}
    _model, yoke, roller = mechanism(
        p["m1"], p["R1"], p["OA"], p["m2"], p["m3"], p["R3"], p["r3"], p["rho3"], p["M"], data.lay
    )
    phi = turn(frames, data.phi)
    y, rl = yoke(phi), roller(phi)
    OA, R3, r3 = p["OA"], p["R3"], p["r3"]

    def pts(x: Array, yy: Array) -> np.ndarray:
        return np.column_stack([np.broadcast_to(x, phi.shape), np.broadcast_to(yy, phi.shape)])

    zero = np.zeros_like(phi)
    rim = rl.theta + math.pi / 2.0  # a mark on the roller's rim, upwards at the start
    points = {
        "O": pts(zero, zero),
        "A": pts(y.pin.x, y.pin.y),
        "S1": pts(y.pin.x, zero + SLOT_HALF * OA),
        "S2": pts(y.pin.x, zero - SLOT_HALF * OA),
        "Y": pts(y.pin.x, zero),
        "C2": pts(y.body.x, zero),
        "D": pts(rl.x, zero),
        "C3": pts(rl.x, rl.y),
        "K": pts(rl.x + R3 * np.cos(rim), rl.y + R3 * np.sin(rim)),
    }
    w = data.omega
    base = -r3 - R3
    xs = np.concatenate([points["C3"][:, 0] - R3, points["C3"][:, 0] + R3])
    return Frames(
        title=WORDS("animation", id=PROBLEM.id),
        phi=phi,
        points=points,
        links=(("O", "A"), ("S1", "S2"), ("Y", "C2", "D"), ("C3", "K")),
        joints=("O", "A", "C3"),
        labelled=("O", "A", "C2", "C3", "K"),
        fixed=("O",),
        traced=("A", "K"),
        guides=(((float(xs.min()), base), (float(xs.max()), base)),),
        discs={"O": (p["R1"],), "C3": (R3, r3) if r3 > 0.0 else (R3,)},
        velocities={
            "A": pts(y.pin.vx * w, y.pin.vy * w),
            "C2": pts(y.body.vx * w, y.body.vy * w),
            "C3": pts(rl.vx * w, rl.vy * w),
        },
        plan_edges=(("A", "C2"),),
        omega1=w,
    )
