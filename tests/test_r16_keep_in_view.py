"""The forces a view shows are drawn in it, not only in an inset (issue 27, review 15: the
knuckle press's lever drew P_ур in inset Л1 at a third μ_F, μ_F* = 500 Н/мм, beside F_D alone on
the lever at 4000 Н/мм; the rocking cylinder's group (2, 3) drew R12 in an inset): where the
view's arrows drawn longer, up to ``KEEP_SHARE`` of its larger drawn side and within its box,
draw the lever's P_ур or a free body's reaction in the view itself, they are, the lever drawn as
large as its box allows first (the double-kulisa screen's lever keeps μ_V = 0,004, not 0,005
with longer arrows)."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.loads import VIEW_OWN_MM

ROOT = Path(__file__).resolve().parent.parent
KNUCKLE = ROOT / "tests" / "linkages_review13" / "knuckle_coining_press.toml"
ROCKING = ROOT / "tests" / "linkages_arms" / "rocking_cylinder_rocker.toml"
SCREEN = ROOT / "tests" / "linkages_layout" / "double_kulisa_screen.toml"


def _views(path: Path, mp: pytest.MonkeyPatch) -> list[tuple[Any, Any, Any]]:
    """The views of the file's forces sheet as placed: (view, placed, force scales)."""
    rec: list[tuple[Any, Any, Any]] = []
    orig = lf._ByScale.placed

    def placed(self: Any, at: Any) -> Any:
        fs = orig(self, at)
        rec.append((self, at, fs))
        return fs

    mp.setattr(lf._ByScale, "placed", placed)
    sheets = lf.force_sheets(solve(parse(tomllib.loads(path.read_text("utf-8")))), "x")
    sheet = sheets[0][1]
    return [r for r in rec if r[1].viewport.sheet is sheet]


def test_the_levers_p_bal_is_drawn_on_the_lever() -> None:
    with pytest.MonkeyPatch.context() as mp:
        views = _views(KNUCKLE, mp)
    (lever, at, fs), *_ = [r for r in views if isinstance(r[0], lf._Lever)]
    P_bal = lever.f.lever.F_bal.norm
    # in the lever itself, at its one μ_F, at least two arrowheads long
    assert fs.tier(P_bal) == 0
    assert P_bal / fs.k >= VIEW_OWN_MM * (1.0 - 1e-9)
    # the arrows keep within the lever's box: the longest within KEEP_SHARE of its larger side
    x0, y0, x1, y1 = lever.extent()
    side = max(at.scale.mm(x1 - x0), at.scale.mm(y1 - y0))
    assert max(lever._forces) / fs.k <= lf.KEEP_SHARE * side * (1.0 + 1e-9)


def test_a_free_bodys_reactions_are_drawn_on_it_where_its_box_has_room() -> None:
    with pytest.MonkeyPatch.context() as mp:
        views = _views(ROCKING, mp)
    bodies = [r for r in views if isinstance(r[0], lf._FreeBody) and "(2, 3)" in r[0].title]
    assert len(bodies) == 1
    body, _, fs = bodies[0]
    assert body._keep
    assert all(fs.tier(F) == 0 for F in body._keep if fs.zero < F)


def test_the_lever_is_drawn_as_large_as_its_box_allows_first() -> None:
    # its P_ур is drawn on it at the lever's grown μ_V already: longer arrows first would
    # have drawn the lever a step smaller (0,005 (м/с)/мм)
    with pytest.MonkeyPatch.context() as mp:
        views = _views(SCREEN, mp)
    (lever, at, fs), *_ = [r for r in views if isinstance(r[0], lf._Lever)]
    assert at.scale.k == pytest.approx(0.004, rel=1e-9)
    assert fs.tier(lever.f.lever.F_bal.norm) == 0
