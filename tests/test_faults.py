"""Faults from outside: the inputs of issue 19, wrong types through the API, internal errors,
and the file system failing under ``build`` (a file for --out, no permission, a full disk, a
kill in the middle of a write)."""

from __future__ import annotations

import dataclasses
import errno
import io
import os
import signal
import subprocess
import sys
import time
from collections.abc import Mapping
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import geomcad
from geomcad import registry
from geomcad.cli import main
from geomcad.render.files import TEMP_NAME, remove_stale_temporaries


def run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def one_error_line(err: str) -> str:
    assert err.startswith("error: ") and err.count("\n") == 1, err
    return err


# --- the reproductions of the issue: one clean line within a second or two ----------------------

ISSUE = [
    (["solve", "2013-8", "--set", "n_rpm=1e-308"], "n_rpm"),
    (["solve", "2013-1", "--set", "n=" + "9" * 38], "parameter n"),
    (["solve", "2013-1", "--set", "e=1e308"], "parameter e"),
    (["solve", "2013-4", "--set", "z=1e308"], "parameter z"),
    (["solve", "2013-7", "--set", "m_ball=5e-324"], "m_ball"),
    (["solve", "2013-2", "--set", "phi_rise_deg=1e-308"], "phi_rise_deg"),
    (["solve", "kulisa-23110713", "--set", "phi_deg=1e308"], "phi_deg"),
    (["solve", "kulisa-23110713", "--set", "phi_deg=1e6"], "phi_deg"),
    (["solve", "2013-9", "--set", "c=1e30"], "parameter c"),
    (["solve", "2013-9", "--set", "c=1e12"], "parameter c"),
    (["solve", "2013-9", "--set", "M0=1000"], "equation of motion"),
    (["solve", "2013-9", "--set", "T=10", "--set", "M0=10"], "equation of motion"),
    (["solve", "2013-9", "--set", "M1=1", "--set", "Omega=1e5"], "equation of motion"),
    (["verify", "2013-6", "--measured", "O1B0=1e308", "--json"], "O1B0"),
    (["verify", "2013-6", "--measured", "O1B0_mm=60", "--scale", "1e308"], "scale"),
    (["verify", "2013-6", "--measured", "O1B0_mm=60", "--scale", "5e-324"], "scale"),
]


@pytest.mark.parametrize(("argv", "words"), ISSUE, ids=[" ".join(a[1:]) for a, _ in ISSUE])
def test_the_issues_inputs_give_one_clean_line_quickly(argv: list[str], words: str) -> None:
    start = time.monotonic()
    code, out, err = run(*argv)
    elapsed = time.monotonic() - start
    assert code == 2 and out == "", err
    assert words in one_error_line(err)
    assert elapsed < 10.0  # about a second on an idle machine; CI machines are shared


def test_a_stiff_damper_is_integrated_implicitly() -> None:
    sol = geomcad.solve("2013-9", k=1e6)
    assert any("LSODA" in n for n in sol.notes)
    # the damper holds the rod: φ' at T is tiny, and finite
    assert 0.0 < sol.results["omega_T"] < 1e-2


def test_an_integration_that_spends_its_budget_names_the_step_and_the_cause() -> None:
    with pytest.raises(geomcad.ConstructionError, match=r"budget of .* evaluations.*oscillates"):
        geomcad.solve("2013-9", c=1e9)


def test_angles_of_a_turn_are_reduced() -> None:
    a = geomcad.solve("2013-1", psi_deg=90.0 + 3600.0, theta1_deg=-360.0)
    assert a.params["psi_deg"] == 90.0 and a.params["theta1_deg"] == 0.0
    assert a.results == geomcad.solve("2013-1").results


WRONG_TYPES: list[tuple[Any, Mapping[str, object]]] = [
    (["2013-6"], {}),
    (None, {}),
    (2013, {}),
    ("2013-6", {"H": "abc"}),
    ("2013-6", {"H": [0.2]}),
    ("2013-6", {"H": None}),
    ("2013-6", {"H": 10**400}),
    ("2013-6", {"H": np.float64("nan")}),
    ("2013-6", {"H": complex(1, 1)}),
    ("2013-6", {"nonsense": 1}),
    ("2013-2", {"law": 3}),
    ("2013-5", {"z1": 2.5}),
]


