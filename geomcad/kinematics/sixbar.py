"""The six-bar of problem 2013-6: crank-rocker O1ABO2 driving slider C through link BC.

Positions, velocities and accelerations over whole arrays of crank angles (and over arrays of
dimensions: many variants at once), and the check by analysis: the slider's actual stroke and
coefficient of velocity change over a turn.

The sweep (:meth:`SixBar.sweep`) is the one implementation of positions and velocities; the other
methods read from it. It runs the dyads' closed forms on the x and y component arrays, in blocks
of :data:`BLOCK` crank angles so that the temporaries stay in the cache, writing into
preallocated outputs. With B on a fixed side of A → O2 and C on a fixed side of B's foot on the
guide for the whole sweep, the mechanism never jumps to its other assembly mode.
"""

from __future__ import annotations

import dataclasses
import math
import threading
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq

from geomcad import tol
from geomcad.errors import ConstructionError, DegenerateInput, NoIntersection, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.dyads import (
    Arr,
    angular_acceleration,
    angular_velocity,
    cross,
    perp,
    rrp_acceleration,
    rrr_acceleration,
)

#: Samples per turn for locating the slider's extreme positions before refining them.
SWEEP_SAMPLES = 3600

#: Crank angles per block of a sweep. Ten scratch arrays and fourteen output rows of a block are
#: in use at once; at 16384 elements (128 KiB each) the scratch stays in a 1 MiB L2 cache.
#: Measured with ``python3 bench/bench_sixbar.py --blocks``: 4096 is 15–20 % slower, 1024 twice
#: as slow (numpy's per-call overhead), 32768 and 65536 no faster.
BLOCK = 16384

#: The steps a sweep can fail at (the names the recorded constructions use).
STEP_B = "B = circle(A, l2) ∩ circle(O2, l3)"
STEP_C = "C = circle(B, l4) ∩ slider path"
STEP_VB = "velocity of B"
STEP_VC = "velocity of C"
STEP_AB = "acceleration of B"
STEP_AC = "acceleration of C"

#: A number, or an array of shape (N,) with one value per position of the sweep.
Num = float | Arr


def grashof_crank_rocker(l1: float, l2: float, l3: float, l0: float) -> bool:
    """True when the four-bar with crank l1, coupler l2, rocker l3 and frame l0 is a crank-rocker.

    Grashof: s + l < p + q with the crank the shortest link (equality, a change-point mechanism,
    does not count: it can fold into the other assembly mode).
    """
    links = sorted((l1, l2, l3, l0))
    s, p, q, lng = links
    margin = (p + q) - (s + lng)
    return l1 <= s and margin > tol.REL_LENGTH * lng


@dataclass(frozen=True)
class SweepResult:
    """The six-bar at N positions: joints and their velocities, the slider along its guide.

    Points and velocities are ``(N, 2)`` arrays (views on component-wise storage, so ``A[:, 0]``
    is contiguous), ``phi``, ``s`` and ``v`` are ``(N,)``. ``s`` is C's coordinate along the guide
    from ``guide_p`` (m), ``v`` its velocity along the guide (m/s; the analogue S' for ω1 = 1).
    """

    phi: Arr
    A: Arr
    B: Arr
    C: Arr
    V_A: Arr
    V_B: Arr
    V_C: Arr
    s: Arr
    v: Arr


@dataclass(frozen=True)
class _Dims:
    """The dimensions of one sweep, each a number or an ``(N,)`` array (one value per position)."""

    o1x: Num
    o1y: Num
    l1: Num
    l2: Num
    o2x: Num
    o2y: Num
    l3: Num
    l4: Num
    qx: Num
    qy: Num
    dx: Num
    dy: Num


