"""The graphical integration and differentiation on the linkage sheets are what the textbook's
methods give (review 2, issue 27): over a full cycle the steady-state ΔT returns to its start
(A_д = A_с), the chord method's polylines cover the whole cycle 0 … 360° and close on position
N = position 0, and every curve of a diagram of several is named."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

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


def _views(tree: Any) -> list[Any]:
    """The views of a sheet's tree, the diagrams of a stack of them (the dynamics sheet's
    M_пр, A, ΔT, I_пр: one view of the layout) each on its own."""
    return [x for v in tree.views() for x in getattr(v, "diagrams", [v])]


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
    diagrams = {v.y.name: v for v in _views(tree) if isinstance(v, Diagram)}
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
    named = 0
    for d in _views(_sheet3(s, fw, 3.5)):
        if isinstance(d, Diagram):
            curves = [c for c in d.curves if not c.points]
            if len(curves) > 1:
                assert all(c.label for c in curves), d.y.name
                assert len({c.label for c in curves}) == len(curves)
                points = [p for _c, p, _up in d._label_points(d.axes(400.0, 150.0)[1])]
                assert len(set(points)) == len(points), (d.y.name, points)
                named += 1
    assert named >= 2  # M_пр beside M_дв, A_с beside A_д


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_chord_polylines_cover_the_cycle(path: Path) -> None:
    """The output's diagrams: the chord polylines of v and a run from 0 to 360° and end where
    they start (the cycle repeats); s and a have a point at every numbered position 0 … N."""
    from geomcad.sheet.linkage import _diagrams, _divisions

    s = geomcad.solve(str(path)).data
    diagrams = _diagrams(s)
    positions = np.linspace(0.0, 360.0, _divisions(s) + 1)
    for d in diagrams:
        gx, gy = _xy(_graphical(d))
        assert gx[0] == 0.0 and gx[-1] == pytest.approx(360.0, abs=1e-9), d.y.name
        assert np.all(np.diff(gx) > 0.0)
        assert gy[-1] == pytest.approx(gy[0], abs=1e-9 * max(1.0, float(np.abs(gy).max())))
    for d in (diagrams[0], diagrams[2]):
        gx = _xy(_graphical(d))[0]
        assert all(np.any(np.abs(gx - p) < 1e-9) for p in positions), d.y.name


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_chord_accelerations_sit_on_the_exact_curve(path: Path) -> None:
    """Review 6 (whitworth: a's dot at position 0 read 12.5 where the curve is 13.4): every
    point of the chord method's a lies within 3 % of a's range of the second finite difference
    of the output's coordinate s(ψ) at the point's own abscissa, and so does the exact curve
    drawn under it. A chord of v's polyline is the derivative at its middle: the old points at
    the division point between unequal intervals were up to 4.7 % off (four-bar)."""
    from geomcad.sheet.linkage import _diagrams, _output_curves

    s = geomcad.solve(str(path)).data
    omega = abs(s.linkage.omega)
    a_diagram = _diagrams(s)[2]
    px, pa = _xy(_graphical(a_diagram))
    ((ex, ea),) = [_xy(c) for c in a_diagram.curves if not c.points]
    psi = np.radians(px)
    h = 1.0e-4

    # one sweep, each point's three samples side by side (an angle's output is unwrapped)
    s3 = _output_curves(s, np.stack([psi - h, psi, psi + h], axis=1).ravel())[1].reshape(-1, 3)
    fd = (s3[:, 0] - 2.0 * s3[:, 1] + s3[:, 2]) / (h / omega) ** 2
    span = float(np.ptp(ea))
    assert np.allclose(np.interp(px, ex, ea), fd, atol=0.005 * span), path.stem
    worst = float(np.max(np.abs(pa - fd))) / span
    assert worst < 0.03, (path.stem, worst)


def test_positions_step_written_as_a_whole_angle() -> None:
    """Review 6: the dynamics sheet wrote "через 30,0°" (the step took the decimals of φ_1 at
    position 0), the kinematic sheets 30°: a whole step is written whole, whatever φ_1 is."""
    sheets = dict(geomcad.solve(str(EXAMPLES / "shaper.toml")).sheets())
    text = " ".join(t.text for t in sheets["dynamics"].texts())
    assert "30,0°" not in text and "30°" in text


def _s_of(f):  # type: ignore[no-untyped-def]
    return lambda psi: f(np.asarray(psi, dtype=np.float64))


def test_chords_of_a_harmonic_motion() -> None:
    """The chord method on s = cos ψ at 12 divisions and ω = 1: v at the intervals' middles is
    sin(Δ/2)/(Δ/2) of the exact, and a at the divisions (sin(Δ/2)/(Δ/2))² of it."""
    from geomcad.sheet.linkage import chord_derivatives

    n = 12
    h = 2.0 * math.pi / n
    _ps, _s, pv, v, pa, a = chord_derivatives(_s_of(np.cos), n, 1.0)
    k = math.sin(h / 2) / (h / 2)
    assert np.allclose(v[1:-1], -k * np.sin(pv[1:-1]), atol=1e-12)
    assert np.allclose(a, -(k**2) * np.cos(pa), atol=1e-12)
    assert len(pa) == n + 1


def test_chords_take_smaller_intervals_at_a_sharp_peak() -> None:
    """A narrow acceleration peak at position 0 (s = −exp(−(ψ/0.2)²) periodically, a(0) =
    2ω²/0.2²): at 30° the second chord gives a fraction of it; the halved intervals about it
    come within 10 %, and a smooth stretch keeps its 30° divisions."""
    from geomcad.sheet.linkage import chord_derivatives

    def s(psi: np.ndarray) -> np.ndarray:
        d = np.mod(psi + math.pi, 2.0 * math.pi) - math.pi
        return np.asarray(-np.exp(-((d / 0.2) ** 2)), dtype=np.float64)

    exact = 2.0 / 0.2**2
    coarse = chord_derivatives(s, 12, 1.0)
    fine = chord_derivatives(s, 12, 1.0, refine=3)
    assert abs(coarse[5][0] - exact) > 0.5 * exact
    assert abs(fine[5][0] - exact) < 0.1 * exact
    assert np.any(np.isclose(fine[0], math.radians(180.0)))
    assert not np.any(np.isclose(fine[0], math.radians(165.0)))


def test_positions_numbered_under_the_phi_axes() -> None:
    """The kinematic and dynamics sheets number the positions 0 … N−1 under each diagram's φ
    axis, one row per diagram, each number under its crank angle from position 0."""
    path = EXAMPLES / "shaper.toml"
    sheets = dict(geomcad.solve(str(path)).sheets())
    for key, diagrams in (("", 3), ("dynamics", 4)):
        texts = [t for t in sheets[key].texts() if t.text in {str(k) for k in range(12)}]
        rows: dict[float, list[str]] = {}
        for t in texts:
            rows.setdefault(round(t.at[1], 3), []).append(t.text)
        full = [r for r in rows.values() if sorted(r, key=int) == [str(k) for k in range(12)]]
        assert len(full) >= diagrams, (key, rows)