@pytest.mark.parametrize(("pid", "params"), WRONG_TYPES)
def test_wrong_types_through_the_api_are_geomcad_errors(
    pid: Any, params: Mapping[str, object]
) -> None:
    with pytest.raises(geomcad.GeomcadError):
        geomcad.solve(pid, **params)


# --- anything unexpected: one line, exit status 70 ---------------------------------------------


def test_an_internal_error_is_one_line_and_status_70(monkeypatch: pytest.MonkeyPatch) -> None:
    real = registry.get("2013-3")

    def boom(p: Mapping[str, Any]) -> Any:
        return {}["no such key"]

    monkeypatch.setattr(registry, "get", lambda pid: dataclasses.replace(real, build=boom))
    code, out, err = run("solve", "2013-3")
    assert code == 70 and out == ""
    line = one_error_line(err)
    assert line.startswith("error: internal error in solve 2013-3")
    assert "KeyError: 'no such key' (please report)" in line


def test_an_internal_error_in_a_file_problem_is_status_70(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    from geomcad import documents

    def broken(pid: str, sets: Any = ()) -> Any:
        raise TypeError("unsupported operand")

    monkeypatch.setattr(documents, "solve", broken)
    f = tmp_path / "mech.toml"
    f.write_text("[drive]\nomega = 1.0\n", encoding="utf-8")
    code, _out, err = run("solve", str(f))
    assert code == 70
    assert "internal error in solve" in one_error_line(err) and "TypeError" in err


def test_a_toml_syntax_error_is_bad_input(tmp_path: Path) -> None:
    f = tmp_path / "mech.toml"
    f.write_text("[drive\nomega = \n", encoding="utf-8")
    code, _, err = run("solve", str(f))
    assert code == 2 and "not valid TOML" in one_error_line(err) and "line 1" in err


def test_two_sliding_pairs_named_by_one_point_are_refused_by_the_key(tmp_path: Path) -> None:
    """Review 10: an RPR block turning on an RRP's slider joint B (``slider = "B"``) stopped
    the solve with an internal AssertionError (both pairs' v_rel and a_cor keyed by B). The
    file is refused on the group's key, with the way out; the same mechanism with a point K
    of the slider at B solves."""
    bad = Path(__file__).parent / "linkages_bad" / "rpr_on_rrp_slider_joint.toml"
    code, _, err = run("solve", str(bad))
    line = one_error_line(err)
    assert code == 2 and "group 2: slider: B" in line and "group 1 (RRP)" in line, line
    good = bad.read_text(encoding="utf-8").replace(
        "[[group]]                 # RPR",
        '[[point]]\nname = "K"\nlink = 3\nfrom = "B"\ntoward = "A"\nalong = 0.0\nleft = 0.0\n\n'
        "[[group]]                 # RPR",
    )
    f = tmp_path / "rpr_on_a_point_of_the_slider.toml"
    f.write_text(good.replace('slider = "B"', 'slider = "K"'), encoding="utf-8")
    code, out, err = run("solve", str(f), "--json")
    assert code == 0 and not err and out, (code, err)


# --- the file system -----------------------------------------------------------------------------


def test_build_out_on_a_file(tmp_path: Path) -> None:
    f = tmp_path / "sheet"
    f.write_text("mine", encoding="utf-8")
    code, out, err = run("build", "2013-3", "--format", "svg", "--out", str(f))
    assert code == 2 and out == "" and "is a file, not a folder" in one_error_line(err)
    assert f.read_text(encoding="utf-8") == "mine"
    code, _, err = run("build", "2013-3", "--format", "svg", "--out", str(f / "below"))
    assert code == 2 and "Not a directory" in one_error_line(err)


def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir()) if folder.exists() else []