@dataclass(frozen=True)
class SixBar:
    """Crank O1A (l1), coupler AB (l2), rocker O2B (l3), link BC (l4), slider C on a guide.

    ``guide_p`` and unit ``guide_d`` give the slider's line; ``branch_B`` (±1) is B's side of
    the directed line A → O2 and ``branch_C`` (±1) C's side along the guide from B's foot: both
    fixed for the whole turn. φ is the crank angle from +x, counter-clockwise. The links are
    numbered as in the subject: 1 crank, 2 coupler AB, 3 rocker O2B, 4 link BC, 5 slider.
    """

    O1: Vec
    l1: float
    l2: float
    O2: Vec
    l3: float
    l4: float
    guide_p: Vec
    guide_d: Vec
    branch_B: int
    branch_C: int

    @cached_property
    def _dims(self) -> _Dims:
        """The mechanism's own dimensions, checked once (the unit guide direction)."""
        return _dims(self)

    def sweep(
        self,
        phi: npt.ArrayLike,
        omega1: npt.ArrayLike = 1.0,
        *,
        block: int = BLOCK,
        O1: npt.ArrayLike | None = None,
        l1: npt.ArrayLike | None = None,
        l2: npt.ArrayLike | None = None,
        O2: npt.ArrayLike | None = None,
        l3: npt.ArrayLike | None = None,
        l4: npt.ArrayLike | None = None,
        guide_p: npt.ArrayLike | None = None,
        guide_d: npt.ArrayLike | None = None,
    ) -> SweepResult:
        """Positions and velocities at crank angles ``phi`` (rad) and crank speed ``omega1``.

        Each step is the dyad's closed form on whole arrays: A on the crank circle; B =
        circle(A, l2) ∩ circle(O2, l3) on ``branch_B``; C = circle(B, l4) ∩ the guide on
        ``branch_C``; V_A = ω1 × O1A; V_B from V_B = V_A + V_BA (⊥ AB) = V_BO2 (⊥ O2B); V_C
        from V_C = V_B + V_CB (⊥ CB), V_C ∥ the guide.

        Many variants at once: any dimension given here replaces the mechanism's own and may be
        an array with one value per position (lengths ``(N,)``, points ``(N, 2)``), and so may
        ``phi`` and ``omega1``; they broadcast to one length N (a number goes with every
        position). Position i is then variant i at angle ``phi[i]``.

        Raises :class:`NoIntersection` naming the step (and the first position index and angle)
        where a dyad cannot close or is in a dead position (V_B or V_C undefined);
        :class:`ParameterError` for a non-positive length, a non-finite angle or arrays of
        different lengths; :class:`DegenerateInput` for a zero guide direction.

        >>> import math
        >>> m = SixBar(Vec(0, 0), 0.1, 0.4, Vec(0.3, 0), 0.3, 0.3, Vec(0, 0.3), Vec(1, 0), 1, 1)
        >>> r = m.sweep([0.0, math.pi / 2], omega1=10.0)
        >>> r.B.shape, r.V_C.shape
        ((2, 2), (2, 2))
        >>> [round(math.dist(a, b), 12) for a, b in zip(r.A, r.B)]
        [0.4, 0.4]
        >>> m.sweep(0.0, l1=[0.1, 0.12, 0.14]).A[:, 0].round(12).tolist()  # three cranks at once
        [0.1, 0.12, 0.14]
        """
        return _sweep(self, phi, omega1, block, True, O1, l1, l2, O2, l3, l4, guide_p, guide_d)

    def positions(self, phi: npt.ArrayLike) -> tuple[Arr, Arr, Arr]:
        """A, B, C as ``(N, 2)`` arrays for crank angles ``phi`` (rad).

        The positions part of :meth:`sweep`: a dead position (where the velocities are
        undefined) is no error here.
        """
        r = _sweep(self, phi, 1.0, BLOCK, False)
        return r.A, r.B, r.C

    def velocities(self, phi: npt.ArrayLike, omega1: float = 1.0) -> tuple[Arr, Arr, Arr]:
        """V_A, V_B, V_C for crank angles ``phi`` at crank speed ``omega1`` (rad/s, ccw > 0)."""
        r = self.sweep(phi, omega1)
        return r.V_A, r.V_B, r.V_C

    def accelerations(
        self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0
    ) -> tuple[Arr, Arr, Arr]:
        """a_A, a_B, a_C as ``(N, 2)`` arrays at crank speed ``omega1`` (rad/s) and crank
        acceleration ``eps1`` (rad/s², both ccw > 0).

        a_A = a^n_A (ω1²·l1 towards O1) + a^τ_A (ε1·l1, ⊥ O1A); a_B from a_B = a_A + a^n_BA +
        a^τ_BA = a^n_BO2 + a^τ_BO2 (:func:`~geomcad.kinematics.dyads.rrr_acceleration`); a_C
        from a_C = a_B + a^n_CB + a^τ_CB with a_C ∥ the guide
        (:func:`~geomcad.kinematics.dyads.rrp_acceleration`). With ω1 = 1 and ε1 = 0 these are
        the acceleration analogues. Dead positions raise :class:`NoIntersection` naming the step.
        """
        r = self.sweep(phi, omega1)
        return self._accelerations(r, omega1, eps1)

    def _accelerations(self, r: SweepResult, omega1: float, eps1: float) -> tuple[Arr, Arr, Arr]:
        rel = r.A - self.O1.array()
        a_a = -(omega1 * omega1) * rel + eps1 * perp(rel)
        zero = np.zeros(2)
        a_b = rrr_acceleration(r.A, r.V_A, a_a, self.O2.array(), zero, zero, r.B, r.V_B, STEP_AB)
        a_c = rrp_acceleration(r.B, r.V_B, a_b, r.C, r.V_C, self._unit_guide(), STEP_AC)
        return a_a, a_b, a_c

    def omegas(self, phi: npt.ArrayLike, omega1: float = 1.0) -> tuple[Arr, Arr, Arr]:
        """Angular velocities (rad/s, ccw > 0) of the coupler AB (ω2), the rocker O2B (ω3) and
        the link BC (ω4): ω = V_QP / l_PQ with the sense of V_QP about P."""
        r = self.sweep(phi, omega1)
        zero = np.zeros(2)
        return (
            angular_velocity(r.A, r.V_A, r.B, r.V_B),
            angular_velocity(self.O2.array(), zero, r.B, r.V_B),
            angular_velocity(r.B, r.V_B, r.C, r.V_C),
        )

    def epsilons(
        self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0
    ) -> tuple[Arr, Arr, Arr]:
        """Angular accelerations (rad/s², ccw > 0) of the coupler AB (ε2), the rocker O2B (ε3)
        and the link BC (ε4): ε = a^τ_QP / l_PQ with the sense of a^τ_QP about P."""
        r = self.sweep(phi, omega1)
        a_a, a_b, a_c = self._accelerations(r, omega1, eps1)
        zero = np.zeros(2)
        return (
            angular_acceleration(r.A, a_a, r.B, a_b),
            angular_acceleration(self.O2.array(), zero, r.B, a_b),
            angular_acceleration(r.B, a_b, r.C, a_c),
        )

    def slider_s(self, phi: npt.ArrayLike) -> Arr:
        """The slider's coordinate along its guide from ``guide_p`` (m)."""
        return _sweep(self, phi, 1.0, BLOCK, False).s

    def slider_v(self, phi: npt.ArrayLike, omega1: float = 1.0) -> Arr:
        """The slider's velocity along its guide (m/s at ``omega1``; the analogue for ω1 = 1)."""
        return self.sweep(phi, omega1).v

    def slider_a(self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0) -> Arr:
        """The slider's acceleration along its guide (m/s² at ``omega1`` and ``eps1``; with
        ω1 = 1 and ε1 = 0 the acceleration analogue S'')."""
        _, _, a_c = self.accelerations(phi, omega1, eps1)
        return np.asarray(a_c @ self._unit_guide(), dtype=np.float64)

    def _unit_guide(self) -> Arr:
        d = self.guide_d.array()
        return np.asarray(d / math.hypot(d[0], d[1]), dtype=np.float64)

    def stroke_and_k(self) -> tuple[float, float, float, float]:
        """The slider's stroke H, the coefficient of velocity change K, and the crank angles of
        its two extreme positions, measured by running the crank through a full turn.

        The extremes are located on a sweep of ``SWEEP_SAMPLES`` angles and refined as roots of
        the slider's velocity analogue (brentq). K is the ratio of the larger to the smaller of
        the two crank angles between the extremes.
        """
        phi = np.linspace(0.0, 2.0 * math.pi, SWEEP_SAMPLES, endpoint=False)
        v = self.slider_v(phi)
        sign_change = np.nonzero(np.signbit(v) != np.signbit(np.roll(v, -1)))[0]
        if sign_change.size < 2:
            raise ConstructionError(
                "check by analysis", "the slider does not reverse over a crank turn"
            )
        step = 2.0 * math.pi / SWEEP_SAMPLES

        def f(x: float) -> float:
            return float(self.slider_v(np.array([x]))[0])

        roots = [brentq(f, phi[i], phi[i] + step, xtol=tol.ROOT_ANGLE) for i in sign_change]
        s = self.slider_s(np.array(roots))
        i_max, i_min = int(np.argmax(s)), int(np.argmin(s))
        stroke = float(s[i_max] - s[i_min])
        phi_max, phi_min = float(roots[i_max]), float(roots[i_min])
        a = (phi_max - phi_min) % (2.0 * math.pi)
        k = max(a, 2.0 * math.pi - a) / min(a, 2.0 * math.pi - a)
        return stroke, k, phi_min, phi_max


