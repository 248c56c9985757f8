"""Review 13, item 1: the forces sheet's force plans fill their room.

The plans shared a Grid of equal cells: a sliver (R01 = -R21, drawn at most SLIVER_GROW_MM
long) took a cell as large as a square plan's, and the square plans were drawn 30-55 mm long
in cells of 100-170 mm (59-77 % of the A1 field's 15 mm cells blank). Now the region of the
plans is cut again into cells fitted to each plan's shape (:func:`linkage_forces._fitted_plans`)
and each plan grown into its cell at the finer μ_F of its series that fits
(:func:`linkage_forces.grow_plan`).

Measured on main (commit 11a8e42) over these files: the smallest ratio of a plan's longest
vector to its cell's smaller side 0.32 (rocking_cylinder_rocker), 0.40 (rocker_press); with
the fitted cells 0.46 at the least (compressor_coupler_cross_slider: 49 mm in 106 mm, the next
finer μ_F overflowing its cell). The brief's aim of 60 % is not reached on every file: a GOST
μ_F step is up to 2×, so a plan that fits its cell may stay at 50-60 % of it.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

import geomcad
from geomcad.linkage.analysis import analyse
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.compose import Layout
from geomcad.sheet.views import Polygon

ROOT = Path(__file__).parent.parent
EXAMPLES = ROOT / "examples"
FILES = sorted(p for p in ROOT.glob("tests/linkages_*/*.toml") if p.parent.name != "linkages_bad")
FILES += [EXAMPLES / f"{n}.toml" for n in ("shaper", "sixbar-2013-6", "crusher", "slider-crank")]

#: The least ratio of a force plan's longest vector (as drawn, at its stated μ_F) to its
#: room's smaller side (its cell less margins and caption), for a plan that grows (not a
#: sliver at its cap).
FILL = 0.45


@functools.cache
def _layout(path: Path) -> Layout | None:
    s = geomcad.solve(str(path)).data
    if analyse(s).forces is None:
        return None
    _tree, z = lf.force_layout(s)
    return z.layout


def _plans(lay: Layout) -> list[tuple[Polygon, float, tuple[float, float, float, float]]]:
    """Each force plan, its longest vector in mm as drawn, and its room: the cell less its
    margins and its caption (:attr:`Placed.inner`), what the plan has to grow into."""
    out = []
    for pl in lay:
        v = pl.view
        if isinstance(v, Polygon) and pl.scale is not None:
            big = max(pv.magnitude for poly, _ in v.layers for pv in poly.vectors)
            out.append((v, big / v.drawn_k(pl.scale.k), pl.inner))
    return out


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_every_plan_fills_its_cell(path: Path) -> None:
    lay = _layout(path)
    if lay is None:
        pytest.skip("no forces sheet")
    for v, mm, box in _plans(lay):
        if v.longest_mm > 0.0:
            continue  # a sliver: drawn at its cap whatever its cell
        side = min(box[2] - box[0], box[3] - box[1])
        assert mm >= FILL * side, (v.title, round(mm), round(side))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_plans_cells_tile_their_region(path: Path) -> None:
    """The fitted cells keep within the region the plans' Grid took, none over another, none
    over another view."""
    lay = _layout(path)
    if lay is None:
        pytest.skip("no forces sheet")
    boxes = [(id(pl), pl.box) for pl in lay]
    e = 1e-6
    for i, (a, b) in enumerate(boxes):
        for c, d in boxes[i + 1 :]:
            assert not (b[0] < d[2] - e and d[0] < b[2] - e and b[1] < d[3] - e
                        and d[1] < b[3] - e), (a, b, c, d)  # fmt: skip
