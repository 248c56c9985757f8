"""A teacher's tables in and out: one CSV reader for rosters and class CSVs, one XLSX writer.

A teacher's spreadsheet export is UTF-8 (with or without a byte-order mark), UTF-16 (Excel's
"Unicode text", with a BOM, or without one when the NUL bytes give it away) or cp1251 (an older
Russian Excel). :func:`decode` finds which: a BOM first, then UTF-16 by the NUL bytes of its
ASCII characters, then strict UTF-8, else cp1251 (every byte is a character there, so it is the
last resort). Cells are separated by ``,``, ``;`` or tabs, whichever the header line holds most
of (outside quotes): a Russian Excel writes ``;`` and a decimal comma, ``0,538``, which
:func:`number` reads.

:func:`xlsx` writes a workbook with openpyxl and then fixes its bytes: openpyxl stamps the time
of writing into the document properties and into each zip entry, and geomcad's output is the
same bytes for the same input.

    >>> decode("ФИО;Группа".encode("cp1251"))
    'ФИО;Группа'
    >>> decode("\\ufeffname".encode("utf-8")), decode("name".encode("utf-16-le"))
    ('name', 'name')
    >>> number("0,538"), number(" 12.5 "), number("1 250,5")
    (0.538, 12.5, 1250.5)
"""

from __future__ import annotations

import csv
import io
import math
import zipfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from geomcad.errors import GeomcadError

#: Cell separators, in the order a tie is decided.
SEPARATORS = (";", "\t", ",")

#: The date written into a workbook's properties and zip entries (the zip format's epoch).
FIXED_DATE = (1980, 1, 1, 0, 0, 0)


def decode(raw: bytes) -> str:
    """The text of a CSV file in UTF-8 (± BOM), UTF-16 (± BOM) or cp1251 (see the module)."""
    if raw.startswith(b"\xef\xbb\xbf"):
        return raw[3:].decode("utf-8")
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        return raw.decode("utf-16")
    if 0 in raw and len(raw) % 2 == 0:
        # UTF-8 and cp1251 text has no NUL; in UTF-16 the separators, digits and line ends
        # are ASCII, whose high byte is NUL: at even offsets for big-endian
        even, odd = raw[0::2].count(0), raw[1::2].count(0)
        return raw.decode("utf-16-be" if even > odd else "utf-16-le")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("cp1251")


def separator(line: str) -> str:
    """The separator a header line uses: the one it holds most of outside quotes (``,`` if
    none)."""
    plain = "".join(part for i, part in enumerate(line.split('"')) if i % 2 == 0)
    best = max(SEPARATORS, key=plain.count)
    return best if plain.count(best) else ","


def read_rows(path: str | Path, what: str) -> list[tuple[int, list[str]]]:
    """The non-blank rows of a CSV file with their line numbers (cells stripped).

    Raises :class:`GeomcadError` naming ``what`` and the file when it is missing, unreadable,
    not CSV, empty or a text of no known encoding.
    """
    try:
        raw = Path(path).read_bytes()
    except FileNotFoundError:
        raise GeomcadError(f"{what} {path}: no such file") from None
    except OSError as exc:
        raise GeomcadError(f"{what} {path}: cannot be read ({exc.strerror or exc})") from None
    try:
        text = decode(raw)
    except UnicodeDecodeError as exc:
        raise GeomcadError(f"{what} {path}: cannot be read ({exc.reason})") from None
    if "\0" in text:
        raise GeomcadError(f"{what} {path}: not a text file")
    text = text.removeprefix("\ufeff")
    first = next((ln for ln in text.splitlines() if ln.strip()), "")
    try:
        rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=separator(first)))
    except csv.Error as exc:
        raise GeomcadError(f"{what} {path}: not a CSV file ({exc})") from None
    out = [(i, [c.strip() for c in row]) for i, row in enumerate(rows, start=1)]
    out = [(i, row) for i, row in out if any(row)]
    if not out:
        raise GeomcadError(f"{what} {path}: the file is empty")
    return out


def number(text: str) -> float:
    """A cell as a number: a decimal point or comma, spaces between thousands; ValueError if
    it is not one."""
    t = text.strip().replace("\u00a0", "").replace("\u202f", "").replace(" ", "")
    if t.count(",") == 1 and "." not in t:
        t = t.replace(",", ".")
    x = float(t)
    if not math.isfinite(x):
        raise ValueError(text)
    return x


def cell_number(text: str) -> float | int | str:
    """A key's printed value as a spreadsheet number (an integer stays one; blank stays text)."""
    t = text.strip()
    if not t:
        return ""
    if t.lstrip("-").isdecimal():
        return int(t)
    try:
        return number(t)
    except ValueError:
        return t


def xlsx(sheets: Sequence[tuple[str, Sequence[Sequence[Any]], Sequence[float]]]) -> bytes:
    """A workbook of ``(title, rows, column widths)`` sheets, the first row of each in bold and
    frozen, as the same bytes for the same rows (see the module)."""
    import datetime

    from openpyxl import Workbook
    from openpyxl.styles import Font

    wb = Workbook()
    wb.remove(wb.active)
    for title, rows, widths in sheets:
        ws = wb.create_sheet(title[:31])
        for row in rows:
            ws.append(list(row))
        for cell in ws[1] if rows else ():
            cell.font = Font(bold=True)
        ws.freeze_panes = "A2"
        for i, w in enumerate(widths, start=1):
            ws.column_dimensions[_column_letter(i)].width = w
    when = datetime.datetime(*FIXED_DATE)
    wb.properties.created = when
    wb.properties.modified = when
    wb.properties.creator = "geomcad"
    buf = io.BytesIO()
    wb.save(buf)
    # openpyxl writes the modified time as "now" whatever it is given, and dates each zip entry
    fixed = io.BytesIO()
    with (
        zipfile.ZipFile(io.BytesIO(buf.getvalue())) as src,
        zipfile.ZipFile(fixed, "w", zipfile.ZIP_DEFLATED) as dst,
    ):
        for info in src.infolist():
            data = src.read(info.filename)
            if info.filename == "docProps/core.xml":
                data = _fixed_core(data)
            entry = zipfile.ZipInfo(info.filename, date_time=FIXED_DATE)
            entry.compress_type = zipfile.ZIP_DEFLATED
            dst.writestr(entry, data)
    return fixed.getvalue()


def _fixed_core(xml: bytes) -> bytes:
    import re

    stamp = b"1980-01-01T00:00:00Z"
    pattern = rb"(<dcterms:(?:created|modified)[^>]*>)[^<]*(<)"
    return re.sub(pattern, rb"\g<1>" + stamp + rb"\2", xml)


def _column_letter(i: int) -> str:
    s = ""
    while i:
        i, r = divmod(i - 1, 26)
        s = chr(ord("A") + r) + s
    return s


def read_xlsx_rows(path: str | Path) -> list[list[Any]]:
    """The first sheet's rows of a workbook (for tests and for reading a register back)."""
    from openpyxl import load_workbook

    wb = load_workbook(path, read_only=True)
    ws = wb.worksheets[0]
    return [list(r) for r in ws.iter_rows(values_only=True)]
