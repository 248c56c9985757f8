"""Disc-cam profiles by inversion, for translating flat-faced, knife-edge and roller followers.

**Frame.** The cam turns about O = (0, 0) through the angle φ; ``sigma`` = +1 when it turns
counter-clockwise, −1 clockwise. The follower translates along +y; at φ = 0 the cam's frame
coincides with the fixed one. A point q of the fixed frame, seen from the cam at angle φ, is
R(−σφ)·q: this is the *inversion* — the cam held still and the follower turned backwards.

**Followers** (``r0`` is the smallest radius of the theoretical profile, the one the follower's
reference point traces: the face for the flat follower, the tip for the knife, the roller's centre
(the pitch curve) for the roller, as in the textbooks' «центровой профиль»):

- ``flat``: a flat face perpendicular to the motion, at y = r0 + S. The profile is the envelope
  of the face lines. The velocity plan puts the contact point B a distance S′ along the face from
  the line through O along the motion: B = (σS′, r0 + S) in the fixed frame (the seed's
  r = √((r0 + S)² + S′²)). The envelope's radius of curvature is ρ = r0 + S + S″; where it would
  be ≤ 0 the profile has a cusp (the base circle is too small for the law).
- ``knife``: the tip q = (e, s0 + S) traces the profile, s0 = √(r0² − e²); ``e`` is the offset of
  the follower's axis from O.
- ``roller``: the roller's centre q = (e, s0 + S) traces the pitch curve, s0 = √(r0² − e²); the
  working profile is the pitch curve's inner offset by r_r, taken exactly along its normals (its
  base circle has the radius r0 − r_r). Where the pitch curve is convex with a radius of
  curvature ≤ r_r the offset has a cusp: undercut.

**Jumps.** Where S′ jumps (the linear law's ends) the profile has a corner: for the flat face a
straight piece of the face line (|ΔS′| long) when S′ rises, for the roller an arc of the roller
circle about the pitch curve's corner when S′ rises; when S′ drops, a flat face or a roller would
have to enter a convex corner of the pitch curve, so that is a cusp or undercut too. Every
jump's points are included (``corner`` marks them), with S′ running between its one-sided values.

The tangent, the normal and the radius of curvature come from the exact derivatives. The pitch
point in the cam's frame is p = R(−σφ)·q, so p′ = R·(q′ − σJq) and p″ = R·(q″ − 2σJq′ − q)
(J turns by +90°). With A = q′ − σJq = (σ(s0 + S), S′ − σe) and B = (2σS′ − e, S″ − s0 − S),
the signed radius of curvature is ρ = −σ|A|³/(A × B) (> 0 where the profile is convex, as the
inversion runs round it against the cam's rotation), the outward normal is
ν = (e − σS′, s0 + S)/|A| and the pressure angle is α = atan2(σS′ − e, s0 + S). For the
flat face the same computation with q = (σS′, r0 + S) and the normal (0, 1) gives
ρ = r0 + S + S″.

>>> from geomcad.kinematics.motion_laws import standard_program
>>> prog = standard_program(0.04, math.pi)  # S = aφ, a = 40/π mm
>>> div = at_angles(prog, Follower("flat", 0.04), [0.0, math.pi / 8], math.pi / 2)
>>> [round(float(r) * 1000, 2) for r in div.radius]  # the seed's r_0, r_1 in mm
[41.98, 46.77]
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
import numpy.typing as npt
from scipy.optimize import minimize_scalar

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.motion_laws import CamProgram, FloatArray, Motion

FollowerKind = Literal["flat", "knife", "roller"]
FOLLOWERS: tuple[str, ...] = ("flat", "knife", "roller")

#: Default angular step of a sampled profile (rad): half a degree.
PROFILE_STEP = math.radians(0.5)
#: Points inserted across one jump of S′ (a roller's corner arc, a flat's straight piece).
CORNER_POINTS = 12

#: The step names the profile errors carry.
STEP_FLAT = "profile = envelope of the face lines (inversion)"
STEP_KNIFE = "profile = path of the knife edge (inversion)"
STEP_ROLLER = "profile = inner offset of the pitch curve by r_roller (inversion)"


def profile_step_name(follower: str) -> str:
    """The construction step a profile of this follower is built in (errors name it)."""
    return {"flat": STEP_FLAT, "knife": STEP_KNIFE, "roller": STEP_ROLLER}[follower]


@dataclass(frozen=True)
class Follower:
    """A translating follower: its kind, the base radius r0 of the cam, the offset e of its axis,
    the roller radius, and the cam's sense of rotation ``sigma`` (+1 counter-clockwise)."""

    kind: str
    r0: float
    e: float = 0.0
    r_roller: float = 0.0
    sigma: int = 1

    def __post_init__(self) -> None:
        if self.kind not in FOLLOWERS:
            raise ParameterError("follower", self.kind, f"must be one of {', '.join(FOLLOWERS)}")
        if not (math.isfinite(self.r0) and self.r0 > 0.0):
            raise ParameterError("r0", self.r0, "the base circle's radius must be > 0")
        if self.sigma not in (1, -1):
            raise ParameterError("omega_sign", self.sigma, "must be +1 (ccw) or −1 (cw)")
        if not math.isfinite(self.e):
            raise ParameterError("e", self.e, "must be a finite number")
        if self.kind == "roller" and not (math.isfinite(self.r_roller) and self.r_roller > 0.0):
            raise ParameterError("r_roller", self.r_roller, "a roller follower needs r_roller > 0")
        if self.kind != "flat" and abs(self.e) >= self.r0:
            raise ParameterError(
                "e",
                self.e,
                f"the follower's axis must cut the circle of radius r0: |e| < r0 = {self.r0:.6g} m",
            )

    @property
    def s0(self) -> float:
        """The reference point's height on the lower dwell: √(r0² − e²) (flat: r0)."""
        if self.kind == "flat":
            return self.r0
        return math.sqrt(self.r0**2 - self.e**2)

    @property
    def base_radius(self) -> float:
        """The working profile's smallest radius on the lower dwell (r0; r0 − r_r for a roller)."""
        return self.r0 - (self.r_roller if self.kind == "roller" else 0.0)


