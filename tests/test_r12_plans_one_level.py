"""One detail level on the force plans (review 12, fix list item 1: the slotter's group (4, 5)
plan had details three deep, Ц → Ш/Ю → Я, a circle of a detail drawn on a detail; the
needle's link 4: П2 → Ц2). Every detail is taken from the plan: its circle is on the plan,
never on another detail's drawing; the details that show what a detail's μ_F leaves short are
drawn beside it at a finer μ_F, their letters on the same circle of the plan."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.sheet.model import CircleItem
from geomcad.sheet.views import Polygon

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
FILES = [
    *sorted((TESTS / "linkages_review12").glob("*.toml")),
    *sorted((TESTS / "linkages_layout").glob("*.toml")),
    ROOT / "examples" / "shaper.toml",
]


def _plans(path: Path, monkeypatch: pytest.MonkeyPatch) -> list[tuple[Polygon, Any, list[Any]]]:
    """Each force plan of the file's forces sheet as drawn last: (plan, placed, its items)."""
    from geomcad.sheet import views

    rec: dict[str, tuple[Polygon, Any, list[Any]]] = {}
    draw = views.Polygon.draw

    def rec_draw(self: Polygon, d: Any, at: Any) -> None:
        i = len(d.sheet.items)
        draw(self, d, at)
        rec[self.title] = (self, at, d.sheet.items[i:])

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    sheets = dict(geomcad.solve(str(path)).sheets())
    if "forces" not in sheets:
        pytest.skip("no forces sheet")
    return list(rec.values())


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_no_detail_circle_is_drawn_on_a_detail(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every circle that marks a detail of a force plan lies on the plan (its centre in none
    of the plan's details' slots: no detail of a detail), one circle per spot of the plan
    (the details taken from the plan; those beside them at a finer μ_F are lettered on it)."""
    for p, at, items in _plans(path, monkeypatch):
        v = at.viewport
        slots = []
        for dt in p.details:
            (ax, ay), (bx, by) = v.p((dt.slot[0], dt.slot[1])), v.p((dt.slot[2], dt.slot[3]))
            slots.append((min(ax, bx), min(ay, by), max(ax, bx), max(ay, by), dt.letter))
        circles = [it for it in items if isinstance(it, CircleItem) and not it.fill
                   and it.role == "construction"]  # fmt: skip
        for c in circles:
            inside = [s[4] for s in slots if s[0] < c.c[0] < s[2] and s[1] < c.c[1] < s[3]]
            assert not inside, (path.stem, p.title, c.c, inside)
        assert len(circles) == len({id(dt) for dt in p.details if dt.host is None}), (
            path.stem, p.title)  # fmt: skip
