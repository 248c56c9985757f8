"""geomcad.dynamics: velocity analogues, the reduced model, the two ways to ω (energy and
solve_ivp), kinetostatics, flywheels; and the sheet helpers the dynamics sheets draw with."""

from __future__ import annotations

import math

import numpy as np
import pytest

from geomcad.dynamics import (
    Body,
    Force,
    Kinetostatics,
    Part,
    ReducedModel,
    Torque,
    crank_point,
    cycle_work,
    flywheel_inertia,
    integrate,
    omega_by_energy,
    omega_curve,
    reach,
    rolling_wheel,
    slotted_yoke,
    speeds_from_max,
    speeds_from_mean,
    time_by_energy,
    turning,
    work,
)
from geomcad.errors import ConstructionError, DegenerateInput, ParameterError
from geomcad.geom import Vec
from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.graph import Axis, Graph
from geomcad.sheet.loads import force, moment
from geomcad.sheet.model import ArcItem, Polyline

PHI = np.linspace(0.0, 2.0 * math.pi, 73)
H = 1e-6  # step of the central differences


def central(f, x: np.ndarray) -> np.ndarray:  # type: ignore[no-untyped-def]
    return (f(x + H) - f(x - H)) / (2.0 * H)


# -- analogues ---------------------------------------------------------------------------------


def test_crank_point_analogues_are_the_derivatives_of_its_position() -> None:
    m = crank_point(PHI, 0.3, (0.1, -0.2))
    assert np.allclose(m.x, 0.1 + 0.3 * np.cos(PHI)) and np.allclose(m.y, -0.2 + 0.3 * np.sin(PHI))
    assert np.allclose(m.vx, central(lambda p: crank_point(p, 0.3).x, PHI), atol=1e-8)
    assert np.allclose(m.ay, central(lambda p: crank_point(p, 0.3).vy, PHI), atol=1e-8)
    # V_A ⊥ OA
    assert np.allclose(m.vx * (m.x - 0.1) + m.vy * (m.y + 0.2), 0.0, atol=1e-15)


@pytest.mark.parametrize(("guide", "slot"), [(0.0, math.pi / 2), (math.pi / 2, 0.0), (0.3, 1.4)])
def test_slotted_yoke_solves_its_velocity_plan(guide: float, slot: float) -> None:
    r = 0.24
    y = slotted_yoke(PHI, r, guide, slot)
    u = np.array([math.cos(guide), math.sin(guide)])
    s = np.array([math.cos(slot), math.sin(slot)])
    # the pin stays on the slot line through the yoke's reference point
    rel = np.stack([y.pin.x - y.body.x, y.pin.y - y.body.y])
    assert np.allclose(rel[0] * s[1] - rel[1] * s[0], 0.0, atol=1e-15)
    # V_A2 = V_A1 + V_A2A1: the yoke's velocity minus the pin's lies along the slot
    dv = np.stack([y.body.vx - y.pin.vx, y.body.vy - y.pin.vy])
    assert np.allclose(dv[0] * s[1] - dv[1] * s[0], 0.0, atol=1e-14)
    assert np.allclose(np.stack([y.body.vx, y.body.vy]), np.outer(u, y.vs), atol=1e-15)
    assert np.allclose(y.vs, central(lambda p: slotted_yoke(p, r, guide, slot).s, PHI), atol=1e-8)
    assert np.allclose(y.as_, central(lambda p: slotted_yoke(p, r, guide, slot).vs, PHI), atol=1e-8)


def test_scotch_yoke_x_is_r_sin_phi_and_r_cos_phi() -> None:
    """The two problems' yokes: x = r·sin φ (guide along y) and x = x0 + OA·cos φ (along x)."""
    valve = slotted_yoke(PHI, 0.05, math.pi / 2, 0.0)
    assert np.allclose(valve.body.y, 0.05 * np.sin(PHI), atol=1e-15)
    assert np.allclose(valve.body.vy, 0.05 * np.cos(PHI), atol=1e-15)
    kulisa = slotted_yoke(PHI, 0.24, 0.0, math.pi / 2, body0=(0.3, 0.0))
    assert np.allclose(kulisa.body.x, 0.3 + 0.24 * np.cos(PHI), atol=1e-15)
    assert np.allclose(kulisa.body.vx, -0.24 * np.sin(PHI), atol=1e-15)


def test_a_slot_along_the_guide_is_degenerate() -> None:
    with pytest.raises(DegenerateInput, match="slot is parallel to the guide"):
        slotted_yoke(0.3, 0.1, 0.2, 0.2 + math.pi)
    with pytest.raises(ParameterError, match="crank radius"):
        slotted_yoke(0.3, 0.0, 0.0, 1.0)


