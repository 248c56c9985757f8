"""The kinematic sheet of a linkage file (A1), laid out for any mechanism.

The field is cut into regions by one layout rule, whatever the mechanism: the mechanism in all
its numbered positions (top left), the velocity plan of every position in a grid (top right;
on a second sheet when there are more than :data:`PLANS_ON_SHEET`), the output's diagrams
s(φ), v(φ), a(φ) (bottom left: the exact curves of the sweep, and the graphical derivatives by
chords through the numbered positions), the acceleration plans of two positions (bottom middle)
and the tables of ω and ε (bottom right). Each view takes the largest scale of its series that
fits its region: a GOST 2.302 ratio for the mechanism, one factor 1, 2, 2.5, 4, 5 × 10^n for all
velocity plans and one for the acceleration plans, so every vector is drawn at the stated μ.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from geomcad import tol
from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import Position, construct
from geomcad.linkage.solution import Solved
from geomcad.linkage.sweep import output_coordinate, sweep
from geomcad.sheet import Drawing, TitleBlock, fmt_number, gost_scale_to_fit, start
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.motion import Frames, turn
from geomcad.sheet.plans import LINE_OVER_MM, draw_plan, plan_scale
from geomcad.sheet.scale import Scale
from geomcad.sheet.scheme import Body, draw_scheme

#: A1 landscape and its regions (x0, y0, x1, y1 in sheet mm).
FORMAT = "A1"
MECH = (26.0, 14.0, 420.0, 318.0)
VPLANS = (428.0, 14.0, 832.0, 318.0)
DIAGRAMS = (26.0, 326.0, 420.0, 584.0)
APLANS = (428.0, 326.0, 642.0, 584.0)
TABLES = (652.0, 326.0, 832.0, 530.0)
#: At most this many velocity plans share the first sheet with the mechanism.
PLANS_ON_SHEET = 12
#: The second sheet's grid region for more plans.
PLANS_ALL = (26.0, 14.0, 832.0, 528.0)
#: Samples of the exact diagrams over a turn.
DIAGRAM_SAMPLES = 361
TITLE_ROOM = 8.0  # mm above a view for its title

Box = tuple[float, float, float, float]


@dataclass(frozen=True)
class Layout:
    """The regions and scales of a linkage's kinematic sheets."""

    k_l: Scale
    k_v: Scale
    k_a: Scale
    cells: tuple[Box, ...]  # one per velocity plan
    second: bool  # the velocity plans go on a second sheet
    accel: tuple[Position, ...]
    acells: tuple[Box, ...]  # one per acceleration plan


