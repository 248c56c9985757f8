"""``geomcad verify --batch answers.csv students.csv``: grade a class.

``answers.csv`` is the one ``geomcad variants`` wrote: a ``variant`` column and a ``file`` column
(the variant's file, beside answers.csv). The students' CSV has a ``student`` and a ``variant``
column, then one column per measured value, named as ``verify --measured`` names them (``l1``,
``O1B1_mm``, ``positions.0.V_D_mm``, ``r.2``); an empty cell is a value not measured. Commas,
semicolons or tabs separate the cells; a decimal comma is accepted.

Each student's values are graded by :func:`geomcad.verify.verify` against the exact solution of
that student's variant, with the same precision rules. The verdicts CSV has one line per value:
row, student, variant, name, reading, measured, exact, deviation, deviation_mm, precision,
unit, ok, error; ``reading`` is the cell as written (sheet mm for a ``NAME_mm`` value), every
other number is in the result's SI unit. A row that cannot be graded (no student, an unknown
variant, no values) gets one line with its error, and a value that cannot be read gets its own
error; every other value is still graded.
The summary (one line per row, then the class) goes to stdout, or to stderr when the verdicts
do.

Exit status: 0 every value within precision and no error, 1 otherwise, 2 when the files
themselves cannot be read.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from geomcad import documents, registry
from geomcad.errors import GeomcadError
from geomcad.teach import variants

if TYPE_CHECKING:
    from geomcad.problem import Solution

COLUMNS = (
    "row", "student", "variant", "name", "reading", "measured", "exact", "deviation",
    "deviation_mm", "precision", "unit", "ok", "error",
)  # fmt: skip


def _read_csv(path: str, what: str) -> tuple[list[str], list[tuple[int, dict[str, str]]]]:
    """The header and the rows (with their line numbers) of a CSV file."""
    try:
        text = Path(path).read_bytes().decode("utf-8-sig")
    except FileNotFoundError:
        raise GeomcadError(f"{what} {path}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise GeomcadError(f"{what} {path}: cannot be read ({exc})") from None
    first = text.split("\n", 1)[0]
    delimiter = max(",;\t", key=first.count) if first else ","
    reader = csv.reader(io.StringIO(text), delimiter=delimiter)
    try:
        rows = list(reader)
    except csv.Error as exc:
        raise GeomcadError(f"{what} {path}: not a CSV file ({exc})") from None
    if not rows:
        raise GeomcadError(f"{what} {path}: the file is empty")
    header = [h.strip() for h in rows[0]]
    out = []
    for line, row in enumerate(rows[1:], start=2):
        if not any(c.strip() for c in row):
            continue
        cells = {h: (row[i].strip() if i < len(row) else "") for i, h in enumerate(header) if h}
        if len(row) > len(header):
            cells["\0extra"] = ",".join(row[len(header) :])
        out.append((line, cells))
    return header, out


def _variant_no(text: str) -> str:
    t = text.strip()
    return str(int(t)) if t.isdecimal() else t


class Answers:
    """The variants of an answers.csv, each solved once, on demand."""

    def __init__(self, path: str) -> None:
        header, rows = _read_csv(path, "answers")
        for col in ("variant", "file"):
            if col not in header:
                raise GeomcadError(
                    f"answers {path}: no {col!r} column (is it the answers.csv of geomcad "
                    "variants?)"
                )
        self.base = Path(path).parent
        self.files = {_variant_no(r["variant"]): r["file"] for _, r in rows if r.get("variant")}
        self._solved: dict[str, Solution[Any] | GeomcadError] = {}

    def solution(self, variant: str) -> Solution[Any]:
        """The exact solution of ``variant``; an unknown or unsolvable one raises."""
        if variant not in self.files:
            known = ", ".join(sorted(self.files, key=lambda v: (len(v), v)))
            raise GeomcadError(f"variant {variant!r} is not in the answers (they have {known})")
        if variant not in self._solved:
            try:
                self._solved[variant] = self._solve(self.base / self.files[variant])
            except GeomcadError as exc:
                self._solved[variant] = exc
        got = self._solved[variant]
        if isinstance(got, GeomcadError):
            raise got
        return got

    @staticmethod
    def _solve(path: Path) -> Solution[Any]:
        if documents.is_file_id(str(path)):
            return documents.solve(str(path))
        pid, sets = variants.variant_sets(path)
        problem = registry.get(pid)
        params = {name: problem.param(name).parse(text) for name, text in sets}
        return problem.solve(**params)


@dataclass
class Graded:
    """The verdict lines, the summary lines, and whether everything was within precision."""

    lines: list[dict[str, str]]
    summary: list[str]
    ok: bool


def grade(answers_path: str, students_path: str, scale: float | None = None) -> Graded:
    """Grade every row of the students' CSV (see the module's docstring)."""
    from geomcad.verify import verify

    answers = Answers(answers_path)
    header, rows = _read_csv(students_path, "students")
    for col in ("student", "variant"):
        if col not in header:
            raise GeomcadError(f"students {students_path}: no {col!r} column")
    names = [h for h in header if h and h not in ("student", "variant")]
    lines: list[dict[str, str]] = []
    summary: list[str] = []
    n_ok = n_values = n_errors = 0
    for line, cells in rows:
        student, variant = cells.get("student", ""), _variant_no(cells.get("variant", ""))
        base = {"row": str(line), "student": student, "variant": variant}
        who = f"row {line} {student or '?'} (variant {variant or '?'})"
        try:
            if not student:
                raise GeomcadError("no student name")
            if not variant:
                raise GeomcadError("no variant")
            if "\0extra" in cells:
                extra = cells["\0extra"]
                raise GeomcadError(f"more cells than the header names ({extra})")
            measured = {n: cells[n] for n in names if cells.get(n, "")}
            if not measured:
                raise GeomcadError("no measured values")
            sol = answers.solution(variant)
        except GeomcadError as exc:
            n_errors += 1
            lines.append({**base, "error": _one_line(str(exc))})
            summary.append(f"{who}: error: {_one_line(str(exc))}")
            continue
        row_ok = row_n = row_err = 0
        for name, text in measured.items():
            try:
                it = verify(sol, {name: text}, scale).items[0]
            except GeomcadError as exc:
                row_err += 1
                lines.append({**base, "name": name, "reading": text, "error": _one_line(str(exc))})
                continue
            row_n += 1
            row_ok += it.ok
            lines.append(
                {
                    **base,
                    "name": name,
                    "reading": text,
                    "measured": _num(it.measured),
                    "exact": _num(it.exact),
                    "deviation": _num(it.deviation),
                    "deviation_mm": _num(it.deviation_mm),
                    "precision": _num(it.precision),
                    "unit": it.unit,
                    "ok": "yes" if it.ok else "no",
                }
            )
        n_ok += row_ok
        n_values += row_n
        n_errors += row_err
        tail = f", {row_err} unreadable" if row_err else ""
        summary.append(f"{who}: {row_ok} of {row_n} within precision{tail}")
    summary.append(
        f"class: {len(rows)} rows, {n_ok} of {n_values} values within precision, {n_errors} errors"
    )
    return Graded(lines, summary, n_ok == n_values and n_errors == 0)


def _num(x: float | None) -> str:
    return "" if x is None else f"{x:.6g}"


def _one_line(text: str) -> str:
    return " ".join(text.split())


def verdicts_csv(lines: list[dict[str, str]]) -> str:
    """The verdict lines as CSV text."""
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for line in lines:
        w.writerow({c: line.get(c, "") for c in COLUMNS})
    return buf.getvalue()


def run_batch(
    answers_path: str,
    students_path: str,
    out: str | None,
    scale: float | None,
    stdout: IO[str],
    stderr: IO[str],
) -> int:
    """The ``verify --batch`` command: write the verdicts and the summary; return the status."""
    graded = grade(answers_path, students_path, scale)
    text = verdicts_csv(graded.lines)
    if out is None:
        stdout.write(text)
        stderr.write("\n".join(graded.summary) + "\n")
    else:
        from geomcad.render.files import write_atomic

        try:
            write_atomic(Path(out), text.encode("utf-8"))
        except OSError as exc:
            raise GeomcadError(f"--out {out}: cannot write ({exc.strerror or exc})") from exc
        stdout.write("\n".join(graded.summary) + f"\nverdicts: {out}\n")
    return 0 if graded.ok else 1
