"""Synthesis from a variant's design data (linkages.md, "Synthesis"; issue 31).

Each kind against an independent closed form (lengths, θ, γ_min), its analysis giving back the
stroke or swing and K (both senses of ω, with and without offset, K and λ), the round trip of
``--emit-linkage``, the refusals, the sheet and ``verify``."""

from __future__ import annotations

import copy
import math
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from scipy.optimize import brentq

from geomcad import documents
from geomcad.errors import FileKeyError, GeomcadError
from geomcad.linkage import parse, sweep
from geomcad.linkage.synthesis import emit, synthesize

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("synthesis-*.toml"))


def data(kind: str, omega: float = 10.0, **keys: float) -> dict[str, Any]:
    return {"synthesis": {"kind": kind, **keys}, "drive": {"omega": omega}}


def solved(d: dict[str, Any]) -> Any:
    """The file's problem solved (results, protocol, the sheets' scales)."""
    return documents.from_data("mem.toml", copy.deepcopy(d)).solve()


class Fast:
    """The synthesis and the analysis of the linkage it finds, without laying out a sheet."""

    def __init__(self, d: dict[str, Any]) -> None:
        from geomcad.linkage.solution import results, solve

        syn = synthesize(copy.deepcopy(d))
        self.lk = parse(syn.linkage)
        self.results = {**results(solve(self.lk)), "synthesis": syn.results}
        self.working = syn.working


# --- independent closed forms ------------------------------------------------------------------


def slider_K(H: float, K: float, e: float) -> tuple[float, float, float]:
    """l1, l2, θ of the offset slider-crank: triangle B0OB1 with OB0 = l2 − l1, OB1 = l2 + l1,
    the angle θ at O and the height e on B0B1 = H: the law of cosines and the area give
    (2·l1)² = H² − 2He·tan(θ/2), (2·l2)² = H² + 2He·cot(θ/2)."""
    th = math.pi * (K - 1.0) / (K + 1.0)
    l1 = 0.5 * math.sqrt(H * H - 2.0 * H * e * math.tan(th / 2.0))
    l2 = 0.5 * math.sqrt(H * H + 2.0 * H * e / math.tan(th / 2.0))
    return l1, l2, th


def slider_lambda(H: float, lam: float, e: float) -> tuple[float, float, float]:
    """l1, l2, θ from H, λ and e: with u = √((λ+1)²l1² − e²), w = √((λ−1)²l1² − e²),
    u − w = H and u² − w² = 4λl1², so x = l1² solves 16λ²x² − 4H²(λ² + 1)x + H⁴ + 4H²e² = 0;
    the largest root with w ≥ 0 is taken."""
    a, b, c = 16.0 * lam**2, -4.0 * H * H * (lam**2 + 1.0), H**4 + 4.0 * H * H * e * e
    disc = b * b - 4.0 * a * c
    roots = sorted(((-b + s * math.sqrt(disc)) / (2.0 * a) for s in (1.0, -1.0)), reverse=True)
    x = next(r for r in roots if 4.0 * lam * r / H - H >= -1e-15)
    l1 = math.sqrt(x)
    l2 = lam * l1
    th = math.asin(e / (l2 - l1)) - math.asin(e / (l2 + l1))
    return l1, l2, th


def gamma_min(l1: float, l2: float, l3: float, l0: float) -> float:
    """The least acute coupler–rocker angle over a dense turn of the crank (rad)."""
    phi = np.linspace(0.0, 2.0 * math.pi, 200001)
    d2 = l0 * l0 + l1 * l1 - 2.0 * l0 * l1 * np.cos(phi)
    g = np.arccos(np.clip((l2 * l2 + l3 * l3 - d2) / (2.0 * l2 * l3), -1.0, 1.0))
    return float(np.min(np.minimum(g, math.pi - g)))


