"""The mechanism's main-line (thick) position is the force analysis' position; where
``[forces] phi`` is none of the numbered angles, the view's title names that angle, so that
the numbered position beside it is not read as the thick one."""

from __future__ import annotations

import math

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _principal, kinematic_sheets, layout
from geomcad.sheet.model import Polyline, TextItem


def _lever(forces: dict[str, float]) -> dict[str, object]:
    return {
        "title": "Кулисный механизм",
        "frame": {"O": [0.0, 0.0], "C": [0.25, 0.0]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.11, "omega": -16.0, "positions": 12},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C", "offset": 0.02}],
        "links": {"3": {"mass": 6.0, "J": 0.09}},
        "forces": forces,
    }


def _text(it: TextItem) -> str:
    return "".join(r.text for r in it.runs)


@pytest.mark.parametrize(("forces", "deg"), [({"phi": 200.0}, 200.0), ({"position": 3}, None)])
def test_the_thick_position_is_the_forces_one(forces: dict[str, float], deg: float | None) -> None:
    s = solve(parse(_lever(forces)))
    P0, k0 = _principal(s)
    numbered = [round(math.degrees(P.phi) % 360.0, 6) for P in s.drawn]
    if deg is not None:
        assert k0 is None and math.isclose(math.degrees(P0.phi) % 360.0, deg)
        assert round(deg, 6) not in numbered  # 200° lies 1.1° from position 3
    else:
        assert k0 == forces["position"]
    sheet = kinematic_sheets(s)[0][1]
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    o, a = v.p(P0.pos["O"]), v.p(P0.pos["A"])
    crank = [
        it
        for it in sheet.items
        if isinstance(it, Polyline) and it.role == "link"
        and {tuple(round(c, 6) for c in p) for p in it.points}
        == {tuple(round(c, 6) for c in p) for p in (o, a)}
    ]  # fmt: skip
    assert crank, "the crank is not drawn in main lines at the forces' angle"
    titles = [_text(it) for it in sheet.items if isinstance(it, TextItem)]
    named = [t for t in titles if t.startswith("Механизм в положениях") and "200" in t]
    assert bool(named) == (deg is not None), titles[:3]
