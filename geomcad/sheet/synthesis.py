"""The synthesis sheet of a linkage file with a ``[synthesis]`` table (issue 31).

The kinematic sheet of a linkage is full (the mechanism in its numbered positions, a velocity
plan for each, the acceleration plans, the diagrams), so the synthesis is a sheet of its own,
the first of the set, as a course project starts with it: A3, or A2 where A3 would draw the
crank shorter than the kinematic sheet's 30 mm. Left: the construction replayed by
its steps' roles (:mod:`geomcad.sheet.replay`): the output's extreme positions, the chord and
the θ-circle (the perpendicular at B0 and the ray at 90° − θ meeting in P), the offset line,
the pivot found, the crank and rod at both dead centres in phantom lines and the crank's
circle; dimensioned here: θ at the pivot (the lever's swing θ at C for the slotted lever), the
offset e. Right: the given data, the lengths found and the order of construction written from
the recorded steps (templates in ``strings/<lang>/synthesis.toml``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from geomcad.construction import Construction
from geomcad.geom import Vec
from geomcad.linkage import synthesis as syn_mod
from geomcad.sheet import Scale, Sheet, TitleBlock, Viewport, start
from geomcad.sheet.compose import Column, Field, Layout, Row, arrange, compose
from geomcad.sheet.lang import Words, current
from geomcad.sheet.linkage import CRANK_MM
from geomcad.sheet.replay import Replay, extent
from geomcad.sheet.views import Steps, Table, num

if TYPE_CHECKING:
    from geomcad.linkage.solution import Solved
    from geomcad.linkage.synthesis import Synthesis

WORDS = Words("geomcad.sheet", "synthesis")
KIN_WORDS = Words("geomcad.sheet", "linkage")

#: The formats tried, smallest first, and the crank's least length on the drawing (mm), as the
#: kinematic sheet asks it (geomcad/sheet/linkage.py).
FORMATS = ("A3", "A2", "A1")
FALLBACK = "A2"


#: Width (mm) of the order of construction's text.
ORDER_W = 150.0

#: The steps the order of construction lists (those a kind records, in their recorded order).
ORDER = ("θ", "l1", "l2", "C", "O", "B0", "B1", "x-x", "n0", "r1", "P", "Γ", "Γ'", "kO", "m",
         "t0", "t1", "A0", "A1", "OB0", "OB1", "p0", "p1", "l3", "D0", "D1",
         "γmin", "H_check")  # fmt: skip

#: The given data and results as the sheet writes them: key → (symbol, unit).
SYMBOLS: dict[str, tuple[str, str]] = {
    "stroke": ("H", "m"),
    "K": ("K", ""),
    "lambda": ("λ", ""),
    "offset": ("e", "m"),
    "swing_deg": ("ψ", "°"),
    "rocker": ("l_3", "m"),
    "frame": ("l_0", "m"),
    "rod": ("l_{BD}", "m"),
    "theta_deg": ("θ", "°"),
    "l1": ("l_1", "m"),
    "l2": ("l_2", "m"),
    "l3": ("l_3", "m"),
    "gamma_min_deg": ("γ_{min}", "°"),
}


def with_sheet(s: Solved, stem: str, sheets: list[tuple[str, Sheet]]) -> list[tuple[str, Sheet]]:
    """``sheets`` with the synthesis sheet first where ``s`` was found by a synthesis."""
    syn = syn_mod.of(s)
    if syn is None:
        return sheets
    return [("synthesis", synthesis_sheet(syn, stem)), *sheets]


def _rows(values: dict[str, float]) -> list[list[str]]:
    m = WORDS("m")
    rows = [[WORDS("quantity"), WORDS("value")]]
    for k, v in values.items():
        sym, unit = SYMBOLS.get(k, (k, ""))
        u = {"m": f", {m}", "°": ", °", "": ""}[unit]
        rows.append([f"{sym}{u}", num(v, 4)])
    return rows


def _extras(syn: Synthesis) -> object:
    c = syn.construction

    def draw(v: Viewport) -> None:
        pivot = c["O"]
        for name in ("O", "C"):
            if name in c:
                v.pivot(c[name])
        theta = syn.results["theta_deg"]
        if syn.kind == "slotted-lever":
            v.dim_angle(c["C"], c["B0"], c["B1"], f"θ = {num(theta, 4)}°", r_mm=25.0)
        elif theta > 0.0:
            v.dim_angle(pivot, c["B0"], c["B1"], f"θ = {num(theta, 4)}°", r_mm=20.0)
        e = syn.given.get("offset", 0.0)
        if syn.kind == "slider-crank" and e > 0.0:
            foot = Vec(pivot.x, 0.0)
            v.dim_linear(foot, pivot, f"e = {num(e, 4)}", offset=10.0 if pivot.y > 0 else -10.0)
        if syn.kind == "crank-rocker":
            psi = syn.given["swing_deg"]
            v.dim_angle(c["C"], c["B0"], c["B1"], f"ψ = {num(psi, 4)}°", r_mm=12.0)
        H = syn.given.get("stroke")
        ends = ("B0", "B1") if syn.kind == "slider-crank" else ("D0", "D1")
        if H is not None and all(n in c for n in ends):  # the stroke between the extremes
            a, b = sorted((c[n] for n in ends), key=lambda q: q.x)
            v.dim_linear(
                a, b, f"H = {num(H, 4)}", offset=12.0 if syn.kind != "slider-crank" else -12.0
            )
        for name in ends:
            if name in c:
                v.slider(c[name])

    return draw


def synthesis_scale(syn: Synthesis) -> float:
    """k_l (m/mm) of the synthesis sheet's drawing."""
    return _arranged(syn)[2].k


