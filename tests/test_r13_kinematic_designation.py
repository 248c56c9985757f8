"""Review 13 of issue 27, the default designation: a file without ``designation`` got its stem's
English words transliterated to Cyrillic (``ТММ.ГАНГ.САВ.ФФ.01`` for gang_saw_frame_feed.toml),
which a teacher reads as nonsense. The default is now an ESKD-like code: the initials of the
file's title in the sheet's script (Механизм лесопильной рамы с приводом подачи → МЛРПП), else a
neutral six-digit number (:func:`geomcad.files.code`)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import geomcad
from geomcad.files import cam_sheets

ROOT = Path(__file__).resolve().parent.parent
SRC = ROOT / "examples" / "slider-crank.toml"


def _designations(path: Path) -> set[str]:
    """The designations printed on the file's sheets (графа 2 and 26)."""
    sheets = geomcad.solve(str(path)).sheets()
    return {t.text for _, sh in sheets for t in sh.texts() if re.match(r"ТММ\.", t.text)}


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The slider-crank under the stem that read as nonsense, with its title and without."""
    d = tmp_path_factory.mktemp("r13")
    titled = d / "gang_saw_frame_feed.toml"
    titled.write_text(SRC.read_text(encoding="utf-8"), encoding="utf-8")
    bare = d / "untitled" / "gang_saw_frame_feed.toml"
    bare.parent.mkdir()
    text = SRC.read_text(encoding="utf-8")
    bare.write_text(re.sub(r"(?m)^title = .*\n", "", text), encoding="utf-8")
    return {"titled": titled, "bare": bare}


def test_a_titled_files_default_designation_is_its_titles_initials(files: dict[str, Path]) -> None:
    # title = "Кривошипно-ползунный механизм"
    assert _designations(files["titled"]) == {"ТММ.КПМ.01"}


def test_an_untitled_files_default_designation_is_a_number(files: dict[str, Path]) -> None:
    got = _designations(files["bare"])
    assert len(got) == 1 and re.fullmatch(r"ТММ\.\d{6}\.01", got.pop())


def test_no_default_designation_transliterates_the_stem(files: dict[str, Path]) -> None:
    for path in files.values():
        assert not any("ГАНГ" in d or "САВ" in d for d in _designations(path))


def test_a_cam_files_default_designation_is_its_titles_initials() -> None:
    # title = "Кулачковый механизм с плоским толкателем": the preposition skipped
    sol = geomcad.solve(str(ROOT / "examples" / "cam-flat.toml"))
    assert cam_sheets.designation(sol) == "ТММ.КМПТ.04"
