"""General lettering rules of the sheets (issue 27's review): a title-block name inside its cell
with an ESKD clearance, a table's heading within its table, a default designation that reads as
a code, the numbered positions of a point labelled once each, large numbers in plain digits."""

from __future__ import annotations

import itertools
import math
import re
import tomllib
from pathlib import Path

import pytest
from layout import layout_problems

from geomcad.files import code
from geomcad.geom import Vec
from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.drawing import Drawing
from geomcad.sheet.frame import CELL_LEAD, clearance, fill_title_blocks, fit_text, new_sheet
from geomcad.sheet.linkage import SHARE_MM, position_numbers
from geomcad.sheet.scale import fmt_column, fmt_number
from geomcad.sheet.text import box, parse
from geomcad.sheet.views import HEADING_LINES, Table

CELL = (100.0, 50.0, 170.0, 75.0)  # the name's cell of form 1: 70 × 25 mm

NAMES = [
    "Кинематический анализ. Ползун на качающемся звене",
    "Силовой анализ. Механизм поперечно-строгального станка",
    "Динамика машины. Маховик. Механизм поперечно-строгального станка",
    "Кинематический анализ",
    "Синтез кривошипно-коромыслового механизма по коэффициенту изменения средней скорости",
]


@pytest.mark.parametrize("name", NAMES)
def test_a_name_sits_inside_its_cell_with_a_clearance(name: str) -> None:
    """Every line of the name keeps clearance(h) from each of the cell's four lines, lines are
    GOST 2.304's 1.7 h apart, and no word is lost or broken but after a hyphen."""
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    items = fit_text(sheet, name, CELL, 5.0, clear=True)
    h = items[0].height
    c = clearance(h)
    x0, y0, x1, y1 = CELL
    for t in items:
        assert t.height == h
        assert t.at[0] >= x0 + c - 1e-9 and t.at[0] + t.width <= x1 - c + 1e-9
    assert items[0].at[1] - h >= y0 + c - 1e-9
    assert items[-1].at[1] <= y1 - c + 1e-9
    for a, b in itertools.pairwise(items):
        assert b.at[1] - a.at[1] == pytest.approx(CELL_LEAD * h)
    joined = "".join(t.text + ("" if t.text.endswith("-") else " ") for t in items)
    assert joined.strip() == name


def test_a_long_name_is_shrunk_before_it_runs_out_and_lines_are_balanced() -> None:
    """A name too wide for one line at 5 mm is broken into lines of about equal width (the
    widest as narrow as any break allows), not a full line and an orphan word."""
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    items = fit_text(sheet, NAMES[1], CELL, 5.0, clear=True)
    widths = [t.width for t in items]
    assert len(items) >= 2
    assert min(widths) > 0.5 * max(widths)


def test_a_name_that_cannot_fit_is_refused_by_name() -> None:
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    with pytest.raises(ValueError, match="title"):
        fit_text(sheet, "Ж" * 80, CELL, 5.0, param="title", clear=True)


def test_a_tables_heading_is_wrapped_to_its_width() -> None:
    rows = [["№", "φ_1, °", "I_{пр}, кг·м²"], ["0", "198,2", "0,000"]]
    heading = "Приведённый момент инерции и приведённый момент сил"
    t = Table(rows, title=heading, height=3.5, title_height=5.0)
    plain = Table(rows, height=3.5)
    assert 2 <= len(t.heading) <= HEADING_LINES
    # a table widened only as far as a heading of HEADING_LINES lines needs
    assert sum(t.widths) >= sum(plain.widths)
    if sum(t.widths) > sum(plain.widths) + 1e-9:
        assert len(t.heading) == HEADING_LINES
        widest = max(box(parse(line), 5.0)[0] for line in t.heading)
        assert widest == pytest.approx(sum(t.widths))
    wide = Table([["№", "φ_1, °", "I_{пр}, кг·м²", "M_{пр}, Н·м"] * 3], title=heading)
    assert len(wide.heading) == 1  # a table wider than its heading: one line
    assert all(box(parse(line), 5.0)[0] <= sum(t.widths) + 1e-9 for line in t.heading)
    assert " ".join(t.heading) == heading
    nat, nat0 = t.natural(), plain.natural()
    assert nat is not None and nat0 is not None
    # the heading's lines are room of the view
    assert nat[1] > nat0[1] + 5.0 * (1 + (len(t.heading) - 1) * CELL_LEAD)
    # the heading is drawn within the table's width, above it
    d = start("A3", TitleBlock(title="t", designation="x"))
    from geomcad.sheet.compose import Field, compose

    compose(d, t, Field((100.0, 30.0, 250.0, 200.0), ()))
    sheet = d.finish()
    lines = [x for x in sheet.texts() if x.text in t.heading]
    table_x0 = min(x.at[0] for x in sheet.texts() if x.text == "№")
    assert len(lines) == len(t.heading)
    assert all(x.at[0] + x.width <= table_x0 + sum(t.widths) for x in lines)


