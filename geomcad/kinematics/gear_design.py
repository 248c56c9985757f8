"""Design of an external involute spur pair with profile shifts (GOST 16532), and its drawing.

For z1, z2, the module m, the basic rack (GOST 13755) and the shifts x1, x2:

- inv α_w = 2(x1 + x2)·tg α/(z1 + z2) + inv α (zero backlash), a_w = a·cos α/cos α_w with the
  standard a = m(z1 + z2)/2; the centre-distance coefficient y = (a_w − a)/m and the equalising
  shift Δy = x1 + x2 − y;
- tip diameters shortened by Δy·m: d_a = d + 2(h_a* + x − Δy)·m, root diameters
  d_f = d − 2(h_a* + c* − x)·m, the tip thickness s_a on d_a (the involute);
- the line of action N1N2 = a_w·sin α_w, its active part from the tip circles:
  g_a1 = √(r_a1² − r_b1²) from N1, g_a2 from N2; ε_α = (g_a1 + g_a2 − N1N2)/p_b, p_b = π·m·cos α;
- the specific slidings at the ends of the active part: λ1 = 1 − (ρ2/ρ1)(z1/z2) at a (the start
  of gear 1's active profile), λ2 = 1 − (ρ1/ρ2)(z2/z1) at b, ρ1 and ρ2 the distances from N1 and
  N2.

The blocking contour's limits, each an error naming the check: no undercut
(x ≥ h_a*·(z_min − z)/z_min with z_min = 2h_a*/sin²α rounded to a whole number, the textbook's
x ≥ (17 − z)/17), tip thickness s_a ≥ s_a_min·m (0.25 by default; ≤ 0 is a pointed tooth), no
interference (the active profile starts above the limit circle of the generated involute),
ε_α ≥ ε_min (1.2).

Shift rules: ``no_undercut`` (the smallest shifts ≥ 0 without undercut), ``equal_sliding``
(x1 + x2 = x_Σ split so that |λ1| = |λ2|, brentq), ``max_contact_ratio`` (the largest ε_α inside
the blocking contour: a grid, then scipy's SLSQP from its best point).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq, minimize

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError
from geomcad.kinematics.gears import GOST_13755, BasicRack, SpurGear, inv, inv_inverse

Arr = npt.NDArray[np.float64]

SHIFT_RULES = ("given", "no_undercut", "equal_sliding", "max_contact_ratio")
#: Default limits of the blocking contour.
SA_MIN = 0.25
EPS_MIN = 1.2

STEP_UNDERCUT = "no undercut (x ≥ (z_min − z)/z_min)"
STEP_INTERFERENCE = "no interference (active profile above the limit circle)"
STEP_TIP = "tip thickness s_a ≥ s_a_min·m"
STEP_EPS = "contact ratio ε_α ≥ ε_min"
STEP_SHIFTS = "shifts x1, x2 by the rule"


def z_min(rack: BasicRack = GOST_13755) -> int:
    """The least tooth number without undercut, rounded as the textbooks do (17 for 20°)."""
    return round(2.0 * rack.ha / math.sin(rack.alpha) ** 2)


def x_no_undercut(z: int, rack: BasicRack = GOST_13755) -> float:
    """x ≥ h_a*·(z_min − z)/z_min: the least shift without undercut."""
    zm = z_min(rack)
    return rack.ha * (zm - z) / zm


@dataclass(frozen=True)
class GearPair:
    """An external involute pair with shifts, every size by GOST 16532 (SI units, radians)."""

    z1: int
    z2: int
    m: float
    x1: float
    x2: float
    rack: BasicRack
    alpha_w: float
    a: float
    a_w: float
    y: float
    dy: float
    gear1: SpurGear
    gear2: SpurGear

    @property
    def d_w1(self) -> float:
        return 2.0 * self.a_w * self.z1 / (self.z1 + self.z2)

    @property
    def d_w2(self) -> float:
        return 2.0 * self.a_w * self.z2 / (self.z1 + self.z2)

    @property
    def p_b(self) -> float:
        return math.pi * self.m * math.cos(self.rack.alpha)

    @property
    def N1N2(self) -> float:
        return self.a_w * math.sin(self.alpha_w)

    @property
    def g_a1(self) -> float:
        """From N1 to b, where gear 1's tip circle cuts the line of action."""
        return math.sqrt(max(0.0, self.gear1.r_a**2 - self.gear1.r_b**2))

    @property
    def g_a2(self) -> float:
        """From N2 to a, where gear 2's tip circle cuts the line of action."""
        return math.sqrt(max(0.0, self.gear2.r_a**2 - self.gear2.r_b**2))

    @property
    def eps_alpha(self) -> float:
        """ε_α = (g_a1 + g_a2 − N1N2)/p_b."""
        return (self.g_a1 + self.g_a2 - self.N1N2) / self.p_b

    @property
    def N1a(self) -> float:
        """From N1 to a (the start of gear 1's active profile)."""
        return self.N1N2 - self.g_a2

    @property
    def N2b(self) -> float:
        return self.N1N2 - self.g_a1

    def sliding(self, rho1: npt.ArrayLike) -> tuple[Arr, Arr]:
        """(λ1, λ2) at distances ρ1 from N1 along the line of action."""
        r1 = np.asarray(rho1, dtype=np.float64)
        r2 = self.N1N2 - r1
        u = self.z2 / self.z1
        with np.errstate(divide="ignore", invalid="ignore"):
            return 1.0 - r2 / (u * r1), 1.0 - u * r1 / r2

    @property
    def lambda1(self) -> float:
        """|λ1| at a, the start of gear 1's active profile."""
        return abs(float(self.sliding([self.N1a])[0][0]))

    @property
    def lambda2(self) -> float:
        """|λ2| at b, the start of gear 2's active profile."""
        return abs(float(self.sliding([self.g_a1])[1][0]))

    def active_start(self) -> tuple[float, float]:
        """The diameters where the active profiles begin: gear 1's at a, gear 2's at b."""
        d1 = 2.0 * math.hypot(self.gear1.r_b, self.N1a)
        d2 = 2.0 * math.hypot(self.gear2.r_b, self.N2b)
        return d1, d2