def crank_rocker(psi_deg: float, K: float, l3: float, l0: float) -> tuple[float, float, float]:
    """l1, l2, γ_min: the pivot O = l0·(cos α, sin α) about C where ∠B0OB1 = θ, found by
    root-finding over α (B0, B1 at 90° ± ψ/2); kept where the four-bar is a crank-rocker with
    B0, B1 on one side of OC; the largest γ_min."""
    th = math.pi * (K - 1.0) / (K + 1.0)
    psi = math.radians(psi_deg)
    B0 = np.array([l3 * math.cos(math.pi / 2 + psi / 2), l3 * math.sin(math.pi / 2 + psi / 2)])
    B1 = np.array([l3 * math.cos(math.pi / 2 - psi / 2), l3 * math.sin(math.pi / 2 - psi / 2)])

    def angle(a: float) -> float:
        P = l0 * np.array([math.cos(a), math.sin(a)])
        u, v = B0 - P, B1 - P
        return math.atan2(abs(u[0] * v[1] - u[1] * v[0]), float(u @ v)) - th

    al = np.linspace(0.0, 2.0 * math.pi, 20001)
    f = [angle(a) for a in al]
    best: tuple[float, float, float] | None = None
    for i in range(len(al) - 1):
        if f[i] * f[i + 1] < 0.0:
            a = brentq(angle, al[i], al[i + 1], xtol=1e-15)
            P = l0 * np.array([math.cos(a), math.sin(a)])
            d0, d1 = float(np.linalg.norm(B0 - P)), float(np.linalg.norm(B1 - P))
            l1, l2 = abs(d1 - d0) / 2.0, (d1 + d0) / 2.0
            ls = sorted([l0, l1, l2, l3])
            if not (l1 == ls[0] and ls[0] + ls[3] < ls[1] + ls[2]):
                continue
            side = [P[0] * b[1] - P[1] * b[0] for b in (B0, B1)]  # C at the origin
            if side[0] * side[1] <= 0.0:
                continue
            g = gamma_min(l1, l2, l3, l0)
            if best is None or g > best[2]:
                best = (l1, l2, g)
    assert best is not None
    return best


def output_cycle(lk: Any, rocker: bool) -> tuple[float, float]:
    """H (or ψ in rad) and K of the parsed linkage by a dense sweep: the output's two extremes
    (roots of its velocity), K = the crank's turn while the output rises (along its guide's
    direction, or ψ) / while it falls."""

    def at(phis: Any) -> tuple[np.ndarray, np.ndarray]:
        st = sweep(lk, np.asarray(phis, float), order=1)
        if rocker:
            d = st.pos["B"] - st.pos["C"]
            return np.arctan2(d[:, 1], d[:, 0]), st.omega[3] * np.ones(len(d))
        u = lk.output_guide.guide.direction  # forward along the guide
        return st.pos[lk.output] @ [u.x, u.y], st.vel[lk.output] @ [u.x, u.y]

    phi = np.linspace(0.0, 2.0 * math.pi, 3601)
    _, v = at(phi)
    roots = [
        brentq(lambda x: float(at([x])[1][0]), phi[i], phi[i + 1], xtol=1e-15)
        for i in range(len(phi) - 1)
        if v[i] * v[i + 1] < 0.0
    ]
    assert len(roots) == 2
    s = [float(at([r])[0][0]) for r in roots]
    lo, hi = (0, 1) if s[0] < s[1] else (1, 0)
    sign = 1.0 if lk.omega > 0 else -1.0
    rise = (sign * (roots[hi] - roots[lo])) % (2.0 * math.pi)
    return s[hi] - s[lo], rise / (2.0 * math.pi - rise)


# --- the kinds against the closed forms and their analysis --------------------------------------

SLIDER_K = [(0.2, 1.2, 0.04), (0.2, 1.5, 0.1), (0.35, 1.1, 0.02), (0.1, 1.8, 0.03)]


@pytest.mark.parametrize("omega", [10.0, -7.0])
@pytest.mark.parametrize(("H", "K", "e"), SLIDER_K)
def test_slider_crank_by_K(H: float, K: float, e: float, omega: float) -> None:
    sol = Fast(data("slider-crank", omega, stroke=H, K=K, offset=e))
    r = sol.results
    l1, l2, th = slider_K(H, K, e)
    assert r["synthesis"]["l1"] == pytest.approx(l1, rel=1e-9, abs=1e-12)
    assert r["synthesis"]["l2"] == pytest.approx(l2, rel=1e-9, abs=1e-12)
    assert r["synthesis"]["theta_deg"] == pytest.approx(math.degrees(th), abs=1e-9)
    # the analysis gives the data back, whatever the sense of ω (the slow stroke works)
    assert r["stroke"] == pytest.approx(H, abs=1e-9)
    assert r["K"] == pytest.approx(K, abs=1e-9)
    assert output_cycle(sol.lk, False) == pytest.approx((H, K), abs=1e-9)


