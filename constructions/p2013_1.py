"""2013-1 · Vulcanizer-lid mechanism: structure and the pusher's dead position.

The seed's figure is lost; the model (problems.md) that matches every number in its text:
lever 1 with a straight slot turns about O and is driven through a four-bar (crank 2 on the frame
at A, coupler 3 from B to C on the lever); roller 6 on pusher 7 runs in the slot; pusher 7 (T)
slides in the frame along its path; link 5 joins the pusher (F) to lid 4, hinged on the frame at D.
That is n = 7, p₅ = 9 (O, A, B, C, M, T, D, E, F), p₄ = 1 (K: roller 6 in the slot of lever 1).

Conventions (problems.md): O is the origin; the slot's points p satisfy p·(−sin θ1, cos θ1) = e;
the pusher path's points satisfy p·(−sin ψ, cos ψ) = h; V_T is measured along (cos ψ, sin ψ);
ω1 is positive counter-clockwise.

**Structure.** Chebyshev's count of the scheme, with its local mobility (the roller's spin about M)
and redundant constraints found from the pairs' velocity conditions (geomcad.structure); the
higher pair K replaced by a substitute link 8 (a slider block in the slot, hinged to the roller at
M: the roller's centre of curvature is M, the slot's is at infinity); the seed's own route (the
roller taken out first, so the block is joined to the pusher); Assur groups of the replaced
mechanism (the roller's spin taken out), crank 2 driving.

**Kinematics.** The pusher's point M is where the slot crosses the path. The velocity plan of the
replaced mechanism: V_M6 = V_M1 + V_M6M1, with V_M1 = ω1 × OM ⊥ OM, V_M6M1 ∥ slot, V_M6 = V_T ∥
path. V_T = 0 when V_M1 = −V_M6M1, i.e. V_M1 ∥ slot, i.e. OM ⊥ slot: M is then the foot of the
perpendicular from O to the slot. The slot stays at distance |e| from O, so it touches the circle
of radius |e| about O at that foot: the zero positions are the points M* where the pusher path
meets that circle, and the slot is the tangent there (ML ⊥ MO, L a point of the slot). Check
formula: θ1 = ψ ± arccos(h/e).

Choices settled here (they change no published number):
- the scheme is drawn in the given position θ1; the four-bar, the lid and link 5 are placed at
  fixed proportions of |e| in the lever's and the path's frames (their sizes are not given);
- the sheet builds the zero position nearest to the given θ1 (the lever rocks about it); both are
  reported;
- V_T also vanishes when ω1 = 0, at the driving four-bar's extreme positions; their crank angles
  need the four-bar's dimensions, which the seed does not give, so they are named, not computed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
from scipy.optimize import brentq

from geomcad import tol
from geomcad.construction import Construction
from geomcad.errors import ConstructionError, NoIntersection, ParallelLines, ParameterError
from geomcad.geom import Circle, Vec
from geomcad.problem import Build, ParamValue
from geomcad.structure import (
    Decomposition,
    Link,
    Mechanism,
    Mobility,
    Removal,
    Replacement,
    assur_groups,
    chebyshev,
    higher,
    mobility,
    prismatic,
    remove_local_mobilities,
    replace_higher_pairs,
    revolute,
)
from geomcad.units import to_deg, wrap_deg

EXPLAIN = (
    "before 2, after 1 (the seed) against 2 and 2 (the standard rule): replacing a higher pair "
    "adds one link and two lower pairs, 3 − 2·2 + 1 = 0, so W cannot change. The seed's 2 counts "
    "the roller's free spin about M, a local mobility that moves nothing; its 1 is counted after "
    "the roller was taken out (the roller and its pin: n − 1, p5 − 1) or, what is the same, made "
    "the slider block of the substitute pair. Counted the same way both times, W = 2 before and "
    "after with W_local = 1, or W = 1 before and after without the roller: W_true = 1"
)

FOUR_BAR_NOTE = (
    "V_T = 0 also where ω1 = 0, at the extreme positions of the driving four-bar (crank 2, "
    "coupler 3, lever 1); its dimensions are not given, so those positions are not computed"
)

#: m → mm for the operands of the order of construction
MM = 1000.0

# The scheme's proportions, in units of |e| (drawing choices; they change no result).
#: lever 1's pin C, and the frame pivot A and crank pin B of the four-bar, in the lever's frame
#: (along the slot, along the slot's normal): a crank-rocker, crank 2 the shortest link.
LEVER_C = (-0.30, -1.30)
FOUR_BAR_A = (-1.90, -1.50)
FOUR_BAR_B = (-1.978, -1.057)
#: the pusher's pin F, the lid's pin E and hinge D, in the path's frame (along the path from M,
#: away from O across it).
PUSHER_F = (1.6, 0.0)
PUSHER_GUIDE = (0.9, 0.0)
LID_E = (2.2, 0.7)
LID_D = (2.5, 1.6)
#: the roller's radius, and how far the slot runs past M and past the foot N of O's perpendicular
ROLLER_R = 0.12
SLOT_PAST = 0.8

#: Sweep of V_T/ω1 over a turn: samples (offset half a step from the slot ∥ path positions).
SWEEP = 7200


@dataclass(frozen=True)
class ZeroPosition:
    """A position with V_T = 0: slot direction θ1, M* (foot of O's perpendicular on the slot)."""

    theta1: float
    M: Vec
    u1: Vec  # slot direction
    L: Vec  # the slot's end point on lever 1


@dataclass(frozen=True)
class Geometry:
    """The solved model besides the recorded steps: the mechanism before and after the
    replacement, the decomposition, the scheme's points and the zero positions."""

    e: float
    psi: float
    h: float
    theta1: float
    counts_mode: bool
    counts: tuple[int, int, int, int]
    before: Mechanism
    replaced: Replacement
    seed_route: Mechanism
    no_roller: Removal
    mob_before: Mobility
    mob_after: Mobility
    mob_seed: Mobility
    decomposition: Decomposition
    points: dict[str, Vec]
    zeros: tuple[ZeroPosition, ...]
    built: int  # index into zeros of the position the sheet builds
    sweep_zeros_deg: tuple[float, ...]


def _frames(theta1: float, psi: float) -> tuple[Vec, Vec, Vec, Vec]:
    """Unit vectors: slot direction u1 and its normal n1; path direction uψ and normal nψ."""
    u1 = Vec(math.cos(theta1), math.sin(theta1))
    up = Vec(math.cos(psi), math.sin(psi))
    return u1, u1.perp(), up, up.perp()


def slot_path_point(
    theta1: npt.ArrayLike, e: float, psi: float, h: float
) -> npt.NDArray[np.float64]:
    """M(θ1) = slot ∩ path for an array of θ1 (rad), shape (N, 2); NaN where they are parallel.

    From p·n1 = e and p·nψ = h: M = h·nψ + s·uψ with s = (e − h·cos(θ1 − ψ)) / sin(ψ − θ1).
    """
    t = np.asarray(theta1, dtype=np.float64)
    d = np.sin(psi - t)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(d != 0.0, (e - h * np.cos(t - psi)) / np.where(d != 0.0, d, 1.0), np.nan)
    return np.stack(
        [-h * math.sin(psi) + s * math.cos(psi), h * math.cos(psi) + s * math.sin(psi)], axis=-1
    )


def pusher_speed_ratio(
    theta1: npt.ArrayLike, e: float, psi: float, h: float
) -> npt.NDArray[np.float64]:
    """V_T/ω1 (m) for an array of θ1 (rad), from the velocity plan of the replaced mechanism.

    V_M6 = V_M1 + V_M6M1 with V_M1 = ω1 × OM, V_M6 = V_T·uψ, V_M6M1 = t·u1: the 2×2 system
    V_T·uψ − t·u1 = ω1 × OM is solved by Cramer's rule at every position at once. NaN where the
    slot is parallel to the path.
    """
    t = np.asarray(theta1, dtype=np.float64)
    m = slot_path_point(t, e, psi, h)
    rhs = np.stack([-m[..., 1], m[..., 0]], axis=-1)  # ω1 × OM for ω1 = 1
    u1 = np.stack([np.cos(t), np.sin(t)], axis=-1)
    up = np.array([math.cos(psi), math.sin(psi)])
    # det [uψ, −u1] and Cramer's numerator for V_T
    det = -(up[0] * u1[..., 1] - up[1] * u1[..., 0])
    num = -(rhs[..., 0] * u1[..., 1] - rhs[..., 1] * u1[..., 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(np.where(det != 0.0, num / np.where(det != 0.0, det, 1.0), np.nan))


def sign_changes_deg(e: float, psi: float, h: float, samples: int = SWEEP) -> tuple[float, ...]:
    """The θ1 (deg, ascending in [0, 360)) where V_T/ω1 changes sign over a turn: a sweep of
    ``samples`` positions, each bracketed change refined by root finding."""
    step = 2.0 * math.pi / samples
    t = psi + (np.arange(samples + 1) + 0.5) * step  # never exactly slot ∥ path
    v = pusher_speed_ratio(t, e, psi, h)
    out: list[float] = []
    for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0.0)[0]:

        def f(x: float) -> float:
            return float(pusher_speed_ratio(np.array([x]), e, psi, h)[0])

        root = brentq(f, float(t[i]), float(t[i + 1]), xtol=tol.ROOT_ANGLE)
        out.append(wrap_deg(to_deg(root)))
    return tuple(sorted(out))


def _counts(p: Mapping[str, ParamValue]) -> tuple[int, int, int, int]:
    return int(p["n"]), int(p["p5"]), int(p["p4"]), int(p["local"])


def vulcanizer(e: float, M: Vec, u1: Vec, up: Vec, h: float) -> tuple[Mechanism, dict[str, Vec]]:
    """The model's structural scheme in the position where the slot (direction u1) meets the
    path (direction up) at M; returns the mechanism and its named points."""
    big = abs(e)
    n1 = u1.perp()
    O_ = Vec(0.0, 0.0)
    N = n1 * e  # the foot of O's perpendicular on the slot

    def lever(x: float, y: float) -> Vec:
        return O_ + u1 * (x * big) + n1 * (y * big)

    # across the path, away from O (O lies on the side of p·nψ = 0 > h or < h)
    side = -up.perp() if h <= 0.0 else up.perp()

    def path(x: float, y: float) -> Vec:
        return M + up * (x * big) + side * (y * big)

    sM = (M - N).dot(u1)
    r = ROLLER_R * big
    pts = {
        "O": O_,
        "N": N,
        "C": lever(*LEVER_C),
        "A": lever(*FOUR_BAR_A),
        "B": lever(*FOUR_BAR_B),
        "M": M,
        "T": path(*PUSHER_GUIDE),
        "F": path(*PUSHER_F),
        "E": path(*LID_E),
        "D": path(*LID_D),
        "S0": N + u1 * (min(0.0, sM) - SLOT_PAST * big),
        "L": N + u1 * (max(0.0, sM) + SLOT_PAST * big),
        "K": M + n1 * (-r if e > 0.0 else r),  # the roller touches the slot's side nearer O
        "R": Vec(r, 0.0),
    }
    links = (
        Link("1", "рычаг с пазом"),
        Link("2", "кривошип"),
        Link("3", "шатун"),
        Link("4", "крышка"),
        Link("5", "тяга"),
        Link("6", "ролик"),
        Link("7", "толкатель T"),
    )
    pairs = (
        revolute("O", "0", "1", O_),
        revolute("A", "0", "2", pts["A"]),
        revolute("B", "2", "3", pts["B"]),
        revolute("C", "3", "1", pts["C"]),
        revolute("M", "6", "7", M),
        prismatic("T", "7", "0", pts["T"], up),
        revolute("D", "0", "4", pts["D"]),
        revolute("E", "4", "5", pts["E"]),
        revolute("F", "5", "7", pts["F"]),
        higher("K", "6", "1", pts["K"], n1, centre_a=M, centre_b=None, kind="slot"),
    )
    return Mechanism(links, pairs), pts


def _structure(
    c: Construction, p: Mapping[str, ParamValue], mech: Mechanism
) -> tuple[dict[str, int], bool, Replacement, Removal, Mechanism, Mobility, Mobility, Mobility]:
    """W by the model (counts derived from its links and pairs) or by the counts alone."""
    n, p5, p4, local = _counts(p)
    mob_b = mobility(mech)
    replaced = replace_higher_pairs(mech, {"K": ("8", "K6", "K1")})
    mob_a = mobility(replaced.mechanism)
    no_roller = remove_local_mobilities(mech)
    # the seed's route: the roller and its pin M go, and the block that replaces K takes the
    # roller's number 6 and the pin's name M (the seed's V_M6 = V_M1 + V_M6M1)
    seed_route = replace_higher_pairs(no_roller.mechanism, {"K": ("6", "M", "K1")}).mechanism
    mob_s = mobility(seed_route)
    derived = (mech.n, mech.p5, mech.p4, mob_b.w_local)
    counts_mode = (n, p5, p4, local) != derived
    if counts_mode:
        if local > n or local > p5:
            raise ParameterError(
                "local",
                local,
                f"must be ≤ n = {n} and ≤ p5 = {p5}: each local mobility here is a roller, "
                "a link of its own on a pin of its own",
            )
        w = chebyshev(n, p5, p4)
        ws = {
            "W_formal": w,
            "W_local": local,
            "W_true": w - local,
            "W_after_replacement": chebyshev(n + p4, p5 + 2 * p4, 0),
            "W_after_seed": chebyshev(n - local + p4, p5 - local + 2 * p4, 0),
        }
    else:
        ws = {
            "W_formal": mob_b.formal,
            "W_local": mob_b.w_local,
            "W_true": mob_b.true,
            "W_after_replacement": mob_a.formal,
            "W_after_seed": mob_s.formal,
        }
    c.value("W", ws["W_true"], "3n − 2p5 − p4 − local (Chebyshev, local mobilities taken out)")
    if ws["W_true"] <= 0:
        raise ConstructionError(
            c.step("W").title,
            f"W = 3·{n} − 2·{p5} − {p4} − {local} = {ws['W_true']} ≤ 0: not a mechanism (no "
            "link can move; counts alone cannot show redundant constraints that would free it)",
        )
    return ws, counts_mode, replaced, no_roller, seed_route, mob_b, mob_a, mob_s


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """The structural analysis, then the zero-velocity positions and the velocity plan at θ1."""
    e, h = float(p["e"]), float(p["h"])
    psi, theta1 = math.radians(float(p["psi_deg"])), math.radians(float(p["theta1_deg"]))
    if e == 0.0:
        raise ParameterError(
            "e", e, "must not be 0: a slot through O would meet OM ⊥ slot only at M = O"
        )
    c = Construction("2013-1: structure and the pusher's dead position (ML ⊥ MO)")
    u1, n1, up, npsi = _frames(theta1, psi)
    O_ = c.point("O", (0.0, 0.0), note="the lever's pivot")
    path = c.line("path", npsi * h, up, "pusher path p·nψ = h", role="given")
    slot = c.line("slot", n1 * e, u1, "slot p·n1 = e at θ1", role="given")
    if abs(u1.cross(up)) <= tol.ANGLE:
        raise ParallelLines(
            "M = slot ∩ pusher path",
            f"the slot (θ1 = {float(p['theta1_deg']):g}°) is parallel to the pusher path "
            f"(ψ = {float(p['psi_deg']):g}°): the roller's centre M would be at infinity",
        )
    M = c.intersect(
        "M", slot, path, op="slot ∩ pusher path", role="link",
        kind="slot_meets_path", args={"th": float(p["theta1_deg"])},
    )  # fmt: skip

    mech, pts = vulcanizer(e, M, u1, up, h)
    ws, counts_mode, replaced, no_roller, seed_route, mob_b, mob_a, mob_s = _structure(c, p, mech)
    decomposition = assur_groups(seed_route, ["2"])

    # the zero positions: the slot touches circle(O, |e|) at the foot of O's perpendicular, so
    # OM ⊥ slot puts M on that circle and on the pusher path
    ke = c.run(
        "k_e", "circle(O, |e|)", lambda: Circle(O_, abs(e)), (O_,),
        note="the slot is always tangent to it",
        kind="slot_circle", args={"o": "O", "e": abs(e) * MM},
    )  # fmt: skip
    feet = c.intersections(
        "M*", path, ke, op="pusher path ∩ circle(O, |e|)", role="result", allow_empty=True,
        kind="dead_points", args={"o": "O", "h": abs(h) * MM},
    )  # fmt: skip
    if not feet:
        raise NoIntersection(
            "M* = pusher path ∩ circle(O, |e|)",
            f"the pusher path passes |h| = {abs(h):.6g} m from O, farther than the slot's "
            f"offset |e| = {abs(e):.6g} m: M never reaches the foot of the perpendicular from O "
            "to the slot, so ML ⊥ MO never happens and V_T ≠ 0 in every position",
        )
    if len(feet) == 1:
        raise NoIntersection(
            "M* = pusher path ∩ circle(O, |e|)",
            f"the pusher path touches the circle (|h| = |e| = {abs(e):.6g} m): the slot tangent "
            "at the touching point lies along the path itself, so M is not defined there, and "
            "nearby V_T/ω1 tends to −e/2, not 0; ML ⊥ MO never happens with V_T = 0",
        )
    zeros: list[ZeroPosition] = []
    for i, Mz in enumerate(feet):
        # OM* = e·n1, so n1 = OM*/e and the slot's direction is n1 turned −90°
        nz = Mz * (1.0 / e)
        th = c.value(f"θ1*{i + 1}", math.atan2(-nz.x, nz.y), "direction of the tangent at M*")
        uz = Vec(math.cos(th), math.sin(th))
        c.line(
            f"slot*{i + 1}", Mz, uz, "tangent to circle(O, |e|) at M*: ML ⊥ MO", role="result",
            kind="dead_slot", args={"th": wrap_deg(to_deg(th))},
        )  # fmt: skip
        zeros.append(ZeroPosition(th, Mz, uz, Mz + uz * (SLOT_PAST * abs(e))))
    zeros.sort(key=lambda z: wrap_deg(to_deg(z.theta1)))
    zero_deg = [wrap_deg(to_deg(z.theta1)) for z in zeros]

    # the velocity plan at θ1 (ω1 = 1 rad/s): V_M6 = V_M1 + V_M6M1
    pole = c.point("p", (0.0, 0.0), note="pole of the velocity plan, ω1 = 1 rad/s")
    th1 = wrap_deg(float(p["theta1_deg"]))
    m1 = c.point(
        "m1", pole + M.perp(), role="construction", op="p + ω1 × OM (pm1 ⊥ OM)",
        kind="plan_turning", args={"a": "m1", "r": "OM", "th": th1},
    )  # fmt: skip
    rel = c.line("m1m6", m1, u1, "through m1 ∥ slot: V_M6M1")
    abs_ = c.line("pm6", pole, up, "through p ∥ pusher path: V_M6 = V_T")
    m6 = c.intersect("m6", rel, abs_, role="result", kind="plan_slot_path", args={"a": "m1"})
    vt = c.value(
        "V_T/ω1", (m6 - pole).dot(up), "pm6 along (cos ψ, sin ψ)", (m6,),
        kind="plan_pusher", args={"value": (m6 - pole).dot(up)},
    )  # fmt: skip

    # the position the sheet builds: the zero position nearest to θ1, with its plan
    built = min(
        range(len(zeros)),
        key=lambda i: abs(math.remainder(zeros[i].theta1 - theta1, 2.0 * math.pi)),
    )
    z = zeros[built]
    thz = wrap_deg(to_deg(z.theta1))
    m1z = c.point(
        "m1*", pole + z.M.perp(), role="construction", op="p + ω1 × OM* (∥ slot)",
        kind="plan_turning", args={"a": "m1", "r": "OM", "th": thz},
    )  # fmt: skip
    m6z = c.intersect(
        "m6*",
        c.line("m1*m6*", m1z, z.u1, "through m1* ∥ slot*: passes through p"),
        c.line("pm6*", pole, up, "through p ∥ pusher path"),
        role="result",
        op="m1*m6* ∩ pm6*: m6* = p, V_T = 0",
        kind="plan_dead",
        args={"a": "m1"},
    )
    if m6z.dist(pole) > tol.DERIVED * abs(e):
        raise ConstructionError(c.step("m6*").title, "the plan at M* does not close at the pole")

    sweep = sign_changes_deg(e, psi, h)
    notes = [EXPLAIN, FOUR_BAR_NOTE]
    if counts_mode:
        n, p5, p4, local = _counts(p)
        notes.append(
            f"analysed by the counts alone (n = {n}, p5 = {p5}, p4 = {p4}, local = {local}); "
            "the sheet still shows the vulcanizer model's schemes"
        )
    notes.append(
        "V_T/ω1 changes sign over a turn at θ1 = "
        + ", ".join(f"{x:.6g}°" for x in sweep)
        + " (a sweep of the velocity plan), the positions the construction finds"
    )
    results: dict[str, Any] = {
        **ws,
        "zero_theta1_deg": zero_deg,
        "VT_over_omega1": vt,
    }
    points = {**pts, "m1": m1, "m6": m6, "m1*": m1z}
    geo = Geometry(
        e,
        psi,
        h,
        theta1,
        counts_mode,
        _counts(p),
        mech,
        replaced,
        seed_route,
        no_roller,
        mob_b,
        mob_a,
        mob_s,
        decomposition,
        points,
        tuple(zeros),
        built,
        sweep,
    )
    return Build(results, c, notes, {}, geo)
