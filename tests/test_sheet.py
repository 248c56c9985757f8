"""The sheet layer: scales (GOST 2.302), dash fitting (GOST 2.303), lettering (GOST 2.304), the
frame and title block (GOST 2.301, 2.104), and the 2013-6 sheet — true to scale, no overlapping
labels, everything inside the frame, for the seed's data and for other variants."""

from __future__ import annotations

import dataclasses
import math
from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from layout import (
    A3_BLOCK,
    Box,
    block_part,
    inside,
    item_box,
    layout_problems,
    overlap,
    overlapping_texts,
    text_box,
)

import geomcad
from geomcad.errors import ParameterError
from geomcad.sheet import TitleBlock, new_sheet, paper
from geomcad.sheet.frame import fill_title_blocks
from geomcad.sheet.model import CircleItem, Polyline, Run, Sheet, TextItem
from geomcad.sheet.scale import NICE, Scale, fmt_number, gost_length_scale, nice_factor
from geomcad.sheet.style import LineType, fit_centre_line, fit_closed, fit_open
from geomcad.sheet.text import HEIGHTS, box, font_path, metrics, parse, width

#: GOST 2.302 ratios paper : nature, written out here independently of the library's table.
GOST_2302 = sorted(
    [Fraction(1, n) for n in (1, 2, 4, 5, 10, 15, 20, 25, 40, 50, 75, 100, 200, 400, 500)]
    + [Fraction(2, 5), Fraction(5, 2)]
    + [Fraction(n) for n in (2, 4, 5, 10, 20, 40, 50, 100)]
)

#: GOST 2.303 dash ranges (mm): (min, max) of a dash.
DASH_RANGE: dict[LineType, tuple[float, float]] = {
    "dashed": (2.0, 8.0),
    "dashdot": (5.0, 30.0),
    "twodot": (5.0, 30.0),
}
BROKEN: tuple[LineType, ...] = ("dashed", "dashdot", "twodot")

#: The right-hand tables of 2013-6 start at x = 262; the mechanism view must stay left of this.
VIEW_RIGHT = 258.0


# -- helpers ---------------------------------------------------------------------------------------


def sheet_2013_6(**params: float) -> Sheet:
    name, sheet = geomcad.solve("2013-6", **params).sheets()[0]
    assert name == ""
    return sheet


# -- scales ----------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("k", "text"),
    [(0.005, "1:5"), (0.0025, "1:2,5"), (0.0005, "2:1"), (0.001, "1:1"), (0.0004, "2,5:1")],
)
def test_ratio_text(k: float, text: str) -> None:
    assert Scale(k, "l").ratio_text() == text


def test_ratio_text_is_empty_off_gost() -> None:
    assert Scale(0.003, "l").ratio_text() == ""  # 1:3 is not a GOST 2.302 scale
    assert Scale(0.005, "v").ratio_text() == ""  # a velocity factor has no ratio


def test_scale_labels() -> None:
    assert Scale(0.005, "l").label() == "μ_l = 0,005 м/мм"
    assert Scale(0.02, "v").label() == "μ_V = 0,02 (м/с)/мм"
    assert Scale(0.005, "l").mm(0.2) == pytest.approx(40.0)
    assert fmt_number(-0.25) == "–0,25"
    assert fmt_number(0.25, "en") == "0.25"


@settings(max_examples=300, deadline=None)
@given(extent=st.floats(0.01, 20.0), room=st.floats(20.0, 800.0))
def test_gost_length_scale_is_the_largest_that_fits(extent: float, room: float) -> None:
    # keep to drawings that fit at the smallest ratio the library offers (1:500)
    assume(extent * 1000.0 / 500.0 <= room)
    s = gost_length_scale(extent, room)
    ratio = Fraction(1, 1000) / Fraction(s.k).limit_denominator(10**9)
    assert ratio in GOST_2302, f"1 : {1 / ratio} is not a GOST 2.302 ratio"
    assert extent / s.k <= room * (1.0 + 1e-12), "the drawing does not fit its room"
    larger = [g for g in GOST_2302 if g > ratio]
    if larger:
        assert extent * 1000.0 * float(larger[0]) > room, f"{larger[0]} fits too"


def test_gost_length_scale_never_returns_a_scale_that_does_not_fit() -> None:
    try:
        s = gost_length_scale(10.0, 10.0)
    except ParameterError:
        return
    assert 10.0 / s.k <= 10.0


def _mantissa(k: float) -> float:
    return k / 10.0 ** math.floor(math.log10(k) + 1e-12)


