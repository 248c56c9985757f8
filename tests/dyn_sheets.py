"""Layout checks for the dynamics problems' sheets (A3 landscape): no two texts overlap, every
drawn item lies inside the frame and off the title block, every glyph is in the font."""

from __future__ import annotations

import itertools
import math

from geomcad.sheet.model import ArcItem, CircleItem, Item, Polyline, Sheet, TextItem
from geomcad.sheet.text import box, metrics

Box = tuple[float, float, float, float]

A3_FRAME: Box = (20.0, 5.0, 415.0, 292.0)
A3_BLOCK: Box = (415.0 - 185.0, 292.0 - 55.0, 415.0, 292.0)


def text_box(t: TextItem) -> Box:
    w, up, down = box(t.runs, t.height)
    return (t.at[0], t.at[1] - up, t.at[0] + w, t.at[1] + down)


def item_box(it: Item) -> Box:
    if isinstance(it, TextItem):
        return text_box(it)
    if isinstance(it, Polyline):
        xs = [p[0] for p in it.points]
        ys = [p[1] for p in it.points]
    elif isinstance(it, CircleItem):
        xs = [it.c[0] - it.r, it.c[0] + it.r]
        ys = [it.c[1] - it.r, it.c[1] + it.r]
    else:
        assert isinstance(it, ArcItem)
        a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
        ts = [a0 + it.sweep * i / 200 for i in range(201)]
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


def layout_problems(sheet: Sheet) -> list[str]:
    """Everything wrong with a sheet's layout, in words (empty when it is fine)."""
    assert sheet.format == "A3"
    n = next(
        i for i, it in enumerate(sheet.items) if it.role not in ("frame", "frame_thin", "title")
    )
    drawn = sheet.items[n:]
    out: list[str] = []
    boxes = [(t, text_box(t)) for t in sheet.texts()]
    for (a, ba), (b, bb) in itertools.combinations(boxes, 2):
        if overlap(ba, bb):
            out.append(f"overlap: {a.text!r} {ba} × {b.text!r} {bb}")
    for it in drawn:
        b = item_box(it)
        what = f"{type(it).__name__} {it.role} {getattr(it, 'text', '')!r} {b}"
        if not inside(b, A3_FRAME):
            out.append(f"outside the frame: {what}")
        if overlap(b, A3_BLOCK):
            out.append(f"on the title block: {what}")
    m = metrics()
    for t in sheet.texts():
        for r in t.runs:
            m.advance(r.text, 1.0)  # raises ValueError naming a missing glyph
    return out


def labels(sheet: Sheet) -> set[str]:
    """The plain text of every placed label."""
    return {t.text for t in sheet.texts() if t.role == "label"}
