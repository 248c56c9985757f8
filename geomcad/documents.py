"""Problems given as files: a path ending in ``.toml`` stands wherever a problem id does.

A file is TOML (read with :mod:`tomllib`). Its kind is told by a top-level table: a file with a
``[cam]`` table is a cam file, one with ``[gears]`` a gear file, and so on for every kind
registered in the ``geomcad.files`` entry-point group (name = the marking table); a file with
none of them is a linkage file (``../shared/linkages.md``), which the library handles itself.

A kind is a callable ``make(file_id, data) -> Problem``: ``file_id`` is the path as the user gave
it, ``data`` the parsed file after every ``--set``. The problem it returns has no parameters (the
file is the data), an empty seed, and ``inputs`` = the data, which ``solve --json`` prints as its
``params``.

``--set KEY=VALUE`` takes a dotted path into the file: ``drive.omega=15``,
``group.1.lengths.1=0.42`` (list items count from 1), ``links.2.mass=10``. The value is read as
a TOML value (a number, a string with or without quotes, ``true``/``false``, an array).

    >>> data = {"drive": {"omega": 20.0}, "group": [{"lengths": [0.4, 0.25]}]}
    >>> apply_set(data, "group.1.lengths.2", "0.3")
    >>> data["group"][0]["lengths"]
    [0.4, 0.3]
"""

from __future__ import annotations

import math
import sys
import tomllib
from collections.abc import Callable, Sequence
from functools import cache
from importlib.metadata import entry_points
from pathlib import Path
from typing import TYPE_CHECKING, Any

from geomcad.errors import FileKeyError, ParameterError

# a file kind's problem and its sheets' name live with the kinds; kept here for the callers
from geomcad.files import file_problem as file_problem
from geomcad.files import stem as stem

if TYPE_CHECKING:
    from geomcad.problem import Problem, Solution

GROUP = "geomcad.files"
SUFFIX = ".toml"

Maker = Callable[[str, dict[str, Any]], "Problem[Any]"]


def is_file_id(pid: str) -> bool:
    """True when ``pid`` names a file (a path ending in ``.toml``) rather than a problem id."""
    return pid.lower().endswith(SUFFIX)


def read(pid: str) -> dict[str, Any]:
    """The file's TOML data (UTF-8, a byte-order mark allowed); a missing file, a syntax error
    or data nested deeper than :data:`MAX_DEPTH` is a :class:`FileKeyError` naming the file."""
    path = Path(pid)
    try:
        text = path.read_bytes().decode("utf-8-sig")  # a byte-order mark, if any, is dropped
    except FileNotFoundError:
        raise FileKeyError(pid, "", "no such file") from None
    except IsADirectoryError:
        raise FileKeyError(pid, "", "is a folder, not a file") from None
    except UnicodeDecodeError as exc:
        raise FileKeyError(pid, "", f"is not UTF-8 text ({exc.reason})") from None
    except OSError as exc:
        raise FileKeyError(pid, "", f"cannot be read ({exc.strerror or exc})") from None
    try:
        return tomllib.loads(text)
    except RecursionError:  # tomllib reads nested arrays and inline tables recursively
        raise FileKeyError(pid, "", TOO_DEEP) from None
    except tomllib.TOMLDecodeError as exc:
        raise FileKeyError(pid, "", f"is not valid TOML: {exc}") from None
    except ValueError:  # Python reads no integer of over 4300 digits
        raise FileKeyError(pid, "", f"is not valid TOML: {HUGE_INTEGER}") from None


def parse_value(text: str, key: str = "") -> Any:
    """A ``--set`` value read as TOML (number, bool, string, array); bare words are strings.
    ``key`` is the dotted key it is set to, named by the error of a value that is not finite."""
    t = text.strip()
    try:
        value = tomllib.loads(f"v = {t}")["v"]
    except RecursionError:
        raise ParameterError(t, text, TOO_DEEP) from None
    except ValueError:  # TOMLDecodeError, or an integer of over 4300 digits
        if t.count(",") == 1 and "." not in t:  # a decimal comma
            try:
                return float(t.replace(",", "."))
            except ValueError:
                pass
        return t
    if isinstance(value, float) and not math.isfinite(value):
        raise ParameterError(key or t, text, "must be a finite number")
    return value


