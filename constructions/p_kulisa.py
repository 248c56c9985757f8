"""kulisa-23110713 · Course work: dynamics of the slotted-link (scotch-yoke) mechanism.

Flywheel 1 (a homogeneous disc m1, R1, I1 = m1·R1²/2) turns about O under a constant moment M
in a horizontal plane. Its pin A (radius OA) works in the vertical slot of yoke 2 (mass m2), which
translates along x: x_C2 = x_C20 + OA·cos φ. The yoke bears, without slip, on the hub radius r3
of roller 3 (mass m3, radius of gyration ρ3), whose radius R3 rolls without slip on the base.
The start is from rest at φ0.

Frame (the report's): O at the origin, φ counter-clockwise from x, A = OA(cos φ, sin φ); the
yoke's contact line with the roller is y = 0 and the roller's centre is C3 = (x_C3, −r3), the
base y = −r3 − R3. The yoke's centre C2 lies on y = 0. Where C2 and the roller sit along x
(x_C20, x_C30) changes no reported result; the sheets place them so that the roller clears the
flywheel (see :func:`layout`).

The model (:mod:`geomcad.dynamics`): the velocity analogues come from the slotted yoke's velocity
plan (V_A2 = V_A1 + V_A2A1) and the roller's instantaneous centre (its base contact P):
v_C3 = R3/(R3 + r3)·v2, ω3 = v2/(R3 + r3). Then

    I_pr = I1 + [m2 + m3·(R3² + ρ3²)/(R3 + r3)²]·OA²·sin²φ = A + B·sin²φ,

the equation of motion I_pr·φ'' + ½·I_pr'·φ'² = M, ω1 by the kinetic-energy theorem from rest
(and by ``solve_ivp``), ε1 from the equation, the reactions by kinetostatics with d'Alembert's
inertia loads, and the horizontal force at the roller's axis that balances M quasi-statically by
equal power, F_x·v_C3 = M·ω1 (checked by a kinetostatic balance without inertia loads).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad import tol
from geomcad.construction import Construction
from geomcad.dynamics import (
    Arrival,
    Body,
    Kinetostatics,
    Motion,
    Part,
    Reactions,
    ReducedModel,
    Torque,
    Yoke,
    ode_settings,
    omega_by_energy,
    reach,
    rolling_wheel,
    slotted_yoke,
    turning,
)
from geomcad.dynamics.analogues import Array, remember_last
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.plan import Plan, Side, velocity_plan
from geomcad.problem import Build, ParamValue
from geomcad.units import deg

#: The farthest φ may lie from φ0: the run-up is integrated and its diagrams drawn turn by turn.
MAX_TURNS = 5

#: The yoke's guide (along x) and its slot (along y): the directions of the yoke's motion and of
#: the pin's slip in the slot, as model angles.
GUIDE = 0.0
SLOT = math.pi / 2.0

#: The operation of the step F_x, which an error names as the protocol does.
F_X_OP = "|M·ω_q1/v_qC3|: equal power of M and F_x"

NOTES = [
    "report erratum: its I_пр(φ) formula prints m3·((R3 + ρ3)/(r3 + R3))²; the kinetic energy "
    "it writes gives m3·(R3² + ρ3²)/(r3 + R3)² (I3 = m3·ρ3²), and its numbers (1,949 = "
    "B) use that; the printed form would give B = 2.428 kg·m² and I_пр = 5.791 kg·m²; the same "
    "slip is in its dI_пр/dφ",
    "report erratum: x_C3 = x_C30 − (R3/(r3 + R3))·OA·cos φ has the wrong sign; rolling under "
    "the yoke moves the roller's centre with the yoke, x_C3 = x_C30 + (R3/(r3 + R3))·OA·cos φ, "
    "as its own v_C3x = R3/(r3 + R3)·v2 says",
]


@dataclass(frozen=True)
class Layout:
    """Where the sheet puts the parts along x (metres): they change no result."""

    x_C20: float
    x_C30: float


def layout(R1: float, OA: float, R3: float, r3: float) -> Layout:
    """The roller clears the flywheel at every φ, and the yoke's centre sits midway between the
    slot's mean position and the roller."""
    k = R3 / (R3 + r3)
    x_C30 = R1 + R3 + k * OA + 0.15 * R1
    return Layout(0.5 * x_C30, x_C30)


@dataclass(frozen=True)
class Data:
    """What the sheets draw."""

    phi: float
    phi0: float
    omega: float
    eps: float
    lay: Layout
    yoke: Yoke
    roller: Motion
    C2: Vec
    C3: Vec
    model: ReducedModel
    arrival: Arrival
    dynamic: Reactions
    static: Reactions
    F_x_kinetostatic: float
    #: the velocity plan of the drawn position (recorded in the construction)
    vplan: Plan
    #: the steps of the plan's order of construction, in recorded order
    plan_steps: tuple[str, ...]


