"""Backends that replay a :class:`~geomcad.sheet.model.Sheet` into files.

- :func:`to_svg`: the sheet as SVG text (svgwrite; needs nothing from the system);
- :func:`to_pdf`, :func:`to_png`: that SVG as PDF or PNG (cairosvg, imported lazily; a missing
  libcairo raises :class:`~geomcad.errors.MissingDependency` with what to install);
- :func:`write_sheets`: a problem's sheets written atomically as ``ID[-NAME].svg|pdf|png``.
"""

from __future__ import annotations

from geomcad.render.files import FORMATS, write_sheets
from geomcad.render.raster import to_pdf, to_png
from geomcad.render.svg import to_svg

__all__ = ["FORMATS", "to_pdf", "to_png", "to_svg", "write_sheets"]