def pair(
    z1: int, z2: int, m: float, x1: float, x2: float, rack: BasicRack = GOST_13755
) -> GearPair:
    """The pair's sizes (module doc). A bad count or module is a :class:`ParameterError`."""
    for name, z in (("z1", z1), ("z2", z2)):
        if isinstance(z, bool) or int(z) != z or z < 5:
            raise ParameterError(name, z, "a tooth number must be a whole number ≥ 5")
    if not (math.isfinite(m) and m > 0.0):
        raise ParameterError("m", m, "the module must be > 0")
    for name, x in (("x1", x1), ("x2", x2)):
        if not (math.isfinite(x) and abs(x) <= 3.0):
            raise ParameterError(name, x, "a shift coefficient must lie between −3 and 3")
    al = rack.alpha
    inv_w = 2.0 * (x1 + x2) * math.tan(al) / (z1 + z2) + inv(al)
    if inv_w <= 0.0:
        raise ConstructionError(
            "α_w from inv α_w = 2(x1 + x2)·tg α/(z1 + z2) + inv α",
            f"x1 + x2 = {x1 + x2:.6g} is so negative that inv α_w ≤ 0",
        )
    a_wd = inv_inverse(inv_w)
    a = m * (z1 + z2) / 2.0
    a_w = a * math.cos(al) / math.cos(a_wd)
    y = (a_w - a) / m
    dy = x1 + x2 - y
    g1 = SpurGear(m, int(z1), x1, rack, m * z1 + 2.0 * (rack.ha + x1 - dy) * m)
    g2 = SpurGear(m, int(z2), x2, rack, m * z2 + 2.0 * (rack.ha + x2 - dy) * m)
    return GearPair(int(z1), int(z2), m, x1, x2, rack, a_wd, a, a_w, y, dy, g1, g2)


