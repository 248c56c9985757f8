"""Kinematic schemes drawn not to scale (GOST 2.770): a machine's drive where the problem gives
no lengths, only what each part does, so the scheme takes whatever enlargement its place allows
and shows no scale.

:class:`PressScheme`: a crank press driven through a flywheel. The motor's pulley and the
flywheel joined by a belt (their outer common tangents), the flywheel on the crankshaft 1 with
the crank, the connecting rod 2, the punch 3 in its vertical guides, the plate on the die's two
hatched blocks; ω at the flywheel, the links numbered and the parts named.

Appended for the seed sheets (2013-8's press); any flywheel press problem may use it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from geomcad.geom import Vec
from geomcad.sheet.compose import Figure
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.model import Polyline


@dataclass(frozen=True)
class Press:
    """The proportions of a press's scheme, in the scheme's own millimetres (drawn at the
    enlargement its place allows): the flywheel's rim, the crank, the rod, the motor's centre
    from the crankshaft's and its pulley, the punch below the slider, the plate and the die, the
    crank's angle. Text heights in paper mm."""

    rim: float = 19.0
    rim_width: float = 2.5
    crank: float = 7.0
    rod: float = 30.0
    crank_deg: float = -60.0
    motor: tuple[float, float] = (-50.0, -4.0)
    motor_r: float = 7.0
    pulley_r: float = 4.0
    #: The motor's foot below its centre (scheme mm) and beyond that in paper mm, and the
    #: foot's half width.
    foot: float = 9.0
    foot_mm: float = 3.1
    foot_half: float = 6.0
    punch: float = 9.0
    guide_half: float = 6.0
    plate_half: float = 13.0
    plate: float = 2.5
    #: The die: two blocks under the plate, from ``die_gap`` to ``die_half`` either side of the
    #: punch, ``die`` deep, hatched by ``hatches`` strokes leaning ``hatch_lean`` each way.
    die_gap: float = 2.5
    die_half: float = 15.0
    die: float = 8.0
    hatches: int = 6
    hatch_lean: float = 1.8
    #: ω's arrow: its start, its sweep (degrees) and its radius beyond the rim (scheme mm).
    omega_start_deg: float = -25.0
    omega_sweep_deg: float = 40.0
    omega_out: float = 3.0
    #: Link 3's number this far over the slider's centre; the die's name this far under the
    #: plate's top.
    number3_up: float = 4.5
    die_name_drop: float = 6.0
    number_h: float = 3.5
    name_h: float = 2.5
    #: The scheme's model box (x0, y0, x1, y1) round the motor's foot, the flywheel with ω's
    #: arrow, the die and the parts' names at the default proportions.
    box: tuple[float, float, float, float] = (-60.0, -55.0, 30.0, 27.0)


class PressScheme(Figure):
    """A crank press with its flywheel, not to scale (:class:`Press`'s proportions).
    ``names``: the words for ``flywheel``, ``motor``, ``plate`` and ``die``; ``box`` overrides
    the model box the layout fits."""

    def __init__(
        self,
        names: Mapping[str, str],
        press: Press | None = None,
        box: tuple[float, float, float, float] | None = None,
        **kw: Any,
    ) -> None:
        self.press = press or Press()
        self.names = dict(names)
        kw.setdefault("show_scale", False)
        kw.setdefault("series", "free")
        super().__init__(box or self.press.box, self._draw, **kw)

    def _draw(self, v: Viewport) -> None:
        draw_press(v, self.press, self.names)


