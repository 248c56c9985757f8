"""For teachers, second round (issue 30): a roster, student-facing cards, answers.xlsx, grading
tolerances and the register, a variant's own sheets; the one CSV reader (issue 29)."""

from __future__ import annotations

import csv
import io
import json
import tomllib
import zipfile
from pathlib import Path

import pytest

from geomcad.cli import main
from geomcad.errors import GeomcadError
from geomcad.teach import quantities, roster, tables

ROOT = Path(__file__).resolve().parent.parent
NAMES = ["Иванов И.И.", "Петров П.П.", "Сидорова А.А.", "Кузнецов К.К.", "Смирнова С.С."]
ROSTER = "ФИО;Группа\n" + "".join(f"{n};МТ-2{i % 2}\n" for i, n in enumerate(NAMES))
VARY = ["--vary", "K=1.2..1.6:0.05"]


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


# --- the one CSV reader -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "encoding", ["utf-8", "utf-8-sig", "cp1251", "utf-16", "utf-16-le", "utf-16-be"]
)
@pytest.mark.parametrize("sep", [";", ",", "\t"])
def test_a_roster_in_any_encoding_and_separator(tmp_path: Path, encoding: str, sep: str) -> None:
    path = tmp_path / "r.csv"
    path.write_bytes(ROSTER.replace(";", sep).encode(encoding))
    students = roster.read(path)
    assert [s.name for s in students] == NAMES
    assert [s.group for s in students] == ["МТ-20", "МТ-21"] * 2 + ["МТ-20"]
    assert [s.number for s in students] == [1, 2, 3, 4, 5]


def test_a_roster_without_header_numbers_its_students(tmp_path: Path) -> None:
    path = tmp_path / "r.csv"
    path.write_text("12;Петров П.П.;МТ-21\n3;Иванов И.И.;МТ-21\n", encoding="utf-8")
    students = roster.read(path)
    assert [(s.number, s.name) for s in students] == [(3, "Иванов И.И."), (12, "Петров П.П.")]
    assert roster.pick(students, "петров").number == 12
    assert roster.pick(students, "3").name == "Иванов И.И."
    with pytest.raises(GeomcadError, match="no student"):
        roster.pick(students, "Сидоров")
    path.write_text("№;ФИО\n1;А\n1;Б\n", encoding="utf-8")
    with pytest.raises(GeomcadError, match="number 1 is given twice"):
        roster.read(path)


def test_decimal_commas_and_semicolons_in_a_class_csv(tmp_path: Path) -> None:
    path = tmp_path / "c.csv"
    path.write_bytes("student;variant;l1\nИванов;1;0,0491\n".encode("cp1251"))
    rows = tables.read_rows(path, "students")
    assert rows == [(1, ["student", "variant", "l1"]), (2, ["Иванов", "1", "0,0491"])]
    assert tables.number(rows[1][1][2]) == 0.0491


def test_a_workbook_is_the_same_bytes_for_the_same_rows() -> None:
    data = tables.xlsx([("S", [["a", "b"], [1, 2.5]], [10.0, 12.0])])
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        assert all(i.date_time == tables.FIXED_DATE for i in z.infolist())
        core = z.read("docProps/core.xml").decode()
    assert "1980-01-01T00:00:00Z" in core and "2026" not in core


# --- a class of five --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def klass(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Five variants of 2013-6 for a roster of five (SVG cards)."""
    out = tmp_path_factory.mktemp("class")
    path = out.parent / "roster.csv"
    path.write_bytes(ROSTER.encode("cp1251"))
    code = main(["variants", "2013-6", "--students", str(path), "--seed", "1", "--out",
                 str(out / "v"), *VARY, "--format", "svg", "--teacher", "Петрова"])  # fmt: skip
    assert code == 0
    return out


def test_five_names_give_five_cards_with_one_name_each(klass: Path) -> None:
    v = klass / "v"
    cards = sorted(v.glob("card-*.svg"))
    schemes: set[str] = set()
    assert [c.name for c in cards] == [f"card-0{i}.svg" for i in range(1, 6)]
    for card, name in zip(cards, NAMES, strict=True):
        text = card.read_text(encoding="utf-8")
        assert [n for n in NAMES if n in text] == [name]
        # student-facing: no seed, no solver checks, symbols and Russian units
        for word in ("seed", "H_check", "K_check", "H\\_check", "Determine", "slider stroke"):
            assert word not in text
        assert "ход ползуна" in text and ">м<" in text
        # the scheme with its letters, the same on every card (not the variant's answer)
        assert "Схема механизма (без масштаба)" in text and ">C<" in text and ">B<" in text
        link = text.index('id="layer-link"')
        schemes.add(text[link : text.index("</g>", link)])
    assert len(schemes) == 1
    rows = list(csv.DictReader(io.StringIO((v / "answers.csv").read_text(encoding="utf-8"))))
    assert [r["student"] for r in rows] == NAMES
    assert "H_check" not in rows[0] and "l1" in rows[0]
    book = tables.read_xlsx_rows(v / "answers.xlsx")
    assert book[0][:3] == ["Вариант", "Студент", "Группа"] and "l1, м" in book[0]
    assert [r[1] for r in book[1:]] == NAMES
    col = book[0].index("l1, м")
    assert [r[col] for r in book[1:]] == [float(r["l1"]) for r in rows]
    spec = json.loads((v / "variant-03.json").read_text(encoding="utf-8"))
    assert spec["sheet"] == {"student": NAMES[2], "group": "МТ-20", "checker": "Петрова"}


