"""Work spread over processes, results in order, with a progress bar on a terminal.

:func:`pool` gives a ``map(fn, args)`` that runs ``fn(*a)`` for each argument tuple in up to
``jobs`` worker processes and returns the results in the order of ``args``: whatever process
did the work, the output is the same, so a parallel build writes the same bytes as a serial one.
``jobs`` = 1 works in this process.

:func:`bar` is a tqdm progress bar on stderr, shown only when stderr is a terminal.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from contextlib import contextmanager, suppress
from typing import Any

from geomcad.errors import ParameterError

Map = Callable[[Callable[..., Any], Sequence[tuple[Any, ...]]], list[Any]]


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


@contextmanager
def pool(jobs: int, tick: Callable[[int], None] | None = None) -> Iterator[Map]:
    """A mapper over ``jobs`` processes; ``tick(1)`` is called as each call finishes."""

    def serial(fn: Callable[..., Any], args: Sequence[tuple[Any, ...]]) -> list[Any]:
        out = []
        for a in args:
            out.append(fn(*a))
            if tick is not None:
                tick(1)
        return out

    if jobs <= 1:
        yield serial
        return
    with ProcessPoolExecutor(max_workers=jobs) as ex:

        def parallel(fn: Callable[..., Any], args: Sequence[tuple[Any, ...]]) -> list[Any]:
            futures: list[Future[Any]] = [ex.submit(_call, fn, a) for a in args]
            if tick is not None:
                for f in futures:
                    f.add_done_callback(lambda _f: tick(1))
            return [f.result() for f in futures]

        yield parallel


@contextmanager
def bar(total: int, unit: str, desc: str = "") -> Iterator[Callable[[int], None]]:
    """A progress bar on stderr when it is a terminal (nothing when piped or in a file)."""
    from tqdm import tqdm

    # no monitor thread: worker processes are forked while the bar runs
    tqdm.monitor_interval = 0
    show = sys.stderr.isatty()
    with tqdm(total=total, unit=unit, desc=desc, disable=not show, leave=False,
              file=sys.stderr) as t:  # fmt: skip
        yield t.update


def warm(file_ids: Sequence[str], raster: bool) -> None:
    """Import in this process what the workers will need, before they are forked: the kinds of
    the files (their modules load with :func:`geomcad.documents.load`) and, for PDF or PNG,
    cairosvg; each worker then starts with them instead of importing them again. A file that
    does not load is left for its worker to report."""
    from geomcad import documents
    from geomcad.errors import GeomcadError

    for pid in file_ids:
        with suppress(GeomcadError):
            documents.load(pid)
    if raster:
        from geomcad.render.raster import _cairosvg

        with suppress(GeomcadError):
            _cairosvg()
