"""Forces and the flywheel of linkage files (issue 15): kinetostatics by groups against one
Newton–Euler system of the whole mechanism, M_bal against Zhukovsky's lever and −ΣP/ω1, a
static case against hand statics, J_fw against the closed form computed here and the check by
the equation of motion, and bad input through the CLI."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from geomcad.cli import main
from geomcad.dynamics import Kinetostatics
from geomcad.geom import Vec
from geomcad.linkage import parse, sweep
from geomcad.linkage.analysis import analyse
from geomcad.linkage.kinetostatics import Forces, kinetostatics
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import Position
from geomcad.linkage.solution import Solved, results, solve

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "sixbar-2013-6.toml"
REL = 1e-9

SLIDER_CRANK = """
title = "slider-crank"
gravity = 9.81
[frame]
O = [0.0, 0.0]
[drive]
pivot = "O"
joint = "A"
length = 0.1
omega = 12.0
phi = [30.0, 100.0, 200.0, 290.0]
[[group]]
kind = "RRP"
links = [2, 3]
joint = "B"
end = "A"
length = 0.4
guide = { through = [0.0, -0.02], angle = 0.0 }
assembly = "forward"
[[point]]
name = "K"
link = 2
from = "A"
toward = "B"
along = 0.15
left = 0.03
[links.1]
mass = 2.0
J = 0.01
[links.2]
mass = 4.0
J = 0.06
centre = "K"
[links.3]
mass = 8.0
[[load]]
point = "B"
value = 1500.0
shape = [[0.0, 0.2], [0.5, 1.0], [1.0, 0.6]]
[[load]]
link = 2
moment = 7.0
[dynamics]
delta = 0.04
flywheel = "rim"
"""

SLOTTED = """
title = "slotted lever"
gravity = 9.81
[frame]
O = [0.0, 0.0]
C = [0.0, -0.35]
[drive]
pivot = "O"
joint = "A"
length = 0.12
omega = -8.0
positions = 8
[[group]]
kind = "RPR"
links = [2, 3]
slider = "A"
pivot = "C"
offset = 0.02
[[point]]
name = "D"
link = 3
from = "C"
toward = "A"
along = 0.6
[[group]]
kind = "RRP"
links = [4, 5]
joint = "E"
end = "D"
length = 0.25
guide = { through = [0.0, 0.3], angle = 0.0 }
assembly = "forward"
[links.2]
mass = 1.0
J = 0.002
[links.3]
mass = 6.0
J = 0.2
[links.4]
mass = 2.0
J = 0.01
[links.5]
mass = 15.0
[[load]]
point = "E"
value = 900.0
working = "backward"
[[load]]
link = 3
moment = -4.0
[dynamics]
delta = 0.08
"""

YOKE = """
title = "scotch yoke"
gravity = 9.81
[frame]
O = [0.0, 0.0]
[drive]
pivot = "O"
joint = "A"
length = 0.1
omega = 15.0
phi = [20.0, 75.0, 160.0, 250.0, 330.0]
[[group]]
kind = "PRP"
links = [2, 3]
slider = "A"
slot_angle = 60.0
guide = { through = [0.0, 0.05], angle = 10.0 }
point = "E"
[[point]]
name = "K"
link = 3
from = "E"
toward = "A"
along = 0.05
left = 0.02
[links.2]
mass = 0.5
J = 0.001
[links.3]
mass = 5.0
J = 0.02
centre = "K"
[[load]]
point = "E"
value = 800.0
stroke = "both"
"""

MOVING_GUIDE = """
title = "a slider on a rocker's guide"
gravity = 9.81
[frame]
O = [0.0, 0.0]
C = [0.3, 0.0]
[drive]
pivot = "O"
joint = "A"
length = 0.08
omega = 10.0
phi = [0.0, 70.0, 145.0, 215.0, 300.0]
[[group]]
kind = "RRR"
links = [2, 3]
joint = "B"
ends = ["A", "C"]
lengths = [0.3, 0.2]
assembly = "left"
[[group]]
kind = "RRP"
links = [4, 5]
joint = "D"
end = "A"
length = 0.5
guide = { link = 3, from = "C", toward = "B", offset = 0.01 }
assembly = "forward"
[links.2]
mass = 3.0
J = 0.03
[links.3]
mass = 2.0
J = 0.01
[links.4]
mass = 2.5
J = 0.05
[links.5]
mass = 1.5
J = 0.004
[[load]]
point = "D"
value = 300.0
stroke = "idle"
[[load]]
link = 3
moment = 5.0
"""

#: The yoke with its slot square to the guide, no weights and a moment on the yoke: the guide's
#: normal force is zero, so the guide carries a couple.
YOKE_COUPLE = (
    YOKE.replace("gravity = 9.81", "gravity = 0.0")
    .replace("slot_angle = 60.0", "slot_angle = 90.0")
    .replace("angle = 10.0", "angle = 0.0")
    + "[[load]]\nlink = 3\nmoment = 6.0\n"
)

FILES = {"slider-crank": SLIDER_CRANK, "slotted": SLOTTED, "yoke": YOKE,
         "moving-guide": MOVING_GUIDE, "yoke-couple": YOKE_COUPLE}  # fmt: skip


def load(text: str) -> Linkage:
    return parse(tomllib.loads(text))


def example() -> Linkage:
    return parse(tomllib.loads(EXAMPLE.read_text(encoding="utf-8")))


@pytest.fixture(scope="module", params=[*FILES, "example"])
def solved(request: pytest.FixtureRequest) -> Solved:
    name = request.param
    return solve(example() if name == "example" else load(FILES[name]))


# --- one Newton–Euler system of the whole mechanism ------------------------------------------


def newton_euler(lk: Linkage, P: Position, f: Forces) -> tuple[dict[str, Any], float]:
    """Every link's ΣF = 0, ΣM = 0 at once (geomcad.dynamics.Kinetostatics, least squares) under
    the same given loads: each revolute an unknown force, each sliding pair a normal force and a
    couple, the crank a balancing moment. Returns the reactions by pair and M_bal."""
    ks = Kinetostatics("whole mechanism")
    for i in lk.moving_links:
        ks.body(str(i))
        for ld in f.loads[i]:
            if ld.force is not None:
                ks.force(str(i), ld.name, ld.force, ld.at)
            else:
                ks.torque(str(i), ld.name, ld.moment)

    def b(i: int) -> str | None:
        return None if i == 0 else str(i)

    own = lk.owner
    pairs: dict[str, tuple[int, int, str, bool]] = {}

    def joint(of: int, on: int, at: str) -> None:
        name = f"{of}>{on}@{at}"
        ks.joint(name, b(of), str(on), P.pos[at])
        pairs[name] = (of, on, at, False)

    def slide(of: int, on: int, at: str, normal: Vec) -> None:
        name = f"{of}>{on}@{at}"
        ks.contact(name, b(of), str(on), P.pos[at], normal)
        ks.couple(name + ":couple", b(of), str(on))
        pairs[name] = (of, on, at, True)

    joint(0, 1, lk.pivot)
    for g in lk.groups:
        a, c = g.links
        if g.kind == "RRR":
            joint(own[g.ends[0]], a, g.ends[0])
            joint(own[g.ends[1]], c, g.ends[1])
            joint(c, a, g.joint)
        elif g.kind == "RRP":
            assert g.guide is not None
            joint(own[g.ends[0]], a, g.ends[0])
            joint(a, c, g.joint)
            slide(g.guide.link, c, g.joint, P.slide[c].perp())
        elif g.kind == "RPR":
            joint(own[g.slider], a, g.slider)
            slide(c, a, g.slider, P.slide[a].perp())
            joint(own[g.pivot], c, g.pivot)
        else:
            assert g.guide is not None
            joint(own[g.slider], a, g.slider)
            slide(c, a, g.slider, P.slide[a].perp())
            slide(0, c, g.joint, g.guide.direction.perp())
    ks.balancing_torque("M_bal", "1")
    sol = ks.solve()
    out: dict[str, Any] = {}
    for name, (_of, _on, _at, sliding) in pairs.items():
        out[name] = (sol.force(name), sol.moment(name + ":couple") if sliding else 0.0)
    return out, sol.moment("M_bal")


def close(a: float, b: float, scale: float, rel: float = REL) -> bool:
    return abs(a - b) <= rel * max(scale, 1e-300)


def test_groups_agree_with_one_newton_euler_system(solved: Solved) -> None:
    lk = solved.linkage
    a = analyse(solved)
    assert a.forces is not None
    for P, f in zip(solved.positions, a.forces, strict=True):
        ne, M = newton_euler(lk, P, f)
        scale = max(r.force.norm for r in f.reactions)
        assert close(f.M_bal, M, scale * lk.length), (f.M_bal, M)
        assert len(ne) == len(f.reactions)
        for r in f.reactions:
            F, couple = ne[f"{r.of}>{r.on}@{r.joint}"]
            assert close(r.force.x, F.x, scale) and close(r.force.y, F.y, scale), (r, F)
            # a sliding pair's reaction at its point = the normal force and a couple at the joint
            moment = (r.at - P.pos[r.joint]).cross(r.force) + r.couple
            assert close(moment, couple, scale * lk.length)


def test_a_slide_without_normal_force_carries_a_couple() -> None:
    lk = load(YOKE_COUPLE)
    f = analyse(solve(lk)).forces
    assert f is not None
    for P, forces in zip(solve(lk).positions, f, strict=True):
        (r03,) = [r for r in forces.reactions if r.key == (0, 3)]
        (r23,) = [r for r in forces.reactions if r.key == (2, 3)]
        assert abs(r03.force.norm) <= 1e-9 and r03.h == 0.0 and r03.couple != 0.0
        # the yoke about E: its loads, the block's force (2 on 3) and the guide's couple
        E = P.pos["E"]
        total = r03.couple + (r23.at - E).cross(-r23.force) - r23.couple
        for ld in forces.loads[3]:
            if ld.force is not None and ld.at is not None:
                total += (ld.at - E).cross(ld.force)
            else:
                total += ld.moment
        assert abs(total) <= 1e-9 * abs(r03.couple)


def test_m_bal_by_groups_lever_and_power(solved: Solved) -> None:
    lk = solved.linkage
    a = analyse(solved)
    assert a.forces is not None
    for P, f in zip(solved.positions, a.forces, strict=True):
        # ΣP here, from the plans' velocities: forces at their points, moments by ω of the link
        power = 0.0
        for i, lds in f.loads.items():
            for ld in lds:
                if ld.force is not None:
                    assert ld.at is not None
                    base = lk.link_points(i)[0]
                    V = P.vel[base] + (ld.at - P.pos[base]).perp() * P.omega[i]
                    power += ld.force.dot(V)
                else:
                    power += ld.moment * P.omega[i]
        by_power = -power / lk.omega
        scale = max(abs(f.M_bal), sum(abs(it.moment) for it in f.lever.items) / abs(lk.omega))
        assert close(f.M_bal, f.lever.M_bal, scale), (f.M_bal, f.lever.M_bal)
        assert close(f.M_bal, by_power, scale), (f.M_bal, by_power)


def test_inertia_loads_follow_the_sweep(solved: Solved) -> None:
    """Ф = −m·a_S and M_Ф = −J·ε, with a_S from the numpy kernel (not the plans)."""
    lk = solved.linkage
    a = analyse(solved)
    assert a.forces is not None
    st = sweep(lk, [P.phi for P in solved.positions], order=2)
    for k, f in enumerate(a.forces):
        for i, m in lk.masses.items():
            name = m.centre or lk.centre(i)
            if name:
                aS = st.acc[name][k]
            else:
                j1, j2 = lk.link_points(i)
                aS = 0.5 * (st.acc[j1][k] + st.acc[j2][k])
            inertia = [ld for ld in f.loads[i] if ld.kind == "inertia"]
            forces = [ld.force for ld in inertia if ld.force is not None]
            moments = [ld.moment for ld in inertia if ld.force is None]
            if m.mass > 0 and np.hypot(*aS) > 0:
                (F,) = forces
                assert np.allclose([F.x, F.y], -m.mass * aS, rtol=1e-9, atol=1e-9 * m.mass)
            eps = float(st.eps[i][k])
            assert math.isclose(sum(moments), -m.J * eps, rel_tol=1e-9, abs_tol=1e-9)


def test_results_carry_the_named_keys() -> None:
    s = solve(example())
    res = results(s)
    pos = res["positions"]
    assert len(pos) == 12
    for row in pos:
        for i, j in [(0, 1), (1, 2), (2, 3), (0, 3), (3, 4), (4, 5), (0, 5)]:
            R = row[f"R_{i}_{j}"]
            assert R >= 0.0
            assert math.isclose(R, math.hypot(row[f"R_{i}_{j}_x"], row[f"R_{i}_{j}_y"]))
        assert math.isclose(row["M_bal"], row["M_bal_lever"], rel_tol=REL, abs_tol=1e-9)
    for key in ("A_cycle", "M_drive", "J_flywheel", "omega_max", "omega_min", "delta_achieved"):
        assert isinstance(res[key], float), key
    assert len(res["I_pr"]) == len(res["M_pr"]) == 12
    # the resistance 2000 N over the working stroke H: its work per cycle is F·H
    assert math.isclose(res["A_cycle"], 2000.0 * res["stroke"], rel_tol=1e-7)
    assert math.isclose(res["M_drive"], res["A_cycle"] / (2 * math.pi), rel_tol=1e-12)
    assert math.isclose(res["omega_max"], 10.0 * 1.025) and math.isclose(
        res["omega_min"], 10.0 * 0.975
    )


def test_no_masses_no_loads_no_forces() -> None:
    data = tomllib.loads(SLIDER_CRANK)
    for key in ("links", "load", "dynamics"):
        del data[key]
    res = results(solve(parse(data)))
    assert not any(k.startswith(("R_", "M_bal")) for k in res["positions"][0])
    assert "J_flywheel" not in res


# --- a static case against hand statics ---------------------------------------------------------


def test_slow_slider_crank_against_hand_statics() -> None:
    """ω1 → 0: the inertia loads vanish; the rod (massless) is a two-force member."""
    w = 1.0e-5
    data = tomllib.loads(SLIDER_CRANK)
    data["drive"]["omega"] = w
    data["drive"]["phi"] = [60.0]
    data["links"] = {"1": {"mass": 2.0}, "3": {"mass": 8.0}}
    data["load"] = [{"point": "B", "value": 1000.0, "stroke": "both"}]
    del data["dynamics"]
    del data["point"]
    lk = parse(data)
    s = solve(lk)
    (f,) = analyse(s).forces or ()
    g = 9.81
    phi = math.radians(60.0)
    A = Vec(0.1 * math.cos(phi), 0.1 * math.sin(phi))
    B = Vec(A.x + math.sqrt(0.4**2 - (A.y + 0.02) ** 2), -0.02)
    u = (B - A).unit()
    # at 60°, ω > 0, the slider moves backward (−x): the load pushes it forward, +x
    F = 1000.0
    S = -F / u.x  # the rod's force on the slider, along u
    N = 8.0 * g - S * u.y  # the guide holds the rest
    M_bal = S * A.cross(u) + 2.0 * g * 0.05 * math.cos(phi)
    tol = 1e-6
    assert math.isclose(f.M_bal, M_bal, rel_tol=tol), (f.M_bal, M_bal)
    R23 = f.R(2, 3)
    assert math.isclose(R23.x, S * u.x, rel_tol=tol) and math.isclose(R23.y, S * u.y, rel_tol=tol)
    R03 = f.R(0, 3)
    assert abs(R03.x) <= tol and math.isclose(R03.y, N, rel_tol=tol)
    R01 = f.R(0, 1)
    assert math.isclose(R01.x, S * u.x, rel_tol=tol)
    assert math.isclose(R01.y, S * u.y + 2.0 * g, rel_tol=tol)


def test_slow_four_bar_with_a_moment_against_hand_statics() -> None:
    data = {
        "frame": {"O": [0.0, 0.0], "C": [0.3, 0.0]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.08, "omega": -1.0e-5, "phi": [40.0]},
        "group": [
            {
                "kind": "RRR",
                "links": [2, 3],
                "joint": "B",
                "ends": ["A", "C"],
                "lengths": [0.3, 0.2],
                "assembly": "left",
            }
        ],
        "load": [{"link": 3, "moment": 12.0}],
    }
    lk = parse(data)
    (P,) = solve(lk).positions
    f = kinetostatics(lk, P)
    A, B, C = P.pos["A"], P.pos["B"], P.pos["C"]
    u = (B - A).unit()
    fb = -12.0 / (B - C).cross(u)  # the coupler's force on the rocker at B, along u
    assert math.isclose(f.M_bal, fb * A.cross(u), rel_tol=1e-6)
    R23 = f.R(2, 3)
    assert math.isclose(R23.x, fb * u.x, rel_tol=1e-6)
    assert math.isclose(f.R(0, 3).y, -fb * u.y, rel_tol=1e-6)


# --- dynamics -------------------------------------------------------------------------------


def closed_form(lk: Linkage, n: int = 40000) -> tuple[float, float]:
    """A_cycle and J_fw of the example by linkages.md, computed here on a grid of n steps."""
    assert lk.dynamics is not None
    s = solve(lk)
    assert s.cycle is not None
    sign = math.copysign(1.0, lk.omega)
    psi = np.linspace(0.0, 2 * math.pi, n + 1)
    st = sweep(lk, s.cycle.phi_start + sign * psi, order=1)
    inertia = np.zeros_like(psi)
    P = np.zeros_like(psi)
    for i, m in lk.masses.items():
        j = lk.link_points(i)
        V = st.vel[j[0]] if len(j) == 1 else 0.5 * (st.vel[j[0]] + st.vel[j[1]])
        inertia += m.mass * (V**2).sum(axis=1) + m.J * st.omega[i] ** 2
        P += -m.mass * 9.81 * V[:, 1]
    v = st.vel["C"][:, 0]
    P += np.where(v > 1e-9, -2000.0 * v, 0.0)  # on the working (forward) stroke only
    inertia /= lk.omega**2
    Mpr = P / lk.omega
    W = sign * np.concatenate([[0.0], np.cumsum(0.5 * (Mpr[1:] + Mpr[:-1]) * np.diff(psi))])
    A = -W[-1]
    dA = A / (2 * math.pi) * psi + W
    w = abs(lk.omega)
    d = lk.dynamics.delta
    wmax, wmin = w * (1 + d / 2), w * (1 - d / 2)
    J = (np.max(0.5 * wmin**2 * inertia - dA) - np.min(0.5 * wmax**2 * inertia - dA)) / (
        0.5 * (wmax**2 - wmin**2)
    )
    return float(A), max(float(J), 0.0)


def test_flywheel_by_wittenbauer_is_the_closed_form_and_keeps_delta() -> None:
    lk = example()
    fw = analyse(solve(lk)).flywheel
    assert fw is not None
    A, J = closed_form(lk)
    assert math.isclose(fw.A_cycle, A, rel_tol=1e-7)
    assert math.isclose(fw.J_flywheel, J, rel_tol=1e-6), (fw.J_flywheel, J)
    # the tangents meet at O' = (−J_fw, −T0)
    t1, t2 = fw.tangents
    x = (t2.p - t1.p).cross(t2.d) / t1.d.cross(t2.d)
    assert math.isclose((t1.p + t1.d * x).x, -fw.J_flywheel, rel_tol=1e-9)
    # the equation of motion with this flywheel runs at the asked δ
    assert lk.dynamics is not None
    assert math.isclose(fw.delta_achieved, lk.dynamics.delta, rel_tol=1e-5), fw.delta_achieved
    assert fw.omega_t is not None
    assert math.isclose(float(np.max(fw.omega_t)), fw.omega_max, rel_tol=1e-6)
    assert math.isclose(float(np.min(fw.omega_t)), fw.omega_min, rel_tol=1e-6)


@pytest.mark.parametrize("name", ["slider-crank", "slotted"])
def test_flywheel_of_hand_written_files(name: str) -> None:
    lk = load(FILES[name])
    s = solve(lk)
    fw = analyse(s).flywheel
    assert fw is not None and lk.dynamics is not None
    assert fw.A_cycle > 0.0
    assert fw.J_flywheel > 0.0
    assert math.isclose(fw.delta_achieved, lk.dynamics.delta, rel_tol=1e-4), fw.delta_achieved
    # the dimensions give back J
    d = lk.dynamics
    if d.flywheel == "disc":
        J = math.pi * d.density * fw.b * fw.D**4 / 32
    else:
        J = fw.mass * fw.D**2 / 4
    assert math.isclose(J, fw.J_flywheel, rel_tol=1e-12)
    # M_pr·ω1 is the power of the loads and weights: zero over a cycle but for the resistance
    assert len(fw.I_pr) == (lk.positions or 12)


# --- bad input through the CLI ------------------------------------------------------------------

BAD = [
    (["links.2.mass=-1"], ["links.2.mass", "≥ 0"]),
    (["dynamics.delta=1.5"], ["dynamics.delta", "< 1"]),
    (["dynamics.delta=0"], ["dynamics.delta", "> 0"]),
    (["load.1.point=Q"], ["load 1", "Q"]),
]


@pytest.mark.parametrize(("sets", "words"), BAD, ids=[s[0] for s, _ in BAD])
def test_bad_input_is_one_error_line(
    capsys: pytest.CaptureFixture[str], sets: list[str], words: list[str]
) -> None:
    argv = ["solve", str(EXAMPLE), "--json"]
    for s in sets:
        argv += ["--set", s]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    for w in words:
        assert w in lines[0], (w, err)


# --- sheets 2 and 3 -------------------------------------------------------------------------


GOLDEN = Path(__file__).parent / "golden" / "linkage"


@pytest.mark.parametrize("name", ["example", "yoke", "moving-guide", "slotted"])
def test_force_and_dynamics_sheets(name: str, update_golden: bool) -> None:
    """The layout checker passes; the example's sheets match their golden files."""
    from layout import labels, layout_problems
    from test_golden import UPDATE_CMD, svg_difference

    from geomcad.render import to_svg
    from geomcad.sheet.linkage_forces import force_sheets
    from geomcad.sheet.model import Sheet

    lk = example() if name == "example" else load(FILES[name])
    s = solve(lk)
    sheets = [(n, sh) for n, sh in force_sheets(s, EXAMPLE.stem, first_no=2)]
    assert [n for n, _ in sheets] == (
        ["forces", "dynamics"] if lk.dynamics is not None else ["forces"]
    )
    for _, sheet in sheets:
        assert isinstance(sheet, Sheet)
        assert sheet.format in ("A2", "A1")  # by content (geomcad.sheet.linkage.fit)
        assert layout_problems(sheet) == []
    first = sheets[0][1]
    assert isinstance(first, Sheet)
    assert any(t.text.startswith("Рычаг Жуковского") for t in first.texts())
    assert any(t.startswith("R") for t in labels(first))
    if name != "example":
        return
    for n, sheet in sheets:
        assert isinstance(sheet, Sheet)
        path = GOLDEN / f"{EXAMPLE.stem}-{n}.svg"
        svg = to_svg(sheet)
        if update_golden:
            GOLDEN.mkdir(parents=True, exist_ok=True)
            path.write_text(svg, encoding="utf-8")
            continue
        assert path.exists(), f"no golden file {path}: run `{UPDATE_CMD}`"
        diff = svg_difference(svg, path.read_text(encoding="utf-8"))
        assert diff is None, f"{path.name} differs from its golden file: {diff}"


