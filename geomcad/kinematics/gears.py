"""Involute spur gears: the involute, tooth thickness, generation by the rack, measurements.

Geometry (SI units, angles in radians). A gear of module m, z teeth and profile shift x, cut by the
basic rack of GOST 13755 (≈ ISO 53: α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38):

- pitch diameter d = m·z, base diameter d_b = d·cos α, pitch p = π·m;
- tooth thickness on the pitch circle s = π·m/2 + 2·x·m·tan α, and on any circle d_y ≥ d_b
  s_y = d_y·(s/d + inv α − inv α_y), cos α_y = d_b/d_y, where inv α = tan α − α;
- ψ_y = s_y/d_y is half the tooth's angular thickness at d_y.

The frame of a tooth: the gear's centre O is the origin and the tooth's axis is +y; the right flank
is the one at x > 0. Its polar half-angle η(R) is measured from +y towards +x, so a point of the
flank at radius R is R·(sin η, cos η), and on the involute η(R) = ψ_y at d_y = 2R.

Generation: the producing rack (the basic rack's complement: its tooth is h_a*·m + c*·m tall,
with the fillet ρ_f*·m at its tip) rolls its line at x·m from its datum line on the pitch circle.
The gear turns counter-clockwise by φ while the rack moves by −r·φ, so P = (0, r) is the pitch
point. A point of the rack profile is a point of the gear's flank when the profile's normal there
passes through P (the meshing condition); that point, turned back by −φ into the gear's frame, is
a point of the envelope. The straight flank envelops the involute, the tip fillet the fillet curve,
the tip line the root circle.

Workshop measurements: the chordal thickness s̄ and chordal height h̄ read with a gear-tooth caliper
(its height jaw rests on the tip circle, its two jaws touch the flanks on a chord), and the span W
over k teeth. Each is predicted from x and, the other way round, x is recovered from a reading; a
reading that no gear of the given m, z, d_a can give is a :class:`ParameterError` that names the
reading and the range it must lie in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError

Arr = npt.NDArray[np.float64]


# -- the involute function ------------------------------------------------------------------------


def inv(alpha: float) -> float:
    """The involute function inv α = tan α − α: the polar angle of the involute's point whose
    pressure angle is α, measured from where the involute leaves the base circle."""
    return math.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """The pressure angle α ∈ [0, π/2) with inv α = ``value`` (scipy brentq, to ``tol.ROOT_ANGLE``).

    inv is increasing on [0, π/2) from 0 to ∞; a value < 0 or not finite is a
    :class:`ParameterError`.
    """
    if not (math.isfinite(value) and value >= 0.0):
        raise ParameterError("inv α", value, "must be a finite number ≥ 0")
    if value == 0.0:
        return 0.0
    # at α = atan(value + π/2), tan α − α = value + π/2 − α > value, and inv α > α³/3: the root
    # lies below both bounds; the second keeps the tolerance relative for small angles
    hi = min(math.atan(value + math.pi / 2.0), (3.0 * value) ** (1.0 / 3.0))
    root: float = brentq(lambda a: inv(a) - value, 0.0, hi, xtol=tol.ROOT_ANGLE * hi)
    return root


def pressure_angle(r_b: float, r: float) -> float:
    """The involute's pressure angle α_y at radius r: cos α_y = r_b / r (r ≥ r_b)."""
    if not r >= r_b * (1.0 - tol.REL_LENGTH):
        raise ParameterError("d_y", 2.0 * r, f"must be ≥ the base diameter d_b = {2.0 * r_b:.6g} m")
    return math.acos(min(1.0, r_b / r))


def involute(r_b: float, t: npt.ArrayLike, start: float = 0.0) -> Arr:
    """Points of the involute of the circle (O, r_b), as an ``(N, 2)`` array.

    The involute leaves the base circle at polar angle ``start`` and unwinds counter-clockwise;
    ``t`` ≥ 0 is the roll angle (tan of the pressure angle): the point is the end of the thread
    of length r_b·t unwound from the base circle, at radius r_b·√(1 + t²) and polar angle
    start + t − atan t = start + inv α.
    """
    tt = np.asarray(t, dtype=np.float64)
    a = start + tt
    return np.stack(
        [r_b * (np.cos(a) + tt * np.sin(a)), r_b * (np.sin(a) - tt * np.cos(a))], axis=-1
    )


