"""The forces sheet's drawings of links at ONE μ_l with the crank at least CRANK_MM long on
it, wherever an arrangement on the largest format holds that (issue 27, review 10 fix 1:
slider_rocker_rpr's mechanism at 1:2.5 with a 20 mm crank and its crank alone at 1:1, watt2's
groups at 1:4 beside its mechanism at 1:2), and the field not left blank.

Over every file of examples/ and tests/linkages_layout/ with loads. Where the sheet keeps the
mechanism and its groups apart, or the crank short, the exception must be forced: at every GOST
step that draws the crank CRANK_MM long, the mechanism is larger than the field or no
arrangement of :func:`~geomcad.sheet.linkage_forces._pinned` holds all the drawings of links at
that one step (:func:`~geomcad.sheet.linkage_forces._pin_try` finds none) with its force plans
at most one step of their series coarser (the plans are no price of the rule: sixbar-2013-6's
one 1:2 fits only with its plans at 100 N/mm for 40, in a 90 mm strip). The exceptions this
leaves (measured on 46c1160's files): sine_crosshead_rocker (its 1:1 mechanism takes a
689 × 343 mm box, the table and the order alone need 231 mm of the 227 mm under it) and
slider_rocker_rpr (1:1: mechanism 494 × 288 mm and groups 547 × 251 mm leave no room for the
plans), both drawn with the crank on the mechanism CRANK_MM long where that fits and the groups
at one μ_l of their own; the crusher (its sweep with the crank 30 mm long is larger than A1).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from layout import empty_share

import geomcad
from geomcad import tol
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.compose import Field, Layout
from geomcad.sheet.frame import FORMATS
from geomcad.sheet.linkage import CRANK_MM, sheet_formats

ROOT = Path(__file__).resolve().parents[1]


def _loaded(p: Path) -> bool:
    text = p.read_text(encoding="utf-8")
    return "[links." in text or "[[load]]" in text


FILES = [
    p
    for p in sorted(
        [*(ROOT / "examples").glob("*.toml"), *(ROOT / "tests" / "linkages_layout").glob("*.toml")]
    )
    if _loaded(p)
]
E = 1.0 + tol.REL_LENGTH


def _scales(lay: Layout) -> tuple[float, list[float], list[float]]:
    """The mechanism's μ_l, the μ_l of each group cut out and of the crank cut out."""
    mech = [pl.scale.k for pl in lay if isinstance(pl.view, lf._Loaded) and pl.scale]
    bodies = [pl for pl in lay if isinstance(pl.view, lf._FreeBody) and pl.scale]
    groups = [pl.scale.k for pl in bodies if pl.view.gf.group is not None]  # type: ignore[attr-defined, union-attr]
    crank = [pl.scale.k for pl in bodies if pl.view.gf.group is None]  # type: ignore[attr-defined, union-attr]
    return mech[0], groups, crank


def _forced(s: object, lay: Layout) -> bool:
    """Whether no arrangement on the largest format holds the mechanism and its groups at one
    μ_l that draws the crank CRANK_MM long, with its force plans at most one step of their
    series coarser than ``lay`` draws them (the plans are no price of the rule)."""
    lk = s.linkage  # type: ignore[attr-defined]
    fmts = sheet_formats(lk)
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    field = Field.of_format(largest, True)
    room = (field.box[2] - field.box[0], field.box[3] - field.box[1])
    w, h = lf.sweep_box(s)  # type: ignore[arg-type]
    P, f, k = lf.force_position(s)  # type: ignore[arg-type]
    for pin in (g for g in lf.GOST_K if lk.length / g >= CRANK_MM / E):
        if w / pin > room[0] or h / pin > room[1]:
            continue
        got = lf._pin_try(s, P, f, k, None, largest, field, pin, pin)  # type: ignore[arg-type]
        if got is not None and lf._no_coarser(lay, got[1].layout, True):
            return False
    return True


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_one_length_scale_with_the_crank_long(path: Path) -> None:
    s = geomcad.solve(str(path)).data
    _tree, z = lf.force_layout(s)
    mk, groups, cranks = _scales(z.layout)
    bodies = [*groups, *cranks]
    one = all(mk / E <= kk <= mk * E for kk in bodies)
    L = s.linkage.length
    if one and L / mk >= CRANK_MM / E:
        return
    # an exception: forced (no A1 arrangement holds one μ_l with the crank CRANK_MM long)
    assert _forced(s, z.layout), (path.stem, mk, bodies, L / mk)
    # and then the groups at ONE μ_l, at least GROUPS_SHARE of the mechanism's size, and the
    # crank cut out CRANK_MM long where the mechanism's is
    assert len({round(kk, 9) for kk in groups}) <= 1, groups
    assert all(mk / kk >= lf.GROUPS_SHARE / E for kk in groups), (mk, groups)
    if L / mk >= CRANK_MM / E:
        assert all(L / kk >= CRANK_MM / E for kk in cranks), (mk, cranks)


#: The share of a forces sheet's field (30 mm cells, :func:`layout.empty_share`: a cell is blank
#: where nothing drawn comes within 15 mm of its centre) that may stay blank. Measured over these
#: files after the one-μ_l rule: 0.445 (slider-crank) … 0.631 (press_offset_long_rod); on review
#: 10's eight sheets 0.51–0.57 by this count (39–54 % by review 10's field.py). The aim of
#: ≤ 40 % is not reached (only watt2 by field.py): the guard keeps every sheet within the worst
#: measured, so that a change leaving more of a sheet blank fails. Review 11 item 6 took the
#: frame's hatched supports off the cut-out groups (a group is cut free of the frame): their
#: hatching was the only ink of one 30 mm cell of tangent_rocking_slider's sheet (0.639 →
#: 0.641), no view moved; the guard is set by that much higher, not for a sparser layout.
#: Review 11's item 1 took press_offset_long_rod from 1:2,5 to 1:2 (its crank 40 mm, the
#: mechanism the sheet's height, every plan at the μ_F it had): 0.641 by this count too, its
#: drawing larger but centred in a taller box.
BLANK_MAX = 0.645


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_forces_sheet_field_not_left_blank(path: Path) -> None:
    s = geomcad.solve(str(path)).data
    sheets = dict(lf.force_sheets(s, path.stem))
    share = empty_share(sheets["forces"], 30.0)
    assert share <= BLANK_MAX, (path.stem, share)
