"""A force plan is one polygon at one μ_F (review 14, fix list item 2 for the plans).

- The knuckle press's group (4, 5) plan was a 40 mm sliver with six details at three more
  μ_F (500, 100 and 10 N/mm) round one vertex; the walkbeam's group (2, 3) had three tiers
  (20, 4 and 0,5 N/mm): a plan's details are at ONE μ_F, all taken from the plan (no detail of
  a detail), one circle per spot.
- The gang saw's crank plan had R₄₁ (16 750 N, a main reaction) only in its detail, a line on
  the plan: every reaction of a plan (found by it, or laid off in it as a known load, and the
  resultant of a split reaction) is an arrow of the plan at the plan's own μ_F.

Each file's forces sheet is drawn once (as ``force_sheets`` draws it); the plans are read as
drawn: their details, and the arrows drawn at the plan's μ_F (``Sheet.scaled``)."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.forces import ForcePolygon
from geomcad.sheet import views
from geomcad.sheet.compose import compose
from geomcad.sheet.drawing import SHORT_MM

TESTS = Path(__file__).resolve().parent
FILES = [
    TESTS / "linkages_review13" / "knuckle_coining_press.toml",
    TESTS / "linkages_review13" / "gang_saw_frame_feed.toml",
    TESTS / "linkages_review14" / "walkbeam.toml",
    TESTS / "linkages_layout" / "compressor_coupler_cross_slider.toml",
]

#: A plan as drawn: its title, the view, its μ_F drawn, the arrows drawn at that μ_F (paper).
Drawn = tuple[str, Any, float, list[tuple[tuple[float, float], tuple[float, float]]]]


def _drawn(path: Path) -> list[Drawn]:
    from geomcad.sheet import linkage_forces as F

    out: dict[str, Drawn] = {}
    draw = views.Polygon.draw

    def rec(self: views.Polygon, d: Any, at: Any) -> None:
        i = len(d.sheet.scaled)
        draw(self, d, at)
        k = at.viewport.scale.k
        arrows = [(a, b) for a, b, sc in d.sheet.scaled[i:] if math.isclose(sc.k, k)]
        out[self.title] = (self.title, self, k, arrows)

    s = geomcad.solve(str(path)).data
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(views.Polygon, "draw", rec)
        tree, z = F.force_layout(s)
        d = z.start(F._title(s.linkage, "forces", "X", 2, 2))
        compose(d, tree, layout=z.layout)
    return list(out.values())


@pytest.fixture(scope="module", params=FILES, ids=lambda p: p.stem)
def plans(request: pytest.FixtureRequest) -> tuple[str, list[Drawn]]:
    path: Path = request.param
    return path.stem, _drawn(path)


def test_one_detail_scale_per_plan(plans: tuple[str, list[Drawn]]) -> None:
    """Every detail of a plan is at one μ_F, taken from the plan (none from a detail)."""
    stem, drawn = plans
    assert drawn, stem
    for title, p, _k, _arrows in drawn:
        scales = sorted({dt.k for dt in p.details})
        assert len(scales) <= 1, (stem, title, scales)
        assert all(dt.host is None for dt in p.details), (stem, title)


def _reactions(poly: ForcePolygon, k: float) -> list[tuple[str, list[tuple[float, float]]]]:
    """The reactions of a plan drawn at μ_F ``k``, each with the arrows (magnitude,
    direction) that draw it: R_{ij} itself; a reaction split into R^n_{ij}, R^τ_{ij} by its
    resultant, or, where its short component is under two arrowheads (the two would run as
    one twin line), by its long component's arrow named with both ("R^n₃₄ ≈ R₃₄")."""
    big = max(pv.magnitude for pv in poly.vectors)
    out = []
    parts: dict[str, list[Any]] = {}
    for pv in poly.vectors:
        if pv.magnitude <= 1e-9 * big:
            continue
        f = pv.head - pv.tail
        if re.fullmatch(r"R_.+", pv.name):
            out.append((pv.name, [(pv.magnitude, math.atan2(f.y, f.x))]))
        m = re.fullmatch(r"R\^(?:n|τ|t)(_.+)", pv.name)
        if m is not None:
            parts.setdefault("R" + m[1], []).append(pv)
    for name, ps in parts.items():
        if len(ps) == 2:
            f = (ps[0].head - ps[0].tail) + (ps[1].head - ps[1].tail)
            ways = [(f.norm, math.atan2(f.y, f.x))]
            small, long = sorted(ps, key=lambda pv: pv.magnitude)
            if small.magnitude / k < SHORT_MM:
                g = long.head - long.tail
                ways.append((long.magnitude, math.atan2(g.y, g.x)))
            out.append((name, ways))
    return out


def test_every_reaction_is_an_arrow_of_its_plan(plans: tuple[str, list[Drawn]]) -> None:
    """Each reaction of a plan is drawn as an arrow at the plan's own μ_F: its length on the
    paper |R|/μ_F and its direction (the paper's y runs down) — never only in a detail."""
    stem, drawn = plans
    for title, p, k, arrows in drawn:
        poly = p.layers[-1][0]
        for name, ways in _reactions(poly, k):
            found = False
            for (ax, ay), (bx, by) in arrows:
                length = math.hypot(bx - ax, by - ay)
                a = math.atan2(-(by - ay), bx - ax)
                for mag, ang in ways:
                    want = mag / k
                    turn = abs((a - ang + math.pi) % (2.0 * math.pi) - math.pi)
                    if abs(length - want) <= 0.02 * want + 0.05 and turn < math.radians(1.0):
                        found = True
            assert found, (stem, title, name, round(ways[0][0] / k, 2))
