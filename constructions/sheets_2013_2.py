"""2013-2's drawing sheet: the cam profile by inversion, the S(φ) graph and the velocity plan.

A2 landscape. Left: the profile at k_l (the seed's 2:1 when it fits; else the largest GOST scale
that does) with the base circle, the follower turned back to each division point (its axis and its
face, or its tip, or its roller), the profile, and the radius vectors r_i dimensioned; the rest of
the program past the span (the seed's second half of the rise) in thin lines, so that the cam's
shape is seen whole; a closed program is drawn as its full turn. Below it the follower's law S(φ)
with the ordinates of the division points. Right: the mechanism at the plan's division point with
the velocity plan pb₁b₂ (with the lines of its equation) and the similar triangle OBB′
(OB′ = BC = S′), the given data, the results and the order of construction.

Composed from the general views: the profile by inversion and the mechanism at a position
(:mod:`geomcad.sheet.cams`), the plan (:class:`~geomcad.sheet.views.PlanView` of the recorded
plan), the diagrams, tables and the order of construction (:mod:`geomcad.sheet.views`).
Scale choice lives here (:func:`scales`): the problem's build returns only its model.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING

import numpy as np

from geomcad import tol
from geomcad.problem import ResultSpec
from geomcad.sheet import Scale, Sheet
from geomcad.sheet import views as V
from geomcad.sheet.cams import CamAt, Inversion, label_step
from geomcad.sheet.compose import (
    Column,
    Field,
    Layout,
    Node,
    Row,
    Spacer,
    View,
    arrange,
)
from geomcad.sheet.drawing import DOT_R
from geomcad.sheet.form import composed
from geomcad.sheet.graph import Graph
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.text import wrap
from geomcad.sheet.views import num

from .spec_2013_2 import PARAMS, RESULTS

if TYPE_CHECKING:
    from geomcad.construction.recorder import Step
    from geomcad.problem import Solution

    from .p2013_2 import Geometry

WORDS = Words(__package__, "sheets_2013_2")
MM = 1000.0
#: Paper margin (mm) the face lines and labels take beyond the profile.
VIEW_PAD = 6.0
#: Rows a results table shows at most (the first, the last and evenly spaced ones between).
MAX_ROWS = 7
#: Width (mm) of the panel's text, and the title block's height (kept free under the panel).
PANEL_W = 250.0
#: Width and letter height (mm) of the order of construction.
ORDER_W = 280.0
ORDER_H = 2.5
BLOCK_H = 52.0


# -- views and scales ------------------------------------------------------------------------------


class _Views:
    """The sheet's views and their tree (composed by :mod:`geomcad.sheet.compose`)."""

    def __init__(self, sol: Solution[Geometry]) -> None:
        geo = sol.data
        f = geo.follower
        rest_text = ""
        if geo.rest is not None:
            rest_text = WORDS("rest_end", phi=num(math.degrees(float(geo.rest.phi[-1]))))
        self.profile = Inversion(
            f, geo.profile, geo.divisions, geo.closed, geo.rest, rest_text,
            title=WORDS("profile_title"), title_height=5.0, margin=VIEW_PAD, weight=3.0,
        )  # fmt: skip
        left: list[View | Node] = [self.profile]
        if geo.rest is not None:
            span, end = math.degrees(float(geo.span)), math.degrees(float(geo.rest.phi[-1]))
            left.append(V.Text([WORDS("rest_note", span=num(span), end=num(end))], height=2.5))
        law = WORDS(f"law_{sol.params['law']}")
        left.append(Row(*_diagrams(sol), weights=(1.0, 1.0), title=WORDS("graph_title", law=law)))
        steps = order_steps(sol)
        plan = geo.plan
        phi = math.degrees(plan.phi)
        self.scheme = CamAt(
            f, geo.profile, plan, geo.closed, geo.rest,
            title=WORDS("scheme_title", i=geo.plan_index, phi=num(phi)), margin=6.0, weight=2.0,
        )  # fmt: skip
        self.plan = V.PlanView(geo.recorded, title=WORDS("plan_title"), margin=8.0)
        eq = "OB' = BC = S'" if f.kind == "flat" else "OB' = S'"
        right: list[View | Node] = [
            Row(self.scheme, self.plan),
            V.Text([f"{WORDS('scheme_note', eq=eq)} {WORDS('plan_omega')}"], height=2.5),
            *_tables(sol),
            V.Text(_notes(sol), width=PANEL_W, height=3.0),
            V.Steps(
                steps, ORDER_W, only=[st.name for st in steps], height=ORDER_H, words=WORDS,
                title_height=5.0,
            ),
            Spacer((10.0, BLOCK_H)),
        ]  # fmt: skip
        self.tree = Row(Column(*left), Column(*right), weights=(1.0, 1.0))

    def scales(self, lay: Layout) -> dict[str, float]:
        k_l, k_v = lay[self.profile].scale, lay[self.plan].scale
        assert k_l is not None and k_v is not None
        return {"l": k_l.k, "v": k_v.k}