def apply_set(data: dict[str, Any], key: str, text: str) -> None:
    """Set the dotted ``key`` of ``data`` to the value ``text`` (see the module's docstring).

    A list item is counted from 1 and must exist; a table may gain a new key (the kind's own
    check then says whether it knows it).
    """
    parts = [p.strip() for p in key.split(".")]
    if not key or any(not p for p in parts):
        raise ParameterError(key, text, "--set takes a dotted key such as drive.omega")
    node: Any = data
    for depth, part in enumerate(parts):
        last = depth == len(parts) - 1
        where = ".".join(parts[: depth + 1])
        if isinstance(node, list):
            if not part.isdigit() or not 1 <= int(part) <= len(node):
                raise ParameterError(
                    key, text, f"{where}: the list has items 1 … {len(node)} (counted from 1)"
                )
            if last:
                node[int(part) - 1] = parse_value(text, key)
                return
            node = node[int(part) - 1]
        elif isinstance(node, dict):
            if last:
                node[part] = parse_value(text, key)
                return
            if part not in node:
                node[part] = {}
            node = node[part]
        else:
            prev = ".".join(parts[:depth])
            raise ParameterError(key, text, f"{prev} is a value, not a table or a list")


@cache
def _kinds() -> dict[str, Any]:
    return {ep.name: ep for ep in entry_points(group=GROUP)}


def kind_of(data: dict[str, Any]) -> str:
    """The file's kind: the first registered kind whose table the file has, else "linkage"."""
    for name in sorted(_kinds()):
        if isinstance(data.get(name), dict):
            return name
    return "linkage"


def _maker(kind: str) -> Maker:
    if kind == "linkage":
        return _linkage_problem
    maker: Maker = _kinds()[kind].load()
    return maker


def load(pid: str, sets: Sequence[tuple[str, str]] = ()) -> Problem[Any]:
    """The problem a file states, with the ``--set`` pairs ``(KEY, VALUE)`` applied."""
    data = read(pid)
    for key, text in sets:
        apply_set(data, key, text)
    return from_data(pid, data)


#: TOML's integers are 64-bit (the specification); :mod:`tomllib` reads longer ones too.
INT_MIN, INT_MAX = -(2**63), 2**63 - 1

HUGE_INTEGER = f"an integer of over {sys.get_int_max_str_digits()} digits"

#: The deepest nesting of tables and arrays a file may have (a linkage file needs 4).
MAX_DEPTH = 32
TOO_DEEP = f"is nested too deeply: a file's tables and arrays go at most {MAX_DEPTH} levels deep"


def check_integers(node: object, path: str = "") -> None:
    """Refuse an integer outside TOML's 64-bit range anywhere in the data (it would overflow
    the float it is read as), and tables or arrays nested deeper than :data:`MAX_DEPTH`: a
    :class:`FileKeyError` naming its key. The walk keeps its own stack (no recursion)."""
    stack: list[tuple[object, str, int]] = [(node, path, 0)]
    while stack:
        item, where, depth = stack.pop()
        if isinstance(item, dict | list):
            if depth > MAX_DEPTH:
                raise FileKeyError(where.split(".", 1)[0], "", TOO_DEEP)
            pairs = item.items() if isinstance(item, dict) else enumerate(item, start=1)
            # in the file's order: the first bad key is the one named
            stack += reversed(
                [(v, f"{where}.{k}" if where else str(k), depth + 1) for k, v in pairs]
            )
        elif (
            isinstance(item, int) and not isinstance(item, bool) and not INT_MIN <= item <= INT_MAX
        ):
            digits = len(str(abs(item))) if abs(item) < 10**4000 else "thousands of"
            raise FileKeyError(
                where, "", f"a whole number of {digits} digits is beyond TOML's 64 bits"
            )


def from_data(pid: str, data: dict[str, Any]) -> Problem[Any]:
    """The problem that the file data ``data`` states, named ``pid`` (a file's data held in
    memory: a variant before it is written)."""
    check_integers(data)
    return _maker(kind_of(data))(pid, data)


def solve(pid: str, sets: Sequence[tuple[str, str]] = ()) -> Solution[Any]:
    """Load the file ``pid`` and solve it."""
    return load(pid, sets).solve()


def _linkage_problem(file_id: str, data: dict[str, Any]) -> Problem[Any]:
    """A linkage file (``../shared/linkages.md``) as a problem: model, solution and sheets."""
    from geomcad.files.linkage import make_problem

    return make_problem(file_id, data)
