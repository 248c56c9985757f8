"""SIGINT, SIGTERM and SIGHUP as one exception, :class:`Interrupted`, that unwinds the command.

The command line (:func:`geomcad.cli.main`) calls :func:`catch` as it starts: from then on each of
the three signals raises :class:`Interrupted` in the main thread, wherever Python is, so every
``finally`` runs (:func:`geomcad.render.files.write_atomic` removes its temporary file) and the
command ends with one ``error:`` line and the conventional status 128 + the signal's number (130,
143, 129). :class:`Interrupted` is a :class:`BaseException`, as :class:`KeyboardInterrupt` is:
no ``except Exception`` swallows it.

Some Python code runs where an exception cannot travel: a callback that C code calls (cairo
writes a PDF through a cffi callback, which prints an exception raised in it and carries on with
a failed write) or a finaliser. Inside :func:`deferred` a signal is held and raised as the block
ends; a signal whose exception was swallowed all the same is still on record
(:func:`received`), so the command ends as interrupted. A process forked from the one that
called :func:`catch` (a worker of a process pool) keeps the signals' usual actions.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
from collections.abc import Iterator
from typing import Any

#: The signals that stop a command, each ending it with status 128 + its number.
SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class Interrupted(BaseException):
    """A signal stopped the work (:data:`SIGNALS`); ``signum`` is its number."""

    def __init__(self, signum: int) -> None:
        self.signum = signum
        super().__init__(signum)

    @property
    def name(self) -> str:
        """The signal's name, e.g. ``SIGTERM``."""
        return signal.Signals(self.signum).name

    @property
    def status(self) -> int:
        """The exit status of a command this signal stopped (128 + its number)."""
        return 128 + self.signum

    def line(self, command: str) -> str:
        """The one ``error:`` line a command this signal stopped ends with."""
        return (
            f"error: {command}: stopped by {self.name}; every file written is complete, no "
            "partial or temporary file is left\n"
        )


_owner: int | None = None  # the process that called catch()
_depth = 0  # how many deferred() blocks are open
_pending: int | None = None  # a signal held by deferred()
_received: int | None = None  # the first signal since catch()


def _handler(signum: int, frame: object) -> None:
    global _pending, _received
    if os.getpid() != _owner:
        # a forked worker: the signal's usual action (SIGINT: KeyboardInterrupt; else death)
        if signum == signal.SIGINT:
            raise KeyboardInterrupt
        signal.signal(signum, signal.SIG_DFL)
        os.kill(os.getpid(), signum)
        return
    first = _received is None
    if first:
        _received = signum
    if _depth > 0:
        if _pending is None:
            _pending = signum
        return
    if first:  # a second signal while the first one unwinds changes nothing
        raise Interrupted(signum)


def _unraisable(hook: Any) -> Any:
    """A ``sys.unraisablehook`` that keeps quiet about an :class:`Interrupted` (the signal is on
    record; the command still ends as interrupted) and passes on everything else."""

    def quiet(info: Any) -> None:
        if not isinstance(info.exc_value, Interrupted):
            hook(info)

    return quiet


def catch() -> dict[int, Any]:
    """Make :data:`SIGNALS` raise :class:`Interrupted` in this process; return what to give
    :func:`restore`. Outside the main thread (where no handler can be set) nothing changes."""
    global _owner, _received, _pending
    if _owner == os.getpid():  # caught already (the console script, then main)
        return {-1: None}
    old: dict[int, Any] = {}
    with contextlib.suppress(ValueError):
        for sig in SIGNALS:
            if sig == signal.SIGHUP and signal.getsignal(sig) is signal.SIG_IGN:
                continue  # `nohup geomcad build …`: a hangup stays ignored, as the user asked
            old[sig] = signal.signal(sig, _handler)
    if old:
        _owner = os.getpid()
        _received = _pending = None
        old[0] = sys.unraisablehook
        sys.unraisablehook = _unraisable(sys.unraisablehook)
    return old


def restore(old: dict[int, Any]) -> None:
    """Give the signals back the handlers :func:`catch` replaced."""
    global _owner
    if -1 in old:
        return
    for sig, handler in old.items():
        if sig == 0:
            sys.unraisablehook = handler
        else:
            signal.signal(sig, handler)
    if old:
        _owner = None


def default() -> None:
    """Give :data:`SIGNALS` their system actions (end the process, no Python code runs)."""
    with contextlib.suppress(ValueError):
        for sig in SIGNALS:
            signal.signal(sig, signal.SIG_DFL)


def received() -> int | None:
    """The first signal since :func:`catch` (``None``: none came)."""
    return _received


@contextlib.contextmanager
def deferred() -> Iterator[None]:
    """Hold a signal while the block runs (C code calling back into Python: an exception
    raised there would be lost); raise it as :class:`Interrupted` when the block ends."""
    global _depth, _pending
    _depth += 1
    try:
        yield
    finally:
        _depth -= 1
        if _depth == 0 and _pending is not None:
            signum, _pending = _pending, None
            raise Interrupted(signum)


def check() -> None:
    """Raise :class:`Interrupted` when a signal came but its exception was swallowed (a
    finaliser's, a callback's): the place to call it is before work that leaves traces."""
    if _received is not None and _owner == os.getpid() and _depth == 0:
        raise Interrupted(_received)
