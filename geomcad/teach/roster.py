"""A class roster (``geomcad variants --students ROSTER.csv``): who gets which variant.

The roster is a CSV file (any encoding and separator :mod:`geomcad.teach.tables` reads) with a
column of names and, optionally, a group and a number. A header row names them (``name`` /
``student`` / ``ФИО`` / ``Студент`` / ``Фамилия``, ``group`` / ``Группа``, ``number`` / ``No`` /
``№`` / ``Номер`` / ``Вариант``); without one, a column of whole numbers is the number, the first
other column the name and the next one the group.

Student i (in the roster's order) gets variant i; when the roster numbers its students, each
gets the variant of its own number, so a register's numbering carries over to the cards.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from geomcad.errors import GeomcadError
from geomcad.teach.tables import read_rows

NAME_WORDS = ("name", "student", "фио", "ф.и.о.", "студент", "фамилия", "фамилия и.о.", "учащийся")
GROUP_WORDS = ("group", "группа", "гр.")
NUMBER_WORDS = ("number", "no", "no.", "n", "#", "№", "№ п/п", "номер", "вариант", "variant")

#: The most students a roster may hold (a stream of a few groups, not a directory dump).
MAX_STUDENTS = 1000


@dataclass(frozen=True)
class Student:
    """One student: the name as written, the group (may be empty), the variant's number."""

    name: str
    group: str
    number: int


def _which(cell: str) -> str | None:
    c = cell.strip().lower()
    for kind, words in (("name", NAME_WORDS), ("group", GROUP_WORDS), ("number", NUMBER_WORDS)):
        if c in words:
            return kind
    return None


def _whole(text: str) -> int | None:
    t = text.strip().rstrip(".")
    return int(t) if t.isdecimal() else None


def read(path: str | Path) -> list[Student]:
    """The students of a roster file, in the order of their variant numbers.

    Raises :class:`GeomcadError` naming the file and line for a roster without names, an empty
    name, a number that is not a whole number ≥ 1, or a number given twice.
    """
    what = "--students"
    rows = read_rows(path, what)
    width = max(len(r) for _, r in rows)
    head = [_which(c) for c in rows[0][1]]
    cols: dict[str, int] = {}
    if any(head):
        for i, kind in enumerate(head):
            if kind is not None and kind not in cols:
                cols[kind] = i
        if "name" not in cols:
            raise GeomcadError(
                f"{what} {path}: no column of names (a header such as name, student, ФИО)"
            )
        body = rows[1:]
    else:
        body = rows
        numeric = [
            i for i in range(width) if all(_whole(r[i] if i < len(r) else "") for _, r in body)
        ]
        if numeric and width > 1:
            cols["number"] = numeric[0]
        rest = [i for i in range(width) if i != cols.get("number")]
        cols["name"] = rest[0]
        if len(rest) > 1:
            cols["group"] = rest[1]
    if not body:
        raise GeomcadError(f"{what} {path}: no students (only a header)")
    if len(body) > MAX_STUDENTS:
        raise GeomcadError(f"{what} {path}: {len(body)} students, more than {MAX_STUDENTS}")

    def cell(row: list[str], kind: str) -> str:
        i = cols.get(kind)
        return row[i] if i is not None and i < len(row) else ""

    students: list[Student] = []
    seen: dict[int, int] = {}
    for k, (line, row) in enumerate(body, start=1):
        name = " ".join(cell(row, "name").split())
        if not name:
            raise GeomcadError(f"{what} {path}: line {line} has no name")
        number = k
        if "number" in cols:
            n = _whole(cell(row, "number"))
            if n is None or n < 1:
                raise GeomcadError(
                    f"{what} {path}: line {line}: the number {cell(row, 'number')[:20]!r} "
                    "is not a whole number ≥ 1"
                )
            if n in seen:
                raise GeomcadError(
                    f"{what} {path}: line {line}: number {n} is given twice (line {seen[n]} too)"
                )
            seen[n] = line
            number = n
        students.append(Student(name, " ".join(cell(row, "group").split()), number))
    return sorted(students, key=lambda s: s.number)


def pick(students: list[Student], which: str) -> Student:
    """The student ``--only`` names: a variant number, or a name (whole, case and spacing
    ignored, else the one name it begins)."""
    n = _whole(which)
    if n is not None:
        for s in students:
            if s.number == n:
                return s
        raise GeomcadError(f"--only {which}: no student has variant {n}")
    key = " ".join(which.split()).casefold()
    for whole in (True, False):
        found = [
            s
            for s in students
            if (s.name.casefold() == key if whole else s.name.casefold().startswith(key))
        ]
        if len(found) == 1:
            return found[0]
        if len(found) > 1:
            names = ", ".join(f"{s.name} ({s.number})" for s in found[:5])
            raise GeomcadError(
                f"--only {which[:60]}: several students match ({names}); give the number"
            )
    raise GeomcadError(f"--only {which[:60]}: no student of that name in the roster")