def violations(
    p: GearPair, sa_min: float = SA_MIN, eps_min: float = EPS_MIN
) -> list[tuple[str, str]]:
    """Every blocking-contour limit the pair breaks: (step, why), in the order of the module doc."""
    out: list[tuple[str, str]] = []
    for i, (g, x) in enumerate(((p.gear1, p.x1), (p.gear2, p.x2)), start=1):
        xm = x_no_undercut(g.z, p.rack)
        if x < xm - tol.DERIVED:
            out.append(
                (STEP_UNDERCUT, f"x{i} = {x:.4g} < (z_min − z{i})/z_min = {xm:.4g}: gear {i} "
                 f"(z{i} = {g.z}) is undercut")
            )  # fmt: skip
    for i, g in enumerate((p.gear1, p.gear2), start=1):
        if g.s_a < sa_min * p.m:
            what = "pointed" if g.s_a <= 0.0 else "too thin at the tip"
            out.append(
                (STEP_TIP, f"gear {i}'s tooth is {what}: s_a{i} = {g.s_a:.4g} m < "
                 f"{sa_min:g}·m = {sa_min * p.m:.4g} m")
            )  # fmt: skip
    d_p1, d_p2 = p.active_start()
    for i, (g, N, d_p) in enumerate(((p.gear1, p.N1a, d_p1), (p.gear2, p.N2b, d_p2)), start=1):
        other = 2 if i == 1 else 1
        if N < 0.0:
            out.append(
                (STEP_INTERFERENCE, f"the tip of gear {other} cuts the line of action beyond "
                 f"N{i} (by {-N:.4g} m): it interferes with gear {i}'s root")
            )  # fmt: skip
            continue
        d_l = g.limit_diameter()
        if d_p < d_l * (1.0 - tol.DERIVED):
            out.append(
                (STEP_INTERFERENCE, f"gear {i}'s active profile would start on d = {d_p:.6g} m, "
                 f"below its limit circle d_l = {d_l:.6g} m (the fillet): interference")
            )  # fmt: skip
    if not out and p.eps_alpha < eps_min:
        out.append((STEP_EPS, f"ε_α = {p.eps_alpha:.4g} < {eps_min:g}"))
    return out


def check(p: GearPair, sa_min: float = SA_MIN, eps_min: float = EPS_MIN) -> None:
    """The first blocking-contour limit the pair breaks, as a :class:`ConstructionError`."""
    bad = violations(p, sa_min, eps_min)
    if bad:
        step, why = bad[0]
        raise ConstructionError(step, f"{why} (x1 = {p.x1:.4g}, x2 = {p.x2:.4g})")


def choose_shifts(
    rule: str,
    z1: int,
    z2: int,
    m: float,
    rack: BasicRack = GOST_13755,
    x_sum: float | None = None,
    sa_min: float = SA_MIN,
    eps_min: float = EPS_MIN,
) -> tuple[float, float]:
    """x1, x2 by a rule (module doc); no pair within the blocking contour is an error naming
    the rule's step."""
    lo1, lo2 = x_no_undercut(z1, rack), x_no_undercut(z2, rack)
    if rule == "no_undercut":
        return max(0.0, lo1), max(0.0, lo2)
    if rule == "equal_sliding":
        xs = (max(0.0, lo1) + max(0.0, lo2)) if x_sum is None else x_sum
        if xs < lo1 + lo2 - tol.DERIVED:
            raise ConstructionError(
                STEP_SHIFTS,
                f"x_sum = {xs:.4g} is below the undercut limits' sum {lo1 + lo2:.4g}",
            )

        def f(x1: float) -> float:
            try:
                p = pair(z1, z2, m, x1, xs - x1, rack)
            except (ConstructionError, ParameterError):
                return math.nan
            return p.lambda1 - p.lambda2

        # x1 from the pinion's undercut limit to the wheel's, each shift within ±3
        a, b = max(lo1, xs - 3.0), min(xs - lo2, 3.0)
        grid = np.linspace(a, b, 81)
        vals = np.array([f(float(x)) for x in grid])
        fin = np.isfinite(vals[:-1]) & np.isfinite(vals[1:])
        idx = np.nonzero(fin & (np.sign(vals[:-1]) != np.sign(vals[1:])))[0]
        if idx.size == 0:
            raise ConstructionError(
                STEP_SHIFTS,
                f"no split of x_sum = {xs:.4g} between x1 ∈ [{a:.4g}, {b:.4g}] equalises the "
                "specific slidings without undercut",
            )
        i = int(idx[0])
        x1 = brentq(f, float(grid[i]), float(grid[i + 1]), xtol=tol.REL_LENGTH)
        return float(x1), float(xs - x1)
    if rule == "max_contact_ratio":
        return _max_eps(z1, z2, m, rack, sa_min, eps_min)
    raise ParameterError("shift", rule, f"must be one of {', '.join(SHIFT_RULES)}")


