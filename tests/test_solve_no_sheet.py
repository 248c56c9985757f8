"""A solve is the model's: it loads no sheet or render module and lays out no sheet (issues 28,
32). The scale of a drawn value belongs to the sheet, asked for (once) by ``Solution.scales``
where ``verify`` needs mm↔SI."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

EX = Path(__file__).resolve().parents[1] / "examples"

#: Solves every registered id and every example file in a fresh interpreter, printing after each
#: the geomcad.sheet/geomcad.render modules loaded so far; then asks one linkage file's scales.
SCRIPT = """
import json, sys
import geomcad

def drawing():
    return sorted(m for m in sys.modules if m.split(".")[:2] in (["geomcad", "sheet"],
                                                                  ["geomcad", "render"]))

out = []
for pid in [*geomcad.problem_ids(), *sys.argv[1:]]:
    geomcad.solve(pid)
    out.append([pid, drawing()])
sol = geomcad.solve(sys.argv[1])
before = drawing()
scales = dict(sol.scales)
out.append(["scales", before, drawing(), scales, sol.scales is sol.scales])
print(json.dumps(out))
"""


#: A ``[sheet]`` table a cam or gear file may carry (checked as the file is read).
SHEET_TABLE = '\n[sheet]\nstudent = "Иванов И. И."\ndate = 2026-11-27\nlang = "en"\nformat = "A2"\n'


def with_sheet_table(tmp: Path) -> list[str]:
    """A cam file and a gear file with their own ``[sheet]`` table."""
    out = []
    for stem in ("cam-flat", "planetary"):
        path = tmp / f"{stem}-sheet.toml"
        path.write_text((EX / f"{stem}.toml").read_text(encoding="utf-8") + SHEET_TABLE,
                        encoding="utf-8")  # fmt: skip
        out.append(str(path))
    return out


def test_a_solve_loads_no_sheet_or_render_module(tmp_path: Path) -> None:
    files = [str(p) for p in sorted(EX.glob("*.toml"))] + with_sheet_table(tmp_path)
    linkage = [f for f in files if "shaper" in f]
    assert linkage and len(files) >= 10
    run = subprocess.run(
        [sys.executable, "-c", SCRIPT, *linkage, *files],
        capture_output=True,
        text=True,
        check=True,
    )
    rows = json.loads(run.stdout)
    *solves, (_, before, after, scales, same) = rows
    assert len(solves) >= 10 + len(files) + 1
    for pid, loaded in solves:
        assert loaded == [], f"solve({pid}) loaded {loaded}"
    # verify's question loads the sheet layer (the check sees it) and answers the drawn scales
    assert before == [] and "geomcad.sheet.linkage" in after
    assert set(scales) == {"l", "v", "a"} and all(k > 0 for k in scales.values())
    assert same  # asked once, then kept


def test_a_files_sheet_table_is_checked_as_it_is_read(tmp_path: Path) -> None:
    """A bad ``[sheet]`` table of a cam or gear file is one ``error:`` line naming its key on
    ``solve`` (checked without the sheet layer), as it was when the sheet layer checked it."""
    from geomcad.cli import main
    from geomcad.sheet.titleblock import TitleData
    from geomcad.titlefields import TITLE_KEYS

    assert TitleData.keys() == TITLE_KEYS  # one list of the title block's fields
    good = with_sheet_table(tmp_path)
    for path in good:
        assert main(["solve", path]) == 0
    text = (EX / "gear-pair.toml").read_text(encoding="utf-8")
    for table, key, why in (
        ('studnet = "x"', "sheet.studnet", "not a title-block field"),
        ('lang = "fr"', "sheet.lang", "must be one of ru, en"),
        ('format = "A7"', "sheet.format", "must be one of A4, A3, A2, A1"),
        ("student = 3", "sheet.student", "must be text"),
        ('org = "a\\nb"', "sheet.org", "one line"),
    ):
        bad = tmp_path / "bad.toml"
        bad.write_text(f"{text}\n[sheet]\n{table}\n", encoding="utf-8")
        run = subprocess.run([sys.executable, "-m", "geomcad", "solve", str(bad)],
                             capture_output=True, text=True)  # fmt: skip
        assert run.returncode == 2, (table, run.stderr)
        assert run.stderr.startswith("error: ") and run.stderr.count("\n") == 1, run.stderr
        assert key in run.stderr and why in run.stderr, run.stderr
