"""Positions, velocities and accelerations of a linkage over whole arrays of crank angles.

One kernel for any linkage file: the crank, then each group in the file's order, each kind solved
from its own vector equations in closed form over numpy arrays (every position at once), with the
assembly mode fixed for the whole sweep. The equations are those of the plans
(:mod:`geomcad.linkage.plans`), which the tests hold to the same numbers:

- crank: V_A = ω1 × OA, a_A = a^n_AO (ε1 = 0);
- RRR: V_B = V_P1 + V_BP1 (⊥ BP1) = V_P2 + V_BP2 (⊥ BP2), and likewise with a^n + a^τ;
- RRP: V_D = V_B + V_DB (⊥ DB) = V_Dg + V_rel (∥ guide), where D_g is the point of the guide's
  link g under D; a_D = a_Dg + a^k + a^r with a^k = 2ω_g × V_rel (none on a fixed guide);
- RPR: V_A = V_A3 + V_rel (∥ slide), V_A3 = V_C + ω3 × CA; a_A = a_A3 + a^k + a^r,
  a^k = 2ω3 × V_rel; the block turns with link 3;
- PRP: the yoke translates along the guide, V_A = V_E + V_rel (∥ slot), neither link turns.

Points are complex numbers x + iy inside the kernel (a turn by 90° is a product by i, a dot
product Re(conj(a)·b), a cross product Im(conj(a)·b)): contiguous arrays and few temporaries. The
crank angles are processed in blocks of :data:`BLOCK`, so that the temporaries stay in the cache.
:class:`State` shows every point as an ``(N, 2)`` float array (a view of the complex one, no
copy); link ω and ε are ``(N,)``. A position where a group cannot close, or a dead position,
raises :class:`~geomcad.errors.NoIntersection` naming the group and the first crank angle where
it happens.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import NoIntersection
from geomcad.linkage.model import Group, Linkage, PointDef

Arr = npt.NDArray[np.float64]
Cx = npt.NDArray[np.complex128]

#: Crank angles per block of the sweep, so that its temporaries stay in the cache (the bespoke
#: six-bar kernel's best block too; 4096 and 8192 measured no faster, `bench/bench_linkage.py`).
BLOCK = 16384


def _xy(z: Cx) -> Arr:
    """A complex array as an ``(N, 2)`` float array (a view; a copy of a broadcast one)."""
    if not z.flags.c_contiguous:  # a frame point or a constant: one value broadcast
        z = np.ascontiguousarray(z)
    return z.view(np.float64).reshape(-1, 2)


def _cx(a: Arr) -> Cx:
    """An ``(N, 2)`` float array as complex numbers."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    return a.view(np.complex128).reshape(-1)


def _dot(a: Cx, b: Cx) -> Arr:
    return np.asarray(a.real * b.real + a.imag * b.imag)


def _cross(a: Cx, b: Cx) -> Arr:
    return np.asarray(a.real * b.imag - a.imag * b.real)


def _abs2(a: Cx) -> Arr:
    return np.asarray(a.real * a.real + a.imag * a.imag)


@dataclass
class State:
    """Positions (``pos``), velocities (``vel``) and accelerations (``acc``) of every point,
    ``(N, 2)`` each, ω and ε of every moving link, the unit slide direction of each link that
    has one (``slide``), and for each sliding pair, keyed by the block's joint, the relative
    velocity along the slide (signed, ``v_rel``) and the Coriolis acceleration (signed, along
    the slide's left normal, ``a_cor``). ``z``, ``vz``, ``az`` and ``sz`` are the same points
    as complex numbers."""

    phi: Arr
    omega1: float
    z: dict[str, Cx] = field(default_factory=dict)
    vz: dict[str, Cx] = field(default_factory=dict)
    az: dict[str, Cx] = field(default_factory=dict)
    sz: dict[int, Cx] = field(default_factory=dict)
    omega: dict[int, Arr] = field(default_factory=dict)
    eps: dict[int, Arr] = field(default_factory=dict)
    v_rel: dict[str, Arr] = field(default_factory=dict)
    a_cor: dict[str, Arr] = field(default_factory=dict)

    @property
    def pos(self) -> dict[str, Arr]:
        return {k: _xy(v) for k, v in self.z.items()}

    @property
    def vel(self) -> dict[str, Arr]:
        return {k: _xy(v) for k, v in self.vz.items()}

    @property
    def acc(self) -> dict[str, Arr]:
        return {k: _xy(v) for k, v in self.az.items()}

    @property
    def slide(self) -> dict[int, Arr]:
        return {k: _xy(v) for k, v in self.sz.items()}


def _raise(step: str, bad: npt.NDArray[np.bool_], phi: Arr, why: str) -> None:
    if np.any(bad):
        i = int(np.argmax(bad))
        deg = math.degrees(float(phi[i])) % 360.0
        raise NoIntersection(step, f"{why} at the crank angle φ = {deg:.6g}°")


