"""Velocity and acceleration plans on a sheet, drawn from the recorded :class:`Plan`.

The plan is drawn as the subject draws it: the thin construction lines of each vector equation
(each spanning the points it joins, a little beyond), the vectors with their arrowheads (the
found ones in the result colour), the points lettered in lower case with subscripts (``b_3``;
coincident points share one label, ``p, o_1, o_2``), and a title with the scale factor:
"План скоростей, μ_V = 0,02 (м/с)/мм" (its words from ``strings/<lang>/plans.toml``).
"""

from __future__ import annotations

import copy
import re
from collections.abc import Collection, Mapping

from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan
from geomcad.sheet.drawing import Drawing, Viewport
from geomcad.sheet.lang import Lang, Words, current
from geomcad.sheet.scale import PLAN_NICE, Scale, ScaleStyle, nice_factor

#: Points closer than this on the paper (mm) share one label.
SAME_POINT_MM = 0.8
#: Distinct points closer than this on the paper (mm, in a chain) are lettered as one list
#: (``a, s_2``) beside whichever of them it stands clearest at: their letters would crowd.
NEAR_POINT_MM = 3.0
#: Construction lines run this far past the points they join (mm).
LINE_OVER_MM = 8.0

#: The plans' titles (``v``, ``a``), per language.
TITLES = Words(__package__, "plans")


def markup_of(name: str) -> str:
    """A plan point's step name as label markup: ``b3`` → ``b_3``, ``n_BA`` → ``n_{BA}``,
    ``c4'`` → ``c_4'``."""
    m = re.fullmatch(r"([^\d_']+)_?([^']*)('*)", name)
    if m is None or not m.group(2):
        return name
    base, sub, prime = m.groups()
    return f"{base}_{{{sub}}}{prime}" if len(sub) > 1 else f"{base}_{sub}{prime}"


def plan_scale(plan: Plan, width_mm: float, height_mm: float) -> Scale:
    """The plan's factor (1, 2 or 5 × 10^n) at which the whole plan fits ``width × height``."""
    x0, y0, x1, y1 = plan.extent()
    need = max((x1 - x0) / width_mm, (y1 - y0) / height_mm)
    return nice_factor(need, 1.0, plan.kind, PLAN_NICE)


def draw_plan(
    d: Drawing,
    plan: Plan,
    scale: Scale,
    box: tuple[float, float, float, float],
    lang: Lang | None = None,
    style: ScaleStyle | None = None,
    title: str | None = None,
    min_mm: float = 0.5,
) -> Viewport:
    """Draw ``plan`` at ``scale`` centred in the sheet rectangle ``box`` (x0, y0, x1, y1; the
    title goes on its top edge: ``title``, or the plan's kind with its factor) and return the
    viewport (pole at the plan's origin). A vector shorter than ``min_mm`` on the paper gets
    no arrow: its end point and label stand for it (the caller says so in a note)."""
    x0, y0, x1, y1 = plan.extent()
    bx0, by0, bx1, by1 = box
    if title is None:
        lang = lang or current()
        title = f"{TITLES(plan.kind, lang)}, {scale.label(style or ScaleStyle(lang=lang))}"
    d.text(title, (bx0, by0 + 3.5), 3.5)
    at = ((bx0 + bx1) / 2.0, (by0 + 6.0 + by1) / 2.0)
    v = d.viewport(scale, ((x0 + x1) / 2.0, (y0 + y1) / 2.0), at)
    plan_lines(v, plan, min_mm)
    return v


#: A centre of mass's image (:func:`with_centres`) is drawn where it stands at least this far
#: (mm) from every other point of its plan: nearer, its letters would crowd theirs (a rocker's
#: s3 beside "p, o, c" where the rocker is nearly at rest).
CENTRE_APART_MM = 2.0 * NEAR_POINT_MM
#: ... and its letters keep this much more room (mm) from the plan's other letters.
CENTRE_SPACE_MM = 0.5


def with_centres(plan: Plan, centres: Mapping[str, tuple[str, str]]) -> Plan:
    """A copy of ``plan`` with the images of links' centres of mass: ``centres`` maps a new
    point's name to the two plan points whose middle it is (``s2``: the middle of ab, by
    similarity: S2 is the middle of AB). The position's own plan is its construction's
    record and keeps its points."""
    add = {n: (plan.points[a] + plan.points[b]) * 0.5 for n, (a, b) in centres.items()}
    if not add:
        return plan
    out = copy.copy(plan)
    out.points = {**plan.points, **add}
    out.images = [*plan.images, *((a, b, n) for n, (a, b) in centres.items())]
    return out


