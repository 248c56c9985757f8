"""Loading libcairo (geomcad.render.raster.cairo): by its soname on Linux, with no child process
(ctypes.util.find_library runs ldconfig, gcc and ld for each name cairocffi asks), and
find_library itself left as it was."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

pytest.importorskip("cairocffi")

PROBE = textwrap.dedent(
    """
    import ctypes.util, resource, sys
    real = ctypes.util.find_library
    from geomcad.render import raster
    cairo = raster.cairo()
    surface = cairo.PDFSurface(None, 10, 10)  # libcairo answers
    surface.finish()
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(used.ru_utime + used.ru_stime > 0.0, ctypes.util.find_library is real,
          vars(sys.modules["cairocffi"])["find_library"] is real)
    """
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the soname is Linux's")
def test_cairo_loads_without_child_processes() -> None:
    out = subprocess.run(
        [sys.executable, "-c", PROBE], capture_output=True, text=True, check=True
    ).stdout.split()
    assert out == ["False", "True", "True"]


def test_cairo_falls_back_to_cairocffis_own_search() -> None:
    """Where opening libcairo by its soname fails, cairocffi is imported again with its own
    search (which finds it here)."""
    probe = textwrap.dedent(
        """
        import sys, types
        from geomcad.render import raster
        raster._prebuilt_ffi()
        if "cairocffi.ffi" not in sys.modules:
            import cairocffi.ffi  # (then drop the rest: imported again below)
            for m in [m for m in sys.modules if m in ("cairocffi",)]:
                del sys.modules[m]
        real, tried = sys.modules["cairocffi.ffi"].ffi, []
        class Proxy:  # an ffi whose first dlopen (libcairo by its soname) fails
            def __getattr__(self, name):
                return getattr(real, name)
            def dlopen(self, name, *a):
                tried.append(name)
                if len(tried) == 1:
                    raise OSError("not by soname")
                return real.dlopen(name, *a)
        module = types.ModuleType("cairocffi.ffi")
        module.ffi = Proxy()
        module.ffi_pixbuf = sys.modules["cairocffi.ffi"].ffi_pixbuf
        sys.modules["cairocffi.ffi"] = module
        raster._prebuilt_ffi = lambda: None  # (the proxy stays)
        cairo = raster.cairo()
        print(len(tried) >= 2, cairo.cairo_version() > 0)
        """
    )
    try:
        out = subprocess.run(
            [sys.executable, "-c", probe], capture_output=True, text=True, check=True
        ).stdout.split()
    except subprocess.CalledProcessError as exc:
        raise AssertionError(exc.stderr) from exc
    assert out == ["True", "True"]
