"""Views of a translating cam mechanism drawn from its model (:mod:`geomcad.kinematics.cams`).

- :class:`Inversion` — the cam profile by inversion: the base circle (a roller's prime circle
  and the working profile's base circle), the follower turned back to each division point (its
  axis and its face, or its tip, or its roller), the profile, the radius vectors r_i written on
  them, the angle of one interval, the sense −ω of the inversion; the rest of the program past
  the span in thin lines, so that the cam's shape is seen whole;
- :class:`CamAt` — the mechanism at one position in the fixed frame: the cam turned to φ (the
  built profile thick, the rest thin), its support and ω, the follower with its stem and guide,
  the links numbered, and the triangle OBB′ similar to the velocity plan (OB′ = S′; C and
  BC = S′ for a flat face), from a :class:`~geomcad.kinematics.cams.VelocityPlan`.

Both take model data only (the follower, the profiles, the plan); their words come from
``strings/<lang>/cams.toml``, the numbers in the language being drawn.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.cams import CamProfile, Follower, VelocityPlan, evert
from geomcad.sheet.compose import Extent, Placed, View
from geomcad.sheet.drawing import ARROW_LEN, Drawing, Viewport
from geomcad.sheet.lang import Words
from geomcad.sheet.views import num

WORDS = Words(__package__, "cams")
MM = 1000.0
#: Division points closer than this on the paper (mm) are not all labelled.
LABEL_APART = 5.0
#: The face lines run this far (paper mm) past the contact point and the follower's axis.
FACE_OVER = 6.0
#: Label every division point up to this many of them, else every second, third …
LABELS_AT_MOST = 13
#: The sense −ω of the inversion: an arc about O at this fraction of r0, between these angles
#: (degrees, counter-clockwise from x), clear of the follower's axes near φ = 0.
INVERSION_ARC = (0.55, 125.0, 165.0)
#: The cam's ω on :class:`CamAt`: an arc about O under it of at least this radius (mm; or
#: OMEGA_R0 of r0), over these angles (degrees) on the side away from B′ (left, right).
OMEGA_MM, OMEGA_R0 = 13.0, 0.35
OMEGA_SPAN = {-1: (200.0, 290.0), 1: (250.0, 340.0)}


def label_step(n: int) -> int:
    """Label every division point up to :data:`LABELS_AT_MOST` of them, else every second,
    third …"""
    return max(1, math.ceil(n / LABELS_AT_MOST))


def turn_arrow(v: Viewport, r: float, a0_deg: float, a1_deg: float, sense: int, text: str) -> None:
    """An arc about O of radius ``r`` (model) from a0 to a1 (degrees, counter-clockwise) with an
    arrowhead at the end the ``sense`` (+1 counter-clockwise) points to, and its label."""
    a0, a1 = math.radians(a0_deg), math.radians(a1_deg)
    v.arc(Arc(Circle(Vec(0.0, 0.0), r), a0, a1), "dimension")
    chord = 2.2 * ARROW_LEN / v.mm(r)  # the head's arc: more than two arrowheads long
    end, before = (a1, a1 - chord) if sense > 0 else (a0, a0 + chord)
    v.arrow(Vec.polar(r, before), Vec.polar(r, end), "dimension")
    mid = (a0 + a1) / 2.0
    v.label(Vec.polar(r, mid), text, height=3.5, prefer=(math.cos(mid), math.sin(mid)), clear=0.5)


class Inversion(View):
    """The profile of a translating cam by inversion (see the module's docstring): ``profile``
    the built profile (``closed`` for a full turn), ``divisions`` its division points,
    ``rest`` the profile on to the program's end (thin, with the axis at its end labelled
    ``rest_text``). Keywords as :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        follower: Follower,
        profile: CamProfile,
        divisions: CamProfile,
        closed: bool = False,
        rest: CamProfile | None = None,
        rest_text: str = "",
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.f, self.profile, self.div = follower, profile, divisions
        self.closed, self.rest, self.rest_text = closed, rest, rest_text
        self._ext = self._extent()

    def extent(self) -> Extent | None:
        return self._ext

    def _extent(self) -> Extent:
        """The base circle, the profile (and the rest of the program), the division points."""
        f = self.f
        parts = [self.profile.contact, self.div.pitch, self.div.contact, self.profile.pitch]
        if self.rest is not None:
            parts += [self.rest.contact, self.rest.pitch]
        pts = np.vstack(parts)
        ext = f.r_roller if f.kind == "roller" else 0.0
        xs = [float(pts[:, 0].min()) - ext, float(pts[:, 0].max()) + ext, -f.r0, f.r0]
        ys = [float(pts[:, 1].min()) - ext, float(pts[:, 1].max()) + ext, -f.r0, f.r0]
        return min(xs), min(ys), max(xs), max(ys)

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        f, div = self.f, self.div
        k = v.scale
        o = Vec(0.0, 0.0)
        # the theoretical profile's base circle r0 (for a roller its prime circle, dash-dot, and
        # the working profile's base circle r0 − r_roller)
        v.circle(o, f.r0, "centre" if f.kind == "roller" else "construction")
        if f.kind == "roller":
            v.circle(o, f.base_radius, "construction")
        v.centre_cross(o, 6.0)
        over = k.model(FACE_OVER)
        n = len(div.phi)
        if n > 1 and math.isclose(float(div.phi[-1] - div.phi[0]), 2.0 * math.pi):
            n -= 1  # the last point of a full turn is the first one again
        shown = self._labelled(v, n)
        for i in range(n):
            turn = -f.sigma * float(div.phi[i])
            up = Vec(0.0, 1.0).rotated(turn)
            across = Vec(1.0, 0.0).rotated(turn)
            C = Vec(*div.pitch[i])
            B = Vec(*div.contact[i])
            # the follower's axis turned back by φ_i (for the flat face the line through O along
            # the motion, on which C_i lies), from O or its foot on the circle of radius e to
            # past C_i
            foot = across * f.e if f.kind != "flat" else o
            tip = C + up * over
            v.seg(foot, tip, "construction")
            if i in shown:
                v.label(tip, str(i), height=2.5, prefer=(up.x, up.y), clear=0.5)
            if f.kind == "flat":
                t_b = (B - C).dot(across)
                lo, hi = min(0.0, t_b) - over, max(0.0, t_b) + over
                v.seg(C + across * lo, C + across * hi, "construction")
            elif f.kind == "roller":
                v.circle(C, f.r_roller, "construction")
            v.dot(C, "point")
            # the radius vector r_i = OB_i: a thin construction line (its length is written on it)
            v.seg(o, B, "construction")
            if i in shown:
                v.label(B, f"B_{{{i}}}", height=2.5, prefer=(up.x, up.y))
        if f.kind != "flat" and f.e != 0.0:
            v.circle(o, abs(f.e), "centre")
        if f.kind == "roller":
            v.polyline(list(self.profile.pitch), "centre", closed=self.closed)
        v.polyline(list(self.profile.contact), "link", closed=self.closed)
        if self.rest is not None:
            self._rest(v, self.rest, over)
        v.label(o, "O", prefer=(-1.0, -1.0), clear=1.0)
        # the inversion: the follower turns about O against the cam's rotation
        share, a0, a1 = INVERSION_ARC
        turn_arrow(v, share * f.r0, a0, a1, -f.sigma, WORDS("minus_omega"))
        # the radius vectors' lengths, written along them
        for i in sorted(shown):
            B = Vec(*div.contact[i])
            text = f"r_{{{i}}} = {num(float(div.radius[i]) * MM)}"
            spots = tuple(v.p(B * t) for t in (0.6, 0.8, 0.5, 0.9, 0.4))
            v.d.label(v.p(B * 0.7), text, 2.5, others=spots)
        # the angle of one interval, between the last two axes
        if n >= 2:
            e0 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-2]))
            e1 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-1]))
            dphi = math.degrees(float(div.phi[-1] - div.phi[-2]))
            v.dim_angle(o, e0, e1, f"{num(dphi)}°", r_mm=k.mm(f.r0) * share, height=2.5)

    def _rest(self, v: Viewport, rest: CamProfile, over: float) -> None:
        """The profile past the span to the program's end in thin lines, with the follower's
        axis at the end (thin) and the words where the program ends."""
        f = self.f
        if f.kind == "roller":
            v.polyline(list(rest.pitch), "centre")
        v.polyline(list(rest.contact), "thin")
        end = float(rest.phi[-1])
        up = Vec(0.0, 1.0).rotated(-f.sigma * end)
        foot = Vec(1.0, 0.0).rotated(-f.sigma * end) * (f.e if f.kind != "flat" else 0.0)
        C = Vec(*rest.pitch[-1])
        v.seg(foot, C + up * over, "construction")
        v.label(C + up * over, self.rest_text, 2.5, prefer=(up.x, up.y), clear=0.5)

    def _labelled(self, v: Viewport, n: int) -> set[int]:
        """The division points that get labels: every :func:`label_step`-th one, and of those
        only points at least LABEL_APART mm on the paper from the ones already taken (the last
        one is preferred to its neighbour)."""
        div = self.div
        step = label_step(n)
        want = [i for i in range(n) if i % step == 0 or i == n - 1]
        taken: list[int] = []
        for i in [want[-1], *want[:-1]] if len(want) > 1 else want:
            q = v.p(div.contact[i])
            if all(math.dist(q, v.p(div.contact[j])) >= LABEL_APART for j in taken):
                taken.append(i)
        return set(taken)


