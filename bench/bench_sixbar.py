"""Benchmark: positions plus velocities of 2013-6's six-bar over N crank angles.

Run on demand (it is not a test; pytest does not collect it)::

    pip install -e '.[bench]'          # pylinkage and numba, for the comparison
    python3 bench/bench_sixbar.py      # the table below, N = 10^3 … 10^6
    python3 bench/bench_sixbar.py --blocks     # also: the sweep's speed per block size
    python3 bench/bench_sixbar.py --repeat 9   # best of 9 runs instead of 5

The mechanism is the one ``geomcad.solve("2013-6")`` synthesizes (its ``data.mechanism``): crank
O1A, coupler AB, rocker O2B, link BC and the slider C on a horizontal guide. One "position" is the
three joints A, B, C with their velocities V_A, V_B, V_C at one crank angle; the rate is N divided
by the wall time, best of ``--repeat`` runs or more (``time.perf_counter``; short runs are
repeated until they add up to a second; the garbage collector is off during a run, as in
``timeit``), on one core.

Columns, all measured in the same run:

- **geomcad**: ``SixBar.sweep(phi)``, the sweep API that the sheets and the tests use (DESIGN.md
  rule 13: the benchmark measures the same code, no kernel of its own): the one sweep kernel of
  every lever mechanism (``geomcad.kinematics.chain``; blocked numpy, closed-form groups, in-place
  temporaries, one output allocation) on the six-bar's plan.
- **loop**: a plain Python loop over the scalar construction, one crank angle at a time:
  ``geomcad.geom.circle_circle`` for B, ``line_circle`` for C, and the velocity plan's vector
  equations in ``Vec`` arithmetic. It is slow, so above N = 10^4 it is timed on 10^4 of the
  angles, spread over the turn (its rate does not depend on N; the table marks those rows ``*``).
- **pylinkage**: pylinkage 1.3 (``Crank`` + ``RRRDyad`` + ``RRPDyad``, the slider being an RRP dyad
  on the line through two ground points) on its numba-compiled path. pylinkage has no compiled path
  for positions and velocities alone: ``Linkage.step_fast_with_kinematics`` gives positions,
  velocities and accelerations (its "kinematics path", the issue's target), and it is compared with
  our sweep. Its ``Linkage.step_fast`` gives positions only and is compared, in a second table,
  with ``SixBar.positions`` (the same blocked kernel without the velocities). Both pylinkage paths
  are warmed up (JIT) and their solver data compiled before timing. The deviation columns are the
  largest distance between pylinkage's joints (and velocities) and ours at the same angles:
  pylinkage advances the crank by Δφ per step, so its angle drifts by rounding over a long run.

Without pylinkage or numba the script says so in one line and prints the rest.
"""

from __future__ import annotations

import argparse
import dataclasses
import gc
import importlib
import importlib.metadata
import math
import platform
import sys
import time
from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np

import geomcad
from geomcad.geom import Circle, Line, Vec, circle_circle, line_circle
from geomcad.kinematics import BLOCK, SixBar

NS = (10**3, 10**4, 10**5, 10**6)
LOOP_MAX = 10**4
MIN_TOTAL = 1.0  # s
MAX_RUNS = 200


def best_of(repeat: int, run: Callable[[], Any], setup: Callable[[], Any] | None = None) -> float:
    """The shortest wall time of at least ``repeat`` runs, and of more while they add up to less
    than ``MIN_TOTAL`` seconds (short runs are repeated more often: other processes on the
    machine only ever make a run slower). ``setup`` runs before each, untimed."""
    best, total, runs = math.inf, 0.0, 0
    while runs < repeat or (total < MIN_TOTAL and runs < MAX_RUNS):
        if setup is not None:
            setup()
        gc.disable()  # as timeit does: collecting what earlier imports left is not the run's cost
        try:
            t0 = time.perf_counter()
            run()
            dt = time.perf_counter() - t0
        finally:
            gc.enable()
        best, total, runs = min(best, dt), total + dt, runs + 1
    return best


# --- (b) the scalar construction, one crank angle at a time --------------------------------------


def scalar_loop(m: SixBar, phis: np.ndarray) -> list[tuple[Vec, ...]]:
    """A, B, C, V_A, V_B, V_C per angle by geomcad.geom's intersections and the velocity plan's
    vector equations, in plain Python floats (ω1 = 1)."""
    out: list[tuple[Vec, ...]] = []
    o1, o2 = m.O1, m.O2
    d = m.guide_d.unit()
    path = Line(m.guide_p, d)
    k2 = Circle(o2, m.l3)
    for phi in phis.tolist():
        a = o1 + Vec.polar(m.l1, phi)
        bs = circle_circle(Circle(a, m.l2), k2)  # left of A → O2 first
        b = bs[0] if m.branch_B > 0 or len(bs) == 1 else bs[1]
        cs = line_circle(path, Circle(b, m.l4))  # ascending along the guide
        c = cs[-1] if m.branch_C > 0 else cs[0]
        va = (a - o1).perp()  # V_A = ω1 × O1A
        # V_B = V_A + V_BA (⊥ AB) = V_BO2 (⊥ O2B)
        e1, e2 = b - a, b - o2
        g = e1.dot(va) / e1.cross(e2)
        vb = Vec(g * e2.y, -g * e2.x)
        # V_C = V_B + V_CB (⊥ CB), V_C ∥ the guide
        e = c - b
        vc = d * (e.dot(vb) / e.dot(d))
        out.append((a, b, c, va, vb, vc))
    return out


