"""The kinematic sheets' composition, review 8 (issue 27): the size rules on every layout test
file (the rocking cylinder's mechanism was drawn at 1:2, its 55 mm crank 27.5 mm long, with
its velocity plans at pa = 38 mm); a crank's detail only beside the finest GOST scale of the
mechanism that fits (the oscillator's 1:2,5 beside a 1:1 detail on a sheet 51 % blank); the
velocity plans' own sheet on the smallest format that holds them at pa's rule (in cells fitted
to each column's and row's largest plan)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, solve
from geomcad.sheet import formats
from geomcad.sheet.compose import _GOST_K, Field, Figure, Grid, arrange
from geomcad.sheet.frame import FORMATS
from geomcad.sheet.linkage import (
    CRANK_MM,
    PA_MM,
    _accel_positions,
    _alternatives,
    _arranged,
    _CrankDetail,
    _Mechanism,
    _trees,
    sheet_formats,
    text_height,
)
from geomcad.sheet.views import PlanView

ROOT = Path(__file__).resolve().parent
LAYOUT_FILES = sorted((ROOT / "linkages_layout").glob("*.toml"))
EXAMPLES = [ROOT.parent / "examples" / f"{n}.toml" for n in ("shaper", "rocking-slider")]


def _solved(path: Path) -> Solved:
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("path", LAYOUT_FILES + EXAMPLES, ids=lambda p: p.stem)
def test_the_crank_and_pa_keep_their_rules_on_every_layout_file(path: Path) -> None:
    """Review 8: the rocking cylinder's kinematic sheet drew its crank 27.5 mm (1:2, no
    detail) and pa 38 mm (μ_V 0,02) beside it: both under the rules the sheet states. The
    mechanism (or its crank's detail) draws the crank CRANK_MM long, pa is PA_MM, every
    sheet fits."""
    s = _solved(path)
    lk = s.linkage
    lay, lays = _arranged(s)
    assert all(z.layout.fits for z in lay.sized)
    crank = max(
        pl.scale.mm(lk.length)
        for pl in lays[0]
        if isinstance(pl.view, _Mechanism | _CrankDetail) and pl.scale is not None
    )
    assert crank >= CRANK_MM - 1e-9
    assert lay.k_v.mm(abs(lk.omega) * lk.length) >= PA_MM - 1e-9


@pytest.mark.parametrize("path", LAYOUT_FILES, ids=lambda p: p.stem)
def test_a_crank_detail_only_beside_the_finest_mechanism_that_fits(path: Path) -> None:
    """Review 8: the oscillator's mechanism at 1:2,5 (crank 20 mm) in a corner beside a 1:1
    detail of its crank, on a sheet half blank where 1:2 fits. Where the first sheet draws
    the crank's detail, the same sheet (its views, its format) arranged to draw the
    mechanism at the next finer GOST scale with the detail at the crank's rule does not
    fit: the detail is the last resort, not a replacement for the mechanism's growth."""
    s = _solved(path)
    lk = s.linkage
    lay, lays = _arranged(s)
    if not any(isinstance(pl.view, _CrankDetail) for pl in lays[0]):
        return
    k = lay.k_l.k
    finer = max((g for g in _GOST_K if g < k * (1.0 - 1e-9)), default=None)
    if finer is None:
        return
    z = lay.sized[0]
    h = text_height((z.fmt,))
    trees, mech, _, _ = _trees(
        s, _accel_positions(s), h, True, (True, True), lay.second, lay.balanced,
        lay.k_v.k, finer,
    )  # fmt: skip
    alt = arrange(trees[0], Field.of_format(z.fmt, z.landscape))
    scale = alt[mech].scale
    detail = [pl for pl in alt if isinstance(pl.view, _CrankDetail)]
    grown = (
        alt.fits
        and scale is not None
        and scale.k <= finer * (1.0 + 1e-9)
        and all(pl.scale is not None and pl.scale.mm(lk.length) >= CRANK_MM for pl in detail)
    )
    assert not grown, (path.stem, k, finer)


@pytest.mark.parametrize("path", LAYOUT_FILES, ids=lambda p: p.stem)
def test_a_plans_sheet_takes_a_larger_format_only_where_a_smaller_one_misses_pa(
    path: Path,
) -> None:
    """Review 8: the rocking cylinder's twelve velocity plans took an A1 68 % blank at pa =
    77 mm (μ_V 0,01; 0,02 draws pa 38.5 mm, under the rule): in equal cells, each as large as
    the largest plan's width and height, they fit no A2. Where a file's velocity plans have a
    sheet of their own, no smaller format of the file's holds them all at that sheet's μ_V
    (pa's rule kept) and fits."""
    s = _solved(path)
    lk = s.linkage
    lay, _ = _arranged(s)
    if not lay.second:
        return
    z = lay.sized[-1]
    assert lay.k_v.mm(abs(lk.omega) * lk.length) >= PA_MM - 1e-9
    area = FORMATS[z.fmt][0] * FORMATS[z.fmt][1]
    smaller = [f for f in sheet_formats(lk) if FORMATS[f][0] * FORMATS[f][1] < area]
    trees, _, _, wants = _trees(
        s, _accel_positions(s), text_height((z.fmt,)), False, (True, True), True, True
    )
    plans = {v: k for v, k in wants.items() if isinstance(v, PlanView)}
    for f in smaller:
        field = Field.of_format(f, True)
        for alt in _alternatives(trees[1]):
            try:
                small = arrange(alt, field)
            except ValueError:
                continue
            assert not (small.fits and formats.meets(small, plans)), (path.stem, f)


def test_a_fitted_grid_draws_unlike_plans_larger_than_equal_cells() -> None:
    """A fitted grid's columns and rows follow their largest drawings: plans long in one
    position and tall in another (a row of two long ones over a row of two tall ones) get a
    larger scale than in equal cells, and each drawing stays inside its cell."""
    sizes = [(8.0, 1.0), (8.0, 1.0), (1.0, 8.0), (1.0, 8.0)]

    def grid(fitted: bool) -> tuple[Grid, list[Figure]]:
        figs = [
            Figure((0.0, 0.0, w, h), lambda v: None, quantity="v", series="nice", group="v")
            for w, h in sizes
        ]
        return Grid(*figs, cols=2, group="v", fitted=fitted), figs

    field = Field.of_format("A3", True)
    equal, _ = grid(False)
    fitted, figs = grid(True)
    k_equal = arrange(equal, field).scale("v").k
    lay = arrange(fitted, field)
    assert lay.fits
    assert lay.scale("v").k < k_equal
    for f, (w, h) in zip(figs, sizes, strict=True):
        x0, y0, x1, y1 = lay[f].box
        assert lay.scale("v").mm(w) <= x1 - x0 and lay.scale("v").mm(h) <= y1 - y0


@pytest.mark.parametrize(
    ("path", "both"),
    [
        (Path(__file__).resolve().parent / "linkages_outlines" / "bellcrank_sixbar.toml", True),
        (Path(__file__).resolve().parent.parent / "examples" / "shaper.toml", False),
    ],
    ids=["phi", "numbered"],
)
def test_the_acceleration_section_is_titled_by_what_it_holds(path: Path, both: bool) -> None:
    """Review 9: "Планы ускорений" stood over the velocity plan of a `phi` position (drawn
    beside its acceleration plan): that section is "Планы скоростей и ускорений"; a section of
    acceleration plans alone keeps its title."""
    from geomcad.sheet.lang import language
    from geomcad.sheet.linkage import kinematic_sheets
    from geomcad.sheet.model import TextItem

    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    with language("ru"):
        texts = [
            "".join(r.text for r in it.runs)
            for _name, sheet in kinematic_sheets(s, "x")
            for it in sheet.items
            if isinstance(it, TextItem)
        ]
    assert any(t.startswith("Планы скоростей и ускорений") for t in texts) is both
    assert any(t.startswith("Планы ускорений") for t in texts) is not both
