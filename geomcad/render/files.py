"""Write a problem's sheets to files: ``ID.svg`` for the main sheet, ``ID-NAME.svg`` for others
(and ``.pdf``, ``.png``, ``.dxf`` beside them).

Every file is written atomically (a temporary file in the same directory, then ``os.replace``),
so a reader never sees half a sheet and a failure leaves neither a partial file nor a stray
temporary one. A process killed outright (SIGKILL, a power cut) cannot clean up after itself: its
temporary file (``.NAME.PID-HEX.tmp``) stays, and the next :func:`write_sheets` into that folder
removes every temporary file of this naming whose process is gone
(:func:`remove_stale_temporaries`). Every SVG and DXF is written before any PDF or PNG: they need
nothing from the system, so a machine without libcairo still gets them before
:class:`~geomcad.errors.MissingDependency`.
"""

from __future__ import annotations

import os
import re
import uuid
from collections.abc import Callable, Sequence
from pathlib import Path

from geomcad import interrupts
from geomcad.errors import ParameterError
from geomcad.render.pdf import sheet_pdf
from geomcad.render.raster import to_png
from geomcad.render.svg import to_svg
from geomcad.sheet.model import Sheet

#: Output formats: the SVG and its PDF and PNG, and the DXF for CAD programs.
FORMATS = ("svg", "pdf", "png", "dxf")

#: What ``write_sheets`` and ``geomcad build`` write when no format is named.
DEFAULT_FORMATS = ("svg", "pdf", "png")

#: The order files are written in: what needs nothing from the system first.
WRITE_ORDER = ("svg", "dxf", "pdf", "png")

#: Resolution of PNG previews (dots per inch).
PNG_DPI = 150

_SEPARATORS = {"/", "\\", "\0", os.sep} | ({os.altsep} if os.altsep else set())


def _check_name(param: str, value: str, *, empty_ok: bool) -> None:
    """Refuse a file-name part that could leave the output directory or is not a plain name."""
    if not value and not empty_ok:
        raise ParameterError(param, value, "must not be empty")
    if any(sep in value for sep in _SEPARATORS) or ".." in value:
        raise ParameterError(
            param, value, "must be a plain file name: no path separator and no '..'"
        )


def _check_formats(formats: Sequence[str]) -> list[str]:
    """The requested formats without repeats, in :data:`WRITE_ORDER`."""
    if isinstance(formats, str):
        formats = [formats]
    for f in formats:
        if f not in FORMATS:
            raise ParameterError("--format", f, f"allowed formats are {', '.join(FORMATS)}")
    return [f for f in WRITE_ORDER if f in formats]


#: The name of a temporary file of :func:`write_atomic`: ``.NAME.PID-HEX12.tmp``.
TEMP_NAME = re.compile(r"^\..+\.(?P<pid>[0-9]+)-[0-9a-f]{12}\.tmp$")


def _alive(pid: int) -> bool:
    """True when a process ``pid`` exists (on this machine's process table)."""
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError):
        return True  # it exists, owned by someone else (or we cannot tell: keep its file)
    return True


def remove_stale_temporaries(folder: Path) -> list[Path]:
    """Remove the temporary files of :func:`write_atomic` in ``folder`` whose writing process no
    longer runs (killed while it wrote); return them. Files of live processes (another build
    writing into the same folder) and every other file are left alone."""
    removed: list[Path] = []
    try:
        names = os.listdir(folder)
    except OSError:
        return removed
    for name in names:
        m = TEMP_NAME.match(name)
        if m is None or _alive(int(m.group("pid"))):
            continue
        path = Path(folder) / name
        try:
            if path.is_file() and not path.is_symlink():
                path.unlink()
                removed.append(path)
        except OSError:
            pass  # another build removed it first, or the folder is read-only: not ours to fix
    return removed


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` so that ``path`` is either untouched or complete.

    The temporary file lives in the same directory (``os.replace`` is atomic only within one
    file system) and is removed if anything fails before the rename.
    """
    interrupts.check()  # a signal whose exception was swallowed: no new file
    tmp = path.with_name(f".{path.name}.{os.getpid()}-{uuid.uuid4().hex[:12]}.tmp")
    # The file is created inside the ``try``: a signal that arrives as soon as it exists (and is
    # raised at the next bytecode) still removes it. O_EXCL: never write through someone else's
    # file (its FileExistsError leaves that file alone); 0o666 lets the umask decide the mode.
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException as exc:
        if not isinstance(exc, FileExistsError):
            tmp.unlink(missing_ok=True)
        raise


def write_sheets(
    pid: str,
    sheets: Sequence[tuple[str, Sheet]],
    out_dir: Path,
    formats: Sequence[str] = DEFAULT_FORMATS,
    *,
    dpi: int = PNG_DPI,
    colour: bool = False,
) -> list[Path]:
    """Write each ``(name, sheet)`` as ``out_dir/ID[-NAME].{svg,pdf,png,dxf}``; return the paths.

    The sheets are black (ESKD); ``colour`` keeps the roles' colours, for screens.

    ``pid`` is the problem id; the main sheet has the name ``""``. ``out_dir`` is created if
    missing. Every SVG is written first, then the DXFs (ezdxf; nothing from the system either),
    then the PDFs and PNGs.

    Raises :class:`~geomcad.errors.ParameterError` for an unknown format (naming ``--format``),
    for an id or sheet name that is empty where it must not be, holds a path separator or ``..``,
    or for two sheets with the same name; :class:`~geomcad.errors.MissingDependency` when a PDF
    or PNG is asked for and libcairo is missing (after the SVGs are on disk).
    """
    wanted = _check_formats(formats)
    _check_name("id", pid, empty_ok=False)
    stems: list[str] = []
    for name, _sheet in sheets:
        _check_name("sheet name", name, empty_ok=True)
        stem = f"{pid}-{name}" if name else pid
        if stem in stems:
            raise ParameterError("sheet name", name, f"two sheets of {pid} share this name")
        stems.append(stem)

    out_dir = Path(out_dir)
    # Render every SVG before writing any, so a sheet that cannot be drawn writes nothing.
    svgs = [to_svg(sheet, colour) for _name, sheet in sheets]
    out_dir.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(out_dir)
    written: list[Path] = []
    if "svg" in wanted:
        for stem, svg in zip(stems, svgs, strict=True):
            path = out_dir / f"{stem}.svg"
            write_atomic(path, svg.encode("utf-8"))
            written.append(path)
    if "dxf" in wanted:
        from geomcad.render.dxf import to_dxf  # ezdxf loads only when a DXF is asked for

        for stem, (_name, sheet) in zip(stems, sheets, strict=True):
            path = out_dir / f"{stem}.dxf"
            write_atomic(path, to_dxf(sheet, colour=colour))
            written.append(path)

    # the PDF straight from the sheet (geomcad.render.pdf: the same drawing, without parsing
    # the SVG back), the PNG from the SVG (cairosvg)
    converters: dict[str, Callable[[Sheet, str], bytes]] = {
        "pdf": lambda sheet, _svg: sheet_pdf(sheet, colour),
        "png": lambda _sheet, svg: to_png(svg, dpi=dpi),
    }
    for fmt in ("pdf", "png"):
        if fmt not in wanted:
            continue
        for stem, (_name, sheet), svg in zip(stems, sheets, svgs, strict=True):
            path = out_dir / f"{stem}.{fmt}"
            write_atomic(path, converters[fmt](sheet, svg))
            written.append(path)
    return written
