"""Measure label placement over every sheet (run on demand, not in CI).

    python3 bench/bench_labels.py [--per-sheet] [ID ...]
    python3 bench/bench_labels.py --baseline   # today's findings, as BASELINE lines

For every sheet of every problem (and of the example linkage files) the placed labels (the ones
with an anchor) are measured through the layout checker's geometry (tests/layout.py): how many are
crossed by a drawn line, how many overlap another text, how many lie nearer another label's point
than their own, and how far each is from the point it names (mean, 95th percentile, max, and how
many are beyond ``layout.ANCHOR_MAX``). The time the sheets took to draw is printed too.
"""

from __future__ import annotations

import argparse
import collections
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests")]

from installed import use_installed  # noqa: E402

use_installed()

import layout  # noqa: E402
from shapely.geometry import Point  # noqa: E402
from shapely.strtree import STRtree  # noqa: E402

import geomcad  # noqa: E402
from geomcad import documents, registry  # noqa: E402
from geomcad.sheet.model import Sheet, TextItem  # noqa: E402

FILES = ("shaper", "four-bar", "sixbar-2013-6", "slider-crank")


def _sheets(ids: list[str]) -> list[tuple[str, Sheet]]:
    out = []
    for pid in ids:
        if pid in FILES:
            sheets = documents.solve(str(ROOT / "examples" / f"{pid}.toml")).sheets()
        else:
            sheets = geomcad.solve(pid).sheets()
        out += [(f"{pid} {name}".strip(), s) for name, s in sheets]
    return out


def label_measures(sheet: Sheet) -> dict[str, object]:
    """The placed labels' figures: how many there are, how many a drawn line crosses (the
    checker's "label-line" test), how many overlap another text, how many lie beyond
    ``layout.ANCHOR_MAX`` of their point, how many lie nearer another label's point than their
    own (by more than 0.5 mm), and each one's distance to its point (mm)."""
    _form, drawn = layout.block_part(sheet)
    texts = [t for t in drawn if isinstance(t, TextItem)]
    lines = [it for it in drawn if not isinstance(it, TextItem)]
    strokes = [layout.stroke(it, sheet.format) for it in lines]
    line_tree = STRtree(strokes)
    polys = [layout.text_poly(t) for t in texts]
    text_tree = STRtree(polys)
    points = [Point(a) for _t, a in sheet.anchors]
    crossed = overlapped = far = ambiguous = 0
    dists: list[float] = []
    for t, anchor in sheet.anchors:
        p = layout.text_poly(t)
        q = p.buffer(-0.25)
        if not q.is_empty and any(
            strokes[j].intersection(q).area > layout.AREA_EPS
            for j in line_tree.query(q, predicate="intersects")
        ):
            crossed += 1
        if any(
            texts[j] is not t and polys[j].intersection(p).area > layout.AREA_EPS
            for j in text_tree.query(p, predicate="intersects")
        ):
            overlapped += 1
        d = p.distance(Point(anchor))
        dists.append(d)
        far += d > layout.ANCHOR_MAX
        others = [o for o in points if o.distance(Point(anchor)) > 1.0]
        ambiguous += any(p.distance(o) < d - 0.5 for o in others)
    return {
        "labels": len(sheet.anchors),
        "label-line": crossed,
        "label-label": overlapped,
        "far": far,
        "ambiguous": ambiguous,
        "distances": dists,
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--per-sheet", action="store_true")
    ap.add_argument(
        "--baseline",
        action="store_true",
        help="print each problem sheet's findings as tests/test_layout_all.py's BASELINE lines",
    )
    args = ap.parse_args()
    if args.baseline:
        for pid in registry.problem_ids():
            for name, s in geomcad.solve(pid).sheets():
                count = collections.Counter(f.kind for f in layout.findings(s))
                print(f"    ({pid!r}, {name!r}): {dict(sorted(count.items()))},".replace("'", '"'))
        return
    ids = args.ids or [*registry.problem_ids(), *FILES]
    t0, c0 = time.perf_counter(), time.process_time()
    sheets = _sheets(ids)
    took, cpu = time.perf_counter() - t0, time.process_time() - c0
    tot = {"labels": 0, "label-line": 0, "label-label": 0, "far": 0, "ambiguous": 0}
    dists: list[float] = []
    for name, s in sheets:
        m = label_measures(s)
        for k in tot:
            tot[k] += int(m[k])
        dists += m["distances"]  # type: ignore[arg-type]
        if args.per_sheet:
            d = m["distances"]
            print(
                f"{name:32s} labels {m['labels']:3d}  label-line {m['label-line']:3d}  "
                f"label-label {m['label-label']:3d}  far {m['far']:3d}  "
                f"ambiguous {m['ambiguous']:3d}  "
                f"max {max(d, default=0.0):5.1f} mm"
            )
    dists.sort()
    p95 = dists[int(0.95 * (len(dists) - 1))] if dists else 0.0
    print(
        f"{len(sheets)} sheets, {tot['labels']} placed labels: label-line {tot['label-line']}, "
        f"label-label {tot['label-label']}, beyond {layout.ANCHOR_MAX} mm {tot['far']}, "
        f"nearer another label's point {tot['ambiguous']}; "
        f"distance to anchor mean {statistics.fmean(dists) if dists else 0.0:.2f} mm, "
        f"p95 {p95:.2f}, max {dists[-1] if dists else 0.0:.2f}; "
        f"drawn in {took:.1f} s ({cpu:.1f} s CPU)"
    )


if __name__ == "__main__":
    main()
