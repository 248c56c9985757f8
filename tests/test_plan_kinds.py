"""The plans' steps carry kinds whose templates write the order of construction (issue 14)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.construction import Construction
from geomcad.geom import Vec
from geomcad.kinematics.plan import Side, velocity_plan
from geomcad.linkage.model import parse
from geomcad.linkage.plans import construct
from geomcad.sheet.lang import language
from geomcad.sheet.views import num, step_text

EXAMPLES = Path(__file__).parent.parent / "examples"


@pytest.mark.parametrize("name", ["four-bar", "shaper", "rocking-slider", "scotch-yoke"])
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_every_plan_step_has_a_text(name: str, lang: str) -> None:
    lk = parse(tomllib.loads((EXAMPLES / f"{name}.toml").read_text()))
    P = construct(lk, math.radians(40.0))
    with language(lang):
        for s in P.c:
            if s.kind.startswith("plan_"):
                text = step_text(s)
                assert "@" not in text and "?" not in text, text


def test_solve_writes_the_equation_and_the_omega_its_value() -> None:
    c = Construction("four-bar")
    A, B, O2 = Vec(0.0, 0.1), Vec(0.3, 0.2), Vec(0.4, 0.0)
    vp = velocity_plan(c)
    vp.given("a", Vec(-1.0, 0.0), "V_A")
    vp.fixed("o2")
    vp.solve(
        "b",
        Side("a", B - A, "⊥ AB", perpendicular=True),
        Side("o2", B - O2, "⊥ O2B", perpendicular=True),
    )
    w = vp.omega(A, B, "a", "b", "ω2", 2, ("A", "B"))
    with language("ru"):
        solve = step_text(c.step("b"))
        omega = step_text(c.step("ω2"))
    assert solve.startswith("V_{B} = V_{A} + V_{BA} = V_{O2} + V_{BO2}: через a")
    assert "через p — прямую перпендикулярно O_2B" in solve
    assert omega.endswith(f"= {num(abs(w))} рад/с")
    assert vp.order == ["a", "b", "ω2"]
