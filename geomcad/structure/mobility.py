"""Degrees of freedom: Chebyshev's count, and what the velocities of the drawn position say.

Chebyshev's structural formula for a planar mechanism counts W = 3n − 2p₅ − p₄: every moving link
has three freedoms in the plane, a lower pair takes away two, a higher pair one. The count is blind
to two things that every TMM course asks about:

- **local mobilities**: a link that can move while nothing else does, such as a roller's free spin
  about its pin. It adds one to the count but moves no output;
- **redundant constraints** q: a constraint that repeats what the others already impose (a
  parallelogram's extra coupler, a third planet gear). Each one takes one from the count although
  the mechanism still moves: the true W is W_formal + q.

:func:`mobility` finds both from the pairs' velocity conditions in the drawn position (the
constraint matrix J; a revolute gives two rows, a prismatic pair two, a higher pair one):
3n − rank J is the instantaneous mobility, q = (2p₅ + p₄) − rank J, and a local mobility is a motion
of one link alone that J allows. Then W_true = W_formal + q − W_local. At a singular position
(a dead centre, a change point) rank J drops and the drop shows as q; draw the scheme in a general
position.
"""

from __future__ import annotations

from dataclasses import dataclass

import networkx as nx
import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import Vec
from geomcad.structure.model import Mechanism, Pair

Arr = npt.NDArray[np.float64]


