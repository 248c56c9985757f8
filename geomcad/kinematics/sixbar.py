"""The six-bar of problem 2013-6: crank-rocker O1ABO2 driving slider C through link BC.

The six-bar is a short definition on the general sweep kernel (:mod:`geomcad.kinematics.chain`):
the crank O1A, the RRR group A–B–O2 and the RRP group B–C on the slider's fixed guide. Every
position, velocity, acceleration, ω and ε below is that kernel's, over whole arrays of crank
angles (and over arrays of dimensions: many variants at once); the check by analysis measures the
slider's actual stroke and coefficient of velocity change over a turn. With B on a fixed side of
A → O2 and C on a fixed side of B's foot on the guide for the whole sweep, the mechanism never
jumps to its other assembly mode.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq

from geomcad import tol
from geomcad.errors import ConstructionError, DegenerateInput, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.chain import BLOCK, RRP, RRR, Chain, Crank, FixedGuide, State, run
from geomcad.kinematics.dyads import Arr, cross

__all__ = [
    "BLOCK",
    "STEP_B",
    "STEP_C",
    "STEP_VB",
    "STEP_VC",
    "SixBar",
    "SweepResult",
    "branch_sign",
    "grashof_crank_rocker",
]

#: Samples per turn for locating the slider's extreme positions before refining them.
SWEEP_SAMPLES = 3600

#: The steps a sweep can fail at (the names the recorded constructions use).
STEP_B = "B = circle(A, l2) ∩ circle(O2, l3)"
STEP_C = "C = circle(B, l4) ∩ slider path"
STEP_VB = "velocity of B"
STEP_VC = "velocity of C"

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


def _chain(g: _Dims, branch_b: int, branch_c: int) -> Chain:
    """The six-bar as the general kernel's plan: crank O1A (link 1), the RRR group A–B–O2
    (links 2 = AB, 3 = O2B) and the RRP group B–C on the fixed guide (links 4 = BC, 5 = the
    slider)."""
    return Chain(
        {"O1": (g.o1x, g.o1y), "O2": (g.o2x, g.o2y)},
        Crank("O1", "A", g.l1),
        (
            RRR("B", ("A", "O2"), (g.l2, g.l3), branch_b, (2, 3), STEP_B, STEP_VB),
            RRP(
                "C",
                "B",
                g.l4,
                branch_c,
                (4, 5),
                FixedGuide((g.qx, g.qy), (g.dx, g.dy)),
                STEP_C,
                STEP_VC,
            ),
        ),
    )


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
    def chain(self) -> Chain:
        """The mechanism as the general kernel's plan, its dimensions checked once."""
        return _chain(_dims(self), self.branch_B, self.branch_C)

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

        The general kernel on the six-bar's plan: A on the crank circle; B =
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
        st = _sweep(self, phi, omega1, 1, block, 0.0, O1, l1, l2, O2, l3, l4, guide_p, guide_d)
        p, v = st.pos, st.vel
        return SweepResult(
            st.phi, p["A"], p["B"], p["C"], v["A"], v["B"], v["C"], st.along["C"], st.v_rel["C"]
        )

    def state(
        self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0, order: int = 2
    ) -> State:
        """The general kernel's whole state at crank angles ``phi``: every joint's position,
        velocity and acceleration, ω and ε of links 1–5, the slider's coordinate and relative
        velocity (:class:`geomcad.kinematics.chain.State`)."""
        return _sweep(self, phi, omega1, order, BLOCK, eps1)

    def positions(self, phi: npt.ArrayLike) -> tuple[Arr, Arr, Arr]:
        """A, B, C as ``(N, 2)`` arrays for crank angles ``phi`` (rad).

        The positions part of :meth:`sweep`: a dead position (where the velocities are
        undefined) is no error here.
        """
        p = self.state(phi, order=0).pos
        return p["A"], p["B"], p["C"]

    def velocities(self, phi: npt.ArrayLike, omega1: float = 1.0) -> tuple[Arr, Arr, Arr]:
        """V_A, V_B, V_C for crank angles ``phi`` at crank speed ``omega1`` (rad/s, ccw > 0)."""
        v = self.state(phi, omega1, order=1).vel
        return v["A"], v["B"], v["C"]

    def accelerations(
        self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0
    ) -> tuple[Arr, Arr, Arr]:
        """a_A, a_B, a_C as ``(N, 2)`` arrays at crank speed ``omega1`` (rad/s) and crank
        acceleration ``eps1`` (rad/s², both ccw > 0).

        a_A = a^n_A (ω1²·l1 towards O1) + a^τ_A (ε1·l1, ⊥ O1A); a_B from a_B = a_A + a^n_BA +
        a^τ_BA = a^n_BO2 + a^τ_BO2; a_C from a_C = a_B + a^n_CB + a^τ_CB with a_C ∥ the guide.
        With ω1 = 1 and ε1 = 0 these are the acceleration analogues. Dead positions raise
        :class:`NoIntersection` naming the step.
        """
        a = self.state(phi, omega1, eps1).acc
        return a["A"], a["B"], a["C"]

    def omegas(self, phi: npt.ArrayLike, omega1: float = 1.0) -> tuple[Arr, Arr, Arr]:
        """Angular velocities (rad/s, ccw > 0) of the coupler AB (ω2), the rocker O2B (ω3) and
        the link BC (ω4)."""
        w = self.state(phi, omega1, order=1).omega
        return w[2], w[3], w[4]

    def epsilons(
        self, phi: npt.ArrayLike, omega1: float = 1.0, eps1: float = 0.0
    ) -> tuple[Arr, Arr, Arr]:
        """Angular accelerations (rad/s², ccw > 0) of the coupler AB (ε2), the rocker O2B (ε3)
        and the link BC (ε4)."""
        e = self.state(phi, omega1, eps1).eps
        return e[2], e[3], e[4]

    def slider_s(self, phi: npt.ArrayLike) -> Arr:
        """The slider's coordinate along its guide from ``guide_p`` (m)."""
        return self.state(phi, order=0).along["C"]

    def slider_v(self, phi: npt.ArrayLike, omega1: float = 1.0) -> Arr:
        """The slider's velocity along its guide (m/s at ``omega1``; the analogue for ω1 = 1)."""
        return self.state(phi, omega1, order=1).v_rel["C"]

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


# --- the dimensions of a sweep ---------------------------------------------------------------


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
    order: int,
    block: int,
    eps1: float,
    O1: npt.ArrayLike | None = None,
    l1: npt.ArrayLike | None = None,
    l2: npt.ArrayLike | None = None,
    O2: npt.ArrayLike | None = None,
    l3: npt.ArrayLike | None = None,
    l4: npt.ArrayLike | None = None,
    guide_p: npt.ArrayLike | None = None,
    guide_d: npt.ArrayLike | None = None,
) -> State:
    ph = np.asarray(phi, dtype=np.float64)
    w = _num(omega1)
    if not np.all(np.isfinite(w)):
        raise ParameterError("omega1", omega1, "must be finite")
    if ph.ndim > 1:
        raise ParameterError("phi", ph.shape, "must be a number or an array of shape (N,)")
    if all(x is None for x in (O1, l1, l2, O2, l3, l4, guide_p, guide_d)) and isinstance(w, float):
        # one mechanism: its plan was made and checked once
        return run(m.chain, ph, order, block, w, eps1)
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
    spread = _spread({**fields, "phi": ph, "omega1": w}, n)
    w = spread.pop("omega1")
    phis = np.asarray(spread.pop("phi"))
    return run(_chain(_Dims(**spread), m.branch_B, m.branch_C), phis, order, block, w, eps1)
