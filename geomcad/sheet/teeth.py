"""Views of one involute tooth cut by the rack, drawn from the gear's model
(:class:`~geomcad.kinematics.gears.SpurGear` and its :class:`~geomcad.kinematics.gears.Flank`).

- :class:`CutTooth` — the tooth at an enlarging scale: its flanks as the rack generates them
  (involute and fillet), the tip land and the root circle in the half spaces either side; the
  circles per GOST 2.402 (tip circle d_a solid thick, pitch circle d dash-dot thin, root circle
  d_f solid thin), the base circle and further construction circles thin, each named with its
  diameter; the producing rack in its central position (two-dot thin) with its datum line shifted
  x·m from the rolling line; optionally a caliper's chord K′K at the height h̄ under the tip T,
  both dimensioned (:class:`Caliper`);
- :class:`ChordInset` — the construction about the centre O for a chord's ends: the axis OT, OK,
  the circles d_b, d_y, d_a, the thread KN tangent to the base circle, and the angles
  ψ_y = ∠TOK, α_y = ∠KON.

The frame is the gear's: O at the origin, the tooth's axis along +y (as
:mod:`geomcad.kinematics.gears` has it). Words from ``strings/<lang>/teeth.toml``.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from geomcad import tol
from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.gears import Flank, SpurGear
from geomcad.sheet.compose import Extent, Placed, View
from geomcad.sheet.drawing import ARROW_LEN, Drawing, Viewport
from geomcad.sheet.lang import Words
from geomcad.sheet.views import num

WORDS = Words(__package__, "teeth")
MM = 1000.0
CENTRE = Vec(0.0, 0.0)  # the gear's centre O
#: The view spans the tooth and this many half pitches about its axis (at most a half turn).
SPAN_PITCHES = 1.3
#: The circles run over this share of the view's half angle (their names at their ends).
CIRCLE_SPAN = 0.97
#: Rack teeth drawn either side of the tooth (they are clipped to the view).
RACK_TEETH = 3
#: Samples of the rack's tip fillet.
FILLET_SAMPLES = 12
#: The caliper's dimensions stand this far (mm) above the tip T and right of K.
CHORD_OVER, HEIGHT_BESIDE = 14.0, 12.0


@dataclass(frozen=True)
class Caliper:
    """A gear-tooth caliper's reading on the tooth: the chord's ends K (right flank) and K′,
    the tip T its stop rests on, and H on the axis at the chord's height (model points)."""

    K: Vec
    K_: Vec
    T: Vec
    H: Vec


def view_half_angle(gear: SpurGear) -> float:
    """Half the angle the tooth view spans about the tooth's axis: the tooth, half a space either
    side, and a little of the circles beyond."""
    return min(SPAN_PITCHES * math.pi / gear.z, math.pi / 2.0)


def tooth_extent(gear: SpurGear) -> Extent:
    """The model box of the tooth view: the tooth with half a space either side, the circles
    a little beyond, down to the lower of the base and root circles, up past the rack's top."""
    half = view_half_angle(gear)
    r_top = max(gear.r_a, gear.r + (gear.x + gear.rack.ha + gear.rack.c) * gear.m)
    r_low = min(gear.r_b, gear.d_f / 2.0)
    w = r_top * math.sin(half)
    pad = 0.35 * gear.m
    return (-w, r_low * math.cos(half) - pad, w, r_top + 1.5 * pad)


def _arc(r: float, half: float) -> Arc:
    """The arc of radius r about O over the view, from the right edge to the left."""
    return Arc(Circle(CENTRE, r), math.pi / 2.0 - half, math.pi / 2.0 + half)


def clip_band(
    pts: list[tuple[float, float]], lo: float, hi: float
) -> list[list[tuple[float, float]]]:
    """The parts of a polyline inside the band lo ≤ x ≤ hi, cut where it crosses its edges."""
    out: list[list[tuple[float, float]]] = []
    cur: list[tuple[float, float]] = []
    for (xa, ya), (xb, yb) in itertools.pairwise(pts):
        ina, inb = lo <= xa <= hi, lo <= xb <= hi
        if ina and not cur:
            cur.append((xa, ya))
        if ina and inb:
            cur.append((xb, yb))
            continue
        for edge in (lo, hi):
            if (xa - edge) * (xb - edge) < 0.0:
                t = (edge - xa) / (xb - xa)
                q = (edge, ya + t * (yb - ya))
                if ina:
                    cur.append(q)
                    out.append(cur)
                    cur = []
                else:
                    cur = [q, (xb, yb)] if inb else []
    if len(cur) > 1:
        out.append(cur)
    return [p for p in out if len(p) > 1]


