"""One sweep kernel for any lever mechanism of a crank and class-II Assur groups.

A :class:`Chain` is the mechanism as a plan: the frame points, the crank, then its groups (RRR;
RRP on a fixed guide or on a guide carried by a moving link; RPR with offset; PRP) and named
points on links, in the order they can be solved. :func:`run` solves it over whole arrays of
crank angles: positions, with ``order`` ≥ 1 velocities, ω of every link and the relative
velocities of the sliding pairs, with ``order`` 2 accelerations, ε and the Coriolis terms. Each
group kind is solved in closed form from its own vector equations (those of the velocity and
acceleration plans):

- crank: V_A = ω1 × O1A; a_A = a^n_AO1 + a^τ_AO1 = −ω1²·O1A + ε1 × O1A;
- RRR (P1, P2 → B, links a = P1B, b = P2B): e_i = B − P_i, det = e1 × e2;
  V_B = V_P1 + ω_a × e1 = V_P2 + ω_b × e2 gives ω_a = e2·(V_P2 − V_P1)/det and
  ω_b = e1·(V_P2 − V_P1)/det; a_B = a_P1 + ε_a × e1 − ω_a²·e1 = a_P2 + ε_b × e2 − ω_b²·e2
  gives ε_a = e2·R/det and ε_b = e1·R/det with R = (a_P2 − ω_b²·e2) − (a_P1 − ω_a²·e1);
- RRP (rod from P to the slider D on a guide q + t·d; d⊥ = d turned 90°): with h = d × (P − q)
  and ρ = ±√(l² − h²) (the branch), D − P = ρ·d − h·d⊥. V_D = V_Dg + v_r·d, where D_g is the
  guide's point under D (at rest on a fixed guide; V_F + ω_g × FD on a guide of link g through
  F), and V_D = V_P + ω × PD: with U = V_P − V_Dg, ω = −(d⊥·U)/ρ and v_r = d·U − h·(d⊥·U)/ρ.
  a_D = a_Dg + a^k + a^r·d with the Coriolis term a^k = 2ω_g × v_r·d; with U = a_P − a_Dg − a^k,
  ε = −(d⊥·U + ω²·h)/ρ and a^r = d·U − (h·(d⊥·U) + ω²·l²)/ρ;
- RPR (block on the slider point A, slotted link through the pivot C, the slide line ``offset``
  to the left of C): r = A − C, d = r·(√(r² − o²) − i·o)/r² (as a complex number), so that
  r·d = √(r² − o²) and r × d = −o; V_A − V_C = ω3 × r + v_r·d gives ω3 = (d × (V_A − V_C))/(r·d)
  and v_r = d·(V_A − V_C) + ω3·o; a_A − a_C = ε3 × r − ω3²·r + 2ω3 × v_r·d + a^r·d gives
  ε3 = (d × (a_A − a_C) + ω3²·o − 2ω3·v_r)/(r·d);
- PRP (a yoke translating along a fixed guide G, driven in its slot S by the slider point):
  E − q = t·G + u·S, solved by Cramer's rule, and likewise for V and a; nothing turns;
- a point of a solved link: P = F + u·(along + i·left); V_P = V_F + ω × FP;
  a_P = a_F + ε × FP − ω²·FP.

The assembly mode of each group is fixed for the whole sweep (the branch signs), so a sweep
never jumps to the other mode. A position where a group cannot close, or (with velocities) a
dead position, raises :class:`~geomcad.errors.NoIntersection` naming the group's step, the first
position index and its crank angle.

Every number of the plan may be an ``(N,)`` array instead of a float (one value per position:
many variants of a mechanism swept at once); frame points are pairs of such numbers. The kernel
works on x and y component arrays (a point's two rows ``(2, N)``, shown as an ``(N, 2)`` view),
in blocks of :data:`BLOCK` positions so that its temporaries, preallocated once per thread and
reused by every group, stay in the cache; every array operation writes in place (``out=``).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import TypeVar

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import NoIntersection, ParameterError

Arr = npt.NDArray[np.float64]
K = TypeVar("K", str, int)

#: A number, or an array of shape (N,) with one value per position of the sweep.
Num = float | Arr

#: Positions per block. Smaller blocks keep the scratch rows in a smaller cache but pay numpy's
#: per-call overhead more often: measured with ``python3 bench/bench_linkage.py --blocks`` (CPU
#: time, 2013-6's six-bar), 16384 is the fastest for N = 10^4 … 10^6 (8192 5–20 % slower, 2048
#: 1.5 times slower, 32768 no faster).
BLOCK = 16384

#: Scratch rows a group may use at once.
SCRATCH = 16

#: Messages of the failures.
CLOSE_RRR = "the group cannot close: the circles do not meet"
CLOSE_RRP = "the group cannot close: the line misses the circle"
DEAD_RRR = "a dead position: the group's links are collinear"
DEAD_RRP = "a dead position: the rod is perpendicular to the guide"


# --- the plan -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class Crank:
    """The driving link ``link`` turning about the frame point ``pivot``; its joint ``joint`` at
    ``length`` (m) at the crank angle φ; ``omega`` (rad/s) and ``eps`` (rad/s²), ccw > 0."""

    pivot: str
    joint: str
    length: Num
    omega: Num = 1.0
    eps: Num = 0.0
    link: int = 1


@dataclass(frozen=True)
class RRR:
    """``joint`` = circle(ends[0], lengths[0]) ∩ circle(ends[1], lengths[1]); ``branch`` +1: on
    the left of ends[0] → ends[1]. ``links`` are the links ends[0]–joint and ends[1]–joint;
    ``step`` names the position's construction and ``dead`` the velocity plan's."""

    joint: str
    ends: tuple[str, str]
    lengths: tuple[Num, Num]
    branch: int
    links: tuple[int, int]
    step: str
    dead: str


@dataclass(frozen=True)
class FixedGuide:
    """A guide on the frame: through ``through``, along the unit vector ``direction``."""

    through: tuple[Num, Num]
    direction: tuple[Num, Num]


@dataclass(frozen=True)
class MovingGuide:
    """A guide on the moving link ``link``: from the point ``frm`` towards ``toward``, shifted
    ``offset`` (m) to the left."""

    frm: str
    toward: str
    offset: float
    link: int


@dataclass(frozen=True)
class RRP:
    """``joint`` = circle(end, length) ∩ the guide; ``branch`` +1: ahead of the end's foot along
    the guide. ``links`` are the rod and the slider; ``step`` names the position's
    construction, ``dead`` the velocity plan's, ``guide_step`` a moving guide's."""

    joint: str
    end: str
    length: Num
    branch: int
    links: tuple[int, int]
    guide: FixedGuide | MovingGuide
    step: str
    dead: str
    guide_step: str = ""


@dataclass(frozen=True)
class RPR:
    """A block on the known point ``slider`` sliding in the link that turns about the known point
    ``pivot``; the slide line passes ``offset`` (m) to the left of the pivot looking from it
    towards the slider. ``links`` are the block and the slotted link."""

    slider: str
    pivot: str
    offset: float
    links: tuple[int, int]
    step: str


@dataclass(frozen=True)
class PRP:
    """A yoke translating along the fixed guide through ``through`` along the unit ``guide``,
    driven by a block on the known point ``slider`` in its slot along the unit ``slot``;
    ``joint`` is the yoke's point on the guide line. ``links`` are the block and the yoke."""

    joint: str
    slider: str
    through: tuple[float, float]
    guide: tuple[float, float]
    slot: tuple[float, float]
    links: tuple[int, int]


