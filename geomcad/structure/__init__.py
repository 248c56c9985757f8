"""Structural analysis of planar mechanisms: links and pairs as data, Chebyshev's W with local
mobilities and redundant constraints, higher pairs replaced by lower ones, Assur groups."""

from geomcad.structure.assur import AssurGroup, Decomposition, Primary, assur_groups
from geomcad.structure.mobility import (
    LocalMobility,
    Mobility,
    chebyshev,
    constraint_matrix,
    local_mobilities,
    mobility,
)
from geomcad.structure.model import (
    FRAME,
    HIGHER,
    LOWER,
    Link,
    Mechanism,
    Pair,
    PairKind,
    higher,
    prismatic,
    revolute,
)
from geomcad.structure.replace import (
    Removal,
    Replacement,
    Substitute,
    remove_local_mobilities,
    replace_higher_pairs,
)

__all__ = [
    "FRAME",
    "HIGHER",
    "LOWER",
    "AssurGroup",
    "Decomposition",
    "Link",
    "LocalMobility",
    "Mechanism",
    "Mobility",
    "Pair",
    "PairKind",
    "Primary",
    "Removal",
    "Replacement",
    "Substitute",
    "assur_groups",
    "chebyshev",
    "constraint_matrix",
    "higher",
    "local_mobilities",
    "mobility",
    "prismatic",
    "remove_local_mobilities",
    "replace_higher_pairs",
    "revolute",
]
