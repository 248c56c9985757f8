"""Synthesis from a variant's design data: a ``[synthesis]`` table turned into a linkage file.

The interface is ``../shared/linkages.md``, section "Synthesis". A course-project variant gives
the output's stroke H (or the rocker's swing ψ), the coefficient of velocity change K and one or
two sizes; the student finds the link lengths by the graphical construction of the subject. Each
kind here records that construction step by step (:class:`~geomcad.construction.Construction`,
so ``--trace`` reads as the student's solution) and turns its result into the explicit linkage
file (``[frame]``, ``[drive]``, ``[[group]]``) that :func:`geomcad.linkage.parse` reads:

``slider-crank`` (crank 1 O–A, rod 2 A–B, slider 3 at B on a horizontal guide)
    θ = 180°·(K − 1)/(K + 1). The slider's extreme positions B0, B1 lie H apart on the guide
    (the x-axis, B0 at the origin); the perpendicular to the guide at B0 and the ray from B1 at
    90° − θ to B1B0 meet in P; the circle Γ through P, B0, B1 (PB1 a diameter) sees B0B1 under
    θ from every point on P's side of the guide. The line at the offset e from the guide meets Γ
    in the pivot O (the point nearer B0: its foot lies outside the stroke, as it must, so e <
    H/tan θ = the height of P). Crank and rod are in line at both extremes: l1 = (OB1 − OB0)/2,
    l2 = (OB1 + OB0)/2. With λ = l2/l1 instead of K: the stroke of the offset slider-crank,
    H(l1) = √((l1 + l2)² − e²) − √((l2 − l1)² − e²), is solved for the largest l1 (H(l1) ≥ 2·l1,
    so l1 ≤ H/2; with e = 0, l1 = H/2 and θ = 0), then B0, B1 are found on the guide by the
    circles of radii l2 − l1 and l2 + l1 about O, and θ = ∠B0OB1 is measured.
``crank-rocker`` (crank 1 O–A, coupler 2 A–B, rocker 3 B–C turning at C)
    The rocker's extreme positions CB0, CB1 are laid symmetric about the y-axis (C at the
    origin, B above it); the θ-circle Γ through B0B1 (constructed as for the slider) and its
    mirror image Γ′ over the chord give the arcs that see B0B1 under θ; the circle about C of
    radius ``frame`` meets them in the candidate pivots. A candidate is kept when its four-bar
    is a crank-rocker (Grashof, the crank shortest) and B0, B1 lie on one side of OC (one
    assembly circuit passes through both); of those, the one whose least transmission angle
    γ_min (the acute angle between coupler and rocker, least over a turn: at the crank's two
    positions in line with the frame) is largest.
``slotted-lever`` (crank 1 O–A, block 2, lever 3 turning at C, link 4 B–D, ram 5 at D)
    The lever swings by θ: its extreme positions are the tangents from C to the crank circle,
    at ±θ/2 from CO, so l1 = l_OC·sin(θ/2) (the feet A0, A1 of the perpendiculars from O). The
    lines parallel to CO at H/2 on either side meet the lever's extremes in B0, B1 (B0B1 = H,
    so l3 = CB0 = H/(2·sin(θ/2))); the ram's guide is perpendicular to CO at the middle of the
    sagitta of B's arc, so that the ram's stroke D0D1 is B0B1 = H.

Where the mechanism sits (documented choices; the checks use lengths, angles, H/ψ and K):
the slider-crank's guide is the x-axis with the pivot above it; the slotted lever's C at the
origin, O on the y-axis above it, the ram's guide above O. The guide's direction is +x where the
stroke towards +x is the slow one for the crank's sense of rotation, else −x (``angle = 180``),
so the slider's working (slow) stroke is always ``forward``. The crank-rocker's C is at the
origin with the rocker's swing about +y; its slow swing is ``forward`` (ψ rising) or
``backward`` as the crank's sense gives it, written in the emitted file where the loader knows
``[drive] working``. Point names: O, A, B (and C for the rocker; C, B, D for the slotted lever).
"""

from __future__ import annotations

import copy
import json
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

from scipy.optimize import brentq, minimize_scalar

from geomcad import tol
from geomcad.construction import Construction, Where, nearest
from geomcad.errors import FileKeyError, GeomcadError
from geomcad.geom import Arc, Circle, Line, Vec, mirror_circle
from geomcad.linkage.model import DRIVE_KEYS, MAX_LENGTH, MIN_LENGTH, _check_keys, _number

Kind = Literal["slider-crank", "crank-rocker", "slotted-lever"]
KINDS: tuple[Kind, ...] = ("slider-crank", "crank-rocker", "slotted-lever")

KEYS: dict[str, tuple[str, ...]] = {
    "slider-crank": ("kind", "stroke", "K", "lambda", "offset"),
    "crank-rocker": ("kind", "swing_deg", "K", "rocker", "frame"),
    "slotted-lever": ("kind", "stroke", "K", "frame", "rod"),
}

#: The keys of an explicit mechanism a synthesis file must not have (the synthesis finds them).
FOUND = ("frame", "group")
FOUND_DRIVE = ("pivot", "joint", "length", "output", "working")

#: K above this is a θ of practically 180°: no mechanism can be drawn.
MAX_K = 1.0e3
#: λ above this is a rod of practically infinite length.
MAX_LAMBDA = 1.0e3
#: Samples of l1 bracketing the roots of H(l1) = H (λ and e > 0).
ROOT_SAMPLES = 400