@pytest.mark.parametrize("which", ["3", "сидорова"])
def test_only_reissues_one_card_byte_for_byte(
    klass: Path, capsys: pytest.CaptureFixture[str], which: str
) -> None:
    again = klass / f"again-{which}"
    code, _, _ = run(capsys, "variants", "2013-6", "--students", str(klass.parent / "roster.csv"),
                       "--seed", "1", "--out", str(again), *VARY, "--format", "svg",
                       "--teacher", "Петрова", "--only", which)  # fmt: skip
    assert code == 0
    assert sorted(p.name for p in again.iterdir()) == ["card-03.svg", "variant-03.json"]
    for name in ("card-03.svg", "variant-03.json"):
        assert (again / name).read_bytes() == (klass / "v" / name).read_bytes()


def test_only_names_a_variant_that_exists(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(capsys, "variants", "2013-6", "--count", "2", "--seed", "1", "--out",
                         str(tmp_path), *VARY, "--only", "3")  # fmt: skip
    assert code == 2 and err.startswith("error:") and "--only" in err
    assert not list(tmp_path.iterdir())


# --- grading ----------------------------------------------------------------------------------


def _class_csv(klass: Path, factor: float) -> Path:
    rows = list(csv.DictReader(io.StringIO((klass / "v" / "answers.csv").read_text("utf-8"))))
    lines = ["student;variant;l1;theta_deg"]
    for i, r in enumerate(rows):
        l1 = float(r["l1"]) * (factor if i == 1 else 1.0)
        cells = f"{l1:.6f};{r['theta_deg']}".replace(".", ",")
        lines.append(f"{r['student']};{r['variant']};{cells}")
    path = klass / f"class-{factor}.csv"
    path.write_bytes(("\n".join(lines) + "\n").encode("cp1251"))
    return path


@pytest.mark.parametrize("tol, code", [("2%", 1), ("5%", 0), ("l1=5%", 0), ("l1=2%", 1)])
def test_three_percent_off_fails_at_2_and_passes_at_5(
    klass: Path, capsys: pytest.CaptureFixture[str], tol: str, code: int
) -> None:
    grades = klass / f"grades-{tol.replace('%', 'pc')}.xlsx"
    got, out, _ = run(capsys, "verify", "--batch", str(klass / "v" / "answers.csv"),
                      str(_class_csv(klass, 1.03)), "--tol", tol, "--out", str(grades))  # fmt: skip
    assert got == code and f"register: {grades}" in out
    book = tables.read_xlsx_rows(grades)
    head = book[0]
    assert head[:3] == ["Студент", "Группа", "Вариант"] and "Оценка" in head
    ok, dev = head.index("l1: ✓/✗"), head.index("l1: откл., %")
    assert [r[0] for r in book[1:]] == NAMES
    assert book[2][ok] == ("✗" if code else "✓") and abs(book[2][dev] - 3.0) < 0.01
    assert all(r[ok] == "✓" for i, r in enumerate(book[1:]) if i != 1)
    assert book[1][head.index("Верно")] == "2/2" and book[1][head.index("Оценка")] is None


def test_the_default_tolerance_and_a_register_csv(
    klass: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    grades = klass / "grades.csv"
    code, _, _ = run(capsys, "verify", "--batch", str(klass / "v" / "answers.csv"),
                     str(_class_csv(klass, 1.0)), "--out", str(grades))  # fmt: skip
    assert code == 0
    rows = list(csv.reader(io.StringIO(grades.read_text(encoding="utf-8"))))
    assert rows[0][0] == "Студент" and [r[0] for r in rows[1:]] == NAMES


@pytest.mark.parametrize("tol", ["2", "x%", "0%", "150%", "2 kg"])
def test_a_bad_tolerance_is_one_error_line(
    klass: Path, capsys: pytest.CaptureFixture[str], tol: str
) -> None:
    code, out, err = run(capsys, "verify", "--batch", str(klass / "v" / "answers.csv"),
                         str(_class_csv(klass, 1.0)), "--tol", tol)  # fmt: skip
    assert code == 2 and out == "" and err.startswith("error:") and "--tol" in err
    assert len(err.splitlines()) == 1


def test_one_scale_per_row_for_mm_and_si_lengths(klass: Path) -> None:
    """l1 in metres and O1B1 in sheet mm are judged at the same k_l: the row's scale column."""
    from geomcad.teach import batch

    rows = list(csv.DictReader(io.StringIO((klass / "v" / "answers.csv").read_text("utf-8"))))
    o1b1 = float(rows[0]["O1B1"])
    path = klass / "scaled.csv"
    path.write_text(f"student,variant,scale,l1,O1B1_mm\nA,1,1:4,{rows[0]['l1']},"
                    f"{o1b1 / 0.004:.2f}\n", encoding="utf-8")  # fmt: skip
    graded = batch.grade(str(klass / "v" / "answers.csv"), str(path))
    scales = {ln["name"]: float(ln["precision"]) for ln in graded.lines}
    assert scales == {"l1": pytest.approx(0.5 * 0.004), "O1B1_mm": pytest.approx(0.5 * 0.004)}
    assert graded.ok


# --- a variant's own sheets -------------------------------------------------------------------


def test_build_with_set_draws_the_variant(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, _ = run(capsys, "build", "2013-6", "--set", "K=1.4", "--format", "svg",
                       "--out", str(tmp_path))  # fmt: skip
    assert code == 0
    sheet = (tmp_path / "2013-6.svg").read_text(encoding="utf-8")
    assert ">1,4<" in sheet and ">1,3<" not in sheet  # the data table's K


def test_a_variant_file_builds_with_its_student(
    klass: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _ = run(capsys, "build", str(klass / "v" / "variant-02.json"), "--format", "svg",
                       "--out", str(tmp_path))  # fmt: skip
    assert code == 0 and str(tmp_path / "variant-02.svg") in out
    sheet = (tmp_path / "variant-02.svg").read_text(encoding="utf-8")
    assert NAMES[1] in sheet and "Петрова" in sheet


def test_build_set_on_no_ids_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "build", "--set", "K=1.4")
    assert code == 2 and err.startswith("error:") and "--set" in err


# --- a linkage file's card --------------------------------------------------------------------


def test_a_linkage_files_data_are_named_quantities() -> None:
    with open(ROOT / "examples" / "sixbar-2013-6.toml", "rb") as f:
        data = tomllib.load(f)
    rows = quantities.linkage_rows(data, "ru")
    text = " ".join(" ".join(r) for r in rows)
    for key in ("drive.", "group.", "links.", "load.", "omega", "lengths", "="):
        assert key not in text
    sym = {r[1]: (r[2], r[3]) for r in rows}
    assert sym["ω_{1}"] == ("10", "с^{-1}") and sym["F_{пс}"] == ("2000", "Н")
    assert sym["l_{O1A}"][0].startswith("0,0641") and sym["m_{5}"] == ("20", "кг")
    assert sym["δ"] == ("0,05", "")
    en = {r[1]: r for r in quantities.linkage_rows(data, "en")}
    assert en["F_{r}"][2] == "2000" and en["ω_{1}"][3] == "s^{-1}"
    assert en["ω_{1}"][0] == "crank, clockwise"


def test_a_class_csv_may_name_students_without_their_variant(
    klass: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rows = list(csv.DictReader(io.StringIO((klass / "v" / "answers.csv").read_text("utf-8"))))
    path = klass / "by-name.csv"
    path.write_text("student;l1\n" + "".join(f"{r['student']};{r['l1']}\n" for r in rows[::-1])
                    + "Никто;0,1\n", encoding="utf-8")  # fmt: skip
    code, verdicts, _ = run(capsys, "verify", "--batch", str(klass / "v" / "answers.csv"),
                            str(path))  # fmt: skip
    got = {r["student"]: r for r in csv.DictReader(io.StringIO(verdicts))}
    assert code == 1 and all(got[n]["ok"] == "yes" for n in NAMES)
    assert got[NAMES[0]]["variant"] == "1" and "no student of that name" in got["Никто"]["error"]
    meta = json.loads((klass / "v" / "answers.json").read_text(encoding="utf-8"))
    assert [v["student"] for v in meta["variants"]] == NAMES


@pytest.mark.parametrize("name", ["cam-translating-roller.toml", "gear-pair.toml"])
def test_cam_and_gear_files_data_are_named_quantities(name: str) -> None:
    with open(ROOT / "examples" / name, "rb") as f:
        data = tomllib.load(f)
    for lang in ("ru", "en"):
        rows = quantities.file_rows(data, lang)
        text = " ".join(" ".join(r) for r in rows)
        assert "cam." not in text and "gears." not in text and "\\_" not in text
        assert all(r[0] for r in rows)  # every quantity has its words
    sym = {r[1]: r for r in quantities.file_rows(data, "ru")}
    if name.startswith("cam"):
        assert sym["H"][2] == "0,03" and sym["φ_{1}"][0].startswith("фаза 1: подъём")
    else:
        assert sym["z_{1}"][2] == "12" and sym["m"][3] == "м"
