"""A sheet whose views depend on the scales the layout gives them: a table that gives the
plans' vectors in mm at the plans' factors, a free body whose loads' reach at μ_F depends on its
length scale. The tree is built for the scales it will get, arranged, and built again with the
scales it got, until they are the ones it was built with (:func:`settle`).

Appended for the seed sheets (2013-6, 2013-9, kulisa-23110713); any tree.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Generic, TypeVar

from geomcad.sheet.compose import Field, Layout, Tree, View, arrange

K = TypeVar("K")
T = TypeVar("T")

#: Builds and arrangements at most: the scales are GOST or nice factors, discrete, so they
#: settle at the second or third.
ROUNDS = 3


class Settled(Generic[T, K]):
    """The tree, what its builder returned besides it (``parts``: its views, to look up in
    the layout), its layout and the scales ``key`` it was built with and got."""

    def __init__(self, tree: Tree, parts: T, layout: Layout, key: K) -> None:
        self.tree, self.parts, self.layout, self.key = tree, parts, layout, key


def settle(
    build: Callable[[K], tuple[Tree, T]],
    got: Callable[[Layout, T], K],
    start: K,
    field: Field,
    rounds: int = ROUNDS,
    same: Callable[[K, K], bool] | None = None,
) -> Settled[T, K]:
    """``build(key)`` (a tree and its parts for the scales ``key``) arranged in ``field`` and
    built again with ``got(layout, parts)`` until that is the key it was built with (``same``,
    default ``==``), at most ``rounds`` times (the last arrangement is kept)."""
    key = start
    while True:
        tree, parts = build(key)
        layout = arrange(tree, field)
        rounds -= 1
        new = got(layout, parts)
        if (same(new, key) if same else new == key) or rounds <= 0:
            return Settled(tree, parts, layout, new)
        key = new


def factor_of(layout: Layout, view: View) -> float:
    """The factor (k) of the scale the layout gave the scaled ``view``."""
    got = layout[view].scale
    if got is None:
        raise ValueError(f"{type(view).__name__} has no scale: it is not a scaled view")
    return got.k
