"""Linkage files: the model, every group kind against closed forms and numerical differentiation,
the plans against the sweep, assembly modes, stroke and K, structure, bad files, the CLI and the
kinematic sheet."""

from __future__ import annotations

import copy
import itertools
import json
import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from layout import layout_problems

import geomcad
from geomcad import documents
from geomcad.cli import main
from geomcad.errors import FileKeyError, GeomcadError, NoIntersection
from geomcad.linkage import parse, sweep
from geomcad.linkage.cycle import cycle
from geomcad.linkage.plans import construct
from geomcad.linkage.solution import moving_points, solve

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.toml"))
LINKAGES = [p for p in EXAMPLES if documents.kind_of(tomllib.loads(p.read_text())) == "linkage"]


def load(path: Path) -> dict[str, Any]:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def slotted(C: tuple[float, float] = (0.0, -0.3), offset: float = 0.0) -> dict[str, Any]:
    return {
        "frame": {"O": [0.0, 0.0], "C": list(C)},
        "drive": {"pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0, "phi": [30.0]},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C", "offset": offset}],
    }


def test_examples_cover_every_group_kind() -> None:
    kinds = {g.kind for p in LINKAGES for g in parse(load(p)).groups}
    assert kinds == {"RRR", "RRP", "RPR", "PRP"}
    assert len(LINKAGES) >= 6
    moving = [g for p in LINKAGES for g in parse(load(p)).groups if g.guide and not g.guide.fixed]
    assert moving, "an example has a guide on a moving link"


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_plans_agree_with_the_sweep(path: Path) -> None:
    """Every value read off the recorded plans equals the vectorised kernel's."""
    lk = parse(load(path))
    s = solve(lk)
    phis = [P.phi for P in s.positions]
    st = sweep(lk, phis)
    L, w = lk.length, abs(lk.omega)
    for i, P in enumerate(s.positions):
        for name in moving_points(lk):
            assert np.allclose(P.pos[name].array(), st.pos[name][i], rtol=0, atol=1e-12 * L)
            assert np.allclose(P.vel[name].array(), st.vel[name][i], rtol=0, atol=1e-9 * w * L)
            assert np.allclose(P.acc[name].array(), st.acc[name][i], rtol=0, atol=1e-9 * w * w * L)
        for j in lk.moving_links:
            assert P.omega[j] == pytest.approx(st.omega[j][i], abs=1e-9 * w)
            assert P.eps[j] == pytest.approx(st.eps[j][i], abs=1e-9 * w * w)
        for name, v in P.v_rel.items():
            assert v == pytest.approx(st.v_rel[name][i], abs=1e-9 * w * L)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_velocities_and_accelerations_are_derivatives_of_positions(path: Path) -> None:
    """Central differences of independently swept positions (order 0) give V and a."""
    lk = parse(load(path))
    phi = np.linspace(0.1, 2.0 * math.pi + 0.1, 24, endpoint=False)
    h = 1e-4
    st = sweep(lk, phi)
    p_m, p_0, p_p = (sweep(lk, phi + k * h, order=0) for k in (-1.0, 0.0, 1.0))
    w = lk.omega
    scale = lk.length * w * w
    for name in moving_points(lk):
        dv = (p_p.pos[name] - p_m.pos[name]) / (2 * h) * w
        da = (p_p.pos[name] - 2 * p_0.pos[name] + p_m.pos[name]) / (h * h) * w * w
        assert np.allclose(st.vel[name], dv, rtol=0, atol=1e-6 * scale)
        assert np.allclose(st.acc[name], da, rtol=0, atol=5e-4 * scale)
    for j in lk.moving_links:
        g = lk.group_of(j)
        if j != 1 and g is not None and g.kind == "RRR":
            e = g.ends[0] if j == g.links[0] else g.ends[1]
            ang = [np.arctan2(*(q.pos[g.joint] - q.pos[e])[:, ::-1].T) for q in (p_m, p_0, p_p)]
            dw = np.unwrap(np.array([ang[0], ang[2]]), axis=0)
            assert np.allclose(st.omega[j], (dw[1] - dw[0]) / (2 * h) * w, atol=1e-6 * abs(w))