def _turn(p: Arr, angle: Arr) -> Arr:
    """Each point p[i] turned counter-clockwise by angle[i] about O."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * p[..., 0] - s * p[..., 1], s * p[..., 0] + c * p[..., 1]], axis=-1)


def half_angle_of(points: Arr) -> Arr:
    """The polar half-angle η of tooth-frame points: the angle from the tooth's axis +y to +x."""
    return np.asarray(np.arctan2(points[..., 0], points[..., 1]), dtype=np.float64)


# -- the basic rack -------------------------------------------------------------------------------


@dataclass(frozen=True)
class BasicRack:
    """A basic rack profile: profile angle ``alpha``, addendum ``ha``·m, clearance ``c``·m and
    root fillet radius ``rho_f``·m (GOST 13755 ≈ ISO 53 by default).

    The producing rack that cuts the gear is its complement: a tooth (ha + c)·m tall whose tip
    corners are rounded with the fillet radius (reduced to what fits the tooth's tip when a
    profile angle other than 20° leaves less room; :meth:`fillet` says which).
    """

    alpha: float = math.radians(20.0)
    ha: float = 1.0
    c: float = 0.25
    rho_f: float = 0.38

    def check(self, name: str = "alpha") -> None:
        """Reject a rack whose producing tooth cannot exist (ParameterError naming ``name``)."""
        a = self.alpha
        if not (0.0 < a < math.pi / 2.0):
            raise ParameterError(name, a, "the profile angle must lie between 0 and 90°")
        if self.ha <= 0.0 or self.c < 0.0 or self.rho_f < 0.0:
            raise ParameterError("rack", self, "h_a* > 0, c* ≥ 0 and ρ_f* ≥ 0 are required")
        if self.tip_width() <= 0.0:
            limit = math.degrees(math.atan(math.pi / (4.0 * (self.ha + self.c))))
            raise ParameterError(
                name,
                math.degrees(a),
                f"the producing rack's tooth, (h_a* + c*)·m = {self.ha + self.c:g}·m tall, is "
                f"pointed at this profile angle: it must be < {limit:.4g}°",
            )

    def tip_width(self) -> float:
        """Width of the producing rack's tooth at its tip line, in modules."""
        return math.pi / 2.0 - 2.0 * (self.ha + self.c) * math.tan(self.alpha)

    def fillet(self) -> float:
        """The tip fillet radius of the producing rack, in modules: ρ_f*, or the largest radius
        whose two fillets fit the tip width when ρ_f* does not."""
        fits = self.tip_width() / (2.0 * math.tan(math.pi / 4.0 - self.alpha / 2.0))
        return max(0.0, min(self.rho_f, fits))


GOST_13755 = BasicRack()


# -- the gear -------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Chord:
    """A gear-tooth caliper reading: the chord ``s_bar`` between the flanks at the chordal height
    ``h_bar`` below the tip circle; its ends lie on the circle ``d_y``, where ``psi_y`` is half the
    tooth's angular thickness."""

    s_bar: float
    h_bar: float
    d_y: float
    psi_y: float


@dataclass(frozen=True)
class Flank:
    """The generated right flank of a tooth, in the tooth's frame, as ``(N, 2)`` arrays of points.

    ``involute``: from the tip circle down to the limit circle (the envelope of the rack's
    straight flank); ``fillet``: from the limit circle down to the root circle (the envelope of
    the rack's tip fillet); the root circle runs from the fillet's end, at half-angle
    ``root_from``, to the middle of the space, at ``root_to`` = π/z; the tip circle from the axis
    to ``tip_to``.
    ``involute_phi`` holds the rack's generating positions φ of the involute's points.
    """

    involute: Arr
    involute_phi: Arr
    fillet: Arr
    root_from: float
    root_to: float
    tip_to: float

    def __str__(self) -> str:
        r_inv = np.hypot(self.involute[:, 0], self.involute[:, 1])
        r_fil = np.hypot(self.fillet[:, 0], self.fillet[:, 1])
        return (
            f"involute R = {r_inv.min():.6f} … {r_inv.max():.6f} ({len(r_inv)} points), "
            f"fillet R = {r_fil.min():.6f} … {r_fil.max():.6f} ({len(r_fil)} points)"
        )


