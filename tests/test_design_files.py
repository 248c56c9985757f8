"""Cam and gear design files (examples/*.toml): each number against an independent computation
(closed forms on dense grids, the cam library's own pressure angle, the rack generation, Willis),
and bad input as one error line naming the step, through the CLI."""

from __future__ import annotations

import collections
import functools
import math
from fractions import Fraction
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from geomcad import documents
from geomcad.cli import main
from geomcad.kinematics import cam_design as cd
from geomcad.kinematics.cams import Follower, cam_profile, pressure_angle_max
from geomcad.kinematics.gears import SpurGear, inv
from geomcad.kinematics.motion_laws import CamProgram, Phase
from geomcad.problem import Solution
from geomcad.sheet import Scale

EX = Path(__file__).resolve().parent.parent / "examples"
ALL = ["cam-translating-roller", "cam-rocking-roller", "cam-flat", "gear-pair", "planetary"]


@functools.cache
def solution(name: str, *sets: tuple[str, str]) -> Solution:
    return documents.solve(str(EX / f"{name}.toml"), list(sets))


def solve(name: str, *sets: tuple[str, str]) -> dict[str, object]:
    return solution(name, *sets).results


def program(phases: list[tuple[str, float, str]], H: float) -> CamProgram:
    return CamProgram.of(
        H,
        [Phase(k, math.radians(a), law) for k, a, law in phases],  # type: ignore[arg-type]
    ).full_turn()


# -- cams ------------------------------------------------------------------------------------------

TRANS = [("rise", 120.0, "cycloidal"), ("dwell", 40.0, "linear"), ("return", 100.0, "poly345")]


def test_translating_roller_centre_is_on_the_allowed_pressure_angles() -> None:
    r = solve("cam-translating-roller")
    prog = program(TRANS, 0.03)
    # at r0_min and e the cam library's own pressure angle reaches 30° on the rise, 45° back
    s0 = math.sqrt(float(r["r0_min"]) ** 2 - float(r["e"]) ** 2)  # type: ignore[arg-type]
    phi = np.linspace(0.0, 2.0 * math.pi, 400001)
    m = prog.motion(phi)
    a = np.degrees(np.arctan2(m.S1 - float(r["e"]), s0 + m.S))  # type: ignore[arg-type]
    back = (phi > math.radians(160)) & (phi < math.radians(260))
    assert np.max(np.abs(a[~back])) == pytest.approx(30.0, abs=1e-6)
    assert np.max(np.abs(a[back])) == pytest.approx(45.0, abs=1e-6)
    # no centre nearer B0 keeps both: a grid of offsets, each at the least s0 it allows
    t30, t45 = math.tan(math.radians(30)), math.tan(math.radians(45))
    best = math.inf
    phi = np.linspace(0.0, 2.0 * math.pi, 20001)
    m = prog.motion(phi)
    back = (phi > math.radians(160)) & (phi < math.radians(260))
    for e in np.linspace(-0.01, 0.01, 2001):
        need = np.where(back, np.abs(m.S1 - e) / t45, np.abs(m.S1 - e) / t30) - m.S
        best = min(best, math.hypot(e, float(np.max(need))))
    assert float(r["r0_min"]) <= best + 1e-9  # type: ignore[arg-type]
    assert best - float(r["r0_min"]) < 2e-5  # type: ignore[arg-type]
    assert r["r0"] == pytest.approx(0.027)
    # the built cam (r0 rounded up): the library's pressure angle stays within the allowed ones
    assert float(r["pressure_angle_max_rise_deg"]) <= 30.0  # type: ignore[arg-type]
    assert float(r["pressure_angle_max_deg"]) <= 45.0  # type: ignore[arg-type]
    f = Follower("roller", 0.027, float(r["e"]), float(r["r_roller"]), 1)  # type: ignore[arg-type]
    prof = cam_profile(prog, f, closed=True)
    assert math.degrees(pressure_angle_max(prog, prof)) == pytest.approx(
        float(r["pressure_angle_max_deg"]),
        abs=1e-6,  # type: ignore[arg-type]
    )
    assert float(r["r_roller"]) < float(r["rho_pitch_min"])  # type: ignore[arg-type]