@settings(max_examples=300, deadline=None)
@given(value=st.floats(1e-4, 1e6), room=st.floats(5.0, 500.0))
def test_nice_factor_is_nice_and_minimal(value: float, room: float) -> None:
    s = nice_factor(value, room, "v")
    m = _mantissa(s.k)
    assert any(math.isclose(m, n, rel_tol=1e-9) for n in (1.0, 2.0, 2.5, 4.0, 5.0)), s.k
    assert value / s.k <= room * (1.0 + 1e-12), "the plan does not fit its room"
    # the next smaller nice factor would not fit
    i = min(range(len(NICE)), key=lambda j: abs(NICE[j] - m))
    smaller = (
        NICE[i - 1] * s.k / m if i > 0 else NICE[-1] * s.k / m / 10.0
    )  # 1 × 10^n → 5 × 10^(n−1)
    assert value / smaller > room * (1.0 - 1e-12), f"{smaller} fits too"


@pytest.mark.parametrize(
    "call",
    [
        lambda: Scale(0.0, "l"),
        lambda: Scale(-0.005, "l"),
        lambda: Scale(math.nan, "v"),
        lambda: Scale(math.inf, "F"),
        lambda: gost_length_scale(0.0, 100.0),
        lambda: gost_length_scale(0.3, -1.0),
        lambda: gost_length_scale(math.nan, 100.0),
        lambda: nice_factor(0.0, 100.0, "v"),
        lambda: nice_factor(1.0, 0.0, "a"),
        lambda: nice_factor(-1.0, 100.0, "F"),
    ],
)
def test_bad_scale_input(call: object) -> None:
    assert callable(call)
    with pytest.raises(ParameterError):
        call()


@pytest.mark.parametrize(
    "call",
    [
        lambda: nice_factor(math.inf, 100.0, "v"),
        lambda: nice_factor(1.0, math.inf, "v"),
        lambda: gost_length_scale(math.inf, 100.0),
    ],
)
def test_non_finite_scale_input(call: object) -> None:
    assert callable(call)
    with pytest.raises(ParameterError):
        call()


# -- dash fitting ----------------------------------------------------------------------------------


def _count(length: float, dash: float, gap: float) -> int:
    """The number of dashes n of a pattern with n·dash + (n − 1)·gap = length (checked)."""
    n = (length + gap) / (dash + gap)
    assert abs(n - round(n)) < 1e-9, f"{length} mm is not a whole number of dashes ({n})"
    return round(n)


@settings(max_examples=300, deadline=None)
@given(line=st.sampled_from(BROKEN), length=st.floats(10.0, 500.0))
def test_fit_open_starts_and_ends_with_a_dash(line: LineType, length: float) -> None:
    d = fit_open(line, length)
    lo, hi = DASH_RANGE[line]
    if d is None:
        # only a line too short for two shortest dashes may be drawn solid; allow the library's
        # rounding to the target dash up to one period (see test_fit_open_short_dashdot)
        assert length < 2.0 * 12.0 + 5.0, f"{line} line of {length} mm left solid"
        return
    dash, *gaps = d.array
    gap = sum(gaps)
    n = _count(length, dash, gap)
    assert n >= 2
    assert abs(n * dash + (n - 1) * gap - length) <= 1e-9
    assert lo <= dash <= hi, f"dash {dash} mm outside GOST {lo}–{hi}"
    assert d.offset == 0.0
    if line != "dashed":
        dots = 1 if line == "dashdot" else 2
        assert len(gaps) == 2 * dots + 1, gaps  # gap, (dot, gap) per dot


def test_fit_open_short_dashdot() -> None:
    assert fit_open("dashdot", 15.0) is not None
    assert fit_closed("dashdot", 20.0) is not None


@settings(max_examples=300, deadline=None)
@given(line=st.sampled_from(BROKEN), length=st.floats(10.0, 500.0))
def test_fit_closed_whole_periods(line: LineType, length: float) -> None:
    d = fit_closed(line, length)
    lo, hi = DASH_RANGE[line]
    if d is None:
        assert length < 2.0 * (12.0 + 5.0) + 5.0, f"{line} circle of {length} mm left solid"
        return
    period = sum(d.array)
    n = length / period
    assert abs(n - round(n)) < 1e-9 and round(n) >= 2, f"{n} periods"
    dash = d.array[0]
    assert lo <= dash <= hi
    # the start point sits in the middle of a gap: the pattern is symmetric about it
    assert d.offset == pytest.approx(dash + (period - dash) / 2.0, abs=1e-12)