def _arranged(syn: Synthesis) -> tuple[Row, Layout, Scale, str]:
    """The sheet's tree, its arrangement, k_l of the drawing and the format: the smallest of
    :data:`FORMATS` on which the crank is drawn at least :data:`CRANK_MM` long, else
    :data:`FALLBACK`."""
    c: Construction = syn.construction
    box = extent(c)
    pad = 0.08 * max(box[2] - box[0], box[3] - box[1])
    box = (box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad)
    title = WORDS("title_lambda" if "lambda" in syn.given else "title")
    labels = {"Γ": "Γ", "Γ'": "Γ'", "x-x": "x–x", "m": "m"}
    only: Sequence[str] = [n for n in ORDER if n in c]
    made: dict[str, tuple[Row, Layout, Scale]] = {}
    for fmt in FORMATS:
        fig = Replay(c, labels=labels, box=box, extra=_extras(syn), title=title, weight=2.0)  # type: ignore[arg-type]
        given = Table(_rows(syn.given), title=WORDS("data"))
        found = Table(_rows(syn.results), title=WORDS("results"))
        order = Steps(c, ORDER_W, only=only, words=WORDS)
        tree = Row(fig, Column(Row(given, found), order))
        lay: Layout = arrange(tree, Field.of_format(fmt))
        got = lay[fig].scale
        k = got if got is not None else Scale(0.001, "l")
        made[fmt] = (tree, lay, k)
        if syn.results["l1"] / k.k >= CRANK_MM:
            return tree, lay, k, fmt
    # no format draws the crank that long: A2, as A1 would stay half empty
    return (*made[FALLBACK], FALLBACK)


def synthesis_sheet(syn: Synthesis, stem: str = "") -> Sheet:
    """The synthesis sheet (landscape, composed; see the module's docstring)."""
    tree, lay, k, fmt = _arranged(syn)
    tb = TitleBlock(
        title=WORDS("tb_title"),
        designation=KIN_WORDS("designation", stem=stem or KIN_WORDS("stem")),
        scale=k.ratio_text(),
        lang=current(),
    )
    d = start(fmt, tb)
    compose(d, tree, layout=lay)
    return d.finish()


__all__ = ["synthesis_sheet", "with_sheet"]