@pytest.mark.parametrize(
    ("title", "expected"),
    [
        # review 13: the default code is the file's title's initials, as a mechanism's name is
        # abbreviated (the stem's English words transliterated, ТММ.ГАНГ.САВ.ФФ.01, read as
        # nonsense); prepositions and conjunctions skipped, each part of a hyphenated word
        # kept, a gloss in brackets left out, a one-word title whole
        ("Шестизвенный кривошипно-ползунный механизм", "ШКПМ"),
        ("Шестизвенный кривошипно-ползунный механизм (задача 2013-6)", "ШКПМ"),
        ("Механизм лесопильной рамы с приводом подачи", "МЛРПП"),
        ("Кривошипно-ползунный механизм с качающейся кулисой", "КПМКК"),
        ("Механизм V-образного двухцилиндрового компрессора", "МОДК"),
        ("Станок-качалка (балансирный привод штангового насоса)", "СК"),
        ("(балансирный привод штангового насоса)", "БПШН"),
        ("Пресс", "ПРЕСС"),
        ("Рычажный механизм 2", "РМ2"),
    ],
)
def test_a_default_code_is_the_titles_initials(title: str, expected: str) -> None:
    assert code("dir/gang_saw_frame_feed.toml", title) == expected


STEMS = [
    "synthesis-slider-crank",
    "synthesis-slotted-lever",
    "synthesis-crank-rocker",
    "cam-rocking-roller",
    "cam-translating-roller",
    "press_offset_long_rod",
    "sixbar_oscillator",
    "sixbar_vertical_slide",
    "sixbar_coupler_slider",
    "v_compressor",
    "кулиса_с_ползуном",
]
ROOT = Path(__file__).resolve().parent.parent
LAYOUT_TITLES = {
    p.stem: tomllib.loads(p.read_text(encoding="utf-8")).get("title", "")
    for p in sorted((ROOT / "tests" / "linkages_layout").glob("*.toml"))
}


@pytest.mark.parametrize("stem", [*STEMS, "gang_saw_frame_feed", "W" * 40])
@pytest.mark.parametrize("title", ["", "Crank-rocker mechanism"])
def test_without_a_title_in_the_sheets_script_the_code_is_a_number(stem: str, title: str) -> None:
    """A file with no title in the sheet's script (none, or an English one on a Russian sheet)
    gets a neutral six-digit code, never its stem transliterated (review 13: ГАНГ.САВ.ФФ), the
    same for the same file and apart for the files here."""
    c = code(stem + ".toml", title)
    assert re.fullmatch(r"\d{6}", c), c
    assert c == code(f"elsewhere/{stem}.toml", title)
    assert len({code(s + ".toml", title) for s in STEMS}) == len(STEMS)


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize(
    ("stem", "title"),
    [(s, "") for s in STEMS]
    + list(LAYOUT_TITLES.items())
    + [("w", "W" * 40), ("ш", "Ш" * 40), ("ws", "W " * 40), ("шс", "Ш " * 40)],
)
def test_a_default_designation_is_one_script_and_fits_графа_26(
    stem: str, title: str, lang: str
) -> None:
    """Review 10: a default designation is letters of one script (Cyrillic with ТММ on a
    Russian sheet, Latin with TMM on an English one), digits and dots, and fits графа 26 at
    the 5 mm that typed designations take (ТММ.KULISA.INCLINED.01 shrank to 3.5 mm)."""
    from geomcad.sheet.frame import G26_WIDTH
    from geomcad.sheet.lang import language

    with language(lang):
        c = code(stem + ".toml", title)
    letters = "А-ЯЁ" if lang == "ru" else "A-Z"
    assert re.fullmatch(rf"[{letters}0-9]+(\.[{letters}0-9]+)*", c), c
    prefix = "ТММ" if lang == "ru" else "TMM"
    assert box(parse(f"{prefix}.{c}.05"), 5.0)[0] <= G26_WIDTH - 2.0


