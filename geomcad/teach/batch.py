"""``geomcad verify --batch answers.csv students.csv``: grade a class.

``answers.csv`` is the one ``geomcad variants`` wrote: a ``variant`` column and a ``file`` column
(the variant's file, beside answers.csv). The students' CSV has a ``student`` and a ``variant``
column, then one column per measured value, named as ``verify --measured`` names them (``l1``,
``O1B1_mm``, ``positions.0.V_D_mm``, ``r.2``); an empty cell is a value not measured. Commas,
semicolons or tabs separate the cells; a decimal comma is accepted.

Against a key made from a roster (answers.csv with a ``student`` column) the ``variant`` column
may be left out: each student's variant is found by name. An optional ``scale`` column gives the
k_l the student drew at (``0.005`` or ``1:5``); else ``--scale``, else the variant's own sheet's.
That one k_l converts the row's ``NAME_mm`` readings and judges its lengths given in metres.

Each student's values are graded by :func:`geomcad.verify.verify` against the exact solution of
that student's variant, with the same precision rules, unless a ``--tol`` says otherwise
(:class:`Tolerance`: ``2%`` of the exact value, ``1mm`` on the sheet at the value's own plan
scale, ``1deg``; ``NAME=…`` for one quantity). ``--out FILE.xlsx`` or ``FILE.csv`` writes the
register (:func:`register_rows`): a row per student, per quantity the reading, its deviation in %
and ✓/✗, the count right and an empty mark column for the teacher.

The verdicts CSV (stdout; the register workbook's second sheet) has one line per value: row,
student, variant, name, reading, measured, exact, deviation, deviation_mm, precision, unit, ok,
error; ``reading`` is the cell as written (sheet mm for a ``NAME_mm`` value), every
other number is in the result's SI unit. A row that cannot be graded (no student, an unknown
variant, no values) gets one line with its error, and a value that cannot be read gets its own
error; every other value is still graded.
The summary (one line per row, then the class) goes to stdout, or to stderr when the verdicts
do.

Exit status: 0 every value within precision and no error, 1 otherwise, 2 when the files
themselves cannot be read.
"""

from __future__ import annotations

import contextlib
import csv
import dataclasses
import fnmatch
import io
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from geomcad import documents, registry, tol
from geomcad.errors import GeomcadError, ParameterError
from geomcad.teach import variants
from geomcad.teach.tables import number, read_rows
from geomcad.verify import DRAWING_PRECISION_MM, Item

if TYPE_CHECKING:
    from geomcad.problem import Solution

COLUMNS = (
    "row", "student", "variant", "name", "reading", "measured", "exact", "deviation",
    "deviation_mm", "precision", "unit", "ok", "error",
)  # fmt: skip


def _read_csv(path: str, what: str) -> tuple[list[str], list[tuple[int, dict[str, str]]]]:
    """The header and the rows (with their line numbers) of a CSV file (any encoding and
    separator :mod:`geomcad.teach.tables` reads)."""
    rows = read_rows(path, what)
    header = rows[0][1]
    out = []
    for line, row in rows[1:]:
        cells = {h: (row[i] if i < len(row) else "") for i, h in enumerate(header) if h}
        if len(row) > len(header) and any(row[len(header) :]):
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
        self.groups = {_variant_no(r["variant"]): r.get("group", "") for _, r in rows}
        self.by_student = {
            " ".join(r["student"].split()).casefold(): _variant_no(r["variant"])
            for _, r in rows
            if r.get("student") and r.get("variant")
        }
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
    """The verdict lines, the summary lines, whether everything was within precision, and the
    register: the quantities graded (in the class CSV's order) and one row per student."""

    lines: list[dict[str, str]]
    summary: list[str]
    ok: bool
    names: list[str] = field(default_factory=list)
    register: list[Entry] = field(default_factory=list)


@dataclass
class Entry:
    """A student's row of the register: per quantity (reading, deviation in %, ok) and an
    error where a value or the row could not be graded."""

    student: str
    variant: str
    group: str
    values: dict[str, tuple[str, float | None, bool | None]] = field(default_factory=dict)
    note: str = ""


# --- tolerances -----------------------------------------------------------------------------------

_TOL = re.compile(r"\s*(\d+(?:[.,]\d*)?|[.,]\d+)\s*(%|mm|мм|deg|°)\s*")


@dataclass(frozen=True)
class Tolerance:
    """A teacher's tolerance: ``2%`` of the exact value, ``1mm`` on the sheet (at the value's
    own plan scale), or ``1deg`` for an angle; ``pattern`` limits it to the quantities it
    matches (``--tol l1=1mm``, ``--tol 'positions.*.V_D=5%'``), else it holds for every one."""

    value: float
    kind: str
    pattern: str = ""

    def applies(self, it: Item) -> bool:
        """True when this tolerance judges ``it`` (a mm tolerance needs a sheet scale, an angle
        tolerance an angle)."""
        if self.pattern and not (
            fnmatch.fnmatchcase(it.name, self.pattern)
            or fnmatch.fnmatchcase(it.result, self.pattern)
        ):
            return False
        if self.kind == "mm":
            return it.scale is not None and it.deviation_mm is not None
        if self.kind == "deg":
            return it.rule == "angle"
        return True

    def precision(self, it: Item) -> float:
        """The precision of ``it`` under this tolerance, in its SI unit."""
        if self.kind == "%":
            return self.value / 100.0 * abs(it.exact)
        if self.kind == "mm":
            assert it.scale is not None
            return self.value * it.scale
        return self.value