def _max_eps(
    z1: int, z2: int, m: float, rack: BasicRack, sa_min: float, eps_min: float
) -> tuple[float, float]:
    lo1, lo2 = x_no_undercut(z1, rack), x_no_undercut(z2, rack)
    g1 = np.linspace(lo1, lo1 + 1.5, 61)
    g2 = np.linspace(lo2, lo2 + 1.5, 61)
    best = (-math.inf, 0.0, 0.0)
    for x1 in g1:
        for x2 in g2:
            try:
                p = pair(z1, z2, m, float(x1), float(x2), rack)
            except (ConstructionError, ParameterError):
                continue
            if not violations(p, sa_min, eps_min) and p.eps_alpha > best[0]:
                best = (p.eps_alpha, float(x1), float(x2))
    if not math.isfinite(best[0]):
        raise ConstructionError(
            STEP_SHIFTS, "the blocking contour is empty: no shifts satisfy every limit"
        )

    def margin(x: Arr) -> Arr:
        p = pair(z1, z2, m, float(x[0]), float(x[1]), rack)
        d1, d2 = p.active_start()
        return np.array(
            [
                x[0] - lo1,
                x[1] - lo2,
                (p.gear1.s_a - sa_min * m) / m,
                (p.gear2.s_a - sa_min * m) / m,
                (p.N1a) / m,
                (p.N2b) / m,
                (d1 - p.gear1.limit_diameter()) / m,
                (d2 - p.gear2.limit_diameter()) / m,
                p.eps_alpha - eps_min,
            ]
        )

    res = minimize(
        lambda x: -pair(z1, z2, m, float(x[0]), float(x[1]), rack).eps_alpha,
        np.array(best[1:]),
        constraints=[{"type": "ineq", "fun": margin}],
        method="SLSQP",
        options={"ftol": tol.DERIVED, "maxiter": 200},
    )
    x1, x2 = float(res.x[0]), float(res.x[1])
    try:
        p = pair(z1, z2, m, x1, x2, rack)
        ok = not violations(p, sa_min, eps_min) and p.eps_alpha >= best[0]
    except (ConstructionError, ParameterError):
        ok = False
    return (x1, x2) if ok else (best[1], best[2])


# -- the drawing: teeth generated by the rack, measured --------------------------------------------


def tooth_outline(g: SpurGear, n: int = 60) -> tuple[Arr, Arr, Arr]:
    """One tooth from the middle of the space on its left to the middle of the space on its right,
    in the tooth's frame (axis +y): the outline, and its right and left involutes (the flanks
    generated by the rack, :meth:`SpurGear.flank`)."""
    fl = g.flank(n)
    ra = g.r_a
    tip = np.linspace(-fl.tip_to, fl.tip_to, 9)
    tip_pts = np.stack([ra * np.sin(tip), ra * np.cos(tip)], axis=-1)
    rf = g.d_f / 2.0
    root = np.linspace(fl.root_from, fl.root_to, 9)
    root_r = np.stack([rf * np.sin(root), rf * np.cos(root)], axis=-1)
    right = np.vstack([fl.involute, fl.fillet, root_r])
    left = right[::-1] * np.array([-1.0, 1.0])
    outline = np.vstack([left, tip_pts, right])
    inv_r = fl.involute
    inv_l = fl.involute * np.array([-1.0, 1.0])
    return outline, inv_r, inv_l


def place(points: Arr, centre: tuple[float, float], axis_angle: float) -> Arr:
    """Tooth-frame points turned so that the tooth's axis (+y) points at ``axis_angle`` (rad,
    from +x) and moved to ``centre``."""
    t = axis_angle - math.pi / 2.0
    c, s = math.cos(t), math.sin(t)
    x, y = points[:, 0], points[:, 1]
    return np.stack([centre[0] + c * x - s * y, centre[1] + s * x + c * y], axis=-1)