TITLES: dict[str, str] = {
    "slider-crank": "Кривошипно-ползунный механизм",
    "crank-rocker": "Кривошипно-коромысловый механизм",
    "slotted-lever": "Кулисный механизм с качающейся кулисой",
}


@dataclass(frozen=True)
class Synthesis:
    """A synthesis: its kind, the recorded construction, ``results.synthesis``, the explicit
    linkage file's data, and the names of the drawing's parts (for the sheet)."""

    kind: Kind
    construction: Construction
    results: dict[str, float]
    linkage: dict[str, Any]
    working: Literal["forward", "backward"]
    given: dict[str, float] = field(default_factory=dict)


def is_synthesis(data: Mapping[str, Any]) -> bool:
    """True for a file's data with a ``[synthesis]`` table."""
    return "synthesis" in data


def theta_of(K: float) -> float:
    """The angle of overlap θ = π·(K − 1)/(K + 1), rad."""
    return math.pi * (K - 1.0) / (K + 1.0)


def synthesize(data: Mapping[str, Any]) -> Synthesis:
    """The synthesis a file's data with ``[synthesis]`` states (see the module's docstring).

    Raises :class:`FileKeyError` naming the key for data that admit no mechanism."""
    t = data.get("synthesis")
    if not isinstance(t, dict):
        raise FileKeyError("synthesis", t, "must be a table")
    kind = t.get("kind")
    if kind not in KINDS:
        raise FileKeyError(
            "synthesis.kind", kind, f"must be one of {', '.join(map(repr, KINDS))}, not {kind!r}"
        )
    _check_keys("synthesis", t, KEYS[kind])
    for k in FOUND:
        if k in data:
            raise FileKeyError(k, data[k], "a synthesis file has no [frame] or [[group]]: the "
                               "synthesis finds the mechanism")  # fmt: skip
    drive = data.get("drive", {})
    if not isinstance(drive, dict):
        raise FileKeyError("drive", drive, "must be a table")
    for k in FOUND_DRIVE:
        if k in drive:
            why = (
                "a synthesis file has no working stroke: the synthesized mechanism works on its "
                "slow stroke, so that K comes back as given"
                if k == "working"
                else "a synthesis file's crank, pivot and output are found by the synthesis"
            )
            raise FileKeyError(f"drive.{k}", drive[k], why)
    loads = data.get("load", [])
    for i, ld in enumerate(loads if isinstance(loads, list) else [loads], start=1):
        if isinstance(ld, dict) and "working" in ld:
            raise FileKeyError(
                f"load {i}: working",
                ld["working"],
                "a synthesis file has no working stroke: the synthesized mechanism works on its "
                "slow stroke, so that K comes back as given",
            )
    if "omega" not in drive:
        raise FileKeyError("drive.omega", None, "missing (a number is required)")
    omega = _number(drive, "omega", "drive", unit="rad/s")
    sense = 1.0 if omega > 0.0 else -1.0
    pos: dict[str, Any] = {"ge": MIN_LENGTH, "le": MAX_LENGTH, "unit": "m"}
    K = None
    if "K" in t or kind != "slider-crank" or "lambda" not in t:
        K = _number(t, "K", "synthesis", le=MAX_K)
        if not K > 1.0:
            raise FileKeyError(
                "synthesis.K", K, f"must be > 1 (K = 1 has no slow stroke, θ = 0), not {K:g}"
            )
    syn: Synthesis
    if kind == "slider-crank":
        H = _number(t, "stroke", "synthesis", **pos)
        if "offset" in t and _number(t, "offset", "synthesis") < 0.0:
            raise FileKeyError(
                "synthesis.offset",
                t["offset"],
                f"must be ≥ 0 m (the pivot's distance from the guide), not {t['offset']:g}",
            )
        e = _number(t, "offset", "synthesis", default=0.0, ge=0.0, le=MAX_LENGTH, unit="m")
        if "lambda" in t:
            if K is not None:
                raise FileKeyError("synthesis.lambda", t["lambda"], "give K or lambda, not both")
            lam = _number(t, "lambda", "synthesis", le=MAX_LAMBDA)
            if not lam > 1.0:
                raise FileKeyError(
                    "synthesis.lambda",
                    lam,
                    f"must be > 1 (l_AB / l_OA: the rod longer than the crank), not {lam:g}",
                )
            syn = _slider_by_lambda(H, lam, e, sense)
        else:
            assert K is not None
            syn = _slider_by_K(H, K, e, sense)
    elif kind == "crank-rocker":
        assert K is not None
        psi = _number(t, "swing_deg", "synthesis", gt=0.0, lt=180.0, unit="°")
        l3 = _number(t, "rocker", "synthesis", **pos)
        l0 = _number(t, "frame", "synthesis", **pos)
        syn = _crank_rocker(math.radians(psi), K, l3, l0, sense)
    else:
        assert K is not None
        H = _number(t, "stroke", "synthesis", **pos)
        l0 = _number(t, "frame", "synthesis", **pos)
        rod = _number(t, "rod", "synthesis", **pos)
        syn = _slotted_lever(H, K, l0, rod, sense)
    full = _rest(data, syn)
    syn.linkage.clear()
    syn.linkage.update(full)
    return syn


