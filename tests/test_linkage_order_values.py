"""One rounding per value on a kinematic sheet: an ω or ε the order of construction reads off a
plan, or uses (a^n = ω²·l), is printed as its table cell prints it (reviews 4 and 5: ω3 −0,225
in the table against 0,2254 in the text, ε3 87,4 against 87,37, ε4 −32,0 against 32)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.linkage import _views, layout
from geomcad.sheet.views import Steps, Table

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
    for m in re.finditer(r"(\|?)([ωε]_\{\d+\})\|? = [^=]+ = [^=]+ = (\S+) ", text):
        bar, sym, printed = m.groups()
        if sym in cells:
            assert printed == cells[sym].lstrip("\u2212\u2013-"), (sym, printed, cells[sym])
            # a magnitude beside a negative cell says so: |ε_4| = 32,00 beside −32,00
            assert bool(bar) == cells[sym].startswith(("\u2212", "\u2013", "-")), (sym, cells)
            checked += 1
    assert checked >= 2, (text, cells)  # the ε at least: every file's table has them
    # a step that uses a tabled ω (a^n = ω²·l, a^k = 2ω·V) writes it as its cell reads
    names = [detail.vp.pole, *detail.vp.order, detail.ap.pole, *detail.ap.order]
    users = [
        st
        for st in (detail.c.step(n) for n in names)
        if st.kind != "plan_omega" and dict(st.args).get("w") in cells and "omega" in dict(st.args)
    ]
    # where the ω table has the detail's row, a link's ω gives a normal acceleration
    assert users or not any(k.startswith("ω") for k in cells), (name, cells)
    for st in users:
        cell = cells[str(dict(st.args)["w"])].lstrip("\u2212\u2013-")
        assert f"= {cell}²·" in text or f"= 2·{cell}·" in text, (st.name, cell, text)
