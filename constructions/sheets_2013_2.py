"""2013-2's drawing sheet: the cam profile by inversion, the S(φ) graph and the velocity plan.

A2 landscape. Left: the profile at k_l (the seed's 2:1 when it fits; else the largest GOST scale
that does) with the base circle, the follower turned back to each division point (its axis and its
face, or its tip, or its roller), the profile, and the radius vectors r_i dimensioned; the rest of
the program past the span (the seed's second half of the rise) in thin lines, so that the cam's
shape is seen whole; a closed program is drawn as its full turn. Below it the follower's law S(φ)
with the ordinates of the division points. Right: the mechanism at the plan's division point with
the velocity plan Bb₁b₂ and the similar triangle OBB′ (OB′ = BC = S′), the given data, the
results and the order of construction.

Scale choice lives here (:func:`scales`): the problem's build returns only its model.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING

import numpy as np

from geomcad import tol
from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.cams import CamProfile, evert
from geomcad.problem import ResultSpec
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
    View,
    arrange,
    compose,
)
from geomcad.sheet.drawing import ARROW_LEN, DOT_R, SHORT_MM
from geomcad.sheet.graph import Graph
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.text import wrap
from geomcad.sheet.views import num

from .spec_2013_2 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.construction.recorder import Step
    from geomcad.problem import Solution

    from .p2013_2 import Geometry

WORDS = Words(__package__, "sheets_2013_2")
MM = 1000.0
#: Paper margin (mm) the face lines and labels take beyond the profile.
VIEW_PAD = 6.0
#: Division points closer than this on the paper (mm) are not all labelled.
LABEL_APART = 5.0
#: Rows a results table shows at most (the first, the last and evenly spaced ones between).
MAX_ROWS = 7
#: The face lines run this far (paper mm) past the contact point and the follower's axis.
FACE_OVER = 6.0
#: A plan vector shorter than this (mm) is drawn as a point with its label (twice the head).
#: Width (mm) of the panel's text, and the title block's height (kept free under the panel).
PANEL_W = 250.0
#: Width and letter height (mm) of the order of construction.
ORDER_W = 280.0
ORDER_H = 2.5
BLOCK_H = 52.0


# -- views and scales ------------------------------------------------------------------------------


def extent(sol: Solution[Geometry]) -> tuple[float, float, float, float]:
    """The model box the profile view draws: the base circle, the profile (and the rest of the
    program past the span), the division points."""
    geo = sol.data
    f = geo.follower
    parts = [geo.profile.contact, geo.divisions.pitch, geo.divisions.contact, geo.profile.pitch]
    if geo.rest is not None:
        parts += [geo.rest.contact, geo.rest.pitch]
    pts = np.vstack(parts)
    ext = f.r_roller if f.kind == "roller" else 0.0
    xs = [float(pts[:, 0].min()) - ext, float(pts[:, 0].max()) + ext, -f.r0, f.r0]
    ys = [float(pts[:, 1].min()) - ext, float(pts[:, 1].max()) + ext, -f.r0, f.r0]
    return min(xs), min(ys), max(xs), max(ys)


class _Views:
    """The sheet's views and their tree (composed by :mod:`geomcad.sheet.compose`)."""

    def __init__(self, sol: Solution[Geometry]) -> None:
        geo = sol.data
        f = geo.follower
        self.profile = Figure(
            extent(sol), lambda v: _profile(v, sol), title=WORDS("profile_title"),
            title_height=5.0, margin=VIEW_PAD, weight=3.0,
        )  # fmt: skip
        left: list[View | Node] = [self.profile]
        if geo.rest is not None:
            span, end = math.degrees(float(geo.span)), math.degrees(float(geo.rest.phi[-1]))
            left.append(V.Text([WORDS("rest_note", span=num(span), end=num(end))], height=2.5))
        law = WORDS(f"law_{sol.params['law']}")
        left.append(Row(*_diagrams(sol), weights=(1.0, 1.0), title=WORDS("graph_title", law=law)))
        steps = order_steps(sol)
        plan = geo.plan
        phi = math.degrees(plan.phi)
        self.scheme = Figure(
            _scheme_extent(sol), lambda v: _scheme(v, sol),
            title=WORDS("scheme_title", i=geo.plan_index, phi=num(phi)), margin=6.0, weight=2.0,
        )  # fmt: skip
        vectors = [plan.V_B1, plan.V_B2, plan.V_B2 - plan.V_B1]
        shortest = min((q.norm for q in vectors if q.norm > 0.0), default=0.0)
        self.plan = Figure(
            _plan_extent(sol), lambda v: _plan(v, sol), title=WORDS("plan_title"),
            quantity="v", series="nice", margin=8.0, readable=shortest,
        )  # fmt: skip
        eq = "OB' = BC = S'" if f.kind == "flat" else "OB' = S'"
        right: list[View | Node] = [
            Row(self.scheme, self.plan),
            V.Text([f"{WORDS('scheme_note', eq=eq)} {WORDS('plan_omega')}"], height=2.5),
            *_tables(sol),
            V.Text(_notes(sol), width=PANEL_W, height=3.0),
            V.Steps(
                steps, ORDER_W, only=[st.name for st in steps], height=ORDER_H, words=WORDS,
                title_height=5.0,
            ),
            Spacer((10.0, BLOCK_H)),
        ]  # fmt: skip
        self.tree = Row(Column(*left), Column(*right), weights=(1.0, 1.0))

    def scales(self, lay: Layout) -> dict[str, float]:
        k_l, k_v = lay[self.profile].scale, lay[self.plan].scale
        assert k_l is not None and k_v is not None
        return {"l": k_l.k, "v": k_v.k}


