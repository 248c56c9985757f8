"""2013-3's drawing sheet: the mechanism with a cross at k_l and its velocity plan at k_v.

A3 landscape, composed by :mod:`geomcad.sheet.compose` (no hand-placed view): the mechanism at
the largest GOST scale its box allows, with the links numbered, the angle α and the lengths
dimensioned, the given velocity V_A and the senses of ω3, ω5 and M; the velocity plan, each
vector equation drawn as its two lines meeting, at a factor 1, 2, 2.5, 4 or 5 × 10^n; the given
data, the results and the vector equations in the order they were solved. :func:`scales` gives
the layout's factors without drawing (``Problem.scales``).

The mechanism is :class:`~geomcad.sheet.views.Scheme` of the model's
:class:`~geomcad.structure.Mechanism` (its symbols, supports and numbers as every scheme
draws them); what the scheme adds (the given V_A, the senses, the dimensions) is drawn on it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.geom import Vec
from geomcad.sheet import Scale, Sheet, Viewport
from geomcad.sheet import views as V
from geomcad.sheet.compose import (
    Column,
    Field,
    Row,
    Spacer,
    Tree,
    arrange,
)
from geomcad.sheet.form import composed
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.scheme import Body
from geomcad.sheet.views import num

from .spec_2013_3 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.construction import Construction
    from geomcad.problem import Solution

    from .p2013_3 import Geometry

#: The given velocity's arrow: its length and its height over A (paper mm).
VA_LEN, VA_LIFT = 14.0, 7.0
#: Width (mm) of the order of construction's text.
ORDER_W = 150.0
#: The title block's height (mm): the right-hand column keeps it free.
BLOCK_H = 52.0
WORDS = Words(__package__, "sheets_2013_3")


def extent(c: Construction, l_ab: float) -> tuple[float, float, float, float]:
    """The model box the mechanism drawing needs: the links, the slots run past C and O2."""
    return V.extent_of((c[n] for n in ("O1", "O2", "A", "B", "C")), 0.35 * l_ab)


def _views(sol: Solution[Geometry], kv: Scale | None = None) -> tuple[Tree, V.Scheme, V.PlanView]:
    """The sheet's tree: the mechanism over the data and the order of construction, the plan
    over the results (their lengths on the plan at ``kv``; the table's size does not depend on
    it, so the layout can be arranged before the scales are known)."""
    geo, c = sol.data, sol.construction
    x0, y0, x1, y1 = extent(c, geo.l_AB)
    scheme = V.Scheme(
        geo.mechanism,
        _bodies(c, geo.l_AB),
        pair_labels=PAIR_LABELS,
        link_labels=_link_at(c, geo.l_AB),
        supports={"O1": _o1_support(c)},
        extra=lambda v: _given(v, geo, c),
        also=[Vec(x0, y0), Vec(x1, y1)],
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
    return [("", composed("A3", tree, WORDS, k.ratio_text()))]


#: The mechanism's pairs named by the scheme (one name per point; A and C are named beside
#: their blocks, see :func:`_given`).
PAIR_LABELS = {"O1": "O_1", "O2": "O_2", "B": "B"}
#: The slotted link 3 runs past B and C, link 5 past C, by this share of l_AB; the numbers of
#: the block 2 and the cross 4 stand this far along the slot from B and from C.
RUN, BLOCK_NO, CROSS_NO = 0.28, 0.16, 0.18


def _o1_support(c: Construction) -> tuple[float, float]:
    """O1's support turned away from the rocker that passes through it and from O1O2 (the sense
    of ω3 is drawn on the other side): along the bisector of the angle between the rocker's
    lower half (towards B) and O1O2."""
    O1, O2, B = (c[n] for n in ("O1", "O2", "B"))
    n3 = ((B - O1).unit() + (O2 - O1).unit()).unit()
    return (n3.x, n3.y)


def _bodies(c: Construction, l_ab: float) -> dict[str, list[Body]]:
    """The rocker 3 as the slot's line B–O1–C run past B and C; link 5 run past C."""
    O2, B, C = (c[n] for n in ("O2", "B", "C"))
    u3, u5 = (C - B).unit(), (C - O2).unit()
    ext = RUN * l_ab
    return {"3": [Body.of([B - u3 * ext, C + u3 * ext])], "5": [Body.of([O2, C + u5 * ext])]}


def _link_at(c: Construction, l_ab: float) -> dict[str, Vec]:
    """Where the links' numbers stand: 2 and 4 along the slot from their blocks."""
    O1, O2, A, B, C = (c[n] for n in ("O1", "O2", "A", "B", "C"))
    u3 = (C - B).unit()
    return {
        "1": A + (B - A) * 0.5,
        "2": B + u3 * (BLOCK_NO * l_ab),
        "3": O1 + (C - O1) * 0.55,
        "4": C + u3 * (CROSS_NO * l_ab),
        "5": O2 + (C - O2) * 0.5,
    }


def _given(v: Viewport, geo: Geometry, c: Construction) -> None:
    """What the scheme adds to the mechanism: link 1's block on its guide (named A), C's name
    beside the cross, the given
    V_A, the senses of ω3 (= ω5) and of M, the line O1O2, and the given angle and lengths
    dimensioned."""
    O1, O2, A, B, C = (c[n] for n in ("O1", "O2", "A", "B", "C"))
    v.slider(A, Vec(1.0, 0.0), with_joint=False)
    v.label(A, "A", prefer=(-1.0, 1.0), clear=3.0)
    v.label(C, "C", prefer=(-1.0, 1.0), clear=5.0)  # clear of the cross's two blocks
    v.seg(O1, O2, "centre")
    sgn = 1.0 if geo.v_A > 0 else -1.0
    tip = A + Vec(sgn * v.scale.model(VA_LEN), 0.0)
    lift = Vec(0.0, v.scale.model(VA_LIFT))
    v.arrow(A + lift, tip + lift, "result")
    v.label(tip + lift, "V_A", 3.5, prefer=(0.0, 1.0), clear=1.0)
    w3 = c["ω3"]
    # each arrow keeps its 100° span whatever its sense: it starts at the span's far end
    a3 = math.degrees((C - O1).angle) + 20.0
    v.turn(O1, w3, a3 if w3 > 0 else a3 + 100.0, "ω_3")
    m_sense = -w3 * (1.0 if geo.M >= 0 else -1.0)  # M resists the motion when M > 0
    v.turn(O2, m_sense, -60.0 if m_sense > 0 else 40.0, "M")
    v.dim_angle(O1, O2, C, "α", r_mm=16.0, height=3.5)
    l_ab, l12 = num(A.dist(B) * 1000.0), num(O1.dist(O2) * 1000.0)
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
