"""The answer key: which results of a solved variant it holds, named and printed how.

A result is flattened into *paths*, the names ``geomcad verify`` reads: ``l1``, ``r.2`` (a list
item, counted from 0), ``positions.0.V_D`` (a field of an object in a list). A key is a list of
patterns matched against those paths (:mod:`fnmatch` wildcards; a bare name also takes every item
under it), so ``stroke,K,positions.*.V_D`` or ``omega*`` choose columns for any kind.

Values are printed with the subject's usual precision: four significant figures, as a plain
decimal (no exponent), integers as they are.

    >>> flatten({"l1": 0.065, "r": [0.04, 0.045], "ok": True, "profile": [[0.0, 1.0]]})
    {'l1': 0.065, 'r.0': 0.04, 'r.1': 0.045}
    >>> select({"l1": 0.065, "r.0": 0.04, "r.1": 0.045}, ["r"])
    ['r.0', 'r.1']
    >>> fmt(1234.5678), fmt(0.00123456), fmt(-0.5), fmt(3), fmt(0.0)
    ('1235', '0.001235', '-0.5000', '3', '0')
"""

from __future__ import annotations

import fnmatch
import math
import numbers
from collections.abc import Iterable, Mapping, Sequence
from decimal import Decimal
from typing import Any

from geomcad import tol

#: Significant figures of the answer key (the subject writes results to 3–4 figures).
FIGURES = 4

#: A list of plain numbers longer than this is a curve (a profile), not answers.
MAX_LIST = 360


def _is_number(x: object) -> bool:
    return isinstance(x, numbers.Real) and not isinstance(x, bool)


def flatten(results: Mapping[str, Any], max_list: int = MAX_LIST) -> dict[str, float | int]:
    """Every number of ``results`` under its path, in the results' order.

    Lists of numbers give ``NAME.i`` (unless longer than ``max_list``); lists of objects give
    ``NAME.i.FIELD``; nested objects ``NAME.FIELD``; lists of lists (curves), strings and
    booleans are left out.
    """
    out: dict[str, float | int] = {}

    def walk(node: Any, path: str) -> None:
        if _is_number(node):
            out[path] = int(node) if isinstance(node, numbers.Integral) else float(node)
        elif isinstance(node, Mapping):
            for k, v in node.items():
                walk(v, f"{path}.{k}")
        elif isinstance(node, list | tuple):
            if all(_is_number(v) for v in node) and len(node) > max_list:
                return
            if any(isinstance(v, list | tuple) for v in node):
                return
            for i, v in enumerate(node):
                walk(v, f"{path}.{i}")

    for name, value in results.items():
        walk(value, str(name))
    return out


def matches(path: str, pattern: str) -> bool:
    """True when ``path`` is the pattern's, or lies under a bare name (``r`` takes ``r.2``)."""
    return fnmatch.fnmatchcase(path, pattern) or path.startswith(pattern + ".")


def select(paths: Iterable[str], patterns: Sequence[str]) -> list[str]:
    """The paths that some pattern matches, in the paths' own order."""
    return [p for p in paths if any(matches(p, pat) for pat in patterns)]


def parse_patterns(text: str) -> list[str]:
    """``--key`` text: names or patterns separated by commas (or spaces)."""
    return [t for t in text.replace(",", " ").split() if t]


def fmt(value: float | int) -> str:
    """A key value: four significant figures, plain decimal; an integer as it is."""
    if isinstance(value, numbers.Integral):
        return str(int(value))
    x = float(value)
    if x == 0.0 or not math.isfinite(x):
        return "0" if x == 0.0 else str(x)
    exp = math.floor(math.log10(abs(x)))
    decimals = FIGURES - 1 - exp
    q = Decimal(repr(x)).quantize(Decimal(1).scaleb(-max(decimals, 0)))
    if decimals < 0:
        q = Decimal(round(x, decimals)).quantize(Decimal(1))
    # round half away from zero can carry into one more digit (9.9996 → 10.000): drop it
    s = format(q, "f")
    if decimals > 0 and len(s.replace("-", "").replace(".", "").lstrip("0")) > FIGURES:
        s = s[:-1]
    return s


def leaf(path: str) -> str:
    """The last name in a path that is not an index (``positions.3.V_D`` → ``V_D``)."""
    for part in reversed(path.split(".")):
        if not part.isdecimal():
            return part
    return path


def rows(
    results: Sequence[Mapping[str, float | int]], columns: Sequence[str], first: Sequence[str]
) -> list[list[str]]:
    """The key's text rows: ``first[i]``, then each column's value of ``results[i]`` (blank
    where a variant lacks it). A value that is round-off beside the largest of its quantity
    (the same name in every position and variant: a slider's V at its extreme, 4.6·10⁻¹⁷ m/s)
    is printed as 0.

    >>> rows([{"p.0.V": 4.6e-17, "p.1.V": 2.0}, {"p.0.V": 1e-16}], ["p.0.V", "p.1.V"], ["1", "2"])
    [['1', '0', '2.000'], ['2', '0', '']]
    """
    big: dict[str, float] = {}
    for r in results:
        for c in columns:
            if c in r:
                big[leaf(c)] = max(big.get(leaf(c), 0.0), abs(float(r[c])))
    out = []
    for head, r in zip(first, results, strict=True):
        row = [head]
        for c in columns:
            if c not in r:
                row.append("")
                continue
            x = r[c]
            if isinstance(x, float) and abs(x) <= tol.DERIVED * big[leaf(c)]:
                x = 0.0
            row.append(fmt(x))
        out.append(row)
    return out


#: Units as a spreadsheet's header writes them (plain text), per language.
HEADER_UNITS = {
    "ru": {"m": "м", "m/s": "м/с", "m/s²": "м/с²", "rad/s": "1/с", "rad/s²": "1/с²", "N": "Н",
           "N·m": "Н·м", "kg": "кг", "kg·m²": "кг·м²", "deg": "°", "s": "с", "J": "Дж"},
    "en": {"rad/s": "1/s", "rad/s²": "1/s²", "deg": "°"},
}  # fmt: skip

#: How a header says "position", per language.
POSITION = {"ru": "пол.", "en": "pos."}


def header(column: str, unit: str, lang: str) -> str:
    """A key column's spreadsheet header: its name, the position or item it is at, its unit.

    >>> header("positions.3.V_D", "m/s", "ru"), header("theta_deg", "deg", "en")
    ('V_D, пол. 3, м/с', 'theta, °')
    >>> header("r.2", "m", "en"), header("K", "1", "ru")
    ('r[2], m', 'K')
    """
    parts = column.split(".")
    name = leaf(column)
    where = ""
    if parts[0] == "positions" and len(parts) == 3 and parts[1].isdecimal():
        where = f", {POSITION.get(lang, 'pos.')} {parts[1]}"
    elif parts[-1].isdecimal():
        name = f"{column.rsplit('.', 1)[0]}[{parts[-1]}]"
    u = HEADER_UNITS.get(lang, {}).get(unit, "" if unit == "1" else unit)
    return name.removesuffix("_deg") + where + (f", {u}" if u else "")
