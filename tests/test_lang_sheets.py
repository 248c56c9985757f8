"""English sheets (issue 18): ``--lang en`` draws every sheet in English, with an ISO 7200 title
block, ISO 128 lines and a decimal point; Russian (GOST 2.104, decimal comma) stays the default.

The walk over every problem id and example file holds a sheet to "no Cyrillic letter" once every
module that draws it is clean (absent from ``tests/lang_baseline.json``), so it tightens by
itself as the sheet modules are converted.
"""

from __future__ import annotations

import io
import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import ezdxf
import pytest
from layout import block_part, layout_problems

import geomcad
from geomcad import documents, registry
from geomcad.cli import main
from geomcad.render import to_svg
from geomcad.render.dxf import ISO_LINETYPE_NAMES, lineweight, to_dxf
from geomcad.render.svg import main_line
from geomcad.sheet import TitleBlock, fmt_number
from geomcad.sheet.frame import (
    ISO_FIELDS,
    ISO_HEIGHT,
    ISO_WIDTH,
    MARGIN,
    fill_title_blocks,
    new_sheet,
)
from geomcad.sheet.lang import current, language
from geomcad.sheet.model import Polyline, TextItem
from geomcad.sheet.scale import Scale, ScaleStyle
from geomcad.sheet.style import ISO_DASHDOT, fit_open
from geomcad.sheet.titleblock import TitleData

ROOT = Path(__file__).resolve().parent.parent
CYRILLIC = re.compile("[\u0400-\u04ff]")
#: A decimal comma between digits: a Russian number on an English sheet.
DECIMAL_COMMA = re.compile(r"\d,\d")
BASELINE: dict[str, int] = json.loads((ROOT / "tests" / "lang_baseline.json").read_text())
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))

#: The modules that draw each problem's sheets, besides geomcad/sheet and geomcad/render.
PROBLEM_MODULES = {
    "2013-1": ["sheets_2013_1"],
    "2013-2": ["sheets_2013_2"],
    "2013-3": ["sheets_2013_3"],
    "2013-4": ["sheets_2013_4"],
    "2013-5": ["sheets_2013_5"],
    "2013-6": ["sheets_2013_6", "sheets_2013_6_kin"],
    "2013-7": ["sheets_2013_7"],
    "2013-8": ["sheets_2013_8"],
    "2013-9": ["sheets_2013_9"],
    "kulisa-23110713": ["sheets_kulisa"],
}
#: The modules that draw each kind of example file (by its marking table; none: a linkage file).
FILE_MODULES = {
    "cam": ["geomcad/files/cam_sheets.py"],
    "gears": ["geomcad/files/gears_sheets.py"],
    "": ["geomcad/sheet/linkage.py", "geomcad/sheet/linkage_forces.py"],
}
#: Drawing code every sheet goes through (its frame, scales, graphs, plans, text).
COMMON = sorted(
    p.relative_to(ROOT).as_posix()
    for p in [
        *(ROOT / "geomcad" / "sheet").glob("*.py"),
        *(ROOT / "geomcad" / "render").glob("*.py"),
    ]
    if not p.name.startswith("linkage")
)


def _kind(path: Path) -> str:
    import tomllib

    data = tomllib.loads(path.read_text(encoding="utf-8"))
    return next((k for k in ("cam", "gears") if k in data), "")


def _targets() -> list[tuple[str, list[str]]]:
    out = [(pid, [f"constructions/{m}.py" for m in mods]) for pid, mods in PROBLEM_MODULES.items()]
    out += [(p.relative_to(ROOT).as_posix(), FILE_MODULES[_kind(p)]) for p in EXAMPLES]
    return out


def test_every_problem_and_example_is_walked() -> None:
    assert set(PROBLEM_MODULES) == set(registry.problem_ids())
    assert len(EXAMPLES) >= 10