@dataclass(frozen=True)
class SpurGear:
    """An involute spur gear of module ``m`` (m), ``z`` teeth and profile shift coefficient ``x``,
    cut by ``rack``; ``d_a`` is its tip diameter (``None``: the standard d + 2(h_a* + x)·m).

    Raises :class:`ParameterError` for m ≤ 0, z < 1, a non-finite x, a tip that the rack cannot
    leave on the blank, or a rack that cannot exist.
    """

    m: float
    z: int
    x: float = 0.0
    rack: BasicRack = GOST_13755
    d_a: float | None = None

    def __str__(self) -> str:
        return (
            f"gear m = {self.m:.6g}, z = {self.z}, x = {self.x:.6f}, d_a = "
            f"{self.tip_diameter:.6f}, α = {math.degrees(self.alpha):.6g}°"
        )

    def __post_init__(self) -> None:
        if not (math.isfinite(self.m) and self.m > 0.0):
            raise ParameterError("m", self.m, "the module must be > 0")
        if isinstance(self.z, bool) or int(self.z) != self.z or self.z < 1:
            raise ParameterError("z", self.z, "the number of teeth must be a whole number ≥ 1")
        if not math.isfinite(self.x):
            raise ParameterError("x", self.x, "must be a finite number")
        self.rack.check()
        if self.d_a is not None and not (math.isfinite(self.d_a) and self.d_a > 0.0):
            raise ParameterError("d_a", self.d_a, "the tip diameter must be > 0")

    # -- sizes ----------------------------------------------------------------------------------
    @property
    def alpha(self) -> float:
        return self.rack.alpha

    @property
    def d(self) -> float:
        """Pitch diameter m·z."""
        return self.m * self.z

    @property
    def r(self) -> float:
        return self.d / 2.0

    @property
    def d_b(self) -> float:
        """Base diameter d·cos α."""
        return self.d * math.cos(self.alpha)

    @property
    def r_b(self) -> float:
        return self.d_b / 2.0

    @property
    def p(self) -> float:
        """Pitch π·m."""
        return math.pi * self.m

    @property
    def s(self) -> float:
        """Tooth thickness on the pitch circle: π·m/2 + 2·x·m·tan α."""
        return math.pi * self.m / 2.0 + 2.0 * self.x * self.m * math.tan(self.alpha)

    @property
    def tip_diameter(self) -> float:
        """d_a as given, else the standard d + 2(h_a* + x)·m."""
        if self.d_a is not None:
            return self.d_a
        return self.d + 2.0 * (self.rack.ha + self.x) * self.m

    @property
    def r_a(self) -> float:
        return self.tip_diameter / 2.0

    @property
    def d_f(self) -> float:
        """Root diameter cut by the rack's tip line: d − 2(h_a* + c* − x)·m."""
        return self.d - 2.0 * (self.rack.ha + self.rack.c - self.x) * self.m

    @property
    def cut_limit_diameter(self) -> float:
        """The largest tip the rack leaves on the blank: its root line, (h_a* + c*)·m above its
        datum line, gives d + 2(h_a* + c* + x)·m."""
        return self.d + 2.0 * (self.rack.ha + self.rack.c + self.x) * self.m

    # -- undercut, limit circle, pointed tip ------------------------------------------------------
    @property
    def x_min(self) -> float:
        """The least shift without undercut: h_a* − z·sin²α/2 (the rack's limit line through the
        interference point N)."""
        return self.rack.ha - self.z * math.sin(self.alpha) ** 2 / 2.0

    @property
    def undercut(self) -> bool:
        """True when the rack's tip undercuts the involute near the base circle: the rack's limit
        line (where its straight flank meets the fillet) passes below the interference point N."""
        return self._lambda_limit() > self._lambda_base() * (1.0 + tol.DERIVED)

    def limit_diameter(self) -> float:
        """d_l, where the involute meets the fillet: the lowest point of the working profile.

        Without undercut it is the envelope of the rack's limit point: R² = r_b² + (r·sin α −
        λ_l)², λ_l = (r − y_l)/sin α. With undercut the fillet crosses the involute; the crossing
        is found exactly on the fillet's parameter (brentq).
        """
        lam_b, lam_l = self._lambda_base(), self._lambda_limit()
        if lam_l <= lam_b * (1.0 + tol.DERIVED):
            return 2.0 * math.hypot(self.r_b, lam_b - lam_l)
        return 2.0 * self._undercut_crossing()[1]

    def half_angle(self, d_y: float) -> float:
        """ψ_y = s/d + inv α − inv α_y: half the tooth's angular thickness on the circle d_y ≥ d_b
        (on the involute; below the limit circle the real flank is the fillet)."""
        a_y = pressure_angle(self.r_b, d_y / 2.0)
        return self.s / self.d + inv(self.alpha) - inv(a_y)

    def thickness(self, d_y: float) -> float:
        """s_y = d_y·(s/d + inv α − inv α_y): the arc thickness of the tooth on the circle d_y."""
        return d_y * self.half_angle(d_y)

    @property
    def s_a(self) -> float:
        """The tooth's arc thickness on the tip circle (≤ 0: the tooth is pointed below it)."""
        return self.thickness(self.tip_diameter)

    def pointed_diameter(self) -> float:
        """The diameter where the two involutes of a tooth meet (ψ_y = 0): inv α_y = s/d + inv α."""
        a_p = inv_inverse(self.s / self.d + inv(self.alpha))
        return self.d_b / math.cos(a_p)

    def check(self) -> None:
        """Reject a gear that cannot be cut as specified (ConstructionError naming the check)."""
        if self.tip_diameter > self.cut_limit_diameter * (1.0 + tol.DERIVED):
            raise ConstructionError(
                "tip circle",
                f"d_a = {self.tip_diameter:.6g} m lies above the rack's root line, which leaves "
                f"at most d + 2(h_a* + c* + x)·m = {self.cut_limit_diameter:.6g} m on the blank",
            )
        if self.s_a <= 0.0:
            raise ConstructionError(
                "pointed tip",
                f"the flanks meet at d = {self.pointed_diameter():.6g} m, below the tip circle "
                f"d_a = {self.tip_diameter:.6g} m (tooth thickness there s_a = {self.s_a:.4g} m)",
            )
        if self.s >= self.p:
            raise ConstructionError(
                "tooth space",
                f"the tooth is {self.s:.6g} m thick on the pitch circle, not less than the pitch "
                f"p = π·m = {self.p:.6g} m: no space is left between the teeth",
            )
        d_l = self.limit_diameter()
        if self.tip_diameter <= d_l:
            raise ConstructionError(
                "limit circle",
                f"the tip circle d_a = {self.tip_diameter:.6g} m lies below the start of the "
                f"involute d_l = {d_l:.6g} m: the tooth has no involute flank",
            )

    # -- workshop measurements ------------------------------------------------------------------
    def chord(self, d_y: float | None = None) -> Chord:
        """The caliper's chordal thickness and height for the chord whose ends lie on the circle
        d_y (default the pitch circle): s̄ = d_y·sin ψ_y, h̄ = r_a − (d_y/2)·cos ψ_y."""
        dy = self.d if d_y is None else d_y
        psi = self.half_angle(dy)
        return Chord(dy * math.sin(psi), self.r_a - dy / 2.0 * math.cos(psi), dy, psi)

    def chord_at_height(self, h_bar: float) -> Chord:
        """The chord the caliper reads with its height jaw set to ``h_bar``: the circle d_y whose
        flank points lie r_a − h̄ from O along the tooth's axis, R·cos ψ(R) = r_a − h̄ (increasing
        in R; scipy brentq), then s̄ = d_y·sin ψ_y.

        The chord must cross both involute flanks: a height that puts it on the tip land, or
        below the limit circle, is a :class:`ParameterError` naming the allowed range.
        """
        lo_r = self.limit_diameter() / 2.0
        hi_r = self.r_a

        def level(radius: float) -> float:
            return radius * math.cos(self.half_angle(2.0 * radius))

        h_min = self.r_a - level(hi_r)
        h_max = self.r_a - level(lo_r)
        if not (h_min <= h_bar <= h_max):
            raise ParameterError(
                "h_chord",
                h_bar,
                f"the chord must cross the involute flanks: the height must lie between "
                f"{h_min:.6g} m (tip corners) and {h_max:.6g} m (limit circle d_l = "
                f"{2.0 * lo_r:.6g} m)",
            )
        target = self.r_a - h_bar
        r_y: float = brentq(
            lambda rr: level(rr) - target,
            lo_r,
            hi_r,
            xtol=tol.REL_LENGTH * self.r_a,
        )
        psi = self.half_angle(2.0 * r_y)
        return Chord(2.0 * r_y * math.sin(psi), h_bar, 2.0 * r_y, psi)

    def constant_chord(self) -> Chord:
        """The constant chord: where the flanks of a rack tooth space straddling the tooth touch
        it, on the lines of action through the pitch point; s̄_c = s·cos²α, at
        r + (s/2)·sin α·cos α from O, so h̄_c = r_a − r − (s̄_c/2)·tan α."""
        s_c = self.s * math.cos(self.alpha) ** 2
        depth = self.r + self.s * math.sin(self.alpha) * math.cos(self.alpha) / 2.0
        d_y = 2.0 * math.hypot(s_c / 2.0, depth)
        return Chord(s_c, self.r_a - depth, d_y, math.atan2(s_c / 2.0, depth))

    def span(self, k: int) -> float:
        """The span W over k teeth: m·cos α·(π(k − 0.5) + z·inv α) + 2·x·m·sin α, the distance
        between parallel jaws touching two opposite flanks k teeth apart (both on one line
        tangent to the base circle)."""
        if isinstance(k, bool) or int(k) != k or not 1 <= k <= self.z:
            raise ParameterError("k", k, f"must be a whole number from 1 to z = {self.z}")
        a = self.alpha
        return self.m * math.cos(a) * (math.pi * (k - 0.5) + self.z * inv(a)) + (
            2.0 * self.x * self.m * math.sin(a)
        )

    def span_teeth(self) -> int:
        """The number of teeth k for a span measurement whose jaws touch near mid-height of the
        profile (on the circle d + 2·x·m): k = z·α_x/π + 0.5 rounded, with the flank's roll angle
        there: k = z/π·(tan α_x − 2x·tan α/z − inv α) + 0.5 (GOST 16532)."""
        a = self.alpha
        a_x = math.acos(self.d_b / (self.d + 2.0 * self.x * self.m))
        k = self.z / math.pi * (math.tan(a_x) - 2.0 * self.x * math.tan(a) / self.z - inv(a)) + 0.5
        return max(1, min(self.z, round(k)))

    def span_contact_diameter(self, W: float) -> float:
        """Where the jaws of a span W touch the flanks: 2·√(r_b² + (W/2)²)."""
        return 2.0 * math.hypot(self.r_b, W / 2.0)

    # -- generation by the rack -----------------------------------------------------------------
    def rack_frame(self) -> tuple[float, float, float, float, float]:
        """(c0, y_t, ρ, C0x, y_c): the rack at φ = 0 in the gear's fixed frame.

        Its right tooth's left flank is the line x + y·tan α = c0 (the tooth space is centred on
        the tooth's axis); its tip line y = y_t cuts the root circle; its tip fillet of radius ρ
        has the centre (C0x, y_c)."""
        m, a = self.m, self.alpha
        c0 = math.pi * m / 4.0 + (self.r + self.x * m) * math.tan(a)
        y_t = self.r + self.x * m - (self.rack.ha + self.rack.c) * m
        rho = self.rack.fillet() * m
        y_c = y_t + rho
        c_x = c0 - y_c * math.tan(a) + rho / math.cos(a)
        return c0, y_t, rho, c_x, y_c

    def _lambda_base(self) -> float:
        """λ at the interference point N (on the base circle): r·sin α."""
        return self.r * math.sin(self.alpha)

    def _lambda_limit(self) -> float:
        """λ at the rack's limit line y_l (where its straight flank meets the fillet)."""
        _, y_t, rho, _, _ = self.rack_frame()
        y_l = y_t + rho * (1.0 - math.sin(self.alpha))
        return (self.r - y_l) / math.sin(self.alpha)

    def flank_points(self, lam: npt.ArrayLike) -> tuple[Arr, Arr]:
        """Envelope of the rack's straight flank: points in the tooth's frame, and their φ.

        At position φ the flank is the line x + y·tan α = c0 − r·φ; the meshing condition puts
        the contact point at the foot K = P − λ·n of the perpendicular from the pitch point
        P = (0, r) (n = (cos α, sin α), the flank's normal), so λ = r·sin α − (c0 − r·φ)·cos α.
        K turned by −φ is the gear's point. λ = r·sin α is the base circle; λ = 0 the pitch circle.
        """
        lam_a = np.asarray(lam, dtype=np.float64)
        a, r = self.alpha, self.r
        c0 = self.rack_frame()[0]
        phi = (lam_a - r * math.sin(a) + c0 * math.cos(a)) / (r * math.cos(a))
        k = np.stack([-lam_a * math.cos(a), r - lam_a * math.sin(a)], axis=-1)
        return _turn(k, -phi), phi

    def fillet_points(self, beta: npt.ArrayLike) -> tuple[Arr, Arr]:
        """Envelope of the rack's tip fillet: points in the tooth's frame, and their φ.

        ``beta`` ∈ [π + α, 3π/2] is the direction of the fillet's outward normal (π + α where it
        meets the straight flank, 3π/2 at the tip line). The contact point K = C + ρ·(cos β,
        sin β) has its normal through P when r·φ = C0x + (r − y_c)·cot β.
        """
        b = np.asarray(beta, dtype=np.float64)
        _, _, rho, c_x, y_c = self.rack_frame()
        r = self.r
        phi = (c_x + (r - y_c) * np.cos(b) / np.sin(b)) / r
        k = np.stack([c_x - r * phi + rho * np.cos(b), y_c + rho * np.sin(b)], axis=-1)
        return _turn(k, -phi), phi

    def _involute_half_angle(self, radius: Arr) -> Arr:
        """η of the exact involute at radius R ≥ r_b (closed form)."""
        a_y = np.arccos(np.minimum(1.0, self.r_b / radius))
        return np.asarray(self.s / self.d + inv(self.alpha) - (np.tan(a_y) - a_y), dtype=np.float64)

    def _undercut_crossing(self) -> tuple[float, float]:
        """(β, R) where the fillet curve crosses the involute (undercut gears), by brentq on the
        fillet's parameter β; the crossing farthest from the centre bounds the involute. Without
        a crossing: the fillet's start, and the base circle."""
        a = self.alpha

        def gaps(b: Arr) -> Arr:
            # η of the fillet minus η of the involute at the same radius (−1 below the base
            # circle, where there is no involute): < 0 where the fillet cuts into the tooth
            q, _ = self.fillet_points(b)
            radius = np.hypot(q[:, 0], q[:, 1])
            inside = radius > self.r_b
            eta_i = self._involute_half_angle(np.where(inside, radius, self.r_b))
            return np.where(inside, half_angle_of(q) - eta_i, -1.0)

        def gap(b: float) -> float:
            return float(gaps(np.array([b]))[0])

        betas = np.linspace(math.pi + a, 1.5 * math.pi, 2001)
        g = gaps(betas)
        best = (math.pi + a, self.r_b)
        for i in np.nonzero(np.diff(np.sign(g)))[0]:
            b0: float = brentq(gap, float(betas[i]), float(betas[i + 1]), xtol=tol.ROOT_ANGLE)
            q, _ = self.fillet_points(np.array([b0]))
            radius = float(np.hypot(q[0, 0], q[0, 1]))
            if radius > best[1]:
                best = (b0, radius)
        return best

    def flank(self, n: int = 200) -> Flank:
        """The right flank of a tooth generated by the rack, in the tooth's frame (see
        :class:`Flank`); ``n`` points per curve. Calls :meth:`check` first."""
        self.check()
        a, r = self.alpha, self.r
        r_l = self.limit_diameter() / 2.0
        lam_tip = r * math.sin(a) - math.sqrt(self.r_a**2 - self.r_b**2)
        lam_low = r * math.sin(a) - math.sqrt(max(0.0, r_l**2 - self.r_b**2))
        inv_pts, inv_phi = self.flank_points(np.linspace(lam_tip, lam_low, n))
        # with undercut the fillet starts where it crosses the involute
        b_start = self._undercut_crossing()[0] if self.undercut else math.pi + a
        fil, _ = self.fillet_points(np.linspace(b_start, 1.5 * math.pi, n))
        _, _, _, c_x, _ = self.rack_frame()
        tip_to = float(half_angle_of(inv_pts[:1])[0])
        return Flank(inv_pts, inv_phi, fil, c_x / r, math.pi / self.z, tip_to)


