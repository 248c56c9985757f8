"""Work spread over processes, results in order, with a progress bar on a terminal.

:func:`pool` gives a ``map(fn, args)`` that runs ``fn(*a)`` for each argument tuple in up to
``jobs`` worker processes and returns the results in the order of ``args``: whatever process
did the work, the output is the same, so a parallel build writes the same bytes as a serial one.
``jobs`` = 1 works in this process.

:meth:`Runner.stream` hands each result back as soon as it is done (its index with it), so a
batch writes every file when it is finished and a killed batch keeps what was finished.

The workers die with their parent (Linux: ``PR_SET_PDEATHSIG``; a worker that finds its parent
gone exits), and the pool is torn down on every way out of :func:`pool` (an error, a signal
turned into an exception, Ctrl-C): the queued calls are cancelled and the workers terminated, so
no worker outlives the command that started it.

:func:`bar` is a tqdm progress bar on stderr, shown only when stderr is a terminal.
"""

from __future__ import annotations

import os
import signal
import sys
from collections.abc import Callable, Collection, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from contextlib import contextmanager, suppress
from typing import Any

from geomcad.errors import ParameterError

#: The most worker processes ``--jobs`` starts (a pool of forked workers starts them all).
MAX_JOBS = 64


def check_jobs(jobs: int) -> int:
    """``--jobs N``: a whole number from 1 to :data:`MAX_JOBS`, or 0 for every core."""
    if not 0 <= jobs <= MAX_JOBS:
        raise ParameterError("--jobs", jobs, f"must be from 1 to {MAX_JOBS} (or 0: one per core)")
    return jobs or (os.cpu_count() or 1)


class Relay:
    """A ``tick`` that passes each call on to whichever progress bar is current (``to``), so one
    pool serves several phases, each with its own bar."""

    def __init__(self) -> None:
        self.to: Callable[[int], None] | None = None

    def __call__(self, n: int) -> None:
        if self.to is not None:
            self.to(n)


def _call(fn: Callable[..., Any], args: tuple[Any, ...]) -> Any:
    return fn(*args)


#: prctl(2)'s option that sends the calling process a signal when its parent dies.
_PR_SET_PDEATHSIG = 1


def _die_with(parent: int) -> None:
    """A worker's initializer: be killed when ``parent`` dies (Linux), and exit at once if it is
    already gone (it died before the request was made). Ctrl-C is the parent's to handle: it
    ends the workers itself (:func:`pool`), without a traceback from each."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if sys.platform.startswith("linux"):
        import ctypes

        with suppress(OSError, AttributeError):
            ctypes.CDLL(None).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:
        os._exit(1)


class Runner:
    """What :func:`pool` gives: called as ``run(fn, args)``, the results in the order of
    ``args``; :meth:`stream` the same results as each is done."""

    def __init__(self, ex: ProcessPoolExecutor | None, tick: Callable[[int], None] | None) -> None:
        self.ex = ex
        self.tick = tick

    def __call__(self, fn: Callable[..., Any], args: Sequence[tuple[Any, ...]]) -> list[Any]:
        out: list[Any] = [None] * len(args)
        for i, r in self.stream(fn, args):
            out[i] = r
        return out

    def stream(
        self, fn: Callable[..., Any], args: Sequence[tuple[Any, ...]]
    ) -> Iterator[tuple[int, Any]]:
        """``(i, fn(*args[i]))`` as each call finishes (in order in this process, in the order
        they finish in workers); ``tick(1)`` after each."""
        if self.ex is None:
            for i, a in enumerate(args):
                r = fn(*a)
                if self.tick is not None:
                    self.tick(1)
                yield i, r
            return
        ex = self.ex
        index: dict[Future[Any], int] = {ex.submit(_call, fn, a): i for i, a in enumerate(args)}
        pending = set(index)
        while pending:
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for f in sorted(done, key=index.__getitem__):
                r = f.result()
                if self.tick is not None:
                    self.tick(1)
                yield index[f], r


def _tear_down(ex: ProcessPoolExecutor) -> None:
    """Cancel what is queued and end the workers now (not after their current call)."""
    procs = list(getattr(ex, "_processes", {}).values())
    ex.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        with suppress(OSError, ValueError, AttributeError):
            p.terminate()
    for p in procs:
        with suppress(OSError, ValueError, AttributeError, AssertionError):
            p.join(1.0)


@contextmanager
def pool(jobs: int, tick: Callable[[int], None] | None = None) -> Iterator[Runner]:
    """A :class:`Runner` over ``jobs`` processes (``jobs`` ≤ 1: in this process); ``tick(1)`` is
    called as each call finishes. Every way out ends the workers (module docstring)."""
    if jobs <= 1:
        yield Runner(None, tick)
        return
    ex = ProcessPoolExecutor(max_workers=jobs, initializer=_die_with, initargs=(os.getpid(),))
    try:
        yield Runner(ex, tick)
    except BaseException:
        _tear_down(ex)
        raise
    ex.shutdown(wait=True)


@contextmanager
def bar(total: int, unit: str, desc: str = "") -> Iterator[Callable[[int], None]]:
    """A progress bar on stderr when it is a terminal (nothing when piped or in a file)."""
    show = sys.stderr.isatty()
    if not show:  # nothing to draw: tqdm is not even imported
        yield lambda n: None
        return
    from tqdm import tqdm

    # no monitor thread: worker processes are forked while the bar runs
    tqdm.monitor_interval = 0
    with tqdm(total=total, unit=unit, desc=desc, disable=not show, leave=False,
              file=sys.stderr) as t:  # fmt: skip
        yield t.update


def warm(file_ids: Sequence[str], formats: Collection[str]) -> None:
    """Import in this process what the workers will need, before they are forked: the kinds of
    the files (their modules load with :func:`geomcad.documents.load`), for PDF the PDF
    writer's cairocffi (:func:`geomcad.render.raster.cairo`), for PNG cairosvg; each worker
    then starts with them instead of importing them again. A file that does not load is left
    for its worker to report."""
    from geomcad import documents
    from geomcad.errors import GeomcadError

    for pid in file_ids:
        with suppress(GeomcadError):
            documents.load(pid)
    if "pdf" in formats:
        from geomcad.render.raster import cairo

        with suppress(GeomcadError):
            cairo()
    if "png" in formats:
        from geomcad.render.raster import _cairosvg

        with suppress(GeomcadError):
            _cairosvg()
