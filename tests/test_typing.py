"""Problems are typed by their model: ``Problem[D]``, ``Build[D]``, ``Solution[D]``.

- mypy reads ``sol.data`` of a ``Solution[Model]`` as a ``Model``: a wrong attribute, or a sheet
  function of another model wired to a problem, is an error (mypy's API on a small snippet).
- ``geomcad_constructions.wiring`` hands every problem's build and sheet functions to mypy
  through ``dataclasses.replace``; here: they are the very functions the lazy references name,
  for every registered problem and file kind.
"""

from __future__ import annotations

import re
import textwrap
from importlib.metadata import entry_points
from pathlib import Path
from typing import Any

import pytest
from geomcad_constructions import wiring

from geomcad import documents, registry
from geomcad.files import wiring as file_wiring
from geomcad.problem import Problem, _Lazy

ROOT = Path(__file__).resolve().parents[1]
FIELDS = ("build", "draw", "motion", "scales")

SNIPPET = textwrap.dedent(
    """\
    from collections.abc import Mapping
    from dataclasses import dataclass

    from geomcad.problem import Build, ParamValue, Problem, Solution


    @dataclass
    class Model:
        stroke: float


    def build(p: Mapping[str, ParamValue]) -> Build[Model]:
        raise NotImplementedError


    def stroke(sol: Solution[Model]) -> float:
        return sol.data.stroke


    def misspelt(sol: Solution[Model]) -> float:
        return float(sol.data.strok)  # expect: attr-defined


    def other(sol: Solution[int]) -> list[tuple[str, object]]:
        return []


    PROBLEM: Problem[Model] = Problem(
        id="x", title="x", params=(), results=(), seed={}, build=build,
        draw=other,  # expect: arg-type
    )
    """
)


def _wiring_of(spec: Problem[Any], wired: Problem[Any]) -> None:
    for name in FIELDS:
        ref, function = getattr(spec, name), getattr(wired, name)
        target = ref.resolve() if isinstance(ref, _Lazy) else ref
        assert target is function, f"{spec.id}: {name} is {ref!r}, the wiring has {function!r}"


def test_mypy_reads_the_model_of_a_typed_solution(tmp_path: Path) -> None:
    api = pytest.importorskip("mypy.api")
    snippet = tmp_path / "snippet.py"
    snippet.write_text(SNIPPET, encoding="utf-8")
    # only the snippet and the installed geomcad.problem are analysed: the rest is skipped
    # (Any), ~3 s; geomcad.problem is found where it is installed (py.typed), as a user's is
    config = tmp_path / "mypy.ini"
    config.write_text(
        "[mypy]\nstrict = True\nfollow_imports = skip\n"
        "[mypy-geomcad.problem]\nfollow_imports = silent\n",
        encoding="utf-8",
    )
    out, err, _ = api.run(
        [
            "--config-file",
            str(config),
            "--no-error-summary",
            "--cache-dir",
            str(tmp_path / "cache"),
            str(snippet),
        ]
    )
    assert not err
    found = {
        (int(m[1]), m[2])
        for m in re.finditer(r"^.*snippet\.py:(\d+): error: .*\[([\w-]+)\]$", out, re.M)
    }
    expected = {
        (no, m[1])
        for no, line in enumerate(SNIPPET.splitlines(), 1)
        if (m := re.search(r"# expect: ([\w-]+)", line))
    }
    # no other error: stroke() returns sol.data.stroke, which strict mode would refuse as Any
    assert found == expected, out


def test_the_wiring_is_the_registered_problems() -> None:
    wired = wiring.wired()
    assert [p.id for p in wired] == registry.problem_ids()
    for p in wired:
        _wiring_of(registry.get(p.id), p)


@pytest.mark.parametrize(
    ("kind", "example"), [("cam", "cam-flat.toml"), ("gears", "gear-pair.toml")]
)
def test_the_wiring_of_the_file_kinds(kind: str, example: str) -> None:
    assert {ep.name for ep in entry_points(group=documents.GROUP)} == {"cam", "gears"}
    problem = documents.load(str(ROOT / "examples" / example))
    _wiring_of(problem, getattr(file_wiring, kind)(problem))
