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

import math
from typing import TYPE_CHECKING

import numpy as np

from geomcad import tol
from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.cams import CamProfile, evert
from geomcad.sheet import (
    Drawing,
    Scale,
    Sheet,
    TitleBlock,
    Viewport,
    fmt_number,
    gost_scale_to_fit,
    nice_factor,
    start,
)
from geomcad.sheet.drawing import ARROW_LEN
from geomcad.sheet.graph import Axis, Graph
from geomcad.sheet.lang import Words, current
from geomcad.sheet.scale import ScaleStyle

from .spec_2013_2 import SEED_K_L

if TYPE_CHECKING:
    from geomcad.problem import Solution

WORDS = Words(__package__, "sheets_2013_2")
MM = 1000.0
#: The field the profile is drawn in (sheet mm: x0, y0, x1, y1).
VIEW = (24.0, 24.0, 274.0, 298.0)
#: Paper margin (mm) the face lines and labels take beyond the profile.
VIEW_PAD = 6.0
#: The mechanism scheme with the velocity plan (sheet mm: x0, y0, x1, y1).
SCHEME = (292.0, 26.0, 585.0, 178.0)
#: The width (mm) kept for the velocity plan at the scheme's right.
PLAN_ROOM = 126.0
#: The S(φ) graph: the data origin's x and the bottom of the axis; its room (mm). The S′(φ)
#: graph stands beside it, GRAPH_GAP mm to the right.
GRAPH = (36.0, 400.0, 150.0, 62.0)
GRAPH_GAP = 40.0
#: The right-hand panel: its left edge, width, top, and the lowest baseline it may use (the S′(φ)
#: graph starts below it).
PANEL_X = 292.0
PANEL_W = 290.0
PANEL_TOP = 182.0
BOTTOM = 326.0
#: Division points closer than this on the paper (mm) are not all labelled.
LABEL_APART = 5.0
#: The follower's stem on the scheme is at least this long on the paper (mm).
STEM_MM = 14.0
#: Rows a results table shows at most (the first, the last and evenly spaced ones between).
MAX_ROWS = 7
#: The face lines run this far (paper mm) past the contact point and the follower's axis.
FACE_OVER = 6.0
#: A plan vector shorter than this (mm) is drawn as a point with its label (twice the head).
SHORTEST = 2.0 * ARROW_LEN


def _n(x: float, digits: int = 4) -> str:
    return fmt_number(x, current(), digits)


def _style() -> ScaleStyle:
    return ScaleStyle(lang=current())


# -- scales ----------------------------------------------------------------------------------------


def extent(sol: Solution) -> tuple[float, float, float, float]:
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


def scales(sol: Solution) -> dict[str, float]:
    """k_l of the profile view: the seed's 2:1 (0.0005 m/mm) for its data when it fits; else the
    largest GOST 2.302 scale at which the profile fits the field."""
    x0, y0, x1, y1 = extent(sol)
    w, h = x1 - x0, y1 - y0
    room_w, room_h = VIEW[2] - VIEW[0] - 2 * VIEW_PAD, VIEW[3] - VIEW[1] - 2 * VIEW_PAD
    if sol.is_seed and w / SEED_K_L <= room_w and h / SEED_K_L <= room_h:
        return {"l": SEED_K_L}
    return {"l": gost_scale_to_fit(w, h, room_w, room_h).k}