def _nonneg(p: Mapping[str, ParamValue], name: str, what: str) -> float:
    v = float(p[name])
    if v < 0.0:
        raise ParameterError(name, v, f"{what} cannot be negative")
    return v


def mechanism(
    m1: float, R1: float, OA: float, m2: float, m3: float, R3: float, r3: float, rho3: float,
    M: float, lay: Layout,
) -> tuple[ReducedModel, Any, Any]:  # fmt: skip
    """The reduced model and the motions of the yoke (with the pin) and of the roller.

    The yoke translates along x (guide angle 0) with its slot along y; the roller's drive is the
    yoke's displacement, so its centre is (x_C30 + k·OA·cos φ, −r3).
    """

    @remember_last
    def yoke(phi: Array) -> Yoke:
        return slotted_yoke(phi, OA, GUIDE, SLOT, body0=(lay.x_C20, 0.0))

    def drive(phi: Array) -> Motion:
        return slotted_yoke(phi, OA, GUIDE, SLOT).body

    @remember_last
    def roller(phi: Array) -> Motion:
        return rolling_wheel(drive(phi), (1.0, 0.0), R3, r3, (lay.x_C30, -r3))

    parts = (
        Part(Body("1", m1, m1 * R1 * R1 / 2.0), turning),
        Part(Body("2", m2), lambda phi: yoke(phi).body),
        Part(Body("3", m3, m3 * rho3 * rho3), roller),
    )

    def moment(phi: Array, dphi: Array, t: Array) -> Array:
        return M + 0.0 * phi

    return ReducedModel(parts, (Torque("M", turning, moment),)), yoke, roller


