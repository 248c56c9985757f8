"""PDF and PNG from the SVG text, through cairosvg (imported only when asked for).

cairosvg needs the system library libcairo; SVG output does not, so the import waits until a PDF
or a PNG is wanted and a missing libcairo becomes one :class:`~geomcad.errors.MissingDependency`
line that says what to install.

cairo finds fonts through fontconfig, which reads its configuration once per process. Before the
first import, ``FONTCONFIG_FILE`` is pointed at ``geomcad/fonts/fonts.conf``, which lists the
package's own fonts directory (the pinned osifont) ahead of the system configuration, so the
text is set in the same font whose metrics placed it.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import io
import os
import re
import struct
import sys
import zlib
from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from types import ModuleType

from geomcad import interrupts
from geomcad.errors import MissingDependency

#: The one line a user sees when libcairo is missing (``geomcad build`` adds that it wrote the
#: SVGs, which need no cairo).
CAIRO_MISSING = (
    "PDF and PNG output need the cairo library: install it with `apt-get install libcairo2`"
)

FONTS_CONF = "fonts.conf"


def fonts_conf() -> Path:
    """The fontconfig file shipped with the package (its fonts directory, then the system's)."""
    return Path(str(resources.files("geomcad.fonts").joinpath(FONTS_CONF)))


def cairo() -> ModuleType:
    """Import cairocffi with fontconfig pointed at the shipped font.

    Raises :class:`MissingDependency` when cairocffi or libcairo cannot be loaded.
    """
    # fontconfig reads this once, when cairo first sets text; set it before anything loads cairo.
    os.environ["FONTCONFIG_FILE"] = str(fonts_conf())
    _prebuilt_ffi()
    try:
        try:
            with _sonames_only():
                import cairocffi
        except OSError:  # not by its soname: as cairocffi looks for it alone
            for name in [m for m in sys.modules if m.partition(".")[0] == "cairocffi"]:
                if name != "cairocffi.ffi":  # (the prebuilt declarations stay)
                    del sys.modules[name]
            import cairocffi
    except (ImportError, OSError) as exc:
        # cairocffi raises OSError from dlopen when libcairo.so.2 is absent.
        raise MissingDependency(CAIRO_MISSING) from exc
    module: ModuleType = cairocffi
    return module


@contextlib.contextmanager
def _sonames_only() -> Iterator[None]:
    """On Linux, cairocffi's import opens libcairo.so.2 by its soname without first asking
    ``ctypes.util.find_library`` for ``cairo-2``, ``cairo`` and ``libcairo-2``: on Linux that
    runs ``ldconfig -p``, gcc and ld in child processes (0.02 s of CPU, 0.07 s of wall time
    of every PDF or PNG written), to find the same soname. Elsewhere find_library gives a
    path that opening by name may miss: cairocffi's own search, unchanged."""
    if not sys.platform.startswith("linux") or "cairocffi" in sys.modules:
        yield
        return
    import ctypes.util

    real = ctypes.util.find_library
    ctypes.util.find_library = _no_library
    try:
        yield
    finally:
        ctypes.util.find_library = real
        module = sys.modules.get("cairocffi")
        if module is not None and vars(module).get("find_library") is _no_library:
            # (cairocffi imported it by name: gdk-pixbuf's own search)
            vars(module)["find_library"] = real


def _no_library(name: str) -> None:
    """``ctypes.util.find_library`` finding nothing: cairocffi then opens its sonames."""
    return None


#: cffi's out-of-line ABI modules of cairocffi's C declarations (:func:`cairo_ffi_code`), the
#: second (gdk-pixbuf's) including the first.
CAIRO_FFI = ("geomcad.render._cairo_ffi", "geomcad.render._cairo_ffi_pixbuf")


def cairo_ffi_sources() -> str | None:
    """The SHA-256 of the installed cairocffi's ``constants.py`` and ``ffi.py``, which declare
    its C interface (read as bytes, without importing cairocffi); None where they cannot be
    read."""
    spec = importlib.util.find_spec("cairocffi")
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations)))
    digest = hashlib.sha256()
    try:
        for name in ("constants.py", "ffi.py"):
            digest.update((folder / name).read_bytes())
    except OSError:
        return None
    return digest.hexdigest()


def cairo_ffi_code() -> tuple[str, str]:
    """The texts of the modules :data:`CAIRO_FFI`, generated (cffi's ``emit_python_code``) from
    the installed cairocffi's own declarations, each ending with the SHA-256 they were
    generated from (:func:`cairo_ffi_sources`). Call it in a process where cairocffi was not
    loaded through :func:`cairo` (``python scripts/cairo_ffi.py`` writes them)."""
    import tempfile

    from cairocffi.ffi import ffi, ffi_pixbuf

    texts = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, f in zip(CAIRO_FFI, (ffi, ffi_pixbuf), strict=True):
            f.set_source(name, None)
            path = Path(tmp) / "ffi.py"
            with contextlib.redirect_stdout(io.StringIO()):  # cffi says "generating …"
                f.emit_python_code(str(path))
            texts.append(
                "# ruff: noqa\n"
                + path.read_text(encoding="utf-8")
                + "\n#: cairocffi's constants.py and ffi.py (SHA-256) this was generated from\n"
                + f'SOURCES = "{cairo_ffi_sources()}"\n'
            )
    return texts[0], texts[1]


