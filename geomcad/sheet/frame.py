"""Sheets: formats (GOST 2.301 ≈ ISO 5457), the frame, and the title block: GOST 2.104 form 1 on
a Russian sheet, the data fields of ISO 7200 on an English one.

The inner frame is a main line 20 mm from the left edge and 5 mm from the others. The Russian
title block is 185 × 55 mm in the bottom-right corner of the frame; its geometry below is in mm
from its own lower-left corner, y up, exactly as GOST 2.104 draws it. The English block
(:data:`ISO_WIDTH` × :data:`ISO_HEIGHT`, ISO 7200: at most 180 mm wide) sits in the same corner,
inside the room form 1 takes, so a sheet's layout is the same in either language. Captions come
from a table per language (``strings/<lang>/frame.toml``); the language of a block is the one
being drawn when it is made (:func:`geomcad.sheet.lang.current`).

The English sheet keeps the frame's GOST margins (20 mm left, 5 mm elsewhere) rather than ISO
5457's 20 / 10: every sheet module lays its views out in the GOST field, and the ISO frame would
take 5 mm off three sides of it.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from geomcad import tol
from geomcad.errors import ParameterError
from geomcad.sheet.lang import Lang, Words, current
from geomcad.sheet.model import XY, Polyline, Sheet, TextItem
from geomcad.sheet.text import HEIGHTS, balanced, box, break_points, escape, metrics, parse
from geomcad.sheet.titleblock import STUDENT_STAGE, TitleData

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
#: Графа 26 (GOST 2.104): the designation turned 180° in the frame's top-left corner, 70 × 14 mm.
G26_WIDTH = 70.0
G26_HEIGHT = 14.0
#: The English title block (ISO 7200: at most 180 mm wide), in the frame's bottom-right corner.
ISO_WIDTH = 180.0
ISO_HEIGHT = 45.0


#: GOST 2.304 allows 1.8 mm lettering (not recommended): the last resort for a narrow cell.
SMALLEST_HEIGHT = 1.8

#: The captions of the title block and the frame, per language.
WORDS = Words(__package__, "frame")


@dataclass(frozen=True)
class TitleBlock:
    """What the title block says. Empty fields stay blank (to be filled in by hand).

    A sheet module gives what it knows (title, designation, scale, its number in the set); the
    people, the organisation, the group and the date come from the user's
    :class:`~geomcad.sheet.titleblock.TitleData` (see :meth:`with_user`).
    """

    title: str
    designation: str
    scale: str = ""
    sheet_no: int = 1
    sheets: int = 1
    organisation: str = ""
    developer: str = ""
    checker: str = ""
    material: str = ""
    lang: Lang = field(default_factory=current)
    group: str = ""
    date: str = ""
    stage: str = ""
    tcontrol: str = ""
    ncontrol: str = ""
    approver: str = ""
    revision: str = ""

    def with_user(self, data: TitleData) -> TitleBlock:
        """This block with the user's data: their designation (one for the whole document)
        replaces the sheet module's, their people and places fill the empty cells."""
        # the user's words are plain text, not label markup (a name may hold an underscore)
        return replace(
            self,
            designation=escape(data.designation) or self.designation,
            developer=escape(data.student) or self.developer,
            checker=escape(data.checker) or self.checker,
            tcontrol=escape(data.tcontrol) or self.tcontrol,
            ncontrol=escape(data.ncontrol) or self.ncontrol,
            approver=escape(data.approver) or self.approver,
            organisation=escape(data.org) or self.organisation,
            group=escape(data.group) or self.group,
            date=escape(data.date) or self.date,
            revision=escape(data.revision) or self.revision,
            # Лит. "У" is a Russian letter: an English sheet (its document status) takes only a
            # stage given to it in other words
            stage=self.stage
            or (escape(data.stage) if self.lang == "ru" or data.stage != STUDENT_STAGE else ""),
        )


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
    """A sheet of ``fmt`` with its frame and the form of its title block, and the free field.

    The block's cells are filled by :func:`fill_title_blocks` once the whole set is drawn, so
    that the numbers (Лист i, Листов n) and the one designation agree across the document.
    Графа 26 (70 × 14 mm, top left) lies inside the frame: the layout keeps views out of
    :func:`reserved` boxes.
    """
    w, h = paper(fmt, landscape)
    sheet = Sheet(w, h, fmt, tb.title, lang=tb.lang)
    x0, y0, x1, y1 = LEFT_MARGIN, MARGIN, w - MARGIN, h - MARGIN
    sheet.add(Polyline(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), "frame", closed=True))
    if tb.lang == "ru":
        _title_form(sheet, x1 - TB_WIDTH, y1, tb.lang)
        sheet.add(Polyline(((x0, y0), (x0 + G26_WIDTH, y0), (x0 + G26_WIDTH, y0 + G26_HEIGHT),
                            (x0, y0 + G26_HEIGHT)), "frame", closed=True))  # fmt: skip
        _under_frame(sheet, x1 - TB_WIDTH, y1, fmt, tb.lang)
    else:
        _iso_form(sheet, x1 - ISO_WIDTH, y1, tb.lang)
    sheet.block = tb
    return sheet, Frame(x0, y0, x1, y1, x1 - TB_WIDTH, y1 - TB_HEIGHT)


