"""The images of the links' centres of mass on the kinematic sheet's plans (review 17: "s_i on
no velocity or acceleration plan", while the forces sheet reads Ф_i = m_i·a_Si and the dynamics
sheet I_пр from them): s2 the middle of ab (S2 the middle of AB), its vector from the pole."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import layout
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent.parent


def test_the_crushers_plans_show_every_centre_of_mass_by_similarity() -> None:
    s = solve(parse(tomllib.loads((ROOT / "examples" / "crusher.toml").read_text("utf-8"))))
    lk = s.linkage
    lay = layout(s)
    views = [p.view for z in lay.sized for p in z.layout if isinstance(p.view, PlanView)]
    accel = [v for v in views if v.plan.kind == "a"]
    assert accel
    shown = 0
    for v in views:
        P = next(Q for Q in (*s.drawn, *lay.accel) if v.plan is Q.vp or v.plan is Q.ap)
        field = P.vel if v.plan.kind == "v" else P.acc
        for link in (2, 3, 4, 5):  # each with a mass, its centre the middle of its joints
            name = v.plan.name(f"s{link}")
            assert name in v.centres, (link, v.title)
            q = v.shown.points[name]
            A, B = lk.link_points(link)
            exact = (field[A] + field[B]) * 0.5  # V_S (a_S) of the middle of AB
            assert math.isclose(q.x, exact.x, abs_tol=1e-9 * max(1.0, exact.norm))
            assert math.isclose(q.y, exact.y, abs_tol=1e-9 * max(1.0, exact.norm))
            shown += 1
    assert shown == 4 * len(views)


def test_the_centres_are_lettered_on_the_sheet() -> None:
    from geomcad.sheet.linkage import kinematic_sheets

    s = solve(parse(tomllib.loads((ROOT / "examples" / "crusher.toml").read_text("utf-8"))))
    texts = [t.text for _, sheet in kinematic_sheets(s, "x") for t in sheet.texts()]
    for link in (2, 3, 4, 5):
        # on a velocity plan ("s2", or in a list "a, s2") and an acceleration plan ("s2'")
        assert any(f"s{link}" in t and "'" not in t for t in texts), link
        assert any(f"s{link}'" in t for t in texts), link
