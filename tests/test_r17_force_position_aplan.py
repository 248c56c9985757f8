"""The kinematic sheet draws the acceleration plan of the force analysis' position (review 17:
"the inertia forces rest on an a_S that no plan shows"), beside the two of ``phi`` (or of the
largest output accelerations), where the sheet keeps its size rules with it; its ε in the
table of accelerations."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

from geomcad.linkage import parse
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _arranged, layout
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent.parent


def test_the_shapers_force_position_has_its_acceleration_plan() -> None:
    s = solve(parse(tomllib.loads((ROOT / "examples" / "shaper.toml").read_text("utf-8"))))
    P0 = analyse(s).force_position
    assert P0 is not None
    # the case of the rule: the force position is neither of the two
    assert all(abs(math.remainder(phi - P0.phi, 2.0 * math.pi)) > 1e-6 for phi in s.accel_phis)
    lay = layout(s)
    assert len(lay.accel) == len(s.accel_phis) + 1
    assert lay.accel[-1] is P0
    _, lays = _arranged(s)
    drawn = [pl.view.plan for z in lays for pl in z if isinstance(pl.view, PlanView)]
    assert any(p is P0.ap for p in drawn)
