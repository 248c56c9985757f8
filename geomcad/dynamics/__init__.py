"""Machine dynamics: the model reduced to the driving link, its motion, kinetostatics, flywheels.

- :mod:`~geomcad.dynamics.analogues`: velocity and acceleration analogues of small mechanisms
  (to be switched to the general velocity-plan solver when it lands);
- :mod:`~geomcad.dynamics.model`: J_pr(φ), dJ_pr/dφ, M_pr by equal power, the equation of motion;
- :mod:`~geomcad.dynamics.motion`: ω by the kinetic-energy theorem and by ``solve_ivp``;
- :mod:`~geomcad.dynamics.kinetostatics`: d'Alembert loads, reactions, balancing loads;
- :mod:`~geomcad.dynamics.flywheel`: energy per cycle, δ and the flywheel's J.
"""

from geomcad.dynamics.analogues import (
    Motion,
    Yoke,
    crank_point,
    rolling_wheel,
    slotted_yoke,
    turning,
)
from geomcad.dynamics.flywheel import (
    Speeds,
    check_delta,
    cycle_work,
    flywheel_inertia,
    speeds_from_max,
    speeds_from_mean,
)
from geomcad.dynamics.kinetostatics import Applied, Kinetostatics, Reactions
from geomcad.dynamics.model import Body, Force, Part, ReducedModel, Torque
from geomcad.dynamics.motion import (
    Arrival,
    Trajectory,
    integrate,
    ode_settings,
    omega_by_energy,
    omega_curve,
    reach,
    time_by_energy,
    work,
)

__all__ = [
    "Applied",
    "Arrival",
    "Body",
    "Force",
    "Kinetostatics",
    "Motion",
    "Part",
    "Reactions",
    "ReducedModel",
    "Speeds",
    "Torque",
    "Trajectory",
    "Yoke",
    "check_delta",
    "crank_point",
    "cycle_work",
    "flywheel_inertia",
    "integrate",
    "ode_settings",
    "omega_by_energy",
    "omega_curve",
    "reach",
    "rolling_wheel",
    "slotted_yoke",
    "speeds_from_max",
    "speeds_from_mean",
    "time_by_energy",
    "turning",
    "work",
]
