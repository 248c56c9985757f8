"""2013-1's drawing sheet: the structural schemes, the Assur groups and the dead position.

A2 landscape. Top: the structural scheme before the replacement (roller 6 in the slot of lever 1)
and after it (the substitute link 8, a slider block in the slot hinged to the roller at M, drawn
in red), both in the given position θ1 at one GOST scale; then the replaced mechanism without the
roller's spin, split into its Assur groups (drawn apart, each with its outer pairs). Bottom: the
position with ML ⊥ MO built (circle(O, |e|) that the slot always touches, the pusher path, their
common point M, the slot as the tangent there, OM and the right angle at M) with its velocity plan
(V_M1 = −V_M6M1, V_T = 0), and the velocity plan at the given θ1. Right: the links and pairs, the
W counts beside the seed's, the Assur groups, the zero positions and why the seed's "2 before, 1
after" differs from the standard rule.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geomcad.geom import Line, Vec
from geomcad.sheet import Scale, Sheet, Viewport
from geomcad.sheet import views as V
from geomcad.sheet.assur import group_schemes, groups_table, pairs_table
from geomcad.sheet.compose import (
    Column,
    Field,
    Figure,
    Layout,
    Row,
    View,
    arrange,
)
from geomcad.sheet.form import composed
from geomcad.sheet.lang import Words, per_language
from geomcad.sheet.scheme import Body
from geomcad.sheet.views import num
from geomcad.structure import Link

if TYPE_CHECKING:
    from geomcad.problem import Solution

    from .p2013_1 import Geometry

#: Width (mm) of the right-hand panel's text.
PANEL_W = 162.0
#: The title block's height (mm): the right-hand panel keeps it free.
BLOCK_H = 52.0
CIRCLE_STEPS = 48
#: Paper length (mm) of the construction lines through a plan's points.
PLAN_LINE = 14.0
WORDS = Words(__package__, "sheets_2013_1")
#: The order of construction (the steps constructions/p2013_1.py records with their kinds): the
#: position with V_T = 0 and its plan, then the plan at the given θ1.
ORDER = ("M", "k_e", "M*", "slot*1", "slot*2", "m1*", "m6*", "m1", "m6", "V_T/ω1")


def _lid_end(pts: dict[str, Vec]) -> Vec:
    return pts["D"] + (pts["E"] - pts["D"]) * 1.6


def _slot_corners(start: Vec, end: Vec, r: float) -> list[Vec]:
    u = (end - start).unit()
    n = u.perp() * r
    return [start - n, end - n, end + n, start + n]


def _scheme_points(geo: Geometry) -> list[Vec]:
    pts = geo.points
    keys = ("O", "N", "C", "A", "B", "M", "T", "F", "E", "D", "S0", "L")
    out = [pts[k] for k in keys] + [_lid_end(pts)]
    r = pts["R"].x
    out += [pts["M"] + Vec(r, r), pts["M"] - Vec(r, r)]
    return out


def _position_points(geo: Geometry) -> list[Vec]:
    e = abs(geo.e)
    z = geo.zeros[geo.built]
    up = Vec(math.cos(geo.psi), math.sin(geo.psi))
    out = [Vec(-e, -e), Vec(e, e), z.L, z.M - z.u1 * (0.6 * e)]
    out += [z.M + up * (1.7 * e), z.M - up * (0.4 * e)]
    for q in geo.zeros:
        out += [q.L + q.u1 * (0.3 * e), q.M - q.u1 * (0.9 * e)]
    return out


def _caption(view: V.Scheme, text: str) -> None:
    """``text`` over the top left corner of the scheme's drawing, inside its margin."""
    ext = view.extent()
    assert ext is not None

    def draw(v: Viewport) -> None:
        x, y = v.p((ext[0], ext[3]))
        v.d.text(text, (x, y - 4.0), 3.5)

    view.extra = draw


class _Rest(View):
    """The rest of a column of tables and text (it keeps them together at the top, and its box
    takes the title block's corner): draws nothing, and is always content with its box."""

    def __init__(self) -> None:
        super().__init__(margin=0.0)

    def stretch(self) -> tuple[tuple[float, float], tuple[float, float]]:
        return (1.0, BLOCK_H), (1.0, BLOCK_H)


