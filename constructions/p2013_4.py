"""2013-4 · Profile shift from a gear-tooth caliper measurement.

A spur gear (module m, z teeth, tip diameter d_a) was cut by the standard rack (GOST 13755,
profile angle α). A gear-tooth caliper, its height jaw resting on the tip circle, reads the chord
s̄ between the flanks at the height h̄ below the tip. Find the shift x and the pitch thickness s.

The construction (tooth frame: centre O at the origin, the tooth's axis +y):
- T, where the axis meets the tip circle, is where the height jaw rests; the chord is the
  perpendicular to the axis at H = T − h̄, and its ends K′, K lie s̄/2 either side of H.
- The circle through K about O is d_y; the angle TOK is ψ_y, half the tooth's angular thickness at
  d_y: tan ψ_y = (s̄/2)/(r_a − h̄) = s̄/(d_a − 2h̄) and d_y = s̄/sin ψ_y.
- The tangent from K to the base circle d_b = m·z·cos α touches it at N (on the side the involute
  through K unwinds from); the angle KON is the pressure angle α_y (cos α_y = d_b/d_y), and the
  thread KN = r_b·tan α_y gives inv α_y = KN/r_b − α_y.
- The involute relation s_y = d_y(s/d + inv α − inv α_y) with s_y = ψ_y·d_y gives
  s = d(ψ_y + inv α_y − inv α), and s = π·m/2 + 2·x·m·tan α gives x.

Checks: the rack with that shift generates a tooth (its flank is the envelope of the rack's flank)
whose involute passes through K exactly, and the caliper set to h̄ on that tooth reads s̄ again.

Choices settled here: the chord ends are on the involute part of the flanks (a reading in the
fillet is an error); the tip circle is the given d_a, not the standard one for the shift found.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from geomcad import tol
from geomcad.construction import Construction, Where, left_of
from geomcad.errors import ConstructionError
from geomcad.geom import Circle, Vec, tangents_from
from geomcad.kinematics.gears import (
    BasicRack,
    Flank,
    SpurGear,
    inv,
    shift_from_chord,
)
from geomcad.problem import (
    Build,
    ParamValue,
)
from geomcad.units import to_deg

#: m → mm for the operands of the order of construction
MM = 1000.0


@dataclass(frozen=True)
class Geometry:
    """The solved model besides the recorded steps: the generated gear and its flank, the
    caliper's angle and circle, the span measurement."""

    gear: SpurGear
    flank: Flank
    psi_y: float
    r_y: float
    k_span: int
    W: float


def _rack(alpha_deg: float) -> BasicRack:
    rack = BasicRack(alpha=math.radians(alpha_deg))
    rack.check("alpha_deg")
    return rack


