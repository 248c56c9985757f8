"""Review 8's drafting rules (issue 27): the letters of details follow GOST 2.316."""

from __future__ import annotations

import itertools
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import (
    LETTER_CLEAR_MM,
    _gap,
    _segment_to_box,
    _text_box,
    kinematic_sheets,
)
from geomcad.sheet.model import CircleItem, Polyline, Sheet, TextItem

STRINGS = Path(__file__).resolve().parent.parent / "geomcad" / "sheet" / "strings"
#: GOST 2.316-2008, 4.17: the letters not used for views, sections and details (they read as
#: digits, as other letters or as a sign): Cyrillic Ё З Й О Ч Х Ъ Ы Ь, Latin I O.
NOT_FOR_VIEWS = {"ru": set("ЁЗЙОЧХЪЫЬ"), "en": set("IO")}
#: … and Э, which the shipped font's small lettering draws like the digit 3 (review 9: "Э1" read
#: as "31" on a force plan's caption line).
NOT_FOR_VIEWS["ru"] |= {"Э"}


@pytest.mark.parametrize("lang", sorted(NOT_FOR_VIEWS))
@pytest.mark.parametrize("table", ["linkage", "views"])
def test_detail_letters_leave_out_gost_2316s(lang: str, table: str) -> None:
    words = tomllib.loads((STRINGS / lang / f"{table}.toml").read_text(encoding="utf-8"))
    letters = words["detail_letters"]
    assert letters, (lang, table)
    assert not set(letters) & NOT_FOR_VIEWS[lang], (lang, table, letters)
    assert len(set(letters)) == len(letters), letters  # no letter twice
    assert all(c.isupper() for c in letters), letters


ROOT = Path(__file__).resolve().parent
#: Files whose forces sheet (and kinematic sheet) mark the crank's detail on the mechanism.
MARKED = {
    "sixbar_oscillator": ROOT / "linkages_layout" / "sixbar_oscillator.toml",
    "crusher": ROOT.parent / "examples" / "crusher.toml",
    "vertical_yoke_rocker": ROOT / "linkages_drafting" / "vertical_yoke_rocker.toml",
}


def _letter_marks(sheet: Sheet) -> list[int]:
    """Where a detail's letter stands on its shelf: a label drawn just after a thin ring and a
    thin three-point leader and shelf (:func:`~geomcad.sheet.linkage.mark_detail`)."""
    items = sheet.items
    return [
        k
        for k in range(2, len(items))
        if isinstance(items[k], TextItem)
        and items[k].role == "label"
        and isinstance(items[k - 1], Polyline)
        and items[k - 1].role == "thin"
        and len(items[k - 1].points) == 3
        and isinstance(items[k - 2], CircleItem)
        and items[k - 2].role == "thin"
    ]


@pytest.mark.parametrize("name", sorted(MARKED))
def test_a_detail_letter_stands_clear_of_its_view(name: str) -> None:
    """The letter on the detail's shelf keeps LETTER_CLEAR_MM (less its 0.3 mm of rounding)
    from every line, circle, dot and text drawn before it (review 8: a link ran through the
    oscillator's "Г", then its "Г" stood on the dot of Φ1's point)."""
    from geomcad.sheet.linkage_forces import force_sheets

    s = solve(parse(tomllib.loads(MARKED[name].read_text(encoding="utf-8"))))
    checked = 0
    for sheet in [sh for _, sh in kinematic_sheets(s, "x")] + [
        sh for _, sh in force_sheets(s, "x")
    ]:
        for k in _letter_marks(sheet):
            t = sheet.items[k]
            assert isinstance(t, TextItem)
            g = LETTER_CLEAR_MM - 0.3
            x0, y0, x1, y1 = _text_box(t)
            grown = (x0 - g, y0 - g, x1 + g, y1 + g)
            for it in sheet.items[: k - 2]:
                if isinstance(it, Polyline):
                    pts = (*it.points, *it.points[:1]) if it.closed else it.points
                    for p, q in itertools.pairwise(pts):
                        assert _segment_to_box(p, q, grown) > 0.0, (name, it.role, p, q)
                elif isinstance(it, CircleItem) and it.r <= 2.0 * LETTER_CLEAR_MM:
                    dot = (it.c[0] - it.r, it.c[1] - it.r, it.c[0] + it.r, it.c[1] + it.r)
                    assert _gap(grown, dot) > 0.0, (name, it.c)
                elif isinstance(it, TextItem) and not it.angle:
                    assert _gap(grown, _text_box(it)) > 0.0, (name, it.text)
            checked += 1
    assert checked, name


#: GOST 2.304's space between words: 0.6 of the letters' height. Two titles nearer than this
#: read as one line.
WORD_SPACE = 0.6


@pytest.mark.parametrize(
    "name", ["rocking_cylinder_rocker", "crank_rocker_inclined_slide", "sixbar_oscillator"]
)
def test_titles_stand_a_word_space_apart(name: str) -> None:
    """No line of a title comes nearer another title (5 mm letters and more) than a word space
    (review 8: the dynamics sheet's title, moved right of графа 26 but broken for its whole
    box, ran to 0.3 mm past the start of Wittenbauer's title over the next column)."""
    from geomcad.sheet.linkage_forces import force_sheets

    s = solve(parse(tomllib.loads((ROOT / "linkages_layout" / f"{name}.toml").read_text("utf-8"))))
    sheets = [sh for _, sh in kinematic_sheets(s, "x")] + [sh for _, sh in force_sheets(s, "x")]
    for sheet in sheets:
        titles = [t for t in sheet.texts() if t.height >= 5.0 and not t.angle]
        for a, b in itertools.combinations(titles, 2):
            if abs(a.at[0] - b.at[0]) < 1e-6:  # the lines of one title, or a column of them
                continue
            gap = _gap(_text_box(a), _text_box(b))
            assert gap >= WORD_SPACE * a.height, (name, a.text, b.text, gap)


#: A point's letter and a position's number nearer than this (mm) read as one text ("D⁷").
LETTER_NUMBER_MM = 1.0
LETTERED = [
    "crank_rocker_inclined_slide",
    "sixbar_coupler_slider",
    "yoke_pump_double_slider",
    "double_kulisa_screen",
    "press_offset_long_rod",
]


@pytest.mark.parametrize("name", LETTERED)
def test_a_points_letter_stands_apart_from_the_position_numbers(name: str) -> None:
    """On the mechanism in its positions, no position's number (NUMBER_H digits) stands within
    LETTER_NUMBER_MM of a point's letter (review 8: crank_rocker_inclined_slide's "D⁷", its
    B beside the row "7 3 6 4 5"; the shaper's "1A", the four-bar's "A⁰")."""
    from geomcad.sheet.linkage import NUMBER_H

    s = solve(parse(tomllib.loads((ROOT / "linkages_layout" / f"{name}.toml").read_text("utf-8"))))
    names = set(s.drawn[0].pos)
    sheet = kinematic_sheets(s, "x")[0][1]
    texts = [t for t in sheet.texts() if not t.angle]
    letters = [t for t in texts if t.height == 3.5 and t.runs[0].text[:1] in names]
    numbers = [t for t in texts if t.height == NUMBER_H and t.text.isdigit()]
    assert letters and numbers, name
    for a in letters:
        for b in numbers:
            gap = _gap(_text_box(a), _text_box(b))
            assert gap >= LETTER_NUMBER_MM, (name, a.text, b.text, round(gap, 2))
