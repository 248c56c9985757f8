"""Batch work streams (issue 28) and its workers never outlive it (issue 29's reproducer 1)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from geomcad.teach import jobs

WAIT_S = 20.0


def _wait_for(flag: str) -> str:
    """Return once ``flag`` exists ("late"), or after WAIT_S ("timeout")."""
    end = time.monotonic() + WAIT_S
    while time.monotonic() < end:
        if os.path.exists(flag):
            return "late"
        time.sleep(0.02)
    return "timeout"


def _at_once(x: str) -> str:
    return x


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie (not yet reaped) has done its work too
    stat = Path(f"/proc/{pid}/stat")
    return not (stat.exists() and stat.read_text().split(") ")[-1].startswith("Z"))


def _gone(pids: list[int], within: float = 10.0) -> bool:
    end = time.monotonic() + within
    while time.monotonic() < end:
        if not any(_alive(p) for p in pids):
            return True
        time.sleep(0.05)
    return False


def test_stream_hands_back_each_result_when_it_is_done(tmp_path: Path) -> None:
    """The first call waits for a flag the consumer sets only on receiving the second: a stream
    that waited for all (or went in order) would time out."""
    flag = str(tmp_path / "flag")
    ticks: list[int] = []
    got: list[tuple[int, str]] = []
    with jobs.pool(2, ticks.append) as run:
        for i, r in run.stream(_dispatch, [("wait", flag), ("now", "second")]):
            got.append((i, r))
            if i == 1:
                Path(flag).touch()
    assert got == [(1, "second"), (0, "late")] and ticks == [1, 1]
    with jobs.pool(1) as run:  # in this process: in order, the same results
        assert run(_dispatch, [("now", "a"), ("now", "b")]) == ["a", "b"]


def _dispatch(what: str, arg: str) -> str:
    return _wait_for(arg) if what == "wait" else _at_once(arg)


def _pid_and_sleep(folder: str) -> None:
    Path(folder, str(os.getpid())).touch()
    time.sleep(60)


def _pids(folder: Path, n: int) -> list[int]:
    end = time.monotonic() + WAIT_S
    while len(list(folder.iterdir())) < n and time.monotonic() < end:
        time.sleep(0.05)
    return [int(p.name) for p in folder.iterdir()]


def test_an_error_in_the_batch_ends_the_workers_at_once(tmp_path: Path) -> None:
    """Busy workers (each in a 60 s call) are ended on the way out, not waited for."""
    started = time.monotonic()
    with pytest.raises(RuntimeError), jobs.pool(2) as run:
        assert run.ex is not None
        for _ in range(2):
            run.ex.submit(_pid_and_sleep, str(tmp_path))
        pids = _pids(tmp_path, 2)
        assert len(pids) == 2 and all(_alive(p) for p in pids)
        raise RuntimeError("stop")
    assert _gone(pids) and time.monotonic() - started < 30.0


PARENT = """
import sys, time
from geomcad.teach import jobs
sys.path.insert(0, sys.argv[2])
import test_jobs
with jobs.pool(2) as run:
    run(test_jobs._pid_and_sleep, [(sys.argv[1],)] * 2)
"""


def test_workers_die_with_a_killed_parent(tmp_path: Path) -> None:
    parent = subprocess.Popen(
        [sys.executable, "-c", PARENT, str(tmp_path), str(Path(__file__).parent)]
    )
    try:
        pids = _pids(tmp_path, 2)
        assert len(pids) == 2 and all(_alive(p) for p in pids)
        parent.kill()  # SIGKILL: no handler, no finally runs in the parent
        parent.wait()
        assert _gone(pids)
    finally:
        parent.kill()


EX = Path(__file__).resolve().parents[1] / "examples"


def test_a_parallel_build_writes_what_was_finished_and_names_what_failed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A file that loads but cannot be solved (its group never closes) fails in its worker; the
    other problems' files are written all the same, and the error names the file."""
    from geomcad.cli import main

    text = (EX / "slider-crank.toml").read_text(encoding="utf-8")
    broken = tmp_path / "open.toml"
    broken.write_text(text.replace("length = 0.30", "length = 0.02"), encoding="utf-8")
    assert broken.read_text(encoding="utf-8") != text
    out_dir = tmp_path / "o"
    argv = ["build", "2013-8", str(broken), "--out", str(out_dir), "--format", "svg"]
    code = main([*argv, "--jobs", "2"])
    out, err = capsys.readouterr()
    assert code == 2 and err.startswith("error: ") and "open.toml" in err and "close" in err
    assert sorted(p.name for p in out_dir.iterdir()) == ["2013-8.svg"]
    assert out == f"{out_dir / '2013-8.svg'}\n"
