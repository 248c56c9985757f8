"""The mechanism view in its numbered positions (GOST 2.770 scheme): a slider's fixed guide drawn
as its axis over the slider's whole travel, every traced path of a named point numbered like the
joints' paths, and a named point's index (S2) set as a subscript."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, scheme, solve
from geomcad.sheet.drawing import Viewport
from geomcad.sheet.linkage import _principal, kinematic_sheets, layout
from geomcad.sheet.model import Polyline, TextItem
from geomcad.sheet.text import SUP_RISE, box, metrics, placed_runs, run_size, sup_rise
from geomcad.sheet.text import parse as markup

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _solved(name: str) -> Solved:
    data = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    return solve(parse(data))


def _viewport(s: Solved) -> Viewport:
    lay = layout(s)
    v = lay.sized[0].layout[lay.mech].viewport
    assert v is not None
    return v


def _along(it: Polyline, ref: tuple[float, float], u: tuple[float, float], ts: list[float]) -> bool:
    """Whether ``it`` is a line on the axis through ``ref`` along ``u`` reaching 3 mm past both
    ends of the travel ``ts`` (positions along ``u`` from ``ref``)."""
    if len(it.points) != 2 or it.closed:
        return False
    if any(abs((p[0] - ref[0]) * u[1] - (p[1] - ref[1]) * u[0]) > 0.3 for p in it.points):
        return False
    ends = [(p[0] - ref[0]) * u[0] + (p[1] - ref[1]) * u[1] for p in it.points]
    return min(ends) < min(ts) - 3.0 and max(ends) > max(ts) + 3.0


def test_a_sliders_frame_guide_is_drawn_over_its_whole_travel() -> None:
    s = _solved("slider-crank")
    sheet = kinematic_sheets(s)[0][1]
    v = _viewport(s)
    P0, _ = _principal(s)
    mech = scheme(s.linkage, P0)
    pairs = [p for p in mech.pairs if p.kind == "P" and mech.frame in p.links]
    assert pairs
    for pair in pairs:
        name = pair.name.split(":")[0]
        assert pair.axis is not None
        u = v.paper_dir(pair.axis)
        stops = [v.p(P.pos[name]) for P in s.drawn]
        ref = stops[0]
        ts = [(q[0] - ref[0]) * u[0] + (q[1] - ref[1]) * u[1] for q in stops]
        assert max(ts) - min(ts) > 10.0  # the slider travels (mm on the sheet)

        lines = [it for it in sheet.items if isinstance(it, Polyline) and _along(it, ref, u, ts)]
        assert lines, f"the guide of {pair.name} is not drawn over the slider's travel"


def _numbers_near(sheet_items: list[object], q: tuple[float, float], mm: float) -> set[int]:
    out: set[int] = set()
    for it in sheet_items:
        if not isinstance(it, TextItem):
            continue
        c = (it.at[0] + it.width / 2.0, it.at[1] - it.height / 2.0)
        if math.dist(c, q) > mm:
            continue
        parts = it.text.split("\u2013")
        if all(p.isdigit() for p in parts):
            lo, hi = int(parts[0]), int(parts[-1])
            out |= set(range(lo, hi + 1))
    return out


def test_a_coupler_points_path_carries_the_position_numbers() -> None:
    s = _solved("four-bar")
    assert [p.name for p in s.linkage.points] == ["M"]
    sheet = kinematic_sheets(s)[0][1]
    v = _viewport(s)
    items = list(sheet.items)
    missing = [
        i for i, P in enumerate(s.drawn) if i not in _numbers_near(items, v.p(P.pos["M"]), 6.0)
    ]
    # every position of M numbered next to it (a number shared by positions closer than 2.5 mm)
    assert not missing, f"M's positions {missing} carry no number"


def test_a_named_points_index_is_a_subscript_on_the_mechanism() -> None:
    s = _solved("slider-crank")
    assert "S2" in [p.name for p in s.linkage.points]
    sheet = kinematic_sheets(s)[0][1]
    v = _viewport(s)
    P0, _ = _principal(s)
    at = v.p(P0.pos["S2"])
    near = [
        it
        for it in sheet.items
        if isinstance(it, TextItem) and math.dist((it.at[0], it.at[1]), at) < 12.0
    ]
    assert not any(it.text == "S2" and len(it.runs) == 1 for it in near), "S2 printed flat"
    assert any(
        [(r.text, r.shift) for r in it.runs] == [("S", "base"), ("2", "sub")] for it in near
    ), [it.text for it in near]


def test_no_index_is_smaller_than_the_least_gost_height() -> None:
    # SHEETS.md (GOST 2.304): indices no smaller than 2.5 mm, on every label of a file's sheet
    # (a subscript and a superscript: a^n, a^τ, i^{-1}, R^* alike)
    m = metrics()
    small = set()
    for _, sheet in kinematic_sheets(_solved("slider-crank")):
        for it in sheet.items:
            if not isinstance(it, TextItem) or it.height < 2.5:
                continue
            for run, _x, _y, size in placed_runs(it):
                cap = size * m.cap_height / m.units_per_em
                if run.shift != "base" and cap < 2.5 - 1e-6:
                    small.add((it.text, it.height, round(cap, 2)))
    assert not small, sorted(small)[:5]


def test_an_index_keeps_its_scale_above_the_least_height() -> None:
    m = metrics()
    fs = m.font_size(5.0)
    assert run_size(fs, "sub") == pytest.approx(0.7 * fs)
    assert run_size(m.font_size(2.5), "sub") == pytest.approx(m.font_size(2.5))
    assert run_size(fs, "base") == fs
    assert run_size(fs, "sup") == pytest.approx(0.7 * fs)
    assert run_size(m.font_size(2.5), "sup") == pytest.approx(m.font_size(2.5))
    assert run_size(m.font_size(3.5), "sup") == pytest.approx(m.font_size(2.5))


def test_a_raised_mark_keeps_its_top_and_stays_raised() -> None:
    # a superscript the least height enlarges rises less: its top (and a label's box, hence the
    # sheets' line pitch) stays where a 0.7 one's would be, its baseline still above the text's
    m = metrics()
    em = m.cap_height / m.units_per_em
    for cap in (2.5, 3.5, 5.0):
        fs = m.font_size(cap)
        top = sup_rise(fs) + run_size(fs, "sup") * em
        assert top == pytest.approx(SUP_RISE * fs + 0.7 * cap)
        assert sup_rise(fs) > 0.25 * cap
        assert box(markup("a^n"), cap)[1] == pytest.approx(top)
