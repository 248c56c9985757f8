"""Where the mechanism's sweep waives the crank's length on the forces sheet (a short crank on
long links: :data:`~geomcad.sheet.linkage_forces.SWEEP_MAX_MM`), the forces sheet's mechanism
is still drawn no coarser than the kinematic sheet draws it, where the format allows it (review
5: the crusher's forces sheet at 1:15, its crank 2.7 mm, beside its kinematic sheet at 1:5)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import linkage_forces as F
from geomcad.sheet.linkage import layout

CRUSHER = (Path(__file__).resolve().parent.parent / "examples" / "crusher.toml").read_text()


def _solved(crank: str) -> Solved:
    """The crusher with its crank ``crank`` m long (the file's is 0.04)."""
    text = CRUSHER.replace("length = 0.04\n", f"length = {crank}\n")
    assert f"length = {crank}\n" in text
    return solve(parse(tomllib.loads(text)))


def _scales(s: Solved) -> tuple[float, float]:
    """The kinematic sheet's μ_l and the forces sheet's mechanism's, where the sweep waives the
    crank's length (the case the rule is for: the crank CRANK_MM long would make the sweep too
    large) and the forces sheet fits."""
    assert F.sweep_mm(s, F.crank_scale(s.linkage).k) > F.SWEEP_MAX_MM
    _tree, z = F.force_layout(s)
    assert z.layout.fits
    (k_mech,) = [pl.scale.k for pl in z.layout
                 if isinstance(pl.view, F._Loaded) and pl.scale is not None]  # fmt: skip
    return layout(s).k_l.k, k_mech


@pytest.mark.parametrize("crank", ["0.04"])
def test_waived_mechanism_no_coarser_than_kinematic(crank: str) -> None:
    k_kin, k_mech = _scales(_solved(crank))
    assert k_mech <= k_kin * (1.0 + 1e-9), (k_mech, k_kin)


def test_waived_mechanism_fits_where_the_kinematic_scale_does_not() -> None:
    """A longer crank: the kinematic sheet's 1:5 leaves the forces sheet no room on A1; the
    sheet still fits, its mechanism as large as the field draws it."""
    s = _solved("0.05")
    assert F.sweep_mm(s, F.crank_scale(s.linkage).k) > F.SWEEP_MAX_MM
    _tree, z = F.force_layout(s)
    assert z.layout.fits


def test_waived_mechanism_at_the_nearest_step_the_format_allows() -> None:
    """A 0.03 m crank: the kinematic sheet keeps its mechanism at 1:4 beside its crank's detail,
    where the forces sheet's A1 holds no 1:4 (nor 1:5): the forces sheet's mechanism is at the
    nearest coarser GOST step that fits, never the field's own search past a step that fits."""
    s = _solved("0.03")
    k_kin, k_mech = _scales(s)
    P, forces, k = F.force_position(s)
    tried = [k_kin, *F._coarser(k_kin)]
    finer = [step for step in tried if step < k_mech * (1.0 - 1e-9)]
    for step in finer:  # every step between the kinematic's and the drawn one: no room on A1
        assert not F._compose2(s, P, forces, k, F.sheet_formats(s.linkage), kin=step)[1].layout.fits
    # (the sheet at k_mech fits: _scales; review 13: the pinned arrangements, the mechanism
    # down the left edge the field's height, hold the kinematic sheet's 1:4 where _compose2's
    # do not, so k_mech may be finer than the steps _compose2 reaches)
