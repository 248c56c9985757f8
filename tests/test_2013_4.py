"""2013-4: the seed's values, the exact values checked independently, the seed's errata, a round
trip through the caliper, the generated tooth, variants, bad input, and the sheet."""

from __future__ import annotations

import math

import pytest
from geomcad_constructions import spec_2013_4

import geomcad
from geomcad.cli import main
from geomcad.errors import ConstructionError, GeomcadError, ParameterError
from geomcad.kinematics.gears import SpurGear
from geomcad.sheet.model import ArcItem, Polyline

SEED = {"m": 0.01, "alpha_deg": 20.0, "z": 40, "d_a": 0.42, "s_chord": 0.0181, "h_chord": 0.0091}
REL = 1e-12


def independent(
    m: float, alpha_deg: float, z: int, d_a: float, s_chord: float, h_chord: float
) -> dict[str, float]:
    """The same answers from the formulas of problems.md, written out afresh."""
    a = math.radians(alpha_deg)
    d = m * z
    d_b = d * math.cos(a)
    psi = math.atan(s_chord / (d_a - 2 * h_chord))
    d_y = s_chord / math.sin(psi)
    a_y = math.acos(d_b / d_y)
    s = d * (psi + (math.tan(a_y) - a_y) - (math.tan(a) - a))
    x = (s - math.pi * m / 2) / (2 * m * math.tan(a))
    return {"d": d, "d_b": d_b, "d_y": d_y, "psi_y": psi, "alpha_y_deg": math.degrees(a_y),
            "s": s, "x": x}  # fmt: skip


def test_seed_values_within_their_precision_except_the_errata() -> None:
    sol = geomcad.solve("2013-4")
    rows = {r["name"]: r for r in sol.seed_report()}
    assert {n for n, r in rows.items() if r["class"] == "erratum"} == {"d_y", "alpha_y_deg"}
    for row in rows.values():
        if row["class"] != "erratum":
            assert row["agrees"], row
    r = sol.results
    assert abs(r["d_b"] * 1000 - 375.88) <= 0.005
    assert abs(r["psi_y"] - 0.04502) <= 0.000005
    assert abs(r["s"] * 1000 - 18.83) <= 0.005
    assert abs(r["x"] - 0.43) <= 0.005


def test_exact_values_against_the_formulas() -> None:
    r = geomcad.solve("2013-4").results
    want = independent(**SEED)
    assert set(r) == set(want)
    for name, value in want.items():
        assert r[name] == pytest.approx(value, rel=REL), name
    assert r["d_y"] == pytest.approx(0.4022074713378656, rel=REL)
    assert r["alpha_y_deg"] == pytest.approx(20.846813960509067, rel=REL)
    assert r["s"] == pytest.approx(0.018826616006394556, rel=1e-11)
    assert r["x"] == pytest.approx(0.42842139889997904, rel=1e-11)


def test_seed_erratum_the_half_angular_thickness_formula_is_garbled() -> None:
    """The seed prints tan φ_y/2 over (d_a − 2h̄) = 18,1/(420 − 2·9,1). Read literally that makes
    tan(φ_y/2) = 18,1 and φ_y ≈ 173,7°, no tooth at all. The chord's ends lie s̄/2 either side of
    the tooth's axis at r_a − h̄ from O, so tg ψ_y = (s̄/2)/(d_a/2 − h̄) = s̄/(d_a − 2h̄): that is
    what it should have written, and its 0,04505 and 2,579° = 0,04502 rad follow from it."""
    literal = 2 * math.degrees(math.atan(18.1 / (420 - 2 * 9.1) * (420 - 2 * 9.1)))
    assert literal > 170.0
    tan_psi = 18.1 / (420 - 2 * 9.1)
    assert round(tan_psi, 5) == 0.04505
    assert round(math.degrees(math.atan(tan_psi)), 3) == 2.579
    assert round(math.atan(tan_psi), 5) == 0.04502
    sol = geomcad.solve("2013-4")
    assert sol.construction.step("ψ_y").op == "∠TOK: tan ψ_y = s̄/(d_a − 2h̄)"
    note = next(n for n in sol.notes if "garbled" in n)
    assert spec_2013_4.CORRECT_PSI_FORMULA in note
    assert "s̄_y/(d_a − 2h̄_ay)" in spec_2013_4.CORRECT_PSI_FORMULA