@pytest.mark.parametrize("letter", ["W", "Ш", "M"])
def test_the_longest_default_designation_fits_графа_2_and_26(letter: str) -> None:
    """The widest letters still fit both cells (at a GOST height), so a default designation
    never refuses to draw."""
    designation = f"ТММ.{code('x.toml', letter * 40)}.05"  # the kinds' widest sheet number
    sheet, _ = new_sheet("A3", TitleBlock(title="x", designation=designation, scale="1:1"))
    fill_title_blocks([sheet])
    assert sum(t.text == designation for t in sheet.texts()) == 2


def _numbers(sheet_texts: list[str]) -> list[int]:
    out: list[int] = []
    for t in sheet_texts:
        m = re.fullmatch(r"(\d+)(?:–(\d+))?", t)
        assert m, t
        a, b = int(m.group(1)), int(m.group(2) or m.group(1))
        out += range(a, b + 1)
    return out


@pytest.mark.parametrize("path", ["line", "arc", "circle"])
def test_each_position_is_numbered_once_clear_of_the_others(path: str) -> None:
    """Twelve positions of a point going and coming back (a slider, a rocker) or round (a
    crank): every number 0…11 stands once, in plain digits or a run "4–6" of neighbours that
    nearly coincide (never a list), and no two labels touch."""
    n = 12
    pts: list[Vec] = []
    vels: list[Vec] = []
    for i in range(n):
        phi = 2.0 * math.pi * i / n
        if path == "circle":
            pts.append(Vec(0.05 * math.cos(phi), 0.05 * math.sin(phi)))
            vels.append(Vec(-math.sin(phi), math.cos(phi)))
        else:
            s = 0.04 * (1.0 - math.cos(phi))  # out and back
            ds = math.sin(phi)
            if path == "line":
                pts.append(Vec(s, 0.0))
                vels.append(Vec(ds, 0.0))
            else:
                a = s / 0.2
                pts.append(Vec(0.2 * math.sin(a), 0.2 - 0.2 * math.cos(a)))
                vels.append(Vec(ds * math.cos(a), ds * math.sin(a)))
    d: Drawing = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.001, "l"), (0.0, 0.0), (200.0, 150.0))
    for q in pts:
        v.dot(q)
    position_numbers(v, pts, vels, Vec(-0.1, -0.1))
    sheet = d.finish()
    labels = [t.text for t in sheet.texts() if t.role == "label"]
    assert sorted(_numbers(labels)) == list(range(n))
    assert all("," not in t for t in labels)
    assert layout_problems(sheet) == []
    # a shared label only where its positions nearly coincide
    for t in labels:
        if "–" in t:
            a, b = map(int, t.split("–"))
            run = range(a, b + 1)
            far = max(v.mm((pts[i] - pts[j]).norm) for i in run for j in run)
            assert far < SHARE_MM


def test_large_numbers_in_plain_grouped_digits() -> None:
    assert fmt_number(11130.0, "ru", 4) == "11\u202f130"
    assert fmt_number(8544.0, "ru", 4) == "8544"
    assert fmt_number(-1.2345e6, "en", 4) == "\u20131\u202f234\u202f000"
    assert "10^" in fmt_number(2e-9, "ru", 4)  # a round-off stays a power of ten
    # a column at its largest value's precision: 12 346 whole, 2.6 then 3
    assert fmt_column([12345.6, 2.6], "ru", 4) == ["12\u202f346", "3"]


def test_the_names_of_one_document_share_one_height() -> None:
    """Every sheet's name (графа 1) of a document is lettered at one height: the least the
    longest name needs, not 5 mm on one sheet and 3.5 mm on the next."""
    import geomcad

    heights = set()
    for _, sheet in geomcad.solve("kulisa-23110713").sheets():
        x0 = sheet.width - 5.0 - 185.0 + 65.0
        y0 = sheet.height - 5.0 - 40.0
        names = [
            t for t in sheet.texts() if x0 <= t.at[0] <= x0 + 70.0 and y0 <= t.at[1] <= y0 + 25.0
        ]
        assert names
        heights |= {t.height for t in names}
    assert len(heights) == 1


