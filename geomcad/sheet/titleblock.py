"""Who hands the sheet in: the user's data for the main title block (GOST 2.104, form 1).

A sheet module knows what it draws (its title, its designation, its scale, its number in the set);
it does not know who draws it. That comes from the user, through :class:`TitleData`:

- the ``--student --checker --group --org --date --designation`` options of ``geomcad build``;
- a ``[sheet]`` table in ``geomcad.toml`` in the working directory;
- a ``[sheet]`` table in a linkage file (:meth:`TitleData.from_mapping` reads either table).

The data in force while sheets are drawn is set with :func:`filled` (a context manager), and
:func:`~geomcad.sheet.frame.new_sheet` merges it into every title block it draws. Without user
data the people's and the organisation's cells stay empty, to be filled in by hand: a program's
name is never written where a person signs.
"""

from __future__ import annotations

import contextlib
import tomllib
from collections.abc import Iterator, Mapping
from contextvars import ContextVar
from dataclasses import dataclass, fields, replace
from pathlib import Path

from geomcad.errors import FileKeyError, ParameterError
from geomcad.sheet.lang import Words
from geomcad.titlefields import title_values

#: The file in the working directory whose ``[sheet]`` table ``geomcad build`` reads.
CONFIG_FILE = "geomcad.toml"

#: Лит. of a student's work (GOST 2.103: "У", учебный документ), from the Russian caption table.
STUDENT_STAGE = Words(__package__, "frame")("student_stage", "ru")


@dataclass(frozen=True)
class TitleData:
    """The user's part of the title block; an empty string leaves its cell blank.

    - ``student``: Разраб. (графа 11, row Разраб.); ``checker``: Пров.; ``tcontrol``: Т.контр.;
      ``ncontrol``: Н.контр.; ``approver``: Утв.
    - ``group`` and ``org``: графа 9 (the organisation, then the student's group).
    - ``date``: графа 13 of the Разраб. row (any text, e.g. ``24.11.26``).
    - ``designation``: графа 2 (and 26), one for every sheet of a document; empty keeps the
      problem's own designation.
    - ``stage``: Лит. (графа 4), "У" for coursework; on an English sheet, ISO 7200's document
      status (the Russian "У" is not carried over).
    - ``revision``: ISO 7200's revision index (English sheets).
    - ``lang``: the language the sheets are drawn in (``ru`` or ``en``; empty: Russian, or what
      a table under these data says).
    """

    student: str = ""
    checker: str = ""
    tcontrol: str = ""
    ncontrol: str = ""
    approver: str = ""
    group: str = ""
    org: str = ""
    date: str = ""
    designation: str = ""
    stage: str = STUDENT_STAGE
    revision: str = ""
    lang: str = ""

    @classmethod
    def keys(cls) -> tuple[str, ...]:
        """The keys a ``[sheet]`` table may hold."""
        return tuple(f.name for f in fields(cls))

    @classmethod
    def from_mapping(cls, data: Mapping[str, object], where: str = "sheet") -> TitleData:
        """The data of a ``[sheet]`` table (``where`` names it in errors).

        Values are strings (a TOML date is written ``YYYY-MM-DD`` → ``DD.MM.YYYY``); an unknown
        key or another type is a :class:`~geomcad.errors.ParameterError` naming ``where.KEY``.
        """
        values = title_values(data, where)  # the keys and values as data (geomcad.titlefields)
        for key, value in values.items():
            _drawable(f"{where}.{key}", value)
        return cls(**values)

    @classmethod
    def from_toml(cls, path: Path) -> TitleData:
        """The ``[sheet]`` table of a TOML file (no table: no data). A file that is not TOML is a
        :class:`~geomcad.errors.FileKeyError` naming the file."""
        here = path.parent.resolve() == Path.cwd().resolve()
        name = path.name if here else str(path)  # errors name a file of the working directory
        try:
            doc = tomllib.loads(path.read_bytes().decode("utf-8-sig"))  # a BOM is dropped
        except UnicodeDecodeError as exc:
            raise FileKeyError(name, "", f"is not UTF-8 text ({exc.reason})") from None
        except RecursionError:  # tomllib reads nested arrays recursively
            raise FileKeyError(name, "", "is not valid TOML: nested too deeply") from None
        except ValueError as exc:  # TOMLDecodeError, or an integer of over 4300 digits
            raise FileKeyError(name, "", f"is not valid TOML: {exc}") from None
        except OSError as exc:
            raise FileKeyError(name, "", f"cannot be read: {exc.strerror or exc}") from None
        table = doc.get("sheet")
        if table is None:
            return cls()
        return cls.from_mapping(table, f"{path.name}: sheet")

    @classmethod
    def from_workdir(cls, directory: Path | None = None) -> TitleData:
        """The ``[sheet]`` table of ``geomcad.toml`` in ``directory`` (default: the working
        directory); no file: no data."""
        path = (directory or Path.cwd()) / CONFIG_FILE
        return cls.from_toml(path) if path.is_file() else cls()

    def over(self, base: TitleData) -> TitleData:
        """These data laid over ``base``: every non-empty field here wins."""
        changes = {f.name: getattr(self, f.name) for f in fields(self) if getattr(self, f.name)}
        return replace(base, **changes)

    @property
    def empty(self) -> bool:
        """True when no person, place or date is given (the stage alone does not count)."""
        return not any(
            getattr(self, f.name) for f in fields(self) if f.name not in ("stage", "lang")
        )


def _drawable(key: str, text: str) -> str:
    """``text`` if the sheet font has a glyph for each of its characters; else a
    :class:`~geomcad.errors.ParameterError` naming ``key``."""
    from geomcad.sheet.text import lacking, no_glyph

    if lacking(text):
        raise ParameterError(key, text, no_glyph(text))
    return text


_CURRENT: ContextVar[TitleData | None] = ContextVar("geomcad_title_data", default=None)


def current() -> TitleData:
    """The title-block data in force (empty cells when none is set)."""
    return _CURRENT.get() or TitleData()


@contextlib.contextmanager
def filled(data: TitleData | None) -> Iterator[TitleData]:
    """Draw the sheets inside this block with ``data`` in their title blocks."""
    token = _CURRENT.set(data)
    try:
        yield current()
    finally:
        _CURRENT.reset(token)
