"""Sheets 2 and 3 of a linkage file's course project (A1): the force analysis and the flywheel.

:func:`force_sheets` returns them for the lead's list of linkage sheets, named ``forces`` and
``dynamics``:

- **sheet 2, the force analysis** at one position (the file's first ``phi``, or the numbered
  position nearest the middle of the working stroke): the mechanism with every load drawn (top
  left); each Assur group and the crank cut out, with their loads and the reactions found (top
  right); each group's force polygons at their μ_F (bottom middle); Zhukovsky's lever, the
  velocity plan turned 90° with the loads at their points' images (bottom left); the table of
  loads, reactions and the two M_bal (bottom right);
- **sheet 3, the dynamics**: M_pr(φ), the works A(φ) (the exact integral and the graphical one
  through the numbered positions), ΔT(φ) and I_pr(φ) (left), Wittenbauer's energy–mass diagram
  with its two tangents and the segment ab they cut (top right), ω(φ) of the steady cycle with
  the flywheel (bottom middle) and the tables (bottom right).

Every vector is drawn at the μ its view states; each view takes the largest scale of its series
that fits its region.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.forces import ForcePolygon
from geomcad.geom import Vec
from geomcad.linkage.analysis import analyse
from geomcad.linkage.dynamics import Flywheel
from geomcad.linkage.kinetostatics import Applied, Forces, GroupForces
from geomcad.linkage.loads import centre_vec
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import Position, plan_name
from geomcad.linkage.solution import Solved, scheme
from geomcad.sheet import Drawing, TitleBlock, gost_scale_to_fit, nice_factor, start
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.graph import Axis, Graph, nice_step
from geomcad.sheet.linkage import link_bodies, table_number
from geomcad.sheet.loads import force, moment
from geomcad.sheet.plans import markup_of
from geomcad.sheet.scale import Scale
from geomcad.sheet.scheme import draw_scheme
from geomcad.structure import Mechanism
from geomcad.structure.model import Link

Box = tuple[float, float, float, float]
FORMAT = "A1"
# sheet 2
MECH: Box = (26.0, 14.0, 330.0, 290.0)
BODIES: Box = (340.0, 14.0, 832.0, 290.0)
LEVER: Box = (26.0, 300.0, 330.0, 584.0)
POLYS: Box = (340.0, 300.0, 640.0, 584.0)
TABLE: Box = (652.0, 300.0, 832.0, 528.0)
# sheet 3
GRAPHS: Box = (26.0, 14.0, 432.0, 584.0)
WITT: Box = (440.0, 14.0, 832.0, 360.0)
OMEGA: Box = (440.0, 372.0, 640.0, 584.0)
TABLE3: Box = (652.0, 372.0, 832.0, 528.0)
TITLE_ROOM = 12.0
#: The longest load arrow on a drawing of links (mm).
LOAD_MM = 24.0
#: The longest load arrow on Zhukovsky's lever (mm); shorter than 1 mm are left out.
LEVER_LOAD_MM = 40.0


def _grid(box: Box, n: int) -> list[Box]:
    """n cells of a grid filling ``box``, as square as it allows, row by row."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    best, side = (1, n), 0.0
    for cols in range(1, n + 1):
        rows = math.ceil(n / cols)
        s = min(w / cols, h / rows)
        if s > side:
            best, side = (cols, rows), s
    cols, rows = best
    cw, ch = w / cols, h / rows
    return [
        (x0 + (i % cols) * cw, y0 + (i // cols) * ch, x0 + (i % cols + 1) * cw,
         y0 + (i // cols + 1) * ch)
        for i in range(n)
    ]  # fmt: skip


def force_position(s: Solved) -> int:
    """The index of the position drawn on sheet 2: the file's first ``phi``, else the numbered
    position nearest the middle of the working stroke (its first acceleration plan's angle)."""
    if s.linkage.phi is not None or not s.accel_phis:
        return 0
    mid = s.accel_phis[0]

    def off(P: Position) -> float:
        return abs(math.remainder(P.phi - mid, 2.0 * math.pi))

    return min(range(len(s.positions)), key=lambda i: off(s.positions[i]))


def force_sheets(
    s: Solved, stem: str = "", first_no: int = 2, count: int = 0
) -> list[tuple[str, object]]:
    """Sheet 2 (where the file gives masses or loads) and sheet 3 (with ``[dynamics]``),
    numbered from ``first_no`` of ``count`` sheets (0: these are the last ones)."""
    a = analyse(s)
    lk = s.linkage
    mine = (a.forces is not None) + (a.flywheel is not None)
    count = count or first_no - 1 + mine
    designation = f"ТММ.{stem or 'МЕХ'}.01"
    out: list[tuple[str, object]] = []
    no = first_no
    if a.forces is not None:
        k = force_position(s)
        d = start(FORMAT, _title(lk, "Силовой анализ", designation, no, count))
        _sheet2(d, s, s.positions[k], a.forces[k], k)
        out.append(("forces", d.finish()))
        no += 1
    if a.flywheel is not None:
        d = start(FORMAT, _title(lk, "Динамика машины. Маховик", designation, no, count))
        _sheet3(d, s, a.flywheel)
        out.append(("dynamics", d.finish()))
    return out


def _title(lk: Linkage, what: str, designation: str, no: int, count: int) -> TitleBlock:
    return TitleBlock(
        title=f"{what}. {lk.title}" if len(lk.title) < 40 else what,
        designation=designation,
        sheet_no=no,
        sheets=count,
    )


def _num(x: float, digits: int = 4, scale: float = 0.0) -> str:
    return table_number(x, scale, digits)


# --- sheet 2 ------------------------------------------------------------------------------


def _sheet2(d: Drawing, s: Solved, P: Position, f: Forces, k: int) -> None:
    lk = s.linkage
    phi = _num(math.degrees(P.phi) % 360.0)
    _mechanism(d, lk, P, f, f"Механизм в положении {k}, φ_1 = {phi}°")
    cells = _grid(BODIES, len(f.groups))
    for gf, cell in zip(f.groups, cells, strict=True):
        _free_body(d, lk, P, gf, cell)
    polys = [(gf, name, poly) for gf in f.groups for name, poly in gf.polygons]
    for (gf, name, poly), cell in zip(polys, _grid(POLYS, len(polys)), strict=True):
        _polygon(d, gf, name, poly, cell)
    _lever(d, lk, P, f)
    _table2(d, lk, f)


def _extent(pts: Sequence[Vec], minimum: float) -> tuple[float, float, float, float]:
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    pad = 0.05 * max(x1 - x0, y1 - y0, minimum)
    return x0 - pad, y0 - pad, x1 + pad, y1 + pad


def _fit(d: Drawing, box: Box, ext: tuple[float, float, float, float]) -> tuple[Viewport, Scale]:
    x0, y0, x1, y1 = ext
    bx0, by0, bx1, by1 = box
    w, h = bx1 - bx0 - LOAD_MM, by1 - by0 - TITLE_ROOM - LOAD_MM
    k = gost_scale_to_fit(x1 - x0, y1 - y0, max(w, 20.0), max(h, 20.0))
    at = ((bx0 + bx1) / 2.0, (by0 + TITLE_ROOM + by1) / 2.0)
    return d.viewport(k, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at), k


def _draw_loads(
    v: Viewport, lk: Linkage, P: Position, loads: Sequence[Applied], k_F: float, role: str
) -> None:
    for ld in loads:
        if ld.force is not None and ld.at is not None:
            force(v, ld.at, ld.force, k_F, ld.name, role=role, height=2.5)
        elif ld.moment != 0.0:
            moment(v, centre_vec(lk, ld.link, P.pos), ld.moment, 6.0, ld.name, role, height=2.5)


def _mechanism(d: Drawing, lk: Linkage, P: Position, f: Forces, title: str) -> None:
    pts = list(P.pos.values())
    v, k = _fit(d, MECH, _extent(pts, lk.length))
    loads = [ld for lds in f.loads.values() for ld in lds]
    big = max([ld.force.norm for ld in loads if ld.force is not None], default=0.0) or 1.0
    kF = nice_factor(big, LOAD_MM, "F")
    d.text(title, (MECH[0] + 2.0, MECH[1] + 4.0), 5.0)
    d.text(f"{k.label()}   (M {k.ratio_text()});   {kF.label()}", (MECH[0] + 2.0, MECH[1] + 10.0),
           3.5)  # fmt: skip
    mech = scheme(lk, P)
    draw_scheme(v, mech, bodies=link_bodies(lk, P), pair_labels={}, label_height=3.5)
    for name in P.pos:
        if name in lk.owner and lk.owner[name] != 0:
            v.label(P.pos[name], name, 3.5, clear=1.0)
    _draw_loads(v, lk, P, loads, kF.k, "vector")
    v.turn(P.pos[lk.pivot], f.M_bal, 30.0, "M_{ур}", 8.0, 250.0, "result", 2.5)


def _free_body(d: Drawing, lk: Linkage, P: Position, gf: GroupForces, cell: Box) -> None:
    links = gf.links
    pts: list[Vec] = []
    for i in links:
        pts += [P.pos[n] for n in lk.points_on(i)]
        pts += [ld.at for ld in gf.loads[i] if ld.at is not None]
    pts += [r.at for r in gf.reactions]
    v, k = _fit(d, cell, _extent(pts, lk.length * 0.5))
    forces = [ld.force.norm for i in links for ld in gf.loads[i] if ld.force is not None]
    forces += [r.force.norm for r in gf.reactions]
    kF = nice_factor(max(forces, default=0.0) or 1.0, LOAD_MM, "F")
    g = gf.group
    what = f"Группа II({links[0]}, {links[1]})" if g is not None else "Кривошип 1"
    d.text(what, (cell[0] + 3.0, cell[1] + 4.0), 3.5)
    d.text(f"{k.label()};  {kF.label()}", (cell[0] + 3.0, cell[1] + 9.0), 2.5)
    full = scheme(lk, P)
    own = {str(i) for i in links}
    pairs = tuple(p for p in full.pairs if own & set(p.links))
    near = {x for p in pairs for x in p.links} - own - {full.frame}
    mech = Mechanism(tuple(Link(x) for x in sorted(own | near)), pairs, full.frame)
    draw_scheme(v, mech, bodies=link_bodies(lk, P, links), pair_labels={}, ghosts=sorted(near))
    for i in links:
        _draw_loads(v, lk, P, gf.loads[i], kF.k, "vector")
    for r in gf.reactions:
        if r.on in links:
            force(v, r.at, r.force, kF.k, r.name, arrive=True, role="result", height=2.5)
            if r.couple:
                label = f"M_{{{r.of}{r.on}}}"
                moment(v, P.pos[r.joint], r.couple, 6.0, label, "result", height=2.5)
    if g is None:
        M = -sum(
            (ld.at - P.pos[lk.pivot]).cross(ld.force)
            if ld.force is not None and ld.at
            else ld.moment
            for ld in gf.loads[1]
        )
        v.turn(P.pos[lk.pivot], M, 30.0, "M_{ур}", 7.0, 250.0, "result", 2.5)


def _polygon(d: Drawing, gf: GroupForces, name: str, poly: ForcePolygon, cell: Box) -> None:
    pts = [q for pv in poly.vectors for q in (pv.tail, pv.head)]
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    w = cell[2] - cell[0] - 16.0
    h = cell[3] - cell[1] - TITLE_ROOM - 10.0
    need = max((max(xs) - min(xs)) / w, (max(ys) - min(ys)) / h, tol.EMPTY_PLAN)
    kF = nice_factor(need, 1.0, "F")
    if gf.group is None:
        title = "План сил кривошипа 1"
    elif "polygon of link" in name:
        title = f"План сил звена {name.rsplit(' ', 1)[-1]}"
    else:
        title = f"План сил группы ({', '.join(str(i) for i in gf.links)})"
    d.text(title, (cell[0] + 3.0, cell[1] + 4.0), 3.5)
    d.text(kF.label(), (cell[0] + 3.0, cell[1] + 9.0), 2.5)
    at = ((cell[0] + cell[2]) / 2.0, (cell[1] + TITLE_ROOM + cell[3]) / 2.0)
    v = d.viewport(kF, ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0), at)
    known = {n for n, _ in poly.solved}
    last = poly.vectors[-1].name if not poly.solved else ""
    for pv in poly.vectors:
        if kF.mm(pv.magnitude) < 0.3:
            continue
        found = pv.name in known or pv.name == last
        v.arrow(pv.tail, pv.head, "result" if found else "vector")
        mid = (pv.tail + pv.head) * 0.5
        v.label(mid, pv.name, 2.5, clear=0.5)
    v.dot(poly.pole)


def _lever(d: Drawing, lk: Linkage, P: Position, f: Forces) -> None:
    lev = f.lever
    pts = [Vec(0.0, 0.0), *lev.images.values(), *(it.image for it in lev.items)]
    xs = [q.x for q in pts]
    ys = [q.y for q in pts]
    bx0, by0, bx1, by1 = LEVER
    w, h = bx1 - bx0 - 2.0 * LOAD_MM, by1 - by0 - TITLE_ROOM - 2.0 * LOAD_MM
    kv = nice_factor(
        max((max(xs) - min(xs)) / w, (max(ys) - min(ys)) / h, tol.EMPTY_PLAN), 1.0, "v"
    )
    forces = [it.force.norm for it in lev.items] + [lev.F_bal.norm]
    kF = nice_factor(max(forces, default=0.0) or 1.0, LEVER_LOAD_MM, "F")
    d.text("Рычаг Жуковского", (bx0 + 2.0, by0 + 4.0), 5.0)
    d.text(f"{kv.label()};  {kF.label()};  M_{{ур}} = {_num(lev.M_bal)} Н·м",
           (bx0 + 2.0, by0 + 10.0), 3.5)  # fmt: skip
    at = ((bx0 + bx1) / 2.0, (by0 + TITLE_ROOM + by1) / 2.0)
    v = d.viewport(kv, ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0), at)
    for vec in P.vp.vectors:
        a, b = P.vp.points[vec.tail].perp(), P.vp.points[vec.head].perp()
        if kv.mm((b - a).norm) > 0.3:
            v.seg(a, b, "construction")
    groups: list[tuple[Vec, list[str]]] = [(Vec(0.0, 0.0), ["p"])]
    for name, im in lev.images.items():
        for q, names in groups:
            if kv.mm(im.dist(q)) < 0.8:
                names.append(markup_of(plan_name(name)))
                break
        else:
            groups.append((im, [markup_of(plan_name(name))]))
    for q, names in groups:
        v.dot(q)
        v.label(q, ", ".join(names), 2.5, clear=0.8)
    for it in lev.items:
        if kF.mm(it.force.norm) >= 1.0:
            force(v, it.image, it.force, kF.k, it.name, height=2.5)
    force(v, lev.images[lk.joint], lev.F_bal, kF.k, "P_{ур}", role="result", height=2.5)


def _table2(d: Drawing, lk: Linkage, f: Forces) -> None:
    rows: list[list[str]] = [["Нагрузка", "Значение", "Ед."]]
    for lds in f.loads.values():
        for ld in lds:
            if ld.force is not None:
                rows.append([ld.name, _num(ld.force.norm), "Н"])
            else:
                rows.append([ld.name, _num(ld.moment), "Н·м"])
    big = max(r.force.norm for r in f.reactions)
    for i, j in f.pairs:
        name = f"R_{{{i}{j}}}" if j < 10 else f"R_{{{i},{j}}}"
        rows.append([name, _num(f.R(i, j).norm, scale=big), "Н"])
    for r in f.reactions:
        if r.couple:
            rows.append([f"M_{{{r.of}{r.on}}}", _num(r.couple), "Н·м"])
    rows.append(["M_{ур} (силы)", _num(f.M_bal), "Н·м"])
    rows.append(["M_{ур} (рычаг)", _num(f.lever.M_bal), "Н·м"])
    x0, y0, x1, y1 = TABLE
    row_h = min(6.0, (y1 - y0 - 10.0) / len(rows))
    d.text("Нагрузки и реакции", (x0, y0 + 4.0), 3.5)
    width = x1 - x0
    d.table(x0, y0 + 7.0, [0.45 * width, 0.35 * width, 0.2 * width], rows, 2.5, row_h)


# --- sheet 3 ------------------------------------------------------------------------------


def _sheet3(d: Drawing, s: Solved, fw: Flywheel) -> None:
    lk = s.linkage
    sign = 1.0 if lk.omega > 0 else -1.0
    psi = fw.psi
    deg = np.degrees(psi)
    n = len(fw.phis)
    psi_k = np.array([2.0 * math.pi * i / n for i in range(n + 1)])
    M_k = np.array([*fw.M_pr, fw.M_pr[0]])
    I_k = np.array([*fw.I_pr, fw.I_pr[0]])
    # the graphical integration through the numbered positions (trapezoids)
    A_k = sign * np.concatenate([[0.0], np.cumsum(0.5 * (M_k[1:] + M_k[:-1]) * np.diff(psi_k))])
    W = fw.dA - fw.M_drive * psi  # the loads' work, exact
    drive = fw.M_drive * psi
    rows = [
        ("M_{пр}", "Н·м", [fw.dense.M_pr * sign, np.full_like(psi, fw.M_drive)], psi_k, M_k * sign,
         "M"),
        ("A", "Дж", [-W, drive], psi_k, -A_k, "A"),
        ("ΔT", "Дж", [fw.dA], psi_k, A_k + fw.M_drive * psi_k, "T"),
        ("I_{пр}", "кг·м²", [fw.dense.I_pr], psi_k, I_k, "I"),
    ]  # fmt: skip
    x0, y0, x1, y1 = GRAPHS
    h = (y1 - y0) / len(rows)
    room_x = x1 - x0 - 42.0
    for i, (sym, unit, curves, gx, gy, name) in enumerate(rows):
        top = y0 + i * h + 12.0
        bottom = y0 + (i + 1) * h - 10.0
        lo = float(min(min(float(c.min()) for c in curves), float(gy.min()), 0.0))
        hi = float(max(max(float(c.max()) for c in curves), float(gy.max()), 0.0))
        ay = Axis.fit(sym, unit, lo, hi, bottom - top, name)
        ax = Axis("φ", "град", 0.0, 360.0, nice_step(360.0 / room_x), "φ", tick=30.0)
        gr = Graph(d, ax, ay, (x0 + 12.0, top + ay.mm(ay.hi - ay.zero)))
        gr.axes(tick_labels=True)
        for j, c in enumerate(curves):
            gr.curve(_thin(deg), _thin(c), "result" if j == 0 else "construction")
        for xx, yy in zip(np.degrees(gx), gy, strict=True):
            gr.point(float(xx), float(yy))
        d.text(f"{ay.factor_text()};  {ax.factor_text()}", (x1, y0 + i * h + 5.0), 2.5,
               anchor="right")  # fmt: skip
    _wittenbauer(d, fw)
    _omega(d, lk, fw)
    _table3(d, lk, fw)


#: At most about this many points of a curve are drawn.
CURVE_POINTS = 720


def _thin(y: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Every k-th sample of a dense curve, its last one kept."""
    k = max(1, len(y) // CURVE_POINTS)
    out = y[::k]
    return out if (len(y) - 1) % k == 0 else np.append(out, y[-1])


def _wittenbauer(d: Drawing, fw: Flywheel) -> None:
    bx0, by0, bx1, by1 = WITT
    I = fw.dense.I_pr  # noqa: E741
    T = fw.dA
    a, b = fw.segment
    k_max, k_min = 0.5 * fw.omega_max**2, 0.5 * fw.omega_min**2
    i_hi = float(I.max())
    lo = float(min(T.min(), b, 0.0))
    hi = float(max(T.max(), a + k_max * i_hi, 0.0))
    ay = Axis.fit("ΔT", "Дж", lo, hi, by1 - by0 - TITLE_ROOM - 30.0, "T")
    ax = Axis.fit("I_{пр}", "кг·м²", 0.0, i_hi, bx1 - bx0 - 60.0, "I")
    d.text("Диаграмма энергомасс (Виттенбауэра)", (bx0, by0 + 4.0), 5.0)
    tan_hi = k_max * ax.k / ay.k
    tan_lo = k_min * ax.k / ay.k
    d.text(
        f"{ay.factor_text()};  {ax.factor_text()};  "
        f"ψ_{{max}} = {_num(math.degrees(math.atan(tan_hi)))}°, "
        f"ψ_{{min}} = {_num(math.degrees(math.atan(tan_lo)))}°",
        (bx0, by0 + 10.0),
        2.5,
    )
    gr = Graph(d, ax, ay, (bx0 + 20.0, by0 + TITLE_ROOM + 16.0 + ay.mm(ay.hi - ay.zero)))
    gr.axes(tick_labels=True)
    gr.curve(_thin(I), _thin(T), "result")
    for y0, slope in ((a, k_max), (b, k_min)):
        x_end = min(i_hi, (ay.hi - y0) / slope) if slope > 0.0 else i_hi
        if x_end > 0.0:
            gr.curve([0.0, x_end], [y0, y0 + slope * x_end], "construction")
    gr.point(0.0, a, "a", prefer=(-1.0, 0.0))
    gr.point(0.0, b, "b", prefer=(-1.0, 0.0))
    gr.span_y(0.0, b, a, f"ab = {_num(a - b)} Дж")
    for (x, y), name in zip(fw.touch, ("ω_{max}", "ω_{min}"), strict=True):
        gr.point(x, y, name)


def _omega(d: Drawing, lk: Linkage, fw: Flywheel) -> None:
    bx0, by0, bx1, by1 = OMEGA
    assert fw.omega_psi is not None and fw.omega_t is not None
    lo = float(min(fw.omega_t.min(), fw.omega_min))
    hi = float(max(fw.omega_t.max(), fw.omega_max))
    pad = 0.25 * (hi - lo)
    ay = Axis.fit("ω_1", "с^{-1}", lo - pad, hi + pad, by1 - by0 - TITLE_ROOM - 25.0, "ω")
    ax = Axis("φ", "град", 0.0, 360.0, nice_step(360.0 / (bx1 - bx0 - 40.0)), "φ", tick=60.0)
    d.text("Угловая скорость кривошипа с маховиком", (bx0, by0 + 4.0), 3.5)
    d.text(
        f"{ay.factor_text()};  δ = {_num(lk.dynamics.delta if lk.dynamics else 0.0, 3)}, "
        f"по уравнению движения δ = {_num(fw.delta_achieved, 4)}",
        (bx0, by0 + 9.0),
        2.5,
    )
    gr = Graph(d, ax, ay, (bx0 + 16.0, by0 + TITLE_ROOM + 10.0 + ay.mm(ay.hi - ay.lo)))
    gr.axes(tick_labels=True)
    gr.curve(_thin(np.degrees(fw.omega_psi)), _thin(fw.omega_t), "result")
    for w in (fw.omega_max, fw.omega_min):
        gr.curve([0.0, 360.0], [w, w], "construction")


def _table3(d: Drawing, lk: Linkage, fw: Flywheel) -> None:
    x0, y0, x1, _ = TABLE3
    width = x1 - x0
    n = len(fw.phis)
    step = max(1, math.ceil(n / 12))
    rows: list[list[str]] = [["№", "φ_1, °", "I_{пр}, кг·м²", "M_{пр}, Н·м"]]
    si = max(abs(x) for x in fw.I_pr)
    sm = max(abs(x) for x in fw.M_pr)
    for i in range(0, n, step):
        rows.append(
            [
                str(i),
                _num(math.degrees(fw.phis[i]) % 360.0),
                _num(fw.I_pr[i], scale=si),
                _num(fw.M_pr[i], scale=sm),
            ]
        )
    d.text("Приведённые момент инерции и момент сил", (x0, y0 + 4.0), 3.5)
    _, th = d.table(x0, y0 + 7.0, [10.0, 0.25 * width, 0.35 * width, width - 10.0 - 0.6 * width],
                    rows, 2.5, 5.0)  # fmt: skip
    res = [
        ["A_{ц}", _num(fw.A_cycle), "Дж"],
        ["M_{дв}", _num(fw.M_drive), "Н·м"],
        ["ω_{max}", _num(fw.omega_max), "с^{-1}"],
        ["ω_{min}", _num(fw.omega_min), "с^{-1}"],
        ["J_{м}", _num(fw.J_flywheel), "кг·м²"],
    ]
    if fw.D > 0.0 and lk.dynamics is not None:
        kind = "диск" if lk.dynamics.flywheel == "disc" else "обод"
        res += [[f"D ({kind})", _num(fw.D), "м"], ["b", _num(fw.b), "м"],
                ["m", _num(fw.mass), "кг"]]  # fmt: skip
    yy = y0 + 7.0 + th + 4.0
    d.table(x0, yy, [0.4 * width, 0.35 * width, 0.25 * width], res, 2.5, 5.0, header=False)
