"""2013-7's drawing sheet: the half-governor with its friction circles and reaction lines, the
joints enlarged, and the force plans of the sleeve and of the arm, composed by the layout step
(geomcad.sheet.compose: no hand-placed view positions).

A3 landscape:
- the right half of the governor (the largest GOST scale that fits), with the friction circles at
  B, F and H drawn to scale, link 3's line of action (their common tangent), the lines of G_6
  and F_i through D, the point Q where R_36's line meets G_6's, P's line through Q, the point K
  where it meets F_i's line, and R_76's line from K tangent to the friction circle at H; the
  forces as arrows on their lines at the view's stated μ_F (one too short there at a stated
  larger μ_F*, its label starred), each outside the link it acts on; the angle β; the links
  numbered;
- the joints B, F, H enlarged at one GOST scale, each with the friction circle, the pin, the
  links' centre lines, the reaction touching the circle and the relative rotation it opposes;
- the force triangle of the sleeve 2 (G_2 + R_32 + R_42 = 0) and the force polygon of arm 6
  (G_6 + R_36 + F_i + R_76 = 0, with P = G_6 + R_36) at one μ_F, the frictionless polygon
  dashed, both drawn by the one polygon drawer (geomcad.sheet.views.draw_polygon);
- the given data, the results with and without friction, the order of construction.

Every word comes from ``strings/<lang>/sheets_2013_7.toml``.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING

from geomcad.forces import ForcePolygon
from geomcad.geom import Vec
from geomcad.sheet import Sheet, TitleBlock, Viewport, fmt_number, start
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Node,
    Row,
    Spacer,
    View,
    arrange,
    compose,
)
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.form import title_block_room, title_block_spacer
from geomcad.sheet.free_body import LoadedFigure
from geomcad.sheet.friction import FrictionJoint
from geomcad.sheet.lang import Words, current
from geomcad.sheet.loads import ForceScales, force_scales
from geomcad.sheet.views import num

from .p2013_7 import Geometry
from .spec_2013_7 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.construction.recorder import Step
    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_7")

#: The longest force arrow on the mechanism drawing (mm): its μ_F is the smallest nice one at
#: which the largest force is at most this long.
LOAD_MM = 20.0


def scales(sol: Solution[Geometry]) -> dict[str, float]:
    """The sheet's k_l and k_F as the layout step chooses them (for ``verify``), and k_j of the
    enlarged joints (absent without friction)."""
    tree, views = _tree(sol)
    lay = arrange(tree, Field.of_format("A3"))
    out = {"l": lay[views["mech"]].scale.k, "F": lay.scale("F").k}  # type: ignore[union-attr]
    out["F_mech"] = mech_forces(sol.data).k
    if "joints" in lay.groups:
        out["j"] = lay.scale("joints").k
    return out


def extent(geo: Geometry) -> tuple[float, float, float, float]:
    """The model box of the mechanism drawing: the shaft, the half-governor with its ball, Q and
    K, with a margin for the force arrows and labels."""
    run = geo.run
    rb = ball_radius(geo.D.dist(geo.H))
    B, F, D, H = geo.B, geo.F, geo.D, geo.H
    pts = [B, F, H, run.Q, run.K, Vec(0.0, 0.0), Vec(0.0, B.y), D + Vec(rb, rb), D - Vec(rb, rb)]
    x0, y0, x1, y1 = V.extent_of(pts)
    return V.extent_of(pts, 0.08 * max(x1 - x0, y1 - y0))


def _magnitudes(geo: Geometry) -> dict[str, float]:
    """The forces drawn on the mechanism (N), by name: their magnitudes off the force plans."""
    run = geo.run

    def size(poly: ForcePolygon, name: str) -> float:
        vec_ = poly[name]
        return float((vec_.head - vec_.tail).norm)

    return {
        "G_6": size(run.poly6, "G_6"),
        "F_i": size(run.poly6, "F_i"),
        "R_36": size(run.poly6, "R_36"),
        "R_76": size(run.poly6, "R_76"),
        "R_32": size(run.tri2, "R_32"),
    }


def mech_forces(geo: Geometry) -> ForceScales:
    """The force scales of the mechanism drawing: μ_F so that the largest force is at most
    :data:`LOAD_MM` long, and a larger μ_F* for those shorter than two arrowheads there."""
    return force_scales(_magnitudes(geo).values(), LOAD_MM)


def ball_radius(l_DH: float) -> float:
    """The radius the ball D is drawn with (the problem gives none): 6 % of the arm HD."""
    return 0.06 * l_DH


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-7."""
    tree, views = _tree(sol)
    lay = arrange(tree, Field.of_format("A3"))
    kl = lay[views["mech"]].scale
    assert kl is not None
    tb = TitleBlock(
        title=WORDS("tb"),
        designation=WORDS("designation"),
        scale=kl.ratio_text(),
        lang=current(),
    )
    d = start("A3", tb)
    compose(d, tree)
    return [("", d.finish())]