class _Views:
    """The sheet's views and their tree (composed by :mod:`geomcad.sheet.compose`)."""

    def __init__(self, sol: Solution[Geometry]) -> None:
        geo = sol.data
        rep = geo.replaced.mechanism
        self.before = V.Scheme(
            geo.before,
            _bodies(geo, roller=False),
            pair_labels=PAIR_TEXT,
            link_labels={k: v for k, v in _link_at(geo).items() if k != "8"},
            also=_scheme_points(geo),
            group="s",
        )
        self.after = V.Scheme(
            rep,
            _bodies(geo, roller=True),
            highlight=[s.link for s in geo.replaced.substitutes],
            pair_labels=PAIR_TEXT,
            link_labels=_link_at(geo),
            also=_scheme_points(geo),
            group="s",
        )
        # each scheme's counts over its drawing (the row's title states the common scale)
        _caption(
            self.before, WORDS("before_title", n=geo.before.n, p5=geo.before.p5, p4=geo.before.p4)
        )
        _caption(self.after, WORDS("after_title", n=rep.n, p5=rep.p5, p4=rep.p4))  # fmt: skip
        t1 = num(math.degrees(geo.theta1) % 360.0, 5)
        schemes = Row(
            self.before, self.after, weights=(1.0, 1.0), title=WORDS("schemes_title", th=t1),
            group="s",
        )  # fmt: skip
        groups = Column(
            *group_schemes(geo.seed_route, geo.decomposition, _bodies(geo, roller=False),
                           label_height=2.5, title_height=2.5, group="g", show_scale=False,
                           margin=6.0),
            title=WORDS("groups_title"), group="g",
        )  # fmt: skip
        self.position = Figure(
            V.extent_of(_position_points(geo)),
            lambda v: _position(v, geo),
            title=WORDS("position_title"),
            title_height=5.0,
            margin=8.0,
            weight=2.0,
        )
        pts = geo.points
        z = geo.zeros[geo.built]
        th = num(math.degrees(z.theta1) % 360.0, 5)
        vt = num(float(pts["m6"].dot(Vec(math.cos(geo.psi), math.sin(geo.psi)))), 5)
        origin = Vec(0.0, 0.0)
        self.plan_zero = Figure(
            V.extent_of([origin, pts["m1*"]]),
            lambda v: _plan_zero(v, geo),
            title=WORDS("plan_zero", th=th),
            show_scale=False,
            quantity="v",
            series="nice",
            group="v",
            margin=PLAN_LINE,
            readable=pts["m1*"].norm,
        )
        self.plan_given = Figure(
            V.extent_of([origin, pts["m1"], pts["m6"]]),
            lambda v: _plan_given(v, geo),
            title=WORDS("plan_given", th=t1, vt=vt),
            show_scale=False,
            quantity="v",
            series="nice",
            group="v",
            margin=PLAN_LINE,
        )
        plans = Column(
            self.plan_zero, self.plan_given, weights=(1.0, 1.0), title=WORDS("plans_title"),
            group="v",
        )  # fmt: skip
        panel = Column(*_panel(sol, geo), _Rest(), gap=2.0)
        self.tree = Row(
            Column(Row(schemes, groups, weights=(2.0, 1.0)), Row(self.position, plans)),
            panel,
        )

    def scales(self, lay: Layout) -> dict[str, float]:
        """k_l of the schemes ("l"), of the dead-position drawing ("l_pos"), k_v of the plans."""
        k_pos = lay[self.position].scale
        assert k_pos is not None
        return {"l": lay.scale("s").k, "l_pos": k_pos.k, "v": lay.scale("v").k}


@per_language
def scales(sol: Solution[Geometry]) -> dict[str, float]:
    """The layout's scale factors (no drawing): see :meth:`_Views.scales`."""
    views = _Views(sol)
    return views.scales(arrange(views.tree, Field.of_format("A2")))


