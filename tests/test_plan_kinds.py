"""The plans' steps carry kinds whose templates write the order of construction (issue 14)."""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest

import geomcad
from geomcad.construction import Construction
from geomcad.geom import Vec
from geomcad.kinematics.plan import Side, velocity_plan
from geomcad.linkage.model import parse
from geomcad.linkage.plans import construct
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage as linkage_sheet
from geomcad.sheet.lang import language
from geomcad.sheet.views import Steps, Table, num, step_text

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


def _numbered(view: Steps) -> list[str]:
    """The numbered lines of an order of construction (the first line of each step)."""
    return [t for t in view.lines if re.match(r"\d+\. ", t)]


def test_linkage_sheet_lists_both_plans_of_its_detailed_position() -> None:
    lang = "ru"
    lk = parse(tomllib.loads((EXAMPLES / "shaper.toml").read_text()))
    s = solve(lk)
    with language(lang):
        lay = linkage_sheet.layout(s)
        (order,) = [v for t in lay.trees for v in t.views() if isinstance(v, Steps)]
        P = lay.accel[0]
        names = [P.vp.pole, *P.vp.order, P.ap.pole, *P.ap.order]
        lines = _numbered(order)
        assert len(lines) == len(names)
        # the velocity plan first, then the acceleration plan; ω3 as recorded, formatted as
        # the ω table prints it in that position (one rounding per value on a sheet)
        k = names.index("ω3")
        assert names.index("π") > k
        line = order.lines[order.lines.index(lines[k])]
        (table,) = [v for t in lay.trees for v in t.views() if isinstance(v, Table) and
                    v.rows[0][0] == "№"]  # fmt: skip
        row = table.rows[1 + next(i for i, Q in enumerate(s.drawn) if Q is P)]
        # ω3's column (headed "ω_{2} = ω_{3}" where the block turns with link 3)
        col = [i for i, h in enumerate(table.rows[0]) if "ω_{3}" in h.split(", ")[0].split(" = ")]
        cell = row[col[0]]
        # the text's quotient is a magnitude: |ω_3| where the table's ω_3 is negative
        w = "|ω_{3}|" if cell.startswith("\u2013") else "ω_{3}"
        assert line.startswith(f"{k + 1}. {w} = V_{{A3C}}/l_{{CA3}}")
        assert float(cell.lstrip("\u2013").replace(",", ".")) == pytest.approx(
            abs(P.c["ω3"]), abs=0.0006
        )
        assert line.endswith(f"{cell.lstrip(chr(0x2013))} {'рад/с' if lang == 'ru' else 'rad/s'}")


def test_2013_3_order_is_the_plans_steps_and_the_reduced_force() -> None:
    from geomcad_constructions.sheets_2013_3 import _views

    sol = geomcad.solve("2013-3")
    with language("ru"):
        tree, _scheme, _plan = _views(sol)
        (order,) = [v for v in tree.views() if isinstance(v, Steps)]
        lines = _numbered(order)
    assert len(lines) == len(sol.data.plan.order) + 1
    assert lines[-1].startswith(f"{len(lines)}. F_{{пр}} = |M·ω_5|/v_A")
    assert num(sol.results["F_red"]) + " Н" in " ".join(order.lines)


def test_2013_6_kinematics_orders_are_each_plans_steps() -> None:
    from geomcad_constructions.sheets_2013_6_kin import _Kin

    sol = geomcad.solve("2013-6")
    an = sol.data.analysis
    with language("en"):
        kin = _Kin(sol)
    for plan, view in ((an.vp, kin.vorder), (an.ap, kin.aorder)):
        listed = [n for n in plan.order if an.c.step(n).kind != "plan_omega"]
        assert len(_numbered(view)) == len(listed)
    assert _numbered(kin.aorder)[0].startswith("1. a_A = ω_{1}²·l_{O1A} = 10²·0.06415")