@pytest.mark.parametrize(
    ("where", "fault"),
    [
        ("fsync", OSError(errno.ENOSPC, "No space left on device")),
        ("open", PermissionError(errno.EACCES, "Permission denied")),
    ],
)
def test_a_write_that_fails_leaves_no_file(
    where: str, fault: OSError, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """A full disk (the write fails at fsync) or a folder without permission (at open)."""
    real = getattr(os, where)

    def failing(*args: Any, **kwargs: Any) -> Any:
        if where == "open" and not str(args[0]).startswith(str(tmp_path)):
            return real(*args, **kwargs)
        raise fault

    monkeypatch.setattr(os, where, failing)
    code, out, err = run("build", "2013-3", "--format", "svg", "--out", str(tmp_path))
    monkeypatch.undo()
    assert code == 2 and out == ""
    assert (fault.strerror or "") in one_error_line(err)
    assert _leftovers(tmp_path) == []


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into any folder")
def test_an_unwritable_folder(tmp_path: Path) -> None:
    tmp_path.chmod(0o500)
    try:
        code, _, err = run("build", "2013-3", "--format", "svg", "--out", str(tmp_path))
    finally:
        tmp_path.chmod(0o700)
    assert code == 2 and "Permission denied" in one_error_line(err)


def _dead_pid() -> int:
    pid = 4_000_000
    while True:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return pid
        except PermissionError:
            pass
        pid += 1


def test_stale_temporaries_of_dead_writers_are_removed(tmp_path: Path) -> None:
    dead = tmp_path / f".2013-3.svg.{_dead_pid()}-0123456789ab.tmp"
    live = tmp_path / f".2013-3.svg.{os.getpid()}-0123456789ab.tmp"
    other = tmp_path / ".notes.tmp"
    for f in (dead, live, other):
        f.write_bytes(b"<svg")
    assert all(TEMP_NAME.match(f.name) for f in (dead, live))
    assert remove_stale_temporaries(tmp_path) == [dead]
    assert sorted(_leftovers(tmp_path)) == sorted([live.name, other.name])


# The child writes slowly (each fsync waits), so the test can act the moment a temporary file
# appears.
SLOW_CHILD = """
import os, sys, time
real = os.fsync
def slow(fd):
    time.sleep(0.3)
    real(fd)
os.fsync = slow
from geomcad.cli import main
sys.exit(main(sys.argv[1:]))
"""


def _child(out: Path, slow: bool) -> subprocess.Popen[str]:
    args = ["build", "2013-3", "--format", "svg,pdf", "--out", str(out)]
    code = SLOW_CHILD if slow else "import sys; from geomcad.cli import main; sys.exit(main())"
    return subprocess.Popen(
        [sys.executable, "-c", code, *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def _wait_for_temporary(proc: subprocess.Popen[str], out: Path) -> bool:
    deadline = time.monotonic() + 60.0
    while time.monotonic() < deadline and proc.poll() is None:
        if out.exists() and any(TEMP_NAME.match(n) for n in os.listdir(out)):
            return True
        time.sleep(0.002)
    return False


def _complete(out: Path) -> None:
    """Every sheet in ``out`` is whole: an SVG ends with its closing tag, a PDF with %%EOF."""
    for p in out.iterdir():
        if p.suffix == ".svg":
            assert p.read_bytes().rstrip().endswith(b"</svg>"), p
        elif p.suffix == ".pdf":
            assert p.read_bytes().rstrip().endswith(b"%%EOF"), p


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL])
def test_a_kill_while_a_file_is_written(sig: signal.Signals, tmp_path: Path) -> None:
    """SIGTERM unwinds (no temporary file stays, one error line); SIGKILL cannot, and the next
    build removes what it left."""
    proc = _child(tmp_path, slow=True)
    assert _wait_for_temporary(proc, tmp_path), proc.communicate()
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    _complete(tmp_path)
    if sig == signal.SIGTERM:
        assert proc.returncode == 128 + signal.SIGTERM
        assert "stopped by SIGTERM" in one_error_line(err)
        assert not any(TEMP_NAME.match(n) for n in _leftovers(tmp_path))
    else:
        assert any(TEMP_NAME.match(n) for n in _leftovers(tmp_path))
    code, _, _ = run("build", "2013-3", "--format", "svg", "--out", str(tmp_path))
    assert code == 0
    assert not any(TEMP_NAME.match(n) for n in _leftovers(tmp_path))
    _complete(tmp_path)


@pytest.mark.parametrize("delay", [0.9, 1.6])
def test_a_kill_at_another_moment_leaves_only_whole_files(delay: float, tmp_path: Path) -> None:
    """Killed at fixed moments of an ordinary build (import, solve, render or write): what is
    there is whole, and the next build cleans up."""
    proc = _child(tmp_path, slow=False)
    time.sleep(delay)
    proc.kill()
    proc.communicate(timeout=60)
    _complete(tmp_path)
    remove_stale_temporaries(tmp_path)
    assert not any(TEMP_NAME.match(n) for n in _leftovers(tmp_path))