SLIDER_LAMBDA = [(0.2, 4.0, 0.04), (0.2, 4.0, 0.0), (0.2, 2.0, 0.05), (0.145, 1.5, 0.03)]


@pytest.mark.parametrize("omega", [12.0, -5.0])
@pytest.mark.parametrize(("H", "lam", "e"), SLIDER_LAMBDA)
def test_slider_crank_by_lambda(H: float, lam: float, e: float, omega: float) -> None:
    sol = Fast(data("slider-crank", omega, stroke=H, offset=e, **{"lambda": lam}))
    r = sol.results
    l1, l2, th = slider_lambda(H, lam, e)
    assert r["synthesis"]["l1"] == pytest.approx(l1, rel=1e-9)
    assert r["synthesis"]["l2"] == pytest.approx(l2, rel=1e-9)
    assert r["synthesis"]["theta_deg"] == pytest.approx(math.degrees(th), abs=1e-7)
    K = (math.pi + th) / (math.pi - th)
    assert r["stroke"] == pytest.approx(H, abs=1e-9)
    assert r["K"] == pytest.approx(K, abs=1e-9)
    if e == 0.0:
        assert r["synthesis"]["theta_deg"] == 0.0 and r["synthesis"]["l1"] == H / 2.0


def test_lambda_takes_the_largest_crank_of_two() -> None:
    """H = 0.145 m, λ = 1.5, e = 0.03 m: two crank lengths give H; the larger is taken."""
    from geomcad.linkage.synthesis import slider_stroke

    r = Fast(data("slider-crank", stroke=0.145, offset=0.03, **{"lambda": 1.5})).results
    l1 = r["synthesis"]["l1"]
    xs = np.linspace(0.03 / 0.5, l1 - 1e-6, 2000)
    hs = np.array([slider_stroke(x, 1.5, 0.03) for x in xs])
    assert np.any(np.diff(np.sign(hs - 0.145)) != 0)  # another root below
    assert slider_stroke(l1, 1.5, 0.03) == pytest.approx(0.145, abs=1e-12)


ROCKERS = [(45.0, 1.2, 0.25, 0.36), (60.0, 1.4, 0.3, 0.4), (30.0, 1.1, 0.2, 0.3)]


@pytest.mark.parametrize("omega", [10.0, -7.0])
@pytest.mark.parametrize(("psi", "K", "l3", "l0"), ROCKERS)
def test_crank_rocker(psi: float, K: float, l3: float, l0: float, omega: float) -> None:
    d = data("crank-rocker", omega, swing_deg=psi, K=K, rocker=l3, frame=l0)
    sol = Fast(d)
    r = sol.results["synthesis"]
    l1, l2, g = crank_rocker(psi, K, l3, l0)
    assert r["l1"] == pytest.approx(l1, rel=1e-8)
    assert r["l2"] == pytest.approx(l2, rel=1e-8)
    assert r["theta_deg"] == pytest.approx(180.0 * (K - 1.0) / (K + 1.0), abs=1e-9)
    assert r["gamma_min_deg"] == pytest.approx(math.degrees(g), abs=1e-6)
    swing, k_rise = output_cycle(sol.lk, True)
    assert math.degrees(swing) == pytest.approx(psi, abs=1e-9)
    # the slow swing is the working one: ψ rising where it is "forward"
    working = sol.working
    assert (k_rise if working == "forward" else 1.0 / k_rise) == pytest.approx(K, abs=1e-9)
    res = sol.results
    if "swing_deg" in res:  # the loader's rocker output (linkages.md, second round)
        assert res["swing_deg"] == pytest.approx(psi, abs=1e-9)
        assert res["K"] == pytest.approx(K, abs=1e-9)


LEVERS = [(0.4, 1.6, 0.35, 0.15), (0.3, 1.3, 0.2, 0.1), (0.5, 2.0, 0.3, 0.2)]


@pytest.mark.parametrize("omega", [8.0, -6.0])
@pytest.mark.parametrize(("H", "K", "l0", "rod"), LEVERS)
def test_slotted_lever(H: float, K: float, l0: float, rod: float, omega: float) -> None:
    sol = Fast(data("slotted-lever", omega, stroke=H, K=K, frame=l0, rod=rod))
    r = sol.results
    th = math.pi * (K - 1.0) / (K + 1.0)
    assert r["synthesis"]["l1"] == pytest.approx(l0 * math.sin(th / 2.0), rel=1e-12)
    assert r["synthesis"]["l3"] == pytest.approx(H / (2.0 * math.sin(th / 2.0)), rel=1e-12)
    assert r["synthesis"]["theta_deg"] == pytest.approx(math.degrees(th), abs=1e-9)
    assert r["stroke"] == pytest.approx(H, abs=1e-9)
    assert r["K"] == pytest.approx(K, abs=1e-9)