def _tip_cut(p0: Arr, t: Arr, c: Arr, r: float, first: bool) -> Arr:
    """The line p0 + s·t ∩ circle (c, r): the point with the smaller s (``first``) or larger."""
    w = p0 - c
    bq = float(w @ t)
    disc = bq * bq - (float(w @ w) - r * r)
    if disc < 0.0:
        raise ConstructionError(
            "a, b = line of action ∩ tip circles", "the line misses a tip circle"
        )
    s = -bq - math.sqrt(disc) if first else -bq + math.sqrt(disc)
    return np.asarray(p0 + s * t, dtype=np.float64)


#: A flank crosses the line of action at a right angle when |cos| of their angle is below this.
NORMAL_COS = 0.02


def normal_hits(p0: Arr, t: Arr, poly: Arr) -> list[float]:
    """:func:`line_hits` where the polyline crosses the line at a right angle."""
    out = []
    for s in line_hits(p0, t, poly):
        q = p0 + s * t
        i = int(np.argmin(np.hypot(*(poly - q).T)))
        j = min(i + 1, len(poly) - 1) if i == 0 or i + 1 < len(poly) else i
        d = poly[j] - poly[j - 1]
        if abs(float(d @ t)) <= NORMAL_COS * float(np.hypot(*d)):
            out.append(s)
    return out


def line_hits(p0: Arr, t: Arr, poly: Arr) -> list[float]:
    """Parameters s of the points p0 + s·t where the line crosses the polyline."""
    a, b = poly[:-1], poly[1:]
    d = b - a
    den = t[0] * d[:, 1] - t[1] * d[:, 0]
    w = a - p0
    with np.errstate(divide="ignore", invalid="ignore"):
        s = (w[:, 0] * d[:, 1] - w[:, 1] * d[:, 0]) / den
        u = (w[:, 0] * t[1] - w[:, 1] * t[0]) / den
    ok = (den != 0.0) & (u >= 0.0) & (u <= 1.0)
    return sorted(float(v) for v in s[ok])


@dataclass(frozen=True)
class Meshing:
    """The meshing drawing's geometry (gear 1 at O1 = (0, 0), gear 2 at O2 = (0, a_w), the pitch
    point P on O1O2): teeth k = −1, 0, 1 of each wheel, the line of action through N1, N2, its
    active part ab, and what is measured off the drawn teeth: the base pitch between neighbouring
    involutes along the line of action, hence ε_α = ab / p_b."""

    pair: GearPair
    teeth1: list[Arr]
    teeth2: list[Arr]
    P: Arr
    N1: Arr
    N2: Arr
    a: Arr
    b: Arr
    t: Arr
    pb_measured: float
    eps_drawn: float


def meshing(p: GearPair, n: int = 60) -> Meshing:
    """Generate and place the teeth, draw the line of action and measure ε_α off them."""
    r_w1 = p.d_w1 / 2.0
    P = np.array([0.0, r_w1])
    O2 = (0.0, p.a_w)
    aw = p.alpha_w
    t = np.array([math.cos(aw), math.sin(aw)])
    N1 = P - r_w1 * math.sin(aw) * t
    N2 = P + (p.d_w2 / 2.0) * math.sin(aw) * t
    out1, r1, l1 = tooth_outline(p.gear1, n)
    out2, r2, l2 = tooth_outline(p.gear2, n)
    tau1, tau2 = 2.0 * math.pi / p.z1, 2.0 * math.pi / p.z2
    teeth1, teeth2 = [], []
    # per gear and flank side, per tooth k: where the line of action crosses the involute at a
    # right angle (the flanks of the other hand cross it obliquely and do not count)
    hits: dict[tuple[int, int], list[list[float]]] = {}
    for k in (-1, 0, 1):
        ang1 = math.pi / 2.0 + k * tau1
        teeth1.append(place(out1, (0.0, 0.0), ang1))
        # gear 2's space is centred on the line of centres: its teeth half a pitch off it
        ang2 = -math.pi / 2.0 + (k + 0.5) * tau2
        teeth2.append(place(out2, O2, ang2))
        for key, flank, centre, ang in (
            ((1, 0), r1, (0.0, 0.0), ang1),
            ((1, 1), l1, (0.0, 0.0), ang1),
            ((2, 0), r2, O2, ang2),
            ((2, 1), l2, O2, ang2),
        ):
            hits.setdefault(key, []).append(normal_hits(P, t, place(flank, centre, ang)))
    # the same flank of neighbouring teeth, each crossed once: their distance is the base pitch
    steps = [
        abs(h[i + 1][0] - h[i][0])
        for h in hits.values()
        for i in range(2)
        if len(h[i]) == 1 and len(h[i + 1]) == 1
    ]
    if not steps:
        raise ConstructionError(
            "base pitch off the drawing",
            "the line of action crosses no two neighbouring involutes at a right angle",
        )
    pb = float(np.mean(steps))
    # a and b: where the line of action cuts the drawn tip circles of gear 2 and gear 1
    a = _tip_cut(N1, t, np.array(O2), p.gear2.r_a, first=True)
    b = _tip_cut(N1, t, np.zeros(2), p.gear1.r_a, first=False)
    ab = float(np.hypot(*(b - a)))
    return Meshing(p, teeth1, teeth2, P, N1, N2, a, b, t, pb, ab / pb)


