"""Linkage files, second round (linkages.md, "Settled in the second round"): a rocker as the
output, ``[drive] working``, moment loads on a stroke, rest on no stroke, loads that add up, the
numbered positions with ``phi``, the force analysis' position, bad combinations, the text
report. Each meaning against a closed form or an independent statement of it."""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.cli import main
from geomcad.errors import FileKeyError, GeomcadError
from geomcad.linkage import parse
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import results, solve

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TWO_PI = 2.0 * math.pi


def load(name: str) -> dict[str, Any]:
    return tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))


def four_bar(
    l1: float = 0.08,
    l2: float = 0.28,
    l3: float = 0.20,
    d: float = 0.30,
    omega: float = 12.0,
    **drive: Any,
) -> dict[str, Any]:
    """A crank-rocker O A B C on the x axis, B above it (no ``output``: the rocker 3 is)."""
    return {
        "frame": {"O": [0.0, 0.0], "C": [d, 0.0]},
        "drive": {"pivot": "O", "joint": "A", "length": l1, "omega": omega, **drive},
        "group": [
            {"kind": "RRR", "links": [2, 3], "joint": "B", "ends": ["A", "C"],
             "lengths": [l2, l3], "assembly": "left"},
        ],
    }  # fmt: skip


def rocker_extremes(
    l1: float, l2: float, l3: float, d: float
) -> tuple[tuple[float, float], tuple[float, float]]:
    """(ψ, φ) of the rocker's two extremes, crank and coupler in line (B above the axis):
    OB = l2 + l1 (crank along OB) and OB = l2 − l1 (crank against OB), by the cosine rule."""
    out = []
    for ob, along in ((l2 + l1, True), (l2 - l1, False)):
        gamma = math.acos((d * d + l3 * l3 - ob * ob) / (2.0 * d * l3))  # the angle at C
        psi = math.pi - gamma  # CB from +x, B above the axis
        B = (d + l3 * math.cos(psi), l3 * math.sin(psi))
        phi = math.atan2(B[1], B[0]) + (0.0 if along else math.pi)
        out.append((psi, phi % TWO_PI))
    return out[0], out[1]


@pytest.mark.parametrize("omega", [12.0, -12.0])
@pytest.mark.parametrize("working", ["forward", "backward"])
def test_a_four_bar_rocker_swing_and_K_by_the_cosine_rule(omega: float, working: str) -> None:
    l1, l2, l3, d = 0.08, 0.28, 0.20, 0.30
    data = four_bar(l1, l2, l3, d, omega, working=working, positions=12)
    r = results(solve(parse(data)))
    (psi_a, phi_a), (psi_b, phi_b) = rocker_extremes(l1, l2, l3, d)
    assert "stroke" not in r
    assert r["swing_deg"] == pytest.approx(math.degrees(abs(psi_a - psi_b)), abs=1e-9)
    # forward: ψ rising; the working swing starts at ψ_min
    lo, hi = ((psi_a, phi_a), (psi_b, phi_b)) if psi_a < psi_b else ((psi_b, phi_b), (psi_a, phi_a))
    start, end = (lo, hi) if working == "forward" else (hi, lo)
    sign = 1.0 if omega > 0 else -1.0
    turn = (sign * (end[1] - start[1])) % TWO_PI
    assert r["K"] == pytest.approx(turn / (TWO_PI - turn), rel=1e-9)
    # numbering from the working swing's start, in the crank's sense
    for k, pos in enumerate(r["positions"]):
        want = math.degrees((start[1] + sign * k * TWO_PI / 12) % TWO_PI)
        assert math.remainder(pos["phi_deg"] - want, 360.0) == pytest.approx(0.0, abs=1e-7)
    p0 = r["positions"][0]
    assert abs(p0["omega_3"]) < 1e-9 * abs(omega)
    psi0 = math.atan2(p0["y_B"], p0["x_B"] - d)
    assert psi0 == pytest.approx(start[0], abs=1e-9)
    # the working swing: ψ moves the named way at position 1
    dpsi = r["positions"][1]["omega_3"]
    assert (dpsi > 0) == (working == "forward")


