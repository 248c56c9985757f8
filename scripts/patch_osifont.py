"""Rebuild the Cyrillic Э э Ё ё that osifont 0.1.20220224 replaced by filled boxes, and redraw
ь and з at lowercase height.

Usage: ``python3 scripts/patch_osifont.py [SRC] [DST]`` (defaults: Debian bookworm's
fonts-osifont file and the package's pinned copy, ``geomcad/fonts/osifont.ttf``).

Upstream's changelog says "removed (ЭёЁ)": the glyphs uni042D, uni044D, uni0401 and uni0451
are each a single four-point box. This script draws them again from the font's own parts:

* ё, Ё: Cyrillic е/Е with the combining diaeresis (uni0308), placed over the letter as the
  font places it in Latin ë/Ë. Latin ë/Ë are copied as they are only when Latin e/E are the
  same outline and advance as Cyrillic е/Е (in 0.1.20220224 they are not: the Latin letters
  have wider side bearings, which would open gaps inside Cyrillic words).
* э, Э: a round bowl open on the left in с/С's box and advance, its top and bottom
  half-ellipses as round as the font's О, its stroke ends round and turned down/up, plus a
  horizontal bar of the font's stroke thickness (the hyphen's) at mid-height of the bowl,
  with a round end like the font's stroke ends, stopping short of the open side. (The mirror
  image of osifont's square-cornered С is its digit 3: review 8 read the detail letter Э as
  "3".)

Two lowercase letters upstream draws at the wrong height (GOST 2.304 type B sets them at the
height of the other lowercase letters without ascenders, the font's x-height):

* ь: upstream's is the capital Ь (cap height: "СкоростЬ"). The font's own ы holds a lowercase ь
  as its first contours (everything left of the stem): ь is those, moved to ь's own side
  bearing, with ь's advance.
* з: upstream's stands between x-height and cap height and reads as the digit 3. It is scaled
  vertically about the baseline to the x-height (the height of в, the lowercase letter of the
  same build), its width and advance kept.

One character upstream lacks is added: U+202F NARROW NO-BREAK SPACE, the separator of a long
number's groups of three digits (GOST 8.417: ``11 130`` reads as one number), an empty glyph
half as wide as the space, appended after the last glyph (no glyph's index moves) and mapped in
the Unicode subtables of the character map.

Everything else is kept byte for byte: the other glyphs (and their stored bounds), advance
widths and side bearings, the other tables, the family name. The version string (nameID 5)
gets "; geomcad: Э э Ё ё restored" appended. The output is deterministic: head.created and
head.modified stay the source's and are not recalculated.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from fontTools.pens.areaPen import AreaPen
from fontTools.pens.boundsPen import ControlBoundsPen
from fontTools.pens.recordingPen import RecordingPen
from fontTools.pens.reverseContourPen import ReverseContourPen
from fontTools.pens.transformPen import TransformPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import TTFont

DEFAULT_SRC = Path("/usr/share/fonts/truetype/osifont/osifont.ttf")
DEFAULT_DST = Path(__file__).resolve().parent.parent / "geomcad" / "fonts" / "osifont.ttf"

VERSION_SUFFIX = "; geomcad: Э э Ё ё restored, ь з at x-height, U+202F"
#: For name records in an 8-bit (Mac Roman) encoding, which has no Cyrillic.
VERSION_SUFFIX_ASCII = (
    "; geomcad: U+042D U+044D U+0401 U+0451 restored, U+044C U+0437 at x-height, U+202F"
)
#: The version suffixes of earlier runs of this script (replaced, not appended to).
OLD_SUFFIXES = (
    "; geomcad: Э э Ё ё restored, ь з at x-height",
    "; geomcad: U+042D U+044D U+0401 U+0451 restored, U+044C U+0437 at x-height",
    "; geomcad: Э э Ё ё restored",
    "; geomcad: U+042D U+044D U+0401 U+0451 restored",
)

#: Where the bar of э/Э starts: this fraction of the way from the open side's tips to the
#: inner edge of the closed side.
BAR_START = 0.4
#: Where the bowl of э/Э ends on the open side: this angle (degrees) round its top and bottom
#: half-ellipses from the right (180: straight down/up, the ends of a half-ellipse).
TERMINAL_DEG = 145.0

Point = tuple[float, float]
Box = tuple[float, float, float, float]


def _box(font: TTFont, name: str) -> Box:
    """The control-point bounds of glyph ``name`` (without touching its stored bounds)."""
    pen = ControlBoundsPen(font.getGlyphSet())
    font.getGlyphSet()[name].draw(pen)
    if pen.bounds is None:
        raise ValueError(f"glyph {name} is empty")
    x0, y0, x1, y1 = pen.bounds
    return (x0, y0, x1, y1)


def _signed_area(font: TTFont, name: str) -> float:
    pen = AreaPen(font.getGlyphSet())
    font.getGlyphSet()[name].draw(pen)
    return float(pen.value)


def _same_outline(font: TTFont, a: str, b: str) -> bool:
    """Whether glyphs ``a`` and ``b`` have the same outline (up to a shift) and advance."""
    gs = font.getGlyphSet()
    rec_a, rec_b = RecordingPen(), RecordingPen()
    gs[a].draw(rec_a)
    gs[b].draw(rec_b)
    dx = _box(font, b)[0] - _box(font, a)[0]
    dy = _box(font, b)[1] - _box(font, a)[1]
    shifted = RecordingPen()
    rec_a.replay(TransformPen(shifted, (1, 0, 0, 1, dx, dy)))
    return bool(shifted.value == rec_b.value and font["hmtx"][a][0] == font["hmtx"][b][0])


def _set_glyph(font: TTFont, name: str, pen: TTGlyphPen, advance: int) -> None:
    glyph = pen.glyph()
    glyf = font["glyf"]
    glyf[name] = glyph
    glyph.recalcBounds(glyf)
    font["hmtx"][name] = (advance, glyph.xMin)


def _stroke(font: TTFont, cmap: Mapping[int, str]) -> int:
    """The font's stroke thickness: the height of the hyphen."""
    _, y_min, _, y_max = _box(font, cmap[ord("-")])
    return round(y_max - y_min)


