"""Kinematic symbols (GOST 2.770), drawn in a local frame through one transform.

Every symbol is drawn in its own frame in paper millimetres: x along the symbol's axis (a guide,
a slider's sliding direction), y to its left, *up* when the axis points right — the way the
standard draws it. :class:`Local` maps that frame onto the sheet (the one turn and the one y
flip of the paper, y down); model directions reach it through
:meth:`~geomcad.sheet.drawing.Viewport.paper_dir`, so no symbol flips a y by hand.

Symbols: :func:`joint` (a revolute joint between moving links), :func:`pivot` (a revolute on
the frame: the joint, its stand and the hatched ground), :func:`ground` (a hatched line),
:func:`guide` (a fixed guide beside a sliding axis), :func:`block` (a slider block, with the
joint circle only where a link is jointed to it), :func:`bearing` (a shaft's bearing on the
frame) and :func:`gear` (a gear wheel as its pitch circle on its axis).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from geomcad.sheet.model import XY, CircleItem, Polyline, Sheet

#: Sizes on paper (mm).
JOINT_R = 1.5
SLIDER_SIZE = (9.0, 5.0)
HATCH_STEP = 2.0
HATCH_LEN = 2.5
#: A pivot's stand: its depth below the joint and its half width (mm).
STAND_DEPTH = 5.0
STAND_HALF = 3.5


@dataclass(frozen=True)
class Local:
    """A symbol's frame on the paper: ``origin`` (sheet mm) and the unit paper direction ``u``
    of its x axis; its y axis is x turned 90° counter-clockwise as seen on the paper."""

    origin: XY
    u: tuple[float, float] = (1.0, 0.0)

    @staticmethod
    def along(origin: XY, direction: tuple[float, float]) -> Local:
        """The frame at ``origin`` whose x axis runs along the paper ``direction``."""
        n = math.hypot(*direction)
        if n == 0.0:
            raise ValueError("a symbol's axis needs a direction")
        return Local(origin, (direction[0] / n, direction[1] / n))

    def p(self, x: float, y: float) -> XY:
        """A local point on the sheet."""
        ux, uy = self.u
        # y (left of u, "up") on paper with y down is (uy, -ux)
        return (self.origin[0] + x * ux + y * uy, self.origin[1] + x * uy - y * ux)

    def pts(self, local: Sequence[tuple[float, float]]) -> tuple[XY, ...]:
        return tuple(self.p(x, y) for x, y in local)


def joint(sheet: Sheet, at: XY, role: str = "joint") -> None:
    """A revolute joint: a small circle drawn over the links (filled white)."""
    sheet.add(CircleItem(at, JOINT_R, role, fill=True))


def ground(sheet: Sheet, a: XY, b: XY, outward: tuple[float, float]) -> None:
    """A ground line from a to b hatched on the ``outward`` side (a paper direction)."""
    length = math.dist(a, b)
    if length == 0.0:
        return
    sheet.add(Polyline((a, b), "link"))
    ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    n = max(2, int(length / HATCH_STEP))
    for i in range(n + 1):
        t = i * length / n
        sx, sy = a[0] + ux * t, a[1] + uy * t
        ex = sx + outward[0] * HATCH_LEN * 0.8 - ux * HATCH_LEN * 0.6
        ey = sy + outward[1] * HATCH_LEN * 0.8 - uy * HATCH_LEN * 0.6
        sheet.add(Polyline(((sx, sy), (ex, ey)), "ground"))


def pivot(sheet: Sheet, at: XY, down: tuple[float, float] = (0.0, 1.0)) -> None:
    """A revolute joint on the frame: the joint, a stand of two lines to the ground and the
    hatched ground, with the stand pointing along the paper direction ``down``."""
    n = math.hypot(*down)
    dx, dy = down[0] / n, down[1] / n
    px, py = -dy, dx  # across the stand
    bx, by = at[0] + dx * STAND_DEPTH, at[1] + dy * STAND_DEPTH
    a = (bx + px * STAND_HALF, by + py * STAND_HALF)
    b = (bx - px * STAND_HALF, by - py * STAND_HALF)
    sheet.add(Polyline((at, a), "link"))
    sheet.add(Polyline((at, b), "link"))
    ground(sheet, (a[0] + px * 1.5, a[1] + py * 1.5), (b[0] - px * 1.5, b[1] - py * 1.5), (dx, dy))
    joint(sheet, at)


def guide(
    sheet: Sheet, a: XY, b: XY, side: tuple[float, float], block: float = SLIDER_SIZE[1]
) -> None:
    """A fixed guide along the sliding axis from a to b, drawn clear of the slider block
    (``block`` mm across the guide) on the paper side ``side`` and hatched away from the axis
    (the offset and the hatching scale with ``side``'s length: give a unit vector)."""
    out = side
    off = block / 2.0 + 0.6
    ground(
        sheet,
        (a[0] + out[0] * off, a[1] + out[1] * off),
        (b[0] + out[0] * off, b[1] + out[1] * off),
        out,
    )


def block(
    sheet: Sheet,
    at: XY,
    along: tuple[float, float],
    role: str = "link",
    with_joint: bool = True,
    size: tuple[float, float] = SLIDER_SIZE,
) -> None:
    """A slider block centred at ``at`` along the paper direction ``along``; the joint circle
    inside it only ``with_joint`` (a link jointed to the block). ``role`` "extreme" draws an
    extreme position in thin two-dot lines; "result" a highlighted block."""
    f = Local.along(at, along)
    hw, hh = size[0] / 2.0, size[1] / 2.0
    corners = f.pts(((-hw, hh), (hw, hh), (hw, -hh), (-hw, -hh)))
    sheet.add(Polyline(corners, "joint" if role in ("link", "extreme") else role, closed=True,
                       fill=True))  # fmt: skip
    sheet.add(Polyline(corners, role, closed=True))
    if with_joint:
        joint(sheet, at)
        if role != "link":
            sheet.add(CircleItem(at, JOINT_R, role))


def bearing(sheet: Sheet, at: XY, axis: tuple[float, float], half: float = 4.0) -> None:
    """A shaft's radial bearing on the frame (GOST 2.770): two short strokes across the shaft's
    ``axis`` (a paper direction) on either side of it, each on hatched ground."""
    f = Local.along(at, axis)
    for s in (1.0, -1.0):
        a, b = f.p(-half / 2.0, s * 2.0), f.p(half / 2.0, s * 2.0)
        sheet.add(Polyline((a, b), "link"))
        c, e = f.p(-half / 2.0 - 1.0, s * 3.5), f.p(half / 2.0 + 1.0, s * 3.5)
        oy = f.p(0.0, s)
        ground(sheet, c, e, (oy[0] - at[0], oy[1] - at[1]))
        sheet.add(Polyline((f.p(0.0, s * 2.0), f.p(0.0, s * 3.5)), "link"))


def gear(sheet: Sheet, centre: XY, r: float, role: str = "link") -> None:
    """A gear wheel on a kinematic scheme (GOST 2.770): its pitch circle of ``r`` mm about its
    axis, with the axis's joint."""
    sheet.add(CircleItem(centre, r, role))
    joint(sheet, centre)
