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


#: The longest code a file's stem gives a default designation (графа 26 is 70 mm wide).
CODE_CHARS = 12


def _words(name: str) -> list[str]:
    """A stem's words: its runs of letters and of digits, a camelCase word split at its capitals
    (``sixBar_press-2`` → six, Bar, press, 2)."""
    out: list[str] = []
    for run in re.findall(r"\d+|[^\W\d_]+", name):
        out += re.findall(r"\d+|[^\W\d_][^\W\d_A-ZА-ЯЁ]*|[A-ZА-ЯЁ]+(?![a-zа-яё])", run) or [run]
    return out


def code(pid: str) -> str:
    """The file's stem as a part of a designation that reads as an ESKD code (letters and
    digits only, upper case, at most :data:`CODE_CHARS`), as a drawing office shortens a name:

    - the whole stem's letters and digits where they fit (``sixbar_press.toml`` →
      ``SIXBARPRESS``, ``sixbar-2013-6`` → ``SIXBAR20136``);
    - else each word cut to its first k letters, k the most that fits (the letters left over go
      one each to the first words still longer), its numbers kept whole, so that the code reads
      back to the file (``tangent_rocking_slider`` → ``TANGROCKSLID``, not the initials TRS;
      ``kulisa-23110713`` → ``KULI23110713``); two stems that share a long first word stay
      apart, as a cut at :data:`CODE_CHARS` letters does not keep them;
    - a single word longer than that, or numbers alone longer, the first :data:`CODE_CHARS`.

    A stem without letters or digits gives ``""``.

    >>> code("sixbar_press.toml"), code("synthesis-slotted-lever.toml"), code("a/kulisa-23110713")
    ('SIXBARPRESS', 'SYNTSLOTLEVE', 'KULI23110713')
    """
    words = [w.upper() for w in _words(stem(pid))]
    whole = "".join(words)
    letters = [w for w in words if not w.isdigit()]
    room = CODE_CHARS - sum(len(w) for w in words if w.isdigit())
    if len(whole) <= CODE_CHARS or len(words) == 1 or room < len(letters):
        return whole[:CODE_CHARS]
    k = max(j for j in range(1, room + 1) if sum(min(len(w), j) for w in letters) <= room)
    spare = room - sum(min(len(w), k) for w in letters)
    out = []
    for w in words:
        if w.isdigit():
            out.append(w)
            continue
        take = min(len(w), k + (1 if spare > 0 and len(w) > k else 0))
        spare -= take - min(len(w), k)
        out.append(w[:take])
    return "".join(out)