def test_rolling_wheel_has_no_slip_at_either_contact() -> None:
    R, r = 0.12, 0.05
    drive = slotted_yoke(PHI, 0.24, 0.0, math.pi / 2).body
    w = rolling_wheel(drive, (1.0, 0.0), R, r, (0.7, -r))
    # base contact P = C − (0, R): v_P = v_C + ω × (P − C) = v_C + ω·R·(1, 0) = 0
    assert np.allclose(w.vx + w.w * R, 0.0, atol=1e-15)
    # drive contact D = C + (0, r): v_D = v_C − ω·r = the drive's velocity
    assert np.allclose(w.vx - w.w * r, drive.vx, atol=1e-15)
    assert np.allclose(w.vx, R / (R + r) * drive.vx, atol=1e-15)
    assert np.allclose(w.ax, central(lambda p: rolling_wheel(
        slotted_yoke(p, 0.24, 0.0, math.pi / 2).body, (1.0, 0.0), R, r, (0.7, -r)).vx, PHI),
        atol=1e-8)  # fmt: skip


# -- the reduced model -------------------------------------------------------------------------


def kulisa_model(m1: float = 80.0, M: float = 34.0) -> ReducedModel:
    OA, R3, r3 = 0.24, 0.12, 0.05

    def yoke(p: np.ndarray):  # type: ignore[no-untyped-def]
        return slotted_yoke(p, OA, 0.0, math.pi / 2).body

    return ReducedModel(
        (
            Part(Body("1", m1, m1 * 0.36**2 / 2), turning),
            Part(Body("2", 20.0), yoke),
            Part(
                Body("3", 25.0, 25.0 * 0.04**2),
                lambda p: rolling_wheel(yoke(p), (1.0, 0.0), R3, r3, (0.7, -r3)),
            ),
        ),
        (Torque("M", turning, lambda p, d, t: M + 0.0 * p),),
    )


def test_reduced_inertia_is_the_kinetic_energy_formula() -> None:
    m = kulisa_model()
    B = (20.0 + 25.0 * (0.12**2 + 0.04**2) / 0.17**2) * 0.24**2
    assert np.allclose(m.J_pr(PHI), 5.184 + B * np.sin(PHI) ** 2, rtol=1e-14)
    assert np.allclose(m.dJ_pr(PHI), B * np.sin(2 * PHI), rtol=1e-12, atol=1e-14)
    assert np.allclose(m.dJ_pr(PHI), central(m.J_pr, PHI), atol=1e-8)
    terms = m.inertia_terms(0.7)
    assert sum(terms.values()) == pytest.approx(float(m.J_pr(0.7)), rel=1e-15)


def test_reduced_moment_by_equal_power() -> None:
    """A spring on the valve rod: M_pr = F·v_q = −c·x·x_q = −½·c·r²·sin 2φ."""
    r, c = 0.05, 4000.0

    def rod(p: np.ndarray):  # type: ignore[no-untyped-def]
        return slotted_yoke(p, r, math.pi / 2, 0.0).body

    m = ReducedModel(
        (Part(Body("2", 2.0), rod),),
        (Force("F", rod, lambda p, d, t: (0.0 * p, -c * rod(p).y)),),
    )
    assert np.allclose(m.M_pr(PHI), -0.5 * c * r * r * np.sin(2 * PHI), atol=1e-12)


def test_zero_reduced_inertia_is_found_and_named() -> None:
    with pytest.raises(ConstructionError, match=r"zero at φ = 0°"):
        kulisa_model(m1=0.0).check_inertia()
    assert kulisa_model().check_inertia() == pytest.approx(5.184, rel=1e-12)


def test_negative_mass_is_a_parameter_error() -> None:
    with pytest.raises(ParameterError, match=r"m of yoke.*cannot be negative"):
        Body("yoke", -1.0)
    with pytest.raises(ParameterError, match="J of disc"):
        Body("disc", 1.0, -0.1)


# -- energy and solve_ivp ----------------------------------------------------------------------


@pytest.mark.parametrize("phi_deg", [10.0, 90.0, 150.0, 275.0, 700.0])
def test_energy_and_solve_ivp_agree(phi_deg: float) -> None:
    m = kulisa_model()
    phi = math.radians(phi_deg)
    w_e = omega_by_energy(m, 0.0, phi)
    arr = reach(m, 0.0, phi)
    assert arr.omega == pytest.approx(w_e, rel=1e-9)
    assert arr.t == pytest.approx(time_by_energy(m, 0.0, phi), rel=1e-9)
    # the closed form for a constant moment from rest
    assert w_e == pytest.approx(math.sqrt(2 * 34.0 * phi / float(m.J_pr(phi))), rel=1e-12)


