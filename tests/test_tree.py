"""The tests run the working tree's code, problems included, and the installed problem ids are
the ones pyproject.toml declares."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from importlib.metadata import entry_points
from pathlib import Path

import geomcad_constructions

import geomcad
from geomcad import registry

ROOT = Path(__file__).resolve().parents[1]


def test_the_library_and_the_problems_come_from_this_checkout() -> None:
    assert Path(geomcad.__file__).resolve().parent == ROOT / "geomcad"
    assert Path(geomcad_constructions.__file__).resolve().parent == ROOT / "constructions"
    problem = registry.get("2013-6")
    problem.build.resolve()  # type: ignore[attr-defined]
    build_module = sys.modules[problem.build.module]  # type: ignore[attr-defined]
    assert Path(build_module.__file__ or "").resolve().parent == ROOT / "constructions"


def test_a_plain_pytest_run_maps_the_tree_too(tmp_path: Path) -> None:
    """A fresh interpreter started elsewhere (as bare ``pytest`` may be) gets the same mapping."""
    code = (
        f"import sys; sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
        "from tree import use_working_tree; use_working_tree()\n"
        "import geomcad_constructions.p2013_6 as m, geomcad\n"
        "print(m.__file__); print(geomcad.__file__)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, check=True
    ).stdout.split()
    assert Path(out[0]).resolve() == ROOT / "constructions" / "p2013_6.py"
    assert Path(out[1]).resolve() == ROOT / "geomcad" / "__init__.py"


def test_the_installed_problem_ids_are_the_ones_pyproject_declares() -> None:
    """A new problem is registered in pyproject.toml; until the package is installed again
    (sh scripts/setup.sh test, or pip install -e .), the registry would not see it."""
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"][
        "entry-points"
    ][registry.GROUP]
    installed = {ep.name: ep.value for ep in entry_points(group=registry.GROUP)}
    assert installed == declared, "reinstall: sh scripts/setup.sh test (or pip install -e .)"
