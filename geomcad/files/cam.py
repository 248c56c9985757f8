"""A ``[cam]`` design file: the cam of the smallest size by the pressure angle (or, for a flat
face, by convexity), its profile by inversion, the roller, the checks (docs/cam-gear-files.md).

The steps:

1. the program S(φ) (or ψ(φ)) phase by phase;
2. the zone of admissible centres on the S–S′ diagram (ψ–lψ′ for a rocker) with the allowed
   pressure angle on the rise and on the return, and its point nearest B0: r0_min and the offset
   (a given offset: the zone's boundary above it; a rocker with a given pivot distance: the zone's
   point on the circle about the pivot); for a flat face r0_min = max (ρ_allowed − S − S″);
3. r0 rounded up to ``r0_step`` (or the file's own r0, which must not be below r0_min);
4. the roller: the file's, or min(0.7·ρ_min of the pitch curve, 0.4·r0) rounded down to
   ``r0_step``; a roller not smaller than ρ_min is an error naming the phase and angle;
5. the profile by inversion over the turn; its largest pressure angle and smallest radius of
   curvature, measured on it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import ConstructionError, ParameterError
from geomcad.files import file_problem
from geomcad.kinematics import cam_design as cd
from geomcad.kinematics.cams import (
    CamProfile,
    Follower,
    cam_profile,
    follow,
    pressure_angle_max,
    profile_step_name,
    rho_min,
)
from geomcad.kinematics.motion_laws import ALL_LAWS, CamProgram, Motion, Phase
from geomcad.problem import Build, Problem, ResultSpec, lazy
from geomcad.units import deg, to_deg

from .common import Table, check_top

KIND = "cam"
FOLLOWERS = ("knife", "roller", "flat")
MOTIONS = ("translating", "rocking")
#: Metres to the millimetres the order of construction states.
MM = 1000.0
#: The roller rule: r_roller ≤ ROLLER_RHO·ρ_min(pitch curve) and ≤ ROLLER_R0·r0.
ROLLER_RHO = 0.7
ROLLER_R0 = 0.4

STEP_R0 = "r0 = r0_min rounded up (or the file's r0)"
STEP_ROLLER = "r_roller from the pitch curve's smallest radius of curvature"

#: A radius on the sheet: in mm, to 0.01 mm or so (5 significant figures).
_MM: dict[str, Any] = {"display": "mm", "digits": 5}

RESULTS = (
    ResultSpec("r0_min", "m", "least radius of the theoretical profile's base circle", "l", **_MM),
    ResultSpec("r0", "m", "the chosen base radius (r0_min rounded up)", "l", **_MM),
    ResultSpec("e", "m", "offset of the follower's axis from O (translating)", "l", **_MM),
    ResultSpec("a_w", "m", "distance from the cam's centre to the rocker's pivot", "l", **_MM),
    ResultSpec("pressure_angle_allowed_deg", "deg", "allowed pressure angle on the rise"),
    ResultSpec("return_pressure_angle_allowed_deg", "deg", "allowed pressure angle on the return"),
    ResultSpec("pressure_angle_max_deg", "deg", "largest pressure angle of the built cam"),
    ResultSpec("pressure_angle_max_rise_deg", "deg", "largest pressure angle on the rise"),
    ResultSpec("pressure_angle_max_return_deg", "deg", "largest pressure angle on the return"),
    ResultSpec("rho_min", "m", "smallest radius of curvature of the working profile", "l", **_MM),
    ResultSpec(
        "rho_pitch_min", "m", "smallest convex radius of curvature of the pitch curve", "l", **_MM
    ),
    ResultSpec("r_roller", "m", "roller radius", "l", **_MM),
    ResultSpec("H", "m", "stroke (translating)", "l"),
    ResultSpec("swing_deg", "deg", "swing of the rocker"),
)


@dataclass(frozen=True)
class CamSpec:
    """What a cam file states, checked."""

    title: str
    follower: str
    motion: str
    sigma: int
    program: CamProgram
    alpha_rise: float
    alpha_return: float
    offset: float | None
    r0_step: float
    r0: float | None
    roller: float | None
    rho_allowed: float
    arm: float
    pivot_distance: float | None
    divisions: int


@dataclass(frozen=True)
class CamDesign:
    """Everything the sheet draws."""

    spec: CamSpec
    zone: cd.TranslatingZone | cd.RockerZone | None
    centre: tuple[float, float]  # O in the diagram frame (B0 at the origin)
    centre_min: tuple[float, float]
    r0_min: float
    r0: float
    e: float
    r_roller: float
    profile: CamProfile | cd.RockerProfile
    pivot: tuple[float, float]  # the rocker's pivot, cam frame (O at the origin)
    divisions: Motion
    flat_phi: float


def read_spec(file_id: str, data: Mapping[str, Any]) -> CamSpec:
    """The checked contents of a cam file; a wrong key or value names its dotted key."""
    title = check_top(data, KIND)
    t = Table(data[KIND], KIND)
    follower = t.choice("follower", FOLLOWERS)
    motion = t.choice("motion", MOTIONS, "translating")
    rot = t.choice("rotation", ("ccw", "cw"), "ccw")
    sigma = 1 if rot == "ccw" else -1
    if motion == "rocking" and follower == "flat":
        raise ParameterError(
            t.key("follower"), follower, "a flat-faced rocker is not built (knife or roller)"
        )
    if motion == "translating":
        H = t.number("stroke", ge=1.0e-6, le=1.0e3, unit="m")
        arm = 0.0
        pivot = None
    else:
        H = deg(t.number("swing_deg", gt=0.0, lt=180.0, unit="°"))
        arm = t.number("arm", ge=1.0e-6, le=1.0e3, unit="m")
        pivot = t.optional_number("pivot_distance", gt=0.0)
    a_rise = deg(t.number("pressure_angle_deg", 30.0))
    a_ret = deg(t.number("return_pressure_angle_deg", to_deg(a_rise)))
    for name, a in (("pressure_angle_deg", a_rise), ("return_pressure_angle_deg", a_ret)):
        cd.check_allowed(t.key(name), a)
    off_raw = t.raw("offset")
    offset: float | None
    if off_raw is None or off_raw == "best":
        offset = None if follower != "flat" else 0.0
    elif isinstance(off_raw, int | float) and not isinstance(off_raw, bool):
        if motion == "rocking":
            raise ParameterError(t.key("offset"), off_raw, "a rocker has no offset")
        if not math.isfinite(off_raw):
            raise ParameterError(t.key("offset"), off_raw, "must be a finite number")
        offset = float(off_raw)
    else:
        raise ParameterError(t.key("offset"), off_raw, 'must be "best" or a number (m)')
    step = t.number("r0_step", 0.001, gt=0.0, unit="m")
    r0 = t.optional_number("r0", gt=0.0)
    roller = t.optional_number("roller_radius", gt=0.0)
    if roller is not None and follower != "roller":
        raise ParameterError(t.key("roller_radius"), roller, f"a {follower} follower has no roller")
    rho_allowed = t.number("rho_allowed", 0.0, ge=0.0, unit="m")
    divisions = t.integer("divisions", 6, ge=2, le=36)
    phases_raw = t.raw("phases")
    if not isinstance(phases_raw, list) or not phases_raw:
        raise ParameterError(t.key("phases"), phases_raw, "must be a list of phase tables")
    phases = []
    for i, raw in enumerate(phases_raw):
        p = Table(raw, f"{KIND}.phases.{i + 1}")
        kind = p.choice("kind", ("rise", "dwell", "return"))
        # a phase under a degree is no phase a cam is cut or drawn with (and it would take
        # millions of samples)
        angle = deg(p.number("angle_deg", ge=1.0, le=360.0, unit="°"))
        law = p.choice("law", ALL_LAWS, "cycloidal") if kind != "dwell" else "linear"
        p.done()
        phases.append(Phase(kind, angle, law))  # type: ignore[arg-type]
    t.done()
    try:
        program = CamProgram.of(H, phases)
    except ParameterError as exc:
        raise ParameterError(f"{KIND}.phases", exc.value, f"{exc.name}: {exc.why}") from None
    if not any(ph.kind == "rise" for ph in program.phases):
        raise ParameterError(f"{KIND}.phases", len(phases), "the program has no rise")
    if not program.closes:
        raise ParameterError(
            f"{KIND}.phases", len(phases), "a cam turns round: the follower must return"
        )
    return CamSpec(
        title or file_id,
        follower,
        motion,
        sigma,
        program.full_turn(),
        a_rise,
        a_ret,
        offset,
        step,
        r0,
        roller,
        rho_allowed,
        arm,
        pivot,
        divisions,
    )


def _deg(a: float) -> float:
    """Degrees, rounded to 12 significant digits so that a file's 30° reads back as 30."""
    return float(f"{to_deg(a):.12g}")


