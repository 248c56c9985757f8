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
from geomcad.problem import ResultSpec
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Extent,
    Field,
    Figure,
    Node,
    Row,
    Spacer,
    Tree,
    View,
    arrange,
    compose,
)
from geomcad.sheet.form import title_block_spacer
from geomcad.sheet.free_body import Where, draw_loads, facing, load, moment_of, short_note, small
from geomcad.sheet.graph import Graph, nice_step
from geomcad.sheet.lang import Words, current
from geomcad.sheet.loads import damper, ground, moment, spring
from geomcad.sheet.scale import fmt_column, nice_factor
from geomcad.sheet.settle import settle
from geomcad.sheet.views import num

from .p2013_9 import ROD, Data
from .spec_2013_9 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_9")

#: The width (mm) of the right-hand panel's text and tables.
PANEL_W = 146.0
DISC = 1.3  # the disc's drawn radius, in units of r
#: Force arrows on the sheet: the largest force gets at most this many mm.
FORCE_ROOM_MM = 40.0
#: The notes under the views: their width and cap height (mm).
NOTES_W = 200.0
NOTES_H = 3.0
#: Room (mm) past the longest load's head for its name.
LABEL_MM = 6.0
#: A load drawn beyond its body keeps this gap (mm) from the body's outline.
GAP_MM = 3.0


def scales(sol: Solution[Data]) -> dict[str, float]:
    """The sheet's μ_F (N/mm): the largest force at most FORCE_ROOM_MM long."""
    res = sol.results
    biggest = max(res["N_pin"], res["F_spring"], res["F_damper"], res["F_inertia_rod"])
    return {"F": nice_factor(biggest, FORCE_ROOM_MM, "F").k if biggest > 0.0 else 1.0}


def sheets(sol: Solution[Data]) -> list[tuple[str, Sheet]]:
    """The main sheet (the parts and their loads) and the ``motion`` sheet."""
    return [("", _main(sol)), ("motion", _motion(sol))]


def _title(sol: Solution[Data], key: str, no: int, scale: str = "") -> TitleBlock:
    return TitleBlock(
        title=WORDS(key),
        designation=WORDS("designation", no=no),
        sheet_no=no,
        sheets=2,
        scale=scale,
        lang=current(),
    )


def _unit(u: str) -> str:
    """A unit's symbol in the language being drawn."""
    return WORDS(f"u_{u}")


def _main(sol: Solution[Data]) -> Sheet:
    tree, _views = _main_tree(sol)
    lay = arrange(tree, Field.of_format("A3"))
    k = lay.scale("l")
    d = start("A3", _title(sol, "tb_main", 1, k.ratio_text()))
    compose(d, tree)
    return d.finish()


def _extents(data: Data, pad: float) -> tuple[Extent, Extent, Extent]:
    """The model boxes of the scheme, the disc and the rod; ``pad`` (model units) above and
    below the disc and the rod is room for their loads at μ_F."""
    r, x = data.r, data.x
    half = max(DISC, ROD.slot_half + ROD.frame) * r
    # the scheme's box: the disc with room (in units of r) left of it for the coordinate x's
    # arrow, under it for O's support, over the support of the spring and the damper
    scheme = (-(DISC + 0.25) * r, -(DISC + 0.1) * r, half, (ROD.ground + 0.15) * r)
    disc = (-DISC * r, -DISC * r - pad, DISC * r, DISC * r + pad)
    rod = (-half, x - ROD.frame * r - pad, half, x + ROD.top * r + pad)
    return scheme, disc, rod


def _main_tree(sol: Solution[Data]) -> tuple[Tree, dict[str, View]]:
    """The three views at one GOST scale (the loads' room above and below the disc and the rod
    found by arranging twice: it depends on that scale), the notes under them, the tables and
    the equations on the right, clear of the title block."""
    data = sol.data
    k_F = sol.scales["F"]
    longest = max(float(sol.results["N_pin"]), float(sol.results["F_spring"])) / k_F + LABEL_MM
    s = settle(
        lambda k: _main_views(sol, _extents(data, longest * k)),
        lambda lay, _: lay.scale("l").k,
        0.0,
        Field.of_format("A3"),
    )
    return s.tree, s.parts