def sheets(sol: Solution[Geometry]) -> list[tuple[str, Sheet]]:
    """The main sheet of 2013-1."""
    got = scales(sol)  # this layout's (in the language being drawn), which compose() repeats
    ks, kp = Scale(got["l"], "l"), Scale(got["l_pos"], "l")
    ratio = ks.ratio_text() + ("" if kp.k == ks.k else f"; {kp.ratio_text()}")
    return [("", composed("A2", _Views(sol).tree, WORDS, ratio))]


# -- the schemes ------------------------------------------------------------------------------


def _circle(c: Vec, r: float) -> Body:
    return Body.of(
        [c + Vec.polar(r, 2.0 * math.pi * i / CIRCLE_STEPS) for i in range(CIRCLE_STEPS)],
        closed=True,
    )


def _bodies(geo: Geometry, roller: bool) -> dict[str, list[Body]]:
    """The bodies of the vulcanizer's links that are not plain lines between pairs."""
    p = geo.points
    r = p["R"].x
    n1 = (p["L"] - p["S0"]).unit().perp()
    # the lever's arm from O ends on the slot's side facing O
    side = 1.0 if n1.dot(p["N"]) > 0.0 else -1.0
    out = {
        "1": [
            Body.of([p["C"], p["O"], p["N"] - n1 * (side * r)]),
            Body.of(_slot_corners(p["S0"], p["L"], r), closed=True),
        ],
        "4": [Body.of([p["D"], p["E"], _lid_end(p)])],
        "7": [Body.of([p["M"], p["F"]])],
    }
    if roller:
        out["6"] = [_circle(p["M"], r)]
    return out


PAIR_TEXT = {k: k for k in ("O", "A", "B", "C", "M", "T", "D", "E", "F", "K")}


def _link_at(geo: Geometry) -> dict[str, Vec]:
    """Link numbers that need a place of their own: roller 6 above the slot, block 8 below."""
    p = geo.points
    r = p["R"].x
    n1 = (p["L"] - p["S0"]).unit().perp()
    away = n1 if n1.dot(p["N"]) > 0.0 else -n1  # from O's side of the slot to the far side
    along = (p["L"] - p["S0"]).unit()
    return {
        "6": p["M"] + away * (2.2 * r) + along * (2.5 * r),
        "7": p["M"] + (p["F"] - p["M"]) * 0.85,
        "8": p["M"] - away * (2.2 * r),
    }


# -- the dead position and the plans ----------------------------------------------------------


