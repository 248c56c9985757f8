"""Assur groups: the structural decomposition of a planar lower-pair mechanism.

A mechanism of W degrees of freedom is its frame with W driving links (primary mechanisms,
class I), onto which groups of zero mobility are attached one after another (Assur's principle):
each group, n links and p lower pairs with 3n − 2p = 0, is fixed completely once the links it
hangs on are in place.

:func:`assur_groups` finds such a sequence over the pair graph:

1. the driving links with their pairs to the frame are in place;
2. among the links not yet in place it takes the smallest set S (2, then 4, then 6 … links, up to
   ``max_links``) that is connected by its own pairs, counts 3·|S| = 2·(its pairs among S and to
   links in place), hangs on at least one link in place, and is rigid in the drawn position (the
   velocity conditions of those pairs fix S: this rules out, e.g., a dyad of three prismatic
   pairs);
3. S is an Assur group; it is now in place; repeat until every link is.

Taking the smallest set first makes every group minimal (no part of it is a group of its own).
The sequence is the order of attachment; a course detaches the groups in the reverse order,
starting with the one farthest from the driving link.

Each group's **order** is the number of its outer pairs (those with links already in place); its
**class** (Artobolevsky) is the number of inner pairs of its most complex closed contour, where a
base link with k inner pairs counts as a contour of k, and a dyad is class II. A dyad's kind is
written with its pairs, outer–inner–outer: RRR (1st kind), RRP (2nd), RPR (3rd), PRP (4th),
RPP (5th).

What it covers: planar mechanisms with revolute and prismatic pairs only (replace higher pairs
first: :func:`geomcad.structure.replace_higher_pairs`), without local mobilities (take them out:
:func:`geomcad.structure.remove_local_mobilities`) and without redundant constraints, whose driving
links are each joined to the frame. Groups of up to ``max_links`` links (6 by default: classes II,
III and IV, and the larger classes that fit) are found; a chain that splits into none of them is a
:class:`ConstructionError`.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

import networkx as nx

from geomcad.errors import ConstructionError
from geomcad.structure.mobility import mobility, rigid
from geomcad.structure.model import Mechanism, Pair

#: Artobolevsky's kinds of class II groups (dyads), outer–inner–outer, read either way.
DYAD_KINDS = {"RRR": 1, "RRP": 2, "PRR": 2, "RPR": 3, "PRP": 4, "RPP": 5, "PPR": 5}

ROMAN = ("", "I", "II", "III", "IV", "V", "VI", "VII", "VIII")

STEP = "Assur groups"


@dataclass(frozen=True)
class Primary:
    """A primary mechanism (class I): driving link ``link`` on the frame through ``pair``."""

    link: str
    pair: str


@dataclass(frozen=True)
class AssurGroup:
    """One Assur group: its links, its inner and outer pairs, class, order and (dyads) kind."""

    links: tuple[str, ...]
    internal: tuple[str, ...]
    external: tuple[str, ...]
    group_class: int
    order: int
    kind: str = ""

    @property
    def pairs(self) -> tuple[str, ...]:
        return self.internal + self.external

    @property
    def kind_no(self) -> int | None:
        """Artobolevsky's kind (1–5) of a dyad; ``None`` for a larger group."""
        return DYAD_KINDS.get(self.kind)

    @property
    def roman(self) -> str:
        """The class as a Roman numeral (``II``)."""
        return ROMAN[self.group_class] if self.group_class < len(ROMAN) else str(self.group_class)

    def describe(self) -> str:
        s = f"class {self.roman}, order {self.order}: links {', '.join(self.links)}"
        if self.kind:
            s += f" ({self.kind}, kind {self.kind_no})"
        return s


@dataclass(frozen=True)
class Decomposition:
    """The primary mechanisms and the Assur groups in the order they are attached."""

    primary: tuple[Primary, ...]
    groups: tuple[AssurGroup, ...]
    frame: str = "0"

    @property
    def mechanism_class(self) -> int:
        """The mechanism's class: the highest class of its groups (I when it has none)."""
        return max((g.group_class for g in self.groups), default=1)

    def formula(self) -> str:
        """The structural formula, e.g. ``I(0, 2) → II(3, 1) → II(8, 7)``."""
        parts = [f"I({self.frame}, {p.link})" for p in self.primary]
        parts += [f"{g.roman}({', '.join(g.links)})" for g in self.groups]
        return " → ".join(parts)