def _with_diaeresis(
    font: TTFont, cmap: Mapping[int, str], target: str, base: str, latin_base: str, latin: str
) -> None:
    """Draw ``target`` as ``base`` with the diaeresis placed as in ``latin`` over ``latin_base``."""
    gs = font.getGlyphSet()
    glyf, hmtx = font["glyf"], font["hmtx"]
    mark = cmap[0x0308]
    advance = hmtx[base][0]
    pen = TTGlyphPen(gs)
    if latin in glyf and latin_base in glyf and _same_outline(font, latin_base, base):
        gs[latin].draw(pen)
        _set_glyph(font, target, pen, hmtx[latin][0])
        return
    bx0, _, bx1, by1 = _box(font, base)
    mx0, my0, mx1, _ = _box(font, mark)
    offsets = [
        (c.x, c.y)
        for c in (glyf[latin].components if latin in glyf and glyf[latin].isComposite() else [])
        if c.glyphName == mark
    ]
    if offsets and latin_base in glyf:
        # the mark keeps its horizontal offset from the base's centre and its height above the top
        lx0, _, lx1, ly1 = _box(font, latin_base)
        dx = offsets[0][0] + ((bx0 + bx1) - (lx0 + lx1)) / 2
        dy = offsets[0][1] + (by1 - ly1)
    else:
        dx = (bx0 + bx1) / 2 - (mx0 + mx1) / 2
        dy = by1 + _stroke(font, cmap) * 0.75 - my0
    gs[base].draw(pen)
    gs[mark].draw(TransformPen(pen, (1, 0, 0, 1, round(dx), round(dy))))
    _set_glyph(font, target, pen, advance)


def _arc(centre: Point, rx: float, ry: float, a0: float, a1: float) -> list[tuple[Point, Point]]:
    """The elliptic arc about ``centre`` from angle ``a0`` to ``a1`` (degrees) as quadratic
    segments of at most 30° each: (off-curve, on-curve) pairs after the start point."""
    n = max(1, math.ceil(abs(a1 - a0) / 30.0))
    step = math.radians((a1 - a0) / n)
    out: list[tuple[Point, Point]] = []
    for i in range(n):
        t0 = math.radians(a0) + i * step
        mid, k = t0 + step / 2, 1 / math.cos(step / 2)
        off = (centre[0] + rx * k * math.cos(mid), centre[1] + ry * k * math.sin(mid))
        on = (centre[0] + rx * math.cos(t0 + step), centre[1] + ry * math.sin(t0 + step))
        out.append((off, on))
    return out


def _round_cap(a: Point, b: Point, u: Point) -> list[tuple[Point, Point]]:
    """A round stroke end from ``a`` to ``b`` bulging along the unit vector ``u``."""
    r = math.dist(a, b) / 2
    apex = ((a[0] + b[0]) / 2 + r * u[0], (a[1] + b[1]) / 2 + r * u[1])
    return [
        ((a[0] + r * u[0], a[1] + r * u[1]), apex),
        ((b[0] + r * u[0], b[1] + r * u[1]), b),
    ]