# -- the blocking contour -------------------------------------------------------------------------

#: The limits of the blocking contour, by name (the sheet's labels).
LIMITS = ("x_min1", "x_min2", "s_a1", "s_a2", "interf1", "interf2", "eps")


def limit_margins(
    p: GearPair, sa_min: float = SA_MIN, eps_min: float = EPS_MIN
) -> dict[str, float]:
    """Each limit's margin, in modules (ε_α: in itself); > 0 inside the blocking contour."""
    d_p1, d_p2 = p.active_start()
    out = {
        "x_min1": p.x1 - x_no_undercut(p.z1, p.rack),
        "x_min2": p.x2 - x_no_undercut(p.z2, p.rack),
        "s_a1": (p.gear1.s_a - sa_min * p.m) / p.m,
        "s_a2": (p.gear2.s_a - sa_min * p.m) / p.m,
        "eps": p.eps_alpha - eps_min,
    }
    for key, N, d_p, g in (("interf1", p.N1a, d_p1, p.gear1), ("interf2", p.N2b, d_p2, p.gear2)):
        out[key] = N / p.m if N < 0.0 else (d_p - g.limit_diameter()) / p.m
    return out


def blocking_contour(
    z1: int,
    z2: int,
    m: float,
    x1: Arr,
    x2: Arr,
    rack: BasicRack = GOST_13755,
    sa_min: float = SA_MIN,
    eps_min: float = EPS_MIN,
) -> dict[str, list[tuple[float, float, float, float]]]:
    """The lines of the blocking contour in the plane (x1, x2): per limit, the segments where its
    margin is zero, by marching squares on the grid ``x1`` × ``x2`` (pairs that cannot exist, a
    negative inv α_w, are left out)."""
    F = {k: np.full((len(x1), len(x2)), np.nan) for k in LIMITS}
    for i, a in enumerate(x1):
        for j, b in enumerate(x2):
            try:
                marg = limit_margins(pair(z1, z2, m, float(a), float(b), rack), sa_min, eps_min)
            except (ConstructionError, ParameterError):
                continue
            for k, v in marg.items():
                F[k][i, j] = v
    return {k: _zero_lines(x1, x2, f) for k, f in F.items()}


def _zero_lines(x1: Arr, x2: Arr, f: Arr) -> list[tuple[float, float, float, float]]:
    """Marching squares: the segments of f = 0 on the grid, interpolated linearly on the edges."""
    segs: list[tuple[float, float, float, float]] = []
    for i in range(len(x1) - 1):
        for j in range(len(x2) - 1):
            c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            v = [f[q] for q in c]
            if any(not math.isfinite(x) for x in v):
                continue
            pts = []
            for k in range(4):
                (ia, ja), (ib, jb) = c[k], c[(k + 1) % 4]
                va, vb = v[k], v[(k + 1) % 4]
                if (va > 0.0) != (vb > 0.0):
                    t = va / (va - vb)
                    pts.append(
                        (
                            float(x1[ia] + t * (x1[ib] - x1[ia])),
                            float(x2[ja] + t * (x2[jb] - x2[ja])),
                        )
                    )
            for k in range(0, len(pts) - 1, 2):
                segs.append((*pts[k], *pts[k + 1]))
    return segs
