"""A data point of a diagram named by a text set apart from it: where the point's own corner
holds the tick values or the curve (a peak on the y axis, a value at the foot of a drop), the
text goes to a stated offset inside the field, with a thin leader back to the point.

Appended for the seed sheets (2013-8's F_max and ω_min); any :class:`~geomcad.sheet.graph.Graph`.
"""

from __future__ import annotations

from geomcad.sheet.graph import Graph
from geomcad.sheet.model import CircleItem, Polyline

#: The marked point's radius (mm).
POINT_R = 0.6
#: The leader stops this far (mm) short of the text's base line start, left and up.
LEADER_SHORT = (0.8, 1.0)


def set_off(
    g: Graph,
    x: float,
    y: float,
    markup: str,
    off: tuple[float, float],
    leader: bool = True,
    height: float = 2.5,
) -> None:
    """The data point (x, y) marked and named by ``markup`` whose base line starts at ``off``
    (mm, y down) from it, with a thin leader to the text when ``leader``."""
    px, py = g.p(x, y)
    g.d.sheet.add(CircleItem((px, py), POINT_R, "point", fill=True))
    if leader:
        end = (px + off[0] - LEADER_SHORT[0], py + off[1] - LEADER_SHORT[1])
        g.d.sheet.add(Polyline(((px, py), end), "dimension"))
    g.d.text(markup, (px + off[0], py + off[1]), height)
