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
#: The mark between a designation's parts: a dot, as between the parts of an ESKD designation
#: (GOST 2.201: ``АБВГ.301261.001``); not a hyphen, which there marks an execution's number
#: (``АБВГ.301261.001-01``). A default designation is then capitals, digits and dots only.
CODE_JOIN = "."
#: The fixed parts of a default designation in each language, ``ТММ.<code>.01``, as its width
#: is measured (the sheet kinds' own templates differ only in the last two digits: 01, 04,
#: 05, of which 05 is the widest).
_CODE_FRAME = {"ru": "ТММ{j}{code}{j}05", "en": "TMM{j}{code}{j}05"}
#: The digits of a numeric code (:func:`code`): six, as the classification part of an ESKD
#: designation (GOST 2.201: ``АБВГ.301261.001``).
CODE_DIGITS = 6
#: The letters of each script a title's initials are taken in (:func:`code`).
_SCRIPT = {"ru": "А-ЯЁа-яё", "en": "A-Za-z"}
#: The words a title's initials skip: prepositions, conjunctions and articles, which an
#: abbreviation of a name leaves out (кривошипно-ползунный механизм с качающейся кулисой →
#: КПМКК, not КПМСКК).
_SKIPPED = frozenset((
    "а", "без", "в", "во", "для", "до", "за", "и", "из", "или", "к", "ко", "на", "над", "о", "об",
    "обо", "от", "по", "под", "при", "с", "со", "у", "через",
    "a", "an", "and", "at", "by", "for", "in", "of", "on", "or", "the", "to", "with",
))  # fmt: skip


def _initials(title: str, lang: str) -> str:
    """A title's initials in the sheet's script, in capitals: the first letter of each word
    (each part of a hyphenated word: кривошипно-ползунный → КП), a run of digits whole,
    without the words of :data:`_SKIPPED`, letters of the other script, and a gloss in
    brackets (``(задача 2013-6)``) where the rest of the title has words; a title of one word
    gives that word whole. ``""`` where the title has no word in the script."""
    bare = re.sub(r"\([^()]*\)", " ", title)
    letters = _SCRIPT.get(lang, _SCRIPT["en"])
    word = rf"[{letters}]+|\d+"
    found: list[str] = re.findall(word, bare) or re.findall(word, title)
    words = [w for w in found if w.lower() not in _SKIPPED]
    if not any(not w.isdigit() for w in words):
        return ""
    if len(words) == 1:
        return words[0].upper()
    return "".join(w if w.isdigit() else w[0] for w in words).upper()


def code(pid: str, title: str = "") -> str:
    """The part of a file's default designation ``ТММ.<code>.01`` that names the file, as an
    ESKD code writes it (review 13 of issue 27: the stem's English words transliterated,
    ``ТММ.ГАНГ.САВ.ФФ.01``, read as nonsense to a teacher):

    - where the file's ``title`` has words in the sheet's script (Cyrillic on a Russian
      sheet, Latin on an English one), the title's initials, as a mechanism's name is
      abbreviated (Шестизвенный кривошипно-ползунный механизм → ШКПМ; :func:`_initials`),
      so the code reads back to the title printed beside it in the title block;
    - else a numeric code of :data:`CODE_DIGITS` digits, as the classification part of an
      ESKD designation: the CRC-32 of the file's stem, so that a file keeps its number from
      build to build and two files' numbers differ but by chance.

    The code is cut (initials from the end) until ``ТММ.<code>.05`` fits графа 26
    (:data:`~geomcad.sheet.frame.G26_WIDTH`) at :data:`CODE_HEIGHT`.

    >>> code("a/sixbar.toml", "Шестизвенный кривошипно-ползунный механизм (задача 2013-6)")
    'ШКПМ'
    >>> code("gang_saw_frame_feed.toml", "Механизм лесопильной рамы с приводом подачи")
    'МЛРПП'
    >>> code("gang_saw_frame_feed.toml")
    '829264'
    """
    import zlib

    from geomcad.sheet.frame import G26_WIDTH
    from geomcad.sheet.lang import current
    from geomcad.sheet.text import box, parse

    lang = current()
    frame = _CODE_FRAME.get(lang, _CODE_FRAME["en"])

    def fits(c: str) -> bool:
        text = frame.format(j=CODE_JOIN, code=c)
        return box(parse(text), CODE_HEIGHT)[0] <= G26_WIDTH - 2.0

    out = _initials(title, lang)
    if not out:
        number = zlib.crc32(stem(pid).encode("utf-8")) % 10**CODE_DIGITS
        return f"{number:0{CODE_DIGITS}d}"
    while len(out) > 1 and not fits(out):
        out = out[:-1]
    return out
