"""The layout checker every sheet test uses (issue 14): what a teacher and a нормоконтроль
checker would return a sheet for, in words.

Geometry goes through shapely: every text is a (turned) box, every drawn line a stroke buffered
by half its width, and an STRtree answers which of them meet. The form (frame, title block,
графа 26, the captions under the frame) is told apart by where it lies, not by drawing order.

Two levels:

- :func:`layout_problems` — what no sheet may have: texts on texts, items outside the frame or on
  the title block or графа 26, glyphs the font lacks, colour in a default (black) build, and a
  plan's or polygon's vector drawn at a scale the sheet does not state (not at its μ).
- :func:`findings` — the drafting findings (:data:`KINDS`): a label crossed by a line, a label
  far from what it names, a vector shorter than twice its head, an empty field. Every sheet is
  held to a recorded count per kind (``BASELINE`` in tests/test_layout_all.py, ``FINDINGS`` in
  tests/test_design_files.py) that may only fall.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass

import shapely
from shapely.geometry import Point, Polygon
from shapely.geometry import box as sbox
from shapely.strtree import STRtree

from geomcad.render import to_svg
from geomcad.sheet.drawing import ARROW_LEN
from geomcad.sheet.frame import reserved
from geomcad.sheet.model import ArcItem, CircleItem, Item, Polyline, Sheet, TextItem
from geomcad.sheet.placer import centre_line, ink, text_outline
from geomcad.sheet.scale import fmt_number
from geomcad.sheet.text import metrics

Box = tuple[float, float, float, float]  # x0, y0 (top), x1, y1 (bottom), sheet mm

#: The drafting findings, each with what it means.
KINDS = {
    "label-line": "a label crossed by a drawn line",
    "tick-label": "a diagram's tick value crossed by a curve or another line",
    "anchor": "a placed label farther than ANCHOR_MAX from the point it names",
    "short-vector": "a vector shorter than twice its arrowhead",
    "empty": "more than EMPTY_MAX of the field left empty",
}
#: A placed label's box keeps within this distance (mm) of its anchor.
ANCHOR_MAX = 6.0
#: The share of the field (10 mm cells) that may stay empty.
EMPTY_MAX = 0.5
#: Overlaps smaller than this (mm²) are touching, not overlapping.
AREA_EPS = 0.05
#: A tick value: a number alone, in the diagrams' small lettering.
TICK_VALUE = re.compile(r"[-−–]?\d+(?:[.,]\d+)?")
TICK_HEIGHT = 2.5


def is_tick_value(t: TextItem) -> bool:
    """Whether a text is a diagram's tick value (a bare number at most TICK_HEIGHT tall)."""
    return t.height <= TICK_HEIGHT and TICK_VALUE.fullmatch(t.text) is not None


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


def text_poly(t: TextItem) -> Polygon:
    """The text's box on the paper, turned by its angle about its baseline's start (the placer's
    own outline, so that the checker and the placer measure alike)."""
    return text_outline(t)


def text_box(t: TextItem) -> Box:
    x0, y0, x1, y1 = text_poly(t).bounds
    return (x0, y0, x1, y1)


def geometry(it: Item) -> shapely.Geometry:
    """The item's centre line (a filled shape: its area; a text: its box)."""
    return centre_line(it)


def stroke(it: Item, fmt: str) -> shapely.Geometry:
    """The ink of a line: its centre line buffered by half its width."""
    return ink(it, fmt)


def item_box(it: Item) -> Box:
    """The paper extent of an item."""
    x0, y0, x1, y1 = geometry(it).bounds
    return (x0, y0, x1, y1)


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
    """Pairs of texts whose boxes overlap (an STRtree query over the boxes)."""
    ts = list(texts)
    polys = [text_poly(t) for t in ts]
    tree = STRtree(polys)
    out = []
    for i, p in enumerate(polys):
        for j in tree.query(p, predicate="intersects"):
            if j > i and p.intersection(polys[j]).area > AREA_EPS:
                out.append(f"{ts[i].text!r} {text_box(ts[i])} × {ts[j].text!r} {text_box(ts[j])}")
    return out


def _form_boxes(sheet: Sheet) -> list[Polygon]:
    x1, y1 = sheet.width - 5.0, sheet.height - 5.0
    under = sbox(x1 - 185.0, y1, x1, sheet.height)  # "Копировал", "Формат" under the frame
    return [sbox(*b) for b in reserved(sheet.width, sheet.height)] + [under]