@settings(max_examples=300, deadline=None)
@given(line=st.sampled_from(("dashdot", "twodot")), half=st.floats(5.0, 250.0))
def test_fit_centre_line_crosses_at_a_dash(line: LineType, half: float) -> None:
    d = fit_centre_line(line, half)
    lo, hi = DASH_RANGE[line]
    if d is None:
        assert 2.0 * half < 3.0 * 12.0 + 2.0 * 5.0, f"centre line of {2 * half} mm left solid"
        return
    dash, *gaps = d.array
    gap = sum(gaps)
    n = _count(2.0 * half, dash, gap)
    assert n % 2 == 1 and n >= 3, f"{n} dashes"
    assert lo <= dash <= hi
    start = (n - 1) // 2 * (dash + gap)  # the middle dash
    assert start < half < start + dash


def test_solid_lines_have_no_pattern() -> None:
    assert fit_open("solid", 100.0) is None
    assert fit_closed("solid", 100.0) is None


# -- lettering -------------------------------------------------------------------------------------


def test_parse_markup() -> None:
    assert parse("V_{B3B2}") == (Run("V"), Run("B3B2", "sub"))
    assert parse("O_1") == (Run("O"), Run("1", "sub"))
    assert parse("O_1B_0") == (Run("O"), Run("1", "sub"), Run("B"), Run("0", "sub"))
    assert parse("x^2") == (Run("x"), Run("2", "sup"))
    assert parse(r"a\_b") == (Run("a_b"),)
    assert parse("план") == (Run("план"),)


def test_parse_unclosed_brace() -> None:
    with pytest.raises(ValueError, match="unclosed"):
        parse("V_{B3")


@pytest.mark.parametrize("h", HEIGHTS)
def test_font_size_gives_the_cap_height(h: float) -> None:
    m = metrics()
    fs = m.font_size(h)
    assert fs * m.cap_height / m.units_per_em == pytest.approx(h, rel=1e-12)
    # the cap height the font declares is that of its capitals (glyph H), within 1 %
    from fontTools.pens.boundsPen import BoundsPen
    from fontTools.ttLib import TTFont

    with TTFont(str(font_path())) as f:
        glyphs = f.getGlyphSet()
        pen = BoundsPen(glyphs)
        glyphs[f.getBestCmap()[ord("H")]].draw(pen)
        assert pen.bounds is not None
        glyph_h = (pen.bounds[3] - pen.bounds[1]) * fs / f["head"].unitsPerEm
    assert glyph_h == pytest.approx(h, rel=0.01)


def test_subscript_is_smaller_and_widths_add_up() -> None:
    fs = metrics().font_size(3.5)
    w_sub = width(parse("O_1"), fs)
    w_base = width(parse("O1"), fs)
    assert 0.0 < w_sub < w_base
    assert width(parse("AB"), fs) == pytest.approx(width(parse("A"), fs) + width(parse("B"), fs))
    _, up, down = box(parse("O_1"), 3.5)
    assert up == 3.5 and down > 0.0


@pytest.mark.parametrize("label", ["⊥", "V_B ⊥ AB", "√2"])
def test_missing_glyph_is_an_error(label: str) -> None:
    bad = next(c for c in label if c in "⊥√")
    with pytest.raises(ValueError, match=bad):
        width(parse(label), 3.5)
    sheet, _ = new_sheet("A3", TitleBlock(title=label, designation="X"))
    with pytest.raises(ValueError, match=bad):
        fill_title_blocks([sheet])


# -- frame and title block -------------------------------------------------------------------------


@pytest.fixture(scope="module")
def a3() -> Sheet:
    sheet, _ = new_sheet(
        "A3", TitleBlock(title="План скоростей", designation="ТММ.01", scale="1:5")
    )
    fill_title_blocks([sheet])
    return sheet


def _block_segments(sheet: Sheet) -> dict[str, set[tuple[float, float, float, float]]]:
    """The title block's straight lines in block mm (origin lower-left, y up), by role."""
    bx, by = A3_BLOCK[0], A3_BLOCK[3]
    out: dict[str, set[tuple[float, float, float, float]]] = {"frame": set(), "frame_thin": set()}
    for it in sheet.items:
        if isinstance(it, Polyline) and it.role in out and len(it.points) == 2:
            (xa, ya), (xb, yb) = ((round(x - bx, 6), round(by - y, 6)) for x, y in it.points)
            out[it.role].add((min(xa, xb), min(ya, yb), max(xa, xb), max(ya, yb)))
    return out


