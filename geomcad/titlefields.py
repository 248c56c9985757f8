"""A user's ``[sheet]`` table checked as data: the title-block fields, the language, the format.

A cam or gear file may carry a ``[sheet]`` table (who hands the sheet in, the language, the
format). It is checked while the file is read, so that a misspelt key or a wrong value is one
``error:`` line naming it even on ``geomcad solve``; the check is data only and needs no drawing
layer (a solve loads no ``geomcad.sheet`` module). The sheet layer
(:class:`geomcad.sheet.titleblock.TitleData`, :mod:`geomcad.sheet.formats`) takes its keys,
languages and formats from here, and adds what only the drawing can tell: whether the sheet
font has a glyph for every character (checked when the sheet is drawn).
"""

from __future__ import annotations

import datetime as _dt
from collections.abc import Mapping
from typing import Literal, get_args

from geomcad.errors import ParameterError

#: The languages the sheets are drawn in.
Lang = Literal["ru", "en"]
LANGS: tuple[Lang, ...] = get_args(Lang)

#: The formats a composed sheet may take, smallest first (A0 is a sheet no course asks for).
SHEET_FORMATS: tuple[str, ...] = ("A4", "A3", "A2", "A1")

#: The keys of a ``[sheet]`` table's title-block data (the fields of ``TitleData``).
TITLE_KEYS: tuple[str, ...] = (
    "student", "checker", "tcontrol", "ncontrol", "approver", "group", "org", "date",
    "designation", "stage", "revision", "lang",
)  # fmt: skip

#: The longest text a title-block field takes (the widest cell, графа 2, holds about 40
#: characters at the smallest GOST height on two lines; the rest is refused by
#: :func:`~geomcad.sheet.frame.fit_text` as not fitting).
MAX_TEXT = 200


def field_text(key: str, value: object) -> str:
    """A title-block field's value as text: a string of one line, at most :data:`MAX_TEXT`
    characters, stripped; a TOML date written ``DD.MM.YYYY``. Anything else is a
    :class:`~geomcad.errors.ParameterError` naming ``key``.

    >>> import datetime
    >>> field_text("sheet.date", datetime.date(2026, 11, 27)), field_text("sheet.org", " МГТУ ")
    ('27.11.2026', 'МГТУ')
    """
    if isinstance(value, _dt.datetime):
        value = value.date()
    if isinstance(value, _dt.date):
        return value.strftime("%d.%m.%Y")
    if isinstance(value, str):
        if "\n" in value:
            raise ParameterError(key, value, "must be one line of text")
        if len(value) > MAX_TEXT:
            raise ParameterError(
                key,
                value,
                f"is {len(value)} characters long: a title-block cell holds at most {MAX_TEXT}",
            )
        return value.strip()
    raise ParameterError(key, value, "must be text")


def title_values(data: object, where: str = "sheet") -> dict[str, str]:
    """The title-block fields of a ``[sheet]`` table (``where`` names it in errors): each key
    one of :data:`TITLE_KEYS`, each value through :func:`field_text`, ``lang`` one of
    :data:`LANGS`; an unknown key or a wrong value is a :class:`~geomcad.errors.ParameterError`
    naming ``where.KEY``."""
    if not isinstance(data, Mapping):
        raise ParameterError(where, data, "must be a table of title-block fields")
    values: dict[str, str] = {}
    for key, value in data.items():
        if key not in TITLE_KEYS:
            raise ParameterError(
                f"{where}.{key}",
                value,
                f"is not a title-block field (known: {', '.join(TITLE_KEYS)})",
            )
        values[key] = field_text(f"{where}.{key}", value)
    if values.get("lang") and values["lang"] not in LANGS:
        raise ParameterError(f"{where}.lang", values["lang"], f"must be one of {', '.join(LANGS)}")
    return values


def check_format(fmt: object, key: str = "sheet.format") -> str:
    """A format a user asks for (``[sheet] format = "A2"``), checked: one of
    :data:`SHEET_FORMATS`; a :class:`~geomcad.errors.ParameterError` naming ``key`` otherwise."""
    if not isinstance(fmt, str) or fmt not in SHEET_FORMATS:
        raise ParameterError(key, fmt, f"must be one of {', '.join(SHEET_FORMATS)}")
    return fmt
