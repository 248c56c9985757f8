"""What a problem takes and gives, in words: ``geomcad params ID``, the parameter list of
``geomcad solve ID --help`` and the generated reference ``docs/problems.md``.

Everything here is read from the problem's own specs (:class:`~geomcad.problem.Param`,
:class:`~geomcad.problem.ResultSpec`, :class:`~geomcad.problem.SeedValue`), so the text cannot
drift from the code. Listing a problem's parameters loads only its light spec module; the
reference document also reads the construction module's docstring (the reconstruction and the
choices it settles).

    >>> from geomcad.problem import Param
    >>> domain(Param("K", 1.3, "coefficient of velocity change", gt=1.0))
    '> 1, at most 1e+06'
    >>> domain(Param("H", 0.2, "stroke", "m", gt=0.0))
    '> 0, 1e-06 … 1000'
    >>> domain(Param("n_div", 4, "intervals", integer=True, ge=1, le=360))
    'whole number, ≥ 1, ≤ 360'
    >>> domain(Param("follower", "flat", "the follower", choices=("flat", "knife")))
    'one of: flat, knife'
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from geomcad.problem import Param, SeedValue, _seed_items

if TYPE_CHECKING:
    from geomcad.problem import Problem, ResultSpec

#: How ``docs/problems.md`` is regenerated (its header says so, and the test that keeps it in step
#: with the code).
REGENERATE = "python3 scripts/gen_problems_md.py"

#: Plan scales a drawn result is read at.
_PLANS = {"l": "k_l", "v": "k_v", "a": "k_a", "F": "k_F"}


def unit_text(unit: str) -> str:
    """A unit as printed in the lists: ``°`` for degrees, ``—`` for a pure number."""
    if unit in ("", "1"):
        return "—"
    return "°" if unit == "deg" else unit


def _num(x: float) -> str:
    return f"{x:g}"


def default_text(p: Param) -> str:
    """The default as it is typed after ``--set NAME=``; "derived" for an optional parameter."""
    if p.default is None:
        return "derived"
    if isinstance(p.default, float):
        return _num(p.default)
    return str(p.default)


def domain(p: Param) -> str:
    """The values a parameter accepts, in words."""
    if p.choices:
        return "one of: " + ", ".join(p.choices)
    parts = ["whole number"] if p.integer else []
    for sign, bound in (("> ", p.gt), ("≥ ", p.ge), ("< ", p.lt), ("≤ ", p.le)):
        if bound is not None:
            parts.append(f"{sign}{_num(bound)}")
    # the physical range (Param.magnitudes): a least size where 0 is refused, a largest size
    lo, hi = p.magnitudes()
    low = max((b for b in (p.gt, p.ge) if b is not None), default=None)
    high = min((b for b in (p.lt, p.le) if b is not None), default=None)
    least = low is not None and low >= 0.0 and p.ge != 0.0 and lo > low and not p.integer
    most = high is None or high > hi
    positive = low is not None and low >= 0.0
    if least and most:
        parts.append(f"{_num(lo)} … {_num(hi)}")
    elif least:
        parts.append(f"at least {_num(lo)}")
    elif most:
        parts.append(f"at most {_num(hi)}" if positive else f"size ≤ {_num(hi)}")
    if p.turn:
        parts.append("taken modulo 360°")
    return ", ".join(parts) or "any number"


def _table(rows: Sequence[Sequence[str]], indent: str = "  ") -> list[str]:
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return [
        indent + "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
        for r in rows
    ]


def params_text(problem: Problem[Any]) -> str:
    """The parameters as a plain-text table (``solve --help``, ``params``)."""
    if not problem.params:
        return (
            f"{problem.id} is stated by a file and has no named parameters: set any of its keys\n"
            "with --set KEY=VALUE (a dotted path into the file, e.g. drive.omega=15).\n"
        )
    rows = [("NAME", "DEFAULT", "UNIT", "ALLOWED", "MEANING")]
    rows += [(p.name, default_text(p), unit_text(p.unit), domain(p), p.doc) for p in problem.params]
    head = (
        f"parameters of {problem.id} (--set NAME=VALUE; SI units, angles *_deg in degrees;\n"
        "an unset parameter keeps its default):"
    )
    return "\n".join([head, *_table(rows)]) + "\n"


def _drawn(r: ResultSpec) -> str:
    return _PLANS.get(r.drawn or "", "—")


def results_text(problem: Problem[Any]) -> str:
    """The results as a plain-text table, with the plan scale each is drawn at (for verify)."""
    if not problem.results:
        return f"{problem.id} declares no results in advance.\n"
    rows = [("NAME", "UNIT", "DRAWN AT", "MEANING")]
    rows += [(r.name, unit_text(r.unit), _drawn(r), r.doc) for r in problem.results]
    head = (
        f"results of {problem.id} (solve prints them; verify --measured NAME=VALUE, or\n"
        "NAME_mm=VALUE for a length read off the drawing; DRAWN AT: the plan's scale):"
    )
    return "\n".join([head, *_table(rows)]) + "\n"


def problem_text(problem: Problem[Any]) -> str:
    """``geomcad params ID``: the title, the parameters and the results."""
    return f"{problem.id} · {problem.title}\n\n{params_text(problem)}\n{results_text(problem)}"


# --- docs/problems.md -------------------------------------------------------------------------


def _cell(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def _rst_to_md(text: str) -> str:
    """A docstring's reStructuredText as Markdown: ``x`` → `x`, :role:`x` → `x`, and a star
    after a letter (M*, a point's name) kept from opening emphasis."""
    text = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", text)
    text = re.sub(r"(?<=\w)\*(?!\*)", r"\\*", text)
    return text.replace("``", "`")


def _docstring_body(doc: str | None) -> str:
    """A docstring without its first paragraph (the title line), dedented."""
    import inspect

    text = inspect.cleandoc(doc or "")
    _, _, rest = text.partition("\n\n")
    return rest.strip()


def construction_module_doc(problem: Problem[Any]) -> str:
    """The docstring of the module that holds the problem's ``build`` (its reconstruction)."""
    name = getattr(problem.build, "module", None) or getattr(problem.build, "__module__", None)
    if not name:
        return ""
    return _docstring_body(importlib.import_module(name).__doc__)


def _seed_rows(problem: Problem[Any]) -> list[str]:
    rows: list[str] = []
    for key, entry in problem.seed.items():
        for name, _index, v in _seed_items(key, entry):
            rows.append(_seed_row(problem, name, key, v))
    return rows


def _seed_row(problem: Problem[Any], name: str, key: str, v: SeedValue) -> str:
    spec = problem.result_spec(key)
    unit = "" if spec is None else unit_text(spec.unit)
    unit = {"—": "", "°": "°"}.get(unit, f" {unit}")
    tol = "erratum: " + v.note if v.kind == "erratum" else f"± {v.tol:.3g}{unit}"
    return f"| `{name}` | {_cell(v.printed)} | {v.value:.6g}{unit} | {v.kind} | {_cell(tol)} |"


def problem_markdown(problem: Problem[Any], description: str) -> str:
    """One problem's section of ``docs/problems.md``."""
    out = [f"## {problem.id} · {problem.title}", ""]
    if description:
        out += [_rst_to_md(description), ""]
    out += ["### Parameters", ""]
    if problem.params:
        out += ["| name | default | unit | allowed | meaning |", "|---|---|---|---|---|"]
        for p in problem.params:
            out.append(
                f"| `{p.name}` | {default_text(p)} | {unit_text(p.unit)} | "
                f"{_cell(domain(p))} | {_cell(p.doc)} |"
            )
    else:
        out.append("None: the problem is stated by a file.")
    out += ["", "### Results", "", "| name | unit | drawn at | meaning |", "|---|---|---|---|"]
    for r in problem.results:
        out.append(f"| `{r.name}` | {unit_text(r.unit)} | {_drawn(r)} | {_cell(r.doc)} |")
    seed = _seed_rows(problem)
    if seed:
        out += [
            "",
            "### The seed's published values",
            "",
            "| result | as printed | in SI | class | compared within |",
            "|---|---|---|---|---|",
            *seed,
        ]
    if problem.seed_k_l is not None:
        out += ["", f"The seed's drawing is at k_l = {_num(problem.seed_k_l)} m/mm."]
    model = construction_module_doc(problem)
    if model:
        out += ["", "### Model, reconstruction and choices", "", _rst_to_md(model)]
    return "\n".join(out).rstrip() + "\n"


HEADER = f"""# The problems: parameters, results, reconstructions

<!-- Generated from the problems' specs by `{REGENERATE}`; do not edit by hand.
     tests/test_reference.py fails when this file and the code disagree. -->

For each problem id: what it does, its parameters (`--set NAME=VALUE`, SI units, angles named
`*_deg` in degrees; defaults are the seed's data), its results (what `geomcad solve` reports and
`geomcad verify` checks; "drawn at" names the plan scale a result is drawn at on the project's own
sheet), the values the seed published with the class that sets how closely they are compared, and
the model the construction reconstructs. The same lists are at the prompt:
`geomcad params ID` or `geomcad solve ID --help`.

Comparison classes: *measured* values were read off the seed's drawing and are compared within
0.5 mm at its scale; *rounded* ones within half a unit of the last printed digit; an *erratum* is
a published value that is wrong, and the results' `notes` say why. `geomcad solve` prints the
comparison; on paper it goes to the review sheets (`geomcad build --review`), never to the sheets
a student hands in.
"""


def problems_markdown(problems: Sequence[tuple[Problem[Any], str]]) -> str:
    """The whole ``docs/problems.md``: a header, an index, and a section per problem.

    ``problems`` pairs each problem with its description (the spec module's docstring)."""
    out = [HEADER, "| id | title |", "|---|---|"]
    for problem, _ in problems:
        anchor = _anchor(f"{problem.id} · {problem.title}")
        out.append(f"| [`{problem.id}`](#{anchor}) | {_cell(problem.title)} |")
    out.append("")
    for problem, description in problems:
        out.append(problem_markdown(problem, description))
    return "\n".join(out).rstrip() + "\n"


def _anchor(heading: str) -> str:
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.lower())
    return text.replace(" ", "-")


