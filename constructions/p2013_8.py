"""2013-8 · Punch-press motor and flywheel.

A press punches holes of diameter d in a plate of thickness h (shear strength τ), z holes a second;
the motor runs at n rpm with the speed fluctuation δ. Find the motor's power and the flywheel.

The model:
- the shear area is π·d·(h − s) after the punch has gone s into the plate, so the force falls
  linearly from F_max = π·d·h·τ at s = 0 to zero at s = h (the seed says "increases": the same
  triangle, mirrored, with the same area);
- the work of one hole is the area of that load diagram, E = F_max·h/2 (the seed's text lost this
  formula; it is restored here and computed as the diagram's area);
- the motor supplies E once per cycle of 1/z s: N = E·z;
- the nominal speed is the largest, ω_max = π·n/30; δ = (ω_max − ω_min)/ω_mean with
  ω_mean = (ω_max + ω_min)/2, so ω_min = ω_max·(2 − δ)/(2 + δ) (19/21·ω_max for δ = 0.1);
- the flywheel gives up E while its speed falls from ω_max to ω_min:
  J = 2E/(ω_max² − ω_min²).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad.construction import Construction
from geomcad.dynamics import cycle_work, flywheel_inertia, speeds_from_max
from geomcad.problem import Build, ParamValue

NOTES = [
    "restored: the seed's text lost the energy formula; the work of one hole is the area of the "
    "load diagram, E = F_max·h/2",
]


@dataclass(frozen=True)
class Data:
    """What the sheet draws: the load diagram and the cycle's energy balance."""

    s: np.ndarray
    F: np.ndarray
    E: float
    cycle: float  # s
    N: float
    omega_max: float
    omega_min: float
    omega_mean: float
    J: float


def build(p: Mapping[str, ParamValue]) -> Build[Data]:
    """The load diagram, its area, the motor's power and the flywheel, as recorded steps."""
    d, h, tau = float(p["d_hole"]), float(p["h_plate"]), float(p["tau"])
    n, delta, z = float(p["n_rpm"]), float(p["delta"]), float(p["holes_per_s"])
    c = Construction("2013-8: punch press, the work of a hole and the flywheel")
    f_max = math.pi * d * h * tau
    # each step's kind and operands: the sheet's solution is written from them
    c.value("F_max", f_max, "π·d·h·τ: the shear area π·d·h times τ", kind="shear_force",
            args={"F_kN": f_max / 1000.0})  # fmt: skip
    s = np.array([0.0, h])
    F = np.array([f_max, 0.0])
    c.record("F(s)", "load diagram: F falls linearly from F_max at s = 0 to 0 at s = h", (s, F))
    E = cycle_work(s, F)
    c.value("E", E, "area under F(s) (= F_max·h/2)", ("F(s)",), kind="work_of_hole", args={"E": E})
    N = c.value("N", E * z, "E·z: the motor supplies E once per cycle of 1/z s",
                kind="motor_power", args={"N": E * z})  # fmt: skip
    w_nom = math.pi * n / 30.0
    sp = speeds_from_max(w_nom, delta)
    c.value("ω_max", sp.omega_max, "π·n/30 (the nominal speed is the largest)",
            kind="nominal_speed", args={"w": sp.omega_max})  # fmt: skip
    c.value("ω_min", sp.omega_min, "ω_max·(2 − δ)/(2 + δ), from δ = (ω_max − ω_min)/ω_mean",
            kind="least_speed", args={"w": sp.omega_min})  # fmt: skip
    J = flywheel_inertia(E, sp)
    c.value("J", J, "2E/(ω_max² − ω_min²): ½J(ω_max² − ω_min²) = E", kind="flywheel_inertia",
            args={"J": J})  # fmt: skip
    results: dict[str, Any] = {
        "F_max": f_max,
        "E": E,
        "N": N,
        "omega_max": sp.omega_max,
        "omega_min": sp.omega_min,
        "J": J,
    }
    data = Data(s, F, E, 1.0 / z, N, sp.omega_max, sp.omega_min, sp.omega_mean, J)
    return Build(results, c, list(NOTES), data=data)
