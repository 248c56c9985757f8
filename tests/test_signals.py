"""Signals and broken streams (issue 29): SIGINT, SIGTERM and SIGHUP end a command at any moment
with one ``error:`` line and the status 130, 143 or 129, no traceback, no partial or temporary
file, also while cairo calls back into Python to write a PDF; stdout or stderr that cannot be
written is the OS's reason in one line and the status 74."""

from __future__ import annotations

import io
import os
import signal
import subprocess
import sys
import time
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path
from typing import Any

import pytest

from geomcad import interrupts
from geomcad.cli import EXIT_IO, main
from geomcad.render import raster
from geomcad.render.files import TEMP_NAME

SIGNALS = [signal.SIGINT, signal.SIGTERM, signal.SIGHUP]


def _geomcad(*args: str, **kw: Any) -> subprocess.Popen[str]:
    """``python -m geomcad ARGS`` (the console script's entry, :func:`geomcad.__main__.run`)."""
    return subprocess.Popen(
        [sys.executable, "-m", "geomcad", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        **kw,
    )


def _stopped_cleanly(proc: subprocess.Popen[str], sig: int, out: Path) -> None:
    _, err = proc.communicate(timeout=120)
    assert "Traceback" not in err and "Exception ignored" not in err
    if proc.returncode == -sig and err.startswith("built ") and err.count("\n") == 1:
        return  # the build was done; the interpreter was ending (the signal's own action)
    assert proc.returncode == 128 + sig, err
    assert err.count("\n") == 1 and err.startswith("error: "), err
    assert f"stopped by {signal.Signals(sig).name}" in err
    left = os.listdir(out) if out.exists() else []
    assert not [n for n in left if TEMP_NAME.match(n) or n.startswith(".")], left
    for name in left:  # what is there is whole
        data = (out / name).read_bytes().rstrip()
        if name.endswith(".svg"):
            assert data.endswith(b"</svg>"), name
        elif name.endswith(".pdf"):
            assert data.endswith(b"%%EOF"), name


# --- the mechanism --------------------------------------------------------------------------------


def test_a_signal_raises_interrupted_and_the_handlers_come_back() -> None:
    before = signal.getsignal(signal.SIGTERM)
    old = interrupts.catch()
    try:
        with pytest.raises(interrupts.Interrupted) as got:
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(5.0)  # the handler runs first
        assert got.value.status == 143 and got.value.name == "SIGTERM"
    finally:
        interrupts.restore(old)
    assert signal.getsignal(signal.SIGTERM) is before


def test_a_signal_inside_deferred_is_raised_as_the_block_ends() -> None:
    old = interrupts.catch()
    went_on = False
    try:
        with pytest.raises(interrupts.Interrupted) as got, interrupts.deferred():
            os.kill(os.getpid(), signal.SIGHUP)
            time.sleep(0.05)  # the handler has run: it held the signal
            went_on = True
        assert got.value.signum == signal.SIGHUP
    finally:
        interrupts.restore(old)
    assert went_on


def test_cairo_is_never_interrupted_inside_its_callbacks(monkeypatch: pytest.MonkeyPatch) -> None:
    """to_pdf and to_png hold a signal while cairo runs (an exception raised in its write
    callback would be printed and lost, and the write would fail)."""
    finished: list[str] = []

    class FakeCairo:
        @staticmethod
        def svg2pdf(**_: object) -> bytes:
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(0.05)
            finished.append("pdf")
            return b"%PDF-1.5\n%%EOF"

    monkeypatch.setattr(raster, "_cairosvg", lambda: FakeCairo)
    old = interrupts.catch()
    try:
        with pytest.raises(interrupts.Interrupted):
            raster.to_pdf("<svg/>")
    finally:
        interrupts.restore(old)
    assert finished == ["pdf"]


def test_main_ends_with_the_signal_status_when_its_exception_was_swallowed(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A finaliser (or a callback) that ate the signal's exception: the command still ends as
    stopped, and no file is begun after it."""
    import geomcad.cli as cli

    def swallowing(ns: object) -> int:
        try:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5.0)
        except interrupts.Interrupted:
            pass  # as a finaliser's caller would
        with pytest.raises(interrupts.Interrupted):
            interrupts.check()
        return 0

    monkeypatch.setattr(cli, "_cmd_list", swallowing)
    before = signal.getsignal(signal.SIGINT)  # Python's own, or SIG_IGN under a background shell
    err = io.StringIO()
    with redirect_stdout(io.StringIO()), redirect_stderr(err):
        code = main(["list"])
    assert code == 130
    assert err.getvalue().startswith("error: list: stopped by SIGINT;")
    assert signal.getsignal(signal.SIGINT) is before


# --- the command: at any moment, in the first tenth of a second, inside cairo ------------------


@pytest.mark.parametrize("sig", SIGNALS)
@pytest.mark.parametrize("delay", [0.5, 1.2, 2.5])
def test_a_signal_at_a_moment_of_a_build(sig: int, delay: float, tmp_path: Path) -> None:
    out = tmp_path / "out"
    proc = _geomcad("build", "2013-3", "--format", "svg,pdf", "--out", str(out))
    time.sleep(delay)
    if proc.poll() is not None:
        pytest.skip("the build ended before the signal")  # a very fast machine
    proc.send_signal(sig)
    _stopped_cleanly(proc, sig, out)


#: A child whose cairo writes slowly through its Python callback (the first writes sleep), and
#: that marks the moment it is inside that callback.
INSIDE_CAIRO = """
import io, sys, time, types
from pathlib import Path
import cairosvg.surface
marker = Path(sys.argv[1])
class SlowIO(io.BytesIO):
    n = 0
    def write(self, data):
        SlowIO.n += 1
        if SlowIO.n <= 40:
            marker.touch()
            time.sleep(0.05)
        return super().write(data)
cairosvg.surface.io = types.SimpleNamespace(BytesIO=SlowIO)  # PNG (and PDF through cairosvg)
import geomcad.render.pdf
geomcad.render.pdf.io = types.SimpleNamespace(BytesIO=SlowIO)  # the PDF drawn from the sheet
from geomcad.__main__ import run
sys.argv = ["geomcad", *sys.argv[2:]]
sys.exit(run())
"""


@pytest.mark.parametrize("sig", SIGNALS)
def test_a_signal_inside_cairos_write_callback(sig: int, tmp_path: Path) -> None:
    """Reproducer 2: was "Exception ignored from cffi callback", then "cannot write", exit 2."""
    out, marker = tmp_path / "out", tmp_path / "inside-cairo"
    proc = subprocess.Popen(
        [sys.executable, "-c", INSIDE_CAIRO, str(marker), "build", "2013-3", "--format",
         "svg,pdf", "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )  # fmt: skip
    deadline = time.monotonic() + 90.0
    while not marker.exists() and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.005)
    assert marker.exists(), proc.communicate()
    proc.send_signal(sig)
    _stopped_cleanly(proc, sig, out)
    assert not list(out.glob("*.pdf"))  # the PDF being written was not written
    assert list(out.glob("*.svg"))  # the SVGs before it are whole


def test_a_signal_while_the_command_line_loads() -> None:
    """The console script catches the signals before geomcad.cli and its imports load."""
    code = (
        "import os, signal, sys\n"
        "from geomcad import interrupts\n"
        "import geomcad.__main__ as m\n"
        "real = m.run\n"
        "import builtins\n"
        "imp = builtins.__import__\n"
        "def slow(name, *a, **k):\n"
        "    if name == 'geomcad.cli':\n"
        "        os.kill(os.getpid(), signal.SIGINT)\n"
        "    return imp(name, *a, **k)\n"
        "builtins.__import__ = slow\n"
        "sys.argv = ['geomcad', 'list']\n"
        "sys.exit(real())\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=False
    )
    assert proc.returncode == 130, proc.stderr
    assert proc.stderr.startswith("error: list: stopped by SIGINT") and "Traceback" not in (
        proc.stderr
    )


# --- stdout and stderr that cannot be written ---------------------------------------------------


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
@pytest.mark.parametrize(
    "argv",
    [["solve", "2013-6", "--json"], ["list"], ["params", "2013-6"], ["solve", "2013-6"]],
)
def test_a_full_stdout_is_an_os_error_and_status_74(argv: list[str]) -> None:
    with open("/dev/full", "w") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "geomcad", *argv],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=120,
            check=False,
        )
    assert proc.returncode == EXIT_IO
    assert proc.stderr == "error: cannot write to stdout: No space left on device\n"


def test_a_closed_stdout_is_an_os_error_and_status_74() -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "geomcad", "list"],
        stdin=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
        check=False,
        preexec_fn=lambda: os.close(1),  # closed in the child only
    )
    assert proc.returncode == EXIT_IO
    assert proc.stderr == "error: cannot write to stdout: it is closed\n"


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full")
def test_a_full_stderr_ends_bad_input_with_status_74_and_nothing_else() -> None:
    with open("/dev/full", "w") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "geomcad", "solve", "no-such-id"],
            stdout=subprocess.PIPE,
            stderr=full,
            text=True,
            timeout=120,
            check=False,
        )
    assert proc.returncode == EXIT_IO and proc.stdout == ""


def test_a_stream_error_in_process_is_not_an_internal_error() -> None:
    class Full(io.StringIO):
        def write(self, s: str) -> int:
            raise OSError(28, "No space left on device")

    err = io.StringIO()
    with redirect_stdout(Full()), redirect_stderr(err):
        code = main(["list"])
    assert code == EXIT_IO
    assert err.getvalue() == "error: cannot write to stdout: No space left on device\n"


def test_an_exception_a_signal_caused_is_the_signal(monkeypatch: pytest.MonkeyPatch) -> None:
    """A signal inside a C extension's import comes out as "ImportError: initialization
    failed" (found by the fuzz): the command ends as stopped, not as an internal error."""
    import geomcad.cli as cli

    def wrapping(ns: object) -> int:
        try:
            os.kill(os.getpid(), signal.SIGHUP)
            time.sleep(5.0)
        except interrupts.Interrupted:
            raise ImportError("initialization failed") from None
        return 0

    monkeypatch.setattr(cli, "_cmd_list", wrapping)
    err = io.StringIO()
    with redirect_stdout(io.StringIO()), redirect_stderr(err):
        code = main(["list"])
    assert code == 129
    assert err.getvalue().count("\n") == 1
    assert err.getvalue().startswith("error: list: stopped by SIGHUP;")


def test_a_hangup_ignored_by_nohup_stays_ignored(tmp_path: Path) -> None:
    """``nohup geomcad build …``: SIGHUP was ignored when the command started, so a hangup
    neither stops it nor is caught; SIGTERM still is."""
    code = (
        "import signal, sys\n"
        "signal.signal(signal.SIGHUP, signal.SIG_IGN)\n"
        "from geomcad import interrupts\n"
        "old = interrupts.catch()\n"
        "print(signal.getsignal(signal.SIGHUP) is signal.SIG_IGN,"
        " signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL)\n"
        "interrupts.restore(old)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=tmp_path
    ).stdout.split()
    assert out == ["True", "True"]
