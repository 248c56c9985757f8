"""For teachers: geomcad variants, verify --batch, build --jobs (issue 16).

Linkage files are the lead's (geomcad.files.linkage); here a small slider-crank maker that
follows ../shared/linkages.md (an RRP group on a fixed guide) stands in for it, solved in closed
form, so the variants' linkage path (TOML variant files, transmission angle, default key, plan
readings in mm) is tested on its own.
"""

from __future__ import annotations

import csv
import io
import json
import math
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad import documents
from geomcad.cli import main
from geomcad.construction import Construction
from geomcad.errors import ConstructionError, GeomcadError, ParameterError
from geomcad.problem import Build, Problem, ResultSpec, Solution
from geomcad.teach import batch, cards, keys, transmission, variants
from geomcad.verify import verify

# --- a stand-in linkage maker: the slider-crank O–A–B, slider B on the line y = e ----------------

SLIDER_CRANK = """\
title = "Slider-crank"

[frame]
O = [0.0, 0.0]

[drive]
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
phi = [30.0, 120.0]

[[group]]
kind = "RRP"
links = [2, 3]
joint = "B"
end = "A"
length = 0.4
guide = { through = [0.0, 0.02], angle = 0.0 }
assembly = "forward"
"""


def _slider_crank(file_id: str, data: dict[str, Any]) -> Problem:
    drive, group = data["drive"], data["group"][0]
    r, w, l_ab = float(drive["length"]), float(drive["omega"]), float(group["length"])
    e = float(group["guide"]["through"][1])
    if group.get("kind") != "RRP":
        raise ParameterError("group.1.kind", group.get("kind"), "the stand-in knows RRP only")

    def at(phi: float) -> dict[str, float]:
        ya = r * math.sin(phi)
        d2 = l_ab**2 - (ya - e) ** 2
        if d2 <= 0.0:
            raise ConstructionError("B = circle(A, l_AB) ∩ guide", "the rod cannot reach")
        xb = r * math.cos(phi) + math.sqrt(d2)
        beta = math.asin((ya - e) / l_ab)  # the rod's angle below the guide
        vb = -r * w * math.sin(phi) - r * w * math.cos(phi) * math.tan(beta)
        w2 = -r * w * math.cos(phi) / (l_ab * math.cos(beta))
        return {"phi_deg": math.degrees(phi) % 360.0, "x_A": r * math.cos(phi), "y_A": ya,
                "x_B": xb, "y_B": e, "V_B": abs(vb), "V_B_x": vb, "omega_2": w2}  # fmt: skip

    def build(_: Mapping[str, Any]) -> Build:
        dense = [at(2 * math.pi * i / 720) for i in range(720)]
        xs = [p["x_B"] for p in dense]
        n = drive.get("positions")
        phis = [360.0 * i / n for i in range(n)] if n else drive["phi"]
        positions = [at(math.radians(p)) for p in phis]
        i_max, i_min = xs.index(max(xs)), xs.index(min(xs))
        work = ((i_max - i_min) % 720) / ((i_min - i_max) % 720)
        results = {"stroke": max(xs) - min(xs), "K": max(work, 1 / work), "positions": positions}
        return Build(
            results,
            Construction("slider-crank"),
            scales={"l": 0.005, "v": 0.05, "a": 0.5, "F": 10.0},
        )

    return Problem(
        id=file_id,
        title=str(data.get("title", "")),
        params=(),
        results=(
            ResultSpec("stroke", "m", "stroke of the slider B", "l"),
            ResultSpec("K", "1", "coefficient of velocity change"),
            ResultSpec("V_B", "m/s", "velocity of the slider B", "v"),
            ResultSpec("omega_2", "rad/s", "angular velocity of the rod 2"),
            ResultSpec("positions", "", "the positions"),
        ),
        seed={},
        build=build,
        draw=lambda sol: [],
        inputs=data,
    )