def _round_up(x: float, step: float, strict: bool = False) -> float:
    """x rounded up to a multiple of step (strictly above it when ``strict``)."""
    k = (
        math.floor(x / step * (1.0 + tol.DERIVED)) + 1
        if strict
        else math.ceil(x / step * (1.0 - tol.DERIVED))
    )
    return max(1, k) * step


def _division_motion(program: CamProgram, n: int) -> Motion:
    """The division points: n equal parts of every rise and return, and the ends of every phase."""
    pts: list[float] = []
    step = min(ph.angle for ph in program.phases if ph.kind != "dwell") / n
    for ph, a0 in zip(program.phases, program.boundaries[:-1], strict=True):
        # dwells in parts of about the same size, so the graphical differentiation's chords
        # stay short there too
        parts = max(1, round(ph.angle / step)) if ph.kind == "dwell" else n
        pts += [float(a0) + ph.angle * i / parts for i in range(parts)]
    pts.append(2.0 * math.pi)
    return program.motion(np.asarray(pts))


def design(spec: CamSpec) -> tuple[CamDesign, Construction, dict[str, Any]]:
    """The design steps (module doc), recorded."""
    prog = spec.program
    c = Construction(f"cam design: {spec.motion} {spec.follower} follower")
    c.point("B0", (0.0, 0.0), note="the follower's lowest position (the diagram's origin)")
    c.record(
        "S(φ)",
        "the law phase by phase over the turn, its analogues by graphical differentiation",
        prog,
        role="hidden",
        kind="cam_law",
        args={"n": float(spec.divisions)},
    )
    zone: cd.TranslatingZone | cd.RockerZone | None = None
    flat_phi = math.nan
    if spec.follower == "flat":
        r0_min, flat_phi = c.run(
            "ρ-condition",
            cd.STEP_CONVEX,
            lambda: cd.flat_r0_min(prog, spec.rho_allowed),
            kind="cam_convex",
            args={"rho": spec.rho_allowed * MM},
        )
        cmin = (0.0, -r0_min)
    elif spec.motion == "translating":
        zone = c.run(
            "zone",
            cd.STEP_ZONE,
            lambda: cd.translating_zone(prog, spec.sigma, spec.alpha_rise, spec.alpha_return),
            role="construction",
            kind="cam_zone",
            args={"rise": to_deg(spec.alpha_rise), "ret": to_deg(spec.alpha_return)},
        )
        assert isinstance(zone, cd.TranslatingZone)
        cmin = zone.nearest() if spec.offset is None else (-spec.offset, zone.g(-spec.offset))
        r0_min = math.hypot(*cmin)
    else:
        geom = cd.RockerGeometry(spec.arm, prog.H, spec.sigma)
        zone = c.run(
            "zone",
            cd.STEP_ROCKER_ZONE,
            lambda: cd.rocker_zone(prog, geom, spec.alpha_rise, spec.alpha_return),
            role="construction",
            kind="cam_rocker_zone",
            args={"rise": to_deg(spec.alpha_rise), "ret": to_deg(spec.alpha_return)},
        )
        assert isinstance(zone, cd.RockerZone)
        z = zone
        if spec.pivot_distance is None:
            cmin = c.run("O_min", "the zone's point nearest B0", z.nearest, kind="cam_nearest")
        else:
            a_w = spec.pivot_distance
            cmin = c.run("O_min", "zone ∩ circle(A, a_w) nearest B0",
                         lambda: cd.rocker_on_circle(z, a_w), kind="cam_on_circle",
                         args={"a": a_w * MM})  # fmt: skip
        r0_min = math.hypot(*cmin)
    if not r0_min > 0.0:
        raise ConstructionError(STEP_R0, "r0_min = 0: the zone reaches B0")
    c.value(
        "r0_min",
        r0_min,
        "|O B0| at the zone's point",
        kind="cam_flat_r0_min" if spec.follower == "flat" else "cam_r0_min",
        args={"r": r0_min * MM},
    )
    if spec.r0 is not None:
        r0 = spec.r0
        low = (
            r0 <= r0_min * (1.0 + tol.DERIVED)
            if spec.follower == "flat"
            else r0 < r0_min * (1.0 - tol.DERIVED)
        )
        if low:
            why = (
                "the profile would have a cusp (r0 + S + S″ ≤ ρ_allowed)"
                if spec.follower == "flat"
                else "the pressure angle would exceed the allowed one"
            )
            raise ConstructionError(
                STEP_R0, f"the file's r0 = {r0:.6g} m is below r0_min = {r0_min:.6g} m: {why}"
            )
    else:
        r0 = _round_up(r0_min, spec.r0_step, strict=spec.follower == "flat")
    c.value("r0", r0, STEP_R0, kind="cam_r0_given" if spec.r0 is not None else "cam_r0",
            args={"r": r0 * MM, "step": spec.r0_step * MM})  # fmt: skip
    centre = _centre(spec, zone, cmin, r0_min, r0)
    e = -centre[0] if spec.motion == "translating" else 0.0
    if spec.follower == "flat":
        e = spec.offset or 0.0
    r_r = 0.0
    if spec.follower == "roller":
        rho_p, at = _pitch_rho_min(spec, centre, r0, e)
        if spec.roller is not None:
            r_r = spec.roller
            if r_r >= rho_p:
                raise ConstructionError(
                    STEP_ROLLER,
                    f"the roller radius {r_r:.6g} m is not smaller than the pitch curve's "
                    f"smallest radius of curvature ρ = {rho_p:.6g} m in "
                    f"{cd.phase_name(prog, at)} at φ = {to_deg(at):.6g}°: the profile would be "
                    "undercut (a cusp); use a smaller roller or a larger r0",
                )
        else:
            cap = min(ROLLER_RHO * rho_p, ROLLER_R0 * r0)
            r_r = math.floor(cap / spec.r0_step * (1.0 + tol.DERIVED)) * spec.r0_step
            if r_r <= 0.0:
                r_r = cap
        c.value("r_roller", r_r, STEP_ROLLER, kind="cam_roller",
                args={"r": r_r * MM, "rho": rho_p * MM})  # fmt: skip
    profile: CamProfile | cd.RockerProfile
    pivot = (0.0, 0.0)
    if spec.motion == "translating":
        cd.check_jumps(prog, spec.follower, profile_step_name(spec.follower))
        f = Follower(spec.follower, r0, e, r_r, spec.sigma)
        profile = c.run(
            "profile",
            profile_step_name(spec.follower).split(" = ", 1)[1] + ", over the turn",
            lambda: cam_profile(prog, f, closed=True),
            role="result",
            kind=f"cam_profile_{spec.follower}",
        )
        assert isinstance(profile, CamProfile)
        p_max = pressure_angle_max(prog, profile)
        rho = rho_min(prog, profile)
    else:
        A = _pivot(spec, centre)
        pivot = (float(A[0]), float(A[1]))
        step = cd.STEP_ROCKER_ZONE.split(" (")[0].replace("zone of admissible centres", "profile")
        profile = c.run(
            "profile",
            "rocker's profile by inversion, over the turn",
            lambda: cd.rocker_profile(prog, A, spec.arm, prog.H, spec.sigma, r_r),
            role="result",
            kind=f"cam_profile_rocker_{spec.follower}",
        )
        assert isinstance(profile, cd.RockerProfile)
        cd.check_rocker_profile(prog, profile, r_r, f"profile ({step})")
        p_max, rho = _rocker_measures(spec, A, r_r)
    p_rise, p_ret = _pressure_by_group(spec, profile)
    results: dict[str, Any] = {
        "r0_min": r0_min,
        "r0": r0,
    }
    if spec.motion == "translating":
        results["e"] = e
        results["H"] = prog.H
    else:
        results["a_w"] = float(np.hypot(*_pivot(spec, centre)))
        results["swing_deg"] = to_deg(prog.H)
    results["pressure_angle_allowed_deg"] = _deg(spec.alpha_rise)
    results["return_pressure_angle_allowed_deg"] = _deg(spec.alpha_return)
    results["pressure_angle_max_deg"] = to_deg(p_max)
    results["pressure_angle_max_rise_deg"] = to_deg(p_rise)
    results["pressure_angle_max_return_deg"] = to_deg(p_ret)
    results["rho_min"] = rho
    if spec.follower == "roller":
        results["r_roller"] = r_r
        results["rho_pitch_min"] = _pitch_rho_min(spec, centre, r0, e)[0]
    div = _division_motion(prog, spec.divisions)
    des = CamDesign(spec, zone, centre, cmin, r0_min, r0, e, r_r, profile, pivot, div, flat_phi)
    return des, c, results


