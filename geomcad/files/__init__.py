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


#: The height at which a default designation fits графа 26 (70 mm, turned, in the frame's
#: top-left corner): 5 mm, the height typed designations take there (review 10 of issue 27:
#: ``ТММ.KULISA.INCLINED.01`` shrank to 3.5 mm where the others were 5).
CODE_HEIGHT = 5.0
#: The mark between a code's words: a dot, as between the parts of an ESKD designation (GOST
#: 2.201: ``АБВГ.301261.001``); not a hyphen, which there marks an execution's number
#: (``АБВГ.301261.001-01``), nor nothing (``CRANKROCKER`` does not read as two words). A
#: default designation is then letters, digits and dots only, as the issue asks of a code:
#: ``ТММ.КРАНК.РОКЕР.01`` (review 8 of issue 27).
CODE_JOIN = "."
#: The fixed parts of a default designation in each language, ``ТММ.<code>.01``, as its width
#: is measured (the sheet kinds' own templates differ only in the last two digits: 01, 04,
#: 05, of which 05 is the widest).
_CODE_FRAME = {"ru": "ТММ{j}{code}{j}05", "en": "TMM{j}{code}{j}05"}


def _words(name: str) -> list[str]:
    """A stem's words: its runs of letters and of digits, a camelCase word split at its capitals
    (``sixBar_press-2`` → six, Bar, press, 2)."""
    out: list[str] = []
    for run in re.findall(r"\d+|[^\W\d_]+", name):
        out += re.findall(r"\d+|[^\W\d_][^\W\d_A-ZА-ЯЁ]*|[A-ZА-ЯЁ]+(?![a-zа-яё])", run) or [run]
    return out


def _script(word: str, lang: str) -> str:
    """A word in the script of the designation's ``ТММ`` (``TMM``), upper case: on a Russian
    sheet its Latin letters transliterated to Cyrillic, on an English one its Cyrillic letters
    to Latin (the ``cyrtranslit`` library's Russian table; x, which it leaves, as кс; marks
    that are not letters dropped), so that a code never mixes scripts (review 10:
    ``ТММ.KULISA…``)."""
    other = r"[A-Za-z]" if lang == "ru" else r"[А-Яа-яЁё]"
    if not re.search(other, word):
        return word.upper()
    import cyrtranslit

    if lang == "ru":
        out = str(cyrtranslit.to_cyrillic(re.sub(r"[xX]", "ks", word.lower()), "ru"))
    else:
        out = str(cyrtranslit.to_latin(word.lower(), "ru"))
    return re.sub(r"[^\w]|_", "", out).upper()


def code(pid: str) -> str:
    """The file's stem as a part of a designation that reads back to the file, as an ESKD code
    writes it: upper case, letters and digits only, in one script with the designation's ``ТММ``
    (Latin letters transliterated to Cyrillic on a Russian sheet, :func:`_script`), and short
    enough that ``ТММ.<code>.01`` fits графа 26 (:data:`~geomcad.sheet.frame.G26_WIDTH`) at
    :data:`CODE_HEIGHT`. The code is the stem's first words whole, joined by
    :data:`CODE_JOIN` (a dot), as many as fit, then the initials of the words left (one part,
    digits whole) where they fit; words are cut at a word's end, never inside one (review 7:
    the syllables of ``TANGROCKSLID`` did not read as words); where not even the first word
    fits, the code is the initials (cut to the width only if they too do not fit). A stem
    without letters or digits gives ``""``.

    >>> code("sixbar_press.toml"), code("kulisa_inclined_ram"), code("a/kulisa-23110713")
    ('СИКСБАР.ПРЕСС', 'КУЛИСА.ИР', 'КУЛИСА')
    """
    from geomcad.sheet.frame import G26_WIDTH
    from geomcad.sheet.lang import current
    from geomcad.sheet.text import box, parse

    lang = current()
    words = [_script(w, lang) for w in _words(stem(pid))]
    if not words:
        return ""
    frame = _CODE_FRAME.get(lang, _CODE_FRAME["en"])

    def fits(c: str) -> bool:
        text = frame.format(j=CODE_JOIN, code=c)
        return box(parse(text), CODE_HEIGHT)[0] <= G26_WIDTH - 2.0

    k = 0
    while k < len(words) and fits(CODE_JOIN.join(words[: k + 1])):
        k += 1
    out = CODE_JOIN.join(words[:k])
    rest = "".join(w if w.isdigit() else w[0] for w in words[k:])
    if rest and fits(CODE_JOIN.join([*words[:k], rest])):
        return CODE_JOIN.join([*words[:k], rest])
    if not out:  # not even the initials fit: they are cut
        while len(rest) > 1 and not fits(rest):
            rest = rest[:-1]
        return rest
    return out