def test_slotted_lever_keeps_its_coriolis_term() -> None:
    """The issue's case: crank 0.1 m, pivots 0.3 m apart, φ = 30°, ω1 = 10 → ε3 = 12.299."""
    lk = parse(slotted())
    st = sweep(lk, [math.radians(30.0)])
    assert st.eps[3][0] == pytest.approx(12.29858562, rel=1e-8)
    # closed form: ω3 = ω1·r·(r + d sin φ)/L² with d = |OC| below O
    r, d, phi = 0.1, 0.3, math.radians(30.0)
    L2 = r * r + d * d + 2 * r * d * math.sin(phi)
    assert st.omega[3][0] == pytest.approx(10.0 * r * (r + d * math.sin(phi)) / L2, rel=1e-12)
    P = construct(lk, math.radians(30.0))
    assert P.eps[3] == pytest.approx(st.eps[3][0], rel=1e-12)
    # the Coriolis vector is 2ω3·V_rel turned 90° in the sense of ω3, across the slide
    k = P.a_cor["A"]
    assert k.norm == pytest.approx(2 * abs(P.omega[3] * P.v_rel["A"]), rel=1e-12)
    assert abs(k.dot(P.slide[3])) <= 1e-12 * k.norm


def test_offset_slide_line_passes_the_pivot_at_its_offset() -> None:
    lk = parse(slotted(offset=0.05))
    P = construct(lk, 1.0)
    A, C, d = P.pos["A"], P.pos["C"], P.slide[3]
    assert (A - C).cross(d) == pytest.approx(-0.05, rel=1e-12)  # C is 0.05 to the right
    assert (A - C).dot(d) > 0


def test_the_six_bar_file_is_2013_6s_sixbar() -> None:
    lk = parse(load(Path(__file__).resolve().parents[1] / "examples" / "sixbar-2013-6.toml"))
    m = geomcad.solve("2013-6").data.mechanism
    phi = np.linspace(0.0, 2.0 * math.pi, 97)
    s, r = sweep(lk, phi), m.sweep(phi, lk.omega)
    assert np.allclose(s.pos["C"], r.C, atol=1e-13) and np.allclose(s.vel["C"], r.V_C, atol=1e-12)
    _, aB, aC = m.accelerations(phi, lk.omega)
    assert np.allclose(s.acc["B"], aB, atol=1e-11) and np.allclose(s.acc["C"], aC, atol=1e-11)
    cyc = cycle(lk)
    assert cyc is not None
    assert cyc.stroke == pytest.approx(0.2, rel=1e-9)
    assert pytest.approx(1.3, rel=1e-9) == cyc.K


def test_scotch_yoke_against_its_closed_form() -> None:
    lk = parse(load(Path(__file__).resolve().parents[1] / "examples" / "scotch-yoke.toml"))
    r, w = lk.length, lk.omega
    phi = np.linspace(0.0, 2 * math.pi, 13)
    st = sweep(lk, phi)
    assert np.allclose(st.pos["E"][:, 0], r * np.cos(phi), atol=1e-15)
    assert np.allclose(st.vel["E"][:, 0], -r * w * np.sin(phi), atol=1e-13)
    assert np.allclose(st.acc["E"][:, 0], -r * w * w * np.cos(phi), atol=1e-12)
    cyc = cycle(lk)
    assert cyc is not None and cyc.stroke == pytest.approx(2 * r) and pytest.approx(1.0) == cyc.K


def test_slider_crank_piston_velocity_closed_form() -> None:
    lk = parse(load(Path(__file__).resolve().parents[1] / "examples" / "slider-crank.toml"))
    r, L, w = 0.08, 0.30, lk.omega
    phi = np.linspace(0.05, 6.2, 17)
    st = sweep(lk, phi)
    beta = np.arcsin(r * np.sin(phi) / L)
    v = -r * w * np.sin(phi + beta) / np.cos(beta)
    assert np.allclose(st.vel["B"][:, 0], v, atol=1e-12)


def test_numbering_starts_the_working_stroke_in_the_crank_s_sense() -> None:
    data = load(Path(__file__).resolve().parents[1] / "examples" / "slider-crank.toml")
    lk = parse(data)
    s = solve(lk)
    # backward working stroke: position 0 at the right extreme (s_max), the piston then moves back
    assert s.positions[0].pos["B"].x == pytest.approx(0.38, rel=1e-12)
    steps = [(b.phi - a.phi) % (2 * math.pi) for a, b in itertools.pairwise(s.positions)]
    assert steps == pytest.approx([math.radians(30.0)] * 11)
    data["drive"]["omega"] = -50.0
    s2 = solve(parse(data))
    steps = [(a.phi - b.phi) % (2 * math.pi) for a, b in itertools.pairwise(s2.positions)]
    assert steps == pytest.approx([math.radians(30.0)] * 11)