def _centre(
    spec: CamSpec,
    zone: cd.TranslatingZone | cd.RockerZone | None,
    cmin: tuple[float, float],
    r0_min: float,
    r0: float,
) -> tuple[float, float]:
    """O in the diagram frame for the chosen r0: straight below for a translating follower
    (the offset kept); for a rocker along B0→O_min, or on the circle (A, a_w)."""
    if spec.motion == "translating":
        X = cmin[0]
        return X, -math.sqrt(max(0.0, r0**2 - X**2))
    assert isinstance(zone, cd.RockerZone)
    if spec.pivot_distance is None:
        k = r0 / r0_min
        q = (cmin[0] * k, cmin[1] * k)
    else:
        A = zone.geometry.A
        a_w = spec.pivot_distance
        d = float(np.hypot(*A))
        # circle(A, a_w) ∩ circle(B0, r0): the point on O_min's side of the line B0A
        x = (d**2 + r0**2 - a_w**2) / (2.0 * d)
        hh = r0**2 - x**2
        if hh < 0.0:
            raise ConstructionError(
                STEP_R0, f"no point of the circle (A, a_w) lies at r0 = {r0:.6g} m from B0"
            )
        u = A / d
        w = np.array([-u[1], u[0]])
        side = 1.0 if float(np.dot(np.array(cmin), w)) >= 0.0 else -1.0
        qq = u * x + side * w * math.sqrt(hh)
        q = (float(qq[0]), float(qq[1]))
    if zone.margin(q) < -tol.DERIVED * spec.arm:
        raise ConstructionError(
            STEP_R0,
            f"the centre at r0 = {r0:.6g} m leaves the zone of admissible centres; use a smaller "
            "r0_step or give r0",
        )
    return q