def _solve2(c1: Cx, c2: Cx, rhs: Cx) -> tuple[Arr, Arr]:
    """x, y with x·c1 + y·c2 = rhs, row by row (Cramer's rule)."""
    det = _cross(c1, c2)
    return _cross(rhs, c2) / det, _cross(c1, rhs) / det


def sweep(lk: Linkage, phi: npt.ArrayLike, order: int = 2) -> State:
    """The linkage at the crank angles ``phi`` (rad): positions, and with ``order`` ≥ 1
    velocities, with ``order`` 2 accelerations too, at the file's constant ω1."""
    ph = np.ascontiguousarray(np.atleast_1d(np.asarray(phi, dtype=np.float64)))
    n = ph.shape[0]
    if n <= BLOCK:
        return _block(lk, ph, order)
    out = State(ph, lk.omega)
    for start in range(0, n, BLOCK):
        b = _block(lk, ph[start : start + BLOCK], order)
        sl = slice(start, start + b.phi.shape[0])
        for name in ("z", "vz", "az", "sz", "omega", "eps", "v_rel", "a_cor"):
            dst, src = getattr(out, name), getattr(b, name)
            for k, v in src.items():
                if k not in dst:
                    if not v.flags.c_contiguous:  # a constant: broadcast over every angle
                        dst[k] = np.broadcast_to(v[0], (n,))
                        continue
                    dst[k] = np.empty(n, dtype=v.dtype)
                if dst[k].flags.writeable:
                    dst[k][sl] = v
    return out


def _block(lk: Linkage, ph: Arr, order: int) -> State:
    n = ph.shape[0]
    s = State(ph, lk.omega)
    zero = np.broadcast_to(np.complex128(0.0), (n,))
    for name, p in lk.frame.items():
        s.z[name] = np.broadcast_to(np.complex128(complex(p.x, p.y)), (n,))
        s.vz[name] = zero
        s.az[name] = zero
    w1 = lk.omega
    O1 = lk.frame[lk.pivot]
    r = lk.length * np.exp(1j * ph)
    s.z[lk.joint] = complex(O1.x, O1.y) + r
    s.omega[1] = np.broadcast_to(np.float64(w1), (n,))
    s.eps[1] = np.broadcast_to(np.float64(0.0), (n,))
    if order >= 1:
        s.vz[lk.joint] = (1j * w1) * r
    if order >= 2:
        s.az[lk.joint] = -(w1 * w1) * r
    _points_of(lk, s, 1, order)
    for g in lk.groups:
        _GROUP[g.kind](lk, g, s, order)
        for link in g.links:
            _points_of(lk, s, link, order)
    return s


def _points_of(lk: Linkage, s: State, link: int, order: int) -> None:
    for p in lk.points:
        if p.link == link:
            point(s, p, order)


def point(s: State, p: PointDef, order: int) -> None:
    """A ``[[point]]`` of a solved link: P = F + along·u + left·u⊥; V_P = V_F + ω × FP;
    a_P = a_F + ε × FP − ω²·FP."""
    F = s.z[p.frm]
    if p.slide:
        u = s.sz[p.link]
    else:
        t = s.z[p.toward] - F
        u = t / np.sqrt(_abs2(t))
    r = u * complex(p.along, p.left)
    s.z[p.name] = F + r
    if order >= 1:
        w = s.omega[p.link]
        s.vz[p.name] = s.vz[p.frm] + 1j * w * r
    if order >= 2:
        w = s.omega[p.link]
        s.az[p.name] = s.az[p.frm] + (1j * s.eps[p.link] - w * w) * r


