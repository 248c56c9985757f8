"""2013-3's drawing sheet: the mechanism with a cross at k_l and its velocity plan at k_v.

A3 landscape, composed by :mod:`geomcad.sheet.compose` (no hand-placed view): the mechanism at
the largest GOST scale its box allows, with the links numbered, the angle α and the lengths
dimensioned, the given velocity V_A and the senses of ω3, ω5 and M; the velocity plan, each
vector equation drawn as its two lines meeting, at a factor 1, 2, 2.5, 4 or 5 × 10^n; the given
data, the results and the vector equations in the order they were solved. :func:`scales` gives
the layout's factors without drawing (``Problem.scales``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.geom import Vec
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Row,
    Spacer,
    Tree,
    arrange,
    compose,
)
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.views import num

from .spec_2013_3 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.construction import Construction
    from geomcad.problem import Solution

    from .p2013_3 import Geometry

#: Paper sizes of the symbols drawn beside the mechanism (mm).
VA_LEN = 14.0
#: Width (mm) of the order of construction's text.
ORDER_W = 150.0
#: The title block's height (mm): the right-hand column keeps it free.
BLOCK_H = 52.0
WORDS = Words(__package__, "sheets_2013_3")


def extent(c: Construction, l_ab: float) -> tuple[float, float, float, float]:
    """The model box the mechanism drawing needs: the links, the slots run past C and O2."""
    return V.extent_of((c[n] for n in ("O1", "O2", "A", "B", "C")), 0.35 * l_ab)


def _views(sol: Solution[Geometry], kv: Scale | None = None) -> tuple[Tree, Figure, V.PlanView]:
    """The sheet's tree: the mechanism over the data and the order of construction, the plan
    over the results (their lengths on the plan at ``kv``; the table's size does not depend on
    it, so the layout can be arranged before the scales are known)."""
    geo, c = sol.data, sol.construction
    scheme = Figure(
        extent(c, geo.l_AB),
        lambda v: _mechanism(v, geo, c, sol),
        title=WORDS("scheme_title"),
        title_height=5.0,
        margin=8.0,
    )
    plan = V.PlanView(geo.plan, title=WORDS("plan_title"), title_height=5.0, margin=6.0)
    # the order of construction: the plan's steps and the force equivalent to M
    order = V.Steps(c, ORDER_W, only=[*geo.plan.order, "F_red"], words=WORDS,
                    title=WORDS("order_title"))  # fmt: skip
    tree = Row(
        Column(scheme, Row(_data(sol), _results(sol, kv))),
        Column(plan, order, Spacer((10.0, BLOCK_H))),
    )
    return tree, scheme, plan


@per_language
def scales(sol: Solution[Geometry]) -> dict[str, float]:
    """k_l of the mechanism and k_v of the plan, as the layout chooses them (no drawing)."""
    tree, scheme, plan = _views(sol)
    lay = arrange(tree, Field.of_format("A3"))
    k_l, k_v = lay[scheme].scale, lay[plan].scale
    assert k_l is not None and k_v is not None
    return {"l": k_l.k, "v": k_v.k}


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-3."""
    got = scales(sol)  # this layout's (in the language being drawn), which compose() repeats
    tree, _scheme, _plan = _views(sol, Scale(got["v"], "v"))
    k = Scale(got["l"], "l")
    tb = TitleBlock(title=WORDS("tb_title"), designation=WORDS("designation"), scale=k.ratio_text())
    d = start("A3", tb)
    compose(d, tree)
    return [("", d.finish())]