def sheets(sol: Solution) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-2."""
    k = Scale(sol.scales["l"], "l")
    tb = TitleBlock(title=WORDS("tb_title"), designation=WORDS("designation"), scale=k.ratio_text())
    d = start("A2", tb)
    d.text(WORDS("profile_title"), (VIEW[0], 13.0), 5.0)
    d.text(WORDS("scale_line", label=k.label(_style()), ratio=k.ratio_text() or "—"),
           (VIEW[0], 20.0), 3.5)  # fmt: skip
    _profile_view(d, sol, k)
    _graph(d, sol)
    _scheme(d, sol)
    _panel(d, sol)
    return [("", d.finish())]


# -- the profile by inversion ----------------------------------------------------------------------


def _profile_view(d: Drawing, sol: Solution, k: Scale) -> None:
    geo = sol.data
    f = geo.follower
    prof, div = geo.profile, geo.divisions
    x0, y0, x1, y1 = extent(sol)
    at = ((VIEW[0] + VIEW[2]) / 2.0, (VIEW[1] + 6.0 + VIEW[3]) / 2.0)
    v = d.viewport(k, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at)
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
        v.arrow(o, B, "result")
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
    # the radius vectors, dimensioned as radii: the line from o, its arrow at B_i, the value
    for i in sorted(shown):
        B = Vec(*div.contact[i])
        text = f"r_{{{i}}} = {_n(float(div.radius[i]) * MM)}"
        spots = tuple(v.p(B * t) for t in (0.6, 0.8, 0.5, 0.9, 0.4))
        d.label(v.p(B * 0.7), text, 2.5, others=spots)
    # the angle of one interval, between the last two axes
    if n >= 2:
        a0 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-2]))
        a1 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-1]))
        dphi = math.degrees(float(div.phi[-1] - div.phi[-2]))
        v.dim_angle(o, a0, a1, f"{_n(dphi)}°", r_mm=k.mm(f.r0) * 0.55, height=2.5)


def _rest(v: Viewport, sol: Solution, rest: CamProfile, over: float) -> None:
    """The profile past the span to the program's end in thin lines, with the follower's axis at
    the end (thin) and a note of where the program ends; the note under the title says what the
    thin line is."""
    f = sol.data.follower
    if f.kind == "roller":
        v.polyline(list(rest.pitch), "centre")
    v.polyline(list(rest.contact), "thin")
    end = float(rest.phi[-1])
    up = Vec(0.0, 1.0).rotated(-f.sigma * end)
    foot = Vec(1.0, 0.0).rotated(-f.sigma * end) * (f.e if f.kind != "flat" else 0.0)
    C = Vec(*rest.pitch[-1])
    v.seg(foot, C + up * over, "construction")
    v.label(C + up * over, WORDS("rest_end", phi=_n(math.degrees(end))), 2.5,
            prefer=(up.x, up.y), clear=0.5)  # fmt: skip
    span = math.degrees(float(sol.data.span))
    v.d.text(WORDS("rest_note", span=_n(span), end=_n(math.degrees(end))), (VIEW[0], 26.0), 2.5)


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


def _graph(d: Drawing, sol: Solution) -> None:
    """The follower's law S(φ) and its analogue of velocity S′(φ) = dS/dφ (the length BC = OB′
    of the scheme), side by side, with the ordinates of the division points."""
    geo = sol.data
    prog = geo.program
    end = 2.0 * math.pi if geo.closed else prog.total
    x_at, y_at, room_w, room_h = GRAPH
    phi = np.linspace(0.0, end, 721)
    motion = prog.motion(phi)
    div = geo.divisions
    n = len(div.phi)
    step = _label_step(n)
    law = WORDS(f"law_{sol.params['law']}")
    d.text(WORDS("graph_title", law=law), (x_at - 6.0, y_at - room_h - 17.0), 5.0)
    for j, (sym, unit, ys, at_div) in enumerate(
        (
            ("S", WORDS("unit_m"), motion.S, div.S),
            ("S'", WORDS("unit_m"), motion.S1, div.S1),
        )
    ):
        lo, hi = min(0.0, float(np.min(ys))), max(0.0, float(np.max(ys)))
        gx = Axis.fit("φ", WORDS("unit_rad"), 0.0, end, room_w)
        gy = Axis.fit(sym, unit, lo, hi, room_h)
        x0 = x_at + j * (room_w + GRAPH_GAP)
        # the data's lowest value on the bottom line y_at (the zero above it when S′ < 0)
        g = Graph(d, gx, gy, (x0, y_at - gy.mm(0.0 - lo)))
        g.axes(current(), tick_labels=True)
        g.curve(phi.tolist(), ys.tolist(), "link")
        for i in range(n):
            g.ordinate(float(div.phi[i]), float(at_div[i]), str(i) if i % step == 0 else "")
        g.factors((x0 + room_w * 0.35, g.box[1] - 5.0), current())


# -- the scheme and the velocity plan --------------------------------------------------------------


def _scheme(d: Drawing, sol: Solution) -> None:
    """The mechanism at the plan's division point, in the fixed frame: the cam (the built profile
    thick, the rest of the program thin), the follower, the triangle OBB′ (and C); links numbered
    (1 the cam, 2 the follower, 3 the roller); beside it the velocity plan pb₁b₂ at its own
    factor."""
    geo = sol.data
    f = geo.follower
    plan = geo.plan
    phi = plan.phi
    cam = evert(geo.profile.contact, np.full(len(geo.profile.phi), phi), f.sigma)
    rest = (
        evert(geo.rest.contact, np.full(len(geo.rest.phi), phi), f.sigma)
        if geo.rest is not None
        else np.zeros((0, 2))
    )
    width = float(np.max(np.abs(geo.profile.S1))) + 0.2 * f.r0
    h = float(plan.B.y)
    x0, y0, x1, y1 = SCHEME
    room_w, room_h = x1 - x0 - PLAN_ROOM - 8.0, y1 - y0 - 4.0
    stem = 0.25 * f.r0
    # the stem starts at the face, the knife's tip or the roller's top
    base = h + (f.r_roller if f.kind == "roller" else 0.0)
    every = np.vstack([cam, rest]) if len(rest) else cam
    for _ in range(2):  # the stem is at least STEM_MM long on the paper
        xs = [*every[:, 0], -f.r0, f.r0, -width, width]
        ys = [*every[:, 1], -f.r0, base + stem]
        w_m, h_m = max(xs) - min(xs), max(ys) - min(ys)
        kl = gost_scale_to_fit(w_m, h_m, room_w, room_h)
        stem = max(0.25 * f.r0, kl.model(STEM_MM))
    left = x0 + 2.0 + (room_w - kl.mm(w_m)) / 2.0
    v = d.viewport(kl, (min(xs), (max(ys) + min(ys)) / 2.0), (left, (y0 + 4.0 + y1) / 2.0))
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
    _right_angle(v, Bp, o, B)
    for q in (o, B, Bp):
        v.dot(q, "point")
    v.label(o, "O", prefer=(-away, 1.0), clear=1.5)
    v.label(B, "B", prefer=(-away, 1.0))
    v.label(Bp, "B'", prefer=(-away, -1.0))
    if f.kind == "flat":
        v.label(C, "C", prefer=(away, -1.0))
    if abs(plan.S1) > 0.0:
        v.dim_linear(o, Bp, "S'", offset=-3.0 if Bp.x > 0 else 3.0, height=2.5)
    k_i = geo.plan_index
    d.text(WORDS("scheme_title", i=k_i, phi=_n(math.degrees(phi))), (x0, y0 - 7.0), 5.0)
    eq = "OB' = BC = S'" if f.kind == "flat" else "OB' = S'"
    d.text(WORDS("scheme_scale", label=kl.label(_style()), ratio=kl.ratio_text(), eq=eq),
           (x0, y0 - 1.0), 2.5)  # fmt: skip
    _plan(d, sol)


def plan_factor(sol: Solution) -> Scale:
    """μ_V of the velocity plan: the smallest factor (1, 2, 2.5, 4 or 5 × 10^n) at which the
    plan fits its room; every vector is drawn at it."""
    plan = sol.data.plan
    pts = [Vec(0.0, 0.0), plan.V_B1, plan.V_B2]
    pw = max(q.x for q in pts) - min(q.x for q in pts)
    ph = max(q.y for q in pts) - min(q.y for q in pts)
    room_w, room_h = PLAN_ROOM - 16.0, SCHEME[3] - SCHEME[1] - 40.0
    return nice_factor(max(pw * room_h / room_w, ph, plan.V_B1.norm * 0.1), room_h, "v")


def _plan(d: Drawing, sol: Solution) -> None:
    """The velocity plan: pb1 = V_B1 ⊥ OB, pb2 = V_B2 along the motion, b1b2 = V_B2B1, each at
    μ_V exactly; a vector under two arrowheads is drawn as a point and the sheet says so."""
    plan = sol.data.plan
    kv = plan_factor(sol)
    _, y0, x1, y1 = SCHEME
    pts = [Vec(0.0, 0.0), plan.V_B1, plan.V_B2]
    # the plan centred in its room under the scheme's title
    cx = (min(q.x for q in pts) + max(q.x for q in pts)) / 2.0
    cy = (min(q.y for q in pts) + max(q.y for q in pts)) / 2.0
    px0 = x1 - PLAN_ROOM
    pv = d.viewport(kv, (cx, cy), (px0 + PLAN_ROOM / 2.0, y0 + 14.0 + (y1 - y0 - 40.0) / 2.0))
    pole = Vec(0.0, 0.0)
    b1, b2 = plan.V_B1, plan.V_B2
    short: list[str] = []
    for a, b, name in ((pole, b1, "V_{B1}"), (pole, b2, "V_{B2}"), (b1, b2, "V_{B2B1}")):
        length = kv.mm((b - a).norm)
        if length >= SHORTEST:
            pv.arrow(a, b, "vector")
        elif length > 0.0:
            pv.dot(b, "point")
            short.append(WORDS("plan_short", name=name, value=_n(length, 3)))
    pv.dot(pole, "point")
    pv.label(pole, "p", height=3.5, prefer=(1.0, -1.0))
    pv.label(b1, "b_1", height=3.5, prefer=(-1.0, 0.0))
    pv.label(b2, "b_2", height=3.5, prefer=(1.0, 1.0))
    low = max(pv.p(q)[1] for q in pts) + 10.0
    d.text(WORDS("plan_title"), (px0 + 2.0, low), 3.5)
    d.text(kv.label(_style()), (px0 + 2.0, low + 4.5), 2.5)
    yy = d.text(WORDS("plan_omega"), (px0 + 2.0, low + 8.5), 2.5).at[1]
    for text in short:
        yy = d.paragraph(text, px0 + 2.0, yy + 1.0, PLAN_ROOM - 4.0, 2.5)


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


def _right_angle(v: Viewport, vertex: Vec, a: Vec, b: Vec, size_mm: float = 2.5) -> None:
    s = v.scale.model(size_mm)
    if (a - vertex).norm == 0.0 or (b - vertex).norm == 0.0:
        return
    ua, ub = (a - vertex).unit() * s, (b - vertex).unit() * s
    v.polyline([vertex + ua, vertex + ua + ub, vertex + ub], "construction")


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


def _panel(d: Drawing, sol: Solution) -> None:
    p, r, geo = sol.params, sol.results, sol.data
    x, y = PANEL_X, PANEL_TOP
    d.text(WORDS("data_title"), (x, y + 3.5), 5.0)
    law = str(p["law"])
    mm = WORDS("mm")
    rise, dwell, ret = (_n(float(p[n])) for n in ("phi_rise_deg", "phi_dwell_deg",
                                                  "phi_return_deg"))  # fmt: skip
    step_deg = _n(math.degrees(geo.span) / int(p["n_div"]), 3)
    e_mm, rr_mm = (_n(float(p[n]) * MM) for n in ("e", "r_roller"))
    rows = [
        [WORDS("c_H"), f"{_n(float(p['H']) * MM)} {mm}", WORDS("c_rise"), f"{rise}°",
         WORDS("c_law"), WORDS(f"short_{law}")],
        [WORDS("c_r0"), f"{_n(float(p['r0']) * MM)} {mm}", WORDS("c_dwell_ret"),
         f"{dwell}° / {ret}°", WORDS("c_follower"), WORDS(f"f_{p['follower']}")],
        [WORDS("c_intervals"), f"{p['n_div']} × {step_deg}°", WORDS("c_omega"),
         WORDS("ccw" if int(p["omega_sign"]) > 0 else "cw"), WORDS("c_offsets"),
         f"{e_mm} / {rr_mm} {mm}"],
    ]  # fmt: skip
    widths = (30.0, 44.0, 38.0, 54.0, 46.0, 58.0)
    _, h = d.table(x, y + 7.0, widths, rows, height=3.5, row_h=6.0, header=False)
    y += 7.0 + h + 7.0
    d.text(WORDS("results_title"), (x, y + 3.5), 5.0)
    rows = [[WORDS(f"h_{q}") for q in ("i", "phi", "S", "S1", "r")]]
    n = len(r["phi"])
    for i in _rows(n):
        rows.append(
            [
                str(i),
                _n(math.degrees(float(r["phi"][i]))),
                _n(_clean(float(r["S"][i]), geo.program.H) * MM),
                _n(_clean(float(geo.divisions.S1[i]), geo.program.H) * MM),
                _n(float(r["r"][i]) * MM),
            ]
        )
    rows.append(["a", "", "", "", _n(float(r["a"]) * MM)])
    r_widths = (30.0, 60.0, 60.0, 60.0, 60.0)
    _, h = d.table(x, y + 7.0, r_widths, rows, height=3.5, row_h=6.5)
    y += 7.0 + h + 2.0
    summary = WORDS(
        "summary",
        rho=_n(float(r["rho_min"]) * MM),
        alpha=_n(float(r["pressure_angle_max_deg"])),
    )
    for text in [summary, *_notes(sol)]:
        y = d.paragraph(text, x, y, PANEL_W, 3.0) + 0.8
    order = _order(sol)
    if y + 9.0 + 5.0 * len(order) <= BOTTOM:
        y = d.text(WORDS("order_title"), (x, y + 7.0), 5.0).at[1] + 1.5
        for i, step in enumerate(order):
            y = d.paragraph(f"{i + 1}. {step}", x, y, PANEL_W, 3.0, indent=5.0) + 0.3


def _order(sol: Solution) -> list[str]:
    """The construction by inversion, step by step (one line each)."""
    kind = sol.data.follower.kind
    return [
        WORDS("order_1"),
        WORDS(
            "order_2",
            lay=WORDS("lay_flat" if kind == "flat" else "lay_other"),
            what=WORDS(f"what_{kind}"),
        ),
        WORDS("order_3", last=WORDS(f"last_{kind}")),
    ]


def _notes(sol: Solution) -> list[str]:
    """The sheet's notes: the radius formula, what happens at a jump of S′."""
    geo = sol.data
    f = geo.follower
    out: list[str] = []
    if f.kind == "flat":
        out.append(WORDS("note_radius"))
    if np.any(geo.profile.corner) and f.kind == "flat" and sol.params["law"] == "linear":
        out.append(WORDS("note_jump", a=_n(float(sol.results["a"]) * MM)))
    return out
