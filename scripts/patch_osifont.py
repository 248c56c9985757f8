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
* э, Э: с/С mirrored left to right (contours reversed to keep the TrueType winding), plus a
  horizontal bar of the font's stroke thickness (the hyphen's) at mid-height of the bowl,
  with a round end like the font's stroke ends, stopping short of the open side.

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

import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from fontTools.pens.areaPen import AreaPen
from fontTools.pens.basePen import BasePen
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
BAR_START = 0.3

Point = tuple[float, float]
Box = tuple[float, float, float, float]


class _SegmentPen(BasePen):  # type: ignore[misc]
    """Flattens an outline into straight segments (for measuring, not for output)."""

    def __init__(self, glyph_set: Any, steps: int = 16) -> None:
        super().__init__(glyph_set)
        self.segments: list[tuple[Point, Point]] = []
        self.steps = steps

    def _moveTo(self, pt: Point) -> None:
        self._start = pt

    def _lineTo(self, pt: Point) -> None:
        self.segments.append((self._getCurrentPoint(), pt))

    def _curveToOne(self, p1: Point, p2: Point, p3: Point) -> None:
        p0 = self._getCurrentPoint()
        prev = p0
        for i in range(1, self.steps + 1):
            t = i / self.steps
            u = 1 - t
            pt = (
                u**3 * p0[0] + 3 * u * u * t * p1[0] + 3 * u * t * t * p2[0] + t**3 * p3[0],
                u**3 * p0[1] + 3 * u * u * t * p1[1] + 3 * u * t * t * p2[1] + t**3 * p3[1],
            )
            self.segments.append((prev, pt))
            prev = pt

    def _qCurveToOne(self, p1: Point, p2: Point) -> None:
        p0 = self._getCurrentPoint()
        prev = p0
        for i in range(1, self.steps + 1):
            t = i / self.steps
            u = 1 - t
            pt = (
                u * u * p0[0] + 2 * u * t * p1[0] + t * t * p2[0],
                u * u * p0[1] + 2 * u * t * p1[1] + t * t * p2[1],
            )
            self.segments.append((prev, pt))
            prev = pt

    def _closePath(self) -> None:
        current = self._getCurrentPoint()
        if current != self._start:
            self.segments.append((current, self._start))


def _crossings(font: TTFont, name: str, y: float, transform: Sequence[float]) -> list[float]:
    """The x where glyph ``name`` (after ``transform``) crosses the horizontal line at y."""
    seg_pen = _SegmentPen(font.getGlyphSet())
    font.getGlyphSet()[name].draw(TransformPen(seg_pen, tuple(transform)))
    xs = []
    for (x0, y0), (x1, y1) in seg_pen.segments:
        if (y0 <= y < y1) or (y1 <= y < y0):
            xs.append(x0 + (y - y0) * (x1 - x0) / (y1 - y0))
    return sorted(xs)


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


def _mirrored_with_bar(font: TTFont, cmap: Mapping[int, str], target: str, source: str) -> None:
    """Draw ``target`` as ``source`` (с/С) mirrored, with a bar across the middle: э/Э."""
    gs = font.getGlyphSet()
    advance = font["hmtx"][source][0]
    mirror = (-1, 0, 0, 1, advance, 0)
    stroke = _stroke(font, cmap)
    radius = stroke / 2
    _, sy0, sx1, sy1 = _box(font, source)
    mid = round((sy0 + sy1) / 2)
    xs = _crossings(font, source, mid, mirror)
    if len(xs) < 2:
        raise ValueError(f"{source}: no closed side to attach the bar to at y={mid}")
    inner, outer = xs[-2], xs[-1]
    tips = advance - sx1  # the open side, after mirroring
    left = round(tips + BAR_START * (inner - tips))
    right = round((inner + outer) / 2)  # inside the stroke: the overlap hides the bar's end
    top, bottom = mid + stroke - round(radius), mid - round(radius)

    pen = TTGlyphPen(gs)
    gs[source].draw(TransformPen(ReverseContourPen(pen), mirror))
    # the bar, drawn in the same direction as the hyphen (clockwise: TrueType's outer contours)
    cap = round(left + radius)
    pen.moveTo((cap, top))
    pen.lineTo((right, top))
    pen.lineTo((right, bottom))
    pen.lineTo((cap, bottom))
    pen.qCurveTo((left, bottom), (left, mid))
    pen.qCurveTo((left, top), (cap, top))
    pen.closePath()
    _set_glyph(font, target, pen, advance)
    if (_signed_area(font, target) > 0) != (_signed_area(font, source) > 0):
        raise AssertionError(f"{target}: contour direction differs from {source}")


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
    _mirrored_with_bar(font, cmap, glyph_for(0x044D), glyph_for(0x0441, 0x0063))
    _mirrored_with_bar(font, cmap, glyph_for(0x042D), glyph_for(0x0421, 0x0043))
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
