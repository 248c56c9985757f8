"""The graphical integration and differentiation on the linkage sheets are what the textbook's
methods give (review 2, issue 27): over a full cycle the steady-state ΔT returns to its start
(A_д = A_с), the chord method's polylines cover the whole cycle 0 … 360° and close on position
N = position 0, and every curve of a diagram of several is named."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import geomcad
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import solve
from geomcad.sheet.views import Curve, Diagram

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
LINKAGES = [
    p
    for p in sorted(EXAMPLES.glob("*.toml"))
    if "[drive]" in p.read_text(encoding="utf-8")
    and ("[[group]]" in p.read_text(encoding="utf-8") or "[synthesis]" in p.read_text("utf-8"))
]
DYNAMICS = [p for p in LINKAGES if "[dynamics]" in p.read_text(encoding="utf-8")]


def _graphical(d: Diagram) -> Curve:
    (c,) = [c for c in d.curves if c.points]
    return c


def _xy(c: Curve) -> tuple[np.ndarray, np.ndarray]:
    return np.asarray(c.xs, dtype=np.float64), np.asarray(c.ys, dtype=np.float64)


@pytest.mark.parametrize("path", DYNAMICS, ids=lambda p: p.stem)
def test_graphical_integration_closes_over_the_cycle(path: Path) -> None:
    """The dynamics sheet: the graphical A_с ends at the cycle's work A_ц, where the drive's
    A_д ends (so ΔT's polyline returns to 0 at 360°), and passes through the exact work at every
    numbered position (the equal-area mean ordinates of the textbook's graphical integration)."""
    from geomcad.sheet.linkage_forces import _sheet3

    s = solve(geomcad.solve(str(path)).data.linkage)
    fw = analyse(s).flywheel
    assert fw is not None
    tree = _sheet3(s, fw, 3.5)
    diagrams = {v.y.name: v for v in tree.views() if isinstance(v, Diagram)}
    A, T = diagrams["A"], diagrams["T"]
    A_c = float(fw.M_drive * 2.0 * math.pi)
    gx, gy = _xy(_graphical(A))
    assert gx[0] == 0.0 and gx[-1] == pytest.approx(360.0, abs=1e-9)
    assert gy[-1] == pytest.approx(A_c, rel=1e-6)
    drive = [c for c in A.curves if not c.points and c.role == "construction"]
    assert _xy(drive[0])[1][-1] == pytest.approx(gy[-1], rel=1e-6)
    tx, ty = _xy(_graphical(T))
    assert ty[0] == 0.0
    assert abs(ty[-1]) <= 1e-6 * float(np.abs(ty).max())
    # on the exact curve at every division point
    ex, ey = _xy(T.curves[0])
    assert np.allclose(ty, np.interp(tx, ex, ey), atol=1e-3 * float(np.abs(ey).max()))


@pytest.mark.parametrize("path", DYNAMICS, ids=lambda p: p.stem)
def test_every_curve_of_a_diagram_of_several_is_named(path: Path) -> None:
    """M_пр beside M_дв, A_с beside A_д: each curve named (the points of the graphical method
    are the same quantity's)."""
    from geomcad.sheet.linkage_forces import _sheet3

    s = solve(geomcad.solve(str(path)).data.linkage)
    fw = analyse(s).flywheel
    assert fw is not None
    for d in _sheet3(s, fw, 3.5).views():
        if isinstance(d, Diagram):
            curves = [c for c in d.curves if not c.points]
            if len(curves) > 1:
                assert all(c.label for c in curves), d.y.name
                assert len({c.label for c in curves}) == len(curves)
                points = [p for _c, p, _up in d._label_points(d.axes(400.0, 150.0)[1])]
                assert len(set(points)) == len(points), (d.y.name, points)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_chord_polylines_cover_the_cycle(path: Path) -> None:
    """The output's diagrams: the chord polylines of v and a run from 0 to 360° and end where
    they start (the cycle repeats), a's points at the numbered positions 0 … N."""
    from geomcad.sheet.linkage import _diagrams

    s = geomcad.solve(str(path)).data
    diagrams = _diagrams(s)
    n = len(_xy(_graphical(diagrams[0]))[0]) - 1
    for d in diagrams[1:]:
        gx, gy = _xy(_graphical(d))
        assert gx[0] == 0.0 and gx[-1] == pytest.approx(360.0, abs=1e-9), d.y.name
        assert np.all(np.diff(gx) > 0.0)
        assert gy[-1] == pytest.approx(gy[0], abs=1e-12 * max(1.0, float(np.abs(gy).max())))
    ax, _ = _xy(_graphical(diagrams[2]))
    assert np.allclose(ax, np.linspace(0.0, 360.0, n + 1))


def test_chords_of_a_harmonic_motion() -> None:
    """The chord method on s = cos ψ (a harmonic motion) at 12 divisions: v at the intervals'
    middles is sin(Δ/2)/(Δ/2) of the exact, and a at the divisions (sin(Δ/2)/(Δ/2))² of it."""
    from geomcad.sheet.linkage import chord_derivatives

    n = 12
    psi = np.linspace(0.0, 2.0 * math.pi, n + 1)
    h = 2.0 * math.pi / n
    pv, v, pa, a = chord_derivatives(psi, np.cos(psi), h)
    k = math.sin(h / 2) / (h / 2)
    assert np.allclose(v, -k * np.sin(pv), atol=1e-12)
    assert np.allclose(a, -(k**2) * np.cos(pa), atol=1e-12)
