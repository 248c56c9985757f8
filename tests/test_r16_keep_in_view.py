"""The forces a view shows are drawn in it, not only in an inset (issue 27, review 15: the
knuckle press's lever drew P_ур in inset Л1 at a third μ_F, μ_F* = 500 Н/мм, beside F_D alone on
the lever at 4000 Н/мм; the rocking cylinder's group (2, 3) drew R12 in an inset): where the
view's arrows drawn longer, up to ``KEEP_SHARE`` of its larger drawn side and within its box,
draw the lever's P_ур or a free body's reaction in the view itself, they are, the lever drawn as
large as its box allows first (the double-kulisa screen's lever keeps μ_V = 0,004, not 0,005
with longer arrows). A free body takes for its arrows the room its box leaves round its drawing,
not only its least margin (``FREE_MARGIN``): "μ_F as fine as fits" (the gang saw's group (4, 5)
drew R05 10 mm in a box with room for 25), every arrow inside its box, its caption's μ_F the
one its arrows are drawn at (the caption is drawn before the view)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.loads import VIEW_OWN_MM
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parent.parent
GANG_SAW = ROOT / "tests" / "linkages_review13" / "gang_saw_frame_feed.toml"
SIXBAR = ROOT / "examples" / "sixbar-2013-6.toml"
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


@pytest.mark.parametrize("path", [GANG_SAW, SIXBAR], ids=lambda p: p.stem)
def test_a_free_body_draws_its_forces_as_long_as_its_box_allows(path: Path) -> None:
    arrows: list[tuple[Any, float, tuple[tuple[float, float], tuple[float, float]]]] = []
    orig = lf.force

    def rec(v: Any, at: Any, F: Any, k_F: float, *a: Any, **kw: Any) -> Any:
        out = orig(v, at, F, k_F, *a, **kw)
        if out is not None:
            arrows.append((v, F.norm, out))
        return out

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(lf, "force", rec)
        views = _views(path, mp)
    sheet = views[0][1].viewport.sheet
    captions = [it.text for it in sheet.items if isinstance(it, TextItem)]
    longer = 0
    for body, at, fs in (r for r in views if isinstance(r[0], lf._FreeBody)):
        mine = [(F, ends) for v, F, ends in arrows if v is at.viewport]
        assert mine, body.title
        x0, y0, x1, y1 = at.box
        for _, ends in mine:
            for x, y in ends:
                assert x0 - 1e-6 <= x <= x1 + 1e-6 and y0 - 1e-6 <= y <= y1 + 1e-6, body.title
        # the caption states the μ_F the view's own arrows are drawn at
        own = [F / (math.dist(*ends)) for F, ends in mine if fs.tier(F) == 0]
        assert own and all(k == pytest.approx(fs.k, rel=1e-6) for k in own), body.title
        said = fs.caption().replace("_", "").replace("{", "").replace("}", "")
        assert any(body.title in c and c.endswith(said) for c in captions), (body.title, said)
        # at its least margin the view would draw them at a coarser μ_F, or at the same
        body.margin = lf.FREE_MARGIN
        body.__dict__.pop("_by_scale", None)
        least = body.scales_at(at.scale)
        assert fs.k <= least.k * (1.0 + 1e-9)
        longer += fs.k < least.k * (1.0 - 1e-9)
    assert longer >= 1