def block_part(sheet: Sheet) -> tuple[list[Item], list[Item]]:
    """(the form: frame, title block, графа 26 and their texts; everything drawn on the field)."""
    forms = _form_boxes(sheet)
    outer = sbox(*frame_box(sheet))
    form: list[Item] = []
    drawn: list[Item] = []
    for it in sheet.items:
        if it.role in ("frame", "frame_thin", "title"):
            g = geometry(it)
            on_form = any(f.buffer(1e-6).covers(g) for f in forms)
            if on_form or (isinstance(it, Polyline) and g.equals(outer.exterior)):
                form.append(it)
                continue
        drawn.append(it)
    return form, drawn


def colours(svg: str) -> set[str]:
    """The paints of an SVG other than black, white and none."""
    paints = set(re.findall(r'(?:stroke|fill)="([^"]+)"', svg))
    return {p for p in paints if p.lower() not in ("#000000", "#ffffff", "none", "black", "white")}


def layout_problems(sheet: Sheet, drawing_right: float | None = None) -> list[str]:
    """Everything no sheet may have, in words (empty when it is fine): texts on one another,
    items outside the frame or on the title block or графа 26, a glyph the font lacks, colour in
    the default build, and, with ``drawing_right``, drawn lines reaching the tables that start at
    that x (mm)."""
    frame = sbox(*frame_box(sheet)).buffer(1e-6)
    forms = [sbox(*b) for b in reserved(sheet.width, sheet.height)]
    _form, drawn = block_part(sheet)
    out = [f"overlap: {o}" for o in overlapping_texts(t for t in drawn if isinstance(t, TextItem))]
    for it in drawn:
        g = geometry(it)
        what = f"{type(it).__name__} {it.role} {getattr(it, 'text', '')!r} {item_box(it)}"
        if not frame.covers(g):
            out.append(f"outside the frame: {what}")
        for f in forms:
            if g.intersection(f).area > AREA_EPS or (
                not isinstance(g, Polygon) and g.intersection(f).length > 0.1
            ):
                out.append(f"on the title block or графа 26: {what}")
        lines = it.role not in ("frame", "frame_thin", "title", "label")
        if drawing_right is not None and lines and item_box(it)[2] >= drawing_right:
            out.append(f"the drawing reaches the tables: {what}")
    m = metrics()
    for t in sheet.texts():
        for r in t.runs:
            m.advance(r.text, 1.0)  # raises ValueError naming a missing glyph
    painted = colours(to_svg(sheet))
    if painted:
        out.append(f"colour in a default build: {sorted(painted)}")
    out += [f"a vector not at a stated μ: {v}" for v in unstated_vectors(sheet)]
    return out


#: A scale factor as a sheet states it: ``μV = 0,01``, ``μ_F = 2,5``, ``μF = 10 000`` (grouped by
#: threes with a narrow no-break space; the markup's plain text).
STATED = re.compile(
    r"μ_?\{?([A-Za-z]+)\}?\s*=\s*([0-9](?:[0-9.,]|\u202f(?=\d))*(?:·10\^?\{?[–-]?\d+\}?)?)"
)


def stated_scales(sheet: Sheet) -> set[tuple[str, str]]:
    """The (symbol, value) pairs of every scale factor written on the sheet."""
    return {(m.group(1), m.group(2)) for t in sheet.texts() for m in STATED.finditer(t.text)}


def unstated_vectors(sheet: Sheet) -> list[str]:
    """The plan and polygon vectors (``Sheet.scaled``) whose scale no text of the sheet states:
    a vector drawn at some μ the reader cannot know is not at its stated μ."""
    stated = stated_scales(sheet)
    out = []
    for tail, tip, scale in sheet.scaled:
        sym = "V" if scale.q == "v" else scale.q
        value = fmt_number(scale.k, sheet.lang)
        plain = value.replace("{", "").replace("}", "").replace("^", "")
        if not any(s == sym and v.replace("{", "").replace("}", "").replace("^", "") == plain
                   for s, v in stated):  # fmt: skip
            out.append(f"{tail}→{tip} at μ{sym} = {value}, stated: {sorted(stated)}")
    return out


@dataclass(frozen=True)
class Finding:
    kind: str
    text: str


