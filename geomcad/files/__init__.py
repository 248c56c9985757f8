"""File kinds: problems given as TOML files, one module per kind, and what they share.

A file kind is registered in the ``geomcad.files`` entry-point group (``pyproject.toml``; the
name is the file's marking table) as a callable ``make_problem(file_id, data) -> Problem``;
:mod:`geomcad.documents` reads the file, tells its kind and calls it.

- :mod:`geomcad.files.common`: the shared reader (typed values with their dotted keys in every
  error, unknown keys refused by name; the top level and the ``[sheet]`` table);
- :mod:`geomcad.files.cam` (``[cam]``) with its sheet :mod:`geomcad.files.cam_sheets`;
- :mod:`geomcad.files.gears` (``[gears]``) with its sheets :mod:`geomcad.files.gears_sheets`;
- :mod:`geomcad.files.linkage`: the linkage file (no marking table, ``../shared/linkages.md``;
  :mod:`geomcad.documents` calls it for a file of no registered kind); its sheets are the sheet
  layer's own (:mod:`geomcad.sheet.linkage`), as they need nothing of the file.

Layers (``tests/test_layers.py``): a kind imports the library below it (up to ``render``) and
:mod:`geomcad.problem`; :mod:`geomcad.documents`, ``verify``, ``teach`` and ``cli`` are above
it. A kind's model module imports no sheet at load time: its sheets are reached through
:func:`~geomcad.problem.lazy` references, so a solve draws nothing. This module imports nothing
heavy: ``geomcad list`` and a file's kind are told without numpy.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

if TYPE_CHECKING:
    from geomcad.problem import Build, Problem, ResultSpec, Solution
    from geomcad.sheet import Sheet
    from geomcad.sheet.motion import Frames

#: The type of a file kind's model (``Build.data``), as :data:`geomcad.problem.D`.
D = TypeVar("D")


def file_problem(
    file_id: str,
    data: dict[str, Any],
    title: str,
    results: tuple[ResultSpec, ...],
    build: Callable[[Mapping[str, Any]], Build[D]],
    draw: Callable[[Solution[D]], Sequence[tuple[str, Sheet]]],
    motion: Callable[[Solution[D], int], Frames] | None = None,
    cls: type[Problem[D]] | None = None,
    scales: Callable[[Solution[D]], Mapping[str, float]] | None = None,
) -> Problem[D]:
    """The problem of a file kind, as :mod:`geomcad.documents` says it is: no parameters (the
    file is the data), no seed, the file's data as its ``inputs``; ``cls`` a subclass of
    :class:`~geomcad.problem.Problem` where the kind needs one."""
    from geomcad.problem import Problem

    return (cls or Problem)(
        id=file_id,
        title=title,
        params=(),
        results=results,
        seed={},
        build=build,
        draw=draw,
        inputs=data,
        motion=motion,
        scales=scales,
    )


def stem(pid: str) -> str:
    """The name a file's sheets are written under: its stem (``mech.toml`` → ``mech``)."""
    return Path(pid).stem


#: The longest code a file's stem gives a default designation: "ТММ.<code>.01" fits графа 26
#: (70 mm) 3.5 mm high in letters of common width, and at GOST's smaller heights in any.
CODE_CHARS = 17
#: The mark between a code's words: a dot, as between the parts of an ESKD designation (GOST
#: 2.201: ``АБВГ.301261.001``); not a hyphen, which there marks an execution's number
#: (``АБВГ.301261.001-01``), nor nothing (``CRANKROCKER`` does not read as two words). A
#: default designation is then letters, digits and dots only, as the issue asks of a code:
#: ``ТММ.CRANK.ROCKER.01`` (review 8 of issue 27).
CODE_JOIN = "."


def _words(name: str) -> list[str]:
    """A stem's words: its runs of letters and of digits, a camelCase word split at its capitals
    (``sixBar_press-2`` → six, Bar, press, 2)."""
    out: list[str] = []
    for run in re.findall(r"\d+|[^\W\d_]+", name):
        out += re.findall(r"\d+|[^\W\d_][^\W\d_A-ZА-ЯЁ]*|[A-ZА-ЯЁ]+(?![a-zа-яё])", run) or [run]
    return out


def code(pid: str) -> str:
    """The file's stem as a part of a designation that reads back to the file, as an ESKD code
    writes it (upper case, letters and digits only, at most :data:`CODE_CHARS`): the stem's
    words whole, joined by :data:`CODE_JOIN` (a dot), as many of its first words as fit; the
    words are cut at a word's end, never inside one (review 7: the syllables of ``TANGROCKSLID``,
    ``YOKPUMDOUSLI`` did not read as words); a first word longer than :data:`CODE_CHARS` alone
    is cut to it. A stem without letters or digits gives ``""``.

    >>> code("sixbar_press.toml"), code("tangent_rocking_slider"), code("a/kulisa-23110713")
    ('SIXBAR.PRESS', 'TANGENT.ROCKING', 'KULISA.23110713')
    """
    words = [w.upper() for w in _words(stem(pid))]
    if not words:
        return ""
    out = words[0][:CODE_CHARS]
    for w in words[1:]:
        if len(out) + len(CODE_JOIN) + len(w) > CODE_CHARS:
            break
        out += CODE_JOIN + w
    return out
