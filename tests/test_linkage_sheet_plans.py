"""Every position whose plans a linkage file's kinematic sheets draw has both of them: each
numbered position its velocity plan, each position of an acceleration plan its velocity plan
too (linkages.md, "Settled in the second round"), in the arrangement the layout chose."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse, synthesis
from geomcad.linkage.plans import Position
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet.linkage import layout
from geomcad.sheet.views import PlanView

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
FILES = sorted(
    p.name
    for p in EXAMPLES.glob("*.toml")
    if "drive" in (d := tomllib.loads(p.read_text(encoding="utf-8"))) or synthesis.is_synthesis(d)
)


def _solved(name: str) -> Solved:
    data = tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))
    if synthesis.is_synthesis(data):
        data = synthesis.synthesize(data).linkage
    return solve(parse(data))


def test_the_examples_are_found() -> None:
    assert {"four-bar.toml", "scotch-yoke.toml", "shaper.toml"} <= set(FILES)


@pytest.mark.parametrize("name", FILES)
def test_every_drawn_position_has_its_velocity_plan(name: str) -> None:
    s = _solved(name)
    lay = layout(s)
    drawn = [p.view.plan for z in lay.sized for p in z.layout if isinstance(p.view, PlanView)]

    def has(plan: object) -> bool:
        return any(plan is q for q in drawn)

    def where(P: Position) -> str:
        return f"{name}: φ = {math.degrees(P.phi):.4g}°"

    for P in s.drawn:
        assert has(P.vp), f"{where(P)}: a numbered position without its velocity plan"
    assert lay.accel, f"{name}: no acceleration plan"
    for P in lay.accel:
        assert has(P.ap), f"{where(P)}: its acceleration plan is not drawn"
        assert has(P.vp), f"{where(P)}: an acceleration plan without its velocity plan"
