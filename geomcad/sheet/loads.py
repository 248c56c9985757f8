"""Loads on a free-body diagram: force vectors at a force scale and curved moment arrows.

A force is drawn as a vector of |F|/μ_F millimetres along its line of action, either leaving its
point of application (a pull, the usual way) or arriving at it (a push, where the tail would run
into the body). A moment is an arc around its point with an arrowhead giving its sense
(counter-clockwise for M > 0, as in the model). Both ask the drawing for a placed label.
"""

from __future__ import annotations

import math

from geomcad.geom import PointLike, Vec
from geomcad.sheet import symbols
from geomcad.sheet.drawing import Viewport, _arrow
from geomcad.sheet.model import XY, Polyline

#: A moment arrow's sweep (rad) and the gap between its ends.
MOMENT_SWEEP = math.radians(250.0)


def force(
    v: Viewport,
    at: PointLike,
    F: Vec,
    k_F: float,
    label: str = "",
    arrive: bool = False,
    role: str = "vector",
    height: float = 3.5,
    prefer: tuple[float, float] | None = None,
) -> tuple[XY, XY] | None:
    """The force ``F`` (N, model directions) at model point ``at``, |F|/k_F mm long.

    ``arrive`` draws it ending at the point instead of leaving it. Returns the (tail, tip) in
    sheet mm, or ``None`` for a zero force (nothing is drawn then).
    """
    length = F.norm / k_F
    if length <= 0.0:
        return None
    p = v.p(at)
    ux, uy = F.x / F.norm, -F.y / F.norm  # paper direction (y down)
    if arrive:
        tail, tip = (p[0] - ux * length, p[1] - uy * length), p
    else:
        tail, tip = p, (p[0] + ux * length, p[1] + uy * length)
    _arrow(v.sheet, tail, tip, role)
    if label:
        end = tail if arrive else tip
        mid = ((tail[0] + tip[0]) / 2.0, (tail[1] + tip[1]) / 2.0)
        away = (-ux, -uy) if arrive else (ux, uy)
        v.d.label(end, label, height, prefer=prefer or away, clear=1.0, others=(mid,))
    return tail, tip


def moment(
    v: Viewport,
    c: PointLike,
    M: float,
    r_mm: float = 7.0,
    label: str = "",
    role: str = "vector",
    start: float = math.radians(-35.0),
    height: float = 3.5,
) -> None:
    """A moment ``M`` (N·m, counter-clockwise positive) about model point ``c``: an arc of radius
    ``r_mm`` from the model angle ``start`` with an arrowhead at its end in the moment's sense.
    A zero moment draws nothing."""
    v.turn(c, M, math.degrees(start), label, r_mm, math.degrees(MOMENT_SWEEP), role, height)


def spring(v: Viewport, a: PointLike, b: PointLike, width_mm: float = 4.0, coils: int = 6) -> None:
    """A spring (GOST 2.770) from model point a to b: short straight ends and a zigzag of
    ``coils`` turns, ``width_mm`` across."""
    pa, pb = v.p(a), v.p(b)
    dx, dy = pb[0] - pa[0], pb[1] - pa[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    lead = min(2.0, 0.15 * length)
    body = length - 2.0 * lead
    pts: list[XY] = [pa, (pa[0] + ux * lead, pa[1] + uy * lead)]
    n = 2 * coils
    for i in range(n):
        t = lead + body * (i + 0.5) / n
        side = width_mm / 2.0 * (1.0 if i % 2 == 0 else -1.0)
        pts.append((pa[0] + ux * t + nx * side, pa[1] + uy * t + ny * side))
    pts += [(pb[0] - ux * lead, pb[1] - uy * lead), pb]
    v.sheet.add(Polyline(tuple(pts), "link"))


def damper(v: Viewport, a: PointLike, b: PointLike, width_mm: float = 5.0) -> None:
    """A viscous damper (dashpot) from model point a (its rod) to b (its cylinder's bottom): an
    open cylinder on b's side and a piston on a rod from a."""
    pa, pb = v.p(a), v.p(b)
    dx, dy = pb[0] - pa[0], pb[1] - pa[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    h = width_mm / 2.0
    cyl = 0.55 * length  # the cylinder's length, from b towards a

    def at(t: float, side: float = 0.0) -> XY:
        return (pa[0] + ux * t + nx * side, pa[1] + uy * t + ny * side)

    mouth = length - cyl
    v.sheet.add(Polyline((at(mouth, h), at(length, h), at(length, -h), at(mouth, -h)), "link"))
    v.sheet.add(Polyline((at(length), pb), "link"))
    piston = mouth + 0.3 * cyl
    v.sheet.add(Polyline((pa, at(piston)), "link"))
    v.sheet.add(Polyline((at(piston, 0.7 * h), at(piston, -0.7 * h)), "link"))


def ground(
    v: Viewport, a: PointLike, b: PointLike, side: tuple[float, float] = (0.0, -1.0)
) -> None:
    """A fixed support from model point a to b, hatched on the model side ``side``."""
    symbols.ground(v.sheet, v.p(a), v.p(b), v.paper_dir(side))
