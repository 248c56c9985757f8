"""The ``geomcad variants`` command (its parser and its run), hooked into :mod:`geomcad.cli`.

Building the parser imports nothing heavy (``geomcad list`` and ``--help`` stay light): the
modules that draw and solve are imported when the command runs.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import dataclasses
import io
import json
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from geomcad.errors import GeomcadError, ParameterError
from geomcad.teach import MIN_TRANSMISSION_DEG, jobs, roster

if TYPE_CHECKING:
    from geomcad.teach import cards, variants

CARD_FORMATS = ("svg", "pdf", "png")


def add_variants(sub: Any, add_set: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add ``variants`` to the command line's subparsers."""
    from geomcad.cli import LANGS

    s = sub.add_parser(
        "variants",
        help="make N variants of a problem or file: variant files, task cards, answer key",
    )
    s.add_argument("template", help="problem id (e.g. 2013-6) or a file FILE.toml")
    s.add_argument("--count", type=int, metavar="N", help="variants to make (an anonymous set)")
    s.add_argument(
        "--students",
        metavar="ROSTER.csv",
        help="a variant per student of the roster (names; optionally a group and a number)",
    )
    s.add_argument(
        "--only",
        metavar="N|NAME",
        help="re-issue one variant's card and file as the full run makes them (a number, or a "
        "student's name with --students)",
    )
    s.add_argument("--seed", type=int, required=True, metavar="S", help="seed of the draws")
    s.add_argument("--out", required=True, metavar="DIR", help="output folder")
    s.add_argument(
        "--vary",
        action="append",
        default=[],
        metavar="KEY=LO..HI[:STEP]",
        help="a key to vary with its range and rounding step (or KEY=a|b|c)",
    )
    add_set(s)
    s.add_argument(
        "--min-transmission-deg",
        type=float,
        default=None,
        metavar="DEG",
        help="linkage files: reject a variant whose transmission angle falls below "
        f"(default {MIN_TRANSMISSION_DEG:g}; 0: no check)",
    )
    s.add_argument("--key", metavar="NAMES", help="results in the answer key, e.g. l1,l2,r.*")
    s.add_argument("--course", default="TMM", help="the course, for the title blocks")
    s.add_argument("--teacher", default="", help="the teacher (Checked), for the title blocks")
    s.add_argument("--lang", default="ru", choices=LANGS, help="the cards' language (default ru)")
    s.add_argument("--format", default="pdf", help="task cards: comma-separated svg,pdf,png")
    s.add_argument(
        "--jobs", type=int, default=1, metavar="N", help="worker processes (default 1; 0: per core)"
    )
    s.set_defaults(func=cmd_variants)


def _pairs(texts: Sequence[str]) -> list[tuple[str, str]]:
    out = []
    for text in texts:
        name, eq, value = text.partition("=")
        if not eq or not name.strip():
            raise GeomcadError(f"--set {text}: expected NAME=VALUE")
        out.append((name.strip(), value))
    return out


def _check_words(*options: tuple[str, str]) -> None:
    """The title blocks' words given on the command line: one line, in the sheet font."""
    from geomcad.sheet.text import lacking, no_glyph

    for option, text in options:
        if "\n" in text:
            raise ParameterError(option, text, "must be one line of text")
        if lacking(text):
            raise ParameterError(option, text, no_glyph(text))


def _formats(text: str) -> tuple[str, ...]:
    fs = [f.strip().lower() for f in text.split(",") if f.strip()]
    for f in fs:
        if f not in CARD_FORMATS:
            raise ParameterError(
                "--format", text, f"each format must be one of {', '.join(CARD_FORMATS)}"
            )
    return tuple(f for f in CARD_FORMATS if f in fs)