def branch_sign(a: Vec, o2: Vec, b: Vec) -> int:
    """The RRR branch flag of B: +1 when B lies left of the directed line A → O2."""
    return 1 if cross((o2 - a).array(), (b - a).array()) > 0.0 else -1


# --- the sweep ---------------------------------------------------------------------------------


def _length(name: str, value: npt.ArrayLike) -> Num:
    a = np.asarray(value, dtype=np.float64)
    bad = ~(np.isfinite(a) & (a > 0.0))
    if np.any(bad):
        v = float(a) if a.ndim == 0 else float(a.reshape(-1)[int(np.argmax(bad))])
        raise ParameterError(name, v, "must be a finite length > 0")
    if a.ndim == 0:
        return float(a)
    if a.ndim != 1:
        raise ParameterError(name, a.shape, "must be a number or an array of shape (N,)")
    return a


def _point(name: str, value: npt.ArrayLike) -> tuple[Num, Num]:
    a = np.asarray(value, dtype=np.float64)
    if a.shape[-1:] != (2,) or a.ndim > 2:
        raise ParameterError(name, a.shape, "must be a point (x, y) or an array of shape (N, 2)")
    if not np.all(np.isfinite(a)):
        raise ParameterError(name, "non-finite", "must have finite coordinates")
    if a.ndim == 1:
        return float(a[0]), float(a[1])
    return a[:, 0], a[:, 1]


