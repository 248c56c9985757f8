"""All tolerances of the library, in one place.

Tolerances are relative: a length tolerance is a fraction of the figure's size (the caller passes
that size as ``scale``), an angle tolerance is in radians. Raw determinants are never compared
with a bare number: they are first normalised to the sine of an angle or to a length.
"""

from __future__ import annotations

#: Relative length tolerance: two lengths within REL_LENGTH · scale are equal.
REL_LENGTH = 1e-12

#: Angle tolerance in radians: directions closer than this are parallel.
ANGLE = 1e-12

#: Relative tolerance for the tangency case of a line–circle or circle–circle intersection:
#: a discriminant within TANGENT · scale of zero counts as touching (one point).
TANGENT = 1e-10

#: Relative tolerance used by tests and by ``close()`` for derived (not primitive) quantities.
DERIVED = 1e-9

#: Numerical rank of a constraint matrix (structure): singular values below RANK times the largest
#: count as zero. The matrix is scaled so that its entries are of order one.
RANK = 1e-9

#: Root finding on angles (scipy brentq): absolute tolerance in radians.
ROOT_ANGLE = 1e-14


def length_eps(scale: float) -> float:
    """Absolute length tolerance for a figure whose characteristic size is ``scale``."""
    return REL_LENGTH * max(abs(scale), 1.0e-300)


def close(a: float, b: float, rel: float = DERIVED, scale: float | None = None) -> bool:
    """True when ``a`` and ``b`` agree within ``rel`` of ``scale`` (default: the larger of them)."""
    s = max(abs(a), abs(b)) if scale is None else abs(scale)
    return abs(a - b) <= rel * s


#: Integration of an equation of motion (scipy solve_ivp, DOP853): relative and absolute
#: tolerances on the state (φ in rad, φ' in rad/s).
ODE_RTOL = 1e-11
ODE_ATOL = 1e-12

#: Quadrature of a work or a time integral (scipy quad): relative tolerance.
QUAD_REL = 1e-12

#: Conditioning of a kinetostatic system: a singular value below this fraction of the largest
#: one makes the reactions indeterminate (a dead position, a load with no arm).
KINETOSTATIC_RANK = 1e-9

#: The nearest point of a convex zone (scipy SLSQP on a squared distance): the optimiser's
#: function tolerance, relative to the squared size of the figure.
QP_FTOL = 1e-16

#: Relative step of a central difference that estimates a derivative (a Jacobian's entries,
#: for the stiffness of an equation of motion).
DIFF_STEP = 1e-6

#: The flywheel check's integration of the equation of motion (linkage files): relative
#: tolerance on the state (δ is read from it to about 1e-8).
FLYWHEEL_ODE_RTOL = 1.0e-10

#: Bounded minimisation of an angle (scipy minimize_scalar): absolute tolerance in radians.
MIN_ANGLE = 1.0e-12

#: A plan or a load group with nothing to show still gets a scale: its size is taken as at
#: least this fraction (plan units per mm), so a factor can be chosen.
EMPTY_PLAN = 1.0e-12

#: Paper lengths (mm) and layout costs compared after arithmetic: below this they are equal.
SHEET_MM = 1.0e-9

#: The least drawn area (mm²) a view counts with in the layout's score (a log): an empty view.
SHEET_AREA = 1.0e-6

#: A crank angle on a sheet (degrees, or radians) within this of a full turn is the turn's start,
#: so that round-off never writes 360° for 0° nor sorts a cycle's last point before its first.
TURN_START = 1.0e-9

#: Points of a mechanism view nearer than this fraction of the crank's length are at one place
#: (named by one label).
SAME_PLACE = 1.0e-6

#: A layout laid out so far whose leaves overflow by this much (mm) more than the best one's
#: total overflow loses to it whatever the rest adds (the layout score compares overflow rounded
#: to a millionth of a mm, so this is well above round-off).
LAYOUT_BEATEN_MM = 1.0e-3

#: A closed path on a sheet whose enclosed area is under this share of its length squared (and
#: that turns back on itself exactly twice) runs over one curve forth and back: a rocker's joint.
RETRACED_AREA = 1.0e-6
