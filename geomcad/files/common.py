"""Reading the tables of design files (``[cam]``, ``[gears]``): typed values with their dotted
keys in every error, and unknown keys refused by name."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import Any

from geomcad.errors import ParameterError
from geomcad.titlefields import SHEET_FORMATS, check_format, title_values


class Table:
    """One table of a file, read key by key: ``where`` is its dotted path (``cam``,
    ``gears.pair``); every value read is remembered, so :meth:`done` can refuse the others."""

    def __init__(self, data: Any, where: str) -> None:
        if not isinstance(data, Mapping):
            raise ParameterError(where, data, "must be a table")
        self.data = data
        self.where = where
        self.read: set[str] = set()

    def key(self, name: str) -> str:
        return f"{self.where}.{name}"

    def has(self, name: str) -> bool:
        return name in self.data

    def raw(self, name: str) -> Any:
        self.read.add(name)
        return self.data.get(name)

    def number(
        self,
        name: str,
        default: float | None = None,
        *,
        gt: float | None = None,
        ge: float | None = None,
        lt: float | None = None,
        le: float | None = None,
        unit: str = "",
    ) -> float:
        """A finite real number in range; a missing key takes ``default`` (None: required)."""
        v = self.raw(name)
        if v is None:
            if default is None:
                raise ParameterError(self.key(name), "missing", "this key is required")
            return default
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            raise ParameterError(self.key(name), v, "must be a finite number")
        x = float(v)
        u = f" {unit}" if unit else ""
        if gt is not None and not x > gt:
            raise ParameterError(self.key(name), v, f"must be > {gt:g}{u}")
        if ge is not None and not x >= ge:
            raise ParameterError(self.key(name), v, f"must be ≥ {ge:g}{u}")
        if lt is not None and not x < lt:
            raise ParameterError(self.key(name), v, f"must be < {lt:g}{u}")
        if le is not None and not x <= le:
            raise ParameterError(self.key(name), v, f"must be ≤ {le:g}{u}")
        return x

    def optional_number(self, name: str, **limits: float) -> float | None:
        if self.data.get(name) is None:
            self.read.add(name)
            return None
        return self.number(name, **limits)  # type: ignore[arg-type]

    def integer(
        self, name: str, default: int | None = None, *, ge: int = 1, le: int = 10**6
    ) -> int:
        v = self.raw(name)
        if v is None:
            if default is None:
                raise ParameterError(self.key(name), "missing", "this key is required")
            return default
        if (
            isinstance(v, bool)
            or not isinstance(v, int | float)
            or not math.isfinite(v)  # inf has no int(); NaN ≠ itself
            or v != int(v)
        ):
            raise ParameterError(self.key(name), v, "must be a whole number")
        if not ge <= int(v) <= le:
            raise ParameterError(self.key(name), v, f"must lie between {ge} and {le}")
        return int(v)

    def choice(self, name: str, choices: Iterable[str], default: str | None = None) -> str:
        opts = tuple(choices)
        v = self.raw(name)
        if v is None:
            if default is None:
                raise ParameterError(self.key(name), "missing", f"one of {', '.join(opts)}")
            return default
        if not isinstance(v, str) or v not in opts:
            raise ParameterError(self.key(name), v, f"must be one of {', '.join(opts)}")
        return v

    def text(self, name: str, default: str = "") -> str:
        v = self.raw(name)
        if v is None:
            return default
        if not isinstance(v, str):
            raise ParameterError(self.key(name), v, "must be a string")
        return v

    def done(self) -> None:
        """Refuse every key that was not read (a misspelt key would otherwise be ignored)."""
        extra = sorted(k for k in self.data if k not in self.read)
        if extra:
            known = ", ".join(sorted(self.read))
            raise ParameterError(
                self.key(extra[0]), self.data[extra[0]], f"unknown key (the table knows {known})"
            )


def check_top(
    data: Mapping[str, Any], kind: str, allowed: Iterable[str] = ("title", "sheet")
) -> str:
    """The file's top level: the marking table ``kind`` and, optionally, a ``title`` string and
    a ``[sheet]`` table of title-block data (``lang = "en"`` among them) and the sheet
    ``format`` (:func:`sheet_formats`), checked here as data (:mod:`geomcad.titlefields`: no
    sheet module is loaded; whether the font draws every character is the sheet's check)."""
    ok = {kind, *allowed}
    for k in data:
        if k not in ok:
            raise ParameterError(
                k, data[k], f"unknown top-level key in a [{kind}] file (it knows {', '.join(ok)})"
            )
    if "sheet" in data:
        title_values(title_fields(data["sheet"]), "sheet")
        sheet_formats(data)
    title = data.get("title", "")
    if not isinstance(title, str):
        raise ParameterError("title", title, "must be a string")
    return title


#: The key of a file's ``[sheet]`` table that asks for a format instead of the one chosen by
#: the sheet's content (:mod:`geomcad.sheet.formats`); the table's other keys are title-block data.
FORMAT_KEY = "format"


def title_fields(table: Any) -> Any:
    """A ``[sheet]`` table without its :data:`FORMAT_KEY` (the title-block data)."""
    if isinstance(table, Mapping):
        return {k: v for k, v in table.items() if k != FORMAT_KEY}
    return table


def sheet_formats(data: Mapping[str, Any]) -> tuple[str, ...]:
    """The formats a file's sheets may take: the one its ``[sheet]`` table asks for
    (``format = "A2"``), else every one of :data:`geomcad.titlefields.SHEET_FORMATS` (the sheet
    module takes the smallest its content allows)."""
    table = data.get("sheet")
    if isinstance(table, Mapping) and table.get(FORMAT_KEY) is not None:
        return (check_format(table[FORMAT_KEY], f"sheet.{FORMAT_KEY}"),)
    return SHEET_FORMATS