@per_language
def scales(sol: Solution[Geometry]) -> dict[str, float]:
    """k_l of the profile and k_v of the velocity plan, as the layout chooses them (no drawing):
    each the largest of its series the view's box allows."""
    views = _Views(sol)
    return views.scales(arrange(views.tree, Field.of_format("A2")))


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-2."""
    k = Scale(scales(sol)["l"], "l")  # this layout's (in the language being drawn)
    return [("", composed("A2", _Views(sol).tree, WORDS, k.ratio_text()))]


# -- the law S(φ) ----------------------------------------------------------------------------------


def _diagrams(sol: Solution[Geometry]) -> list[V.Diagram]:
    """The follower's law S(φ) and its analogue of velocity S′(φ) = dS/dφ (the length BC = OB′
    of the scheme), side by side, with the ordinates of the division points."""
    geo = sol.data
    prog = geo.program
    end = 2.0 * math.pi if geo.closed else prog.total
    phi = np.linspace(0.0, end, 721)
    motion = prog.motion(phi)
    div = geo.divisions
    n = len(div.phi)
    step = label_step(n)
    out = []
    for sym, ys, at_div in (("S", motion.S, div.S), ("S'", motion.S1, div.S1)):

        def ordinates(g: Graph, at_div: np.ndarray = at_div) -> None:
            for i in range(n):
                x, y = float(div.phi[i]), float(at_div[i])
                mark = str(i) if i % step == 0 else ""
                if x != g.x.zero or not mark:
                    g.ordinate(x, y, mark)
                    continue
                # a division point on the ordinate axis: its number inside, right of the axis, not
                # over it where it would read as a tick value
                g.ordinate(x, y)
                up = -1.0 if y >= g.y.zero else 1.0
                g.d.label(g.p(x, y), mark, 2.5, prefer=(1.0, -up), clear=DOT_R)

        out.append(
            V.Diagram(
                V.AxisSpec("φ", WORDS("unit_rad"), lo=0.0, hi=end),
                V.AxisSpec(sym, WORDS("unit_m")),
                [V.Curve(phi, ys, "link")],
                extra=ordinates,
                least=(90.0, 45.0),
                prefer=(160.0, 70.0),
            )
        )
    return out


# -- the scheme and the velocity plan --------------------------------------------------------------


# -- tables ----------------------------------------------------------------------------------------


def _rows(n: int) -> list[int]:
    """The division points a table shows: all of them, or MAX_ROWS spread evenly."""
    if n <= MAX_ROWS:
        return list(range(n))
    idx = np.unique(np.round(np.linspace(0, n - 1, MAX_ROWS)).astype(int))
    return [int(i) for i in idx]


def _clean(x: float, size: float) -> float:
    """A value that is zero up to rounding (sin π …) printed as 0."""
    return 0.0 if abs(x) <= tol.DERIVED * size else x


#: The columns of the results table (mm); the data table above it is as wide.
RESULTS_W = (24.0, 64.0, 64.0, 64.0, 64.0)


def _tables(sol: Solution[Geometry]) -> list[V.Table]:
    """The given data and the results at the division points."""
    p, r, geo = sol.params, sol.results, sol.data
    law = str(p["law"])
    step_deg = num(math.degrees(geo.span) / int(p["n_div"]), 3)
    shown = {
        **p,
        "law": WORDS(f"short_{law}"),
        "follower": WORDS(f"f_{p['follower']}"),
        "omega_sign": WORDS("ccw" if int(p["omega_sign"]) > 0 else "cw"),
        "n_div": f"{p['n_div']} × {step_deg}°",
    }
    by = {s.name: s for s in PARAMS}
    names = ("H", "r0", "n_div", "phi_rise_deg", "phi_dwell_deg", "phi_return_deg", "law",
             "follower", "omega_sign", "e", "r_roller")  # fmt: skip
    labels = {n: WORDS(k) for n, k in (
        ("r0", "c_r0"), ("n_div", "c_intervals"), ("phi_rise_deg", "c_rise"),
        ("phi_dwell_deg", "c_dwell"), ("phi_return_deg", "c_return"), ("law", "c_law"),
        ("follower", "c_follower"), ("r_roller", "c_roller"),
    )}  # fmt: skip
    data = V.Table.of_specs(
        [by[n] for n in names], shown, labels=labels, style="value", pairs=4, header=False,
        height=3.5, row_h=6.0, fill=sum(RESULTS_W), title=WORDS("data_title"), title_height=5.0,
    )  # fmt: skip
    spec = {s.name: s for s in RESULTS}
    s1 = ResultSpec("S1", "m", "S′ at the division points", symbol="S'_i", display="mm")
    idx = _rows(len(r["phi"]))
    H = geo.program.H
    table = V.Table.of_series(
        [
            (spec["phi"], [float(r["phi"][i]) for i in idx]),
            (spec["S"], [_clean(float(r["S"][i]), H) for i in idx]),
            (s1, [_clean(float(geo.divisions.S1[i]), H) for i in idx]),
            (spec["r"], [float(r["r"][i]) for i in idx]),
        ],
        index=("i", [str(i) for i in idx]),
    )
    a = V.Table.of_specs([spec["a"]], r, style="label", header=False).rows[0]
    results = V.Table(
        [*table.rows, [a[0], "", "", "", a[1]]], widths=RESULTS_W,
        height=3.5, row_h=6.5, title=WORDS("results_title"), title_height=5.0,
    )  # fmt: skip
    return [data, results]


def order_steps(sol: Solution[Geometry]) -> list[Step]:
    """The steps of the order of construction, in the order a student writes them: the base
    circle and the division, the steps of one division written for any index i ("for each
    φ_i"), the profile, then the velocity plan at the plan's division point (its pole, its
    points, the vector read off) and the similar triangle OBB′."""
    c = sol.construction
    one = 1 if len(sol.data.divisions.phi) > 1 else 0
    each = [f"axis_{one}", f"C_{one}", f"face_{one}", f"B_{one}"]
    plan = ["B", "p", "b1", "b2", "pb2", "B′"]
    names = ["base", "Δφ", *(n for n in each if n in c), "profile", *plan]
    return [_for_each(c.step(n)) if n in each else c.step(n) for n in names]


def _for_each(step: Step) -> Step:
    """A division's step written for any division: its index operand ``i`` as the letter i."""
    return dataclasses.replace(step, args=tuple((k, "i" if k == "i" else v) for k, v in step.args))


def _notes(sol: Solution[Geometry]) -> list[str]:
    """The sheet's notes, wrapped to the panel: the summary, the radius formula, what happens at
    a jump of S′."""
    geo = sol.data
    f = geo.follower
    r = sol.results
    out: list[str] = [
        WORDS("summary", rho=num(float(r["rho_min"]) * MM),
              alpha=num(float(r["pressure_angle_max_deg"]))),
    ]  # fmt: skip
    if f.kind == "flat":
        out.append(WORDS("note_radius"))
    if np.any(geo.profile.corner) and f.kind == "flat" and sol.params["law"] == "linear":
        out.append(WORDS("note_jump", a=num(float(sol.results["a"]) * MM)))
    return [line for par in out for line in wrap(par, PANEL_W, 3.0)]
