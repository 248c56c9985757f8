"""Forces and dynamics of a solved linkage, worded as the results of linkages.md.

:func:`analyse` runs the kinetostatics of every result position (where the file gives masses or
loads) and the dynamics (with ``[dynamics]``), once per :class:`Solved`; :func:`add_results`
puts their numbers into the ``results`` object:

- each position: ``R_i_j`` (i < j, the force of link i on link j; magnitude), ``R_i_j_x``,
  ``R_i_j_y``, ``M_bal`` (kinetostatics) and ``M_bal_lever`` (Zhukovsky's lever);
- top level: ``forces_phi_deg``, the crank angle of the force analysis (``[forces] position``
  or ``phi``; default: the first numbered position where the point loads' resistance is
  largest, else where |M_bal| is), and ``forces``, that position's object with its reactions
  and moments; ``I_pr`` and ``M_pr`` over the numbered positions (their crank angles in
  ``dynamics_phi_deg``), ``A_cycle``, ``M_drive``, ``J_flywheel``, ``omega_max``, ``omega_min``,
  and beside them ``delta_achieved`` (the check by the equation of motion) and the flywheel's
  ``D_flywheel``, ``b_flywheel`` (m) and ``m_flywheel`` (kg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from geomcad import tol
from geomcad.construction import Construction
from geomcad.linkage.dynamics import Flywheel, dynamics
from geomcad.linkage.kinetostatics import Forces, kinetostatics
from geomcad.linkage.plans import Position, construct

if TYPE_CHECKING:
    from geomcad.linkage.solution import Solved


@dataclass(frozen=True)
class Analysis:
    """The kinetostatics of each result position (``None`` without masses and loads), the
    dynamics (``None`` without ``[dynamics]``), and the force analysis' position: its crank
    angle's :class:`Position`, its forces and its index among the numbered positions (``None``
    for a ``[forces] phi`` that is none of them)."""

    forces: tuple[Forces, ...] | None
    flywheel: Flywheel | None
    force_position: Position | None = None
    force_forces: Forces | None = None
    force_index: int | None = None

    @property
    def constructions(self) -> list[Construction]:
        out = [f.c for f in self.forces or ()]
        if self.force_forces is not None and all(
            f is not self.force_forces for f in self.forces or ()
        ):
            out.append(self.force_forces.c)
        if self.flywheel is not None:
            out.append(self.flywheel.c)
        return out


def resistance(f: Forces) -> float:
    """The point loads' resistance at a position: the sum of their magnitudes."""
    return sum(
        float(dict(st.args).get("value", 0.0)) for st in f.c.steps if st.kind == "given_force"
    )


def first_largest(xs: list[float]) -> int:
    """The first index whose value is largest, within :data:`~geomcad.tol.DERIVED` of the
    maximum, relative."""
    top = max(xs)
    return next(i for i, x in enumerate(xs) if x >= top - tol.DERIVED * abs(top))


def analyse(s: Solved) -> Analysis:
    """The forces and the dynamics of ``s`` (computed once and kept with it)."""
    kept = getattr(s, "_analysis", None)
    if isinstance(kept, Analysis):
        return kept
    lk = s.linkage
    forces = None
    at: Position | None = None
    at_f: Forces | None = None
    at_k: int | None = None
    if lk.masses or lk.loads:
        forces = tuple(kinetostatics(lk, P, s.cycle) for P in s.positions)
        drawn = s.drawn or s.positions
        if drawn is s.positions:
            numbered_f = forces
        else:
            numbered_f = tuple(kinetostatics(lk, P, s.cycle) for P in drawn)
        if lk.forces_position is not None:
            at_k = lk.forces_position
        elif lk.forces_phi is not None:
            two = 2.0 * math.pi
            at_k = next(
                (
                    k
                    for k, P in enumerate(drawn)
                    if abs(math.remainder(P.phi - lk.forces_phi, two)) <= tol.ANGLE
                ),
                None,
            )
            if at_k is None:
                at = construct(lk, lk.forces_phi)
                at_f = kinetostatics(lk, at, s.cycle)
        else:
            r = [resistance(f) for f in numbered_f]
            if max(r) > 0.0:
                at_k = first_largest(r)
            else:
                at_k = first_largest([abs(f.M_bal) for f in numbered_f])
        if at_k is not None:
            at, at_f = drawn[at_k], numbered_f[at_k]
    fw = None
    if lk.dynamics is not None:
        fw = dynamics(lk, s.cycle, lk.positions)  # N of the numbering: the file's, or 12
    a = Analysis(forces, fw, at, at_f, at_k)
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
    if a.force_position is not None and a.force_forces is not None:
        from geomcad.linkage.solution import position_results

        out["forces_phi_deg"] = round(math.degrees(a.force_position.phi) % 360.0, 10) % 360.0
        row = position_results(s.linkage, a.force_position)
        row.update(position_forces(a.force_forces))
        out["forces"] = row
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
