"""The transmission angle of a linkage file (``../shared/linkages.md``) over a full crank turn.

The transmission angle γ of a group is the angle between the force its driving link can pass on
(along a two-force link, or normal to a slide) and the velocity of the point it drives; 90° is
best, and a course project keeps γ ≥ 40° or so over the whole turn. Per group kind, from the
joints' positions the solved file reports (``x_P``, ``y_P``; frame points from ``[frame]``):

- ``RRR`` (links 2 = ends[0]–B, 3 = B–ends[1]): the angle between the two links at B, folded
  into [0°, 90°];
- ``RRP`` (link 4 = end–D, slider at D): 90° less the angle between the rod and the guide
  (a fixed guide's ``angle``; a guide on a moving link: ``from`` → ``toward`` in each position);
- ``RPR`` (block at A sliding on link 3 about C, its slide line at ``offset`` from C):
  90° − arcsin(|offset| / CA);
- ``PRP`` (block in the slot of link 3, which slides on the guide): the slot's angle to the
  guide, folded into [0°, 90°].

A group kind this module does not know is refused with an error that says so, never skipped:
``--min-transmission-deg 0`` turns the check off.

The turn is sampled by solving a copy of the file, reduced to its kinematics (no loads, masses
or flywheel), at :data:`CHECK_POSITIONS` evenly spaced crank positions; a mechanism that cannot
assemble somewhere on the turn fails that solve.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Mapping, Sequence
from typing import Any

from geomcad.errors import GeomcadError

#: Crank positions of the full-turn check (every 5°).
CHECK_POSITIONS = 72

KNOWN_KINDS = ("RRR", "RRP", "RPR", "PRP")


def kinematic_copy(data: Mapping[str, Any], positions: int = CHECK_POSITIONS) -> dict[str, Any]:
    """The file's data reduced to its kinematics, numbered at ``positions`` crank positions."""
    out = copy.deepcopy(dict(data))
    for key in ("load", "links", "dynamics"):
        out.pop(key, None)
    drive = dict(out.get("drive", {}))
    drive.pop("phi", None)
    drive["positions"] = positions
    out["drive"] = drive
    return out


def _fold(deg: float) -> float:
    """An angle between two lines, in [0°, 90°]."""
    a = abs(deg) % 180.0
    return min(a, 180.0 - a)


def _angle_between(u: tuple[float, float], v: tuple[float, float]) -> float:
    return math.degrees(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _sub(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
    return (a[0] - b[0], a[1] - b[1])


class _Points:
    """Positions of named points in one solved position (moving ones) or the frame."""

    def __init__(self, position: Mapping[str, Any], frame: Mapping[str, Any]) -> None:
        self.position = position
        self.frame = frame

    def __call__(self, name: object, group: int) -> tuple[float, float]:
        n = str(name)
        x, y = self.position.get(f"x_{n}"), self.position.get(f"y_{n}")
        if isinstance(x, int | float) and isinstance(y, int | float):
            return (float(x), float(y))
        p = self.frame.get(n)
        if isinstance(p, list | tuple) and len(p) == 2:
            return (float(p[0]), float(p[1]))
        raise GeomcadError(
            f"transmission angle: group {group}: the results give no position of point {n!r}"
        )


def group_angles(data: Mapping[str, Any], position: Mapping[str, Any]) -> list[float]:
    """The transmission angle (degrees, 0…90) of every group of the file in one position."""
    frame = data.get("frame", {})
    pt = _Points(position, frame if isinstance(frame, Mapping) else {})
    groups = data.get("group", [])
    out: list[float] = []
    for i, g in enumerate(groups if isinstance(groups, list) else [], start=1):
        kind = str(g.get("kind", ""))
        if kind == "RRR":
            b = pt(g["joint"], i)
            ends = g["ends"]
            out.append(_fold(_angle_between(_sub(pt(ends[0], i), b), _sub(pt(ends[1], i), b))))
        elif kind == "RRP":
            rod = _sub(pt(g["joint"], i), pt(g["end"], i))
            guide = g.get("guide", {})
            if "link" in guide:
                u = _sub(pt(guide["toward"], i), pt(guide["from"], i))
            else:
                a = math.radians(float(guide.get("angle", 0.0)))
                u = (math.cos(a), math.sin(a))
            out.append(90.0 - _fold(_angle_between(rod, u)))
        elif kind == "RPR":
            ca = math.dist(pt(g["slider"], i), pt(g["pivot"], i))
            off = abs(float(g.get("offset", 0.0)))
            if ca <= off:
                raise GeomcadError(
                    f"transmission angle: group {i} (RPR): the block's joint comes within the "
                    "slide line's offset of the pivot"
                )
            out.append(90.0 - math.degrees(math.asin(off / ca)))
        elif kind == "PRP":
            out.append(_fold(float(g.get("slot_angle", 90.0))))
        else:
            raise GeomcadError(
                f"transmission angle: group {i} is of kind {kind!r}, whose transmission angle "
                f"geomcad variants does not know (it knows {', '.join(KNOWN_KINDS)}); give "
                "--min-transmission-deg 0 to keep such variants without the check"
            )
    return out


def minimum(data: Mapping[str, Any], positions: Sequence[Mapping[str, Any]]) -> float:
    """The smallest transmission angle (degrees) of any group over the solved ``positions``."""
    angles = [a for pos in positions for a in group_angles(data, pos)]
    if not angles:
        raise GeomcadError("transmission angle: the file has no groups to check")
    return min(angles)
