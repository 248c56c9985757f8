"""Assur dyads solved over whole arrays of positions at once (numpy), with an explicit branch.

Every function takes ``(N, 2)`` arrays of points (or broadcastable ones) and returns ``(N, 2)``
arrays; the branch flag is fixed for the whole sweep, so a mechanism never jumps to its other
assembly mode. A position where a dyad cannot close raises :class:`NoIntersection` naming the step
and the first failing index.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import NoIntersection, ParameterError

Arr = npt.NDArray[np.float64]


def cross(a: Arr, b: Arr) -> Arr:
    """z-component of a × b, row by row."""
    return np.asarray(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0], dtype=np.float64)


def dot(a: Arr, b: Arr) -> Arr:
    """a · b, row by row."""
    return np.asarray(a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1], dtype=np.float64)


def perp(a: Arr) -> Arr:
    """Each vector turned 90° counter-clockwise."""
    return np.stack([-a[..., 1], a[..., 0]], axis=-1)


def _fail(step: str, bad: npt.NDArray[np.bool_], why: str) -> None:
    if np.any(bad):
        i = int(np.argmax(bad))
        raise NoIntersection(step, f"{why} (first at position index {i})")


def rrr(p1: Arr, r1: float, p2: Arr, r2: float, branch: int, step: str = "RRR dyad") -> Arr:
    """The joint at distance r1 from p1 and r2 from p2 (circle ∩ circle).

    ``branch`` +1 takes the point on the left of p1 → p2, −1 the one on the right (the order of
    :func:`geomcad.geom.circle_circle`).
    """
    dv = p2 - p1
    d2 = dot(dv, dv)
    d = np.sqrt(d2)
    a = (r1 * r1 - r2 * r2 + d2) / (2.0 * d)
    h2 = r1 * r1 - a * a
    scale = max(r1, r2)
    _fail(
        step,
        ~(h2 >= -tol.TANGENT * scale * scale),
        "the dyad cannot close: the circles do not meet",
    )
    h = np.sqrt(np.maximum(h2, 0.0))
    u = dv / d[..., None]
    return np.asarray(p1 + u * a[..., None] + perp(u) * (branch * h)[..., None], dtype=np.float64)


def rrp(p: Arr, r: float, q: Arr, d: Arr, branch: int, step: str = "RRP dyad") -> Arr:
    """The slider joint on the line q + t·d (d unit) at distance r from p (circle ∩ line).

    ``branch`` +1 takes the point further along d, −1 the nearer one (the order of
    :func:`geomcad.geom.line_circle`).
    """
    t0 = dot(p - q, d)
    h = cross(d, p - q)
    w2 = r * r - h * h
    _fail(step, ~(w2 >= -tol.TANGENT * r * r), "the dyad cannot close: the line misses the circle")
    w = np.sqrt(np.maximum(w2, 0.0))
    return np.asarray(q + d * (t0 + branch * w)[..., None], dtype=np.float64)


def rrr_velocity(p1: Arr, v1: Arr, p2: Arr, v2: Arr, b: Arr, step: str = "RRR dyad") -> Arr:
    """The velocity of joint b of an RRR dyad from its two vector equations.

    V_B = V_1 + V_B1 with V_B1 ⊥ B p1, and V_B = V_2 + V_B2 with V_B2 ⊥ B p2: the two lines of
    the velocity plan meet in b. Solved in closed form: (b − p_i)·(V_B − v_i) = 0.
    """
    e1 = b - p1
    e2 = b - p2
    det = cross(e1, e2)
    scale = np.sqrt(dot(e1, e1) * dot(e2, e2))
    _fail(
        step, np.abs(det) <= tol.ANGLE * scale, "the dyad is in a dead position (links collinear)"
    )
    r1 = dot(e1, v1)
    r2 = dot(e2, v2)
    vx = (r1 * e2[..., 1] - r2 * e1[..., 1]) / det
    vy = (e1[..., 0] * r2 - e2[..., 0] * r1) / det
    return np.stack([vx, vy], axis=-1)


def rrp_velocity(p: Arr, vp: Arr, c: Arr, d: Arr, step: str = "RRP dyad") -> Arr:
    """The velocity of slider c on a fixed guide along d, linked to p by a rod.

    V_C = V_P + V_CP with V_C ∥ the guide and V_CP ⊥ CP: (c − p)·(V_C − V_P) = 0.
    """
    e = c - p
    den = dot(e, d)
    scale = np.sqrt(dot(e, e))
    _fail(step, np.abs(den) <= tol.ANGLE * scale, "the rod is perpendicular to the guide")
    v = dot(e, vp) / den
    return np.asarray(d * v[..., None], dtype=np.float64)


def rrr_acceleration(
    p1: Arr,
    v1: Arr,
    a1: Arr,
    p2: Arr,
    v2: Arr,
    a2: Arr,
    b: Arr,
    vb: Arr,
    step: str = "RRR dyad",
) -> Arr:
    """The acceleration of joint b of an RRR dyad from its two vector equations.

    a_B = a_1 + a^n_B1 + a^τ_B1 = a_2 + a^n_B2 + a^τ_B2, where a^n_Bi = V_Bi² / l_i points from
    B to p_i and a^τ_Bi ⊥ B p_i. Projected on the link B p_i the tangential term drops out and the
    normal one is −|V_Bi|², so the two lines of the acceleration plan give the 2×2 system
    (b − p_i)·a_B = (b − p_i)·a_i − |v_b − v_i|², solved in closed form.

    ``p1, v1, a1`` and ``p2, v2, a2`` are the outer joints with their velocities and
    accelerations, ``b, vb`` the dyad's joint and its velocity (from :func:`rrr_velocity`).
    Raises :class:`NoIntersection` naming ``step`` where the links are collinear (dead position).
    """
    e1 = b - p1
    e2 = b - p2
    u1 = vb - v1
    u2 = vb - v2
    det = cross(e1, e2)
    scale = np.sqrt(dot(e1, e1) * dot(e2, e2))
    _fail(
        step, np.abs(det) <= tol.ANGLE * scale, "the dyad is in a dead position (links collinear)"
    )
    r1 = dot(e1, a1) - dot(u1, u1)
    r2 = dot(e2, a2) - dot(u2, u2)
    ax = (r1 * e2[..., 1] - r2 * e1[..., 1]) / det
    ay = (e1[..., 0] * r2 - e2[..., 0] * r1) / det
    return np.stack([ax, ay], axis=-1)


def rrp_acceleration(
    p: Arr, vp: Arr, ap: Arr, c: Arr, vc: Arr, d: Arr, step: str = "RRP dyad"
) -> Arr:
    """The acceleration of slider c on a fixed guide along d (unit), linked to p by a rod.

    a_C = a_P + a^n_CP + a^τ_CP with a_C ∥ the guide, a^n_CP = V_CP² / l from C to P and
    a^τ_CP ⊥ CP. Projected on the rod: (c − p)·a_C = (c − p)·a_P − |v_c − v_p|², and a_C = α d.
    Raises :class:`NoIntersection` naming ``step`` where the rod is perpendicular to the guide.
    """
    e = c - p
    u = vc - vp
    den = dot(e, d)
    scale = np.sqrt(dot(e, e))
    _fail(step, np.abs(den) <= tol.ANGLE * scale, "the rod is perpendicular to the guide")
    alpha = (dot(e, ap) - dot(u, u)) / den
    return np.asarray(d * alpha[..., None], dtype=np.float64)


def _one_link(p: Arr, vp: Arr, q: Arr, vq: Arr) -> tuple[Arr, Arr, Arr]:
    """e = q − p, u = v_q − v_p and |e|², refusing where p and q cannot be two points of one
    rigid link: where they coincide, or where their relative velocity has a component along pq
    (a rigid link's V_QP is ⊥ PQ). A block sliding on the link is such a case: the point under
    the block moves with the link, the block's joint does not, and the difference is the
    relative velocity along the slide whose Coriolis term 2ω × V_rel no two-point formula sees.
    """
    e = np.asarray(q, dtype=np.float64) - np.asarray(p, dtype=np.float64)
    u = np.asarray(vq, dtype=np.float64) - np.asarray(vp, dtype=np.float64)
    e2 = dot(e, e)
    if np.any(~(e2 > 0.0)):
        i = int(np.argmax(~(e2 > 0.0))) if e2.ndim else 0
        raise ParameterError(
            f"q[{i}]" if e2.ndim else "q", "p", "the two points of a link must not coincide"
        )
    along = dot(e, u)
    bad = ~(np.abs(along) <= tol.DERIVED * np.sqrt(e2 * dot(u, u)))
    if np.any(bad):
        i = int(np.argmax(bad)) if bad.ndim else 0
        v = float(np.reshape(along / np.sqrt(e2), -1)[i])
        raise ParameterError(
            f"vq[{i}]" if bad.ndim else "vq",
            v,
            "q is no point of the link through p: its velocity relative to p has this component "
            "along pq (m/s) (a slider on the link? its relative velocity and Coriolis term are "
            "not this formula's: take ω and ε from the sweep, geomcad.kinematics.chain)",
        )
    return e, u, e2


def angular_velocity(p: Arr, vp: Arr, q: Arr, vq: Arr) -> Arr:
    """The angular velocity (rad/s, counter-clockwise > 0) of the link through p and q.

    V_QP = V_Q − V_P ⊥ PQ and ω = V_QP / l_PQ, its sense that of V_QP turning about P:
    ω = (q − p) × (v_q − v_p) / |q − p|². p and q must be two points of the link: where their
    relative velocity is not ⊥ PQ (q the joint of a block sliding on the link, say) there is no
    right answer and :class:`ParameterError` is raised.
    """
    e, u, e2 = _one_link(p, vp, q, vq)
    return np.asarray(cross(e, u) / e2, dtype=np.float64)


def angular_acceleration(p: Arr, vp: Arr, ap: Arr, q: Arr, vq: Arr, aq: Arr) -> Arr:
    """The angular acceleration (rad/s², counter-clockwise > 0) of the link through p and q.

    a_QP = a_Q − a_P = −ω² (q − p) + ε (q − p) turned 90°: only the tangential term has a
    component across the link, so ε = (q − p) × (a_q − a_p) / |q − p|². The velocities show
    whether p and q are two points of one link (V_QP ⊥ PQ): for q the joint of a block sliding
    on the link, a_Q − a_P would hold the relative and Coriolis accelerations, and the formula
    would give a wrong ε (19.985 instead of 12.299 rad/s² for a slotted lever with crank 0.1 m,
    pivots 0.3 m apart, φ = 30°, ω1 = 10): :class:`ParameterError` is raised instead.
    """
    e, _, e2 = _one_link(p, vp, q, vq)
    da = np.asarray(aq, dtype=np.float64) - np.asarray(ap, dtype=np.float64)
    return np.asarray(cross(e, da) / e2, dtype=np.float64)