def _main_views(
    sol: Solution[Data], boxes: tuple[Extent, Extent, Extent]
) -> tuple[Node, dict[str, View]]:
    data = sol.data
    k_F = sol.scales["F"]
    heads = ("view_scheme", "view_disc", "view_rod")
    draws = (
        lambda v: _scheme(v, data),
        lambda v: _disc(v, data, k_F),
        lambda v: _rod(v, data, k_F),
    )
    figs = [
        Figure(box, fn, title=WORDS(h), group="l", show_scale=False, margin=3.0)
        for box, fn, h in zip(boxes, draws, heads, strict=True)
    ]
    state = WORDS(
        "state",
        phi=num(math.degrees(data.phi)),
        dphi=num(data.dphi),
        ddphi=num(data.ddphi),
        t=num(float(sol.params["t"])),
        k_F=num(k_F),
    )
    notes = V.Text(
        paragraphs=[
            WORDS("rod_motion", x=num(data.x), xd=num(data.xd), xdd=num(data.xdd)),
            WORDS("forces_at_mu", note=short_note(k_F, data.reactions)),
        ],
        width=NOTES_W,
        height=NOTES_H,
    )
    left = Column(
        V.Text(lines=[state], height=3.5),
        Row(*figs, title=WORDS("views_head"), group="l", title_height=3.5),
        Row(notes, Spacer((20.0, 10.0))),  # the notes kept 20 mm short of the panel
        weights=(1.0, 0.86, 0.14),
    )
    tree = Row(left, _panel_main(sol, data), weights=(0.62, 0.38))
    return tree, {"scheme": figs[0], "disc": figs[1], "rod": figs[2]}


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
    gap = v.scale.model(1.2)  # the bushings 1.2 mm off the stem: the stem reads as free in them
    for s in (-1.0, 1.0):
        ground(v, (s * gap, g0), (s * gap, g1), (s, 0.0))
    # the spring (left) and the damper (right) between the crossbar and the support
    top = x + ROD.top * r
    gy = ROD.ground * r
    b = ROD.bar_half * r
    spring(v, (-b, top), (-b, gy))
    damper(v, (b, top), (b, gy))
    # the support under the spring and the damper, a little wider than the crossbar
    ground(v, (-1.3 * b - 0.1 * r, gy), (1.3 * b + 0.1 * r, gy), (0.0, 1.0))
    v.pivot((0.0, 0.0))
    v.joint(A)
    rho = phi_arc_radius(data, v.scale)
    v.dim_angle((0.0, 0.0), (rho, 0.0), A, "φ", r_mm=v.mm(rho), height=2.5)
    v.seg((0.0, 0.0), (1.25 * DISC * r, 0.0), "centre")
    # M(t) on a 5 mm arc about O from 150° (hand-set: above O's support, under the arc of φ)
    moment(v, (0.0, 0.0), data.M_t, 5.0, "M(t)", role="vector", start=math.radians(150.0))
    # the rod's coordinate x along its axis, from the spring's free position, left of the disc
    xs = -(DISC + 0.15) * r
    v.arrow((xs, 0.0), (xs, 1.3 * r), "dimension")
    v.label((xs, 1.3 * r), "x", prefer=(-1.0, 0.0))
    v.label(A, "A", prefer=(1.0, -1.0))
    v.label((0.0, 0.0), "O", prefer=(-1.0, -1.0))
    # the spring's and the damper's constants beside their symbols' middles, clear of the coils
    v.label((-b, 0.5 * (top + gy)), "c", prefer=(-1.0, 0.0), clear=3.0)
    v.label((b, 0.5 * (top + gy)), "k", prefer=(1.0, 0.0), clear=3.5)
    # the links' numbers (GOST 2.770): the disc 1, the rod 2; the frame 0 at its supports
    v.label(Vec.polar(DISC * r, math.radians(-60.0)), "1", prefer=(1.0, -1.0), clear=1.5)
    v.label((0.0, 0.5 * (x + ROD.frame * r + g0)), "2", prefer=(1.0, 0.0), clear=1.5)


