"""Write docs/problems.md from the registered problems' specs (``--check``: only compare).

python3 scripts/gen_problems_md.py           # regenerate
python3 scripts/gen_problems_md.py --check   # exit 1 when the file is out of date
"""

from __future__ import annotations

import sys
from pathlib import Path

from geomcad.reference import REGENERATE, registered_markdown

TARGET = Path(__file__).resolve().parents[1] / "docs" / "problems.md"


def main(argv: list[str]) -> int:
    text = registered_markdown()
    if "--check" in argv:
        same = TARGET.exists() and TARGET.read_text(encoding="utf-8") == text
        if not same:
            print(f"{TARGET} is out of date: run {REGENERATE}", file=sys.stderr)
        return 0 if same else 1
    TARGET.write_text(text, encoding="utf-8")
    print(TARGET)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
