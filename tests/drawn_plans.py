"""The force plans of a file's forces sheet as they are drawn (for the plan tests)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.sheet.views import Polygon

#: A plan as drawn: (plan, placed, its items).
Drawn = tuple[Polygon, Any, list[Any]]


def drawn_plans(path: Path, monkeypatch: pytest.MonkeyPatch) -> list[Drawn]:
    """Each force plan of the file's forces sheet as drawn last; the test is skipped where the
    file has no forces sheet."""
    from geomcad.sheet import views

    rec: dict[str, Drawn] = {}
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
