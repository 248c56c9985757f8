"""Notebooks: a solution and a sheet display themselves (IPython's ``_repr_*_`` methods), and
``examples/notebook.ipynb`` runs: its code cells are executed here in-process, in order, in one
namespace, the value of each cell's last expression displayed as a notebook would."""

from __future__ import annotations

import ast
import json
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.render import to_svg
from geomcad.sheet.model import Sheet, set_svg_writer

NOTEBOOK = Path(__file__).resolve().parents[1] / "examples" / "notebook.ipynb"
SVG_NS = "{http://www.w3.org/2000/svg}"


def _display(value: object) -> dict[str, str]:
    """What a notebook shows for ``value``: its HTML and SVG representations, when it has them."""
    shown = {}
    for mime, method in (("text/html", "_repr_html_"), ("image/svg+xml", "_repr_svg_")):
        fn = getattr(value, method, None)
        if callable(fn) and not isinstance(value, type):
            out = fn()
            if out is not None:
                shown[mime] = out
    return shown


def run_notebook(path: Path) -> list[Any]:
    """Execute the notebook's code cells; return each cell's displayed value (or None)."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    assert nb["nbformat"] == 4
    namespace: dict[str, Any] = {"__name__": "__main__"}
    results = []
    for i, cell in enumerate(c for c in nb["cells"] if c["cell_type"] == "code"):
        source = "".join(cell["source"])
        tree = ast.parse(source, filename=f"{path.name}[{i}]")
        last = tree.body[-1] if tree.body and isinstance(tree.body[-1], ast.Expr) else None
        if last is not None:
            tree.body.pop()
        exec(compile(tree, f"{path.name}[{i}]", "exec"), namespace)
        value = None
        if last is not None:
            value = eval(
                compile(ast.Expression(last.value), f"{path.name}[{i}]", "eval"), namespace
            )
        results.append(value)
    return results


def test_the_example_notebook_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # it writes a DXF file
    values = run_notebook(NOTEBOOK)
    shown = [_display(v) for v in values]
    tables = [s["text/html"] for s in shown if "text/html" in s]
    sheets = [s["image/svg+xml"] for s in shown if "text/html" not in s and "image/svg+xml" in s]
    assert len(tables) == 2 and len(sheets) == 1
    assert "exact − seed" in tables[0] and "exact − seed" not in tables[1]  # seed vs variant
    root = ET.fromstring(sheets[0])
    assert root.tag == f"{SVG_NS}svg" and root.get("width") == "420mm"
    assert values[-1] is True and (tmp_path / "2013-6-variant.dxf").stat().st_size > 10_000
    # the values the notebook prints are the library's
    l1, l2, theta = values[1]
    sol = geomcad.solve("2013-6")
    assert (l1, l2, theta) == (sol.results["l1"], sol.results["l2"], sol.results["theta_deg"])


def test_a_solution_shows_its_results_as_a_table() -> None:
    sol = geomcad.solve("2013-3")
    page = sol._repr_html_()
    root = ET.fromstring(f"<div>{page}</div>")  # well-formed: escaped text, closed tags
    rows = root.findall(".//tr")
    names = [r[0].text for r in rows[1:]]
    assert names == list(sol.results)
    head = [c.text for c in rows[0]]
    assert head == ["result", "value", "unit", "seed", "exact − seed"]
    v_b3 = next(r for r in rows if r[0].text == "V_B3")
    assert [c.text for c in v_b3][1:3] == [f"{sol.results['V_B3']:.6g}", "m/s"]


def test_a_list_of_solutions_gets_a_row_each() -> None:
    sol = geomcad.solve("2013-6")
    root = ET.fromstring(f"<div>{sol._repr_html_()}</div>")
    names = [r[0].text for r in root.findall(".//tr")]
    n = len(sol.results["solutions"])
    assert [f"solutions.{i}" for i in range(n)] == [x for x in names if x.startswith("solutions")]


def test_a_solution_and_its_sheets_show_the_svg_build_writes() -> None:
    sol = geomcad.solve("2013-3")
    sheets = sol.sheets()
    svg = to_svg(sheets[0][1])
    assert sol._repr_svg_() == svg[svg.index("<svg") :]
    for _name, sheet in sheets:
        text = to_svg(sheet)
        assert sheet._repr_svg_() == text[text.index("<svg") :]


def test_a_sheet_without_a_backend_shows_no_picture() -> None:
    import geomcad.notebook

    sheet = Sheet(210.0, 297.0, "A4", "t")
    try:
        set_svg_writer(None)
        assert sheet._repr_svg_() is None
    finally:
        set_svg_writer(geomcad.notebook.sheet_svg)
    assert ET.fromstring(sheet._repr_svg_() or "").get("width") == "210mm"
