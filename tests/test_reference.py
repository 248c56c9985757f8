"""The reference a user reads: docs/problems.md is what the generator makes of the specs, and
``params``, ``solve ID --help``, ``verify --help``, ``--help`` and ``--version`` say what they
promise. Listing problems loads no construction code."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

import geomcad
from geomcad import reference, registry
from geomcad.cli import main

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "problems.md"


def test_docs_problems_md_is_what_the_generator_writes() -> None:
    assert DOC.read_text(encoding="utf-8") == reference.registered_markdown(), (
        f"docs/problems.md is out of date: run {reference.REGENERATE}"
    )


def test_docs_problems_md_names_every_parameter_and_result() -> None:
    text = DOC.read_text(encoding="utf-8")
    for pid in geomcad.problem_ids():
        problem = registry.get(pid)
        assert f"## {pid} · {problem.title}" in text
        for name in [p.name for p in problem.params] + [r.name for r in problem.results]:
            assert f"| `{name}` |" in text, (pid, name)


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_params_lists_units_defaults_domains_and_choices(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out, err = run(capsys, "params", "2013-2")
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert lines[0].startswith("2013-2 · Cam profile")
    row = next(ln for ln in lines if ln.split()[:1] == ["n_div"])
    assert row.split()[:3] == ["n_div", "4", "—"] and "whole number, ≥ 1, ≤ 360" in row
    row = next(ln for ln in lines if ln.split()[:1] == ["phi_rise_deg"])
    assert row.split()[:3] == ["phi_rise_deg", "180", "°"] and "> 0, ≤ 360" in row
    assert "one of: flat, knife, roller" in out
    assert any(ln.split()[:3] == ["r", "m", "k_l"] for ln in lines)  # a result, drawn at k_l


def test_params_json(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "params", "2013-5", "--json")
    data = json.loads(out)
    z4 = next(p for p in data["params"] if p["name"] == "z4")
    assert code == 0 and z4["default"] is None and z4["optional"] and z4["ge"] == 1
    assert [r["name"] for r in data["results"]][:2] == ["W", "z4"]


def test_an_optional_parameter_is_listed_as_derived(capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = run(capsys, "params", "2013-5")
    assert next(ln for ln in out.splitlines() if ln.split()[:1] == ["z4"]).split()[1] == "derived"


def test_solve_help_lists_the_problems_parameters(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "solve", "2013-6", "--set", "K=1.4", "--help")
    assert code == 0
    assert "usage: geomcad solve" in out and "parameters of 2013-6" in out
    row = next(ln for ln in out.splitlines() if ln.split()[:1] == ["K"])
    assert row.split()[:4] == ["K", "1.3", "—", ">"]


def test_solve_help_of_an_unknown_id_says_so(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "solve", "nope", "--help")
    assert code == 0 and "unknown problem id 'nope'" in out


def test_verify_help_states_precision_and_exit_statuses(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out, _ = run(capsys, "verify", "--help")
    assert code == 0
    for words in ("0.5 mm", "0.5°", "0.5 %", "exit status: 0", "1 one or more", "2 bad input"):
        assert words in out
    _, out, _ = run(capsys, "verify", "2013-6", "--help")
    assert "results of 2013-6" in out and "O1B1" in out


def test_top_level_help_has_examples_and_version(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "--help")
    assert code == 0 and "examples:" in out and "geomcad params 2013-6" in out
    assert "usage: geomcad [-h] [--version]" in out
    code, out, _ = run(capsys, "--version")
    assert code == 0 and out == f"geomcad {geomcad.__version__}\n"


def test_id_is_written_the_same_in_every_subcommand(capsys: pytest.CaptureFixture[str]) -> None:
    for command in ("params", "solve", "build", "verify"):
        _, out, _ = run(capsys, command, "--help")
        usage = out.split("\n\n")[0]
        assert "ID" in usage and " id" not in usage, usage


def test_listing_every_problem_imports_no_construction_code() -> None:
    """``geomcad list`` and ``--help`` read the light spec modules only (bench/bench_cli.py
    times them)."""
    code = (
        "import sys\n"
        "from geomcad.cli import main\n"
        "from geomcad import registry\n"
        "main(['list'])\n"
        "main(['solve', '2013-6', '--help'])\n"
        "p = registry.get('2013-6')\n"
        "heavy = sorted(m for m in sys.modules if m.split('.')[0] in "
        "('numpy', 'scipy', 'networkx', 'shapely', 'svgwrite'))\n"
        "loaded = [m for m in sys.modules if m.startswith('geomcad_constructions.p')]\n"
        "print(heavy, loaded, file=sys.stderr)\n"
        "assert not heavy and not loaded\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, cwd=ROOT
    )
    assert proc.returncode == 0, proc.stderr


def test_the_registry_still_gives_a_full_problem() -> None:
    problem = registry.get("2013-6")
    sol = problem.solve(K=1.4)
    assert sol.results["theta_deg"] == pytest.approx(30.0)
    assert sol.sheets()[0][0] == ""
    from geomcad_constructions import spec_2013_6

    assert spec_2013_6.PROBLEM is problem


def test_the_light_spec_and_the_library_agree_on_the_cam_laws() -> None:
    from geomcad_constructions.spec_2013_2 import LAWS

    from geomcad.kinematics.motion_laws import LAWS as LIBRARY_LAWS

    assert LAWS == LIBRARY_LAWS
