"""Write cffi's out-of-line ABI modules of cairocffi's C declarations
(geomcad/render/_cairo_ffi.py and _cairo_ffi_pixbuf.py), which spare every PDF's process
cairocffi's parse of its C header (geomcad.render.raster.cairo).

Usage: ``python3 scripts/cairo_ffi.py`` after cairocffi changes; until then the installed
cairocffi parses its header itself, and ``tests/test_render.py`` fails while the modules are
not the installed cairocffi's.
"""

from __future__ import annotations

from pathlib import Path

from geomcad.render.raster import CAIRO_FFI, cairo_ffi_code

if __name__ == "__main__":
    root = Path(__file__).resolve().parent.parent
    for name, text in zip(CAIRO_FFI, cairo_ffi_code(), strict=True):
        path = root / (name.replace(".", "/") + ".py")
        path.write_text(text, encoding="utf-8")
        print(path)
