"""Forces and dynamics of a solved linkage, worded as the results of linkages.md.

:func:`analyse` runs the kinetostatics of every result position (where the file gives masses or
loads) and the dynamics (with ``[dynamics]``), once per :class:`Solved`; :func:`add_results`
puts their numbers into the ``results`` object:

- each position: ``R_i_j`` (i < j, the force of link i on link j; magnitude), ``R_i_j_x``,
  ``R_i_j_y``, ``M_bal`` (kinetostatics) and ``M_bal_lever`` (Zhukovsky's lever);
- top level: ``I_pr`` and ``M_pr`` over the numbered positions (their crank angles in
  ``dynamics_phi_deg``), ``A_cycle``, ``M_drive``, ``J_flywheel``, ``omega_max``, ``omega_min``,
  and beside them ``delta_achieved`` (the check by the equation of motion) and the flywheel's
  ``D_flywheel``, ``b_flywheel`` (m) and ``m_flywheel`` (kg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from geomcad.construction import Construction
from geomcad.linkage.dynamics import Flywheel, dynamics
from geomcad.linkage.kinetostatics import Forces, kinetostatics

if TYPE_CHECKING:
    from geomcad.linkage.solution import Solved


@dataclass(frozen=True)
class Analysis:
    """The kinetostatics of each result position (``None`` without masses and loads) and the
    dynamics (``None`` without ``[dynamics]``)."""

    forces: tuple[Forces, ...] | None
    flywheel: Flywheel | None

    @property
    def constructions(self) -> list[Construction]:
        out = [f.c for f in self.forces or ()]
        if self.flywheel is not None:
            out.append(self.flywheel.c)
        return out


def analyse(s: Solved) -> Analysis:
    """The forces and the dynamics of ``s`` (computed once and kept with it)."""
    kept = getattr(s, "_analysis", None)
    if isinstance(kept, Analysis):
        return kept
    lk = s.linkage
    forces = None
    if lk.masses or lk.loads:
        forces = tuple(kinetostatics(lk, P, s.cycle) for P in s.positions)
    fw = None
    if lk.dynamics is not None:
        fw = dynamics(lk, s.cycle, lk.positions)  # N of the numbering: the file's, or 12
    a = Analysis(forces, fw)
    object.__setattr__(s, "_analysis", a)
    return a


def position_forces(f: Forces) -> dict[str, float]:
    """One position's force results."""
    out: dict[str, float] = {}
    for i, j in f.pairs:
        R = f.R(i, j)
        out[f"R_{i}_{j}"] = math.hypot(R.x, R.y)
        out[f"R_{i}_{j}_x"] = R.x
        out[f"R_{i}_{j}_y"] = R.y
    out["M_bal"] = f.M_bal
    out["M_bal_lever"] = f.lever.M_bal
    return out


def add_results(s: Solved, out: dict[str, Any]) -> None:
    """Add the forces and the dynamics to ``out``, the ``results`` of :func:`results`."""
    a = analyse(s)
    if a.forces is not None:
        for row, f in zip(out["positions"], a.forces, strict=True):
            row.update(position_forces(f))
    fw = a.flywheel
    if fw is not None:
        out["dynamics_phi_deg"] = [math.degrees(p) % 360.0 for p in fw.phis]
        out["I_pr"] = fw.I_pr
        out["M_pr"] = fw.M_pr
        out["A_cycle"] = fw.A_cycle
        out["M_drive"] = fw.M_drive
        out["J_flywheel"] = fw.J_flywheel
        out["omega_max"] = fw.omega_max
        out["omega_min"] = fw.omega_min
        out["delta_achieved"] = fw.delta_achieved
        out["D_flywheel"] = fw.D
        out["b_flywheel"] = fw.b
        out["m_flywheel"] = fw.mass
