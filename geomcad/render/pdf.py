"""A :class:`~geomcad.sheet.model.Sheet` replayed straight into a cairo PDF surface.

The PDF draws the same items as the SVG (:mod:`geomcad.render.svg`), layer by layer in the
order of :data:`~geomcad.sheet.style.STYLES`, with the same line widths, dashes, fills and
text positions (:func:`~geomcad.sheet.text.placed_runs`), but without writing the SVG and
parsing it back: cairosvg set every letter of every label on its own (a text-extents call and
a text call per letter) and spent most of a sheet's PDF time on it; here a run of text is one
``show_text`` in the pinned font, and its glyph advances are the font's, as the SVG's per-run
positions assume (no kerning). Text stays real text. cairo is loaded through
:func:`geomcad.render.raster.cairo` (fontconfig pointed at the shipped font first); a missing
libcairo is the same :class:`~geomcad.errors.MissingDependency` line.
"""

from __future__ import annotations

import io
import math
from typing import Any

from geomcad import interrupts
from geomcad.render.raster import cairo, pin_creation_date
from geomcad.render.svg import _fill_colour, main_line, monochrome
from geomcad.sheet.model import ArcItem, CircleItem, Dash, Item, Polyline, Sheet, TextItem
from geomcad.sheet.style import STYLES, Style, for_language, style
from geomcad.sheet.text import FONT_FAMILY, parse, placed_runs

#: PDF points per millimetre.
PT_PER_MM = 72.0 / 25.4


def _rgb(colour: str) -> tuple[float, float, float]:
    """``#rrggbb`` as cairo's three fractions."""
    h = colour.lstrip("#")
    return int(h[0:2], 16) / 255.0, int(h[2:4], 16) / 255.0, int(h[4:6], 16) / 255.0


def _path(ctx: Any, item: Polyline | CircleItem | ArcItem) -> None:
    ctx.new_path()
    if isinstance(item, Polyline):
        (x, y), *rest = item.points
        ctx.move_to(x, y)
        for x, y in rest:
            ctx.line_to(x, y)
        if item.closed:
            ctx.close_path()
    elif isinstance(item, CircleItem):
        ctx.arc(item.c[0], item.c[1], item.r, 0.0, 2.0 * math.pi)
        ctx.close_path()
    else:  # y points down on paper: a clockwise sweep is an increasing angle, cairo's arc
        a0 = math.atan2(item.start[1] - item.c[1], item.start[0] - item.c[0])
        draw = ctx.arc if item.sweep > 0.0 else ctx.arc_negative
        draw(item.c[0], item.c[1], item.r, a0, a0 + item.sweep)


def _shape(ctx: Any, item: Polyline | CircleItem | ArcItem, st: Style, width: float) -> None:
    """Fill (a filled polygon or circle: in the role's fill colour), then stroke in the role's
    line, as an SVG renderer paints a shape of the role's layer."""
    filled = not isinstance(item, ArcItem) and item.fill
    stroked = width > 0.0 and st.stroke != "none"
    if not (filled or stroked):
        return
    _path(ctx, item)
    if filled:
        ctx.set_source_rgb(*_rgb(_fill_colour(st)))
        if stroked:
            ctx.fill_preserve()
        else:
            ctx.fill()
    if stroked:
        dash: Dash | None = item.dash
        ctx.set_dash(list(dash.array) if dash else [], dash.offset if dash else 0.0)
        ctx.set_source_rgb(*_rgb(st.stroke))
        ctx.stroke()


def _text(ctx: Any, t: TextItem, st: Style) -> None:
    ctx.set_source_rgb(*_rgb(_fill_colour(st)))
    turned = bool(t.angle) or t.stretch != 1.0
    if turned:
        ctx.save()
        ctx.translate(t.at[0], t.at[1])
        ctx.rotate(math.radians(-t.angle))
        ctx.scale(t.stretch, 1.0)  # condensed about its start, as the SVG's matrix
        ctx.translate(-t.at[0], -t.at[1])
    for run, x, y, size in placed_runs(t):
        if run.text.isspace():
            continue
        ctx.set_font_size(size)
        ctx.move_to(x, y)
        ctx.show_text(run.text)
    if turned:
        ctx.restore()


def sheet_pdf(sheet: Sheet, colour: bool = False) -> bytes:
    """The sheet as a one-page PDF of its paper size, black on white (``colour``: the roles'
    colours, as :func:`~geomcad.render.svg.to_svg`); the same sheet gives the same bytes."""
    for item in sheet.items:
        style(item.role)
    # cairo writes through a Python callback, where a signal's exception would be lost
    with interrupts.deferred():
        return _draw(sheet, colour)


def _draw(sheet: Sheet, colour: bool) -> bytes:
    c = cairo()
    out = io.BytesIO()
    surface = c.PDFSurface(out, sheet.width * PT_PER_MM, sheet.height * PT_PER_MM)
    if sheet.title:  # the title block's markup as plain text, as the SVG's <title>
        surface.set_metadata(c.PDF_METADATA_TITLE, "".join(r.text for r in parse(sheet.title)))
    ctx = c.Context(surface)
    ctx.scale(PT_PER_MM, PT_PER_MM)
    ctx.set_line_cap(c.LINE_CAP_ROUND)
    ctx.set_line_join(c.LINE_JOIN_ROUND)
    ctx.select_font_face(FONT_FAMILY, c.FONT_SLANT_NORMAL, c.FONT_WEIGHT_NORMAL)
    s = main_line(sheet.format)
    by_role: dict[str, list[Item]] = {}
    for item in sheet.items:
        by_role.setdefault(item.role, []).append(item)
    for role, base in STYLES.items():
        items = by_role.get(role)
        if not items:
            continue
        # the layer's line (colour, width) and fill, as the SVG's group and items carry them
        st = for_language(base, sheet.lang)
        st = st if colour else monochrome(st)
        width = st.weight * s
        ctx.set_line_width(width)
        for item in items:
            if isinstance(item, TextItem):
                _text(ctx, item, st)
            else:
                _shape(ctx, item, st, width)
    surface.finish()
    return pin_creation_date(out.getvalue())