@pytest.fixture
def linkage(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Path:
    monkeypatch.setattr(documents, "_linkage_problem", _slider_crank)
    path = tmp_path / "crank.toml"
    path.write_text(SLIDER_CRANK, encoding="utf-8")
    return path


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def bad(code: int, out: str, err: str, *words: str) -> None:
    assert code == 2 and out == "" and len(err.splitlines()) == 1, (code, out, err)
    assert err.startswith("error: ") and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)


# --- --vary ---------------------------------------------------------------------------------------


def test_vary_takes_multiples_of_the_step() -> None:
    v = variants.parse_vary("H=0.152..0.25:0.005")
    assert (v.text(0), v.text(v.n - 1), v.n) == ("0.155", "0.25", 20)
    d = variants.parse_vary("e=0.20..0.35")  # the step: the last written decimal place
    assert (d.text(0), d.text(1), d.n) == ("0.2", "0.21", 16)
    w = variants.parse_vary("law=linear|harmonic")
    assert (w.n, w.text(1)) == (2, "harmonic")


@pytest.mark.parametrize(
    "text, words",
    [
        ("H", ["KEY=LO..HI"]),
        ("H=0.1-0.2", ["KEY=LO..HI"]),
        ("H=0.2..0.1", ["LO must be less than HI"]),
        ("H=0.1..0.2:0", ["STEP must be > 0"]),
        ("H=0.1..0.2:x", ["STEP must be a number"]),
        ("H=0.10..0.11:0.05", ["fewer than two multiples"]),
        ("law=a|a", ["distinct"]),
    ],
)
def test_bad_vary(text: str, words: list[str]) -> None:
    with pytest.raises(GeomcadError) as info:
        variants.parse_vary(text)
    for w in words:
        assert w in str(info.value)


@pytest.mark.parametrize(
    "argv, words",
    [
        (["2013-6", "--vary", "K=0.5..1.5:0.1"], ["--vary K", "must be > 1"]),
        (["2013-6", "--vary", "nope=1..2"], ["nope", "no such parameter"]),
        (["2013-6"], ["--vary"]),
        (["2013-2", "--vary", "law=1..2"], ["law", "takes one of"]),
        (["2013-2", "--vary", "n_div=2..6:0.5"], ["n_div", "whole-number"]),
        (["2013-6", "--vary", "H=0.1..0.2:0.05"], ["only 3 different variants"]),
        (["2013-6", "--vary", "H=0.15..0.25", "--min-transmission-deg", "40"], ["linkage files"]),
        (["2013-6", "--vary", "H=0.15..0.25", "--key", "nope"], ["--key nope", "no result"]),
        (["no-such-id", "--vary", "H=0.1..0.3"], ["no-such-id"]),
    ],
)
def test_variants_bad_input(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, argv: list[str], words: list[str]
) -> None:
    out_dir = tmp_path / "v"
    code, out, err = run(
        capsys, "variants", *argv, "--count", "5", "--seed", "1", "--out", str(out_dir)
    )
    bad(code, out, err, *words)
    assert not out_dir.exists()


# --- problem ids ----------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def governor(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Four variants of 2013-7 with their cards (SVG) and answer key."""
    out = tmp_path_factory.mktemp("gov")
    code = main(["variants", "2013-7", "--count", "4", "--seed", "7", "--out", str(out),
                 "--vary", "m2=8..12:0.5", "--vary", "f=0.1..0.3:0.05", "--format", "svg",
                 "--course", "ТММ-21", "--teacher", "Petrova"])  # fmt: skip
    assert code == 0
    return out


def _answers(out: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO((out / "answers.csv").read_text(encoding="utf-8"))))


