"""Benchmark: the general linkage sweep against the bespoke six-bar kernel, and a sheet build.

Run on demand (not a test)::

    python3 bench/bench_linkage.py              # N = 10^3 … 10^6, best of 5
    python3 bench/bench_linkage.py --repeat 7   # best of 7
    python3 bench/bench_linkage.py --blocks     # also: the general sweep's speed per block size

Every column sweeps the same mechanism, 2013-6's six-bar, positions and velocities per crank
angle (a "position" is one crank angle):

- **linkage sweep**: ``examples/sixbar-2013-6.toml`` through :func:`geomcad.linkage.sweep`
  (order 1: positions and velocities of every joint, ω of every link, the slider's relative
  velocity and coordinate), the one kernel :mod:`geomcad.kinematics.chain`;
- **SixBar.sweep**: ``geomcad.solve("2013-6").data.mechanism.sweep``, since issue 13 a short
  definition on the same kernel (the plan built from the SixBar's dimensions);
- **reference**: the bespoke six-bar kernel that ``SixBar.sweep`` ran before issue 13 (positions
  and velocities of A, B, C, the slider's s and v, on component arrays in blocks), copied below
  verbatim as :func:`reference_kernel` *only* to keep this comparison measurable after the switch;
  the library does not use it;
- **pylinkage**: pylinkage's numba path ``Linkage.step_fast_with_kinematics`` (positions,
  velocities and accelerations: it has no compiled path for positions and velocities alone),
  when pylinkage and numba are installed (``pip install -e '.[bench]'``; model and JIT warm-up as
  in ``bench/bench_sixbar.py``).

The columns are measured interleaved, one run of each per round, and the best round of each is
kept (short runs repeated to 0.2 s, the garbage collector off), so that the load of other
processes on a shared machine hits them alike; one core. The clock is this process's CPU time
(``time.process_time``): on a machine shared with other busy processes the wall time counts
their turns too (``--wall`` uses ``time.perf_counter`` instead). The last lines time ``geomcad
build FILE --format svg,pdf`` of each example file in this process (solve, draw, render; CPU and
wall time), after a first build that pays the imports.
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
import math
import tempfile
import time
import tomllib
from collections.abc import Callable
from pathlib import Path

import numpy as np
import numpy.typing as npt

import geomcad
from geomcad import tol
from geomcad.cli import main
from geomcad.errors import NoIntersection, ParameterError
from geomcad.kinematics import SixBar, SweepResult
from geomcad.kinematics.chain import BLOCK, run
from geomcad.kinematics.sixbar import STEP_B, STEP_C, STEP_VB, STEP_VC, _Dims, _dims
from geomcad.linkage import parse, sweep
from geomcad.linkage.sweep import plan

ROOT = Path(__file__).resolve().parents[1]
NS = (10**3, 10**4, 10**5, 10**6)
Arr = npt.NDArray[np.float64]
Num = float | Arr


CLOCK = time.process_time


def rates(fs: list[Callable[[np.ndarray], object]], n: int, repeat: int) -> list[float]:
    """Positions per second of each f over n crank angles: the best of ``repeat`` interleaved
    rounds."""
    phi = np.linspace(0.0, 2.0 * math.pi, n)
    for f in fs:
        f(phi)
    best = [math.inf] * len(fs)
    gc.disable()
    try:
        for _ in range(repeat):
            for k, f in enumerate(fs):
                t0 = CLOCK()
                reps = 0
                while True:
                    f(phi)
                    reps += 1
                    if CLOCK() - t0 > 0.2:
                        break
                best[k] = min(best[k], (CLOCK() - t0) / reps)
    finally:
        gc.enable()
    return [n / b for b in best]


# --- REFERENCE ONLY: the bespoke six-bar kernel SixBar.sweep ran before issue 13 -------------
# Copied verbatim from geomcad/kinematics/sixbar.py as it was before SixBar became a definition
# on the general kernel, to keep the side-by-side comparison measurable. Not library code.

_scratch_buf: list[Arr] = []


def _scratch(size: int) -> Arr:
    if not _scratch_buf or _scratch_buf[0].size < size:
        _scratch_buf[:] = [np.empty(size)]
    return _scratch_buf[0][:size]


def _at(x: Num, sl: slice) -> Num:
    return x if isinstance(x, float) else x[sl]


def _any_below(x: Arr, limit: Num) -> bool:
    """True when some element of x is ≤ limit or NaN (the test on which a step fails)."""
    if isinstance(limit, float):
        return not bool(x.min() > limit)
    return bool(np.any(~(x > limit)))


def _raise(step: str, bad: npt.NDArray[np.bool_], i0: int, phi: Arr, why: str) -> None:
    """Raise NoIntersection naming ``step`` at the first position where ``bad`` holds."""
    if not np.all(np.isfinite(phi)):
        i = int(np.argmax(~np.isfinite(phi)))
        raise ParameterError(f"phi[{i0 + i}]", float(phi[i]), "a crank angle must be finite")
    if np.any(bad):
        i = int(np.argmax(bad))
        raise NoIntersection(
            step,
            f"{why} (first at position index {i0 + i}, φ = {math.degrees(phi[i]):.6g}°)",
        )


def reference_kernel(
    phi: Arr, g: _Dims, wl1_all: Num, br_b: int, br_c: int, block: int, with_velocities: bool
) -> SweepResult:
    """The closed forms of the dyads, block by block, on component arrays.

    RRR (B): with dv = O2 − A and d² = |dv|², the foot of B on AO2 is at k1 = a/d =
    1/2 + (l2² − l3²)/(2d²) of dv and B's height above it is k2 = h/d = ±√(l2²/d² − k1²) of
    dv turned 90°; so B − A = k1·dv + k2·dv⊥, B − O2 = (B − A) − dv, and the determinant of
    the velocity plan, (B − A) × (B − O2) = k2·d², vanishes exactly at the dead position.
    V_B solves (B − A)·V_B = (B − A)·V_A and (B − O2)·V_B = 0: V_B = g·(B − O2)⊥⁻ with
    g = (B − A)·V_A / det.

    RRP (C): with w = B − q, t0 = w·d its foot on the guide and hh = d × w its height above it,
    s = t0 ± √(l4² − hh²) and C = q + s·d; since (C − B)·d = ±√(l4² − hh²), projecting
    V_C = V_B + V_CB (⊥ CB) on CB gives v = d·V_B − hh·(d⊥·V_B) / (±√(l4² − hh²)).
    """
    n = phi.shape[0]
    # one allocation for every output: x and y rows of A, B, C (and V_A, V_B, V_C), s (and v)
    out = np.empty((14 if with_velocities else 7, n))
    pos = out[0:6].reshape(3, 2, n)
    vel = out[6:12].reshape(3, 2, n) if with_velocities else out[0:0].reshape(3, 2, 0)
    s_out = out[12] if with_velocities else out[6]
    v_out = out[13] if with_velocities else out[0:0].reshape(0)
    half_diff = 0.5 * (g.l2 * g.l2 - g.l3 * g.l3)
    l2sq = g.l2 * g.l2
    l4sq = g.l4 * g.l4
    # the tolerances of geomcad.geom's circle_circle / line_circle tangency, and of a dead
    # position (sin of the angle between the links), per position when the lengths vary
    touch_b = -tol.TANGENT * np.maximum(g.l2, g.l3) ** 2
    touch_c = -tol.TANGENT * l4sq
    dead_b = tol.ANGLE * g.l2 * g.l3
    dead_c = (tol.ANGLE * g.l4) ** 2
    b = min(block, max(n, 1))
    tmp = _scratch(10 * b).reshape(10, b)
    for i0 in range(0, n, b):
        i1 = min(i0 + b, n)
        sl = slice(i0, i1)
        k = i1 - i0
        t1, t2, dvx, dvy, d2, k1, k2, wx, wy, hh = (tmp[j, :k] for j in range(10))
        ph = phi[sl]
        ax, ay = pos[0, 0, sl], pos[0, 1, sl]
        bx, by = pos[1, 0, sl], pos[1, 1, sl]
        cx, cy = pos[2, 0, sl], pos[2, 1, sl]
        s = s_out[sl]
        l1, l2sq_, half_ = _at(g.l1, sl), _at(l2sq, sl), _at(half_diff, sl)
        dx, dy, qx, qy = _at(g.dx, sl), _at(g.dy, sl), _at(g.qx, sl), _at(g.qy, sl)

        # A = O1 + l1·(cos φ, sin φ)
        np.cos(ph, out=t1)
        np.sin(ph, out=t2)
        np.multiply(t1, l1, out=ax)
        ax += _at(g.o1x, sl)
        np.multiply(t2, l1, out=ay)
        ay += _at(g.o1y, sl)
        if with_velocities:
            # V_A = ω1 × O1A = ω1·l1·(−sin φ, cos φ)
            wl1 = _at(wl1_all, sl)
            np.multiply(t2, -wl1, out=vel[0, 0, sl])
            np.multiply(t1, wl1, out=vel[0, 1, sl])

        # B = circle(A, l2) ∩ circle(O2, l3)
        np.subtract(_at(g.o2x, sl), ax, out=dvx)
        np.subtract(_at(g.o2y, sl), ay, out=dvy)
        np.multiply(dvx, dvx, out=d2)
        np.multiply(dvy, dvy, out=t1)
        d2 += t1
        np.divide(1.0, d2, out=t2)
        np.multiply(t2, half_, out=k1)
        k1 += 0.5
        np.multiply(t2, l2sq_, out=k2)
        np.multiply(k1, k1, out=t1)
        k2 -= t1  # (h/d)²
        if _any_below(k2, 0.0):
            np.multiply(k2, d2, out=t1)  # h²
            _raise(
                STEP_B,
                ~(t1 >= _at(touch_b, sl)),
                i0,
                ph,
                "the dyad cannot close: the circles do not meet",
            )
            np.maximum(k2, 0.0, out=k2)
        np.sqrt(k2, out=k2)
        if with_velocities:
            np.multiply(k2, d2, out=d2)  # |det| = h·d = |AB × O2B|
            if _any_below(d2, _at(dead_b, sl)):
                _raise(
                    STEP_VB,
                    ~(d2 > _at(dead_b, sl)),
                    i0,
                    ph,
                    "the dyad is in a dead position (links AB and O2B collinear)",
                )
            if br_b < 0:
                np.negative(d2, out=d2)
        if br_b < 0:
            np.negative(k2, out=k2)
        np.multiply(dvx, k1, out=wx)
        np.multiply(dvy, k2, out=t1)
        wx -= t1  # (B − A)x
        np.multiply(dvy, k1, out=wy)
        np.multiply(dvx, k2, out=t1)
        wy += t1  # (B − A)y
        np.add(ax, wx, out=bx)
        np.add(ay, wy, out=by)
        if with_velocities:
            vbx, vby = vel[1, 0, sl], vel[1, 1, sl]
            np.multiply(wx, vel[0, 0, sl], out=t1)
            np.multiply(wy, vel[0, 1, sl], out=t2)
            t1 += t2
            t1 /= d2  # g = (B − A)·V_A / det
            np.subtract(wy, dvy, out=t2)  # (B − O2)y
            np.multiply(t1, t2, out=vbx)
            np.subtract(dvx, wx, out=t2)  # −(B − O2)x
            np.multiply(t1, t2, out=vby)

        # C = circle(B, l4) ∩ the guide q + s·d
        np.subtract(bx, qx, out=wx)
        np.subtract(by, qy, out=wy)
        np.multiply(wx, dx, out=s)
        np.multiply(wy, dy, out=t1)
        s += t1  # t0, B's foot on the guide
        np.multiply(wy, dx, out=hh)
        np.multiply(wx, dy, out=t1)
        hh -= t1  # d × (B − q)
        np.multiply(hh, hh, out=t2)
        np.subtract(_at(l4sq, sl), t2, out=t2)
        if _any_below(t2, 0.0):
            _raise(
                STEP_C,
                ~(t2 >= _at(touch_c, sl)),
                i0,
                ph,
                "the dyad cannot close: the line misses the circle",
            )
            np.maximum(t2, 0.0, out=t2)
        if with_velocities and _any_below(t2, _at(dead_c, sl)):
            _raise(
                STEP_VC,
                ~(t2 > _at(dead_c, sl)),
                i0,
                ph,
                "the rod BC is perpendicular to the guide",
            )
        np.sqrt(t2, out=t2)
        if br_c < 0:
            np.negative(t2, out=t2)
        s += t2
        np.multiply(s, dx, out=cx)
        cx += qx
        np.multiply(s, dy, out=cy)
        cy += qy
        if with_velocities:
            vbx, vby = vel[1, 0, sl], vel[1, 1, sl]
            v = v_out[sl]
            np.multiply(vbx, dx, out=v)
            np.multiply(vby, dy, out=t1)
            v += t1  # d·V_B
            np.multiply(vby, dx, out=k1)
            np.multiply(vbx, dy, out=t1)
            k1 -= t1  # d⊥·V_B
            k1 *= hh
            k1 /= t2
            v -= k1
            np.multiply(v, dx, out=vel[2, 0, sl])
            np.multiply(v, dy, out=vel[2, 1, sl])

    return SweepResult(
        phi,
        pos[0].T,
        pos[1].T,
        pos[2].T,
        vel[0].T,
        vel[1].T,
        vel[2].T,
        s_out,
        v_out,
    )


def reference_sweep(m: SixBar, phi: Arr, omega1: float) -> SweepResult:
    """The reference kernel on the six-bar's own dimensions."""
    g = _dims(m)
    return reference_kernel(phi, g, omega1 * float(g.l1), m.branch_B, m.branch_C, BLOCK, True)


