"""One detail level on the force plans (review 12, fix list item 1: the slotter's group (4, 5)
plan had details three deep, Ц → Ш/Ю → Я, a circle of a detail drawn on a detail; the
needle's link 4: П2 → Ц2). Every detail is taken from the plan: its circle is on the plan,
never on another detail's drawing; the details that show what a detail's μ_F leaves short are
drawn beside it at a finer μ_F, their letters on the same circle of the plan."""

from __future__ import annotations

from pathlib import Path

import pytest
from drawn_plans import drawn_plans

from geomcad.sheet.model import CircleItem

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
FILES = [
    *sorted((TESTS / "linkages_review12").glob("*.toml")),
    *sorted((TESTS / "linkages_layout").glob("*.toml")),
    ROOT / "examples" / "shaper.toml",
]


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_no_detail_circle_is_drawn_on_a_detail(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every circle that marks a detail of a force plan lies on the plan (its centre in none
    of the plan's details' slots: no detail of a detail), one circle per spot of the plan
    (the details taken from the plan; those beside them at a finer μ_F are lettered on it)."""
    for p, at, items in drawn_plans(path, monkeypatch):
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
