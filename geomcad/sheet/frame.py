"""ESKD sheets: formats (GOST 2.301), the frame, and the main title block, form 1 (GOST 2.104).

The inner frame is a main line 20 mm from the left edge and 5 mm from the others. The title block
is 185 × 55 mm in the bottom-right corner of the frame; its geometry below is in mm from its own
lower-left corner, y up, exactly as GOST 2.104 draws it. Its captions come from a table per
language (``CAPTIONS``), so an English sheet changes words, not code.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from geomcad.errors import ParameterError
from geomcad.sheet.model import XY, Polyline, Sheet, TextItem
from geomcad.sheet.text import HEIGHTS, box, metrics, parse

#: Paper sizes (short side, long side) in mm.
FORMATS: dict[str, tuple[float, float]] = {
    "A4": (210.0, 297.0),
    "A3": (297.0, 420.0),
    "A2": (420.0, 594.0),
    "A1": (594.0, 841.0),
    "A0": (841.0, 1189.0),
}

LEFT_MARGIN = 20.0
MARGIN = 5.0
TB_WIDTH = 185.0
TB_HEIGHT = 55.0

Lang = Literal["ru", "en"]

#: GOST 2.304 allows 1.8 mm lettering (not recommended): the last resort for a narrow cell.
SMALLEST_HEIGHT = 1.8

CAPTIONS: dict[str, dict[str, str]] = {
    "ru": {
        "izm": "Изм.",
        "list": "Лист",
        "doc": "№ докум.",
        "sign": "Подп.",
        "date": "Дата",
        "dev": "Разраб.",
        "chk": "Пров.",
        "tchk": "Т.контр.",
        "nchk": "Н.контр.",
        "appr": "Утв.",
        "lit": "Лит.",
        "mass": "Масса",
        "scale": "Масштаб",
        "sheet": "Лист",
        "sheets": "Листов",
    },
    "en": {
        "izm": "Rev.",
        "list": "Sheet",
        "doc": "Doc. No.",
        "sign": "Sign.",
        "date": "Date",
        "dev": "Drawn",
        "chk": "Checked",
        "tchk": "Tech.",
        "nchk": "Std.",
        "appr": "Appr.",
        "lit": "Stage",
        "mass": "Mass",
        "scale": "Scale",
        "sheet": "Sheet",
        "sheets": "Sheets",
    },
}


@dataclass(frozen=True)
class TitleBlock:
    """What the title block says. Empty fields stay blank (to be filled in by hand)."""

    title: str
    designation: str
    scale: str = ""
    sheet_no: int = 1
    sheets: int = 1
    organisation: str = ""
    developer: str = ""
    checker: str = ""
    material: str = ""
    lang: Lang = "ru"


@dataclass(frozen=True)
class Frame:
    """The usable drawing field inside the frame, above and left of the title block (sheet mm)."""

    left: float
    top: float
    right: float
    bottom: float
    tb_left: float  # x of the title block's left edge
    tb_top: float  # y of the title block's top edge


def paper(fmt: str, landscape: bool = True) -> tuple[float, float]:
    """(width, height) in mm of a format; A4 is portrait only."""
    if fmt not in FORMATS:
        raise ParameterError("format", fmt, f"must be one of {', '.join(FORMATS)}")
    short, long = FORMATS[fmt]
    if fmt == "A4" or not landscape:
        return short, long
    return long, short


def new_sheet(fmt: str, tb: TitleBlock, landscape: bool = True) -> tuple[Sheet, Frame]:
    """A sheet of ``fmt`` with its frame and filled title block, and the free field inside."""
    w, h = paper(fmt, landscape)
    sheet = Sheet(w, h, fmt, tb.title)
    x0, y0, x1, y1 = LEFT_MARGIN, MARGIN, w - MARGIN, h - MARGIN
    sheet.add(Polyline(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), "frame", closed=True))
    _title_block(sheet, x1 - TB_WIDTH, y1, tb)
    return sheet, Frame(x0, y0, x1, y1, x1 - TB_WIDTH, y1 - TB_HEIGHT)


def text_at(
    sheet: Sheet,
    markup: str,
    at: XY,
    height: float,
    role: str = "title",
    anchor: str = "left",
    id: str = "",
) -> TextItem:
    """Put a line of text with its baseline at ``at``; ``anchor`` left, centre or right."""
    runs = parse(markup)
    w, _, _ = box(runs, height)
    x = at[0] - (w / 2.0 if anchor == "centre" else w if anchor == "right" else 0.0)
    item = TextItem((x, at[1]), runs, height, metrics().font_size(height), w, role, id)
    sheet.add(item)
    return item


def fit_text(
    sheet: Sheet,
    markup: str,
    cell: tuple[float, float, float, float],
    height: float,
    role: str = "title",
    anchor: str = "centre",
) -> list[TextItem]:
    """Text centred in a cell (x0, y0 top, x1, y1 bottom), shrunk to a smaller GOST height and
    then broken into lines until it fits."""
    x0, y0, x1, y1 = cell
    room_w, room_h = x1 - x0 - 0.8, y1 - y0 - 1.0
    heights = [*(hh for hh in reversed(HEIGHTS) if hh <= height), SMALLEST_HEIGHT]
    words = markup.split(" ")
    for hh in heights:
        for n_lines in range(1, len(words) + 1):
            lines = _split(words, n_lines)
            lead = hh * 1.6
            total = hh + (n_lines - 1) * lead
            if total > room_h:
                break
            if all(box(parse(ln), hh)[0] <= room_w for ln in lines):
                cx = (x0 + x1) / 2.0 if anchor == "centre" else x0 + 1.0
                top = (y0 + y1) / 2.0 - total / 2.0 + hh
                return [
                    text_at(sheet, ln, (cx, top + i * lead), hh, role, anchor)
                    for i, ln in enumerate(lines)
                ]
    raise ParameterError("title block", markup, "the text does not fit its cell")


def _split(words: list[str], n: int) -> list[str]:
    """Words split into ``n`` lines of about equal length (greedy on character counts)."""
    if n == 1:
        return [" ".join(words)]
    total = sum(len(w) for w in words) + len(words) - 1
    target = total / n
    lines: list[str] = []
    cur: list[str] = []
    for w in words:
        if cur and len(" ".join([*cur, w])) > target and len(lines) < n - 1:
            lines.append(" ".join(cur))
            cur = [w]
        else:
            cur.append(w)
    lines.append(" ".join(cur))
    return lines


def _title_block(sheet: Sheet, bx: float, by: float, tb: TitleBlock) -> None:
    """Draw form 1 with its lower-left corner at sheet point (bx, by)."""

    def pt(x: float, y: float) -> XY:
        return (bx + x, by - y)

    def seg(x_a: float, y_a: float, x_b: float, y_b: float, thick: bool) -> None:
        sheet.add(Polyline((pt(x_a, y_a), pt(x_b, y_b)), "frame" if thick else "frame_thin"))

    def cell(x_a: float, y_a: float, x_b: float, y_b: float) -> tuple[float, float, float, float]:
        return (bx + x_a, by - y_b, bx + x_b, by - y_a)

    cap = CAPTIONS[tb.lang]
    # outline and the main dividers (thick)
    sheet.add(Polyline((pt(0, 0), pt(185, 0), pt(185, 55), pt(0, 55)), "frame", closed=True))
    for x in (17, 40, 55, 65):
        seg(x, 0, x, 55, True)
    seg(7, 30, 7, 55, True)
    for y in (30, 35):
        seg(0, y, 65, y, True)
    seg(65, 40, 185, 40, True)
    seg(65, 15, 185, 15, True)
    seg(135, 0, 135, 40, True)
    for y in (20, 35):
        seg(135, y, 185, y, True)
    for x in (150, 167):
        seg(x, 20, x, 40, True)
    seg(155, 15, 155, 20, True)
    # the 5 mm rows of the left part and the three cells of the stage (thin)
    for y in (5, 10, 15, 20, 25, 40, 45, 50):
        seg(0, y, 65, y, False)
    for x in (140, 145):
        seg(x, 20, x, 35, False)

    small = 2.5
    for (x_a, x_b), key in zip(
        ((0, 7), (7, 17), (17, 40), (40, 55), (55, 65)),
        ("izm", "list", "doc", "sign", "date"),
        strict=True,
    ):
        fit_text(sheet, cap[key], cell(x_a, 30, x_b, 35), small)
    for row, key in enumerate(("dev", "chk", "tchk", "", "nchk", "appr")):
        if key:
            fit_text(sheet, cap[key], cell(0, 25 - 5 * row, 17, 30 - 5 * row), small, anchor="left")
    if tb.developer:
        fit_text(sheet, tb.developer, cell(17, 25, 40, 30), small, anchor="left")
    if tb.checker:
        fit_text(sheet, tb.checker, cell(17, 20, 40, 25), small, anchor="left")
    for (x_a, x_b), key in zip(
        ((135, 150), (150, 167), (167, 185)), ("lit", "mass", "scale"), strict=True
    ):
        fit_text(sheet, cap[key], cell(x_a, 35, x_b, 40), small)
    fit_text(sheet, f"{cap['sheet']} {tb.sheet_no}", cell(135, 15, 155, 20), small)
    fit_text(sheet, f"{cap['sheets']} {tb.sheets}", cell(155, 15, 185, 20), small)
    if tb.scale:
        fit_text(sheet, tb.scale, cell(167, 20, 185, 35), 5.0)
    fit_text(sheet, tb.designation, cell(65, 40, 185, 55), 7.0)
    fit_text(sheet, tb.title, cell(65, 15, 135, 40), 5.0)
    if tb.material:
        fit_text(sheet, tb.material, cell(65, 0, 135, 15), 5.0)
    if tb.organisation:
        fit_text(sheet, tb.organisation, cell(135, 0, 185, 15), 3.5)