def parse_tol(text: str) -> Tolerance:
    """``--tol [NAME=]VALUE%|mm|deg`` (a decimal comma is accepted)."""
    name, _, spec = text.rpartition("=")
    m = _TOL.fullmatch(spec)
    if m is None:
        raise ParameterError("--tol", text[:60], "must be like 2%, 1mm or 0.5deg (or NAME=2%)")
    value = float(m.group(1).replace(",", "."))
    kind = {"мм": "mm", "°": "deg"}.get(m.group(2), m.group(2))
    if not value > 0.0 or (kind == "%" and value >= 100.0):
        raise ParameterError("--tol", text[:60], "must be > 0 (a percentage below 100)")
    return Tolerance(value, kind, name.strip())


def judge(it: Item, tols: Sequence[Tolerance]) -> Item:
    """``it`` judged by the last tolerance that applies to it (a named one before a general
    one), else by its default precision (:mod:`geomcad.verify`)."""
    chosen = [t for t in tols if t.applies(it)]
    named = [t for t in chosen if t.pattern]
    pick = (named or chosen)[-1] if chosen else None
    if pick is None:
        return it
    prec = pick.precision(it)
    return dataclasses.replace(
        it, precision=prec, ok=abs(it.deviation) <= prec * (1.0 + tol.DERIVED)
    )


def _row_scale(text: str, given: float | None, sol: Solution[Any]) -> float | None:
    """The one k_l (m/mm) of a student's row: its ``scale`` cell (``0.005`` or ``1:5``), else
    ``--scale``, else the variant's own sheet's, else the seed's."""
    t = text.strip().replace(" ", "")
    if t:
        ratio = re.fullmatch(r"(?:[MmМм])?(\d+(?:[.,]\d+)?):(\d+(?:[.,]\d+)?)", t)
        try:
            if ratio:
                a, b = (float(x.replace(",", ".")) for x in ratio.groups())
                k = 0.001 * b / a
            else:
                k = number(t)
        except ValueError:
            raise GeomcadError(f"scale {text[:30]!r}: must be k_l in m/mm or a ratio 1:5") from None
        if not (math.isfinite(k) and k > 0.0):
            raise GeomcadError(f"scale {text[:30]!r}: must be > 0")
        return k
    if given is not None:
        return given
    own = sol.scales.get("l")
    if own is not None and own > 0.0:
        return own
    return sol.problem.seed_k_l


def _one_scale(it: Item, k: float | None) -> Item:
    """A length given in SI (``l1``), judged at the same k_l as the row's mm readings."""
    if k is None or it.plan != "l" or it.measured_mm is not None or it.rule != "drawing":
        return it
    prec = DRAWING_PRECISION_MM * k
    return dataclasses.replace(
        it,
        scale=k,
        deviation_mm=it.deviation / k,
        precision=prec,
        ok=abs(it.deviation) <= prec * (1.0 + tol.DERIVED),
    )


def grade(
    answers_path: str,
    students_path: str,
    scale: float | None = None,
    tols: Sequence[Tolerance] = (),
) -> Graded:
    """Grade every row of the students' CSV (see the module's docstring)."""
    from geomcad.verify import verify

    answers = Answers(answers_path)
    header, rows = _read_csv(students_path, "students")
    for col in ("student", "variant"):
        if col not in header and not (col == "variant" and answers.by_student):
            raise GeomcadError(f"students {students_path}: no {col!r} column")
    names = [h for h in header if h and h not in ("student", "variant", "scale", "group")]
    lines: list[dict[str, str]] = []
    summary: list[str] = []
    register: list[Entry] = []
    n_ok = n_values = n_errors = 0
    for line, cells in rows:
        student, variant = cells.get("student", ""), _variant_no(cells.get("variant", ""))
        if "variant" not in header:  # the roster's answers know each student's variant
            variant = answers.by_student.get(" ".join(student.split()).casefold(), "")
        base = {"row": str(line), "student": student, "variant": variant}
        who = f"row {line} {student or '?'} (variant {variant or '?'})"
        entry = Entry(student, variant, cells.get("group", "") or answers.groups.get(variant, ""))
        register.append(entry)
        try:
            if not student:
                raise GeomcadError("no student name")
            if not variant and "variant" not in header:
                raise GeomcadError("no variant: the key's roster has no student of that name")
            if not variant:
                raise GeomcadError("no variant")
            if "\0extra" in cells:
                extra = cells["\0extra"]
                raise GeomcadError(f"more cells than the header names ({extra})")
            measured = {n: cells[n] for n in names if cells.get(n, "")}
            if not measured:
                raise GeomcadError("no measured values")
            sol = answers.solution(variant)
            k = _row_scale(cells.get("scale", ""), scale, sol)
        except GeomcadError as exc:
            n_errors += 1
            lines.append({**base, "error": _one_line(str(exc))})
            summary.append(f"{who}: error: {_one_line(str(exc))}")
            entry.note = _one_line(str(exc))
            continue
        row_ok = row_n = row_err = 0
        for name, text in measured.items():
            try:
                it = judge(_one_scale(verify(sol, {name: text}, k).items[0], k), tols)
            except GeomcadError as exc:
                row_err += 1
                lines.append({**base, "name": name, "reading": text, "error": _one_line(str(exc))})
                entry.values[name] = (text, None, None)
                entry.note = (entry.note + "; " if entry.note else "") + _one_line(str(exc))
                continue
            row_n += 1
            row_ok += it.ok
            rel = 100.0 * it.deviation / abs(it.exact) if it.exact != 0.0 else None
            entry.values[name] = (text, rel, it.ok)
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
    return Graded(lines, summary, n_ok == n_values and n_errors == 0, names, register)


