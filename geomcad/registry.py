"""Discovery of problems through the ``geomcad.constructions`` entry-point group.

Modules are imported lazily: listing ids reads only the entry points; a problem's module is
imported when that problem is asked for.
"""

from __future__ import annotations

from functools import cache
from importlib.metadata import EntryPoint, entry_points
from typing import TYPE_CHECKING, Any

from geomcad.errors import UnknownProblem

if TYPE_CHECKING:
    from geomcad.problem import Problem

GROUP = "geomcad.constructions"


@cache
def _entry_points() -> dict[str, EntryPoint]:
    return {ep.name: ep for ep in entry_points(group=GROUP)}


def _sort_key(pid: str) -> tuple[int, str]:
    return (0 if pid[:1].isdigit() else 1, pid)


def problem_ids() -> list[str]:
    """Every registered id, in a stable order (numbered ids first)."""
    return sorted(_entry_points(), key=_sort_key)


def get(pid: str) -> Problem[Any]:
    """The problem registered under ``pid``; :class:`UnknownProblem` names the known ids (and
    a ``pid`` that is not a string at all)."""
    if not isinstance(pid, str):
        raise UnknownProblem(f"a problem id is a string such as '2013-6', not {type(pid).__name__}")
    return _get(pid)


@cache
def _get(pid: str) -> Problem[Any]:
    eps = _entry_points()
    if pid not in eps:
        known = ", ".join(problem_ids()) or "none (is geomcad installed with pip install .?)"
        raise UnknownProblem(f"unknown problem id {pid!r}; known ids: {known}")
    problem: Problem[Any] = eps[pid].load()
    return problem


def entry_point(pid: str) -> EntryPoint:
    """The entry point ``pid`` is registered under; :class:`UnknownProblem` as :func:`get`."""
    get(pid)
    return _entry_points()[pid]


#: The table of the problems' titles in each language (``<package>/strings/<lang>/titles.toml``).
TITLES = "titles"


def title(problem: Problem[Any], lang: str | None = None) -> str:
    """``problem``'s title in ``lang`` (default: the language being drawn): its entry in the
    ``titles`` table of the package that registers it, else its own :attr:`Problem.title`
    (a file's problem, or a package without the table)."""
    from importlib import resources

    from geomcad.sheet.lang import Words, check_lang, current

    ep = _entry_points().get(problem.id)
    if ep is None or ep.module is None:
        return problem.title
    package = ep.module.rpartition(".")[0]
    lang_ = check_lang(lang) if lang else current()
    try:
        has = resources.files(package).joinpath("strings", lang_, f"{TITLES}.toml").is_file()
    except ModuleNotFoundError:
        has = False
    if not has:
        return problem.title
    return Words(package, TITLES).table(lang_).get(problem.id, problem.title)


#: The table of the task cards' words per language (``<package>/strings/<lang>/cards.toml``).
CARDS = "cards"


def card_words(problem: Problem[Any], lang: str) -> dict[str, str]:
    """``problem``'s entries of its package's ``cards`` table in ``lang``, by parameter or
    result name (``ID.NAME`` keys with the id taken off); empty where there is none."""
    from importlib import resources

    from geomcad.sheet.lang import Words, check_lang

    ep = _entry_points().get(problem.id)
    if ep is None or ep.module is None:
        return {}
    package = ep.module.rpartition(".")[0]
    lang_ = check_lang(lang)
    try:
        has = resources.files(package).joinpath("strings", lang_, f"{CARDS}.toml").is_file()
    except ModuleNotFoundError:
        has = False
    if not has:
        return {}
    head = f"{problem.id}."
    table = Words(package, CARDS).table(lang_)
    return {k.removeprefix(head): v for k, v in table.items() if k.startswith(head)}
