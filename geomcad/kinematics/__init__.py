"""Kinematics: dyads over arrays of positions, the six-bar, velocity analogues."""

from geomcad.kinematics.dyads import rrp, rrp_velocity, rrr, rrr_velocity
from geomcad.kinematics.sixbar import SixBar, branch_sign, grashof_crank_rocker

__all__ = [
    "SixBar",
    "branch_sign",
    "grashof_crank_rocker",
    "rrp",
    "rrp_velocity",
    "rrr",
    "rrr_velocity",
]