@dataclass(frozen=True)
class Point:
    """A point of a solved link: ``along`` (m) from ``frm`` towards ``toward`` (the link's slide
    direction when ``toward`` is empty) and ``left`` (m) to its left."""

    name: str
    link: int
    frm: str
    toward: str
    along: float
    left: float


Step = RRR | RRP | RPR | PRP | Point


@dataclass(frozen=True)
class Chain:
    """A mechanism as a plan: the frame points (m), the crank, then the groups and points in the
    order they can be solved."""

    frame: Mapping[str, tuple[Num, Num]]
    crank: Crank
    steps: tuple[Step, ...]

    def rows(self, order: int) -> int:
        """The output rows of a sweep of ``order`` (counted once per order)."""
        cache = self._rows
        if order not in cache:
            cache[order] = _rows(self, order)
        return cache[order]

    @cached_property
    def _rows(self) -> dict[int, int]:
        return {}

    @cached_property
    def _consts(self) -> dict[int, tuple[Num, ...]]:
        """Each step's constant coefficients, computed once per plan."""
        out: dict[int, tuple[Num, ...]] = {}
        for i, st in enumerate(self.steps):
            if isinstance(st, RRR):
                l1, l2 = st.lengths
                out[i] = (
                    0.5 * (l1 * l1 - l2 * l2),  # half difference of the squares
                    l1 * l1,
                    -tol.TANGENT * np.maximum(l1, l2) ** 2,  # h² at tangency
                    tol.ANGLE * l1 * l2,  # |det| at a dead position
                    (tol.REL_LENGTH * (l1 + l2)) ** 2,  # d² where the ends coincide
                )
            elif isinstance(st, RRP):
                ln = st.length
                out[i] = (ln * ln, -tol.TANGENT * ln * ln, (tol.ANGLE * ln) ** 2)
        return out


# --- the result ---------------------------------------------------------------------------------


class State:
    """A mechanism over N positions: positions (``pos``), velocities (``vel``) and accelerations
    (``acc``) of every point as ``(N, 2)`` arrays, ω and ε of every moving link ``(N,)``, the
    unit slide direction ``(N, 2)`` of each link that has one (``slide``), and for each sliding
    pair, keyed by the block's joint, the relative velocity along the slide (signed, ``v_rel``)
    and the Coriolis acceleration (signed, along the slide's left normal, ``a_cor``); ``along``
    is an RRP slider's coordinate along its guide from the guide's point q (m). A quantity
    that does not change over the sweep (a frame point, a fixed guide's direction, ω of a link
    that does not turn) is a constant array (a read-only broadcast above :data:`SMALL`
    positions). Each table is assembled on first use."""

    def __init__(self, chain: Chain, phi: Arr, omega1: Num, out: _Out, order: int) -> None:
        self.phi = phi
        self.omega1 = omega1
        self._chain, self._out, self._order = chain, out, order

    def _points(self, table: dict[str, Full2], order: int) -> dict[str, Arr]:
        n = self.phi.shape[0]
        if self._order < order:
            return {}
        if order == 0:
            got = {k: _full2(v, n) for k, v in self._chain.frame.items()}
        else:
            zero = _full2((0.0, 0.0), n)
            got = dict.fromkeys(self._chain.frame, zero)
        got.update((k, _full2(v, n)) for k, v in table.items())
        return got

    def _numbers(self, table: dict[K, Num], order: int) -> dict[K, Arr]:
        if self._order < order:
            return {}
        n = self.phi.shape[0]
        return {k: _full(v, n) for k, v in table.items()}

    @cached_property
    def pos(self) -> dict[str, Arr]:
        return self._points(self._out.pos, 0)

    @cached_property
    def vel(self) -> dict[str, Arr]:
        return self._points(self._out.vel, 1)

    @cached_property
    def acc(self) -> dict[str, Arr]:
        return self._points(self._out.acc, 2)

    @cached_property
    def slide(self) -> dict[int, Arr]:
        n = self.phi.shape[0]
        return {k: _full2(v, n) for k, v in self._out.slide.items()}

    @cached_property
    def omega(self) -> dict[int, Arr]:
        return self._numbers(self._out.omega, 1)

    @cached_property
    def eps(self) -> dict[int, Arr]:
        return self._numbers(self._out.eps, 2)

    @cached_property
    def v_rel(self) -> dict[str, Arr]:
        return self._numbers(self._out.v_rel, 1)

    @cached_property
    def a_cor(self) -> dict[str, Arr]:
        return self._numbers(self._out.a_cor, 1)

    @cached_property
    def along(self) -> dict[str, Arr]:
        return self._numbers(self._out.along, 0)


