"""An oscillating slotted lever with an offset (an RPR group's ``offset``): its arm from the
pivot C to the slide line is drawn clear of C's support, the support turned away from it."""

from __future__ import annotations

import math

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _principal, kinematic_sheets, layout
from geomcad.sheet.model import Polyline
from geomcad.sheet.scheme import SUPPORT_CLEAR
from geomcad.sheet.symbols import STAND_DEPTH, STAND_HALF


def _lever(offset: float, C: tuple[float, float]) -> dict[str, object]:
    return {
        "title": "Кулисный механизм",
        "frame": {"O": [0.0, 0.0], "C": list(C)},
        "drive": {"pivot": "O", "joint": "A", "length": 0.11, "omega": -16.0, "positions": 12},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C", "offset": offset}],
    }


@pytest.mark.parametrize(
    ("offset", "C"), [(0.02, (0.25, 0.0)), (-0.02, (0.25, 0.0)), (0.03, (0.0, 0.25))]
)
def test_the_offset_arm_is_clear_of_the_support(offset: float, C: tuple[float, float]) -> None:
    s = solve(parse(_lever(offset, C)))
    P0, _ = _principal(s)
    sheet = kinematic_sheets(s)[0][1]
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    c = v.p(P0.pos["C"])
    foot = v.p(P0.pos["C"] + P0.slide[3].perp() * offset)
    arm = ((foot[0] - c[0]), (foot[1] - c[1]))
    assert math.hypot(*arm) > 5.0  # the arm is long enough to be seen
    stand = math.hypot(STAND_DEPTH, STAND_HALF)
    legs = [
        it.points[1]
        for it in sheet.items
        if isinstance(it, Polyline) and it.role == "link" and len(it.points) == 2
        and math.dist(it.points[0], c) < 1e-6
        and abs(math.dist(it.points[0], it.points[1]) - stand) < 1e-6
    ]  # fmt: skip
    assert len(legs) == 2, "no support at C"
    down = ((legs[0][0] + legs[1][0]) / 2 - c[0], (legs[0][1] + legs[1][1]) / 2 - c[1])
    cos = (down[0] * arm[0] + down[1] * arm[1]) / (math.hypot(*down) * math.hypot(*arm))
    assert math.acos(max(-1.0, min(1.0, cos))) >= SUPPORT_CLEAR - 1e-9, (
        "C's support stands on the lever's offset arm"
    )
