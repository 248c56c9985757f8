"""Views of a cam mechanism drawn from its model (:mod:`geomcad.kinematics.cams`).

- :class:`Inversion` — the cam profile by inversion, for a translating follower or a rocker
  (a seed problem's and a design file's profile alike): the base circle (a roller's prime
  circle and the working profile's base circle), the follower turned back to each division
  point (its axis and its face, or its tip, or its roller; a rocker's arm from its turned
  pivot A_i), the profile, the radius vectors; lettered (a textbook's few points) with r_i
  written on them, the angle of one interval and the sense −ω of the inversion, else (a
  design's many points) numbered with ω and −ω outside the profile; the rest of the program
  past the span in thin lines, so that the cam's shape is seen whole;
- :class:`CamAt` — the mechanism at one position in the fixed frame: the cam turned to φ (the
  built profile thick, the rest thin), its support and ω, the follower with its stem and guide,
  the links numbered, and the triangle OBB′ similar to the velocity plan (OB′ = S′; C and
  BC = S′ for a flat face), from a :class:`~geomcad.kinematics.cams.VelocityPlan`.

Both take model data only (the follower, the profiles, the plan); their words come from
``strings/<lang>/cams.toml``, the numbers in the language being drawn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from geomcad.geom import Arc, Circle, Vec
from geomcad.kinematics.cams import CamProfile, Follower, VelocityPlan, evert, invert
from geomcad.kinematics.motion_laws import FloatArray
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
#: Paper room (mm) round the cam's centre kept for its letter where many rays meet there.
O_ROOM = 6.0
#: The arcs of ω and −ω outside a design's profile: this many times its outer reach (the
#: rollers').
SENSE_OUT = 1.06


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


class Points(Protocol):
    """Points of a profile by their angle φ of the cam: the follower's reference point
    (``pitch``: the roller's centre, the knife's tip, the flat face's point on its axis) and the
    profile's point of contact, in the cam's frame (O at the origin). A
    :class:`~geomcad.kinematics.cams.CamProfile` or a rocker's profile is one."""

    @property
    def phi(self) -> FloatArray: ...
    @property
    def pitch(self) -> FloatArray: ...
    @property
    def contact(self) -> FloatArray: ...


@dataclass(frozen=True)
class Division:
    """The division points a profile is built at: ``phi``, ``pitch``, ``contact`` (as
    :class:`Points`)."""

    phi: FloatArray
    pitch: FloatArray
    contact: FloatArray


class Inversion(View):
    """The profile of a cam by inversion (see the module's docstring): ``profile`` the built
    profile (``closed`` for a full turn), ``divisions`` its division points, ``rest`` the profile
    on to the program's end (thin, with the axis at its end labelled ``rest_text``).

    The follower is translating (``follower``'s kind, offset and roller) or, given its
    ``pivot`` A (cam frame, on the lower dwell), a rocker: then the arm A_i C_i is drawn at each
    division point with A_i on the circle of radius OA. ``lettered`` (a textbook's few points)
    names each division point B_i, writes its radius vector r_i on it and dimensions one
    interval, the sense −ω by the axes; else (a design's many points) each point gets its
    number only, the radius vectors start clear of the letter O and the arcs of ω and −ω stand
    outside the profile. Keywords as :class:`~geomcad.sheet.compose.View`."""

    def __init__(
        self,
        follower: Follower,
        profile: Points,
        divisions: Points,
        closed: bool = False,
        rest: Points | None = None,
        rest_text: str = "",
        pivot: tuple[float, float] | None = None,
        lettered: bool = True,
        **kw: Any,
    ) -> None:
        super().__init__(**kw)
        self.f, self.profile, self.div = follower, profile, divisions
        self.closed, self.rest, self.rest_text = closed, rest, rest_text
        self.pivot = None if pivot is None else Vec(*pivot)
        self.lettered = lettered
        self._ext = self._extent()

    def extent(self) -> Extent | None:
        return self._ext

    def _extent(self) -> Extent:
        """The base circle, the profile (and the rest of the program), the division points, a
        rocker's circle of pivots."""
        f = self.f
        parts = [self.profile.contact, self.div.pitch, self.div.contact, self.profile.pitch]
        if self.rest is not None:
            parts += [self.rest.contact, self.rest.pitch]
        pts = np.vstack(parts)
        ext = f.r_roller if f.kind == "roller" else 0.0
        r = max(f.r0, self.pivot.norm if self.pivot is not None else 0.0)
        xs = [float(pts[:, 0].min()) - ext, float(pts[:, 0].max()) + ext, -r, r]
        ys = [float(pts[:, 1].min()) - ext, float(pts[:, 1].max()) + ext, -r, r]
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
        # where many rays meet at O they begin clear of its letter
        room = 0.0 if self.lettered else k.model(O_ROOM)
        n = len(div.phi)
        if n > 1 and math.isclose(float(div.phi[-1] - div.phi[0]), 2.0 * math.pi):
            n -= 1  # the last point of a full turn is the first one again
        shown = self._labelled(v, n) if self.lettered else set(range(n))
        pivots = (
            invert(np.repeat([[self.pivot.x, self.pivot.y]], n, axis=0), div.phi[:n], f.sigma)
            if self.pivot is not None
            else None
        )
        if pivots is not None:
            assert self.pivot is not None
            v.circle(o, self.pivot.norm, "centre")
        elif f.kind != "flat" and f.e != 0.0:
            v.circle(o, abs(f.e), "centre")
        dirs: list[float] = []  # the directions of the rays from O (the letter O stands clear)
        for i in range(n):
            turn = -f.sigma * float(div.phi[i])
            up = Vec(0.0, 1.0).rotated(turn)
            across = Vec(1.0, 0.0).rotated(turn)
            C = Vec(*div.pitch[i])
            B = Vec(*div.contact[i])
            if pivots is not None:
                # the rocker's arm turned back by φ_i: from its pivot A_i to the roller's centre
                A = Vec(*pivots[i])
                v.seg(A, C, "construction")
                v.dot(A, "point")
                v.label(A, f"A_{{{i}}}", height=2.5, prefer=(A.x, A.y))
                tip = C
            else:
                # the follower's axis turned back by φ_i (for the flat face the line through O
                # along the motion, on which C_i lies), from O or its foot on the circle of
                # radius e to past C_i
                foot = across * f.e if f.kind != "flat" else o
                tip = C + up * over
                _ray(v, foot, tip, room)
                dirs.append(turn + math.pi / 2.0)
            if f.kind == "flat":
                t_b = (B - C).dot(across)
                lo, hi = min(0.0, t_b) - over, max(0.0, t_b) + over
                v.seg(C + across * lo, C + across * hi, "construction")
            elif f.kind == "roller":
                v.circle(C, f.r_roller, "construction")
            if i in shown:
                self._number(v, i, B, C, tip, up)
            if C.dist(B) > 0.0:
                v.dot(C, "point")
            v.dot(B, "point")
            # the radius vector r_i = OB_i: a thin construction line
            _ray(v, o, B, room)
            dirs.append(B.angle)
        if f.kind == "roller":
            v.polyline(list(self.profile.pitch), "centre", closed=self.closed)
        v.polyline(list(self.profile.contact), "link", closed=self.closed)
        if self.rest is not None:
            self._rest(v, self.rest, over)
        # the letter O in the quadrant of the centre cross the widest gap between the rays opens
        gx, gy = _widest_gap(dirs)
        v.label(o, "O", prefer=(math.copysign(1.0, gx), math.copysign(1.0, gy)), clear=1.0)
        if not self.lettered:
            _senses(v, self.f, self.profile)
            return
        # the inversion: the follower turns about O against the cam's rotation
        share, a0, a1 = INVERSION_ARC
        turn_arrow(v, share * f.r0, a0, a1, -f.sigma, WORDS("minus_omega"))
        # the radius vectors' lengths, written along them
        for i in sorted(shown):
            B = Vec(*div.contact[i])
            text = f"r_{{{i}}} = {num(B.norm * MM)}"
            spots = tuple(v.p(B * t) for t in (0.6, 0.8, 0.5, 0.9, 0.4))
            v.d.label(v.p(B * 0.7), text, 2.5, others=spots)
        # the angle of one interval, between the last two axes
        if n >= 2:
            e0 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-2]))
            e1 = Vec(0.0, 1.0).rotated(-f.sigma * float(div.phi[-1]))
            dphi = math.degrees(float(div.phi[-1] - div.phi[-2]))
            v.dim_angle(o, e0, e1, f"{num(dphi)}°", r_mm=k.mm(f.r0) * share, height=2.5)

    def _number(self, v: Viewport, i: int, B: Vec, C: Vec, tip: Vec, up: Vec) -> None:
        """Division point i's number (and, lettered, B_i at its point of contact): a roller's
        outside its circle, by its point farthest from O; else at the axis's end (lettered) or
        at B_i, outward."""
        f = self.f
        if f.kind == "roller":
            u = C.unit() if C.norm > 0.0 else B.unit()
            v.label(C + u * f.r_roller, str(i), height=2.5, prefer=(u.x, u.y), clear=0.5)
        elif self.lettered and self.pivot is None:
            v.label(tip, str(i), height=2.5, prefer=(up.x, up.y), clear=0.5)
        else:
            v.label(B, str(i), height=2.5, prefer=(B.x, B.y))
        if self.lettered:
            v.label(B, f"B_{{{i}}}", height=2.5, prefer=(up.x, up.y))

    def _rest(self, v: Viewport, rest: Points, over: float) -> None:
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