# --- the kernel ---------------------------------------------------------------------------------

#: A value inside a block: a number (constant over the block) or the block's slice of an array.
X = float | Arr
#: A vector inside a block, or ``None`` for a zero one (a frame point's velocity).
V2 = tuple[X, X] | None
#: A vector over the whole sweep: two rows ``(2, N)``, or a pair of numbers.
Full2 = Arr | tuple[Num, Num]

_local = threading.local()


def _scratch(rows: int, size: int) -> Arr:
    """This thread's scratch rows for a sweep's temporaries, kept between sweeps (a fresh
    allocation each time would pay its page faults on every call)."""
    buf: Arr | None = getattr(_local, "scratch", None)
    if buf is None or buf.shape[0] < rows or buf.shape[1] < size:
        buf = np.empty((rows, size))
        _local.scratch = buf
    return buf


def _at(x: Num, sl: slice) -> X:
    return x if isinstance(x, float) else x[sl]


def _all_above(x: Arr, limit: X) -> bool:
    """True when every element of x is > limit (False where one is NaN)."""
    if not x.size:
        return True
    if isinstance(limit, float):
        return bool(x.min() > limit)
    return bool(np.all(x > limit))


def _zero(x: Num) -> bool:
    return isinstance(x, float) and x == 0.0


def _rows(chain: Chain, order: int) -> int:
    """How many output rows a sweep of ``order`` fills: two per vector, one per number."""
    per_point = 2 * (1 + min(order, 2))
    rows = per_point  # the crank's joint
    w = 1 if order >= 1 else 0
    e = 1 if order >= 2 else 0
    for st in chain.steps:
        if isinstance(st, Point):
            rows += per_point
        elif isinstance(st, RRR):
            rows += per_point + 2 * (w + e)
        elif isinstance(st, RRP):
            moving = isinstance(st.guide, MovingGuide)
            rows += per_point + 1 + (2 if moving else 0) + (w + e) + w * (2 if moving else 1)
        elif isinstance(st, RPR):
            rows += 2 + (w + e) + 2 * w
        else:
            rows += per_point + 2 * w
    return rows


class _Out:
    """The sweep's results over all N positions: vectors as two rows, numbers as one row, of
    one array allocated at once and handed out on first use (and quantities that do not change
    as numbers)."""

    def __init__(self, n: int, rows: int) -> None:
        self.n = n
        self.buf = np.empty((rows, n))
        self.used = 0
        self.pos: dict[str, Full2] = {}
        self.vel: dict[str, Full2] = {}
        self.acc: dict[str, Full2] = {}
        self.slide: dict[int, Full2] = {}
        self.omega: dict[int, Num] = {}
        self.eps: dict[int, Num] = {}
        self.v_rel: dict[str, Num] = {}
        self.a_cor: dict[str, Num] = {}
        self.along: dict[str, Num] = {}

    def take(self, k: int) -> Arr:
        i = self.used
        self.used = i + k
        if self.used > self.buf.shape[0]:  # more rows than counted: no harm, only slower
            return np.empty(self.n) if k == 1 else np.empty((k, self.n))
        return self.buf[i] if k == 1 else self.buf[i : i + k]


