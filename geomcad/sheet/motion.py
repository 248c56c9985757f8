"""A mechanism in motion (:class:`Frames`): its points frame by frame over one crank turn.

Model units (m, m/s, rad). This is what an animation draws (:mod:`geomcad.render.animate`),
and all it needs: any mechanism, a problem's or a linkage file's, gives its sweep as named point
positions per frame and says which points its links join. Nothing here knows a particular
mechanism.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from geomcad.errors import ParameterError

Arr = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Frames:
    """Named points of a mechanism at N frames of one crank turn (SI: m, m/s, rad).

    - ``points``: name → ``(N, 2)`` positions (m). A point on the frame has the same row in
      every frame.
    - ``links``: each a chain of point names drawn as one line (a link with three joints is a
      closed chain of three); ``closed`` chains are the names listed in ``closed_links``.
    - ``fixed``: points on the frame, drawn as supports; ``sliders``: name → the unit direction
      of its guide (the block is drawn along it); ``guides``: fixed lines, each two model points.
    - ``discs``: name → radii (m) of circles drawn about that point as it moves (a flywheel, a
      roller and its hub).
    - ``traced``: the points whose paths over the turn are drawn.
    - ``joints``: the points drawn as revolute joints (default: every point a link names);
      ``labelled``: the points whose names are written by them (default: all).
    - ``velocities``: name → ``(N, 2)`` velocities (m/s) at crank speed ``omega1`` (rad/s): the
      velocity plan's vectors from its pole, its points named in lower case; ``plan_edges``: the
      relative velocities drawn between two plan points (ab = V_BA).
    - ``phi``: the crank angle of each frame (rad).
    """

    title: str
    phi: Arr
    points: Mapping[str, Arr]
    links: tuple[tuple[str, ...], ...]
    fixed: tuple[str, ...] = ()
    traced: tuple[str, ...] = ()
    sliders: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    guides: tuple[tuple[tuple[float, float], tuple[float, float]], ...] = ()
    closed_links: tuple[int, ...] = ()
    discs: Mapping[str, tuple[float, ...]] = field(default_factory=dict)
    joints: tuple[str, ...] | None = None
    labelled: tuple[str, ...] | None = None
    velocities: Mapping[str, Arr] = field(default_factory=dict)
    plan_edges: tuple[tuple[str, str], ...] = ()
    omega1: float = 1.0

    def __post_init__(self) -> None:
        n = self.frames
        if n < 2:
            raise ParameterError("frames", n, "an animation needs at least 2 frames")
        for kind, table in (("point", self.points), ("velocity", self.velocities)):
            for name, arr in table.items():
                if arr.shape != (n, 2):
                    raise ValueError(f"{kind} {name!r} has shape {arr.shape}, not ({n}, 2)")
                if not np.all(np.isfinite(arr)):
                    raise ValueError(f"{kind} {name!r} is not finite in every frame")
        named = set(self.points)
        for chain in self.links:
            missing = [p for p in chain if p not in named]
            if missing or len(chain) < 2:
                raise ValueError(f"link {chain!r} names no such point {missing!r}")
        extra = (*(self.joints or ()), *(self.labelled or ()))
        for name in (*self.fixed, *self.traced, *self.sliders, *self.discs, *extra):
            if name not in named:
                raise ValueError(f"no point {name!r} in the motion")
        for a, b in self.plan_edges:
            if a not in self.velocities or b not in self.velocities:
                raise ValueError(f"plan edge {a}{b} names a point without a velocity")
        if not (math.isfinite(self.omega1) and self.omega1 != 0.0):
            raise ParameterError("omega1", self.omega1, "the crank must turn")

    @property
    def frames(self) -> int:
        return int(self.phi.shape[0])

    def extent(self) -> tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) of every point in every frame and of the guides (m)."""
        xs = [a[:, 0] for a in self.points.values()]
        ys = [a[:, 1] for a in self.points.values()]
        for name, radii in self.discs.items():
            r = max(radii, default=0.0)
            xs += [self.points[name][:, 0] - r, self.points[name][:, 0] + r]
            ys += [self.points[name][:, 1] - r, self.points[name][:, 1] + r]
        for g in self.guides:
            xs.append(np.array([g[0][0], g[1][0]]))
            ys.append(np.array([g[0][1], g[1][1]]))
        x, y = np.concatenate(xs), np.concatenate(ys)
        return float(x.min()), float(y.min()), float(x.max()), float(y.max())


def turn(frames: int, start: float = 0.0, sense: float = 1.0) -> Arr:
    """``frames`` crank angles over one turn from ``start`` (rad), the last one short of a full
    turn so that the animation loops without a repeated frame; ``sense`` −1 turns clockwise."""
    if not 2 <= frames <= MAX_FRAMES:
        raise ParameterError("--frames", frames, f"must be a whole number from 2 to {MAX_FRAMES}")
    step = math.copysign(2.0 * math.pi / frames, sense)
    return np.asarray(start + step * np.arange(frames, dtype=np.float64), dtype=np.float64)


#: The most frames an animation may have (a 1° step is 360; beyond a few thousand only the file
#: grows).
MAX_FRAMES = 3600