def test_central_follower_r0_min_is_the_closed_form() -> None:
    r = solve("cam-translating-roller", ("cam.offset", "0"))
    H, rise = 0.03, math.radians(120)
    u = np.linspace(0.0, 1.0, 200001)
    S = H * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    S1 = H / rise * (1 - np.cos(2 * np.pi * u))
    need_rise = np.max(S1 / math.tan(math.radians(30)) - S)
    ret = math.radians(100)
    S_r = H * (1 - (10 * u**3 - 15 * u**4 + 6 * u**5))
    S1_r = -H / ret * 30 * u**2 * (1 - u) ** 2
    need_ret = np.max(np.abs(S1_r) / math.tan(math.radians(45)) - S_r)
    assert r["e"] == 0.0
    assert r["r0_min"] == pytest.approx(max(need_rise, need_ret), rel=1e-8)


def test_rocking_roller_is_on_the_allowed_angle_and_no_nearer_centre_is() -> None:
    r = solve("cam-rocking-roller")
    prog = program(
        [("rise", 110.0, "poly345"), ("dwell", 30.0, "linear"),
         ("return", 110.0, "modified_trapezoid")],
        math.radians(20),
    )  # fmt: skip
    geom = cd.RockerGeometry(0.1, math.radians(20), -1)
    zone = cd.rocker_zone(prog, geom, math.radians(35), math.radians(45))
    O = np.array(zone.nearest())  # noqa: E741
    assert float(np.hypot(*O)) == pytest.approx(float(r["r0_min"]), rel=1e-12)  # type: ignore[arg-type]
    phi = np.linspace(0.0, 2.0 * math.pi, 50001)
    back = (phi > math.radians(140)) & (phi < math.radians(250))

    def worst(q: np.ndarray) -> tuple[float, float]:
        a = np.degrees(cd.rocker_pressure(prog, geom.A - q, 0.1, math.radians(20), -1, phi))
        return float(np.max(a[~back])), float(np.max(a[back]))

    rise, ret = worst(O)
    assert max(rise - 35.0, ret - 45.0) == pytest.approx(0.0, abs=1e-3)
    assert rise <= 35.0 + 1e-3 and ret <= 45.0 + 1e-3
    # a centre 0.2 % nearer B0, in any direction, breaks an allowed angle
    for ang in np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False):
        q = O * 0.998 + 0.0 * ang
        q = q + 0.0005 * float(np.hypot(*O)) * np.array([math.cos(ang), math.sin(ang)])
        if np.hypot(*q) < np.hypot(*O) * 0.999:
            rr, rt = worst(q)
            assert rr > 35.0 or rt > 45.0
    assert r["r0"] == pytest.approx(0.028)
    assert float(r["pressure_angle_max_rise_deg"]) <= 35.0  # type: ignore[arg-type]
    assert float(r["pressure_angle_max_return_deg"]) <= 45.0  # type: ignore[arg-type]


def test_rocker_with_a_given_pivot_distance_keeps_it() -> None:
    r = solve("cam-rocking-roller", ("cam.pivot_distance", "0.12"))
    assert r["a_w"] == pytest.approx(0.12, rel=1e-12)
    assert float(r["r0"]) >= float(r["r0_min"])  # type: ignore[arg-type]
    assert float(r["pressure_angle_max_rise_deg"]) <= 35.0  # type: ignore[arg-type]


def test_flat_face_r0_min_is_the_convexity_closed_form() -> None:
    r = solve("cam-flat")
    H, rise, ret = 0.02, math.radians(90), math.radians(90)
    u = np.linspace(0.0, 1.0, 200001)
    rise_v = H * (1 - np.cos(np.pi * u)) / 2 + H * np.pi**2 / (2 * rise**2) * np.cos(np.pi * u)
    tu = 2 * np.pi * u
    ret_v = H * (1 - (u - np.sin(tu) / (2 * np.pi))) - H / ret**2 * 2 * np.pi * np.sin(tu)
    r0_min = 0.005 - min(float(np.min(rise_v)), float(np.min(ret_v)), 0.0)
    assert r["r0_min"] == pytest.approx(r0_min, rel=1e-9)
    assert r["r0"] == pytest.approx(math.ceil(r0_min * 1000) / 1000)
    # the built profile's smallest radius of curvature: r0 − r0_min + ρ_allowed
    assert r["rho_min"] == pytest.approx(float(r["r0"]) - r0_min + 0.005, rel=1e-6)  # type: ignore[arg-type]
    assert r["pressure_angle_max_deg"] == 0.0


