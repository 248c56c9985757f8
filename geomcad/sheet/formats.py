"""The sheet format chosen by what the sheet holds (GOST 2.301), as a drawing office chooses it.

A sheet's views are arranged (:func:`~geomcad.sheet.compose.arrange`) on the ESKD formats from
the smallest up — A4 (portrait only), A3, A2, A1, each landscape, then portrait — and the first
is taken on which everything fits (:attr:`~geomcad.sheet.compose.Layout.fits`: tables and texts
whole, every diagram at least its least size, every title on its box) and every view the subject
sets a scale for reaches it. ``wants`` maps such a view to the largest model length per paper
millimetre it may have: 0.001 m/mm for a cam profile at 1:1 or larger, or a gear mesh's k at
which a tooth is tall enough to read. A larger format than that is not taken; on the format
taken the layout draws every view as large as it can. Where no format meets the wants (a
cam too large for 1:1 even on A1), the largest format is taken, in the orientation that scores
better: the views are then as large as that sheet allows.

>>> from geomcad.sheet.compose import Figure
>>> small = Figure((0.0, 0.0, 0.1, 0.1), lambda v: None, title="cam")
>>> fit = choose(small, {small: 0.001})
>>> fit.fmt, fit.landscape, fit.layout[small].scale.ratio_text()
('A4', False, '1:1')
>>> choose(small, {small: 0.0004}).fmt              # 2.5:1 needs a larger sheet
'A3'
>>> choose(small, {small: 0.001}, formats=("A2",)).fmt   # a format the user asked for
'A2'
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass

from geomcad import tol
from geomcad.errors import ParameterError
from geomcad.sheet.compose import Field, Layout, Tree, View, arrange, least_room
from geomcad.sheet.drawing import Drawing
from geomcad.sheet.frame import FORMATS, TitleBlock
from geomcad.titlefields import SHEET_FORMATS, check_format

#: The formats a composed sheet may take, smallest first (A0 is a sheet no course asks for).
SIZES: tuple[str, ...] = SHEET_FORMATS


@dataclass(frozen=True)
class Sized:
    """The format chosen (``fmt``, ``landscape``) and the views' arrangement on it."""

    fmt: str
    landscape: bool
    layout: Layout

    def start(self, tb: TitleBlock) -> Drawing:
        """A new drawing of this format (:func:`geomcad.sheet.start`)."""
        from geomcad.sheet import start

        return start(self.fmt, tb, self.landscape)


def check(fmt: str, key: str = "sheet.format") -> str:
    """A format a user asks for (``[sheet] format = "A2"``), checked: one of :data:`SIZES`; a
    :class:`~geomcad.errors.ParameterError` naming ``key`` otherwise."""
    return check_format(fmt, key)


def candidates(formats: Sequence[str] = SIZES) -> Iterator[tuple[str, bool]]:
    """(format, landscape) from the smallest sheet up; A4 portrait only (GOST 2.301)."""
    for fmt in sorted(formats, key=lambda f: FORMATS[f][0] * FORMATS[f][1]):
        if fmt != "A4":
            yield fmt, True
        yield fmt, False


def _views(tree: Tree) -> list[View]:
    return [tree] if isinstance(tree, View) else list(tree.views())


def _may_fit(tree: Tree, wants: Mapping[View, float], field: Field) -> bool:
    """A quick necessary test before arranging: each wanted view at its scale, and the fixed
    views and the diagrams at their least sizes, find room in the field (by size and area)."""
    x0, y0, x1, y1 = field.box
    fw, fh = x1 - x0, y1 - y0
    area = fw * fh - sum(
        max(0.0, min(o[2], x1) - max(o[0], x0)) * max(0.0, min(o[3], y1) - max(o[1], y0))
        for o in field.obstacles
    )
    need = 0.0
    for v in _views(tree):
        if v in wants:
            ext = v.extent()
            assert ext is not None
            w = (ext[2] - ext[0]) / wants[v] + 2.0 * v.margin
            h = (ext[3] - ext[1]) / wants[v] + 2.0 * v.margin + v.title_room()
        elif v.kind == "fixed":
            nat = v.natural()
            assert nat is not None
            w, h = nat
        elif v.kind == "stretch":
            w, h = v.stretch()[0]
            h += v.title_room()
        else:
            continue
        if w > fw + tol.SHEET_MM or h > fh + tol.SHEET_MM:
            return False
        need += w * h
    return need <= area


def may_reach(tree: Tree, wants: Mapping[View, float], field: Field) -> bool:
    """A necessary test before arranging: whether the field's box has room for one of the
    least sizes at which ``tree`` draws every view of ``wants`` at its scale
    (:func:`~geomcad.sheet.compose.least_room`). False: no arrangement on this field
    :func:`meets` the wants, so the search need not run to find that out."""
    if not wants:
        return True
    x0, y0, x1, y1 = field.box
    fw, fh = x1 - x0 + tol.SHEET_MM, y1 - y0 + tol.SHEET_MM
    return any(w <= fw and h <= fh for w, h in least_room(tree, wants))


def meets(lay: Layout, wants: Mapping[View, float]) -> bool:
    """Whether every wanted view is drawn at its scale or larger."""
    for v, k in wants.items():
        s = lay[v].scale
        if s is None or s.k > k * (1.0 + tol.REL_LENGTH):
            return False
    return True


def choose(
    tree: Tree, wants: Mapping[View, float] | None = None, formats: Sequence[str] = SIZES
) -> Sized:
    """The smallest of ``formats`` (either orientation GOST 2.301 allows) on which ``tree``
    fits with every view of ``wants`` at its scale or larger (module docstring); else the
    largest of them, in its better orientation."""
    wants = wants or {}
    # the layout's search seeks the wanted scales itself: a wanted view's ``readable`` length
    # (at least ``readable_mm`` on paper, a term of the search's score) is raised to the model
    # length that ``readable_mm`` stands for at its wanted scale
    for v, k in wants.items():
        v.readable = max(v.readable, k * v.readable_mm)
    largest = max(formats, key=lambda f: FORMATS[f][0] * FORMATS[f][1])
    fallback: list[Sized] = []
    for fmt, land in candidates(formats):
        field = Field.of_format(fmt, land)
        if fmt != largest and not (_may_fit(tree, wants, field) and may_reach(tree, wants, field)):
            continue
        try:
            lay = arrange(tree, field)
        except ParameterError:  # a view with no room at all on this sheet
            continue
        if lay.fits and meets(lay, wants):
            return Sized(fmt, land, lay)
        if fmt == largest:
            fallback.append(Sized(fmt, land, lay))
    if not fallback:  # no room on the largest either: its arrangement says which view
        land = largest != "A4"
        fallback.append(Sized(largest, land, arrange(tree, Field.of_format(largest, land))))
    return max(fallback, key=lambda s: (s.layout.fits, s.layout.score))