def _rest(data: Mapping[str, Any], syn: Synthesis) -> dict[str, Any]:
    """The file's other tables, carried into the explicit file ([drive] merged with the
    synthesis' crank; a load on the output told the working stroke the synthesis took)."""
    out: dict[str, Any] = {}
    for k, v in data.items():
        if k in ("synthesis", "drive"):
            continue
        out[k] = copy.deepcopy(v)
    out.setdefault("title", TITLES[syn.kind])
    drive = dict(syn.linkage["drive"])
    drive.update(copy.deepcopy(data.get("drive", {})))
    if "working" in DRIVE_KEYS:  # the second round's [drive] working (linkages.md)
        drive["working"] = syn.working
    out["drive"] = drive
    output = syn.linkage["drive"]["output"]
    loads = out.get("load")
    if isinstance(loads, list):
        for ld in loads:
            if isinstance(ld, dict) and ld.get("point") == output:
                ld["working"] = syn.working
    # the order of a linkage file: top-level keys, [frame], [drive], [[group]], the rest
    first: dict[str, Any] = {k: out.pop(k) for k in ("title", "gravity") if k in out}
    theirs = out.pop("point", [])
    points = [*syn.linkage.get("point", []), *(theirs if isinstance(theirs, list) else [theirs])]
    more = {"point": points} if points else {}
    return {**first, "frame": syn.linkage["frame"], "drive": drive,
            "group": syn.linkage["group"], **more, **out}  # fmt: skip


def _slow_forward(sense: float, phi_from: float, phi_to: float) -> bool:
    """True when the crank's turn (in its sense of rotation) from ``phi_from`` to ``phi_to``
    exceeds half a turn: the stroke between them is the slow one."""
    return (sense * (phi_to - phi_from)) % (2.0 * math.pi) > math.pi


def _dead_centres(c: Construction, Op: Vec, l1: float, B_fold: Vec, B_ext: Vec) -> None:
    """Record the crank's two dead-centre positions: A0 on the far side of O from the folded
    B0 (crank and rod overlapping), A1 on OB1 (in line), each with its crank and rod."""
    A0 = c.point("A0", Op - (B_fold - Op).unit() * l1, role="extreme",
                 op="on B0O beyond O at l1: crank and rod overlap", kind="syn_fold",
                 args={"o": Op, "b": B_fold})  # fmt: skip
    A1 = c.point("A1", Op + (B_ext - Op).unit() * l1, role="extreme",
                 op="on OB1 at l1: crank and rod in line", kind="syn_ext",
                 args={"o": Op, "b": B_ext})  # fmt: skip
    c.segment("OA0", Op, A0, role="extreme")
    c.segment("A0B0", A0, B_fold, role="extreme")
    c.segment("OA1", Op, A1, role="extreme")
    c.segment("A1B1", A1, B_ext, role="extreme")
    c.circle("k1", Op, l1, role="aux", r_name="l1", note="the crank's circle")


def _theta_circle(
    c: Construction,
    B0: Vec,
    B1: Vec,
    theta: float,
    side: float,
    role: str = "construction",
    chord: Line | None = None,
) -> tuple[Line, Vec, Circle]:
    """The chord B0B1, the perpendicular n0 at B0, the ray r1 from B1 at 90° − θ to B1B0 (to
    the left of B0 → B1 where ``side`` > 0) meeting it in P, and the circle Γ through P, B0, B1."""
    if chord is None:  # the slider's guide is the chord already
        chord = c.line_through("B0B1", B0, B1, role="hidden")
    n0 = c.perpendicular("n0", chord, B0, note="perpendicular to B0B1 at B0")
    # B1 → B0 turned cw by 90° − θ points to the left of B0 → B1
    r1 = c.ray_at_angle("r1", B1, B0, -side * (math.pi / 2.0 - theta), "90° – θ")
    P = c.intersect("P", n0, r1, role="construction")
    gamma = c.circle_through("Γ", P, B0, B1, role=role,
                             note="PB1 a diameter: B0B1 seen under θ from P's side")  # fmt: skip
    return chord, P, gamma


def _theta_step(c: Construction, K: float) -> float:
    theta = theta_of(K)
    c.value("θ", theta, "180°·(K − 1)/(K + 1), in radians", kind="syn_theta",
            args={"K": K, "deg": math.degrees(theta)},
            note=f"θ = {math.degrees(theta):.6g}° at K = {K:g}")  # fmt: skip
    return theta


# --- the slider-crank ------------------------------------------------------------------------


def _slider_by_K(H: float, K: float, e: float, sense: float) -> Synthesis:
    theta = theta_of(K)
    if e == 0.0:
        raise FileKeyError(
            "synthesis.offset",
            e,
            "must be > 0 with K: a central slider-crank has K = 1 (give lambda for e = 0)",
        )
    e_max = H / math.tan(theta)
    if e >= e_max:
        raise FileKeyError(
            "synthesis.offset",
            e,
            f"too large for H and K: the pivot's foot must lie outside the stroke, so e < "
            f"H/tan θ = {e_max:.6g} m (θ = {math.degrees(theta):.6g}°), not {e:g} m",
        )
    first = _slider_K_construction(H, K, e, 1.0)
    Op, A0, A1 = (first[n] for n in ("O", "A0", "A1"))
    # the slow stroke runs forward (+x, B0 → B1): the pivot below the guide where it would not
    # the slow stroke is the working one: forward along the guide's direction, +x where the
    # stroke B0 → B1 is the slow one, else −x
    way = 1.0 if _slow_forward(sense, (A0 - Op).angle, (A1 - Op).angle) else -1.0
    c = first
    res = {"theta_deg": math.degrees(theta), "l1": c["l1"], "l2": c["l2"]}
    return Synthesis("slider-crank", c, res, _slider_file(c, way), "forward",
                     {"stroke": H, "K": K, "offset": e})  # fmt: skip