def test_paper_sizes() -> None:
    assert paper("A3") == (420.0, 297.0)
    assert paper("A3", landscape=False) == (297.0, 420.0)
    assert paper("A4") == (210.0, 297.0)
    assert paper("A4", landscape=True) == (210.0, 297.0)  # A4 is portrait only
    assert paper("A1") == (841.0, 594.0)


@pytest.mark.parametrize("fmt", ["A5", "a3", "", "Letter"])
def test_unknown_format(fmt: str) -> None:
    with pytest.raises(ParameterError, match="format"):
        paper(fmt)
    with pytest.raises(ParameterError):
        new_sheet(fmt, TitleBlock(title="x", designation="y"))


def test_frame_margins(a3: Sheet) -> None:
    assert (a3.width, a3.height, a3.format) == (420.0, 297.0, "A3")
    outer = a3.items[0]
    assert isinstance(outer, Polyline) and outer.closed and outer.role == "frame"
    assert set(outer.points) == {(20.0, 5.0), (415.0, 5.0), (415.0, 292.0), (20.0, 292.0)}
    a4, frame = new_sheet("A4", TitleBlock(title="x", designation="y"))
    assert (a4.width, a4.height) == (210.0, 297.0)
    assert (frame.left, frame.top, frame.right, frame.bottom) == (20.0, 5.0, 205.0, 292.0)
    assert (frame.tb_left, frame.tb_top) == (20.0, 237.0)


def test_title_block_outline(a3: Sheet) -> None:
    outlines = [
        it
        for it in a3.items
        if isinstance(it, Polyline) and it.closed and it.role == "frame" and it is not a3.items[0]
    ]
    assert len(outlines) == 2  # the title block and графа 26
    assert set(outlines[1].points) == {(20.0, 5.0), (90.0, 5.0), (90.0, 19.0), (20.0, 19.0)}
    xs = [p[0] for p in outlines[0].points]
    ys = [p[1] for p in outlines[0].points]
    assert (min(xs), min(ys), max(xs), max(ys)) == A3_BLOCK  # 185 × 55 in the corner
    assert (max(xs) - min(xs), max(ys) - min(ys)) == (185.0, 55.0)


def test_title_block_lines(a3: Sheet) -> None:
    seg = _block_segments(a3)
    thick, thin = seg["frame"], seg["frame_thin"]
    for x in (17, 40, 55, 65):
        assert (x, 0, x, 55) in thick, f"thick vertical x = {x}"
    assert (7, 30, 7, 55) in thick
    assert (135, 0, 135, 40) in thick
    for y in (30, 35):
        assert (0, y, 65, y) in thick, f"thick horizontal y = {y}"
    for y in (40, 15):
        assert (65, y, 185, y) in thick, f"thick horizontal y = {y} across the right part"
    for y in (20, 35):
        assert (135, y, 185, y) in thick
    for x in (150, 167):
        assert (x, 20, x, 40) in thick
    assert (155, 15, 155, 20) in thick
    # the left part's 5 mm rows are thin, except the header's thick lines
    rows = {y for (_x0, y, _x1, y2) in thin if y == y2}
    assert rows == {5, 10, 15, 20, 25, 40, 45, 50}
    for row in rows:
        assert (0, row, 65, row) in thin
    # the stage ("Лит.") has three cells
    assert {(140, 20, 140, 35), (145, 20, 145, 35)} <= thin


CAPTION_CELLS = {
    "Изм.": (0, 30, 7, 35),
    "Лист": (7, 30, 17, 35),
    "№ докум.": (17, 30, 40, 35),
    "Подп.": (40, 30, 55, 35),
    "Дата": (55, 30, 65, 35),
    "Разраб.": (0, 25, 17, 30),
    "Пров.": (0, 20, 17, 25),
    "Т.контр.": (0, 15, 17, 20),
    "Н.контр.": (0, 5, 17, 10),
    "Утв.": (0, 0, 17, 5),
    "Лит.": (135, 35, 150, 40),
    "Масса": (150, 35, 167, 40),
    "Масштаб": (167, 35, 185, 40),
    "Лист 1": (135, 15, 155, 20),
    "Листов 1": (155, 15, 185, 20),
    "1:5": (167, 20, 185, 35),
    "ТММ.01": (65, 40, 185, 55),
    "План скоростей": (65, 15, 135, 40),
}