class _Block:
    """One block of a sweep: its crank angles, the scratch rows, and the block's values of every
    point's position, velocity and acceleration, every link's ω, ε and slide direction."""

    def __init__(self, out: _Out, sl: slice, phi: Arr, tmp: Arr, order: int) -> None:
        self.out, self.sl, self.phi, self.order = out, sl, phi, order
        self.t = tmp[:, : phi.shape[0]]
        self.P: dict[str, tuple[X, X]] = {}
        self.V: dict[str, V2] = {}
        self.A: dict[str, V2] = {}
        self.W: dict[int, X | None] = {}
        self.E: dict[int, X | None] = {}
        self.S: dict[int, tuple[X, X]] = {}

    def fail(self, step: str, bad: npt.NDArray[np.bool_], why: str) -> None:
        """Raise NoIntersection naming ``step`` at the first position where ``bad`` holds (a
        ParameterError if a crank angle is not finite)."""
        phi = self.phi
        i0 = self.sl.start
        if not np.all(np.isfinite(phi)):
            i = int(np.argmax(~np.isfinite(phi)))
            raise ParameterError(f"phi[{i0 + i}]", float(phi[i]), "a crank angle must be finite")
        if np.any(bad):
            i = int(np.argmax(bad))
            deg = math.degrees(float(phi[i])) % 360.0
            raise NoIntersection(
                step, f"{why} (first at position index {i0 + i}, at the crank angle φ = {deg:.6g}°)"
            )

    def _vec(self, table: dict[K, Full2], key: K) -> tuple[Arr, Arr]:
        a = table.get(key)
        if a is None:
            a = table[key] = self.out.take(2)
        assert isinstance(a, np.ndarray)
        return a[0, self.sl], a[1, self.sl]

    def _num(self, table: dict[K, Num], key: K) -> Arr:
        a = table.get(key)
        if a is None:
            a = table[key] = self.out.take(1)
        assert isinstance(a, np.ndarray)
        return a[self.sl]

    def pos(self, name: str) -> tuple[Arr, Arr]:
        v = self.P[name] = self._vec(self.out.pos, name)
        return v

    def vel(self, name: str) -> tuple[Arr, Arr]:
        v = self._vec(self.out.vel, name)
        self.V[name] = v
        return v

    def acc(self, name: str) -> tuple[Arr, Arr]:
        v = self._vec(self.out.acc, name)
        self.A[name] = v
        return v

    def omega(self, link: int) -> Arr:
        w = self.W[link] = self._num(self.out.omega, link)
        return w

    def eps(self, link: int) -> Arr:
        e = self.E[link] = self._num(self.out.eps, link)
        return e

    def slide(self, link: int) -> tuple[Arr, Arr]:
        d = self.S[link] = self._vec(self.out.slide, link)
        return d

    def same(self, link: int, like: int) -> None:
        """Link ``link`` turns with link ``like`` (its ω and ε, whichever are known)."""
        out = self.out
        if like in self.W:
            out.omega[link] = out.omega[like]
            self.W[link] = self.W[like]
        if like in self.E:
            out.eps[link] = out.eps[like]
            self.E[link] = self.E[like]

    def const_w(self, link: int, w: Num, e: Num) -> None:
        """Link ``link`` has ω = ``w`` and ε = ``e`` (numbers, or arrays over the sweep)."""
        self.out.omega[link], self.out.eps[link] = w, e
        self.W[link] = None if _zero(w) else _at(w, self.sl)
        self.E[link] = None if _zero(e) else _at(e, self.sl)


def run(
    chain: Chain,
    phi: npt.ArrayLike,
    order: int = 1,
    block: int = BLOCK,
    omega1: Num | None = None,
    eps1: Num | None = None,
) -> State:
    """The mechanism at the crank angles ``phi`` (rad): positions, with ``order`` ≥ 1
    velocities, ω and relative velocities, with ``order`` 2 accelerations, ε and the Coriolis
    terms too, at the crank's ω1 and ε1 (or at ``omega1`` and ``eps1`` when given). Every array
    of the plan must have the length of ``phi``."""
    if block < 1:
        raise ParameterError("block", block, "must be ≥ 1")
    crank = chain.crank
    if omega1 is not None or eps1 is not None:
        crank = Crank(
            crank.pivot,
            crank.joint,
            crank.length,
            crank.omega if omega1 is None else omega1,
            crank.eps if eps1 is None else eps1,
            crank.link,
        )
    ph = np.ascontiguousarray(np.atleast_1d(np.asarray(phi, dtype=np.float64)))
    n = ph.shape[0]
    out = _Out(n, chain.rows(order))
    b = min(block, max(n, 1))
    tmp = _scratch(SCRATCH, b)
    const = chain._consts
    steps = [(st, const.get(i, ())) for i, st in enumerate(chain.steps)]
    frame = chain.frame
    scale = crank.length
    for i0 in range(0, max(n, 1), b):  # one empty block when there is no position
        sl = slice(i0, min(i0 + b, n))
        bk = _Block(out, sl, ph[sl], tmp, order)
        for name, (x, y) in frame.items():
            bk.P[name] = (_at(x, sl), _at(y, sl))
            bk.V[name] = None
            bk.A[name] = None
        _crank(crank, bk)
        for st, c in steps:
            if isinstance(st, Point):
                _point(st, bk)
            elif isinstance(st, RRR):
                _rrr(st, c, bk)
            elif isinstance(st, RRP):
                _rrp(st, c, bk, scale)
            elif isinstance(st, RPR):
                _rpr(st, bk)
            else:
                _prp(st, bk)
    return State(chain, ph, crank.omega, out, order)


def _crank(cr: Crank, bk: _Block) -> None:
    sl, t = bk.sl, bk.t
    c, s = t[0], t[1]
    np.cos(bk.phi, out=c)
    np.sin(bk.phi, out=s)
    ox, oy = bk.P[cr.pivot]
    ln = _at(cr.length, sl)
    ax, ay = bk.pos(cr.joint)
    np.multiply(c, ln, out=ax)
    ax += ox
    np.multiply(s, ln, out=ay)
    ay += oy
    bk.const_w(cr.link, cr.omega, cr.eps)
    if bk.order < 1:
        return
    w = _at(cr.omega, sl)
    wl = w * ln
    vx, vy = bk.vel(cr.joint)
    np.multiply(s, -wl, out=vx)  # V_A = ω1 × O1A
    np.multiply(c, wl, out=vy)
    if bk.order < 2:
        return
    w2l = w * wl
    px, py = bk.acc(cr.joint)
    np.multiply(c, -w2l, out=px)  # a^n_A = −ω1²·O1A
    np.multiply(s, -w2l, out=py)
    if not _zero(cr.eps):
        el = _at(cr.eps, sl) * ln  # a^τ_A = ε1 × O1A
        np.multiply(s, el, out=t[2])
        px -= t[2]
        np.multiply(c, el, out=t[2])
        py += t[2]


