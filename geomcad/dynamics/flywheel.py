"""Flywheels: the energy per cycle from a load diagram, the speed fluctuation, the flywheel's J.

Over one cycle of steady motion the flywheel gives up the energy E that the load takes beyond
what the motor supplies meanwhile, and its speed falls from ω_max to ω_min:

    ½·J·(ω_max² − ω_min²) = E,   δ = (ω_max − ω_min)/ω_mean,   ω_mean = (ω_max + ω_min)/2,

so J = 2E/(ω_max² − ω_min²) = E/(δ·ω_mean²).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from geomcad.errors import ParameterError


def cycle_work(s: npt.ArrayLike, F: npt.ArrayLike) -> float:
    """The work of a load diagram F(s): the area under the polyline through (s_i, F_i) (J).

    Exact for a diagram made of straight pieces (trapezoids). The s values must ascend.
    """
    ss = np.asarray(s, dtype=np.float64)
    ff = np.asarray(F, dtype=np.float64)
    if ss.shape != ff.shape or ss.ndim != 1 or len(ss) < 2:
        raise ParameterError(
            "load diagram", ss.shape, "needs two equal-length arrays of ≥ 2 points"
        )
    if not (np.all(np.isfinite(ss)) and np.all(np.isfinite(ff))):
        raise ParameterError("load diagram", "…", "holds a non-finite value")
    if np.any(np.diff(ss) <= 0.0):
        raise ParameterError("load diagram", "s", "the displacements must ascend")
    return float(np.trapezoid(ff, ss))


@dataclass(frozen=True)
class Speeds:
    """The extreme and mean angular velocities of a cycle (rad/s) and δ."""

    omega_max: float
    omega_min: float
    omega_mean: float
    delta: float


def check_delta(delta: float, name: str = "delta") -> None:
    """0 < δ < 2: δ = 0 asks for an infinite flywheel, δ ≥ 2 for ω_min ≤ 0."""
    if not math.isfinite(delta) or delta <= 0.0:
        raise ParameterError(
            name, delta, "the coefficient of speed fluctuation δ must be > 0 (δ = 0 needs an "
            "infinite flywheel: J = E/(δ·ω_mean²))",
        )  # fmt: skip
    if delta >= 2.0:
        raise ParameterError(
            name, delta, "δ must be < 2: δ = 2(ω_max − ω_min)/(ω_max + ω_min) ≥ 2 means "
            "ω_min ≤ 0, the machine would stop or turn back",
        )  # fmt: skip


def speeds_from_max(omega_max: float, delta: float) -> Speeds:
    """The speeds of a cycle whose nominal (largest) speed is ω_max:
    ω_min = ω_max·(2 − δ)/(2 + δ), ω_mean = (ω_max + ω_min)/2."""
    check_delta(delta)
    if not (math.isfinite(omega_max) and omega_max > 0.0):
        raise ParameterError("omega_max", omega_max, "the nominal speed must be positive")
    w_min = omega_max * (2.0 - delta) / (2.0 + delta)
    return Speeds(omega_max, w_min, 0.5 * (omega_max + w_min), delta)


def speeds_from_mean(omega_mean: float, delta: float) -> Speeds:
    """The speeds of a cycle with the mean speed ω_mean: ω_max, ω_min = ω_mean·(1 ± δ/2)."""
    check_delta(delta)
    if not (math.isfinite(omega_mean) and omega_mean > 0.0):
        raise ParameterError("omega_mean", omega_mean, "the mean speed must be positive")
    return Speeds(omega_mean * (1 + delta / 2), omega_mean * (1 - delta / 2), omega_mean, delta)


def flywheel_inertia(E: float, speeds: Speeds) -> float:
    """The flywheel's moment of inertia J = 2E/(ω_max² − ω_min²) (kg·m²) that gives up the
    energy ``E`` (J) while its speed falls from ω_max to ω_min."""
    if not (math.isfinite(E) and E > 0.0):
        raise ParameterError("E", E, "the energy per cycle must be positive")
    return 2.0 * E / (speeds.omega_max**2 - speeds.omega_min**2)