def _slider_K_construction(H: float, K: float, e: float, side: float) -> Construction:
    c = Construction("synthesis of the slider-crank by H, K and e (the θ-circle)")
    theta = _theta_step(c, K)
    B0 = c.point("B0", (0.0, 0.0), role="given", op="an extreme position of the slider",
                 kind="syn_given_point", args={"what": "@slider_end"})  # fmt: skip
    B1 = c.point("B1", (H, 0.0), role="given", op="B0 + H along the guide", kind="syn_stroke",
                 args={"p": B0, "h": H})  # fmt: skip
    guide = c.line_through("x-x", B0, B1, role="aux", note="the slider's guide")
    _, _, gamma = _theta_circle(c, B0, B1, theta, side, chord=guide)
    m = c.parallel("m", guide, offset=side * e, op="line ∥ the guide at e",
                   kind="syn_offset_line", args={"e": e})  # fmt: skip
    Op = c.intersect("O", gamma, m, nearest(B0, "B0 (its foot outside the stroke)"),
                    role="result", kind="syn_pivot", args={"a": gamma, "b": m})  # fmt: skip
    _lengths(c, Op, B0, B1)
    _dead_centres(c, Op, c["l1"], B0, B1)
    return c


def _lengths(c: Construction, Op: Vec, B0: Vec, B1: Vec) -> None:
    """OB0, OB1 measured; l1 and l2 as their half difference and half sum (B0 folded, B1 in
    line)."""
    d0 = c.value("OB0", Op.dist(B0), "|OB0| = l2 − l1", (Op, B0), kind="syn_measure",
                 args={"a": Op, "b": B0})  # fmt: skip
    d1 = c.value("OB1", Op.dist(B1), "|OB1| = l1 + l2", (Op, B1), kind="syn_measure",
                 args={"a": Op, "b": B1})  # fmt: skip
    c.value("l1", (d1 - d0) / 2.0, "(OB1 − OB0) / 2", kind="syn_half_difference",
            args={"va": d1, "vb": d0, "v": (d1 - d0) / 2.0})  # fmt: skip
    c.value("l2", (d1 + d0) / 2.0, "(OB1 + OB0) / 2", kind="syn_half_sum",
            args={"va": d1, "vb": d0, "v": (d1 + d0) / 2.0})  # fmt: skip


def slider_stroke(l1: float, lam: float, e: float) -> float:
    """The stroke of the offset slider-crank: √((l1 + l2)² − e²) − √((l2 − l1)² − e²)."""
    l2 = lam * l1
    return math.sqrt((l1 + l2) ** 2 - e * e) - math.sqrt(max((l2 - l1) ** 2 - e * e, 0.0))


def largest_l1(H: float, lam: float, e: float) -> float | None:
    """The largest crank length whose stroke is H (λ, e given), or ``None``.

    H(l1) ≥ 2·l1 (the offset lengthens the stroke), so every root lies in [e/(λ − 1), H/2];
    H falls from the smallest l1 (the rod ⊥ the guide at the folded dead centre) to a least
    stroke and then rises: the largest root is on the rising branch."""
    if e == 0.0:
        return H / 2.0
    lo, hi = e / (lam - 1.0), H / 2.0
    if hi < lo:
        return None

    def f(x: float) -> float:
        return slider_stroke(x, lam, e) - H

    if f(hi) == 0.0:
        return hi
    best = minimize_scalar(
        f, bounds=(lo, hi), method="bounded", options={"xatol": tol.REL_LENGTH * hi}
    )
    x_min = float(best.x)
    # the sampled least (and the ends), in case the bounded search stopped on a shoulder
    n = ROOT_SAMPLES
    xs = [lo + (hi - lo) * i / n for i in range(n + 1)]
    for x in xs:
        if f(x) < f(x_min):
            x_min = x
    if f(x_min) > 0.0:
        return None
    if f(x_min) == 0.0:
        return x_min
    root: float = brentq(f, x_min, hi, xtol=tol.REL_LENGTH * hi, rtol=4.0 * 2.0**-52)
    return root


def _slider_by_lambda(H: float, lam: float, e: float, sense: float) -> Synthesis:
    l1 = largest_l1(H, lam, e)
    if l1 is None:
        lo, hi = e / (lam - 1.0), H / 2.0
        if hi < lo:
            why = (
                f"no crank length gives H = {H:g} m: with λ = {lam:g} the crank must be at "
                f"least e/(λ − 1) = {lo:.6g} m, whose stroke exceeds H"
            )
        else:
            least = minimize_scalar(
                lambda x: slider_stroke(x, lam, e), bounds=(lo, hi), method="bounded"
            )
            why = (
                f"no crank length gives H = {H:g} m with λ = {lam:g} and e = {e:g} m: the "
                f"least stroke is {float(least.fun):.6g} m"
            )
        raise FileKeyError("synthesis.lambda", lam, why)
    first = _slider_lambda_construction(H, lam, e, l1, 1.0)
    Op, A0, A1 = (first[n] for n in ("O", "A0", "A1"))
    way = 1.0 if e == 0.0 or _slow_forward(sense, (A0 - Op).angle, (A1 - Op).angle) else -1.0
    c = first
    res = {"theta_deg": math.degrees(c["θ"]), "l1": c["l1"], "l2": c["l2"]}
    return Synthesis("slider-crank", c, res, _slider_file(c, way), "forward",
                     {"stroke": H, "lambda": lam, "offset": e})  # fmt: skip


