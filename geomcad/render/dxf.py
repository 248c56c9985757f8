"""Replay a :class:`~geomcad.sheet.model.Sheet` into DXF (ezdxf), for КОМПАС and AutoCAD users.

The DXF is the same drawing as the SVG, item for item, in real millimetres at 1:1: the sheet's
lower-left corner is the origin, y points up (the sheet model's y is flipped once, here), and the
drawing's extents are the paper format (``$EXTMIN``/``$EXTMAX`` and ``$LIMMIN``/``$LIMMAX``).

- **Layers**: one per role that has items, named like the role and in the order of
  :data:`~geomcad.sheet.style.STYLES` (the SVG's Inkscape layers), each with the role's
  lineweight (the role's multiple of the sheet's main line S, rounded to the nearest DXF
  lineweight), colour (black as ACI 7, which CAD shows black on white paper and white on a dark
  screen; with ``colour``, as ``build --color`` draws the SVG, a coloured role keeps its colour
  as a true colour) and linetype: ``GOST_DASHED``, ``GOST_DASHDOT`` or
  ``GOST_TWODOT`` with the GOST 2.303 target dash, or ``Continuous`` (an English sheet:
  ``ISO128_02``, ``ISO128_04``, ``ISO128_05`` with ISO 128-20's, and its narrow lines at S/2).
- **Dash patterns as drawn**: the sheet fits each dashed line's pattern to its own length (a
  dash-dot line starts and ends with a dash, a circle's pattern is centred on its start point);
  an entity whose fitted pattern differs from its layer's gets a linetype of that exact pattern,
  named after it (``GOST_DASHDOT_11.375``). A short centre line that the sheet draws solid gets
  ``Continuous``. Polylines carry the "linetype generation" flag, so a pattern runs on across
  their vertices, as SVG's dash array does.
- **The paper's edge** is a closed polyline on the layer ``paper``, which does not plot, so that
  "zoom extents" in a CAD program shows the whole format.
- **Entities**: a segment is a LINE, a longer polyline an LWPOLYLINE, a circle a CIRCLE, an arc
  an ARC (true curves, not chords). A filled shape (an arrowhead, a point's dot, a joint's white
  disc over its links) is its outline plus a solid HATCH of the role's fill colour underneath.
  Lettering is one TEXT per run of a label (a subscript is its own smaller TEXT, moved down as
  in the SVG), left-aligned on its baseline at the x the pinned font's advance widths give, in
  the text style ``OSIFONT`` whose font is ``osifont.ttf`` (the height of a DXF TEXT is its cap
  height, as the sheet's is). Dimensions are the lines, arrowheads and texts the sheet draws (no
  DIMENSION entities). The hatching of supports and of areas under a graph is drawn by the sheet
  as separate strokes, and stays so (lines on the layer of its role).
- The file is DXF R2010 (UTF-8, so Cyrillic text is stored as it is), in millimetres
  (``$INSUNITS`` 4, metric), and passes ezdxf's audit. The header's timestamps and the document's
  GUIDs are fixed, so the same sheet gives the same bytes (DESIGN.md rule 9).
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterable

import ezdxf
from ezdxf import colors
from ezdxf.document import Drawing
from ezdxf.enums import TextEntityAlignment
from ezdxf.layouts import Modelspace
from ezdxf.lldxf.const import LINEWEIGHT_DEFAULT, VALID_DXF_LINEWEIGHTS

from geomcad import tol
from geomcad.render.svg import main_line as svg_main_line
from geomcad.render.svg import monochrome
from geomcad.sheet.model import XY, ArcItem, CircleItem, Dash, Item, Polyline, Sheet, TextItem
from geomcad.sheet.style import (
    STYLES,
    LineType,
    Style,
    for_language,
    patterns,
    style,
)
from geomcad.sheet.text import FONT_FAMILY, FONT_FILE, placed_runs

#: The DXF version written: R2010 (AutoCAD 2010 and later, КОМПАС-3D, LibreCAD, QCAD read it).
DXF_VERSION = "R2010"

#: The layer of the paper's edge (not plotted; not a role of the sheet).
PAPER_LAYER = "paper"

#: The text style of every label.
TEXT_STYLE = FONT_FAMILY.upper()

#: The DXF name of each dashed line type, and its description.
LINETYPE_NAMES: dict[LineType, str] = {
    "dashed": "GOST_DASHED",
    "dashdot": "GOST_DASHDOT",
    "twodot": "GOST_TWODOT",
}
_DESCRIPTIONS: dict[LineType, str] = {
    "dashed": "GOST 2.303 dashed __ __ __",
    "dashdot": "GOST 2.303 dash-dot thin __ . __ . __",
    "twodot": "GOST 2.303 two-dot thin __ . . __ . . __",
}
#: The same on an English sheet (ISO 128-20 line types 02, 04 and 05).
ISO_LINETYPE_NAMES: dict[LineType, str] = {
    "dashed": "ISO128_02",
    "dashdot": "ISO128_04",
    "twodot": "ISO128_05",
}
_ISO_DESCRIPTIONS: dict[LineType, str] = {
    "dashed": "ISO 128-20 type 02 dashed __ __ __",
    "dashdot": "ISO 128-20 type 04 long-dashed dotted __ . __ . __",
    "twodot": "ISO 128-20 type 05 long-dashed double-dotted __ . . __ . . __",
}


def linetype_names(lang: str = "ru") -> dict[LineType, str]:
    """The DXF names of the dashed line types of a sheet drawn in ``lang``: GOST 2.303's in
    Russian, ISO 128-20's otherwise."""
    return LINETYPE_NAMES if lang == "ru" else ISO_LINETYPE_NAMES


