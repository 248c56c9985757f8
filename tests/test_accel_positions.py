"""The acceleration plans' positions show something (issue 27, review 6 item 7): where the
output's strokes are mirror images (an axial slider-crank, a V engine's cylinder), the idle
stroke's plan is not the mirror of the working stroke's (the same |a| turned over) but the
largest |a| among the other positions of that stroke; files whose picks already differ keep
the plain rule (largest |a| of the output in each stroke)."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, output_acceleration, solve

ROOT = Path(__file__).resolve().parent
FILES = {
    "v_engine": ROOT / "linkages_positions" / "v_engine.toml",
    "slider-crank": ROOT.parent / "examples" / "slider-crank.toml",
    "rocking-slider": ROOT.parent / "examples" / "rocking-slider.toml",
    "shaper": ROOT.parent / "examples" / "shaper.toml",
    "scotch-yoke": ROOT.parent / "examples" / "scotch-yoke.toml",
    "crusher": ROOT.parent / "examples" / "crusher.toml",
    "sixbar_oscillator": ROOT / "linkages_positions" / "sixbar_oscillator.toml",
}
TWO_PI = 2.0 * math.pi


def _solved(name: str) -> Solved:
    return solve(parse(tomllib.loads(FILES[name].read_text(encoding="utf-8"))))


def _strokes(s: Solved) -> tuple[list[int], list[int], list[float]]:
    """The numbered positions inside the working and the idle stroke, and |a| of the output
    in every numbered position."""
    cyc = s.cycle
    assert cyc is not None
    n = len(s.drawn)
    working = [k for k in range(1, n) if k * TWO_PI / n < cyc.phi_working - 1e-9]
    idle = [k for k in range(1, n) if k * TWO_PI / n > cyc.phi_working + 1e-9]
    acc = [abs(output_acceleration(s.linkage, P)) for P in s.drawn]
    return working, idle, acc


def _index(s: Solved, phi: float) -> int:
    """The numbered position at the crank angle ``phi``."""
    return next(k for k, P in enumerate(s.drawn)
                if abs((P.phi - phi + math.pi) % TWO_PI - math.pi) < 1e-9)  # fmt: skip


def _mirrored(s: Solved) -> bool:
    cyc = s.cycle
    assert cyc is not None
    working, _, acc = _strokes(s)
    n = len(s.drawn)
    top = max(acc)
    return abs(cyc.phi_working - math.pi) < 1e-9 and all(
        abs(acc[k] - acc[n - k]) <= 1e-9 * top for k in working
    )


@pytest.mark.parametrize("name", ["v_engine", "slider-crank", "rocking-slider"])
def test_mirror_strokes_give_a_second_plan_that_is_no_mirror(name: str) -> None:
    s = _solved(name)
    assert _mirrored(s)  # the case this rule is for
    working, idle, acc = _strokes(s)
    n = len(s.drawn)
    k1, k2 = (_index(s, phi) for phi in s.accel_phis)
    assert k1 in working and k2 in idle  # one in each stroke, as before
    assert acc[k1] == pytest.approx(max(acc[k] for k in working), rel=1e-9)
    assert k2 != n - k1  # not the working plan turned over
    assert acc[k2] == pytest.approx(max(acc[k] for k in idle if k != n - k1), rel=1e-9)
    assert abs(acc[k2] - acc[k1]) > 1e-6 * acc[k1]  # it shows another acceleration


@pytest.mark.parametrize("name", ["shaper", "scotch-yoke", "crusher"])
def test_picks_that_differ_keep_the_largest_in_each_stroke(name: str) -> None:
    """Strokes that are no mirrors (a quick return, a rocker), or picks that are no mirror of
    each other (the scotch yoke's 30° and 210°): the largest |a| in each stroke, unchanged."""
    s = _solved(name)
    working, idle, acc = _strokes(s)
    got = [_index(s, phi) for phi in s.accel_phis]
    want = []
    for ks in (working, idle):
        top = max(acc[k] for k in ks)
        want.append(next(k for k in ks if acc[k] >= top * (1 - 1e-9)))
    assert got == want


def _apart(s: Solved, k: int, j: int) -> float:
    n = len(s.drawn)
    d = abs(k - j) % n
    return min(d, n - d) * TWO_PI / n


@pytest.mark.parametrize("name", ["sixbar_oscillator", "sixbar-2013-6"])
def test_neighbours_about_the_extreme_give_a_second_plan_farther_away(name: str) -> None:
    """review 7 item 7: a rocker's largest |a| in each stroke lies at the two positions that
    straddle its extreme (6 and 7), nearly one figure; the idle stroke's plan is then its
    largest |a| among the positions more than one step (and 45°) from the working pick."""
    path = {
        "sixbar_oscillator": ROOT / "linkages_positions" / "sixbar_oscillator.toml",
        "sixbar-2013-6": ROOT.parent / "examples" / "sixbar-2013-6.toml",
    }[name]
    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    working, idle, acc = _strokes(s)
    n = len(s.drawn)
    near = max(TWO_PI / n, math.pi / 4) * (1 + 1e-9)
    k1, k2 = (_index(s, phi) for phi in s.accel_phis)
    assert k1 in working and k2 in idle
    assert acc[k1] == pytest.approx(max(acc[k] for k in working), rel=1e-9)
    top = max(acc[k] for k in idle)
    plain = next(k for k in idle if acc[k] >= top * (1 - 1e-9))
    assert _apart(s, plain, k1) <= near  # the case this rule is for: neighbours
    assert _apart(s, k2, k1) > near  # the second plan is away from the first
    far = [k for k in idle if _apart(s, k, k1) > near]
    assert acc[k2] == pytest.approx(max(acc[k] for k in far), rel=1e-9)