def test_the_omega_curve_matches_the_theorem() -> None:
    m = kulisa_model()
    phis = np.linspace(0.0, 2 * math.pi, 37)
    curve = omega_curve(m, 0.0, phis)
    exact = np.sqrt(2 * 34.0 * phis / m.J_pr(phis))
    assert np.allclose(curve, exact, rtol=1e-9, atol=1e-12)


def test_kinetic_energy_plus_potential_is_conserved_on_an_integrated_motion() -> None:
    """The valve without damping: ½·J_pr·φ'² − ∫M_pr dφ stays at its start value."""
    r, c, M0 = 0.05, 4000.0, 2.0

    def rod(p: np.ndarray):  # type: ignore[no-untyped-def]
        return slotted_yoke(p, r, math.pi / 2, 0.0).body

    m = ReducedModel(
        (Part(Body("1", 0.0, 0.05), turning), Part(Body("2", 2.0), rod)),
        (
            Torque("M", turning, lambda p, d, t: M0 + 0.0 * p),
            Force("F", rod, lambda p, d, t: (0.0 * p, -c * rod(p).y)),
        ),
    )
    tr = integrate(m, 0.0, 0.0, 0.6)
    for t in (0.1, 0.3, 0.6):
        phi, w = tr.at(t)
        energy = 0.5 * float(m.J_pr(phi)) * w * w - work(m, 0.0, phi)
        assert abs(energy) < 1e-9
        if phi > 1e-3 and w > 0:
            assert omega_by_energy(m, 0.0, phi) == pytest.approx(w, rel=1e-7)


def test_a_moment_that_cannot_reach_the_position() -> None:
    with pytest.raises(ConstructionError, match="cannot bring the machine to φ = 150°"):
        omega_by_energy(kulisa_model(M=-5.0), 0.0, math.radians(150.0))
    with pytest.raises(ConstructionError, match="does not start"):
        reach(kulisa_model(M=-5.0), 0.0, math.radians(150.0))


def test_a_machine_that_stops_on_the_way() -> None:
    """A spring that wins before φ: the energy method and the integration both say so."""
    r, c = 0.05, 4000.0

    def rod(p: np.ndarray):  # type: ignore[no-untyped-def]
        return slotted_yoke(p, r, math.pi / 2, 0.0).body

    m = ReducedModel(
        (Part(Body("1", 0.0, 0.05), turning), Part(Body("2", 2.0), rod)),
        (
            Torque("M", turning, lambda p, d, t: 1.0 + 0.0 * p),
            Force("F", rod, lambda p, d, t: (0.0 * p, -c * rod(p).y)),
        ),
    )
    with pytest.raises(ConstructionError, match="stops or turns back"):
        omega_by_energy(m, 0.0, math.radians(60.0))
    with pytest.raises(ConstructionError, match="stops at t ="):
        reach(m, 0.0, math.radians(60.0))


def test_the_energy_method_refuses_velocity_dependent_loads() -> None:
    m = ReducedModel(
        (Part(Body("1", 0.0, 1.0), turning),),
        (Torque("damper", turning, lambda p, d, t: -d, positional=False),),
    )
    with pytest.raises(ConstructionError, match="depends on φ' or on t"):
        omega_by_energy(m, 0.0, 1.0)


# -- kinetostatics -----------------------------------------------------------------------------


def test_a_lever_balanced_by_a_force() -> None:
    """A lever turning about O with a moment M: the balancing force at 0.5 m is M/0.5."""
    ks = Kinetostatics("lever")
    ks.body("1")
    ks.torque("1", "M", 10.0)
    ks.joint("R01", None, "1", (0.0, 0.0))
    ks.balancing_force("F", "1", (0.5, 0.0), (0.0, 1.0))
    r = ks.solve()
    assert r.magnitudes["F"] == pytest.approx(-20.0, rel=1e-14)
    assert r.force("R01").y == pytest.approx(20.0, rel=1e-14)
    assert {a.name for a in r.loads["1"]} == {"M", "R01", "F"}


def test_dalembert_loads_enter_the_balance() -> None:
    """A translating block of 2 kg accelerating at 3 m/s² needs 6 N."""
    ks = Kinetostatics("block")
    ks.body("1", m=2.0, centre=(0.0, 0.0), a=(3.0, 0.0))
    ks.balancing_force("F", "1", (0.0, 0.0), (1.0, 0.0))
    ks.contact("N", None, "1", (0.0, 0.0), (0.0, 1.0))
    ks.couple("Mg", None, "1")
    assert ks.solve().magnitudes["F"] == pytest.approx(6.0, rel=1e-14)