#: Decimals kept in a fitted pattern (1 µm on paper, as in the SVG).
DECIMALS = 3

_DRAWING_ORDER = tuple(STYLES)


def _nominal(line: LineType, lang: str = "ru") -> Dash:
    """The pattern a layer carries (GOST 2.303, or ISO 128-20 on an English sheet): the target
    dash and the sheet's own gaps."""
    dashed, dashdot, twodot = patterns("ru" if lang == "ru" else "en")
    if line == "dashed":
        _lo, target, _hi, gap = dashed
        return Dash((target, gap))
    _lo, target, _hi, s, dot = dashdot if line == "dashdot" else twodot
    dots = 1 if line == "dashdot" else 2
    return Dash((target, s, *(dot, s) * dots))


def lineweight(mm: float) -> int:
    """The DXF lineweight (1/100 mm) nearest to a line width of ``mm``."""
    hundredths = mm * 100.0
    return min((w for w in VALID_DXF_LINEWEIGHTS if w > 0), key=lambda w: abs(w - hundredths))


def _colour(hex_colour: str) -> tuple[int, int | None]:
    """(ACI, true colour): black is ACI 7 (black on paper, white on a dark screen)."""
    h = hex_colour.lstrip("#")
    rgb = colors.RGB(int(h[0:2], 16), int(h[2:4], 16), int(h[4:6], 16))
    if rgb == (0, 0, 0):
        return 7, None
    return 256, colors.rgb2int(rgb)


def _fill_colour(st: Style) -> str:
    return st.stroke if st.fill == "none" else st.fill


def _pattern(dash: Dash) -> list[float]:
    """The DXF pattern of a fitted SVG dash array: dashes > 0, gaps < 0, started at its offset.

    SVG dash arrays alternate dash, gap, dash …; a DXF linetype spells the same with negative
    gaps. An SVG offset starts the pattern part-way in; a DXF pattern cannot, so the pattern is
    rotated to begin there (a circle's pattern then starts in the middle of its dot or gap).
    """
    signed = [round(v if i % 2 == 0 else -v, DECIMALS) for i, v in enumerate(dash.array)]
    if len(signed) % 2:  # an odd SVG array repeats itself to an even one
        signed += [-v for v in signed]
    offset = dash.offset % sum(dash.array)
    if offset <= 0.0:
        return signed
    out: list[float] = []
    pos = 0.0
    for i, v in enumerate(signed):
        length = abs(v)
        if pos + length <= offset:
            pos += length
            continue
        cut = offset - pos
        sign = 1.0 if v > 0 else -1.0
        head = [sign * round(length - cut, DECIMALS)]
        tail = [sign * round(cut, DECIMALS)] if cut > 0.0 else []
        out = head + signed[i + 1 :] + signed[:i] + tail
        break
    return [v for v in out if v != 0.0]


