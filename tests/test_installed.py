"""What pip installs is what the tests test (``tests/installed.py``), and what a user gets works.

- The suite imports the installed package; a child Python started in the checkout does too.
- A ``pip install .`` holds every file of the tree (its RECORD against the folders).
- The wheel built from the tree holds every file of the tree, whatever the developer installed.
- From outside: the wheel installed in a fresh virtual environment, run from an empty folder,
  solves and builds every example, makes variants of a linkage file, and prints a file's help.
"""

from __future__ import annotations

import os
import shutil
import site
import subprocess
import sys
import tomllib
import zipfile
from importlib.metadata import distribution, entry_points
from pathlib import Path

import geomcad_constructions
import pytest
from installed import PACKAGES, ROOT, editable_of_this_checkout, tree_files

import geomcad
from geomcad import documents, registry

#: What a wheel is built from: the package folders and the files that describe the package.
PROJECT_FILES = ("pyproject.toml", "setup.py", "MANIFEST.in", "README.md")
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def _installed_here(module_file: str | None) -> bool:
    """Whether a module file lies in the checkout (only an editable install puts it there)."""
    return Path(module_file or "").resolve().is_relative_to(ROOT)


def test_the_tests_import_the_installed_package() -> None:
    editable = editable_of_this_checkout()
    for module in (geomcad, geomcad_constructions):
        assert _installed_here(module.__file__) == editable, module.__file__
    problem = registry.get("2013-6")
    problem.build.resolve()  # type: ignore[attr-defined]
    build_module = sys.modules[problem.build.module]  # type: ignore[attr-defined]
    assert _installed_here(build_module.__file__) == editable


def test_a_python_started_in_the_checkout_imports_the_install_too() -> None:
    """``python3 -m geomcad`` in a test (cwd = the checkout) runs the same package as the suite."""
    out = subprocess.run(
        [sys.executable, "-c", "import geomcad; print(geomcad.__file__)"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    assert Path(out).resolve() == Path(geomcad.__file__).resolve()


@pytest.mark.parametrize("group", [registry.GROUP, documents.GROUP])
def test_the_installed_entry_points_are_the_ones_pyproject_declares(group: str) -> None:
    """A problem or file kind is registered in pyproject.toml; until the package is installed
    again (sh scripts/setup.sh test, or pip install -e .), the registry would not see it."""
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"][
        "entry-points"
    ][group]
    installed = {ep.name: ep.value for ep in entry_points(group=group)}
    assert installed == declared, "reinstall: sh scripts/setup.sh test (or pip install -e .)"


def test_the_installed_package_holds_every_file_of_the_tree() -> None:
    if editable_of_this_checkout():
        pytest.skip("an editable install reads the tree itself; the wheel test checks its files")
    record = distribution("geomcad").read_text("RECORD") or ""
    installed = {line.split(",")[0] for line in record.splitlines() if line}
    missing = sorted(set(tree_files()) - installed)
    assert not missing, f"pip install . left out {missing}"
    # a file the tree has not came from a stale build/ folder (setuptools reuses build/lib),
    # which can also hide a file the package would leave out
    ours = {n for n in installed if n.split("/")[0] in PACKAGES and "__pycache__" not in n}
    extra = sorted(ours - set(tree_files()))
    assert not extra, f"the install holds files the tree has not (rm -rf build, reinstall): {extra}"


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel of the tree as it stands, built from a copy (no stale build/ of the checkout)."""
    src = tmp_path_factory.mktemp("src")
    for folder in PACKAGES.values():
        shutil.copytree(
            folder, src / folder.name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc")
        )
    for name in PROJECT_FILES:
        shutil.copy2(ROOT / name, src / name)
    dist = tmp_path_factory.mktemp("dist")
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(dist), str(src)],
        check=True,
        capture_output=True,
        text=True,
        timeout=300,
    )
    (built,) = dist.glob("geomcad-*.whl")
    return built


def test_the_wheel_holds_every_file_of_the_tree(wheel: Path) -> None:
    names = {n for n in zipfile.ZipFile(wheel).namelist() if ".dist-info/" not in n}
    tree = set(tree_files())
    assert not tree - names, f"the wheel leaves out {sorted(tree - names)}"
    assert not names - tree, f"the wheel holds files the tree has not: {sorted(names - tree)}"


def test_a_fresh_install_works_from_an_empty_folder(wheel: Path, tmp_path: Path) -> None:
    """A new user's first commands, with the wheel in a fresh virtual environment (the
    dependencies from the running Python's, so no download) and an empty working folder."""
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python, geomcad_cmd = venv / "bin" / "python", venv / "bin" / "geomcad"
    subprocess.run(
        [python, "-m", "pip", "install", "-q", "--no-deps", "--no-index", str(wheel)],
        check=True,
        capture_output=True,
    )
    # then the dependencies: the running Python's site folders after the venv's own (so the
    # wheel's geomcad comes first; a folder named in a .pth runs none of its own .pth files)
    (own,) = (venv / "lib").glob("python*/site-packages")
    (own / "_dependencies.pth").write_text(
        "".join(f"{p}\n" for p in site.getsitepackages() if Path(p).is_dir()), encoding="utf-8"
    )
    work = tmp_path / "work"
    work.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONSAFEPATH")}
    env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"

    def run(*argv: str | Path) -> str:
        proc = subprocess.run(
            [geomcad_cmd, *map(str, argv)], cwd=work, env=env, capture_output=True, text=True
        )
        assert proc.returncode == 0, f"geomcad {' '.join(map(str, argv))}:\n{proc.stderr}"
        assert "Traceback" not in proc.stderr
        return proc.stdout

    where = subprocess.run(
        [python, "-c", "import geomcad, geomcad_constructions as c; print(geomcad.__file__)"],
        cwd=work,
        env=env,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert Path(where.strip()).is_relative_to(venv), where

    for example in EXAMPLES:
        assert run("solve", example).strip()
    run("build", *EXAMPLES, "--out", "sheets", "--format", "svg", "--jobs", "2")
    drawn = [p.stem for p in work.glob("sheets/*.svg")]
    for example in EXAMPLES:
        assert any(d == example.stem or d.startswith(example.stem + "-") for d in drawn), example
    run("build", "2013-6", "--out", "seed", "--format", "pdf,png")
    assert (work / "seed" / "2013-6.pdf").stat().st_size > 0
    run("variants", ROOT / "examples" / "slider-crank.toml", "--count", "2", "--seed", "1",
        "--out", "class", "--vary", "drive.length=0.06..0.09:0.005")  # fmt: skip
    assert (work / "class" / "answers.csv").is_file()
    assert "--set KEY=VALUE" in run("solve", ROOT / "examples" / "shaper.toml", "--help")
