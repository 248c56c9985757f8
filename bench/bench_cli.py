"""Time the commands a newcomer types first (run on demand, not in CI).

    python3 bench/bench_cli.py [--repeat N]

Each command runs as a fresh process (the interpreter's start-up included, as a user sees it);
the median of N runs is printed beside the 0.2 s the front door allows. ``geomcad list`` and the
help texts read only the light spec modules (constructions/spec_*.py); the last line times
loading every construction module, the cost they avoid.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import time

BUDGET_S = 0.2

COMMANDS = [
    ["list"],
    ["--help"],
    ["solve", "2013-6", "--help"],
    ["params", "2013-2"],
]

LOAD_ALL = (
    "from geomcad import registry\n"
    "for pid in registry.problem_ids():\n"
    "    registry.get(pid).build.resolve()\n"
)


def _median_s(argv: list[str], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    n = ap.parse_args().repeat
    exe = shutil.which("geomcad")
    base = [exe] if exe else [sys.executable, "-m", "geomcad"]
    worst = 0.0
    for cmd in COMMANDS:
        t = _median_s(base + cmd, n)
        worst = max(worst, t)
        mark = "ok" if t < BUDGET_S else "OVER"
        print(f"geomcad {' '.join(cmd):<28} {t * 1000:7.1f} ms  ({mark}, budget {BUDGET_S} s)")
    t = _median_s([sys.executable, "-c", LOAD_ALL], n)
    print(f"{'(loading every construction module)':<36} {t * 1000:7.1f} ms")
    return 0 if worst < BUDGET_S else 1


if __name__ == "__main__":
    sys.exit(main())