# -- recovering the shift from a reading ----------------------------------------------------------


@dataclass(frozen=True)
class ChordReading:
    """What a caliper reading gives: ψ_y, d_y, α_y, the pitch thickness s and the shift x."""

    psi_y: float
    d_y: float
    alpha_y: float
    s: float
    x: float


def chord_circle(d_a: float, s_chord: float, h_chord: float) -> tuple[float, float]:
    """(ψ_y, d_y) of a caliper chord: its ends lie r_a − h̄ from O along the tooth's axis and s̄/2
    either side of it, so tan ψ_y = (s̄/2)/(r_a − h̄) = s̄/(d_a − 2h̄) and
    d_y = √(s̄² + (d_a − 2h̄)²) = s̄/sin ψ_y."""
    depth = d_a - 2.0 * h_chord
    return math.atan2(s_chord, depth), math.hypot(s_chord, depth)


def shift_from_chord(
    m: float,
    z: int,
    d_a: float,
    s_chord: float,
    h_chord: float,
    rack: BasicRack = GOST_13755,
) -> ChordReading:
    """The shift x and pitch thickness s of a gear from a caliper reading (s̄, h̄).

    ψ_y and d_y from :func:`chord_circle`; cos α_y = d_b/d_y; the involute gives
    s = d·(ψ_y + inv α_y − inv α) and s = π·m/2 + 2·x·m·tan α gives x. Exact (closed form).

    A reading no gear can give is a :class:`ParameterError` naming ``s_chord`` or ``h_chord`` and
    the range it must lie in: the chord's ends outside the tip circle or below the base circle,
    a chord wider than the angular pitch, a tooth thicker than the pitch; a reading whose chord
    ends in the fillet (below the limit circle of the gear it implies) or on a pointed tooth is a
    :class:`ConstructionError`.
    """
    gear0 = SpurGear(m, z, 0.0, rack, d_a)
    if not (math.isfinite(s_chord) and s_chord > 0.0):
        raise ParameterError("s_chord", s_chord, "the chordal thickness must be > 0")
    if not (math.isfinite(h_chord) and 0.0 < h_chord < d_a / 2.0):
        raise ParameterError(
            "h_chord", h_chord, f"the chordal height must lie between 0 and d_a/2 = {d_a / 2:.6g} m"
        )
    depth = d_a - 2.0 * h_chord
    psi_y, d_y = chord_circle(d_a, s_chord, h_chord)
    s_max = math.sqrt(max(0.0, d_a**2 - depth**2))
    s_min = math.sqrt(max(0.0, gear0.d_b**2 - depth**2))
    if d_y > d_a:
        raise ParameterError(
            "s_chord",
            s_chord,
            f"the chord's ends lie outside the tip circle (d_y = {d_y:.6g} m > d_a = {d_a:.6g} m); "
            f"at h_chord = {h_chord:.6g} m it must be ≤ {s_max:.6g} m",
        )
    if d_y < gear0.d_b:
        raise ParameterError(
            "s_chord",
            s_chord,
            f"the chord's ends lie below the base circle (d_y = {d_y:.6g} m < d_b = "
            f"{gear0.d_b:.6g} m), where there is no involute; at h_chord = {h_chord:.6g} m it "
            f"must be ≥ {s_min:.6g} m",
        )
    if 2.0 * psi_y >= 2.0 * math.pi / z:
        raise ParameterError(
            "s_chord",
            s_chord,
            f"the chord spans {math.degrees(2.0 * psi_y):.4g}°, not less than the angular pitch "
            f"360°/z = {360.0 / z:.4g}°",
        )
    a = rack.alpha
    alpha_y = math.acos(gear0.d_b / d_y)
    s = gear0.d * (psi_y + inv(alpha_y) - inv(a))
    if s >= gear0.p:
        raise ParameterError(
            "s_chord",
            s_chord,
            f"it gives a tooth {s:.6g} m thick on the pitch circle, not less than the pitch "
            f"p = π·m = {gear0.p:.6g} m",
        )
    x = (s - math.pi * m / 2.0) / (2.0 * m * math.tan(a))
    gear = SpurGear(m, z, x, rack, d_a)
    gear.check()
    d_l = gear.limit_diameter()
    if d_y < d_l * (1.0 - tol.DERIVED):
        raise ConstructionError(
            "chord on the flanks",
            f"the chord's ends lie on d_y = {d_y:.6g} m, below the limit circle d_l = "
            f"{d_l:.6g} m of the gear it implies (x = {x:.4g}): they touch the fillet, not the "
            "involute",
        )
    return ChordReading(psi_y, d_y, alpha_y, s, x)