# -- gears -----------------------------------------------------------------------------------------


def test_gear_pair_by_gost_16532_against_independent_forms() -> None:
    r = solve("gear-pair")
    z1, z2, m = 12, 30, 0.005
    x1, x2 = float(r["x1"]), float(r["x2"])  # type: ignore[arg-type]
    al = math.radians(20)
    aw = math.radians(float(r["alpha_w_deg"]))  # type: ignore[arg-type]
    a_w = float(r["a_w"])  # type: ignore[arg-type]
    # zero backlash on the rolling circles, by the involute thickness of each wheel
    g1, g2 = SpurGear(m, z1, x1), SpurGear(m, z2, x2)
    d_w1, d_w2 = 2 * a_w * z1 / (z1 + z2), 2 * a_w * z2 / (z1 + z2)
    assert g1.thickness(d_w1) + g2.thickness(d_w2) == pytest.approx(math.pi * d_w1 / z1, rel=1e-9)
    assert a_w * math.cos(aw) == pytest.approx(m * (z1 + z2) / 2 * math.cos(al), rel=1e-12)
    dy = x1 + x2 - (a_w - m * (z1 + z2) / 2) / m
    assert r["d_a1"] == pytest.approx(m * (z1 + 2 + 2 * x1 - 2 * dy), rel=1e-12)
    assert r["d_a2"] == pytest.approx(m * (z2 + 2 + 2 * x2 - 2 * dy), rel=1e-12)
    # s_a off the rack-generated tooth: its tip corner's half-angle times d_a
    for d_a, x, z, key in ((r["d_a1"], x1, z1, "s_a1"), (r["d_a2"], x2, z2, "s_a2")):
        g = SpurGear(m, z, x, d_a=float(d_a))  # type: ignore[arg-type]
        assert float(d_a) * g.flank(50).tip_to == pytest.approx(float(r[key]), rel=1e-9)  # type: ignore[arg-type]
    ta = [
        math.tan(math.acos(m * z * math.cos(al) / float(d)))  # type: ignore[arg-type]
        for z, d in ((z1, r["d_a1"]), (z2, r["d_a2"]))
    ]
    eps = (z1 * ta[0] + z2 * ta[1] - (z1 + z2) * math.tan(aw)) / (2 * math.pi)
    assert r["eps_alpha"] == pytest.approx(eps, rel=1e-12)
    assert r["eps_alpha_drawn"] == pytest.approx(eps, rel=1e-4)
    assert r["lambda1_max"] == pytest.approx(r["lambda2_max"], rel=1e-9)
    assert x1 + x2 == pytest.approx((17 - 12) / 17, rel=1e-12)
    assert inv(aw) == pytest.approx(2 * (x1 + x2) * math.tan(al) / (z1 + z2) + inv(al), rel=1e-12)


def test_shift_rules() -> None:
    r = solve("gear-pair", ("gears.pair.shift", "no_undercut"))
    assert (r["x1"], r["x2"]) == (pytest.approx(5 / 17), 0.0)
    r = solve("gear-pair", ("gears.pair.shift", "max_contact_ratio"))
    base = solve("gear-pair", ("gears.pair.shift", "no_undercut"))
    assert float(r["eps_alpha"]) >= float(base["eps_alpha"])  # type: ignore[arg-type]
    assert float(r["x1"]) >= 5 / 17 - 1e-9 and float(r["x2"]) >= -13 / 17 - 1e-9  # type: ignore[arg-type]
    assert float(r["s_a1"]) >= 0.25 * 0.005 - 1e-12  # type: ignore[arg-type]


def test_planetary_tooth_numbers() -> None:
    r = solve("planetary")
    z1, z2, z3, z4 = r["z"]  # type: ignore[misc]
    assert z1 + z2 == z4 - z3  # coaxiality
    u = 1 + Fraction(z2 * z4, z1 * z3)  # Willis: u_1H = 1 − u_14^(H)
    assert r["u"] == pytest.approx(float(u), rel=1e-15)
    assert r["u_error"] == pytest.approx((float(u) - 12.5) / 12.5, rel=1e-12)
    assert abs(float(r["u_error"])) <= 0.02  # type: ignore[arg-type]
    assert (z2 + z1) * math.sin(math.pi / 3) > max(z2, z3) + 2  # neighbours
    assert min(z1, z2, z3) >= 17