def _tree(sol: Solution[Geometry]) -> tuple[Node, dict[str, View]]:
    """The sheet's views and how they share the field."""
    geo = sol.data
    run, free = geo.run, geo.free
    fs = mech_forces(geo)
    mech = LoadedFigure(
        extent(geo), lambda v: _mechanism(v, geo, fs), fs, title=WORDS("mech"), margin=5.0,
        weight=4.0,
    )  # fmt: skip
    # the joints enlarged (one scale), or a note where there are no friction circles
    if run.rho > 0.0:
        S = Vec(0.0, geo.B.y)
        u76 = run.R76_line.d
        specs = (
            (run.fc_B, [geo.F, S], run.link3.line, run.u32, "R_{32}", "ω_{32}"),
            (run.fc_F, [geo.B, geo.H, geo.D], run.link3.line, run.link3.line.d, "R_{36}",
             "ω_{36}"),
            (run.fc_H, [Vec(0.0, 0.0), geo.D], run.R76_line, u76, "R_{76}", "ω_{67}"),
        )  # fmt: skip
        # R_ij acts on link j from link i and its moment opposes ω_ji = ω_j − ω_i (the order's
        # notation): the rotation drawn is that one, in its own sense
        joints: list[View] = [
            FrictionJoint(fc, towards, line, force, fname, wname, geo.d,
                          WORDS("joint", name=fc.name), group="joints", margin=2.0)
            for fc, towards, line, force, fname, wname in specs
        ]  # fmt: skip
        joint_row: Node | View = Row(
            *joints, title=WORDS("joints"), group="joints", title_height=3.5
        )
    else:
        joint_row = V.Text(paragraph=WORDS("no_friction"), width=150.0, height=3.5)
    names = {"G_6": "G_6", "R_36": "R_{36}", "F_i": WORDS("Phi6"), "R_76": "R_{76}"}
    plan6 = Figure(
        V.extent_of(
            q for p in (run.poly6, free.poly6) for vv in p.vectors for q in (vv.tail, vv.head)
        ),
        lambda v: _plan6(v, geo, names),
        title=WORDS("plan6"),
        quantity="F",
        series="nice",
        group="F",
        margin=5.0,
        weight=2.0,
    )
    plan2 = V.Polygon(
        run.tri2,
        names={"G_2": "G_2", "R_32": "R_{32}", "R_42": "R_{42}"},
        title=WORDS("plan2"),
        group="F",
        margin=5.0,
        weight=2.0,
    )
    corner = title_block_room()
    # the middle and the right columns keep the title block's corner free
    tree = Row(
        Column(
            Row(mech, plan6, plan2, weights=(0.42, 0.34, 0.24)),
            joint_row,
            Row(_steps(sol), Spacer((corner[0] - STEPS_CLEAR, 10.0))),
        ),
        Column(_given(sol), _compare(geo), _results(sol), _note(), title_block_spacer()),
        weights=(0.82, 0.18),
    )
    return tree, {"mech": mech, "plan6": plan6, "plan2": plan2}