# --- the explicit file ---------------------------------------------------------------------------


def _close(a: Any, b: Any, path: str = "") -> None:
    if isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for k in a:
            _close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, f"{path}.{i}")
    elif isinstance(a, float):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-12), path
    else:
        assert a == b, path


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_emitted_file_round_trips(path: Path) -> None:
    """The emitted file loads and solves to the same results (all but results.synthesis)."""
    d = tomllib.loads(path.read_text(encoding="utf-8"))
    from geomcad.linkage.solution import results, solve

    sol = Fast(d)
    text = emit(synthesize(d))
    again = tomllib.loads(text)
    assert "synthesis" not in again and "frame" in again and "group" in again
    r1 = {k: v for k, v in sol.results.items() if k != "synthesis"}
    _close(r1, results(solve(parse(again))))


def test_emit_linkage_on_the_command_line(tmp_path: Path) -> None:
    src = EXAMPLES[0]
    out = subprocess.run(
        [sys.executable, "-m", "geomcad", "solve", str(src), "--emit-linkage"],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    parsed = tomllib.loads(out.stdout)
    l1 = solved(tomllib.loads(src.read_text())).results["synthesis"]["l1"]
    assert parsed["drive"]["length"] == l1
    bad = subprocess.run(
        [sys.executable, "-m", "geomcad", "solve", str(ROOT / "examples" / "four-bar.toml"),
         "--emit-linkage"], capture_output=True, text=True,
    )  # fmt: skip
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    assert bad.stderr.startswith("error:") and "[synthesis]" in bad.stderr


def test_a_mechanism_found_feeds_the_whole_analysis() -> None:
    """Masses, loads and [dynamics] keyed by the kind's link numbers: forces and flywheel."""
    path = ROOT / "examples" / "synthesis-slotted-lever.toml"
    r = Fast(tomllib.loads(path.read_text())).results
    assert "R_0_1" in r["positions"][0] and "M_bal" in r["positions"][0]
    assert r["J_flywheel"] >= 0.0 and r["A_cycle"] != 0.0


# --- refusals -------------------------------------------------------------------------------------

BAD: list[tuple[dict[str, Any], str, str]] = [
    (data("slider-crank", stroke=0.2, K=1.0, offset=0.04), "synthesis.K", "> 1"),
    (data("slider-crank", stroke=0.2, K=0.8, offset=0.04), "synthesis.K", "> 1"),
    (data("slider-crank", stroke=0.2, offset=0.04, **{"lambda": 1.0}), "synthesis.lambda", "> 1"),
    (data("slider-crank", stroke=0.2, K=1.2, offset=-0.01), "synthesis.offset", "≥ 0"),
    (data("slider-crank", stroke=0.2, K=1.2), "synthesis.offset", "K = 1"),
    (data("slider-crank", stroke=0.2, K=1.2, offset=0.0), "synthesis.offset", "K = 1"),
    (data("slider-crank", stroke=0.2, K=1.2, offset=0.7), "synthesis.offset", "too large"),
    (data("slider-crank", stroke=0.2, offset=0.08, **{"lambda": 1.5}), "synthesis.lambda",
     "no crank length"),
    (data("slider-crank", stroke=0.14, offset=0.03, **{"lambda": 1.5}), "synthesis.lambda",
     "least stroke"),
    (data("slider-crank", stroke=0.2, K=1.2, offset=0.04, **{"lambda": 3.0}),
     "synthesis.lambda", "not both"),
    (data("crank-rocker", swing_deg=45.0, K=1.2, rocker=0.25, frame=5.0), "synthesis.frame",
     "no crank-rocker pivot"),
    (data("crank-rocker", swing_deg=45.0, K=1.2, rocker=0.25, frame=0.2), "synthesis.frame",
     "no crank-rocker pivot"),
    (data("crank-rocker", swing_deg=45.0, K=0.9, rocker=0.25, frame=0.36), "synthesis.K", "> 1"),
    (data("slotted-lever", stroke=0.4, K=1.6, frame=0.35, rod=0.01), "synthesis.rod",
     "too short"),
    (data("slotted-lever", stroke=0.4, frame=0.35, rod=0.15), "synthesis.K", "missing"),
    (data("four-bar", stroke=0.4), "synthesis.kind", "must be one of"),
    (data("slider-crank", stroke=0.2, K=1.2, offset=0.04, H=0.3), "synthesis.H", "unknown key"),
    ({**data("slider-crank", stroke=0.2, K=1.2, offset=0.04),
      "drive": {"omega": 10.0, "working": "forward"}}, "drive.working", "slow stroke"),
    ({**data("slider-crank", stroke=0.2, K=1.2, offset=0.04),
      "load": [{"point": "B", "value": 100.0, "working": "backward"}]}, "load 1: working",
     "slow stroke"),
    ({**data("slider-crank", stroke=0.2, K=1.2, offset=0.04),
      "drive": {"omega": 10.0, "length": 0.1}}, "drive.length", "found by the synthesis"),
    ({**data("slider-crank", stroke=0.2, K=1.2, offset=0.04), "frame": {"O": [0, 0]}}, "frame",
     "no [frame]"),
]  # fmt: skip


@pytest.mark.parametrize(("d", "key", "words"), BAD, ids=[f"{b[1]}-{i}" for i, b in enumerate(BAD)])
def test_impossible_data_are_refused(d: dict[str, Any], key: str, words: str) -> None:
    with pytest.raises(FileKeyError) as exc:
        solved(d)
    assert str(exc.value).startswith(f"{key}: ")
    assert words in str(exc.value)


def test_a_refusal_is_one_error_line(tmp_path: Path) -> None:
    f = tmp_path / "bad.toml"
    f.write_text('[synthesis]\nkind = "slider-crank"\nstroke = 0.2\nK = 1.2\noffset = 0.9\n'
                 "[drive]\nomega = 10.0\n")  # fmt: skip
    out = subprocess.run(
        [sys.executable, "-m", "geomcad", "solve", str(f)], capture_output=True, text=True
    )
    assert out.returncode == 2 and out.stdout == ""
    assert out.stderr.count("\n") == 1 and out.stderr.startswith("error: ")
    assert "synthesis.offset" in out.stderr and "Traceback" not in out.stderr


# --- the protocol, the sheet, verify -------------------------------------------------------


def test_the_protocol_reads_as_the_solution() -> None:
    sol = solved(data("slider-crank", stroke=0.2, K=1.2, offset=0.04))
    first = sol.trace().split("\n\n")[0]
    names = [line.split(" = ")[0].split(". ", 1)[1] for line in first.splitlines()[1:]]
    order = ["θ", "B0", "B1", "x-x", "n0", "r1", "P", "Γ", "m", "O", "OB0", "OB1", "l1"]
    assert names[: len(order)] == order


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_synthesis_sheet(path: Path) -> None:
    from geomcad.sheet.synthesis import WORDS, synthesis_sheet
    from geomcad.sheet.views import step_text

    syn = synthesize(tomllib.loads(path.read_text(encoding="utf-8")))
    sheet = synthesis_sheet(syn, path.stem)
    texts = " ".join(getattr(it, "text", "") for it in sheet.items)
    assert "θ" in texts
    for s in syn.construction:
        if s.kind and s.role != "hidden":
            assert step_text(s, WORDS)  # every listed step has its words


def test_verify_reads_the_synthesis_results() -> None:
    from geomcad.verify import verify

    sol = solved(data("slider-crank", stroke=0.2, K=1.2, offset=0.04))
    l1 = sol.results["synthesis"]["l1"]
    k = sol.scales["ls"]
    good = verify(sol, {"synthesis.l1_mm": l1 / k + 0.3, "synthesis.theta_deg": 16.5})
    assert good.ok
    bad = verify(sol, {"synthesis.l2": sol.results["synthesis"]["l2"] + 2.0 * k})
    assert not bad.ok


def test_examples_solve() -> None:
    assert len(EXAMPLES) == 3
    kinds = {tomllib.loads(p.read_text())["synthesis"]["kind"] for p in EXAMPLES}
    assert kinds == {"slider-crank", "crank-rocker", "slotted-lever"}
    for p in EXAMPLES:
        parse(tomllib.loads(p.read_text()))  # the loader reads a synthesis file as it is


def test_geomcad_errors_only() -> None:
    with pytest.raises(GeomcadError):
        solved({"synthesis": "x", "drive": {"omega": 1.0}})
