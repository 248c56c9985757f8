"""Drawing on a sheet: viewports at a scale, TMM symbols, arrows, dimensions, placed labels.

A :class:`Viewport` maps model coordinates (metres, or m/s, or N; y up) to sheet millimetres
(y down) through its :class:`~geomcad.sheet.scale.Scale`: the y axis is flipped here and only
here, by transforming coordinates, so text stays upright and line widths stay in mm.

Labels are placed last, by :meth:`Drawing.finish`, through the one placer of every sheet
(:mod:`geomcad.sheet.placer`): candidate positions around each label's point scored against an
index of every drawn line and text.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from geomcad import tol
from geomcad.geom import Arc, Circle, Line, PointLike, vec
from geomcad.sheet import symbols
from geomcad.sheet.frame import Frame, reserved, text_at
from geomcad.sheet.model import XY, ArcItem, CircleItem, Polyline, Sheet, TextItem
from geomcad.sheet.placer import (
    DimText,
    Index,
    LabelRequest,
    break_under_labels,
    drop_crossed,
    place_dims,
    place_labels,
    shrink_moved,
)
from geomcad.sheet.scale import Scale
from geomcad.sheet.style import (
    arc_length,
    circle_length,
    fit_centre_line,
    fit_closed,
    fit_open,
    style,
)
from geomcad.sheet.text import box, parse, wrap

#: Symbol sizes on paper (mm).
JOINT_R = symbols.JOINT_R
DOT_R = 0.6
ARROW_LEN = 3.5
ARROW_HALF_WIDTH = 0.6
#: The shortest vector drawn as an arrow (mm): two arrowheads. A shorter one is drawn as a point
#: with its label, and the sheet says so.
SHORT_MM = 2.0 * ARROW_LEN
SLIDER_SIZE = symbols.SLIDER_SIZE
HATCH_STEP = symbols.HATCH_STEP
HATCH_LEN = symbols.HATCH_LEN

#: Fixed text moved off a box of the form keeps this far from it (mm).
RESERVED_GAP = 3.0
#: A curved arrow's shaft stops this far (rad) short of its head's tip …
TURN_HEAD_GAP = 0.35
#: … but never more than this (mm) along the arc, so that on a large arc the head stays on it.
TURN_HEAD_GAP_MM = 0.9 * ARROW_LEN
#: Baseline-to-baseline distance of wrapped text, in cap heights (GOST 2.304, type B: 17/10 h).
LINE_SPACING = 1.7


#: A table cell that is a number: sign, digits (grouped by no-break spaces), a decimal part.
NUMBER = re.compile(r"[\u2013+-]?\d[\d\u202f\u00a0]*(?:[.,]\d+)?")


def number_parts(cell: str) -> tuple[str, str] | None:
    """A number cell's whole part (with its sign) and its decimal part (with the separator,
    ``""`` for a whole number); None for a cell that is not a plain number."""
    if not NUMBER.fullmatch(cell):
        return None
    i = max(cell.find(","), cell.find("."))
    return (cell, "") if i < 0 else (cell[:i], cell[i:])


def number_columns(
    rows: Sequence[Sequence[str]], height: float, columns: int = 0
) -> list[tuple[float, float]]:
    """Per column of ``rows`` (at least ``columns`` of them): the widths (mm, text ``height``
    high) of its number cells' widest whole part and widest decimal part (0, 0 for a column
    without numbers): the room the numbers aligned on their separator take."""
    n = max([columns, *(len(r) for r in rows)])
    out = [(0.0, 0.0)] * n
    for r in rows:
        for c, cell in enumerate(r):
            parts = number_parts(cell)
            if parts is not None:
                a = box(parse(parts[0]), height)[0]
                b = box(parse(parts[1]), height)[0] if parts[1] else 0.0
                out[c] = (max(out[c][0], a), max(out[c][1], b))
    return out


def _dist(a: XY, b: XY) -> float:
    return math.hypot(b[0] - a[0], b[1] - a[1])


@dataclass
class Drawing:
    """A sheet being drawn: its items, its free field, and the labels still to place."""

    sheet: Sheet
    frame: Frame
    pending: list[LabelRequest] = field(default_factory=list)
    dims: list[DimText] = field(default_factory=list)
    #: Fixed texts moved off графа 26: :meth:`finish` sets them smaller if they then run into
    #: other text.
    moved: list[TextItem] = field(default_factory=list)
    #: Fixed texts that may be left out (a diagram's tick values): :meth:`finish` drops each one
    #: a line crosses.
    optional: list[TextItem] = field(default_factory=list)
    #: The clearance (mm) the labels asked for now keep from every line's centre line where
    #: they can (:attr:`LabelRequest.keep`), and at least as much further from other texts
    #: (``space``: "1" beside "O" reads "10"): a view sets it while it draws (0: the placer's).
    keep: float = 0.0
    #: Areas (shapely polygons, sheet mm) that :meth:`finish`'s labels keep out of as out of a
    #: text: lines a view cleared from round a symbol (a hub's joint and support) that a label
    #: would otherwise take for free room.
    occupied: list[Any] = field(default_factory=list)

    def viewport(self, scale: Scale, origin: PointLike, at: XY) -> Viewport:
        """A viewport that puts model point ``origin`` at sheet point ``at``."""
        return Viewport(self, scale, vec(origin).x, vec(origin).y, at)

    def text(
        self, markup: str, at: XY, height: float = 3.5, anchor: str = "left", role: str = "label"
    ) -> TextItem:
        """Fixed text with its baseline at ``at`` (titles, notes).

        Left-anchored text that would run into a box of the form inside the frame (графа 26 in
        the top-left corner) starts just right of that box instead.
        """
        moved = False
        if anchor == "left":
            w, up, down = box(parse(markup), height)
            for x0, y0, x1, y1 in reserved(self.sheet.width, self.sheet.height):
                if at[0] < x1 and x0 < at[0] + w and at[1] - up < y1 and y0 < at[1] + down:
                    at = (x1 + RESERVED_GAP, at[1])
                    moved = True
        item = text_at(self.sheet, markup, at, height, role, anchor)
        if moved:
            self.moved.append(item)
        return item

    def label(
        self,
        anchor: XY,
        markup: str,
        height: float = 3.5,
        prefer: tuple[float, float] | None = None,
        clear: float = 0.0,
        role: str = "label",
        id: str = "",
        others: tuple[XY, ...] = (),
        space: float = 0.0,
        within: tuple[float, float, float, float] | None = None,
    ) -> None:
        """Ask for a label next to a sheet point (or one of ``others``); :meth:`finish` places
        it, ``space`` mm further than usual from other texts, inside the box ``within`` (sheet
        mm: its view's cell) where it can."""
        space = max(space, self.keep)
        self.pending.append(
            LabelRequest(
                anchor, markup, height, role, prefer, clear, id, others, space, self.keep, within
            )
        )

    def table(
        self,
        x: float,
        y: float,
        widths: Sequence[float],
        rows: Sequence[Sequence[str]],
        height: float = 2.5,
        row_h: float = 6.0,
        header: bool = True,
        center: bool = False,
    ) -> tuple[float, float]:
        """A ruled table with its top-left corner at (x, y); returns its (width, height).

        The first row is the header (ruled off with a main line), unless ``header`` is False.
        Text stands at a cell's left; the numbers of a column below its header are aligned on
        their decimal separator (GOST 2.105: by their digits), whole numbers ending where the
        others' separator stands (:func:`number_columns`); ``center``: the block of them in
        the middle of the column (not at the left of a column its heading widens).
        """
        total_w = sum(widths)
        total_h = row_h * len(rows)
        s = self.sheet
        s.add(
            Polyline(
                ((x, y), (x + total_w, y), (x + total_w, y + total_h), (x, y + total_h)),
                "frame_thin",
                closed=True,
            )
        )
        for i in range(1, len(rows)):
            yy = y + i * row_h
            thick = i == 1 and header
            s.add(Polyline(((x, yy), (x + total_w, yy)), "frame" if thick else "frame_thin"))
        xx = x
        for w in widths[:-1]:
            xx += w
            s.add(Polyline(((xx, y), (xx, y + total_h)), "frame_thin"))
        body = rows[1:] if header else rows
        parts_w = number_columns(body, height, len(widths))
        whole = [w for w, _ in parts_w]
        shift = [
            max(0.0, (w - 2.4 - a - b) / 2.0) if center else 0.0
            for w, (a, b) in zip(widths, parts_w, strict=True)
        ]
        for i, row in enumerate(rows):
            xx = x
            for c, (w, cell) in enumerate(zip(widths, row, strict=True)):
                if cell:
                    dx = 0.0
                    parts = number_parts(cell) if i or not header else None
                    if parts is not None:
                        dx = shift[c] + whole[c] - box(parse(parts[0]), height)[0]
                    self.text(
                        cell,
                        (xx + 1.2 + dx, y + i * row_h + row_h / 2 + height / 2),
                        height,
                        role="title",
                    )
                xx += w
        return total_w, total_h

    def paragraph(
        self,
        markup: str,
        x: float,
        y: float,
        width: float,
        height: float = 2.5,
        indent: float = 0.0,
    ) -> float:
        """Text from (x, y top) wrapped at spaces into lines of at most ``width`` mm; following
        lines are indented by ``indent`` mm. Returns the y below the last line."""
        lead = height * LINE_SPACING
        lines = wrap(markup, width, height, indent)
        for i, line in enumerate(lines):
            at = (x + (indent if i else 0.0), y + height + i * lead)
            self.text(line, at, height, role="title")
        return y + height + (len(lines) - 1) * lead + (lead - height)

    # -- label placement -----------------------------------------------------------------------
    def finish(self, breaks: bool = True) -> Sheet:
        """Drop the optional texts a line crosses, place every dimension's text and every pending
        label (:mod:`geomcad.sheet.placer`), break the thin lines under the labels
        (:func:`~geomcad.sheet.placer.break_under_labels`; ``breaks=False``: the caller moves
        labels after and breaks them itself) and return the sheet."""
        shrink_moved(self.sheet, self.moved)
        self.moved.clear()
        index = Index(self.sheet, self.frame)  # the lines drawn; texts join it as they are set
        for area in self.occupied:
            index.add_text(area)
        drop_crossed(self.sheet, index, self.optional)
        self.optional.clear()
        place_dims(self.sheet, index, self.dims)
        self.dims.clear()
        place_labels(self.sheet, index, self.pending)
        self.pending.clear()
        if breaks:
            break_under_labels(self.sheet)
        return self.sheet


class Viewport:
    """A view of the model at a scale: model point (ox, oy) lands on sheet point ``at``."""

    def __init__(self, drawing: Drawing, scale: Scale, ox: float, oy: float, at: XY) -> None:
        self.d = drawing
        self.scale = scale
        self.ox, self.oy = ox, oy
        self.at = at
        #: The box (sheet mm) its labels keep inside where they can (:meth:`label`): its view's
        #: cell, for a view among others in a grid (a plan); ``None``: anywhere on the field.
        self.within: tuple[float, float, float, float] | None = None

    @property
    def sheet(self) -> Sheet:
        return self.d.sheet

    def p(self, q: PointLike) -> XY:
        """A model point on the sheet (the one y flip of the library)."""
        v = vec(q)
        k = self.scale.k
        return (self.at[0] + (v.x - self.ox) / k, self.at[1] - (v.y - self.oy) / k)

    def mm(self, length: float) -> float:
        return self.scale.mm(length)

    # -- lines ---------------------------------------------------------------------------------
    def seg(self, a: PointLike, b: PointLike, role: str = "link") -> None:
        pa, pb = self.p(a), self.p(b)
        self.sheet.add(Polyline((pa, pb), role, dash=fit_open(style(role).line, _dist(pa, pb))))

    def polyline(self, pts: Sequence[PointLike], role: str = "link", closed: bool = False) -> None:
        sp = tuple(self.p(q) for q in pts)
        length = sum(_dist(a, b) for a, b in itertools.pairwise(sp))
        dash = (
            fit_closed(style(role).line, length) if closed else fit_open(style(role).line, length)
        )
        self.sheet.add(Polyline(sp, role, closed=closed, dash=dash))

    def right_angle(
        self,
        vertex: PointLike,
        a: PointLike,
        b: PointLike,
        size_mm: float = 3.0,
        role: str = "construction",
    ) -> None:
        """The right-angle mark at ``vertex`` between the directions to ``a`` and ``b``: the
        square's two far sides, ``size_mm`` long on the paper; nothing where a direction is
        undefined (``a`` or ``b`` at the vertex)."""
        o, pa, pb = vec(vertex), vec(a), vec(b)
        if (pa - o).norm == 0.0 or (pb - o).norm == 0.0:
            return
        s = self.scale.model(size_mm)
        ua, ub = (pa - o).unit() * s, (pb - o).unit() * s
        self.polyline([o + ua, o + ua + ub, o + ub], role)

    def line_over(
        self,
        line: Line,
        points: Sequence[PointLike],
        role: str = "construction",
        over: float = 8.0,
    ) -> None:
        """The part of an infinite line that spans the feet of ``points``, ``over`` mm beyond."""
        ts = [line.param(q) for q in points]
        extra = self.scale.model(over)
        self.seg(line.at(min(ts) - extra), line.at(max(ts) + extra), role)

    def centre_cross(self, c: PointLike, half_mm: float) -> None:
        """Two centre lines crossing at ``c`` (dash-dot, crossing at a dash)."""
        x, y = self.p(c)
        dash = fit_centre_line("dashdot", half_mm)
        role = "centre" if dash is not None else "dimension"
        for a, b in (((x - half_mm, y), (x + half_mm, y)), ((x, y - half_mm), (x, y + half_mm))):
            self.sheet.add(Polyline((a, b), role, dash=dash))

    def circle(self, c: PointLike, r: float, role: str = "construction") -> None:
        rr = self.mm(r)
        dash = fit_closed(style(role).line, circle_length(rr))
        self.sheet.add(CircleItem(self.p(c), rr, role, dash=dash))

    def arc(self, arc: Arc, role: str = "construction") -> None:
        """A model arc (counter-clockwise from ``start`` to ``end``)."""
        rr = self.mm(arc.circle.r)
        dash = fit_open(style(role).line, arc_length(rr, arc.sweep))
        self.sheet.add(
            ArcItem(
                self.p(arc.circle.c),
                rr,
                self.p(arc.start_point),
                self.p(arc.end_point),
                -arc.sweep,
                role,
                dash=dash,
            )
        )

    # -- symbols -------------------------------------------------------------------------------
    def dot(self, q: PointLike, role: str = "point") -> None:
        self.sheet.add(CircleItem(self.p(q), DOT_R, role, fill=True))

    def joint(self, q: PointLike) -> None:
        """A revolute joint: a small circle drawn over the links."""
        symbols.joint(self.sheet, self.p(q))

    def paper_dir(self, d: PointLike) -> tuple[float, float]:
        """A model direction as a paper direction (y down)."""
        v = vec(d)
        return (v.x, -v.y)

    def pivot(self, q: PointLike, down: tuple[float, float] = (0.0, -1.0)) -> None:
        """A revolute joint on the frame (GOST 2.770): the joint, its stand, hatched ground;
        the stand points along the model direction ``down``."""
        symbols.pivot(self.sheet, self.p(q), self.paper_dir(down))

    def guide(
        self, a: PointLike, b: PointLike, side: tuple[float, float] = (0.0, -1.0),
        block: float = symbols.SLIDER_SIZE[1],
    ) -> None:  # fmt: skip
        """A slider's fixed guide from a to b, hatched on the model side ``side``, drawn
        clear of the slider block (``block`` mm across the guide)."""
        symbols.guide(self.sheet, self.p(a), self.p(b), self.paper_dir(side), block)

    def slider(
        self,
        q: PointLike,
        along: PointLike = (1.0, 0.0),
        role: str = "link",
        with_joint: bool = True,
    ) -> None:
        """A slider block on its guide, with the joint of the link that drives it (none
        ``with_joint=False``: a block rigid with its link, a cross's slide); ``role`` "extreme"
        draws an extreme position in thin two-dot lines."""
        symbols.block(
            self.sheet, self.p(q), self.paper_dir(vec(along).unit()), role, with_joint=with_joint
        )

    def turn(
        self,
        centre: PointLike,
        sense: float,
        start_deg: float,
        markup: str = "",
        r_mm: float = 9.0,
        sweep_deg: float = 100.0,
        role: str = "vector",
        height: float = 3.5,
    ) -> None:
        """A curved arrow about ``centre`` (an angular velocity, a moment): an arc of ``r_mm``
        from ``start_deg`` (model degrees, ccw from +x) over ``sweep_deg`` in the sense of
        ``sense`` (> 0: counter-clockwise), its head at the far end (the shaft stops short of the
        tip), and an optional label by the arc's middle. A zero ``sense`` draws nothing."""
        if sense == 0.0:
            return
        cx, cy = self.p(centre)
        s = 1.0 if sense > 0.0 else -1.0
        sweep = math.radians(sweep_deg)
        a0 = math.radians(start_deg)
        a1 = a0 + s * sweep
        gap = min(TURN_HEAD_GAP, TURN_HEAD_GAP_MM / r_mm)

        def at(a: float) -> XY:
            return (cx + r_mm * math.cos(a), cy - r_mm * math.sin(a))

        self.sheet.add(
            ArcItem(
                (cx, cy),
                r_mm,
                at(a0),
                at(a1 - s * gap),
                -s * (sweep - gap),
                role,
            )
        )
        _head(self.sheet, at(a1), (-math.sin(a1) * s, -math.cos(a1) * s), role)
        if markup:
            mid = a0 + s * sweep / 2.0
            self.d.label(at(mid), markup, height, prefer=(math.cos(mid), -math.sin(mid)),
                         clear=0.8, others=(at(a1), at(a0)))  # fmt: skip

    def arrow(self, a: PointLike, b: PointLike, role: str = "vector") -> None:
        """A vector from a to b with a filled arrowhead at b (a plan's or a polygon's vector is
        kept with its scale in ``Sheet.scaled``, for the checker)."""
        pa, pb = self.p(a), self.p(b)
        _arrow(self.sheet, pa, pb, role)
        if self.scale.q != "l" and pa != pb:
            self.sheet.scaled.append((pa, pb, self.scale))

    # -- dimensions ----------------------------------------------------------------------------
    def dim_linear(
        self, a: PointLike, b: PointLike, text: str, offset: float = 10.0, height: float = 3.5
    ) -> None:
        """An aligned dimension of segment ab, ``offset`` mm to the left of a → b on the paper
        (negative: to the right). Its text runs along the dimension line, above it, reading
        from the bottom or from the right (GOST 2.307), in the middle of the line, or beside
        its end where the line is shorter than the text.
        """
        pa, pb = self.p(a), self.p(b)
        length = _dist(pa, pb)
        ux, uy = (pb[0] - pa[0]) / length, (pb[1] - pa[1]) / length
        nx, ny = uy, -ux  # left of a → b on paper (y down)
        da = (pa[0] + nx * offset, pa[1] + ny * offset)
        db = (pb[0] + nx * offset, pb[1] + ny * offset)
        s = math.copysign(1.0, offset)
        for p0, p1 in ((pa, da), (pb, db)):
            start = (p0[0] + nx * s * 1.0, p0[1] + ny * s * 1.0)
            end = (p1[0] + nx * s * 2.0, p1[1] + ny * s * 2.0)
            self.sheet.add(Polyline((start, end), "dimension"))
        self.sheet.add(Polyline((da, db), "dimension"))
        _head(self.sheet, db, (ux, uy), "dimension")
        _head(self.sheet, da, (-ux, -uy), "dimension")
        # the text's direction: the line's, turned to read from the bottom or the right
        level = tol.DERIVED
        tx, ty = (ux, uy) if ux > level or (abs(ux) <= level and uy < 0.0) else (-ux, -uy)
        angle = math.degrees(math.atan2(-ty, tx))
        upx, upy = ty, -tx  # the text's up on the paper
        width, rise, down = box(parse(text), height)
        line = _dist(da, db)
        gap = 1.0 + down
        # candidates along the line (the middle first), then beyond either end where the line
        # is short; Drawing.finish takes the first whose turned box crosses no drawn line
        fits = width <= line - 2.0 * ARROW_LEN
        inside = (
            sorted((k / 20.0 for k in range(2, 19)), key=lambda f: abs(f - 0.5)) if fits else []
        )
        far = 0.5 + (line + width) / (2.0 * line) + 1.0 / line
        cands: list[XY] = []
        # above the line first (GOST 2.307), below it only where every place above is crossed,
        # then a little further off the line on either side
        for lift in (gap, -(1.0 + rise), gap + 2.0, -(3.0 + rise)):
            for f in (*inside, far, 1.0 - far):
                cx = da[0] + (db[0] - da[0]) * f - tx * width / 2.0 + upx * lift
                cy = da[1] + (db[1] - da[1]) * f - ty * width / 2.0 + upy * lift
                cands.append((cx, cy))
        self.d.dims.append(
            DimText(text, height, angle, (tx, ty), tuple(cands), (width, rise, down))
        )

    def dim_angle(
        self,
        vertex: PointLike,
        p1: PointLike,
        p2: PointLike,
        text: str,
        r_mm: float = 15.0,
        height: float = 3.5,
    ) -> None:
        """The angle p1-vertex-p2 (the smaller one) as an arc of ``r_mm`` with two arrowheads."""
        v = vec(vertex)
        a1 = (vec(p1) - v).angle
        a2 = (vec(p2) - v).angle
        sweep = math.remainder(a2 - a1, 2.0 * math.pi)
        start, sweep = (a1, sweep) if sweep > 0 else (a2, -sweep)
        r = self.scale.model(r_mm)
        arc = Arc(Circle(v, r), start, start + sweep)
        self.arc(arc, "dimension")
        c = self.p(v)
        for ang, sgn in ((start, -1.0), (start + sweep, 1.0)):
            tip = (c[0] + r_mm * math.cos(ang), c[1] - r_mm * math.sin(ang))
            # the tangent on paper, pointing along the arc towards its end
            tx, ty = -math.sin(ang) * sgn, -math.cos(ang) * sgn
            _head(self.sheet, tip, (tx, ty), "dimension")

        def on_arc(t: float) -> XY:
            a = start + sweep * t
            return (c[0] + r_mm * math.cos(a), c[1] - r_mm * math.sin(a))

        mid = start + sweep / 2.0
        others = tuple(on_arc(t) for t in (0.3, 0.7))
        self.d.label(
            on_arc(0.5), text, height, prefer=(math.cos(mid), -math.sin(mid)), others=others
        )

    # -- labels --------------------------------------------------------------------------------
    def label(
        self,
        q: PointLike,
        markup: str,
        height: float = 3.5,
        prefer: tuple[float, float] | None = None,
        clear: float = JOINT_R,
        id: str = "",
        space: float = 0.0,
        others: Sequence[PointLike] = (),
    ) -> None:
        """A label next to a model point (or one of ``others``, where it stands clearer);
        ``prefer`` is a model direction to try first; ``space``: mm kept further than usual
        from other texts."""
        pref = None if prefer is None else (prefer[0], -prefer[1])
        at = tuple(self.p(o) for o in others)
        self.d.label(
            self.p(q), markup, height, pref, clear, id=id, space=space, others=at,
            within=self.within,
        )  # fmt: skip


def _head(sheet: Sheet, tip: XY, u: tuple[float, float], role: str) -> None:
    """A filled arrowhead at ``tip`` pointing along the paper direction ``u``."""
    ux, uy = u
    bx, by = tip[0] - ux * ARROW_LEN, tip[1] - uy * ARROW_LEN
    px, py = -uy * ARROW_HALF_WIDTH, ux * ARROW_HALF_WIDTH
    sheet.add(Polyline((tip, (bx + px, by + py), (bx - px, by - py)), role, closed=True, fill=True))


def _arrow(sheet: Sheet, a: XY, b: XY, role: str) -> None:
    length = _dist(a, b)
    if length <= 0.0:
        return
    ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    end = (b[0] - ux * ARROW_LEN * 0.8, b[1] - uy * ARROW_LEN * 0.8) if length > ARROW_LEN else a
    sheet.vectors.append((a, b))
    sheet.add(Polyline((a, end), role))
    _head(sheet, b, (ux, uy), role)