def test_solve_json_of_every_example_with_masses(capsys: pytest.CaptureFixture[str]) -> None:
    """`geomcad solve FILE --json`: the force results at each position, the dynamics on top."""
    import json

    files = [p for p in sorted(EXAMPLE.parent.glob("*.toml")) if "[links." in p.read_text()]
    assert len(files) >= 2
    for path in files:
        assert main(["solve", str(path), "--json"]) == 0
        res = json.loads(capsys.readouterr().out)["results"]
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        for row in res["positions"]:
            assert {"M_bal", "M_bal_lever", "R_0_1", "R_0_1_x", "R_0_1_y"} <= set(row)
            assert math.isclose(row["M_bal"], row["M_bal_lever"], rel_tol=1e-9, abs_tol=1e-9)
        if "dynamics" in data:
            n = data["drive"].get("positions", 12)
            assert len(res["I_pr"]) == len(res["M_pr"]) == n
            for key in ("A_cycle", "M_drive", "J_flywheel", "omega_max", "omega_min"):
                assert isinstance(res[key], float), (path.name, key)
            delta = data["dynamics"]["delta"]
            assert math.isclose(res["delta_achieved"], delta, rel_tol=1e-4), path.name


# --- the order of the force analysis, written from the recorded steps ----------------------


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_the_order_of_the_analysis_is_the_recorded_steps(solved: Solved, lang: str) -> None:
    """Every position's order: the loads, each group cut out from the last (its kind's
    template), its moment equations and polygons, the crank's M_bal and Zhukovsky's lever, each
    line one recorded step through its kind's template, the values the recorded ones."""
    from geomcad.sheet.lang import language
    from geomcad.sheet.linkage_forces import WORDS, order_steps
    from geomcad.sheet.views import num, step_text

    lk = solved.linkage
    a = analyse(solved)
    assert a.forces is not None
    for f in a.forces[:2]:
        with language(lang):
            steps = order_steps(f)
        assert [s.name for s in steps] == f.order
        kinds = [s.kind for s in steps]
        groups = [dict(s.args)["type"] for s in steps if s.kind == "group"]
        assert groups == [f"@{g.kind.lower()}" for g in reversed(lk.groups)]
        assert kinds[-4:] == ["polygon_closing", "balancing_moment", "zhukovsky", "lever_check"]
        with language(lang):
            texts = [step_text(s, WORDS) for s in steps]
            m_bal, lever = num(f.M_bal), num(f.lever.M_bal)
        assert f"= {m_bal} " in texts[kinds.index("balancing_moment")]
        assert f"= {lever} " in texts[kinds.index("zhukovsky")]
        if lang == "en":
            assert not any(chr(0x424) in t for t in texts)  # Φ, not the Cyrillic Ф


