"""``geomcad build --jobs N``: problems solved, drawn and rendered in worker processes.

Each worker prepares one problem or file as a serial build does (:func:`geomcad.cli._prepare`:
the same title-block data, the review sheets when asked) and writes its files with
:func:`geomcad.render.write_sheets` itself, into a private temporary folder, then hands back
their names and bytes. The parent writes each problem's files into the output folder as soon as
its worker is done (a killed build keeps what was finished); a file that does not load fails
before any work starts, and the output is byte-identical to a serial build whatever formats
``write_sheets`` knows.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from geomcad.errors import GeomcadError, MissingDependency


def build_one(
    pid: str,
    formats: tuple[str, ...],
    plain: tuple[str, ...],
    colour: bool,
    options: Any,
    workdir: Any,
    review: bool,
    sets: tuple[str, ...] = (),
) -> tuple[str, int, list[tuple[str, bytes]], str, str]:
    """Prepare and render ``pid``: (stem, number of sheets, [(file name, bytes)], error,
    missing dependency).

    Errors come back as text (worker exceptions need not pickle): the files are then none, or
    only the ``plain`` formats (SVG, DXF) when libcairo is missing; a sheet that could not be
    drawn comes back as its ``error:`` text beside the files of the problem's other sheets
    (already prefixed with the problem id, review 14).
    """
    from geomcad import cli
    from geomcad.render import write_sheets

    try:
        stem, sheets, failed = cli._prepare(pid, options, workdir, review, sets=sets)
    except (GeomcadError, cli._Failed) as exc:
        return pid, 0, [], str(exc), ""
    missing = ""
    with tempfile.TemporaryDirectory(prefix="geomcad-build-") as tmp:
        try:
            paths = write_sheets(stem, sheets, Path(tmp), list(formats), colour=colour)
        except MissingDependency as exc:
            missing = str(exc)
            paths = write_sheets(stem, sheets, Path(tmp), list(plain), colour=colour)
        except GeomcadError as exc:
            return pid, 0, [], str(exc), ""
        files = [(p.name, p.read_bytes()) for p in paths]
    return stem, len(sheets), files, failed, missing


def write(out: Path, files: list[tuple[str, bytes]]) -> list[Path]:
    """Write the rendered files atomically into ``out``; return their paths."""
    from geomcad.render.files import write_atomic

    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, data in files:
        path = out / name
        write_atomic(path, data)
        paths.append(path)
    return paths