@dataclass(frozen=True, eq=False)
class CamProfile:
    """Points of a cam profile and what belongs to each, as arrays over the samples.

    ``contact`` (N, 2) are the profile's points in the cam's frame; ``pitch`` the follower's
    reference point there (flat: the point C where the face crosses the line through O along the
    motion; knife: the tip, = contact; roller: the roller's centre); ``normal`` the profile's
    outward unit normal; ``rho`` its signed radius of curvature (> 0 convex, ``inf`` on a straight
    piece); ``rho_pitch`` the pitch curve's (knife, roller); ``pressure`` the pressure angle (rad);
    ``corner`` marks the points inserted across a jump of S′. ``closed`` is True for a full turn.
    """

    follower: Follower
    phi: FloatArray
    S: FloatArray
    S1: FloatArray
    S2: FloatArray
    contact: FloatArray
    pitch: FloatArray
    normal: FloatArray
    rho: FloatArray
    rho_pitch: FloatArray
    pressure: FloatArray
    corner: npt.NDArray[np.bool_] = field(default_factory=lambda: np.zeros(0, dtype=bool))
    closed: bool = False

    def __str__(self) -> str:
        n = len(self.phi)
        lo, hi = (math.degrees(float(x)) for x in (self.phi[0], self.phi[-1]))
        shut = ", closed" if self.closed else ""
        return f"{self.follower.kind} follower profile: {n} points, φ {lo:.6g}° … {hi:.6g}°{shut}"

    @property
    def radius(self) -> FloatArray:
        """The radius vectors |O contact| (m)."""
        return np.asarray(np.hypot(self.contact[:, 0], self.contact[:, 1]), dtype=np.float64)