class CamAt(View):
    """A translating cam mechanism at the position of ``plan`` (see the module's docstring):
    ``profile`` the built profile (``closed`` for a full turn), ``rest`` the profile on to the
    program's end (thin). Keywords as :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        follower: Follower,
        profile: CamProfile,
        plan: VelocityPlan,
        closed: bool = False,
        rest: CamProfile | None = None,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.f, self.profile, self.plan = follower, profile, plan
        self.closed, self.rest = closed, rest
        self._ext = self._extent()

    def cam_now(self) -> tuple[np.ndarray, np.ndarray]:
        """The cam's built profile and the rest of the program, turned to the plan's φ."""
        f, phi = self.f, self.plan.phi
        cam = evert(self.profile.contact, np.full(len(self.profile.phi), phi), f.sigma)
        rest = (
            evert(self.rest.contact, np.full(len(self.rest.phi), phi), f.sigma)
            if self.rest is not None
            else np.zeros((0, 2))
        )
        return cam, rest

    def follower_size(self) -> tuple[float, float, float]:
        """The face's half width, the stem's base (the face, the knife's tip or the roller's
        top) and the stem's length, in model units."""
        f = self.f
        width = float(np.max(np.abs(self.profile.S1))) + 0.2 * f.r0
        base = float(self.plan.B.y) + (f.r_roller if f.kind == "roller" else 0.0)
        return width, base, 0.35 * f.r0

    def extent(self) -> Extent | None:
        return self._ext

    def _extent(self) -> Extent:
        """The cam turned to φ (and the rest of the program), the follower up to its stem."""
        f = self.f
        cam, rest = self.cam_now()
        every = np.vstack([cam, rest]) if len(rest) else cam
        width, base, stem = self.follower_size()
        xs = [*every[:, 0], -f.r0, f.r0, -width, width]
        ys = [*every[:, 1], -f.r0, base + stem]
        return min(xs), min(ys), max(xs), max(ys)

    def draw(self, d: Drawing, at: Placed) -> None:
        v = at.viewport
        assert v is not None
        f, plan = self.f, self.plan
        kl = v.scale
        cam, rest = self.cam_now()
        width, base, stem = self.follower_size()
        h = float(plan.B.y)
        o = Vec(0.0, 0.0)
        # the cam: its built profile and the base circle, turned to φ; the rest of the program
        # thin
        v.circle(o, f.base_radius, "construction")
        v.polyline(list(cam), "link", closed=self.closed)
        if len(rest):
            v.polyline(list(rest), "thin")
        Bp, C, B = plan.B_prime, plan.C, plan.B
        away = -1.0 if Bp.x >= 0.0 else 1.0
        v.pivot(o, down=(away, -1.0))
        a0, a1 = OMEGA_SPAN[-1 if away <= 0.0 else 1]
        turn_arrow(v, max(f.r0 * OMEGA_R0, kl.model(OMEGA_MM)), a0, a1, f.sigma, WORDS("omega"))
        # the follower: flat face (or knife, roller), stem, its guide on the frame (hatched on
        # both sides)
        top = Vec(f.e, base + stem)
        if f.kind == "flat":
            v.seg(Vec(-width, h), Vec(width, h), "link")
            v.seg(Vec(f.e, h), top, "link")
        elif f.kind == "roller":
            v.circle(B, f.r_roller, "link")
            v.seg(B, top, "link")
            v.joint(B)
        else:
            v.seg(B, top, "link")
        g_lo, g_hi = Vec(f.e, base + stem * 0.45), Vec(f.e, base + stem * 0.95)
        v.guide(g_lo, g_hi, (1.0, 0.0))
        v.guide(g_lo, g_hi, (-1.0, 0.0))
        # link numbers: the cam 1 inside its base circle, the follower 2 by its stem, the roller 3
        v.label(Vec(0.0, -0.6 * f.base_radius), "1", 3.5, clear=0.5)
        v.label(Vec(f.e, base + stem * 0.22), "2", 3.5, prefer=(-away, 0.0), clear=1.0)
        if f.kind == "roller":
            v.label(B + Vec(f.r_roller, 0.0) * (-away), "3", 3.5, prefer=(-away, 0.0), clear=1.0)
        # the triangle OBB′ similar to the plan, and C (BC = OB′ = S′)
        v.seg(o, B, "construction")
        v.seg(B, Bp, "construction")
        v.seg(o, Bp, "construction")
        if f.kind == "flat":
            v.seg(o, C, "construction")
        v.right_angle(Bp, o, B, 2.5)
        for q in (o, B, Bp):
            v.dot(q, "point")
        v.label(o, "O", prefer=(-away, 1.0), clear=1.5)
        v.label(B, "B", prefer=(-away, 1.0))
        v.label(Bp, "B'", prefer=(-away, -1.0))
        if f.kind == "flat":
            v.label(C, "C", prefer=(away, -1.0))
        if abs(plan.S1) > 0.0:
            v.dim_linear(o, Bp, "S'", offset=-3.0 if Bp.x > 0 else 3.0, height=2.5)
