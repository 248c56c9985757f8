"""2013-5's drawing sheet: the kinematic scheme, Smirnov's plan of linear velocities, the angle
diagram, and the tables.

A3 landscape. Left: the scheme (GOST 2.770) in the section through the central axis and the axis
O_25 of block 2-5, radii to scale (r = m·z/2) at k_l: shafts and carriers as main lines, each gear
as its web with the rim at its pitch radius, an internal gear as a cup open towards its mesh, the
pitch lines dash-dot through the pitch points; the frame's bearings and the fixed gear 3 hatched.
Beside it, on the same radii, the plan of linear velocities at k_v: horizontal lines carry each
point's level across, the velocities are arrows from the axis v = 0, and each link's line passes
through the ends of its points. Below: the angle diagram from pole S, its rays parallel to the
links' lines cut the line at H above S in segments ω/k_ω. Right: the data, the results (Willis),
the angular velocities three ways (mesh equations, slopes, angle diagram) and the order of
construction. A velocity shorter than two arrowheads is drawn as its end point and named in a
note under the plan.

Composed (geomcad.sheet.compose): the scheme and the plan are one Figure in metres at k_l (the
plan's velocities drawn as lengths at k_l/k_v, so the levels carry across), the angle diagram a
second Figure at the same k_l, the tables and the order of construction views of their own. The
tree is rebuilt until k_l (the layout's) and k_v (the plan's factor for the room the scheme
leaves in its box) settle; μ_ω follows from them.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from geomcad.geom import Vec
from geomcad.sheet import (
    Scale,
    Sheet,
    Viewport,
)
from geomcad.sheet.views import factor, num

if TYPE_CHECKING:
    from geomcad.construction import Construction
    from geomcad.problem import Solution

    from .p2013_5 import Geometry

from geomcad.kinematics.trains import RayPlan
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Extent,
    Field,
    Figure,
    Layout,
    Node,
    Row,
    Spacer,
    View,
    arrange,
)
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.form import composed
from geomcad.sheet.gearing import gear_web, ground_line, ring_gear, shaft_bearing
from geomcad.sheet.lang import Words
from geomcad.sheet.scale import WORDS as SCALE_WORDS
from geomcad.sheet.scale import gost_length_scale, nice_factor
from geomcad.sheet.trains import AngleDiagram, linear_velocities, scaled_rays

from .p2013_5 import BLOCK25, FRAME, H1, H2, PLANET, SUN
from .spec_2013_5 import PARAMS, RESULTS

#: Sizes (mm): the gap between the scheme and the plan; the room kept for labels left of the
#: scheme, right of the plan, under them (the axis' name and the note) and over them (the
#: titles); the scheme's greatest height (the first guess of k_l); the scheme's unit
#: u = (radii spanned)/SCHEME_UNITS; the angle diagram's greatest width and pole distance.
GAP = 14.0
PAD_L, PAD_R, PAD_B, PAD_T = 6.0, 7.0, 24.0, 14.0
SCHEME_H = 140.0
SCHEME_UNITS = 14.5
RAY_W = 177.0
RAY_H = 40.0
#: Width (mm) of the order of construction.
ORDER_W = 148.0

#: The kinds of the steps the order of construction lists (geomcad.kinematics.trains' plan of
#: linear velocities and its angle diagram, then the ratio read off the diagram).
ORDER_KINDS = (
    "train_radii",
    "train_rest",
    "train_start",
    "train_line",
    "train_point",
    "ray_plan",
    "ratio_rays",
)

WORDS = Words(__package__, "sheets_2013_5")


#: How the links are named on the sheet.
LINK_LABEL = {SUN: "1", BLOCK25: "2–5", PLANET: "6", H1: "H_1–4", H2: "H_2–7", FRAME: "0"}


def _factors(geo: Geometry) -> tuple[float, float]:
    """The first guess of the layout's factors: k_l of the scheme (the largest GOST 2.302 scale
    at which its radii fit SCHEME_H), k_v of the plan (its velocities in half that height: a
    narrow plan first, so that the layout can give the scheme its largest scale)."""
    y_lo, y_hi = geo.extent
    k_l = gost_length_scale(y_hi - y_lo, SCHEME_H).k
    v_ends = [e.x for e in geo.plan.ends.values()]
    v_span = max(max(v_ends), 0.0) - min(min(v_ends), 0.0)
    return k_l, nice_factor(v_span, 0.5 * SCHEME_H, "v").k


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-5."""
    tree, lay, k_l, _, _ = _arranged(sol)
    k = Scale(k_l, "l")
    return [("", composed("A3", tree, WORDS, k.ratio_text(), lay))]