def _slider_lambda_construction(
    H: float, lam: float, e: float, l1: float, side: float
) -> Construction:
    c = Construction("synthesis of the slider-crank by H, λ and e")
    l1 = c.value("l1", l1, "the largest l1 with √((l1 + λl1)² − e²) − √((λl1 − l1)² − e²) = H",
                 kind="syn_l1_lambda", args={"H": H, "lam": lam, "e": e, "v": l1})  # fmt: skip
    l2 = c.value("l2", lam * l1, "λ·l1", kind="syn_l2_lambda", args={"lam": lam, "v": lam * l1})
    g0 = c.point("G", (0.0, 0.0), role="hidden", op="the guide's origin", kind="given")
    guide = c.line("x-x", g0, (1.0, 0.0), "the slider's guide", role="aux", kind="syn_guide")
    Op = c.point("O", (0.0, side * e), role="result", op="at e from the guide",
                kind="syn_pivot_at", args={"e": e})  # fmt: skip
    ahead = Where(lambda q: q.x > Op.x, "ahead of O's foot along the guide")
    k0 = c.circle("k0", Op, l2 - l1, role="hidden", r_name="l2 – l1")
    kk = c.circle("k2", Op, l1 + l2, role="hidden", r_name="l1 + l2")
    B0 = c.intersect("B0", guide, k0, ahead, role="result", kind="syn_extreme",
                     args={"r": "l_{2} – l_{1}", "o": Op})  # fmt: skip
    B1 = c.intersect("B1", guide, kk, ahead, role="result", kind="syn_extreme",
                     args={"r": "l_{1} + l_{2}", "o": Op})  # fmt: skip
    u0, u1 = B0 - Op, B1 - Op
    th = abs(math.atan2(u0.cross(u1), u0.dot(u1)))
    c.value("θ", th, "∠B0OB1", (B0, Op, B1), kind="syn_angle", args={"deg": math.degrees(th)})
    if e > 0.0:
        c.circle_through("Γ", Op, B0, B1, role="aux", note="the θ-circle: B0B1 seen under θ")
    _dead_centres(c, Op, l1, B0, B1)
    return c


def _slider_file(c: Construction, way: float) -> dict[str, Any]:
    """The explicit file: the guide along +x (``way`` > 0) or −x, so that its forward stroke
    is the slow one; B ahead of A's foot is then "forward" or "backward"."""
    Op = c["O"]
    return {
        "frame": {"O": [Op.x, Op.y]},
        "drive": {"pivot": "O", "joint": "A", "length": c["l1"], "output": "B"},
        "group": [
            {"kind": "RRP", "links": [2, 3], "joint": "B", "end": "A", "length": c["l2"],
             "guide": {"through": [0.0, 0.0], "angle": 0.0 if way > 0 else 180.0},
             "assembly": "forward" if way > 0 else "backward"},
        ],
    }  # fmt: skip


# --- the crank-rocker ------------------------------------------------------------------------


@dataclass(frozen=True)
class _Candidate:
    Op: Vec
    l1: float
    l2: float
    gamma_min: float
    fits: bool
    why: str


def gamma_min(l1: float, l2: float, l3: float, l0: float) -> float:
    """The least over a turn of the acute angle between coupler and rocker (rad): at the
    crank's positions in line with the frame, |AC| = l0 ∓ l1."""
    out = math.pi / 2.0
    for d in (l0 - l1, l0 + l1):
        cg = (l2 * l2 + l3 * l3 - d * d) / (2.0 * l2 * l3)
        g = math.acos(max(-1.0, min(1.0, cg)))
        out = min(out, g, math.pi - g)
    return out


def is_crank_rocker(l1: float, l2: float, l3: float, l0: float) -> bool:
    """Grashof's condition with the crank the shortest link, strictly."""
    longest = max(l0, l2, l3)
    return l1 < min(l0, l2, l3) and l1 + longest < l0 + l2 + l3 - longest


def _on_side(line: Line, sign: float) -> Callable[[Vec], bool]:
    return lambda q: line.side(q) * sign > 0.0


def _candidate(Op: Vec, B0: Vec, B1: Vec, C: Vec, l3: float, l0: float) -> _Candidate:
    d0, d1 = Op.dist(B0), Op.dist(B1)
    l1, l2 = abs(d1 - d0) / 2.0, (d1 + d0) / 2.0
    if not is_crank_rocker(l1, l2, l3, l0):
        return _Candidate(Op, l1, l2, 0.0, False, "not a crank-rocker")
    oc = Line.through(Op, C)
    if oc.side(B0) * oc.side(B1) <= 0.0:
        return _Candidate(Op, l1, l2, 0.0, False, "B0 and B1 on two sides of OC")
    return _Candidate(Op, l1, l2, gamma_min(l1, l2, l3, l0), True, "")