def _position(v: Viewport, geo: Geometry) -> None:
    """The position with ML ⊥ MO built: circle(O, |e|), the pusher's path, M, the slot as the
    tangent there, OM and the right angle at M; the other zero position in two-dot lines."""
    k = v.scale
    z = geo.zeros[geo.built]
    e = abs(geo.e)
    r = geo.points["R"].x
    up = Vec(math.cos(geo.psi), math.sin(geo.psi))
    th = num(math.degrees(z.theta1) % 360.0, 5)
    O_ = Vec(0.0, 0.0)
    v.circle(O_, e, "construction")
    path = Line(up.perp() * geo.h, up)
    v.line_over(path, [q.M for q in geo.zeros] + [path.foot(O_)], "centre", over=18.0)
    # the other zero position (GOST 2.303: thin two-dot lines): lever 1's slot outline and its
    # arm from O, the point M* where it touches the circle (named inside the outline)
    for i, q in enumerate(geo.zeros):
        if i == geo.built:
            continue
        nq = q.u1.perp()
        sq = 1.0 if nq.dot(q.M) > 0.0 else -1.0
        a, b = q.M - q.u1 * (0.6 * e), q.L
        v.polyline(_slot_corners(a, b, r), "extreme", closed=True)
        v.seg(O_, q.M - nq * (sq * r), "extreme")
        v.dot(q.M, "result")
        v.label(q.M, "M*", height=2.5, prefer=(q.u1.x, q.u1.y))
        tq = num(math.degrees(q.theta1) % 360.0, 5)
        v.label(b, f"θ_1 = {tq}°", height=2.5, prefer=(1.0, -1.0))
    # the built position: lever 1 with its slot tangent to the circle at M
    n1 = z.u1.perp()
    side = 1.0 if n1.dot(z.M) > 0.0 else -1.0
    start_ = z.M - z.u1 * (0.6 * e)
    v.polyline(_slot_corners(start_, z.L, r), "link", closed=True)
    v.seg(O_, z.M - n1 * (side * r), "link")
    v.seg(start_ - z.u1 * (0.3 * e), z.L + z.u1 * (0.3 * e), "centre")
    v.pivot(O_, (-(z.M.x), -(z.M.y)))
    # pusher 7 with roller 6 at M
    v.circle(z.M, r, "link")
    v.seg(z.M, z.M + up * (1.6 * e), "link")
    g0, g1 = z.M + up * (0.75 * e), z.M + up * (1.05 * e)
    n = up.perp()
    v.guide(g0, g1, (n.x, n.y))
    v.guide(g1, g0, (-n.x, -n.y))
    v.joint(z.M)
    # OM ⊥ ML: the lever's arm is OM itself
    v.right_angle(z.M, O_, z.L, r / k.k + 5.0)
    v.dot(z.L, "result")
    v.label(O_, "O", prefer=(-1.0, -1.0), clear=3.0)
    v.label(z.M, "M*", prefer=(1.0, 1.0), clear=r / k.k + 0.5)
    v.label(z.L, "L", prefer=(0.0, 1.0))
    v.label(z.M + up * (1.6 * e), "7", prefer=(1.0, 0.0))
    v.label(z.M - z.u1 * r, "6", prefer=(-z.u1.x, -z.u1.y), clear=0.5)
    # lever 1's number beside its slot's outline, on the side away from O
    edge = z.L - z.u1 * (0.3 * e) + n1 * (side * r)
    v.label(edge, "1", prefer=(side * n1.x, side * n1.y), clear=0.5)
    v.label((O_ + z.M) * 0.5, "|e|", prefer=(-n1.x, -n1.y), height=2.5)
    v.label(z.L + z.u1 * (0.3 * e), f"θ_1 = {th}°", height=2.5, prefer=(1.0, -1.0))
    foot = path.foot(O_)
    if foot.norm > 0.0:
        mm = 1000.0
        v.dim_linear(O_, foot, f"|h| = {num(abs(geo.h) * mm, 4)}", 8.0, 2.5)


def _plan_zero(v: Viewport, geo: Geometry) -> None:
    """The plan of the zero position: pm1 and m1m6 on one line, m6 = p (V_T = 0)."""
    kv = v.scale
    up = Vec(math.cos(geo.psi), math.sin(geo.psi))
    m1 = geo.points["m1*"]
    p = Vec(0.0, 0.0)
    ext = kv.model(PLAN_LINE)
    v.seg(p - up * ext, p + up * ext, "construction")
    v.arrow(p, m1, "vector")
    off = m1.perp().unit() * kv.model(1.2)
    v.arrow(m1 + off, p + off, "result")
    v.label(p, "p, m_6", prefer=(-1.0, -1.0))
    v.label(m1, "m_1", prefer=(1.0, 1.0))
    v.label((p + m1) * 0.5, "V_{M1} = –V_{M6M1}", height=2.5, prefer=(-m1.y, m1.x))


def _plan_given(v: Viewport, geo: Geometry) -> None:
    """The plan at the given θ1: pm1 ⊥ OM, m1m6 along the slot, pm6 along the pusher's path."""
    kv = v.scale
    pts = geo.points
    up = Vec(math.cos(geo.psi), math.sin(geo.psi))
    p, m1, m6 = Vec(0.0, 0.0), pts["m1"], pts["m6"]
    u1 = Vec(math.cos(geo.theta1), math.sin(geo.theta1))
    ext = kv.model(PLAN_LINE)
    v.seg(m6 - u1 * ext, m6 + u1 * ext, "construction")
    v.seg(m6 - up * ext, m6 + up * ext, "construction")
    v.arrow(p, m1, "vector")
    if (m6 - m1).norm > 0.0:
        v.arrow(m1, m6, "vector")
    if m6.norm > 0.0:
        v.arrow(p, m6, "result")
    v.label(p, "p", prefer=(-1.0, -1.0))
    v.label(m1, "m_1", prefer=(1.0, 1.0))
    v.label(m6, "m_6", prefer=(1.0, -1.0))


