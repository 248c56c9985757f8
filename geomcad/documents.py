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
    """The file's TOML data; a missing file or a syntax error is a :class:`ParameterError`."""
    path = Path(pid)
    try:
        text = path.read_bytes().decode("utf-8")
    except FileNotFoundError:
        raise ParameterError(pid, "", "no such file") from None
    except IsADirectoryError:
        raise ParameterError(pid, "", "is a folder, not a file") from None
    except UnicodeDecodeError as exc:
        raise ParameterError(pid, "", f"is not UTF-8 text ({exc.reason})") from None
    except OSError as exc:
        raise ParameterError(pid, "", f"cannot be read ({exc.strerror or exc})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ParameterError(pid, "", f"is not valid TOML: {exc}") from None


def parse_value(text: str) -> Any:
    """A ``--set`` value read as TOML (number, bool, string, array); bare words are strings."""
    t = text.strip()
    try:
        value = tomllib.loads(f"v = {t}")["v"]
    except tomllib.TOMLDecodeError:
        if t.count(",") == 1 and "." not in t:  # a decimal comma
            try:
                return float(t.replace(",", "."))
            except ValueError:
                pass
        return t
    if isinstance(value, float) and not math.isfinite(value):
        raise ParameterError(t, text, "must be a finite number")
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
                node[int(part) - 1] = parse_value(text)
                return
            node = node[int(part) - 1]
        elif isinstance(node, dict):
            if last:
                node[part] = parse_value(text)
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


def check_integers(node: object, path: str = "") -> None:
    """Refuse an integer outside TOML's 64-bit range anywhere in the data (it would overflow
    the float it is read as): a :class:`FileKeyError` naming its key."""
    if isinstance(node, dict):
        for k, v in node.items():
            check_integers(v, f"{path}.{k}" if path else str(k))
    elif isinstance(node, list):
        for i, v in enumerate(node, start=1):
            check_integers(v, f"{path}.{i}")
    elif isinstance(node, int) and not isinstance(node, bool) and not INT_MIN <= node <= INT_MAX:
        digits = len(str(abs(node)))
        raise FileKeyError(path, "", f"a whole number of {digits} digits is beyond TOML's 64 bits")


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
