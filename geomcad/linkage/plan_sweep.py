"""The points of a linkage's velocity and acceleration plans over a whole sweep, as arrays.

:func:`geomcad.linkage.plans.construct` draws the plans of one crank angle as recorded steps;
an interactive page shows them at every angle of a turn, so this module reads the same plan
points off the sweep kernel's arrays (:func:`geomcad.linkage.sweep.sweep`) for all angles at
once, under the same names (:func:`~geomcad.linkage.plans.plan_name`; ``'`` on the
acceleration plan). A plan point is one of

- the pole (``p``, ``π``) and the frame points at it;
- a mechanism point ``x``: V_X, a_X from the sweep;
- the point of link L under a joint X that L does not carry (``d3``: a moving guide's point
  under its slider, ``a3``: an RPR's slotted link under its block): V = V_F + ω_L × FX,
  a = a_F + ε_L × FX − ω_L²·FX with F a point of L;
- the end of a known term of an acceleration equation: ``n_BA'`` = a_A + a^n_BA (a^n_BA =
  −ω²·AB), ``k_D'`` = the guide's point + a^k (a^k = 2ω_g × V_rel).

The tests hold every point to :func:`~geomcad.linkage.plans.construct` at the numbered
positions, so the names and values here are the recorded plans' own.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from geomcad.kinematics.chain import State
from geomcad.linkage.model import Linkage
from geomcad.linkage.plans import plan_name

Arr = npt.NDArray[np.float64]


def _perp(r: Arr) -> Arr:
    """r turned 90° counter-clockwise, row by row."""
    return np.stack([-r[:, 1], r[:, 0]], axis=1)


def _bases(lk: Linkage) -> dict[int, str]:
    """A point each moving link carries (the first of its handles on the plans)."""
    out = {1: lk.pivot}
    for g in lk.groups:
        a, b = g.links
        if g.kind == "RRR":
            out[a], out[b] = g.ends
        elif g.kind == "RRP":
            out[a], out[b] = g.ends[0], g.joint
        elif g.kind == "RPR":
            out[a], out[b] = g.slider, g.pivot
        else:  # PRP: the block and the yoke
            out[a], out[b] = g.slider, g.joint
    return out


def plan_points(lk: Linkage, st: State) -> tuple[dict[str, Arr], dict[str, Arr]]:
    """The velocity plan's and the acceleration plan's points over the sweep ``st`` (taken with
    ``order`` 2): name → ``(N, 2)`` in m/s and m/s² from the pole (module docstring)."""
    n = st.phi.shape[0]
    zero = np.zeros((n, 2))
    taken = frozenset(lk.owner)
    vp: dict[str, Arr] = {"p": zero}
    ap: dict[str, Arr] = {"π": zero}
    pos, vel, acc, w, e = st.pos, st.vel, st.acc, st.omega, st.eps
    for name in pos:
        own = plan_name(name, taken, lk.owner.get(name, 0))
        vp[own] = np.asarray(vel[name])
        ap[own + "'"] = np.asarray(acc[name])
    base = _bases(lk)

    def on_link(link: int, x: str) -> tuple[Arr, Arr]:
        f = base[link]
        r = pos[x] - pos[f]
        wl, el = w[link][:, None], e[link][:, None]
        return vel[f] + wl * _perp(r), acc[f] + el * _perp(r) - wl * wl * r

    def normal(head: str, x: str, frm: str, link: int) -> None:
        wl = w[link][:, None]
        ap[head + "'"] = acc[frm] - wl * wl * (pos[x] - pos[frm])

    for g in lk.groups:
        if g.kind == "RRR":
            for end, link in zip(g.ends, g.links, strict=True):
                normal(f"n_{g.joint}{end}", g.joint, end, link)
        elif g.kind == "RRP":
            gd = g.guide
            assert gd is not None
            j, end = g.joint, g.ends[0]
            normal(f"n_{j}{end}", j, end, g.links[0])
            if not gd.fixed:
                jg = f"{plan_name(j, taken, lk.owner.get(j, 0))}{gd.link}"
                vp[jg], ap[jg + "'"] = on_link(gd.link, j)
                v_rel = vel[j] - vp[jg]
                ap[f"k_{j}'"] = ap[jg + "'"] + 2.0 * w[gd.link][:, None] * _perp(v_rel)
        elif g.kind == "RPR":
            s, c, rocker = g.slider, g.pivot, g.links[1]
            s3 = f"{plan_name(s, taken, lk.owner.get(s, 0))}{rocker}"
            vp[s3], ap[s3 + "'"] = on_link(rocker, s)
            v_rel = vel[s] - vp[s3]  # V_S about the slotted link's point under it
            ap[f"k_{s}'"] = acc[s] - 2.0 * w[rocker][:, None] * _perp(v_rel)
            normal(f"n_{s}{rocker}{c}", s, c, rocker)
    return vp, ap
