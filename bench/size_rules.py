"""The linkage sheets' size rules, file by file (run on demand): the crank's drawn length on the
kinematic sheet's mechanism (rule: at least ``CRANK_MM``), the velocity plans' pa (at least
``PA_MM``), the format and the tables' text height.

    python3 bench/size_rules.py [FILE.toml …]   (default: every examples/*.toml with a linkage)
"""

from __future__ import annotations

import sys
from pathlib import Path

import geomcad
from geomcad.sheet import linkage as kin

ROOT = Path(__file__).resolve().parent.parent


def main() -> int:
    files = sys.argv[1:] or sorted(str(p) for p in (ROOT / "examples").glob("*.toml"))
    bad = 0
    for f in files:
        sol = geomcad.solve(f)
        s = getattr(sol, "data", None)
        if s is None or not hasattr(s, "linkage"):
            continue
        lay = kin.layout(s)
        lk = s.linkage
        crank = lk.length / lay.k_l.k
        pa = abs(lk.omega) * lk.length / lay.k_v.k
        fmt = "+".join(z.fmt for z in lay.sized)
        hs = sorted({v.height for t in lay.trees for v in kin._views(t) if hasattr(v, "height")})
        # a crank the mechanism draws short is drawn again on its detail view (ESKD 2.305)
        detail = next((v for v in kin._views(lay.trees[0]) if isinstance(v, kin._CrankDetail)),
                      None)  # fmt: skip
        k_d = lay.sized[0].layout[detail].scale if detail is not None else None
        shown = crank if k_d is None else lk.length / k_d.k
        on = "" if k_d is None else f", detail {shown:5.1f} mm ({k_d.ratio_text()})"
        ok = shown >= kin.CRANK_MM - 0.05 and pa >= kin.PA_MM - 0.05
        bad += not ok
        print(f"{Path(f).stem:24s} {fmt:6s} crank {crank:6.1f} mm ({lay.k_l.ratio_text():6s}{on})"
              f" pa {pa:6.1f} mm  text {hs}  {'ok' if ok else 'RULE BROKEN'}")  # fmt: skip
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