def _sheet_cell(cell: tuple[float, float, float, float]) -> Box:
    x0, y0, x1, y1 = cell
    return (A3_BLOCK[0] + x0, A3_BLOCK[3] - y1, A3_BLOCK[0] + x1, A3_BLOCK[3] - y0)


def test_title_block_captions_in_their_cells(a3: Sheet) -> None:
    texts = {t.text: t for t in a3.texts() if not t.angle}
    for caption, cell in CAPTION_CELLS.items():
        assert caption in texts, f"caption {caption!r} missing; have {sorted(texts)}"
        tb = text_box(texts[caption])
        assert inside(tb, _sheet_cell(cell)), f"{caption!r} {tb} outside its cell {cell}"
    g26 = (20.0, 5.0, 90.0, 19.0)
    under = (A3_BLOCK[0], A3_BLOCK[3], A3_BLOCK[2], 297.0)
    for t in a3.texts():
        places = (A3_BLOCK, g26, under)
        assert any(inside(text_box(t), b) for b in places), f"{t.text!r} outside the form"
        assert t.role == "title"
    # графа 26: the designation turned 180° in the top-left corner
    (d26,) = [t for t in a3.texts() if t.angle]
    assert (d26.text, d26.angle) == ("ТММ.01", 180.0) and inside(text_box(d26), g26)
    # under the frame: Копировал and Формат; Лит. "У" for coursework
    words = {t.text for t in a3.texts()}
    assert {"Копировал", "Формат A3", "У", "Лист 1", "Листов 1"} <= words
    assert not overlapping_texts(a3.texts())


def test_long_title_is_broken_into_lines() -> None:
    title = "Синтез шестизвенного механизма по коэффициенту изменения средней скорости"
    sheet, _ = new_sheet("A3", TitleBlock(title=title, designation="X"))
    fill_title_blocks([sheet])
    lines = [t for t in sheet.texts() if t.text in title and t.text not in ("X",)]
    assert len(lines) >= 2
    assert " ".join(t.text for t in lines) == title
    for t in lines:
        assert inside(text_box(t), _sheet_cell((65, 15, 135, 40)))
    assert not overlapping_texts(sheet.texts())


# -- the 2013-6 sheet ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def seed_sheet() -> Sheet:
    return sheet_2013_6()


def test_2013_6_is_a3(seed_sheet: Sheet) -> None:
    assert (seed_sheet.format, seed_sheet.width, seed_sheet.height) == ("A3", 420.0, 297.0)