def test_working_backward_is_the_other_swing() -> None:
    fwd = results(solve(parse(four_bar(positions=12))))
    back = results(solve(parse(four_bar(positions=12, working="backward"))))
    assert back["K"] == pytest.approx(1.0 / fwd["K"], rel=1e-9)
    assert back["swing_deg"] == pytest.approx(fwd["swing_deg"], rel=1e-12)


def slotted_lever(r: float = 0.1, d: float = 0.3, **drive: Any) -> dict[str, Any]:
    return {
        "frame": {"O": [0.0, 0.0], "C": [0.0, -d]},
        "drive": {"pivot": "O", "joint": "A", "length": r, "omega": 10.0, **drive},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C"}],
    }


def test_a_slotted_lever_as_the_output() -> None:
    """Link 3 of an RPR turning at a frame point is the default output: the swing is
    2·asin(r/d), and the lever is perpendicular to the crank at both extremes, so K =
    (180° + θ)/(180° − θ) with θ the swing, the slow stroke being the one the crank turns
    through the far side."""
    r, d = 0.1, 0.3
    res = results(solve(parse(slotted_lever(r, d, positions=12))))
    theta = 2.0 * math.asin(r / d)
    assert res["swing_deg"] == pytest.approx(math.degrees(theta), abs=1e-9)
    # ω1 > 0: A crosses the far side of C (the longer arc, π + θ) moving left, so the lever's
    # ψ (C → A) rises there: the forward (default working) swing is the slow one
    assert res["K"] == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-9)
    # the working swing has ω3 > 0 at every numbered position inside it, the idle one < 0
    s = solve(parse(slotted_lever(r, d, positions=24)))
    cyc = s.cycle
    assert cyc is not None
    for k, P in enumerate(s.drawn):
        turn = k * TWO_PI / 24
        if 1e-9 < turn < cyc.phi_working - 1e-9:
            assert P.omega[3] > 0.0
        elif turn > cyc.phi_working + 1e-9:
            assert P.omega[3] < 0.0


def test_output_names_a_link_or_a_point() -> None:
    assert parse(four_bar(output=3)).rocker == 3
    assert parse(four_bar(output="B")).rocker == 3
    assert parse(four_bar()).rocker == 3  # the default: the RRR's rocker turns about C
    slider = load("slider-crank.toml")
    slider["drive"]["output"] = 3
    lk = parse(slider)
    assert lk.output == "B" and lk.rocker == 0
    # the coupler is neither a slider nor a rocker: refused as a link; a point on it is an
    # output with no stroke, swing or K, numbered from φ = 0
    with pytest.raises(FileKeyError, match=r"drive\.output"):
        parse(four_bar(output=2))
    with pytest.raises(FileKeyError, match="frame point"):
        parse(four_bar(output="C"))
    with pytest.raises(FileKeyError, match=r"drive\.output"):
        parse(four_bar(output=1))
    data = four_bar(positions=4)
    data["point"] = [{"name": "M", "link": 2, "from": "A", "toward": "B", "along": 0.1}]
    data["drive"]["output"] = "M"
    r = results(solve(parse(data)))
    assert "K" not in r and "swing_deg" not in r
    assert r["positions"][0]["phi_deg"] == 0.0


def test_a_double_crank_has_no_swing() -> None:
    """A "rocker" that turns fully is a crank: no swing, no K, numbered from φ = 0."""
    data = four_bar(l1=0.3, l2=0.3, l3=0.35, d=0.1, positions=6)
    r = results(solve(parse(data)))
    assert "K" not in r and "swing_deg" not in r
    assert r["positions"][0]["phi_deg"] == 0.0
    data["drive"]["working"] = "forward"  # a working stroke it cannot have is named
    with pytest.raises(FileKeyError, match=r"drive\.working.*turns fully"):
        solve(parse(data))
    data["drive"].pop("working")
    data["load"] = [{"link": 3, "moment": 1.0, "stroke": "both"}]
    with pytest.raises(FileKeyError, match="load 1: stroke"):
        solve(parse(data))


def rocker_with_moment(stroke: str | None, moment: float = 10.0, **drive: Any) -> dict[str, Any]:
    data = four_bar(positions=12, **drive)
    load_t: dict[str, Any] = {"link": 3, "moment": moment}
    if stroke is not None:
        load_t["stroke"] = stroke
    data["load"] = [load_t]
    return data


