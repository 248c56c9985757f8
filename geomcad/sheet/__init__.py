"""The drawing model in sheet millimetres: pages, frame and title block, viewports at a scale,
line roles, labels, arrows, dimensions and kinematic symbols. No file I/O (see ``render``)."""

from geomcad.sheet.drawing import Drawing, Viewport
from geomcad.sheet.frame import FORMATS, Frame, TitleBlock, new_sheet, paper
from geomcad.sheet.model import ArcItem, CircleItem, Dash, Item, Polyline, Run, Sheet, TextItem
from geomcad.sheet.scale import (
    Scale,
    ScaleStyle,
    fmt_number,
    gost_length_scale,
    gost_scale_to_fit,
    nice_factor,
)

__all__ = [
    "FORMATS",
    "ArcItem",
    "CircleItem",
    "Dash",
    "Drawing",
    "Frame",
    "Item",
    "Polyline",
    "Run",
    "Scale",
    "ScaleStyle",
    "Sheet",
    "TextItem",
    "TitleBlock",
    "Viewport",
    "fmt_number",
    "gost_length_scale",
    "gost_scale_to_fit",
    "new_sheet",
    "nice_factor",
    "paper",
]


def start(fmt: str, tb: TitleBlock, landscape: bool = True) -> Drawing:
    """A new sheet with its frame and title block, ready to draw on."""
    sheet, frame = new_sheet(fmt, tb, landscape)
    return Drawing(sheet, frame)