def _rrr(st: RRR, c: tuple[Num, ...], bk: _Block) -> None:
    sl, t = bk.sl, bk.t
    half, l1sq, touch, dead, coinc = (_at(x, sl) for x in c)
    x1, y1 = bk.P[st.ends[0]]
    x2, y2 = bk.P[st.ends[1]]
    dvx, dvy, d2, inv, k1, k2, tmp, det = t[:8]
    np.subtract(x2, x1, out=dvx)
    np.subtract(y2, y1, out=dvy)
    np.multiply(dvx, dvx, out=d2)
    np.multiply(dvy, dvy, out=tmp)
    d2 += tmp
    if not _all_above(d2, coinc):
        bk.fail(st.step, ~(d2 > coinc), f"the ends {st.ends[0]} and {st.ends[1]} coincide")
    # B − P1 = k1·dv + k2·dv⊥: k1 = a/d = 1/2 + (l1² − l2²)/(2d²), k2 = ±h/d = ±√(l1²/d² − k1²)
    np.divide(1.0, d2, out=inv)
    np.multiply(inv, half, out=k1)
    k1 += 0.5
    np.multiply(inv, l1sq, out=k2)
    np.multiply(k1, k1, out=tmp)
    k2 -= tmp
    if not _all_above(k2, 0.0):
        np.multiply(k2, d2, out=tmp)  # h²
        bk.fail(st.step, ~(tmp >= touch), CLOSE_RRR)
        np.maximum(k2, 0.0, out=k2)
    np.sqrt(k2, out=k2)
    order = bk.order
    if order >= 1:
        np.multiply(k2, d2, out=det)  # |e1 × e2| = h·d
        if not _all_above(det, dead):
            bk.fail(st.dead, ~(det > dead), DEAD_RRR)
    if st.branch < 0:
        np.negative(k2, out=k2)
    wx, wy = inv, d2
    if order >= 1 and st.branch < 0:
        np.negative(det, out=det)
    np.multiply(dvx, k1, out=wx)
    np.multiply(dvy, k2, out=tmp)
    wx -= tmp
    np.multiply(dvy, k1, out=wy)
    np.multiply(dvx, k2, out=tmp)
    wy += tmp  # e1 = B − P1
    bx, by = bk.pos(st.joint)
    np.add(x1, wx, out=bx)
    np.add(y1, wy, out=by)
    if order < 1:
        return
    ex, ey = k1, k2
    np.subtract(wx, dvx, out=ex)
    np.subtract(wy, dvy, out=ey)  # e2 = B − P2
    V1, V2 = bk.V[st.ends[0]], bk.V[st.ends[1]]
    a, b = st.links
    wa, wb = bk.omega(a), bk.omega(b)
    vbx, vby = bk.vel(st.joint)
    if V1 is None and V2 is None:
        wa.fill(0.0)
        wb.fill(0.0)
        vbx.fill(0.0)
        vby.fill(0.0)
    else:
        # ω_a = e2·(V2 − V1)/det, ω_b = e1·(V2 − V1)/det
        if V1 is None:
            assert V2 is not None
            dx, dy = V2
            np.divide(1.0, det, out=det)
        elif V2 is None:
            dx, dy = V1
            np.divide(-1.0, det, out=det)
        else:
            dx, dy = t[8], t[9]
            np.subtract(V2[0], V1[0], out=dx)
            np.subtract(V2[1], V1[1], out=dy)
            np.divide(1.0, det, out=det)
        np.multiply(ex, dx, out=wa)
        np.multiply(ey, dy, out=tmp)
        wa += tmp
        wa *= det
        np.multiply(wx, dx, out=wb)
        np.multiply(wy, dy, out=tmp)
        wb += tmp
        wb *= det
        # V_B = V1 + ω_a × e1 = V2 + ω_b × e2
        if V2 is None:
            np.multiply(wb, ey, out=vbx)
            np.negative(vbx, out=vbx)
            np.multiply(wb, ex, out=vby)
        else:
            np.multiply(wa, wy, out=vbx)
            np.multiply(wa, wx, out=vby)
            if V1 is None:
                np.negative(vbx, out=vbx)
            else:
                np.subtract(V1[0], vbx, out=vbx)
                vby += V1[1]
    if order < 2:
        return
    if V1 is None and V2 is None:
        np.divide(1.0, det, out=det)
    elif V2 is None:
        np.negative(det, out=det)  # back to 1/det
    A1, A2 = bk.A[st.ends[0]], bk.A[st.ends[1]]
    rx, ry, q = t[8], t[9], t[10]
    # R = (a2 − ω_b²·e2) − (a1 − ω_a²·e1); ε_a = e2·R/det, ε_b = e1·R/det
    np.multiply(wa, wa, out=q)
    np.multiply(q, wx, out=rx)
    np.multiply(q, wy, out=ry)
    np.multiply(wb, wb, out=q)
    np.multiply(q, ex, out=tmp)
    rx -= tmp
    np.multiply(q, ey, out=tmp)
    ry -= tmp
    if A2 is not None:
        rx += A2[0]
        ry += A2[1]
    if A1 is not None:
        rx -= A1[0]
        ry -= A1[1]
    ea, eb = bk.eps(a), bk.eps(b)
    np.multiply(ex, rx, out=ea)
    np.multiply(ey, ry, out=tmp)
    ea += tmp
    ea *= det
    np.multiply(wx, rx, out=eb)
    np.multiply(wy, ry, out=tmp)
    eb += tmp
    eb *= det
    # a_B = a2 − ω_b²·e2 + ε_b × e2 (q holds ω_b²)
    abx, aby = bk.acc(st.joint)
    np.multiply(q, ex, out=abx)
    np.multiply(eb, ey, out=tmp)
    abx += tmp
    np.negative(abx, out=abx)
    np.multiply(eb, ex, out=aby)
    np.multiply(q, ey, out=tmp)
    aby -= tmp
    if A2 is not None:
        abx += A2[0]
        aby += A2[1]