@pytest.mark.parametrize("stroke", ["working", "idle", "both", None])
@pytest.mark.parametrize("working", ["forward", "backward"])
def test_a_moment_load_on_a_stroke(stroke: str | None, working: str) -> None:
    """Without masses the crank's balancing moment is the power balance of the one load:
    M_bal·ω1 + M·ω3 = 0, M = −|M|·sign(ω3) while the rocker moves on the named stroke (the sign
    of ω3 times the working direction), 0 at rest; without stroke, the signed constant."""
    M = -10.0
    s = solve(parse(rocker_with_moment(stroke, M, working=working)))
    r = results(s)
    fwd = 1.0 if working == "forward" else -1.0
    for k, pos in enumerate(r["positions"]):
        w3, w1 = pos["omega_3"], 12.0
        moving = 0.0 if (k == 0 or abs(w3) < 1e-9 * w1) else math.copysign(1.0, w3) * fwd
        if stroke is None:
            m = M
        else:
            on = {"working": moving > 0, "idle": moving < 0, "both": moving != 0}[stroke]
            m = -abs(M) * math.copysign(1.0, w3) if on else 0.0
        assert pos["M_bal"] == pytest.approx(-m * w3 / w1, abs=1e-9)
        assert pos["M_bal_lever"] == pytest.approx(pos["M_bal"], abs=1e-9)
    if stroke is not None:
        assert r["positions"][0]["M_bal"] == 0.0  # position 0: at rest by definition


def test_a_moment_load_with_stroke_in_the_dynamics() -> None:
    """A_cycle of |M| against ω3 on the working swing is |M| times the swing (in rad)."""
    data = rocker_with_moment("working", 10.0)
    data["links"] = {"3": {"mass": 1.0, "J": 0.01}}
    data["dynamics"] = {"delta": 0.05}
    data["gravity"] = 0.0
    r = results(solve(parse(data)))
    assert r["A_cycle"] == pytest.approx(10.0 * math.radians(r["swing_deg"]), rel=1e-6)


def test_loads_add_up() -> None:
    """Two loads on one point (or one link) act as their sum."""
    one = load("slider-crank.toml")
    two = copy.deepcopy(one)
    two["load"] = [dict(one["load"][0], value=1000.0), dict(one["load"][0], value=500.0)]
    a, b = results(solve(parse(one))), results(solve(parse(two)))
    for pa, pb in zip(a["positions"], b["positions"], strict=True):
        for k, v in pa.items():
            assert pb[k] == pytest.approx(v, abs=1e-9 * max(1.0, abs(v))), k
    m1 = rocker_with_moment(None, -15.0)
    m2 = rocker_with_moment(None, -10.0)
    m2["load"].append({"link": 3, "moment": -5.0})
    a, b = results(solve(parse(m1))), results(solve(parse(m2)))
    assert [p["M_bal"] for p in a["positions"]] == pytest.approx(
        [p["M_bal"] for p in b["positions"]], abs=1e-12
    )


def test_rest_is_on_no_stroke() -> None:
    """A central slider-crank (K = 1): positions 0 and N/2 are the two extremes; no load acts
    there, so without masses M_bal = 0 exactly."""
    data = load("slider-crank.toml")
    data.pop("links")
    data["load"][0]["stroke"] = "both"
    r = results(solve(parse(data)))
    assert r["K"] == pytest.approx(1.0, abs=1e-12)
    assert r["positions"][0]["M_bal"] == 0.0
    assert r["positions"][6]["M_bal"] == 0.0
    assert r["positions"][3]["M_bal"] != 0.0


def test_phi_keeps_the_numbered_positions() -> None:
    data = load("slider-crank.toml")
    data["drive"]["phi"] = [60.0, 200.0]
    s = solve(parse(data))
    assert len(s.drawn) == 12 and len(s.positions) == 2
    assert [math.degrees(p) % 360.0 for p in s.accel_phis] == pytest.approx([60.0, 200.0])
    r = results(s)
    assert [p["phi_deg"] for p in r["positions"]] == pytest.approx([60.0, 200.0])