def invert(points: npt.ArrayLike, phi: npt.ArrayLike, sigma: int) -> FloatArray:
    """Fixed-frame points (N, 2) at cam angles φ (N,) seen from the cam: R(−σφ)·q."""
    q = np.asarray(points, dtype=np.float64)
    t = -sigma * np.asarray(phi, dtype=np.float64)
    c, s = np.cos(t), np.sin(t)
    return np.stack([c * q[..., 0] - s * q[..., 1], s * q[..., 0] + c * q[..., 1]], axis=-1)


def evert(points: npt.ArrayLike, phi: npt.ArrayLike, sigma: int) -> FloatArray:
    """Cam-frame points back to the fixed frame at cam angles φ: R(σφ)·p."""
    return invert(points, -np.asarray(phi, dtype=np.float64), sigma)


def _fixed_frame(
    f: Follower, S: FloatArray, S1: FloatArray, S2: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """(contact, pitch, normal, rho, rho_pitch, pressure) in the fixed frame's orientation."""
    sg = float(f.sigma)
    ones = np.ones_like(S)
    if f.kind == "flat":
        h = f.r0 + S
        contact = np.stack([sg * S1, h], axis=-1)
        pitch = np.stack([0.0 * S, h], axis=-1)
        normal = np.stack([0.0 * S, ones], axis=-1)
        rho = h + S2
        return contact, pitch, normal, rho, rho.copy(), np.zeros_like(S)
    y = f.s0 + S
    pitch = np.stack([f.e * ones, y], axis=-1)
    ax, ay = sg * y, S1 - sg * f.e
    bx, by = 2.0 * sg * S1 - f.e, S2 - y
    la = np.hypot(ax, ay)
    cross = ax * by - ay * bx
    with np.errstate(divide="ignore"):
        rho_p = np.where(cross == 0.0, np.inf, -sg * la**3 / np.where(cross == 0.0, 1.0, cross))
    normal = np.stack([(f.e - sg * S1) / la, y / la], axis=-1)
    contact = pitch - f.r_roller * normal if f.kind == "roller" else pitch.copy()
    rho = rho_p - f.r_roller if f.kind == "roller" else rho_p.copy()
    pressure = np.arctan2(sg * S1 - f.e, y)
    return contact, pitch, normal, rho, rho_p, pressure


def follow(motion: Motion, f: Follower) -> CamProfile:
    """The profile points at the motion's angles (no jumps inserted, nothing checked)."""
    contact, pitch, normal, rho, rho_p, pressure = _fixed_frame(f, motion.S, motion.S1, motion.S2)
    phi = motion.phi
    return CamProfile(
        f,
        phi,
        motion.S,
        motion.S1,
        motion.S2,
        invert(contact, phi, f.sigma),
        invert(pitch, phi, f.sigma),
        invert(normal, phi, f.sigma),
        rho,
        rho_p,
        pressure,
        np.zeros(phi.shape, dtype=bool),
    )


def at_angles(program: CamProgram, f: Follower, phi: npt.ArrayLike, end: float) -> CamProfile:
    """The profile points at given angles (the division points), each taken on the phase that
    starts there, except an angle at ``end`` (the last angle built), taken on the phase that ends
    there. Angles within rounding of a phase boundary are put on it."""
    p = snap(np.asarray(phi, dtype=np.float64), program.breaks())
    right = program.motion(p, "right")
    left = program.motion(p, "left")
    use_left = np.isclose(p, end, rtol=0.0, atol=tol.DERIVED)
    m = Motion(
        p,
        np.where(use_left, left.S, right.S),
        np.where(use_left, left.S1, right.S1),
        np.where(use_left, left.S2, right.S2),
    )
    return follow(m, f)


def snap(phi: FloatArray, breaks: FloatArray) -> FloatArray:
    """Angles within rounding (tol.DERIVED of a turn) of a break put exactly on it."""
    out = phi.copy()
    for b in breaks:
        out = np.where(np.abs(out - b) <= tol.DERIVED * 2.0 * math.pi, b, out)
    return out


def _jump_scale(program: CamProgram) -> float:
    return tol.DERIVED * program.H / min(ph.angle for ph in program.phases)


def _samples(
    program: CamProgram, lo: float, hi: float, closed: bool, step: float
) -> tuple[Motion, npt.NDArray[np.bool_], list[tuple[float, float, float]]]:
    """The motion sampled over [lo, hi] with both one-sided values at each break and the points
    of each jump of S′ in between; returns the motion, the corner mask and the jumps
    (φ, S′ before, S′ after)."""
    brk = [float(b) for b in program.breaks() if lo < b < hi]
    knots = [lo, *brk, hi]
    eps = _jump_scale(program)
    phis: list[FloatArray] = []
    S: list[FloatArray] = []
    S1: list[FloatArray] = []
    S2: list[FloatArray] = []
    corner: list[npt.NDArray[np.bool_]] = []
    jumps: list[tuple[float, float, float]] = []

    def add(m: Motion, is_corner: bool) -> None:
        phis.append(m.phi)
        S.append(m.S)
        S1.append(m.S1)
        S2.append(m.S2)
        corner.append(np.full(m.phi.shape, is_corner))

    def jump(at: float, before: Motion, after: Motion) -> None:
        d0, d1 = float(before.S1[-1]), float(after.S1[0])
        if abs(d1 - d0) <= eps:
            return
        jumps.append((at, d0, d1))
        t = np.linspace(0.0, 1.0, CORNER_POINTS + 2)[1:-1]
        n = len(t)
        add(
            Motion(
                np.full(n, at),
                np.full(n, float(after.S[0])),
                d0 + (d1 - d0) * t,
                np.zeros(n),
            ),
            True,
        )

    # the value just before lo: a full turn wraps round to 2π
    before = program.motion([2.0 * math.pi if closed else lo], "left")
    prev = Motion(np.array([lo]), before.S, before.S1, before.S2)
    for i, (a, b) in enumerate(itertools.pairwise(knots)):
        n = max(2, math.ceil((b - a) / step))
        grid = np.linspace(a, b, n + 1)
        right = program.motion(grid[:-1], "right")
        end = program.motion(grid[-1:], "left")
        piece = Motion(
            grid,
            np.concatenate([right.S, end.S]),
            np.concatenate([right.S1, end.S1]),
            np.concatenate([right.S2, end.S2]),
        )
        head = Motion(piece.phi[:1], piece.S[:1], piece.S1[:1], piece.S2[:1])
        if i == 0 and abs(float(prev.S1[0]) - float(head.S1[0])) > eps:
            add(prev, False)  # the profile starts before the jump at lo
        jump(a, prev, head)
        add(piece, False)
        prev = Motion(piece.phi[-1:], piece.S[-1:], piece.S1[-1:], piece.S2[-1:])
    cat = np.concatenate
    m = Motion(cat(phis), cat(S), cat(S1), cat(S2))
    mask = cat(corner)
    if closed:  # the last point, at 2π, is the first one again
        m = Motion(m.phi[:-1], m.S[:-1], m.S1[:-1], m.S2[:-1])
        mask = mask[:-1]
    return m, mask, jumps


def _refined_min(
    program: CamProgram,
    prof: CamProfile,
    qty: Callable[[CamProfile], FloatArray],
    keep: npt.NDArray[np.bool_],
) -> tuple[float, float]:
    """The smallest value of the quantity ``qty`` over the samples ``keep``, refined between the
    neighbouring samples by minimising it exactly (scipy's bounded Brent). Returns (value, φ);
    (inf, nan) when no sample is kept."""
    values = qty(prof)
    idx = np.nonzero(keep & np.isfinite(values))[0]
    if idx.size == 0:
        return math.inf, math.nan
    j = int(idx[np.argmin(values[idx])])
    best, at = float(values[j]), float(prof.phi[j])
    lo = j - 1 if j > 0 and keep[j - 1] else j
    hi = j + 1 if j + 1 < len(prof.phi) and keep[j + 1] else j
    a, b = float(prof.phi[lo]), float(prof.phi[hi])
    if b - a <= tol.ROOT_ANGLE:
        return best, at

    def fun(x: float) -> float:
        v = float(qty(follow(program.motion([x], "right"), prof.follower))[0])
        return v if math.isfinite(v) else math.inf

    res = minimize_scalar(fun, bounds=(a, b), method="bounded", options={"xatol": tol.ROOT_ANGLE})
    if float(res.fun) < best:
        return float(res.fun), float(res.x)
    return best, at


def cam_profile(
    program: CamProgram,
    f: Follower,
    lo: float = 0.0,
    hi: float | None = None,
    closed: bool = False,
    step: float = PROFILE_STEP,
) -> CamProfile:
    """The sampled profile over the cam angles [lo, hi] (rad; ``closed``: the full turn 0 … 2π),
    with every jump's points, checked for cusps and undercut.

    Raises :class:`ConstructionError` naming the profile's step when the profile has a cusp: a
    flat face whose ρ = r0 + S + S″ would be ≤ 0 (the base circle is too small for the law), a
    roller larger than the pitch curve's smallest convex radius of curvature (undercut), or a
    drop of S′ (the flat face or the roller would have to enter a convex corner).
    """
    if closed:
        lo, hi = 0.0, 2.0 * math.pi
    hi = program.total if hi is None else hi
    if not (math.isfinite(lo) and math.isfinite(hi) and hi > lo):
        raise ParameterError("span", (lo, hi), "the profile needs an angle span hi > lo")
    m, corner, jumps = _samples(program, lo, hi, closed, step)
    prof = follow(m, f)
    rho = prof.rho.copy()
    rho_p = prof.rho_pitch.copy()
    if f.kind == "flat":
        rho[corner] = np.inf
        rho_p[corner] = np.inf
    elif f.kind == "roller":
        rho[corner] = -f.r_roller
        rho_p[corner] = 0.0
    else:
        rho[corner] = 0.0
        rho_p[corner] = 0.0
    prof = CamProfile(
        f,
        prof.phi,
        prof.S,
        prof.S1,
        prof.S2,
        prof.contact,
        prof.pitch,
        prof.normal,
        rho,
        rho_p,
        prof.pressure,
        corner,
        closed,
    )
    _check(program, f, prof, jumps)
    return prof


def _check(
    program: CamProgram, f: Follower, prof: CamProfile, jumps: list[tuple[float, float, float]]
) -> None:
    step = profile_step_name(f.kind)
    smooth = ~prof.corner
    for at, d0, d1 in jumps:
        if d1 < d0 and f.kind != "knife":
            what = "the flat face" if f.kind == "flat" else "the roller"
            raise ConstructionError(
                step,
                f"S′ drops from {d0:.6g} to {d1:.6g} m at φ = {math.degrees(at):.6g}°, so "
                f"{what} would have to enter a convex corner of the profile: the profile has a "
                "cusp there (the follower cannot keep to this law); choose a law whose S′ is "
                "continuous (constant_acceleration, harmonic, cycloidal, poly345)",
            )
    if f.kind == "flat":
        v, at = _refined_min(program, prof, lambda p: p.rho, smooth)
        if v <= tol.REL_LENGTH * f.r0:
            need = f.r0 - v
            raise ConstructionError(
                step,
                f"the profile has a cusp at φ = {math.degrees(at):.6g}°: ρ = r0 + S + S″ = "
                f"{v:.6g} m ≤ 0; the base circle is too small for this law (r0 must exceed "
                f"{need:.6g} m)",
            )
    elif f.kind == "roller":
        if f.r_roller >= f.r0:
            raise ConstructionError(
                step,
                f"the roller radius r_roller = {f.r_roller:.6g} m is not smaller than r0 = "
                f"{f.r0:.6g} m, the pitch curve's radius (and radius of curvature) on the lower "
                "dwell: the profile would be undercut down to the cam's centre",
            )
        convex = smooth & (prof.rho_pitch > 0.0)
        v, at = _refined_min(program, prof, lambda p: p.rho_pitch, convex)
        if v <= f.r_roller:
            raise ConstructionError(
                step,
                f"the roller radius r_roller = {f.r_roller:.6g} m is not smaller than the pitch "
                f"curve's smallest radius of curvature ρ = {v:.6g} m (at φ = "
                f"{math.degrees(at):.6g}°): the profile would be undercut (a cusp); use a "
                "smaller roller or a larger base circle",
            )


def rho_min(program: CamProgram, prof: CamProfile) -> float:
    """The smallest radius of curvature |ρ| of the profile (m), refined between samples.

    Straight pieces (ρ = ∞) do not count, nor a knife's corners (ρ = 0 at a point: a sharp edge,
    which the problem reports in its notes instead); a roller's corner arcs count (|ρ| = r_r).
    """
    f = prof.follower
    smooth = np.isfinite(prof.rho) & ~prof.corner
    best = math.inf
    if np.any(smooth & (prof.rho > 0.0)):
        best = _refined_min(program, prof, lambda p: p.rho, smooth & (prof.rho > 0.0))[0]
    if np.any(smooth & (prof.rho < 0.0)):
        v = _refined_min(program, prof, lambda p: -p.rho, smooth & (prof.rho < 0.0))[0]
        best = min(best, v)
    if f.kind == "roller" and np.any(prof.corner):
        best = min(best, f.r_roller)
    return best


def pressure_angle_max(program: CamProgram, prof: CamProfile) -> float:
    """The largest pressure angle |α| along the profile (rad), refined between samples."""
    smooth = ~prof.corner
    v = -_refined_min(program, prof, lambda p: -np.abs(p.pressure), smooth)[0]
    corner = float(np.max(np.abs(prof.pressure[prof.corner]))) if np.any(prof.corner) else 0.0
    return max(v, corner)


@dataclass(frozen=True)
class VelocityPlan:
    """The seed's velocity-plan argument at one position, in the fixed frame.

    B is the contact point (flat) or the follower's reference point (knife tip, roller centre);
    B₁ is the cam's point there and B₂ the follower's. The plan drawn from B: Bb₁ = V_B1 ⊥ OB,
    Bb₂ = V_B2 along the motion, b₁b₂ = V_B2B1 along the face (the pitch curve's tangent).
    Turned by 90° and divided by ω it is the triangle OBB′: B′ is where the normal at B meets the
    line through O across the motion, and OB′ = S′ (b₂b₁/BB′ = Bb₂/OB′ = Bb₁/OB = ω). C is
    where the flat face crosses the line through O along the motion, so BC = OB′ = S′.
    Velocities are in m/s at the angular speed ``omega`` (rad/s).
    """

    phi: float
    omega: float
    B: Vec
    B_prime: Vec
    C: Vec
    V_B1: Vec
    V_B2: Vec
    V_B2B1: Vec
    S: float
    S1: float


def velocity_plan(
    program: CamProgram, f: Follower, phi: float, omega: float = 1.0, side: str = "right"
) -> VelocityPlan:
    """The velocity plan at cam angle ``phi`` for an angular speed ``omega`` > 0 (rad/s)."""
    m = program.motion([phi], "right" if side == "right" else "left")
    prof = follow(m, f)
    S, S1 = float(m.S[0]), float(m.S1[0])
    bx, by = evert(prof.pitch if f.kind != "flat" else prof.contact, m.phi, f.sigma)[0]
    B = Vec(float(bx), float(by))
    w = f.sigma * omega
    v1 = B.perp() * w  # ω × OB
    v2 = Vec(0.0, S1 * omega)
    h = f.r0 + S if f.kind == "flat" else f.s0 + S
    return VelocityPlan(
        phi,
        omega,
        B,
        Vec(f.sigma * S1, 0.0),
        Vec(0.0, h),
        v1,
        v2,
        v2 - v1,
        S,
        S1,
    )
