"""Backends that replay a :class:`~geomcad.sheet.model.Sheet` into files.

- :func:`to_svg`: the sheet as SVG text (svgwrite; needs nothing from the system);
- :func:`to_pdf`, :func:`to_png`: that SVG as PDF or PNG (cairosvg, imported lazily; a missing
  libcairo raises :class:`~geomcad.errors.MissingDependency` with what to install);
- :func:`sheet_pdf`: the sheet straight into a cairo PDF, the same drawing without the SVG's
  round trip (what :func:`write_sheets` writes; :mod:`geomcad.render.pdf`);
- :func:`to_dxf`: the sheet as DXF for CAD programs (ezdxf, imported when asked for; see
  :mod:`geomcad.render.dxf`);
- :func:`write_sheets`: a problem's sheets written atomically as ``ID[-NAME].svg|pdf|png|dxf``.
"""

from __future__ import annotations

from geomcad.render.files import DEFAULT_FORMATS, FORMATS, write_sheets
from geomcad.render.pdf import sheet_pdf
from geomcad.render.raster import to_pdf, to_png
from geomcad.render.svg import to_svg
from geomcad.sheet.model import Sheet

__all__ = [
    "DEFAULT_FORMATS",
    "FORMATS",
    "sheet_pdf",
    "to_dxf",
    "to_pdf",
    "to_png",
    "to_svg",
    "write_sheets",
]


def to_dxf(sheet: Sheet, colour: bool = False) -> bytes:
    """The sheet as DXF R2010 bytes, black unless ``colour`` (see :mod:`geomcad.render.dxf`;
    ezdxf loads on first use)."""
    from geomcad.render.dxf import to_dxf as dxf

    return dxf(sheet, colour=colour)
