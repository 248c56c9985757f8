"""A linkage sheet's name in its title block: what it draws and the file's title wherever the
two fit the name's cell at a GOST height (review 4: a 43-character title was dropped)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import geomcad
from geomcad.sheet.frame import name_fits
from geomcad.sheet.lang import language
from geomcad.sheet.linkage import sheet_name

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _linkage(title: str):  # type: ignore[no-untyped-def]
    lk = geomcad.solve(str(EXAMPLES / "shaper.toml")).data.linkage
    return dataclasses.replace(lk, title=title)


def test_a_long_title_that_fits_is_kept() -> None:
    title = "Шестизвенный механизм вертикального пресса"  # 43 characters
    with language("ru"):
        assert sheet_name(_linkage(title), "Силовой анализ") == f"Силовой анализ. {title}"


def test_a_title_that_fits_no_height_leaves_what_the_sheet_draws() -> None:
    title = " ".join(["Механизм"] * 60)
    with language("ru"):
        assert not name_fits(f"Силовой анализ. {title}", "ru")
        assert sheet_name(_linkage(title), "Силовой анализ") == "Силовой анализ"


def test_a_russian_title_stays_off_an_english_sheet() -> None:
    with language("en"):
        assert sheet_name(_linkage("Механизм пресса"), "Force analysis") == "Force analysis"
        assert sheet_name(_linkage("Press linkage"), "Force analysis") == (
            "Force analysis. Press linkage"
        )
