"""The output over a crank turn: its extremes, the stroke H (or a rocker's swing), K, and the
numbered positions.

The output slider's coordinate s(φ) along its guide (a rocker's angle ψ, unwrapped) is swept
over a turn; a "rocker" whose angle gains a whole turn is a crank: no cycle; each extreme is a root
of ds/dφ between two samples of opposite sign, refined by :func:`scipy.optimize.brentq`. The
working stroke runs from s_min to s_max (``working = "forward"``) or from s_max to s_min; the
crank's turn during it, measured in the crank's sense of rotation, is φ_w, and K = φ_w / (2π − φ_w).
Position 0 of ``positions = N`` is the crank angle where the working stroke begins; position k
lies k·2π/N further in the crank's sense of rotation. A mechanism whose output is no slider is
numbered from φ = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from geomcad import tol
from geomcad.errors import ConstructionError
from geomcad.linkage.model import Linkage
from geomcad.linkage.sweep import output_coordinate, output_velocity, sweep

#: Samples of a turn used to bracket the output's extremes.
SAMPLES = 720


@dataclass(frozen=True)
class Cycle:
    """The output's cycle: ``phi_min``/``phi_max`` (rad, crank angles of s_min and s_max),
    ``s_min``/``s_max`` (m), ``stroke`` H, ``K``, the working stroke's start ``phi_start`` and
    the crank's turn ``phi_working`` during it (rad)."""

    phi_min: float
    phi_max: float
    s_min: float
    s_max: float
    phi_start: float
    phi_working: float

    @property
    def stroke(self) -> float:
        return self.s_max - self.s_min

    @property
    def K(self) -> float:
        return self.phi_working / (2.0 * math.pi - self.phi_working)

    @property
    def swing_deg(self) -> float:
        """A rocker's swing ψ_max − ψ_min in degrees (its ``stroke`` is in radians)."""
        return math.degrees(self.stroke)

    @property
    def phi_end(self) -> float:
        """The crank angle where the working stroke ends (the idle stroke begins)."""
        return self.phi_min if self.phi_start == self.phi_max else self.phi_max


def cycle(lk: Linkage) -> Cycle | None:
    """The output slider's cycle, or ``None`` when the output is no slider.

    Raises :class:`ConstructionError` when the output does not move (H = 0)."""
    if lk.output_guide is None and not lk.rocker:
        return None
    phi = np.linspace(0.0, 2.0 * math.pi, SAMPLES + 1)
    st = sweep(lk, phi, order=1)
    s_all = output_coordinate(lk, st)
    assert s_all is not None
    if lk.rocker and abs(s_all[-1] - s_all[0]) > math.pi:
        return None  # the link turns fully: a crank, no swing
    s = s_all[:-1]
    phi = phi[:-1]
    i_min, i_max = int(np.argmin(s)), int(np.argmax(s))
    scale = 1.0 if lk.rocker else lk.length
    if s[i_max] - s[i_min] <= tol.REL_LENGTH * 1.0e3 * scale:
        raise ConstructionError(f"output {lk.output}", "the output does not move over a turn")

    def v(x: float) -> float:
        out = output_velocity(lk, sweep(lk, [x], order=1))
        assert out is not None
        return float(out[0])

    def refine(i: int) -> float:
        h = 2.0 * math.pi / SAMPLES
        x = float(phi[i])
        for a, b in ((x - h, x), (x, x + h)):
            fa, fb = v(a), v(b)
            if fa == 0.0:
                return a % (2.0 * math.pi)
            if fa * fb <= 0.0:
                root: float = brentq(v, a, b, xtol=tol.ROOT_ANGLE)
                return root % (2.0 * math.pi)
        return float(phi[i] % (2.0 * math.pi))

    p_min, p_max = refine(i_min), refine(i_max)
    sm = output_coordinate(lk, sweep(lk, [p_min, p_max], order=0))
    assert sm is not None
    if lk.rocker:  # the refined angles on the sweep's unwrapped branch
        two = 2.0 * math.pi
        refs = (s[i_min], s[i_max])
        sm = np.array([x + two * round((r - x) / two) for x, r in zip(sm, refs, strict=True)])
    sign = 1.0 if lk.omega > 0 else -1.0
    start, end = (p_min, p_max) if lk.working == "forward" else (p_max, p_min)
    working = (sign * (end - start)) % (2.0 * math.pi)
    return Cycle(p_min, p_max, float(sm[0]), float(sm[1]), start, working)


def numbered(lk: Linkage, cyc: Cycle | None, n: int) -> list[float]:
    """The crank angles (rad, in [0, 2π)) of positions 0 … n−1 (see the module's docstring)."""
    start = cyc.phi_start if cyc is not None else 0.0
    sign = 1.0 if lk.omega > 0 else -1.0
    return [(start + sign * k * 2.0 * math.pi / n) % (2.0 * math.pi) for k in range(n)]


def stroke_middles(lk: Linkage, cyc: Cycle) -> tuple[float, float]:
    """The crank angles in the middles of the working and the idle stroke (by crank turn)."""
    sign = 1.0 if lk.omega > 0 else -1.0
    w = cyc.phi_working
    mid_w = (cyc.phi_start + sign * w / 2.0) % (2.0 * math.pi)
    mid_i = (cyc.phi_start + sign * (w + (2.0 * math.pi - w) / 2.0)) % (2.0 * math.pi)
    return mid_w, mid_i