def test_assembly_modes_mirror_the_joint() -> None:
    data = load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml")
    left = construct(parse(data), 1.0)
    data["group"][0]["assembly"] = "right"
    right = construct(parse(data), 1.0)
    A, C = left.pos["A"], left.pos["C"]
    assert (C - A).cross(left.pos["B"] - A) > 0 > (C - A).cross(right.pos["B"] - A)
    # B and its mirror image are symmetric about AC
    mid = (left.pos["B"] + right.pos["B"]) * 0.5
    assert abs((C - A).cross(mid - A)) <= 1e-12


def test_coupler_point_image_is_similar_to_the_link() -> None:
    lk = parse(load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml"))
    P = construct(lk, 0.7)
    A, B, M = P.pos["A"], P.pos["B"], P.pos["M"]
    for plan in (P.vp, P.ap):
        a, b, m = plan["a"], plan["b"], plan["m"]
        z = complex(*(m - a)) / complex(*(b - a))
        Z = complex(*(M - A)) / complex(*(B - A))
        assert abs(z - Z) <= 1e-9 * abs(Z)


def test_structure_and_mobility() -> None:
    lk = parse(load(Path(__file__).resolve().parents[1] / "examples" / "shaper.toml"))
    s = solve(lk)
    assert s.W == 1
    assert (s.scheme.n, s.scheme.p5) == (5, 7)


def test_set_edits_the_file_by_dotted_keys(tmp_path: Path) -> None:
    path = str(Path(__file__).resolve().parents[1] / "examples" / "scotch-yoke.toml")
    a = documents.solve(path).results["positions"][1]
    b = documents.solve(path, [("drive.omega", "60")]).results["positions"][1]
    assert b["V_E"] == pytest.approx(2 * a["V_E"], rel=1e-12)
    with pytest.raises(GeomcadError, match="items 1 … 1"):
        documents.solve(path, [("group.2.slot_angle", "80")])


BAD: list[tuple[str, Any, str]] = [
    ("group.0.kind", "RRX", "group 1: kind must be one of RRR, RRP, RPR, PRP"),
    ("group.0.ends", ["A", "Q"], 'group 1: ends: point "Q" is not known yet'),
    ("group.0.lengths", [0.28, -1.0], "group 1: lengths.2: must be ≥ 1e-06 m, not -1"),
    ("group.0.assembly", "up", "group 1: assembly: must be one of 'left', 'right'"),
    ("group.0.lenghts", [1, 2], "did you mean 'lengths'"),
    ("drive.omega", 0.0, "drive.omega: |ω1| must be 1e-06 … 100000 rad/s"),
    ("drive.pivot", "X", 'drive.pivot: point "X" is not a [frame] point'),
    ("frame.C", [0.3], "frame.C: must be a point [x, y]"),
    ("colour", "red", "colour: unknown key"),
]


@pytest.mark.parametrize(("key", "value", "words"), BAD, ids=[b[0] for b in BAD])
def test_bad_files_name_their_key(key: str, value: Any, words: str) -> None:
    data = copy.deepcopy(load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml"))
    node: Any = data
    parts = key.split(".")
    for p in parts[:-1]:
        node = node[int(p)] if isinstance(node, list) else node[p]
    node[parts[-1]] = value
    with pytest.raises(FileKeyError) as exc:
        parse(data)
    assert words in str(exc.value)


def test_a_group_that_cannot_close_names_the_group_and_the_angle() -> None:
    data = load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml")
    data["group"][0]["lengths"] = [0.1, 0.1]
    with pytest.raises(NoIntersection, match=r"group 1: B = circle.*at the crank angle φ = "):
        solve(parse(data))


def test_cli_solve_json_and_bad_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = str(Path(__file__).resolve().parents[1] / "examples" / "shaper.toml")
    assert main(["solve", path, "--json", "--set", "drive.positions=6"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["id"] == path and out["results"]["W"] == 1
    assert len(out["results"]["positions"]) == 6
    first = out["results"]["positions"][0]
    assert {"phi_deg", "x_D", "V_D", "a_D_y", "omega_3", "eps_3", "V_rel_A", "a_cor_A"} <= set(
        first
    )
    bad = tmp_path / "bad.toml"
    bad.write_text('[frame]\nO = [0, 0]\n[drive]\npivot = "O"\n', encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and "drive.joint" in err[0]
    bad.write_text("[frame\n", encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    assert "is not valid TOML" in capsys.readouterr().err
    assert main(["solve", str(tmp_path / "none.toml")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_cli_trace_shows_the_plans(capsys: pytest.CaptureFixture[str]) -> None:
    path = str(Path(__file__).resolve().parents[1] / "examples" / "rocking-slider.toml")
    assert main(["solve", path, "--trace", "--set", "drive.positions=1"]) == 0
    out = capsys.readouterr().out
    assert "d3 = " in out and "k_D'" in out and "a^k = 2ω3 × V_rel" in out


@pytest.mark.parametrize(("name", "fmt"), [("shaper", "A1"), ("four-bar", "A1")])
def test_kinematic_sheet_layout(name: str, fmt: str) -> None:
    """The format by content: the shaper's twelve positions need A1 for its crank at 30 mm
    and its plans' pa at 40 mm; so do the four-bar's (its ``phi`` chooses the acceleration
    plans, the twelve numbered positions are drawn all the same)."""
    sol = documents.solve(str(Path(__file__).resolve().parents[1] / "examples" / f"{name}.toml"))
    sheets = sol.sheets()
    assert sheets[0][0] == ""
    assert sheets[0][1].format == fmt
    for _, sheet in sheets:
        # the forces and dynamics sheets take the format their own content needs (the
        # shaper's dynamics fit A2 once a long title is broken within its box), never larger
        assert sheet.format in ("A2", fmt)
        assert layout_problems(sheet) == []
    assert set(sol.scales) == {"l", "v", "a"}


def test_a_file_asks_for_its_sheets_format(tmp_path: Path) -> None:
    from geomcad.errors import ParameterError

    data = load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml")
    data["sheet"] = {"format": "A1"}
    sheets = documents.from_data("four-bar.toml", data).solve().sheets()
    assert [sh.format for _, sh in sheets] == ["A1"]
    data["sheet"] = {"format": "B5"}
    with pytest.raises(ParameterError, match=r"sheet\.format"):
        documents.from_data("four-bar.toml", data).solve().sheets()


def test_verify_reads_a_plan_vector_at_its_scale(capsys: pytest.CaptureFixture[str]) -> None:
    path = str(Path(__file__).resolve().parents[1] / "examples" / "slider-crank.toml")
    sol = documents.solve(path)
    v = sol.results["positions"][3]["V_B"]
    assert main(["verify", path, "--measured", f"positions.3.V_B={v * 1.001}", "--json"]) == 0
    item = json.loads(capsys.readouterr().out)["items"][0]
    assert item["ok"] and item["precision"] == pytest.approx(0.5 * sol.scales["v"])


def test_a_guide_must_lie_on_a_link_placed_before() -> None:
    data = load(Path(__file__).resolve().parents[1] / "examples" / "rocking-slider.toml")
    data["group"][1]["guide"]["link"] = 7
    with pytest.raises(FileKeyError, match="group 2: guide: link: 7 is not a link placed before"):
        parse(data)
    data["group"][1]["guide"] = {"link": 2, "from": "A", "toward": "C"}
    with pytest.raises(FileKeyError, match='toward: point "C" is not a point of link 2'):
        parse(data)


def test_lower_case_point_names_keep_their_plan_points_apart() -> None:
    data = load(Path(__file__).resolve().parents[1] / "examples" / "four-bar.toml")
    data["group"][0]["joint"] = "b"
    data["point"][0]["toward"] = "b"
    P = construct(parse(data), 1.0)
    # the mechanism's b is imaged as b of its link (b₃), apart from the plan point b
    assert "b" in P.pos and P.pn("b") == "b3" and "b3" in P.vp.points
    assert P.vp.label_of("b3") == "V_{b}"


@pytest.mark.parametrize("name", ["shaper", "scotch-yoke"])
def test_animate_a_linkage_file(name: str, tmp_path: Path) -> None:
    import xml.etree.ElementTree as ET

    path = str(Path(__file__).resolve().parents[1] / "examples" / f"{name}.toml")
    assert main(["animate", path, "--out", str(tmp_path), "--frames", "12"]) == 0
    svg = tmp_path / f"{name}-animated.svg"
    root = ET.parse(svg).getroot()
    assert root.tag.endswith("svg")
    frames = documents.load(path).solve()
    m = frames.problem.motion
    assert m is not None
    fr = m(frames, 12)
    assert fr.frames == 12
    # the crank keeps its length in every frame
    lk = frames.data.linkage
    r = fr.points[lk.joint] - fr.points[lk.pivot]
    assert np.allclose(np.hypot(r[:, 0], r[:, 1]), lk.length, rtol=1e-12)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_the_file_s_groups_are_the_assur_groups_of_its_scheme(path: Path) -> None:
    """geomcad.structure decomposes the scheme the file builds into the file's own groups."""
    from geomcad.structure import assur_groups

    s = solve(parse(load(path)))
    dec = assur_groups(s.scheme, ["1"])
    assert [tuple(int(i) for i in g.links) for g in dec.groups] == [
        g.links for g in s.linkage.groups
    ]
    assert all(g.group_class == 2 and g.order == 2 for g in dec.groups)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_every_plan_vector_joins_its_points_and_the_plans_close(path: Path) -> None:
    """Each recorded plan vector is head − tail, and each absolute vector from the pole equals
    the sum of the known and found vectors along its vector equation (the polygon closes)."""
    lk = parse(load(path))
    P = construct(lk, 0.9)
    for plan in (P.vp, P.ap):
        for v in plan.vectors:
            step = P.c[v.step]
            assert step == plan.points[v.head] - plan.points[v.tail]
        for line in plan.lines:  # each solved point lies on both of its lines
            solved = line.step.rsplit(":", 1)[0]
            q = plan.points[solved]
            assert abs(line.line.side(q)) <= 1e-9 * max(1.0, q.norm)
    for g in lk.groups:
        if g.kind == "RRR":  # V_B = V_A + V_BA and a_B = a_A + a^n_BA + a^τ_BA
            e, j = plan_points(P, g.ends[0]), plan_points(P, g.joint)
            vb = P.vp[e] + P.vp.between(e, j)
            assert vb == P.vel[g.joint]
            n = f"n_{g.joint}{g.ends[0]}"
            ab = P.ap[e] + P.ap.between(e, n) + P.ap.between(n, j)
            assert (ab - P.acc[g.joint]).norm <= 1e-12 * max(1.0, ab.norm)


def plan_points(P: Any, name: str) -> str:
    return P.pn(name)


# Unusual but valid files: a guide on the crank, an RPR pivoting on a moving joint with offset,
# a slanted PRP, a group attached through an along = 0 point of another link.
ODD: dict[str, dict[str, Any]] = {
    "guide_on_crank": {
        "frame": {"O": [0, 0], "C": [0.25, 0.05]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.1, "omega": -7, "positions": 8},
        "group": [
            {
                "kind": "RRP",
                "links": [2, 3],
                "joint": "D",
                "end": "C",
                "length": 0.3,
                "guide": {"link": 1, "from": "O", "toward": "A", "offset": 0.02},
                "assembly": "forward",
            }
        ],
    },
    "moving_rpr_pivot": {
        "frame": {"O": [0, 0], "C": [0.3, 0.0]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.08, "omega": 5, "phi": [10, 100, 200]},
        "group": [
            {
                "kind": "RRR",
                "links": [2, 3],
                "joint": "B",
                "ends": ["A", "C"],
                "lengths": [0.3, 0.2],
                "assembly": "right",
            },
            {"kind": "RPR", "links": [4, 5], "slider": "M", "pivot": "B", "offset": 0.03},
        ],
        "point": [{"name": "M", "link": 2, "from": "A", "toward": "B", "along": 0.1, "left": 0.02}],
    },
    "slanted_prp": {
        "frame": {"O": [0, 0]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.05, "omega": 12, "positions": 6},
        "group": [
            {
                "kind": "PRP",
                "links": [2, 3],
                "slider": "A",
                "slot_angle": 60,
                "guide": {"through": [0.01, -0.02], "angle": 30},
                "point": "E",
            }
        ],
        "point": [
            {"name": "F", "link": 3, "from": "E", "toward": "A", "along": 0.05, "left": 0.01}
        ],
    },
    "attach_via_point": {
        "frame": {"O": [0, 0], "C": [0.3, 0.0], "G": [0.1, 0.35]},
        "drive": {
            "pivot": "O",
            "joint": "A",
            "length": 0.08,
            "omega": 10,
            "positions": 12,
            "output": "H",
        },
        "group": [
            {
                "kind": "RRR",
                "links": [2, 3],
                "joint": "B",
                "ends": ["A", "C"],
                "lengths": [0.3, 0.22],
                "assembly": "left",
            },
            {
                "kind": "RRR",
                "links": [4, 5],
                "joint": "H",
                "ends": ["K", "G"],
                "lengths": [0.2, 0.25],
                "assembly": "left",
            },
        ],
        "point": [{"name": "K", "link": 2, "from": "A", "toward": "B", "along": 0.0}],
    },
}


@pytest.mark.parametrize("name", list(ODD))
def test_unusual_files_plans_sweep_and_derivatives_agree(name: str) -> None:
    lk = parse(copy.deepcopy(ODD[name]))
    s = solve(lk)
    st = sweep(lk, [P.phi for P in s.positions])
    w, L = lk.omega, lk.length
    for i, P in enumerate(s.positions):
        for n in moving_points(lk):
            assert np.allclose(P.vel[n].array(), st.vel[n][i], rtol=0, atol=1e-12 * abs(w) * L)
            assert np.allclose(P.acc[n].array(), st.acc[n][i], rtol=0, atol=1e-12 * w * w * L)
    phi, h = np.linspace(0.3, 6.5, 17), 1e-4
    a = sweep(lk, phi)
    pm, p0, pp = (sweep(lk, phi + k * h, order=0) for k in (-1.0, 0.0, 1.0))
    for n in moving_points(lk):
        dv = (pp.pos[n] - pm.pos[n]) / (2 * h) * w
        da = (pp.pos[n] - 2 * p0.pos[n] + pm.pos[n]) / (h * h) * w * w
        assert np.allclose(a.vel[n], dv, rtol=0, atol=1e-6 * abs(w) * L)
        assert np.allclose(a.acc[n], da, rtol=0, atol=1e-5 * w * w * L)


def test_slanted_prp_stroke() -> None:
    cyc = cycle(parse(copy.deepcopy(ODD["slanted_prp"])))
    assert cyc is not None
    assert cyc.stroke == pytest.approx(2 * 0.05 / math.sin(math.radians(60.0)), rel=1e-12)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_the_output_diagrams_exact_curves_are_the_derivatives_of_s(path: Path) -> None:
    """The kinematic sheet's exact v and a (or ω and ε) of the output are ds/dt and dv/dt of its
    exact coordinate, for every example (a PRP yoke's velocity was taken across its slot: 0)."""
    from geomcad.sheet.linkage import _output_curves

    s = documents.solve(str(path)).data
    psi = np.linspace(0.0, 2.0 * math.pi, 4001)
    _names, s_m, v_m, a_m = _output_curves(s, psi)
    w = abs(s.linkage.omega)
    inner = slice(2, -2)
    for y, dy in ((s_m, v_m), (v_m, a_m)):
        num = np.gradient(y, psi) * w
        assert float(np.abs(dy).max()) > 0.0
        assert np.allclose(num[inner], dy[inner], atol=1e-3 * float(np.abs(dy).max()))


COUPLER_P = """
title = "crank-rocker, coupler point P"
[frame]
O = [0.0, 0.0]
D = [0.42, 0.05]
[drive]
pivot = "O"
joint = "A"
length = 0.11
omega = -15.0
phi = [40.0]
[[group]]
kind = "RRR"
links = [2, 3]
joint = "B"
ends = ["A", "D"]
lengths = [0.38, 0.30]
[[point]]
name = "P"
link = 2
from = "A"
toward = "B"
along = 0.20
left = 0.10
"""


def test_a_point_named_like_the_pole_is_imaged_by_its_link_not_p_p() -> None:
    """The image of P cannot be "p" (the pole): it is p with its link's number (p₂ on the
    velocity plan, p₂′ on the acceleration plan), the step saying whose image it is, never
    "p_P" beside the pole; other points keep their own lower-case letters."""
    from geomcad.linkage.plans import plan_name
    from geomcad.sheet.views import step_text

    assert plan_name("B") == "b" and plan_name("P", frozenset({"P"}), 2) == "p2"
    assert plan_name("P", frozenset({"P", "P2"}), 2) == "p_P"  # p2 is another point's letter
    lk = parse(tomllib.loads(COUPLER_P))
    P = construct(lk, math.radians(40.0))
    assert "p2" in P.vp.points and "p2'" in P.ap.points and "p_P" not in P.vp.points
    assert P.vp.label_of("p2") == "V_{P}"
    steps = {s.name: s for s in P.c.steps}
    for name in ("p2", "p2'"):
        s = steps[name]
        assert s.kind == "plan_image_own"
        text = step_text(s)
        assert "P" in text and "2" in text and "ABP" in text
    assert P.vel["P"] == P.vp.points["p2"]
