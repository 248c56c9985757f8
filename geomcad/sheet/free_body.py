"""Free-body diagrams: every solved load on a body (a kinetostatic solution's reactions,
inertia loads and driving loads) drawn on its line of action at a force scale μ_F, each force an
arrow exactly at μ_F (one too short there at a stated larger μ_F*, its label marked *), each
moment a curved arrow about its point, with their values; and the sheet's words on the scales.

Moved here from the seed problems' package (it was ``constructions/dyn_common.py``, shared by the
sheets of 2013-9 and kulisa-23110713), so that any dynamics sheet draws its free bodies the
same way. Its words are in ``strings/<lang>/free_body.toml``."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from geomcad import tol
from geomcad.geom import Vec
from geomcad.sheet import Drawing, Scale, Viewport
from geomcad.sheet.compose import TITLE_LEAD, TITLE_SPACING, Extent, Figure, Placed
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.lang import Words
from geomcad.sheet.loads import MOMENT_SWEEP, ForceScales, force, force_scales, moment
from geomcad.sheet.views import num

ORIGIN = Vec(0.0, 0.0)
WORDS = Words(__package__, "free_body")

#: A force arrow shorter than this (mm) is drawn this long, so that its head shows.
#: A force shorter than this at μ_F (two arrowheads) cannot be read as an arrow: it is drawn as
#: a point with its label, and the sheet says so (SHEETS.md).


def small(x: float, scale: float, unit: str = "", symbol: str = "") -> str:
    """A quantity that should vanish, written after its ``symbol``: "M_у = 0,012 Н·м", or
    "|M_у| < 2·10^{–9} Н·м" when it is round-off (so that the sheet does not print noise that
    differs from machine to machine). Non-breaking spaces keep the symbol, the value and the
    unit on one line when the text is wrapped."""
    nb = "\u00a0"
    tail = f"{nb}{unit}" if unit else ""
    bound = tol.DERIVED * abs(scale)
    if abs(x) <= bound:
        return (
            f"|{symbol}|{nb}<{nb}{num(bound, 1)}{tail}" if symbol else f"<{nb}{num(bound, 1)}{tail}"
        )
    return f"{symbol}{nb}={nb}{num(x, 3)}{tail}" if symbol else f"{num(x, 3)}{tail}"


def facing(sense: float, at_deg: float, open_: bool = False) -> float:
    """The start angle (model degrees) of a moment's arc (:data:`MOMENT_SWEEP` long, in the
    sense of ``sense``) whose middle, or with ``open_`` whose opening, faces ``at_deg``: two
    moments about one point, drawn on radii far apart, the inner one's middle (where its label
    goes) facing the outer one's opening, can be told apart."""
    s = 1.0 if sense >= 0.0 else -1.0
    half = math.degrees(MOMENT_SWEEP) / 2.0
    return at_deg - s * (180.0 + half if open_ else half)


#: The longest arrow of a force drawn at a second μ_F (mm).
LOAD_ROOM_MM = 24.0


def scales_of(reactions: Any, k_F: float) -> ForceScales:
    """The sheet's force scales: μ_F = ``k_F``, and for the forces shorter than
    :data:`SHORT_MM` at it the larger μ_F* (μ_F** …) they are drawn at, marked ``*``; the
    balancing check moment's forces and round-off forces are left out."""
    mags = [
        a.force.norm
        for lds in reactions.loads.values()
        for a in lds
        if a.force is not None and a.kind != "balancing"
    ]
    return force_scales(mags, LOAD_ROOM_MM, first=Scale(k_F, "F"))


def short_note(k_F: float, reactions: Any = None) -> str:
    """The sheet's words for the scales of the forces: every force an arrow at μ_F, those
    too short there at the larger μ_F* (μ_F** …) it states by value (their labels starred)."""
    fs = scales_of(reactions, k_F) if reactions is not None else None
    if fs is None or not fs.tiered:
        return WORDS("short_none", k_F=num(k_F))
    return WORDS("short_note", mm=num(SHORT_MM), k_F=num(k_F), scales=fs.further())