def test_planetary_scheme_a_is_the_smallest_by_brute_force() -> None:
    r = solve("planetary", ("gears.planetary.scheme", "A"), ("gears.planetary.ratio", "5.6"))
    z1, z2, z3 = r["z"]  # type: ignore[misc]
    smallest = min(
        c
        for a in range(17, 60)
        for b in range(17, 60)
        for c in [a + 2 * b]
        if abs(1 + c / a - 5.6) <= 0.02 * 5.6
        and (a + c) % 3 == 0
        and (a + b) * math.sin(math.pi / 3) > b + 2
    )
    assert z3 == smallest == z1 + 2 * z2


@pytest.mark.parametrize(("scheme", "u"), [("C", 40.0), ("D", -30.0)])
def test_planetary_schemes_with_the_carrier_driving(scheme: str, u: float) -> None:
    r = solve("planetary", ("gears.planetary.scheme", scheme), ("gears.planetary.ratio", str(u)))
    z1, z2, z3, z4 = r["z"]  # type: ignore[misc]
    if scheme == "C":
        assert z1 + z2 == z4 + z3
        two_a = z1 + z2
    else:
        assert z1 - z2 == z4 - z3 and z1 - z2 >= 8 and z4 - z3 >= 8
        two_a = z1 - z2
    # u_H1 = 1/u_1H^(4), u_1H^(4) = 1 − u_14^(H), u_14^(H) = (∓z2/z1)(∓z4/z3)
    exact = 1 / (1 - Fraction(z2 * z4, z1 * z3))
    assert r["u"] == pytest.approx(float(exact), rel=1e-15)
    assert abs(float(exact) - u) <= 0.02 * abs(u)
    assert two_a * math.sin(math.pi / 3) > max(z2, z3) + 2


# -- bad input through the CLI ---------------------------------------------------------------------

BAD = [
    ("cam-translating-roller", "cam.pressure_angle_deg=95", "pressure_angle_deg"),
    ("cam-translating-roller", "cam.r0=0.02", "r0 = r0_min"),
    ("cam-translating-roller", "cam.roller_radius=0.03", "phase 1"),
    ("cam-rocking-roller", "cam.pressure_angle_deg=8", "zone"),
    ("cam-flat", "cam.phases.1.law=linear", "envelope of the face lines"),
    ("cam-flat", "cam.stroke=-1", "cam.stroke"),
    ("gear-pair", "gears.pair.shift=max", "gears.pair.shift"),
    ("planetary", "gears.planetary.ratio=200", "tooth numbers"),
]


@pytest.mark.parametrize(("name", "setting", "words"), BAD)
def test_bad_input_is_one_error_line(
    capsys: pytest.CaptureFixture[str], name: str, setting: str, words: str
) -> None:
    code = main(["solve", str(EX / f"{name}.toml"), "--set", setting])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert words in lines[0], err


def test_pointed_teeth_are_refused(capsys: pytest.CaptureFixture[str]) -> None:
    sets = ["gears.pair.shift=given", "gears.pair.x1=1.2", "gears.pair.x2=0"]
    argv = ["solve", str(EX / "gear-pair.toml")]
    for s in sets:
        argv += ["--set", s]
    code = main(argv)
    _, err = capsys.readouterr()
    assert code == 2 and "pointed" in err and "tip thickness" in err


# -- sheets ----------------------------------------------------------------------------------------


#: The drafting findings (tests/layout.py) each composed sheet may still have; a count may only
#: fall. The rocker: '19' 7.5 mm off its point, where the dwell's division points crowd at 1:1.
FINDINGS = {
    "cam-translating-roller": {"empty": 1},
    "cam-rocking-roller": {"anchor": 1, "empty": 1},
    "cam-flat": {"empty": 1},
    "gear-pair": {},
    "planetary": {"empty": 1},
}

#: The format each sheet takes by its content (geomcad.sheet.formats): the smallest on which the
#: cam's profile and diagram reach 1:1, the mesh's teeth 40 mm, the train's sun 15 mm across.
FORMAT = {
    "cam-translating-roller": (594.0, 420.0),  # A2: profile 2:1
    "cam-rocking-roller": (594.0, 420.0),  # A2: profile 1:1 (the pivot's circle 206 mm across)
    "cam-flat": (594.0, 420.0),  # A2: profile 2:1
    "gear-pair": (841.0, 594.0),  # A1: the mesh at 4:1 (m = 5 mm)
    "planetary": (420.0, 297.0),  # A3: the scheme at 1:2
}


