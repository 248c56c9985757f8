"""A mechanism's structure on a sheet, drawn from its model (:mod:`geomcad.structure`): its
pairs and its Assur groups as tables, and each group cut out as a scheme of its own.

- :func:`cut_out` — one group (or a primary mechanism) on its own: its pairs with moving links
  outside it join it to placeholder links (drawn as ghosts: the pair's symbol stays), its pairs
  with the frame stay;
- :func:`group_schemes` — a :class:`~geomcad.sheet.views.Scheme` of each primary mechanism and
  each Assur group of a :class:`~geomcad.structure.assur.Decomposition`, captioned with its
  class, order and kind, all at one scale;
- :func:`pairs_table` — the pairs: name, links, kind, class (p₅, p₄);
- :func:`groups_table` — the primary mechanisms and the groups: links, pairs, class, order, kind.

Words from ``strings/<lang>/assur.toml``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from geomcad.sheet.lang import Words
from geomcad.sheet.scheme import Body
from geomcad.sheet.views import Scheme, Table
from geomcad.structure import Link, Mechanism, Pair
from geomcad.structure.assur import Decomposition

WORDS = Words(__package__, "assur")


def group_kind(kind: str) -> str:
    """An Assur group's kind (RRR, PRP, …) in the language's letters (ВВВ, ПВП, … in Russian)."""
    return "".join(WORDS(f"pair_letter_{ch}") for ch in kind)


def cut_out(mech: Mechanism, part: Sequence[str]) -> Mechanism:
    """The links ``part`` of ``mech`` on their own (see the module's docstring); a placeholder
    link is named after the link it stands for with a prime (``3'``)."""
    links = [lk for lk in mech.links if lk.id in part]
    pairs: list[Pair] = []
    outside: dict[str, str] = {}
    for p in mech.pairs:
        if not set(p.links) & set(part):
            continue
        for lk in p.links:
            if lk not in part and lk != mech.frame:
                outside.setdefault(lk, f"{lk}'")
        pairs.append(
            Pair(p.name, p.kind, outside.get(p.a, p.a), outside.get(p.b, p.b), p.at, p.axis)
        )
    links += [Link(x) for x in outside.values()]
    return Mechanism(tuple(links), tuple(pairs), mech.frame)


def group_schemes(
    mech: Mechanism,
    dec: Decomposition,
    bodies: Mapping[str, Sequence[Body]] | None = None,
    **kw: Any,
) -> list[Scheme]:
    """A scheme of each primary mechanism and each Assur group of ``dec`` (``mech`` cut into
    them by :func:`cut_out`), each pair labelled, each captioned; ``bodies`` as
    :class:`~geomcad.sheet.views.Scheme`'s. Keywords as :class:`~geomcad.sheet.views.Scheme`
    (a scale group, a margin, the labels' height)."""
    parts: list[tuple[str, tuple[str, ...]]] = [
        (WORDS("primary", frame=dec.frame, link=p.link), (p.link,)) for p in dec.primary
    ]
    for g in dec.groups:
        kind = f", {group_kind(g.kind)}" if g.kind else ""
        caption = WORDS("group", links=", ".join(g.links), cls=g.roman, order=g.order, kind=kind)
        parts.append((caption, g.links))
    bodies = bodies or {}
    out = []
    for caption, part in parts:
        sub = cut_out(mech, part)
        out.append(
            Scheme(
                sub,
                {lk: bodies[lk] for lk in part if lk in bodies},
                pair_labels={q.name: q.name for q in sub.pairs},
                ghosts=[lk.id for lk in sub.links if lk.id not in part],
                also=[x for lk in part for b in bodies.get(lk, []) for x in b.points],
                title=caption,
                **kw,
            )
        )
    return out


def pair_kind(kind: str) -> str:
    """A pair's kind in words (``R`` → вращ.)."""
    return WORDS(f"kind_{kind}")


def pairs_table(mech: Mechanism, extra: Iterable[Pair] = (), mark: str = "*", **kw: Any) -> Table:
    """The pairs of ``mech`` (then the pairs ``extra``, their names marked ``mark``: a
    substitute link's): pair, links, kind, class. Keywords as
    :class:`~geomcad.sheet.views.Table`."""
    rows = [[WORDS(k) for k in ("h_pair", "h_links", "h_kind", "h_class")]]
    for p, m in [*((p, "") for p in mech.pairs), *((p, mark) for p in extra)]:
        rows.append([f"{p.name}{m}", f"{p.a}–{p.b}", pair_kind(p.kind), f"p_{p.pair_class}"])
    return Table(rows, **kw)


def groups_table(dec: Decomposition, **kw: Any) -> Table:
    """The primary mechanisms and the Assur groups of ``dec`` in the order they are attached:
    links, pairs, class, order, kind (and Artobolevsky's kind number of a dyad). Keywords as
    :class:`~geomcad.sheet.views.Table`."""
    heads = ("h_group", "h_links", "h_pairs", "h_class", "h_order", "h_kind")
    rows = [[WORDS(k) for k in heads]]
    for pm in dec.primary:
        rows.append([WORDS("primary_row"), f"{dec.frame}, {pm.link}", pm.pair, "I", "–", "–"])
    for i, g in enumerate(dec.groups):
        kind = f"{group_kind(g.kind)} ({g.kind_no})" if g.kind else "–"
        rows.append(
            [f"{i + 1}", ", ".join(g.links), ", ".join(g.pairs), g.roman, str(g.order), kind]
        )
    return Table(rows, **kw)