def test_acceleration_plans_at_the_largest_output_acceleration() -> None:
    """Default: in each stroke, the numbered position where |a| of the output is largest."""
    data = load("shaper.toml")
    s = solve(parse(data))
    r = results(s)
    cyc = s.cycle
    assert cyc is not None
    n = len(r["positions"])
    strokes: dict[str, list[int]] = {"working": [], "idle": []}
    for k in range(1, n):
        turn = k * TWO_PI / n
        if abs(turn - cyc.phi_working) > 1e-9:
            strokes["working" if turn < cyc.phi_working else "idle"].append(k)
    want = []
    for ks in strokes.values():
        a = [r["positions"][k]["a_D"] for k in ks]  # the ram on a fixed guide: |a| along it
        want.append(r["positions"][ks[a.index(max(a))]]["phi_deg"])
    got = [math.degrees(p) % 360.0 for p in s.accel_phis]
    assert got == pytest.approx(want, abs=1e-7)


def test_the_default_force_position() -> None:
    """The first numbered position where the point loads' resistance is largest; results.forces
    holds that position's reactions and moments."""
    data = load("slider-crank.toml")
    s = solve(parse(data))
    r = results(s)
    fwd = 1.0 if s.linkage.working == "forward" else -1.0
    res = []
    for k, pos in enumerate(r["positions"]):  # the load has no shape: 1500 N on the working stroke
        v = pos["V_B_x"]
        moving = 0.0 if k == 0 or abs(v) < 1e-9 * 50 * 0.08 else math.copysign(1.0, v) * fwd
        res.append(1500.0 if moving > 0 else 0.0)
    k = res.index(max(res))
    assert r["forces_phi_deg"] == pytest.approx(r["positions"][k]["phi_deg"], abs=1e-9)
    for key, v in r["forces"].items():
        assert r["positions"][k][key] == pytest.approx(v, abs=1e-12)


def test_force_position_and_phi() -> None:
    data = load("slider-crank.toml")
    data["forces"] = {"position": 4}
    r = results(solve(parse(data)))
    assert r["forces_phi_deg"] == pytest.approx(r["positions"][4]["phi_deg"], abs=1e-9)
    data["forces"] = {"phi": 77.0}
    r = results(solve(parse(data)))
    assert r["forces_phi_deg"] == pytest.approx(77.0, abs=1e-9)
    at = copy.deepcopy(data)
    at.pop("forces")
    at["drive"]["phi"] = [77.0]
    want = results(solve(parse(at)))["positions"][0]
    for key, v in r["forces"].items():
        assert want[key] == pytest.approx(v, abs=1e-9 * max(1.0, abs(v))), key
    with pytest.raises(FileKeyError, match=r"forces\.position"):
        parse(dict(data, forces={"position": 12}))
    with pytest.raises(FileKeyError, match="not both"):
        parse(dict(data, forces={"position": 1, "phi": 3.0}))


def test_no_point_load_takes_the_largest_balancing_moment() -> None:
    data = rocker_with_moment("working", 10.0)
    s = solve(parse(data))
    r = results(s)
    m = [abs(p["M_bal"]) for p in r["positions"]]
    assert r["forces_phi_deg"] == pytest.approx(r["positions"][m.index(max(m))]["phi_deg"])
    assert analyse(s).force_index == m.index(max(m))


@pytest.mark.parametrize(
    ("edit", "key"),
    [
        (lambda d: d["load"].__setitem__(0, {"link": 3, "moment": 1.0, "shape": [[0, 0], [1, 1]]}),
         "load 1: shape"),
        (lambda d: d["load"].__setitem__(0, {"link": 3, "moment": 1.0, "working": "forward"}),
         "load 1: working"),
        (lambda d: d["drive"].__setitem__("working", "sideways"), "drive.working"),
        (lambda d: d.__setitem__("forces", {"pos": 1}), "forces.pos"),
    ],
)  # fmt: skip
def test_bad_combinations_are_named(edit: Any, key: str) -> None:
    data = rocker_with_moment("working")
    edit(data)
    with pytest.raises(FileKeyError, match=key.replace(".", r"\.")):
        parse(data)


def test_working_keys_must_agree() -> None:
    data = load("slider-crank.toml")
    data["drive"]["working"] = "forward"  # the load says backward
    with pytest.raises(FileKeyError, match=r"disagrees with drive\.working"):
        parse(data)
    data["drive"]["working"] = "backward"
    assert parse(data).working == "backward"