def _crank_rocker(psi: float, K: float, l3: float, l0: float, sense: float) -> Synthesis:
    c = Construction("synthesis of the crank-rocker by ψ, K, the rocker and the frame")
    theta = _theta_step(c, K)
    C = c.point("C", (0.0, 0.0), role="given", op="the rocker's pivot", kind="syn_given_point",
                args={"what": "@rocker_pivot"})  # fmt: skip
    B0 = c.point("B0", Vec.polar(l3, math.pi / 2.0 + psi / 2.0), role="given",
                 op="C + l3 at 90° + ψ/2", kind="syn_rocker_end",
                 args={"c": C, "sign": "+"})  # fmt: skip
    B1 = c.point("B1", Vec.polar(l3, math.pi / 2.0 - psi / 2.0), role="given",
                 op="C + l3 at 90° − ψ/2", kind="syn_rocker_end",
                 args={"c": C, "sign": "–"})  # fmt: skip
    c.record("kB", "the arc of B", Arc(Circle(C, l3), math.pi / 2.0 - psi / 2.0 - 0.15,
             math.pi / 2.0 + psi / 2.0 + 0.15), (C,), role="aux", kind="syn_arc",
             args={"c": C})  # fmt: skip
    c.segment("CB0", C, B0, role="extreme")
    c.segment("CB1", C, B1, role="extreme")
    # Γ on the side away from C (left of B0 → B1, which runs cw about C), Γ′ its mirror
    chord, P, gamma = _theta_circle(c, B0, B1, theta, 1.0)
    gamma_m = c.record("Γ'", "mirror of Γ over B0B1", mirror_circle(gamma, chord), (gamma, chord),
                       note="the other circle that sees B0B1 under θ", kind="syn_mirror",
                       args={"a": gamma, "line": chord})  # fmt: skip
    kO = c.circle("kO", C, l0, role="aux", r_name="l0", note="the pivot's locus at the frame")
    p_side = chord.side(P)
    found: list[_Candidate] = []
    for circ, name, sign in ((gamma, "Γ", 1.0), (gamma_m, "Γ'", -1.0)):
        on_arc = Where(
            _on_side(chord, sign * p_side), f"on the arc of {name} that sees B0B1 under θ"
        )
        pts = c.intersections(f"{name}∩kO", circ, kO, on_arc, role="hidden", allow_empty=True)
        found += [_candidate(q, B0, B1, C, l3, l0) for q in pts]
    fits = [cd for cd in found if cd.fits]
    if not fits:
        why = (
            f"no crank-rocker pivot fits: the circle of radius frame = {l0:g} m about C meets "
            "no arc that sees B0B1 under θ"
            if not found
            else f"no crank-rocker pivot fits: of the {len(found)} points of the θ-arcs at "
            f"frame = {l0:g} m from C, none gives a crank-rocker "
            f"({'; '.join(sorted({cd.why for cd in found}))})"
        )
        raise FileKeyError("synthesis.frame", l0, why)
    best = max(fits, key=lambda cd: cd.gamma_min)
    Op = c.point("O", best.Op, role="result", op="of the pivots that fit, the one with the "
                "largest γ_min", kind="syn_pick", args={"n": len(fits)})  # fmt: skip
    for i, cd in enumerate(fits):
        if cd is not best:
            c.point(f"O({i + 1})", cd.Op, role="aux", op=f"another pivot that fits, γ_min = "
                    f"{math.degrees(cd.gamma_min):.4g}°", kind="syn_other",
                    args={"g": math.degrees(cd.gamma_min)})  # fmt: skip
    d0, d1 = Op.dist(B0), Op.dist(B1)
    fold, ext = ("B0", "B1") if d0 <= d1 else ("B1", "B0")
    Bf, Be = c[fold], c[ext]
    dn = c.value(f"O{fold}", min(d0, d1), f"|O{fold}| = l2 − l1", (Op, Bf), kind="syn_measure",
                 args={"a": Op, "b": Bf})  # fmt: skip
    dx = c.value(f"O{ext}", max(d0, d1), f"|O{ext}| = l1 + l2", (Op, Be), kind="syn_measure",
                 args={"a": Op, "b": Be})  # fmt: skip
    l1 = c.value("l1", (dx - dn) / 2.0, f"(O{ext} − O{fold}) / 2", kind="syn_half_difference",
                 args={"va": dx, "vb": dn, "v": (dx - dn) / 2.0})  # fmt: skip
    l2 = c.value("l2", (dx + dn) / 2.0, f"(O{ext} + O{fold}) / 2", kind="syn_half_sum",
                 args={"va": dx, "vb": dn, "v": (dx + dn) / 2.0})  # fmt: skip
    g = c.value("γmin", best.gamma_min, "min over a turn of the acute angle between AB and BC",
                kind="syn_gamma", args={"deg": math.degrees(best.gamma_min)})  # fmt: skip
    _rocker_dead_centres(c, Op, l1, Bf, Be, fold)
    A_ext = Op + (Be - Op).unit() * l1
    branch = "left" if Line.through(A_ext, C).side(Be) > 0.0 else "right"
    # the crank angles at the rocker's extremes: B1 (ψ least) and B0 (ψ largest)
    a_at = {ext: (Be - Op).angle, fold: (Op - Bf).angle}
    working: Literal["forward", "backward"] = (
        "forward" if _slow_forward(sense, a_at["B1"], a_at["B0"]) else "backward"
    )
    res = {"theta_deg": math.degrees(theta), "l1": l1, "l2": l2,
           "gamma_min_deg": math.degrees(g)}  # fmt: skip
    lk = {
        "frame": {"O": [Op.x, Op.y], "C": [C.x, C.y]},
        "drive": {"pivot": "O", "joint": "A", "length": l1, "output": "B"},
        "group": [{"kind": "RRR", "links": [2, 3], "joint": "B", "ends": ["A", "C"],
                   "lengths": [l2, l3], "assembly": branch}],
    }  # fmt: skip
    given = {"swing_deg": math.degrees(psi), "K": K, "rocker": l3, "frame": l0}
    return Synthesis("crank-rocker", c, res, lk, working, given)


