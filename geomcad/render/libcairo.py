"""The cairo calls the PDF writer makes (:mod:`geomcad.render.pdf`), bound through cffi.

cairocffi declares the whole of cairo, about 600 functions, and hands those C declarations to
cffi's parser at every import: 0.09 s of CPU time, and three ``ldconfig -p`` children of
``ctypes.util.find_library`` (0.02 s), in a process that builds a sheet set in about 1.5 s. The
PDF writer calls 26 of them. They are declared here with cairo's own names and signatures
(cffi's ABI mode: no compiler), and libcairo is opened by its shared-object name, so the module
loads in a few milliseconds. The classes give the calls cairocffi's names (``PDFSurface``,
``Context.move_to`` …) and make the same C calls in the same order, so the PDF is the same,
byte for byte; every call's status is checked, as cairocffi does. cairocffi itself still
serves cairosvg (the PNG output).

A missing cffi or libcairo is the one :class:`~geomcad.errors.MissingDependency` line of
:data:`geomcad.render.raster.CAIRO_MISSING`. Before libcairo is opened, ``FONTCONFIG_FILE`` is
pointed at the shipped font's configuration (:func:`geomcad.render.raster.fonts_conf`).
"""

from __future__ import annotations

import functools
import os
from collections.abc import Sequence
from typing import Any, BinaryIO

from geomcad.errors import GeomcadError, MissingDependency
from geomcad.render.raster import CAIRO_MISSING, fonts_conf

#: cairo's declarations of what the PDF writer calls (enums as ints: their values below).
DECLARATIONS = """
typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;
typedef int cairo_status_t;
typedef cairo_status_t (*cairo_write_func_t)
    (void *closure, const unsigned char *data, unsigned int length);

cairo_surface_t *cairo_pdf_surface_create_for_stream
    (cairo_write_func_t write_func, void *closure, double width_in_points,
     double height_in_points);
void cairo_pdf_surface_set_metadata (cairo_surface_t *surface, int metadata, const char *utf8);
cairo_status_t cairo_surface_status (cairo_surface_t *surface);
void cairo_surface_finish (cairo_surface_t *surface);
void cairo_surface_destroy (cairo_surface_t *surface);
const char *cairo_status_to_string (cairo_status_t status);

cairo_t *cairo_create (cairo_surface_t *target);
void cairo_destroy (cairo_t *cr);
cairo_status_t cairo_status (cairo_t *cr);
void cairo_save (cairo_t *cr);
void cairo_restore (cairo_t *cr);
void cairo_scale (cairo_t *cr, double sx, double sy);
void cairo_translate (cairo_t *cr, double tx, double ty);
void cairo_rotate (cairo_t *cr, double angle);
void cairo_set_line_cap (cairo_t *cr, int line_cap);
void cairo_set_line_join (cairo_t *cr, int line_join);
void cairo_set_line_width (cairo_t *cr, double width);
void cairo_set_dash (cairo_t *cr, const double *dashes, int num_dashes, double offset);
void cairo_set_source_rgb (cairo_t *cr, double red, double green, double blue);
void cairo_new_path (cairo_t *cr);
void cairo_move_to (cairo_t *cr, double x, double y);
void cairo_line_to (cairo_t *cr, double x, double y);
void cairo_close_path (cairo_t *cr);
void cairo_arc (cairo_t *cr, double xc, double yc, double radius, double angle1, double angle2);
void cairo_arc_negative
    (cairo_t *cr, double xc, double yc, double radius, double angle1, double angle2);
void cairo_fill (cairo_t *cr);
void cairo_fill_preserve (cairo_t *cr);
void cairo_stroke (cairo_t *cr);
void cairo_select_font_face (cairo_t *cr, const char *family, int slant, int weight);
void cairo_set_font_size (cairo_t *cr, double size);
void cairo_show_text (cairo_t *cr, const char *utf8);
"""

#: The shared-object names libcairo goes by (Linux, macOS, Windows), tried in this order;
#: then the names ``ctypes.util.find_library`` finds (a macOS library outside the loader's
#: path), as cairocffi does.
SONAMES = ("libcairo.so.2", "libcairo.2.dylib", "libcairo-2.dll")
LIBRARY_NAMES = ("cairo-2", "cairo", "libcairo-2")

#: The values of cairo's enums that the PDF writer passes.
STATUS_SUCCESS = 0
STATUS_WRITE_ERROR = 11
LINE_CAP_ROUND = 1
LINE_JOIN_ROUND = 1
FONT_SLANT_NORMAL = 0
FONT_WEIGHT_NORMAL = 0
PDF_METADATA_TITLE = 0


@functools.cache
def _loaded() -> tuple[Any, Any]:
    """cffi's FFI with :data:`DECLARATIONS` and the opened libcairo (once per process)."""
    # fontconfig reads this once, when cairo first sets text: before libcairo is opened
    os.environ["FONTCONFIG_FILE"] = str(fonts_conf())
    try:
        from cffi import FFI
    except ImportError as exc:
        raise MissingDependency(CAIRO_MISSING) from exc
    ffi = FFI()
    ffi.cdef(DECLARATIONS)
    failed: OSError | None = None
    for name in SONAMES:
        try:
            return ffi, ffi.dlopen(name)
        except OSError as exc:
            failed = exc
    from ctypes.util import find_library

    for lib_name in LIBRARY_NAMES:
        path = find_library(lib_name)
        if path:
            try:
                return ffi, ffi.dlopen(path)
            except OSError as exc:
                failed = exc
    raise MissingDependency(CAIRO_MISSING) from failed


