"""Velocities drawn on the mechanism itself: each point's velocity an arrow from the point,
|V|/μ_V millimetres long (on the drawing |V|·μ_l/μ_V metres), named at its tip. A velocity
shorter than two arrowheads cannot be read as an arrow: it is drawn as its lettered end point
(the sheet says so, SHEETS.md). A relative velocity runs from one tip to the other.

Appended for the seed sheets (kulisa-23110713's scheme: V_A, V_A2, V_D, V_C3); any viewport
drawn at a length scale.
"""

from __future__ import annotations

from geomcad.geom import Vec
from geomcad.sheet.drawing import SHORT_MM, Viewport


def tip(v: Viewport, at: Vec, vel: Vec, k_v: float) -> Vec:
    """The tip (model units) of the velocity ``vel`` (m/s) drawn from ``at`` at μ_V = ``k_v``
    ((m/s)/mm) on a drawing at the viewport's length scale."""
    return at + vel * (v.scale.k / k_v)


def vector(v: Viewport, a: Vec, b: Vec, mm: float, role: str) -> None:
    """A vector ``mm`` long on the paper from ``a`` to ``b``: an arrow, or its end point if
    shorter than two arrowheads (:data:`~geomcad.sheet.drawing.SHORT_MM`)."""
    if mm >= SHORT_MM:
        v.arrow(a, b, role)
    else:
        v.dot(b)


def velocity(
    v: Viewport,
    at: Vec,
    vel: Vec,
    k_v: float,
    name: str,
    prefer: tuple[float, float] | None = None,
    role: str = "result",
    height: float = 2.5,
) -> None:
    """The velocity ``vel`` of the point ``at`` at μ_V = ``k_v``, named ``name`` at its tip
    (``prefer``: the side, default along the velocity); nothing for a point at rest."""
    if vel.norm <= 0.0:
        return
    end = tip(v, at, vel, k_v)
    vector(v, at, end, vel.norm / k_v, role)
    v.label(end, name, height, prefer=prefer or (vel.x, vel.y))


def relative(
    v: Viewport,
    at: Vec,
    base: Vec,
    vel: Vec,
    k_v: float,
    name: str,
    prefer: tuple[float, float] = (1.0, 0.0),
    role: str = "construction",
    height: float = 2.5,
) -> None:
    """The relative velocity ``vel − base`` of the point ``at``, from ``base``'s tip to
    ``vel``'s, named beside its middle."""
    rel = vel - base
    if rel.norm <= 0.0:
        return
    a, b = tip(v, at, base, k_v), tip(v, at, vel, k_v)
    vector(v, a, b, rel.norm / k_v, role)
    v.label(0.5 * (a + b), name, height, prefer=prefer)