@per_language
def scales(sol: Solution[Geometry]) -> dict[str, float]:
    """k_l of the profile and k_v of the velocity plan, as the layout chooses them (no drawing):
    each the largest of its series the view's box allows."""
    views = _Views(sol)
    return views.scales(arrange(views.tree, Field.of_format("A2")))


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-2."""
    k = Scale(scales(sol)["l"], "l")  # this layout's (in the language being drawn)
    tb = TitleBlock(title=WORDS("tb_title"), designation=WORDS("designation"), scale=k.ratio_text())
    d = start("A2", tb)
    compose(d, _Views(sol).tree)
    return [("", d.finish())]


# -- the profile by inversion ----------------------------------------------------------------------


def _profile(v: Viewport, sol: Solution[Geometry]) -> None:
    """The profile by inversion (see the module's docstring)."""
    geo = sol.data
    f = geo.follower
    prof, div = geo.profile, geo.divisions
    k = v.scale
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
        # the radius vector r_i = OB_i: a thin construction line (its length is written on it)
        v.seg(o, B, "construction")
        if i in shown:
            v.label(B, f"B_{{{i}}}", height=2.5, prefer=(up.x, up.y))
    if f.kind != "flat" and f.e != 0.0:
        v.circle(o, abs(f.e), "centre")
    if f.kind == "roller":
        v.polyline(list(prof.pitch), "centre", closed=geo.closed)
    v.polyline(list(prof.contact), "link", closed=geo.closed)
    if geo.rest is not None:
        _rest(v, sol, geo.rest, over)
    v.label(o, "O", prefer=(-1.0, -1.0), clear=1.0)
    # the inversion: the follower turns about O against the cam's rotation
    _turn_arrow(v, 0.55 * f.r0, 125.0, 165.0, -f.sigma, WORDS("minus_omega"))
    # the radius vectors' lengths, written along them
    for i in sorted(shown):
        B = Vec(*div.contact[i])
        text = f"r_{{{i}}} = {num(float(div.radius[i]) * MM)}"
        spots = tuple(v.p(B * t) for t in (0.6, 0.8, 0.5, 0.9, 0.4))
        v.d.label(v.p(B * 0.7), text, 2.5, others=spots)
    # the angle of one interval, between the last two axes
    if n >= 2:
        a0 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-2]))
        a1 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-1]))
        dphi = math.degrees(float(div.phi[-1] - div.phi[-2]))
        v.dim_angle(o, a0, a1, f"{num(dphi)}°", r_mm=k.mm(f.r0) * 0.55, height=2.5)


def _rest(v: Viewport, sol: Solution[Geometry], rest: CamProfile, over: float) -> None:
    """The profile past the span to the program's end in thin lines, with the follower's axis at
    the end (thin) and a note of where the program ends (a note under the view says what the
    thin line is)."""
    f = sol.data.follower
    if f.kind == "roller":
        v.polyline(list(rest.pitch), "centre")
    v.polyline(list(rest.contact), "thin")
    end = float(rest.phi[-1])
    up = Vec(0.0, 1.0).rotated(-f.sigma * end)
    foot = Vec(1.0, 0.0).rotated(-f.sigma * end) * (f.e if f.kind != "flat" else 0.0)
    C = Vec(*rest.pitch[-1])
    v.seg(foot, C + up * over, "construction")
    v.label(C + up * over, WORDS("rest_end", phi=num(math.degrees(end))), 2.5,
            prefer=(up.x, up.y), clear=0.5)  # fmt: skip


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


