"""A planar mechanism described as data: links, and kinematic pairs between them.

A structural scheme is a set of links (the frame, link ``"0"`` by default, is implied) and the
kinematic pairs that join them, each placed where it sits in the drawn position:

- lower pairs, class 5 (p₅), one degree of freedom each:
  - ``R``, revolute: the two links share the point ``at`` (the pair's axis);
  - ``P``, prismatic: the links slide relative to each other along ``axis`` and cannot turn
    relative to each other; ``at`` is a point of the sliding axis;
- higher pairs, class 4 (p₄), two degrees of freedom each: ``cam`` (a cam and its follower),
  ``slot`` (a roller in a slot), ``gear`` (a gear mesh). The profiles touch at ``at``; ``axis`` is
  their common normal there; ``centre_a`` and ``centre_b`` are the centres of curvature of the two
  profiles at the contact, ``None`` for a straight profile (its centre is at infinity). Both lie on
  the common normal; they are where :func:`geomcad.structure.replace_higher_pairs` puts the
  substitute link's two lower pairs.

The positions matter: they let :func:`geomcad.structure.mobility` find redundant constraints and
local mobilities from the velocities the pairs allow, which counting alone cannot see.

>>> m = Mechanism(
...     links=(Link("1"), Link("2"), Link("3")),
...     pairs=(
...         revolute("O", "0", "1", (0, 0)),
...         revolute("A", "1", "2", (0, 1)),
...         revolute("B", "2", "3", (3, 2)),
...         revolute("C", "3", "0", (4, 0)),
...     ),
... )
>>> (m.n, m.p5, m.p4)
(3, 4, 0)
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Literal

import networkx as nx

from geomcad import tol
from geomcad.errors import DegenerateInput
from geomcad.geom import Line, PointLike, Vec, vec

PairKind = Literal["R", "P", "cam", "slot", "gear"]

#: Lower pairs (class 5, one relative freedom) and higher pairs (class 4, two freedoms).
LOWER: tuple[PairKind, ...] = ("R", "P")
HIGHER: tuple[PairKind, ...] = ("cam", "slot", "gear")

#: The frame's id unless a mechanism names another.
FRAME = "0"


@dataclass(frozen=True)
class Link:
    """A link of the mechanism: its id (``"1"``, ``"2"`` … as the scheme numbers it) and name."""

    id: str
    name: str = ""


@dataclass(frozen=True)
class Pair:
    """A kinematic pair joining links ``a`` and ``b`` (see the module's docstring)."""

    name: str
    kind: PairKind
    a: str
    b: str
    at: Vec
    axis: Vec | None = None
    centre_a: Vec | None = None
    centre_b: Vec | None = None

    @property
    def lower(self) -> bool:
        """True for a lower pair (revolute or prismatic)."""
        return self.kind in LOWER

    @property
    def pair_class(self) -> int:
        """5 for a lower pair (one relative freedom), 4 for a higher pair (two)."""
        return 5 if self.lower else 4

    @property
    def links(self) -> tuple[str, str]:
        return (self.a, self.b)

    def other(self, link: str) -> str:
        """The link this pair joins to ``link``."""
        return self.b if link == self.a else self.a

    def centre_on(self, link: str) -> Vec | None:
        """A higher pair's centre of curvature of ``link``'s profile (``None``: straight)."""
        return self.centre_a if link == self.a else self.centre_b

    def rejoined(self, old: str, new: str) -> Pair:
        """The same pair with link ``old`` replaced by ``new`` (its geometry unchanged)."""
        if old == self.a:
            return Pair(self.name, self.kind, new, self.b, self.at, self.axis, *self._c())
        return Pair(self.name, self.kind, self.a, new, self.at, self.axis, *self._c())

    def _c(self) -> tuple[Vec | None, Vec | None]:
        return self.centre_a, self.centre_b


def revolute(name: str, a: str, b: str, at: PointLike) -> Pair:
    """A revolute pair (hinge) of links a and b with its axis at ``at``."""
    return Pair(name, "R", a, b, vec(at))


def prismatic(name: str, a: str, b: str, at: PointLike, along: PointLike) -> Pair:
    """A prismatic pair: a slides on b along ``along`` (any length), ``at`` on the axis."""
    try:
        u = vec(along).unit()
    except DegenerateInput:
        raise DegenerateInput(
            f"pair {name}", "a prismatic pair needs a sliding direction"
        ) from None
    return Pair(name, "P", a, b, vec(at), u)


def higher(
    name: str,
    a: str,
    b: str,
    contact: PointLike,
    normal: PointLike,
    centre_a: PointLike | None = None,
    centre_b: PointLike | None = None,
    kind: PairKind = "cam",
) -> Pair:
    """A higher pair: the profiles of a and b touch at ``contact`` with common ``normal``.

    ``centre_a``, ``centre_b``: the centres of curvature of the two profiles at the contact, on the
    common normal; ``None`` for a straight profile. At least one must be finite (two straight
    profiles in line contact make a prismatic pair, not a higher one). A centre off the normal is
    :class:`DegenerateInput`.
    """
    if kind not in HIGHER:
        raise DegenerateInput(f"pair {name}", f"{kind!r} is not a higher pair ({HIGHER})")
    p = vec(contact)
    try:
        n = vec(normal).unit()
    except DegenerateInput:
        raise DegenerateInput(f"pair {name}", "a higher pair needs its common normal") from None
    ca = None if centre_a is None else vec(centre_a)
    cb = None if centre_b is None else vec(centre_b)
    if ca is None and cb is None:
        raise DegenerateInput(
            f"pair {name}",
            "both profiles are straight: that is a prismatic pair, not a higher one",
        )
    normal_line = Line(p, n)
    for c in (ca, cb):
        if c is not None:
            off = abs(normal_line.side(c))
            if off > tol.TANGENT * max(1.0, c.dist(p)):
                raise DegenerateInput(
                    f"pair {name}",
                    f"a centre of curvature lies {off:.6g} off the common normal at the contact",
                )
    return Pair(name, kind, a, b, p, n, ca, cb)


@dataclass(frozen=True)
class Mechanism:
    """Links and pairs of a planar mechanism in one position; the frame is ``frame``.

    Link ids and pair names are unique; a pair joins two different known links (the frame
    included); otherwise :class:`DegenerateInput` names the pair. ``links`` lists the moving links
    only: n = len(links).
    """

    links: tuple[Link, ...]
    pairs: tuple[Pair, ...]
    frame: str = FRAME
    _index: dict[str, Link] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        ids = [lk.id for lk in self.links]
        dup = {i for i in ids if ids.count(i) > 1}
        if dup:
            raise DegenerateInput("mechanism", f"link ids are used twice: {', '.join(sorted(dup))}")
        if self.frame in ids:
            raise DegenerateInput("mechanism", f"the frame {self.frame} is listed as a moving link")
        names = [p.name for p in self.pairs]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise DegenerateInput(
                "mechanism", f"pair names are used twice: {', '.join(sorted(dup))}"
            )
        known = {*ids, self.frame}
        for p in self.pairs:
            for lk in p.links:
                if lk not in known:
                    raise DegenerateInput(f"pair {p.name}", f"it joins the unknown link {lk!r}")
            if p.a == p.b:
                raise DegenerateInput(f"pair {p.name}", f"it joins link {p.a} to itself")
        object.__setattr__(self, "_index", {lk.id: lk for lk in self.links})

    # -- counts --------------------------------------------------------------------------------
    @property
    def n(self) -> int:
        """The number of moving links."""
        return len(self.links)

    @property
    def p5(self) -> int:
        """The number of lower pairs (class 5)."""
        return sum(1 for p in self.pairs if p.lower)

    @property
    def p4(self) -> int:
        """The number of higher pairs (class 4)."""
        return sum(1 for p in self.pairs if not p.lower)

    # -- look-ups ------------------------------------------------------------------------------
    def link(self, link_id: str) -> Link:
        """The moving link ``link_id``."""
        try:
            return self._index[link_id]
        except KeyError:
            raise DegenerateInput("mechanism", f"there is no moving link {link_id!r}") from None

    def pair(self, name: str) -> Pair:
        """The pair called ``name``."""
        for p in self.pairs:
            if p.name == name:
                return p
        raise DegenerateInput("mechanism", f"there is no pair {name!r}")

    def pairs_of(self, link_id: str) -> Iterator[Pair]:
        """The pairs that ``link_id`` takes part in, in the mechanism's order."""
        return (p for p in self.pairs if link_id in p.links)

    @property
    def ids(self) -> tuple[str, ...]:
        """The moving links' ids, in order."""
        return tuple(lk.id for lk in self.links)

    def graph(self) -> nx.MultiGraph:
        """The pair graph: a node per link (the frame too), an edge per pair keyed by its name."""
        g = nx.MultiGraph()
        g.add_node(self.frame)
        g.add_nodes_from(self.ids)
        for p in self.pairs:
            g.add_edge(p.a, p.b, key=p.name, pair=p)
        return g

    def size(self) -> float:
        """The characteristic size of the scheme: the largest distance of a pair from their
        centroid (1 when the pairs all coincide); tolerances and scalings are relative to it."""
        pts = [p.at for p in self.pairs] + [
            c for p in self.pairs for c in (p.centre_a, p.centre_b) if c is not None
        ]
        if not pts:
            return 1.0
        cx = sum(q.x for q in pts) / len(pts)
        cy = sum(q.y for q in pts) / len(pts)
        r = max(math.hypot(q.x - cx, q.y - cy) for q in pts)
        return r if r > 0.0 else 1.0

    def centroid(self) -> Vec:
        """The centroid of the pairs' points (the origin of the velocity coordinates)."""
        pts = [p.at for p in self.pairs]
        if not pts:
            return Vec(0.0, 0.0)
        return Vec(sum(q.x for q in pts) / len(pts), sum(q.y for q in pts) / len(pts))

    def with_pairs(self, links: tuple[Link, ...], pairs: tuple[Pair, ...]) -> Mechanism:
        """A mechanism on the same frame with other links and pairs."""
        return Mechanism(links, pairs, self.frame)

    def next_id(self) -> str:
        """A free link id: one more than the largest numeric id (``"1"`` when there is none)."""
        nums = [int(i) for i in (*self.ids, self.frame) if i.isdigit()]
        k = max(nums, default=0) + 1
        while str(k) in self._index or str(k) == self.frame:
            k += 1
        return str(k)
