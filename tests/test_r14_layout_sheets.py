"""Review 14, item 1: every sheet of a linkage file is built and written on its own.

A forces layout that failed ("parameter layout = 'План сил группы (4, 5)': has no room on the
sheet") cost review 14's pump file all four sheets. Now the failed sheet prints its one
``error:`` line (the sheet, then the parameter or construction step), the build exits with
status 2, and the file's other sheets are written, numbered as in the whole planned document
(the failed sheet keeps its number: Листов counts it). The forces layout is made to fail here
by a monkeypatch, in a serial build (in-process) and in the worker's own function of
``build --jobs`` (:func:`geomcad.teach.build.build_one`, called in-process).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad import cli
from geomcad.errors import ParameterError
from geomcad.sheet import linkage_forces

PUMP = Path(__file__).parent / "linkages_review14" / "pump-inclined-kulisa.toml"
WHY = "has no room on the sheet"


def _no_room(*_a: Any, **_k: Any) -> Any:
    raise ParameterError("layout", "План сил группы (4, 5)", WHY)


@pytest.fixture(scope="module")
def serial(tmp_path_factory: pytest.TempPathFactory) -> tuple[int, str, Path]:
    out = tmp_path_factory.mktemp("r14-sheets")
    mp = pytest.MonkeyPatch()
    mp.setattr(linkage_forces, "force_layout", _no_room)
    import contextlib
    import io

    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            rc = cli.main(["build", str(PUMP), "--format", "svg", "--out", str(out)])
    finally:
        mp.undo()
    return rc, err.getvalue(), out


def test_a_failed_forces_sheet_leaves_the_other_sheets_written(
    serial: tuple[int, str, Path],
) -> None:
    rc, _err, out = serial
    assert rc == cli.EXIT_BAD_INPUT
    names = sorted(p.name for p in out.iterdir())
    stem = PUMP.stem
    assert names == sorted(f"{stem}{s}.svg" for s in ("", "-plans", "-dynamics")), names


def test_the_failed_sheet_prints_one_error_line_naming_it(serial: tuple[int, str, Path]) -> None:
    _rc, err, _out = serial
    errors = [line for line in err.splitlines() if line.startswith("error:")]
    assert len(errors) == 1, err
    assert "forces" in errors[0] and WHY in errors[0] and PUMP.name in errors[0]


def test_the_other_sheets_keep_their_planned_numbers(serial: tuple[int, str, Path]) -> None:
    """Kinematic 1, plans 2, (forces 3 not drawn), dynamics 4: Листов 4 on each."""
    _rc, _err, out = serial
    for suffix, no in (("", 1), ("-plans", 2), ("-dynamics", 4)):
        svg = (out / f"{PUMP.stem}{suffix}.svg").read_text(encoding="utf-8")
        assert f"Лист {no}<" in svg and "Листов 4<" in svg, suffix


def test_the_solution_hands_back_the_drawn_sheets(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(linkage_forces, "force_layout", _no_room)
    sol = geomcad.solve(str(PUMP))
    with pytest.raises(geomcad.GeomcadError) as info:
        sol.sheets()
    assert [n for n, _ in info.value.sheets] == ["", "plans", "dynamics"]  # type: ignore[attr-defined]
    assert all(s is not None for _, s in info.value.sheets)  # type: ignore[attr-defined]


def test_the_parallel_worker_hands_back_the_other_sheets(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from geomcad.teach import build

    monkeypatch.setattr(linkage_forces, "force_layout", _no_room)
    options, workdir = cli._title_data(cli._parser().parse_args(["build", str(PUMP)]))
    stem, n, files, error, _missing = build.build_one(
        str(PUMP), ("svg",), ("svg",), False, options, workdir, False
    )
    assert n == 3 and len(files) == 3
    assert "forces" in error and WHY in error and PUMP.name in error
    assert f"{stem}-forces.svg" not in {name for name, _ in files}