def _prebuilt_ffi() -> None:
    """cairocffi's C declarations from :data:`CAIRO_FFI` (cffi's out-of-line ABI modules,
    generated from them), not parsed again: cairocffi parses its 2,000 lines of C header
    through pycparser on every import (0.11 s of a shaper's 2.3 s build). Only where the
    installed cairocffi declares exactly what they were generated from; else cairocffi parses
    them itself, as it does alone."""
    if "cairocffi" in sys.modules:
        return
    try:  # (a cffi that no longer reads the generated modules refuses them: ImportError)
        from geomcad.render import _cairo_ffi, _cairo_ffi_pixbuf
    except ImportError:
        return
    if cairo_ffi_sources() != _cairo_ffi.SOURCES:
        return
    module = ModuleType("cairocffi.ffi", "cairocffi's C interface (geomcad.render._cairo_ffi)")
    module.ffi = _cairo_ffi.ffi  # type: ignore[attr-defined]
    module.ffi_pixbuf = _cairo_ffi_pixbuf.ffi  # type: ignore[attr-defined]
    sys.modules["cairocffi.ffi"] = module


def _cairosvg() -> ModuleType:
    """Import cairosvg with fontconfig pointed at the shipped font.

    Raises :class:`MissingDependency` when cairosvg or libcairo cannot be loaded.
    """
    cairo()
    try:
        import cairosvg
    except (ImportError, OSError) as exc:
        raise MissingDependency(CAIRO_MISSING) from exc
    # Text without a text-rendering attribute gets unhinted metrics (its outlines stay hinted):
    # cairo's image surfaces otherwise round each glyph's advance to whole pixels, and at
    # 150 dpi a long line of 2.5 mm lettering ran ~2 mm past the sheet's metrics, so a late
    # subscript landed on its letter. (text-rendering="geometricPrecision" would switch off
    # outline hinting too, which moves osifont's glyphs by up to 0.35 mm.) PDFs are unaffected.
    import cairocffi

    cairosvg.surface.TEXT_HINT_METRICS.setdefault(None, cairocffi.HINT_METRICS_OFF)
    module: ModuleType = cairosvg
    return module


#: cairo 1.16 stamps the PDF with the time of writing and ignores SOURCE_DATE_EPOCH.
_CREATION_DATE = re.compile(rb"/CreationDate \(D:\d{14}Z\)")
_EPOCH_DATE = b"/CreationDate (D:19700101000000Z)"


def to_pdf(svg: str) -> bytes:
    """The SVG as a one-page PDF whose page is the sheet's paper size; text stays real text.

    The creation date is set to the epoch (a string of the same length, so the cross-reference
    offsets stay right): the same sheet gives the same bytes.
    """
    cairosvg = _cairosvg()
    # cairo writes through a Python callback, where a signal's exception would be lost
    with interrupts.deferred():
        pdf = bytes(cairosvg.svg2pdf(bytestring=svg.encode("utf-8")))
    return pin_creation_date(pdf)


def pin_creation_date(pdf: bytes) -> bytes:
    """``pdf`` with cairo's creation date set to the epoch (same length: the offsets hold)."""
    return _CREATION_DATE.sub(_EPOCH_DATE, pdf, count=1)


def to_png(svg: str, dpi: int = 150) -> bytes:
    """The SVG as a PNG at ``dpi`` pixels per inch, on a white background, with its resolution
    recorded (a pHYs chunk), so that it prints at the sheet's true size."""
    cairosvg = _cairosvg()
    with interrupts.deferred():  # as in to_pdf
        png = bytes(
            cairosvg.svg2png(bytestring=svg.encode("utf-8"), dpi=dpi, background_color="white")
        )
    return with_resolution(png, dpi)


_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: The signature and the IHDR chunk, which a PNG always starts with (its data is 13 bytes).
_IHDR_END = len(_PNG_SIGNATURE) + 4 + 4 + 13 + 4
_MM_PER_INCH = 25.4


def _chunk(kind: bytes, data: bytes) -> bytes:
    """A PNG chunk: length, type, data, and the CRC-32 of type and data."""
    crc = zlib.crc32(kind + data) & 0xFFFFFFFF
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)


def with_resolution(png: bytes, dpi: float) -> bytes:
    """``png`` with a pHYs chunk saying ``dpi`` (in pixels per metre, as PNG counts), right
    after IHDR, in place of any it had.

    cairo writes no resolution, so a viewer or a printer would take 72 or 96 dpi and print an
    A3 sheet at twice its size. The chunk is spliced in rather than the image re-encoded (e.g. by
    Pillow), which would decompress and recompress every pixel of a large sheet to add 21 bytes.
    """
    if not png.startswith(_PNG_SIGNATURE) or png[12:16] != b"IHDR":
        raise ValueError("not a PNG that starts with its IHDR chunk")
    per_metre = round(dpi * 1000.0 / _MM_PER_INCH)
    phys = _chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1))  # 1: the unit is metre
    rest, pos = [], _IHDR_END
    while pos < len(png):
        (length,) = struct.unpack(">I", png[pos : pos + 4])
        end = pos + 12 + length
        if png[pos + 4 : pos + 8] != b"pHYs":
            rest.append(png[pos:end])
        pos = end
    return png[:_IHDR_END] + phys + b"".join(rest)