def _ray(v: Viewport, a: Vec, b: Vec, room: float) -> None:
    """The construction segment ``ab`` less its part within ``room`` of the cam's centre (where
    the radius vectors and the follower's axes meet, the room of the letter O)."""
    d = b - a
    t0 = 0.0
    if room > 0.0 and d.norm > 0.0:
        # the segment's points at distance ``room`` from O: |a + t·d| = room
        p, q = a.dot(d) / d.dot(d), (a.dot(a) - room * room) / d.dot(d)
        disc = p * p - q
        if disc > 0.0:
            lo, hi = -p - math.sqrt(disc), -p + math.sqrt(disc)
            if lo <= 0.0 < hi:
                t0 = hi
    if t0 < 1.0:
        v.seg(a + d * t0, b, "construction")


def _widest_gap(angles: list[float]) -> tuple[float, float]:
    """The direction in the middle of the widest gap between ``angles`` (radians; down-left
    when there are none)."""
    if not angles:
        return (-1.0, -1.0)
    ang = np.sort(np.remainder(np.asarray(angles), 2.0 * math.pi))
    gaps = np.diff(np.append(ang, ang[0] + 2.0 * math.pi))
    j = int(np.argmax(gaps))
    mid = float(ang[j] + gaps[j] / 2.0)
    return (math.cos(mid), math.sin(mid))


