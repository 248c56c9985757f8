"""The forces sheet's mechanism at the largest GOST 2.302 step at which everything fits, both
ways (fix list of review 11, item 1):

- an instrument-size mechanism ENLARGED: the yarn traverse's 12 mm crank was drawn 1:1 with a
  2,5:1 crank detail; a teacher wants the mechanism at 2,5:1 (crank CRANK_MM long) with the
  sheet's height, its groups beside at one μ_l of their own at least GROUPS_SHARE of its size,
  and the title block's Масштаб "2,5:1";
- no reduction coarser than needed: where the search kept the crank's rule, the next finer
  GOST step of the mechanism and its groups is taken wherever an arrangement holds it with
  every view but the force plans at a scale no coarser and every plan still read
  (:data:`~geomcad.sheet.linkage_forces.PLAN_READ_MM`; kulisa_inclined_ram was left at 1:4
  where 1:2,5 fits with plans 55–103 mm long).
"""

from __future__ import annotations

from pathlib import Path

import pytest

import geomcad
from geomcad import tol
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.compose import Field, Layout
from geomcad.sheet.frame import FORMATS
from geomcad.sheet.linkage import CRANK_MM, sheet_formats

ROOT = Path(__file__).resolve().parents[1]
YARN = ROOT / "tests" / "linkages_review11" / "yarn_guide_traverse.toml"
E = 1.0 + tol.REL_LENGTH


def _loaded(p: Path) -> bool:
    text = p.read_text(encoding="utf-8")
    return "[links." in text or "[[load]]" in text


FILES = [
    p
    for p in sorted(
        [
            *(ROOT / "tests" / "linkages_layout").glob("*.toml"),
            *(ROOT / "tests" / "linkages_review11").glob("*.toml"),
            ROOT / "examples" / "shaper.toml",
            ROOT / "examples" / "sixbar-2013-6.toml",
        ]
    )
    if _loaded(p)
]


def _links(lay: Layout) -> tuple[float, list[float]]:
    """The mechanism's μ_l and those of its groups and crank cut out."""
    mech = [pl.scale.k for pl in lay if isinstance(pl.view, lf._Loaded) and pl.scale]
    bodies = [pl.scale.k for pl in lay if isinstance(pl.view, lf._FreeBody) and pl.scale]
    return mech[0], bodies


def test_instrument_mechanism_enlarged() -> None:
    """The yarn traverse (12 mm crank): its forces sheet's mechanism at the GOST enlargement
    that draws the crank CRANK_MM long, its groups at least GROUPS_SHARE of its size, the title
    block's Масштаб the enlargement's; no crank detail (the crank is read on the mechanism)."""
    s = geomcad.solve(str(YARN)).data
    L = s.linkage.length
    _tree, z = lf.force_layout(s)
    mk, bodies = _links(z.layout)
    assert mk < L / CRANK_MM * E  # the crank CRANK_MM long on the mechanism: an enlargement
    assert mk * E < 0.001, mk  # finer than 1:1
    assert all(mk / kk >= lf.GROUPS_SHARE / E for kk in bodies), (mk, bodies)
    sheet = dict(lf.force_sheets(s, YARN.stem))["forces"]
    assert sheet.block is not None and sheet.block.scale == "2,5:1", sheet.block
    texts = " ".join(getattr(it, "text", "") for it in sheet.items)
    assert "(2,5:1)" not in texts.replace("М 2,5:1", "")  # no crank detail "Б (2,5:1)"


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_links_at_the_finest_step_that_keeps_plans_read(path: Path) -> None:
    """Where the forces sheet keeps its drawings of links at one μ_l with the crank CRANK_MM
    long, no finer GOST step holds them with every other view but the plans no coarser and
    every plan still read: the links take the field before the plans grow."""
    s = geomcad.solve(str(path)).data
    _tree, z = lf.force_layout(s)
    lay = z.layout
    mk, bodies = _links(lay)
    L = s.linkage.length
    if not (all(mk / E <= kk <= mk * E for kk in bodies) and L / mk >= CRANK_MM / E):
        return  # an exception of test_forces_one_scale's rule: not this rule's case
    lk = s.linkage
    fmts = sheet_formats(lk)
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    if z.fmt != largest:
        return  # a smaller format holds the sheet with its rules: it is full enough
    field = Field.of_format(largest, True)
    room = (field.box[2] - field.box[0], field.box[3] - field.box[1])
    w, h = lf.sweep_box(s)
    finer = [g for g in lf.GOST_K if g * E < mk]
    if not finer:
        return
    pin = max(finer)  # the next finer step
    if w / pin > room[0] or h / pin > room[1]:
        return  # the mechanism alone is larger than the field
    P, f, k = lf.force_position(s)
    got = lf._pin_try(s, P, f, k, None, largest, field, pin, pin)
    assert got is None or not (
        lf._no_coarser(lay, got[1].layout, plans=False) and lf._plans_read(got[1].layout)
    ), (path.stem, mk, pin)


def test_kulisa_at_one_to_two_and_a_half() -> None:
    """kulisa_inclined_ram (120 mm crank): 1:2,5 holds its mechanism, groups and crank at one
    μ_l with plans still read (review 11 found it at 1:4 on a 56 %-blank A1)."""
    path = ROOT / "tests" / "linkages_layout" / "kulisa_inclined_ram.toml"
    s = geomcad.solve(str(path)).data
    _tree, z = lf.force_layout(s)
    mk, bodies = _links(z.layout)
    assert mk <= 0.0025 * E, mk
    assert all(mk / E <= kk <= mk * E for kk in bodies), (mk, bodies)
    assert lf._plans_read(z.layout)