def fill_title_blocks(sheets: Sequence[Sheet | None], data: TitleData | None = None) -> None:
    """Fill the title blocks of one document's sheets, in order: Лист i of Листов n, one
    designation (the user's, else the first sheet's), the user's people, places and date, and
    графа 26. A sheet drawn without :func:`new_sheet`, or already filled, is left alone; a
    ``None`` is a sheet of the document that could not be drawn: it keeps its number (the
    others are numbered as in the whole planned document)."""
    data = data or TitleData()
    blocks = [s.block for s in sheets if s is not None and s.block is not None]
    if not blocks:
        return
    designation = escape(data.designation) or blocks[0].designation  # plain text, as with_user
    n = len(blocks) + sum(s is None for s in sheets)
    # one height for the names of the document's sheets: the least any of them needs
    scratch = Sheet(1.0, 1.0, "A4", "")
    title_h = min(
        (fit_text(scratch, b.title, _NAME_CELL, 5.0, clear=True)[0].height for b in blocks
         if b.lang == "ru" and b.title),
        default=5.0,
    )  # fmt: skip
    i = 0
    for sheet in sheets:
        if sheet is None:
            i += 1  # the failed sheet's number
            continue
        tb = sheet.block
        if tb is None:
            continue
        i += 1
        tb = replace(tb.with_user(data), designation=designation, sheet_no=i, sheets=n)
        x1, y1 = sheet.width - MARGIN, sheet.height - MARGIN
        if tb.lang == "ru":
            _title_fill(sheet, x1 - TB_WIDTH, y1, tb, title_h)
            _text26(sheet, LEFT_MARGIN, MARGIN, tb.designation)
        else:
            _iso_fill(sheet, x1 - ISO_WIDTH, y1, tb)
        sheet.block = None


def short_date(text: str) -> str:
    """A date written DD.MM.YYYY shortened to DD.MM.YY, as the 10 mm Дата cell holds it."""
    parts = text.split(".")
    if len(parts) == 3 and all(p.isdigit() for p in parts) and len(parts[2]) == 4:
        return f"{parts[0]}.{parts[1]}.{parts[2][2:]}"
    return text


def reserved(sheet_w: float, sheet_h: float) -> list[tuple[float, float, float, float]]:
    """The boxes (x0, y0 top, x1, y1 bottom) inside the frame that belong to the form, not to
    the drawing: the title block and графа 26 (kept free on an English sheet too, so that a
    sheet's layout does not depend on its language)."""
    x0, y0, x1, y1 = LEFT_MARGIN, MARGIN, sheet_w - MARGIN, sheet_h - MARGIN
    return [
        (x1 - TB_WIDTH, y1 - TB_HEIGHT, x1, y1),
        (x0, y0, x0 + G26_WIDTH, y0 + G26_HEIGHT),
    ]


def _text26(sheet: Sheet, x0: float, y0: float, designation: str) -> None:
    """Графа 26: the designation turned 180°, so that it reads from the sheet's top edge."""
    x1, y1 = x0 + G26_WIDTH, y0 + G26_HEIGHT
    if not designation:
        return
    cx, cy = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    tries = [(hh, designation) for hh in reversed(HEIGHTS) if hh <= 5.0]
    tries += [(HEIGHTS[0], condensed(designation)), (SMALLEST_HEIGHT, designation)]
    for hh, text in tries:
        runs = parse(text)
        w, _, _ = box(runs, hh)
        if w <= G26_WIDTH - 2.0:
            # turned 180° about its baseline's left end: the text runs leftwards, above it
            at = (cx + w / 2.0, cy - hh / 2.0)
            sheet.add(TextItem(at, runs, hh, metrics().font_size(hh), w, "title", angle=180.0))
            return
    raise ParameterError(
        "designation", designation, "does not fit box 26 in the frame's top-left corner (70 mm)"
    )


