"""The language of a sheet's words: one table per language, and the language being drawn.

Drawing code holds no words of a natural language. It asks a :class:`Words` table for them by key;
the table of a language is the union of the TOML files ``<package>/strings/<lang>/<name>.toml``
(one file per sheet module, so that modules never share a file). The language being drawn is a
context variable set once by the caller of a problem's ``draw`` (``with language("en"): ...``);
Russian is the default::

    WORDS = Words(__package__, "linkage")        # geomcad/sheet/strings/{ru,en}/linkage.toml
    d.text(WORDS("vplans", n=12), at)            # "Планы скоростей (12)" or "Velocity plans (12)"

A key missing from a language's table is a programming error (``LookupError``), and the tests
check that every language's table has the same keys.
"""

from __future__ import annotations

import functools
import tomllib
import weakref
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from functools import cache
from importlib import resources
from typing import TypeVar

# the languages: a user's [sheet] table is checked against them without the sheet layer
from geomcad.titlefields import LANGS as LANGS
from geomcad.titlefields import Lang as Lang

_CURRENT: ContextVar[Lang] = ContextVar("geomcad_lang", default="ru")


def current() -> Lang:
    """The language being drawn (``"ru"`` unless a caller chose another)."""
    return _CURRENT.get()


def check_lang(lang: str) -> Lang:
    """``lang`` as a :data:`Lang`, or ``ValueError`` naming the languages there are."""
    if lang not in LANGS:
        raise ValueError(f"--lang: {lang!r} is not a language of the sheets ({', '.join(LANGS)})")
    return lang


@contextmanager
def language(lang: str) -> Iterator[Lang]:
    """Draw in ``lang`` inside the ``with`` block."""
    token = _CURRENT.set(check_lang(lang))
    try:
        yield _CURRENT.get()
    finally:
        _CURRENT.reset(token)


_O = TypeVar("_O")
_R = TypeVar("_R")


def per_language(fn: Callable[[_O], _R]) -> Callable[[_O], _R]:
    """``fn(obj)`` computed once per object and language being drawn, and kept while the object
    lives (by identity: a frozen dataclass that compares equal to another is still itself).

    A composed sheet's layout depends on the language (the words' widths): ``Problem.scales``
    arranges the views to learn the scales, the sheet arranges them again to draw; with this
    both use one arrangement, and a sheet drawn in English after the Russian scales were read
    arranges its own layout once and never states another layout's scales. The result is
    shared, not copied: callers treat it as read-only.
    """
    kept: dict[int, tuple[weakref.ref[_O], dict[Lang, _R]]] = {}

    @functools.wraps(fn)
    def once(obj: _O) -> _R:
        key = id(obj)
        hit = kept.get(key)
        if hit is None or hit[0]() is not obj:
            hit = (weakref.ref(obj), {})
            kept[key] = hit
            weakref.finalize(obj, kept.pop, key, None)
        by_lang = hit[1]
        lang = current()
        if lang not in by_lang:
            by_lang[lang] = fn(obj)
        return by_lang[lang]

    return once


@cache
def _table(package: str, name: str, lang: Lang) -> Mapping[str, str]:
    path = resources.files(package).joinpath("strings", lang, f"{name}.toml")
    with path.open("rb") as f:
        data = tomllib.load(f)
    out: dict[str, str] = {}
    for key, value in data.items():
        if not isinstance(value, str):
            raise TypeError(f"{package}/strings/{lang}/{name}.toml: {key} is not a string")
        out[key] = value
    return out


class Words:
    """The words of one sheet module, in every language (see the module's docstring)."""

    def __init__(self, package: str | None, name: str) -> None:
        if not package:
            raise ValueError("Words needs the package that holds the strings/ folder")
        self.package = package
        self.name = name

    def table(self, lang: Lang | None = None) -> Mapping[str, str]:
        """The whole table of ``lang`` (default: the language being drawn)."""
        return _table(self.package, self.name, lang or current())

    def __call__(self, key: str, /, lang: Lang | None = None, **fields: object) -> str:
        """The text of ``key`` in ``lang`` (default: the language being drawn), with ``{field}``
        placeholders filled from ``fields``."""
        table = self.table(lang)
        try:
            text = table[key]
        except KeyError:
            where = f"{self.package}/strings/{lang or current()}/{self.name}.toml"
            raise LookupError(f"{where}: no key {key!r}") from None
        return text.format(**fields) if fields else text