def _build_box(geo: Geometry, k_l: float, k_v: float) -> Extent:
    """The model box (m, at k_l) of the scheme and the plan beside it: the plan's velocities
    drawn at k_v as lengths k_l/k_v, the gap and the room for the labels (paper mm) at k_l."""
    y_lo, y_hi = geo.extent
    u = (y_hi - y_lo) / SCHEME_UNITS
    v_ends = [e.x for e in geo.plan.ends.values()]
    right = _x_end(u) + 0.4 * u
    plan_w = (max(max(v_ends), 0.0) - min(min(v_ends), 0.0)) * k_l / k_v
    y_min = min(p.y for p in geo.points)
    bottom = min(y_lo - 0.9 * u - 4.0 * k_l, y_min - PAD_B * k_l)
    return (-0.4 * u - PAD_L * k_l, bottom, right + (GAP + PAD_R) * k_l + plan_w,
            y_hi + PAD_T * k_l)  # fmt: skip


def _tree(sol: Solution[Geometry], k_l: float, k_v: float) -> tuple[Node, dict[str, View], float]:
    """The sheet's views at the factors k_l, k_v: the heading, the scheme with the plan, the
    angle diagram under them, the panel on the right; and μ_ω of the angle diagram."""
    geo = sol.data
    k, kv = Scale(k_l, "l"), Scale(k_v, "v")
    om = [abs(w) for w in geo.plan.omega.values()]
    k_omega = max(nice_factor(max(om), RAY_W, "v").k, nice_factor(k_v / k_l, RAY_H, "v").k)
    rays = scaled_rays(geo.rays, k_v, k_omega)
    build = Figure(_build_box(geo, k_l, k_v), lambda v: _build(v, geo, kv), group="l",
                   margin=0.5, weight=2.0)  # fmt: skip
    ray_view = AngleDiagram(
        rays, k_l, kv, LINK_LABEL, (SUN, H2, "u_{1H2} = ω_1/ω_{H2}"), group="l", margin=1.0,
        title=WORDS("rays_title", k=num(k_omega, 6)), show_scale=False,
    )  # fmt: skip
    head = V.Text(paragraph=WORDS("title"), width=160.0, height=5.0)
    factors = V.Text(
        lines=[
            f"{factor(k)} ({SCALE_WORDS('ratio', ratio=k.ratio_text() or '—')});  {factor(kv)};  "
            f"μ_ω = {num(k_omega, 6)} {WORDS('rad_s_mm')}"
        ],
        height=3.5,
    )
    field = Field.of_format("A3")
    tb = Spacer((10.0, field.box[3] - field.obstacles[0][1]))
    tree = Row(Column(head, factors, build, ray_view), Column(*_panel(sol, rays, k_v), tb))
    return tree, {"build": build, "rays": ray_view}, k_omega


