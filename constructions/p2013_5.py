"""2013-5 · Planetary gear ratio u_1H2 (Willis' method, checked by the mesh equations and by the
plan of linear velocities).

The train (reconstructed, problems.md; the seed's figure is lost). Moving links: the input sun 1
on the central axis; block 2-5 (ring 2 with internal teeth and pinion 5) turning on the axis O_25,
which the outer carrier H2 carries at the distance a from the central axis; block H1-4 (carrier H1
and gear 4) turning on the same axis O_25; planet 6 on H1; block H2-7 (the outer carrier and the
ring 7, coaxial with O_25). Gear 3 on the central axis is fixed (part of the frame 0).

Meshes (each with the link on which both its axes are fixed): 1–2 internal on H2; 4–3 external on
H2; 5–6 external and 6–7 internal on H1. Coaxiality: the pairs 1–2 and 4–3 both join the central
axis to O_25, so m(z2 − z1)/2 = m(z3 + z4)/2 and z4 = z2 − z1 − z3 (the seed misprints the left
side as z1 − z2); the pairs 5–6 and 6–7 both join O_25 to the planet's axis, so
m(z5 + z6)/2 = m(z7 − z6)/2 and z7 = z5 + 2·z6.

Willis (the seed's way): with H2 held, the train is a fixed-axis train of three stages,
u_13^(H2) = u_12 · u_5H1^(7) · u_43 with u_12 = z2/z1, u_43 = −z3/z4 and, for the stage 5–6–7 in
which ring 7 is held (it is part of H2), u_5H1^(7) = 1 − u_57^(H1) = 1 + z7/z5. Then
u_1H2 = 1 − u_13^(H2). All ratios are exact fractions.

Checks: the mesh equations in absolute angular velocities (ω_0 = 0, ω_1 = 1) solved exactly; and
the graphical method. Smirnov's plan of linear velocities is drawn on the radial line through both
axes, with the radii y of its points: O (central axis, y = 0), A (mesh 1–2, y = a − r2),
C (mesh 4–3, y = r3), B (axis O_25, y = a), D (mesh 5–6, y = a + r5), E (axis of planet 6,
y = a + r5 + r6) and F (mesh 6–7, y = a + r7). The plan starts from the output: the line of H2
through o (v = 0) and b, with ω_H2 taken as 1 rad/s (any value would do: the plan is linear);
then H1-4 through c (the pitch point with the fixed gear 3 has v = 0) and b; 6 through e and f;
2-5 through b and d; 1 through o and a. Each line's slope dv/dy is its link's ω, so ω_1 read off
the plan is u_1H2. The angle diagram draws rays parallel to the lines from one pole; their
intercepts on a line at distance H from the pole are H·ω, and their ratio is the train's ratio.

Choices settled here (they change no published number): the planet 6 drawn is the one on the side
of O_25 away from the central axis; the module m only sizes the drawing.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.trains import (
    Mesh,
    PlanPoint,
    RayPlan,
    VelocityPlan,
    chain_ratio,
    coaxial_count,
    link_markup,
    mobility,
    ray_plan,
    solve_speeds,
    velocity_plan,
    willis,
)
from geomcad.problem import Build, ParamValue

#: The links: the frame (with the fixed gear 3) and the five moving links.
FRAME, SUN, BLOCK25, PLANET, H1, H2 = "0", "1", "2-5", "6", "H1-4", "H2-7"


@dataclass(frozen=True)
class Geometry:
    """What the sheet needs besides the recorded steps (lengths in m, the module's drawing)."""

    z: dict[str, int]
    m: float
    a: float
    points: tuple[PlanPoint, ...]
    plan: VelocityPlan
    rays: RayPlan
    omega_exact: dict[str, Fraction]  # ω_i / ω_H2, exactly
    extent: tuple[float, float]  # the radii the scheme spans (y_min, y_max)


def _given_count(
    p: Mapping[str, ParamValue], name: str, derived: Fraction, rule: str, why: str
) -> int | None:
    """A tooth count given explicitly, checked against the one coaxiality gives; ``None`` when
    it is not given."""
    if name not in p:
        return None
    given = int(p[name])
    if Fraction(given) != derived:
        tail = "" if derived.denominator == 1 and derived >= 1 else ", which no gear can have"
        raise ParameterError(name, given, f"breaks coaxiality: {why}, so {rule} = {derived}{tail}")
    return given


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """Willis' method as in the seed, checked by the mesh equations and the velocity plan."""
    z1, z2, z3, z5, z6 = (int(p[n]) for n in ("z1", "z2", "z3", "z5", "z6"))
    m = float(p["m"])
    if z2 <= z1:
        raise ParameterError(
            "z2",
            z2,
            f"the ring 2 meshes with the sun 1 inside it: it needs more teeth than z1 = {z1}",
        )
    c = Construction("2013-5: planetary train, Willis' method and the plan of linear velocities")
    # coaxiality: the centre distances, in modules
    a12 = Mesh(SUN, z1, BLOCK25, z2, H2, internal=True).centre_distance()
    c.value("a_12", float(a12), "m(z2 − z1)/2 in modules: centre distance of 1–2")
    z4 = _given_count(
        p,
        "z4",
        2 * a12 - z3,
        "z4 = z2 − z1 − z3",
        f"the pairs 1–2 and 4–3 share the centre distance m(z2 − z1)/2 = {a12}·m",
    )
    if z4 is None:
        z4 = c.run(
            "z4",
            "z2 − z1 − z3 (coaxiality of 1–2 and 4–3)",
            lambda: coaxial_count("z4", a12, z3, internal=False),
        )
    else:
        c.value("z4", float(z4), "given; equals z2 − z1 − z3 (coaxiality of 1–2 and 4–3)")
    a56 = Mesh(BLOCK25, z5, PLANET, z6, H1).centre_distance()
    c.value("a_56", float(a56), "m(z5 + z6)/2 in modules: centre distance of 5–6")
    z7 = _given_count(
        p,
        "z7",
        2 * a56 + z6,
        "z7 = z5 + 2·z6",
        f"the pairs 5–6 and 6–7 share the centre distance m(z5 + z6)/2 = {a56}·m",
    )
    if z7 is None:
        z7 = c.run(
            "z7",
            "z5 + 2·z6 (coaxiality of 5–6 and 6–7)",
            lambda: coaxial_count("z7", a56, z6, internal=True, ring_unknown=True),
        )
    else:
        c.value("z7", float(z7), "given; equals z5 + 2·z6 (coaxiality of 5–6 and 6–7)")

    m12 = Mesh(SUN, z1, BLOCK25, z2, H2, internal=True)
    m56 = Mesh(BLOCK25, z5, PLANET, z6, H1)
    m67 = Mesh(PLANET, z6, H2, z7, H1, internal=True)
    m43 = Mesh(H1, z4, FRAME, z3, H2)
    meshes = (m12, m56, m67, m43)

    # structure: five moving links, five revolute pairs (1–0, H2–0, 2-5 on H2, H1-4 on H2,
    # 6 on H1) and one higher pair per mesh
    moving = (SUN, BLOCK25, PLANET, H1, H2)
    lower = ((SUN, FRAME), (H2, FRAME), (BLOCK25, H2), (H1, H2), (PLANET, H1))
    W = mobility(len(moving), len(lower), len(meshes))
    c.value("W", float(W), "3n − 2p_l − p_h")

    # Willis, stage by stage with H2 held
    u12 = chain_ratio([m12])
    u57_h1 = chain_ratio([m56, m67])
    u5h1_7 = willis(u57_h1)
    u43 = chain_ratio([m43])
    u13_h2 = u12 * u5h1_7 * u43
    u1h2 = willis(u13_h2)
    for name, value, op in (
        ("u12", u12, "z2/z1"),
        ("u57(H1)", u57_h1, "(−z6/z5)·(z7/z6) = −z7/z5"),
        ("u5H1(7)", u5h1_7, "1 − u57(H1)"),
        ("u43", u43, "−z3/z4"),
        ("u13(H2)", u13_h2, "u12·u5H1(7)·u43"),
        ("u1H2", u1h2, "1 − u13(H2)"),
    ):
        c.value(name, float(value), f"{op} = {value}")

    # check: the mesh equations in absolute angular velocities, exactly
    speeds = c.run(
        "ω (mesh equations)",
        "z_a(ω_a − ω_H) ± z_b(ω_b − ω_H) = 0 per mesh, ω_0 = 0, ω_1 = 1",
        lambda: solve_speeds(meshes, {FRAME: Fraction(0), SUN: Fraction(1)}),
    )
    if speeds[H2] == 0 or 1 / speeds[H2] != u1h2:
        raise ConstructionError(
            c.step("ω (mesh equations)").title,
            f"ω_1/ω_H2 = {1 / speeds[H2] if speeds[H2] else '∞'} differs from Willis' {u1h2}",
        )
    omega_exact = {k: v / speeds[H2] for k, v in speeds.items()}

    # the graphical method: Smirnov's plan, trial ω_H2 = 1 rad/s
    r = {k: m * zz / 2.0 for k, zz in (("1", z1), ("2", z2), ("3", z3), ("4", z4))}
    r.update({k: m * zz / 2.0 for k, zz in (("5", z5), ("6", z6), ("7", z7))})
    a = m * float(a12)
    points = (
        PlanPoint("O", 0.0, (FRAME, SUN, H2)),
        PlanPoint("A", a - r["2"], (SUN, BLOCK25)),
        PlanPoint("C", r["3"], (H1, FRAME)),
        PlanPoint("B", a, (H2, BLOCK25, H1)),
        PlanPoint("D", a + r["5"], (BLOCK25, PLANET)),
        PlanPoint("E", a + r["5"] + r["6"], (PLANET, H1)),
        PlanPoint("F", a + r["7"], (PLANET, H2)),
    )
    omega_h2 = 1.0
    plan = velocity_plan(c, points, FRAME, H2, "B", omega_h2 * a)
    u_plan = plan.omega[SUN] / plan.omega[H2]
    # the radii the scheme spans
    y_lo = min(-r["1"], -r["3"], a - r["2"], a - r["7"])
    y_hi = max(a + r["2"], a + r["7"], a + r["5"] + 2 * r["6"])
    # the angle diagram: pole S below the plan on its axis v = 0, pole distance H = a (any
    # distance would do: the diagram is linear in it); ray i ends at v = H·ω_i
    links = (SUN, BLOCK25, PLANET, H1, H2)
    S = Vec(0.0, y_lo - 2.0 * a)
    rays = ray_plan(c, plan, S, a, links)
    u_rays = rays.ratio(SUN, H2)
    ratio = {"a": link_markup(SUN), "b": link_markup(H2)}
    c.value("u1H2 (plan)", u_plan, "slope of line 1 / slope of line H2", kind="ratio_slopes",
            args={**ratio, "u": u_plan})  # fmt: skip
    c.value("u1H2 (angle diagram)", u_rays, "intercept of ray 1 / intercept of ray H2",
            kind="ratio_rays", args={**ratio, "u": u_rays})  # fmt: skip
    for name, got in (("u1H2 (plan)", u_plan), ("u1H2 (angle diagram)", u_rays)):
        if not math.isclose(got, float(u1h2), rel_tol=tol.DERIVED):
            raise ConstructionError(
                c.step(name).title, f"u_1H2 = {got!r} differs from Willis' {float(u1h2)!r}"
            )

    results: dict[str, Any] = {
        "W": W,
        "z4": z4,
        "z7": z7,
        "u12": float(u12),
        "u5H1_7": float(u5h1_7),
        "u43": float(u43),
        "u13_H2": float(u13_h2),
        "u1H2": float(u1h2),
        "u1H2_fraction": [u1h2.numerator, u1h2.denominator],
    }
    notes = [  # the seed's misprint comes before them (the spec's seed_notes)
        f"checks: the mesh equations give ω_1/ω_H2 = {1 / speeds[H2]} exactly; the plan of "
        f"linear velocities gives {u_plan:.12g} (slopes) and {u_rays:.12g} (angle diagram)"
    ]
    zs = {"1": z1, "2": z2, "3": z3, "4": z4, "5": z5, "6": z6, "7": z7}
    geo = Geometry(zs, m, a, points, plan, rays, omega_exact, (y_lo, y_hi))
    return Build(results, c, notes, data=geo)
