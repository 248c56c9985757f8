"""Hand-in sheets (issue 14): the user's title block, one document per problem, black by default,
and the audit of the published solution only on the review sheets."""

from __future__ import annotations

from pathlib import Path

import pytest
from layout import colours

import geomcad
from geomcad.cli import main
from geomcad.errors import ParameterError
from geomcad.render import to_svg
from geomcad.review import review_sheets
from geomcad.sheet.titleblock import TitleData

PEOPLE = TitleData(
    student="Иванов И.И.", checker="Петров П.П.", group="ТМ-231", org="ВолгГТУ", date="24.11.2026"
)
#: Words of the audit that no hand-in sheet may carry.
AUDIT = ("опубл", "разност", "ошибк", "опечатк", "восстановл", "rtol", "atol", "seed", "geomcad")


def _words(sheet: object) -> list[str]:
    return [t.text for t in sheet.texts()]  # type: ignore[attr-defined]


@pytest.fixture(scope="module")
def kulisa() -> list[tuple[str, object]]:
    return geomcad.solve("kulisa-23110713").sheets(PEOPLE)  # type: ignore[return-value]


def test_title_block_takes_the_user_data(kulisa: list[tuple[str, object]]) -> None:
    for i, (_, sheet) in enumerate(kulisa, 1):
        words = _words(sheet)
        for w in ("Иванов И.И.", "Петров П.П.", "ТМ-231", "ВолгГТУ", "24.11.26", "У"):
            assert w in words
        assert f"Лист {i}" in words and f"Листов {len(kulisa)}" in words


def test_one_designation_per_document(kulisa: list[tuple[str, object]]) -> None:
    designations = set()
    for _, sheet in kulisa:
        turned = [t for t in sheet.texts() if t.angle == 180.0]  # type: ignore[attr-defined]
        assert len(turned) == 1  # графа 26
        designations.add(turned[0].text)
        assert turned[0].text in _words(sheet)  # графа 2 says the same
    assert len(designations) == 1


@pytest.mark.parametrize("pid", ["2013-6", "2013-9"])
def test_sets_are_numbered_and_cells_stay_empty_without_data(pid: str) -> None:
    sheets = geomcad.solve(pid).sheets()
    for i, (_, sheet) in enumerate(sheets, 1):
        words = _words(sheet)
        assert f"Лист {i}" in words and f"Листов {len(sheets)}" in words
        assert not any("geomcad" in w for w in words)


@pytest.mark.parametrize("pid", ["2013-1", "2013-2", "2013-4", "2013-8", "2013-9"])
def test_hand_in_sheets_carry_no_audit(pid: str) -> None:
    sol = geomcad.solve(pid)
    for _, sheet in sol.sheets():
        text = " ".join(_words(sheet)).lower()
        assert not [w for w in AUDIT if w in text], pid
        assert not colours(to_svg(sheet))
    for _, sheet in review_sheets(sol):
        if sol.problem.seed:  # a table of the published values
            assert "Опубликовано" in _words(sheet)


def test_review_sheet_without_published_values() -> None:
    """2013-9 prints no values to compare, yet its errata and the solver's settings go to a
    review sheet (issue 27), never to the hand-in sheets."""
    sol = geomcad.solve("2013-9")
    assert not sol.problem.seed and sol.notes
    sheets = review_sheets(sol)
    assert [n for n, _ in sheets] == ["review"]
    text = " ".join(_words(sheets[0][1]))
    assert "rtol" in text and "seed error" in text


def test_colour_only_when_asked() -> None:
    (_, sheet), *_ = geomcad.solve("2013-6").sheets()
    assert not colours(to_svg(sheet))
    assert colours(to_svg(sheet, colour=True))


def test_sheet_table_is_checked() -> None:
    assert TitleData.from_mapping({"student": "А. Б."}).student == "А. Б."
    with pytest.raises(ParameterError, match=r"sheet\.teacher"):
        TitleData.from_mapping({"teacher": "x"})
    with pytest.raises(ParameterError, match=r"sheet\.group"):
        TitleData.from_mapping({"group": 231})
    over = TitleData(student="A").over(TitleData(student="B", checker="C"))
    assert (over.student, over.checker) == ("A", "C")


def test_build_reads_geomcad_toml_and_options(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "geomcad.toml").write_text(
        '[sheet]\nstudent = "Сидоров С.С."\norg = "МГТУ"\ndate = 2026-11-24\n', encoding="utf-8"
    )
    monkeypatch.chdir(tmp_path)
    code = main(["build", "2013-3", "--format", "svg", "--out", "o", "--checker", "Петров П.П."])
    assert code == 0
    svg = (tmp_path / "o" / "2013-3.svg").read_text(encoding="utf-8")
    for w in ("Сидоров С.С.", "МГТУ", "Петров П.П.", "24.11.26"):
        assert w in svg
    assert not (tmp_path / "o" / "2013-3-review.svg").exists()
    assert main(["build", "2013-3", "--format", "svg", "--out", "o", "--review"]) == 0
    assert (tmp_path / "o" / "2013-3-review.svg").exists()
    (tmp_path / "geomcad.toml").write_text("[sheet]\nstudnet = 1\n", encoding="utf-8")
    capsys.readouterr()
    assert main(["build", "2013-3", "--format", "svg", "--out", "p"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error:") and "studnet" in err and err.count("\n") == 1
    assert not (tmp_path / "p").exists()
