"""One rounding of the numbers on every sheet of a linkage file (issue 27, reviews 4 and 5: M_пр
−288,859, V_D 1,2552 beside ω3 −0,225; R05 "11 130" read as two numbers).

- A table column of one quantity (the ω, ε, V, a tables over the positions; I_пр and M_пр)
  has one count of decimals, and its largest value at most 4 significant figures (3–4: the
  decimals are those of 4 figures at the largest, fewer where they write every value exactly;
  the smaller values keep fewer figures, as a plan read at one μ does).
- A number of five or more whole digits is grouped by threes with a narrow no-break space
  (GOST 8.417); four digits stay whole; no run of five digits is printed ungrouped.

The examples, the test files and a file of this test's own (tests/rounding/offset-press.toml:
five-digit reactions, ω and M_пр over three orders of magnitude)."""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path
from typing import Any

import pytest

from geomcad import documents
from geomcad.sheet import views
from geomcad.sheet.drawing import NUMBER
from geomcad.sheet.scale import GROUP_SEP, fmt_column, fmt_number

ROOT = Path(__file__).resolve().parents[1]
FILES = [
    *(ROOT / "examples" / f"{n}.toml" for n in ("shaper", "crusher", "sixbar-2013-6", "four-bar")),
    *(ROOT / "examples" / f"{n}.toml" for n in ("slider-crank", "scotch-yoke", "rocking-slider")),
    *sorted((ROOT / "tests" / "linkages").glob("*.toml")),
    ROOT / "tests" / "rounding" / "offset-press.toml",
]


@functools.cache
def _drawn(path: Path) -> tuple[list[list[list[str]]], list[str]]:
    """Every table (its rows) built while drawing ``path``'s sheets, and every text printed."""
    tables: list[list[list[str]]] = []
    real = views.Table.__init__

    def spy(self: views.Table, rows: Any, *args: Any, **kw: Any) -> None:
        real(self, rows, *args, **kw)
        tables.append([list(r) for r in self.rows])

    mp = pytest.MonkeyPatch()
    mp.setattr(views.Table, "__init__", spy)
    try:
        sheets = documents.solve(str(path)).sheets()
    finally:
        mp.undo()
    texts = [t.text for _, sheet in sheets for t in sheet.texts()]
    return tables, texts


def _value(cell: str) -> float:
    return float(cell.replace("\u2013", "-").replace(GROUP_SEP, "").replace(",", "."))


def _figures(cell: str) -> int:
    """The significant figures a printed number shows (its trailing zeros among them)."""
    digits = re.sub(r"\D", "", cell.replace(GROUP_SEP, ""))
    return len(digits.lstrip("0"))


def _quantity_columns(rows: list[list[str]]) -> list[tuple[str, list[str]]]:
    """The columns of a table over positions (its header starts with № or φ_1): each quantity's
    header and number cells; not the position numbers, not the crank angle."""
    head = rows[0]
    if not head or head[0] not in ("№", "φ_1, °"):
        return []
    out = []
    for j, h in enumerate(head):
        if h in ("№", "φ_1, °"):
            continue
        cells = [r[j] for r in rows[1:] if j < len(r) and NUMBER.fullmatch(r[j])]
        out.append((h, cells))
    return out


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_a_column_has_one_count_of_decimals_and_at_most_4_figures(path: Path) -> None:
    tables, _ = _drawn(path)
    columns = [c for rows in tables for c in _quantity_columns(rows)]
    assert len(columns) >= 3, path.stem  # ω and ε at least
    for head, cells in columns:
        assert cells, (path.stem, head)
        decimals = {len(c.partition(",")[2]) for c in cells}
        assert len(decimals) == 1, (path.stem, head, cells)
        big = max(cells, key=lambda c: abs(_value(c)))
        if abs(_value(big)) < 1.0e4:  # a five-digit value is written whole
            assert _figures(big) <= 4, (path.stem, head, cells)


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_a_long_number_is_grouped_by_threes_and_four_digits_stay_whole(path: Path) -> None:
    _, texts = _drawn(path)
    assert texts
    for t in texts:
        # a sheet's numbers, not its designation's code (letters and dots between digits)
        for m in re.finditer(r"(?<![\w.])[\d" + GROUP_SEP + r"]+(?:,\d+)?(?![\w.])", t):
            whole = m.group().partition(",")[0].strip(GROUP_SEP)
            if GROUP_SEP in whole:
                groups = whole.split(GROUP_SEP)
                assert len(whole.replace(GROUP_SEP, "")) >= 5, (path.stem, t)
                assert all(len(g) == 3 for g in groups[1:]) and 1 <= len(groups[0]) <= 3, t
            else:
                assert len(whole) <= 4, (path.stem, t)


def test_the_own_files_reactions_are_grouped() -> None:
    """The own test file's press force gives five-digit reactions: they are printed grouped."""
    _, texts = _drawn(FILES[-1])
    assert any(re.search(r"\d\d" + GROUP_SEP + r"\d{3}", t) for t in texts)


def test_the_rule_on_values() -> None:
    """4 figures at a column's largest (−149,8 beside −0,3), grouping from five digits."""
    assert fmt_column([-149.806, -0.337, 0.0], "ru") == ["\u2013149,8", "\u20130,3", "0,0"]
    assert fmt_column([1.2552, -2.7662, 0.0726], "ru") == ["1,255", "\u20132,766", "0,073"]
    assert fmt_column([0.16684, 0.00863], "ru") == ["0,1668", "0,0086"]
    assert fmt_number(11130.0, "ru", 4) == "11" + GROUP_SEP + "130"
    assert fmt_number(8544.0, "ru", 4) == "8544"
    assert fmt_number(89.0, "ru", 4, zeros=True) == "89,00"
    assert math.isclose(_value(fmt_number(-1234567.0, "ru", 7)), -1234567.0)


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_the_forces_sheet_prints_a_tabled_eps_and_a_as_the_kinematic_table(path: Path) -> None:
    """M_Ф = −J·ε and Ф = m·a in the order of the analysis: an ε or a that the kinematic
    sheet tables in the force position (its acceleration plan's) reads as its cell there
    (offset-press: ε2 95,4 in the table, never 95,37 in the text)."""
    import tomllib

    from geomcad.linkage import parse
    from geomcad.linkage.analysis import analyse
    from geomcad.linkage.solution import solve
    from geomcad.sheet import linkage_forces as lf
    from geomcad.sheet.lang import language
    from geomcad.sheet.linkage import tabled_cells
    from geomcad.sheet.views import step_text

    s = solve(parse(tomllib.loads(path.read_text(encoding="utf-8"))))
    if analyse(s).force_position is None:
        pytest.skip("no force analysis")
    with language("ru"):
        P, f, _ = lf.force_position(s)
        cells = tabled_cells(s, P)
        steps = lf.order_steps(f)
        given = lf._as_loads(steps, cells)
        checked = 0
        for st in steps:
            args = dict(st.args)
            text = step_text(st, lf.WORDS, given.get(st.name))
            if st.kind == "inertia_moment" and args["e"] in cells:
                assert f"{args['e']} = {cells[str(args['e'])]} " in text, (text, cells)
                checked += 1
            if st.kind == "inertia_force" and args["a"] in cells:
                assert f"·{cells[str(args['a'])].lstrip(chr(0x2013))} = " in text, (text, cells)
                checked += 1
    if path.stem == "offset-press":
        assert checked == 2  # ε2 and a_B at its force position, the first acceleration plan's
