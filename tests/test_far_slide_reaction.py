"""A sliding pair's reaction whose point would lie off the mechanism (review 11: a small
traverse's guide bar, its 0.34 N reaction 2.8 m from E on a 0.1 m mechanism) is drawn at its
joint with the pair's couple, the same equivalent system, and the forces sheet is laid out."""

from __future__ import annotations

from pathlib import Path

import geomcad
from geomcad.linkage import kinetostatics
from geomcad.sheet import linkage_forces as lf

HERE = Path(__file__).resolve().parent
FILE = HERE / "linkages_review11" / "yarn_guide_traverse.toml"


def _forces() -> tuple[object, kinetostatics.Forces]:
    s = geomcad.solve(str(FILE)).data
    P, f, _k = lf.force_position(s)
    return P, f


def test_a_reaction_off_the_mechanism_is_a_force_at_its_joint_and_a_couple() -> None:
    P, f = _forces()
    pts = list(P.pos.values())  # type: ignore[attr-defined]
    reach = max((p - q).norm for p in pts for q in pts)
    far = []
    for gf in f.groups:
        for r in gf.reactions:
            if r.sliding:
                assert abs(r.h) <= kinetostatics.REACH_MAX * reach
                if r.couple:
                    far.append(r)
                    assert r.h == 0.0
                    assert (r.at - P.pos[r.joint]).norm == 0.0  # type: ignore[attr-defined]
    # the guide bar's frame reaction: a force of 0.34 N that would act 2.8 m off
    assert [r.name for r in far] == ["R_{05}"]
    assert abs(far[0].couple) > kinetostatics.REACH_MAX * reach * far[0].force.norm


def test_the_forces_sheet_of_a_small_traverse_is_laid_out() -> None:
    s = geomcad.solve(str(FILE)).data
    _tree, sized = lf.force_layout(s)  # raised "has no room on the sheet" (review 11)
    titles = {pl.view.title for pl in sized.layout}
    assert {"Группа II(2, 3)", "Группа II(4, 5)"} <= titles
    # no GOST step draws its 12 mm crank 30 mm long on an A1 with the rest: the finest that
    # holds the sheet (1:1; the search alone took 1:4, a 3 mm crank)
    (mech,) = [pl for pl in sized.layout if isinstance(pl.view, lf._Loaded)]
    assert mech.scale is not None
    assert s.linkage.length / mech.scale.k >= 12.0 * (1.0 - 1e-9)