def build(p: Mapping[str, ParamValue]) -> Build[Geometry]:
    """The seed's solution as a recorded construction, checked against the generated gear."""
    m, alpha_deg, d_a = float(p["m"]), float(p["alpha_deg"]), float(p["d_a"])
    z = int(p["z"])
    s_bar, h_bar = float(p["s_chord"]), float(p["h_chord"])
    rack = _rack(alpha_deg)
    alpha = rack.alpha
    # an impossible reading fails here, naming the reading and its range
    reading = shift_from_chord(m, z, d_a, s_bar, h_bar, rack)

    c = Construction("2013-4: profile shift from a gear-tooth caliper reading")
    centre = c.point("O", (0.0, 0.0), note="centre of the gear")
    axis = c.line("axis", centre, (0.0, 1.0), "axis of the tooth through O", role="given")
    k_a = c.circle("k_a", centre, d_a / 2.0, role="given", r_name="d_a/2", note="tip circle")
    T = c.intersect(
        "T",
        axis,
        k_a,
        Where(lambda q: q.y > 0.0, "on the tooth's side of O"),
        role="given",
        op="axis ∩ tip circle (the height jaw rests here)",
        kind="caliper_tip",
        args={"d_a": d_a * MM},
    )
    H = c.point(
        "H", T - Vec(0.0, h_bar), "construction", op="T − h̄ along the axis",
        kind="caliper_height", args={"t": "T", "h": h_bar * MM},
    )  # fmt: skip
    c.perpendicular("chord", axis, H, note="the caliper's jaws touch the flanks on it")
    # K on the right flank (x > 0), K′ on the left one
    right = Vec(axis.d.y, -axis.d.x)
    K = c.point(
        "K", H + right * (s_bar / 2.0), "result", op="H + s̄/2 along the chord",
        kind="caliper_chord", args={"h": "H", "other": "K'", "half": s_bar / 2.0 * MM},
    )  # fmt: skip
    c.point("K'", H - right * (s_bar / 2.0), "result", op="H − s̄/2 along the chord")
    psi = math.atan2(K.x, K.y)
    psi_y = c.value(
        "ψ_y", psi, "∠TOK: tan ψ_y = s̄/(d_a − 2h̄)", (T, centre, K),
        kind="chord_half_angle",
        args={"s": s_bar * MM, "den": (d_a - 2.0 * h_bar) * MM, "tan": K.x / K.y, "value": psi},
    )  # fmt: skip
    k_y = c.circle(
        "k_y", centre, centre.dist(K), role="construction", r_name="|OK|", note="circle d_y"
    )
    d_y = c.value(
        "d_y", 2.0 * k_y.r, "2·|OK| = s̄/sin ψ_y",
        kind="circle_through", args={"o": "O", "k": "K", "value": 2.0 * k_y.r * MM},
    )  # fmt: skip
    d = c.value("d", m * z, "m·z")
    d_b = c.value(
        "d_b", d * math.cos(alpha), "d·cos α",
        kind="base_diameter",
        args={"m": m * MM, "z": float(z), "alpha": alpha_deg, "value": d * math.cos(alpha) * MM},
    )  # fmt: skip
    k_b = c.circle(
        "k_b", centre, d_b / 2.0, role="construction", r_name="d_b/2", note="base circle"
    )
    # the involute through K on the right flank unwinds counter-clockwise: its thread KN touches
    # the base circle counter-clockwise of OK, i.e. left of O → K
    N = c.record(
        "N",
        "tangent from K to the base circle",
        _thread_end(K, k_b, centre),
        (K, k_b),
        "construction",
        note="KN is the involute's normal at K",
        kind="tangent_to_base",
        args={"k": "K"},
    )
    a_y = abs((N - centre).angle - (K - centre).angle)
    alpha_y = c.value(
        "α_y", a_y, "∠KON: cos α_y = d_b/d_y",
        kind="pressure_angle_at", args={"k": "K", "n": "N", "cos": d_b / d_y, "deg": to_deg(a_y)},
    )  # fmt: skip
    thread = K.dist(N)
    inv_y = c.value(
        "inv α_y", thread / k_b.r - alpha_y, "KN/r_b − α_y = tan α_y − α_y",
        kind="involute_function",
        args={"kn": thread * MM, "rb": k_b.r * MM, "a": alpha_y,
              "value": thread / k_b.r - alpha_y},
    )  # fmt: skip
    s = c.value(
        "s", d * (psi_y + inv_y - inv(alpha)), "d·(ψ_y + inv α_y − inv α)",
        kind="thickness_from_involute",
        args={"d": d * MM, "inv": inv(alpha), "value": d * (psi_y + inv_y - inv(alpha)) * MM},
    )  # fmt: skip
    x_val = (s - math.pi * m / 2.0) / (2.0 * m * math.tan(alpha))
    x = c.value(
        "x", x_val, "(s − πm/2)/(2m·tg α)",
        kind="shift_from_thickness", args={"value": 0.0 if abs(x_val) < tol.DERIVED else x_val},
    )  # fmt: skip

    gear = c.run(
        "gear",
        "the rack with shift x cuts the blank d_a",
        lambda: _checked_gear(m, z, x, rack, d_a),
        note="GOST 13755 producing rack",
    )
    flank = c.run("flank", "envelope of the rack's flank", lambda: gear.flank(240))
    c.point("S", Vec.polar(gear.r, math.pi / 2.0 - s / d), "result", op="flank ∩ pitch circle")
    psi_gen = c.value("ψ_y (generated)", gear.half_angle(d_y), "η of the generated flank at d_y")
    s_gen = gear.chord_at_height(h_bar).s_bar
    s_back = c.value(
        "s̄ (caliper on the generated tooth)", s_gen, "chord at h̄ below the tip",
        kind="caliper_check",
        args={"k": "K", "h": h_bar * MM, "s": s_gen * MM,
              "x": 0.0 if abs(x_val) < tol.DERIVED else x_val},
    )  # fmt: skip
    for name, got, want in (
        ("ψ_y (generated)", psi_gen, psi_y),
        ("s̄ (caliper on the generated tooth)", s_back, s_bar),
        ("x", x, reading.x),  # against the library's reading
    ):
        if not math.isclose(got, want, rel_tol=tol.DERIVED, abs_tol=tol.DERIVED * m):
            raise ConstructionError(
                c.step(name).title,
                f"{got!r} differs from {want!r}: the construction is inconsistent",
            )

    results: dict[str, Any] = {
        "d": d,
        "d_b": d_b,
        "d_y": d_y,
        "psi_y": psi_y,
        "alpha_y_deg": to_deg(alpha_y),
        "s": s,
        "x": x,
    }
    notes: list[str] = []  # the seed's misprinted formula: the spec's seed_notes
    d_a_std = gear.d + 2.0 * (rack.ha + x) * m
    if not math.isclose(d_a, d_a_std, rel_tol=tol.DERIVED):
        notes.append(
            f"the given tip d_a = {d_a * 1e3:.6g} mm differs from the standard tip "
            f"d + 2(h_a* + x)·m = {d_a_std * 1e3:.6g} mm of a gear with this shift "
            f"(by {(d_a - d_a_std) * 1e3:+.4g} mm): the caliper's height is measured from the "
            "actual tip, so the reading uses the given d_a"
        )
    if gear.undercut:
        notes.append(
            f"the gear is undercut: x = {x:.4g} < x_min = h_a* − z·sin²α/2 = {gear.x_min:.4g}"
        )
    if gear.s_a < 0.25 * m:
        notes.append(
            f"the tip is thin: s_a = {gear.s_a * 1e3:.4g} mm < 0,25·m (pointed at d = "
            f"{gear.pointed_diameter() * 1e3:.6g} mm)"
        )
    k_span = gear.span_teeth()
    W = gear.span(k_span)
    geo = Geometry(gear, flank, psi_y, k_y.r, k_span, W)
    return Build(results, c, notes, {}, geo)


def _thread_end(K: Vec, base: Circle, centre: Vec) -> Vec:
    """The tangent point N of the line from K touching the base circle, counter-clockwise of OK
    (K itself when K lies on the base circle)."""
    kept = left_of(centre, K, "O→K").keep(tangents_from(K, base))
    return kept[0] if kept else K


def _checked_gear(m: float, z: int, x: float, rack: BasicRack, d_a: float) -> SpurGear:
    gear = SpurGear(m, z, x, rack, d_a)
    gear.check()
    return gear