# --- the register ---------------------------------------------------------------------------------

#: The register's words, per language.
REGISTER_WORDS = {
    "ru": {"student": "Студент", "group": "Группа", "variant": "Вариант", "dev": "откл., %",
           "right": "Верно", "mark": "Оценка", "note": "Примечание", "title": "Ведомость",
           "lines": "Проверка"},
    "en": {"student": "Student", "group": "Group", "variant": "Variant", "dev": "dev., %",
           "right": "Right", "mark": "Mark", "note": "Note", "title": "Register",
           "lines": "Verdicts"},
}  # fmt: skip

MARK_OK, MARK_OUT = "✓", "✗"


def register_rows(graded: Graded, lang: str = "ru") -> list[list[object]]:
    """The register as rows: a header, then one row per student: each quantity's reading,
    its deviation from the exact value in % and ✓/✗, the count right, an empty mark column
    for the teacher, and a note for what could not be graded."""
    w = REGISTER_WORDS[lang]
    head: list[object] = [w["student"], w["group"], w["variant"]]
    for n in graded.names:
        head += [n, f"{n}: {w['dev']}", f"{n}: ✓/✗"]
    head += [w["right"], w["mark"], w["note"]]
    out = [head]
    for e in graded.register:
        row: list[object] = [
            e.student,
            e.group,
            int(e.variant) if e.variant.isdecimal() else e.variant,
        ]
        right = total = 0
        for n in graded.names:
            text, rel, ok = e.values.get(n, ("", None, None))
            value: object = text
            with contextlib.suppress(ValueError):
                value = number(text) if text else ""
            row += [value, "" if rel is None else round(rel, 2),
                    "" if ok is None else (MARK_OK if ok else MARK_OUT)]  # fmt: skip
            if ok is not None:
                total += 1
                right += ok
        row += [f"{right}/{total}" if total else "", "", e.note]
        out.append(row)
    return out


def register_csv(rows: Sequence[Sequence[object]]) -> str:
    """The register as CSV text (numbers with a decimal point)."""
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(
        [[("" if c is None else c) for c in r] for r in rows]
    )
    return buf.getvalue()


def register_xlsx(graded: Graded, lang: str = "ru") -> bytes:
    """The register as a workbook: the register sheet, then every verdict line."""
    from geomcad.teach import tables

    rows = register_rows(graded, lang)
    w = REGISTER_WORDS[lang]
    widths = [28.0, 10.0, 9.0, *([11.0, 10.0, 7.0] * len(graded.names)), 8.0, 9.0, 40.0]
    verdicts: list[list[object]] = [list(COLUMNS)]
    verdicts += [[ln.get(c, "") for c in COLUMNS] for ln in graded.lines]
    return tables.xlsx([(w["title"], rows, widths), (w["lines"], verdicts, [10.0] * len(COLUMNS))])


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
    tols: Sequence[Tolerance] = (),
    lang: str = "ru",
) -> int:
    """The ``verify --batch`` command: write the verdicts (stdout) or the register (``--out``
    ``.xlsx`` or ``.csv``) and the summary; return the status."""
    suffix = Path(out).suffix.lower() if out is not None else ""
    if out is not None and suffix not in (".xlsx", ".csv"):
        raise ParameterError("--out", out[:80], "the register is FILE.xlsx or FILE.csv")
    graded = grade(answers_path, students_path, scale, tols)
    if out is None:
        stdout.write(verdicts_csv(graded.lines))
        stderr.write("\n".join(graded.summary) + "\n")
    else:
        from geomcad.render.files import write_atomic

        if suffix == ".xlsx":
            data = register_xlsx(graded, lang)
        else:
            data = register_csv(register_rows(graded, lang)).encode("utf-8")
        try:
            write_atomic(Path(out), data)
        except OSError as exc:
            raise GeomcadError(f"--out {out}: cannot write ({exc.strerror or exc})") from exc
        stdout.write("\n".join(graded.summary) + f"\nregister: {out}\n")
    return 0 if graded.ok else 1