class _Linetypes:
    """The document's linetypes: one per GOST (ISO) line type, one per fitted pattern that
    differs."""

    def __init__(self, doc: Drawing, lang: str = "ru") -> None:
        self._doc = doc
        self._made: dict[tuple[float, ...], str] = {}
        self.names = linetype_names(lang)
        self._descriptions = _DESCRIPTIONS if lang == "ru" else _ISO_DESCRIPTIONS
        for line, name in self.names.items():
            pattern = _pattern(_nominal(line, lang))
            doc.linetypes.add(
                name,
                [sum(abs(v) for v in pattern), *pattern],
                description=self._descriptions[line],
            )
            self._made[tuple(pattern)] = name

    def of(self, line: LineType, dash: Dash | None) -> str:
        """The linetype of an item of a ``line``-type role whose fitted pattern is ``dash``:
        ``BYLAYER`` when the layer's own (a solid role drawn solid, or the nominal pattern),
        ``Continuous`` for a dashed role's line drawn solid (too short for two dashes)."""
        if dash is None:
            return "BYLAYER" if line == "solid" else "Continuous"
        family = line if line != "solid" else _family(dash)
        pattern = _pattern(dash)
        key = tuple(pattern)
        name = self._made.get(key)
        if name is None:
            name = f"{self.names[family]}_{_fmt(dash.array[0])}"
            if dash.offset:
                name += "_C"  # a closed line's pattern, centred on its start
            taken = set(self._made.values())
            stem, n = name, 1
            while name in taken:
                n += 1
                name = f"{stem}_{n}"
            self._doc.linetypes.add(
                name,
                [sum(abs(v) for v in pattern), *pattern],
                description=f"{self._descriptions[family]} fitted",
            )
            self._made[key] = name
        return "BYLAYER" if name == self.names.get(line) else name


def _family(dash: Dash) -> LineType:
    """The GOST line type a dash array spells: dash-gap, dash-gap-dot-gap, or with two dots."""
    n = len(dash.array)
    if n == 2:
        return "dashed"
    return "dashdot" if n == 4 else "twodot"


def _fmt(x: float) -> str:
    return f"{x:.{DECIMALS}f}".rstrip("0").rstrip(".")