def is_bar_of(it: Item, t: TextItem) -> bool:
    """Whether a line is a bar drawn as part of the label ``t`` (an overline, s̄, h̄): one
    straight stroke no longer than a letter is high, along the baseline, within the label's box
    (or just over its top) and above its lower-case letters. A line that crosses the label runs out
    of its box, or across its baseline, or through its letters: it is none of these."""
    if not isinstance(it, Polyline) or len(it.points) != 2 or it.closed or it.fill:
        return False
    (ax, ay), (bx, by) = it.points
    length = math.hypot(bx - ax, by - ay)
    if not 0.0 < length <= t.height:
        return False
    # the stroke's direction and its height over the baseline, in the label's own frame
    # (angle counter-clockwise on the paper, y down)
    c, s = math.cos(math.radians(t.angle)), math.sin(math.radians(t.angle))
    along = abs((bx - ax) * c - (by - ay) * s) / length
    rise = [-(x - t.at[0]) * s - (y - t.at[1]) * c for x, y in it.points]
    if along < math.cos(math.radians(1.0)) or min(rise) < 0.7 * t.height:
        return False
    # over a capital or an ascender the bar stands a little above the cap height
    return bool(text_poly(t).buffer(0.3 + 0.2 * t.height).contains(geometry(it)))


def findings(sheet: Sheet) -> list[Finding]:
    """The drafting findings of :data:`KINDS` on a sheet."""
    _form, drawn = block_part(sheet)
    out: list[Finding] = []
    texts = [t for t in drawn if isinstance(t, TextItem)]
    lines = [it for it in drawn if not isinstance(it, TextItem)]
    strokes = [stroke(it, sheet.format) for it in lines]
    tree = STRtree(strokes)
    for t in texts:
        # a label may touch a line at its edge: the box shrunk by 0.25 mm must stay clear
        p = text_poly(t).buffer(-0.25)
        if p.is_empty:
            continue
        for j in tree.query(p, predicate="intersects"):
            if strokes[j].intersection(p).area > AREA_EPS and not is_bar_of(lines[j], t):
                it = lines[j]
                kind = "tick-label" if t.role != "title" and is_tick_value(t) else "label-line"
                out.append(Finding(kind, f"{t.text!r} {text_box(t)} × {it.role} {item_box(it)}"))
                break
    for t, anchor in sheet.anchors:
        d = text_poly(t).distance(Point(anchor))
        if d > ANCHOR_MAX:
            out.append(Finding("anchor", f"{t.text!r} is {d:.1f} mm from its point {anchor}"))
    for tail, tip in sheet.vectors:
        n = math.dist(tail, tip)
        if n < 2.0 * ARROW_LEN:
            out.append(Finding("short-vector", f"{n:.2f} mm from {tail} to {tip}"))
    share = empty_share(sheet)
    if share > EMPTY_MAX:
        out.append(Finding("empty", f"{share:.0%} of the field is empty"))
    return out


def empty_share(sheet: Sheet, cell: float = 10.0) -> float:
    """The share of the field (the frame less the title block and графа 26) in ``cell`` mm
    squares that nothing drawn reaches."""
    _form, drawn = block_part(sheet)
    field = sbox(*frame_box(sheet))
    for f in reserved(sheet.width, sheet.height):
        field = field.difference(sbox(*f))
    ink = shapely.union_all([_area(it).buffer(cell / 2.0) for it in drawn]) if drawn else None
    x0, y0, x1, y1 = frame_box(sheet)
    total = empty = 0
    y = y0
    while y + cell <= y1 + 1e-9:
        x = x0
        while x + cell <= x1 + 1e-9:
            c = Point(x + cell / 2.0, y + cell / 2.0)
            if field.contains(c):
                total += 1
                if ink is None or not ink.contains(c):
                    empty += 1
            x += cell
        y += cell
    return empty / total if total else 0.0


def _area(it: Item) -> shapely.Geometry:
    """What an item takes of the field: a circle or a closed outline with its inside."""
    if isinstance(it, CircleItem | ArcItem):
        return Point(it.c).buffer(it.r)
    if isinstance(it, Polyline) and it.closed and len(it.points) >= 3:
        return Polygon(it.points)
    return geometry(it)


def labels(sheet: Sheet) -> set[str]:
    """The plain text of every placed label."""
    return {t.text for t in sheet.texts() if t.role == "label"}