def _mechanism(v: Viewport, geo: Geometry, c: Construction, sol: Solution[Geometry]) -> None:
    O1, O2, A, B, C = (c[n] for n in ("O1", "O2", "A", "B", "C"))
    u3 = (C - B).unit()  # along the slot, from B through O1 to C
    u5 = (C - O2).unit()
    ext = v.scale.model(14.0)
    # link 1: the body AB sliding along O1O2 on its guide
    v.guide(A - Vec(v.scale.model(14.0), 0.0), A + Vec(v.scale.model(14.0), 0.0), (0.0, -1.0))
    v.seg(A, B, "link")
    v.slider(A, Vec(1.0, 0.0), with_joint=False)
    # link 3: the slotted rocker B–O1–C, run past B and C
    v.seg(B - u3 * ext, C + u3 * ext, "link")
    # link 5: O2 through C and on
    v.seg(O2, C + u5 * ext, "link")
    v.seg(O1, O2, "centre")
    # block 2 in the slot at B; the cross 4 at C, one slide on each link (no joint inside)
    v.slider(B, u3)
    v.slider(C, u3, with_joint=False)
    v.slider(C, u5, with_joint=False)
    # O1's support turned away from the rocker that passes through it and from O1O2: along the
    # bisector of the angle between the rocker's lower half (towards B) and O1O2
    n3 = ((B - O1).unit() + (O2 - O1).unit()).unit()
    v.pivot(O1, (n3.x, n3.y))
    v.pivot(O2)
    # the given velocity, and the senses of ω3 (= ω5) and of M
    sgn = 1.0 if geo.v_A > 0 else -1.0
    tip = A + Vec(sgn * v.scale.model(VA_LEN), 0.0)
    va_from = A + Vec(0.0, v.scale.model(7.0))
    v.arrow(va_from, tip + Vec(0.0, v.scale.model(7.0)), "result")
    v.label(tip + Vec(0.0, v.scale.model(7.0)), "V_A", 3.5, prefer=(0.0, 1.0), clear=1.0)
    w3 = c["ω3"]
    # each arrow keeps its 100° span whatever its sense: it starts at the span's far end
    a3 = math.degrees((C - O1).angle) + 20.0
    v.turn(O1, w3, a3 if w3 > 0 else a3 + 100.0, "ω_3")
    m_sense = -w3 * (1.0 if geo.M >= 0 else -1.0)  # M resists the motion when M > 0
    v.turn(O2, m_sense, -60.0 if m_sense > 0 else 40.0, "M")
    # letters and link numbers
    v.label(O1, "O_1", prefer=(1.0, -1.0), clear=2.5)
    v.label(O2, "O_2", prefer=(1.0, -1.0), clear=4.0)
    v.label(A, "A", prefer=(-1.0, -1.0), clear=3.0)
    v.label(B, "B", prefer=(-1.0, -1.0), clear=3.5)
    v.label(C, "C", prefer=(-1.0, 1.0), clear=5.0)
    for q, n in (
        (A + (B - A) * 0.5, "1"),
        (B + u3 * v.scale.model(8.0), "2"),
        (O1 + (C - O1) * 0.55, "3"),
        (C + u3 * v.scale.model(9.0), "4"),
        (O2 + (C - O2) * 0.5, "5"),
    ):
        v.label(q, n, 3.5, clear=0.8)
    # the given geometry, dimensioned
    v.dim_angle(O1, O2, C, "α", r_mm=16.0, height=3.5)
    l_ab, l12 = (
        num(A.dist(B) * 1000.0),
        num(O1.dist(O2) * 1000.0),
    )
    v.dim_linear(A, B, f"l_{{AB}} = {l_ab}", offset=-10.0, height=2.5)
    v.dim_linear(O1, O2, f"l_{{O1O2}} = {l12}", offset=-22.0, height=2.5)


def _results(sol: Solution[Geometry], kv: Scale | None) -> V.Table:
    """The results with their lengths on the plan (velocities) at ``kv``."""

    def on_plan(spec: V.Spec, x: object) -> str:
        if kv is None or spec.unit != "m/s" or not isinstance(x, int | float):
            return ""
        return num(kv.mm(float(x)), 3)

    return V.Table.of_specs(
        RESULTS, sol.results, labels={"F_red": WORDS("F_red")}, style="value",
        extra=(WORDS("h_on_plan"), on_plan), row_h=5.5, title=WORDS("results_title"),
    )  # fmt: skip


def _data(sol: Solution[Geometry]) -> V.Table:
    return V.Table.of_specs(PARAMS, sol.params, style="value",
                            row_h=5.5, title=WORDS("data_title"))  # fmt: skip
