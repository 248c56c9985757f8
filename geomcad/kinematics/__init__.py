"""Kinematics: the one sweep kernel of lever mechanisms (:mod:`geomcad.kinematics.chain`), the
six-bar of 2013-6 as a definition on it, dyads over arrays of positions, velocity and
acceleration analogues."""

from geomcad.kinematics.dyads import (
    angular_acceleration,
    angular_velocity,
    rrp,
    rrp_acceleration,
    rrp_velocity,
    rrr,
    rrr_acceleration,
    rrr_velocity,
)
from geomcad.kinematics.sixbar import (
    BLOCK,
    SixBar,
    SweepResult,
    branch_sign,
    grashof_crank_rocker,
)

__all__ = [
    "BLOCK",
    "SixBar",
    "SweepResult",
    "angular_acceleration",
    "angular_velocity",
    "branch_sign",
    "grashof_crank_rocker",
    "rrp",
    "rrp_acceleration",
    "rrp_velocity",
    "rrr",
    "rrr_acceleration",
    "rrr_velocity",
]
