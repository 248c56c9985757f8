"""The command line of the interface (problems.md): list, solve, build, verify, and bad input."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

import geomcad
import geomcad.render
from geomcad import registry
from geomcad.cli import main
from geomcad.errors import GeomcadError, MissingDependency, ParameterError
from geomcad.verify import verify

PID = "2013-6"
K_L = 0.005  # the seed's k_l, m/mm
EXACT = geomcad.solve(PID).results


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def no_nan(name: str) -> float:
    raise AssertionError(f"the JSON holds {name}")


def loads(text: str) -> Any:
    return json.loads(text, parse_constant=no_nan)


def assert_bad_input(code: int, out: str, err: str, *words: str) -> None:
    assert code == 2
    assert out == ""
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: "), err
    assert "Traceback" not in err
    for w in words:
        assert w in lines[0], (w, err)


def cli(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "geomcad", *argv],
        capture_output=True,
        text=True,
        encoding="utf-8",
        cwd=cwd,
        timeout=120,
    )


# --- list and solve ---------------------------------------------------------------------------


def test_list_prints_each_id_with_its_title(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "list")
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert len(lines) == len(geomcad.problem_ids())
    line = next(x for x in lines if x.split()[0] == PID)
    assert registry.get(PID).title in line


def test_solve_json_is_the_interface_object(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "solve", PID, "--json")
    assert code == 0 and err == ""
    data = loads(out)
    assert set(data) == {"id", "params", "results", "seed", "diff", "notes"}
    assert data["id"] == PID
    assert data["params"] == {"H": 0.2, "K": 1.3, "l3": 0.3, "l4": 0.3, "e": 0.3}
    assert data["seed"]["O1B1"] == pytest.approx(89.5 * K_L, abs=1e-15)
    assert data["seed"]["O1B1"] == 0.4475
    assert data["results"]["O1B1"] == EXACT["O1B1"]
    assert set(data["diff"]) == set(data["seed"])
    for name, seed in data["seed"].items():
        assert data["diff"][name] == pytest.approx(data["results"][name] - seed, abs=1e-15)
    assert isinstance(data["results"]["solutions"][0]["crank_rocker"], bool)
    assert data["notes"] and all(isinstance(n, str) for n in data["notes"])


def test_solve_variant_has_no_seed(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "solve", PID, "--set", "K=1.4", "--set", "H=0.15", "--set", "e=0.25",
                       "--json")  # fmt: skip
    assert code == 0
    data = loads(out)
    assert (
        data["params"]["K"] == 1.4 and data["params"]["H"] == 0.15 and data["params"]["e"] == 0.25
    )
    assert data["seed"] == {} and data["diff"] == {}
    assert data["results"]["K_check"] == pytest.approx(1.4, rel=1e-9)


def test_solve_report_is_readable(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "solve", PID)
    assert code == 0 and err == ""
    assert "parameters:" in out and "K = 1.3" in out
    assert "theta_deg = 23.4783°" in out
    assert "solutions.0: O1 = [" in out and "crank_rocker = yes" in out
    header = next(line for line in out.splitlines() if "seed (printed)" in line)
    for col in ("exact", "diff", "class", "within tolerance"):
        assert col in header
    row = next(line for line in out.splitlines() if line.split("|")[0].strip() == "O1B1")
    assert "0.4475 (O1B1 = 89,5 мм)" in row and "measured" in row and "yes" in row
    assert "notes:" in out and "seed formula slip" in out


def test_solve_report_of_a_variant_says_the_seed_is_not_compared(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out, _ = run(capsys, "solve", PID, "--set", "K=1.4")
    assert code == 0
    assert "not compared" in out and "seed (printed)" not in out
    assert "K = 1.4   (set; default 1.3)" in out


def test_trace_goes_to_stdout(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "solve", PID, "--trace")
    assert code == 0 and err == ""
    assert geomcad.solve(PID).trace().strip() in out


def test_trace_with_json_goes_to_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "solve", PID, "--json", "--trace")
    assert code == 0
    assert loads(out)["id"] == PID  # stdout stays pure JSON
    assert err.strip() == geomcad.solve(PID).trace().strip()
    assert "B0 = circle(O2, l3) ∩ circle(C0, l4)" in err


# --- bad input --------------------------------------------------------------------------------

BAD = [
    (["solve", "no-such-id"], ["unknown problem id", "no-such-id", PID]),
    (["solve", PID, "--set", "K=0.8"], [f"{PID}: parameter K = 0.8: must be > 1"]),
    (["solve", PID, "--set", "Q=1"], [PID, "Q", "no such parameter"]),
    (["solve", PID, "--set", "K=abc"], [PID, "K", "abc", "must be a number"]),
    (["solve", PID, "--set", "K"], [PID, "--set K", "NAME=VALUE"]),
    (["solve", PID, "--set", "=1"], ["NAME=VALUE"]),
    (["solve", PID, "--set", "K=nan"], ["K", "finite"]),
    (
        ["solve", PID, "--set", "e=2"],
        [PID, 'step "O1 = leftmost point of the θ-arcs on y = l3 − e"'],
    ),
    (["solve", PID, "--bogus"], ["--bogus"]),
    (["solve"], ["solve", "ID"]),
    ([], ["command"]),
    (["frobnicate"], ["frobnicate"]),
    (["build", "no-such-id"], ["no-such-id"]),
    (["build", PID, "--format", "svg,jpg"], ["--format", "jpg"]),
    (["verify", PID], ["--measured"]),
    (["verify", PID, "--measured", "nope=1"], [PID, "nope", "O1B1", "theta_deg", "solutions"]),
    (["verify", PID, "--measured", "nope_mm=1"], [PID, "nope"]),
    (["verify", PID, "--measured", "O1B1=abc"], [PID, "O1B1", "must be a number"]),
    (["verify", PID, "--measured", "O1B1=inf"], [PID, "O1B1", "finite"]),
    (["verify", PID, "--measured", "O1B1"], ["--measured O1B1", "NAME=VALUE"]),
    (["verify", PID, "--measured", "solutions.4.O1B0=1"], ["solutions.4", "out of range"]),
    (["verify", PID, "--measured", "solutions.x.O1B0=1"], ["solutions", "index"]),
    (["verify", PID, "--measured", "solutions.0.nope=1"], ["nope", "O1B0"]),
    (["verify", PID, "--measured", "solutions.0.crank_rocker=1"], ["crank_rocker", "not a number"]),
    (["verify", PID, "--measured", "solutions=1"], ["solutions", "list"]),
    (["verify", PID, "--measured", "solutions.0=1"], ["solutions.0", "object"]),
    (["verify", PID, "--measured", "O1B1.0=1"], ["O1B1", "single value"]),
    (["verify", PID, "--measured", "theta_deg_mm=23"], ["theta_deg", "not a length"]),
    (["verify", PID, "--measured", "O1B1_mm=89.5", "--scale", "0"], ["--scale", "> 0"]),
    (["verify", PID, "--measured", "O1B1_mm=89.5", "--scale", "-0.005"], ["--scale"]),
    (["verify", PID, "--measured", "O1B1_mm=89.5", "--scale", "x"], ["--scale", "number"]),
    (["verify", PID, "--measured", "O1B1_mm=89.5", "--set", "K=0.8"], ["K", "> 1"]),
    (["verify", "no-such-id", "--measured", "O1B1=1"], ["no-such-id"]),
]


@pytest.mark.parametrize(("argv", "words"), BAD, ids=[" ".join(a) or "(none)" for a, _ in BAD])
def test_bad_input_is_one_error_line_and_status_2(
    capsys: pytest.CaptureFixture[str], argv: list[str], words: list[str]
) -> None:
    code, out, err = run(capsys, *argv)
    assert_bad_input(code, out, err, *words)


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["solve", PID, "--set", "K=0.8"], ["K"]),
        (["solve", "no-such-id", "--json"], ["no-such-id"]),
        (["solve", PID, "--set", "K"], ["K"]),
        (["verify", PID, "--measured", "nope=1", "--json"], ["nope"]),
        (["solve"], ["ID"]),
    ],
)
def test_bad_input_through_a_process(argv: list[str], words: list[str], tmp_path: Path) -> None:
    p = cli(*argv, cwd=tmp_path)
    assert_bad_input(p.returncode, p.stdout, p.stderr, *words)


def test_a_process_solves_from_any_directory(tmp_path: Path) -> None:
    p = cli("solve", PID, "--json", "--trace", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert loads(p.stdout)["seed"]["O1B1"] == 0.4475
    assert "Traceback" not in p.stderr and "O1B1" in p.stderr


# --- verify -----------------------------------------------------------------------------------


def verify_json(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, dict[str, Any]]:
    code, out, err = run(capsys, "verify", PID, *argv, "--json")
    assert err == ""
    data = loads(out)
    assert set(data) == {"id", "items", "ok"} and data["id"] == PID
    for item in data["items"]:
        assert set(item) == {
            "name", "measured", "exact", "deviation", "deviation_mm", "precision", "ok"
        }  # fmt: skip
    return code, data


def test_verify_seed_measurements_are_within_precision(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, data = verify_json(capsys, "--measured", "O1B1_mm=89.5", "--measured", "O1B0_mm=63.5")
    assert code == 0 and data["ok"] is True
    b1, b0 = data["items"]
    assert b1["name"] == "O1B1_mm" and b0["name"] == "O1B0_mm"
    for item, mm, exact in ((b1, 89.5, EXACT["O1B1"]), (b0, 63.5, EXACT["O1B0"])):
        assert item["deviation_mm"] == pytest.approx(mm - exact / K_L, abs=1e-9)
        assert item["measured"] == pytest.approx(mm * K_L, abs=1e-15)
        assert item["exact"] == exact
        assert item["deviation"] == pytest.approx(mm * K_L - exact, abs=1e-15)
        assert item["precision"] == pytest.approx(0.5 * K_L, abs=1e-15)
        assert item["ok"] is True


def test_verify_far_off_exits_1(capsys: pytest.CaptureFixture[str]) -> None:
    code, data = verify_json(capsys, "--measured", "O1B1_mm=89.5", "--measured", "O1B0_mm=70")
    assert code == 1 and data["ok"] is False
    assert [i["ok"] for i in data["items"]] == [True, False]
    assert data["items"][1]["deviation_mm"] == pytest.approx(70 - EXACT["O1B0"] / K_L, abs=1e-9)


def test_verify_scale_changes_the_conversion(capsys: pytest.CaptureFixture[str]) -> None:
    code, data = verify_json(capsys, "--measured", "O1B1_mm=44.7", "--scale", "0.01")
    (item,) = data["items"]
    assert code == 0
    assert item["measured"] == pytest.approx(0.447, abs=1e-15)
    assert item["deviation_mm"] == pytest.approx(44.7 - EXACT["O1B1"] / 0.01, abs=1e-9)
    assert item["precision"] == pytest.approx(0.005, abs=1e-15)
    # the seed's reading at the wrong scale is far off
    code, data = verify_json(capsys, "--measured", "O1B1_mm=89.5", "--scale", "0.01")
    assert code == 1 and data["items"][0]["deviation_mm"] > 40


def test_verify_angle_has_half_a_degree(capsys: pytest.CaptureFixture[str]) -> None:
    code, data = verify_json(capsys, "--measured", "theta_deg=23.5")
    (item,) = data["items"]
    assert code == 0
    assert item["precision"] == 0.5 and item["deviation_mm"] is None
    assert item["deviation"] == pytest.approx(23.5 - EXACT["theta_deg"], abs=1e-12)
    assert verify_json(capsys, "--measured", "theta_deg=24.1")[0] == 1


def test_verify_a_number_not_drawn_has_half_a_percent(capsys: pytest.CaptureFixture[str]) -> None:
    code, data = verify_json(capsys, "--measured", "K_check=1.3")
    (item,) = data["items"]
    assert code == 0 and item["deviation_mm"] is None
    assert item["precision"] == pytest.approx(0.005 * EXACT["K_check"], rel=1e-12)
    assert verify_json(capsys, "--measured", "K_check=1.31")[0] == 1


def test_verify_a_drawn_length_in_metres_uses_the_sheet_scale(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, data = verify_json(capsys, "--measured", "l2=0.383")
    (item,) = data["items"]
    k = geomcad.solve(PID).scales["l"]
    assert code == 0
    assert item["precision"] == pytest.approx(0.5 * k, abs=1e-15)
    assert item["deviation_mm"] == pytest.approx((0.383 - EXACT["l2"]) / k, abs=1e-9)


def test_verify_paths_into_the_list_of_solutions(capsys: pytest.CaptureFixture[str]) -> None:
    s = EXACT["solutions"]
    code, data = verify_json(
        capsys,
        "--measured", "solutions.0.O1B1_mm=89.5",
        "--measured", f"solutions.1.O1B0={s[1]['O1B0'] + 0.002}",
        "--measured", f"solutions.2.O1.0={s[2]['O1'][0]}",
    )  # fmt: skip
    a, b, c = data["items"]
    assert code == 0
    assert a["exact"] == s[0]["O1B1"]
    assert a["deviation_mm"] == pytest.approx(89.5 - s[0]["O1B1"] / K_L, abs=1e-9)
    # a field with its own spec (O1B0, drawn at k_l) takes that precision ...
    assert b["precision"] == pytest.approx(0.5 * K_L, abs=1e-15) and b["ok"]
    assert b["deviation_mm"] == pytest.approx(0.4, abs=1e-9)
    # ... and one without takes its parent's (solutions: not drawn, 0.5 %)
    assert c["precision"] == pytest.approx(0.005 * abs(s[2]["O1"][0]), rel=1e-12)
    assert c["deviation"] == 0.0 and c["deviation_mm"] is None


def test_verify_report_in_words(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(
        capsys, "verify", PID, "--measured", "O1B1_mm=89.5", "--measured", "theta_deg=25",
        "--measured", "K_check=1.3",
    )  # fmt: skip
    assert code == 1 and err == ""
    lines = out.splitlines()
    assert lines[0].startswith("O1B1: measured 89.5 mm, exact 89.336")
    assert "(0.446681 m at k_l = 0.005 m/mm), off by +0.164 mm" in lines[0]
    assert lines[0].endswith("within the drawing precision of 0.5 mm")
    assert "NOT within the angle precision of 0.5°" in lines[1]
    assert "within 0.5 % of the exact value" in lines[2]
    assert lines[-1] == f"{PID}: 1 of 3 measurements out of precision"


def test_verify_with_set_compares_with_the_variant(capsys: pytest.CaptureFixture[str]) -> None:
    exact = geomcad.solve(PID, K=1.4).results["theta_deg"]
    code, data = verify_json(capsys, "--set", "K=1.4", "--measured", f"theta_deg={exact}")
    assert code == 0 and data["items"][0]["exact"] == exact


def test_verify_api() -> None:
    sol = geomcad.solve(PID)
    report = verify(sol, {"O1B1_mm": "89,5", "theta_deg": 23.5}, None)
    assert report.ok and report.id == PID
    first = report.items[0]
    assert first.result == "O1B1" and first.measured_mm == 89.5 and first.scale == K_L
    assert report.to_json()["items"][1]["precision"] == 0.5
    with pytest.raises(ParameterError, match="scale"):
        verify(sol, {"O1B1_mm": 89.5}, 0.0)
    with pytest.raises(GeomcadError, match="must be a number"):
        verify(sol, {"O1B1": True}, None)
    with pytest.raises(GeomcadError, match="unknown result 'x'; the results are theta_deg"):
        verify(sol, {"x": 1.0}, None)


# --- build ------------------------------------------------------------------------------------


class FakeSolution:
    def __init__(self, pid: str) -> None:
        self.pid = pid
        self.problem = SimpleNamespace(inputs=None)

    def sheets(self, title: object = None) -> list[tuple[str, object]]:
        return [("", f"main sheet of {self.pid}"), ("plan", f"plan of {self.pid}")]


class FakeWriter:
    """Stands in for geomcad.render.write_sheets; no libcairo from ``no_cairo_from`` on."""

    def __init__(self, no_cairo_from: str | None = None) -> None:
        self.calls: list[tuple[str, list[str], Path]] = []
        self.no_cairo_from = no_cairo_from
        self.cairo = True

    def __call__(
        self,
        pid: str,
        sheets: Sequence[tuple[str, object]],
        out_dir: Path,
        formats: Sequence[str],
        colour: bool = False,
    ) -> list[Path]:
        self.calls.append((pid, list(formats), out_dir))
        if pid == self.no_cairo_from:
            self.cairo = False
        stems = [f"{pid}-{n}" if n else pid for n, _ in sheets]
        written = [out_dir / f"{s}.svg" for s in stems] if "svg" in formats else []
        if not self.cairo and set(formats) - {"svg"}:
            raise MissingDependency("PDF and PNG need libcairo: install libcairo2 (apt)")
        return written + [out_dir / f"{s}.{f}" for f in formats if f != "svg" for s in stems]


@pytest.fixture
def fake_problems(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    ids = ["p-a", "p-b", "p-c"]
    monkeypatch.setattr(registry, "problem_ids", lambda: list(ids))

    def get(pid: str) -> object:
        if pid not in ids:
            raise geomcad.UnknownProblem(f"unknown problem id {pid!r}")
        return object()

    monkeypatch.setattr(registry, "get", get)
    monkeypatch.setattr(geomcad, "solve", lambda pid: FakeSolution(pid))
    return ids


def test_build_writes_every_id_in_every_format(
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    fake_problems: list[str],
    tmp_path: Path,
) -> None:
    writer = FakeWriter()
    monkeypatch.setattr(geomcad.render, "write_sheets", writer)
    code, out, err = run(capsys, "build", "--out", str(tmp_path))
    assert code == 0 and err == "built 6 sheets of 3 problems in " + err.split(" in ")[1]
    assert writer.calls == [(pid, ["svg", "pdf", "png"], tmp_path) for pid in fake_problems]
    assert len(out.splitlines()) == 3 * 2 * 3
    assert str(tmp_path / "p-b-plan.pdf") in out.splitlines()


def test_build_without_cairo_still_writes_every_svg(
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    fake_problems: list[str],
    tmp_path: Path,
) -> None:
    writer = FakeWriter(no_cairo_from="p-b")
    monkeypatch.setattr(geomcad.render, "write_sheets", writer)
    code, out, err = run(capsys, "build", "--out", str(tmp_path), "--format", "svg,pdf")
    assert code == 2
    assert [(pid, f) for pid, f, _ in writer.calls] == [
        ("p-a", ["svg", "pdf"]),
        ("p-b", ["svg", "pdf"]),
        ("p-b", ["svg"]),
        ("p-c", ["svg"]),
    ]
    written = out.splitlines()
    for pid in fake_problems:
        assert str(tmp_path / f"{pid}.svg") in written
        assert str(tmp_path / f"{pid}-plan.svg") in written
    assert str(tmp_path / "p-a.pdf") in written and str(tmp_path / "p-b.pdf") not in written
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and "libcairo" in lines[0]


def test_build_of_a_named_id_with_a_bad_one_writes_nothing(
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    fake_problems: list[str],
    tmp_path: Path,
) -> None:
    writer = FakeWriter()
    monkeypatch.setattr(geomcad.render, "write_sheets", writer)
    code, out, err = run(capsys, "build", "p-a", "nope", "--out", str(tmp_path))
    assert_bad_input(code, out, err, "nope")
    assert writer.calls == []


def test_build_writes_real_svg(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, out, err = run(capsys, "build", PID, "--out", str(tmp_path), "--format", "svg")
    assert code == 0 and err.startswith("built ") and len(err.splitlines()) == 1
    assert out.splitlines()[0] == str(tmp_path / f"{PID}.svg")
    for line in out.splitlines():
        assert Path(line).read_text(encoding="utf-8").lstrip().startswith(("<?xml", "<svg"))


def test_a_help_whose_problem_fails_to_load_prints_the_help_and_one_error_line(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """Whatever fails while a file's --help is built (once: a module missing from the wheel),
    the help is printed with one error: line and no traceback."""
    from geomcad import cli as cli_module
    from geomcad import reference

    def missing(problem: object) -> str:
        raise ModuleNotFoundError("No module named 'geomcad.linkage'")

    monkeypatch.setattr(reference, "params_text", missing)
    monkeypatch.setattr(cli_module, "_HELP_FAILED", [])
    status = cli_module.main(
        ["solve", str(Path(__file__).resolve().parents[1] / "examples" / "shaper.toml"), "--help"]
    )
    out, err = capsys.readouterr()
    assert status == 70
    assert out.startswith("usage: geomcad solve")
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: internal error listing the parameters")
    assert "geomcad.linkage" in lines[0] and "Traceback" not in err
