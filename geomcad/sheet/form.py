"""The room the form takes in the field: what a composed sheet keeps free so that its views
stay clear of the title block (a :class:`~geomcad.sheet.compose.Spacer` of this size at the
foot of the right-hand column, or beside the view that would run over it).

Appended for the seed sheets; it reads the field's own boxes, so a change of the form moves
every sheet that keeps its corner free.
"""

from __future__ import annotations

from geomcad.sheet import Sheet, TitleBlock, start
from geomcad.sheet.compose import Field, Layout, Spacer, Tree, compose
from geomcad.sheet.lang import Words

#: The width (mm) of :func:`title_block_spacer`: narrow, so that it widens no column.
SPACER_W = 10.0


def title_block_room(fmt: str = "A3", landscape: bool = True) -> tuple[float, float]:
    """The width and height (mm) of the title block with the field's margin round it, in the
    lower right corner of the field of ``fmt``."""
    tb = Field.of_format(fmt, landscape).obstacles[0]
    return tb[2] - tb[0], tb[3] - tb[1]


def title_block_spacer(fmt: str = "A3", landscape: bool = True) -> Spacer:
    """Room as tall as the title block with its margin (and narrow), for the foot of the
    column over the title block."""
    return Spacer((SPACER_W, title_block_room(fmt, landscape)[1]))


def composed(
    fmt: str,
    tree: Tree,
    words: Words,
    scale: str = "",
    layout: Layout | None = None,
    title: str = "tb_title",
) -> Sheet:
    """A sheet of ``fmt`` with ``tree`` composed on it (:func:`~geomcad.sheet.compose.compose`,
    or ``layout`` as arranged) under the title block named by the sheet's ``words`` (its
    ``title`` and ``designation``) with the main view's ``scale`` (Масштаб, as ratio text)."""
    tb = TitleBlock(title=words(title), designation=words("designation"), scale=scale)
    d = start(fmt, tb)
    compose(d, tree, layout=layout)
    return d.finish()
