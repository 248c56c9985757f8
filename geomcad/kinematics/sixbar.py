"""The six-bar of problem 2013-6: crank-rocker O1ABO2 driving slider C through link BC.

Positions and velocity analogues (ω1 = 1 rad/s) over whole arrays of crank angles, and the
check by analysis: the slider's actual stroke and coefficient of velocity change over a turn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from geomcad import tol
from geomcad.errors import ConstructionError
from geomcad.geom import Vec
from geomcad.kinematics.dyads import Arr, cross, perp, rrp, rrp_velocity, rrr, rrr_velocity

#: Samples per turn for locating the slider's extreme positions before refining them.
SWEEP_SAMPLES = 3600


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
class SixBar:
    """Crank O1A (l1), coupler AB (l2), rocker O2B (l3), link BC (l4), slider C on a guide.

    ``guide_p`` and unit ``guide_d`` give the slider's line; ``branch_B`` (±1) is B's side of
    the directed line A → O2 and ``branch_C`` (±1) C's side along the guide from B's foot: both
    fixed for the whole turn. φ is the crank angle from +x, counter-clockwise.
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

    def positions(self, phi: Arr) -> tuple[Arr, Arr, Arr]:
        """A, B, C as ``(N, 2)`` arrays for crank angles ``phi`` (rad)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=np.float64))
        n = phi.shape[0]
        o1 = np.broadcast_to(self.O1.array(), (n, 2))
        o2 = np.broadcast_to(self.O2.array(), (n, 2))
        a = o1 + self.l1 * np.stack([np.cos(phi), np.sin(phi)], axis=-1)
        b = rrr(a, self.l2, o2, self.l3, self.branch_B, "B = circle(A, l2) ∩ circle(O2, l3)")
        c = rrp(
            b,
            self.l4,
            self.guide_p.array(),
            self.guide_d.array(),
            self.branch_C,
            "C = circle(B, l4) ∩ slider path",
        )
        return a, b, c

    def velocities(self, phi: Arr, omega1: float = 1.0) -> tuple[Arr, Arr, Arr]:
        """V_A, V_B, V_C for crank angles ``phi`` at crank speed ``omega1`` (rad/s, ccw > 0)."""
        a, b, c = self.positions(phi)
        o1 = self.O1.array()
        va = omega1 * perp(a - o1)
        vb = rrr_velocity(a, va, self.O2.array(), np.zeros_like(va), b, "velocity of B")
        vc = rrp_velocity(b, vb, c, self.guide_d.array(), "velocity of C")
        return va, vb, vc

    def slider_s(self, phi: Arr) -> Arr:
        """The slider's coordinate along its guide (m)."""
        _, _, c = self.positions(phi)
        return np.asarray((c - self.guide_p.array()) @ self.guide_d.array(), dtype=np.float64)

    def slider_v(self, phi: Arr, omega1: float = 1.0) -> Arr:
        """The slider's velocity along its guide (m/s at ``omega1``; the analogue for ω1 = 1)."""
        _, _, vc = self.velocities(phi, omega1)
        return np.asarray(vc @ self.guide_d.array(), dtype=np.float64)

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
