"""Gear trains (geomcad.kinematics.trains): Willis' ratios exactly, coaxiality, the mesh equations,
and Smirnov's plan of linear velocities with its angle diagram."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geomcad.construction import Construction
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import Vec
from geomcad.kinematics.trains import (
    Mesh,
    PlanPoint,
    chain_ratio,
    coaxial_count,
    mobility,
    ray_plan,
    solve_speeds,
    velocity_plan,
    willis,
)


def test_mesh_ratios_and_centre_distances() -> None:
    ext = Mesh("1", 20, "2", 50, "0")
    ring = Mesh("1", 20, "3", 80, "H", internal=True)
    assert ext.ratio() == Fraction(-5, 2)
    assert ring.ratio() == Fraction(4)
    assert ext.centre_distance() == 35
    assert ring.centre_distance() == 30


def test_fixed_axis_train_is_the_product_of_its_stages() -> None:
    u = chain_ratio([Mesh("1", 20, "2", 40, "0"), Mesh("2", 15, "3", 45, "0")])
    assert u == 6  # (−2)(−3)


def test_simple_planetary_by_willis_and_by_the_mesh_equations() -> None:
    """Sun 1, planet 2 on carrier H, fixed ring 3: u_1H^(3) = 1 + z3/z1."""
    z1, z2, z3 = 24, 18, 60
    meshes = [Mesh("1", z1, "2", z2, "H"), Mesh("2", z2, "3", z3, "H", internal=True)]
    u = willis(chain_ratio(meshes))
    assert u == 1 + Fraction(z3, z1)
    w = solve_speeds(meshes, {"3": 0, "1": 1})
    assert 1 / w["H"] == u
    assert w["2"] == w["H"] - (1 - w["H"]) * Fraction(z1, z2)


def test_mobility_of_the_seed_train() -> None:
    assert mobility(5, 5, 4) == 1


COAXIAL = [
    (Fraction(40), 60, False, False, 20),
    (Fraction(24), 26, True, True, 74),
    (Fraction(30), 80, True, False, 20),
]


@pytest.mark.parametrize(("distance", "z_other", "internal", "ring", "z"), COAXIAL)
def test_coaxial_counts(
    distance: Fraction, z_other: int, internal: bool, ring: bool, z: int
) -> None:
    assert coaxial_count("z", distance, z_other, internal, ring) == z


@pytest.mark.parametrize(
    ("distance", "words"),
    [(Fraction(20), r"gives -20 teeth"), (Fraction(30), r"gives 0 teeth"),
     (Fraction(121, 4), r"gives 1/2 teeth")],
)  # fmt: skip
def test_a_coaxial_count_that_is_not_a_positive_integer_is_an_error(
    distance: Fraction, words: str
) -> None:
    with pytest.raises(ConstructionError, match=r'step "z4": it ' + words + ".*whole number ≥ 1"):
        coaxial_count("z4", distance, 60, False)


def test_a_tooth_count_of_zero_is_refused() -> None:
    with pytest.raises(ParameterError, match="z of 1 = 0"):
        Mesh("1", 0, "2", 20, "0")


def test_an_undetermined_train_is_an_error() -> None:
    meshes = [Mesh("1", 20, "2", 30, "H")]
    with pytest.raises(ConstructionError, match="not determined"):
        solve_speeds(meshes, {"1": 1})


def _planetary_plan(z1: int, z2: int) -> tuple[Fraction, float, float]:
    """Sun 1, planet 2 on H, fixed ring 3 (z3 = z1 + 2·z2): Willis, the plan's slope ratio and
    the angle diagram's intercept ratio."""
    z3 = z1 + 2 * z2
    m = 0.002
    r1, r2 = m * z1 / 2, m * z2 / 2
    pts = (
        PlanPoint("O", 0.0, ("0", "1", "H")),
        PlanPoint("A", r1, ("1", "2")),
        PlanPoint("B", r1 + r2, ("2", "H")),
        PlanPoint("C", r1 + 2 * r2, ("2", "0")),
    )
    c = Construction("planetary")
    plan = velocity_plan(c, pts, "0", "1", "A", 1.0)
    rays = ray_plan(c, plan, Vec(0.0, -0.1), 0.05, ("1", "2", "H"))
    u = 1 + Fraction(z3, z1)
    return u, plan.omega["1"] / plan.omega["H"], rays.ratio("1", "H")


@settings(max_examples=40, deadline=None)
@given(st.integers(min_value=12, max_value=60), st.integers(min_value=12, max_value=60))
def test_the_graphical_ratio_equals_willis(z1: int, z2: int) -> None:
    u, by_slopes, by_rays = _planetary_plan(z1, z2)
    assert by_slopes == pytest.approx(float(u), rel=1e-12)
    assert by_rays == pytest.approx(float(u), rel=1e-12)


def test_a_plan_that_does_not_close_names_the_link() -> None:
    pts = (PlanPoint("O", 0.0, ("0", "1")), PlanPoint("A", 0.01, ("1", "2")))
    with pytest.raises(ConstructionError, match=r'step "v\(2\)": fewer than two points'):
        velocity_plan(Construction("open"), pts, "0", "1", "A", 1.0)
