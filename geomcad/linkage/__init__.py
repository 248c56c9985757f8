"""Lever mechanisms of a crank and class-II Assur groups, given as linkage files.

- :mod:`~geomcad.linkage.model`: the file's data checked into a :class:`Linkage`;
- :mod:`~geomcad.linkage.sweep`: positions, velocities, accelerations over arrays of crank angles;
- :mod:`~geomcad.linkage.plans`: the mechanism and its plans at one crank angle, recorded steps;
- :mod:`~geomcad.linkage.cycle`: the output's extremes, stroke, K and the numbered positions.
"""

from __future__ import annotations

from geomcad.linkage.model import Linkage, parse
from geomcad.linkage.sweep import State, sweep

__all__ = ["Linkage", "State", "parse", "sweep"]