def test_seed_erratum_d_y_and_alpha_y_carry_the_rounded_psi() -> None:
    """The seed's d_y = 18,1/sin 2,579° = 402,25 mm uses ψ_y rounded to 2,579°; exactly
    d_y = √(s̄² + (d_a − 2h̄)²) = 402,207 mm. Its α_y = 20,86° follows from its d_y."""
    assert round(18.1 / math.sin(math.radians(2.579)), 2) == 402.25
    exact = math.hypot(18.1, 420 - 2 * 9.1)
    assert round(exact, 3) == 402.207
    assert round(math.degrees(math.acos(375.88 / 402.25)), 2) == 20.86
    sol = geomcad.solve("2013-4")
    assert sol.diff["d_y"] == pytest.approx(exact / 1000 - 0.40225, abs=1e-12)
    assert any(n.startswith("erratum d_y:") for n in sol.notes)
    assert any(n.startswith("erratum alpha_y_deg:") for n in sol.notes)


@pytest.mark.parametrize(
    ("m", "z", "x", "where"),
    [(0.01, 40, 0.43, 0.5), (0.005, 12, 0.3, 0.3), (0.002, 80, -0.5, 0.8), (0.02, 25, 0.8, 0.6),
     (0.003, 18, 0.0, 0.5), (0.004, 30, 0.25, 0.1)],
)  # fmt: skip
def test_round_trip_chord_predicted_from_x_gives_x(
    m: float, z: int, x: float, where: float
) -> None:
    """Predict the caliper's reading on a gear with shift x, then solve the problem with it."""
    g = SpurGear(m, z, x)
    d_l, d_a = g.limit_diameter(), g.tip_diameter
    ch = g.chord(d_l + where * (d_a - d_l))
    sol = geomcad.solve("2013-4", m=m, z=z, d_a=d_a, s_chord=ch.s_bar, h_chord=ch.h_bar)
    assert sol.results["x"] == pytest.approx(x, abs=1e-11)
    assert sol.results["d_y"] == pytest.approx(ch.d_y, rel=1e-12)
    assert sol.results["s"] == pytest.approx(g.s, rel=1e-11)
    assert sol.seed == {} and sol.diff == {}


def test_the_generated_tooth_passes_through_the_chord_ends() -> None:
    sol = geomcad.solve("2013-4")
    c = sol.construction
    geo = sol.data
    assert c["ψ_y (generated)"] == pytest.approx(c["ψ_y"], rel=REL)
    assert c["s̄ (caliper on the generated tooth)"] == pytest.approx(0.0181, rel=REL)
    # the involute of the generated flank crosses the circle d_y at K
    g = geo.gear
    K = c["K"]
    assert math.atan2(K.x, K.y) == pytest.approx(g.half_angle(sol.results["d_y"]), rel=REL)
    assert not g.undercut and g.s_a > 0


def test_notes_of_the_seed_mention_the_short_tip() -> None:
    notes = geomcad.solve("2013-4").notes
    assert any("428.568" in n for n in notes)


