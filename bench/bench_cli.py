"""Time the commands a newcomer types first (run on demand, not in CI).

    python3 bench/bench_cli.py [--repeat N]

Each command runs as a fresh process (the interpreter's start-up included, as a user sees it);
the median of N runs is printed beside the 0.2 s the front door allows, as wall-clock time and as
the process's CPU time (user + system), which a busy machine inflates less. ``geomcad list`` and the
help texts read only the light spec modules (constructions/spec_*.py); the last line times
loading every construction module, the cost they avoid.
"""

from __future__ import annotations

import argparse
import resource
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


def _median_s(argv: list[str], repeat: int) -> tuple[float, float]:
    """Median wall-clock and CPU seconds of ``argv`` run ``repeat`` times."""
    walls, cpus = [], []
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)
        walls.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return statistics.median(walls), statistics.median(cpus)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    n = ap.parse_args().repeat
    exe = shutil.which("geomcad")
    base = [exe] if exe else [sys.executable, "-m", "geomcad"]
    worst = 0.0
    for cmd in COMMANDS:
        wall, cpu = _median_s(base + cmd, n)
        worst = max(worst, wall)
        mark = "ok" if wall < BUDGET_S else "OVER"
        print(
            f"geomcad {' '.join(cmd):<28} {wall * 1000:7.1f} ms wall, {cpu * 1000:7.1f} ms CPU"
            f"  ({mark}, budget {BUDGET_S} s)"
        )
    wall, cpu = _median_s([sys.executable, "-c", LOAD_ALL], n)
    print(f"{'(loading every construction module)':<36} {wall * 1000:7.1f} ms wall, "
          f"{cpu * 1000:7.1f} ms CPU")  # fmt: skip
    return 0 if worst < BUDGET_S else 1


if __name__ == "__main__":
    sys.exit(main())
