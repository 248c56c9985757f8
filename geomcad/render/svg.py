"""Replay a :class:`~geomcad.sheet.model.Sheet` into SVG text (the only module that uses svgwrite).

The SVG works in paper millimetres: the root is ``width="420mm" height="297mm"
viewBox="0 0 420 297"``, so one user unit is one millimetre and every length inside is a plain
number (cairosvg scales ``"0.7mm"`` with the dpi and ``"70%"`` with the page).

The output is byte-stable (DESIGN.md rule 9): numbers are written with at most three decimals and
never as ``-0``, attributes are sorted (svgwrite does that), ids come from the sheet's roles and
text ids, and nothing depends on the clock or on chance.

Layers: one ``<g>`` per role that has items, in the order of :data:`~geomcad.sheet.style.STYLES`
(later roles on top), marked as an Inkscape layer. The group carries the role's stroke colour,
width, caps and joins and ``fill="none"``; items keep the sheet's order inside their layer.

Text: one ``<text>`` per label with one ``<tspan>`` per run, each at an absolute x and y computed
here from the pinned font's advance widths. cairosvg ignores ``baseline-shift`` and misplaces
``text-anchor="middle"`` with tspans, so neither is used.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace

import svgwrite

from geomcad.sheet.model import XY, ArcItem, CircleItem, Dash, Item, Polyline, Sheet, TextItem
from geomcad.sheet.style import MAIN_LINE, STYLES, Style, for_language, style
from geomcad.sheet.text import FONT_FAMILY, parse, placed_runs

#: Main line S (mm) for a sheet whose format is not in MAIN_LINE (GOST 2.303: 0.7 on A3/A4).
DEFAULT_MAIN_LINE = 0.7

#: Decimals of every number written (1 µm on paper).
DECIMALS = 3

INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
XML_DECLARATION = '<?xml version="1.0" encoding="utf-8" ?>\n'


def num(x: float) -> str:
    """``x`` with at most :data:`DECIMALS` decimals, trailing zeros dropped, never ``-0``.

    Raises ``ValueError`` for NaN or infinity: a sheet never holds one on purpose.
    """
    if not math.isfinite(x):
        raise ValueError(f"cannot write the non-finite number {x!r} into an SVG sheet")
    s = f"{x:.{DECIMALS}f}".rstrip("0").rstrip(".")
    # Rounding a tiny negative value gives "-0"; it would differ from "0" byte for byte.
    return "0" if s in ("-0", "") else s


def _pt(p: XY) -> str:
    return f"{num(p[0])},{num(p[1])}"


def main_line(fmt: str) -> float:
    """The main line S (mm) of a sheet format; :data:`DEFAULT_MAIN_LINE` for an unknown one."""
    return MAIN_LINE.get(fmt, DEFAULT_MAIN_LINE)


#: The colours a black-and-white sheet keeps: paper white (a joint's inside) and no paint.
_NOT_INK = ("none", "#ffffff")


def monochrome(st: Style) -> Style:
    """The style in black (ESKD has no colour): every ink is black, paper white stays white."""
    stroke = st.stroke if st.stroke in _NOT_INK else "#000000"
    fill = st.fill if st.fill in _NOT_INK else "#000000"
    return replace(st, stroke=stroke, fill=fill)


def _fill_colour(st: Style) -> str:
    """The colour of a filled shape: the role's fill, or its stroke when the role has no fill."""
    return st.stroke if st.fill == "none" else st.fill


def _dash_attrs(dash: Dash | None) -> dict[str, str]:
    if dash is None:
        return {}
    attrs = {"stroke-dasharray": " ".join(num(d) for d in dash.array)}
    offset = num(dash.offset)
    if offset != "0":
        attrs["stroke-dashoffset"] = offset
    return attrs


def _is_name_char(ch: str, first: bool) -> bool:
    """Whether ``ch`` may stand in an XML id (ASCII, or a letter/digit of Latin-1 … Greek and
    Cyrillic, which XML 1.0 allows in names)."""
    if ch.isascii():
        if ch.isalpha() or ch == "_":
            return True
        return not first and (ch.isdigit() or ch in "-.")
    code = ord(ch)
    in_range = 0xC0 <= code <= 0x1FFF and code not in (0xD7, 0xF7, 0x37E)
    return in_range and (ch.isalpha() or (not first and ch.isdigit()))


def xml_id(raw: str) -> str:
    """``raw`` made into a valid XML id: other characters become ``_``; a leading character that
    cannot start a name gets the prefix ``t-``. Deterministic; uniqueness is the caller's job."""
    body = "".join(ch if _is_name_char(ch, False) else "_" for ch in raw)
    if not body or not _is_name_char(body[0], True):
        body = "t-" + body
    return body


class _Ids:
    """Hands out unique element ids in document order: a repeated id gets ``-2``, ``-3`` …"""

    def __init__(self, reserved: Iterable[str]) -> None:
        self._used = set(reserved)

    def take(self, raw: str) -> str:
        base = xml_id(raw)
        out, n = base, 1
        while out in self._used:
            n += 1
            out = f"{base}-{n}"
        self._used.add(out)
        return out


