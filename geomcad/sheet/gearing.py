"""Gear trains in the axial section (GOST 2.770), drawn through a viewport in model units.

A gear is its web from the hub to the rim at the pitch radius, the rim of the gear's width (both
halves about its axis); an internal gear a cup open towards its mesh; a shaft's bearing a small
box round it, on the frame with a post down to a hatched ground line. Used by the seed problem
2013-5's scheme and the planetary train of a gear file.
"""

from __future__ import annotations

from geomcad.geom import Vec
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.model import Polyline


def gear_web(
    v: Viewport,
    x: float,
    y_c: float,
    r: float,
    b: float,
    halves: tuple[int, ...] = (1, -1),
    hub: float = 0.0,
) -> None:
    """An external gear (GOST 2.770): its web from the hub (``hub`` off the axis) to the rim at
    the pitch radius r, the rim of width b."""
    for s in halves:
        v.seg(Vec(x, y_c + s * hub), Vec(x, y_c + s * r), "link")
        v.seg(Vec(x - b / 2.0, y_c + s * r), Vec(x + b / 2.0, y_c + s * r), "link")


def ring_gear(v: Viewport, x: float, x_web: float, y_c: float, r: float, b: float) -> None:
    """An internal gear: the rim at the pitch radius from x − b/2 to the web at ``x_web`` (a cup
    open towards its mesh), the web across the axis."""
    for s in (1, -1):
        v.seg(Vec(x - b / 2.0, y_c + s * r), Vec(x_web, y_c + s * r), "link")
    v.seg(Vec(x_web, y_c - r), Vec(x_web, y_c + r), "link")


def ground_line(v: Viewport, at: Vec, half_mm: float = 5.0) -> None:
    """The frame under a support: a ground line hatched below (sheet mm from the model point)."""
    x, y = v.p(at)
    s = v.sheet
    s.add(Polyline(((x - half_mm, y), (x + half_mm, y)), "link"))
    n = int(2.0 * half_mm / 2.0)
    for i in range(n + 1):
        hx = x - half_mm + i * 2.0 * half_mm / n
        s.add(Polyline(((hx, y), (hx - 2.0, y + 2.5)), "ground"))


def shaft_bearing(v: Viewport, at: Vec, on_frame: bool, drop: float = 0.0) -> None:
    """A revolute pair on a shaft: a small box round it; on the frame, a post down to the ground
    (``drop`` model units long)."""
    x, y = v.p(at)
    w, h = 4.0, 3.0
    box = (
        (x - w / 2, y - h / 2),
        (x + w / 2, y - h / 2),
        (x + w / 2, y + h / 2),
        (x - w / 2, y + h / 2),
    )
    v.sheet.add(Polyline(box, "joint", closed=True, fill=True))
    v.sheet.add(Polyline(box, "link", closed=True))
    if on_frame:
        foot = Vec(at.x, at.y - drop)
        v.sheet.add(Polyline(((x, y + h / 2), v.p(foot)), "link"))
        ground_line(v, foot)
