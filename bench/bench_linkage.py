"""Benchmark: the general linkage sweep against the bespoke six-bar kernel, and a sheet build.

Run on demand (not a test)::

    python3 bench/bench_linkage.py              # N = 10^3 … 10^6, best of 5
    python3 bench/bench_linkage.py --repeat 9

Both columns sweep the same mechanism, 2013-6's six-bar: ``examples/sixbar-2013-6.toml`` through
:func:`geomcad.linkage.sweep` (order 1: positions and velocities of every joint, ω of every link,
relative velocities) and ``geomcad.solve("2013-6").data.mechanism`` through ``SixBar.sweep``
(positions and velocities of A, B, C and the slider's s and v). A "position" is one crank angle;
the rate is N over the best wall time (``time.perf_counter``, short runs repeated to 0.3 s, the
garbage collector off), on one core. The last lines time ``geomcad build FILE --format svg,pdf``
of each example file in this process (solve, draw, render), after a first build that pays the
imports.
"""

from __future__ import annotations

import argparse
import gc
import math
import tempfile
import time
import tomllib
from collections.abc import Callable
from pathlib import Path

import numpy as np

import geomcad
from geomcad.cli import main
from geomcad.linkage import parse, sweep

ROOT = Path(__file__).resolve().parents[1]
NS = (10**3, 10**4, 10**5, 10**6)


def rate(f: Callable[[np.ndarray], object], n: int, repeat: int) -> float:
    phi = np.linspace(0.0, 2.0 * math.pi, n)
    f(phi)
    best = math.inf
    gc.disable()
    try:
        for _ in range(repeat):
            t0 = time.perf_counter()
            reps = 0
            while True:
                f(phi)
                reps += 1
                if time.perf_counter() - t0 > 0.3:
                    break
            best = min(best, (time.perf_counter() - t0) / reps)
    finally:
        gc.enable()
    return n / best


def main_() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    lk = parse(tomllib.loads((ROOT / "examples" / "sixbar-2013-6.toml").read_text()))
    m = geomcad.solve("2013-6").data.mechanism
    print(f"{'N':>8} | {'linkage sweep /s':>16} | {'SixBar.sweep /s':>15} | ratio")
    for n in NS:
        g = rate(lambda p: sweep(lk, p, order=1), n, args.repeat)
        b = rate(lambda p: m.sweep(p, lk.omega), n, args.repeat)
        print(f"{n:>8} | {g:16.3g} | {b:15.3g} | {b / g:5.2f}")
    with tempfile.TemporaryDirectory() as out:
        main(["build", str(ROOT / "examples" / "shaper.toml"), "--out", out, "--format", "svg"])
        for path in sorted((ROOT / "examples").glob("*.toml")):
            t0 = time.perf_counter()
            main(["build", str(path), "--out", out, "--format", "svg,pdf"])
            print(f"build {path.name}: {time.perf_counter() - t0:.2f} s")


if __name__ == "__main__":
    main_()