def _rrr(lk: Linkage, g: Group, s: State, order: int) -> None:
    P1, P2 = s.z[g.ends[0]], s.z[g.ends[1]]
    l1, l2 = g.lengths
    dv = P2 - P1
    d2 = _abs2(dv)
    d = np.sqrt(d2)
    why = f"the ends {g.ends[0]} and {g.ends[1]} coincide"
    _raise(g.key, d <= tol.REL_LENGTH * (l1 + l2), s.phi, why)
    a = (l1 * l1 - l2 * l2 + d2) / (2.0 * d)
    h2 = l1 * l1 - a * a
    _raise(
        f"{g.key}: {g.joint} = circle({g.ends[0]}, {l1:g}) ∩ circle({g.ends[1]}, {l2:g})",
        ~(h2 >= -tol.TANGENT * max(l1, l2) ** 2),
        s.phi,
        "the group cannot close: the circles do not meet",
    )
    h = np.sqrt(np.maximum(h2, 0.0))
    B = P1 + dv * ((a + (1j * g.branch) * h) / d)
    s.z[g.joint] = B
    if order < 1:
        return
    V1, V2 = s.vz[g.ends[0]], s.vz[g.ends[1]]
    e1, e2 = B - P1, B - P2
    det = _cross(e1, e2)
    _raise(
        f"{g.key}: velocity plan point {g.joint.lower()}",
        np.abs(det) <= tol.ANGLE * l1 * l2,
        s.phi,
        "a dead position: the group's links are collinear",
    )
    # V_B from e_i·(V_B − V_i) = 0: V_B = i(r2·e1 − r1·e2)/det, r_i = e_i·V_i
    VB = 1j * (_dot(e2, V2) * e1 - _dot(e1, V1) * e2) / det
    s.vz[g.joint] = VB
    a_, b_ = g.links
    u1, u2 = VB - V1, VB - V2
    s.omega[a_] = _cross(e1, u1) / (l1 * l1)
    s.omega[b_] = _cross(e2, u2) / (l2 * l2)
    if order < 2:
        return
    A1, A2 = s.az[g.ends[0]], s.az[g.ends[1]]
    r1 = _dot(e1, A1) - _abs2(u1)
    r2 = _dot(e2, A2) - _abs2(u2)
    aB = 1j * (r2 * e1 - r1 * e2) / det
    s.az[g.joint] = aB
    s.eps[a_] = _cross(e1, aB - A1) / (l1 * l1)
    s.eps[b_] = _cross(e2, aB - A2) / (l2 * l2)


def _guide_cx(lk: Linkage, g: Group, s: State) -> tuple[Cx, Cx]:
    gd = g.guide
    assert gd is not None
    n = s.phi.shape[0]
    if gd.fixed:
        gdir = gd.direction
        return (
            np.full(n, complex(gd.through.x, gd.through.y)),
            np.full(n, complex(gdir.x, gdir.y)),
        )
    F, T = s.z[gd.frm], s.z[gd.toward]
    t2 = _abs2(T - F)
    _raise(
        f"{g.key}: guide",
        t2 <= (tol.REL_LENGTH * lk.length) ** 2,
        s.phi,
        f"the guide's points {gd.frm} and {gd.toward} coincide",
    )
    d = (T - F) / np.sqrt(t2)
    return F + 1j * d * gd.offset, d


def guide_line(lk: Linkage, g: Group, s: State) -> tuple[Arr, Arr]:
    """The guide of an RRP/PRP group in every position: a point q on it and its unit
    direction d, ``(N, 2)`` each (a guide on a moving link: from → toward, shifted ``offset``
    to the left)."""
    q, d = _guide_cx(lk, g, s)
    return _xy(q), _xy(d)


def _rrp(lk: Linkage, g: Group, s: State, order: int) -> None:
    gd = g.guide
    assert gd is not None
    B = s.z[g.ends[0]]
    (length,) = g.lengths
    q, d = _guide_cx(lk, g, s)
    bq = B - q
    t0 = _dot(d, bq)
    h = _cross(d, bq)
    w2 = length * length - h * h
    _raise(
        f"{g.key}: {g.joint} = circle({g.ends[0]}, {length:g}) ∩ guide",
        ~(w2 >= -tol.TANGENT * length * length),
        s.phi,
        "the group cannot close: the guide misses the circle",
    )
    D = q + d * (t0 + g.branch * np.sqrt(np.maximum(w2, 0.0)))
    s.z[g.joint] = D
    rod, slider = g.links
    s.sz[slider] = d
    if order < 1:
        return
    n = s.phi.shape[0]
    VB = s.vz[g.ends[0]]
    e = D - B
    den = _dot(e, d)
    _raise(
        f"{g.key}: velocity plan point {g.joint.lower()}",
        np.abs(den) <= tol.ANGLE * length,
        s.phi,
        "a dead position: the rod is perpendicular to the guide",
    )
    if gd.fixed:
        wg = np.zeros(n)
        vr = _dot(e, VB) / den
        VD = d * vr
    else:
        wg = s.omega[gd.link]
        rF = D - s.z[gd.frm]
        VDg = s.vz[gd.frm] + 1j * wg * rF
        vr = _dot(e, VB - VDg) / den
        VD = VDg + d * vr
    s.vz[g.joint] = VD
    u = VD - VB
    s.omega[rod] = _cross(e, u) / (length * length)
    s.omega[slider] = wg
    s.v_rel[g.joint] = vr
    s.a_cor[g.joint] = 2.0 * wg * vr
    if order < 2:
        return
    aB = s.az[g.ends[0]]
    if gd.fixed:
        eg = np.zeros(n)
        ar = (_dot(e, aB) - _abs2(u)) / den
        aD = d * ar
    else:
        eg = s.eps[gd.link]
        aDg = s.az[gd.frm] + (1j * eg - wg * wg) * rF
        acor = 1j * d * (2.0 * wg * vr)
        ar = (_dot(e, aB - aDg - acor) - _abs2(u)) / den
        aD = aDg + acor + d * ar
    s.az[g.joint] = aD
    s.eps[rod] = _cross(e, aD - aB) / (length * length)
    s.eps[slider] = eg