def _rocker_dead_centres(c: Construction, Op: Vec, l1: float, Bf: Vec, Be: Vec, fold: str) -> None:
    A_f = Op - (Bf - Op).unit() * l1
    A_e = Op + (Be - Op).unit() * l1
    nf, ne = ("A0", "A1") if fold == "B0" else ("A1", "A0")
    bf, be = fold, ("B1" if fold == "B0" else "B0")
    c.point(nf, A_f, role="extreme", op=f"on {bf}O beyond O at l1: crank and coupler overlap",
            kind="syn_fold", args={"o": Op, "b": Bf})  # fmt: skip
    c.point(ne, A_e, role="extreme", op=f"on O{be} at l1: crank and coupler in line",
            kind="syn_ext", args={"o": Op, "b": Be})  # fmt: skip
    for a, b, pa, pb in ((nf, bf, A_f, Bf), (ne, be, A_e, Be)):
        c.segment(f"O{a}", Op, pa, role="extreme")
        c.segment(f"{a}{b}", pa, pb, role="extreme")
    c.circle("k1", Op, l1, role="aux", r_name="l1", note="the crank's circle")


# --- the slotted lever -----------------------------------------------------------------------


def _slotted_lever(H: float, K: float, l0: float, rod: float, sense: float) -> Synthesis:
    theta = theta_of(K)
    l3 = H / (2.0 * math.sin(theta / 2.0))
    sag = l3 * (1.0 - math.cos(theta / 2.0))
    if not rod > sag / 2.0:
        raise FileKeyError(
            "synthesis.rod",
            rod,
            f"too short: the ram's guide lies half the sagitta f = {sag:.6g} m from B's extreme "
            f"positions, so the rod must be longer than f/2 = {sag / 2.0:.6g} m",
        )
    first = _lever_construction(H, K, l0, rod, 1.0)
    Op, A0, A1 = (first[n] for n in ("O", "A0", "A1"))
    way = 1.0 if _slow_forward(sense, (A0 - Op).angle, (A1 - Op).angle) else -1.0
    c = first
    res = {"theta_deg": math.degrees(theta), "l1": c["l1"], "l3": c["l3"]}
    Op, C, yg = c["O"], c["C"], c["x-x"].p.y
    lk = {
        "frame": {"O": [Op.x, Op.y], "C": [C.x, C.y]},
        "drive": {"pivot": "O", "joint": "A", "length": c["l1"], "output": "D"},
        "group": [
            {"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C", "offset": 0.0},
            {"kind": "RRP", "links": [4, 5], "joint": "D", "end": "B", "length": rod,
             "guide": {"through": [0.0, yg], "angle": 0.0 if way > 0 else 180.0},
             "assembly": "forward" if way > 0 else "backward"},
        ],
        "point": [{"name": "B", "link": 3, "from": "C", "toward": "A", "along": c["l3"]}],
    }  # fmt: skip
    return Synthesis("slotted-lever", c, res, lk, "forward",
                     {"stroke": H, "K": K, "frame": l0, "rod": rod})  # fmt: skip


def _lever_construction(H: float, K: float, l0: float, rod: float, side: float) -> Construction:
    c = Construction("synthesis of the slotted lever by H, K, the frame and the rod")
    theta = _theta_step(c, K)
    C = c.point("C", (0.0, 0.0), role="given", op="the lever's pivot", kind="syn_given_point",
                args={"what": "@lever_pivot"})  # fmt: skip
    Op = c.point("O", (0.0, side * l0), role="given", op="C + l0 along the axis CO",
                kind="syn_frame", args={"c": C})  # fmt: skip
    axis = c.line_through("CO", C, Op, role="aux")
    # the lever's extremes at θ/2 either side of CO: B0 on the left (x < 0)
    t0 = c.ray_at_angle("t0", C, Op, side * theta / 2.0, "θ/2", role="construction")
    t1 = c.ray_at_angle("t1", C, Op, -side * theta / 2.0, "θ/2", role="construction")
    n0 = c.perpendicular("n0", t0, Op, role="hidden")
    n1 = c.perpendicular("n1", t1, Op, role="hidden")
    A0 = c.intersect("A0", t0, n0, role="extreme", kind="syn_foot", args={"o": Op, "t": t0})
    A1 = c.intersect("A1", t1, n1, role="extreme", kind="syn_foot", args={"o": Op, "t": t1})
    l1 = c.value("l1", Op.dist(A0), "|OA0| = l0·sin(θ/2)", (Op, A0), kind="syn_crank_lever",
                 args={"o": Op, "a": A0, "v": Op.dist(A0)})  # fmt: skip
    # B0 on the left of C → O (with t0), B1 on the right
    p0 = c.parallel("p0", axis, offset=side * H / 2.0, op="line ∥ CO at H/2",
                    kind="syn_half_stroke", args={"h": H / 2.0}, role="hidden")  # fmt: skip
    p1 = c.parallel("p1", axis, offset=-side * H / 2.0, op="line ∥ CO at H/2",
                    kind="syn_half_stroke", args={"h": H / 2.0}, role="hidden")  # fmt: skip
    B0 = c.intersect("B0", t0, p0, role="result", kind="syn_lever_end", args={"t": t0, "p": p0})
    B1 = c.intersect("B1", t1, p1, role="result", kind="syn_lever_end", args={"t": t1, "p": p1})
    l3 = c.value("l3", C.dist(B0), "|CB0| = H / (2·sin(θ/2))", (C, B0), kind="syn_lever",
                 args={"c": C, "b": B0, "v": C.dist(B0)})  # fmt: skip
    c.record("kB", "the arc of B", Arc(Circle(C, l3), *_arc_span(C, B0, B1, 0.15)), (C,),
             role="aux", kind="syn_arc", args={"c": C})  # fmt: skip
    sag = l3 * (1.0 - math.cos(theta / 2.0))
    yg = side * (l3 - sag / 2.0)
    guide = c.line("x-x", Vec(0.0, yg), (1.0, 0.0), "the ram's guide ⊥ CO at half the sagitta",
                   role="aux", kind="syn_ram_guide", args={"f": sag})  # fmt: skip
    ahead = Where(lambda q: True, "ahead of B along the guide")  # the text of the rule below
    D0 = c.intersect("D0", guide, c.circle("kD0", B0, rod, role="hidden", r_name="l_BD"),
                     Where(lambda q: q.x > B0.x, ahead.text), role="extreme",
                     kind="syn_ram_end", args={"b": B0})  # fmt: skip
    D1 = c.intersect("D1", guide, c.circle("kD1", B1, rod, role="hidden", r_name="l_BD"),
                     Where(lambda q: q.x > B1.x, ahead.text), role="extreme",
                     kind="syn_ram_end", args={"b": B1})  # fmt: skip
    c.value("H_check", D0.dist(D1), "|D0D1| = |B0B1| = H", (D0, D1), kind="syn_check_h",
            args={"v": D0.dist(D1)})  # fmt: skip
    pairs = (("O", "A0", Op, A0), ("O", "A1", Op, A1), ("C", "B0", C, B0), ("C", "B1", C, B1),
             ("B0", "D0", B0, D0), ("B1", "D1", B1, D1))  # fmt: skip
    for a, b, pa, pb in pairs:
        c.segment(f"{a}{b}", pa, pb, role="extreme")
    c.circle("k1", Op, l1, role="aux", r_name="l1", note="the crank's circle")
    return c


