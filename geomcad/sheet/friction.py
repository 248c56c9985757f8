"""A joint with friction enlarged: the pin, its friction circle (radius ρ), the links' centre
lines through the joint, the reaction touching the friction circle on its line, and the
relative rotation whose moment the reaction opposes, as a curved arrow.

The reaction shows its line and sense only (its magnitude is read off the force plan): an arrow
at least :data:`ARROW_MM` long at any scale of the enlarged views, its head just outside the
pin, where its name has room. ρ is marked on a radius in the direction farthest from every
line drawn.

Appended for the seed sheets (2013-7's joints B, F, H); it takes any
:class:`~geomcad.forces.FrictionCircle`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from geomcad.forces import FrictionCircle
from geomcad.geom import Circle, Line, Vec, line_circle
from geomcad.sheet.compose import Figure
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse

#: The reaction on an enlarged joint is at least this long (mm): two arrowheads and more.
ARROW_MM = 8.0
#: Room over the joint for its caption, as a share of the view's half-size.
CAPTION_ROOM = 0.6
#: The view's half-size: at least this share of the pin's diameter and this many ρ.
PIN_SHARE = 0.52
RHO_SHARE = 2.5
#: The reaction's head this far (mm) outside the pin.
HEAD_OUT_MM = 2.0
#: The rotation's arrow: between the pin and the friction circle where the two are this far
#: apart (mm) on the paper, else this far (mm) outside the pin; it spans this many degrees and
#: keeps this room (mm) under the caption.
ROTATION_BETWEEN_MM = 8.0
ROTATION_OUT_MM = 3.0
ROTATION_SWEEP_DEG = 90.0
CAPTION_CLEAR_MM = 2.0
#: Directions tried for ρ and the rotation (a full turn in this many steps).
DIRECTIONS = 72
#: Text heights (mm): the caption, and the names of ρ and of the rotation.
CAPTION_H = 3.5
NAME_H = 2.5


def inset_reach(pin_d: float, rho: float) -> float:
    """The half-size (model units) of a joint's enlarged view: the pin with room round it."""
    return max(PIN_SHARE * pin_d, RHO_SHARE * rho)


def free_angle(taken: Sequence[Vec]) -> float:
    """The direction (rad) farthest, in angle, from every direction in ``taken``."""
    angles = [t.angle for t in taken]
    best, best_gap = 0.0, -1.0
    half = DIRECTIONS / 2.0
    for i in range(DIRECTIONS):
        a = i * math.pi / half
        gap = min(abs(math.remainder(a - b, 2.0 * math.pi)) for b in angles)
        if gap > best_gap:
            best, best_gap = a, gap
    return best


def draw_joint(
    v: Viewport,
    fc: FrictionCircle,
    towards: Sequence[Vec],
    line: Line,
    force: Vec,
    fname: str,
    wname: str,
    pin_d: float,
) -> float:
    """One enlarged joint: its friction circle, pin (diameter ``pin_d``), the links' centre
    lines towards the points ``towards``, the reaction named ``fname`` on ``line`` in the sense
    of ``force``, and the rotation ``wname`` it opposes (``fc.sense``: of the link the reaction
    acts on, relative to the other). Returns how far (model) over the joint's centre the
    drawing reaches (a caption goes above)."""
    k = v.scale
    reach = inset_reach(pin_d, fc.arm)
    J = fc.c
    # the links' centre lines through the joint, the pin, the friction circle
    dirs = [(q - J).unit() for q in towards]
    for u in dirs:
        v.seg(J, J + u * reach, "centre")
    v.circle(J, pin_d / 2.0, "dimension")
    v.circle(J, fc.arm, "construction")
    v.dot(J)
    # the reaction's line inside the view, and the reaction from its point of contact
    chord = line_circle(line, Circle(J, reach))
    touch = line.foot(J)
    if len(chord) == 2:
        v.seg(chord[0], chord[1], "result")
    u = force.unit()
    out = [q for q in line_circle(Line(touch, u), Circle(J, pin_d / 2.0)) if (q - touch).dot(u) > 0]
    exit_ = (out[0] - touch).dot(u) + k.model(HEAD_OUT_MM) if out else 0.0
    tip = touch + u * max(exit_, k.model(ARROW_MM))
    v.arrow(touch, tip, "vector")
    v.dot(touch, "result")
    v.label(tip, fname, prefer=(u.x, u.y), clear=0.5)
    # ρ: a radius of the friction circle in a free direction
    taken = [*dirs, (touch - J).unit(), u, -u, (tip - J).unit(), ((touch + tip) * 0.5 - J).unit()]
    taken += [(q - J).unit() for q in chord]  # the reaction's line where it leaves the view
    a_rho = free_angle(taken)
    v.seg(J, J + Vec.polar(fc.arm, a_rho), "dimension")
    v.label(
        J + Vec.polar(fc.arm, a_rho), "ρ", height=NAME_H, prefer=(math.cos(a_rho), math.sin(a_rho))
    )
    # the relative rotation the reaction opposes, as a curved arrow outside the pin
    a_w = free_angle([*taken, Vec.polar(1.0, a_rho)])
    r_w = (
        (fc.arm + pin_d / 2.0) / 2.0
        if k.mm(pin_d / 2.0 - fc.arm) > ROTATION_BETWEEN_MM
        else pin_d / 2.0 + k.model(ROTATION_OUT_MM)
    )
    # a curved arrow (an arc with its head, as the textbooks draw a rotation)
    start = math.degrees(a_w) - math.copysign(ROTATION_SWEEP_DEG / 2.0, fc.sense)
    v.turn(J, fc.sense, start, wname, k.mm(r_w), ROTATION_SWEEP_DEG, "dimension", NAME_H)
    return max(reach, r_w + k.model(CAPTION_CLEAR_MM))


class FrictionJoint(Figure):
    """A joint with friction enlarged (:func:`draw_joint`) under its ``caption``, at the scale
    the layout gives it (enlarged joints of one sheet share a ``group``)."""

    def __init__(
        self,
        fc: FrictionCircle,
        towards: Sequence[Vec],
        line: Line,
        force: Vec,
        fname: str,
        wname: str,
        pin_d: float,
        caption: str,
        **kw: Any,
    ) -> None:
        r = inset_reach(pin_d, fc.arm)
        c = fc.c
        box = (c.x - r, c.y - r, c.x + r, c.y + r * (1.0 + CAPTION_ROOM))
        kw.setdefault("show_scale", False)
        super().__init__(box, self._draw, **kw)
        self.fc, self.towards, self.line, self.force = fc, list(towards), line, force
        self.fname, self.wname, self.pin_d, self.name_text = fname, wname, pin_d, caption

    def _draw(self, v: Viewport) -> None:
        fc = self.fc
        top = draw_joint(v, fc, self.towards, self.line, self.force, self.fname, self.wname,
                         self.pin_d)  # fmt: skip
        w = text_box(parse(self.name_text), CAPTION_H)[0]
        x, y = v.p(fc.c + Vec(0.0, top))
        v.d.text(self.name_text, (x - w / 2.0, y - CAPTION_CLEAR_MM), CAPTION_H)