# -- the mechanism --------------------------------------------------------------------------------


def _mechanism(v: Viewport, geo: Geometry, fs: ForceScales) -> None:
    """The half-governor with its friction circles, the lines of action, Q, K and β; the
    forces as arrows at the view's μ_F (a short one at the stated μ_F*, its label starred),
    each on its line outside the link it acts on, its head at its point."""
    run = geo.run
    k = v.scale
    _x0, y0, _x1, y1 = extent(geo)
    B, F, D, H = geo.B, geo.F, geo.D, geo.H
    S = Vec(0.0, B.y)  # the sleeve's centre on the shaft
    # the shaft stops 4 mm inside the view's box, its axis runs 4 mm past it (GOST 2.303)
    over = k.model(4.0)
    # the shaft 7 and its axis, the collar, the sleeve 2 (a slider on the shaft)
    top, bottom = Vec(0.0, y1 - over), Vec(0.0, y0 + over)
    v.seg(top, bottom, "link")
    v.seg(top + Vec(0.0, over), bottom - Vec(0.0, over), "centre")
    v.seg(Vec(0.0, 0.0), H, "link")
    v.seg(S, B, "link")
    # the sleeve slides on the shaft: a block without a joint circle (GOST 2.770)
    v.slider(S, Vec(0.0, 1.0), with_joint=False)
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
    # the lines of action: link 3's (the common tangent), G_6's and F_i's through D, P's, R_76's,
    # each run a few mm (6, 8) past its last point so that its end reads as a line, not a side
    ends3 = [run.link3.touch_a, run.link3.touch_b, run.Q]
    v.line_over(run.link3.line, ends3, "result", over=6.0)
    v.seg(D, run.Q, "construction")
    # F_i's line from D to K and on 17 mm past K, where the angle β is marked (its arc 13 mm,
    # its sides 16 mm long: hand-set, the value outside P's line)
    past = k.model(17.0) * (1.0 if run.K.x >= D.x else -1.0)
    v.seg(D, Vec(run.K.x + past, D.y), "construction")
    v.line_over(run.P_line, [run.Q, run.K], "construction", over=8.0)
    t76 = run.R76_line.foot(H)
    v.line_over(run.R76_line, [run.K, t76], "result", over=8.0)
    for q in (run.Q, run.K):
        v.dot(q, "result")
    # the forces on their lines, each |F|/μ_F long at its tier's μ_F (the label starred there)
    mags = _magnitudes(geo)

    def m(name: str) -> tuple[float, str]:
        tier = fs.tier(mags[name])
        if tier is None:  # a zero force (round-off): nothing drawn, its 0 is in the tables
            return 0.0, ""
        return k.model(mags[name] / fs.scales[tier].k), fs.mark(tier)

    u36 = run.link3.line.d
    m6, s6 = m("G_6")
    _force(v, D, D + Vec(0.0, -m6), "G_6" + s6, (1.0, -1.0))
    mi, si = m("F_i")
    _force(v, D, D + Vec(mi, 0.0), WORDS("Phi6") + si, (1.0, 1.0))
    # R_36 and R_32 act along link 3's line: drawn beyond F and below B, off the link
    # R_36 named beside its shaft's middle, on the side away from arm 6 (its head at F is
    # crowded by the arm, link 3 and F's name)
    m36, s36 = m("R_36")
    if m36 > 0.0:
        tail36 = run.link3.touch_b - u36 * m36
        v.arrow(tail36, run.link3.touch_b, "vector")
        side = u36.perp() if u36.perp().dot(D - F) < 0.0 else -u36.perp()
        v.label((tail36 + run.link3.touch_b) * 0.5, "R_{36}" + s36, prefer=(side.x, side.y),
                clear=1.0)  # fmt: skip
    m32, s32 = m("R_32")
    _force(v, run.link3.touch_a - run.u32 * m32, run.link3.touch_a, "R_{32}" + s32, (-1.0, -1.0))
    u76 = run.R76_line.d
    m76, s76 = m("R_76")
    _force(v, t76, t76 + u76 * m76, "R_{76}" + s76, (-1.0, 1.0))
    # the angle β between R_76's line and the horizontal, at K
    left = run.K + Vec(-1.0 if u76.x < 0.0 else 1.0, 0.0) * k.model(16.0)
    up = run.K + (u76 if u76.y > 0.0 else -u76) * k.model(16.0)
    v.dim_angle(run.K, left, up, f"β = {fmt_number(math.degrees(run.beta), digits=3)}°", 13.0, 2.5)
    # labels: preferred direction and clearance (mm), hand-set clear of the friction circles
    v.label(H, "H", prefer=(1.0, 1.0), clear=3.0)
    v.label(F, "F", prefer=(1.0, 0.0), clear=3.0)
    v.label(B, "B", prefer=(1.0, -1.0), clear=3.0)
    # the ball is named at its rim (its centre is inside the drawn circle)
    rim = D + Vec(1.0, -1.0).unit() * ball_radius(geo.D.dist(H))
    v.label(rim, "D", prefer=(1.0, -1.0), clear=1.0)
    v.label(run.Q, "Q", prefer=(1.0, 0.0))
    v.label(run.K, "K", prefer=(0.0, -1.0), clear=2.0)
    # the links' numbers (GOST 2.770): sleeve 2, link 3, arm 6, shaft 7
    v.label(S, "2", prefer=(-1.0, -1.0), clear=5.0)
    # link 3's number on its stretch below F_i's line through D and K (the line, K, P's line
    # and the angle β crowd BF where it crosses it), on the side away from its line of action
    t = (D.y - B.y) / (F.y - B.y) if F.y != B.y else 1.0
    at3 = B + (F - B) * (0.5 * t if 0.2 < t < 1.0 else 0.5)
    v.label(at3, "3", prefer=(1.0, -1.0), clear=1.5)
    v.label((H + F) * 0.5, "6", prefer=(1.0, 1.0), clear=1.5)
    v.label(top, "7", prefer=(1.0, 0.0))