def test_problem_variants_solve_to_their_key(governor: Path) -> None:
    rows = _answers(governor)
    assert [r["variant"] for r in rows] == ["01", "02", "03", "04"]
    assert list(rows[0])[2:] == [r.name for r in geomcad.registry.get("2013-7").results]
    for row in rows:
        spec = json.loads((governor / row["file"]).read_text(encoding="utf-8"))
        assert spec["id"] == "2013-7" and set(spec["set"]) == {"m2", "f"}
        sol = geomcad.solve("2013-7", **{k: float(v) for k, v in spec["set"].items()})
        for name in ("omega", "R32", "alpha_deg"):
            assert row[name] == keys.fmt(sol.results[name])
    sets = [tuple(json.loads((governor / r["file"]).read_text())["set"].items()) for r in rows]
    assert len(set(sets)) == len(sets)
    card = (governor / "card-02.svg").read_text(encoding="utf-8")
    for text in ("Вариант 02", "Дано:", "Определить:", "ТММ-21", "Petrova", "ω"):
        assert text in card
    assert (governor / "answers.pdf").read_bytes().startswith(b"%PDF")
    meta = json.loads((governor / "answers.json").read_text(encoding="utf-8"))
    assert meta["count"] == 4 and meta["variants"][1]["variant"] == "02"
    assert meta["variants"][1]["answers"]["omega"] == float(rows[1]["omega"])