@pytest.mark.parametrize("name", ALL)
def test_sheets_pass_the_layout_checker(name: str) -> None:
    from layout import findings, layout_problems

    sheets = solution(name).sheets()
    assert sheets
    for _, sheet in sheets:
        assert (sheet.width, sheet.height) == FORMAT[name]
        assert layout_problems(sheet) == []
        found = collections.Counter(f.kind for f in findings(sheet))
        grown = {k: n for k, n in found.items() if n > FINDINGS[name].get(k, 0)}
        assert not grown, (grown, findings(sheet))


def test_the_format_is_the_smallest_that_reaches_the_subjects_scale() -> None:
    """A cam sheet on the smallest format where its profile and diagram reach 1:1: every
    smaller candidate fails (a view under 1:1 or something overflowing), and the views grow on
    the format taken; a format the file asks for is the only one tried."""
    from geomcad.files import cam_sheets as sheets_cam
    from geomcad.files import common as file_common
    from geomcad.sheet import formats
    from geomcad.sheet.compose import Field, arrange

    sol = solution("cam-flat")
    tree, profile, diagram, got = sheets_cam._sized(sol)  # the arrangement the sheet drew
    wants = {profile: sheets_cam.WANT_K, diagram: sheets_cam.WANT_K}
    assert (got.fmt, got.landscape) == ("A2", True)
    assert formats.meets(got.layout, wants) and got.layout.fits
    assert got.layout[profile].scale.k < sheets_cam.WANT_K  # type: ignore[union-attr]  # 2:1
    for fmt, land in formats.candidates(("A4", "A3")):
        field = Field.of_format(fmt, land)
        if formats._may_fit(tree, wants, field):
            lay = arrange(tree, field)
            assert not (lay.fits and formats.meets(lay, wants)), (fmt, land)
    assert file_common.sheet_formats({"sheet": {"format": "A1"}}) == ("A1",)
    assert file_common.sheet_formats({"sheet": {"student": "x"}}) == formats.SIZES


def test_a_format_the_file_asks_for_is_checked(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["solve", str(EX / "cam-flat.toml"), "--set", "sheet.format=A7"])
    _, err = capsys.readouterr()
    assert code == 2 and err.startswith("error: ") and "sheet.format" in err and "A1" in err


def test_meshed_teeth_touch_on_the_line_of_action_and_never_overlap() -> None:
    """The drawn teeth of the two wheels (each closed to its centre) share no area, touch
    (backlash-free meshing: the pinion's middle tooth on both flanks) and the contact of the
    drawn line of action lies on it; a wheel turned by a tenth of a pitch overlaps (the check
    can fail)."""
    from shapely.geometry import MultiLineString, Polygon
    from shapely.ops import nearest_points, unary_union

    from geomcad.kinematics import gear_design as gd

    sol = solution("gear-pair")
    p, me = sol.data.pair, sol.data.meshing
    m = p.m

    def body(teeth: list[np.ndarray], centre: tuple[float, float]) -> object:
        return unary_union([Polygon([*t.tolist(), centre]) for t in teeth])

    one = body(me.teeth1, (0.0, 0.0))
    two = body(me.teeth2, (0.0, p.a_w))
    assert one.intersection(two).area < 1e-6 * m * m
    mid = me.teeth1[1]
    P = me.P
    for side in (1.0, -1.0):  # each flank of the middle tooth touches the wheel
        flank = MultiLineString([mid[mid[:, 0] * side > 0.0].tolist()])
        wheel = MultiLineString([t.tolist() for t in me.teeth2])
        assert flank.distance(wheel) < 1e-3 * m
        if side > 0.0:  # the right flank's contact is on the drawn line N1N2 (the flanks are
            # tangent there: the nearest points of the polylines find it to a few µm)
            d = np.array(nearest_points(flank, wheel)[0].coords[0]) - P
            assert abs(float(me.t[0] * d[1] - me.t[1] * d[0])) < 0.02 * m
    # gd.place turns the tooth's frame (+y) to the given angle: +y → +y turned by a tenth pitch
    turned = gd.place(
        me.teeth2[1] - [0.0, p.a_w], (0.0, p.a_w), math.pi / 2.0 + 0.2 * math.pi / p.z2
    )
    assert one.intersection(Polygon([*turned.tolist(), (0.0, p.a_w)])).area > 1e-3 * m * m