def test_2013_6_is_true_to_scale() -> None:
    sol = geomcad.solve("2013-6")
    k = sol.scales["l"]
    sheet = sol.sheets()[0][1]
    O1 = sol.data.chosen.O1
    # O1B0 and O1B1 are the dead-centre lines of the extreme positions: A0·O1·B0 (folded)
    # and O1·A1·B1 (extended), each one two-dot line
    lines = [it.points for it in sheet.items if isinstance(it, Polyline) and it.role == "extreme"]
    joints = [it.c for it in sheet.items if isinstance(it, CircleItem) and it.role == "joint"]

    def on(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> bool:
        ab = math.dist(a, b)
        return abs(math.dist(a, p) + math.dist(p, b) - ab) < 1e-7

    found = 0
    for o1 in joints:
        ok = True
        for name in ("B0", "B1"):
            q = sol.construction[name]
            # the model vector O1 → B at k_l, y flipped once
            want = (o1[0] + (q.x - O1.x) / k, o1[1] - (q.y - O1.y) / k)
            hit = [e for ln in lines if len(ln) == 2 and on(o1, *ln) for e in ln
                   if math.dist(e, want) < 1e-9 * 100.0]  # fmt: skip
            if not hit:
                ok = False
                break
            assert math.dist(o1, hit[0]) * k == pytest.approx(sol.results[f"O1{name}"], rel=1e-9)
        found += ok
    # (the crank's centre on the sheet is a drawn joint circle: O1 is sought among them)
    assert found == 1, "one joint O1 from which the extreme lines reach B0 and B1 to scale"


def test_2013_6_scale_in_the_title_block(seed_sheet: Sheet) -> None:
    k = geomcad.solve("2013-6").scales["l"]
    cell = _sheet_cell((167, 20, 185, 35))
    in_cell = [t.text for t in seed_sheet.texts() if inside(text_box(t), cell)]
    assert in_cell == [Scale(k, "l").ratio_text()] == ["1:5"]
    assert any(Scale(k, "l").label().replace("_", "") in t.text for t in seed_sheet.texts())


def _check_layout(sheet: Sheet) -> None:
    _block, drawn = block_part(sheet)
    # the one checker: texts on texts, outside the frame, on the title block or графа 26, colour
    problems: list[str] = layout_problems(sheet)
    for it in drawn:
        b = item_box(it)
        what = f"{type(it).__name__} {it.role} {getattr(it, 'text', '')!r} {b}"
        geometry = not isinstance(it, TextItem) and it.role not in ("frame", "frame_thin")
        if geometry and b[2] >= VIEW_RIGHT:
            problems.append(f"mechanism view reaches the tables (x ≥ {VIEW_RIGHT}): {what}")
    # every placed label keeps off the tables' rulings
    tables = [
        item_box(it)
        for it in drawn
        if isinstance(it, Polyline) and it.closed and it.role == "frame_thin"
    ]
    assert tables, "the right-hand tables are missing"
    for t in sheet.texts():
        if t.role == "label" and t.at[0] < VIEW_RIGHT:
            problems += [
                f"label {t.text!r} on a table" for tb in tables if overlap(text_box(t), tb)
            ]
    # every glyph is in the font, and the stored width is the font's
    m = metrics()
    for t in sheet.texts():
        for r in t.runs:
            m.advance(r.text, 1.0)  # raises ValueError naming a missing glyph
        assert t.width == pytest.approx(width(t.runs, t.font_size), abs=1e-9)
    assert not problems, "\n".join(problems)


def test_2013_6_layout(seed_sheet: Sheet) -> None:
    _check_layout(seed_sheet)


def test_2013_6_labels_name_the_points(seed_sheet: Sheet) -> None:
    words = {t.text for t in seed_sheet.texts() if t.role == "label"}
    for name in ("O1", "O2", "A", "B", "C", "B0", "B1", "C0", "C1", "O", "θ"):
        assert name in words, f"no label {name!r}"


VARIANTS = [
    {"K": 1.4, "H": 0.15, "e": 0.25},
    {"K": 1.15, "H": 0.25, "l3": 0.35, "l4": 0.4, "e": 0.2},
    {"K": 1.6, "H": 0.1, "l3": 0.25, "l4": 0.5, "e": 0.1},
]


@pytest.mark.parametrize(
    "params", VARIANTS, ids=lambda p: ",".join(f"{k}={v}" for k, v in p.items())
)
def test_2013_6_variant_layout(params: dict[str, float]) -> None:
    sol = geomcad.solve("2013-6", **params)
    k = Scale(sol.scales["l"], "l")
    assert k.ratio_text(), f"k_l = {k.k} is not a GOST 2.302 scale"
    sheet = sol.sheets()[0][1]
    assert sheet.format == "A3"
    _check_layout(sheet)
    scale_cell = _sheet_cell((167, 20, 185, 35))
    assert [t.text for t in sheet.texts() if inside(text_box(t), scale_cell)] == [k.ratio_text()]


def test_layout_check_can_fail(seed_sheet: Sheet) -> None:
    """The layout check sees a label on another one and a line in the tables."""
    labels = [t for t in seed_sheet.texts() if t.role == "label"]
    last = labels[-1]
    twin = dataclasses.replace(last, at=(last.at[0] + 0.5, last.at[1] + 0.5))
    broken = Sheet(420.0, 297.0, "A3", "x", [*seed_sheet.items, twin])
    with pytest.raises(AssertionError, match="overlap"):
        _check_layout(broken)
    stray = Polyline(((100.0, 100.0), (300.0, 100.0)), "construction")
    broken = Sheet(420.0, 297.0, "A3", "x", [*seed_sheet.items, stray])
    with pytest.raises(AssertionError, match="reaches the tables"):
        _check_layout(broken)


@pytest.mark.parametrize(("w", "h"), [(0.6, 0.1), (0.1, 0.6), (0.3, 0.3), (0.002, 0.001)])
def test_scale_to_fit_holds_both_directions(w: float, h: float) -> None:
    from geomcad.sheet.scale import gost_scale_to_fit

    k = gost_scale_to_fit(w, h, 200.0, 120.0)
    assert w / k.k <= 200.0 + 1e-9 and h / k.k <= 120.0 + 1e-9
    smaller = [g for g in GOST_2302 if g > k.ratio]  # the next larger drawing must not fit
    if smaller:
        g = float(min(smaller))
        assert w * 1000.0 * g > 200.0 + 1e-9 or h * 1000.0 * g > 120.0 + 1e-9