def _rpr_dir(A: Cx, C: Cx, offset: float, step: str, phi: Arr) -> Cx:
    r = A - C
    L2 = _abs2(r)
    t2 = L2 - offset * offset
    _raise(
        step,
        ~(t2 > tol.REL_LENGTH * L2),
        phi,
        f"the slider comes within the offset {abs(offset):g} m of the pivot",
    )
    return np.asarray(r * ((np.sqrt(t2) - 1j * offset) / L2))


def rpr_direction(A: Arr, C: Arr, offset: float, step: str, phi: Arr) -> Arr:
    """The slide line's unit direction of an RPR group, ``(N, 2)``: through A, ``offset`` to the
    left of C looking from C towards A, directed from C's foot to A."""
    return _xy(_rpr_dir(_cx(A), _cx(C), offset, step, phi))


def _rpr(lk: Linkage, g: Group, s: State, order: int) -> None:
    A, C = s.z[g.slider], s.z[g.pivot]
    d = _rpr_dir(A, C, g.offset, f"{g.key}: slide line through {g.slider}", s.phi)
    block, rocker = g.links
    s.sz[block] = d
    s.sz[rocker] = d
    if order < 1:
        return
    ir = 1j * (A - C)
    VA, VC = s.vz[g.slider], s.vz[g.pivot]
    w3, vr = _solve2(ir, d, VA - VC)
    s.omega[block] = w3
    s.omega[rocker] = w3
    s.v_rel[g.slider] = vr
    s.a_cor[g.slider] = 2.0 * w3 * vr
    if order < 2:
        return
    rhs = s.az[g.slider] - s.az[g.pivot] - (w3 * w3) * ir * 1j - 1j * d * (2.0 * w3 * vr)
    e3, _ = _solve2(ir, d, rhs)
    s.eps[block] = e3
    s.eps[rocker] = e3


def prp_frame(g: Group) -> tuple[Arr, Arr, Arr]:
    """A PRP group's guide point, guide direction and slot direction (unit vectors), ``(2,)``."""
    gd = g.guide
    assert gd is not None
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    q = np.array([gd.through.x, gd.through.y])
    return q, np.array([gdir.x, gdir.y]), np.array([sdir.x, sdir.y])


def _prp(lk: Linkage, g: Group, s: State, order: int) -> None:
    gd = g.guide
    assert gd is not None
    n = s.phi.shape[0]
    gdir = gd.direction
    sdir = gdir.rotated(g.slot_angle)
    G = np.full(n, complex(gdir.x, gdir.y))
    S = np.full(n, complex(sdir.x, sdir.y))
    q = complex(gd.through.x, gd.through.y)
    t, _ = _solve2(G, S, s.z[g.slider] - q)
    s.z[g.joint] = np.asarray(q + G * t, dtype=np.complex128)
    block, yoke = g.links
    s.sz[block] = S
    s.sz[yoke] = S
    if order < 1:
        return
    v, w = _solve2(G, S, s.vz[g.slider])
    s.vz[g.joint] = np.asarray(G * v, dtype=np.complex128)
    for link in g.links:
        s.omega[link] = np.zeros(n)
    s.v_rel[g.slider] = w
    s.a_cor[g.slider] = np.zeros(n)
    s.v_rel[g.joint] = v
    s.a_cor[g.joint] = np.zeros(n)
    if order < 2:
        return
    a, _ = _solve2(G, S, s.az[g.slider])
    s.az[g.joint] = np.asarray(G * a, dtype=np.complex128)
    for link in g.links:
        s.eps[link] = np.zeros(n)


_GROUP: dict[str, Callable[[Linkage, Group, State, int], None]] = {
    "RRR": _rrr,
    "RRP": _rrp,
    "RPR": _rpr,
    "PRP": _prp,
}


def output_coordinate(lk: Linkage, s: State) -> Arr | None:
    """s of the output slider along its guide (m), or ``None`` when the output is no slider."""
    g = lk.output_guide
    if g is None:
        return None
    P = s.z[lk.output]
    if g.kind == "RRP":
        q, d = _guide_cx(lk, g, s)
        return _dot(d, P - q)
    gd = g.guide
    assert gd is not None
    dq = gd.direction
    return _dot(np.full(P.shape, complex(dq.x, dq.y)), P - complex(gd.through.x, gd.through.y))


def output_velocity(lk: Linkage, s: State) -> Arr | None:
    """ds/dt of the output slider along its guide (its relative velocity on a moving guide)."""
    g = lk.output_guide
    if g is None:
        return None
    return s.v_rel[lk.output]