def test_gear_circles_are_thin_and_alpha_w_is_an_angle_dimension() -> None:
    """No thick tip arc across a space (it would read as the other wheel's outline crossing
    the teeth); α_w dimensioned at P; both wheels numbered with their ω."""
    from geomcad.files.gears_sheets import _mesh
    from geomcad.geom import Arc

    class Recorder:
        """A viewport that keeps the arcs, angle dimensions, labels and turns drawn."""

        def __init__(self) -> None:
            self.arcs: list[tuple[Arc, str]] = []
            self.calls: list[tuple[str, tuple[object, ...]]] = []
            self.scale = Scale(0.00025, "l")

        def arc(self, arc: Arc, role: str) -> None:
            self.arcs.append((arc, role))

        def __getattr__(self, name: str) -> object:
            return lambda *a, **k: self.calls.append((name, a))

    sol = solution("gear-pair")
    p, me = sol.data.pair, sol.data.meshing
    v = Recorder()
    _mesh(v, p, me)  # type: ignore[arg-type]
    assert v.arcs and {r for _, r in v.arcs} <= {"thin", "centre"}
    dims = [a for n, a in v.calls if n == "dim_angle"]
    assert len(dims) == 1 and "α_w" in str(dims[0][3])
    vertex, q1, q2 = (np.array([float(c.x), float(c.y)]) for c in dims[0][:3])  # type: ignore[attr-defined]
    u1, u2 = q1 - vertex, q2 - vertex
    ang = math.acos(float(u1 @ u2) / float(np.hypot(*u1) * np.hypot(*u2)))
    assert np.allclose(vertex, me.P) and ang == pytest.approx(p.alpha_w, abs=1e-12)
    labels = {str(a[1]) for n, a in v.calls if n == "label"}
    assert {"1", "2"} <= labels
    turns = sorted((str(a[3]), float(a[1])) for n, a in v.calls if n == "turn")  # type: ignore[arg-type]
    assert turns == [("ω_1", -1.0), ("ω_2", 1.0)]


def test_library_solve_takes_a_file_and_its_sheet_scales_come_from_the_sheet() -> None:
    """geomcad.solve accepts a file as the CLI does; its scales are the sheet layer's (the
    build asks no sheet module), and a file takes no parameters."""
    import geomcad

    root = Path(__file__).resolve().parent.parent / "examples"
    sol = geomcad.solve(str(root / "gear-pair.toml"))
    assert sol.problem.scales is not None
    assert sol.scales["l"] == pytest.approx(0.00025, rel=1e-12)  # the mesh at 4:1 on A1
    with pytest.raises(geomcad.ParameterError, match="is a file"):
        geomcad.solve(str(root / "cam-flat.toml"), stroke=0.02)


@pytest.mark.parametrize("name", ["cam-translating-roller", "cam-rocking-roller", "cam-flat"])
def test_cam_order_of_construction_is_the_recorded_steps(name: str) -> None:
    """The cam sheet's order of construction: one numbered item per recorded design step (by
    its kind's template), with the recorded values in the language drawn."""
    from geomcad.files import cam_sheets as sheets_cam
    from geomcad.sheet.lang import language

    sol = solution(name)
    listed = [n for n in sheets_cam.ORDER if n in sol.construction]
    assert listed[0] == "S(φ)" and listed[-1] == "profile"
    for lang, r0 in (("ru", "r_0 = {} мм"), ("en", "r_0 = {} mm")):
        with language(lang):  # type: ignore[arg-type]
            order = sheets_cam._order(sol)
        text = " ".join(order.lines)
        numbered = [t for t in order.lines if t.split(". ", 1)[0].isdigit()]
        assert len(numbered) == len(listed)
        value = f"{float(sol.results['r0']) * 1000:g}"  # type: ignore[arg-type]
        assert r0.format(value) in text