def _arranged(sol: Solution[Geometry]) -> tuple[Node, Layout, float, float, float]:
    """The tree rebuilt until its factors settle: k_l is the layout's, k_v the plan's factor
    for the room the scheme leaves in the view's box (the plan's width depends on both)."""
    geo = sol.data
    y_lo, y_hi = geo.extent
    u = (y_hi - y_lo) / SCHEME_UNITS
    v_ends = [e.x for e in geo.plan.ends.values()]
    v_span = max(max(v_ends), 0.0) - min(min(v_ends), 0.0)
    k_l, k_v = _factors(geo)
    field = Field.of_format("A3")
    least_v = 0.0  # once the plan was narrowed for the scheme's scale, k_v stays that coarse
    for _ in range(8):
        tree, views, k_omega = _tree(sol, k_l, k_v)
        lay = arrange(tree, field)
        placed = lay[views["build"]]
        assert placed.scale is not None
        nk_l = placed.scale.k
        if nk_l > k_l and least_v < k_v:
            # the scheme would lose its scale: a narrower plan (the next coarser k_v) first
            k_v = least_v = nice_factor(v_span, 0.99 * v_span / k_v, "v").k
            continue
        scheme_w = (_x_end(u) + 0.8 * u) / nk_l + PAD_L
        room = placed.inner[2] - placed.inner[0] - scheme_w - GAP - PAD_R
        nk_v = max(nice_factor(v_span, max(room, 1.0), "v").k, least_v)
        if (nk_l, nk_v) == (k_l, k_v):
            break
        k_l, k_v = nk_l, nk_v
    return tree, lay, k_l, k_v, k_omega


def scales(sol: Solution[Geometry]) -> Mapping[str, float]:
    """The sheet's factors: k_l of the scheme and k_v of the plan of linear velocities."""
    _, _, k_l, k_v, _ = _arranged(sol)
    return {"l": k_l, "v": k_v}


def _build(v: Viewport, geo: Geometry, kv: Scale) -> None:
    """The scheme and, beside it on the same levels, the plan of linear velocities."""
    y_lo, y_hi = geo.extent
    u = (y_hi - y_lo) / SCHEME_UNITS
    right, spots = _scheme(v, geo, u)
    top = v.p(Vec(0.0, y_hi))[1]
    d = v.d
    d.text(WORDS("scheme"), (v.p(Vec(-0.4 * u, 0.0))[0], top - 12.0), 3.5)
    x_axis = right + GAP + (-min(0.0, *(e.x for e in geo.plan.ends.values()))) / kv.k
    vp = d.viewport(v.scale, (0.0, y_hi), (x_axis, top))
    d.text(WORDS("plan"), (right + GAP, top - 12.0), 3.5)
    short = linear_velocities(v, vp, geo.points, geo.plan, kv, spots, LINK_LABEL, WORDS("v0"))
    if short:
        names = ", ".join(n.lower() for n in short)
        # the note under the plan, below the axis' own label
        y_note = vp.p(Vec(0.0, min(p.y for p in geo.points)))[1] + 12.0
        note = WORDS("short", names=names, mm=num(SHORT_MM, 2))
        v_ends = [e.x for e in geo.plan.ends.values()]
        width = (max(max(v_ends), 0.0) - min(min(v_ends), 0.0)) / kv.k + PAD_R
        d.paragraph(note, right + GAP, y_note, max(width, 60.0), 2.5)


# -- the scheme ----------------------------------------------------------------------------------
# Hand-laid, on purpose, from the general symbols of geomcad.sheet.gearing: the radii are the
# model's (r = m·z/2), but where each gear sits along its shaft is the drawing's choice (the
# model has no axial dimension), so the axial positions are multiples of the unit u (the radii
# spanned / SCHEME_UNITS), laid as the seed draws the train.


def _x_end(u: float) -> float:
    """The output shaft's free end (model x) on the scheme of unit u."""
    return 10.8 * u + 0.35 * u + 0.6 * u + 2.6 * u