def _force(v: Viewport, tail: Vec, head: Vec, name: str, prefer: tuple[float, float]) -> None:
    if tail == head:  # a zero force
        return
    v.arrow(tail, head, "vector")
    v.label(head, name, prefer=prefer, clear=0.5)


# -- the force plans ------------------------------------------------------------------------------


def _plan6(v: Viewport, geo: Geometry, names: dict[str, str]) -> None:
    """The polygon of arm 6 by the one polygon drawer, over the frictionless one (a second
    variant in thin lines, from the same pole: G_6 is common), with P = G_6 + R_36 as its
    diagonal."""
    run, free = geo.run, geo.free
    if run.rho > 0.0:
        for vec_ in free.poly6.vectors:
            if vec_.name != "G_6":
                v.seg(vec_.tail, vec_.head, "construction")
    # P = G_6 + R_36 runs beside R_36: P's label goes outside, R_36's inside the polygon
    V.draw_polygon(v, run.poly6, names, "vector", inward=("R_36",))
    p = run.poly6.diagonal("G_6", "R_36", "P")
    v.arrow(p.tail, p.head, "result")
    c = sum((vv.tail for vv in run.poly6.vectors), Vec(0.0, 0.0)) * (1.0 / len(run.poly6.vectors))
    n = (p.head - p.tail).perp()
    mid = (p.tail + p.head) * 0.5
    if n.dot(mid - c) < 0.0:
        n = -n
    u = n.unit()
    v.label(mid, "P", height=2.5, prefer=(u.x, u.y))
    if run.rho > 0.0:
        # the frictionless variant named beside its own side R_76 (the one apart from the
        # polygon with friction), inside the polygon
        r76 = free.poly6["R_76"]
        at = (r76.tail + r76.head) * 0.5
        inner = (c - at).unit()
        v.label(at, "f = 0", height=2.5, prefer=(inner.x, inner.y), clear=0.8)


