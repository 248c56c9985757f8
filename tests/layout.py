"""Layout checks shared by the sheet tests: paper boxes of items, overlap and containment, and
`layout_problems`, which lists everything wrong with a sheet in words. The frame and the title
block are derived from the sheet's own size (GOST 2.301: 20 mm left, 5 mm elsewhere; GOST 2.104
form 1: 185 × 55 mm in the lower right corner)."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable

from geomcad.sheet.model import CircleItem, Item, Polyline, Sheet, TextItem
from geomcad.sheet.text import box, metrics

Box = tuple[float, float, float, float]  # x0, y0 (top), x1, y1 (bottom), sheet mm


def frame_box(sheet: Sheet) -> Box:
    """The inner frame of a sheet."""
    return (20.0, 5.0, sheet.width - 5.0, sheet.height - 5.0)


def block_box(sheet: Sheet) -> Box:
    """The title block (form 1) in the frame's lower right corner."""
    x1, y1 = sheet.width - 5.0, sheet.height - 5.0
    return (x1 - 185.0, y1 - 55.0, x1, y1)


# A3 landscape, as most sheets are
A3_FRAME: Box = (20.0, 5.0, 415.0, 292.0)
A3_BLOCK: Box = (415.0 - 185.0, 292.0 - 55.0, 415.0, 292.0)


def text_box(t: TextItem) -> Box:
    w, up, down = box(t.runs, t.height)
    return (t.at[0], t.at[1] - up, t.at[0] + w, t.at[1] + down)


def item_box(it: Item) -> Box:
    """The paper extent of an item (an arc sampled along its sweep)."""
    if isinstance(it, TextItem):
        return text_box(it)
    if isinstance(it, Polyline):
        xs = [p[0] for p in it.points]
        ys = [p[1] for p in it.points]
    elif isinstance(it, CircleItem):
        xs = [it.c[0] - it.r, it.c[0] + it.r]
        ys = [it.c[1] - it.r, it.c[1] + it.r]
    else:
        # y is down on paper: a clockwise sweep (> 0) is an increasing atan2 angle
        a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
        ts = [a0 + it.sweep * i / 400 for i in range(401)]
        xs = [it.c[0] + it.r * math.cos(t) for t in ts]
        ys = [it.c[1] + it.r * math.sin(t) for t in ts]
    return (min(xs), min(ys), max(xs), max(ys))


def overlap(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def inside(a: Box, outer: Box, tol: float = 1e-9) -> bool:
    return (
        a[0] >= outer[0] - tol
        and a[1] >= outer[1] - tol
        and a[2] <= outer[2] + tol
        and a[3] <= outer[3] + tol
    )


def overlapping_texts(texts: Iterable[TextItem]) -> list[str]:
    boxes = [(t, text_box(t)) for t in texts]
    return [
        f"{a.text!r} {ba} × {b.text!r} {bb}"
        for (a, ba), (b, bb) in itertools.combinations(boxes, 2)
        if overlap(ba, bb)
    ]


def block_part(sheet: Sheet) -> tuple[list[Item], list[Item]]:
    """(the frame and title block, everything drawn after them): new_sheet draws those first."""
    n = next(
        i for i, it in enumerate(sheet.items) if it.role not in ("frame", "frame_thin", "title")
    )
    return sheet.items[:n], sheet.items[n:]


def layout_problems(sheet: Sheet, drawing_right: float | None = None) -> list[str]:
    """Everything wrong with a sheet's layout, in words (empty when it is fine): texts on one
    another, items outside the frame or on the title block, a glyph the font lacks, and, with
    ``drawing_right``, drawn lines reaching the tables that start at that x (mm)."""
    frame, block = frame_box(sheet), block_box(sheet)
    out = [f"overlap: {o}" for o in overlapping_texts(sheet.texts())]
    for it in block_part(sheet)[1]:
        b = item_box(it)
        what = f"{type(it).__name__} {it.role} {getattr(it, 'text', '')!r} {b}"
        if not inside(b, frame):
            out.append(f"outside the frame: {what}")
        if overlap(b, block):
            out.append(f"on the title block: {what}")
        lines = it.role not in ("frame", "frame_thin", "title", "label")
        if drawing_right is not None and lines and b[2] >= drawing_right:
            out.append(f"the drawing reaches the tables: {what}")
    m = metrics()
    for t in sheet.texts():
        for r in t.runs:
            m.advance(r.text, 1.0)  # raises ValueError naming a missing glyph
    return out


def labels(sheet: Sheet) -> set[str]:
    """The plain text of every placed label."""
    return {t.text for t in sheet.texts() if t.role == "label"}
