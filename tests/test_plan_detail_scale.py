"""One detail μ_F per force plan, one letter per detail circle, and two-force plans of sane
length, on the forces sheet of every example and layout test file (issue 27, review 7 item 4:
the oscillator's group (2, 3) carried details at 0,5 / 0,05 / 1 N/mm beside its own 4 N/mm,
one circle was lettered "П1, Ш1, Э1", and the plans of two-force links were 90–100 mm twin
lines)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from drawn_plans import drawn_plans

from geomcad.sheet.linkage_forces import SLIVER_GROW_MM
from geomcad.sheet.model import TextItem
from geomcad.sheet.views import DETAIL_MAX_MM, SLIVER_MM, is_sliver

ROOT = Path(__file__).resolve().parents[1]
TESTS = Path(__file__).resolve().parent
TOMLS = [
    *sorted((ROOT / "examples").glob("*.toml")),
    *sorted((TESTS / "linkages_layout").glob("*.toml")),
]
FILES = [
    p
    for p in TOMLS
    if "[drive]" in p.read_text(encoding="utf-8") and "[[group]]" in p.read_text(encoding="utf-8")
]

#: A stated μ_F in a caption: "μF = 0,5 Н/мм" (the value, decimal comma).
MU_F = re.compile(r"μF = ([\d\s]+(?:,\d+)?)")
#: A two-force plan is at most this long (mm; review 7: "≤ ~60 mm", a sane closed figure;
#: review 11: 30–50 mm plans in cells twice their size, so it grows to 80 mm where its box
#: holds it, still one thin closed figure).
TWO_FORCE_MM = 80.0
#: A circle's lettering that lists several details ("П1, Ш1, Э1").
LETTER_LIST = re.compile(r"^[А-ЯA-Z]\d*(, [А-ЯA-Z]\d*)+$")


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_plan_states_one_detail_scale_and_one_letter_per_circle(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every force plan states its own μ_F (in its caption) and one for all its details of a
    tier (each detail's caption states it): one for the details taken from the plan, one
    finer for the details of those details (review 9, item 1: a detail of a detail shows
    what the first cannot); a circle on the plan is lettered with one detail's letter,
    never a list of them."""
    plans = drawn_plans(path, monkeypatch)
    assert plans
    for p, _, items in plans:
        texts = [it.text for it in items if isinstance(it, TextItem)]
        stated = {m for t in texts for m in MU_F.findall(t)}
        tiers = {dt.tier for dt in p.details}
        assert len(stated) <= len(tiers), (path.stem, p.title, sorted(stated))
        for t in tiers:
            assert len({dt.k for dt in p.details if dt.tier == t}) == 1, (path.stem, p.title)
        lists = [t for t in texts if LETTER_LIST.match(t)]
        assert not lists, (path.stem, p.title, lists)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_two_force_plan_is_drawn_short(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A plan along one line (a two-force link, R₀₁ = −R₂₁, or two reactions with a small
    load between: :func:`is_sliver`) draws its longest vector at most SLIVER_MM long, at the
    μ_F its caption states (the shaper's links 2, 3 and crank were 90–100 mm twin lines), and
    SLIVER_MM is within the review's bound."""
    assert SLIVER_MM <= SLIVER_GROW_MM <= TWO_FORCE_MM
    plans = drawn_plans(path, monkeypatch)
    for p, at, _ in plans:
        poly = p.layers[-1][0]
        if not is_sliver(poly):
            continue
        k = at.viewport.scale.k
        big = max(pv.magnitude for pv in poly.vectors)
        assert big / k <= TWO_FORCE_MM * (1.0 + 1e-9), (path.stem, p.title, big / k)
        assert big / k >= SLIVER_MM / 2.0 * (1.0 - 1e-9), (path.stem, p.title, big / k)


def test_a_two_force_plan_grows_into_its_box(monkeypatch: pytest.MonkeyPatch) -> None:
    """Where its box holds it, a sliver is drawn at the finest μ_F of its series that keeps
    its longest vector within SLIVER_GROW_MM, so at least half that long (review 11, item 2:
    the shaper's link 3, R23 = 3458 N at 100 N/mm, 35 mm in a 138 mm × 62 mm cell)."""
    slivers = 0
    for p, at, _ in drawn_plans(ROOT / "examples" / "shaper.toml", monkeypatch):
        poly = p.layers[-1][0]
        if not is_sliver(poly):
            continue
        slivers += 1
        big = max(pv.magnitude for pv in poly.vectors)
        assert big / at.viewport.scale.k >= SLIVER_GROW_MM / 2.0, (
            p.title,
            big / at.viewport.scale.k,
        )
    assert slivers >= 3  # links 2, 3 and the crank


#: A detail's longest vector is drawn at most this long (mm; review 8, item 3: the
#: oscillator's G4 = 24 N drawn 59 mm in a detail beside G5 = 64 N at 16 mm in its plan, the
#: yoke's G5 = 31 N at 15.7 mm beside F_D = 2490 N at 12.4 mm; review 9, item 1: at 30 mm the
#: details named G4, Φ4, Rτ34 of the shaper's group (4, 5) and the given F_B of a compressor's
#: instead of drawing them, the polygon not closed on the sheet: completeness first, 60 mm).
DETAIL_LONGEST_MM = DETAIL_MAX_MM


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_a_detail_is_not_drawn_longer_than_its_plan_needs(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A plan's details of one tier (:attr:`Detail.tier`: one μ_F for them all) enlarge
    their runs at the coarsest μ_F that keeps their longest
    vector within DETAIL_LONGEST_MM, never at a finer one: the detail copy of a small force is
    not drawn several times longer than the plan's own vectors; and at the next coarser μ_F of
    the series its shortest vector drawn would be shorter than two arrowheads, or none of its
    vectors would be drawn longer than at that one, or it would enlarge its plan less than
    DETAIL_LEAST times (it is the coarsest that still reads)."""
    from geomcad.sheet.drawing import SHORT_MM
    from geomcad.sheet.scale import nice_factor
    from geomcad.sheet.views import DETAIL_LEAST

    for p, at, _ in drawn_plans(path, monkeypatch):
        poly = p.layers[-1][0]
        for tier in sorted({dt.tier for dt in p.details}):
            # the details of one tier share one μ_F; the vectors they draw: not those drawn
            # again in a detail of theirs
            of = [dt for dt in p.details if dt.tier == tier]
            k_d = of[0].k
            finer = {n for d2 in p.details for n in d2.run if d2.host in of}
            drawn = [poly[n].magnitude / k_d for dt in of for n in dt.run
                     if n not in dt.listed and n not in finer]  # fmt: skip
            drawn = [mm for mm in drawn if mm > 0.0]
            if not drawn:
                continue
            assert max(drawn) <= DETAIL_LONGEST_MM * (1.0 + 1e-9), (path.stem, p.title, drawn)
            coarser = nice_factor(k_d * 1.01, 1.0, "F").k
            shortest = min(drawn) * k_d / coarser
            # the drawing it is taken from: the plan, or the details of the tier before
            from_k = at.viewport.scale.k
            if tier > 1:
                from_k = next(d2.k for d2 in p.details if d2.tier == tier - 1)
            least = coarser * DETAIL_LEAST > from_k * (1.0 + 1e-9)
            assert (
                shortest < SHORT_MM * (1.0 - 1e-9)
                or max(drawn) * k_d / coarser > DETAIL_LONGEST_MM
                or least
            ), (path.stem, p.title, k_d, coarser, min(drawn))
