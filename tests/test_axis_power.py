"""Tiny values along an axis and in the I_пр column are written times a power of ten, named by
the axis or the column (review 11: an instrument's I_пр as 0,000004 … 0,000024 on its axis and
0,00000236 in its table)."""

from __future__ import annotations

from pathlib import Path

import geomcad
from geomcad.linkage.analysis import analyse
from geomcad.sheet.graph import FACTOR_PLACES, Axis
from geomcad.sheet.linkage_forces import _tables3

HERE = Path(__file__).resolve().parent


def test_an_axis_of_tiny_values_writes_them_times_a_power_of_ten() -> None:
    ax = Axis.fit("I_{пр}", "кг·м²", 0.0, 2.5e-5, 100.0)
    assert ax.places() > FACTOR_PLACES
    assert ax.power() == 6
    texts = [ax.tick_text(v, "ru") for v in ax.ticks()]
    assert texts[0] == "0" and all("0,0" not in t for t in texts), texts
    assert ax.tick_text(ax.ticks()[1], "ru") == f"{ax.ticks()[1] * 1e6:g}".replace(".", ",")
    assert ax.caption() == "I_{пр}·10^{6}, кг·м²"


def test_an_axis_of_ordinary_values_is_written_as_before() -> None:
    for lo, hi in ((0.0, 0.3), (-0.28, 0.08), (0.0, 24.0), (0.0, 2.5e-3)):
        ax = Axis.fit("M", "Н·м", lo, hi, 100.0)
        assert ax.power() == 0
        assert ax.caption() == "M, Н·м"


def test_the_i_pr_column_of_an_instrument_is_written_times_a_power_of_ten() -> None:
    s = geomcad.solve(str(HERE / "linkages_review11" / "yarn_guide_traverse.toml")).data
    fw = analyse(s).flywheel
    assert fw is not None
    tables = _tables3(s.linkage, fw, 3.5)
    cells = [c for t in tables for row in getattr(t, "rows", []) for c in row]
    assert any("·10^{6}" in c for c in cells), cells[:8]
    assert not any(c.startswith("0,0000") for c in cells), cells