def draw_press(v: Viewport, pr: Press, names: Mapping[str, str]) -> None:
    """The press's scheme through ``v`` (model units: the scheme's millimetres)."""
    R, r1, l2 = pr.rim, pr.crank, pr.rod
    O1 = Vec(0.0, 0.0)
    z = 1.0 / v.scale.k
    s = v.sheet
    # the motor on its foot, its pulley on the shaft
    Mo = Vec(*pr.motor)
    rp = pr.pulley_r
    v.circle(Mo, pr.motor_r, "construction")
    v.circle(Mo, rp, "link")
    foot = -pr.foot - pr.foot_mm / z
    v.seg(Mo, Mo + Vec(0.0, foot), "link")
    v.guide(Mo + Vec(-pr.foot_half, foot), Mo + Vec(pr.foot_half, foot))
    # the belt: the outer common tangents of the pulley and the flywheel's rim
    dv = O1 - Mo
    u = dv.unit()
    n = u.perp()
    c = (R - rp) / dv.norm
    sn = math.sqrt(1.0 - c * c)
    for sg in (1.0, -1.0):
        w = u * (-c) + n * (sg * sn)
        v.seg(Mo + w * rp, O1 + w * R, "link")
    # the flywheel (its rim) on the crankshaft 1, the crank O1 A, the rod 2
    v.circle(O1, R, "link")
    v.circle(O1, R - pr.rim_width, "link")
    phi = math.radians(pr.crank_deg)
    A = O1 + Vec.polar(r1, phi)
    B = Vec(0.0, A.y - math.sqrt(l2 * l2 - A.x * A.x))
    v.seg(O1, A, "link")
    v.seg(A, B, "link")
    # the punch 3: a slider at B between vertical guides, the punch below it down to the plate
    tip = B - Vec(0.0, pr.punch)
    v.seg(B, tip, "link")
    v.slider(B, (0.0, 1.0))
    for side in (-1.0, 1.0):
        v.guide(B + Vec(0.0, -pr.guide_half), B + Vec(0.0, pr.guide_half), (side, 0.0))
    # the plate over the die's two blocks (hatched), the die's hole under the punch
    py = tip.y
    ph, pt = pr.plate_half, pr.plate
    plate = [Vec(-ph, py), Vec(ph, py), Vec(ph, py - pt), Vec(-ph, py - pt)]
    v.polyline(plate, "link", closed=True)
    for x0, x1 in ((-pr.die_half, -pr.die_gap), (pr.die_gap, pr.die_half)):
        y0, y1 = py - pt, py - pr.die
        v.polyline([Vec(x0, y0), Vec(x1, y0), Vec(x1, y1), Vec(x0, y1)], "link", closed=True)
        for i in range(1, pr.hatches):
            xa = x0 + (x1 - x0) * i / float(pr.hatches)
            lean = pr.hatch_lean
            s.add(Polyline((v.p(Vec(xa - lean, y1)), v.p(Vec(xa + lean, y0))), "ground"))
    v.joint(A)
    v.pivot(O1, (0.0, 1.0))
    v.turn(O1, 1.0, pr.omega_start_deg, "ω", r_mm=(R + pr.omega_out) * z,
           sweep_deg=pr.omega_sweep_deg)  # fmt: skip
    # the links' numbers and the parts' names
    nh, th = pr.number_h, pr.name_h
    v.label(O1 + (A - O1) * 0.5, "1", nh, prefer=(1.0, 0.3), clear=0.8)
    v.label(A + (B - A) * 0.5, "2", nh, prefer=(1.0, 0.0), clear=0.8)
    v.label(B + Vec(0.0, pr.number3_up), "3", nh, prefer=(1.0, 0.0), clear=4.0)
    v.label(O1 + Vec(R * 0.71, R * 0.71), names["flywheel"], th, prefer=(1.0, 1.0), clear=1.0)
    v.label(Mo + Vec(0.0, pr.motor_r), names["motor"], th, prefer=(0.0, 1.0), clear=1.0)
    v.label(Vec(ph, py - pt / 2.0), names["plate"], th, prefer=(1.0, 0.0), clear=1.0)
    v.label(Vec(pr.die_half, py - pr.die_name_drop), names["die"], th, prefer=(1.0, 0.0),
            clear=1.0)  # fmt: skip