def _grid(box: Box, n: int, content: tuple[float, float] = (1.0, 1.0)) -> tuple[Box, ...]:
    """n cells filling ``box`` row by row, in the arrangement (columns × rows) that draws a
    content of ``content`` = (width, height) (model units, each cell alike) the largest."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    cw_, ch_ = (c if c > 0.0 else 1.0 for c in content)  # a plan all at its pole
    cols = max(
        range(1, n + 1),
        key=lambda c: min(
            (w / c - 2 * LINE_OVER_MM) / cw_,
            (h / math.ceil(n / c) - TITLE_ROOM - 2 * LINE_OVER_MM) / ch_,
        ),
    )
    rows = math.ceil(n / cols)
    cw, ch = w / cols, h / rows
    return tuple(
        (x0 + c * cw, y0 + r * ch, x0 + (c + 1) * cw, y0 + (r + 1) * ch)
        for r, c in (divmod(i, cols) for i in range(n))
    )


def _content(plans: Sequence[Plan]) -> tuple[float, float]:
    """The largest width and height of the plans (plan units)."""
    ext = [p.extent() for p in plans]
    return max(e[2] - e[0] for e in ext), max(e[3] - e[1] for e in ext)


def _inner(cell: Box, title: float = TITLE_ROOM) -> tuple[float, float]:
    """The room a plan's points have in a cell: clear of its title, and of its neighbours by the
    length its construction lines run past the points (:data:`LINE_OVER_MM`) on each side."""
    margin = 2.0 * LINE_OVER_MM
    return cell[2] - cell[0] - margin, cell[3] - cell[1] - title - margin


def _common_scale(plans: Sequence[Plan], cells: Sequence[Box]) -> Scale:
    """The one factor at which every plan fits its cell: the largest of their own."""
    scales = [plan_scale(p, *_inner(c)) for p, c in zip(plans, cells, strict=True)]
    return max(scales, key=lambda s: s.k)


def _mechanism_extent(s: Solved) -> tuple[float, float, float, float]:
    """The model box of everything the mechanism view draws: every position's points and link
    bodies, the crank circle and the traced paths."""
    lk = s.linkage
    pts: list[Vec] = []
    for P in s.positions:
        pts += list(P.pos.values())
        for bodies in link_bodies(lk, P).values():
            for b in bodies:
                pts += list(b.points)
    O1 = lk.frame[lk.pivot]
    pts += [O1 + Vec(lk.length, lk.length), O1 - Vec(lk.length, lk.length)]
    for path in _paths(lk).values():
        pts += path
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _paths(lk: Linkage) -> dict[str, list[Vec]]:
    """The paths of the named points over a turn (sampled by the sweep)."""
    phi = np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES)
    st = sweep(lk, phi, order=0)
    return {p.name: [Vec(float(a), float(b)) for a, b in st.pos[p.name]] for p in lk.points}


def layout(s: Solved) -> Layout:
    """Where every view goes and at what scale (see the module's docstring)."""
    n = len(s.positions)
    second = n > PLANS_ON_SHEET
    cells = _grid(PLANS_ALL if second else VPLANS, n, _content([P.vp for P in s.positions]))
    k_v = _common_scale([P.vp for P in s.positions], cells)
    lk = s.linkage
    accel = tuple(
        next((P for P in s.positions if abs(P.phi - phi) <= tol.ANGLE), None) or construct(lk, phi)
        for phi in s.accel_phis
    )
    acells = _grid(APLANS, len(accel), _content([P.ap for P in accel]))
    k_a = _common_scale([P.ap for P in accel], acells)
    x0, y0, x1, y1 = _mechanism_extent(s)
    pad = 0.04 * max(x1 - x0, y1 - y0, lk.length)
    w, h = _inner(MECH, TITLE_ROOM + 4.0)
    k_l = gost_scale_to_fit(x1 - x0 + 2 * pad, y1 - y0 + 2 * pad, w, h)
    return Layout(k_l, k_v, k_a, cells, second, accel, acells)


def sheet_scales(s: Solved) -> dict[str, float]:
    """The scale of each drawn quantity (for ``verify``): k_l, k_v, k_a."""
    lay = layout(s)
    return {"l": lay.k_l.k, "v": lay.k_v.k, "a": lay.k_a.k}


def kinematic_sheets(s: Solved, stem: str = "") -> list[tuple[str, object]]:
    """The kinematic sheet (and, with many positions, a second sheet of velocity plans)."""
    lk = s.linkage
    lay = layout(s)
    count = 2 if lay.second else 1
    designation = f"ТММ.{stem or 'МЕХ'}.01"
    d = start(FORMAT, _title(lk, "Кинематический анализ", designation, lay.k_l, 1, count))
    _mechanism(d, s, lay.k_l)
    if not lay.second:
        _vplans(d, s, lay)
    _diagrams(d, s)
    _aplans(d, lay)
    _tables(d, s, lay)
    out: list[tuple[str, object]] = [("", d.finish())]
    if lay.second:
        d2 = start(FORMAT, _title(lk, "Планы скоростей", designation, None, 2, count))
        _vplans(d2, s, lay)
        out.append(("plans", d2.finish()))
    return out


def _title(
    lk: Linkage, what: str, designation: str, k: Scale | None, no: int, count: int
) -> TitleBlock:
    return TitleBlock(
        title=f"{what}. {lk.title}" if len(lk.title) < 40 else what,
        designation=designation,
        scale=k.ratio_text() if k is not None else "",
        sheet_no=no,
        sheets=count,
    )


# --- the mechanism ----------------------------------------------------------------------------


def link_bodies(
    lk: Linkage, P: Position, links: Sequence[int] | None = None
) -> dict[str, list[Body]]:
    """Each link's body in position P through all its points: a slotted link along its slide,
    past the block; a PRP yoke with its slot through the block; a link carrying a guide with
    the guide run on to its slider. ``links``: those to draw (default: every moving link)."""
    out: dict[str, list[Body]] = {}
    for link in lk.moving_links if links is None else links:
        uniq: list[Vec] = []
        for n in lk.points_on(link):
            q = P.pos[n]
            if not any(q.dist(u) <= tol.DERIVED * max(1.0, q.norm) for u in uniq):
                uniq.append(q)
        g = lk.group_of(link)
        if g is not None and g.kind == "RPR" and link == g.links[1]:
            d = P.slide[link]
            C = P.pos[g.pivot]
            far = max([(q - C).dot(d) for q in [P.pos[g.slider], *uniq]])
            foot = C + d.perp() * g.offset
            out[str(link)] = (
                [Body.of([C, foot, foot + d * (far * 1.15)])]
                if g.offset
                else [Body.of([C, C + d * (far * 1.15)])]
            )
            continue
        if len(uniq) == 2:
            out[str(link)] = [Body.of(uniq)]
        elif len(uniq) > 2:
            cx = sum(q.x for q in uniq) / len(uniq)
            cy = sum(q.y for q in uniq) / len(uniq)
            ring = sorted(uniq, key=lambda q: math.atan2(q.y - cy, q.x - cx))
            out[str(link)] = [Body.of(ring, closed=True)]
        if g is not None and g.kind == "PRP" and link == g.links[1]:
            # the yoke's slot: from its reference point through the block, a little past it
            E, A = P.pos[g.joint], P.pos[g.slider]
            if E.dist(A) > 0.0:
                out.setdefault(str(link), []).append(Body.of([E, A + (A - E) * 0.15]))
        # a guide on this link runs on to the slider it carries
        for g2 in lk.groups:
            gd = g2.guide
            if g2.kind == "RRP" and gd is not None and gd.link == link:
                line = P.lines[g2.index]
                t = [(P.pos[n] - line.p).dot(line.d) for n in (gd.frm, gd.toward, g2.joint)]
                out.setdefault(str(link), []).append(Body.of([line.at(min(t)), line.at(max(t))]))
                if gd.offset:
                    out[str(link)].append(Body.of([P.pos[gd.frm], line.p]))
    return out


def _mechanism(d: Drawing, s: Solved, k: Scale) -> None:
    lk = s.linkage
    x0, y0, x1, y1 = _mechanism_extent(s)
    d.text(
        "Механизм в положениях 0 … " + str(len(s.positions) - 1),
        (MECH[0] + 2.0, MECH[1] + 4.0),
        5.0,
    )
    d.text(f"{k.label()}   (M {k.ratio_text()})", (MECH[0] + 2.0, MECH[1] + 10.5), 3.5)
    at = ((MECH[0] + MECH[2]) / 2.0, (MECH[1] + TITLE_ROOM + 8.0 + MECH[3]) / 2.0)
    v = d.viewport(k, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at)
    # paths: the crank circle, the traced points, the guides
    v.circle(lk.frame[lk.pivot], lk.length, "centre")
    for path in _paths(lk).values():
        v.polyline(path, "centre")
    # every other position in thin lines, numbered at the crank's joint and the output
    P0 = s.positions[0]
    for i, P in enumerate(s.positions):
        if i > 0:
            for bodies in link_bodies(lk, P).values():
                for b in bodies:
                    v.polyline(b.points, "thin", closed=b.closed)
        for name in dict.fromkeys((lk.joint, lk.output)):
            v.dot(P.pos[name])
            v.label(P.pos[name], f"{name}_{{{i}}}", 2.5, clear=1.0)
    labels = {}
    for pair in s.scheme.pairs:
        name = pair.name.split(":")[0]
        if name in P0.pos and name not in (lk.joint, lk.output):
            labels[pair.name] = name
    draw_scheme(v, s.scheme, bodies=link_bodies(lk, P0), pair_labels=labels, label_height=3.5)
    for p in lk.points:
        if p.name not in labels.values():
            v.dot(P0.pos[p.name])
            v.label(P0.pos[p.name], p.name, 3.5, clear=1.0)


# --- the plans --------------------------------------------------------------------------------


def _vplans(d: Drawing, s: Solved, lay: Layout) -> None:
    box = PLANS_ALL if lay.second else VPLANS
    d.text(f"Планы скоростей, {lay.k_v.label()}", (box[0] + 2.0, box[1] + 4.0), 5.0)
    for i, (P, cell) in enumerate(zip(s.positions, lay.cells, strict=True)):
        inner = (cell[0] + 3.0, cell[1] + 8.0, cell[2] - 3.0, cell[3] - 2.0)
        draw_plan(
            d,
            P.vp,
            lay.k_v,
            inner,
            title=f"Положение {i}, φ_1 = {fmt_number(math.degrees(P.phi) % 360, digits=4)}°",
        )


def _aplans(d: Drawing, lay: Layout) -> None:
    for P, cell in zip(lay.accel, lay.acells, strict=True):
        phi = fmt_number(math.degrees(P.phi) % 360, digits=4)
        draw_plan(d, P.ap, lay.k_a, cell, title=f"План ускорений, φ_1 = {phi}°, {lay.k_a.label()}")


# --- the diagrams -----------------------------------------------------------------------------


def _output_curves(
    s: Solved, psi: np.ndarray
) -> tuple[list[tuple[str, str, str]], np.ndarray, np.ndarray, np.ndarray]:
    """The output's coordinate and its first two time derivatives over the crank's turn ψ from
    position 0, with their (symbol, unit, factor name): a slider's s, v, a from the working
    stroke's start in the working direction, else the output link's angle ψ (from position 0,
    ccw > 0, rad), ω and ε."""
    lk = s.linkage
    sign = 1.0 if lk.omega > 0 else -1.0
    phi = s.positions[0].phi + sign * psi
    st = sweep(lk, phi, order=2)
    g = lk.output_guide
    if g is not None and s.cycle is not None:
        coord = output_coordinate(lk, st)
        assert coord is not None
        fwd = 1.0 if lk.working == "forward" else -1.0
        sl = st.slide[g.links[1]]
        s_m = fwd * (coord - (s.cycle.s_min if fwd > 0 else s.cycle.s_max))
        v_m = fwd * (st.vel[lk.output] * sl).sum(axis=1)
        a_m = fwd * (st.acc[lk.output] * sl).sum(axis=1)
        names = [("S", "м", "s"), ("v", "м/с", "v"), ("a", "м/с²", "a")]
        return names, s_m, v_m, a_m
    link = lk.owner[lk.output]
    base = next(p for p in lk.points_on(link) if p != lk.output)
    r = st.pos[lk.output] - st.pos[base]
    ang = np.unwrap(np.arctan2(r[:, 1], r[:, 0]))
    names = [
        (f"ψ_{{{link}}}", "рад", "ψ"),
        (f"ω_{{{link}}}", "с^{-1}", "ω"),
        (f"ε_{{{link}}}", "с^{-2}", "ε"),
    ]
    return names, ang - ang[0], st.omega[link], st.eps[link]


def _diagrams(d: Drawing, s: Solved) -> None:
    """The output's diagrams over a turn from position 0: the exact curves of the sweep, and
    the derivatives by chords through the numbered positions (graphical differentiation)."""
    lk = s.linkage
    psi = np.linspace(0.0, 2.0 * math.pi, DIAGRAM_SAMPLES)
    names, s_m, v_m, a_m = _output_curves(s, psi)
    n = max(len(s.positions), 12) if lk.phi is not None else len(s.positions)
    psi_k = np.array([2.0 * math.pi * k / n for k in range(n + 1)])
    s_k = np.interp(psi_k, psi, s_m)
    dt = (2.0 * math.pi / n) / abs(lk.omega)
    v_ch = np.diff(s_k) / dt
    psi_v = (psi_k[:-1] + psi_k[1:]) / 2.0
    a_ch = np.diff(np.concatenate([v_ch, v_ch[:1]])) / dt
    psi_a = (psi_v + math.pi / n) % (2.0 * math.pi)
    rows = [(s_m, psi_k, s_k), (v_m, psi_v, v_ch), (a_m, psi_a, a_ch)]
    x0, y0, x1, y1 = DIAGRAMS
    h = (y1 - y0) / 3.0
    room_x = x1 - x0 - 24.0
    k_phi = 1.0 if room_x >= 360.0 else nice_step(360.0 / room_x)
    through = (
        f"положения 0 … {n - 1}" if lk.phi is None else f"{n} равных делений оборота кривошипа"
    )
    d.text(f"Диаграммы выходного звена: точные кривые и хорды через {through}", (x0, y0), 3.5)
    for i, ((sym, unit, name), (exact, gx, gy)) in enumerate(zip(names, rows, strict=True)):
        top = y0 + i * h + 12.0
        bottom = y0 + (i + 1) * h - 9.0
        lo = float(min(exact.min(), gy.min(), 0.0))
        hi = float(max(exact.max(), gy.max(), 0.0))
        ax_y = Axis.fit(sym, unit, lo, hi, bottom - top, name)
        ax_x = Axis("φ", "град", 0.0, 360.0, k_phi, "φ", tick=30.0)
        at = (x0 + 4.0, top + ax_y.mm(ax_y.hi - ax_y.zero))
        gr = Graph(d, ax_x, ax_y, at)
        gr.axes(tick_labels=True)
        gr.curve(np.degrees(psi), exact, "result")
        order = np.argsort(gx)
        gxs, gys = np.degrees(gx[order]), gy[order]
        gr.curve(gxs, gys, "construction")
        for xx, yy in zip(gxs, gys, strict=True):
            gr.point(float(xx), float(yy))
        d.text(
            f"{ax_y.factor_text()};  {ax_x.factor_text()}",
            (x1, y0 + i * h + 8.0),
            2.5,
            anchor="right",
        )


# --- the tables -------------------------------------------------------------------------------


def _tables(d: Drawing, s: Solved, lay: Layout) -> None:
    lk = s.linkage
    links = [i for i in lk.moving_links if i != 1 and _turns(lk, i)]
    head = ["№", "φ_1, °", f"V_{{{lk.output}}}, м/с", *[f"ω_{{{i}}}, с^{{-1}}" for i in links]]
    rows: list[list[str]] = [head]
    for i, P in enumerate(s.positions):
        rows.append(
            [
                str(i),
                fmt_number(math.degrees(P.phi) % 360, digits=4),
                table_number(P.vel[lk.output].norm, abs(lk.omega) * lk.length),
                *[table_number(P.omega[j], abs(lk.omega)) for j in links],
            ]
        )
    x0, y0, x1, y1 = TABLES
    width = x1 - x0
    first = [8.0, 16.0, 20.0]
    rest = (width - sum(first)) / max(len(links), 1)
    widths = [*first, *[rest] * len(links)]
    row_h = min(7.0, (y1 - y0 - 60.0) / (len(rows) + 1))
    d.text("Угловые скорости звеньев", (x0, y0 + 4.0), 3.5)
    _, th = d.table(x0, y0 + 7.0, widths, rows, 2.5, row_h)
    head2 = ["φ_1, °", f"a_{{{lk.output}}}, м/с²", *[f"ε_{{{i}}}, с^{{-2}}" for i in links]]
    rows2: list[list[str]] = [head2]
    for P in lay.accel:
        rows2.append(
            [
                fmt_number(math.degrees(P.phi) % 360, digits=4),
                table_number(P.acc[lk.output].norm, lk.omega**2 * lk.length),
                *[table_number(P.eps[j], lk.omega**2) for j in links],
            ]
        )
    w2 = [16.0, 22.0, *[(width - 38.0) / max(len(links), 1)] * len(links)]
    yy = y0 + 7.0 + th + 8.0
    d.text("Угловые ускорения звеньев", (x0, yy), 3.5)
    d.table(x0, yy + 3.0, w2, rows2, 2.5, 7.0)


def _turns(lk: Linkage, link: int) -> bool:
    """False for a link that cannot turn: a slider on a fixed guide, the links of a PRP."""
    g = lk.group_of(link)
    if g is None:
        return True
    if g.kind == "PRP":
        return False
    return not (g.kind == "RRP" and link == g.links[1] and g.guide is not None and g.guide.fixed)


#: Values below this fraction of their quantity's scale print as 0 (round-off of a zero).
ZERO = tol.DERIVED


def table_number(x: float, scale: float = 0.0, digits: int = 3) -> str:
    """A table value to ``digits`` significant figures; round-off of a zero (at most
    :data:`ZERO` of ``scale``, the size of its quantity) as 0."""
    return "0" if abs(x) <= ZERO * scale else fmt_number(x, digits=digits)


# --- the moving mechanism ---------------------------------------------------------------------


def motion(s: Solved, frames: int) -> Frames:
    """The linkage over one crank turn from position 0 (:mod:`geomcad.sheet.motion`): every
    joint and point from the sweep, each link as the chain of its points, the sliders along
    their guides, the paths of the named points and the output, and the velocity plan with its
    relative velocities along each link."""
    lk = s.linkage
    phi = turn(frames, s.positions[0].phi, 1.0 if lk.omega > 0 else -1.0)
    st = sweep(lk, phi, order=1)
    pos, vel = st.pos, st.vel
    names = [*lk.frame, *(n for n in lk.owner if n not in lk.frame)]
    points = {n: np.array(pos[n]) for n in names if n in pos}
    links: list[tuple[str, ...]] = []
    edges: list[tuple[str, str]] = []
    for link in lk.moving_links:
        on = [n for n in dict.fromkeys(lk.points_on(link)) if n in points]
        if len(on) >= 2:
            links.append(tuple(on))
            edges += [(on[0], q) for q in on[1:] if q in vel and on[0] in vel]
    sliders = {}
    guides = []
    for g in lk.groups:
        if g.kind in ("RRP", "PRP") and g.guide is not None:
            d = st.slide[g.links[1]][0]
            sliders[g.joint] = (float(d[0]), float(d[1]))
            if g.guide.fixed:
                P = points[g.joint]
                t = (P - np.array([g.guide.through.x, g.guide.through.y])) @ d
                q = np.array([g.guide.through.x, g.guide.through.y])
                reach = 0.15 * float(t.max() - t.min()) + 0.1 * lk.length
                a, b = q + d * (t.min() - reach), q + d * (t.max() + reach)
                guides.append(((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))))
    traced = tuple(dict.fromkeys((lk.joint, *(p.name for p in lk.points), lk.output)))
    return Frames(
        title=f"{lk.title}: один оборот кривошипа",
        phi=phi,
        points=points,
        links=tuple(links),
        fixed=tuple(lk.frame),
        traced=traced,
        sliders=sliders,
        guides=tuple(guides),
        velocities={n: np.array(vel[n]) for n in points if n in vel},
        plan_edges=tuple(dict.fromkeys(edges)),
        omega1=lk.omega,
    )
