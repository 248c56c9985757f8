"""A recorded construction replayed on a sheet by its steps' roles (issue 14).

Every step of a :class:`~geomcad.construction.Construction` carries its role on the drawing
(:data:`geomcad.construction.recorder.ROLES`); this module draws the steps from it, so that a
sheet does not draw its construction a second time by hand:

========================  ==========================================================
role                      drawn as
========================  ==========================================================
``given``                 thin lines; points as dots
``construction``          thin lines; points as dots
``result``                thick lines (the result's line); points as marked dots
``link``                  the links' main lines
``extreme``               thin phantom (two-dot) lines
``aux``                   thin dash-dot lines (paths, loci); points as dots
``hidden``                not drawn
========================  ==========================================================

A point is a dot; a line (or a ray) is drawn over the recorded points that lie on it, ``over``
mm beyond the outermost (a line through fewer than two recorded points is clipped to the view's
extent); a segment, a circle and an arc as they are; a tuple of results (the points of
``intersections``, the arcs of ``angle_arcs``) member by member. Points are labelled by their
names (``O1`` → O₁) through the sheet's label placer; a curve only when ``labels`` names it.

:func:`replay` draws into a viewport (inside a view of the sheet's own);
:class:`Replay` is the scaled view that draws nothing else.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

from geomcad import tol
from geomcad.construction.recorder import Construction, Step
from geomcad.geom import Arc, Circle, Line, Ray, Segment, Vec
from geomcad.sheet.compose import Extent, Figure
from geomcad.sheet.drawing import JOINT_R, Viewport
from geomcad.sheet.views import name_markup

#: The sheet role of a line, circle or arc per step role.
STROKE: dict[str, str] = {
    "given": "construction",
    "construction": "construction",
    "result": "result",
    "link": "link",
    "extreme": "extreme",
    "aux": "centre",
}

#: The sheet role of a point's dot per step role.
DOT: dict[str, str] = {
    "given": "point",
    "construction": "point",
    "result": "result",
    "link": "point",
    "extreme": "point",
    "aux": "point",
}

#: Label heights (mm): points and circles, lines.
POINT_H = 3.5
LINE_H = 2.5

#: A step name that is a point's name on the drawing (``O``, ``B0``, ``O1``, ``C1'``).
_POINT_NAME = re.compile(r"[A-Za-z][A-Za-z]?\d*'*")

Labels = Mapping[str, str | Sequence[str]]


def drawn(
    construction: Construction | Iterable[Step], names: Sequence[str] | None = None
) -> list[Step]:
    """The steps a replay draws: ``names`` (in recorded order) or every step whose role is
    drawn (all but ``hidden``)."""
    steps = list(construction)
    if names is not None:
        known = {s.name for s in steps}
        missing = [n for n in names if n not in known]
        if missing:
            raise ValueError(f"no recorded step named {', '.join(map(repr, missing))}")
        return [s for s in steps if s.name in names]
    return [s for s in steps if s.role in STROKE]


def _points(value: Any) -> list[Vec]:
    if isinstance(value, Vec):
        return [value]
    if isinstance(value, tuple):
        return [q for v in value for q in _points(v)]
    return []


def _arc_points(arc: Arc, n: int = 64) -> list[Vec]:
    return [arc.circle.at(arc.start + arc.sweep * i / n) for i in range(n + 1)]


def extent(
    construction: Construction | Iterable[Step], names: Sequence[str] | None = None
) -> Extent:
    """The model box of the bounded items a replay draws (points, segments, circles, arcs;
    lines are clipped to it)."""
    xs: list[float] = []
    ys: list[float] = []

    def add(value: Any) -> None:
        if isinstance(value, Vec):
            xs.append(value.x)
            ys.append(value.y)
        elif isinstance(value, Segment):
            add(value.a)
            add(value.b)
        elif isinstance(value, Circle):
            xs.extend((value.c.x - value.r, value.c.x + value.r))
            ys.extend((value.c.y - value.r, value.c.y + value.r))
        elif isinstance(value, Arc):
            for q in _arc_points(value):
                add(q)
        elif isinstance(value, Ray):
            add(value.origin)
        elif isinstance(value, tuple):
            for v in value:
                add(v)

    for s in drawn(construction, names):
        add(s.result)
    if not xs:
        raise ValueError("the replayed steps hold no bounded item to take an extent from")
    return min(xs), min(ys), max(xs), max(ys)


def _clip(line: Line, box: Extent, t_min: float = -math.inf) -> tuple[float, float] | None:
    """The parameters along ``line`` (from ``t_min``) inside ``box`` (Liang–Barsky)."""
    t0, t1 = t_min, math.inf
    for p, q in (
        (-line.d.x, line.p.x - box[0]),
        (line.d.x, box[2] - line.p.x),
        (-line.d.y, line.p.y - box[1]),
        (line.d.y, box[3] - line.p.y),
    ):
        if p == 0.0:
            if q < 0.0:
                return None
            continue
        r = q / p
        if p < 0.0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
    return (t0, t1) if t0 < t1 else None


def replay(
    v: Viewport,
    construction: Construction | Iterable[Step],
    names: Sequence[str] | None = None,
    labels: Labels | None = None,
    prefer: Mapping[str, tuple[float, float]] | None = None,
    over: float | Mapping[str, float] = 4.0,
    box: Extent | None = None,
    along: Mapping[str, float] | None = None,
) -> None:
    """Draw the steps of ``construction`` (``names`` or every drawn role) into ``v`` by their
    roles (:data:`STROKE`, :data:`DOT`).

    ``labels`` gives a step's label markup ("" for none; a sequence for a tuple result, member
    by member); by default a point whose name is a point's name is labelled with it (``O1`` →
    ``O_1``), other steps not. ``prefer`` gives a label's preferred model direction; ``over``
    (mm, one number or per line) how far a line runs past its outermost recorded point; ``box``
    the model box lines are clipped to when fewer than two recorded points lie on them
    (default: :func:`extent`); ``along`` where a line's label stands, as a fraction of its drawn
    piece from its start (default: the placer's choice of its middle or a quarter from an
    end)."""
    steps = list(construction)
    along = along or {}
    shown = drawn(steps, names)
    labels = labels or {}
    prefer = prefer or {}
    every = [q for s in steps for q in _points(s.result)]
    clip_box = box or extent(steps, names)
    span = max(clip_box[2] - clip_box[0], clip_box[3] - clip_box[1], tol.REL_LENGTH)

    def label(
        step: Step,
        at: Vec,
        i: int,
        height: float,
        default: str = "",
        out: tuple[float, float] | None = None,
        others: Sequence[Vec] = (),
        clear: float = 0.8,
    ) -> None:
        given = labels.get(step.name)
        text = (given if isinstance(given, str) else given[i]) if given is not None else default
        if text:
            pref = prefer.get(step.name, out)
            paper = None if pref is None else v.paper_dir(pref)
            more = tuple(v.p(q) for q in others)
            v.d.label(v.p(at), text, height, paper, clear, others=more)

    for s in shown:
        stroke, dot = STROKE.get(s.role), DOT.get(s.role)
        if stroke is None or dot is None:  # hidden, named all the same
            continue
        items = list(s.result) if isinstance(s.result, tuple) else [s.result]
        for i, item in enumerate(items):
            if isinstance(item, Vec):
                v.dot(item, dot)
                own = name_markup(s.name) if _POINT_NAME.fullmatch(s.name) else ""
                # clear of a joint's circle, as a point named on a mechanism is
                label(s, item, i, POINT_H, own if len(items) == 1 else "", clear=JOINT_R)
            elif isinstance(item, Line | Ray):
                line = item if isinstance(item, Line) else item.line
                ts = sorted(
                    line.param(q)
                    for q in every
                    if abs(line.side(q)) <= tol.DERIVED * span
                    and (isinstance(item, Line) or line.param(q) >= -tol.DERIVED * span)
                )
                if len(ts) >= 2 and ts[-1] - ts[0] > tol.DERIVED * span:
                    mm = over if isinstance(over, float | int) else over.get(s.name, 4.0)
                    extra = v.scale.model(mm)
                    t0, t1 = ts[0] - extra, ts[-1] + extra
                    if isinstance(item, Ray):
                        t0 = max(t0, 0.0)
                else:
                    got = _clip(line, clip_box, 0.0 if isinstance(item, Ray) else -math.inf)
                    if got is None:
                        continue
                    t0, t1 = got
                v.seg(line.at(t0), line.at(t1), stroke)
                f = along.get(s.name)
                if f is not None:
                    label(s, line.at(t0 + f * (t1 - t0)), i, LINE_H)
                else:  # beside the middle, or a quarter from either end
                    q = [line.at(t0 + g * (t1 - t0)) for g in (0.5, 0.3, 0.7)]
                    label(s, q[0], i, LINE_H, others=q[1:])
            elif isinstance(item, Segment):
                v.seg(item.a, item.b, stroke)
                label(s, item.midpoint, i, LINE_H)
            elif isinstance(item, Circle):
                v.circle(item.c, item.r, stroke)
                label(s, item.c + Vec(0.0, item.r), i, POINT_H, out=(0.0, 1.0))
            elif isinstance(item, Arc):
                v.arc(item, stroke)
                mid = item.start + item.sweep / 2.0
                out = (math.cos(mid), math.sin(mid))
                label(s, item.circle.at(mid), i, POINT_H, out=out)


class Replay(Figure):
    """The scaled view of a replayed construction (:func:`replay`): its extent is the drawn
    items' (or ``box``); ``extra(viewport)`` draws more on it after the steps. Keywords of
    :func:`replay`, then those of :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        construction: Construction | Iterable[Step],
        names: Sequence[str] | None = None,
        labels: Labels | None = None,
        prefer: Mapping[str, tuple[float, float]] | None = None,
        over: float | Mapping[str, float] = 4.0,
        box: Extent | None = None,
        along: Mapping[str, float] | None = None,
        extra: Callable[[Viewport], None] | None = None,
        **kw: Any,
    ) -> None:
        steps = list(construction)
        self.steps = steps
        bounds = box or extent(steps, names)

        def draw(v: Viewport) -> None:
            replay(v, steps, names, labels, prefer, over, bounds, along)
            if extra is not None:
                extra(v)

        super().__init__(bounds, draw, **kw)