def _rrp(st: RRP, c: tuple[Num, ...], bk: _Block, scale: Num) -> None:
    sl, t = bk.sl, bk.t
    lsq, touch, dead = (_at(x, sl) for x in c)
    g = st.guide
    rod, slider = st.links
    wx, wy, ar, h, rho, tmp = t[:6]
    s = bk._num(bk.out.along, st.joint)
    moving = isinstance(g, MovingGuide)
    if isinstance(g, FixedGuide):
        qx, qy = (_at(x, sl) for x in g.through)
        dx, dy = (_at(x, sl) for x in g.direction)
        bk.out.slide[slider] = g.direction
        bk.S[slider] = (dx, dy)
    else:
        fx, fy = bk.P[g.frm]
        dx, dy = bk.slide(slider)
        np.subtract(bk.P[g.toward][0], fx, out=dx)
        np.subtract(bk.P[g.toward][1], fy, out=dy)
        np.multiply(dx, dx, out=tmp)
        np.multiply(dy, dy, out=ar)
        tmp += ar
        lim = (tol.REL_LENGTH * _at(scale, sl)) ** 2
        if not _all_above(tmp, lim):
            bk.fail(
                st.guide_step, ~(tmp > lim), f"the guide's points {g.frm} and {g.toward} coincide"
            )
        np.sqrt(tmp, out=tmp)
        dx /= tmp
        dy /= tmp
        # q = F + offset·d⊥
        qx, qy = t[6], t[7]
        np.multiply(dy, -g.offset, out=qx)
        qx += fx
        np.multiply(dx, g.offset, out=qy)
        qy += fy
    px, py = bk.P[st.end]
    np.subtract(px, qx, out=wx)
    np.subtract(py, qy, out=wy)
    np.multiply(wx, dx, out=s)
    np.multiply(wy, dy, out=tmp)
    s += tmp  # the end's foot on the guide
    np.multiply(wy, dx, out=h)
    np.multiply(wx, dy, out=tmp)
    h -= tmp  # its height above the guide, d × (P − q)
    np.multiply(h, h, out=rho)
    np.subtract(lsq, rho, out=rho)
    if not _all_above(rho, 0.0):
        bk.fail(st.step, ~(rho >= touch), CLOSE_RRP)
        np.maximum(rho, 0.0, out=rho)
    order = bk.order
    if order >= 1 and not _all_above(rho, dead):
        bk.fail(st.dead, ~(rho > dead), DEAD_RRP)
    np.sqrt(rho, out=rho)
    if st.branch < 0:
        np.negative(rho, out=rho)
    s += rho
    Dx, Dy = bk.pos(st.joint)
    np.multiply(s, dx, out=Dx)
    Dx += qx
    np.multiply(s, dy, out=Dy)
    Dy += qy
    if order < 1:
        return
    # U = V_P − V_Dg; ω = −(d × U)/ρ; v_r = d·U − h·(d × U)/ρ
    VP = bk.V[st.end]
    ux, uy, p = t[8], t[9], t[10]
    if moving:
        assert isinstance(g, MovingGuide)
        wg = bk.W[g.link]
        VF = bk.V[g.frm]
        gx, gy = t[11], t[12]  # V_Dg = V_F + ω_g × FD
        rfx, rfy = t[13], t[14]
        np.subtract(Dx, fx, out=rfx)
        np.subtract(Dy, fy, out=rfy)
        if wg is None:
            gx.fill(0.0)
            gy.fill(0.0)
        else:
            np.multiply(rfy, wg, out=gx)
            np.negative(gx, out=gx)
            np.multiply(rfx, wg, out=gy)
        if VF is not None:
            gx += VF[0]
            gy += VF[1]
        if VP is None:
            np.negative(gx, out=ux)
            np.negative(gy, out=uy)
        else:
            np.subtract(VP[0], gx, out=ux)
            np.subtract(VP[1], gy, out=uy)
    elif VP is None:
        ux.fill(0.0)
        uy.fill(0.0)
    else:
        ux, uy = VP
    np.multiply(uy, dx, out=p)
    np.multiply(ux, dy, out=tmp)
    p -= tmp
    p /= rho  # (d × U)/ρ
    np.negative(p, out=bk.omega(rod))
    vr = bk._num(bk.out.v_rel, st.joint)
    np.multiply(ux, dx, out=vr)
    np.multiply(uy, dy, out=tmp)
    vr += tmp
    np.multiply(h, p, out=tmp)
    vr -= tmp
    vdx, vdy = bk.vel(st.joint)
    np.multiply(vr, dx, out=vdx)
    np.multiply(vr, dy, out=vdy)
    if moving:
        vdx += gx
        vdy += gy
        bk.same(slider, g.link)  # type: ignore[union-attr]
        ak = bk._num(bk.out.a_cor, st.joint)
        if wg is None:
            ak.fill(0.0)
        else:
            np.multiply(vr, wg, out=ak)
            ak *= 2.0  # a^k = 2ω_g·v_r (along d⊥)
    else:
        bk.const_w(slider, 0.0, 0.0)
        bk.out.a_cor[st.joint] = 0.0
    if order < 2:
        return
    # U = a_P − a_Dg − a^k; ε = −(d × U + ω²·h)/ρ; a^r = d·U − (h·(d × U) + ω²·l²)/ρ
    AP = bk.A[st.end]
    if moving:
        assert isinstance(g, MovingGuide)
        eg = bk.E[g.link]
        AF = bk.A[g.frm]
        # a_Dg + a^k = a_F + ε_g × FD − ω_g²·FD + a^k·d⊥
        if wg is None:
            gx.fill(0.0)
            gy.fill(0.0)
        else:
            np.multiply(wg, wg, out=p)
            np.multiply(rfx, p, out=gx)
            np.negative(gx, out=gx)
            np.multiply(rfy, p, out=gy)
            np.negative(gy, out=gy)
            np.multiply(ak, dy, out=tmp)
            gx -= tmp
            np.multiply(ak, dx, out=tmp)
            gy += tmp
        if eg is not None:
            np.multiply(rfy, eg, out=tmp)
            gx -= tmp
            np.multiply(rfx, eg, out=tmp)
            gy += tmp
        if AF is not None:
            gx += AF[0]
            gy += AF[1]
        if AP is None:
            np.negative(gx, out=ux)
            np.negative(gy, out=uy)
        else:
            np.subtract(AP[0], gx, out=ux)
            np.subtract(AP[1], gy, out=uy)
    elif AP is None:
        ux = t[8]
        uy = t[9]
        ux.fill(0.0)
        uy.fill(0.0)
    else:
        ux, uy = AP
    w = bk.W[rod]
    assert w is not None
    w2 = t[15]
    np.multiply(w, w, out=w2)
    np.multiply(uy, dx, out=p)
    np.multiply(ux, dy, out=tmp)
    p -= tmp  # d × U
    e = bk.eps(rod)
    np.multiply(w2, h, out=e)
    e += p
    e /= rho
    np.negative(e, out=e)
    np.multiply(h, p, out=ar)
    np.multiply(w2, lsq, out=tmp)
    ar += tmp
    ar /= rho
    np.negative(ar, out=ar)
    np.multiply(ux, dx, out=tmp)
    ar += tmp
    np.multiply(uy, dy, out=tmp)
    ar += tmp
    adx, ady = bk.acc(st.joint)
    np.multiply(ar, dx, out=adx)
    np.multiply(ar, dy, out=ady)
    if moving:
        adx += gx
        ady += gy
        bk.same(slider, g.link)  # type: ignore[union-attr]