def test_a_stroke_needs_an_output_with_strokes() -> None:
    data = four_bar(positions=4)
    data["point"] = [{"name": "M", "link": 2, "from": "A", "toward": "B", "along": 0.1}]
    data["drive"]["output"] = "M"
    data["load"] = [{"link": 3, "moment": 1.0, "stroke": "working"}]
    with pytest.raises(FileKeyError, match="no strokes"):
        parse(data)


def test_crusher_example() -> None:
    """The jaw is a rocker output, worked clockwise; the moment resists it on that swing."""
    s = solve(parse(load("crusher.toml")))
    r = results(s)
    assert s.linkage.rocker == 5 and s.linkage.working == "backward"
    p0 = r["positions"][0]
    assert abs(p0["omega_5"]) < 1e-9 * 25.0
    assert r["positions"][1]["omega_5"] < 0.0  # the working swing: clockwise
    assert 0.0 < r["swing_deg"] < 10.0 and r["K"] > 0.0
    assert "forces" in r and "J_flywheel" in r


def test_the_text_report(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["solve", str(EXAMPLES / "crusher.toml")]) == 0
    out = capsys.readouterr().out
    assert "parameters:" not in out
    assert "e-1" not in out  # no round-off printed as 5.02e-16
    for head in ("x, m", "ω5, rad/s", "R_i_j, N", "M_bal, N·m", "I_pr, kg·m²"):
        assert head in out
    assert "swing_deg = " in out and "° " not in out.split("swing_deg = ")[1].split("\n")[0][:-1]
    assert "A_cycle = " in out and out.split("A_cycle = ")[1].split("\n")[0].endswith(" J")
    assert "M_drive = " in out and out.split("M_drive = ")[1].split("\n")[0].endswith(" N·m")


def test_errors_name_a_crank_angle_not_an_index() -> None:
    data = four_bar(l1=0.12, l2=0.2, l3=0.1, d=0.3)
    with pytest.raises(GeomcadError) as info:
        solve(parse(data))
    msg = str(info.value)
    assert "group 1" in msg and "crank angle φ = " in msg and "index" not in msg


@pytest.mark.parametrize("offset", [0.0, 0.03, -0.05])
@pytest.mark.parametrize("omega", [10.0, -10.0])
def test_an_oscillating_cylinder_against_a_dense_sweep(offset: float, omega: float) -> None:
    """Link 3 of an RPR at a frame pivot, its angle the slide line's direction: ψ = ∠(A − C) −
    asin(o/|A − C|). Its swing and K against the extremes of ψ over 200 000 crank angles (an
    independent statement of the geometry, no root refinement)."""
    r, C = 0.08, (0.25, 0.1)
    data = {
        "frame": {"O": [0.0, 0.0], "C": list(C)},
        "drive": {"pivot": "O", "joint": "A", "length": r, "omega": omega, "positions": 8,
                  "working": "backward"},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C",
                   "offset": offset}],
    }  # fmt: skip
    res = results(solve(parse(data)))
    n = 200_000
    psi, phis = [], []
    for i in range(n):
        phi = TWO_PI * i / n
        ax, ay = r * math.cos(phi) - C[0], r * math.sin(phi) - C[1]
        psi.append(math.atan2(ay, ax) - math.asin(offset / math.hypot(ax, ay)))
        phis.append(phi)
    hi, lo = psi.index(max(psi)), psi.index(min(psi))
    assert res["swing_deg"] == pytest.approx(math.degrees(psi[hi] - psi[lo]), abs=1e-6)
    sign = 1.0 if omega > 0 else -1.0
    turn = (sign * (phis[lo] - phis[hi])) % TWO_PI  # backward: from ψ_max down to ψ_min
    assert res["K"] == pytest.approx(turn / (TWO_PI - turn), abs=1e-3)
    assert res["positions"][0]["phi_deg"] == pytest.approx(math.degrees(phis[hi]), abs=0.01)


def test_the_report_prints_round_off_as_zero() -> None:
    from geomcad.files.linkage_report import table

    lines = table(["a, m/s", "b, N"], [[4.0, 1500.0], [5.022e-16, 1e-3], [-2.0, -0.5]])
    cells = [ln.split() for ln in lines[2:]]
    assert cells[1] == ["0", "0.001"]  # 5e-16 of 4 m/s is round-off; 1e-3 of 1500 N is not
    assert cells[2] == ["-2", "-0.5"]
    assert lines[0].split() == ["a,", "m/s", "b,", "N"]
