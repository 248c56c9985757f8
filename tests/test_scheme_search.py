"""The scheme's number searches ask their fixed rules of every place at once (arrays); they
must answer as the exact tests of one place do, and try the places in the same order."""

from __future__ import annotations

import math
import random

import numpy as np

from geomcad.sheet import linkage as lk


def _boxes(rng: random.Random, n: int) -> list[tuple[float, float, float, float]]:
    out = []
    for _ in range(n):
        x, y = rng.uniform(0.0, 40.0), rng.uniform(0.0, 40.0)
        out.append((x, y, x + rng.uniform(0.0, 8.0), y + rng.uniform(0.0, 5.0)))
    return out


def test_box_gaps_are_the_gaps() -> None:
    rng = random.Random(7)
    cs, bs = _boxes(rng, 30), _boxes(rng, 20)
    for along in (1.0, lk.LINK_ALONG):
        got = lk._box_gaps(np.asarray(cs), np.asarray(bs), along)
        want = [[lk._gap(c, b, along) for b in bs] for c in cs]
        assert np.allclose(got, want, rtol=0.0, atol=1e-12)


def test_too_near_agrees_with_the_exact_rules() -> None:
    rng = random.Random(11)
    cs, bs = _boxes(rng, 200), _boxes(rng, 15)
    # a place exactly at the limit from a box: the exact test must decide it
    cs.append((bs[0][2] + 5.0, bs[0][1], bs[0][2] + 8.0, bs[0][3]))
    for limit, read in ((lk.LINK_CLEAR_MM, True), (lk.LINK_SAME_MM, False), (1.0, False)):
        sure, ask = lk._too_near(np.asarray(cs), bs, limit, read)
        for k, c in enumerate(cs):
            exact = any((lk._apart(c, b) if read else lk._gap(c, b)) < limit for b in bs)
            assert not (sure[k] and not exact)  # never refuses a place the rule lets stand
            assert sure[k] or ask[k] or not exact  # never lets stand one it refuses unasked
    edge_sure, edge_ask = lk._too_near(np.asarray(cs[-1:]), bs[:1], 5.0)
    assert edge_ask[0] and not edge_sure[0]
    empty_sure, empty_ask = lk._too_near(np.asarray(cs), [], 5.0)
    assert not empty_sure.any() and not empty_ask.any()


def test_places_in_the_order_tried() -> None:
    p, w, h, steps = (3.0, -2.0), 4.0, 2.5, 7
    rs, cs = lk._tried_places(p, steps, w, h)
    k = 0
    for step in range(1, steps + 1):
        r = step * lk.LINK_STEP_MM
        for ux, uy in lk._LINK_DIRS:
            cx, cy = p[0] + ux * (r + w / 2.0), p[1] + uy * (r + h / 2.0)
            assert rs[k] == r
            assert tuple(cs[k]) == (cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0)
            k += 1
    assert k == len(cs) and math.isclose(rs[-1], steps * lk.LINK_STEP_MM)