def test_a_dead_position_is_indeterminate() -> None:
    """The lever's balancing force along the lever itself has no arm."""
    ks = Kinetostatics("dead")
    ks.body("1")
    ks.torque("1", "M", 10.0)
    ks.joint("R01", None, "1", (0.0, 0.0))
    ks.balancing_force("F", "1", (0.5, 0.0), (1.0, 0.0))
    with pytest.raises(ConstructionError, match="dead position"):
        ks.solve("F_x")


def test_loads_that_cannot_be_balanced() -> None:
    ks = Kinetostatics("no balance")
    ks.body("1")
    ks.torque("1", "M", 10.0)
    ks.joint("R01", None, "1", (0.0, 0.0))
    with pytest.raises(ConstructionError, match="cannot be balanced"):
        ks.solve()


# -- flywheels ---------------------------------------------------------------------------------


def test_flywheel_from_a_load_diagram() -> None:
    E = cycle_work([0.0, 0.03], [282743.0, 0.0])
    assert pytest.approx(282743.0 * 0.015, rel=1e-15) == E
    sp = speeds_from_max(50 * math.pi, 0.1)
    assert sp.omega_min == pytest.approx(50 * math.pi * 19 / 21, rel=1e-15)
    assert (sp.omega_max - sp.omega_min) / sp.omega_mean == pytest.approx(0.1, rel=1e-14)
    J = flywheel_inertia(E, sp)
    assert pytest.approx(E / (0.1 * sp.omega_mean**2), rel=1e-13) == J
    mean = speeds_from_mean(100.0, 0.04)
    assert (mean.omega_max, mean.omega_min) == pytest.approx((102.0, 98.0), rel=1e-15)


@pytest.mark.parametrize(
    ("delta", "words"),
    [(0.0, "must be > 0"), (-0.1, "must be > 0"), (2.0, "must be < 2"), (3.0, "ω_min ≤ 0"),
     (math.nan, "must be > 0")],
)  # fmt: skip
def test_bad_delta(delta: float, words: str) -> None:
    with pytest.raises(ParameterError, match=words):
        speeds_from_max(100.0, delta)


def test_bad_load_diagrams() -> None:
    with pytest.raises(ParameterError, match="ascend"):
        cycle_work([0.0, 0.0], [1.0, 2.0])
    with pytest.raises(ParameterError, match="≥ 2 points"):
        cycle_work([0.0], [1.0])
    with pytest.raises(ParameterError, match="positive"):
        flywheel_inertia(0.0, speeds_from_max(10.0, 0.1))


# -- sheet helpers -----------------------------------------------------------------------------


def test_force_arrow_is_drawn_at_its_scale_and_a_moment_in_its_sense() -> None:
    d = start("A3", TitleBlock(title="t", designation="x"))
    v = d.viewport(Scale(0.01, "l"), (0.0, 0.0), (100.0, 100.0))
    n = len(d.sheet.items)
    tail, tip = force(v, (0.1, 0.0), Vec(30.0, 40.0), 2.5, "F") or ((0, 0), (0, 0))
    assert tail == pytest.approx((110.0, 100.0))
    assert math.dist(tail, tip) == pytest.approx(20.0)  # 50 N at 2.5 N/mm
    assert tip[1] < tail[1]  # up in the model is up on the paper
    assert force(v, (0.0, 0.0), Vec(0.0, 0.0), 1.0) is None
    moment(v, (0.0, 0.0), 5.0, 6.0, "M")
    arcs = [it for it in d.sheet.items[n:] if isinstance(it, ArcItem)]
    assert arcs and arcs[-1].sweep < 0.0  # counter-clockwise on the paper too
    moment(v, (0.0, 0.0), -5.0, 6.0)
    arcs = [it for it in d.sheet.items[n:] if isinstance(it, ArcItem)]
    assert arcs[-1].sweep > 0.0


def test_graph_tick_step_span_and_point_label() -> None:
    d = start("A3", TitleBlock(title="t", designation="x"))
    ax = Axis.fit("φ", "°", 0.0, 360.0, 180.0).with_tick(30.0)
    assert ax.ticks() == [30.0 * i for i in range(13)]
    with pytest.raises(ParameterError, match="tick"):
        ax.with_tick(0.0)
    g = Graph(d, ax, Axis.fit("E", "Дж", 0.0, 100.0, 50.0), (50.0, 150.0))
    n = len(d.sheet.items)
    g.span_y(360.0, 0.0, 100.0, "E")
    line = d.sheet.items[n]
    assert isinstance(line, Polyline)
    assert line.points[0] == pytest.approx(g.p(360.0, 0.0))
    assert line.points[1] == pytest.approx(g.p(360.0, 100.0))
    g.point(90.0, 50.0, "P", prefer=(1.0, -1.0))
    sheet = d.finish()
    assert {"E", "P"} <= {t.text for t in sheet.texts()}