# --- (c) pylinkage ------------------------------------------------------------------------------


def pylinkage_missing() -> str | None:
    """Why the pylinkage columns cannot be measured, or None when they can."""
    missing = []
    for name in ("pylinkage", "numba"):
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    if missing:
        return (
            f"pylinkage comparison skipped: {' and '.join(missing)} not installed "
            "(pip install -e '.[bench]')"
            + ("; without numba pylinkage runs pure Python" if "numba" in missing else "")
        )
    return None


def pylinkage_model(m: SixBar, phi0: float, dphi: float) -> tuple[Any, Any]:
    """The six-bar in pylinkage: crank A, RRR dyad B, RRP dyad C on the line G1G2. The crank
    steps by dphi before each recorded position, so it starts at phi0 − dphi; B and C start at
    our assembly (pylinkage then keeps the solution nearest the previous one)."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRPDyad, RRRDyad
    from pylinkage.simulation import Linkage

    o1 = Ground(m.O1.x, m.O1.y, name="O1")
    o2 = Ground(m.O2.x, m.O2.y, name="O2")
    g1 = Ground(m.guide_p.x, m.guide_p.y, name="G1")
    g2 = Ground(m.guide_p.x + m.guide_d.x, m.guide_p.y + m.guide_d.y, name="G2")
    crank = Crank(o1, m.l1, angular_velocity=dphi, initial_angle=phi0 - dphi, name="A")
    _, b, c = m.positions(np.array([phi0 - dphi]))
    jb = RRRDyad(crank.output, o2, m.l2, m.l3, x=b[0, 0], y=b[0, 1], name="B")
    jc = RRPDyad(jb, g1, g2, m.l4, x=c[0, 0], y=c[0, 1], name="C")
    lk = Linkage([o1, o2, g1, g2, crank, jb, jc], name="2013-6")
    lk.set_input_velocity(crank, omega=1.0)  # ω1 = 1 rad/s for the velocities
    lk.compile()
    return lk, crank


# --- the run ------------------------------------------------------------------------------------


@dataclasses.dataclass
class Row:
    n: int
    ours: float
    ours_pos: float
    loop: float
    loop_n: int
    pl_kin: float = math.nan
    pl_pos: float = math.nan
    dev_pos: float = math.nan
    dev_vel: float = math.nan


def measure(m: SixBar, n: int, repeat: int, with_pylinkage: bool) -> Row:
    dphi = 2.0 * math.pi / n
    phi = np.arange(n) * dphi
    t_ours = best_of(repeat, lambda: m.sweep(phi))
    few = phi[:: max(1, n // LOOP_MAX)]  # at most LOOP_MAX angles, spread over the turn
    t_loop = best_of(repeat, lambda: scalar_loop(m, few))
    t_pos = best_of(repeat, lambda: m.positions(phi))
    row = Row(n, n / t_ours, n / t_pos, few.size / t_loop, few.size)
    # the loop and the sweep are the same construction: they must agree
    ref = m.sweep(few)
    pts = scalar_loop(m, few)
    got = np.array([[list(p) for p in pos] for pos in pts])  # (angles, 6, 2)
    want = np.stack([ref.A, ref.B, ref.C, ref.V_A, ref.V_B, ref.V_C], axis=1)
    assert np.max(np.abs(got - want)) <= 1e-12, "the loop and the sweep disagree"
    if not with_pylinkage:
        return row
    holder: dict[str, Any] = {}

    def fresh() -> None:
        holder["lk"], _ = pylinkage_model(m, 0.0, dphi)

    def kin() -> None:
        holder["out"] = holder["lk"].step_fast_with_kinematics(iterations=n, dt=1.0)

    def pos() -> None:
        holder["traj"] = holder["lk"].step_fast(iterations=n, dt=1.0)

    row.pl_kin = n / best_of(repeat, kin, fresh)
    row.pl_pos = n / best_of(repeat, pos, fresh)
    r = m.sweep(phi)
    p_pl, v_pl, _ = holder["out"]
    ours_p = np.stack([r.A, r.B, r.C], axis=1)
    ours_v = np.stack([r.V_A, r.V_B, r.V_C], axis=1)
    row.dev_pos = float(np.max(np.hypot(*(p_pl[:, 4:7] - ours_p).transpose(2, 0, 1))))
    row.dev_vel = float(np.max(np.hypot(*(v_pl[:, 4:7] - ours_v).transpose(2, 0, 1))))
    assert np.max(np.abs(holder["traj"][:, 4:7] - p_pl[:, 4:7])) == 0.0
    return row


def block_scan(m: SixBar, repeat: int) -> None:
    print("\nSixBar.sweep by block size (positions + velocities per second):")
    print(f"{'block':>8}" + "".join(f"{'N = 10^' + str(round(math.log10(n))):>14}" for n in NS[1:]))
    for block in (1024, 2048, 4096, 8192, 16384, 32768, 65536):
        rates = []
        for n in NS[1:]:
            phi = np.arange(n) * (2.0 * math.pi / n)
            rates.append(n / best_of(repeat, partial(m.sweep, phi, block=block)))
        mark = "  (default)" if block == BLOCK else ""
        print(f"{block:>8}" + "".join(f"{r:>14.3g}" for r in rates) + mark)


def version(name: str) -> str:
    try:
        return importlib.metadata.version(name)
    except importlib.metadata.PackageNotFoundError:
        return "missing"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs per figure; the best is kept")
    ap.add_argument("--blocks", action="store_true", help="also scan the sweep's block size")
    args = ap.parse_args(argv)

    m = geomcad.solve("2013-6").data.mechanism
    assert isinstance(m, SixBar)
    why_not = pylinkage_missing()
    print(
        "2013-6 six-bar, positions + velocities of A, B, C per crank angle "
        f"(l1 = {m.l1:.4f}, l2 = {m.l2:.4f}, l3 = {m.l3:g}, l4 = {m.l4:g} m)"
    )
    print(
        f"Python {platform.python_version()}, numpy {np.__version__}, "
        f"pylinkage {version('pylinkage')}, numba {version('numba')}; "
        f"{platform.processor() or platform.machine()}; best of >= {args.repeat} runs; "
        f"sweep block {BLOCK}"
    )
    if why_not:
        print(why_not)
    else:  # JIT-compile pylinkage's solvers (cached by numba) before anything is timed
        lk, _ = pylinkage_model(m, 0.0, 0.1)
        lk.step_fast_with_kinematics(iterations=10)
        lk.step_fast(iterations=10)
    rows = [measure(m, n, args.repeat, why_not is None) for n in NS]

    def cell(x: float, spec: str, width: int, unit: str = "") -> str:
        return f"{(format(x, spec) + unit) if math.isfinite(x) else '-':>{width}}"

    print()
    print("positions + velocities of A, B, C per second")
    print(
        f"{'N':>9} {'geomcad':>10} {'loop':>10} {'pylinkage':>11} {'geomcad/':>9} {'geomcad/':>10}"
        f" {'max deviation of pylinkage':>27}"
    )
    print(
        f"{'':>9} {'sweep':>10} {'(scalar)':>10} {'numba kin.':>11} {'loop':>9} {'pylinkage':>10}"
        f" {'positions m':>13} {'velocities m/s':>14}"
    )
    for r in rows:
        loop = f"{r.loop:.3g}" + ("*" if r.loop_n < r.n else " ")
        print(
            f"{r.n:>9} {r.ours:>10.3g} {loop:>10} {cell(r.pl_kin, '.3g', 11)}"
            f" {cell(r.ours / r.loop, '.0f', 9, 'x')} {cell(r.ours / r.pl_kin, '.1f', 10, 'x')}"
            f" {cell(r.dev_pos, '.1e', 13)} {cell(r.dev_vel, '.1e', 14)}"
        )
    print(f"* loop timed on {LOOP_MAX} of the N angles, spread over the turn")
    print(
        "pylinkage numba kin. = Linkage.step_fast_with_kinematics (positions, velocities and "
        "accelerations:\n  pylinkage has no compiled path for positions and velocities alone)"
    )
    print()
    print("positions of A, B, C only, per second")
    print(f"{'N':>9} {'geomcad':>12} {'pylinkage':>11} {'geomcad/':>10}")
    print(f"{'':>9} {'positions()':>12} {'step_fast':>11} {'pylinkage':>10}")
    for r in rows:
        print(
            f"{r.n:>9} {r.ours_pos:>12.3g} {cell(r.pl_pos, '.3g', 11)}"
            f" {cell(r.ours_pos / r.pl_pos, '.1f', 10, 'x')}"
        )
    print()
    big = [r for r in rows if r.n >= 10**4]
    low = min(r.ours for r in big)
    print(
        f"targets for N >= 10^4: >= 1e7 positions+velocities/s: "
        f"{'met' if low >= 1e7 else 'NOT met'} (lowest {low:.3g}/s)",
        end="",
    )
    if why_not is None:
        k = min(r.ours / r.pl_kin for r in big)
        kp = min(r.ours_pos / r.pl_pos for r in big)
        print(
            f"; >= 5x pylinkage's numba kinematics path: {'met' if k >= 5 else 'NOT met'} "
            f"(lowest {k:.1f}x; positions only against step_fast: lowest {kp:.1f}x)"
        )
    else:
        print("; pylinkage ratio not measured")
    if args.blocks:
        block_scan(m, args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
