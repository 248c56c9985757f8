"""A plan's vectors too short to be read as arrows at the plan's scale: shorter than two
arrowheads (:data:`~geomcad.sheet.drawing.SHORT_MM`), a plan vector is drawn as its lettered end
point, and the sheet says which ones and how long they are.

Appended for the seed sheets (2013-6's kinematics, kulisa-23110713's velocity plan); any plan.
"""

from __future__ import annotations

from dataclasses import dataclass

from geomcad.kinematics.plan import Plan, PlanVector
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.scale import Scale


@dataclass(frozen=True)
class Short:
    """A short plan vector: the vector, its value (plan units) and its length on the paper."""

    vector: PlanVector
    value: float
    mm: float


def short_vectors(plan: Plan, k: Scale, zero: bool = False) -> list[Short]:
    """The vectors of ``plan`` shorter than two arrowheads at the scale ``k`` (with ``zero``
    the vanishing ones too), in the plan's order."""
    out = []
    for vec in plan.vectors:
        value = (plan.points[vec.head] - plan.points[vec.tail]).norm
        mm = k.mm(value)
        if (zero or mm > 0.0) and mm < SHORT_MM:
            out.append(Short(vec, value, mm))
    return out
