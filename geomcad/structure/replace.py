"""Replacing higher pairs by lower ones, and taking local mobilities out.

**Replacement** (the substitute mechanism of a TMM course). A higher pair between a and b is
replaced by a substitute link with two lower pairs at the centres of curvature of the two
profiles at the contact: a revolute on a's profile centre, joined to a, and one on b's, joined to
b. A straight profile has its centre at infinity along the normal, so its revolute becomes a
prismatic pair sliding along the profile (across the normal). The substitute link keeps the
profiles' centres of curvature at their distance, so the replaced mechanism has the same
velocities (and accelerations) in this position, and the same W: one link (+3) and two lower pairs
(−4) replace one higher pair (−1).

**Local mobilities out.** A roller that spins on its pin adds a freedom that moves nothing. Taking
it out before the count (as many textbooks do) removes the roller and its pin and hands its higher
pairs to the link that carries the pin: the centre of curvature of the roller's profile is the pin
itself, so the contact geometry does not change. A roller left in after the replacement spins
between two revolutes on one axis; taking it out joins the two links it separates by one revolute.
"""

from __future__ import annotations

from dataclasses import dataclass

from geomcad import tol
from geomcad.errors import ConstructionError
from geomcad.geom import Vec
from geomcad.structure.mobility import local_mobilities
from geomcad.structure.model import Link, Mechanism, Pair, prismatic, revolute


@dataclass(frozen=True)
class Substitute:
    """The substitute link ``link`` that replaced higher pair ``replaces``, with its two lower
    pairs: ``pair_a`` joins it to the pair's link a, ``pair_b`` to link b."""

    replaces: str
    link: str
    pair_a: str
    pair_b: str


@dataclass(frozen=True)
class Replacement:
    """A mechanism after replacing its higher pairs, and what replaced each one."""

    mechanism: Mechanism
    substitutes: tuple[Substitute, ...]


def _lower_at(name: str, new: str, old: str, centre: Vec | None, other: Vec, axis: Vec) -> Pair:
    """The substitute's pair with link ``old``: a revolute at the profile's centre of curvature,
    or, for a straight profile, a prismatic pair sliding along it (across the normal) through the
    other profile's centre."""
    if centre is not None:
        return revolute(name, new, old, centre)
    return prismatic(name, new, old, other, axis.perp())


def replace_higher_pairs(
    mech: Mechanism, names: dict[str, tuple[str, str, str]] | None = None
) -> Replacement:
    """Replace every higher pair of ``mech`` by a substitute link with two lower pairs.

    ``names`` may give, per higher pair, (the substitute link's id, the name of its pair with
    link a, the name of its pair with link b). By default the link takes the next free number and
    the pairs are called ``<pair><a>`` and ``<pair><b>``. The substitutes are added after the
    existing links, in the order of the higher pairs.
    """
    names = names or {}
    links = list(mech.links)
    pairs: list[Pair] = []
    subs: list[Substitute] = []
    work = mech
    for p in mech.pairs:
        if p.lower:
            pairs.append(p)
            continue
        assert p.axis is not None
        default = (work.next_id(), f"{p.name}{p.a}", f"{p.name}{p.b}")
        sid, na, nb = names.get(p.name, default)
        links.append(Link(sid, f"substitute for {p.name}"))
        # the finite centre stands in for the other one when a profile is straight
        ca = p.centre_a or p.centre_b
        cb = p.centre_b or p.centre_a
        assert ca is not None and cb is not None
        pairs.append(_lower_at(na, sid, p.a, p.centre_a, cb, p.axis))
        pairs.append(_lower_at(nb, sid, p.b, p.centre_b, ca, p.axis))
        subs.append(Substitute(p.name, sid, na, nb))
        work = mech.with_pairs(tuple(links), mech.pairs)
    return Replacement(mech.with_pairs(tuple(links), tuple(pairs)), tuple(subs))


@dataclass(frozen=True)
class Removal:
    """A mechanism with its local mobilities taken out: the links removed, and how."""

    mechanism: Mechanism
    removed: tuple[str, ...]
    how: tuple[str, ...]


def _same(a: Vec, b: Vec, size: float) -> bool:
    """Two points coincide (one of them derived from a null space, hence the derived tolerance)."""
    return a.dist(b) <= tol.DERIVED * size


def remove_local_mobilities(mech: Mechanism) -> Removal:
    """Take out every link whose only motion of its own is a spin about its pin (a roller).

    - a roller on one pin with higher pairs whose profile centre is that pin: the roller and its
      pin go, and its higher pairs pass to the link that carries the pin (n − 1, p₅ − 1);
    - a roller between two revolutes on one axis (after a replacement): it goes, and the two
      links it joined share one revolute there (n − 1, p₅ − 1).

    A local mobility of another kind cannot be taken out this way: :class:`ConstructionError`.
    """
    size = mech.size()
    cur = mech
    removed: list[str] = []
    how: list[str] = []
    for lm in local_mobilities(mech):
        lk = lm.link
        pairs = list(cur.pairs_of(lk))
        rev = [p for p in pairs if p.kind == "R"]
        hig = [p for p in pairs if not p.lower]
        c = lm.centre
        ok = (
            c is not None
            and len(rev) + len(hig) == len(pairs)
            and all(_same(p.at, c, size) for p in rev)
            and all((q := p.centre_on(lk)) is not None and _same(q, c, size) for p in hig)
        )
        if not ok or not ((len(rev) == 1 and hig) or (len(rev) == 2 and not hig)):
            raise ConstructionError(
                "remove local mobilities",
                f"{lm.describe()}, but it is not a roller on one pin; take it out by hand",
            )
        assert c is not None
        links = tuple(x for x in cur.links if x.id != lk)
        if len(rev) == 1:
            carrier = rev[0].other(lk)
            new = [p.rejoined(lk, carrier) if p in hig else p for p in cur.pairs if p is not rev[0]]
            how.append(
                f"roller {lk} and its pin {rev[0].name} removed; "
                f"{', '.join(p.name for p in hig)} now on link {carrier}"
            )
            cur = cur.with_pairs(links, tuple(new))
        else:
            a, b = rev[0].other(lk), rev[1].other(lk)
            joined = revolute(rev[0].name, a, b, c)
            new = [
                joined if p is rev[0] else p for p in cur.pairs if p is rev[0] or lk not in p.links
            ]
            how.append(
                f"roller {lk} removed; links {a} and {b} share the revolute {rev[0].name} "
                f"(pair {rev[1].name} dropped)"
            )
            cur = cur.with_pairs(links, tuple(new))
        removed.append(lk)
    return Removal(cur, tuple(removed), tuple(how))