def _diagrams(sol: Solution[Geometry]) -> list[V.Diagram]:
    """The follower's law S(φ) and its analogue of velocity S′(φ) = dS/dφ (the length BC = OB′
    of the scheme), side by side, with the ordinates of the division points."""
    geo = sol.data
    prog = geo.program
    end = 2.0 * math.pi if geo.closed else prog.total
    phi = np.linspace(0.0, end, 721)
    motion = prog.motion(phi)
    div = geo.divisions
    n = len(div.phi)
    step = _label_step(n)
    out = []
    for sym, ys, at_div in (("S", motion.S, div.S), ("S'", motion.S1, div.S1)):

        def ordinates(g: Graph, at_div: np.ndarray = at_div) -> None:
            for i in range(n):
                x, y = float(div.phi[i]), float(at_div[i])
                mark = str(i) if i % step == 0 else ""
                if x != g.x.zero or not mark:
                    g.ordinate(x, y, mark)
                    continue
                # a division point on the ordinate axis: its number inside, right of the axis, not
                # over it where it would read as a tick value
                g.ordinate(x, y)
                up = -1.0 if y >= g.y.zero else 1.0
                g.d.label(g.p(x, y), mark, 2.5, prefer=(1.0, -up), clear=DOT_R)

        out.append(
            V.Diagram(
                V.AxisSpec("φ", WORDS("unit_rad"), lo=0.0, hi=end),
                V.AxisSpec(sym, WORDS("unit_m")),
                [V.Curve(phi, ys, "link")],
                extra=ordinates,
                least=(90.0, 45.0),
                prefer=(160.0, 70.0),
            )
        )
    return out


# -- the scheme and the velocity plan --------------------------------------------------------------


def _cam_now(sol: Solution[Geometry]) -> tuple[np.ndarray, np.ndarray]:
    """The cam's built profile and the rest of the program, turned to the plan's φ."""
    geo = sol.data
    f = geo.follower
    phi = geo.plan.phi
    cam = evert(geo.profile.contact, np.full(len(geo.profile.phi), phi), f.sigma)
    rest = (
        evert(geo.rest.contact, np.full(len(geo.rest.phi), phi), f.sigma)
        if geo.rest is not None
        else np.zeros((0, 2))
    )
    return cam, rest


def _follower_size(sol: Solution[Geometry]) -> tuple[float, float, float]:
    """The face's half width, the stem's base (the face, the knife's tip or the roller's top)
    and the stem's length, in model units."""
    geo = sol.data
    f = geo.follower
    width = float(np.max(np.abs(geo.profile.S1))) + 0.2 * f.r0
    base = float(geo.plan.B.y) + (f.r_roller if f.kind == "roller" else 0.0)
    return width, base, 0.35 * f.r0


def _scheme_extent(sol: Solution[Geometry]) -> tuple[float, float, float, float]:
    f = sol.data.follower
    cam, rest = _cam_now(sol)
    every = np.vstack([cam, rest]) if len(rest) else cam
    width, base, stem = _follower_size(sol)
    xs = [*every[:, 0], -f.r0, f.r0, -width, width]
    ys = [*every[:, 1], -f.r0, base + stem]
    return min(xs), min(ys), max(xs), max(ys)