#: The height (mm) of the line under a view's caption that states its further μ_F.
FURTHER_H = 2.5


class LoadedFigure(Figure):
    """A problem's own figure (:class:`~geomcad.sheet.compose.Figure`) with forces drawn on it
    at the force scales ``fs``: its caption states the view's μ_F after the length scale, and a
    line under it the larger μ_F* (μ_F** …) of the forces too short at μ_F (their labels
    starred); ``draw_fn`` draws each force at ``fs.scales[fs.tier(F)]``, never a dot, never a
    fixed length."""

    def __init__(
        self, box: Extent, draw_fn: Callable[[Viewport], None], fs: ForceScales, **kw: Any
    ) -> None:
        super().__init__(box, draw_fn, **kw)
        self.fs = fs

    def title_room(self) -> float:
        if not self.fs.tiered:
            return super().title_room()
        return (
            super().title_room()
            + FURTHER_H * TITLE_LEAD
            + self.fs.further_rise(FURTHER_H)
            - FURTHER_H
        )

    def caption(self, scale: Scale | None) -> str:
        return f"{super().caption(scale)};  {self.fs.caption()}"

    def draw(self, d: Drawing, at: Placed) -> None:
        if self.fs.tiered:
            lines = (self.title_lines - 1) * TITLE_SPACING  # a caption broken into lines
            lead = self.title_height * (TITLE_LEAD + lines)
            top = at.box[1] + lead + self.fs.further_rise(FURTHER_H)
            d.text(self.fs.further(), (at.box[0], top), FURTHER_H)
        super().draw(d, at)


@dataclass(frozen=True)
class Where:
    """How a load is drawn: its label, the point it is drawn at (None: where it acts), whether
    the arrow arrives there, a preferred label direction, a moment's radius and start angle, and
    the point where a force too short for an arrow is drawn as a dot (None: ``at``): on its line
    of action outside the body, never on the body's outline."""

    label: str
    at: Vec | None = None
    arrive: bool = False
    prefer: tuple[float, float] | None = None
    radius: float = 8.0
    start_deg: float = -35.0
    short_at: Vec | None = None


def load(reactions: Any, body: str, name: str) -> Vec | None:
    """The force of the load ``name`` on ``body`` (``None``: no such force)."""
    for ld in reactions.loads.get(body, ()):
        if ld.name == name and ld.force is not None:
            return ld.force  # type: ignore[no-any-return]
    return None


def moment_of(reactions: Any, body: str, name: str) -> float:
    """The moment of the load ``name`` on ``body`` (0: no such moment)."""
    return sum(float(ld.moment) for ld in reactions.loads.get(body, ()) if ld.name == name)


def draw_loads(
    v: Viewport,
    reactions: Any,
    k_F: float,
    body: str,
    where: dict[str, Where],
    centre: Vec = ORIGIN,
) -> None:
    """Every solved load on ``body``: forces at their points exactly at k_F (one shorter than
    :data:`SHORT_MM` at the larger μ_F* of :func:`scales_of`, its label marked *; never a
    dot), moments about their points; the balancing check moment and round-off forces are left
    out."""
    fs = scales_of(reactions, k_F)
    for ld in reactions.loads[body]:
        if ld.kind == "balancing":
            continue
        w = where.get(ld.name, Where(ld.name))
        if ld.force is not None:
            tier = fs.tier(ld.force.norm)
            if tier is None:
                continue
            text = f"{w.label}{fs.mark(tier)} = {num(ld.force.norm)} {WORDS('N')}"
            force(v, w.at or ld.at, ld.force, fs.scales[tier].k, text, w.arrive,
                  role="result", height=2.5, prefer=w.prefer)  # fmt: skip
        elif abs(ld.moment) > 0.0:
            text = f"{w.label} = {num(abs(ld.moment))} {WORDS('Nm')}"
            moment(v, w.at or centre, ld.moment, w.radius, text, role="result",
                   start=math.radians(w.start_deg), height=2.5)  # fmt: skip