def build(p: Mapping[str, ParamValue]) -> Build[Data]:
    """Reduced inertia, ω1 and ε1 at φ (energy and ODE), reactions, balancing force."""
    m1 = _nonneg(p, "m1", "the flywheel's mass")
    m2 = _nonneg(p, "m2", "the yoke's mass")
    m3 = _nonneg(p, "m3", "the roller's mass")
    R1, OA, R3 = float(p["R1"]), float(p["OA"]), float(p["R3"])
    r3, rho3, M = float(p["r3"]), float(p["rho3"]), float(p["M"])
    phi, phi0 = deg(float(p["phi_deg"])), deg(float(p["phi0_deg"]))
    if not phi > phi0:
        raise ParameterError(
            "phi_deg", p["phi_deg"], f"must be > phi0_deg = {p['phi0_deg']}: the flywheel starts "
            "from rest at φ0 and turns forward (counter-clockwise) to φ",
        )  # fmt: skip
    if phi - phi0 > MAX_TURNS * 2.0 * math.pi:
        raise ParameterError(
            "phi_deg", p["phi_deg"], f"must be at most {MAX_TURNS} turns ahead of phi0_deg = "
            f"{p['phi0_deg']}, i.e. ≤ {float(p['phi0_deg']) + 360.0 * MAX_TURNS:g}: the run-up "
            "from rest is integrated and drawn turn by turn",
        )  # fmt: skip
    lay = layout(R1, OA, R3, r3)
    model, yoke, roller = mechanism(m1, R1, OA, m2, m3, R3, r3, rho3, M, lay)
    c = Construction("kulisa-23110713: dynamics of the slotted-link mechanism")
    c.run("I_pr,min", "the smallest I_pr(φ) over a turn from φ0 (must be > 0)",
          lambda: model.check_inertia(phi0))  # fmt: skip
    a_ = c.value("A", float(model.J_pr(0.0)), "I_pr at sin φ = 0: the flywheel alone")
    b_ = c.value("B", float(model.J_pr(math.pi / 2.0)) - a_, "I_pr(90°) − A")
    i_pr = c.value("I_pr", float(model.J_pr(phi)), "Σ(m·v_q² + J·ω_q²) at φ")
    di_pr = c.value("dI_pr", float(model.dJ_pr(phi)), "Σ 2(m·v_q·a_q + J·ω_q·ε_q) at φ")
    # the order's operands: the work of the constant M from rest, 2M(φ − φ0), over I_pr(φ)
    work2 = 2.0 * M * (phi - phi0)
    w = c.run("ω1", "√(2·∫M dφ / I_pr(φ)): kinetic-energy theorem from rest at φ0",
              lambda: omega_by_energy(model, phi0, phi), kind="energy_theorem",
              args={"M": M, "dphi": phi - phi0, "I": i_pr,
                    "w": math.sqrt(work2 / i_pr) if work2 > 0.0 < i_pr else 0.0})  # fmt: skip
    e1 = float(model.phi_ddot(phi, w))
    eps = c.value("ε1", e1, "(M − ½·I_pr'·ω1²)/I_pr", kind="motion_equation",
                  args={"M": M, "dI": di_pr, "w": w, "I": i_pr, "e": e1})  # fmt: skip
    arr = c.run("t_reach", f"equation of motion from rest at φ0 to φ, {ode_settings()}",
                lambda: reach(model, phi0, phi))  # fmt: skip
    c.value("ω1 (ODE)", arr.omega, "φ' at φ from the integration")
    # kinematics at the position
    y = yoke(phi)
    rl = roller(phi)
    C2, C3 = y.body.point(), rl.point()
    vp, plan_steps = plan(c, y.pin.point(), C3, R3, w)
    # reactions with d'Alembert's inertia loads (a balancing moment that must come out zero)
    dyn = c.run("reactions", "equilibrium of flywheel, yoke and roller with inertia loads",
                lambda: kinetostatics(m1, R1, OA, m2, m3, R3, r3, rho3, M, phi, w, eps, lay,
                                      y, rl, inertia=True).solve())  # fmt: skip
    r_o = dyn.force("R_{01}")
    n_a = abs(dyn.magnitudes["N_A"])
    # the balancing force at the roller's axis by equal power: F_x·v_C3 = M·ω1
    v_c3 = float(rl.vx)
    if abs(v_c3) <= tol.length_eps(OA):
        raise ConstructionError(
            f"F_x = {F_X_OP}",
            f"at φ = {p['phi_deg']}° the roller's axis stands still (v_C3 = 0: the pin is on the "
            "yoke's line of motion, a dead position), so no finite force at the axis balances M",
        )
    f_x = abs(M / v_c3)
    c.value("F_x", f_x, F_X_OP, kind="equal_power",
            args={"M": abs(M), "w": abs(w), "v": abs(v_c3 * w), "F": f_x})  # fmt: skip
    st = c.run("F_x (kinetostatics)", "equilibrium of the three bodies without inertia loads",
               lambda: kinetostatics(m1, R1, OA, m2, m3, R3, r3, rho3, M, phi, w, eps, lay,
                                     y, rl, inertia=False).solve())  # fmt: skip
    f_ks = abs(st.magnitudes["F_x"])
    c.value("|F_x| (kinetostatics)", f_ks, "|F_x| of that equilibrium", kind="balance_statics",
            args={"F": f_ks})  # fmt: skip
    results: dict[str, Any] = {
        "I_pr_A": a_,
        "I_pr_B": b_,
        "I_pr": i_pr,
        "dI_pr": di_pr,
        "omega1": w,
        "eps1": eps,
        "N_A": n_a,
        "X_O": abs(r_o.x),
        "Y_O": abs(r_o.y),
        "F_x": f_x,
        "t_reach": arr.t,
        "omega_ode": arr.omega,
    }
    notes = [*NOTES, f"t_reach and omega_ode: {ode_settings(arr.trajectory.method)}"]
    data = Data(phi, phi0, w, eps, lay, y, rl, C2, C3, model, arr, dyn, st, f_ks, vp, plan_steps)
    return Build(results, c, notes, data=data)


def plan(c: Construction, A: Vec, C3: Vec, R3: float, omega: float) -> tuple[Plan, tuple[str, ...]]:
    """The velocity plan at the drawn position, recorded in ``c``, and its order of construction.

    V_A1 = ω1 × OA (the pin on the flywheel); the yoke's point A2 under the pin from
    V_A2 = V_A1 + V_A2A1 (∥ the slot) = V_A0 + V_A2A0 (∥ the guide, A0 of the frame); the
    yoke translates, so its point D (the contact with the roller's hub) has V_D = V_A2 = V_2;
    the roller turns about its instantaneous centre P3 (its contact with the base, at rest), so
    its axis C3 is the image of P3DC3 on the plan (c3 on pd at P3C3/P3D) and ω3 = V_D/l_P3D.
    """
    D = Vec(C3.x, 0.0)
    P3 = Vec(C3.x, C3.y - R3)
    vp = velocity_plan(c)
    vp.fixed("a0")
    vp.rigid("a1", vp.pole, Vec(0.0, 0.0), A, omega, "V_{A1}", "the pin A of flywheel 1", link=1,
             model=("O", "A"))  # fmt: skip
    vp.solve(
        "a2",
        Side("a1", Vec.polar(1.0, SLOT), "∥ the slot", line="@slot"),
        Side("a0", Vec.polar(1.0, GUIDE), "∥ the guide", line="@guide"),
    )
    vp.unknown("a1", "a2", "V_{A2A1}", "the pin's slip along the slot")
    vp.absolute("a2", "V_{A2}", "the yoke's velocity V_2")
    vp.same("d", "a2", "yoke 2 translates", reason="@translates")
    c.point("P3", P3, role="construction", op="the roller's instantaneous centre: its contact "
            "with the base (rolling without slip)", kind="instant_centre",
            args={"pt": "P3", "link": "3"})  # fmt: skip
    vp.fixed("p3")
    vp.image("c3", "p3", "d", P3, D, C3, why="roller 3 turns about P3", model=("P3", "D", "C3"))
    vp.absolute("c3", "V_{C3}", "the roller's axis")
    vp.omega(P3, D, "p3", "d", name="ω3", link=3, model=("P3", "D"))
    listed = {vp.pole, vp.name("a0"), "P3", vp.name("p3"), *vp.order, *vp.values}
    return vp, tuple(s.name for s in c if s.name in listed)