class CutTooth(View):
    """One tooth of ``gear`` as the rack cuts it (see the module's docstring): ``flank`` its
    right flank (:meth:`SpurGear.flank`), ``circles`` further construction circles as
    (radius, name markup), ``caliper`` a chord to draw and dimension. Keywords as
    :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        gear: SpurGear,
        flank: Flank,
        circles: Sequence[tuple[float, str]] = (),
        caliper: Caliper | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.gear, self.flank = gear, flank
        self.circles = tuple(circles)
        self.caliper = caliper
        self._ext = tooth_extent(gear)

    def extent(self) -> Extent | None:
        return self._ext

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        x0, _y0, x1, _y1 = self._ext
        self._circles(v, view_half_angle(self.gear))
        self._rack(v, x0, x1)
        self._tooth(v)
        if self.caliper is not None:
            self._caliper(v, self.caliper)

    def _circles(self, v: Viewport, half: float) -> None:
        """The gear's circles across the view, labelled at their ends."""
        gear = self.gear
        span = CIRCLE_SPAN * half
        items = [
            (gear.r_a, "link", "d_a", gear.tip_diameter, -1.0),
            (gear.r, "centre", "d", gear.d, 1.0),
            (gear.d_f / 2.0, "thin", "d_f", gear.d_f, 1.0),
            (gear.r_b, "construction", "d_b", gear.d_b, -1.0),
        ]
        items += [(r, "construction", name, 2.0 * r, -1.0) for r, name in self.circles]
        for r, role, name, dia, side in items:
            v.arc(_arc(r, span), role)
            end = Vec.polar(r, math.pi / 2.0 + side * span)
            v.label(end, f"{name} = ⌀{num(dia * MM, 4)}", 2.5, prefer=(-side, 1.0))
        # the tooth's axis
        low = min(gear.r_b, gear.d_f / 2.0) - 0.3 * gear.m
        v.seg(Vec(0.0, low), Vec(0.0, self._ext[3]), "centre")

    def _rack(self, v: Viewport, x_lo: float, x_hi: float) -> None:
        """The producing rack at φ = 0 (its space straddles the tooth), its datum line and the
        shift."""
        gear = self.gear
        m, a = gear.m, gear.alpha
        c0, _y_t, rho, c_x, y_c = gear.rack_frame()
        y_top = gear.r + gear.x * m + (gear.rack.ha + gear.rack.c) * m
        pts: list[tuple[float, float]] = []
        for kk in range(-RACK_TEETH, RACK_TEETH):
            shift = kk * math.pi * m  # tooth centred at π·m/2 + shift
            # left flank from the top down to the fillet, the fillet, the tip, and back up
            # mirrored
            xc = math.pi * m / 2.0 + shift
            top_left = c0 + shift - y_top * math.tan(a)
            b = np.linspace(math.pi + a, 1.5 * math.pi, FILLET_SAMPLES)
            fil = np.stack([c_x + shift + rho * np.cos(b), y_c + rho * np.sin(b)], axis=-1)
            left = [(top_left, y_top), *map(tuple, fil)]
            right = [(2.0 * xc - px, py) for px, py in reversed(left)]
            pts += [(float(px), float(py)) for px, py in left + right]
        for piece in clip_band(pts, x_lo, x_hi):
            v.polyline([Vec(px, py) for px, py in piece], "extreme")
        y_d = gear.r + gear.x * m
        v.seg(Vec(x_lo, y_d), Vec(x_hi, y_d), "centre")
        # the datum line's name right of the x·m dimension (whose text may run past its arrow)
        v.label(Vec(0.7 * x_lo, y_d), WORDS("rack_datum"), 2.5, prefer=(1.0, 1.0))
        v.seg(Vec(x_lo, gear.r), Vec(0.6 * x_lo, gear.r), "centre")
        if abs(gear.x) > tol.DERIVED:  # no shift to dimension for x = 0
            xd = 0.93 * x_lo
            v.dim_linear(
                Vec(xd, gear.r),
                Vec(xd, y_d),
                f"xm = {num(gear.x * m * MM, 4)}",
                offset=6.0,
                height=2.5,
            )

    def _tooth(self, v: Viewport) -> None:
        """The tooth's outline (main line): both flanks, the tip land and the root in the
        spaces."""
        gear, fl = self.gear, self.flank
        right = np.concatenate([fl.involute, fl.fillet[1:]])
        left = right * np.array([-1.0, 1.0])
        v.polyline([Vec(float(px), float(py)) for px, py in right], "link")
        v.polyline([Vec(float(px), float(py)) for px, py in left], "link")
        r_a, r_f = gear.r_a, gear.d_f / 2.0
        up = math.pi / 2.0
        v.arc(Arc(Circle(CENTRE, r_a), up - fl.tip_to, up + fl.tip_to), "link")
        lo, hi = fl.root_from, fl.root_to
        v.arc(Arc(Circle(CENTRE, r_f), up - hi, up - lo), "link")
        v.arc(Arc(Circle(CENTRE, r_f), up + lo, up + hi), "link")

    def _caliper(self, v: Viewport, cal: Caliper) -> None:
        """The caliper's chord K′K, its height below the tip T, and their dimensions."""
        K, K_, T, H = cal.K, cal.K_, cal.T, cal.H
        v.seg(K_, K, "result")
        v.seg(T, H, "result")
        for q in (K, K_, T):
            v.dot(q, "result")
        v.label(K, "K", prefer=(1.0, -1.0), clear=1.0)
        v.label(K_, "K'", prefer=(-1.0, -1.0), clear=1.0)
        v.label(T, "T", prefer=(-1.0, 1.0), clear=1.0)
        rise = v.mm(T.y - K.y)
        s_txt = num(float(K.dist(K_)) * MM, 4)
        v.dim_linear(K_, K, f"s̄ = {s_txt}", offset=rise + CHORD_OVER, height=3.5)
        h_txt = num((T.y - H.y) * MM, 4)
        side = v.mm(K.x) + HEIGHT_BESIDE
        v.dim_linear(T, H, f"h̄ = {h_txt}", offset=side, height=3.5)


