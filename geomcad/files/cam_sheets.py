"""The cam design sheet (A1 landscape).

Left: the follower's law over the turn — S (ψ for a rocker), its first and second velocity
analogues, each exact (solid) with the graphical differentiation by chords beside it (dashed, its
points at the middles of the intervals between the division points) — and the pressure angle
over the turn with the allowed angles. Middle: the diagram the cam's size comes from — S against
−σS′ with the zone's boundary rays (translating), the arm's positions, the points C and the
active rays (rocker), S against S″ with the 45° tangent (flat face) — with B0, the zone's point
O_min and the chosen centre O. Right: the profile by inversion at a GOST scale with the base
circle, the pitch curve, the follower turned back to the division points and the radius vectors;
under it the tables of the data and the results.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad import tol
from geomcad.geom import Vec
from geomcad.kinematics import cam_design as cd
from geomcad.kinematics.cams import CamProfile, Follower, at_angles
from geomcad.sheet import TitleBlock, Viewport, fmt_number
from geomcad.sheet.cams import Division, Inversion
from geomcad.sheet.compose import Choice, Column, Figure, Row, Tree, compose
from geomcad.sheet.formats import Sized, choose
from geomcad.sheet.graph import Graph
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.placer import DimText
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.sheet.views import AxisSpec, Curve, Diagram, Steps, Table, Text

from .cam import RESULTS
from .common import sheet_formats

if TYPE_CHECKING:
    from geomcad.problem import Solution
    from geomcad.sheet import Sheet

    from .cam import CamDesign

#: The sheet's words, per language (geomcad/files/strings/<lang>/cam_sheets.toml).
WORDS = Words(__package__, "cam_sheets")
MM = 1000.0
#: Width (mm) of the notes under the tables.
NOTE_W = 130.0
#: A division point within this fraction of the stroke of the φ axis is drawn on it; its number
#: is written NUMBER_LIFT mm above the axis.
ON_AXIS, NUMBER_LIFT = 0.005, 4.0
#: The law graphs' least and preferred sizes (mm).
LAW_LEAST, LAW_PREFER = (130.0, 70.0), (280.0, 120.0)


def _tree(sol: Solution[CamDesign]) -> tuple[Tree, Inversion, Figure]:
    """The sheet as a composition: the law and its analogues with the pressure angle (or the
    curvature) in a column, the diagram of the cam's size over the tables and notes, and the
    profile (the main view, at the GOST scale the layout picks)."""
    des = sol.data
    profile = _profile(des)
    graphs = [*_laws(des), _pressure(des)]
    laws = Column(*graphs)
    data, res = _tables(des, sol.results)
    diagram = _diagram(des)
    phases, note = _notes(des), _order(sol)
    tables = Row(data, res)
    tree = Choice(
        Row(laws, Column(diagram, tables, phases, note), profile),
        Row(laws, Column(Row(diagram, profile), Row(tables, Column(phases, note)))),
        Column(Row(*graphs), Row(diagram, profile, Column(data, res, phases, note))),
    )
    return tree, profile, diagram


#: The profile and the diagram of the cam's size at 1:1 or larger (where a sheet up to A1 allows):
#: the scale a cam is drawn and measured at.
WANT_K = 0.001


@per_language
def _sized(sol: Solution[CamDesign]) -> tuple[Tree, Inversion, Figure, Sized]:
    """The views and the format they take: the smallest on which the profile and the diagram
    reach 1:1 and the laws their least size (or the file's ``[sheet] format``)."""
    tree, profile, diagram = _tree(sol)
    sized = choose(
        tree, {profile: WANT_K, diagram: WANT_K}, sheet_formats(sol.problem.inputs or {})
    )
    return tree, profile, diagram, sized


def designation(sol: Solution[Any]) -> str:
    """The document's designation from its file's title, else its name (as a linkage file's:
    :func:`geomcad.files.code`), so that every design file is its own document;
    ``designation`` in [sheet] or ``--designation`` override it."""
    from geomcad.files import code

    title = (sol.problem.inputs or {}).get("title", "")
    return WORDS("designation", stem=code(sol.problem.id, str(title)) or "CAM")


def scales(sol: Solution[CamDesign]) -> dict[str, float]:
    """k_l of the profile view: the GOST scale the layout gives it (``Problem.scales``)."""
    _, profile, _, sized = _sized(sol)
    scale = sized.layout[profile].scale
    assert scale is not None
    return {"l": scale.k}


def sheets(sol: Solution[CamDesign]) -> list[tuple[str, Sheet]]:
    tree, profile, _, sized = _sized(sol)
    k = sized.layout[profile].scale
    assert k is not None
    tb = TitleBlock(title=WORDS("tb_title"), designation=designation(sol), scale=k.ratio_text())
    d = sized.start(tb)
    compose(d, tree, layout=sized.layout)
    return [("", d.finish())]


# -- the law and its analogues ---------------------------------------------------------------------


def _law_values(des: CamDesign) -> tuple[float, float, str, str, str, str]:
    """(factor of S to its drawn unit, of the analogues to theirs, unit of S, of S′, of S″, the
    symbol). A rocker's ψ in degrees, its analogues dψ/dφ, d²ψ/dφ² with both angles in radians:
    pure numbers (rad/rad), no mixed °/rad."""
    if des.spec.motion == "rocking":
        return math.degrees(1.0), 1.0, "°", "1", "1", "ψ"
    mm = WORDS("u_mm")
    return MM, MM, mm, mm, mm, "S"


def _phi_axis() -> AxisSpec:
    return AxisSpec("φ", "°", lo=0.0, hi=360.0, tick=30.0)


def _laws(des: CamDesign) -> list[Diagram]:
    prog = des.spec.program
    f0, f1, u0, u1, u2, sym = _law_values(des)
    phi = np.linspace(0.0, 2.0 * math.pi, 1441)
    m = prog.motion(phi)
    div = des.divisions
    # graphical differentiation by chords: the slope of each chord at its interval's middle
    p = div.phi
    s1_g = np.diff(div.S) / np.diff(p)
    mid = (p[:-1] + p[1:]) / 2.0
    s2_g = np.diff(s1_g) / np.diff(mid)
    mid2 = (mid[:-1] + mid[1:]) / 2.0
    rows = [
        (f"{sym}(φ)", u0, f0, m.S, None, None, WORDS("what_S")),
        (f"d{sym}/dφ", u1, f1, m.S1, mid, s1_g, WORDS("what_S1")),
        (f"d^2{sym}/dφ^2", u2, f1, m.S2, mid2, s2_g, WORDS("what_S2")),
    ]
    out = []
    for name, unit, f, exact, gx, gy, what in rows:
        curves = [Curve(np.degrees(phi), exact * f, "link")]
        extra = None
        if gy is not None and gx is not None:
            curves.append(Curve(np.degrees(gx), gy * f, "locus", points=True))
        else:

            def extra(g: Graph, f: float = f) -> None:
                top = float(np.max(np.abs(div.S))) * f
                for i, (a, b) in enumerate(zip(np.degrees(div.phi), div.S * f, strict=True)):
                    text = str(i) if i < len(div.phi) - 1 else ""
                    if abs(float(b)) > ON_AXIS * top:
                        g.ordinate(float(a), float(b), text)
                    elif text:
                        # a point on the axis (a dwell at the bottom): its number lifted off
                        # the axis, clear of the row of the tick labels under it
                        x, y = g.p(float(a), float(b))
                        g.d.label((x, y - NUMBER_LIFT), text, 2.5, prefer=(0.0, -1.0))

        key = "graph_exact" if gy is not None else "graph_plain"
        out.append(
            Diagram(
                _phi_axis(),
                AxisSpec(name, unit),
                curves,
                extra=extra,
                least=LAW_LEAST,
                prefer=LAW_PREFER,
                title=WORDS(key, what=what, name=name),
            )
        )
    return out


def _pressure(des: CamDesign) -> Diagram:
    if des.spec.follower == "flat":
        return _curvature(des)
    prof = des.profile
    keep = ~prof.corner
    phi = np.degrees(prof.phi[keep])
    a = np.degrees(prof.pressure[keep])
    amax = max(math.degrees(des.spec.alpha_rise), math.degrees(des.spec.alpha_return))
    lo = float(min(np.min(a), -amax if np.min(a) < 0 else 0.0))
    curves = [Curve(phi, a, "link")]
    for al in (des.spec.alpha_rise, des.spec.alpha_return):
        v = math.degrees(al)
        for sgn in (1.0, -1.0) if lo < 0 else (1.0,):
            curves.append(Curve([0.0, 360.0], [sgn * v, sgn * v], "locus"))
    return Diagram(
        _phi_axis(),
        AxisSpec("α", "°", lo=lo, hi=amax, tick=15.0),
        curves,
        least=LAW_LEAST,
        prefer=LAW_PREFER,
        title=WORDS("pressure_title"),
    )


def _curvature(des: CamDesign) -> Diagram:
    """A flat face: the profile's radius of curvature ρ = r0 + S + S″ over the turn, with the
    required smallest one."""
    prog = des.spec.program
    phi = np.linspace(0.0, 2.0 * math.pi, 1441)
    m = prog.motion(phi)
    rho = (des.r0 + m.S + m.S2) * MM
    curves = [Curve(np.degrees(phi), rho, "link")]
    if des.spec.rho_allowed > 0.0:
        lim = des.spec.rho_allowed * MM
        curves.append(Curve([0.0, 360.0], [lim, lim], "locus"))
    return Diagram(
        _phi_axis(),
        AxisSpec("ρ", WORDS("u_mm"), lo=0.0, hi=float(np.max(rho))),
        curves,
        least=LAW_LEAST,
        prefer=LAW_PREFER,
        title=WORDS("curvature_title"),
    )


# -- the diagram of the cam's size -----------------------------------------------------------------


def _diagram(des: CamDesign) -> Figure:
    """The diagram the cam's size comes from, as a view at a GOST scale."""
    spec = des.spec
    prog = spec.program
    phi = np.linspace(0.0, 2.0 * math.pi, 1441)
    m = prog.motion(phi)
    O = Vec(*des.centre)  # noqa: E741 (the cam's centre, as the textbooks write it)
    Om = Vec(*des.centre_min)
    if spec.follower == "flat":
        pts = np.stack([m.S2, m.S], axis=-1)
        title = WORDS("diagram_flat")
    elif spec.motion == "translating":
        pts = np.stack([cd.diagram_x(spec.sigma, m.S1), m.S], axis=-1)
        title = WORDS("diagram_translating")
    else:
        geom = cd.RockerGeometry(spec.arm, prog.H, spec.sigma)
        pts = geom.C(m.S, m.S1)
        title = WORDS("diagram_rocking")
    xs = [*pts[:, 0], O.x, Om.x, 0.0]
    ys = [*pts[:, 1], O.y, Om.y, 0.0]
    if spec.motion == "rocking":
        A = cd.RockerGeometry(spec.arm, prog.H, spec.sigma).A
        xs.append(float(A[0]))
        ys.append(float(A[1]))
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    cx, cy = (max(xs) + min(xs)) / 2.0, (max(ys) + min(ys)) / 2.0
    box = (cx - 0.55 * w, cy - 0.55 * h, cx + 0.55 * w, cy + 0.55 * h)
    return Figure(box, lambda v: _diagram_draw(v, des, pts, O, Om, h, max(ys)), title=title)


def _diagram_draw(
    v: Viewport, des: CamDesign, pts: np.ndarray, centre: Vec, Om: Vec, h: float, top_y: float
) -> None:
    O = centre  # noqa: E741 (the cam's centre, as the textbooks write it)
    spec = des.spec
    prog = spec.program
    kl = v.scale
    ys = [top_y]
    v.polyline(list(pts), "link")
    B0 = Vec(0.0, 0.0)
    ext = 0.15 * h
    if spec.follower == "flat":
        # the 45° tangent S + S″ = ρ − r0_min and the S axis
        c0 = spec.rho_allowed - des.r0_min
        top = max(ys)
        v.seg(Vec(c0 - top, top), Vec(-(O.y - ext) + c0, O.y - ext), "construction")
        v.seg(Vec(0.0, O.y - ext), Vec(0.0, top + ext * 0.3), "centre")
        v.dot(Vec(0.0, c0), "point")
    elif spec.motion == "translating":
        zone = des.zone
        assert isinstance(zone, cd.TranslatingZone)
        low = min(O.y, Om.y) - ext
        for r in zone.rays:
            start_ = Vec(r.x, r.S)
            X_low = (low - r.c) / r.b if r.b != 0.0 else r.x
            v.seg(start_, Vec(X_low, low), "construction")
            v.dot(start_, "point")
        v.seg(Vec(0.0, low), Vec(0.0, max(ys) + ext * 0.3), "centre")
        if O.x != 0.0:
            v.seg(Vec(O.x, O.y), Vec(O.x, 0.0), "centre")
            e_mm = fmt_number(abs(des.e) * MM, digits=4)
            v.dim_linear(Vec(O.x, O.y), Vec(0.0, O.y), f"e = {e_mm}", offset=-8.0, height=2.5)
    else:
        zone = des.zone
        assert isinstance(zone, cd.RockerZone)
        geom = zone.geometry
        Av = Vec(*geom.A)
        div = des.divisions
        B = geom.B(div.S)
        C = geom.C(div.S, div.S1)
        for i in range(len(div.phi)):
            v.seg(Av, Vec(*B[i]), "construction")
            v.seg(Vec(*B[i]), Vec(*C[i]), "construction")
            v.dot(Vec(*C[i]), "point")
        slack = zone.h - zone.n @ np.array([Om.x, Om.y])
        nrow = len(zone.phi)
        for j in np.argsort(slack)[:2]:
            i = int(j) % nrow
            sgn = 1.0 if j < nrow else -1.0
            a = math.atan(float(zone.t[i]))
            dd = zone.down[i]
            ray = Vec(math.cos(sgn * a) * dd[0] - math.sin(sgn * a) * dd[1],
                      math.sin(sgn * a) * dd[0] + math.cos(sgn * a) * dd[1])  # fmt: skip
            Ci = Vec(*zone.C[i])
            v.seg(Ci, Ci + ray * (1.3 * float(np.hypot(*(np.array([O.x, O.y]) - zone.C[i])))),
                  "construction")  # fmt: skip
        Bs = geom.B(np.linspace(0.0, prog.H, 50))
        v.polyline(list(Bs), "centre")
        v.joint(Av)
        v.label(Av, "A", prefer=(1.0, 1.0))
        v.seg(Av, O, "thin")
    v.seg(B0, O, "result")
    v.dot(B0, "point")
    v.dot(Om, "point")
    v.joint(O)
    v.label(B0, "B_0", prefer=(-1.0, 1.0))
    v.label(O, "O", prefer=(-1.0, -1.0))
    if (Om - O).norm > kl.model(3.0):
        v.label(Om, "O_{min}", prefer=(1.0, 0.0))
    r0 = fmt_number(des.r0 * MM, digits=4)
    _along(v, O, B0, f"r_0 = {r0}", 2.5)


def _along(v: Viewport, a: Vec, b: Vec, text: str, height: float) -> None:
    """``text`` written along the segment ``ab`` (a radius named on its line, GOST 2.307: above
    it, reading from the bottom or the right), where it crosses no drawn line: the places along
    the segment from its middle out, above it first."""
    pa, pb = v.p(a), v.p(b)
    length = math.dist(pa, pb)
    if length <= 0.0:
        return
    ux, uy = (pb[0] - pa[0]) / length, (pb[1] - pa[1]) / length
    tx, ty = (ux, uy) if ux > tol.DERIVED or (abs(ux) <= tol.DERIVED and uy < 0.0) else (-ux, -uy)
    upx, upy = ty, -tx
    width, rise, down = text_box(parse(text), height)
    cands: list[tuple[float, float]] = []
    for lift in (1.0 + down, -(1.0 + rise), 3.0 + down, -(3.0 + rise)):
        for f in sorted((i / 20.0 for i in range(1, 20)), key=lambda f: abs(f - 0.5)):
            cx = pa[0] + (pb[0] - pa[0]) * f - tx * width / 2.0 + upx * lift
            cy = pa[1] + (pb[1] - pa[1]) * f - ty * width / 2.0 + upy * lift
            cands.append((cx, cy))
    angle = math.degrees(math.atan2(-ty, tx))
    v.d.dims.append(DimText(text, height, angle, (tx, ty), tuple(cands), (width, rise, down)))


# -- the profile -----------------------------------------------------------------------------------


def _profile(des: CamDesign) -> Inversion:
    """The profile by inversion (:class:`~geomcad.sheet.cams.Inversion`, a design's many points):
    the full turn with the follower turned back to each division point — its axis (translating)
    or its arm from the pivot A_i (rocking)."""
    spec = des.spec
    rocking = spec.motion == "rocking"
    f = Follower(spec.follower, des.r0, 0.0 if rocking else des.e, des.r_roller, spec.sigma)
    div = des.divisions
    n = len(div.phi) - 1  # the last division point of the turn is the first one again
    points: Division | CamProfile
    if rocking:
        pitch, contact = _rocker_points(des, div.phi[:n])
        points = Division(div.phi[:n], pitch, contact)
    else:
        points = at_angles(spec.program, f, div.phi[:n], 2.0 * math.pi)
    return Inversion(
        f, des.profile, points, closed=True, pivot=des.pivot if rocking else None,
        lettered=False, title=WORDS("profile_title"), margin=8.0, weight=3.0,
    )  # fmt: skip


def _rocker_points(des: CamDesign, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The rocker turned back to the angles ``phi``: its roller's centres and contact points."""
    spec = des.spec
    A = np.asarray(des.pivot)
    prof = cd.rocker_profile(spec.program, A, spec.arm, spec.program.H, spec.sigma, des.r_roller)
    idx = [int(np.argmin(np.abs(prof.phi - p) + 10.0 * prof.corner)) for p in phi]
    return prof.pitch[idx], prof.contact[idx]


# -- tables ----------------------------------------------------------------------------------------


def _tables(des: CamDesign, r: dict[str, Any]) -> tuple[Table, Table]:
    spec = des.spec
    u = WORDS("u_mm")
    rows = [
        [WORDS("row_follower"),
         f"{WORDS('follower_' + spec.follower)}, {WORDS('motion_' + spec.motion)}"],
        [WORDS("row_rotation"), WORDS("ccw" if spec.sigma > 0 else "cw")],
    ]  # fmt: skip
    if spec.motion == "translating":
        rows.append([WORDS("row_stroke"), f"{fmt_number(spec.program.H * MM, digits=4)} {u}"])
    else:
        rows.append([WORDS("row_swing"), f"{fmt_number(math.degrees(spec.program.H), digits=4)}°, "
                     f"{fmt_number(spec.arm * MM, digits=4)} {u}"])  # fmt: skip
    if spec.follower != "flat":
        a_r = fmt_number(math.degrees(spec.alpha_rise), digits=4)
        a_t = fmt_number(math.degrees(spec.alpha_return), digits=4)
        rows.append([WORDS("row_alpha"), f"{a_r}° / {a_t}°"])
    else:
        rows.append([WORDS("row_rho"), f"{fmt_number(spec.rho_allowed * MM, digits=4)} {u}"])
    data = Table(rows, header=False, title=WORDS("data_title"))
    names = ("r0_min", "r0", "e", "a_w", "r_roller", "rho_pitch_min", "rho_min",
             "pressure_angle_max_rise_deg", "pressure_angle_max_return_deg")  # fmt: skip
    by = {s.name: s for s in RESULTS}
    labels = {n: WORDS(n) for n in names[:7]} | {
        "pressure_angle_max_rise_deg": WORDS("alpha_rise"),
        "pressure_angle_max_return_deg": WORDS("alpha_return"),
    }
    res = Table.of_specs([by[n] for n in names], r, labels=labels, style="value",
                         title=WORDS("results_title"))  # fmt: skip
    return data, res


def _notes(des: CamDesign) -> Text:
    """The phases and laws of the program."""
    laws = ", ".join(
        f"{WORDS('phase_' + ph.kind)} {fmt_number(math.degrees(ph.angle), digits=4)}°"
        + (f" ({WORDS('law_' + ph.law)})" if ph.kind != "dwell" else "")
        for ph in des.spec.program.phases
    )
    return Text(paragraph=WORDS("phases", laws=laws), width=NOTE_W)


#: The recorded steps the order of construction lists (geomcad/files/cam.py), in order.
ORDER = ("S(φ)", "zone", "ρ-condition", "O_min", "r0_min", "r0", "r_roller", "profile")


def _order(sol: Solution[CamDesign]) -> Steps:
    """The order of construction, written from the design's recorded steps."""
    names = [n for n in ORDER if n in sol.construction]
    return Steps(sol.construction, width=NOTE_W, only=names, words=WORDS)