def _disc(v: Viewport, data: Data, k_F: float) -> None:
    r, phi = data.r, data.phi
    A = Vec(r * math.cos(phi), r * math.sin(phi))
    v.circle((0.0, 0.0), DISC * r, "link")
    v.seg((0.0, 0.0), A, "link")
    v.joint((0.0, 0.0))
    v.joint(A)
    v.label(A, "A", prefer=(1.0, 1.0))
    v.label((0.0, 0.0), "O", prefer=(-1.0, 1.0))
    # the two moments about O on two radii far apart: the inertia moment's arc open at the
    # lower left, the driving moment's inner arc and its label in that opening
    draw_loads(
        v,
        data.reactions,
        k_F,
        "1",
        {
            "M(t)": Where(
                "M(t)", radius=7.0, start_deg=facing(moment_of(data.reactions, "1", "M(t)"), 225.0)
            ),
            "M_Phi1": Where(
                WORDS("M_in1"),
                radius=16.0,
                start_deg=facing(moment_of(data.reactions, "1", "M_Phi1"), 225.0, True),
            ),
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
    v.label(A, "A", prefer=(1.0, -1.0))
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


def _given(sol: Solution[Data], title: str = "given") -> View:
    """The given data as a table, under the words ``title``."""
    head = [WORDS("param"), "M(t) = M_0 + M_1·sin Ωt"]
    return V.Table.of_specs(PARAMS, sol.params, style="equation", pairs=2, head=head,
                            fill=PANEL_W, title=WORDS(title))  # fmt: skip


def _paragraphs(head: str, items: list[str], dash: bool = True) -> View:
    """A titled block of paragraphs, each wrapped to the panel's width."""
    pars = [f"– {it}" if dash else it for it in items]
    return V.Text(paragraphs=pars, width=PANEL_W, title=head)


def _panel_main(sol: Solution[Data], data: Data) -> Node:
    res = sol.results
    R = data.reactions
    nm = _unit("Nm")
    # the reactions the problem does not report, read off its model, written like its results
    read = (
        ResultSpec("R_01", "N", "", symbol="R_{01}"),
        ResultSpec("M_02", "N·m", "", symbol="M_{02}"),
        ResultSpec("R_02", "N", "", symbol="R_{02}", digits=3),
    )
    values = {
        **res,
        "R_01": R.force("R_{01}").norm,
        "M_02": abs(R.moment("M_{02}")),
        "R_02": _zero(R.magnitudes["R_{02}"], res["N_pin"]),
    }
    by = {s.name: s for s in (*RESULTS, *read)}
    order = ("J_pr", "dJ_pr", "M_pr", "phi_ddot", "N_pin", "R_01", "F_spring", "F_damper",
             "F_inertia_rod", "M_inertia_disc", "M_02", "R_02")  # fmt: skip
    labels = {
        "J_pr": WORDS("J_pr"), "dJ_pr": WORDS("dJ_pr"), "M_pr": WORDS("M_pr"),
        "N_pin": "R_{12} = R_{21}", "F_spring": f"{WORDS('F_spring')} = c|x|",
        "F_damper": f"{WORDS('F_damper')} = k|x'|", "F_inertia_rod": f"{WORDS('Phi2')} = m|x''|",
        "M_inertia_disc": f"{WORDS('M_in1')} = J|φ''|",
    }  # fmt: skip
    results = V.Table.of_specs(
        [by[n] for n in order], values, labels=labels, style="value", pairs=2,
        fill=PANEL_W, title=WORDS("results_state"),
    )  # fmt: skip
    eq = _paragraphs(WORDS("eq_head"), [WORDS(k) for k in ("eq_1", "eq_2", "eq_3", "eq_4")],
                     dash=False)  # fmt: skip
    mb = R.moment("M_b")
    loads = _paragraphs(
        WORDS("loads_head"),
        [
            WORDS("loads_1"),
            WORDS("loads_2"),
            WORDS("loads_3", mb=small(mb, data.M_t or 1.0, nm, WORDS("M_bal"))),
        ],
    )
    return Column(_given(sol), results, eq, loads, title_block_spacer())


def _motion(sol: Solution[Data]) -> Sheet:
    """φ(t) above φ'(t) on a common t axis on the left (with the ordinates of the table's
    instants); on the right the integration, the table of the motion, the derivation and the
    given data."""
    data = sol.data
    tr = data.motion
    T = tr.t_end
    ts = list(tr.t)
    times = np.linspace(0.0, T, 11)
    state = tr.sol(times)
    tick = nice_step(T / 10.0)
    diagrams: list[View] = []
    for i, (vals, sym, unit) in enumerate(
        ((list(tr.phi), "φ", "rad"), (list(tr.omega), "φ'", "rad_s"))
    ):

        def extra(g: Graph, i: int = i, vals: list[float] = vals, sym: str = sym) -> None:
            for tt, val in zip(times, state[i], strict=True):
                if val > 0.0:  # ordinates on the t axis's upper side, clear of its values
                    g.curve([tt, tt], [0.0, val], "construction")
            g.point(T, vals[-1], f"{sym}(T) = {num(vals[-1])}", prefer=(1.0, -1.0))

        diagrams.append(
            V.Diagram(
                V.AxisSpec("t", _unit("s"), tick=tick),
                V.AxisSpec(sym, _unit(unit)),
                [V.Curve(ts, vals)],
                extra=extra,
                title=f"{i + 1}. {sym}(t)",
                least=(150.0, 70.0),
                prefer=(230.0, 120.0),
            )
        )
    res = sol.results
    integ = _paragraphs(
        WORDS("int_head"),
        [
            WORDS("int_1"),
            WORDS("int_2"),
            WORDS("int_rk") if tr.method == "DOP853" else WORDS("int_lsoda"),
            WORDS("int_3", phi=num(res["phi_T"]), omega=num(res["omega_T"]), T=num(T)),
        ],
    )
    phis, omegas = state
    rows = [[f"t, {_unit('s')}", f"φ, {_unit('rad')}", f"φ, {_unit('deg')}",
             f"φ', {_unit('rad_s')}"]]  # fmt: skip
    # each column of one quantity with one count of decimals
    cols = [fmt_column([float(x) for x in xs]) for xs in (times, phis, np.degrees(phis), omegas)]
    rows += [list(r) for r in zip(*cols, strict=True)]
    table = V.Table(rows, widths=(PANEL_W / 4.0,) * 4, title=WORDS("table_head"))
    deriv = _paragraphs(WORDS("deriv_head"), [WORDS(k) for k in ("deriv_1", "deriv_2", "deriv_3",
                                                                  "deriv_4")])  # fmt: skip
    right = Column(integ, table, deriv, _given(sol, "given_motion"), title_block_spacer())
    # the lower diagram keeps clear of the title block's corner on its right, and the upper one
    # is as wide: one μ_t, their t ticks one above the other
    left = Column(*(Row(dg, Spacer((30.0, 10.0))) for dg in diagrams))
    tree = Row(left, right, weights=(0.6, 0.4))
    d = start("A3", _title(sol, "tb_motion", 2))
    compose(d, tree)
    return d.finish()