def _reversed_bowl_with_bar(
    font: TTFont, cmap: Mapping[int, str], target: str, source: str
) -> None:
    """Draw ``target`` (э/Э) in the box and advance of ``source`` (с/С) as a round bowl open
    on the left with a bar (tongue) across the middle: the top and bottom are half-ellipses
    as round as the font's О (not the square corners of its С, whose mirror image is its
    digit 3: review 8 read the detail letter Э as "3"), the stroke ends round and turned
    down/up (``TERMINAL_DEG``), the bar from ``BAR_START`` of the way from the stroke ends to
    the closed side. The strokes are the font's (the hyphen's thickness)."""
    gs = font.getGlyphSet()
    advance = font["hmtx"][source][0]
    t = _stroke(font, cmap)
    sx0, y0, sx1, y1 = _box(font, source)
    x0, x1 = advance - sx1, advance - sx0  # mirrored: the open side on the left
    rx = (x1 - x0) / 2
    ry = min(rx, (y1 - y0) / 2)
    cx = x0 + rx
    top, bottom = (cx, y1 - ry), (cx, y0 + ry)
    a = TERMINAL_DEG

    def at(c: Point, k: float, deg: float) -> Point:
        return (c[0] + (rx - k) * math.cos(math.radians(deg)),
                c[1] + (ry - k) * math.sin(math.radians(deg)))  # fmt: skip

    segs: list[tuple[Point | None, Point]] = []
    start = at(top, 0, a)
    segs += _arc(top, rx, ry, a, 0)  # outer: over the top, down the right, round the bottom
    segs.append((None, at(bottom, 0, 0)))
    segs += _arc(bottom, rx, ry, 0, -a)
    down = (math.sin(math.radians(-a)), -math.cos(math.radians(-a)))  # onwards past -a
    segs += _round_cap(at(bottom, 0, -a), at(bottom, t, -a), down)
    segs += _arc(bottom, rx - t, ry - t, -a, 0)  # inner, back up
    segs.append((None, at(top, t, 0)))
    segs += _arc(top, rx - t, ry - t, 0, a)
    up = (-math.sin(math.radians(a)), math.cos(math.radians(a)))
    segs += _round_cap(at(top, t, a), start, up)

    def r(p: Point) -> tuple[int, int]:
        return (round(p[0]), round(p[1]))

    pen = TTGlyphPen(gs)
    rec = RecordingPen()
    rec.moveTo(r(start))
    for off, on in segs:
        if off is None:
            rec.lineTo(r(on))
        else:
            rec.qCurveTo(r(off), r(on))
    rec.closePath()
    # the bar, a round end on the open side, its other end inside the closed side's stroke
    mid = round((y0 + y1) / 2)
    tips = min(at(top, 0, a)[0], at(top, t, a)[0])
    inner = x1 - t
    left = round(tips + BAR_START * (inner - tips))
    right = round(x1 - t / 2)
    radius = t / 2
    btop, bbottom = mid + t - round(radius), mid - round(radius)
    cap = round(left + radius)
    rec.moveTo((cap, btop))
    rec.lineTo((right, btop))
    rec.lineTo((right, bbottom))
    rec.lineTo((cap, bbottom))
    rec.qCurveTo((left, bbottom), (left, mid))
    rec.qCurveTo((left, btop), (cap, btop))
    rec.closePath()
    # each contour drawn in the direction of the source's outer contour (TrueType: clockwise)
    outward = _signed_area(font, source) > 0
    contours: list[list[tuple[str, tuple[Any, ...]]]] = [[]]
    for op, args in rec.value:
        contours[-1].append((op, args))
        if op == "closePath":
            contours.append([])
    for contour in contours[:-1]:
        one = RecordingPen()
        one.value = contour
        area = AreaPen()
        one.replay(area)
        one.replay(ReverseContourPen(pen) if (area.value > 0) != outward else pen)
    _set_glyph(font, target, pen, advance)


def _soft_sign_from_yeru(font: TTFont, cmap: Mapping[int, str]) -> None:
    """Draw ь as the contours of ы left of its stem (ы = ь + І), at ь's side bearing."""
    glyf, hmtx = font["glyf"], font["hmtx"]
    target, yeru = cmap[0x044C], cmap[0x044B]
    coords, ends, _ = glyf[yeru].getCoordinates(glyf)
    # the stem: ы's last contour
    stem_left = min(x for x, _ in list(coords)[ends[-2] + 1 : ends[-1] + 1])
    # keep the on-curve flags: replay the outline through a pen, contour by contour
    rec = RecordingPen()
    font.getGlyphSet()[yeru].draw(rec)
    kept: list[tuple[str, tuple[Any, ...]]] = []
    contour: list[tuple[str, tuple[Any, ...]]] = []
    for op, args in rec.value:
        contour.append((op, args))
        if op in ("closePath", "endPath"):
            xs = [pt[0] for _, a in contour for pt in a]
            if xs and max(xs) < stem_left:
                kept += contour
            contour = []
    if not kept:
        raise ValueError(f"{yeru}: no contours left of its stem")
    x_min = min(pt[0] for _, a in kept for pt in a)
    dx = hmtx[target][1] - x_min  # ь's own left side bearing
    pen = TTGlyphPen(font.getGlyphSet())
    shifted = TransformPen(pen, (1, 0, 0, 1, dx, 0))
    for op, args in kept:
        getattr(shifted, op)(*args)
    _set_glyph(font, target, pen, hmtx[target][0])