def _scheme(v: Viewport, geo: Geometry, u: float) -> tuple[float, dict[str, Vec]]:
    """Draw the scheme; return its right edge on the sheet (mm) and where each point of the plan
    lies on it."""
    z, m, a = geo.z, geo.m, geo.a
    r = {k: m * zz / 2.0 for k, zz in z.items()}
    b = 0.7 * u
    dlt = v.scale.model(1.2)  # half the gap between a sleeve and the shaft inside it
    x1, x3, xh1, x5 = 3.0 * u, 6.5 * u, 9.0 * u, 10.8 * u
    xw2 = x1 + b / 2.0 + 0.6 * u
    xw7 = x5 + b / 2.0 + 0.6 * u
    x_end = _x_end(u)
    y_e = a + r["5"] + r["6"]
    y_ground = geo.extent[0] - 0.9 * u  # the frame's supports all stand on this level
    # axes
    v.seg(Vec(-0.4 * u, 0.0), Vec(x_end + 0.4 * u, 0.0), "centre")
    v.seg(Vec(xw2 - 0.4 * u, a), Vec(xw7 + 0.5 * u, a), "centre")
    v.seg(Vec(xh1 - 0.3 * u, y_e), Vec(x5 + b / 2.0 + 0.3 * u, y_e), "centre")
    # input shaft 1 and the sun 1
    v.seg(Vec(0.0, 0.0), Vec(x1, 0.0), "link")
    gear_web(v, x1, 0.0, r["1"], b)
    shaft_bearing(v, Vec(1.2 * u, 0.0), True, -y_ground)
    # block 2-5: the ring 2, the shaft along O_25, the pinion 5
    ring_gear(v, x1, xw2, a, r["2"], b)
    v.seg(Vec(xw2, a), Vec(xw7, a), "link")
    gear_web(v, x5, a, r["5"], b)
    # gear 3, fixed: its web on a post to the frame
    gear_web(v, x3, 0.0, r["3"], b)
    post = Vec(x3, y_ground)
    v.seg(Vec(x3, -r["3"]), post, "link")
    ground_line(v, post)
    # block H1-4: the sleeve round the shaft 2-5, gear 4, the arm H1 and the planet's axle
    for s in (1, -1):
        v.seg(Vec(x3 - b / 2.0, a + s * dlt), Vec(xh1, a + s * dlt), "link")
    gear_web(v, x3, a, r["4"], b, hub=dlt)
    v.seg(Vec(xh1, a + dlt), Vec(xh1, y_e), "link")
    v.seg(Vec(xh1, y_e), Vec(x5, y_e), "link")
    # the planet 6 (the one on the far side of O_25)
    gear_web(v, x5, y_e, r["6"], b)
    shaft_bearing(v, Vec(0.5 * (xh1 + x5), y_e), False)
    # block H2-7: the ring 7, its web carrying the shaft 2-5, the arm to the central axis and
    # the output shaft
    ring_gear(v, x5, xw7, a, r["7"], b)
    v.seg(Vec(xw7, min(a - r["7"], 0.0)), Vec(xw7, max(a - r["7"], 0.0)), "link")
    v.seg(Vec(xw7, 0.0), Vec(x_end, 0.0), "link")
    shaft_bearing(v, Vec(xw7, a), False)
    shaft_bearing(v, Vec(xw7 + 1.4 * u, 0.0), True, -y_ground)
    # pitch lines through the pitch points, and the points of the plan
    ext = b / 2.0 + 0.35 * u
    meshes = {"A": x1, "C": x3, "D": x5, "F": x5}
    for p in geo.points:
        if p.name in meshes:
            xm = meshes[p.name]
            v.seg(Vec(xm - ext, p.y), Vec(xm + ext, p.y), "centre")
    spots = {"O": Vec(x1, 0.0), "B": Vec(x5, a), "E": Vec(x5, y_e)}
    spots.update(
        {n: Vec(xm, next(p.y for p in geo.points if p.name == n)) for n, xm in meshes.items()}
    )
    geo_spots = {p.name: spots[p.name] for p in geo.points}
    for name, q in geo_spots.items():
        v.dot(q, "result")
        v.label(q, name, 2.5, prefer=(-1.0, 1.0), clear=0.8)
    # the links' numbers
    for text, q, pref in (
        ("1", Vec(0.4 * u, 0.0), (0.0, 1.0)),
        ("2", Vec(xw2, a + 0.55 * r["2"]), (1.0, 0.0)),
        ("3", Vec(x3, -0.55 * r["3"]), (1.0, 0.0)),
        ("4", Vec(x3, a + 0.6 * r["4"]), (-1.0, 0.0)),
        ("5", Vec(x5, a - 0.6 * r["5"]), (1.0, 0.0)),
        ("6", Vec(x5, y_e + 0.5 * r["6"]), (1.0, 0.0)),
        ("7", Vec(xw7, a + 0.8 * r["7"]), (1.0, 0.0)),
        ("H_1", Vec(xh1, 0.5 * (a + y_e)), (-1.0, 0.0)),
        ("H_2", Vec(x_end - 0.5 * u, 0.0), (0.0, 1.0)),
    ):
        v.label(q, text, 3.5, prefer=pref, clear=1.0)
    # the input and output named at the shafts' free ends, clear of the links' numbers
    v.label(Vec(-0.4 * u, 0.0), WORDS("input"), 2.5, prefer=(-1.0, 0.0), clear=0.5)
    v.label(Vec(x_end + 0.4 * u, 0.0), WORDS("output"), 2.5, prefer=(1.0, -1.0), clear=0.8)
    return v.p(Vec(x_end + 0.4 * u, 0.0))[0], geo_spots