# -- the panel --------------------------------------------------------------------------------


def _link_name(lk: Link) -> str:
    """A link's name in the language being drawn (the model's own name for a link the table
    does not know)."""
    try:
        return WORDS(f"link_{lk.id}")
    except LookupError:
        return lk.name


def _panel(sol: Solution[Geometry], geo: Geometry) -> list[View]:
    """The right-hand panel: the links, the pairs, the W counts, the Assur groups, the pusher's
    zero positions, each a table or a paragraph."""
    r = sol.results
    out: list[View] = []

    def text(markup: str) -> None:
        out.append(V.Text(paragraph=markup, width=PANEL_W))

    names = "; ".join(f"{lk.id} – {_link_name(lk)}" for lk in geo.before.links)
    out.append(
        V.Text(paragraph=f"{names}; {WORDS('link_8')}", width=PANEL_W, title=WORDS("links_title"))
    )
    subs = [geo.replaced.mechanism.pair(n) for s in geo.replaced.substitutes
            for n in (s.pair_a, s.pair_b)]  # fmt: skip
    out.append(pairs_table(geo.before, subs, row_h=5.0, title=WORDS("pairs_title")))
    text(WORDS("pairs_note"))
    n, p5, p4, _local = geo.counts
    rows = [[WORDS("h_quantity"), WORDS("h_count"), "W"]]
    if geo.counts_mode:
        formal = f"3·{n} – 2·{p5} – {p4}"
        after = f"3·{n + p4} – 2·{p5 + 2 * p4}"
    else:
        mb, ma = geo.mob_before, geo.mob_after
        formal = f"3·{mb.n} – 2·{mb.p5} – {mb.p4}"
        after = f"3·{ma.n} – 2·{ma.p5} – {ma.p4}"
    for name, label, how in (
        ("W_formal", WORDS("w_formal"), formal),
        ("W_local", WORDS("w_local"), WORDS("w_local_how")),
        ("W_true", WORDS("w_true"), WORDS("w_true_how")),
        ("W_after_replacement", WORDS("w_after"), after),
    ):
        rows.append([label, how, str(r[name])])
    out.append(V.Table(rows, fill=PANEL_W, row_h=5.0, title=WORDS("mobility_title")))
    text(WORDS("mobility_note"))
    dec = geo.decomposition
    out.append(groups_table(dec, fill=PANEL_W, row_h=5.0, title=WORDS("groups_table")))
    text(
        WORDS(
            "formula",
            formula=dec.formula().replace("→", "+"),
            cls=["", "I", "II", "III", "IV"][min(dec.mechanism_class, 4)],
        )
    )
    zs = ", ".join(f"{num(t, 6)}°" for t in r["zero_theta1_deg"])
    e, h_ = geo.e, geo.h
    psi = math.degrees(geo.psi)
    acos = math.degrees(math.acos(max(-1.0, min(1.0, h_ / e))))
    sweep = ", ".join(f"{num(t, 6)}°" for t in geo.sweep_zeros_deg) or WORDS("none")
    t1 = num(math.degrees(geo.theta1) % 360.0, 5)
    vt = num(float(r["VT_over_omega1"]), 6)
    check = f"{num(psi, 6)}° ± {num(acos, 6)}°"
    rows = [
        [WORDS("h_quantity"), WORDS("h_value")],
        [WORDS("zero_built"), zs],
        [WORDS("zero_check"), check],
        [WORDS("zero_sweep"), sweep],
        [WORDS("vt_at", th=t1), f"{vt} {WORDS('metre')}"],
    ]
    out.append(V.Table(rows, fill=PANEL_W, row_h=5.0, title=WORDS("pusher_title")))
    steps = [sol.construction.step(n) for n in ORDER]
    out.append(V.Steps(steps, PANEL_W, only=ORDER, words=WORDS))
    text(WORDS("four_bar_note"))
    if geo.counts_mode:
        text(WORDS("counts_note"))
    return out