def _count(name: str, value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ParameterError(name, value, "a count must be a whole number")
    if value < 0:
        raise ParameterError(name, value, "a count must be ≥ 0")
    return value


def chebyshev(n: int, p5: int, p4: int) -> int:
    """Chebyshev's W = 3n − 2p₅ − p₄ (planar mechanisms). Counts must be whole and ≥ 0.

    >>> chebyshev(3, 4, 0)  # a four-bar
    1
    >>> chebyshev(7, 9, 1)  # 2013-1 before the replacement, the roller's spin included
    2
    """
    return 3 * _count("n", n) - 2 * _count("p5", p5) - _count("p4", p4)


@dataclass(frozen=True)
class LocalMobility:
    """A motion of ``link`` alone: a turn about ``centre``, or a slide along ``direction``."""

    link: str
    centre: Vec | None
    direction: Vec | None

    def describe(self) -> str:
        if self.centre is not None:
            return f"link {self.link} turns alone about ({self.centre.x:.6g}, {self.centre.y:.6g})"
        d = self.direction or Vec(1.0, 0.0)
        return f"link {self.link} slides alone along ({d.x:.6g}, {d.y:.6g})"


@dataclass(frozen=True)
class Mobility:
    """The structural count and what the position's velocities add to it.

    - ``formal``: Chebyshev's 3n − 2p₅ − p₄;
    - ``local``: the local mobilities found (one entry per independent motion of one link);
    - ``redundant``: q, the redundant constraints (at a singular position: its rank drop);
    - ``true``: the mobility of the motion that matters, W_formal + q − W_local.
    """

    n: int
    p5: int
    p4: int
    formal: int
    local: tuple[LocalMobility, ...]
    redundant: int
    rank: int

    @property
    def w_local(self) -> int:
        return len(self.local)

    @property
    def instantaneous(self) -> int:
        """3n − rank J: every independent velocity state the pairs allow, local ones included."""
        return 3 * self.n - self.rank

    @property
    def true(self) -> int:
        return self.formal + self.redundant - self.w_local

    def report(self) -> str:
        """The count in words, as a course writes it."""
        s = f"W = 3·{self.n} − 2·{self.p5} − {self.p4} = {self.formal}"
        if self.local:
            s += f"; local mobilities: {'; '.join(m.describe() for m in self.local)}"
        if self.redundant:
            s += f"; redundant constraints q = {self.redundant}"
        return s + f"; W_true = {self.true}"


def _point_rows(p: Vec, ref: Vec, size: float) -> Arr:
    """Rows mapping a link's velocity state (ω·size, v_x, v_y at ``ref``) to the velocity of its
    point ``p``: v + ω × (p − ref)."""
    dx, dy = (p.x - ref.x) / size, (p.y - ref.y) / size
    return np.array([[-dy, 1.0, 0.0], [dx, 0.0, 1.0]], dtype=np.float64)


def _pair_rows(pair: Pair, ref: Vec, size: float) -> Arr:
    """The velocity conditions of a pair on (state of a) − (state of b): one row per condition."""
    if pair.kind == "R":
        # the common point has one velocity on both links
        return _point_rows(pair.at, ref, size)
    assert pair.axis is not None
    n = pair.axis.perp() if pair.kind == "P" else pair.axis
    if pair.kind == "P":
        # no relative turn, and no relative velocity across the sliding axis
        turn = np.array([[1.0, 0.0, 0.0]])
        across = np.array([[n.x, n.y]]) @ _point_rows(pair.at, ref, size)
        return np.vstack([turn, across])
    # a higher pair: no relative velocity along the common normal (any point of it will do;
    # a finite centre of curvature is used, as it lies on the normal)
    c = pair.centre_a or pair.centre_b or pair.at
    return np.asarray(np.array([[n.x, n.y]]) @ _point_rows(c, ref, size), dtype=np.float64)


def constraint_matrix(mech: Mechanism) -> Arr:
    """J: the pairs' velocity conditions on the moving links' states, shape (2p₅ + p₄, 3n).

    A link's state is (ω·s, v_x, v_y): its angular velocity times the scheme's size s and the
    velocity of its point at the pairs' centroid, so every entry is of order one.
    """
    ref, size = mech.centroid(), mech.size()
    col = {lk: 3 * i for i, lk in enumerate(mech.ids)}
    rows: list[Arr] = []
    for p in mech.pairs:
        r = _pair_rows(p, ref, size)
        block = np.zeros((r.shape[0], 3 * mech.n))
        if p.a in col:
            block[:, col[p.a] : col[p.a] + 3] += r
        if p.b in col:
            block[:, col[p.b] : col[p.b] + 3] -= r
        rows.append(block)
    if not rows:
        return np.zeros((0, 3 * mech.n))
    return np.vstack(rows)


def rank(m: Arr) -> int:
    """The numerical rank: singular values above :data:`geomcad.tol.RANK` of the largest."""
    if m.size == 0:
        return 0
    s = np.linalg.svd(m, compute_uv=False)
    if s[0] == 0.0:
        return 0
    return int(np.count_nonzero(s > tol.RANK * s[0]))


def _null_space(m: Arr) -> Arr:
    """An orthonormal basis of the null space of ``m`` (as rows)."""
    _, s, vt = np.linalg.svd(m)
    r = int(np.count_nonzero(s > tol.RANK * s[0])) if s.size and s[0] > 0.0 else 0
    return np.asarray(vt[r:], dtype=np.float64)


def check_connected(mech: Mechanism) -> None:
    """Every moving link must be joined to the frame through pairs; else a
    :class:`ConstructionError` names the loose links."""
    g = mech.graph()
    loose = sorted(set(mech.ids) - nx.node_connected_component(g, mech.frame))
    if loose:
        raise ConstructionError(
            "mechanism",
            f"links {', '.join(loose)} are not joined to the frame {mech.frame}: "
            "a mechanism is one kinematic chain",
        )


def local_mobilities(mech: Mechanism) -> tuple[LocalMobility, ...]:
    """Every motion of one link alone that the pairs allow (a roller's free spin).

    For each link, the conditions of its own pairs with the other links held still; each
    independent motion they leave is one local mobility.
    """
    ref, size = mech.centroid(), mech.size()
    out: list[LocalMobility] = []
    for lk in mech.ids:
        pairs = list(mech.pairs_of(lk))
        rows = [_pair_rows(p, ref, size) * (1.0 if p.a == lk else -1.0) for p in pairs]
        m = np.vstack(rows) if rows else np.zeros((0, 3))
        basis = _null_space(m) if m.size else np.eye(3)
        for row in basis:
            w, vx, vy = (float(x) for x in row)
            if abs(w) > tol.RANK:
                # the point of zero velocity: v + ω × (c − ref) = 0
                wr = w / size
                centre = Vec(ref.x - vy / wr, ref.y + vx / wr)
                out.append(LocalMobility(lk, centre, None))
            else:
                out.append(LocalMobility(lk, None, Vec(vx, vy).unit()))
    return tuple(out)


def mobility(mech: Mechanism) -> Mobility:
    """Chebyshev's count of ``mech`` with its local mobilities and redundant constraints.

    A link not joined to the frame is a :class:`ConstructionError` naming it.

    >>> from geomcad.structure.model import Link, Mechanism, revolute
    >>> para = Mechanism(  # a parallelogram with a second coupler: q = 1
    ...     (Link("1"), Link("2"), Link("3"), Link("4")),
    ...     (revolute("A0", "0", "1", (0, 0)), revolute("A", "1", "2", (0, 1)),
    ...      revolute("B", "2", "3", (2, 1)), revolute("B0", "3", "0", (2, 0)),
    ...      revolute("E0", "0", "4", (1, 0)), revolute("E", "4", "2", (1, 1))),
    ... )
    >>> m = mobility(para)
    >>> (m.formal, m.redundant, m.true)
    (0, 1, 1)
    """
    check_connected(mech)
    j = constraint_matrix(mech)
    r = rank(j)
    return Mobility(
        mech.n,
        mech.p5,
        mech.p4,
        chebyshev(mech.n, mech.p5, mech.p4),
        local_mobilities(mech),
        j.shape[0] - r,
        r,
    )


def rigid(mech: Mechanism, links: tuple[str, ...], pairs: tuple[Pair, ...]) -> bool:
    """True when ``pairs`` fix ``links`` completely, every other link held still: the velocity
    conditions on those links' states have full rank 3·len(links)."""
    ref, size = mech.centroid(), mech.size()
    col = {lk: 3 * i for i, lk in enumerate(links)}
    rows: list[Arr] = []
    for p in pairs:
        r = _pair_rows(p, ref, size)
        block = np.zeros((r.shape[0], 3 * len(links)))
        if p.a in col:
            block[:, col[p.a] : col[p.a] + 3] += r
        if p.b in col:
            block[:, col[p.b] : col[p.b] + 3] -= r
        rows.append(block)
    if not rows:
        return False
    return rank(np.vstack(rows)) == 3 * len(links)