def _rpr(st: RPR, bk: _Block) -> None:
    t = bk.t
    ax, ay = bk.P[st.slider]
    cx, cy = bk.P[st.pivot]
    rx, ry, inv, sq, tmp = t[:5]
    o = st.offset
    np.subtract(ax, cx, out=rx)
    np.subtract(ay, cy, out=ry)
    np.multiply(rx, rx, out=inv)
    np.multiply(ry, ry, out=tmp)
    inv += tmp  # r²
    np.subtract(inv, o * o, out=sq)
    np.multiply(inv, tol.REL_LENGTH, out=tmp)
    np.subtract(sq, tmp, out=tmp)
    if not _all_above(tmp, 0.0):
        bk.fail(
            st.step, ~(tmp > 0.0), f"the slider comes within the offset {abs(o):g} m of the pivot"
        )
    np.sqrt(sq, out=sq)  # r·d
    np.divide(1.0, inv, out=inv)
    block, rocker = st.links
    # d = r·(√(r² − o²) − i·o)/r²
    dx, dy = bk.slide(block)
    bk.S[rocker] = (dx, dy)
    bk.out.slide[rocker] = bk.out.slide[block]
    np.multiply(rx, sq, out=dx)
    np.multiply(ry, sq, out=dy)
    if o != 0.0:
        np.multiply(ry, o, out=tmp)
        dx += tmp
        np.multiply(rx, o, out=tmp)
        dy -= tmp
    dx *= inv
    dy *= inv
    if bk.order < 1:
        return
    VA, VC = bk.V[st.slider], bk.V[st.pivot]
    wx, wy = t[5], t[6]
    _diff(VA, VC, wx, wy)
    w = bk.omega(block)
    bk.same(rocker, block)
    np.multiply(wy, dx, out=w)
    np.multiply(wx, dy, out=tmp)
    w -= tmp
    w /= sq  # ω3 = d × (V_A − V_C)/(r·d)
    vr = bk._num(bk.out.v_rel, st.slider)
    np.multiply(wx, dx, out=vr)
    np.multiply(wy, dy, out=tmp)
    vr += tmp
    if o != 0.0:
        np.multiply(w, o, out=tmp)
        vr += tmp  # v_r = d·(V_A − V_C) + ω3·o
    ak = bk._num(bk.out.a_cor, st.slider)
    np.multiply(w, vr, out=ak)
    ak *= 2.0
    if bk.order < 2:
        return
    _diff(bk.A[st.slider], bk.A[st.pivot], wx, wy)
    e = bk.eps(block)
    bk.same(rocker, block)
    np.multiply(wy, dx, out=e)
    np.multiply(wx, dy, out=tmp)
    e -= tmp
    e -= ak
    if o != 0.0:
        np.multiply(w, w, out=tmp)
        tmp *= o
        e += tmp
    e /= sq  # ε3 = (d × (a_A − a_C) + ω3²·o − 2ω3·v_r)/(r·d)


def _diff(a: V2, b: V2, x: Arr, y: Arr) -> None:
    """x, y = a − b (``None`` a zero vector)."""
    if a is None:
        if b is None:
            x.fill(0.0)
            y.fill(0.0)
        else:
            np.negative(b[0], out=x)
            np.negative(b[1], out=y)
    elif b is None:
        np.copyto(x, a[0])
        np.copyto(y, a[1])
    else:
        np.subtract(a[0], b[0], out=x)
        np.subtract(a[1], b[1], out=y)