def _arc_path(a: ArcItem) -> str:
    """The path data of an arc: sweep > 0 is clockwise on the paper, SVG's sweep-flag 1.

    An arc longer than a half circle is written as two halves through its midpoint: a single
    large arc whose ends nearly meet (a full circle, or ends that round to the same point) would
    otherwise vanish or flip, since SVG recovers the centre from the ends alone.
    """
    r = num(a.r)
    flag = "1" if a.sweep > 0.0 else "0"
    head = f"M{_pt(a.start)}"
    if abs(a.sweep) <= math.pi:
        return f"{head} A{r},{r} 0 0 {flag} {_pt(a.end)}"
    # y points down on paper, so a clockwise turn is an increasing atan2 angle.
    mid_angle = math.atan2(a.start[1] - a.c[1], a.start[0] - a.c[0]) + a.sweep / 2.0
    mid = (a.c[0] + a.r * math.cos(mid_angle), a.c[1] + a.r * math.sin(mid_angle))
    return f"{head} A{r},{r} 0 0 {flag} {_pt(mid)} A{r},{r} 0 0 {flag} {_pt(a.end)}"


def _text(dwg: svgwrite.Drawing, t: TextItem, st: Style, ids: _Ids) -> svgwrite.text.Text:
    """A label: absolute x and y per run, from the pinned font's advance widths."""
    attrs = {
        "xml:space": "preserve",
        "font-family": FONT_FAMILY,
        "fill": _fill_colour(st),
        # A text in a stroked layer (a red result label) must not inherit the layer's outline.
        "stroke": "none",
    }
    if t.id:
        attrs["id"] = ids.take(t.id)
    turns = []
    if t.angle:
        # SVG turns clockwise on the paper (y down); the model's angle is counter-clockwise.
        turns.append(f"rotate({num(-t.angle)} {num(t.at[0])} {num(t.at[1])})")
    if t.stretch != 1.0:  # condensed about its start, the glyphs with their positions
        turns.append(f"matrix({num(t.stretch)} 0 0 1 {num(t.at[0] * (1.0 - t.stretch))} 0)")
    if turns:
        attrs["transform"] = " ".join(turns)
    # x and y set as attributes (one number each), not through svgwrite's x= and y= lists,
    # which flatten and join every value: the same attribute text, a third of the time
    el = dwg.text("", **attrs)
    el["x"], el["y"] = num(t.at[0]), num(t.at[1])
    for run, x, y, size in placed_runs(t):
        span = dwg.tspan(run.text, **{"font-size": num(size)})
        span["x"], span["y"] = num(x), num(y)
        el.add(span)
    return el


def _element(
    dwg: svgwrite.Drawing, item: Item, ids: _Ids, colour: bool
) -> svgwrite.base.BaseElement:
    st = style(item.role) if colour else monochrome(style(item.role))
    if isinstance(item, TextItem):
        return _text(dwg, item, st, ids)
    if isinstance(item, Polyline):
        attrs = _dash_attrs(item.dash)
        if item.fill:
            attrs["fill"] = _fill_colour(st)
        points = [(num(p[0]), num(p[1])) for p in item.points]
        if item.closed:
            return dwg.polygon(points=points, **attrs)
        return dwg.polyline(points=points, **attrs)
    if isinstance(item, CircleItem):
        attrs = _dash_attrs(item.dash)
        if item.fill:
            attrs["fill"] = _fill_colour(st)
        return dwg.circle(center=(num(item.c[0]), num(item.c[1])), r=num(item.r), **attrs)
    return dwg.path(d=_arc_path(item), **_dash_attrs(item.dash))


def _layer(dwg: svgwrite.Drawing, role: str, st: Style, s: float) -> svgwrite.container.Group:
    """The group of one role: an Inkscape layer that carries the role's line style."""
    attrs = {
        "id": f"layer-{role}",
        "inkscape:groupmode": "layer",
        "inkscape:label": role,
        "fill": "none",
        "stroke-linecap": "round",
        "stroke-linejoin": "round",
    }
    if st.weight > 0.0:
        attrs["stroke"] = st.stroke
        attrs["stroke-width"] = num(st.weight * s)
    else:
        # Lettering layers have no line of their own.
        attrs["stroke"] = "none"
    return dwg.g(**attrs)


def to_svg(sheet: Sheet, colour: bool = False) -> str:
    """The sheet as an SVG document (UTF-8 text with its XML declaration): black on white, as
    ESKD draws; ``colour`` keeps the roles' colours (blue construction, red results) for screens.

    Raises ``KeyError`` for an item whose role is not in ``STYLES``, and ``ValueError`` for a
    non-finite coordinate or a character the pinned font lacks.
    """
    for item in sheet.items:
        style(item.role)
    dwg = svgwrite.Drawing(
        size=(f"{num(sheet.width)}mm", f"{num(sheet.height)}mm"),
        viewBox=f"0 0 {num(sheet.width)} {num(sheet.height)}",
        debug=False,
    )
    dwg.attribs["xmlns:inkscape"] = INKSCAPE_NS
    if sheet.title:  # the title block's markup (u_{1H2}) as plain text
        dwg.set_desc(title="".join(r.text for r in parse(sheet.title)))
    s = main_line(sheet.format)
    by_role: dict[str, list[Item]] = {}
    for item in sheet.items:
        by_role.setdefault(item.role, []).append(item)
    ids = _Ids(f"layer-{role}" for role in STYLES)
    for role, st in STYLES.items():
        items = by_role.get(role)
        if not items:
            continue
        st = for_language(st, sheet.lang)
        group = _layer(dwg, role, st if colour else monochrome(st), s)
        for item in items:
            group.add(_element(dwg, item, ids, colour))
        dwg.add(group)
    body: str = dwg.tostring()
    return XML_DECLARATION + body + "\n"
