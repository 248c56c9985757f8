"""What users wait for, in units of ``geomcad solve 2013-3 --json`` CPU time (run on demand).

    python3 bench/bench_speed.py [--skip-variants]

Runs, one after the other in fresh processes, the baseline ``solve 2013-3 --json`` and the three
figures of issue 28: ``solve examples/shaper.toml --json``, ``build examples/shaper.toml --format
svg,pdf`` and ``variants examples/shaper.toml --count 30 --jobs 1`` (cards and answer key, the
vary ranges of bench_cohort.py). Each figure is the process's CPU time (user + system, children
included) divided by the baseline's, so a busy shared machine moves the units less than the
seconds. Budgets: 1.6, 3 and 40 units.

The package is measured as ``pip install .`` leaves it, its modules compiled to bytecode: the
commands run once first, without ``PYTHONDONTWRITEBYTECODE``, so that an editable install (or
an environment that sets the variable) does not charge the figures with compiling the sources
(0.3 s of the shaper's build).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SHAPER = str(ROOT / "examples" / "shaper.toml")
VARY = ["drive.omega=5..9:0.5", "group.2.length=0.14..0.2:0.005"]
#: The commands' environment: bytecode written and read, as after ``pip install .``.
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _cpu(argv: list[str]) -> tuple[float, float]:
    """CPU seconds (user + system, with the process's children) and wall seconds of ``argv``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=ENV)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime, wall


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--skip-variants", action="store_true", help="leave out the 30 variants")
    ns = ap.parse_args()
    exe = shutil.which("geomcad")
    base = [exe] if exe else [sys.executable, "-m", "geomcad"]
    with tempfile.TemporaryDirectory() as tmp:
        figures: list[tuple[str, list[str], float]] = [
            ("solve shaper --json", ["solve", SHAPER, "--json"], 1.6),
            ("build shaper svg,pdf",
             ["build", SHAPER, "--format", "svg,pdf", "--out", f"{tmp}/b"], 3.0),
        ]  # fmt: skip
        if not ns.skip_variants:
            cmd = ["variants", SHAPER, "--count", "30", "--seed", "2026", "--jobs", "1"]
            for v in VARY:
                cmd += ["--vary", v]
            figures.append(("variants shaper x30 --jobs 1", [*cmd, "--out", f"{tmp}/v"], 40.0))
        for argv in (["solve", "2013-3", "--json"], *(f[1] for f in figures[:2])):
            _cpu([*base, *argv])  # bytecode written once, as pip install does
        unit, unit_wall = _cpu([*base, "solve", "2013-3", "--json"])
        print(f"unit: solve 2013-3 --json = {unit:.2f} s CPU ({unit_wall:.2f} s wall)")
        worst = 0.0
        for name, argv, budget in figures:
            cpu, wall = _cpu([*base, *argv])
            units = cpu / unit
            worst = max(worst, units / budget)
            print(f"{name:30s} {cpu:7.2f} s CPU {wall:7.2f} s wall {units:6.2f} units"
                  f" (budget {budget:g})")  # fmt: skip
    return 0 if worst <= 1.0 else 1


if __name__ == "__main__":
    sys.exit(main())