# -- the tables ----------------------------------------------------------------------------------


def _panel(sol: Solution[Geometry], rays: RayPlan, k_v: float) -> list[View]:
    """The data, the results (Willis), the angular velocities three ways, the order of
    construction."""
    p, r, geo = sol.params, sol.results, sol.data
    by = {s.name: s for s in PARAMS}
    given = {**p, **{n: str(r[n]) + ("*" if n not in p else "") for n in ("z4", "z7")}}
    data = V.Table.of_specs(
        [by[n] for n in ("z1", "z2", "z3", "z4", "z5", "z6", "z7", "m")], given, style="label",
        transpose=True, widths=(18.0,) * 7 + (24.0,), row_h=5.5, title=WORDS("data"),
    )  # fmt: skip
    coaxial = V.Text(lines=[WORDS("coaxial")])
    top, den = r["u1H2_fraction"]
    u = num(float(r["u1H2"]), 4)
    shown = {**r, "u1H2": f"{top}/{den} = {u}" if den != 1 else u}
    results = V.Table.of_specs(RESULTS, shown, style="value", widths=(36.0, 60.0), row_h=5.5,
                               title=WORDS("results"))  # fmt: skip
    rows = [[WORDS("link"), WORDS("by_meshes"), WORDS("by_slopes"), WORDS("by_rays")]]
    for link in (SUN, BLOCK25, PLANET, H1, H2):
        exact = geo.omega_exact[link]
        ray_mm = (rays.ends[link].x - rays.S.x) / k_v
        rows.append(
            [
                LINK_LABEL[link],
                str(exact) if exact.denominator == 1 else f"{exact} = {num(float(exact), 4)}",
                num(geo.plan.omega[link], 4),
                num(ray_mm, 4),
            ]
        )
    omegas = V.Table(rows, widths=(18.0, 58.0, 36.0, 34.0), row_h=5.5, title=WORDS("omegas"))
    order = V.Steps(sol.construction, ORDER_W, only=order_steps(sol.construction), words=WORDS)
    return [data, coaxial, results, omegas, order]


def order_steps(c: Construction) -> list[str]:
    """The steps the order of construction lists: the plan of linear velocities and the plan
    of angular velocities as recorded (:data:`ORDER_KINDS`), in their recorded order."""
    return [s.name for s in c if s.kind in ORDER_KINDS]