def _pivot(spec: CamSpec, centre: tuple[float, float]) -> np.ndarray:
    geom = cd.RockerGeometry(spec.arm, spec.program.H, spec.sigma)
    return np.asarray(geom.A - np.array(centre), dtype=np.float64)


def _pitch_rho_min(
    spec: CamSpec, centre: tuple[float, float], r0: float, e: float
) -> tuple[float, float]:
    """The pitch curve's smallest convex radius of curvature and its angle, refined."""
    prog = spec.program
    if spec.motion == "translating":
        f = Follower("knife", r0, e, 0.0, spec.sigma)

        def rho(m: Motion) -> np.ndarray:
            return follow(m, f).rho_pitch
    else:
        A = _pivot(spec, centre)

        def rho(m: Motion) -> np.ndarray:
            return cd.rocker_rho_pitch(A, spec.arm, prog.H, spec.sigma, m)

    best = (math.inf, 0.0)
    for k in range(len(prog.phases)):

        def qty(m: Motion) -> np.ndarray:
            r = rho(m)
            return np.where(r > 0.0, r, np.inf)

        v, at = cd.phase_extreme(prog, k, qty)
        if v < best[0]:
            best = (v, at)
    return best


def _pressure_by_group(spec: CamSpec, prof: CamProfile | cd.RockerProfile) -> tuple[float, float]:
    """The largest sampled |α| on the rise (and dwells) and on the return."""
    prog = spec.program
    b = prog.boundaries
    k = np.clip(np.searchsorted(b, prof.phi, side="right") - 1, 0, len(prog.phases) - 1)
    ret = np.array([prog.phases[i].kind == "return" for i in k]) & ~prof.corner
    a = np.abs(prof.pressure)
    rise = float(np.max(a[~ret])) if np.any(~ret) else 0.0
    back = float(np.max(a[ret])) if np.any(ret) else 0.0
    return rise, back


