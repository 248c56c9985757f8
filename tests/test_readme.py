"""The README's two commands are exactly what CI runs."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def commands(text: str) -> list[str]:
    return [ln.strip() for ln in text.splitlines() if re.match(r"\s*sh scripts/setup\.sh", ln)]


def test_ci_runs_the_readme_commands_as_written() -> None:
    readme = commands((ROOT / "README.md").read_text(encoding="utf-8"))
    ci = commands((ROOT / ".ci" / "run").read_text(encoding="utf-8"))
    assert len(readme) == 2
    assert ci == readme


def test_readme_lists_every_problem_id() -> None:
    import geomcad

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    for pid in geomcad.problem_ids():
        assert f"`{pid}`" in text