def render_card(
    template: variants.Template,
    values: tuple[tuple[str, str], ...],
    number: int,
    width: int,
    columns: tuple[str, ...],
    info: cards.CardInfo,
    formats: tuple[str, ...],
    file_id: str,
) -> dict[str, bytes]:
    """One variant's task card rendered to each format (run in a worker process)."""
    from geomcad.render import sheet_pdf, to_png, to_svg
    from geomcad.render.files import PNG_DPI
    from geomcad.teach import cards

    sol = template.solve(values, file_id)
    data = template.variant_data(values) if template.is_file else None
    from geomcad.sheet.lang import language

    with language(info.lang):
        sheet = cards.task_card(sol, number, width, columns, info, data, template.stem)
    svg = to_svg(sheet)
    out: dict[str, bytes] = {}
    if "svg" in formats:
        out["svg"] = svg.encode("utf-8")
    if "pdf" in formats:
        out["pdf"] = sheet_pdf(sheet)
    if "png" in formats:
        out["png"] = to_png(svg, dpi=PNG_DPI)
    return out


def cmd_variants(ns: argparse.Namespace) -> int:
    """Run ``geomcad variants`` (see :mod:`geomcad.teach.variants`)."""
    from geomcad.render.files import write_atomic
    from geomcad.teach import cards, keys, variants

    started = time.perf_counter()
    n_jobs = jobs.check_jobs(ns.jobs)
    if ns.seed < 0:
        raise ParameterError("--seed", ns.seed, "must be a whole number ≥ 0")
    if ns.count is not None and not 1 <= ns.count <= variants.MAX_COUNT:
        raise ParameterError("--count", ns.count, f"must be from 1 to {variants.MAX_COUNT}")
    _check_words(("--course", ns.course), ("--teacher", ns.teacher))
    formats = _formats(ns.format)
    template = variants.load_template(ns.template, _pairs(ns.set))
    varies = [variants.parse_vary(t) for t in ns.vary]
    linkage = template.kind == "linkage"
    if ns.min_transmission_deg is None:
        min_tr = MIN_TRANSMISSION_DEG if linkage else 0.0
    else:
        min_tr = float(ns.min_transmission_deg)
        if not 0.0 <= min_tr < 90.0:
            raise ParameterError(
                "--min-transmission-deg", ns.min_transmission_deg, "must be in [0, 90)"
            )
        if not linkage and min_tr > 0.0:
            raise ParameterError(
                "--min-transmission-deg", ns.min_transmission_deg, "applies to linkage files only"
            )
    info = cards.CardInfo(course=ns.course, teacher=ns.teacher, lang=ns.lang)
    students = roster.read(ns.students) if ns.students is not None else None
    if students is None and ns.count is None:
        raise GeomcadError("variants: give --count N or --students ROSTER.csv")
    if students is not None and ns.count is not None and ns.count != len(students):
        raise ParameterError("--count", ns.count, f"the roster has {len(students)} students")
    count = len(students) if students is not None else ns.count
    if students is not None and not 1 <= count <= variants.MAX_COUNT:
        raise ParameterError("--students", ns.students, f"must list 1 to {variants.MAX_COUNT}")

    # what every variant needs is imported here, once, before the workers fork
    with contextlib.suppress(GeomcadError):
        template.solve(())
    jobs.warm([], formats)
    relay = jobs.Relay()
    with jobs.pool(n_jobs, relay) as run:
        with jobs.bar(count, "variant", "solve") as tick:
            drawn = variants.draw(template, varies, count, ns.seed, min_tr, run, tick)
        for v, student in zip(drawn.variants, students or [], strict=False):
            v.number = student.number  # the roster's numbering carries over to the cards
        only = _only(ns.only, students, count)
        patterns = keys.parse_patterns(ns.key or "") or variants.default_key(
            template, drawn.variants[0].results
        )
        columns = variants.key_columns(drawn.variants, patterns, explicit=bool(ns.key))
        if not ns.key:  # the default key asks for results, not for the data given back
            given = set(variants.echoes(template, drawn.variants, columns))
            columns = [c for c in columns if c not in given] or columns
        width = variants.number_width(max(v.number for v in drawn.variants))
        out = Path(ns.out)
        names = [variants.variant_name(template, v.number, width) for v in drawn.variants]
        who = {s.number: s for s in students or []}
        infos = [
            dataclasses.replace(info, student=who[v.number].name, group=who[v.number].group)
            if v.number in who
            else info
            for v in drawn.variants
        ]
        first = drawn.variants[0]
        # a file's result specs follow from its solution (a file names its own points)
        problem = template.solve(first.values, str(out / names[0])).problem
        units = {c: variants.unit_of(problem, c) for c in columns}

        chosen = [i for i, v in enumerate(drawn.variants) if only in (None, v.number)]
        args = [
            (template, v.values, v.number, width, tuple(columns), infos[i], formats,
             str(out / names[i]))
            for i, v in ((i, drawn.variants[i]) for i in chosen)
        ]  # fmt: skip
        # each variant's file and cards written as soon as its card is rendered (a killed run
        # keeps what was finished); the bar counts the files
        written: list[Path] = []
        with jobs.bar(len(args) * (1 + len(formats)), "file", "cards") as tick:
            for k, files in run.stream(render_card, args):
                i = chosen[k]
                v = drawn.variants[i]
                try:
                    out.mkdir(parents=True, exist_ok=True)
                    path = out / names[i]
                    write_atomic(
                        path, variants.variant_file(template, v, width, _title_data(infos[i]))
                    )
                    written.append(path)
                    tick(1)
                    for fmt, data in files.items():
                        card = out / f"card-{v.number:0{width}d}.{fmt}"
                        write_atomic(card, data)
                        written.append(card)
                        tick(1)
                except OSError as exc:
                    raise GeomcadError(f"cannot write to {out}: {exc.strerror or exc}") from exc
        if only is not None:
            sys.stdout.write("".join(f"{p}\n" for p in written))
            return 0

        numbers = [f"{v.number:0{width}d}" for v in drawn.variants]
        rows = keys.rows([v.results for v in drawn.variants], columns, numbers)
        title = str(template.data.get("title", "")) if template.data else ""
        sheets = cards.answer_sheets(
            title or cards._title(problem, info.lang), columns, units, rows, info, template.stem
        )
        answer_pdfs: list[bytes] = (
            [] if only is not None else run(_sheet_pdf, [(sh,) for sh in sheets])
        )

    try:
        out.mkdir(parents=True, exist_ok=True)
        people = [(f.student, f.group) for f in infos] if students is not None else None
        csv_path = out / "answers.csv"
        write_atomic(csv_path, _answers_csv(columns, rows, names, people).encode("utf-8"))
        xlsx_path = out / "answers.xlsx"
        write_atomic(
            xlsx_path, _answers_xlsx(columns, units, rows, names, people, template, info.lang)
        )
        json_path = out / "answers.json"
        obj = _answers_json(ns, template, min_tr, drawn, columns, units, names, rows)
        for entry, person in zip(obj["variants"], people or [], strict=False):
            entry["student"], entry["group"] = person
        text = json.dumps(obj, ensure_ascii=False, indent=2, allow_nan=False) + "\n"
        write_atomic(json_path, text.encode("utf-8"))
        pdf_path = out / "answers.pdf"
        write_atomic(pdf_path, _one_pdf(answer_pdfs))
    except OSError as exc:
        raise GeomcadError(f"cannot write to {out}: {exc.strerror or exc}") from exc
    report = variants.summary(drawn, template, ns.seed, out)
    pages = f" ({len(answer_pdfs)} sheets)" if len(answer_pdfs) > 1 else ""
    report += f"answer key: {csv_path}, {xlsx_path}, {json_path}, {pdf_path}{pages}\n"
    report += f"{len(written)} variant files and cards, {time.perf_counter() - started:.1f} s\n"
    sys.stdout.write(report)
    sys.stdout.flush()
    return 0


