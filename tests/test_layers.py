"""Imports flow one way (DESIGN.md): a layer imports only the layers below it.

    errors, tol, units ← geom ← construction ← kinematics / forces / structure ← dynamics
        ← linkage ← sheet ← render ← (problem, registry, documents, verify, cli)

(dynamics above kinematics: its velocity analogues come from the kinematics' sweep kernel)

and the library never imports a problem module.
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
    "geom": 1,
    "construction": 2,
    "kinematics": 3,
    "forces": 3,
    "structure": 3,
    "dynamics": 4,
    "linkage": 5,
    "sheet": 6,
    "render": 7,
}
TOP = 8  # problem, registry, draw, verify, cli, __init__, __main__
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
            assert target == name or t_level < level, f"{name} imports the higher layer {mod}"


def test_the_check_sees_the_layers() -> None:
    names = {layer_of(p)[0] for p in MODULES}
    assert {"geom", "construction", "kinematics", "sheet", "render"} <= names
