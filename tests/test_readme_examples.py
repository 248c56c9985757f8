"""The README as a newcomer reads it: its links resolve inside the repository, every command of
its "Use" block runs, its error examples are what the command prints, and each problem has a
short line (the detail is in docs/problems.md)."""

from __future__ import annotations

import itertools
import re
import shlex
from pathlib import Path

import pytest

from geomcad.cli import main

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _block_after(heading: str, lang: str) -> str:
    """The first code block (```lang) after the line that starts with ``heading``."""
    section = README.split(f"\n{heading}", 1)[1]
    return section.split(f"```{lang}\n", 1)[1].split("```", 1)[0]


def test_every_relative_link_resolves_inside_the_repository() -> None:
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README)
    relative = [ln for ln in links if not re.match(r"[a-z]+://", ln)]
    assert "docs/problems.md" in relative
    for link in relative:
        target = (ROOT / link).resolve()
        assert target.is_relative_to(ROOT), f"{link} points outside the repository"
        assert target.exists(), f"{link} does not exist"


USE = [
    ln.split("  #")[0].strip()
    for ln in _block_after("## Use", "sh").splitlines()
    if ln.startswith("geomcad ")
]


@pytest.mark.parametrize("line", USE)
def test_every_use_example_runs(
    line: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = shlex.split(line)[1:]
    if argv[0] == "build":  # into a scratch folder; SVG only (the renderers have their own tests)
        argv = [*argv[: argv.index("--out")], "--out", str(tmp_path), "--format", "svg"]
    assert main(argv) == 0, capsys.readouterr().err
    err = capsys.readouterr().err
    if argv[0] == "build":  # a build ends with its one summary line
        assert err.startswith("built ") and len(err.splitlines()) == 1, err
    else:
        assert err == ""


def test_the_error_examples_are_what_the_commands_print(capsys: pytest.CaptureFixture[str]) -> None:
    lines = _block_after("Bad input never gives a traceback", "").splitlines()
    pairs = [(a[2:], b) for a, b in itertools.pairwise(lines) if a.startswith("$ ")]
    assert pairs
    for command, shown in pairs:
        assert main(shlex.split(command)[1:]) == 2
        err = capsys.readouterr().err.rstrip("\n")
        assert err.startswith(shown.removesuffix(" …")), (command, err)


def test_each_problem_has_a_short_line() -> None:
    rows = [ln for ln in README.splitlines() if re.match(r"\| `[^`]+` \|", ln)]
    assert len(rows) >= 10
    for row in rows:
        words = len(row.split("|")[2].split())
        assert words <= 40, row


def test_what_build_writes_is_what_the_readme_says() -> None:
    """The README's count of sheets and its ID-NAME examples match the golden sheets, one per
    sheet that `geomcad build` writes (tests/test_golden.py keeps those in step with the code)."""
    # the problems' sheets (linkage-* are the example files' golden sheets)
    golden = {
        p.stem
        for p in (ROOT / "tests" / "golden").glob("*.svg")
        if not p.stem.startswith("linkage-")
    }
    said = re.search(r"`geomcad build` draws (\d+) sheets", README)
    assert said and int(said.group(1)) == len(golden)
    paragraph = README.split("`geomcad build` draws", 1)[1].split("\n\n", 1)[0]
    named = set(re.findall(r"`(\w[\w-]*-[a-z]+)`", paragraph))
    assert named and named <= golden
    assert named == {g for g in golden if not re.fullmatch(r"2013-\d|kulisa-\d+", g)}