BAD = [
    ({"m": 0.0}, ParameterError, r"parameter m = 0\.0: must be > 0"),
    ({"z": 0}, ParameterError, r"parameter z = 0: must be ≥ 1"),
    ({"z": 2.5}, ParameterError, r"parameter z = 2\.5: must be a whole number"),
    ({"alpha_deg": 35.0}, ParameterError, r"alpha_deg = 35\.0: .*pointed at this profile angle"),
    ({"s_chord": 0.13}, ParameterError, r"s_chord = 0\.13: the chord's ends lie outside the tip"),
    ({"s_chord": 0.05}, ParameterError, r"s_chord = 0\.05: the chord spans .* angular pitch"),
    ({"h_chord": 0.03}, ParameterError, r"s_chord = 0\.0181: .* below the base circle"),
    ({"h_chord": 0.25}, ParameterError, r"h_chord = 0\.25: the chordal height must lie between"),
    ({"h_chord": -0.001}, ParameterError, r"parameter h_chord = -0\.001: must be > 0"),
    ({"s_chord": 0.024, "h_chord": 0.0016}, ConstructionError, r'"limit circle": .*no involute'),
    ({"s_chord": "x"}, ParameterError, r"parameter s_chord = 'x': must be a number"),
]


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_api(params: dict[str, object], exc: type, words: str) -> None:
    with pytest.raises(exc, match=words):
        geomcad.solve("2013-4", **params)


@pytest.mark.parametrize(("params", "exc", "words"), BAD)
def test_bad_input_through_the_cli(
    params: dict[str, object], exc: type, words: str, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = ["solve", "2013-4"]
    for k, v in params.items():
        argv += ["--set", f"{k}={v}"]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: 2013-4: ")
    assert "Traceback" not in err
    assert issubclass(exc, GeomcadError)


def test_the_sheet_draws_the_tooth_at_5_to_1() -> None:
    sol = geomcad.solve("2013-4")
    assert sol.scales["l"] == pytest.approx(0.0002)
    ((name, sheet),) = sol.sheets()
    assert name == ""
    texts = [t.text for t in sheet.texts()]
    assert "5:1" in texts
    # the tip circle (solid thick) at its true radius, r_a/k_l mm
    tips = [it for it in sheet.items if isinstance(it, ArcItem) and it.role == "link"]
    assert any(it.r == pytest.approx(210 / 0.2, rel=1e-9) for it in tips)
    roots = [it for it in sheet.items if isinstance(it, ArcItem) and it.role == "thin"]
    assert any(it.r == pytest.approx(sol.data.gear.d_f / 2 / 0.0002, rel=1e-9) for it in roots)
    # the caliper's dimensions, with the bar drawn over s and h
    assert any(t.startswith("s = 18,1") for t in texts)
    assert any(t.startswith("h = 9,1") for t in texts)
    assert "\u0304" not in "".join(texts)
    bars = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "dimension"]
    assert len(bars) >= 2
    bars = [it for it in sheet.items if isinstance(it, Polyline) and it.role == "frame_thin"]
    assert len(bars) >= 10  # the tables' rulings and the bars over s and h in them


@pytest.mark.parametrize("params", [{"z": 10, "m": 0.004, "d_a": 0.048,
                                     "s_chord": 0.006257378601609235,
                                     "h_chord": 0.004246233188097245}])  # fmt: skip
def test_an_undercut_variant_draws(params: dict[str, float]) -> None:
    sol = geomcad.solve("2013-4", **params)
    assert sol.data.gear.undercut
    assert any("undercut" in n for n in sol.notes)
    assert sol.sheets()


LAYOUT_VARIANTS = [
    {},
    {"z": 10, "m": 0.004, "d_a": 0.048, "s_chord": 0.006257378601609235,
     "h_chord": 0.004246233188097245},
    {"z": 80, "m": 0.002, "d_a": 0.162, "s_chord": 0.002413560641474962,
     "h_chord": 0.001009102509988799},
    {"z": 25, "m": 0.02, "d_a": 0.572, "s_chord": 0.043009755888149065,
     "h_chord": 0.036926636862529116},
]  # fmt: skip