def test_the_force_sheet_lists_the_order() -> None:
    """Sheet 2 writes one numbered line per step of the order (the composition places it)."""
    from geomcad.sheet.linkage_forces import force_position, force_sheets

    s = solve(load(FILES["yoke"]))
    sheet = force_sheets(s)[0][1]
    n = len(force_position(s)[1].order)
    numbered = [t.text for t in sheet.texts() if t.role == "title" and t.text[:1].isdigit()
                and t.text.split(". ", 1)[0].isdigit()]  # fmt: skip
    assert [t.split(". ", 1)[0] for t in numbered][-n:] == [str(i) for i in range(1, n + 1)]
    assert any(t.text == "Порядок силового расчёта" for t in sheet.texts())


INVERTED = """
title = "inverted slider-crank"
[frame]
O = [0.0, 0.0]
C = [0.0, -0.06]
[drive]
pivot = "O"
joint = "A"
length = 0.12
omega = 20.0
phi = [90.0, 270.0, 30.0]
[[group]]
kind = "RPR"
links = [2, 3]
slider = "A"
pivot = "C"
offset = 0.0
[links.2]
mass = 2.0
J = 0.002
[links.3]
mass = 6.0
J = 0.04
[[load]]
link = 3
moment = -60.0
"""


def test_a_vanishing_angular_acceleration_is_zero_in_every_result() -> None:
    """With the crank along the line of the pivots, the rotating guide's ε vanishes: the plan
    reads ε = 0 (not 4·10^-13), the analysis has no inertia moment of 10^-16 N·m, and the
    JSON says 0; where ε does not vanish it is read as before."""
    from geomcad.linkage.plans import construct

    lk = load(INVERTED)
    for deg in (90.0, 270.0):
        P = construct(lk, math.radians(deg))
        assert P.eps[2] == 0.0 and P.eps[3] == 0.0
        f = kinetostatics(lk, P)
        inertia = [a for ls in f.loads.values() for a in ls if a.kind == "inertia"]
        assert inertia and all(a.force is not None for a in inertia)
    P = construct(lk, math.radians(30.0))
    assert abs(P.eps[3]) > 1.0  # a real ε is kept
    out = results(solve(lk))["positions"]
    vanishing = [p for p in out if round(p["phi_deg"]) % 180 == 90]
    assert len(vanishing) == 2
    assert all(p["eps_2"] == 0.0 and p["eps_3"] == 0.0 for p in vanishing)


