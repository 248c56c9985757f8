"""The forces sheet's main view at one μ_l with its groups and crank cut out, the crank at least
CRANK_MM long on it (review 12, fix list item 4): the pinned arrangements
(:func:`~geomcad.sheet.linkage_forces._pinned_tree`) are offered whatever the mechanism's shape,
one of them the mechanism over the lever down the left edge the field's height."""

from __future__ import annotations

from pathlib import Path

import geomcad
from geomcad import tol
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.compose import Choice, Column, Row
from geomcad.sheet.linkage import CRANK_MM, _alternatives

ROOT = Path(__file__).resolve().parents[1]
YARN = ROOT / "tests" / "linkages_review11" / "yarn_guide_traverse.toml"
SHAPER = ROOT / "examples" / "shaper.toml"
E = 1.0 + tol.REL_LENGTH


def test_yarn_main_view_crank() -> None:
    """The yarn traverse (12 mm crank, mechanism 297 x 325 mm at 2,5:1): its forces sheet's
    main view draws the crank at least CRANK_MM long (on main: 2:1, 24 mm, the rule met only in
    a crank detail)."""
    s = geomcad.solve(str(YARN)).data
    _tree, z = lf.force_layout(s)
    mech = [pl.scale.k for pl in z.layout if isinstance(pl.view, lf._Loaded) and pl.scale]
    assert s.linkage.length / mech[0] >= CRANK_MM / E, mech


def test_yarn_groups_at_the_main_views_scale() -> None:
    """The yarn traverse's groups and crank cut out at its main view's μ_l (2,5:1; review 13:
    the pinned search takes one μ_l where the groups were apart at the cost of its lever one
    step coarser, its plans still read)."""
    s = geomcad.solve(str(YARN)).data
    _tree, z = lf.force_layout(s)
    mech = [pl.scale.k for pl in z.layout if isinstance(pl.view, lf._Loaded) and pl.scale]
    bodies = [pl.scale.k for pl in z.layout if isinstance(pl.view, lf._FreeBody) and pl.scale]
    assert all(mech[0] / E <= kk <= mech[0] * E for kk in bodies), (mech, bodies)


def _leaves(t: object) -> list[object]:
    items = getattr(t, "items", None)
    return [t] if items is None else [x for it in items for x in _leaves(it)]


def test_pinned_tree_offers_every_form() -> None:
    """Wide or tall, a mechanism is offered across the top and down the left edge, and once
    over the lever in the left column (on main the mechanism's aspect chose the band alone for
    the yarn traverse, which has no room for the polygons under it)."""
    for path, pin in ((YARN, 0.0004), (SHAPER, 0.002)):
        s = geomcad.solve(str(path)).data
        P, f, k = lf.force_position(s)
        tree, _w = lf._sheet2(s, P, f, k, lf.TEXT_H, pin=pin)
        assert isinstance(tree, Choice)
        alts = _alternatives(tree)
        assert len(alts) >= 3, path
        # one alternative whose first column holds the mechanism over the lever
        column = [
            a
            for a in alts
            if isinstance(a, Row)
            and isinstance(a.items[0], Column)
            and [type(v) for v in _leaves(a.items[0])] == [lf._Loaded, lf._Lever]
        ]
        assert column, path
        # and one with the mechanism across the top
        assert any(isinstance(a, Column) and lf._Loaded in map(type, _leaves(a.items[0]))
                   for a in alts), path  # fmt: skip


NEEDLE = ROOT / "tests" / "linkages_review12" / "needle_takeup_sewing.toml"


def test_pinned_box_holds_its_caption_at_its_scale() -> None:
    """The box :func:`~geomcad.sheet.linkage_forces._pinned_tree` gives the mechanism holds its
    caption as it reads at the pinned μ_l on one line (on main the typical caption's width: the
    needle's at 2,5:1 broke into two lines, its drawing fell to 2:1)."""
    from geomcad.sheet.compose import Scale, _lines_width

    s = geomcad.solve(str(NEEDLE)).data
    P, f, _k = lf.force_position(s)
    mech = lf._Loaded(s.linkage, P, f, "Механизм в положении 4, φ_1 = 210°")
    mech.solved = s
    for pin in (0.0004, 0.0005, 0.001):
        said = _lines_width(mech.caption(Scale(pin, "l")), mech.title_height, 1)
        assert lf._body_size(mech, pin)[0] >= said, pin


def test_needle_at_the_kinematic_enlargement() -> None:
    """The needle (15 mm crank): its forces sheet at 2,5:1 (crank 37,5 mm), the scale of its
    kinematic sheet, which its left column holds (on main 2:1, the crank exactly 30 mm), the
    groups and crank cut out at it too."""
    s = geomcad.solve(str(NEEDLE)).data
    _tree, z = lf.force_layout(s)
    mech = [pl.scale.k for pl in z.layout if isinstance(pl.view, lf._Loaded) and pl.scale]
    bodies = [pl.scale.k for pl in z.layout if isinstance(pl.view, lf._FreeBody) and pl.scale]
    assert mech[0] <= 0.0004 * E, mech
    assert all(mech[0] / E <= kk <= mech[0] * E for kk in bodies), (mech, bodies)
