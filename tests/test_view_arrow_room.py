"""A forces-sheet view's μ_F from its drawn size (issue 27): the longest load arrow of the
mechanism view, of a group's free body and of Zhukovsky's lever takes up to ARROW_SHARE of the
view's larger drawn side (at least its least room, LOAD_MM or LEVER_LOAD_MM), so that a view
drawn large draws more of its forces in itself and fewer in insets; never so long that an
arrow at its point would leave the view's box (then the least room's μ_F)."""

from __future__ import annotations

import itertools
import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve

ROOT = Path(__file__).resolve().parent.parent
FILES = [ROOT / "examples" / f"{n}.toml" for n in ("crusher", "shaper", "slider-crank")]
FILES += sorted((ROOT / "tests" / "linkages").glob("*.toml"))[:3]


@pytest.mark.parametrize(("least", "margin"), [(24.0, 24.0), (24.0, 18.0), (40.0, 40.0)])
def test_arrow_room_grows_with_the_view_and_keeps_in_its_box(least: float, margin: float) -> None:
    from geomcad.sheet.linkage_forces import ARROW_SHARE, arrow_room

    sizes = [(w, h) for w in (5.0, 60.0, 150.0, 300.0) for h in (5.0, 40.0, 120.0, 280.0)]
    for w, h in sizes:
        room = arrow_room(least, margin, (w, h))
        assert room >= least
        # an arrow at a point of the drawing keeps in the box, leaving or arriving
        assert room <= max(least, margin + 0.5 * min(w, h)) + 1e-9
        assert room <= max(least, ARROW_SHARE * max(w, h)) + 1e-9
        # larger on paper: never less room
        for a, b in ((w * 1.5, h), (w, h * 1.5)):
            assert arrow_room(least, margin, (a, b)) >= room - 1e-9
    # a view 300 mm across draws its longest arrow a quarter to a third of it
    assert 75.0 <= arrow_room(least, margin, (300.0, 280.0)) <= 100.0 + 1e-9


def _placed(text: str, monkeypatch: pytest.MonkeyPatch) -> list[tuple[Any, Any, Any, Any]]:
    from geomcad.sheet import linkage_forces as lf

    rec: list[tuple[Any, Any, Any, Any]] = []
    orig = lf._ByScale.placed

    def placed(self: Any, at: Any) -> Any:
        fs = orig(self, at)
        rec.append((self, at, self.arrows(), fs))
        return fs

    monkeypatch.setattr(lf._ByScale, "placed", placed)
    lf.force_sheets(solve(parse(tomllib.loads(text))), "x")
    return rec


def test_views_draw_their_forces_as_long_as_their_size_allows(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from geomcad.sheet.linkage_forces import ARROW_SHARE, _within, arrow_room
    from geomcad.sheet.loads import INSET_CAP_MM, VIEW_SHORT_MM

    finer = 0
    for path in FILES:
        rec = _placed(path.read_text("utf-8"), monkeypatch)
        assert rec, path
        for view, at, arrows, fs in rec:
            least = view.scales_at(None)
            x0, y0, x1, y1 = view._ext
            size = (at.scale.mm(x1 - x0), at.scale.mm(y1 - y0))
            room = arrow_room(view._least, view.margin, size)
            big = max(view._forces)
            # within its arrow room; past it (up to ARROW_SHARE of its larger side) only where
            # that leaves out fewer forces (issue 27: a free body's reaction never left out)
            far = max(room, ARROW_SHARE * max(size))
            assert big / fs.k <= far * (1.0 + 1e-9), (path.stem, fs.k, room)
            # never coarser than the least room's; never a force more left out (named, not
            # drawn), and then never one more in an inset (issue 27: one inset μ_F a view)
            assert fs.k <= least.k
            short = [F for F in view._forces if fs.tier(F) not in (0, None)]

            def cost(f: Any, forces: list[float] = view._forces) -> tuple[int, int, int]:
                left = sum(1 for F in forces if f.zero < F and f.tier(F) is None)
                over = int(f.over > 1.0 + 1e-9)  # an inset arrow past the view's shortest
                return left, over, sum(1 for F in forces if f.tier(F) not in (0, None))

            assert cost(fs) <= cost(least)
            # in insets: the forces short at the view's μ_F, or under its least drawn there
            # where that lets its insets draw more (issue 27, review 7 item 2)
            assert all(F / fs.k < INSET_CAP_MM and fs.least > F for F in short)
            assert all(F / fs.k >= VIEW_SHORT_MM * (1.0 - 1e-9) for F in view._forces
                       if fs.tier(F) == 0)  # fmt: skip
            # the caption states the μ_F drawn: one function of the view's scale
            # (each inset at one μ_F: the same scales with the forces of a place pinned to one
            # of its tiers, a tier no force is drawn at left out, the view's own μ_F kept)
            base = view.scales_at(at.scale)
            assert fs == base or (
                fs.pinned and fs.k == base.k and set(fs.scales) <= set(base.scales)
            ), (fs, base)
            if fs.k < least.k:
                finer += 1
                # no more forces left out or in insets than at the least room (as many: the
                # longer arrows use the view, review 7), and each arrow fits at its point
                # within the drawing and its margin
                assert cost(fs) <= cost(least)
                m = view.margin * at.scale.k
                box = (x0 - m, y0 - m, x1 + m, y1)  # the caption over the drawing
                for p, F in arrows:
                    if fs.tier(F.norm) == 0:
                        u = F * (at.scale.k / fs.k)
                        ends = [(p.x + u.x, p.y + u.y), (p.x - u.x, p.y - u.y)]
                        assert any(_within(e, box, 0.1 * at.scale.k) for e in ends), (path.stem, F)
    assert finer, "some view drawn large takes a finer μ_F than its least room's"


def test_share_of_the_view_is_nice_and_monotone() -> None:
    from geomcad.sheet.loads import view_scales

    forces = [6160.0, 5080.0, 3920.0, 1080.0, 1020.0, 580.0, 260.0, 200.0, 140.0, 100.0]
    counts, left = [], []
    for room in (40.0, 55.0, 75.0, 100.0):
        fs = view_scales(forces, room)
        assert max(forces) / fs.k <= room
        # not drawn in the view itself: in its insets or named under its caption
        counts.append(sum(1 for F in forces if fs.tier(F) != 0))
        # drawn to no scale (each over 0.5 % of the largest: never, review 9)
        left.append(sum(1 for F in forces if fs.tier(F) is None or fs.is_fixed(F)))
        assert all(fs.tier(F) is not None for F in forces)
    assert all(a >= b for a, b in itertools.pairwise(counts)), counts
    # no room leaves one to no scale: a second inset μ_F draws what one cannot (review 9;
    # review 7 item 2: a larger room left fewer out)
    assert left == [0] * len(left), left
