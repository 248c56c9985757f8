"""Imports flow one way (README, "Layout"): a layer imports only the layers below it.

    errors, tol, units ← geom | titlefields ← construction ← kinematics / forces / structure
        ← dynamics ← linkage ← sheet ← render ← problem (with notebook) ← files
        ← (registry, documents, verify, review, reference, teach, cli)

(dynamics above kinematics: its velocity analogues come from the kinematics' sweep kernel;
``files`` is the file kinds, geomcad/files/: a kind imports the problem and the drawing layers,
and ``documents``, which reads a file and calls its kind, is above it)

The library never imports a problem module; the seed problems (constructions/) import no file
kind, and no module of constructions/ imports another that imports it back.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1] / "geomcad"
LEVEL = {
    "errors": 0,
    "interrupts": 0,
    "tol": 0,
    "units": 0,
    "titlefields": 1,  # a user's [sheet] table as data (beside geom)
    "geom": 1,
    "construction": 2,
    "kinematics": 3,
    "forces": 3,
    "structure": 3,
    "dynamics": 4,
    "linkage": 5,
    "sheet": 6,
    "render": 7,
    "problem": 8,
    "notebook": 8,  # the problem's Jupyter display: one layer with problem (each imports the other)
    "files": 9,
}
#: Layers that are one layer under two module names.
SAME = {"notebook": "problem"}
TOP = 10  # registry, documents, verify, review, reference, teach, cli, __init__, __main__
DRAWING = ("svgwrite", "cairosvg", "cairocffi")


def layer_of(path: Path) -> tuple[str, int]:
    part = path.relative_to(ROOT).parts[0].removesuffix(".py")
    return part, LEVEL.get(part, TOP)


def imports(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append(node.module)
    return out


MODULES = sorted(p for p in ROOT.rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(ROOT)))
def test_imports_flow_one_way(path: Path) -> None:
    name, level = layer_of(path)
    for mod in imports(path):
        assert not mod.startswith("geomcad_constructions"), f"{path} imports a problem module"
        if level < LEVEL["render"]:
            assert not mod.startswith(DRAWING), f"{name} (level {level}) imports {mod}"
        if mod.startswith("geomcad.") and level < TOP:
            target = mod.split(".")[1]
            t_level = LEVEL.get(target, TOP)
            same = SAME.get(target, target) == SAME.get(name, name)
            assert same or t_level < level, f"{name} imports the higher layer {mod}"


def test_the_check_sees_the_layers() -> None:
    names = {layer_of(p)[0] for p in MODULES}
    assert {"geom", "construction", "kinematics", "sheet", "render", "files"} <= names


# -- the file kinds: one home, in the library --------------------------------------------------

PROJECT = ROOT.parent
SEEDS = PROJECT / "constructions"


def test_file_kinds_live_in_the_library() -> None:
    """Every kind of the entry-point group ``geomcad.files`` is a module of geomcad/files/, and
    constructions/ holds no file kind."""
    import tomllib

    project = tomllib.loads((PROJECT / "pyproject.toml").read_text(encoding="utf-8"))
    kinds = project["project"]["entry-points"]["geomcad.files"]
    assert kinds
    for name, target in kinds.items():
        module = target.split(":")[0]
        assert module.startswith("geomcad.files."), f"kind {name} lives in {module}"
        assert (PROJECT / (module.replace(".", "/") + ".py")).is_file(), target
    assert not sorted(SEEDS.glob("file_*.py"))


SEED_MODULES = sorted(SEEDS.glob("*.py"))
#: What a seed problem may not import: the file kinds and what is above them.
ABOVE_SEEDS = ("geomcad.files", "geomcad.documents", "geomcad.cli", "geomcad.teach")


@pytest.mark.parametrize("path", SEED_MODULES, ids=lambda p: p.name)
def test_seed_problems_import_no_file_kind(path: Path) -> None:
    for mod in imports(path):
        assert not mod.startswith(ABOVE_SEEDS), f"{path.name} imports {mod}"


def seed_imports(path: Path) -> set[str]:
    """The modules of constructions/ that ``path`` imports (relative or as
    ``geomcad_constructions.x``, at load time or inside a function), by file stem."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level == 1:
                if node.module:
                    out.add(node.module.split(".")[0])
                else:  # from . import a, b
                    out |= {a.name for a in node.names}
            elif node.module and node.module.startswith("geomcad_constructions"):
                rest = node.module.split(".")[1:]
                out |= {rest[0]} if rest else {a.name for a in node.names}
        elif isinstance(node, ast.Import):
            out |= {
                a.name.split(".")[1]
                for a in node.names
                if a.name.startswith("geomcad_constructions.")
            }
    return out - {path.stem}


def import_circles(graph: dict[str, set[str]]) -> list[tuple[str, ...]]:
    """Each pair of modules of ``graph`` (name → the names it imports) that import each other,
    directly or through others: (a, b) with a < b, b reachable from a and a from b."""

    def reach(start: str) -> set[str]:
        seen: set[str] = set()
        todo = [start]
        while todo:
            for nxt in graph.get(todo.pop(), set()):
                if nxt not in seen:
                    seen.add(nxt)
                    todo.append(nxt)
        return seen

    reached = {name: reach(name) for name in graph}
    return sorted(
        (a, b) for a in graph for b in reached[a] if a < b and b in graph and a in reached[b]
    )


def test_no_import_circles_in_constructions() -> None:
    """No module of constructions/ imports another that imports it back (a spec names the
    parameters and results; the geometry module takes values and imports no spec)."""
    graph = {p.stem: seed_imports(p) for p in SEED_MODULES}
    assert {"spec_2013_1", "p2013_1"} <= graph.keys()
    assert not import_circles(graph)


def test_the_circle_check_sees_a_circle() -> None:
    assert import_circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [
        ("a", "b"),
        ("a", "c"),
        ("b", "c"),
    ]
    assert import_circles({"spec": {"geo"}, "geo": set()}) == []