def _under_frame(sheet: Sheet, bx: float, by: float, fmt: str, lang: Lang) -> None:
    """The captions "Копировал" and "Формат A3" under the title block (графы 29, 30)."""
    cap = WORDS.table(lang)
    base = by + (MARGIN + 2.5) / 2.0
    text_at(sheet, cap["copied"], (bx + 75.0, base), 2.5)
    text_at(sheet, f"{cap['format']} {fmt}", (bx + 140.0, base), 2.5)


def text_at(
    sheet: Sheet,
    markup: str,
    at: XY,
    height: float,
    role: str = "title",
    anchor: str = "left",
    id: str = "",
    stretch: float = 1.0,
) -> TextItem:
    """Put a line of text with its baseline at ``at``; ``anchor`` left, centre or right;
    ``stretch``: its width factor (a condensed line)."""
    runs = parse(markup)
    w = box(runs, height)[0] * stretch
    x = at[0] - (w / 2.0 if anchor == "centre" else w if anchor == "right" else 0.0)
    item = TextItem((x, at[1]), runs, height, metrics().font_size(height), w, role, id,
                    stretch=stretch)  # fmt: skip
    sheet.add(item)
    return item


#: Baseline-to-baseline distance of a cell's lines, in cap heights (GOST 2.304, type B: 17/10 h).
CELL_LEAD = 1.7


def clearance(height: float) -> float:
    """The room (mm) a filled title-block cell keeps between its text and its lines, for text
    ``height`` mm high: 0.3 of the height and 0.25 mm more (1.75 mm at 5 mm, 1 mm at 2.5), so
    that no letter touches a line, as a drawing office letters a form."""
    return 0.3 * height + 0.25


#: The least width factor a title-block line is condensed to at GOST's least height before
#: it is set smaller (GOST 2.304's type A is about 0.7 of type B's width).
MIN_STRETCH = 0.7
#: The room (mm) a condensed line (narrow spaces, a width factor) keeps from its cell's room,
#: either side: clear of the half of a thick line.
STRETCH_CLEAR = 0.4
#: The space a line condensed to fit its cell spaces its words with (U+202F, the narrow
#: no-break space: half a word space in the pinned font).
NARROW_SPACE = "\u202f"


def condensed(markup: str) -> str:
    """``markup`` with its word spaces narrowed (:data:`NARROW_SPACE`): a line written at
    GOST's least height (2.5 mm) that is a little too wide for its cell is condensed in its
    spacing, never set smaller (GOST 2.304)."""
    return markup.replace(" ", NARROW_SPACE)