def _ze_at_x_height(font: TTFont, cmap: Mapping[int, str]) -> None:
    """Scale з vertically about the baseline to the height of в (the x-height)."""
    target = cmap[0x0437]
    _, y0, _, y1 = _box(font, target)
    _, _, _, x_height = _box(font, cmap[0x0432])
    k = (x_height - y0) / (y1 - y0)
    pen = TTGlyphPen(font.getGlyphSet())
    font.getGlyphSet()[target].draw(TransformPen(pen, (1, 0, 0, k, 0, y0 * (1 - k))))
    _set_glyph(font, target, pen, font["hmtx"][target][0])


#: The narrow no-break space (U+202F) is this fraction of the font's space wide.
NARROW_SPACE = 0.5


def _narrow_space(font: TTFont) -> None:
    """Add U+202F as an empty glyph ``NARROW_SPACE`` of the space's advance wide, appended to
    the glyph order (the other glyphs keep their indices) and mapped in the Unicode subtables
    of the character map (platform 0 and platform 3, encoding 1 or 10)."""
    name = "uni202F"
    order = font.getGlyphOrder()
    cmap = font["cmap"]
    space = cmap.getBestCmap()[0x0020]
    if name not in order:
        font.setGlyphOrder([*order, name])
        font["glyf"].glyphOrder = font.getGlyphOrder()
        font["glyf"][name] = TTGlyphPen(None).glyph()
    font["hmtx"][name] = (round(NARROW_SPACE * font["hmtx"][space][0]), 0)
    for table in cmap.tables:
        if table.isUnicode():
            table.cmap[0x202F] = name


def _append_version(font: TTFont) -> None:
    for record in font["name"].names:
        if record.nameID != 5:
            continue
        text = record.toUnicode().rstrip()
        if VERSION_SUFFIX in text or VERSION_SUFFIX_ASCII in text:
            continue
        for old in OLD_SUFFIXES:
            text = text.replace(old, "")
        suffix = VERSION_SUFFIX if record.isUnicode() else VERSION_SUFFIX_ASCII
        record.string = text + suffix


def patch(src: Path, dst: Path) -> None:
    """Read ``src``, rebuild Э э Ё ё and ь з, write ``dst``."""
    # recalcBBoxes=False: fontTools would otherwise recompute (and change by a unit) the stored
    # bounds of every glyph it decompiles; only the four new glyphs get fresh bounds (below, and
    # in _set_glyph), then the font-wide values that depend on them.
    font = TTFont(str(src), recalcTimestamp=False, recalcBBoxes=False)
    cmap: dict[int, str] = dict(font.getBestCmap())

    def glyph_for(*codes: int) -> str:
        for code in codes:
            if code in cmap:
                return cmap[code]
        raise KeyError(f"no glyph for any of {[hex(c) for c in codes]}")

    cyr_e, cyr_E = glyph_for(0x0435), glyph_for(0x0415)
    lat_e, lat_E = glyph_for(0x0065), glyph_for(0x0045)
    lat_edier, lat_Edier = cmap.get(0x00EB, "edieresis"), cmap.get(0x00CB, "Edieresis")
    _with_diaeresis(font, cmap, glyph_for(0x0451), cyr_e, lat_e, lat_edier)
    _with_diaeresis(font, cmap, glyph_for(0x0401), cyr_E, lat_E, lat_Edier)
    _reversed_bowl_with_bar(font, cmap, glyph_for(0x044D), glyph_for(0x0441, 0x0063))
    _reversed_bowl_with_bar(font, cmap, glyph_for(0x042D), glyph_for(0x0421, 0x0043))
    _soft_sign_from_yeru(font, cmap)
    _ze_at_x_height(font, cmap)
    _narrow_space(font)
    _append_version(font)
    font["maxp"].recalc(font)  # also head's bounding box and its "lsb = xMin" flag
    font["hhea"].recalc(font)
    font["OS/2"].recalcAvgCharWidth(font)
    dst.parent.mkdir(parents=True, exist_ok=True)
    font.save(str(dst))


def main(argv: Sequence[str]) -> int:
    if len(argv) > 2:
        print(__doc__, file=sys.stderr)
        return 2
    src = Path(argv[0]) if argv else DEFAULT_SRC
    dst = Path(argv[1]) if len(argv) > 1 else DEFAULT_DST
    patch(src, dst)
    print(f"wrote {dst}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