def _rocker_measures(spec: CamSpec, A: np.ndarray, r_r: float) -> tuple[float, float]:
    """The rocker cam's largest pressure angle and its profile's smallest |ρ|, refined."""
    prog = spec.program
    p_max = 0.0
    rho = math.inf
    for k in range(len(prog.phases)):
        v, _ = cd.phase_extreme(
            prog,
            k,
            lambda m: -cd.rocker_pressure_of(A, spec.arm, prog.H, spec.sigma, m),
        )
        p_max = max(p_max, -v)

        def arho(m: Motion) -> np.ndarray:
            r = cd.rocker_rho_pitch(A, spec.arm, prog.H, spec.sigma, m)
            return np.where(np.isfinite(r), np.abs(r - r_r), np.inf)

        v, _ = cd.phase_extreme(prog, k, arho)
        rho = min(rho, v)
    return p_max, rho


def build_file(file_id: str, data: Mapping[str, Any]) -> Build[CamDesign]:
    spec = read_spec(file_id, data)
    des, c, results = design(spec)
    return Build(results, c, [], data=des)


def make_problem(file_id: str, data: dict[str, Any]) -> Problem[CamDesign]:
    """The ``geomcad.files`` kind ``cam``."""
    spec = read_spec(file_id, data)

    def build(_: Mapping[str, Any]) -> Build[CamDesign]:
        return build_file(file_id, data)

    draw = lazy(".cam_sheets:sheets", __package__)
    scales = lazy(".cam_sheets:scales", __package__)
    return file_problem(file_id, data, spec.title, RESULTS, build, draw, scales=scales)