def fit_text(
    sheet: Sheet,
    markup: str,
    cell: tuple[float, ...],
    height: float,
    role: str = "title",
    anchor: str = "centre",
    param: str = "title block",
    max_lines: int = 0,
    clear: bool = False,
) -> list[TextItem]:
    """Text centred in a cell (x0, y0 top, x1, y1 bottom) at the largest GOST height up to
    ``height`` at which it fits (at 2.5 mm, its word spaces narrowed before it is set smaller:
    :func:`condensed`), broken into as few lines as it needs at that height (at most
    ``max_lines``, when given; lines of about equal width, broken at spaces or after a
    compound's hyphen, ``поперечно-`` / ``строгального``); else a :class:`ParameterError`
    naming ``param``. ``clear``: the text keeps :func:`clearance` from the cell's lines (the
    filled cells); else 0.4 mm across and 0.5 mm up and down (the form's own captions, as
    GOST 2.104 prints them in its narrow columns)."""
    x0, y0, x1, y1 = cell
    heights = [*(hh for hh in reversed(HEIGHTS) if hh <= height), SMALLEST_HEIGHT]
    tokens = break_points(markup)
    for hh in heights:
        c = clearance(hh) if clear else 0.0
        room_w = x1 - x0 - 2.0 * c - (0.0 if clear else 0.8)
        room_h = y1 - y0 - 2.0 * c - (0.0 if clear else 1.0)
        lead = hh * CELL_LEAD
        # each sentence beginning a line in as few lines as the cell holds, before lines
        # broken mid-sentence ("Силовой анализ." / "Шестизвенный механизм" / "с ползуном",
        # not "Силовой анализ. Шестизвенный" / "механизм с ползуном")
        tries = [(n, True) for n in range(1, min(len(tokens), max_lines or len(tokens)) + 1)]
        tries += [(n, False) for n, _ in tries]
        # at the least GOST height, the word spaces narrowed before the height is (review 14:
        # "Шарипова Л. Р." at 1.8 mm in Разраб. where it fits the column at 2.5 mm condensed),
        # then, the lines in as few as the cell holds, their width factor (GOST 2.304's
        # narrow type A: "Никифоров С. Ю.", "Ахмедова-Лунд С. И." in the 23 mm column)
        modes = ("plain", "narrow", "stretch") if hh == HEIGHTS[0] else ("plain",)
        for mode, (n_lines, whole) in ((m, t) for m in modes for t in tries):
            total = hh + (n_lines - 1) * lead
            if total > room_h:
                continue
            lines = _by_sentences(markup, n_lines, hh, room_w / (MIN_STRETCH if mode ==
                                  "stretch" else 1.0), whole)  # fmt: skip
            if mode != "plain":
                lines = [condensed(ln) for ln in lines]
            if not lines:
                continue
            wide = max(box(parse(ln), hh)[0] for ln in lines)
            # a condensed line keeps STRETCH_CLEAR more from the cell's (thick) lines
            room = room_w - (2.0 * STRETCH_CLEAR if mode != "plain" else 0.0)
            k = min(1.0, room / wide) if mode == "stretch" else 1.0
            if wide * k <= room * (1.0 + tol.DERIVED) and k >= MIN_STRETCH:
                # a left-set text 1 mm in from the cell's line (its clearance where more), or
                # centred where its width leaves less room either side
                indent = min(max(c, 1.0), (x1 - x0 - wide * k) / 2.0)
                cx = (x0 + x1) / 2.0 if anchor == "centre" else x0 + indent
                top = (y0 + y1) / 2.0 - total / 2.0 + hh
                return [
                    text_at(sheet, ln, (cx, top + i * lead), hh, role, anchor, stretch=k)
                    for i, ln in enumerate(lines)
                ]
    raise ParameterError(
        param, markup, f"does not fit its title-block cell ({x1 - x0:g} × {y1 - y0:g} mm)"
    )


def _by_sentences(
    markup: str, n: int, height: float, room: float, whole: bool = False
) -> list[str]:
    """``markup`` in ``n`` lines, each sentence (a sheet's subject, then its mechanism)
    beginning a line where that fits in ``room`` mm (the sentences' lines shared so that the
    widest is narrowest); else in lines of about equal width (:func:`balanced`), or none
    with ``whole`` (a text of several sentences that cannot begin each on a line)."""
    sentences = re.split(r"(?<=\.) ", markup)
    best: tuple[float, list[str]] | None = None
    if 1 < len(sentences) <= n:
        parts = [break_points(t) for t in sentences]
        for shares in itertools.product(range(1, n + 1), repeat=len(parts)):
            if sum(shares) != n or any(k > len(p) for k, p in zip(shares, parts, strict=True)):
                continue
            lines = [
                ln for k, p in zip(shares, parts, strict=True) for ln in balanced(p, k, height)
            ]
            wide = max(box(parse(ln), height)[0] for ln in lines)
            if wide <= room and (best is None or wide < best[0]):
                best = (wide, lines)
    if best:
        return best[1]
    if whole and len(sentences) > 1:
        return []
    return balanced(break_points(markup), n, height)


@dataclass(frozen=True)
class _Block:
    """Form 1's own coordinates (mm from its lower-left corner, y up) on a sheet."""

    sheet: Sheet
    bx: float
    by: float

    def pt(self, x: float, y: float) -> XY:
        return (self.bx + x, self.by - y)

    def seg(self, x_a: float, y_a: float, x_b: float, y_b: float, thick: bool) -> None:
        role = "frame" if thick else "frame_thin"
        self.sheet.add(Polyline((self.pt(x_a, y_a), self.pt(x_b, y_b)), role))

    def cell(self, x_a: float, y_a: float, x_b: float, y_b: float) -> tuple[float, ...]:
        return (self.bx + x_a, self.by - y_b, self.bx + x_b, self.by - y_a)


