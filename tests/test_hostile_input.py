"""Inputs of issue 29 that broke the command line: each gives a result or one clean ``error:``
line of about 300 characters at most, quoting at most the start of the bad value."""

from __future__ import annotations

import io
import json
import math
import re
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from geomcad import documents
from geomcad.cli import LONG_ERROR_LINE, main
from geomcad.errors import QUOTE_CHARS, ParameterError, quote
from geomcad.sheet.text import escape, lacking, parse

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def bad(argv: list[str], *words: str) -> str:
    code, out, err = run(*argv)
    assert code == 2 and out == "", (code, err[:500])
    assert err.startswith("error: ") and err.count("\n") == 1, err[:500]
    assert len(err) <= LONG_ERROR_LINE + 1, len(err)
    for w in words:
        assert w in err, err
    return err


# --- an error quotes the start of a long value ---------------------------------------------------

HUGE = "9" * 5_000_000
SPACED = "a b " * 100_000


@pytest.mark.parametrize(
    "argv",
    [
        ["solve", "2013-6", "--set", f"K={HUGE}"],
        ["solve", "2013-6", "--set", f"K={SPACED}"],
        ["solve", "2013-6", "--set", f"{HUGE}=1"],
        ["solve", HUGE],
        ["verify", "2013-6", "--measured", HUGE],
        ["verify", "2013-6", "--measured", "K=1", "--scale", SPACED],
        ["build", "2013-6", "--format", HUGE],
        ["build", "2013-6", "--student", SPACED, "--format", "svg"],
        ["animate", "2013-6", "--frames", HUGE],
        ["variants", "2013-6", "--count", "1", "--seed", "1", "--out", "v", "--vary", f"K={HUGE}"],
        ["solve", str(EXAMPLES / "four-bar.toml"), "--set", f"drive.omega='{SPACED}'"],
        ["solve", str(EXAMPLES / "four-bar.toml"), "--set", f"{HUGE}=2"],
    ],
    ids=lambda a: " ".join(x[:12] for x in a)[:60],
)
def test_a_huge_value_is_quoted_by_its_start(argv: list[str], tmp_path: Path) -> None:
    err = bad(argv)
    assert "9" * (QUOTE_CHARS + 2) not in err and "a b " * 40 not in err


def test_quote_bounds_strings_and_nesting() -> None:
    assert quote("x" * 1000).startswith("'xxx") and len(quote("x" * 1000)) <= QUOTE_CHARS + 1
    deep: list[object] = []
    node = deep
    for _ in range(5000):
        node.append([])
        node = node[0]  # type: ignore[assignment]
    assert len(quote(deep)) <= QUOTE_CHARS + 1  # no RecursionError either
    assert "x" * 61 not in str(ParameterError("x" * 1000, "y" * 1000, "why"))


# --- a character the sheet font lacks: refused, naming the field and the character -------------


@pytest.mark.parametrize(
    "option, text", [("--student", "Ivanov 😀"), ("--designation", "ТММ 💥"), ("--org", "a\tb")]
)
def test_a_title_word_the_font_cannot_letter_is_refused(
    option: str, text: str, tmp_path: Path
) -> None:
    char = lacking(text)
    bad(["build", "2013-8", "--out", str(tmp_path), "--format", "svg", option, text],
              option, f"U+{ord(char):04X}")  # fmt: skip
    assert not list(tmp_path.iterdir())


def test_a_point_name_the_font_cannot_letter_is_refused(tmp_path: Path) -> None:
    src = (EXAMPLES / "four-bar.toml").read_text(encoding="utf-8")
    f = tmp_path / "m.toml"
    f.write_text(src.replace('name = "M"', 'name = "E💥"'), encoding="utf-8")
    bad(["build", str(f), "--out", str(tmp_path / "o"), "--format", "svg"], "'E💥'", "U+1F4A5")
    assert not (tmp_path / "o").exists()


def test_a_title_word_is_plain_text_not_markup(tmp_path: Path) -> None:
    assert parse(escape("Ivan_ov^2 a_{b")) == parse("Ivan\\_ov\\^2 a\\_{b")
    assert [r.text for r in parse(escape("Ivan_ov^2 a_{b"))] == ["Ivan_ov^2 a_{b"]
    code, _, err = run("build", "2013-6", "--out", str(tmp_path), "--format", "svg",
                       "--student", "Ivan_ov a_{b", "--designation", "ТММ.01 ^2")  # fmt: skip
    assert code == 0, err
    svg = (tmp_path / "2013-6.svg").read_text(encoding="utf-8")
    assert ">Ivan_ov a_{b<" in svg
    assert svg.count(">ТММ.01 ^2<") == 2  # графы 2 and 26


# --- files: a byte-order mark, other encodings, deep nesting, infinities -------------------------


def test_a_file_with_a_byte_order_mark_is_read(tmp_path: Path) -> None:
    f = tmp_path / "bom.toml"
    f.write_bytes(b"\xef\xbb\xbf" + (EXAMPLES / "four-bar.toml").read_bytes())
    code, out, err = run("solve", str(f), "--json")
    assert code == 0, err
    assert json.loads(out)["results"]


