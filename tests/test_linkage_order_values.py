"""One rounding per value on a kinematic sheet: an ω or ε the order of construction reads off a
plan is printed with the decimals its table column prints it with (review 4: ω3 −0,225 in the
table against 0,2254 in the text, ε3 87,4 against 87,37)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _views, layout
from geomcad.sheet.views import Steps, Table, step_text

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("name", ["four-bar", "crusher", "shaper", "sixbar-2013-6"])
def test_the_order_prints_a_tabled_value_as_its_table(name: str) -> None:
    s = solve(parse(tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))))
    lay = layout(s)
    views = [v for t in lay.trees for v in _views(t)]
    (steps,) = [v for v in views if isinstance(v, Steps)]
    text = " ".join(steps.lines)
    detail = lay.accel[0]
    cells: dict[str, str] = {}
    for table in (v for v in views if isinstance(v, Table)):
        head = table.rows[0]
        # ω in every numbered position (the detail's row, if it is one); ε in the acceleration
        # plans' positions, the detail's the first
        numbered = next((i for i, P in enumerate(s.drawn) if P is detail), None)
        row = numbered if head[0] == "№" else 0
        if row is not None:
            cells.update(
                {h.split(", ")[0]: c for h, c in zip(head, table.rows[1 + row], strict=True)}
            )
    checked = 0
    for m in re.finditer(r"([ωε]_\{\d+\}) = [^=]+ = [^=]+ = (\S+) ", text):
        sym, printed = m.groups()
        if sym in cells:
            assert printed == cells[sym].lstrip("\u2212\u2013-"), (sym, printed, cells[sym])
            checked += 1
    assert checked >= 2, (text, cells)  # the ε at least: every file's table has them
    # every other step keeps its own values (a^n = ω²·l, a^k = 2ω·V: not ω's table cell)
    names = [detail.vp.pole, *detail.vp.order, detail.ap.pole, *detail.ap.order]
    others = [detail.c.step(n) for n in names if detail.c.step(n).kind != "plan_omega"]
    assert others
    for step in others:
        assert step_text(step) in text, step_text(step)