def _spread(values: dict[str, Num], n: int) -> dict[str, Num]:
    """Each array broadcast to length n (contiguous, so that a block is a plain slice)."""
    out: dict[str, Num] = {}
    for k, v in values.items():
        if isinstance(v, float):
            out[k] = v
        else:
            try:
                out[k] = np.ascontiguousarray(np.broadcast_to(v, (n,)))
            except ValueError:
                raise ParameterError(
                    k, v.shape, f"does not match the {n} positions of the sweep"
                ) from None
    return out


_local = threading.local()


def _scratch(size: int) -> Arr:
    """This thread's scratch buffer for a sweep's temporaries, kept between sweeps: a fresh one
    each time would cost the page faults of a new allocation on every call."""
    buf: Arr | None = getattr(_local, "scratch", None)
    if buf is None or buf.size < size:
        buf = np.empty(size)
        _local.scratch = buf
    return buf[:size]


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


def _dims(
    m: SixBar,
    O1: npt.ArrayLike | None = None,
    l1: npt.ArrayLike | None = None,
    l2: npt.ArrayLike | None = None,
    O2: npt.ArrayLike | None = None,
    l3: npt.ArrayLike | None = None,
    l4: npt.ArrayLike | None = None,
    guide_p: npt.ArrayLike | None = None,
    guide_d: npt.ArrayLike | None = None,
) -> _Dims:
    """The checked dimensions: the mechanism's own, or the arrays that replace them."""
    if m.branch_B not in (1, -1) or m.branch_C not in (1, -1):
        raise ParameterError("branch", (m.branch_B, m.branch_C), "must be +1 or −1")
    o1x, o1y = _point("O1", m.O1.array() if O1 is None else O1)
    o2x, o2y = _point("O2", m.O2.array() if O2 is None else O2)
    qx, qy = _point("guide_p", m.guide_p.array() if guide_p is None else guide_p)
    dx, dy = _point("guide_d", m.guide_d.array() if guide_d is None else guide_d)
    dn = np.hypot(dx, dy)
    if not np.all(dn > 0.0):
        raise DegenerateInput("slider path", "the guide direction is a zero vector")
    dx, dy = dx / dn, dy / dn
    la, lb, lc, ld = (
        _length(n, getattr(m, n) if v is None else v)
        for n, v in (("l1", l1), ("l2", l2), ("l3", l3), ("l4", l4))
    )
    return _Dims(*(_num(x) for x in (o1x, o1y, la, lb, o2x, o2y, lc, ld, qx, qy, dx, dy)))