def registered_markdown() -> str:
    """``docs/problems.md`` for every registered problem, described by its spec module."""
    from geomcad import registry

    pairs = []
    for pid in registry.problem_ids():
        problem = registry.get(pid)
        pairs.append((problem, _docstring_of_entry_point(pid)))
    return problems_markdown(pairs)


def _docstring_of_entry_point(pid: str) -> str:
    import inspect

    from geomcad import registry

    module = registry.entry_point(pid).module
    return inspect.cleandoc(importlib.import_module(module).__doc__ or "")


def problem_json(problem: Problem[Any]) -> dict[str, Any]:
    """``geomcad params ID --json``: the title, every parameter and every result."""
    return {
        "id": problem.id,
        "title": problem.title,
        "params": [
            {
                "name": p.name,
                "default": p.default,
                "unit": p.unit,
                "doc": p.doc,
                "allowed": domain(p),
                "choices": list(p.choices),
                "integer": p.integer,
                "optional": p.optional,
                **{
                    k: b
                    for k, b in (("gt", p.gt), ("ge", p.ge), ("lt", p.lt), ("le", p.le))
                    if b is not None
                },
            }
            for p in problem.params
        ],
        "results": [
            {"name": r.name, "unit": r.unit, "doc": r.doc, "drawn": r.drawn}
            for r in problem.results
        ],
    }