# --- pylinkage -------------------------------------------------------------------------------


def pylinkage_kin(m: SixBar) -> Callable[[np.ndarray], object] | None:
    """pylinkage's numba kinematics path over len(phi) steps of the crank, or None when
    pylinkage or numba is missing."""
    if importlib.util.find_spec("pylinkage") is None or importlib.util.find_spec("numba") is None:
        return None
    from bench_sixbar import pylinkage_model

    lk, _ = pylinkage_model(m, 0.0, 0.1)
    lk.step_fast_with_kinematics(iterations=10)  # JIT

    def kin(phi: np.ndarray) -> object:
        n = phi.shape[0]
        model, _ = pylinkage_model(m, 0.0, 2.0 * math.pi / n)
        return model.step_fast_with_kinematics(iterations=n, dt=1.0)

    return kin


def main_() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--blocks", action="store_true", help="scan the general sweep's block size")
    ap.add_argument("--no-build", action="store_true", help="skip the build timings")
    ap.add_argument("--wall", action="store_true", help="time by the wall clock, not CPU time")
    args = ap.parse_args()
    global CLOCK
    if args.wall:
        CLOCK = time.perf_counter
    lk = parse(tomllib.loads((ROOT / "examples" / "sixbar-2013-6.toml").read_text()))
    m = geomcad.solve("2013-6").data.mechanism
    assert isinstance(m, SixBar)
    w = lk.omega
    # the three kernels are one mechanism: they must agree
    phi = np.linspace(0.0, 2.0 * math.pi, 1001)
    st, r, ref = sweep(lk, phi, order=1), m.sweep(phi, w), reference_sweep(m, phi, w)
    for name in "ABC":
        assert np.max(np.abs(st.pos[name] - getattr(ref, name))) <= 1e-12
        assert np.max(np.abs(st.vel[name] - getattr(ref, "V_" + name))) <= 1e-11
        assert np.array_equal(st.pos[name], getattr(r, name))
    kin = pylinkage_kin(m)
    fs: list[Callable[[np.ndarray], object]] = [
        lambda p: sweep(lk, p, order=1),
        lambda p: m.sweep(p, w),
        lambda p: reference_sweep(m, p, w),
    ]
    head = f"{'N':>8} | {'linkage sweep/s':>15} | {'SixBar.sweep/s':>14} | {'reference/s':>11}"
    head += f" | {'ref/linkage':>11}"
    if kin is not None:
        fs.append(kin)
        head += f" | {'pylinkage kin/s':>15} | {'linkage/pylinkage':>17}"
    clock = "wall" if args.wall else "CPU"
    print(
        f"positions + velocities per second ({clock} time),"
        f" best of {args.repeat} interleaved rounds"
    )
    print(head)
    for n in NS:
        got = rates(fs, n, args.repeat)
        line = (
            f"{n:>8} | {got[0]:15.3g} | {got[1]:14.3g} | {got[2]:11.3g} | {got[2] / got[0]:11.2f}"
        )
        if kin is not None:
            line += f" | {got[3]:15.3g} | {got[0] / got[3]:17.1f}"
        print(line, flush=True)
    if kin is None:
        print(
            "pylinkage column skipped: pylinkage or numba not installed (pip install -e '.[bench]')"
        )
    if args.blocks:
        ch = plan(lk)
        print("\nlinkage sweep by block size (positions + velocities per second)")
        print(
            f"{'block':>8}"
            + "".join(f"{'N = 10^' + str(round(math.log10(n))):>14}" for n in NS[1:])
        )
        for block in (2048, 4096, 8192, 16384, 32768):
            row = [rates([lambda p, b=block: run(ch, p, 1, b)], n, args.repeat)[0] for n in NS[1:]]
            mark = "  (default)" if block == BLOCK else ""
            print(f"{block:>8}" + "".join(f"{x:>14.3g}" for x in row) + mark, flush=True)
    if args.no_build:
        return
    with tempfile.TemporaryDirectory() as out:
        main(["build", str(ROOT / "examples" / "shaper.toml"), "--out", out, "--format", "svg"])
        for path in sorted((ROOT / "examples").glob("*.toml")):
            t0, c0 = time.perf_counter(), time.process_time()
            main(["build", str(path), "--out", out, "--format", "svg,pdf"])
            cpu, wall = time.process_time() - c0, time.perf_counter() - t0
            print(f"build {path.name}: {cpu:.2f} s CPU, {wall:.2f} s wall")


if __name__ == "__main__":
    main_()
