"""The linkage sheets' size rules, file by file (run on demand): the crank's drawn length on the
kinematic sheet's mechanism (rule: at least ``CRANK_MM``), the velocity plans' pa (at least
``PA_MM``), the format and the tables' text height; then, for a file with masses or loads, the
forces sheet's: its format, the crank on its mechanism and cut out (at least ``CRANK_MM`` where
the sweep allows it), the μ_l of the mechanism and of its groups cut out, the smallest force
polygon's larger side and the tables' text height.

    python3 bench/size_rules.py [FILE.toml …]   (default: every examples/*.toml with a linkage)
"""

from __future__ import annotations

import sys
from pathlib import Path

import geomcad
from geomcad.linkage.analysis import analyse
from geomcad.sheet import linkage as kin
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.views import Polygon

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
        if analyse(s).forces is not None:
            bad += not _forces(s)
    return 1 if bad else 0


def _forces(s: object) -> bool:
    """Print the forces sheet's size rules; whether they hold."""
    tree, z = lf.force_layout(s)  # type: ignore[arg-type]
    lk = s.linkage  # type: ignore[attr-defined]
    placed = list(z.layout)
    (mech,) = [pl for pl in placed if isinstance(pl.view, lf._Loaded)]
    groups = {pl.scale.ratio_text() for pl in placed
              if isinstance(pl.view, lf._FreeBody) and pl.view.gf.group is not None}  # fmt: skip
    (cut,) = [pl for pl in placed if isinstance(pl.view, lf._FreeBody) and pl.view.gf.group is None]
    sides = [
        max(e[2] - e[0], e[3] - e[1]) / pl.scale.k
        for pl in placed
        if isinstance(pl.view, Polygon) and pl.scale and (e := pl.view.extent())
    ]
    hs = sorted({v.height for v in kin._views(tree) if hasattr(v, "height")})
    crank = lk.length / mech.scale.k
    wanted = lf.sweep_mm(s, lf.crank_scale(lk).k) <= lf.SWEEP_MAX_MM  # type: ignore[arg-type]
    cut_mm = lk.length / cut.scale.k
    ok = (min(crank, cut_mm) >= kin.CRANK_MM - 0.05 or not wanted) and len(groups) == 1
    print(f"{'  forces':24s} {z.fmt:6s} crank {crank:6.1f} mm ({mech.scale.ratio_text():6s})"
          f" groups {'/'.join(sorted(groups)):6s} crank cut out {cut_mm:5.1f} mm"
          f" polygons ≥ {min(sides, default=0):5.1f} mm"
          f"  text {hs}  {'ok' if ok else 'RULE BROKEN'}"
          f"{'' if wanted else ' (crank: the sweep forbids 30 mm)'}")  # fmt: skip
    return ok


if __name__ == "__main__":
    sys.exit(main())
