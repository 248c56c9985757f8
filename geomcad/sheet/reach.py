"""The room a drawing really takes at a scale: a view whose loads, values and labels are drawn
at their own factor (forces at μ_F, velocities at μ_V) reaches past its body's box by an amount
that depends on its length scale. :func:`drawn_extent` draws it once on a scratch sheet at that
scale and measures, so the view's extent takes in its loads' reach (arrange, measure at the
scale it got, arrange again until the scales settle).

Appended for the seed sheets (kulisa-23110713's free-body diagrams); any draw function.
"""

from __future__ import annotations

from collections.abc import Callable

from geomcad.sheet import start
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.frame import TitleBlock, paper
from geomcad.sheet.placer import centre_line
from geomcad.sheet.scale import Scale

Box = tuple[float, float, float, float]

#: The scratch sheet's format; the drawing is placed at its middle.
SCRATCH = "A3"


def drawn_extent(box: Box, draw_fn: Callable[[Viewport], None], k: Scale) -> Box:
    """The model box a view takes at scale ``k``: ``box`` (its body) with everything
    ``draw_fn`` draws round it (its labels placed) taken in."""
    d = start(SCRATCH, TitleBlock(title="", designation=""))
    first = len(d.sheet.items)
    w, h = paper(SCRATCH, True)
    at = (w / 2.0, h / 2.0)
    draw_fn(d.viewport(k, (box[0], box[3]), at))
    sheet = d.finish()
    x0, y0, x1, y1 = box
    for it in sheet.items[first:]:
        bx0, by0, bx1, by1 = centre_line(it).bounds
        x0, x1 = min(x0, box[0] + (bx0 - at[0]) * k.k), max(x1, box[0] + (bx1 - at[0]) * k.k)
        y0, y1 = min(y0, box[3] - (by1 - at[1]) * k.k), max(y1, box[3] - (by0 - at[1]) * k.k)
    return (x0, y0, x1, y1)