def test_a_geomcad_toml_with_a_bom_or_not_utf8(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    cfg = tmp_path / "geomcad.toml"
    cfg.write_bytes(b'\xef\xbb\xbf[sheet]\nstudent = "Petrova"\n')
    code, _, err = run("build", "2013-6", "--out", "o", "--format", "svg")
    assert code == 0, err
    assert "Petrova" in (tmp_path / "o" / "2013-6.svg").read_text(encoding="utf-8")
    cfg.write_bytes('[sheet]\nstudent = "Петрова"\n'.encode("cp1251"))
    bad(["build", "2013-6", "--out", "o2", "--format", "svg"], "geomcad.toml", "not UTF-8")
    cfg.write_text("[sheet]\nx = " + "[" * 3000 + "]" * 3000 + "\n", encoding="utf-8")
    bad(["build", "2013-6", "--out", "o2", "--format", "svg"], "geomcad.toml")
    assert not (tmp_path / "o2").exists()


@pytest.mark.parametrize(
    "text, words",
    [
        ("title = 'x'\nv = " + "[" * 3000 + "]" * 3000 + "\n", "nested too deeply"),
        ("[" + ".".join(["a"] * 5000) + "]\n", "nested too deeply"),
        ("title = 'x'\nv = " + "9" * 5000 + "\n", "an integer of over 4300 digits"),
        ("title = 'x'\nv = " + "9" * 30 + "\n", "beyond TOML's 64 bits"),
    ],
    ids=["array-3000-deep", "header-5000-deep", "int-5000-digits", "int-30-digits"],
)
def test_deep_or_huge_toml_is_refused(text: str, words: str, tmp_path: Path) -> None:
    f = tmp_path / "x.toml"
    f.write_text(text, encoding="utf-8")
    bad(["solve", str(f)], "x.toml", words)


def test_a_deep_set_value_is_refused() -> None:
    bad(["solve", str(EXAMPLES / "four-bar.toml"), "--set", "drive.omega=" + "[" * 3000],
        "nested too deeply")  # fmt: skip


@pytest.mark.parametrize("value", ["inf", "-inf", "nan", "1e400", "1e300", "'x'", "12.5"])
@pytest.mark.parametrize("key", ["z1", "z2"])
def test_a_gear_count_that_is_not_a_whole_number(key: str, value: str, tmp_path: Path) -> None:
    src = (EXAMPLES / "gear-pair.toml").read_text(encoding="utf-8")
    f = tmp_path / "g.toml"
    f.write_text(re.sub(rf"(?m)^{key} = .*$", f"{key} = {value}", src), encoding="utf-8")
    bad(["solve", str(f)], f"gears.pair.{key}")


def test_check_integers_walks_without_recursion() -> None:
    data: dict[str, object] = {}
    node = data
    for _ in range(100_000):
        node["a"] = {}
        node = node["a"]  # type: ignore[assignment]
    with pytest.raises(ParameterError, match="nested too deeply"):
        documents.check_integers(data)
    documents.check_integers({"a": [[{"b": 2**63 - 1}]]})  # at the edge: fine


# --- variants and verify --batch ------------------------------------------------------------------

VARY = ["variants", "2013-6", "--count", "1", "--out", "v", "--vary", "K=1.2..1.6:0.05"]


@pytest.mark.parametrize(
    "extra, words",
    [
        (["--seed", "-1"], "--seed"),
        (["--seed", "1", "--vary", "H=0.1..0.3:1e-300"], "STEP"),
        (["--seed", "1", "--vary", "H=1e999999999..2e999999999"], "LO"),
        (["--seed", "1", "--vary", "H=0.1..0.3:1e-12"], "coarser STEP"),
        (["--seed", "1", "--count", "0"], "--count"),
        (["--seed", "1", "--count", "1000000000"], "--count"),
        (["--seed", "1", "--jobs", "100000"], "--jobs"),
        (["--seed", "1", "--jobs", "-3"], "--jobs"),
        (["--seed", "1", "--course", "ТММ 😀"], "--course"),
        (["--seed", "1", "--teacher", "a\nb"], "--teacher"),
    ],
)
def test_variants_arguments(
    extra: list[str], words: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    bad([*VARY, *extra], words)
    assert not (tmp_path / "v").exists()


def test_verify_batch_json_writes_json(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, _, err = run("variants", "2013-6", "--count", "2", "--seed", "3", "--out", "v",
                       "--vary", "K=1.2..1.6:0.05", "--format", "svg")  # fmt: skip
    assert code == 0, err
    answers = (tmp_path / "v" / "answers.csv").read_text(encoding="utf-8").splitlines()
    theta = float(answers[1].split(",")[2])
    (tmp_path / "class.csv").write_text(
        f"student,variant,theta_deg,l1\nIvanov,1,{theta + 0.1},\nPetrov,2,abc,\n", "utf-8"
    )
    code, out, err = run("verify", "class.csv", "--batch", "v/answers.csv", "--json")
    assert code == 1, err
    obj = json.loads(out)
    assert obj["ok"] is False and obj["students"] == "class.csv"
    first, second = obj["verdicts"]
    assert first["student"] == "Ivanov" and first["ok"] is True and first["row"] == 2
    assert math.isclose(first["measured"], theta + 0.1)
    assert math.isclose(first["exact"], theta, rel_tol=1e-3)  # the key prints 4 figures
    assert second["ok"] is None and "must be a number" in second["error"]
    assert err.splitlines()[-1].startswith("class: 2 rows")
    code, out, err = run("verify", "class.csv", "--batch", "v/answers.csv", "--json",
                         "--out", "verdicts.json")  # fmt: skip
    assert code == 1 and err == ""
    assert json.loads((tmp_path / "verdicts.json").read_text(encoding="utf-8")) == obj
    assert out.endswith("verdicts: verdicts.json\n")


@pytest.mark.parametrize("value", ["nan", "inf", "-inf"])
@pytest.mark.parametrize("key", ["drive.omega", "group.1.lengths.1"])
def test_a_set_value_that_is_not_finite_names_its_key(key: str, value: str) -> None:
    """The error names the dotted key the value was set to, not the value as a key
    ("parameter nan = 'nan'" before)."""
    argv = ["solve", str(EXAMPLES / "shaper.toml"), "--set", f"{key}={value}"]
    err = bad(argv, "must be a finite number")
    assert f"parameter {key} = '{value}'" in err, err
