"""Every composed sheet's layout: what it decided and what it cost (run on demand, not in CI).

    python3 bench/bench_layout.py [--dump FILE] [--only ID …]

Builds the sheets of every problem (``geomcad list``) and of every ``examples/*.toml``, with
:func:`geomcad.sheet.compose.arrange` timed on every call (the format trials included) and every
:func:`~geomcad.sheet.compose.compose` recorded. Prints the number of layouts and the mean and
largest milliseconds (process CPU time) per layout, and the candidates the search laid out (a
figure the load of a shared machine does not move). ``--dump FILE`` writes, for every sheet
drawn: its format, each view's kind, title, box size and scale, and the text heights of its
tables and texts — the record to diff before and after a change of the layout
(``diff before.txt after.txt``).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dump", help="write the sheets' formats, scales and text heights here")
    ap.add_argument("--only", nargs="*", help="problem ids or example stems")
    ap.add_argument("-v", "--verbose", action="store_true", help="layouts and seconds per file")
    ns = ap.parse_args()

    import geomcad
    from geomcad import registry
    from geomcad.sheet import compose as cm

    times: list[float] = []
    real_arrange = cm.arrange

    def timed(tree: Any, field: Any, *args: Any, **kw: Any) -> Any:
        t0 = time.process_time()
        try:
            return real_arrange(tree, field, *args, **kw)
        finally:
            times.append(time.process_time() - t0)

    # candidates laid out by the search: a figure the load of a shared machine does not move
    scored = [0]
    real_solve = cm._Solver.solve

    def counted(self: Any) -> Any:
        try:
            return real_solve(self)
        finally:
            scored[0] += self.evaluations

    cm._Solver.solve = counted  # type: ignore[method-assign]

    drawn: list[tuple[Any, Any, Any]] = []
    real_compose = cm.compose

    def recorded(d: Any, tree: Any, field_: Any = None, layout: Any = None) -> Any:
        lay = real_compose(d, tree, field_, layout)
        drawn.append((d, tree, lay))
        return lay

    def patch() -> None:
        # every module that imported arrange / compose by name (the problems load lazily)
        for mod in list(sys.modules.values()):
            if getattr(mod, "arrange", None) is real_arrange:
                mod.arrange = timed  # type: ignore[attr-defined]
            if getattr(mod, "compose", None) is real_compose:
                mod.compose = recorded  # type: ignore[attr-defined]

    import importlib
    import pkgutil

    import geomcad_constructions as constructions

    for pkg in (geomcad, constructions):  # every module, so that patch() finds each importer
        for m in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + "."):
            if not m.name.endswith("__main__"):
                importlib.import_module(m.name)
    patch()
    ids = list(registry.problem_ids()) + sorted(str(p) for p in (ROOT / "examples").glob("*.toml"))
    if ns.only:
        ids = [i for i in ids if i in ns.only or Path(i).stem in ns.only]
    out: list[str] = []
    total = 0.0
    seen = 0
    for pid in ids:
        drawn.clear()
        t0 = time.process_time()
        sol = geomcad.solve(pid)
        patch()
        for name, sheet in sol.sheets():
            patch()
            out.append(f"== {Path(pid).stem} {name or '-'}: {sheet.width:.0f}x{sheet.height:.0f}")
        total += time.process_time() - t0
        if ns.verbose:
            print(f"{Path(pid).stem:24s} {len(times) - seen:3d} layouts {sum(times[seen:]):6.2f} s")
        seen = len(times)
        for d, _tree, lay in drawn:
            out.append(f"  sheet {d.sheet.width:.0f}x{d.sheet.height:.0f} score {_fmt(lay.score)}")
            for g, s in sorted(lay.groups.items()):
                if not g.startswith("#"):
                    out.append(f"    group {g}: k={s.k:g} {s.ratio_text()}")
            for pl in lay:
                v = pl.view
                title = (v.title or "").replace("\n", " ")[:40]
                w, h = pl.box[2] - pl.box[0], pl.box[3] - pl.box[1]
                sc = f" k={pl.scale.k:g} {pl.scale.ratio_text()}" if pl.scale else ""
                th = f" text {v.height:g}" if hasattr(v, "height") else ""
                out.append(f"    {type(v).__name__:10s} {w:6.1f}x{h:6.1f}{sc}{th} {title}")
    n = len(times)
    print(f"{len(ids)} problems/examples, {n} layouts arranged, {total:.1f} s CPU in all")
    if n:
        print(f"ms per layout: mean {1000 * sum(times) / n:.1f}, max {1000 * max(times):.1f}, "
              f"total {sum(times):.2f} s; {scored[0]} candidates laid out")  # fmt: skip
    if ns.dump:
        Path(ns.dump).write_text("\n".join(out) + "\n", encoding="utf-8")
    return 0


def _fmt(score: tuple[float, ...]) -> str:
    return "(" + ", ".join(f"{x:.3f}" for x in score) + ")"


if __name__ == "__main__":
    sys.exit(main())