@pytest.mark.parametrize("params", LAYOUT_VARIANTS, ids=lambda p: f"z={p.get('z', 40)}")
def test_sheet_layout(params: dict[str, float]) -> None:
    """No text on another, everything inside the frame and off the title block, the tooth view
    left of the tables, and the scale in the title block."""
    from geomcad_constructions.sheets_2013_4 import _views
    from layout import item_box, layout_problems

    from geomcad.sheet import views as V
    from geomcad.sheet.compose import Field, arrange

    sol = geomcad.solve("2013-4", **params)
    ((_, sheet),) = sol.sheets()
    problems = layout_problems(sheet)
    # no drawn line reaches a table or the order of construction
    tree, _main = _views(sol)
    lay = arrange(tree, Field.of_format("A3"))
    boxes = [pl.inner for pl in lay if isinstance(pl.view, V.Table | V.Text | V.Steps)]
    for it in sheet.items:
        if getattr(it, "role", "") in ("frame", "frame_thin", "title", "label"):
            continue
        x0, y0, x1, y1 = item_box(it)
        for b in boxes:
            if x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1:
                problems.append(f"{it.role} line {item_box(it)} reaches the table at {b}")
    assert not problems, "\n".join(problems)


def test_order_of_construction_is_the_recorded_steps() -> None:
    """The order of construction lists the steps of ORDER through their kinds' templates, in
    both languages, with the recorded values (ψ_y, x) as the student writes them."""
    from geomcad_constructions.sheets_2013_4 import ORDER, WORDS

    from geomcad.sheet import views as V
    from geomcad.sheet.lang import language

    sol = geomcad.solve("2013-4")
    c = sol.construction
    cases = (
        ("ru", "ψ_y = 0,04502 рад", "x = (s – πm/2)/(2m·tg α) = 0,4284"),
        ("en", "ψ_y = 0.04502 rad", "x = (s – πm/2)/(2m·tan α) = 0.4284"),
    )
    for lang, psi, x in cases:
        with language(lang):
            steps = V.Steps(c, 140.0, only=ORDER, words=WORDS)
            numbered = [t for t in steps.lines if t[:1].isdigit()]
            assert len(numbered) == len(ORDER) == 12
            text = " ".join(steps.lines)
            assert psi in text and x in text
            assert f"ψ_y = {V.num(c['ψ_y'])}" in text and x.endswith(V.num(c["x"]))
            assert all(c.step(n).kind for n in ORDER)


def test_bars_belong_to_their_labels() -> None:
    """The bars over s̄ and h̄ lie on their letters (the turned h̄ of the vertical dimension
    too), and the checker takes them for part of their labels, not lines crossing them; a line
    through a label is still found."""
    from layout import findings, is_bar_of, text_poly

    from geomcad.sheet.model import TextItem

    ((_, sheet),) = geomcad.solve("2013-4").sheets()
    texts = [t for t in sheet.items if isinstance(t, TextItem)]
    bars = [
        it
        for it in sheet.items
        if isinstance(it, Polyline) and len(it.points) == 2
        and math.dist(*it.points) < 2.0 and it.role in ("dimension", "frame_thin")
    ]  # fmt: skip
    assert len(bars) >= 6  # s̄, h̄ in the dimensions, the data table and the order
    for b in bars:
        assert any(is_bar_of(b, t) for t in texts), b
    assert not [f for f in findings(sheet) if f.kind == "label-line"]
    turned = [t for t in texts if t.angle and any(is_bar_of(b, t) for b in bars)]
    assert turned, "the bar over h̄ of the vertical dimension turns with its text"
    # a line across a label, or one over its whole length, is not a bar of it
    t = turned[0]
    x0, y0, x1, y1 = text_poly(t).bounds
    mid = ((x0 + x1) / 2.0, (y0 + y1) / 2.0)
    for pts in (((x0 - 3.0, mid[1]), (x1 + 3.0, mid[1])), ((mid[0], y0 - 3.0), (mid[0], y1 + 3.0))):
        assert not is_bar_of(Polyline(pts, "thin"), t)


def test_the_seed_notes_come_with_the_seed_data_only() -> None:
    """The note on the seed's garbled formula is the spec's (``seed_notes``): first among the
    notes of the seed's solve, absent from a variant's (its numbers are not the seed's)."""
    seed = geomcad.solve("2013-4")
    assert seed.notes[: len(spec_2013_4.SEED_NOTES)] == list(spec_2013_4.SEED_NOTES)
    variant = geomcad.solve("2013-4", s_chord=0.0182)
    assert not any("garbled" in n for n in variant.notes)
