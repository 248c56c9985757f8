"""A gear train's plan of linear velocities (Smirnov's) and its angle diagram, drawn from the
model of :mod:`geomcad.kinematics.trains` (:class:`~geomcad.kinematics.trains.PlanPoint`,
:class:`~geomcad.kinematics.trains.VelocityPlan`, :class:`~geomcad.kinematics.trains.RayPlan`).

- :func:`linear_velocities` — the plan beside the train's scheme, on the same radii: each
  point's level carried across from the scheme by a thin line, its velocity an arrow from the
  axis v = 0 at μ_V, each link's line through the ends of its points and named past its upper
  end; a velocity shorter than two arrowheads is its end only (returned, for a note);
- :class:`AngleDiagram` — the angle diagram: from the pole S, rays parallel to the links' lines
  cut the line at H above S in segments ω_i/μ_ω, each named (staggered where they would
  collide), H dimensioned, and optionally a ratio read off two intercepts.

Both draw in a viewport at the scheme's k_l whose x is velocity drawn at k_l/k_v
(:func:`at_kl`), so that the plan's levels are the scheme's.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from geomcad.geom import Vec
from geomcad.kinematics.trains import PlanPoint, RayPlan, VelocityPlan
from geomcad.sheet.compose import Extent, Placed, View
from geomcad.sheet.drawing import SHORT_MM, Drawing, Viewport
from geomcad.sheet.model import Polyline
from geomcad.sheet.scale import Scale
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.sheet.views import num

#: Each point's level runs this far (mm) past its velocity's end; each link's line this far
#: past its outermost points.
LEVEL_OVER, LINE_OVER = 3.0, 5.0
#: The axis v = 0 runs this share of the points' span past the outermost ones.
AXIS_OVER = 0.06
#: The angle diagram's line at H runs this share of the rays' span past their ends; its
#: intercepts' names stand ROW_LIFT mm above it, a staggered row ROW_STEP higher.
BASE_OVER, ROW_LIFT, ROW_STEP = 0.02, 2.0, 6.0
#: The ratio stands this share of H under S; the dimension of H this far (mm) beside S.
RATIO_BELOW, H_BESIDE, H_BESIDE_MAX = 0.55, 12.0, 12.0
#: Room (mm) the diagram keeps left of its rays and right of them, and for its rows above.
ROOM_LEFT, ROOM_RIGHT, ROOM_ROW = 20.0, 4.0, 6.5
#: The room a ratio's value takes, for its width.
RATIO_SAMPLE = " = 000,0/00,00 = 00,0"


def at_kl(q: Vec, k_l: float, k_v: float) -> Vec:
    """A plan point (v in m/s, y in m) as a model point of the viewport at k_l: v drawn at
    k_v."""
    return Vec(q.x * k_l / k_v, q.y)


def linear_velocities(
    v_scheme: Viewport,
    vp: Viewport,
    points: Sequence[PlanPoint],
    plan: VelocityPlan,
    kv: Scale,
    spots: Mapping[str, Vec],
    link_label: Mapping[str, str],
    axis_text: str,
) -> list[str]:
    """Draw the plan in ``vp`` (its axis v = 0 at the viewport's x = 0, labelled ``axis_text``)
    beside the scheme drawn in ``v_scheme``, where each point lies at ``spots[name]``; return
    the points whose velocity is shorter than two arrowheads (drawn as their ends only, at
    μ_V, for a note)."""
    short: list[str] = []
    k_l = vp.scale.k
    ys = [p.y for p in points]
    y_min, y_max = min(ys), max(ys)
    pad = AXIS_OVER * (y_max - y_min)

    def P(q: Vec) -> Vec:
        return at_kl(q, k_l, kv.k)

    # the axis v = 0: the line of the fixed link (and of the points at rest)
    vp.seg(Vec(0.0, y_min - pad), Vec(0.0, y_max + pad), "link")
    vp.label(Vec(0.0, y_min - pad), axis_text, 2.5, prefer=(0.0, -1.0), clear=0.0)
    for p in points:
        end = P(plan.ends[p.name])
        level = vp.p(Vec(0.0, p.y))[1]
        # the level of the point carried across from the scheme
        x0 = v_scheme.p(spots[p.name])[0]
        x_end = max(vp.p(end)[0], vp.p(Vec(0.0, p.y))[0]) + LEVEL_OVER
        vp.d.sheet.add(Polyline(((x0, level), (x_end, level)), "construction"))
        length = abs(vp.mm(end.x))
        if length >= SHORT_MM:
            vp.arrow(Vec(0.0, p.y), end, "vector")
        elif length > 0.0:
            short.append(p.name)
        vp.dot(end, "result")
        vp.label(end, p.name.lower(), 3.5, prefer=(1.0 if end.x >= 0 else -1.0, 1.0), clear=0.8)
    # each link's line through the ends of its points, beyond the outermost ones
    for link in plan.order:
        pts = sorted(
            (vp.p(P(plan.ends[p.name])) for p in points if link in p.links), key=lambda q: q[1]
        )
        (xa, ya), (xb, yb) = pts[-1], pts[0]
        length = math.hypot(xb - xa, yb - ya)
        ux, uy = (xb - xa) / length, (yb - ya) / length
        a_ = (xa - LINE_OVER * ux, ya - LINE_OVER * uy)
        b_ = (xb + LINE_OVER * ux, yb + LINE_OVER * uy)
        vp.d.sheet.add(Polyline((a_, b_), "result"))
        # the link's name just past the line's upper end, along the line, off every other line
        vp.d.label(a_, link_label[link], 3.5, prefer=(-ux, -uy), clear=1.0)
    return short


def scaled_rays(rays: RayPlan, k_v: float, k_omega: float) -> RayPlan:
    """The recorded angle diagram enlarged about its pole S so that its pole distance is
    k_v/k_ω (the rays keep their directions, so the intercepts read ω_i at μ_ω = k_ω)."""
    H = k_v / k_omega
    f = H / rays.H
    return RayPlan(rays.S, H, {k: rays.S + (e - rays.S) * f for k, e in rays.ends.items()})


class AngleDiagram(View):
    """The angle diagram of ``rays`` (already at its pole distance k_v/k_ω: :func:`scaled_rays`)
    drawn at k_l with velocities at ``kv`` (see the module's docstring); ``link_label`` names
    each link; ``ratio = (a, b, markup)`` writes ``markup = …`` (e.g. ``u_{1H} = ω_1/ω_H``), the
    quotient of the intercepts of links a and b read off the diagram. Keywords as
    :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        rays: RayPlan,
        k_l: float,
        kv: Scale,
        link_label: Mapping[str, str],
        ratio: tuple[str, str, str] | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.rays, self.k_l, self.kv = rays, k_l, kv
        self.link_label, self.ratio = link_label, ratio

    def extent(self) -> Extent | None:
        """The rays, their labels' rows and the ratio under them (at k_l)."""
        rays, k_l, k_v = self.rays, self.k_l, self.kv.k
        ends = [at_kl(e, k_l, k_v) for e in rays.ends.values()]
        S = at_kl(rays.S, k_l, k_v)
        xs = [e.x for e in ends] + [S.x]
        text = text_box(parse(self.ratio[2] + RATIO_SAMPLE), 3.5)[0] if self.ratio else 0.0
        lo = min(xs) - ROOM_LEFT * k_l
        hi = max(max(xs) + ROOM_RIGHT * k_l, S.x + text * k_l)
        top = S.y + rays.H + 3.0 * ROOM_ROW * k_l
        return (lo, S.y - RATIO_BELOW * rays.H - 3.0 * k_l, hi, top)

    def draw(self, d: Drawing, at: Placed) -> None:
        assert at.viewport is not None
        angle_diagram(at.viewport, self.rays, self.kv, self.link_label, self.ratio)


def angle_diagram(
    v: Viewport,
    rays: RayPlan,
    kv: Scale,
    link_label: Mapping[str, str],
    ratio: tuple[str, str, str] | None = None,
) -> None:
    """Draw the angle diagram of ``rays`` (at its pole distance k_v/k_ω) in ``v`` at k_l with
    velocities at ``kv``: what :class:`AngleDiagram` draws, in any viewport (under a plan)."""
    d = v.d
    k_l = v.scale.k
    ends = {kk: at_kl(e, k_l, kv.k) for kk, e in rays.ends.items()}
    S = at_kl(rays.S, k_l, kv.k)
    xs = [e.x for e in ends.values()] + [S.x]
    lo, hi = min(xs), max(xs)
    h_mm = rays.H / k_l
    width = (hi - lo) / k_l
    base_lo = Vec(lo - BASE_OVER * (hi - lo), S.y + rays.H)
    base_hi = Vec(hi + BASE_OVER * (hi - lo), S.y + rays.H)
    v.seg(base_lo, base_hi, "construction")
    v.seg(S, Vec(S.x, S.y + rays.H), "construction")
    v.dot(S)
    v.label(S, "S", 3.5, prefer=(0.0, -1.0))
    # the intercepts' names above the line, staggered upwards where they would collide
    rows: list[float] = []
    for link, e in sorted(ends.items(), key=lambda kv_: kv_[1].x):
        v.seg(S, e, "result")
        v.dot(e, "result")
        x_mm, y_mm = v.p(e)
        label = link_label[link]
        w = text_box(parse(label), 3.5)[0]
        row = next((i for i, right in enumerate(rows) if right < x_mm - w / 2.0 - 1.0), len(rows))
        if row == len(rows):
            rows.append(0.0)
        rows[row] = x_mm + w / 2.0
        y_text = y_mm - ROW_LIFT - ROW_STEP * row
        if row:
            d.sheet.add(Polyline(((x_mm, y_mm - 0.8), (x_mm, y_text + 1.0)), "dimension"))
        d.text(label, (x_mm, y_text), 3.5, anchor="centre")
    if ratio is not None:
        # the ratio of the two intercepts as read off the diagram: the quotient of the
        # printed segments (4 significant figures), printed to 3 so that the figures agree
        a, b, markup = ratio
        x1, x2 = (float(f"{(rays.ends[kk].x - rays.S.x) / kv.k:.4g}") for kk in (a, b))
        d.text(
            f"{markup} = {num(x1, 4)}/{num(x2, 4)} = {num(x1 / x2, 3)}",
            v.p(Vec(S.x, S.y - RATIO_BELOW * rays.H)),
            3.5,
        )
    beside = min(H_BESIDE_MAX, 0.5 * width) + 4.0
    v.dim_linear(
        S,
        Vec(S.x, S.y + rays.H),
        f"H = {num(h_mm, 4)}",
        offset=-beside if (S.x - lo) > (hi - S.x) else H_BESIDE,
        height=2.5,
    )