class _Writer:
    def __init__(self, sheet: Sheet, main_line: float, colour: bool) -> None:
        doc = ezdxf.new(DXF_VERSION, setup=False, units=ezdxf.units.MM)
        self.doc = doc
        self.sheet = sheet
        self.msp: Modelspace = doc.modelspace()
        self.linetypes = _Linetypes(doc, sheet.lang)
        doc.styles.add(TEXT_STYLE, font=FONT_FILE).dxf.height = 0.0
        doc.header["$MEASUREMENT"] = 1
        doc.header["$LWDISPLAY"] = 1
        doc.header["$LTSCALE"] = 1.0
        doc.header["$PSLTSCALE"] = 0
        doc.header["$TEXTSTYLE"] = TEXT_STYLE
        # The paper is the drawing's extent and its limits. (ezdxf copies the model space's
        # extents to the header only when they are not at the origin, so set both.)
        ext = ((0.0, 0.0, 0.0), (sheet.width, sheet.height, 0.0))
        lim = ((0.0, 0.0), (sheet.width, sheet.height))
        doc.header["$EXTMIN"], doc.header["$EXTMAX"] = ext
        doc.header["$LIMMIN"], doc.header["$LIMMAX"] = lim
        self.msp.dxf.extmin, self.msp.dxf.extmax = ext
        self.msp.dxf.limmin, self.msp.dxf.limmax = lim
        self.main_line = main_line
        self.colour = colour

    def style(self, role: str) -> Style:
        """The role's style, in black unless the sheet is drawn in colour (as the SVG)."""
        st = for_language(style(role), self.sheet.lang)
        return st if self.colour else monochrome(st)

    def p(self, q: XY) -> tuple[float, float]:
        """A sheet point (y down from the top edge) in DXF coordinates (y up from the bottom)."""
        return (q[0], self.sheet.height - q[1])

    def paper(self) -> None:
        """The paper's edge, on a layer that does not print: a CAD user's "zoom extents" then
        shows the whole format, and the sheet can be plotted 1:1 by that window."""
        layer = self.doc.layers.add(PAPER_LAYER, color=8, lineweight=0)
        layer.dxf.plot = 0
        layer.description = "the edge of the paper (not plotted)"
        corners = [(0.0, 0.0), (self.sheet.width, 0.0), (self.sheet.width, self.sheet.height)]
        corners.append((0.0, self.sheet.height))
        self.msp.add_lwpolyline(corners, close=True, dxfattribs={"layer": PAPER_LAYER})

    def layer(self, role: str, st: Style) -> None:
        aci, true_colour = _colour(st.stroke if st.weight > 0.0 else _fill_colour(st))
        layer = self.doc.layers.add(
            role,
            color=aci if aci != 256 else 7,
            true_color=true_colour,
            linetype=self.linetypes.names.get(st.line, "Continuous"),
            lineweight=lineweight(st.weight * self.main_line)
            if st.weight > 0.0
            else LINEWEIGHT_DEFAULT,
        )
        layer.description = f"geomcad sheet role {role}"

    def attrs(self, item: Item, st: Style) -> dict[str, object]:
        out: dict[str, object] = {"layer": item.role}
        if not isinstance(item, TextItem):
            lt = self.linetypes.of(st.line, item.dash)
            if lt != "BYLAYER":
                out["linetype"] = lt
        return out

    def fill(self, item: Polyline | CircleItem, st: Style) -> None:
        """A solid HATCH of the role's fill colour, drawn under the item's outline."""
        aci, true_colour = _colour(_fill_colour(st))
        hatch = self.msp.add_hatch(color=aci, dxfattribs={"layer": item.role})
        if true_colour is not None:
            hatch.dxf.true_color = true_colour
        if isinstance(item, Polyline):
            hatch.paths.add_polyline_path([self.p(q) for q in item.points], is_closed=True)
        else:
            edges = hatch.paths.add_edge_path()
            edges.add_arc(self.p(item.c), item.r, 0.0, 360.0)

    def item(self, item: Item) -> None:
        st = self.style(item.role)
        if isinstance(item, TextItem):
            self.text(item, st)
            return
        attrs = self.attrs(item, st)
        if isinstance(item, Polyline):
            if item.fill:
                self.fill(item, st)
            if len(item.points) == 2 and not item.closed:
                self.msp.add_line(self.p(item.points[0]), self.p(item.points[1]), dxfattribs=attrs)
                return
            pl = self.msp.add_lwpolyline(
                [self.p(q) for q in item.points], close=item.closed, dxfattribs=attrs
            )
            if item.dash is not None:
                pl.dxf.flags = pl.dxf.flags | ezdxf.const.LWPOLYLINE_PLINEGEN
        elif isinstance(item, CircleItem):
            if item.fill:
                self.fill(item, st)
            self.msp.add_circle(self.p(item.c), item.r, dxfattribs=attrs)
        else:
            self.arc(item, attrs)

    def arc(self, a: ArcItem, attrs: dict[str, object]) -> None:
        """An ARC: DXF arcs turn counter-clockwise from start to end angle (y up), so an arc that
        turns clockwise on the paper (sweep > 0) runs from its end to its start."""
        c = self.p(a.c)
        if abs(a.sweep) >= 2.0 * math.pi - tol.ANGLE:
            self.msp.add_circle(c, a.r, dxfattribs=attrs)
            return
        s, e = self.p(a.start), self.p(a.end)
        ang_s = math.degrees(math.atan2(s[1] - c[1], s[0] - c[0]))
        ang_e = math.degrees(math.atan2(e[1] - c[1], e[0] - c[0]))
        if a.sweep > 0.0:
            ang_s, ang_e = ang_e, ang_s
        # Take the end angle from the sweep, so an arc whose ends nearly meet keeps its length.
        ang_e = ang_s + math.degrees(abs(a.sweep))
        self.msp.add_arc(c, a.r, ang_s % 360.0, ang_e % 360.0, dxfattribs=attrs)

    def text(self, t: TextItem, st: Style) -> None:
        """One TEXT per run, at the x and baseline the SVG sets it."""
        aci, true_colour = _colour(_fill_colour(st))
        layer_aci, layer_true = _colour(st.stroke if st.weight > 0.0 else _fill_colour(st))
        # a turned text (графа 26, a dimension along its line): each run's start turned about
        # the text's start, counter-clockwise on the paper, and the TEXT turned alike
        a = math.radians(t.angle)
        cos, sin = math.cos(a), math.sin(a)
        for run, x, y, size in placed_runs(t):
            attrs: dict[str, object] = {"layer": t.role, "style": TEXT_STYLE}
            if t.stretch != 1.0:  # condensed about its start: TEXT's width factor
                x = t.at[0] + (x - t.at[0]) * t.stretch
                attrs["width"] = t.stretch
            if t.angle:
                dx, dy = x - t.at[0], y - t.at[1]
                x, y = t.at[0] + dx * cos + dy * sin, t.at[1] - dx * sin + dy * cos
                attrs["rotation"] = t.angle % 360.0
            if (aci, true_colour) != (layer_aci, layer_true):
                attrs["color"] = aci
                if true_colour is not None:
                    attrs["true_color"] = true_colour
            entity = self.msp.add_text(
                _escape(run.text), height=t.height * size / t.font_size, dxfattribs=attrs
            )
            entity.set_placement(self.p((x, y)), align=TextEntityAlignment.LEFT)


