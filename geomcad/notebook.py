"""How a solution and a sheet show themselves in Jupyter (IPython's ``_repr_*_`` protocol).

- ``Solution._repr_html_``: :func:`results_html`, a table of the results (value and unit; with
  the seed's data also the published value and exact − seed), then the notes;
- ``Solution._repr_svg_`` and ``Sheet._repr_svg_``: :func:`sheet_svg`, the sheet's own SVG (the
  main sheet of a solution), exactly what ``geomcad build`` writes, without its XML declaration.

Notebook front ends prefer HTML to SVG, so a solution displays as its table; display a sheet
(``sol.sheets()[0][1]``, or ``IPython.display.SVG(sol._repr_svg_())``) to see the drawing.
Nothing here imports IPython: the protocol is plain methods that return strings.
"""

from __future__ import annotations

import html
import math
from typing import TYPE_CHECKING, Any

from geomcad.render.svg import to_svg
from geomcad.sheet import model

if TYPE_CHECKING:
    from geomcad.problem import Problem, Solution

#: Significant digits of a number in the table.
DIGITS = 6


def sheet_svg(sheet: model.Sheet) -> str:
    """The sheet's SVG as an ``<svg>`` element (the XML declaration dropped: HTML has none)."""
    text = to_svg(sheet)
    return text[text.index("<svg") :]


# A sheet shows itself through the render layer, which the sheet layer may not import.
model.set_svg_writer(sheet_svg)


def _num(x: float) -> str:
    if not math.isfinite(x):
        return str(x)
    return f"{x:.{DIGITS}g}"


def _fmt(value: object) -> str:
    """A value as escaped HTML: numbers to 6 digits, lists in brackets, objects as key = value."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return _num(value)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_fmt(v) for v in value) + "]"
    if isinstance(value, dict):
        return ", ".join(f"{html.escape(str(k))} = {_fmt(v)}" for k, v in value.items())
    return html.escape(str(value))


def _unit(problem: Problem[Any], name: str) -> str:
    spec = problem.result_spec(name)
    if spec is None or spec.unit in ("", "1"):
        return ""
    return "°" if spec.unit == "deg" else html.escape(spec.unit)


def _cell(text: str, tag: str = "td", align: str = "left") -> str:
    return f'<{tag} style="text-align:{align}">{text}</{tag}>'


def _row(cells: list[str], tag: str = "td") -> str:
    aligned = [_cell(c, tag, "left" if i == 0 else "right") for i, c in enumerate(cells)]
    return "<tr>" + "".join(aligned) + "</tr>"


def _objects(problem: Problem[Any], name: str, items: list[dict[str, Any]]) -> list[list[str]]:
    """One row per object of a list result (several solutions): ``name.i`` and its fields."""
    return [
        [
            f"{html.escape(name)}.{i}",
            "; ".join(
                f"{html.escape(str(k))} = {_fmt(v)}"
                + (f" {_unit(problem, k)}" if _unit(problem, k) else "")
                for k, v in obj.items()
            ),
            "",
        ]
        for i, obj in enumerate(items)
    ]


def results_html(sol: Solution[Any]) -> str:
    """The results of a solution as an HTML table, with the seed's values when it has them."""
    problem = sol.problem
    seed, diff = sol.seed, sol.diff
    head = ["result", "value", "unit"] + (["seed", "exact − seed"] if seed else [])
    rows = [_row(head, "th")]
    for name, value in sol.results.items():
        if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for cells in _objects(problem, name, value):
                rows.append(_row(cells + (["", ""] if seed else [])))
            continue
        cells = [html.escape(name), _fmt(value), _unit(problem, name)]
        if seed:
            cells += [_fmt(seed[name]) if name in seed else "", _diff(diff.get(name))]
        rows.append(_row(cells))
    params = ", ".join(f"{html.escape(k)} = {_fmt(v)}" for k, v in sol.params.items())
    out = [
        f"<div><b>{html.escape(problem.id)}</b> · {html.escape(problem.title)}</div>",
        f"<div><small>{params}</small></div>" if params else "",
        "<table>" + "".join(rows) + "</table>",
    ]
    if sol.notes:
        items = "".join(f"<li>{html.escape(n)}</li>" for n in sol.notes)
        out.append(f"<div>notes:</div><ul>{items}</ul>")
    return "\n".join(part for part in out if part)


def _diff(value: object) -> str:
    if isinstance(value, float):
        return f"{value:+.3g}"
    if isinstance(value, list):
        return "[" + ", ".join(f"{v:+.3g}" for v in value) + "]"
    return ""
