"""Review 14, item 2: the forces layout falls back instead of failing.

A forces layout that finds no room for a view on the file's formats ("parameter layout =
'План сил группы (4, 5)': has no room on the sheet") is laid out again on the next larger
format (A1 → A0, :func:`linkage_forces.fallback_formats`) before it fails. The failure is made
here by a monkeypatch of the composition on the file's own formats (no file of the review's 39
fails at any of its numbered force positions on fe82f2d: the sweep of the report); the sweep
below runs a few force positions of review 14's files through the layout and the layout checker.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from layout import layout_problems

from geomcad import cli
from geomcad.errors import ParameterError
from geomcad.sheet import linkage_forces as lf

HERE = Path(__file__).parent
PUMP = HERE / "linkages_review14" / "pump-inclined-kulisa.toml"
ELLIPSOGRAPH = HERE / "linkages_review14" / "ellipsograph_blanking_press.toml"
WALKBEAM = HERE / "linkages_review14" / "walkbeam.toml"


def _solved(path: Path, position: int | None = None) -> Any:
    sets = [] if position is None else [f"forces.position={position}"]
    return cli._solve(str(path), sets).data


def _forces_sheet(s: Any) -> Any:
    tree, z = lf.force_layout(s)
    d = z.start(lf._title(s.linkage, "forces", "X", 3, 4))
    lf.compose(d, tree, layout=z.layout)
    for pl in z.layout:
        if isinstance(pl.view, lf._Loaded):
            pl.view.sheet_detail(d, pl)
    return z, d.finish()


def _no_room_below_a0(monkeypatch: pytest.MonkeyPatch) -> None:
    """The forces layout finds no room for a view on any format smaller than A0."""
    real = lf._compose2

    def no_room(s: Any, P: Any, f: Any, k: Any, fmts: Any, kin: Any = None) -> Any:
        if "A0" not in fmts:
            raise ParameterError("layout", "План сил группы (4, 5)", "has no room on the sheet")
        return real(s, P, f, k, fmts, kin=kin)

    monkeypatch.setattr(lf, "_compose2", no_room)


def test_no_room_on_a1_falls_back_on_a0(monkeypatch: pytest.MonkeyPatch) -> None:
    _no_room_below_a0(monkeypatch)
    z, sheet = _forces_sheet(_solved(PUMP))
    assert z.fmt == "A0"
    assert (sheet.width, sheet.height) == (1189.0, 841.0)
    assert not [p for p in layout_problems(sheet) if p.startswith("outside the frame")]


def test_the_fallback_is_the_next_larger_format() -> None:
    lk = _solved(PUMP).linkage
    assert lf.fallback_formats(lk) == ("A0",)


def test_a_format_the_file_states_is_kept(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """A file's ``[sheet] format`` is the format the sheets are handed in on: no room on it is
    the layout's error naming the view, never a sheet on the next larger format."""
    _no_room_below_a0(monkeypatch)
    path = tmp_path / PUMP.name
    text = PUMP.read_text(encoding="utf-8").replace("[sheet]\n", '[sheet]\nformat = "A1"\n')
    path.write_text(text, encoding="utf-8")
    s = _solved(path)
    assert s.linkage.sheet["format"] == "A1"
    assert lf.fallback_formats(s.linkage) == ()
    with pytest.raises(ParameterError, match="has no room on the sheet"):
        lf.force_layout(s)


@pytest.mark.parametrize(
    ("path", "position"),
    [(PUMP, 4), (ELLIPSOGRAPH, None), (WALKBEAM, 7)],
    ids=["pump-4", "ellipsograph", "walkbeam-7"],
)
def test_force_positions_are_laid_out_within_the_frame(path: Path, position: int | None) -> None:
    z, sheet = _forces_sheet(_solved(path, position))
    assert z.fmt in ("A2", "A1")
    bad = [p for p in layout_problems(sheet) if p.startswith("outside the frame")]
    assert not bad, bad