def _title_form(sheet: Sheet, bx: float, by: float, lang: Lang) -> None:
    """Draw form 1's lines and captions with its lower-left corner at sheet point (bx, by)."""
    b = _Block(sheet, bx, by)
    pt, seg, cell = b.pt, b.seg, b.cell
    cap = WORDS.table(lang)
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
    for (x_a, x_b), key in zip(
        ((135, 150), (150, 167), (167, 185)), ("lit", "mass", "scale"), strict=True
    ):
        fit_text(sheet, cap[key], cell(x_a, 35, x_b, 40), small)


#: The sheet's name cell of form 1 (графа 1: x 65–135, y 15–40 from the block's lower-left
#: corner), as (x0, y0 top, x1, y1 bottom) of a block whose lower-left corner is at (0, 55).
_NAME_CELL = (65.0, 15.0, 135.0, 40.0)


def name_fits(name: str, lang: str) -> bool:
    """Whether a sheet's name fits its title block's name cell (графа 1 of GOST 2.104, the
    ISO 7200 block's title field) at some GOST height, as :func:`fit_text` writes it."""
    x0, y0, x1, y1 = next(f[1:] for f in ISO_FIELDS if f[0] == "iso_title")
    cell = _NAME_CELL if lang == "ru" else (x0, y0, x1, y1)
    try:
        fit_text(Sheet(1.0, 1.0, "A4", ""), name, cell, 5.0, clear=True)
    except ParameterError:
        return False
    return True


def _title_fill(sheet: Sheet, bx: float, by: float, tb: TitleBlock, title_h: float = 5.0) -> None:
    """Fill form 1's cells (lower-left corner at sheet point (bx, by)) from ``tb``, the sheet's
    name at most ``title_h`` high (the height the whole document's names share)."""
    cell = _Block(sheet, bx, by).cell
    cap = WORDS.table(tb.lang)
    small = 2.5
    people = (
        (tb.developer, "student"),
        (tb.checker, "checker"),
        (tb.tcontrol, "tcontrol"),
        ("", ""),
        (tb.ncontrol, "ncontrol"),
        (tb.approver, "approver"),
    )
    for row, (name, key) in enumerate(people):
        if name:
            c = cell(17, 25 - 5 * row, 40, 30 - 5 * row)
            fit_text(sheet, name, c, small, anchor="left", param=key)
    if tb.date:
        fit_text(sheet, short_date(tb.date), cell(55, 25, 65, 30), small, param="date")
    if tb.stage:
        fit_text(sheet, tb.stage, cell(135, 20, 140, 35), 5.0)
    fit_text(sheet, f"{cap['sheet']} {tb.sheet_no}", cell(135, 15, 155, 20), small)
    fit_text(sheet, f"{cap['sheets']} {tb.sheets}", cell(155, 15, 185, 20), small)
    if tb.scale:
        fit_text(sheet, tb.scale, cell(167, 20, 185, 35), 5.0, clear=True)
    fit_text(sheet, tb.designation, cell(65, 40, 185, 55), 7.0, param="designation", clear=True)
    fit_text(sheet, tb.title, cell(65, 15, 135, 40), title_h, clear=True)
    if tb.material:
        fit_text(sheet, tb.material, cell(65, 0, 135, 15), 5.0, clear=True)
    # графа 9: the organisation, and under it the student's group
    if tb.organisation and tb.group:
        fit_text(sheet, tb.organisation, cell(135, 6, 185, 15), 3.5, param="org", clear=True)
        fit_text(sheet, tb.group, cell(135, 0, 185, 6), 2.5, param="group")
    elif tb.organisation or tb.group:
        key = "org" if tb.organisation else "group"
        fit_text(
            sheet, tb.organisation or tb.group, cell(135, 0, 185, 15), 3.5, param=key, clear=True
        )


#: ISO 7200's data fields on the English block: (caption key, x0, y0, x1, y1) in mm from the
#: block's lower-left corner, y up. The caption sits small in the cell's top-left corner and the
#: data in the room below it.
ISO_FIELDS: tuple[tuple[str, float, float, float, float], ...] = (
    ("iso_techref", 0, 36, 45, 45),
    ("iso_creator", 45, 36, 88, 45),
    ("iso_approver", 88, 36, 130, 45),
    ("iso_type", 130, 36, 180, 45),
    ("iso_owner", 0, 0, 45, 36),
    ("iso_title", 45, 9, 130, 36),
    ("iso_status", 130, 27, 180, 36),
    ("iso_id", 130, 9, 180, 27),
    ("iso_scale", 45, 0, 65, 9),
    ("iso_format", 65, 0, 80, 9),
    ("iso_rev", 80, 0, 92, 9),
    ("iso_date", 92, 0, 130, 9),
    ("iso_lang", 130, 0, 145, 9),
    ("iso_sheet", 145, 0, 180, 9),
)
#: The caption's height (mm) and the band it takes at the top of its cell.
ISO_CAPTION = SMALLEST_HEIGHT
ISO_BAND = 3.0