def _sense_radius(f: Follower, profile: Points, angle: float) -> float:
    """The radius (model) of an arc of ω or −ω about ``angle``: just outside the profile (its
    rollers) within 45° of that direction."""
    pts = np.vstack([profile.contact, profile.pitch])
    r = np.hypot(pts[:, 0], pts[:, 1])
    off = np.abs(np.remainder(np.arctan2(pts[:, 1], pts[:, 0]) - angle + math.pi, 2 * math.pi))
    near = np.abs(off - math.pi) <= math.radians(45.0)
    reach = float(np.max(r[near] if near.any() else r))
    return SENSE_OUT * (reach + (f.r_roller if f.kind == "roller" else 0.0))


def _senses(v: Viewport, f: Follower, profile: Points) -> None:
    """The cam's ω and −ω, the sense in which the follower is turned back in the inversion:
    arcs about O just outside the profile with its rollers, towards the view's empty corners
    (upper left, lower right)."""
    k = v.scale
    o = Vec(0.0, 0.0)
    s = f.sigma
    sweep = math.radians(30.0)
    for sense, start, name in ((s, math.radians(135.0), "ω"), (-s, math.radians(315.0), "−ω")):
        r = _sense_radius(f, profile, start)
        # the arrow's last straight piece (a vector twice its head and more), as an angle
        head = 2.2 * k.model(ARROW_LEN) / r
        a0 = start - sense * sweep / 2.0
        a1 = start + sense * sweep / 2.0
        lo, hi = sorted((a0, a1 - sense * head))
        v.arc(Arc(Circle(o, r), lo, hi), "vector")
        v.arrow(Vec.polar(r, a1 - sense * head), Vec.polar(r, a1))
        v.label(Vec.polar(r, start), name, prefer=(math.cos(start), math.sin(start)))


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
