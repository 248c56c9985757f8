"""The loads of a linkage file: weights, inertia loads and the ``[[load]]`` rules.

One law for the numbered positions (read off a :class:`~geomcad.linkage.plans.Position`) and for
the dense sweeps of the dynamics (:class:`~geomcad.linkage.sweep.State` arrays), as linkages.md
settles it:

- a link's centre of mass S is :meth:`Linkage.centre` (``""``: the middle of its two joints;
  its velocity and acceleration are then the mean of theirs, the link being rigid);
- the weight G = m·g along −y at S; the inertia loads Ф = −m·a_S at S and M_Ф = −J·ε;
- a force load on a slider's joint acts on the slider (the link that owns the point) along its
  guide, against the joint's velocity along the guide (its relative velocity on a moving guide),
  with the magnitude ``value·shape(s/H)``, while the output moves on the named stroke (read
  from the sign of the output's velocity; where the output has no strokes, from the joint's
  own). s is the joint's coordinate along its guide, measured from the start of the working
  stroke in the working direction, H its range over a turn. The working direction is the
  file's ``working`` (it belongs to the output; a load on another slider takes the same
  direction);
- a moment load acts on its link: the file's signed moment, or with a ``stroke`` |M| against
  the link's ω while the output moves on that stroke;
- rest is on no stroke: at the output's two extremes (by definition, within
  :data:`EXTREME_ANGLE` of their crank angles) and where |v| < :data:`REST`·|ω1|·l_crank (a
  slider) or |ω_out| < :data:`REST`·|ω1| (a rocker), loads on a stroke are zero;
- several loads on one point or one link act together (their sum).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.geom import Vec
from geomcad.linkage.cycle import Cycle
from geomcad.linkage.model import Group, Linkage
from geomcad.linkage.model import Load as LoadRule
from geomcad.linkage.sweep import State, guide_line, prp_frame, sweep

Arr = npt.NDArray[np.float64]

#: A slider whose velocity along its guide is below this fraction of |ω1|·l_crank is at rest.
REST = tol.DERIVED
#: A crank angle this close (rad) to one of the output's extremes is that extreme.
EXTREME_ANGLE = tol.DERIVED
#: Samples of a turn for the range of a loaded slider that is not the output.
RANGE_SAMPLES = 7200


@dataclass(frozen=True)
class Range:
    """The range of a loaded slider's coordinate along its guide over a turn (m)."""

    s_min: float
    s_max: float

    @property
    def H(self) -> float:
        return self.s_max - self.s_min


def slider_group(lk: Linkage, point: str) -> Group:
    """The RRP or PRP group whose slider joint is ``point``."""
    for g in lk.groups:
        if g.joint == point and g.kind in ("RRP", "PRP"):
            return g
    raise KeyError(point)


def ranges(lk: Linkage, cyc: Cycle | None) -> dict[str, Range]:
    """The stroke range of every loaded slider (the output's from its cycle)."""
    out: dict[str, Range] = {}
    for ld in lk.loads:
        if not ld.point or ld.point in out:
            continue
        if ld.point == lk.output and cyc is not None and not lk.rocker:
            out[ld.point] = Range(cyc.s_min, cyc.s_max)
            continue
        phi = np.linspace(0.0, 2.0 * math.pi, RANGE_SAMPLES, endpoint=False)
        st = sweep(lk, phi, order=0)
        s, _ = guide_coordinate(lk, slider_group(lk, ld.point), st)
        out[ld.point] = Range(float(np.min(s)), float(np.max(s)))
    return out


def guide_coordinate(lk: Linkage, g: Group, st: State) -> tuple[Arr, Arr]:
    """s of a slider's joint along its guide and the guide's unit direction, ``(N,)`` and
    ``(N, 2)``."""
    n = st.phi.shape[0]
    if g.kind == "RRP":
        q, d = guide_line(lk, g, st)
    else:
        q0, d0, _ = prp_frame(g)
        q, d = np.broadcast_to(q0, (n, 2)), np.broadcast_to(d0, (n, 2))
    P = st.pos[g.joint]
    return np.einsum("ij,ij->i", P - q, d), np.asarray(d, dtype=np.float64)


def piece(shape: tuple[tuple[float, float], ...], u: Arr) -> Arr:
    """shape(u) for u = s/H: the linear pieces through the file's points (1 without a shape)."""
    if not shape:
        return np.ones_like(u)
    xs = np.array([p[0] for p in shape])
    ys = np.array([p[1] for p in shape])
    return np.asarray(np.interp(np.clip(u, 0.0, 1.0), xs, ys), dtype=np.float64)