def _arc_span(C: Vec, B0: Vec, B1: Vec, pad: float) -> tuple[float, float]:
    a0, a1 = (B0 - C).angle, (B1 - C).angle
    lo, hi = (a1, a0) if (a0 - a1) % (2.0 * math.pi) < math.pi else (a0, a1)
    return lo - pad, hi + pad


def attach(s: Any, syn: Synthesis, results: dict[str, Any], protocol: Any) -> None:
    """Keep the synthesis with the solved linkage ``s`` (:func:`of`): ``results.synthesis``,
    and its construction first in the protocol (``protocol.parts``)."""
    rest = dict(results)
    results.clear()
    results["synthesis"] = dict(syn.results)  # first, as the solution starts with it
    results.update(rest)
    protocol.parts.insert(0, syn.construction)
    object.__setattr__(s, "_synthesis", syn)


def of(s: object) -> Synthesis | None:
    """The synthesis a solved linkage was found by (``None`` for an explicit file)."""
    syn = getattr(s, "_synthesis", None)
    return syn if isinstance(syn, Synthesis) else None


# --- the explicit file -----------------------------------------------------------------------


def emit(syn: Synthesis) -> str:
    """The explicit linkage file the synthesis found, as TOML text (floats written in full, so
    that it loads to the same mechanism)."""
    found = ", ".join(f"{k} = {v:.9g}" for k, v in syn.results.items())
    return f"# The mechanism found by the synthesis ({syn.kind}): {found}\n" + dumps(syn.linkage)


def emitted(file_id: str, solved: object) -> str:
    """``solve FILE --emit-linkage``: the explicit file of the synthesis that found ``solved``;
    a :class:`GeomcadError` for anything that is no file with ``[synthesis]``."""
    syn = of(solved)
    if syn is None:
        raise GeomcadError("--emit-linkage: the file has no [synthesis] table to find a linkage by")
    return emit(syn)


def dumps(data: Mapping[str, Any]) -> str:
    """A linkage file's data as TOML: top-level values, then tables (``[frame]``, ``[links.2]``)
    and arrays of tables (``[[group]]``) in the data's order, arrays and small tables inline."""
    top: list[str] = []
    rest: list[str] = []
    for k, v in data.items():
        if isinstance(v, list) and v and all(isinstance(t, dict) for t in v):
            for t in v:
                rest.append(f"\n[[{_key(k)}]]")
                rest += [f"{_key(kk)} = {_value(vv)}" for kk, vv in t.items()]
        elif isinstance(v, dict):
            rest += _table(_key(k), v)
        else:
            top.append(f"{_key(k)} = {_value(v)}")
    return "\n".join([*top, *rest]) + "\n"


def _table(name: str, t: Mapping[str, Any]) -> list[str]:
    plain = {k: v for k, v in t.items() if not isinstance(v, dict)}
    subs = {k: v for k, v in t.items() if isinstance(v, dict)}
    out = (
        [f"\n[{name}]", *(f"{_key(k)} = {_value(v)}" for k, v in plain.items())]
        if plain or not subs
        else []
    )
    for k, v in subs.items():
        out += _table(f"{name}.{_key(str(k))}", v)
    return out


def _key(k: str) -> str:
    return (
        k
        if k and all(ch.isascii() and (ch.isalnum() or ch in "_-") for ch in k)
        else json.dumps(k, ensure_ascii=False)
    )


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(str(k))} = {_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"no TOML form for {v!r}")


#: The slider's and the rocker's point: what a [[load]] or --measured may name.
OUTPUTS: Mapping[str, str] = {"slider-crank": "B", "crank-rocker": "B", "slotted-lever": "D"}
