"""Review sheets: a solution beside the published one, apart from what a student hands in.

``geomcad build`` draws hand-in sheets, which show the solution and nothing of its audit. The
comparison with the seed's published solution (its printed values, the differences, each value's
class and tolerance, the errata, the notes on the numerical method) goes to the ``ID-review``
sheets, drawn here from :meth:`~geomcad.problem.Solution.seed_report` and
:attr:`~geomcad.problem.Solution.notes` for any problem, and written by
``geomcad build --review``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from geomcad.registry import title as problem_title
from geomcad.sheet import Drawing, Sheet, TitleBlock, fmt_number, start
from geomcad.sheet.frame import fill_title_blocks
from geomcad.sheet.lang import Words, current, language
from geomcad.sheet.text import SUBSTITUTE, metrics

if TYPE_CHECKING:
    from geomcad.problem import Solution
    from geomcad.sheet.titleblock import TitleData

#: The review sheets' words, per language (``geomcad/sheet/strings/<lang>/review.toml``).
WORDS = Words("geomcad.sheet", "review")
#: Columns of the comparison: header key and width (mm).
COLUMNS = (
    ("h_name", 38.0),
    ("h_unit", 16.0),
    ("h_exact", 34.0),
    ("h_seed", 34.0),
    ("h_printed", 96.0),
    ("h_diff", 30.0),
    ("h_class", 24.0),
    ("h_tol", 28.0),
    ("h_agrees", 22.0),
)
#: The classes of a seed value (``Solution.seed_report``'s ``class``): their table keys.
CLASSES = ("measured", "rounded", "erratum")
ROW_H = 6.0
TOP = 30.0
#: The lowest y (mm) a table row or a note line may reach on an A3 sheet (above the title block).
BOTTOM = 230.0


def review_sheets(sol: Solution[Any], title: TitleData | None = None) -> list[tuple[str, Sheet]]:
    """The review sheets of a solution: ``[("review", sheet), ("review-2", sheet) …]``, one
    document with its own sheet numbers: the comparison with the published values, and the
    notes (the seed's errata, the numerical method and its settings), so a seed problem without
    printed values (2013-9) still gets its errata and solver settings on a review sheet; none for
    a variant or where there is nothing to compare or note. Drawn in ``title.lang`` when given,
    else in the language being drawn."""
    if not sol.is_seed or not (sol.problem.seed or sol.notes):
        return []
    with language((title.lang if title is not None else "") or current()):
        return _review_sheets(sol, title)


def _review_sheets(sol: Solution[Any], title: TitleData | None) -> list[tuple[str, Sheet]]:
    units = {r.name: r.unit for r in sol.problem.results}
    rows = [
        [
            _plain(row["name"]),
            units.get(row["name"].split(".")[0], ""),
            fmt_number(row["exact"], digits=6),
            fmt_number(row["seed"], digits=6),
            _plain(row["printed"]),
            fmt_number(row["diff"], digits=2),
            WORDS(row["class"]) if row["class"] in CLASSES else row["class"],
            fmt_number(row["tol"], digits=2),
            WORDS("yes" if row["agrees"] else "no"),
        ]
        for row in sol.seed_report()
    ]
    lines = [_plain(n) for n in sol.notes]
    drawings: list[Drawing] = []
    d = _new(sol, 1)
    drawings.append(d)
    y = TOP
    widths = [w for _, w in COLUMNS]
    header = [WORDS(h) for h, _ in COLUMNS]
    while rows:
        room = int((BOTTOM - y) // ROW_H) - 1
        if room < 1:
            d = _new(sol, len(drawings) + 1)
            drawings.append(d)
            y = TOP
            continue
        chunk, rows = rows[:room], rows[room:]
        _w, h = d.table(30.0, y, widths, [header, *chunk], height=3.5, row_h=ROW_H)
        y += h + 8.0
    if lines:
        if y > BOTTOM - 20.0:
            d = _new(sol, len(drawings) + 1)
            drawings.append(d)
            y = TOP
        d.text(WORDS("notes"), (30.0, y + 5.0), 5.0)
        y += 9.0
        for i, line in enumerate(lines, 1):
            if y > BOTTOM:
                d = _new(sol, len(drawings) + 1)
                drawings.append(d)
                y = TOP
            y = d.paragraph(f"{i}. {line}", 30.0, y, 360.0, 3.5, indent=5.0) + 1.5
    sheets = [d.finish() for d in drawings]
    fill_title_blocks(sheets, title)
    return [("review" if i == 0 else f"review-{i + 1}", s) for i, s in enumerate(sheets)]


def _new(sol: Solution[Any], no: int) -> Drawing:
    pid = sol.problem.id
    tb = TitleBlock(title=WORDS("tb_title", id=pid), designation=WORDS("designation", id=pid))
    d = start("A3", tb)
    head = WORDS("head", title=problem_title(sol.problem))
    if no > 1:
        head += WORDS("continued", no=no)
    d.paragraph(head, 95.0, 8.0, 310.0, 5.0)
    return d


#: Characters of the notes the font lacks, written with ones it has (subscript digits, roots).
_SPELL = {
    **SUBSTITUTE,
    **{chr(0x2080 + i): str(i) for i in range(10)},
    **{"²": "^2", "³": "^3"},
    "√": "sqrt",
    "⊥": " perp. ",
    "∥": " par. ",
    "→": "->",
    "\u0304": "",  # a combining macron (h̄): the letter stays
}


def _plain(text: str) -> str:
    """Text as printed, with the markup characters escaped and the glyphs the font lacks spelt
    out (a note quotes formulas verbatim)."""
    text = text.replace("\\", "\\\\").replace("_", "\\_").replace("^", "\\^")
    widths = metrics().widths
    out = []
    for ch in text:
        if ch in _SPELL:
            out.append(_SPELL[ch])
        elif ord(ch) in widths:
            out.append(ch)
        else:
            out.append("?")
    return "".join(out)