def _sheet_pdf(sheet: Any) -> bytes:
    from geomcad.render import sheet_pdf

    pdf: bytes = sheet_pdf(sheet)
    return pdf


def _one_pdf(pdfs: Sequence[bytes]) -> bytes:
    """The answer key's sheets as one PDF, a page per sheet (pypdf writes no date or random
    id, so the bytes stay the same run after run)."""
    if len(pdfs) == 1:
        return pdfs[0]
    from pypdf import PdfWriter

    writer = PdfWriter()
    for pdf in pdfs:
        writer.append(io.BytesIO(pdf))
    buf = io.BytesIO()
    writer.write(buf)
    return buf.getvalue()


def _answers_csv(
    columns: Sequence[str],
    rows: Sequence[Sequence[str]],
    names: Sequence[str],
    people: Sequence[tuple[str, str]] | None = None,
) -> str:
    """answers.csv: variant, (student, group,) file, then the key's columns."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    who = ["student", "group"] if people is not None else []
    w.writerow(["variant", *who, "file", *columns])
    for k, (row, name) in enumerate(zip(rows, names, strict=True)):
        w.writerow([row[0], *(people[k] if people is not None else ()), name, *row[1:]])
    return buf.getvalue()


def _answers_xlsx(
    columns: Sequence[str],
    units: dict[str, str],
    rows: Sequence[Sequence[str]],
    names: Sequence[str],
    people: Sequence[tuple[str, str]] | None,
    template: variants.Template,
    lang: str,
) -> bytes:
    """answers.xlsx: the key as answers.csv has it, with readable headers and units (``θ, °``,
    ``V_D, пол. 3, м/с``) and the values as numbers."""
    from geomcad.teach import keys, tables

    words = XLSX_WORDS[lang]
    who = [words["student"], words["group"]] if people is not None else []
    head = [words["variant"], *who, *(keys.header(c, units.get(c, ""), lang) for c in columns),
            words["file"]]  # fmt: skip
    body: list[list[object]] = []
    for k, (row, name) in enumerate(zip(rows, names, strict=True)):
        cells: list[object] = [int(row[0])]
        cells += list(people[k]) if people is not None else []
        cells += [tables.cell_number(t) for t in row[1:]]
        body.append([*cells, name])
    widths = [9.0, *([28.0, 10.0] if people is not None else []), *([13.0] * len(columns)), 16.0]
    return tables.xlsx([(words["key"], [head, *body], widths)])


#: The headers of answers.xlsx, per language.
XLSX_WORDS = {
    "ru": {"variant": "Вариант", "student": "Студент", "group": "Группа", "file": "Файл",
           "key": "Ключ"},
    "en": {"variant": "Variant", "student": "Student", "group": "Group", "file": "File",
           "key": "Key"},
}  # fmt: skip


def _only(which: str | None, students: Sequence[roster.Student] | None, count: int) -> int | None:
    """The variant number ``--only`` names (``None``: every variant)."""
    if which is None:
        return None
    if students is not None:
        return roster.pick(list(students), which).number
    t = which.strip()
    if not t.isdecimal() or not 1 <= int(t) <= count:
        raise ParameterError("--only", which[:40], f"must be a variant number, 1 … {count}")
    return int(t)


def _title_data(info: cards.CardInfo) -> dict[str, str]:
    """The title-block data a variant's file carries (its [sheet] table)."""
    data = {"student": info.student, "group": info.group, "checker": info.teacher}
    return {k: v for k, v in data.items() if v}


def _answers_json(
    ns: argparse.Namespace,
    template: variants.Template,
    min_tr: float,
    drawn: variants.Drawn,
    columns: Sequence[str],
    units: dict[str, str],
    names: Sequence[str],
    rows: Sequence[Sequence[str]],
) -> dict[str, Any]:
    """answers.json: the run's inputs and rejections, and per variant its values and key (the
    key's numbers as answers.csv prints them)."""

    def number(text: str) -> float | int:
        return int(text) if text.lstrip("-").isdecimal() else float(text)

    return {
        "template": template.ref,
        "kind": template.kind,
        "seed": ns.seed,
        "count": len(drawn.variants),
        "vary": list(ns.vary),
        "set": list(ns.set),
        "min_transmission_deg": min_tr,
        "draws": drawn.draws,
        "rejected": dict(drawn.rejected),
        "columns": list(columns),
        "units": units,
        "variants": [
            {
                "variant": row[0],
                "file": name,
                "values": dict(v.values),
                "answers": {c: number(t) for c, t in zip(columns, row[1:], strict=True) if t},
            }
            for v, name, row in zip(drawn.variants, names, rows, strict=True)
        ],
    }
