"""2013-2 · Cam profile for S = a·φ ("cam profile radii").

A disc cam turns about O at constant ω and drives a translating follower with a flat face
perpendicular to its motion. The stroke on the rise angle φ_у = 180° is H = 40 mm, the cam's
smallest radius r0 = 40 mm, the law S = aφ. The seed builds the profile on the first half of the
rise (φ = 0 … 90°, four intervals of π/8) by inversion and draws it at 2:1.

The seed's argument: in the mechanism's velocity plan Bb₁b₂ (V_B2 = V_B1 + V_B2B1, V_B2 along
the motion, V_B2B1 along the face), turned by 90°, is similar to the triangle OBB′ with the ratio
ω, so the contact point B lies S′ = dS/dφ along the face from the line through O along the motion:
r = √((r0 + S)² + S′²). For S = aφ, S′ = a = H/φ_у, and the envelope of the face lines is an
involute of the circle of radius a.

Frame (problems.md): O is the origin, the follower moves along +y, at φ = 0 the cam's frame is
the fixed one; ``omega_sign`` +1 turns the cam counter-clockwise. Choices settled here (no
published number depends on them):

- the division points φ_i = i·span/n_div, span = span_fraction·(φ_rise + φ_dwell + φ_return);
  each takes the value of the phase that starts there (at φ = 0: S′ = a, the seed's r_0), the
  last one the value of the phase that ends there;
- without a return phase the profile is built over the span; with one (``phi_return_deg`` > 0)
  the program is completed by the lower dwell to a full turn and the closed profile is built;
- ``law`` drives both the rise and the return;
- r0 is the smallest radius of the theoretical profile (textbook «центровой профиль»): the
  flat face's (the seed's r_Omin, the cam's smallest radius), the knife's tip path, the roller
  centre's pitch curve; the roller's working profile then has the base circle r0 − r_roller.
  ``r`` lists the radius vectors of the working profile (what is cut). ``e`` offsets the
  follower's axis (for the flat face it moves the stem only: the profile does not change);
- the velocity plan is drawn for ω = 1 rad/s at a division point where |S′| is largest, the
  middle one among equals (the seed's φ_2 = 45°).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import ConstructionError, GeomcadError, ParameterError
from geomcad.geom import Circle, Vec, perpendicular
from geomcad.kinematics.cams import (
    CamProfile,
    Follower,
    VelocityPlan,
    at_angles,
    cam_profile,
    pressure_angle_max,
    profile_step_name,
    rho_min,
    velocity_plan,
)
from geomcad.kinematics.motion_laws import CamProgram, standard_program
from geomcad.kinematics.plan import Plan, Side
from geomcad.kinematics.plan import velocity_plan as plan_of
from geomcad.problem import Build, ParamValue
from geomcad.units import deg, to_deg

#: m → mm for the operands of the order of construction
MM = 1000.0

NOTES = [
    "seed notation: it calls the similar triangle OBB′ but writes its sides as Bb and Ob in "
    "b₂b₁/Bb = Bb₂/Ob = Bb₁/OB = ω (b is B′: the foot of B on the line through O across the "
    "motion), and C, in BC = Ob = S′, is where the face crosses the follower's axis; the "
    "figure is lost, no number is affected",
]


@dataclass(frozen=True)
class Geometry:
    """The solved model besides the recorded steps: the program, the follower, the profile over
    the span (and, for a full turn, closed), the division points and the velocity plan."""

    program: CamProgram
    follower: Follower
    profile: CamProfile
    divisions: CamProfile
    span: float
    closed: bool
    plan: VelocityPlan
    plan_index: int
    #: The velocity plan at the plan's division point as recorded (its vector equation
    #: V_B2 = V_B1 + V_B2B1, the lines it was solved on), for the sheet's plan view.
    recorded: Plan
    #: The profile on from the span's end to the program's end (the rest of the program, which
    #: the sheet draws in thin lines so that the cam's shape is seen whole); ``None`` when the
    #: span covers the program (or the profile is closed), or when the rest has a cusp.
    rest: CamProfile | None = None


def _check(p: Mapping[str, ParamValue]) -> None:
    sigma = int(p["omega_sign"])
    if sigma not in (1, -1):
        raise ParameterError("omega_sign", p["omega_sign"], "must be +1 or −1")
    total = float(p["phi_rise_deg"]) + float(p["phi_dwell_deg"]) + float(p["phi_return_deg"])
    if total > 360.0:
        raise ParameterError(
            "phi_return_deg" if float(p["phi_return_deg"]) > 0.0 else "phi_dwell_deg",
            p["phi_return_deg"] if float(p["phi_return_deg"]) > 0.0 else p["phi_dwell_deg"],
            f"rise + dwell + return = {total:g}° is more than a full turn (360°)",
        )
    if p["follower"] == "roller" and not float(p["r_roller"]) > 0.0:
        raise ParameterError("r_roller", p["r_roller"], "a roller follower needs r_roller > 0")


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """The profile by inversion, its division points, radius vectors and the velocity plan."""
    _check(p)
    H, r0 = float(p["H"]), float(p["r0"])
    rise, dwell, ret = (deg(float(p[n])) for n in ("phi_rise_deg", "phi_dwell_deg",
                                                   "phi_return_deg"))  # fmt: skip
    n_div, sigma = int(p["n_div"]), int(p["omega_sign"])
    law, kind = str(p["law"]), str(p["follower"])
    e, r_r = float(p["e"]), float(p["r_roller"]) if p["follower"] == "roller" else 0.0
    f = Follower(kind, r0, e, r_r, sigma)
    program = standard_program(H, rise, law, dwell, ret)
    closed = ret > 0.0
    span = float(p["span_fraction"]) * (rise + dwell + ret)

    c = Construction(f"2013-2: cam profile by inversion ({law} law, {kind} follower)")
    centre = c.point("O", (0.0, 0.0), note="the cam's centre of rotation")
    c.run(
        "base", "circle(O, r0)", lambda: Circle(centre, r0), (centre,), "given",
        "the theoretical profile's", kind=f"cam_base_{kind}", args={"r": r0 * MM},
    )  # fmt: skip
    a = c.value("a", H / rise, "H / φ_rise (S′ of the linear law)")
    what = "the full turn" if closed else f"φ = 0 … {to_deg(span):.6g}°"
    prof = c.run(
        "profile",
        f"{profile_step_name(kind).split(' = ', 1)[1]}, over {what}",
        lambda: cam_profile(program, f, 0.0, span, closed),
        role="result",
        kind=f"cam_profile_{kind}",
        args={"r": r_r * MM},
    )
    phis = np.linspace(0.0, span, n_div + 1)
    div = at_angles(program, f, phis, span)
    _record_divisions(c, f, div, span)
    k = _plan_index(div.S1)
    plan = velocity_plan(program, f, float(div.phi[k]))
    recorded = _record_plan(c, f, plan, k)

    r = [float(x) for x in div.radius]
    results: dict[str, Any] = {
        "phi": [float(x) for x in div.phi],
        "S": [float(x) for x in div.S],
        "r": r,
        "a": a,
        "pressure_angle_max_deg": to_deg(pressure_angle_max(program, prof)),
        "rho_min": c.value("ρ_min", rho_min(program, prof), "smallest |ρ| of the profile"),
        "profile": _points(prof),
    }
    notes = list(NOTES) + _jump_notes(prof, program, f)
    rest = _rest(program, f, span, closed)
    geo = Geometry(program, f, prof, div, span, closed, plan, k, recorded, rest)
    return Build(results, c, notes, {}, geo)


def _rest(program: CamProgram, f: Follower, span: float, closed: bool) -> CamProfile | None:
    """The profile from the span's end to the end of the program (not recorded as a step: no
    result depends on it); ``None`` when there is nothing more, or when it cannot be cut (a cusp
    past the span is not this problem's error)."""
    if closed or span >= program.total * (1.0 - tol.DERIVED):
        return None
    try:
        return cam_profile(program, f, span, program.total)
    except GeomcadError:
        return None


def _plan_index(S1: np.ndarray) -> int:
    """The division point the velocity plan is drawn at: one where |S′| is largest (so that the
    triangle OBB′ does not degenerate), the one nearest the middle among equals."""
    mag = np.abs(S1)
    top = float(mag.max())
    mid = (len(S1) - 1) // 2
    best = [i for i in range(len(S1)) if mag[i] >= top * (1.0 - tol.DERIVED)]
    return min(best, key=lambda i: (abs(i - mid), i))


def _record_divisions(c: Construction, f: Follower, div: CamProfile, span: float) -> None:
    """Per division point: the follower turned back by φ_i, its face (or tip) and B_i, r_i.

    Each step's kind is a general step of the inversion, its operand ``i`` the division's index
    (the sheet writes the steps of one division with ``i`` for the index: "for each φ_i")."""
    centre = c["O"]
    n = len(div.phi) - 1
    c.value(
        "Δφ", span / n, f"the span {to_deg(span):.6g}° in {n} equal intervals",
        kind="cam_divide", args={"span": to_deg(span), "n": float(n), "d": to_deg(span / n)},
    )  # fmt: skip
    offset = f.kind != "flat" and f.e != 0.0
    for i in range(len(div.phi)):
        phi = float(div.phi[i])
        c.value(f"φ_{i}", phi, f"division point {i}")
        c.value(f"S_{i}", float(div.S[i]), f"S(φ_{i})")
        c.value(f"S′_{i}", float(div.S1[i]), f"dS/dφ at φ_{i}")
        turn = -f.sigma * phi
        up = Vec(0.0, 1.0).rotated(turn)
        # the flat face is built from the line through O along the motion (the stem's offset
        # does not change the profile); a knife's or roller's axis is offset by e
        foot = Vec(0.0 if f.kind == "flat" else f.e, 0.0).rotated(turn)
        axis = c.line(
            f"axis_{i}", foot, up, f"the follower's axis turned back by φ_{i}",
            kind="cam_axis_offset" if offset else "cam_axis",
            args={"i": float(i), "e": abs(f.e) * MM} if offset else {"i": float(i)},
        )  # fmt: skip
        C = c.point(
            f"C_{i}",
            Vec(*div.pitch[i]),
            role="construction",
            op=f"on axis_{i} at {'r0 + S' if f.kind == 'flat' else 's0 + S'}_{i}",
            kind="cam_lay_offset" if offset else "cam_lay",
            args={"i": float(i), "s0": f.s0 * MM} if offset else {"i": float(i)},
        )
        if f.kind == "flat":
            c.record(
                f"face_{i}", f"perpendicular to axis_{i} at C_{i}", perpendicular(axis, C),
                (axis, C), note="the face, ⊥ the motion", kind="cam_face", args={"i": float(i)},
            )  # fmt: skip
            op = f"on face_{i} at S′_{i} from C_{i} (the velocity plan)"
        elif f.kind == "roller":
            op = f"circle(C_{i}, r_roller) touching the profile along its normal"
        else:
            op = f"the knife's tip C_{i}"
        B = c.point(
            f"B_{i}", Vec(*div.contact[i]), role="result", op=op,
            kind=f"cam_contact_{f.kind}", args={"i": float(i), "r": f.r_roller * MM},
        )  # fmt: skip
        c.value(f"r_{i}", B.dist(centre), f"|OB_{i}|", (centre, B))


def _record_plan(c: Construction, f: Follower, plan: VelocityPlan, k: int) -> Plan:
    """The velocity plan at division point k (fixed frame, ω = 1 rad/s), built as the vector
    equation V_B2 = V_B1 + V_B2B1 (:mod:`geomcad.kinematics.plan`), and the triangle OBB′
    similar to it; the plan must agree with the cam's (:func:`velocity_plan` of the law)."""
    B = c.point(
        "B", plan.B, role="construction", op=f"the contact point at φ_{k}, fixed frame",
        kind="cam_plan_at", args={"k": float(k), "phi": to_deg(plan.phi)},
    )  # fmt: skip
    vp = plan_of(c)
    vp.rigid("b1", "p", Vec(0.0, 0.0), B, f.sigma * plan.omega, "V_{B1}", "the cam's point at B",
             link=1, model=("O", "B"))  # fmt: skip
    # V_B2B1 along the face (flat) or along the pitch curve's tangent at B (knife, roller)
    along = Vec(1.0, 0.0) if f.kind == "flat" else plan.V_B2B1
    vp.solve(
        "b2",
        Side("b1", along, "∥ the face BC" if f.kind == "flat" else "∥ the pitch curve's tangent",
             line="BC" if f.kind == "flat" else "@tangent", unknown="V_{B2B1}"),
        Side("p", Vec(0.0, 1.0), "∥ the motion", line="@guide"),
    )  # fmt: skip
    vp.unknown("b1", "b2", "V_{B2B1}", "the follower's velocity relative to the cam")
    b2 = vp.absolute("b2", "V_{B2}", "the follower's velocity")
    if b2.dist(plan.V_B2) > tol.DERIVED * max(plan.V_B1.norm, plan.V_B2.norm):
        raise ConstructionError(
            c.step("b2").title, f"{b2!r} differs from the cam's V_B2 = {plan.V_B2!r}"
        )
    c.point(
        "B′", plan.B_prime, role="construction", op="normal at B ∩ line through O across motion",
        kind="cam_similar", args={"value": abs(plan.S1) * MM},
    )  # fmt: skip
    c.value("OB′", plan.B_prime.norm, "|OB′| = S′ (the similar triangle OBB′)")
    return vp


def _points(prof: CamProfile) -> list[list[float]]:
    """The profile as [x, y] pairs, consecutive duplicates dropped."""
    pts = prof.contact
    keep = np.ones(len(pts), dtype=bool)
    keep[1:] = np.any(pts[1:] != pts[:-1], axis=1)
    return [[float(x), float(y)] for x, y in pts[keep]]


def _jump_notes(prof: CamProfile, program: CamProgram, f: Follower) -> list[str]:
    """What happens where S′ jumps inside the built profile (the linear law's ends)."""
    out: list[str] = []
    corner = prof.corner
    if not np.any(corner):
        return out
    starts = [i for i in range(len(corner)) if corner[i] and (i == 0 or not corner[i - 1])]
    for i in starts:
        j = i
        while j < len(corner) and corner[j]:
            j += 1
        at = to_deg(float(prof.phi[i]))
        d0 = float(prof.S1[i - 1]) if i > 0 else 0.0
        d1 = float(prof.S1[j]) if j < len(corner) else 0.0
        head = (
            f"at φ = {at:.6g}°, S′ jumps from {d0 * 1000:.6g} to {d1 * 1000:.6g} mm, so S″ is "
            "infinite there (a rigid impact)"
        )
        if f.kind == "flat":
            p0 = prof.contact[i - 1] if i > 0 else prof.contact[0]
            p1 = prof.contact[j] if j < len(corner) else prof.contact[-1]
            r1 = math.hypot(*p1)
            out.append(
                f"{head}: the contact point moves {abs(d1 - d0) * 1000:.6g} mm along the face in "
                f"no time, so the profile has a straight piece of the face line there, from "
                f"({p0[0] * 1000:.4g}; {p0[1] * 1000:.4g}) to ({p1[0] * 1000:.4g}; "
                f"{p1[1] * 1000:.4g}) mm; the radius vector at its end is {r1 * 1000:.6g} mm"
                + (
                    f" (the seed's r_0 = 41.98 mm), not the base radius r0 = {f.r0 * 1000:g} mm"
                    if at == 0.0 and d0 == 0.0
                    else ""
                )
                + (
                    "; from there on the profile is the involute of the circle of radius a"
                    if program.phases[0].law == "linear" and at == 0.0
                    else ""
                )
            )
        elif f.kind == "roller":
            out.append(
                f"{head}: the roller rests in a corner of the pitch curve while the cam turns "
                f"on, so the profile has an arc of the roller circle (radius "
                f"{f.r_roller * 1000:g} mm) there"
            )
        else:
            out.append(f"{head}: the profile has a sharp corner there (the knife's path bends)")
    return out