def at_extreme(cyc: Cycle | None, phi: Arr) -> Arr:
    """True at the crank angles that are the output's two extremes (within
    :data:`EXTREME_ANGLE`): the output rests there by definition."""
    phi = np.asarray(phi, dtype=np.float64)
    if cyc is None:
        return np.zeros(phi.shape, dtype=bool)
    two = 2.0 * math.pi
    out = np.zeros(phi.shape, dtype=bool)
    for e in (cyc.phi_min, cyc.phi_max):
        d = np.abs(np.remainder(phi - e + math.pi, two) - math.pi)
        out |= d <= EXTREME_ANGLE
    return out


def stroke_sign(lk: Linkage, cyc: Cycle | None, phi: Arr, v_out: Arr | None) -> Arr | None:
    """+1 where the output moves on its working stroke, −1 on the idle one, 0 at rest (an
    extreme, or |v| < REST·|ω1|·l_crank for a slider, |ω_out| < REST·|ω1| for a rocker);
    ``None`` when the output has no strokes."""
    if cyc is None or v_out is None:
        return None
    fwd = 1.0 if lk.working == "forward" else -1.0
    rest = REST * abs(lk.omega) * (1.0 if lk.rocker else lk.length)
    v = np.asarray(v_out, dtype=np.float64)
    still = np.logical_or(np.abs(v) < rest, at_extreme(cyc, phi))
    sign = np.where(still, 0.0, np.sign(v))
    return np.asarray(sign * fwd, dtype=np.float64)


def _on(stroke: str, moving: Arr) -> npt.NDArray[np.bool_]:
    if stroke == "working":
        return np.asarray(moving > 0)
    if stroke == "idle":
        return np.asarray(moving < 0)
    return np.asarray(moving != 0)


def force_value(
    lk: Linkage, ld: LoadRule, rng: Range, s: Arr, v: Arr, moving: Arr | None = None
) -> Arr:
    """The signed magnitude of a force load along its guide's direction at coordinates ``s``
    and velocities ``v`` along the guide (arrays): −value·shape(s/H)·sign(v) on its stroke
    (``moving``: the output's :func:`stroke_sign`; ``None``: read from ``v`` itself)."""
    fwd = 1.0 if lk.working == "forward" else -1.0
    u = (s - rng.s_min) / rng.H if fwd > 0 else (rng.s_max - s) / rng.H
    rest = REST * abs(lk.omega) * lk.length
    sign = np.where(np.abs(v) <= rest, 0.0, np.sign(v))
    if moving is None:
        moving = sign * fwd  # +1 on the working stroke, −1 on the idle one, 0 at rest
    on = _on(ld.stroke, moving)
    return np.asarray(np.where(on, -ld.value * piece(ld.shape, u) * sign, 0.0), dtype=np.float64)


def moment_value(ld: LoadRule, omega: Arr, moving: Arr | None) -> Arr:
    """A moment load on its link (N·m, ccw > 0): the file's signed moment, or with a
    ``stroke`` |M| against the link's ω while the output moves on that stroke."""
    w = np.asarray(omega, dtype=np.float64)
    if not ld.on_stroke:
        return np.full(w.shape, ld.moment)
    assert moving is not None
    on = _on(ld.stroke, moving)
    return np.asarray(np.where(on, -abs(ld.moment) * np.sign(w), 0.0), dtype=np.float64)


def centre_arrays(lk: Linkage, link: int, data: dict[str, Arr]) -> Arr:
    """A link's centre of mass from a dict of point arrays (positions, velocities or
    accelerations: the middle of two joints is the mean of theirs)."""
    name = lk.centre(link)
    if name:
        return data[name]
    a, b = lk.link_points(link)[:2]
    return 0.5 * (data[a] + data[b])


def centre_name(lk: Linkage, link: int) -> str:
    """The centre's label: its point's name, or S<link> for the middle of the joints."""
    return lk.centre(link) or f"S{link}"


def centre_vec(lk: Linkage, link: int, data: dict[str, Vec]) -> Vec:
    """A link's centre of mass from a dict of Vec (see :func:`centre_arrays`)."""
    name = lk.centre(link)
    if name:
        return data[name]
    a, b = lk.link_points(link)[:2]
    return (data[a] + data[b]) * 0.5
