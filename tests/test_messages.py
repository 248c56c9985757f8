"""The words a user reads: errors name steps as ``--trace`` does, values are kept, counts agree
in number, deviations carry no float noise, and the missing-libcairo line says it once."""

from __future__ import annotations

import ast
import math
import sys
from pathlib import Path

import pytest

import geomcad
from geomcad.cli import _dev, main
from geomcad.errors import ConstructionError

CONSTRUCTIONS = Path(__file__).resolve().parents[1] / "constructions"
ERRORS = {"ConstructionError", "NoIntersection", "ParallelLines", "DegenerateInput"}


def _problem_id(tree: ast.Module) -> str | None:
    """The id a construction module is for, from its docstring's first word (``2013-6 · …``)."""
    doc = ast.get_docstring(tree) or ""
    return doc.split(" ", 1)[0] or None


def _raised_steps(path: Path) -> list[tuple[int, ast.expr]]:
    """Every step argument of an error a module raises: (line, expression)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call):
            func = node.exc.func
            if isinstance(func, ast.Name) and func.id in ERRORS and node.exc.args:
                out.append((node.lineno, node.exc.args[0]))
    return out


def _trace_titles(pid: str) -> set[str]:
    sol = geomcad.solve(pid)
    return {st.title for st in sol.construction}


MODULES = [p for p in sorted(CONSTRUCTIONS.glob("p*.py")) if _raised_steps(p)]


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.stem)
def test_every_error_names_a_step_the_protocol_records(path: Path) -> None:
    """An error's step is written as a recorded step's ``name = op``: either ``c.step(NAME).title``
    or text that a default run's protocol contains (an f-string may prefix ``pre``, the
    frictionless run's "f=0: ", and use the module's constants)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    pid = _problem_id(tree)
    steps = _raised_steps(path)
    assert pid in geomcad.problem_ids(), f"{path.name}: docstring does not start with its id"
    titles = _trace_titles(pid)
    module = __import__(f"geomcad_constructions.{path.stem}", fromlist=["_"])
    for line, arg in steps:
        if isinstance(arg, ast.Attribute) and arg.attr == "title":
            continue  # c.step(NAME).title: the recorded step itself
        try:
            text = eval(  # the module's constants only, no call
                compile(ast.Expression(arg), str(path), "eval"), dict(vars(module)), {"pre": ""}
            )
        except NameError as exc:
            pytest.fail(f"{path.name}:{line}: cannot read the step name ({exc})")
        assert text in titles, f"{path.name}:{line}: step {text!r} is not in {pid}'s protocol"


@pytest.mark.parametrize(
    ("pid", "params"),
    [
        ("2013-6", {"e": 2.0}),
        ("2013-1", {"local": 3}),
        ("2013-7", {"d": 0.5, "direction": -1}),
        ("kulisa-23110713", {"phi_deg": 180.0}),
    ],
)
def test_a_failing_step_is_named_as_the_protocol_of_a_working_run_names_it(
    pid: str, params: dict[str, float]
) -> None:
    with pytest.raises(ConstructionError) as info:
        geomcad.solve(pid, **params)
    assert info.value.step in _trace_titles(pid)


def test_an_unknown_parameter_keeps_its_value(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["solve", "2013-6", "--set", "Z=1"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: 2013-6: parameter Z = '1': 2013-6 has no such parameter")
    with pytest.raises(geomcad.ParameterError, match=r"parameter Z = 1: "):
        geomcad.solve("2013-6", Z=1)


def test_one_measurement_is_counted_in_the_singular(capsys: pytest.CaptureFixture[str]) -> None:
    theta = geomcad.solve("2013-6").results["theta_deg"]
    assert main(["verify", "2013-6", "--measured", f"theta_deg={theta!r}"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[-1] == "2013-6: the measurement is within precision"
    assert main(["verify", "2013-6", "--measured", "theta_deg=30"]) == 1
    assert capsys.readouterr().out.splitlines()[-1] == "2013-6: the measurement is out of precision"


def test_verify_prints_no_float_noise(capsys: pytest.CaptureFixture[str]) -> None:
    r = geomcad.solve("2013-6").results
    # a reading that differs from the exact value by round-off only
    theta = math.nextafter(math.nextafter(r["theta_deg"], 0.0), 0.0)
    assert theta != r["theta_deg"]
    argv = ["verify", "2013-6", "--measured", f"theta_deg={theta}", "--measured", f"l1={r['l1']}"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "e-1" not in out and "off by 0°" in out and "off by 0 m (0 mm)" in out


@pytest.mark.parametrize(
    ("dev", "values", "text"),
    [
        (-2.22e-16, (23.47, 23.47), "0"),
        (-0.0, (1.0, 1.0), "0"),
        (0.1637, (89.5, 89.3363), "+0.164"),
        (-3.2e-7, (0.001, 0.0010003), "-3.2e-07"),
        (5.0, (0.0, 0.0), "+5"),
    ],
)
def test_deviations_are_rounded_to_the_digits_of_their_values(
    dev: float, values: tuple[float, float], text: str
) -> None:
    assert _dev(dev, *values) == text


def test_missing_libcairo_is_said_once(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setitem(sys.modules, "cairosvg", None)  # `import cairosvg` fails
    assert main(["build", "2013-8", "--out", str(tmp_path), "--format", "svg,png"]) == 2
    captured = capsys.readouterr()
    assert captured.err == (
        "error: PDF and PNG output need the cairo library: install it with "
        "`apt-get install libcairo2`; only the SVGs were written\n"
    )
    assert (tmp_path / "2013-8.svg").exists() and not (tmp_path / "2013-8.png").exists()
