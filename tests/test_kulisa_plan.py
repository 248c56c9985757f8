"""kulisa-23110713: the velocity plan of the drawn position is a recorded construction
(geomcad.kinematics.plan), its vectors are the model's velocities, the main sheet draws it by
views.PlanView and writes its order of construction from its steps in either language."""

from __future__ import annotations

import math
import re
from typing import Any

import pytest
from layout import findings

import geomcad
from geomcad.sheet.lang import language
from geomcad.sheet.views import step_text

PID = "kulisa-23110713"


@pytest.fixture(scope="module")
def seed() -> tuple[Any, dict[str, Any]]:
    """The seed's solution and its three sheets in Russian, drawn once for the module."""
    sol = geomcad.solve(PID)
    return sol, dict(sol.sheets())


def _main_sheet(sol: Any) -> Any:
    """Only the main sheet (the sheet module's own function: the other two are not needed)."""
    from geomcad_constructions.sheets_kulisa import _main

    return _main(sol)


@pytest.mark.parametrize("params", [{}, {"phi_deg": 60.0}, {"phi_deg": 300.0, "r3": 0.0}])
def test_the_plan_gives_the_models_velocities(params: dict[str, float]) -> None:
    sol = geomcad.solve(PID, **params)
    d = sol.data
    vp, w = d.vplan, d.omega
    va, _ = d.yoke.pin.velocity(w)
    v2, _ = d.yoke.body.velocity(w)
    vc, w3 = d.roller.velocity(w)
    for got, want in ((vp.vector("a1"), va), (vp.vector("a2"), v2), (vp.vector("d"), v2),
                      (vp.vector("c3"), vc), (vp.between("a1", "a2"), v2 - va)):  # fmt: skip
        assert (got - want).norm <= 1e-9 * max(va.norm, 1.0)
    assert sol.construction["ω3"] == pytest.approx(w3, rel=1e-9)
    # the slip is along the slot (y), the yoke along its guide (x), c3 on pd at R3/(R3 + r3)
    assert abs(vp.between("a1", "a2").x) <= 1e-12 and abs(vp.vector("a2").y) <= 1e-12
    p = sol.params
    k = float(p["R3"]) / (float(p["R3"]) + float(p["r3"]))
    assert (vp.vector("c3") - vp.vector("d") * k).norm <= 1e-12


def test_the_plan_is_recorded_with_kinds() -> None:
    sol = geomcad.solve(PID)
    steps = {s.name: s for s in sol.construction}
    kinds = [steps[n].kind for n in sol.data.plan_steps]
    assert kinds == [
        "plan_pole", "plan_fixed", "plan_rigid", "plan_solve", "plan_unknown", "plan_absolute",
        "plan_same_why", "instant_centre", "plan_fixed", "plan_image_line", "plan_absolute",
        "plan_omega",
    ]  # fmt: skip
    trace = sol.construction.trace()
    assert "a2 = line a2:1 ∩ line a2:2" in trace and "ω3 = " in trace
    # the results are the model's as before (the plan only records them)
    assert sol.results["F_x"] == pytest.approx(34 / (0.12 / 0.17 * 0.24 * 0.5), rel=1e-12)


@pytest.mark.parametrize(("lang", "w3"), [("ru", "3,955 рад/с"), ("en", "3.955 rad/s")])
def test_the_order_on_the_sheet_is_the_plans_steps(
    seed: tuple[Any, dict[str, Any]], lang: str, w3: str
) -> None:
    from geomcad_constructions.sheets_kulisa import WORDS

    sol = seed[0]
    with language(lang):
        main = seed[1][""] if lang == "ru" else _main_sheet(sol)
        steps = {s.name: s for s in sol.construction}
        want = [step_text(steps[n], WORDS) for n in sol.data.plan_steps]
    items = [t.text for t in main.texts() if re.match(r"\d+\. ", t.text)]
    assert len(items) == len(sol.data.plan_steps) == 12
    assert items[-1].startswith("12. ω3 = ") and items[-1].endswith(w3)
    # each item is its step's text (the sheet's texts are plain: markup dropped, lines wrapped)
    assert want[-1].endswith(w3) and want[0] == items[0][3:]
    assert abs(sol.construction["ω3"]) == pytest.approx(3.95484511, rel=1e-8)
    # the hand-written order is gone from both tables
    assert not any(k.startswith("plan_") for k in WORDS.table())


def test_the_plan_is_drawn_at_its_stated_mu(seed: tuple[Any, dict[str, Any]]) -> None:
    sol, main = seed[0], seed[1][""]
    scaled = [s for _, _, s in main.scaled if s.q == "v"]
    assert len(scaled) == len(sol.data.vplan.vectors) == 4
    k = scaled[0].k
    titles = [t.text for t in main.texts() if t.text.startswith("План скоростей")]
    assert titles == [f"План скоростей, μV = {k:g}".replace(".", ",") + " (м/с)/мм"]
    assert not math.isnan(k)


def test_the_solution_lines_are_written_from_their_steps(seed: tuple[Any, dict[str, Any]]) -> None:
    """The graphs sheet's ω1 and ε1 and the fbd sheet's F_x lines are the steps' texts; their
    operands are the recorded values (ω1 by the energy formula = the recorded ω1)."""
    sol = seed[0]
    steps = {s.name: s for s in sol.construction}
    assert [steps[n].kind for n in ("ω1", "ε1", "F_x", "|F_x| (kinetostatics)")] == [
        "energy_theorem", "motion_equation", "equal_power", "balance_statics",
    ]  # fmt: skip
    assert dict(steps["ω1"].args)["w"] == pytest.approx(sol.results["omega1"], rel=1e-12)
    assert dict(steps["ε1"].args)["e"] == sol.results["eps1"]
    assert dict(steps["F_x"].args)["F"] == sol.results["F_x"]
    assert dict(steps["|F_x| (kinetostatics)"].args)["F"] == sol.data.F_x_kinetostatic
    graphs, fbd = seed[1]["graphs"], seed[1]["fbd"]
    g = " ".join(t.text for t in graphs.texts())
    assert "[2·34·2,618/5,671]1/2 = 5,603 рад/с" in g and "= 10,67 рад/с²" in g
    b = " ".join(t.text for t in fbd.texts())
    assert "= 34·5,603/0,4746 = 401,4 Н;" in b and "без сил инерции (г): 401,4 Н." in b


def test_short_velocities_are_points_with_a_note(seed: tuple[Any, dict[str, Any]]) -> None:
    """Near the dead position (φ = 179°) V_2 and V_C3 are under two arrowheads on the plan and
    on the scheme: drawn as their lettered end points, and a note says so; not at the seed."""
    near = _main_sheet(geomcad.solve(PID, phi_deg=179.0))
    note = "короче 7 мм показаны точкой"
    assert note not in " ".join(t.text for t in seed[1][""].texts())
    assert note in " ".join(t.text for t in near.texts())
    assert not [x for x in findings(near) if x.kind == "short-vector"]