def _iso_form(sheet: Sheet, bx: float, by: float, lang: Lang) -> None:
    """The ISO 7200 block's lines and field captions, lower-left corner at sheet point (bx, by):
    the outline a main line, the fields' borders thin."""
    b = _Block(sheet, bx, by)
    cap = WORDS.table(lang)
    w, h = ISO_WIDTH, ISO_HEIGHT
    sheet.add(Polyline((b.pt(0, 0), b.pt(w, 0), b.pt(w, h), b.pt(0, h)), "frame", closed=True))
    edges: set[tuple[float, float, float, float]] = set()
    for _key, x_a, y_a, x_b, y_b in ISO_FIELDS:
        for e in ((x_a, y_a, x_b, y_a), (x_a, y_b, x_b, y_b), (x_a, y_a, x_a, y_b),
                  (x_b, y_a, x_b, y_b)):  # fmt: skip
            on_outline = (e[0] == e[2] and e[0] in (0, w)) or (e[1] == e[3] and e[1] in (0, h))
            if not on_outline:
                edges.add(e)
    for x_a, y_a, x_b, y_b in sorted(edges):
        b.seg(x_a, y_a, x_b, y_b, False)
    for key, x_a, _y_a, x_b, y_b in ISO_FIELDS:
        x0, top = b.pt(x_a, y_b)
        fit_text(sheet, cap[key], (x0, top, b.pt(x_b, 0)[0], top + ISO_BAND), ISO_CAPTION,
                 anchor="left")  # fmt: skip


def _iso_fill(sheet: Sheet, bx: float, by: float, tb: TitleBlock) -> None:
    """Fill the ISO 7200 block's fields (lower-left corner at sheet point (bx, by)) from ``tb``;
    a field without data stays blank."""
    b = _Block(sheet, bx, by)
    cap = WORDS.table(tb.lang)
    owner = [(tb.organisation, "org"), (tb.group, "group")]
    data = {
        "iso_techref": (tb.checker, 2.5, "checker"),
        "iso_creator": (tb.developer, 2.5, "student"),
        "iso_approver": (tb.approver, 2.5, "approver"),
        "iso_type": (cap["iso_type_value"], 2.5, "document type"),
        "iso_title": (tb.title, 5.0, "title"),
        "iso_status": (tb.stage, 2.5, "stage"),
        "iso_id": (tb.designation, 5.0, "designation"),
        "iso_scale": (tb.scale, 3.5, "scale"),
        "iso_format": (sheet.format, 3.5, "format"),
        "iso_rev": (tb.revision, 3.5, "revision"),
        "iso_date": (tb.date, 3.5, "date"),
        "iso_lang": (tb.lang, 3.5, "language"),
        "iso_sheet": (f"{tb.sheet_no}/{tb.sheets}", 3.5, "sheet"),
    }
    for key, x_a, y_a, x_b, y_b in ISO_FIELDS:
        x0, top = b.pt(x_a, y_b)
        x1, bottom = b.pt(x_b, y_a)
        room = (x0 + 0.6, top + ISO_BAND, x1 - 0.6, bottom)  # 1 mm clear of the borders
        if key == "iso_owner":
            given = [(text, param) for text, param in owner if text]
            if len(given) == 2:
                mid = top + ISO_BAND + (bottom - top - ISO_BAND) * 0.6
                fit_text(sheet, given[0][0], (x0, top + ISO_BAND, x1, mid), 3.5, param="org")
                fit_text(sheet, given[1][0], (x0, mid, x1, bottom), 2.5, param="group")
            elif given:
                fit_text(sheet, given[0][0], room, 3.5, param=given[0][1])
            continue
        text, height, param = data[key]
        if text:
            # one line for the identification number, as ISO 7200 writes it (16 characters)
            lines = 1 if key == "iso_id" else 0
            fit_text(sheet, text, room, height, param=param, max_lines=lines)
