"""Review 14, item 6: the title block's lettering never below GOST 2.304's 2.5 mm where the
text fits its графа at 2.5 mm with its word spaces condensed ("Шарипова Л. Р." was set 1.8 mm
high in Разраб., 23.2 mm wide at 2.5 mm by the font's advances in a 22.2 mm room)."""

from __future__ import annotations

import pytest

from geomcad.sheet import TitleBlock
from geomcad.sheet.frame import NARROW_SPACE, fill_title_blocks, fit_text, new_sheet
from geomcad.sheet.model import TextItem
from geomcad.sheet.text import box, parse
from geomcad.sheet.titleblock import TitleData

#: Names that are wider than the Разраб. column's room at 2.5 mm with word spaces, and fit it
#: with narrow ones (measured with the pinned font's advances).
TIGHT = ["Шарипова Л. Р.", "Шишкина М. Ш.", "Жуковская М. Р."]
COLUMN = (17.0, 0.0, 40.0, 5.0)  # графа 11's column, 23 mm wide


@pytest.mark.parametrize("name", TIGHT)
def test_a_name_a_little_too_wide_is_condensed_not_shrunk(name: str) -> None:
    room = COLUMN[2] - COLUMN[0] - 0.8
    assert box(parse(name), 2.5)[0] > room  # the case: too wide with word spaces
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    (item,) = fit_text(sheet, name, COLUMN, 2.5, anchor="left")
    assert item.height == 2.5
    assert item.text.replace(NARROW_SPACE, " ") == name
    assert item.at[0] >= COLUMN[0] + 0.4 - 1e-9
    assert item.at[0] + item.width <= COLUMN[2] - 0.4 + 1e-9


def test_a_name_that_fits_keeps_its_word_spaces() -> None:
    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    (item,) = fit_text(sheet, "Киселёв В. Н.", COLUMN, 2.5, anchor="left")
    assert item.height == 2.5 and item.text == "Киселёв В. Н."


def test_every_графа_of_a_filled_block_is_at_least_2_5_mm() -> None:
    """The walkbeam's [sheet] data (review 14's crop): every text of the filled title block,
    графа 26 too, at least 2.5 mm high (a date is left out: DD.MM.YY is 12.4 mm at 2.5 mm, wider
    than the 10 mm Дата column, and is still set smaller)."""
    data = TitleData(student="Шарипова Л. Р.", checker="Киселёв В. Н.", group="ПТМ-32",
                     org="ЮУрГУ, каф. ТММ")  # fmt: skip
    tb = TitleBlock(title="Динамика машины. Маховик. Механизм шагового транспортёра",
                    designation="ШТ.ТММ.14.03.000 ПЗ", scale="1:2")  # fmt: skip
    sheet, _ = new_sheet("A2", tb)
    before = len(sheet.items)
    fill_title_blocks([sheet], data)
    texts = [t for t in sheet.items[before:] if isinstance(t, TextItem)]
    assert any("Шарипова" in t.text for t in texts)
    small = [(t.text, t.height) for t in texts if t.height < 2.5]
    assert not small


@pytest.mark.parametrize("name", ["Ахмедова-Лунд С. И.", "Никифоров С. Ю."])
def test_a_name_too_wide_even_condensed_takes_a_width_factor(name: str) -> None:
    """Wider than the column with narrow spaces too: set at a width factor (GOST 2.304's
    narrow type), 2.5 mm high, inside the column; every backend condenses its glyphs."""
    from geomcad.render.dxf import to_dxf_document
    from geomcad.render.svg import to_svg

    sheet, _ = new_sheet("A3", TitleBlock(title="t", designation="x"))
    (item,) = fit_text(sheet, name, COLUMN, 2.5, anchor="left")
    assert item.height == 2.5
    assert 0.7 <= item.stretch < 1.0
    assert item.width == pytest.approx(box(parse(item.text), 2.5)[0] * item.stretch)
    assert COLUMN[0] + 0.4 <= item.at[0] and item.at[0] + item.width <= COLUMN[2] - 0.4 + 1e-9
    assert f"matrix({item.stretch:.3f}".rstrip("0") in to_svg(sheet)
    widths = [e.dxf.width for e in to_dxf_document(sheet).modelspace().query("TEXT")
              if "." in e.dxf.text and e.dxf.width != 1.0]  # fmt: skip
    assert widths and widths[0] == pytest.approx(item.stretch)