def _crowded(plan: Plan, scale: Scale, centres: Collection[str]) -> Plan:
    """``plan`` without those of its ``centres`` that stand nearer than
    :data:`CENTRE_APART_MM` on the paper to another of its points."""
    near = {
        n
        for n in centres
        if n in plan.points
        and any(
            m != n and scale.mm((q - plan.points[n]).norm) < CENTRE_APART_MM
            for m, q in plan.points.items()
        )
    }
    if not near:
        return plan
    out = copy.copy(plan)
    out.points = {n: q for n, q in plan.points.items() if n not in near}
    out.images = [im for im in plan.images if im[2] not in near]
    return out


def plan_lines(
    v: Viewport,
    plan: Plan,
    min_mm: float = 0.5,
    over_mm: float = LINE_OVER_MM,
    centres: Collection[str] = (),
) -> None:
    """The plan drawn through viewport ``v`` (its pole where ``v`` puts the plan's origin): the
    construction lines (run on ``over_mm`` past their points), the vectors (those shorter than
    ``min_mm`` on the paper without an arrow) and the lettered points; of the images of
    centres of mass named in ``centres``, those clear of the other points
    (:data:`CENTRE_APART_MM`)."""
    scale = v.scale
    plan = _crowded(plan, scale, centres)
    over = scale.model(over_mm)
    for ln in plan.lines:
        solved = ln.step.rsplit(":", 1)[0]
        ts = [ln.line.param(plan.points[n]) for n in (ln.through, solved)]
        v.seg(ln.line.at(min(ts) - over), ln.line.at(max(ts) + over), "construction")
    for vec in plan.vectors:
        a, b = plan.points[vec.tail], plan.points[vec.head]
        if scale.mm((b - a).norm) >= min_mm:
            v.arrow(a, b, "vector" if vec.known else "result")
    images(v, plan, min_mm)
    for g in _near(plan.points, scale):
        places: list[Vec] = []
        for n in g:
            q = plan.points[n]
            if all(scale.mm((q - o).norm) >= SAME_POINT_MM for o in places):
                places.append(q)
                v.dot(q)
        # a centre's letters (drawn where they find room: CENTRE_APART_MM) kept a little
        # further from the others' than a plan's own letters
        space = CENTRE_SPACE_MM if any(n in centres for n in g) else 0.0
        v.label(places[0], ", ".join(markup_of(n) for n in g), 3.5, clear=1.0,
                others=places[1:], space=space)  # fmt: skip


def _near(points: Mapping[str, Vec], scale: Scale) -> list[list[str]]:
    """A plan's points in the sets lettered as one list: chains of points each closer than
    :data:`NEAR_POINT_MM` on the paper to the next, in the plan's order."""
    names = list(points)
    root = list(range(len(names)))

    def find(i: int) -> int:
        while root[i] != i:
            i = root[i]
        return i

    for i, a in enumerate(names):
        for j in range(i):
            if scale.mm((points[a] - points[names[j]]).norm) < NEAR_POINT_MM:
                root[find(i)] = find(j)
    groups: dict[int, list[str]] = {}
    for i, a in enumerate(names):
        groups.setdefault(find(i), []).append(a)
    return list(groups.values())


def images(v: Viewport, plan: Plan, min_mm: float = 0.5) -> None:
    """Every point the plan finds by similarity drawn complete: the image triangle ``abm`` of
    the link's points in thin lines (similar to ABM, turned the same way) and the point's
    absolute vector from the pole (``pm`` = V_M, ``πm′`` = a_M), unless a vector from the pole
    to it is drawn already or it is shorter than ``min_mm`` on the paper."""
    scale = v.scale
    pole = plan.pole
    drawn = {vec.head for vec in plan.vectors if vec.tail in {pole, *plan.at_pole}}
    for a, b, q in plan.images:
        pa, pb, pq = plan.points[a], plan.points[b], plan.points[q]
        for u, w in ((pa, pq), (pb, pq), (pa, pb)):
            if scale.mm((w - u).norm) >= min_mm:
                v.seg(u, w, "construction")
        if q not in drawn and scale.mm((pq - plan.points[pole]).norm) >= min_mm:
            v.arrow(plan.points[pole], pq, "result")
            drawn.add(q)


def vector_rows(plan: Plan, scale: Scale, digits: int = 4) -> list[tuple[str, str, float, float]]:
    """The plan's vectors as table rows: (step, label markup, value, length in mm)."""
    rows = []
    for vec in plan.vectors:
        value = (plan.points[vec.head] - plan.points[vec.tail]).norm
        rows.append((vec.step, vec.label, value, round(scale.mm(value), digits)))
    return rows
