"""An inset's caption clear of the texts of its view (issue 27, review 15: the rocking
cylinder's lever set the caption "Г2 (μV = 0,005 (м/с)/мм)" of its enlarged inset over the
letter Ш1; a large inset in a full view finds no free place, and its caption now goes under its
arrows where the place's top is taken and its bottom less so)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parent.parent
FILES = [
    ROOT / "tests" / "linkages_arms" / "rocking_cylinder_rocker.toml",
    ROOT / "tests" / "linkages_layout" / "double_kulisa_screen.toml",
]


def _rect(t: TextItem) -> tuple[float, float, float, float]:
    return t.at[0], t.at[1] - t.height, t.at[0] + t.width, t.at[1] + 0.25 * t.height


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_an_inset_caption_meets_no_other_text(path: Path) -> None:
    sheets = lf.force_sheets(solve(parse(tomllib.loads(path.read_text("utf-8")))), "x")
    texts = [t for t in sheets[0][1].items if isinstance(t, TextItem) and not t.angle]
    # an inset's caption with its own scale: "Г2 (μV = 0,005 (м/с)/мм)", "Б (2:1)"
    captions = [t for t in texts if re.match(r"^\S+ \(", t.text)]
    assert captions
    for c in captions:
        a = _rect(c)
        for t in texts:
            b = _rect(t)
            assert t is c or not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (
                c.text,
                t.text,
            )