def load() -> Any:
    """This module, once libcairo is open (:class:`MissingDependency` where it cannot be)."""
    _loaded()
    import sys

    return sys.modules[__name__]


def _check(status: int) -> None:
    if status != STATUS_SUCCESS:
        ffi, lib = _loaded()
        reason = ffi.string(lib.cairo_status_to_string(status)).decode("utf-8", "replace")
        raise GeomcadError(f"cairo could not write the PDF: {reason}")


#: The write callbacks of the surfaces not finished yet: cairo may call one until its surface
#: is finished (an unfinished surface writes its end when libcairo frees it, which may be
#: after Python has dropped the surface's object), so each lives here till then.
_WRITERS: set[Any] = set()


class PDFSurface:
    """A one-page PDF of ``width`` × ``height`` points written to ``target`` as cairo makes it
    (``cairo_pdf_surface_create_for_stream``)."""

    def __init__(self, target: BinaryIO, width: float, height: float) -> None:
        ffi, lib = _loaded()

        def put(_closure: Any, data: Any, length: int) -> int:
            try:
                target.write(ffi.buffer(data, length))
            except OSError:
                return STATUS_WRITE_ERROR  # cairo's status says it (:meth:`finish`)
            return STATUS_SUCCESS

        write = ffi.callback("cairo_write_func_t", put, error=STATUS_WRITE_ERROR)
        _WRITERS.add(write)
        self._write = write
        self._pointer = ffi.gc(
            lib.cairo_pdf_surface_create_for_stream(write, ffi.NULL, width, height),
            lib.cairo_surface_destroy,
        )
        self._check()

    def _check(self) -> None:
        _check(_loaded()[1].cairo_surface_status(self._pointer))

    def set_metadata(self, metadata: int, utf8: str) -> None:
        _loaded()[1].cairo_pdf_surface_set_metadata(self._pointer, metadata, utf8.encode())
        self._check()

    def finish(self) -> None:
        """Write the rest of the PDF (through ``target``); cairo writes nothing after it."""
        _loaded()[1].cairo_surface_finish(self._pointer)
        self._check()
        _WRITERS.discard(self._write)


class Context:
    """A cairo drawing context on ``surface``: the calls of the same names, each followed by
    a check of the context's status."""

    def __init__(self, surface: PDFSurface) -> None:
        ffi, self._lib = _loaded()
        self._surface = surface
        self._pointer = ffi.gc(self._lib.cairo_create(surface._pointer), self._lib.cairo_destroy)
        self._check()

    def _check(self) -> None:
        _check(self._lib.cairo_status(self._pointer))

    def save(self) -> None:
        self._lib.cairo_save(self._pointer)
        self._check()

    def restore(self) -> None:
        self._lib.cairo_restore(self._pointer)
        self._check()

    def scale(self, sx: float, sy: float) -> None:
        self._lib.cairo_scale(self._pointer, sx, sy)
        self._check()

    def translate(self, tx: float, ty: float) -> None:
        self._lib.cairo_translate(self._pointer, tx, ty)
        self._check()

    def rotate(self, radians: float) -> None:
        self._lib.cairo_rotate(self._pointer, radians)
        self._check()

    def set_line_cap(self, line_cap: int) -> None:
        self._lib.cairo_set_line_cap(self._pointer, line_cap)
        self._check()

    def set_line_join(self, line_join: int) -> None:
        self._lib.cairo_set_line_join(self._pointer, line_join)
        self._check()

    def set_line_width(self, width: float) -> None:
        self._lib.cairo_set_line_width(self._pointer, width)
        self._check()

    def set_dash(self, dashes: Sequence[float], offset: float = 0.0) -> None:
        ffi = _loaded()[0]
        self._lib.cairo_set_dash(
            self._pointer, ffi.new("double[]", list(dashes)), len(dashes), offset
        )
        self._check()

    def set_source_rgb(self, red: float, green: float, blue: float) -> None:
        self._lib.cairo_set_source_rgb(self._pointer, red, green, blue)
        self._check()

    def new_path(self) -> None:
        self._lib.cairo_new_path(self._pointer)
        self._check()

    def move_to(self, x: float, y: float) -> None:
        self._lib.cairo_move_to(self._pointer, x, y)
        self._check()

    def line_to(self, x: float, y: float) -> None:
        self._lib.cairo_line_to(self._pointer, x, y)
        self._check()

    def close_path(self) -> None:
        self._lib.cairo_close_path(self._pointer)
        self._check()

    def arc(self, xc: float, yc: float, radius: float, angle1: float, angle2: float) -> None:
        self._lib.cairo_arc(self._pointer, xc, yc, radius, angle1, angle2)
        self._check()

    def arc_negative(
        self, xc: float, yc: float, radius: float, angle1: float, angle2: float
    ) -> None:
        self._lib.cairo_arc_negative(self._pointer, xc, yc, radius, angle1, angle2)
        self._check()

    def fill(self) -> None:
        self._lib.cairo_fill(self._pointer)
        self._check()

    def fill_preserve(self) -> None:
        self._lib.cairo_fill_preserve(self._pointer)
        self._check()

    def stroke(self) -> None:
        self._lib.cairo_stroke(self._pointer)
        self._check()

    def select_font_face(self, family: str, slant: int, weight: int) -> None:
        self._lib.cairo_select_font_face(self._pointer, family.encode(), slant, weight)
        self._check()

    def set_font_size(self, size: float) -> None:
        self._lib.cairo_set_font_size(self._pointer, size)
        self._check()

    def show_text(self, text: str) -> None:
        self._lib.cairo_show_text(self._pointer, text.encode())
        self._check()
