"""Review 12's kinematic and plans sheets' crowding (issue 27, fix-list item 5).

- A yoke's rod (the yarn traverse's guide bar 5) was drawn ≈55 mm past the end of its hatched
  guide: its guide now covers the rod's end in every position (GUIDE_HOLD).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcad import tol
from geomcad.linkage.model import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import GUIDE_HOLD, link_bodies, yoke

ROOT = Path(__file__).parent
YOKED = [
    p
    for p in [
        ROOT / "linkages_review11" / "yarn_guide_traverse.toml",
        *sorted((ROOT / "linkages_layout").glob("*.toml")),
        *sorted((ROOT / "linkages_review12").glob("*.toml")),
    ]
    if '"PRP"' in p.read_text(encoding="utf-8")
]


def _solved(path: Path):  # type: ignore[no-untyped-def]
    return solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))


@pytest.mark.parametrize("path", YOKED, ids=lambda p: p.stem)
def test_a_yoke_rod_ends_inside_its_guide_in_every_position(path: Path) -> None:
    """Every drawn position's rod of a PRP yoke ends on its hatched guide, and holds in it at
    least GUIDE_HOLD of the rod's travel (never barely touching its near end)."""
    s = _solved(path)
    lk = s.linkage
    groups = [g for g in lk.groups if g.kind == "PRP" and g.guide is not None]
    if not groups:
        pytest.skip("no yoke on a guide")
    for g in groups:
        assert g.guide is not None
        yk, d = yoke(lk, g), g.guide.direction
        g0, g1 = (yk.guide - d * yk.half).dot(d), (yk.guide + d * yk.half).dot(d)
        ends = []
        for P in s.drawn:
            rod = link_bodies(lk, P)[str(g.links[1])][0]
            end = max(rod.points, key=lambda q: abs((q - P.pos[g.joint]).dot(d)))
            t = end.dot(d)
            slack = tol.SAME_PLACE * lk.length
            assert g0 - slack <= t <= g1 + slack, (t, g0, g1)
            ends.append(t)
        travel = max(ends) - min(ends)
        hold = min(abs(t - (g0 if yk.rod > 0 else g1)) for t in ends)
        assert hold >= GUIDE_HOLD * travel - tol.SAME_PLACE * lk.length, (hold, travel)