def test_every_design_file_is_its_own_document() -> None:
    """The designation (графа 2) from the file's title (its initials) or, on a sheet of the
    other script, its name (a number), one per file, in either language."""
    from geomcad.files import cam_sheets as sheets_cam
    from geomcad.files import code
    from geomcad.files import gears_sheets as sheets_gears
    from geomcad.sheet.lang import language

    for lang in ("ru", "en"):
        with language(lang):
            got = {
                n: (sheets_gears if n in ("gear-pair", "planetary") else sheets_cam).designation(
                    solution(n)
                )
                for n in ALL
            }
            codes = {n: code(n, solution(n).problem.inputs["title"]) for n in ALL}
        assert len(set(got.values())) == len(ALL)
        assert all(d.split(".")[1:-1] == codes[n].split(".") for n, d in got.items())


def test_planetary_plan_is_projected_from_the_scheme() -> None:
    """Smirnov's plan in the scheme's viewport: o, a, b, c at the heights of O, A, B, C, each
    level carried across from its point on the scheme, each link's velocity line named, the
    ray diagram's H and μ_ω written (μ_ω a round factor)."""
    from geomcad.files import gears_sheets as sg
    from geomcad.geom import Vec
    from geomcad.sheet import TitleBlock, start
    from geomcad.sheet.model import Polyline, TextItem

    sol = solution("planetary")
    des = sol.data
    pp = des.spec.planetary
    pts, link, pt = sg._plan_points(pp.scheme, des.candidates[0].z, pp.m)
    by = {q.name: q.y for q in pts}
    k = Scale(0.002, "l")
    d = start("A3", TitleBlock(title="t", designation="d"))
    v = d.viewport(k, (0.0, 0.0), (60.0, 150.0))
    spots = {q.name: Vec(0.1 + 0.01 * i, q.y) for i, q in enumerate(pts)}
    top = 0.2
    sg._plan(v, pp, pts, link, pt, by, (0.6 * top, top), 0.5, spots)
    sheet = d.finish()
    at = {it.text: xy for it, xy in sheet.anchors}
    for name, y in by.items():
        assert at[name.lower()][1] == pytest.approx(v.p(Vec(0.0, y))[1])
        level = v.p(spots[name])
        assert any(
            isinstance(it, Polyline) and it.points[0] == pytest.approx(level) for it in sheet.items
        )
    assert {"1", "2", "H"} <= set(at)
    texts = [it.text for it in sheet.items if isinstance(it, TextItem)]
    factor = next(t for t in texts if "μω" in t and "H = " in t)
    mu = float(factor.rsplit("=", 1)[1].split()[0].replace(",", "."))
    assert f"{mu:.1e}"[0] in "1245"  # μ_ω = m × 10^n, m one of 1, 2, 2.5, 4, 5


@pytest.mark.parametrize("name", ["cam-rocking-roller", "cam-translating-roller"])
def test_cam_profile_shows_omega_and_the_inversion_and_names_the_pivots(name: str) -> None:
    """ω in the cam's sense (the data table's), −ω against it; a rocker's turned pivots A_i."""
    from geomcad.files import cam_sheets as sheets_cam

    class Recorder:
        def __init__(self) -> None:
            self.calls: list[tuple[str, tuple[object, ...]]] = []
            self.scale = Scale(0.001, "l")

        def __getattr__(self, attr: str) -> object:
            return lambda *a, **k: self.calls.append((attr, a))

    sol = solution(name)
    des = sol.data
    v = Recorder()
    view = sheets_cam._profile(des)  # the sheet's view of the profile, drawn through v
    view.draw(None, SimpleNamespace(viewport=v))  # type: ignore[arg-type]
    labels = [str(a[1]) for n, a in v.calls if n == "label"]
    arrows = [a for n, a in v.calls if n == "arrow"]
    senses = []
    for tail, tip in ((a[0], a[1]) for a in arrows):
        senses.append(np.sign(tail.x * tip.y - tail.y * tip.x))  # type: ignore[attr-defined]
    named = [lab for lab in labels if lab in ("ω", "−ω")]
    assert named == ["ω", "−ω"] and senses == [des.spec.sigma, -des.spec.sigma]
    n = len(des.divisions.phi) - 1
    pivots = {f"A_{{{i}}}" for i in range(n)}
    assert (pivots <= set(labels)) == (des.spec.motion == "rocking")
    _, _, *units, _ = sheets_cam._law_values(des)
    assert "°/" not in "".join(units)  # no mixed ° and rad in the analogues' units