def _prp(st: PRP, bk: _Block) -> None:
    gx, gy = st.guide
    sx, sy = st.slot
    qx, qy = st.through
    det = gx * sy - gy * sx  # G × S
    block, yoke = st.links
    bk.out.slide[block] = bk.out.slide[yoke] = st.slot
    bk.S[block] = bk.S[yoke] = (sx, sy)
    t = bk.t[0]
    ex, ey = bk.P[st.slider]

    def along_guide(x: X, y: X, out: Arr) -> None:  # (x, y) × S / det
        np.multiply(x, sy / det, out=out)
        np.multiply(y, sx / det, out=t)
        out -= t

    ts = bk.t[1]
    along_guide(ex, ey, ts)
    ts -= (qx * sy - qy * sx) / det
    jx, jy = bk.pos(st.joint)
    np.multiply(ts, gx, out=jx)
    jx += qx
    np.multiply(ts, gy, out=jy)
    jy += qy
    bk.const_w(block, 0.0, 0.0)
    bk.const_w(yoke, 0.0, 0.0)
    if bk.order < 1:
        return
    VE = bk.V[st.slider]
    v = bk._num(bk.out.v_rel, st.joint)
    w = bk._num(bk.out.v_rel, st.slider)
    bk.out.a_cor[st.slider] = bk.out.a_cor[st.joint] = 0.0
    vx, vy = bk.vel(st.joint)
    if VE is None:
        v.fill(0.0)
        w.fill(0.0)
    else:
        along_guide(VE[0], VE[1], v)
        np.multiply(VE[1], gx / det, out=w)  # G × V_E / det
        np.multiply(VE[0], gy / det, out=t)
        w -= t
    np.multiply(v, gx, out=vx)
    np.multiply(v, gy, out=vy)
    if bk.order < 2:
        return
    AE = bk.A[st.slider]
    ax, ay = bk.acc(st.joint)
    if AE is None:
        ax.fill(0.0)
        ay.fill(0.0)
        return
    along_guide(AE[0], AE[1], ts)
    np.multiply(ts, gx, out=ax)
    np.multiply(ts, gy, out=ay)


def _point(st: Point, bk: _Block) -> None:
    t = bk.t
    fx, fy = bk.P[st.frm]
    ux, uy, tmp, rx, ry = t[:5]
    if st.toward:
        tx, ty = bk.P[st.toward]
        np.subtract(tx, fx, out=ux)
        np.subtract(ty, fy, out=uy)
        np.multiply(ux, ux, out=tmp)
        np.multiply(uy, uy, out=rx)
        tmp += rx
        np.sqrt(tmp, out=tmp)
        ux /= tmp
        uy /= tmp
        u: tuple[X, X] = (ux, uy)
    else:
        u = bk.S[st.link]
    sx, sy = u
    # FP = u·(along + i·left)
    np.multiply(sx, st.along, out=rx)
    np.multiply(sx, st.left, out=ry)
    if st.left != 0.0:
        np.multiply(sy, st.left, out=tmp)
        rx -= tmp
    np.multiply(sy, st.along, out=tmp)
    ry += tmp
    px, py = bk.pos(st.name)
    np.add(fx, rx, out=px)
    np.add(fy, ry, out=py)
    if bk.order < 1:
        return
    w = bk.W[st.link]
    VF = bk.V[st.frm]
    vx, vy = bk.vel(st.name)
    if w is None:
        vx.fill(0.0)
        vy.fill(0.0)
    else:  # V_P = V_F + ω × FP
        np.multiply(ry, w, out=vx)
        np.negative(vx, out=vx)
        np.multiply(rx, w, out=vy)
    if VF is not None:
        vx += VF[0]
        vy += VF[1]
    if bk.order < 2:
        return
    e = bk.E[st.link]
    AF = bk.A[st.frm]
    ax, ay = bk.acc(st.name)
    ax.fill(0.0)
    ay.fill(0.0)
    if w is not None:  # a_P = a_F + ε × FP − ω²·FP
        np.multiply(w, w, out=tmp)
        tmp *= -1.0
        np.multiply(rx, tmp, out=ax)
        np.multiply(ry, tmp, out=ay)
    if e is not None:
        np.multiply(ry, e, out=tmp)
        ax -= tmp
        np.multiply(rx, e, out=tmp)
        ay += tmp
    if AF is not None:
        ax += AF[0]
        ay += AF[1]


#: Up to this many positions a quantity that does not change is a filled array (cheaper to make
#: than a broadcast view); above, a read-only broadcast (no memory).
SMALL = 256


def _full(x: Num, n: int) -> Arr:
    """A number over n positions, or the array itself."""
    if isinstance(x, float):
        if n <= SMALL:
            return np.full(n, x)
        return np.broadcast_to(np.float64(x), (n,))
    return x


def _full2(v: Full2, n: int) -> Arr:
    """A vector over n positions as ``(N, 2)``: a view of its two rows, or a constant."""
    if isinstance(v, np.ndarray):
        return v.T
    x, y = v
    if isinstance(x, float) and isinstance(y, float):
        if n <= SMALL:
            a = np.empty((n, 2))
            a[:, 0] = x
            a[:, 1] = y
            return a
        return np.broadcast_to(np.array([x, y]), (n, 2))
    return np.stack(np.broadcast_arrays(np.asarray(x), np.asarray(y)), axis=-1)