def _escape(text: str) -> str:
    """TEXT reads ``%%`` as the start of a control code (``%%d`` is °); keep a literal one."""
    return text.replace("%%", "%%%%")


def _layers_in_order(items: Iterable[Item]) -> list[str]:
    used = {i.role for i in items}
    return [r for r in _DRAWING_ORDER if r in used]


def to_dxf_document(sheet: Sheet, main_line: float | None = None, colour: bool = False) -> Drawing:
    """The sheet as an ezdxf document (for tests and for further editing in Python).

    ``main_line`` is the sheet's main line S in mm (default: the format's, as the SVG draws it);
    the drawing is black (ESKD) unless ``colour`` keeps the roles' colours, as in the SVG.
    Raises ``KeyError`` for an item whose role is not in ``STYLES``, and ``ValueError`` for a
    non-finite coordinate.
    """
    for item in sheet.items:
        style(item.role)
    w = _Writer(sheet, svg_main_line(sheet.format) if main_line is None else main_line, colour)
    w.paper()
    roles = _layers_in_order(sheet.items)
    for role in roles:
        w.layer(role, w.style(role))
    by_role: dict[str, list[Item]] = {}
    for item in sheet.items:
        by_role.setdefault(item.role, []).append(item)
    for role in roles:
        for item in by_role[role]:
            _check_finite(item)
            w.item(item)
    return w.doc


def _check_finite(item: Item) -> None:
    if isinstance(item, Polyline):
        values: list[float] = [c for q in item.points for c in q]
    elif isinstance(item, TextItem):
        values = [*item.at, item.height]
    elif isinstance(item, CircleItem):
        values = [*item.c, item.r]
    else:
        values = [*item.c, item.r, *item.start, *item.end, item.sweep]
    if not all(math.isfinite(v) for v in values):
        raise ValueError(f"cannot write a non-finite coordinate of a {item.role} item into DXF")


def to_dxf(sheet: Sheet, main_line: float | None = None, colour: bool = False) -> bytes:
    """The sheet as DXF R2010 bytes (UTF-8 text), byte-stable for the same sheet.

    ezdxf stamps the time and fresh GUIDs into the document as it creates and writes it; its own
    switch for reproducible files fixes them (2000-01-01, null GUIDs) while this one is made.
    """
    stream = io.StringIO()
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc = to_dxf_document(sheet, main_line, colour)
        doc.write(stream)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed
    return doc.encode(stream.getvalue())