def test_same_seed_same_bytes_other_seed_other_variants(
    governor: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    for seed, same in (("7", True), ("8", False)):
        out = tmp_path / seed
        code, _, _ = run(capsys, "variants", "2013-7", "--count", "4", "--seed", seed, "--out",
                         str(out), "--vary", "m2=8..12:0.5", "--vary", "f=0.1..0.3:0.05",
                         "--format", "svg", "--course", "ТММ-21",
                         "--teacher", "Petrova")  # fmt: skip
        assert code == 0
        names = ["answers.csv", "answers.json", "variant-01.json", "card-01.svg"]
        equal = [(out / n).read_bytes() == (governor / n).read_bytes() for n in names]
        assert all(equal) if same else not any(equal[:3])


def test_draws_do_not_depend_on_the_seeded_values_being_solved_in_parallel() -> None:
    t = variants.load_template("2013-2")
    vs = [variants.parse_vary("H=0.02..0.05:0.005"), variants.parse_vary("r0=0.03..0.05:0.005")]
    from geomcad.teach import jobs

    serial = variants.draw(t, vs, 3, 11)
    with jobs.pool(2) as run_two:
        parallel = variants.draw(t, vs, 3, 11, mapper=run_two)
    assert [v.values for v in serial.variants] == [v.values for v in parallel.variants]
    assert serial.rejected == parallel.rejected


def test_unsolvable_and_duplicate_variants_are_redrawn() -> None:
    # 2013-6: a crank centre line y = l3 − e far from the θ-arcs misses them
    t = variants.load_template("2013-6")
    vs = [variants.parse_vary("e=0.2..2.0:0.1"), variants.parse_vary("K=1.2..1.4:0.1")]
    drawn = variants.draw(t, vs, 6, 3)
    assert drawn.rejected["unsolvable"] > 0 and drawn.rejected["duplicate"] > 0
    assert "O1" in drawn.examples["unsolvable"]
    assert drawn.draws == 6 + sum(drawn.rejected.values())
    for v in drawn.variants:  # every kept one solves; none twice
        geomcad.solve("2013-6", **{k: float(x) for k, x in v.values})
    assert len({v.values for v in drawn.variants}) == 6


def test_variants_of_2013_2_take_a_choice_and_fixed_sets(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, out, _ = run(capsys, "variants", "2013-2", "--count", "3", "--seed", "2", "--out",
                       str(tmp_path), "--vary", "law=linear|harmonic|cycloidal", "--vary",
                       "r0=0.04..0.06:0.005", "--set", "n_div=6", "--key", "r,rho_min",
                       "--format", "svg")  # fmt: skip
    assert code == 0 and "3 variants of 2013-2" in out
    rows = _answers(tmp_path)
    assert list(rows[0])[2:] == [*(f"r.{i}" for i in range(7)), "rho_min"]
    spec = json.loads((tmp_path / "variant-01.json").read_text())
    assert spec["set"]["n_div"] == "6" and spec["set"]["law"] in ("linear", "harmonic", "cycloidal")


# --- linkage files --------------------------------------------------------------------------------


def test_linkage_variants_keep_a_transmission_angle_of_40(
    linkage: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "v"
    code, text, _ = run(capsys, "variants", str(linkage), "--count", "5", "--seed", "4", "--out",
                        str(out), "--vary", "group.1.length=0.09..0.2:0.005", "--vary",
                        "drive.omega=5..15:1", "--format", "svg")  # fmt: skip
    assert code == 0, text
    meta = json.loads((out / "answers.json").read_text(encoding="utf-8"))
    assert meta["rejected"]["transmission"] > 0 and meta["rejected"]["unsolvable"] > 0
    for row in meta["variants"]:
        data = tomllib.loads((out / row["file"]).read_text(encoding="utf-8"))
        length = data["group"][0]["length"]
        assert str(length) == row["values"]["group.1.length"]
        # the rod's largest angle to the guide is asin((r + e)/l): γ = 90° − that ≥ 40°
        assert 90.0 - math.degrees(math.asin((0.1 + 0.02) / length)) >= 40.0 - 0.5
        assert data["drive"]["phi"] == [30.0, 120.0] and data["title"] == "Slider-crank"
    # the default key: stroke, K, ω of each link and the output's V at the plans' positions
    assert meta["columns"] == ["stroke", "K", "positions.0.V_B", "positions.0.omega_2",
                               "positions.1.V_B", "positions.1.omega_2"]  # fmt: skip
    card = (out / "card-01.svg").read_text(encoding="utf-8")
    # the data as named quantities (no file keys) and the scheme's scale
    assert "group.1.length" not in card and "drive." not in card and "μ" in card
    assert "ω" in card and ">AB<" in card  # ω_1, l_AB as symbols


def test_transmission_angle_by_group_kind() -> None:
    pos = {"x_A": 0.0, "y_A": 0.1, "x_B": 0.1, "y_B": 0.0}
    rrr = {"frame": {"C": [0.1, 0.1]}, "group": [{"kind": "RRR", "joint": "B", "ends": ["A", "C"]}]}
    assert transmission.group_angles(rrr, pos) == pytest.approx([45.0])
    rrp = {"group": [{"kind": "RRP", "joint": "B", "end": "A", "guide": {"angle": 0.0}}]}
    assert transmission.group_angles(rrp, pos) == pytest.approx([45.0])
    rpr = {"group": [{"kind": "RPR", "slider": "A", "pivot": "B", "offset": 0.0}]}
    assert transmission.group_angles(rpr, pos) == pytest.approx([90.0])
    prp = {"group": [{"kind": "PRP", "slot_angle": 120.0}]}
    assert transmission.group_angles(prp, pos) == pytest.approx([60.0])
    with pytest.raises(GeomcadError, match=r"RRRR.*--min-transmission-deg 0"):
        transmission.group_angles({"group": [{"kind": "RRRR"}]}, pos)
    with pytest.raises(GeomcadError, match="no position of point 'Q'"):
        transmission.group_angles({"group": [{"kind": "RRR", "joint": "Q", "ends": []}]}, pos)


def test_an_unknown_group_kind_refuses_the_check_instead_of_skipping_it(
    linkage: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    t = variants.load_template(str(linkage))
    assert t.data is not None
    t.data["group"][0]["kind"] = "RRRR"
    out = variants.judge(t, (("drive.omega", "10"),), 40.0)
    assert out.status == "unsolvable"  # the stand-in refuses RRRR itself
    t.data["group"][0]["kind"] = "RRP"
    t.data["group"].append({"kind": "RRRR"})
    out = variants.judge(t, (("drive.omega", "10"),), 40.0)
    assert out.refused and "RRRR" in out.message
    assert variants.judge(t, (("drive.omega", "10"),), 0.0).status == "ok"


def test_verify_reads_linkage_plan_vectors_in_mm(linkage: Path) -> None:
    sol = documents.solve(str(linkage))
    v = sol.results["positions"][1]["V_B"]
    rep = verify(sol, {"positions.1.V_B_mm": v / 0.05 + 0.4, "positions.1.V_B": v + 0.03,
                       "stroke_mm": sol.results["stroke"] / 0.005 - 0.6})  # fmt: skip
    a, b, c = rep.items
    assert (a.plan, a.scale, a.ok, a.measured_mm) == (
        "v",
        0.05,
        True,
        pytest.approx(v / 0.05 + 0.4),
    )
    assert a.deviation_mm == pytest.approx(0.4) and a.precision == pytest.approx(0.025)
    assert (b.rule, b.ok) == ("drawing", False)  # 0.03 m/s is 0.6 mm on the plan
    assert (c.plan, c.ok) == ("l", False)
    with pytest.raises(GeomcadError, match="not a length"):
        verify(sol, {"positions.1.omega_2_mm": 1.0})


# --- verify --batch -------------------------------------------------------------------------------


def test_batch_grades_a_class_and_reports_bad_rows(
    governor: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    rows = _answers(governor)
    students = tmp_path / "class.csv"
    om1, om2 = float(rows[0]["omega"]), float(rows[1]["omega"])
    students.write_text(
        "student;variant;omega;R32;alpha_deg\n"
        f"Ivanov;1;{om1 + 0.05:.4f};;\n"  # within 0.5 % of ω
        f"Petrova;02;{om2 * 1.02:.4f};{rows[1]['R32']};{rows[1]['alpha_deg'].replace('.', ',')}\n"
        "Sidorov;99;1;;\n"
        ";3;1;;\n"
        "Kuz;4;abc;;\n"
        "Lee;4;;;\n",
        encoding="utf-8",
    )
    code, verdicts, out = run(capsys, "verify", "--batch", str(governor / "answers.csv"),
                              str(students))  # fmt: skip
    assert code == 1 and "Traceback" not in out
    lines = list(csv.DictReader(io.StringIO(verdicts)))
    got = {(ln["student"], ln["name"]): ln for ln in lines}
    assert got[("Ivanov", "omega")]["ok"] == "yes"
    assert got[("Petrova", "omega")]["ok"] == "no"
    assert got[("Petrova", "R32")]["ok"] == "yes" and got[("Petrova", "alpha_deg")]["ok"] == "yes"
    assert "not in the answers" in got[("Sidorov", "")]["error"]
    assert got[("", "")]["error"] == "no student name"
    assert "must be a number" in got[("Kuz", "omega")]["error"]
    assert got[("Lee", "")]["error"] == "no measured values"
    assert "row 3 Petrova (variant 2): 2 of 3 within precision" in out
    assert "class: 6 rows, 3 of 4 values within precision, 4 errors" in out


@pytest.mark.parametrize(
    "answers, students, words",
    [
        ("missing.csv", "class.csv", ["missing.csv", "no such file"]),
        ("class.csv", "class.csv", ["no 'file' column"]),
        ("answers.csv", "answers.csv", ["no 'student' column"]),
    ],
)
def test_batch_bad_files(
    governor: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    answers: str,
    students: str,
    words: list[str],
) -> None:
    (tmp_path / "class.csv").write_text("student,variant,omega\nA,1,20\n", encoding="utf-8")
    (tmp_path / "answers.csv").write_bytes((governor / "answers.csv").read_bytes())
    code, out, err = run(capsys, "verify", "--batch", str(tmp_path / answers),
                         str(tmp_path / students))  # fmt: skip
    bad(code, out, err, *words)


def test_batch_graded_without_the_cli(governor: Path, tmp_path: Path) -> None:
    students = tmp_path / "s.csv"
    row = _answers(governor)[2]
    students.write_text(f"student,variant,r_D\nA,{row['variant']},{row['r_D']}\n", "utf-8")
    graded = batch.grade(str(governor / "answers.csv"), str(students))
    assert graded.ok and graded.lines[0]["ok"] == "yes"


# --- build --jobs ---------------------------------------------------------------------------------


def test_parallel_build_is_byte_identical_to_serial(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    ids = ["2013-8", "2013-7"]
    code1, out1, err1 = run(capsys, "build", *ids, "--out", str(tmp_path / "s"), "--format",
                            "svg,pdf,dxf")  # fmt: skip
    code2, out2, err2 = run(capsys, "build", *ids, "--out", str(tmp_path / "p"), "--format",
                            "svg,pdf,dxf", "--jobs", "2")  # fmt: skip
    assert code1 == code2 == 0
    serial = sorted(p.name for p in (tmp_path / "s").iterdir())
    assert serial == sorted(p.name for p in (tmp_path / "p").iterdir()) and len(serial) == 6
    for name in serial:
        assert (tmp_path / "s" / name).read_bytes() == (tmp_path / "p" / name).read_bytes(), name
    assert out2 == out1.replace(str(tmp_path / "s"), str(tmp_path / "p"))
    # piped: no progress bar, one summary line
    for err in (err1, err2):
        assert err.startswith("built 2 sheets of 2 problems in ") and len(err.splitlines()) == 1


def test_parallel_build_with_bad_input_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], linkage: Path
) -> None:
    broken = tmp_path / "broken.toml"
    broken.write_text("[frame\n", encoding="utf-8")
    code, out, err = run(capsys, "build", "2013-8", str(broken), "--out", str(tmp_path / "o"),
                         "--jobs", "2")  # fmt: skip
    bad(code, out, err, "broken.toml", "TOML")
    assert not (tmp_path / "o").exists()
    bad(*run(capsys, "build", "2013-8", "--jobs", "-1"), "--jobs")


def test_solution_is_what_the_key_flattens() -> None:
    sol: Solution = geomcad.solve("2013-2")
    flat = keys.flatten(sol.results)
    assert "profile.0.0" not in flat and flat["r.1"] == sol.results["r"][1]


# --- the sheets -----------------------------------------------------------------------------------


def test_answer_key_tables_put_positions_in_rows() -> None:
    columns = ["stroke", "positions.0.V_C", "positions.0.omega_2", "positions.1.V_C",
               "positions.1.omega_2"]  # fmt: skip
    units = {"stroke": "m", "positions.0.V_C": "m/s", "positions.0.omega_2": "rad/s"}
    rows = [["01", "0.2", "1.0", "2.0", "3.0", "4.0"], ["02", "0.3", "5.0", "6.0", "7.0", "8.0"]]
    single, per_pos = cards._key_tables(columns, units, rows, cards.WORDS["en"])
    assert single[1] == [["No.", "stroke"], ["", "m"]] and single[2] == [
        ["01", "0.2"],
        ["02", "0.3"],
    ]
    assert per_pos[1] == [["No.", "pos.", "V_C", "omega_2"], ["", "", "m/s", "rad/s"]]
    assert per_pos[2] == [["01", "0", "1.0", "2.0"], ["01", "1", "3.0", "4.0"],
                          ["02", "0", "5.0", "6.0"], ["02", "1", "7.0", "8.0"]]  # fmt: skip
    parts = cards._split_wide(per_pos, sum(per_pos[0][:3]) + 1.0)
    assert [p[1][0] for p in parts] == [["No.", "pos.", "V_C"], ["No.", "pos.", "omega_2"]]
    sheets = cards.answer_sheets("T", columns, units, rows * 40, cards.CardInfo(), "x")
    # 80 variants: 80 rows of single results and 160 of positions, in blocks of 41 rows side
    # by side on one A3 sheet
    assert len(sheets) == 1 and sheets[0].format == "A3"
    assert sum(t.text == "No." for t in sheets[0].texts()) == 2 + 4


def test_cards_in_russian(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, _ = run(capsys, "variants", "2013-7", "--count", "2", "--seed", "1", "--out",
                     str(tmp_path), "--vary", "m2=8..12:1", "--format", "svg",
                     "--lang", "ru")  # fmt: skip
    assert code == 0
    card = (tmp_path / "card-01.svg").read_text(encoding="utf-8")
    for word in ("Вариант 01", "Дано:", "Определить:", "Разраб."):
        assert word in card


def test_a_long_answer_key_is_one_pdf_of_several_pages(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    from pypdf import PdfReader

    code, out, _ = run(capsys, "variants", "2013-2", "--count", "2", "--seed", "1", "--out",
                       str(tmp_path), "--vary", "r0=0.04..0.06:0.005", "--set", "n_div=60",
                       "--key", "r", "--format", "svg")  # fmt: skip
    pages = PdfReader(tmp_path / "answers.pdf").pages
    assert code == 0 and f"({len(pages)} sheets)" in out and len(pages) >= 2
    assert "r.60" in pages[-1].extract_text() and "r.60" not in pages[0].extract_text()


# --- the lead's linkage files (examples/) ---------------------------------------------------------

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_variants_of_a_real_linkage_file_and_a_class_graded_off_its_plans(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    out = tmp_path / "v"
    code, text, _ = run(capsys, "variants", str(EXAMPLES / "slider-crank.toml"), "--count", "2",
                        "--seed", "5", "--out", str(out), "--vary", "drive.length=0.06..0.1:0.005",
                        "--vary", "group.1.length=0.2..0.4:0.01", "--format", "svg")  # fmt: skip
    assert code == 0, text
    meta = json.loads((out / "answers.json").read_text(encoding="utf-8"))
    assert meta["kind"] == "linkage" and meta["columns"][:2] == ["stroke", "K"]
    assert "positions.3.V_B" in meta["columns"] and "positions.2.omega_2" in meta["columns"]
    # at φ1 = 90° the axial slider-crank's rod stands at its largest angle: ω2 is 0 (to the
    # plan's tolerance, not 10^-16) in every variant, and the key leaves it out
    assert "positions.3.omega_2" not in meta["columns"]
    row = meta["variants"][0]
    sol = documents.solve(str(out / row["file"]))
    assert sol.results["stroke"] == pytest.approx(2 * float(row["values"]["drive.length"]))
    v, kv = sol.results["positions"][3]["V_B"], sol.scales["v"]
    students = tmp_path / "class.csv"
    students.write_text(
        "student,variant,positions.3.V_B_mm,stroke_mm\n"
        f"A,{row['variant']},{v / kv + 0.4:.3f},{sol.results['stroke'] / sol.scales['l']:.3f}\n"
        f"B,{row['variant']},{v / kv + 0.6:.3f},\n",
        encoding="utf-8",
    )
    code, csv_text, summary = run(capsys, "verify", "--batch", str(out / "answers.csv"),
                                  str(students))  # fmt: skip
    assert code == 1, summary
    verdicts = list(csv.DictReader(io.StringIO(csv_text)))
    assert [(d["student"], d["name"], d["ok"]) for d in verdicts] == [
        ("A", "positions.3.V_B_mm", "yes"), ("A", "stroke_mm", "yes"),
        ("B", "positions.3.V_B_mm", "no")]  # fmt: skip
    assert float(verdicts[0]["precision"]) == pytest.approx(0.5 * kv)


def test_the_default_key_of_a_gear_file_leaves_out_the_data_it_gives_back(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, _, _ = run(capsys, "variants", str(EXAMPLES / "gear-pair.toml"), "--count", "2",
                     "--seed", "1", "--out", str(tmp_path), "--vary", "gears.pair.z2=25..40:1",
                     "--format", "svg")  # fmt: skip
    assert code == 0
    columns = list(_answers(tmp_path)[0])[2:]
    assert "x1" in columns and "a_w" in columns
    assert not {"z1", "z2", "m"} & set(columns)