def kinetostatics(
    m1: float, R1: float, OA: float, m2: float, m3: float, R3: float, r3: float, rho3: float,
    M: float, phi: float, omega: float, eps: float, lay: Layout, y: Yoke, rl: Motion,
    inertia: bool,
) -> Kinetostatics:  # fmt: skip
    """Flywheel 1, yoke 2 and roller 3 at φ; link 0 is the frame.

    Flywheel: M, its inertia moment −I1·ε1 (its centre O does not move), the bearing R_01 at O,
    the yoke's push at A (N_A, along x: the slot is vertical and frictionless). Yoke: N_A, its
    inertia force −m2·a2 at C2, the roller's friction at the contact D (x_C3, 0) along x, its
    guide's pressure (along y) and couple. Roller: that friction reversed, the base's friction
    at P (x_C3, −r3 − R3), its inertia force −m3·a_C3 and moment −I3·ε3. In the horizontal plane
    no weight presses the roller, so its contacts carry only their friction forces.

    With ``inertia`` the accelerations follow from ε1 and ω1, and a balancing moment M_b on the
    flywheel must come out zero (the equation of motion); without it the mechanism is balanced
    quasi-statically by an unknown horizontal force F_x at the roller's axis.
    """
    ks = Kinetostatics("kinetostatics of flywheel, yoke and roller")
    A = y.pin.point()
    C2 = y.body.point()
    C3 = rl.point()
    D = Vec(C3.x, 0.0)
    P = Vec(C3.x, -r3 - R3)
    if inertia:
        a2, _ = y.body.acceleration(omega, eps)
        a3, e3 = rl.acceleration(omega, eps)
        ks.body("1", J=m1 * R1 * R1 / 2.0, eps=eps, inertia_names=("Phi_1", "M_Phi1"))
        ks.body("2", m=m2, centre=C2, a=a2, inertia_names=("Phi_2", "M_Phi2"))
        ks.body("3", m=m3, J=m3 * rho3 * rho3, centre=C3, a=a3, eps=e3,
                inertia_names=("Phi_3", "M_Phi3"))  # fmt: skip
    else:
        ks.body("1")
        ks.body("2", centre=C2)
        ks.body("3", centre=C3)
    ks.torque("1", "M", M)
    ks.joint("R_{01}", None, "1", (0.0, 0.0))
    ks.contact("N_A", "1", "2", A, (1.0, 0.0))
    ks.contact("R_{32}", "3", "2", D, (1.0, 0.0))
    ks.contact("R_{02}", None, "2", C2, (0.0, 1.0))
    ks.couple("M_{02}", None, "2")
    ks.contact("R_{03}", None, "3", P, (1.0, 0.0))
    if inertia:
        ks.balancing_torque("M_b", "1")
    else:
        ks.balancing_force("F_x", "3", C3, (1.0, 0.0))
    return ks


def turns(data: Data) -> int:
    """Whole turns from φ0 that the diagrams show: one, or as many as it takes to reach φ."""
    return max(1, math.ceil((data.phi - data.phi0) / (2.0 * math.pi) - tol.DERIVED))


def sweep(data: Data, n: int = 361) -> dict[str, np.ndarray]:
    """I_pr, dI_pr and ω1 (kinetic-energy theorem from rest at φ0) over the turns from φ0 that
    reach φ (:func:`turns`)."""
    from geomcad.dynamics import omega_curve

    span = 2.0 * math.pi * turns(data)
    phis = data.phi0 + np.linspace(0.0, span, n * turns(data))
    return {
        "phi": phis,
        "I_pr": data.model.J_pr(phis),
        "dI_pr": data.model.dJ_pr(phis),
        "omega": omega_curve(data.model, data.phi0, phis),
    }
