"""Lines and literal positions of sheet modules: how much of a sheet is still laid by hand.

A literal position is an int or float constant in the code (a paper size in mm, a factor of a
model length, an angle) other than 0, 1, 2 and 0.5 (which say "none", "one", "both sides",
"half"); a negative number counts once (its constant), a bool never. Docstrings and comments
hold no constants, so they do not count.

    python scripts/count_literals.py constructions/sheets_2013_[1-5].py
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

#: The constants that say what they mean without a position.
PLAIN = {0, 1, 2, 0.5}


def literals(source: str) -> int:
    """The int and float constants of ``source`` other than :data:`PLAIN`."""
    return sum(
        1
        for node in ast.walk(ast.parse(source))
        if isinstance(node, ast.Constant)
        and type(node.value) in (int, float)
        and node.value not in PLAIN
    )


def main(paths: list[str]) -> int:
    total_lines = total_lits = 0
    for p in paths:
        text = Path(p).read_text(encoding="utf-8")
        lines, lits = len(text.splitlines()), literals(text)
        total_lines += lines
        total_lits += lits
        print(f"{p}\t{lines} lines\t{lits} literals")
    if len(paths) > 1:
        print(f"total\t{total_lines} lines\t{total_lits} literals")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
