"""The scales a composed sheet's layout chooses, kept per solution and language.

A sheet module's ``scales(sol)`` arranges its views (:func:`geomcad.sheet.compose.arrange`) to
learn the factors the drawing will use; ``Problem.scales`` asks for them once per solution, and
the sheet asks again when it draws (its title block states them). The layout depends on the
language being drawn (the words' widths), so the answer is kept per language: a sheet drawn in
English after the Russian scales were read arranges its own layout once, and never states
another layout's scales.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar
from weakref import WeakKeyDictionary

from geomcad.sheet.lang import current

if TYPE_CHECKING:
    from geomcad.problem import Solution

_S = TypeVar("_S", bound="Solution")
_KEPT: WeakKeyDictionary[object, dict[str, dict[str, float]]] = WeakKeyDictionary()


def per_language(fn: Callable[[_S], dict[str, float]]) -> Callable[[_S], dict[str, float]]:
    """``fn(sol)`` computed once per solution and language being drawn."""

    @functools.wraps(fn)
    def kept(sol: _S) -> dict[str, float]:
        by_lang = _KEPT.setdefault(sol, {})
        lang = current()
        if lang not in by_lang:
            by_lang[lang] = fn(sol)
        return dict(by_lang[lang])

    return kept