# --- Zhukovsky's lever: the links' images joined, every load's point lettered ------------------


def joined_up(pts: list[Vec], segs: list[tuple[Vec, Vec, float]], k: float) -> bool:
    """Whether the segments ``segs`` (drawn at ``k`` mm per model unit) running from point to
    point of ``pts`` (those within 0.3 mm of each other one point) join them all."""
    uniq: list[Vec] = []
    for q in pts:
        if all(q.dist(u) * k > 0.3 for u in uniq):
            uniq.append(q)

    def at(q: Vec) -> int:
        return next((i for i, u in enumerate(uniq) if u.dist(q) * k < 0.05), -1)

    parent = list(range(len(uniq)))

    def root(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for a, b, _ in segs:
        i, j = at(a), at(b)
        if i >= 0 and j >= 0 and i != j:
            parent[root(i)] = root(j)
    return len({root(i) for i in range(len(uniq))}) <= 1


@pytest.mark.parametrize("name", [*FILES, "example", "shaper"])
def test_the_lever_joins_each_links_images_and_letters_every_load_point(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """On Zhukovsky's lever every moving link's image is drawn as on the velocity plan: a
    figure of segments from image to image joins the images of all its points (its points on
    the plans, a3 of a sliding pair included, and the points its force loads act at), and
    every point a load
    (a couple's two forces too) or the balancing force acts at carries a label."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.drawing import Viewport

    if name == "shaper":
        lk = parse(tomllib.loads((EXAMPLE.parent / "shaper.toml").read_text(encoding="utf-8")))
    else:
        lk = example() if name == "example" else load(FILES[name])
    s = solve(lk)
    P, f, _ = lf.force_position(s)
    segs: list[tuple[Vec, Vec, float]] = []  # (a, b, mm per model unit)
    anchors: list[tuple[Vec, str, float]] = []
    inside = [False]
    seg, label, draw = Viewport.seg, Viewport.label, lf._Lever.draw

    def rec_seg(v: Viewport, a: Any, b: Any, role: str = "link") -> None:
        if inside[0]:
            segs.append((Vec(*a), Vec(*b), v.mm(1.0)))
        seg(v, a, b, role)

    def rec_label(v: Viewport, q: Any, markup: str, *args: Any, **kw: Any) -> None:
        if inside[0]:
            anchors.append((Vec(*q), markup, v.mm(1.0)))
        label(v, q, markup, *args, **kw)

    levers: list[Any] = []

    def rec_draw(self: Any, d: Any, at: Any) -> None:
        inside[0] = True
        levers.append(self)
        try:
            draw(self, d, at)
        finally:
            inside[0] = False

    monkeypatch.setattr(Viewport, "seg", rec_seg)
    monkeypatch.setattr(Viewport, "label", rec_label)
    monkeypatch.setattr(lf._Lever, "draw", rec_draw)
    lf.force_sheets(s, name, first_no=2)
    assert segs and anchors and levers

    k = segs[0][2]
    for link in lk.moving_links:
        pts = [P.vp.points[n].perp() for _, n in P.handles.get(link, [])]
        pts += [ld.velocity.perp() for ld in f.loads.get(link, []) if ld.velocity is not None]
        # the images closer than 0.3 mm are one point; segments between them join them all
        assert joined_up(pts, segs, k), (name, link, pts)
    lev = f.lever
    # (a point off the velocity plan whose loads are all left out, named in the caption as
    # under the share drawn, is not drawn: review 12's unexplained d4)
    # (a moment is an arc on its link's image: its couple's points, the image's ends, drawn)
    fs = levers[-1].fs
    forces, moments = lf.lever_loads(f)
    drawn = [it.image for it in forces
             if fs.tier(it.force.norm) is not None or P.pn(it.point) in P.vp.points]  # fmt: skip
    drawn += [it.image for m in moments for it in m.pair]
    for q in [*drawn, lev.images[lk.joint]]:
        assert any(a.dist(q) * k < 0.85 and m.strip() for a, m, k in anchors), (name, q)


def test_a_links_figure_is_its_outline_through_its_points() -> None:
    """A link ABM with its centre S on AB: the outline a–s–b–m–a, no diagonal s–m; points in
    a line: consecutive segments; a point inside: joined to every corner."""
    from geomcad.sheet.linkage_forces import figure_edges

    a, b, m, s = Vec(0.0, 0.0), Vec(4.0, 0.0), Vec(1.0, 3.0), Vec(2.0, 0.0)
    pairs = {frozenset((x, y)) for x, y in figure_edges([a, b, m, s], 1e-6)}
    assert pairs == {frozenset(p) for p in [(a, s), (s, b), (b, m), (m, a)]}
    line = {frozenset((x, y)) for x, y in figure_edges([b, a, s], 1e-6)}
    assert line == {frozenset((a, s)), frozenset((s, b))}
    inside = Vec(1.5, 1.0)
    got = {frozenset((x, y)) for x, y in figure_edges([a, b, m, inside], 1e-6)}
    assert {frozenset((inside, q)) for q in (a, b, m)} <= got
    assert figure_edges([a, Vec(0.0, 1e-9)], 1e-6) == []


def _drawn_polygons(name: str, monkeypatch: pytest.MonkeyPatch) -> tuple[Linkage, Forces, Any]:
    """The forces sheet of ``name`` built with each group polygon's arrows and labels and
    each detail's letter recorded: (linkage, forces, record)."""
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet import views
    from geomcad.sheet.drawing import Viewport

    if name in ("shaper", "crusher", "slider-crank-example"):
        stem = "slider-crank" if name == "slider-crank-example" else name
        lk = parse(tomllib.loads((EXAMPLE.parent / f"{stem}.toml").read_text(encoding="utf-8")))
    else:
        lk = example() if name == "example" else load(FILES[name])
    rec: dict[str, Any] = {
        k: [] for k in ("arrows", "lines", "labels", "letters", "polys", "in_details", "ks")
    }
    rec["in"] = [False, False]
    arrow, label, draw, mark = Viewport.arrow, Viewport.label, views.draw_polygon, views.mark_detail
    detail = views.draw_detail
    seg = Viewport.seg

    def rec_seg(v: Viewport, a: Any, b: Any, role: str = "link") -> None:
        if rec["in"][0]:
            rec["lines"][-1].append((Vec(*a), Vec(*b)))
        seg(v, a, b, role)

    def rec_arrow(v: Viewport, a: Any, b: Any, role: str = "vector") -> None:
        if rec["in"][0]:
            rec["arrows"][-1].append((Vec(*a), Vec(*b)))
        arrow(v, a, b, role)

    def rec_label(v: Viewport, q: Any, markup: str, *args: Any, **kw: Any) -> None:
        if rec["in"][0]:
            rec["labels"][-1].append(markup)
        elif rec["in"][1]:
            rec["in_details"][-1].append(markup)
        label(v, q, markup, *args, **kw)

    def rec_draw(v: Viewport, poly: Any, *args: Any, **kw: Any) -> list[str]:
        rec["in"][0] = True
        rec["arrows"].append([])
        rec["lines"].append([])
        rec["labels"].append([])
        rec["in_details"].append([])
        rec["polys"].append((poly, kw.get("details", args[5] if len(args) > 5 else ())))
        rec["ks"].append(v.scale.k)
        try:
            return draw(v, poly, *args, **kw)
        finally:
            rec["in"][0] = False

    def rec_mark(v: Viewport, c: Any, r: float, letters: str, **kw: Any) -> Any:
        rec["letters"] += letters.split(", ")  # one circle for the pieces of one run
        return mark(v, c, r, letters, **kw)

    def rec_detail(v: Viewport, poly: Any, dt: Any, *args: Any, **kw: Any) -> None:
        rec["in"][1] = True
        try:
            detail(v, poly, dt, *args, **kw)
        finally:
            rec["in"][1] = False

    monkeypatch.setattr(Viewport, "arrow", rec_arrow)
    monkeypatch.setattr(Viewport, "seg", rec_seg)
    monkeypatch.setattr(Viewport, "label", rec_label)
    monkeypatch.setattr(views, "draw_polygon", rec_draw)
    monkeypatch.setattr(views, "mark_detail", rec_mark)
    monkeypatch.setattr(views, "draw_detail", rec_detail)
    s = solve(lk)
    lf.force_sheets(s, name, first_no=2)
    _, f, _ = lf.force_position(s)
    return lk, f, rec


@pytest.mark.parametrize("name", ["example", "slider-crank", "crusher", "shaper"])
def test_a_reaction_split_into_components_is_drawn_as_their_resultant(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """In a group's force polygon every reaction found by its components R^n, R^τ is drawn as
    well as their resultant, an arrow labelled R_{12} that closes them (from the tail of the
    one to the head of the other, or beside a component it would lie over) and is the
    reaction's force, except where its other component is too short to part it from its
    long one (a twin line): the long one's arrow is then named "R^n_{12} ≈ R_{12}"; and every
    vector a detail enlarges is still in the main polygon's chain, drawn there and named in
    its detail (and, a reaction, named on the plan too: every reaction is an arrow of it)."""
    from geomcad.sheet.views import main_arrows, twin_resultants

    _, f, rec = _drawn_polygons(name, monkeypatch)
    reactions = {r.name: r.force for gf in f.groups for r in gf.reactions}
    split = 0
    for (poly, details), arrows, lines, labels, in_details, k in zip(
        rec["polys"], rec["arrows"], rec["lines"], rec["labels"], rec["in_details"], rec["ks"],
        strict=True,
    ):  # fmt: skip
        big = max(pv.magnitude for pv in poly.vectors)
        twins = twin_resultants(poly, k)
        comps: dict[str, list[Any]] = {}
        for pv in poly.vectors:
            if "^n" in pv.name or "^τ" in pv.name:
                comps.setdefault(pv.name.replace("^n", "").replace("^τ", ""), []).append(pv)
        for rname, (a, b) in comps.items():
            if min(a.magnitude, b.magnitude) <= 1e-9 * big:
                continue
            split += 1
            total = a.force + b.force
            assert rname in reactions and reactions[rname].dist(total) <= 1e-6 * big, rname
            if rname in twins:
                assert f"{twins[rname]} ≈ {rname}" in labels, (name, rname, labels)
                assert rname not in labels
                continue
            assert rname in labels, (name, rname, labels)
            tails, heads = {a.tail, b.tail}, {a.head, b.head}
            # from the tail of the one to the head of the other, or (along a component it
            # would be drawn over) that closing vector moved across its own line beside it
            u = total.unit()
            assert any(
                (q - p).dist(total) <= 1e-6 * big
                and any(
                    (p - t).dist(q - h) <= 1e-6 * big and abs(u.dot(p - t)) <= 1e-6 * big
                    for t in tails
                    for h in heads
                )
                for p, q in arrows
            ), (name, rname)
        for dt in details:
            for n in dt.run:
                pv = poly[n]
                assert any(
                    p.dist(pv.tail) <= 1e-6 * big and q.dist(pv.head) <= 1e-6 * big
                    for p, q in arrows + lines
                ), (name, n)
                # named in its detail (the circle round it on the polygon is clear of labels),
                # or, too short there, listed with its value under the detail's caption
                assert n in in_details or n in dt.listed, (name, n, in_details)
                # a reaction is an arrow of the plan, named there too, however short
                # (round 14: views.main_arrows); any other vector only in its detail
                assert n not in labels or n in main_arrows(poly), (name, n, labels)
    assert split >= 1


_LATIN_LIKE = dict(zip("АВЕКМНОРСТУХ", "ABEKMHOPCTYX", strict=True))


@pytest.mark.parametrize("name", ["example", "slider-crank-example", "crusher", "shaper"])
def test_no_detail_letter_reads_as_a_point_or_a_force(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The letters of the polygons' details (ESKD выносной элемент) are never a point's letter
    on the sheet, nor a Cyrillic capital drawn as one, nor a force's letter, and each is used
    once."""
    lk, _, rec = _drawn_polygons(name, monkeypatch)
    from geomcad.sheet import linkage_forces as lf

    P, _, _ = lf.force_position(solve(lk))
    taken = {n[0] for n in P.pos} | set("FGMPRSФΦ")
    letters = rec["letters"]
    assert letters, name
    assert len(set(letters)) == len(letters), letters
    for c in letters:
        assert c[0] not in taken and _LATIN_LIKE.get(c[0]) not in taken, (name, c, sorted(taken))


def test_detail_letters_leave_out_the_used_ones_and_never_run_out() -> None:
    from geomcad.sheet.views import detail_letters

    it = detail_letters(["A", "B", "E", "O1", "Б"])
    first = [next(it) for _ in range(40)]
    assert not {"А", "В", "Е", "О", "Б", "A", "B", "E", "O"} & {c[0] for c in first}
    assert len(set(first)) == 40