def shift_from_span(
    m: float,
    z: int,
    k: int,
    W: float,
    rack: BasicRack = GOST_13755,
    d_a: float | None = None,
) -> float:
    """The shift x from a span W over k teeth: x = (W/(m·cos α) − π(k − 0.5) − z·inv α)/(2 tan α).

    The jaws touch the flanks at d = 2·√(r_b² + (W/2)²); a span whose touching points lie outside
    the tip circle or below the limit circle of the gear it implies is a :class:`ParameterError`
    naming W and the range for this k.
    """
    SpurGear(m, z, 0.0, rack, d_a)  # checks m, z, the rack and d_a
    if isinstance(k, bool) or int(k) != k or not 1 <= k <= z:
        raise ParameterError("k", k, f"must be a whole number from 1 to z = {z}")
    if not (math.isfinite(W) and W > 0.0):
        raise ParameterError("W", W, "the span must be > 0")
    a = rack.alpha
    x = (W / (m * math.cos(a)) - math.pi * (k - 0.5) - z * inv(a)) / (2.0 * math.tan(a))
    gear = SpurGear(m, z, x, rack, d_a)
    gear.check()
    d_w = gear.span_contact_diameter(W)
    d_l, d_tip = gear.limit_diameter(), gear.tip_diameter
    if not d_l <= d_w <= d_tip:
        raise ParameterError(
            "W",
            W,
            f"over k = {k} teeth the jaws would touch the flanks on d = {d_w:.6g} m, outside "
            f"the involute (d_l = {d_l:.6g} m … d_a = {d_tip:.6g} m of the gear it implies, "
            f"x = {x:.4g}); measure over another number of teeth",
        )
    return x