def _check(mech: Mechanism, drivers: Sequence[str]) -> list[Primary]:
    higher = [p.name for p in mech.pairs if not p.lower]
    if higher:
        raise ConstructionError(
            STEP,
            f"higher pairs {', '.join(higher)}: replace the higher pairs by lower ones first",
        )
    mob = mobility(mech)
    if mob.local:
        raise ConstructionError(
            STEP, f"{mob.local[0].describe()}: take the local mobilities out first"
        )
    if mob.redundant:
        raise ConstructionError(
            STEP,
            f"the scheme has {mob.redundant} redundant constraint(s) (or is drawn in a singular "
            "position): Assur groups need a statically determinate chain",
        )
    if len(drivers) != mob.true or len(set(drivers)) != len(drivers):
        raise ConstructionError(
            STEP,
            f"W = {mob.true} needs {mob.true} different driving link(s); "
            f"{len(drivers)} given ({', '.join(drivers) or 'none'})",
        )
    out = []
    for d in drivers:
        mech.link(d)
        on_frame = [p for p in mech.pairs_of(d) if mech.frame in p.links]
        if not on_frame:
            raise ConstructionError(STEP, f"driving link {d} has no pair with the frame")
        out.append(Primary(d, on_frame[0].name))
    return out


def _group_class(links: tuple[str, ...], inner: list[Pair]) -> int:
    """The class: the inner pairs of the most complex closed contour, or of the base link."""
    if len(links) == 2:
        return 2
    g = nx.Graph()
    g.add_nodes_from(links)
    g.add_edges_from((p.a, p.b) for p in inner)
    degree = max((len([p for p in inner if lk in p.links]) for lk in links), default=2)
    longest = max((len(c) for c in nx.simple_cycles(g)), default=0)
    return max(2, degree, longest)


def _dyad_kind(links: tuple[str, ...], inner: list[Pair], outer: list[Pair]) -> str:
    a, b = links
    oa = [p for p in outer if a in p.links]
    ob = [p for p in outer if b in p.links]
    if len(inner) != 1 or len(oa) != 1 or len(ob) != 1:
        return ""
    return oa[0].kind + inner[0].kind + ob[0].kind


def assur_groups(mech: Mechanism, drivers: Sequence[str], max_links: int = 6) -> Decomposition:
    """Split ``mech`` into its primary mechanisms and Assur groups (see the module docstring).

    ``drivers``: the driving links, each joined to the frame; as many as the mechanism's W.
    Raises :class:`ConstructionError` (step "Assur groups") for a scheme outside the method's
    reach: higher pairs, local mobilities, redundant constraints, the wrong number of drivers,
    or links that form no group of at most ``max_links`` links.
    """
    primary = _check(mech, drivers)
    placed = {mech.frame, *drivers}
    rest = [lk for lk in mech.ids if lk not in placed]
    g = mech.graph()
    groups: list[AssurGroup] = []
    while rest:
        found = _smallest_group(mech, g, placed, rest, max_links)
        if found is None:
            raise ConstructionError(
                STEP,
                f"links {', '.join(rest)} form no group of zero mobility of at most "
                f"{max_links} links on the links in place ({', '.join(sorted(placed))})",
            )
        groups.append(found)
        placed |= set(found.links)
        rest = [lk for lk in rest if lk not in placed]
    return Decomposition(tuple(primary), tuple(groups), mech.frame)


def _smallest_group(
    mech: Mechanism, g: nx.MultiGraph, placed: set[str], rest: list[str], max_links: int
) -> AssurGroup | None:
    for size in range(2, min(max_links, len(rest)) + 1, 2):
        for cand in itertools.combinations(rest, size):
            s = set(cand)
            if not nx.is_connected(g.subgraph(cand)):
                continue
            pairs = [
                p
                for p in mech.pairs
                if (p.a in s or p.b in s) and p.a in s | placed and p.b in s | placed
            ]
            if 3 * size != 2 * len(pairs):
                continue
            outer = [p for p in pairs if not (p.a in s and p.b in s)]
            if not outer or not rigid(mech, cand, tuple(pairs)):
                continue
            inner = [p for p in pairs if p.a in s and p.b in s]
            return AssurGroup(
                cand,
                tuple(p.name for p in inner),
                tuple(p.name for p in outer),
                _group_class(cand, inner),
                len(outer),
                _dyad_kind(cand, inner, outer) if size == 2 else "",
            )
    return None