# -- the tables and the order of construction ----------------------------------------------------


def _with_unit(value: str, unit: str) -> str:
    """A value with its unit: ``0,15 м``, ``45°`` (no space before the degree sign)."""
    return value + unit if unit in ("°", "") else f"{value} {unit}"


def _u(key: str) -> str:
    return WORDS(f"u_{key}")


def _given(sol: Solution[Geometry]) -> View:
    p = sol.params
    mode = WORDS("speeding_up" if int(p["direction"]) > 0 else "slowing_down")
    labels = {"m_ball": WORDS("m_ball"), "direction": WORDS("mode")}
    return V.Table.of_specs(PARAMS, {**p, "direction": mode}, labels=labels, style="value",
                            pairs=2, title=WORDS("given"))  # fmt: skip


def _compare(geo: Geometry) -> View:
    run, free = geo.run, geo.free
    rows = [["", f"f = {num(run.f)}", "f = 0"]]
    for label, a, b, unit in (
        ("R_{32}", run.R32, free.R32, _u("N")),
        ("P", run.P, free.P, _u("N")),
        ("β", math.degrees(run.beta), math.degrees(free.beta), "°"),
        ("F_i", run.F_i, free.F_i, _u("N")),
        ("ω", run.omega, free.omega, _u("rad_s")),
    ):
        rows.append([label, _with_unit(num(a), unit), _with_unit(num(b), unit)])
    return V.Table(rows, title=WORDS("compare"))


def _results(sol: Solution[Geometry]) -> View:
    return V.Table.of_specs(RESULTS, sol.results, labels={"F_i": f"F_i = {WORDS('Phi6')}"},
                            style="value", title=WORDS("results"))  # fmt: skip


#: The steps the order of construction lists, by name, in their recorded order: with friction,
#: the senses of the relative rotations, the friction circles, link 3's line, the sleeve's
#: polygon, Q, P, K, R_76's line, the arm's polygon, ω, and ω of the same construction with f = 0;
#: without friction the steps that remain.
ORDER = ("ω_3/ω_6", "sense ω_32", "sense ω_36", "sense ω_67", "ρ", "α", "plan 2", "Q",
         "line P", "K", "line R_76", "plan 6", "ω", "f=0: ω")  # fmt: skip
ORDER_NO_FRICTION = ("ρ", "α", "plan 2", "Q", "line P", "K", "line R_76", "plan 6", "ω")


def order_steps(sol: Solution[Geometry]) -> list[Step]:
    """The steps of the order of construction, their operands in the language being drawn (the
    inertia force's letter: Ф in Russian, Φ in English)."""
    geo: Geometry = sol.data
    names = ORDER if geo.run.rho > 0.0 else ORDER_NO_FRICTION
    phi = WORDS("Phi6")[0]
    out = []
    for name in names:
        st = sol.construction.step(name)
        args = tuple(
            (k, a.replace(chr(0x424), phi) if isinstance(a, str) else a) for k, a in st.args
        )
        out.append(replace(st, args=args))
    return out


def _steps(sol: Solution[Geometry]) -> View:
    """The order of construction written from the recorded steps (their kinds' templates in
    ``strings/<lang>/sheets_2013_7.toml``)."""
    steps = order_steps(sol)
    return V.Steps(steps, STEPS_WIDTH, only=[st.name for st in steps], words=WORDS,
                   title=WORDS("order"))  # fmt: skip


def _note() -> View:
    """The one note no step records: how the forces are drawn on the scheme (at its μ_F)."""
    return V.Text(paragraph=WORDS("note", mm=num(SHORT_MM)), width=NOTE_WIDTH, height=2.5)


#: How much (mm) of the title block's width the order of construction may run over: the
#: middle column is above the title block, so the order's row need not keep all of it free.
STEPS_CLEAR = 70.0
#: The width (mm) of the order of construction.
STEPS_WIDTH = 200.0
#: The width (mm) of the note under the tables.
NOTE_WIDTH = 68.0