def _num(x: npt.ArrayLike) -> Num:
    a = np.asarray(x, dtype=np.float64)
    return float(a) if a.ndim == 0 else a


def _sweep(
    m: SixBar,
    phi: npt.ArrayLike,
    omega1: npt.ArrayLike,
    block: int,
    with_velocities: bool,
    O1: npt.ArrayLike | None = None,
    l1: npt.ArrayLike | None = None,
    l2: npt.ArrayLike | None = None,
    O2: npt.ArrayLike | None = None,
    l3: npt.ArrayLike | None = None,
    l4: npt.ArrayLike | None = None,
    guide_p: npt.ArrayLike | None = None,
    guide_d: npt.ArrayLike | None = None,
) -> SweepResult:
    if block < 1:
        raise ParameterError("block", block, "must be ≥ 1")
    ph = np.asarray(phi, dtype=np.float64)
    w = _num(omega1)
    if not np.all(np.isfinite(w)):
        raise ParameterError("omega1", omega1, "must be finite")
    if ph.ndim > 1:
        raise ParameterError("phi", ph.shape, "must be a number or an array of shape (N,)")
    if all(x is None for x in (O1, l1, l2, O2, l3, l4, guide_p, guide_d)) and isinstance(w, float):
        # one mechanism: its dimensions were checked once
        g = m._dims
        return _kernel(
            np.ascontiguousarray(np.atleast_1d(ph)),
            g,
            w * float(g.l1),
            m.branch_B,
            m.branch_C,
            block,
            with_velocities,
        )
    g = _dims(m, O1, l1, l2, O2, l3, l4, guide_p, guide_d)
    if np.ndim(w) > 1:
        raise ParameterError("omega1", np.shape(w), "must be a number or an array of shape (N,)")
    fields = {f.name: getattr(g, f.name) for f in dataclasses.fields(g)}
    shapes = [np.shape(v) for v in fields.values()] + [ph.shape, np.shape(w)]
    try:
        (n,) = np.broadcast_shapes((1,), *shapes)
    except ValueError:
        raise ParameterError(
            "sweep", [s for s in shapes if s], "arrays of different lengths do not broadcast"
        ) from None
    spread = _spread({**fields, "phi": ph, "wl1": _num(w * g.l1)}, n)
    wl1 = spread.pop("wl1")
    phis = np.asarray(spread.pop("phi"))
    return _kernel(
        phis,
        _Dims(**spread),
        wl1,
        m.branch_B,
        m.branch_C,
        block,
        with_velocities,
    )


def _kernel(
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
