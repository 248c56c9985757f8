"""A cohort for a term: 30 variants' task cards (PDF) and answer key, timed on two cores.

    python3 bench/bench_cohort.py [TEMPLATE] [--jobs 2] [--count 30]

TEMPLATE is a problem id (default 2013-6, the six-bar synthesis: its variants each solve a
construction and a full-turn check) or a linkage file (``examples/slider-crank.toml``,
``examples/shaper.toml``: each variant solved, checked for its transmission angle over a turn
at 72 positions, and drawn with its scheme); others take ``--vary``. It runs the
command a teacher runs, ``geomcad variants``, once serially and once with ``--jobs``, into
temporary folders, checks that both wrote the same bytes, and prints the wall times. Run on
demand, not in CI.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

VARY = {
    "2013-6": ["H=0.15..0.25:0.01", "K=1.2..1.6:0.05", "e=0.2..0.35:0.01"],
    "2013-7": ["m2=8..12:0.5", "f=0.1..0.3:0.05", "theta_deg=35..55:1"],
    "2013-2": ["H=0.03..0.05:0.005", "r0=0.035..0.06:0.005", "law=linear|harmonic|cycloidal"],
    "examples/slider-crank.toml": [
        "drive.length=0.06..0.1:0.005",
        "group.1.length=0.2..0.4:0.01",
        "drive.omega=30..60:5",
    ],
    "examples/shaper.toml": ["drive.omega=5..9:0.5", "group.2.length=0.14..0.2:0.005"],
}


def run(template: str, vary: list[str], count: int, jobs: int, out: Path) -> float:
    cmd = [sys.executable, "-m", "geomcad", "variants", template, "--count", str(count),
           "--seed", "2026", "--out", str(out), "--jobs", str(jobs)]  # fmt: skip
    for v in vary:
        cmd += ["--vary", v]
    t = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("template", nargs="?", default="2013-6")
    ap.add_argument("--vary", action="append", default=None)
    ap.add_argument("--count", type=int, default=30)
    ap.add_argument("--jobs", type=int, default=2)
    ns = ap.parse_args()
    vary = ns.vary or VARY[ns.template]
    with tempfile.TemporaryDirectory() as tmp:
        a, b = Path(tmp, "serial"), Path(tmp, "jobs")
        t1 = run(ns.template, vary, ns.count, 1, a)
        tn = run(ns.template, vary, ns.count, ns.jobs, b)
        files = sorted(p.name for p in a.iterdir())
        same = files == sorted(p.name for p in b.iterdir()) and all(
            (a / f).read_bytes() == (b / f).read_bytes() for f in files
        )
        cards = sum(1 for f in files if f.startswith("card-"))
    print(f"{ns.template}: {cards} task cards + answer key ({len(files)} files)")
    print(f"  --jobs 1: {t1:.1f} s   --jobs {ns.jobs}: {tn:.1f} s   same bytes: {same}")


if __name__ == "__main__":
    main()
