"""Cam design: the smallest cam by the pressure angle, the flat face's convexity, rocking followers.

**The S–S′ diagram (translating follower).** With the follower's lowest point B0 as the origin,
each position is the point (x, S) with x = −σ·S′ (the velocity analogue laid off across the path,
turned by 90° against the sense σ of the cam's rotation: σ = +1 counter-clockwise). The cam's
centre O = (X, Y) sees the point under the pressure angle: the line from O to (x, S) is parallel
to the normal at the contact, so tan α = (x − X)/(S − Y) (Y < 0). |α| ≤ α_allowed at a point
means O lies in the wedge below it bounded by the two rays at ±α_allowed from the downward
vertical: Y ≤ S − |x − X|/tg α_allowed. Over all the points of a phase group with one allowed
angle this is Y ≤ c − X/t and Y ≤ c′ + X/t, where c = min (S + x/t) and c′ = min (S − x/t) are
the intercepts of the two rays *tangent* to the diagram (t = tg α_allowed): the zone of
admissible centres is bounded by at most four rays (two on the rise, with the rise's allowed
angle; two on the return, with the return's), the textbook's construction, exactly. The offset of
the follower's axis is e = −X (the axis at x = e from O, as :mod:`geomcad.kinematics.cams`
writes it), and r0 = |OB0| = √(X² + Y²).

The centre nearest B0 in the zone (the least r0) is its point closest to the origin: the zone is
convex, so it is a vertex or the foot of the perpendicular on one ray, both found exactly.

**Flat face.** The profile is convex where ρ = r0 + S + S″ > 0; the smallest base circle is
r0_min = max (ρ_min − S − S″) over the turn (ρ_min ≥ 0 a required smallest radius of curvature).
The pressure angle of a face perpendicular to the motion is 0.

**Rocking follower (knife or roller).** The pivot A and the arm l: the follower's point B swings
on the arc (A, l). With B0 at the origin, the arm horizontal at mid-swing and pointing from A to
the left, B(ψ) = A + l·(−cos θ, sin θ), θ = ψ − ψ_max/2, A = l·(cos ψ_max/2, sin ψ_max/2): the
rise lifts B (the arm turns clockwise). The velocity analogue l·ψ′ laid off along the arm from B
gives C = A + (1 + σψ′)(B − A); the line OC is parallel to the normal at the contact (the
relative instantaneous centre lies on OA; the intercept theorem), so the pressure angle at B is
the angle between OC and the perpendicular to the arm at C. O must lie in the wedge at each C
of half-angle α_allowed about the perpendicular pointing away from the follower (downwards):
two half-planes per point. Their intersection (the zone) is convex; it is found from the
half-planes of the positions sampled at ``ZONE_STEP`` (and both sides of each jump), and its point
nearest B0 is the least r0; the pivot distance a_w = |OA| follows. With a_w given, O lies on the
circle (A, a_w), and the zone's point on it nearest B0 is taken.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq, linprog, minimize, minimize_scalar

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError
from geomcad.kinematics.cams import _samples
from geomcad.kinematics.motion_laws import CamProgram, FloatArray, Motion

#: Angular step of the sampled positions the zones and extremes start from (rad): a quarter degree.
ZONE_STEP = math.radians(0.25)
#: Angular step of the sampled rocker zone's half-planes (rad).
ROCKER_STEP = math.radians(0.1)

STEP_ZONE = "zone of admissible centres (S–S′ diagram, allowed pressure angle)"
STEP_ROCKER_ZONE = "zone of admissible centres (ψ–lψ′ diagram, allowed pressure angle)"
STEP_CONVEX = "r0_min from the convexity of the flat face (r0 + S + S″ > 0)"


def check_allowed(name: str, alpha: float) -> float:
    """tg of an allowed pressure angle (rad), which must lie strictly between 0 and 90°."""
    if not (math.isfinite(alpha) and 0.0 < alpha < math.pi / 2.0):
        raise ParameterError(
            name, math.degrees(alpha), "the allowed pressure angle must lie between 0 and 90°"
        )
    return math.tan(alpha)


def phase_name(program: CamProgram, phi: float) -> str:
    """Which phase an angle lies in, in words: ``phase 3 (return, cycloidal)``."""
    b = program.boundaries
    k = int(np.clip(np.searchsorted(b, phi, side="right") - 1, 0, len(program.phases) - 1))
    if phi >= b[-1] * (1.0 + tol.DERIVED) or phi < 0.0:
        return "the lower dwell"
    ph = program.phases[k]
    what = ph.kind if ph.kind == "dwell" else f"{ph.kind}, {ph.law}"
    return f"phase {k + 1} ({what})"


def _phase_motion(program: CamProgram, k: int, phi: FloatArray) -> Motion:
    """The motion on phase k at angles inside it, its end values taken from inside the phase."""
    b = program.boundaries
    right = program.motion(phi, "right")
    left = program.motion(phi, "left")
    at_end = phi >= b[k + 1]
    return Motion(
        phi,
        np.where(at_end, left.S, right.S),
        np.where(at_end, left.S1, right.S1),
        np.where(at_end, left.S2, right.S2),
    )


def check_jumps(program: CamProgram, follower: str, step: str) -> None:
    """A drop of S′ at a break (the linear law's end) under a roller or a flat face is a cusp:
    the follower would have to enter a convex corner. An error names the phases and the angle."""
    if follower == "knife":
        return
    b = program.boundaries
    eps = tol.DERIVED * program.H / min(ph.angle for ph in program.phases)
    for at in program.breaks():
        x = float(at) % (2.0 * math.pi)
        d0 = float(program.motion([x if x > 0.0 else 2.0 * math.pi], "left").S1[0])
        d1 = float(program.motion([x], "right").S1[0])
        if d1 < d0 - eps:
            k = int(np.clip(np.searchsorted(b, x, side="right") - 1, 0, len(program.phases) - 1))
            before = (
                phase_name(program, float(b[k]) - 0.5 * program.phases[k - 1].angle)
                if k
                else (phase_name(program, float(b[-1]) - tol.DERIVED))
            )
            what = "the flat face" if follower == "flat" else "the roller"
            raise ConstructionError(
                step,
                f"S′ drops from {d0:.6g} to {d1:.6g} at φ = {math.degrees(x):.6g}°, between "
                f"{before} and {phase_name(program, x)}: {what} would have to enter a convex "
                "corner of the profile (a cusp); choose a law whose S′ is continuous there",
            )


def phase_extreme(
    program: CamProgram,
    k: int,
    qty: Callable[[Motion], FloatArray],
    step: float = ZONE_STEP,
) -> tuple[float, float]:
    """The smallest value of ``qty`` on phase ``k`` (both ends included), and its angle:
    sampled at ``step``, then refined between the neighbouring samples by scipy's bounded Brent."""
    b = program.boundaries
    a0, a1 = float(b[k]), float(b[k + 1])
    n = max(8, math.ceil((a1 - a0) / step))
    grid = np.linspace(a0, a1, n + 1)
    vals = qty(_phase_motion(program, k, grid))
    j = int(np.argmin(vals))
    best, at = float(vals[j]), float(grid[j])
    lo, hi = float(grid[max(0, j - 1)]), float(grid[min(n, j + 1)])
    if hi - lo > tol.ROOT_ANGLE:

        def fun(x: float) -> float:
            return float(qty(_phase_motion(program, k, np.array([x])))[0])

        res = minimize_scalar(fun, bounds=(lo, hi), method="bounded",
                              options={"xatol": tol.ROOT_ANGLE})  # fmt: skip
        if float(res.fun) < best:
            best, at = float(res.fun), float(res.x)
    return best, at


# -- translating follower: the S–S′ diagram --------------------------------------------------------


@dataclass(frozen=True)
class ZoneRay:
    """One boundary ray of the zone: Y ≤ c + b·X, tangent to the diagram at the point
    (x, S) of angle ``phi`` in phase group ``group`` ("rise" or "return")."""

    c: float
    b: float
    phi: float
    x: float
    S: float
    group: str

    def y(self, X: float) -> float:
        return self.c + self.b * X


@dataclass(frozen=True)
class TranslatingZone:
    """The zone of admissible centres of a translating follower on the S–S′ diagram."""

    sigma: int
    alpha_rise: float
    alpha_return: float
    rays: tuple[ZoneRay, ...]

    def g(self, X: float) -> float:
        """The zone's upper boundary at X: the admissible centres below it are Y ≤ g(X)."""
        return min(r.y(X) for r in self.rays)

    def contains(self, X: float, Y: float, slack: float = 0.0) -> bool:
        return self.g(X) + slack >= Y

    def nearest(self) -> tuple[float, float]:
        """The zone's point nearest B0 (the origin): the least r0 with a free offset."""
        halves = [(np.array([-r.b, 1.0]), r.c) for r in self.rays]
        return nearest_point(halves, np.zeros(2))


def diagram_x(sigma: int, S1: npt.ArrayLike) -> FloatArray:
    """The abscissa of the S–S′ diagram: x = −σ·S′."""
    return np.asarray(-sigma * np.asarray(S1, dtype=np.float64), dtype=np.float64)


def translating_zone(
    program: CamProgram, sigma: int, alpha_rise: float, alpha_return: float
) -> TranslatingZone:
    """The four rays tangent to the S–S′ diagram that bound the zone (see the module's doc).

    The rise's allowed angle holds on the rise and the dwells, the return's on the return."""
    t_r = check_allowed("pressure_angle_deg", alpha_rise)
    t_t = check_allowed("return_pressure_angle_deg", alpha_return)
    rays: list[ZoneRay] = []
    for group, t in (("rise", t_r), ("return", t_t)):
        ks = [
            k for k, ph in enumerate(program.phases) if (ph.kind == "return") == (group == "return")
        ]
        if not ks:
            continue
        for side in (1.0, -1.0):
            # Y ≤ (S + side·x/t) − side·X/t
            best = (math.inf, 0.0, 0)
            for k in ks:

                def qty(m: Motion, side: float = side, t: float = t) -> FloatArray:
                    return np.asarray(m.S + side * diagram_x(sigma, m.S1) / t, dtype=np.float64)

                v, at = phase_extreme(program, k, qty)
                if v < best[0]:
                    best = (v, at, k)
            v, at, k = best
            m = _phase_motion(program, k, np.array([at]))
            x = float(diagram_x(sigma, m.S1)[0])
            rays.append(ZoneRay(v, -side / t, at, x, float(m.S[0]), group))
    return TranslatingZone(sigma, alpha_rise, alpha_return, tuple(rays))


def flat_r0_min(program: CamProgram, rho_allowed: float = 0.0) -> tuple[float, float]:
    """(r0_min, φ) for a flat face: max (ρ_allowed − S − S″) over the phases (convexity)."""
    best = (-math.inf, 0.0)
    for k, ph in enumerate(program.phases):
        if ph.kind == "dwell":
            v, at = -0.0, float(program.boundaries[k])
        else:
            v, at = phase_extreme(program, k, lambda m: np.asarray(m.S + m.S2))
        if rho_allowed - v > best[0]:
            best = (rho_allowed - v, at)
    return best


# -- the nearest point of a convex polygon ---------------------------------------------------------


def nearest_point(
    halves: Sequence[tuple[npt.NDArray[np.float64], float]], p0: npt.NDArray[np.float64]
) -> tuple[float, float]:
    """The point of {q: n_k·q ≤ h_k} nearest p0, exactly: among the feet of the perpendiculars
    from p0 on the boundary lines and the lines' pairwise crossings, the feasible one nearest p0
    (at most a few dozen lines; :func:`nearest_in_zone` handles many)."""
    n = np.array([h[0] for h in halves], dtype=np.float64)
    hh = np.array([h[1] for h in halves], dtype=np.float64)
    scale = max(1.0, float(np.max(np.abs(hh))))
    slack = tol.DERIVED * scale
    if np.all(n @ p0 <= hh + slack):
        return float(p0[0]), float(p0[1])
    cands: list[npt.NDArray[np.float64]] = []
    for k in range(len(hh)):
        nn = float(n[k] @ n[k])
        cands.append(p0 - (float(n[k] @ p0) - hh[k]) / nn * n[k])
        for j in range(k + 1, len(hh)):
            det = n[k, 0] * n[j, 1] - n[k, 1] * n[j, 0]
            if abs(det) <= tol.RANK:
                continue
            cands.append(
                np.array(
                    [
                        (hh[k] * n[j, 1] - hh[j] * n[k, 1]) / det,
                        (n[k, 0] * hh[j] - n[j, 0] * hh[k]) / det,
                    ]
                )
            )
    best: tuple[float, float] | None = None
    dist = math.inf
    for q in cands:
        if np.all(n @ q <= hh + slack):
            dq = float(np.hypot(*(q - p0)))
            if dq < dist:
                dist, best = dq, (float(q[0]), float(q[1]))
    if best is None:
        raise ConstructionError(STEP_ZONE, "the zone of admissible centres is empty")
    return best


def nearest_in_zone(
    n: npt.NDArray[np.float64], h: npt.NDArray[np.float64], p0: npt.NDArray[np.float64], step: str
) -> tuple[float, float]:
    """The point of {q: n_k·q ≤ h_k} (many half-planes) nearest p0: a feasible start by linear
    programming (the centre of the largest inscribed circle, scipy's HiGHS; none is an error
    naming ``step``), the convex quadratic problem by SLSQP, then polished on the active lines
    (one: the foot of the perpendicular; two: their crossing)."""
    norms = np.hypot(n[:, 0], n[:, 1])
    nu, hu = n / norms[:, None], h / norms
    size = max(1.0, float(np.max(np.abs(hu))))
    big = 100.0 * size
    res = linprog(
        c=[0.0, 0.0, -1.0],
        A_ub=np.column_stack([nu, np.ones(len(hu))]),
        b_ub=hu,
        bounds=[(-big, big), (-big, big), (None, size)],
        method="highs",
    )
    if res.status != 0 or -float(res.fun) <= tol.DERIVED * size:
        raise ConstructionError(
            step,
            "no centre of the cam satisfies the allowed pressure angle at every position (the "
            "wedges of admissible centres have no common point): allow a larger pressure angle, "
            "a smaller swing or a longer arm",
        )
    start = np.asarray(res.x[:2], dtype=np.float64)
    sol = minimize(
        lambda q: float((q - p0) @ (q - p0)),
        start,
        jac=lambda q: 2.0 * (q - p0),
        constraints=[{"type": "ineq", "fun": lambda q: hu - nu @ q, "jac": lambda q: -nu}],
        method="SLSQP",
        options={"ftol": tol.QP_FTOL, "maxiter": 500},
    )
    q = np.asarray(sol.x, dtype=np.float64)
    slack = hu - nu @ q
    active = np.argsort(slack)[:6]
    halves = [(nu[k], float(hu[k])) for k in active]
    best = nearest_point(halves, p0)
    bq = np.array(best)
    if np.all(nu @ bq <= hu + tol.DERIVED * size):
        return best
    return float(q[0]), float(q[1])


# -- rocking follower ------------------------------------------------------------------------------


@dataclass(frozen=True)
class RockerGeometry:
    """A rocking follower in the diagram frame (B0 at the origin): the pivot ``A``, the arm
    ``arm`` l, the swing ``swing`` (rad) and the cam's sense ``sigma``."""

    arm: float
    swing: float
    sigma: int

    @property
    def A(self) -> npt.NDArray[np.float64]:
        h = self.swing / 2.0
        return np.array([self.arm * math.cos(h), self.arm * math.sin(h)])

    def theta(self, psi: npt.ArrayLike) -> FloatArray:
        return np.asarray(np.asarray(psi, dtype=np.float64) - self.swing / 2.0, dtype=np.float64)

    def B(self, psi: npt.ArrayLike) -> FloatArray:
        """The follower's point B at swing ψ (N, 2)."""
        th = self.theta(psi)
        return np.asarray(
            self.A + self.arm * np.stack([-np.cos(th), np.sin(th)], axis=-1), dtype=np.float64
        )

    def C(self, psi: npt.ArrayLike, psi1: npt.ArrayLike) -> FloatArray:
        """The diagram points C = A + (1 + σψ′)(B − A): l·ψ′ laid off along the arm from B."""
        k = 1.0 + self.sigma * np.asarray(psi1, dtype=np.float64)
        return np.asarray(self.A + k[:, None] * (self.B(psi) - self.A), dtype=np.float64)

    def down(self, psi: npt.ArrayLike) -> FloatArray:
        """The unit perpendicular to the arm pointing away from the follower's rise."""
        th = self.theta(psi)
        return np.stack([-np.sin(th), -np.cos(th)], axis=-1)


def _rocker_motion(program: CamProgram, step: float) -> tuple[Motion, list[str]]:
    """The program sampled over the turn with both one-sided values at every break, and per
    sample its group ("rise" for rises and dwells, "return")."""
    m, corner, _ = _samples(program, 0.0, 2.0 * math.pi, True, step)
    keep = ~corner
    m = Motion(m.phi[keep], m.S[keep], m.S1[keep], m.S2[keep])
    b = program.boundaries
    groups = []
    for phi, s1 in zip(m.phi, m.S1, strict=True):
        k = int(np.clip(np.searchsorted(b, phi, side="right") - 1, 0, len(program.phases) - 1))
        ret = program.phases[k].kind == "return" or (
            k > 0 and phi == b[k] and program.phases[k - 1].kind == "return" and s1 < 0.0
        )
        groups.append("return" if ret else "rise")
    return m, groups


@dataclass(frozen=True)
class RockerZone:
    """The zone of a rocking follower as half-planes n_k·O ≤ h_k (two per sampled position)."""

    geometry: RockerGeometry
    n: npt.NDArray[np.float64]
    h: npt.NDArray[np.float64]
    C: npt.NDArray[np.float64]
    down: npt.NDArray[np.float64]
    phi: FloatArray
    t: FloatArray

    def margin(self, q: npt.ArrayLike) -> float:
        """min_k (h_k − n_k·q)/|n_k|: ≥ 0 inside the zone."""
        qq = np.asarray(q, dtype=np.float64)
        return float(np.min(self.h - self.n @ qq))

    def nearest(self) -> tuple[float, float]:
        return nearest_in_zone(self.n, self.h, np.zeros(2), STEP_ROCKER_ZONE)


def rocker_zone(
    program: CamProgram,
    geom: RockerGeometry,
    alpha_rise: float,
    alpha_return: float,
    step: float = ROCKER_STEP,
) -> RockerZone:
    """The half-planes of the rocker's zone: at each C_k the two lines at ±α_allowed from the
    perpendicular to the arm; O on the inner side of both."""
    t_r = check_allowed("pressure_angle_deg", alpha_rise)
    t_t = check_allowed("return_pressure_angle_deg", alpha_return)
    m, groups = _rocker_motion(program, step)
    C = geom.C(m.S, m.S1)
    d = geom.down(m.S)
    t = np.array([t_t if g == "return" else t_r for g in groups])
    a = np.arctan(t)
    rows = []
    rhs = []
    for sgn in (1.0, -1.0):
        # the ray from C at +sgn·α from d; O lies on the side of it towards d:
        # cross(r, O − C)·sgn ≤ 0 … written as n·O ≤ n·C with n = sgn·J⁻¹r
        rx = np.cos(sgn * a) * d[:, 0] - np.sin(sgn * a) * d[:, 1]
        ry = np.sin(sgn * a) * d[:, 0] + np.cos(sgn * a) * d[:, 1]
        # the normal pointing out of the wedge: r turned by +90° times sgn
        nx, ny = -sgn * ry, sgn * rx
        rows.append(np.stack([nx, ny], axis=-1))
        rhs.append(nx * C[:, 0] + ny * C[:, 1])
    return RockerZone(geom, np.vstack(rows), np.concatenate(rhs), C, d, m.phi, t)


def rocker_on_circle(zone: RockerZone, a_w: float) -> tuple[float, float]:
    """The zone's point on the circle (A, a_w) nearest B0 (the origin): the arcs of the circle
    inside the zone, sampled and their ends refined by brentq; none is an error."""
    A = zone.geometry.A
    gam = np.linspace(-math.pi, math.pi, 1441)
    pts = A + a_w * np.stack([np.cos(gam), np.sin(gam)], axis=-1)
    marg = np.min(zone.h[None, :] - pts @ zone.n.T, axis=1)
    ok = marg >= 0.0
    if not np.any(ok):
        raise ConstructionError(
            STEP_ROCKER_ZONE + " ∩ circle (A, a_w)",
            f"no point of the circle of radius a_w = {a_w:.6g} m about the pivot lies in the "
            "zone of admissible centres: no cam centre at this pivot distance keeps the "
            "pressure angle within the allowed one",
        )
    dist = np.hypot(pts[:, 0], pts[:, 1])
    j = int(np.argmin(np.where(ok, dist, np.inf)))

    def f(g: float) -> float:
        return zone.margin(A + a_w * np.array([math.cos(g), math.sin(g)]))

    best = float(gam[j])
    for nb in (j - 1, j + 1):
        if 0 <= nb < len(gam) and not ok[nb]:
            g = brentq(f, float(gam[nb]), float(gam[j]), xtol=tol.ROOT_ANGLE)
            q = A + a_w * np.array([math.cos(g), math.sin(g)])
            if float(np.hypot(*q)) < float(dist[j]):
                best = float(g)
    q = A + a_w * np.array([math.cos(best), math.sin(best)])
    return float(q[0]), float(q[1])


# -- the rocker's profile --------------------------------------------------------------------------


@dataclass(frozen=True)
class RockerProfile:
    """A rocking follower's cam profile over the turn (cam frame, O at the origin): the pitch
    curve (the roller's centre or the knife's tip), the working profile, the signed radii of
    curvature (> 0 convex) and the pressure angle |α| at each sample."""

    phi: FloatArray
    psi: FloatArray
    psi1: FloatArray
    pitch: FloatArray
    contact: FloatArray
    rho_pitch: FloatArray
    rho: FloatArray
    pressure: FloatArray
    corner: npt.NDArray[np.bool_]
    #: the angles where the pitch curve has a convex corner (a drop of the velocity analogue
    #: that a roller cannot follow)
    convex_corners: tuple[float, ...] = ()


def _rocker_frame(
    A: npt.NDArray[np.float64], arm: float, swing: float, sigma: int, m: Motion
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """(q, tangent A-vector, B-vector, arm direction u) in the fixed frame, O at the origin."""
    th = m.S - swing / 2.0
    u = np.stack([-np.cos(th), np.sin(th)], axis=-1)
    ut = np.stack([np.sin(th), np.cos(th)], axis=-1)
    q = A + arm * u
    q1 = arm * m.S1[:, None] * ut
    q2 = arm * (m.S2[:, None] * ut - (m.S1**2)[:, None] * u)
    sg = float(sigma)

    def J(v: FloatArray) -> FloatArray:
        return np.stack([-v[:, 1], v[:, 0]], axis=-1)

    av = q1 - sg * J(q)
    bv = q2 - 2.0 * sg * J(q1) - q
    return q, av, bv, u


def rocker_profile(
    program: CamProgram,
    A: npt.ArrayLike,
    arm: float,
    swing: float,
    sigma: int,
    r_roller: float = 0.0,
    step: float = math.radians(0.5),
) -> RockerProfile:
    """The profile of a rocker with its pivot at ``A`` (fixed frame, cam centre O at the origin),
    by inversion over the full turn; ``r_roller`` 0 is a knife. Nothing is checked here."""
    from geomcad.kinematics.cams import invert

    Av = np.asarray(A, dtype=np.float64)
    m, corner, _ = _samples(program, 0.0, 2.0 * math.pi, True, step)
    q, av, bv, u = _rocker_frame(Av, arm, swing, sigma, m)
    la = np.hypot(av[:, 0], av[:, 1])
    cross = av[:, 0] * bv[:, 1] - av[:, 1] * bv[:, 0]
    with np.errstate(divide="ignore"):
        rho_p = np.where(cross == 0.0, np.inf, -sigma * la**3 / np.where(cross == 0.0, 1.0, cross))
    normal = sigma * np.stack([-av[:, 1], av[:, 0]], axis=-1) / la[:, None]
    contact = q - r_roller * normal
    rho = rho_p - r_roller
    dot = np.abs(av[:, 0] * u[:, 0] + av[:, 1] * u[:, 1])
    crs = np.abs(av[:, 0] * u[:, 1] - av[:, 1] * u[:, 0])
    pressure = np.arctan2(crs, dot)
    rho_p = np.where(corner, 0.0, rho_p)
    rho = np.where(corner, -r_roller if r_roller > 0.0 else 0.0, rho)
    convex: list[float] = []
    n = len(m.phi)
    i = 0
    while i < n:
        if not corner[i]:
            i += 1
            continue
        j = i
        while j < n and corner[j]:
            j += 1
        a0, a1 = av[(i - 1) % n], av[j % n]
        # ρ > 0 where −σ·(A × B) > 0: the corner is convex when the tangent turns that way
        if -sigma * float(a0[0] * a1[1] - a0[1] * a1[0]) > 0.0:
            convex.append(float(m.phi[i]))
        i = j
    return RockerProfile(
        m.phi,
        m.S,
        m.S1,
        invert(q, m.phi, sigma),
        invert(contact, m.phi, sigma),
        rho_p,
        rho,
        pressure,
        corner,
        tuple(convex),
    )


def rocker_pressure_of(
    A: npt.ArrayLike, arm: float, swing: float, sigma: int, m: Motion
) -> FloatArray:
    """|α| of the motion's positions by the direct formula: cos α = |t̂·u|, the pitch curve's
    tangent t against the arm's direction u (the normal against B's velocity, ⊥ the arm)."""
    _, av, _, u = _rocker_frame(np.asarray(A, dtype=np.float64), arm, swing, sigma, m)
    dot = np.abs(av[:, 0] * u[:, 0] + av[:, 1] * u[:, 1])
    crs = np.abs(av[:, 0] * u[:, 1] - av[:, 1] * u[:, 0])
    return np.asarray(np.arctan2(crs, dot), dtype=np.float64)


def rocker_pressure(
    program: CamProgram, A: npt.ArrayLike, arm: float, swing: float, sigma: int, phi: FloatArray
) -> FloatArray:
    """|α| at the angles ``phi`` (right-hand values), see :func:`rocker_pressure_of`."""
    return rocker_pressure_of(A, arm, swing, sigma, program.motion(phi, "right"))


def rocker_rho_pitch(
    A: npt.ArrayLike, arm: float, swing: float, sigma: int, m: Motion
) -> FloatArray:
    """The pitch curve's signed radius of curvature (> 0 convex) at the motion's positions."""
    _, av, bv, _ = _rocker_frame(np.asarray(A, dtype=np.float64), arm, swing, sigma, m)
    la = np.hypot(av[:, 0], av[:, 1])
    cross = av[:, 0] * bv[:, 1] - av[:, 1] * bv[:, 0]
    safe = np.where(cross == 0.0, 1.0, cross)
    return np.asarray(np.where(cross == 0.0, np.inf, -sigma * la**3 / safe), dtype=np.float64)


def check_rocker_profile(
    program: CamProgram, prof: RockerProfile, r_roller: float, step: str
) -> None:
    """A roller larger than the pitch curve's smallest convex radius of curvature, or a convex
    corner of the pitch curve under a roller, is an error naming the phase and the angle."""
    if r_roller <= 0.0:
        return
    for at in prof.convex_corners:
        raise ConstructionError(
            step,
            f"the velocity analogue ψ′ jumps in {phase_name(program, at)} at φ = "
            f"{math.degrees(at):.6g}° so that the pitch curve has a convex corner the roller "
            "would have to enter (a cusp); choose a law whose ψ′ is continuous",
        )
    smooth = ~prof.corner
    convex = smooth & (prof.rho_pitch > 0.0)
    if np.any(convex):
        j = int(np.argmin(np.where(convex, prof.rho_pitch, np.inf)))
        v = float(prof.rho_pitch[j])
        if v <= r_roller:
            at = float(prof.phi[j])
            raise ConstructionError(
                step,
                f"the roller radius r_roller = {r_roller:.6g} m is not smaller than the pitch "
                f"curve's radius of curvature ρ = {v:.6g} m in {phase_name(program, at)} at "
                f"φ = {math.degrees(at):.6g}°: the profile would be undercut (a cusp); use a "
                "smaller roller or a larger cam",
            )
