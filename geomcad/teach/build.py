"""``geomcad build --jobs N``: problems solved and drawn in worker processes.

Each worker solves one problem (or file), draws its sheets and renders every requested format to
bytes, named as :func:`geomcad.render.write_sheets` names them; the parent writes the files in
the order of the ids, after every worker has finished, so bad input writes nothing and the output
is byte-identical to a serial build.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from geomcad.errors import GeomcadError, MissingDependency


def build_one(
    pid: str, formats: tuple[str, ...], colour: bool, options: Any, workdir: Any, review: bool
) -> tuple[str, list[tuple[str, bytes]], str, str]:
    """Solve, draw and render ``pid`` as a serial ``build`` does (:func:`geomcad.cli._prepare`
    with the same title-block data): (stem, [(file name, bytes)], error, missing dependency).

    Errors come back as text (worker exceptions need not pickle); the files then are none, or
    the SVGs only when libcairo is missing.
    """
    from geomcad import cli
    from geomcad.render import to_pdf, to_png, to_svg
    from geomcad.render.files import PNG_DPI

    try:
        stem, sheets = cli._prepare(pid, options, workdir, review)
        stems = [f"{stem}-{name}" if name else stem for name, _ in sheets]
        svgs = [to_svg(sheet, colour) for _, sheet in sheets]
    except (GeomcadError, cli._Failed) as exc:
        return pid, [], str(exc), ""
    files: list[tuple[str, bytes]] = []
    if "svg" in formats:
        files += [(f"{s}.svg", svg.encode("utf-8")) for s, svg in zip(stems, svgs, strict=True)]
    try:
        for fmt in ("pdf", "png"):
            if fmt not in formats:
                continue
            for s, svg in zip(stems, svgs, strict=True):
                data = to_pdf(svg) if fmt == "pdf" else to_png(svg, dpi=PNG_DPI)
                files.append((f"{s}.{fmt}", data))
    except MissingDependency as exc:
        svg_only = [(f"{s}.svg", svg.encode("utf-8")) for s, svg in zip(stems, svgs, strict=True)]
        return stem, svg_only, "", str(exc)
    return stem, files, "", ""


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
