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


def test_a_solve_loads_no_sheet_or_render_module() -> None:
    files = [str(p) for p in sorted(EX.glob("*.toml"))]
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