@pytest.mark.parametrize(("target", "modules"), _targets(), ids=lambda t: str(t))
def test_english_sheets_hold_no_russian(
    target: str, modules: list[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every sheet drawn in English has no Cyrillic letter and passes the layout checker, once
    the modules that draw it hold no Russian literal."""
    left = [m for m in [*COMMON, *modules] if BASELINE.get(m, 0)]
    if left:
        pytest.skip(f"not converted yet: {', '.join(left)}")
    monkeypatch.chdir(ROOT)
    sol = documents.solve(target) if documents.is_file_id(target) else geomcad.solve(target)
    with language("en"):
        sheets = sol.sheets(TitleData(student="I. Ivanov", org="VSTU", date="24.11.2026"))
    assert sheets
    for name, sheet in sheets:
        russian = [t.text for t in sheet.texts() if CYRILLIC.search(t.text)]
        assert not russian, (target, name, russian[:5])
        _form, drawn = block_part(sheet)
        commas = [t.text for t in drawn if isinstance(t, TextItem) and DECIMAL_COMMA.search(t.text)]
        assert not commas, (target, name, commas[:5])
        assert sheet.lang == "en"
        assert not layout_problems(sheet), (target, name, layout_problems(sheet))
        assert "Identification number" in {t.text for t in sheet.texts()}


# -- the ISO 7200 title block, read back from the SVG ----------------------------------------------


def _svg_texts(svg: str) -> list[tuple[str, float, float]]:
    """Every text of an SVG as (text, x, y) of its first run's baseline start."""
    ns = {"s": "http://www.w3.org/2000/svg"}
    out = []
    for el in ET.fromstring(svg.split("?>", 1)[1]).iter("{http://www.w3.org/2000/svg}text"):
        spans = el.findall("s:tspan", ns)
        text = "".join(s.text or "" for s in spans) or (el.text or "")
        first = spans[0] if spans else el
        out.append((text, float(first.get("x", "0")), float(first.get("y", "0"))))
    return out


def test_iso_7200_block_fields_read_back_from_the_svg() -> None:
    data = TitleData(
        student="I. Ivanov",
        checker="P. Petrov",
        approver="S. Sidorov",
        org="VSTU",
        group="TM-231",
        date="24.11.2026",
        revision="A",
        stage="Released",
    )
    with language("en"):
        tb = TitleBlock(title="Velocity plan of the six-bar", designation="TMM.01", scale="1:5")
        sheet, _ = new_sheet("A3", tb)
    assert tb.lang == "en"
    fill_title_blocks([sheet], data)
    texts = _svg_texts(to_svg(sheet))
    assert not any(CYRILLIC.search(t) for t, _, _ in texts)
    x1, y1 = sheet.width - MARGIN, sheet.height - MARGIN
    bx, by = x1 - ISO_WIDTH, y1
    assert ISO_WIDTH <= 180.0 and ISO_HEIGHT <= 55.0  # ISO 7200; inside form 1's room

    def in_cell(key: str) -> list[str]:
        (_, xa, ya, xb, yb) = next(f for f in ISO_FIELDS if f[0] == key)
        return [
            t for t, x, y in texts if bx + xa <= x <= bx + xb and by - yb <= y <= by - ya + 0.01
        ]

    expected = {
        "iso_owner": ["Legal owner", "VSTU", "TM-231"],
        "iso_id": ["Identification number", "TMM.01"],
        "iso_rev": ["Rev.", "A"],
        "iso_date": ["Date of issue", "24.11.2026"],
        "iso_sheet": ["Sheet", "1/1"],
        "iso_type": ["Document type", "Coursework drawing"],
        "iso_status": ["Document status", "Released"],
        "iso_creator": ["Created by", "I. Ivanov"],
        "iso_approver": ["Approved by", "S. Sidorov"],
        "iso_techref": ["Technical reference", "P. Petrov"],
        "iso_lang": ["Lang.", "en"],
        "iso_scale": ["Scale", "1:5"],
        "iso_format": ["Format", "A3"],
    }
    for key, words in expected.items():
        assert in_cell(key) == words, key
    title = " ".join(in_cell("iso_title")[1:])
    assert in_cell("iso_title")[0] == "Title" and title == "Velocity plan of the six-bar"
    # no GOST form on an English sheet: no графа 26, no "Copied" under the frame
    words = [t for t, _, _ in texts]
    assert words.count("TMM.01") == 1 and "Copied" not in words and "Format A3" not in words
    assert all(y <= y1 for _, _, y in texts)


def test_russian_stage_letter_stays_off_an_english_block() -> None:
    with language("en"):
        sheet, _ = new_sheet("A4", TitleBlock(title="Task", designation="X"))
    fill_title_blocks([sheet], TitleData())  # the default stage is the Russian "У"
    assert not [t.text for t in sheet.texts() if CYRILLIC.search(t.text)]


# -- numbers, scales and lines follow the language being drawn -------------------------------------


def test_decimal_sign_and_units_follow_the_language() -> None:
    assert current() == "ru"
    k = Scale(0.0025, "l")
    assert fmt_number(0.25) == "0,25" and k.ratio_text() == "1:2,5"
    assert k.label() == "μ_l = 0,0025 м/мм"
    with language("en"):
        assert fmt_number(0.25) == "0.25" and k.ratio_text() == "1:2.5"
        assert k.label() == "μ_l = 0.0025 m/mm"
        assert Scale(2.0, "F").label(ScaleStyle(inverse=True)) == "μ_F = 0.5 mm/N"
        assert fmt_number(0.25, "ru") == "0,25"


def test_english_lines_are_iso_128() -> None:
    """ISO 128-20 elements (long dash 24d, space 3d, dot 0.5d at d = 0.35) on an English sheet."""
    gost = fit_open("dashdot", 100.0)
    with language("en"):
        iso = fit_open("dashdot", 100.0)
    assert gost is not None and iso is not None
    lo, target, hi, space, dot = ISO_DASHDOT
    assert iso.array[1:] == (space, dot, space)
    assert lo <= iso.array[0] <= hi and abs(iso.array[0] - target) < 0.2 * target
    assert iso.array != gost.array


def test_english_dxf_has_iso_linetypes_and_narrow_lines() -> None:
    """The DXF of an English sheet: ISO 128-20 linetypes, narrow lines at half the main line."""
    with language("en"):
        sheet, _ = new_sheet("A3", TitleBlock(title="T", designation="X"))
        line = Polyline(((30.0, 30.0), (130.0, 30.0)), "centre", dash=fit_open("dashdot", 100.0))
    sheet.add(line)
    doc = ezdxf.read(io.StringIO(to_dxf(sheet).decode("utf-8")))
    names = {lt.dxf.name for lt in doc.linetypes}
    assert set(ISO_LINETYPE_NAMES.values()) <= names and "GOST_DASHDOT" not in names
    centre = doc.layers.get("centre")
    assert centre.dxf.linetype == "ISO128_04"
    assert centre.dxf.lineweight == lineweight(main_line("A3") / 2.0)


def test_the_command_line_knows_every_language() -> None:
    from geomcad import cli
    from geomcad.sheet.lang import LANGS

    assert cli.LANGS == LANGS


def test_problem_titles_in_both_languages() -> None:
    for pid in registry.problem_ids():
        p = registry.get(pid)
        assert registry.title(p, "en") == p.title
        ru = registry.title(p, "ru")
        assert ru != p.title and CYRILLIC.search(ru), pid


# -- the command line ------------------------------------------------------------------------------


def _run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_lang_option_and_config(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = _run(capsys, "build", "2013-3", "--lang", "de", "--out", "o")
    assert code == 2 and not out and err.count("\n") == 1 and err.startswith("error:")
    assert "--lang" in err and "'de'" in err
    code, out, err = _run(capsys, "animate", "2013-6", "--lang", "de", "--out", "o")
    assert code == 2 and "--lang" in err and err.count("\n") == 1
    (tmp_path / "geomcad.toml").write_text('[sheet]\nlang = "de"\n')
    code, out, err = _run(capsys, "build", "2013-3", "--format", "svg", "--out", "o")
    assert code == 2 and "sheet.lang" in err and err.count("\n") == 1
    assert not (tmp_path / "o").exists()
    (tmp_path / "geomcad.toml").write_text('[sheet]\nlang = "en"\n')
    code, out, err = _run(capsys, "build", "2013-3", "--format", "svg", "--out", "en")
    assert code == 0, err
    assert "Identification number" in (tmp_path / "en" / "2013-3.svg").read_text()
    # the option wins over the file, and the workers of --jobs draw in it too
    code, out, err = _run(capsys, "build", "2013-3", "2013-4", "--lang", "ru", "--jobs", "2",
                          "--format", "svg", "--out", "ru")  # fmt: skip
    assert code == 0, err
    svg = (tmp_path / "ru" / "2013-4.svg").read_text()
    assert "Масштаб" in svg and "Identification number" not in svg
    # a cam or gear file's own [sheet] table may set it too, and is checked when it is read
    text = (ROOT / "examples" / "planetary.toml").read_text(encoding="utf-8")
    (tmp_path / "p.toml").write_text(text + '\n[sheet]\nlang = "fr"\n', encoding="utf-8")
    code, out, err = _run(capsys, "build", "p.toml", "--lang", "en", "--out", "p")
    assert code == 2 and "sheet.lang" in err and err.count("\n") == 1
    (tmp_path / "p.toml").write_text(text + '\n[sheet]\nlang = "en"\n', encoding="utf-8")
    (tmp_path / "geomcad.toml").unlink()
    code, out, err = _run(capsys, "build", "p.toml", "--format", "svg", "--out", "p")
    assert code == 0, err
    assert "Planetary gear train design" in (tmp_path / "p" / "p.svg").read_text()