#: The inset's arcs run this far (rad) past OT and ON; its box this share of r_a round O, K, N.
INSET_OVER = 0.12
INSET_PAD, INSET_BELOW, INSET_ABOVE = 0.1, 0.06, 1.08
#: The angles' arcs at these shares of the base circle's radius on the paper.
ALPHA_AT, PSI_AT = 0.55, 0.85


class ChordInset(View):
    """The construction about O for a chord's end K on the circle of radius ``r_y`` (see the
    module's docstring): T the tooth's tip on its axis, N the foot of the thread from K on the
    base circle. Keywords as :class:`~geomcad.sheet.compose.View`."""

    def __init__(self, gear: SpurGear, K: Vec, N: Vec, T: Vec, r_y: float, **kw: Any) -> None:
        super().__init__(**kw)
        self.gear, self.K, self.N, self.T, self.r_y = gear, K, N, T, r_y

    def extent(self) -> Extent | None:
        """O, the axis up past the tip, K and N."""
        r_a = self.gear.r_a
        x_lo = min(self.N.x, 0.0) - INSET_PAD * r_a
        x_hi = max(self.K.x, 0.0) + INSET_PAD * r_a
        return (x_lo, -INSET_BELOW * r_a, x_hi, INSET_ABOVE * r_a)

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        gear, K, N, T = self.gear, self.K, self.N, self.T
        a_lo, a_hi = math.pi / 2.0 - INSET_OVER, N.angle + INSET_OVER
        for r, role in ((gear.r_b, "construction"), (self.r_y, "construction"), (gear.r_a, "link")):
            v.arc(Arc(Circle(CENTRE, r), a_lo, a_hi), role)
        v.seg(CENTRE, T, "centre")
        v.seg(CENTRE, K, "construction")
        v.seg(CENTRE, N, "construction")
        v.seg(K, N, "result")
        v.dot(CENTRE)
        for q in (K, N, T):
            v.dot(q, "result")
        v.label(CENTRE, "O", 3.5, prefer=(1.0, -1.0), clear=1.5)
        v.label(K, "K", 2.5, prefer=(1.0, 0.0))
        v.label(N, "N", 2.5, prefer=(-1.0, 0.0))
        v.label(T, "T", 2.5, prefer=(-1.0, 1.0))
        v.dim_angle(CENTRE, N, K, "α_y", r_mm=ALPHA_AT * v.mm(gear.r_b), height=2.5)
        small_angle(v, CENTRE, K, T, "ψ_y", PSI_AT * v.mm(gear.r_b))


def small_angle(v: Viewport, vertex: Vec, p1: Vec, p2: Vec, text: str, r_mm: float) -> None:
    """An angle too small for arrows inside its arc: the arc, and two arrows outside it pointing
    at its ends (GOST 2.307)."""
    a1, a2 = (p1 - vertex).angle, (p2 - vertex).angle
    lo, hi = min(a1, a2), max(a1, a2)
    r = v.scale.model(r_mm)
    v.arc(Arc(Circle(vertex, r), lo, hi), "dimension")
    step = 2.2 * ARROW_LEN / r_mm  # arrows outside the arc, each over two heads long
    for a_end, a_out in ((lo, lo - step), (hi, hi + step)):
        v.arrow(vertex + Vec.polar(r, a_out), vertex + Vec.polar(r, a_end), "dimension")
    v.label(vertex + Vec.polar(r, hi + step), text, 2.5, prefer=(-1.0, 0.0))