def _plan_extent(sol: Solution[Geometry]) -> tuple[float, float, float, float]:
    plan = sol.data.plan
    pts = [Vec(0.0, 0.0), plan.V_B1, plan.V_B2]
    xs, ys = [q.x for q in pts], [q.y for q in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _scheme(v: Viewport, sol: Solution[Geometry]) -> None:
    """The mechanism at the plan's division point, in the fixed frame: the cam (the built profile
    thick, the rest of the program thin), the follower, the triangle OBB′ (and C); links numbered
    (1 the cam, 2 the follower, 3 the roller); beside it the velocity plan pb₁b₂ at its own
    factor."""
    geo = sol.data
    f = geo.follower
    plan = geo.plan
    kl = v.scale
    cam, rest = _cam_now(sol)
    width, base, stem = _follower_size(sol)
    h = float(plan.B.y)
    o = Vec(0.0, 0.0)
    # the cam: its built profile and the base circle, turned to φ; the rest of the program thin
    v.circle(o, f.base_radius, "construction")
    v.polyline(list(cam), "link", closed=geo.closed)
    if len(rest):
        v.polyline(list(rest), "thin")
    Bp, C, B = plan.B_prime, plan.C, plan.B
    away = -1.0 if Bp.x >= 0.0 else 1.0
    v.pivot(o, down=(away, -1.0))
    _omega_arrow(v, max(f.r0 * 0.35, kl.model(13.0)), f.sigma, away)
    # the follower: flat face (or knife, roller), stem, its guide on the frame (hatched both sides)
    top = Vec(f.e, base + stem)
    if f.kind == "flat":
        v.seg(Vec(-width, h), Vec(width, h), "link")
        v.seg(Vec(f.e, h), top, "link")
    elif f.kind == "roller":
        v.circle(B, f.r_roller, "link")
        v.seg(B, top, "link")
        v.joint(B)
    else:
        v.seg(B, top, "link")
    g_lo, g_hi = Vec(f.e, base + stem * 0.45), Vec(f.e, base + stem * 0.95)
    v.guide(g_lo, g_hi, (1.0, 0.0))
    v.guide(g_lo, g_hi, (-1.0, 0.0))
    # link numbers: the cam 1 inside its base circle, the follower 2 by its stem, the roller 3
    v.label(Vec(0.0, -0.6 * f.base_radius), "1", 3.5, clear=0.5)
    v.label(Vec(f.e, base + stem * 0.22), "2", 3.5, prefer=(-away, 0.0), clear=1.0)
    if f.kind == "roller":
        v.label(B + Vec(f.r_roller, 0.0) * (-away), "3", 3.5, prefer=(-away, 0.0), clear=1.0)
    # the triangle OBB′ similar to the plan, and C (BC = OB′ = S′)
    v.seg(o, B, "construction")
    v.seg(B, Bp, "construction")
    v.seg(o, Bp, "construction")
    if f.kind == "flat":
        v.seg(o, C, "construction")
    v.right_angle(Bp, o, B, 2.5)
    for q in (o, B, Bp):
        v.dot(q, "point")
    v.label(o, "O", prefer=(-away, 1.0), clear=1.5)
    v.label(B, "B", prefer=(-away, 1.0))
    v.label(Bp, "B'", prefer=(-away, -1.0))
    if f.kind == "flat":
        v.label(C, "C", prefer=(away, -1.0))
    if abs(plan.S1) > 0.0:
        v.dim_linear(o, Bp, "S'", offset=-3.0 if Bp.x > 0 else 3.0, height=2.5)


def _plan(pv: Viewport, sol: Solution[Geometry]) -> None:
    """The velocity plan: pb1 = V_B1 ⊥ OB, pb2 = V_B2 along the motion, b1b2 = V_B2B1, each at
    μ_V exactly; a vector under two arrowheads is drawn as a point with its name."""
    plan = sol.data.plan
    kv = pv.scale
    pole = Vec(0.0, 0.0)
    b1, b2 = plan.V_B1, plan.V_B2
    for a, b, name in ((pole, b1, "V_{B1}"), (pole, b2, "V_{B2}"), (b1, b2, "V_{B2B1}")):
        length = kv.mm((b - a).norm)
        if length >= SHORT_MM:
            pv.arrow(a, b, "vector")
        elif length > 0.0:
            pv.dot(b, "point")
            pv.label(b, WORDS("plan_short", name=name, value=num(length, 3)), 2.5)
    pv.dot(pole, "point")
    pv.label(pole, "p", height=3.5, prefer=(1.0, -1.0))
    pv.label(b1, "b_1", height=3.5, prefer=(-1.0, 0.0))
    pv.label(b2, "b_2", height=3.5, prefer=(1.0, 1.0))


def _omega_arrow(v: Viewport, r: float, sigma: int, side: float) -> None:
    """The cam's sense of rotation: an arc about O below it, on ``side`` (±1 in x), with an
    arrowhead, labelled ω."""
    a0, a1 = (200.0, 290.0) if side <= 0.0 else (250.0, 340.0)
    _turn_arrow(v, r, a0, a1, sigma, WORDS("omega"))


def _turn_arrow(v: Viewport, r: float, a0_deg: float, a1_deg: float, sense: int, text: str) -> None:
    """An arc about O from a0 to a1 (degrees, counter-clockwise) with an arrowhead at the end the
    ``sense`` (+1 counter-clockwise) points to, and its label."""
    a0, a1 = math.radians(a0_deg), math.radians(a1_deg)
    v.arc(Arc(Circle(Vec(0.0, 0.0), r), a0, a1), "dimension")
    chord = 2.2 * ARROW_LEN / v.mm(r)  # the head's arc: more than two arrowheads long
    end, before = (a1, a1 - chord) if sense > 0 else (a0, a0 + chord)
    v.arrow(Vec.polar(r, before), Vec.polar(r, end), "dimension")
    mid = (a0 + a1) / 2.0
    v.label(Vec.polar(r, mid), text, height=3.5, prefer=(math.cos(mid), math.sin(mid)), clear=0.5)


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


#: The columns of the results table (mm); the data table above it is as wide.
RESULTS_W = (24.0, 64.0, 64.0, 64.0, 64.0)


def _tables(sol: Solution[Geometry]) -> list[V.Table]:
    """The given data and the results at the division points."""
    p, r, geo = sol.params, sol.results, sol.data
    law = str(p["law"])
    step_deg = num(math.degrees(geo.span) / int(p["n_div"]), 3)
    shown = {
        **p,
        "law": WORDS(f"short_{law}"),
        "follower": WORDS(f"f_{p['follower']}"),
        "omega_sign": WORDS("ccw" if int(p["omega_sign"]) > 0 else "cw"),
        "n_div": f"{p['n_div']} × {step_deg}°",
    }
    by = {s.name: s for s in PARAMS}
    names = ("H", "r0", "n_div", "phi_rise_deg", "phi_dwell_deg", "phi_return_deg", "law",
             "follower", "omega_sign", "e", "r_roller")  # fmt: skip
    labels = {n: WORDS(k) for n, k in (
        ("r0", "c_r0"), ("n_div", "c_intervals"), ("phi_rise_deg", "c_rise"),
        ("phi_dwell_deg", "c_dwell"), ("phi_return_deg", "c_return"), ("law", "c_law"),
        ("follower", "c_follower"), ("r_roller", "c_roller"),
    )}  # fmt: skip
    data = V.Table.of_specs(
        [by[n] for n in names], shown, labels=labels, style="value", pairs=4, header=False,
        height=3.5, row_h=6.0, fill=sum(RESULTS_W), title=WORDS("data_title"), title_height=5.0,
    )  # fmt: skip
    spec = {s.name: s for s in RESULTS}
    s1 = ResultSpec("S1", "m", "S′ at the division points", symbol="S'_i", display="mm")
    idx = _rows(len(r["phi"]))
    H = geo.program.H
    table = V.Table.of_series(
        [
            (spec["phi"], [float(r["phi"][i]) for i in idx]),
            (spec["S"], [_clean(float(r["S"][i]), H) for i in idx]),
            (s1, [_clean(float(geo.divisions.S1[i]), H) for i in idx]),
            (spec["r"], [float(r["r"][i]) for i in idx]),
        ],
        index=("i", [str(i) for i in idx]),
    )
    a = V.Table.of_specs([spec["a"]], r, style="label", header=False).rows[0]
    results = V.Table(
        [*table.rows, [a[0], "", "", "", a[1]]], widths=RESULTS_W,
        height=3.5, row_h=6.5, title=WORDS("results_title"), title_height=5.0,
    )  # fmt: skip
    return [data, results]


def order_steps(sol: Solution[Geometry]) -> list[Step]:
    """The steps of the order of construction, in the order a student writes them: the base
    circle and the division, the steps of one division written for any index i ("for each
    φ_i"), the profile, then the velocity plan at the plan's division point (its pole, its
    points, the vector read off) and the similar triangle OBB′."""
    c = sol.construction
    one = 1 if len(sol.data.divisions.phi) > 1 else 0
    each = [f"axis_{one}", f"C_{one}", f"face_{one}", f"B_{one}"]
    plan = ["B", "p", "b1", "b2", "pb2", "B′"]
    names = ["base", "Δφ", *(n for n in each if n in c), "profile", *plan]
    return [_for_each(c.step(n)) if n in each else c.step(n) for n in names]


def _for_each(step: Step) -> Step:
    """A division's step written for any division: its index operand ``i`` as the letter i."""
    return dataclasses.replace(step, args=tuple((k, "i" if k == "i" else v) for k, v in step.args))


def _notes(sol: Solution[Geometry]) -> list[str]:
    """The sheet's notes, wrapped to the panel: the summary, the radius formula, what happens at
    a jump of S′."""
    geo = sol.data
    f = geo.follower
    r = sol.results
    out: list[str] = [
        WORDS("summary", rho=num(float(r["rho_min"]) * MM),
              alpha=num(float(r["pressure_angle_max_deg"]))),
    ]  # fmt: skip
    if f.kind == "flat":
        out.append(WORDS("note_radius"))
    if np.any(geo.profile.corner) and f.kind == "flat" and sol.params["law"] == "linear":
        out.append(WORDS("note_jump", a=num(float(sol.results["a"]) * MM)))
    return [line for par in out for line in wrap(par, PANEL_W, 3.0)]