def test_a_position_numbered_by_another_point_is_not_numbered_again() -> None:
    """Where a point's position falls on the same position of a point numbered before (a
    scotch yoke's slider at the crank's extremes), its number stands once."""
    pts = [Vec(0.05 * math.cos(a), 0.0) for a in (0.0, 1.0, 2.0, math.pi)]
    crank = [Vec(0.05 * math.cos(a), 0.05 * math.sin(a)) for a in (0.0, 1.0, 2.0, math.pi)]
    vels = [Vec(1.0, 0.0)] * 4
    d: Drawing = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.001, "l"), (0.0, 0.0), (200.0, 150.0))
    position_numbers(v, pts, vels, Vec(0.0, 0.0), crank)
    sheet = d.finish()
    assert sorted(_numbers([t.text for t in sheet.texts() if t.role == "label"])) == [1, 2]


INVERTED = """
title = "Кулисный механизм с вращающейся кулисой"
[frame]
O = [0.0, 0.0]
C = [0.0, -0.06]
[drive]
pivot = "O"
joint = "A"
length = 0.12
omega = 20.0
positions = 12
[[group]]
kind = "RPR"
links = [2, 3]
slider = "A"
pivot = "C"
offset = 0.0
[links.2]
mass = 2.0
J = 0.002
[links.3]
mass = 6.0
J = 0.04
[[load]]
link = 3
moment = -60.0
"""


def test_a_vanishing_load_is_written_0_in_the_loads_table(tmp_path: Path) -> None:
    """An inverted slider-crank whose forces position has ε = 0: its inertia moments vanish
    (ε is 0 to the plan's tolerance, not 10^-13): no row, no step and no arrow of M_Ф, and
    never a power of ten."""
    from geomcad import documents

    path = tmp_path / "inverted.toml"
    path.write_text(INVERTED, encoding="utf-8")
    sheets = dict(documents.solve(str(path)).sheets())
    forces = next(sh for name, sh in sheets.items() if "forces" in name)
    cells = [t.text for t in forces.texts()]
    assert not [c for c in cells if re.fullmatch(r"[–-]?[\d,]+·10.*", c)]
    assert not [c for c in cells if "MФ" in c or "M_{Ф" in c]
    assert "Ф2" in cells  # the inertia force is there


def test_a_short_heading_stands_on_one_line_over_a_narrow_table() -> None:
    """A two-word heading over a narrow table is written on one line (the view as wide as the
    heading, the table keeping its columns), never broken over a table with room beside it;
    a long heading wrapped for its table is drawn on one line where the layout gives room."""
    from geomcad.sheet.compose import Field, compose, text_width

    rows = [["Параметр", "Значение"], ["v_A", "1 м/с"], ["α", "60°"]]
    plain = Table(rows, height=2.5)
    t = Table(rows, height=2.5, title="Исходные данные", title_height=5.0)
    assert text_width("Исходные данные", 5.0) > sum(plain.widths)  # it is wider than the table
    assert t.heading == ["Исходные данные"]
    assert t.widths == plain.widths
    nat = t.natural()
    assert nat is not None and nat[0] == pytest.approx(text_width("Исходные данные", 5.0))
    # a long heading over a narrow table is still wrapped to the table ...
    heading = "Приведённый момент инерции и приведённый момент сил"
    long = Table(rows, height=2.5, title=heading, title_height=5.0)
    assert len(long.heading) >= 2
    # ... and drawn on one line where its box has room for that line
    d = start("A3", TitleBlock(title="t", designation="x"))
    compose(d, long, Field((20.0, 30.0, 400.0, 200.0), ()))
    sheet = d.finish()
    assert [x.text for x in sheet.texts() if x.text == heading] == [heading]
    assert not any(x.text in long.heading for x in sheet.texts())


def test_a_names_sentences_each_begin_a_line_before_one_is_broken_mid_line() -> None:
    """ "Силовой анализ. Шестизвенный механизм с ползуном" fits in two lines only by breaking
    after "Шестизвенный"; the cell holds three: each sentence begins a line."""
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    items = fit_text(
        sheet, "Силовой анализ. Шестизвенный механизм с ползуном", CELL, 5.0, clear=True
    )
    assert items[0].text == "Силовой анализ."
    assert items[1].text.startswith("Шестизвенный")
    # a name of one sentence is still set in balanced lines
    one = fit_text(sheet, "Шестизвенный механизм с ползуном и кулисой", CELL, 5.0, clear=True)
    assert " ".join(t.text for t in one) == "Шестизвенный механизм с ползуном и кулисой"
