"""Forces: friction circles, two- and three-force members, force polygons.

The textbook's graphical kinetostatics with friction in revolute joints: the friction circle of a
joint (:func:`friction_circle`), the line of action of a two-force member as a common tangent of
its friction circles (:func:`two_force_line`), a reaction through a point tangent to a friction
circle (:func:`tangent_reaction`), the three-force theorem (:func:`three_force_point`) and force
polygons closed for two unknown magnitudes (:func:`close_polygon`, recorded:
:func:`force_polygon`).
"""

from geomcad.forces.friction import (
    FrictionCircle,
    TwoForceLine,
    friction_angle,
    friction_circle,
    friction_radius,
    tangent_reaction,
    two_force_line,
)
from geomcad.forces.polygon import (
    ForcePolygon,
    Known,
    PlanVector,
    Term,
    Unknown,
    close_polygon,
    closing_lines,
    force_polygon,
    inclination_to_horizontal,
    moment,
    three_force_point,
)

__all__ = [
    "ForcePolygon",
    "FrictionCircle",
    "Known",
    "PlanVector",
    "Term",
    "TwoForceLine",
    "Unknown",
    "close_polygon",
    "closing_lines",
    "force_polygon",
    "friction_angle",
    "friction_circle",
    "friction_radius",
    "inclination_to_horizontal",
    "moment",
    "tangent_reaction",
    "three_force_point",
    "two_force_line",
]
