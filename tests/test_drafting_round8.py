"""Review 8's drafting rules (issue 27): the letters of details follow GOST 2.316."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

STRINGS = Path(__file__).resolve().parent.parent / "geomcad" / "sheet" / "strings"
#: GOST 2.316-2008, 4.17: the letters not used for views, sections and details (they read as
#: digits, as other letters or as a sign): Cyrillic Ё З Й О Ч Х Ъ Ы Ь, Latin I O.
NOT_FOR_VIEWS = {"ru": set("ЁЗЙОЧХЪЫЬ"), "en": set("IO")}


@pytest.mark.parametrize("lang", sorted(NOT_FOR_VIEWS))
@pytest.mark.parametrize("table", ["linkage", "views"])
def test_detail_letters_leave_out_gost_2316s(lang: str, table: str) -> None:
    words = tomllib.loads((STRINGS / lang / f"{table}.toml").read_text(encoding="utf-8"))
    letters = words["detail_letters"]
    assert letters, (lang, table)
    assert not set(letters) & NOT_FOR_VIEWS[lang], (lang, table, letters)
    assert len(set(letters)) == len(letters), letters  # no letter twice
    assert all(c.isupper() for c in letters), letters
