"""Loads on a free-body diagram: force vectors at a force scale and curved moment arrows.

A force is drawn as a vector of |F|/μ_F millimetres along its line of action, either leaving its
point of application (a pull, the usual way) or arriving at it (a push, where the tail would run
into the body). A moment is an arc around its point with an arrowhead giving its sense
(counter-clockwise for M > 0, as in the model). Both ask the drawing for a placed label.
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.geom import PointLike, Vec
from geomcad.sheet import symbols
from geomcad.sheet.drawing import ARROW_HALF_WIDTH, ARROW_LEN, JOINT_R, SHORT_MM, Viewport, _arrow
from geomcad.sheet.model import XY, ArcItem, CircleItem, Polyline, Sheet, TextItem
from geomcad.sheet.scale import Scale, nice_below, nice_factor

#: A moment arrow's sweep (rad) and the gap between its ends.
MOMENT_SWEEP = math.radians(250.0)


#: The mark of a force drawn at the view's second, third … μ_F (appended to its label and to
#: the symbol of that μ_F in the view's caption).
MARK = "*"


@dataclass(frozen=True)
class ForceScales:
    """The force scales of one view: a force is always an arrow at a stated μ_F, never a dot.

    ``scales[0]`` is the view's μ_F. The forces that come out shorter than :data:`SHORT_MM`
    (two arrowheads) at it are drawn at ``scales[1]`` (larger arrows, their labels marked
    ``*``), those still too short there at ``scales[2]`` (``**``), and so on: each tier's μ_F is
    stated in the view's caption (:meth:`caption`). A force under ``zero`` N is round-off of a
    zero force and is not drawn (its value, 0, is in the table).
    """

    scales: tuple[Scale, ...]
    zero: float = 0.0
    #: forces up to this (N), a negligible share of the view's largest, are not drawn where
    #: drawing them would take a fourth μ_F (:func:`force_tiers`; the view names them)
    negligible: float = 0.0
    #: the scales after the first are those of the view's insets (:func:`view_scales`: the
    #: view itself draws every force at one μ_F), not of further arrows in the view
    insets: bool = False
    #: the share of the view's largest force under which its forces are named, not drawn
    #: (:func:`view_scales`)
    limit: float = 0.0
    #: the shortest arrow (mm) drawn at a scale: a force shorter there goes to the next one
    #: (:data:`SHORT_MM`, two arrowheads)
    short: float = SHORT_MM
    #: the least force (N) a view with insets draws at its own μ_F: a smaller one long enough
    #: there too is drawn in its insets where that lets them draw more (:func:`view_scales`)
    least: float = 0.0
    #: how many times (≥ 1) the insets' longest arrow is as long as the view's own shortest:
    #: 1 where no inset arrow is longer (:func:`view_scales`)
    over: float = 1.0
    #: the length (mm) of the direction arrows of the forces too short at the last μ_F and
    #: over ``negligible`` (:func:`view_scales`' third tier, :meth:`tier` ``len(scales)``,
    #: drawn without a scale: the view's caption says so); 0: no such tier (those forces are
    #: drawn at the last μ_F)
    fixed: float = 0.0
    #: (force N, tier) of the forces an inset draws at a tier other than their magnitude's:
    #: every force at one point (one inset) at ONE μ_F, the finest of theirs
    #: (:func:`~geomcad.sheet.insets.one_scale_per_inset`)
    pinned: tuple[tuple[float, int], ...] = ()

    @property
    def k(self) -> float:
        """The view's own μ_F (N/mm)."""
        return self.scales[0].k

    def tier(self, F: float) -> int | None:
        """The index of the scale a force of ``F`` N is drawn at (``None``: a zero force)."""
        if max(self.zero, self.negligible) >= F:
            return None
        for G, t in self.pinned:
            if abs(G - F) <= tol.DERIVED * G:
                return t
        for i, sc in enumerate(self.scales):
            if F / sc.k >= self.short * (1.0 - tol.DERIVED) and (i > 0 or self.least <= F):
                return i
        last = len(self.scales) - 1
        if self.fixed and F / self.scales[last].k < self.short * (1.0 - tol.DERIVED):
            return last + 1  # a direction arrow, self.fixed mm long
        return last

    def is_fixed(self, F: float) -> bool:
        """Whether a force of ``F`` N is drawn as a direction arrow :attr:`fixed` mm long,
        without a scale (the third tier of a view, :func:`view_scales`)."""
        return self.tier(F) == len(self.scales)

    def k_at(self, F: float) -> float:
        """The μ_F (N/mm) a force of ``F`` N (> 0, not left out) is drawn at: its tier's, or,
        a direction arrow, the one that draws it :attr:`fixed` mm long."""
        tier = self.tier(F)
        assert tier is not None
        return F / self.fixed if tier == len(self.scales) else self.scales[tier].k

    @staticmethod
    def mark(tier: int) -> str:
        """The mark of a label drawn at scale ``tier`` ("" at the view's own μ_F): its stars as
        a superscript (``R_{03}^{*}``), where a star reads as one; on the line osifont sets
        ``*`` at the height of ``=``."""
        return f"^{{{MARK * tier}}}" if tier > 0 else ""

    def caption(self) -> str:
        """The view's own μ_F as its caption states it: ``μ_F = 100 Н/мм``."""
        from geomcad.sheet.compose import scale_text

        return scale_text(self.scales[0])

    def further(self, tiers: Iterable[int] | None = None) -> str:
        """The further scales, by their marks, the unit written once: ``μ_F* = 10,
        μ_F** = 2 Н/мм`` ("" when every force is at the view's own μ_F); ``tiers``: only
        those (an inset's)."""
        from geomcad.sheet.compose import scale_text

        mine = range(1, len(self.scales)) if tiers is None else sorted(set(tiers))
        texts = [(i, scale_text(self.scales[i])) for i in mine if 0 < i < len(self.scales)]
        if not texts:
            return ""
        unit = texts[-1][1].rsplit(" ", 1)[-1]
        parts = [t.replace(" = ", f"{self.mark(i)} = ", 1) for i, t in texts]
        heads = [p[: -len(unit)].rstrip() if p.endswith(unit) else p for p in parts[:-1]]
        return ", ".join([*heads, parts[-1]])

    def further_rise(self, height: float) -> float:
        """How far (mm) the line of :meth:`further` at cap height ``height`` reaches above its
        baseline: its stars are superscripts, above the capitals."""
        from geomcad.sheet.text import box, parse

        return box(parse(self.further()), height)[1] if self.tiered else height

    def longest(self, forces: Iterable[float]) -> float:
        """The longest arrow (mm) of forces of magnitudes ``forces`` (N), each at its tier."""
        out = 0.0
        for F in forces:
            if self.tier(abs(F)) is not None:
                out = max(out, abs(F) / self.k_at(abs(F)))
        return out

    @property
    def tiered(self) -> bool:
        """Whether some forces are drawn at a second μ_F (the sheet says what the mark means)."""
        return len(self.scales) > 1


def force_scales(
    forces: Iterable[float], room_mm: float, first: Scale | None = None, short: float = SHORT_MM
) -> ForceScales:
    """The force scales of a view whose forces have the magnitudes ``forces`` (N): the first
    so that the largest is at most ``room_mm`` long, then one more (the largest remaining at
    most ``room_mm``) while some force would be shorter than ``short`` (:data:`SHORT_MM`, two
    arrowheads). Forces under ``tol.DERIVED`` of the largest are zero. ``room_mm`` is at least
    2.5 · ``short`` (a rounded μ_F draws the largest force at least ``room_mm``/2.5 long), so
    every tier takes at least its largest force. ``first``: the view's μ_F where the sheet has
    chosen it."""
    mags = sorted((abs(F) for F in forces), reverse=True)
    big = mags[0] if mags else 0.0
    room = max(room_mm, 2.5 * short)
    if big <= 0.0:
        return ForceScales((first or nice_factor(1.0, room, "F"),), short=short)
    zero = tol.DERIVED * big
    scales = [first or nice_factor(big, room, "F")]
    rest = [F for F in mags if zero < F and F / scales[-1].k < short * (1.0 - tol.DERIVED)]
    while rest:
        scales.append(nice_factor(rest[0], room, "F"))
        rest = [F for F in rest if F / scales[-1].k < short * (1.0 - tol.DERIVED)]
    return ForceScales(tuple(scales), zero, short=short)


#: A view draws its forces at most at this many μ_F (its own and one stated μ_F*, a third
#: only where two cannot draw every force between SHORT_MM and the view's limit; never four).
MOST_TIERS = 3
#: A force drawn at a further μ_F is at most this many times the view's room long (the room
#: its largest force takes at the view's own μ_F).
TIER_LIMIT = 1.5
#: Forces under this share of a view's largest are left out (and named) where drawing them
#: would take a fourth μ_F: they change no result drawn (0,1 % of the largest).
NEGLIGIBLE = 0.001


def force_tiers(forces: Iterable[float], room_mm: float) -> ForceScales:
    """The force scales of a view with few tiers (a teacher accepts the view's μ_F and one
    μ_F* stated under its caption): every force an arrow at least :data:`SHORT_MM` long at a
    stated μ_F, at most :data:`MOST_TIERS` of them (forces under :data:`NEGLIGIBLE` of the
    largest that would take a fourth are left out: ``negligible``, the view names them).

    The forces are cut into bands from the smallest up: each band's μ_F draws its smallest
    force :data:`SHORT_MM` long (the coarsest factor that does) and takes every larger force
    it draws at most ``TIER_LIMIT · room_mm`` long; the top band is drawn at the μ_F that puts
    the view's largest force into ``room_mm`` where that draws the band's smallest at least
    :data:`SHORT_MM`. Where more than :data:`MOST_TIERS` bands would be needed (forces over
    four decades), the two neighbouring bands whose union draws its longest force shortest are
    joined (a longer arrow, at its stated μ_F, rather than a fourth tier). Forces under
    ``tol.DERIVED`` of the largest are zero (not drawn)."""
    mags = sorted((abs(F) for F in forces), reverse=True)
    big = mags[0] if mags else 0.0
    room = max(room_mm, 2.5 * SHORT_MM)
    if big <= 0.0:
        return ForceScales((nice_factor(1.0, room, "F"),))
    zero = tol.DERIVED * big
    live = sorted(F for F in mags if zero < F)
    limit = TIER_LIMIT * room
    short = SHORT_MM * (1.0 - tol.DERIVED)
    top = nice_factor(big, room, "F")
    if live[0] / top.k >= short:
        return ForceScales((top,), zero)
    # bands from the smallest force up: (their smallest, their largest)
    bands: list[list[float]] = []
    for F in live:
        if bands and F / nice_below(bands[-1][0], SHORT_MM).k <= limit * (1.0 + tol.DERIVED):
            bands[-1][1] = F
        else:
            bands.append([F, F])
    # the top band at the view's own μ_F where that draws all of it long enough
    lo = next((b[0] for b in bands if big / top.k >= short and b[0] / top.k >= short), None)
    if lo is not None:
        bands = [b for b in bands if b[0] < lo]
        bands.append([lo, big])
    negligible = 0.0
    if len(bands) > MOST_TIERS:
        # forces too small to matter are named, not drawn at a fourth μ_F
        low = [b for b in bands if b[1] < NEGLIGIBLE * big]
        if low:
            negligible = low[-1][1]
            bands = bands[len(low) :]
    while len(bands) > MOST_TIERS:
        i = min(range(len(bands) - 1),
                key=lambda j: bands[j + 1][1] / nice_below(bands[j][0], SHORT_MM).k)  # fmt: skip
        bands[i : i + 2] = [[bands[i][0], bands[i + 1][1]]]
    scales = [top if b[0] / top.k >= short else nice_below(b[0], SHORT_MM) for b in reversed(bands)]
    return ForceScales(tuple(dict.fromkeys(scales)), zero, negligible)


#: A load of a view under this share of the view's largest force is named ("не показаны",
#: with its value and the share stated) under its caption, not drawn (:func:`view_scales`):
#: the teacher's "negligible, listed" — 0,1 % of the largest, the share a force plan leaves
#: out too (:data:`NEGLIGIBLE`), under the width of a line (0,2 mm) on a 200-mm arrow (a 2 N
#: weight beside 4560 N, 0,04 %, is listed; one of 0,3 % is drawn at a stated μ_F: review 10,
#: slider_rocker_rpr hid G1…G4, Ф4 < 0,34 % under the 0,5 % of before). Every load over it is
#: drawn: to scale in the view or in its insets, else as a direction arrow VIEW_SHORT_MM long
#: (review 8: a lever that hid 12 of its loads "менее 7,5 %" could not be checked).
HIDE_SHARE = NEGLIGIBLE
#: A reaction of a free body (or the lever's P_ур) over this share of the view's largest force
#: is drawn to scale (the insets' μ_F is the one that draws it, :func:`view_scales`); a smaller
#: one is a direction arrow, never left out.
VIEW_NEGLIGIBLE = HIDE_SHARE
#: The shortest arrow (mm) of a view's insets: a head (ARROW_LEN) and a shaft that shows its
#: direction (5 mm rather than SHORT_MM's two heads: an inset with its longest arrow no longer
#: than the view's shortest spans forces cap/5 apart, not cap/7, and leaves fewer out).
VIEW_SHORT_MM = 5.0
#: The shortest arrow (mm) at a view's own μ_F: two arrowheads (SHORT_MM), the length the
#: drawing of links places clear of the links (an arrow 5–7 mm long is set along its link
#: there, the compressor's F_D); a shorter force goes to the insets.
VIEW_OWN_MM = SHORT_MM
#: The longest arrow (mm) of a view's insets, where the view's own shortest arrow is longer
#: (:func:`view_scales`).
INSET_CAP_MM = 25.0


def view_scales(
    forces: Iterable[float], room_mm: float, keep: Iterable[float] = (), given: Iterable[float] = ()
) -> ForceScales:
    """:func:`_view_scales`, remembered: the layout asks a view's scales for each room it
    tries, the same forces each time (a frozen :class:`ForceScales`, shared)."""
    return _view_scales(tuple(forces), room_mm, tuple(keep), tuple(given))


@functools.lru_cache(maxsize=4096)
def _view_scales(
    forces: tuple[float, ...], room_mm: float, keep: tuple[float, ...], given: tuple[float, ...]
) -> ForceScales:
    """The force scales of a view that draws its forces at ONE μ_F and its short ones at ONE
    more (a teacher accepts the view's μ_F and one other), so that a longer arrow is a larger
    force throughout the view, across both scales as far as the GOST steps allow:

    - ``scales[0]``, the view's μ_F, puts the largest force into ``room_mm`` (the coarsest GOST
      step that does); every force at least :data:`VIEW_OWN_MM` long there is drawn in the
      view itself;
    - a shorter force is drawn again in an inset (an ESKD detail of its point) at
      ``scales[1]``, the one μ_F of all the view's insets: the finest GOST step that draws the
      largest of them no longer than the view's own shortest arrow nor :data:`INSET_CAP_MM`
      (so no inset arrow outgrows an arrow of the view), where it draws as many of them as it
      can at least :data:`VIEW_SHORT_MM` long;
    - a force still shorter than :data:`VIEW_SHORT_MM` there (with the view's largest arrow
      ``L`` mm long, the smallest force drawn in the view is 7/``L`` of the largest, and the
      insets take forces ``cap``/5 times smaller, ``cap`` the insets' longest arrow: the
      forces under about 35/(``L`` · ``cap``) of the largest, 1.4 % for ``L`` = 100 mm and
      ``cap`` = 25 mm, several % in a small free body or a lever) is drawn in the insets too,
      as a direction arrow of the fixed length :data:`VIEW_SHORT_MM` (``fixed``, the third
      tier: no arrow of a scale is shorter, so a longer arrow is never a smaller force), its
      value in the table of loads, where it is at least :data:`HIDE_SHARE` of the largest;
    - a smaller force is named, not drawn (``negligible``: the largest such; ``limit``: its
      share of the largest force, under :data:`HIDE_SHARE`);
    - a force of ``keep`` (a free body's reaction, the lever's P_ур: what the view shows) is
      never named: over :data:`VIEW_NEGLIGIBLE` of the largest, where the insets' μ_F would
      draw the smallest of them shorter than :data:`VIEW_SHORT_MM`, it is the coarsest step
      that draws it that long, the cap or not; a smaller one is a direction arrow (and so is
      every load larger than it).

    Where that would draw a load of :data:`HIDE_SHARE` of the largest or more (or one of
    ``given``, a load the file gives: never without a scale) as a direction arrow, the insets
    take up to :data:`INSET_SCALES` μ_F of their own instead (:func:`inset_scales`: every such
    load drawn to a stated scale, review 9).

    :meth:`ForceScales.tier` gives a force's scale (0: the view itself, 1, 2: its insets, the
    number of scales: a direction arrow, ``None``: named). Forces under ``tol.DERIVED`` of the
    largest are zero."""
    mags = sorted((abs(F) for F in forces), reverse=True)
    big = mags[0] if mags else 0.0
    room = max(room_mm, 2.5 * SHORT_MM)
    if big <= 0.0:
        return ForceScales((nice_factor(1.0, room, "F"),), insets=True, short=VIEW_SHORT_MM)
    zero = tol.DERIVED * big
    top = nice_factor(big, room, "F")
    short = VIEW_SHORT_MM * (1.0 - tol.DERIVED)
    live = sorted(F for F in mags if zero < F)
    # the view's own forces from ``live[j]`` up, the insets' below it: first every force at
    # least VIEW_OWN_MM long in the view, then also those under INSET_CAP_MM, the shortest
    # first, while that names fewer forces
    first = next(j for j, F in enumerate(live) if F / top.k >= VIEW_OWN_MM * (1.0 - tol.DERIVED))
    if first == 0:
        return ForceScales((top,), zero, insets=True, short=VIEW_SHORT_MM)
    kept = [F for F in keep if VIEW_NEGLIGIBLE * big < F]
    best: tuple[tuple[int, int, int], Scale, list[float], float] | None = None
    for j in range(first, len(live)):
        if j > first and live[j - 1] / top.k >= INSET_CAP_MM:
            break
        # the insets' longest arrow: never longer than the view's own shortest
        cap = min(live[j] / top.k, INSET_CAP_MM)
        k = nice_factor(live[j - 1], cap, "F")
        mine = [F for F in kept if live[j] > F]
        over = 0
        if mine and min(mine) / k.k < short:
            k, over = nice_below(min(mine), VIEW_SHORT_MM), 1  # a reaction past the cap
        named = [F for F in live[:j] if F / k.k < short]
        if len(named) == j or k.k >= top.k * (1.0 - tol.DERIVED):
            # no inset draws more: those VIEW_SHORT_MM long at the view's μ_F are drawn in it
            k, named = top, [F for F in live[:j] if F / top.k < short]
        score = (len(named), over, j)
        if best is None or score < best[0]:
            best = (score, k, named, live[j - 1] / k.k / (live[j] / top.k))
    assert best is not None
    (_, _, j), k2, named, ratio = best
    floor = HIDE_SHARE * big
    shown = [F for F in given if zero < F]
    if any(floor * (1.0 - tol.DERIVED) <= F or F in shown for F in named):
        # a load of HIDE_SHARE or more (or a given one) too short at the insets' μ_F: the
        # insets at up to INSET_SCALES μ_F of their own instead (:func:`inset_scales`)
        return inset_scales(live, top, first, shown, keep)
    scales = (top,) if k2 is top else (top, k2)
    # too short at every μ_F: left out under HIDE_SHARE (and under every reaction), else a
    # direction arrow VIEW_SHORT_MM long
    floor = min([HIDE_SHARE * big, *(F for F in keep if zero < F)])
    negligible = max((F for F in named if floor > F), default=0.0)
    limit = negligible / big
    fixed = VIEW_SHORT_MM if any(negligible < F for F in named) else 0.0
    return ForceScales(scales, zero, negligible, insets=True, limit=limit, short=VIEW_SHORT_MM,
                       least=live[j], over=max(1.0, ratio) if k2 is not top else 1.0,
                       fixed=fixed)  # fmt: skip


#: A view's insets draw their forces at most at this many μ_F (μF*, μF**, each stated under
#: the view's caption; review 9: one μ_F drew 6 of watt2's lever loads as direction arrows).
INSET_SCALES = 2
#: How much longer (a factor) each further cap of the insets' longest arrow tried is, where
#: INSET_SCALES μ_F with their arrows at most INSET_CAP_MM long cannot draw them all.
CAP_STEP = 1.25


def inset_scales(
    live: list[float], top: Scale, first: int, given: list[float], keep: Iterable[float]
) -> ForceScales:
    """:func:`view_scales` where one inset μ_F would leave a load of :data:`HIDE_SHARE` of the
    view's largest or more (or a ``given`` one) without a scale: the view draws its forces
    ``live[first:]`` (ascending, N) at its own μ_F ``top``, and its insets every smaller one of
    HIDE_SHARE or more and every given one at the fewest μ_F (at most :data:`INSET_SCALES`) of
    :func:`force_scales` with arrows :data:`VIEW_SHORT_MM` … ``cap`` long, each finer tier
    marked (``*``, ``**``) and stated: ``cap`` no longer than the view's own shortest arrow
    where that does (a longer arrow a larger force across the view and its insets), else
    :data:`INSET_CAP_MM`, else (two μ_F still too few) each :data:`CAP_STEP` longer until they
    are enough. A smaller force too short at the finest is named (under HIDE_SHARE), a
    reaction among them (``keep``) a direction arrow :data:`VIEW_SHORT_MM` long."""
    big = live[-1]
    zero = tol.DERIVED * big
    floor = HIDE_SHARE * big
    below = live[:first]
    draw = [F for F in below if floor * (1.0 - tol.DERIVED) <= F or F in given]
    own = live[first] / top.k
    short = VIEW_SHORT_MM * (1.0 - tol.DERIVED)
    caps = [min(own, INSET_CAP_MM), INSET_CAP_MM]
    found: ForceScales | None = None
    for most in range(1, INSET_SCALES + 1):
        for cap in caps:
            fs = force_scales(draw, cap, short=VIEW_SHORT_MM)
            if len(fs.scales) <= most:
                found = fs
                break
        if found is not None:
            break
    cap = INSET_CAP_MM
    while found is None:
        cap *= CAP_STEP
        fs = force_scales(draw, cap, short=VIEW_SHORT_MM)
        found = fs if len(fs.scales) <= INSET_SCALES else None
    scales = (top, *found.scales)
    # too short at every μ_F: named under HIDE_SHARE (and under every reaction), else a
    # direction arrow VIEW_SHORT_MM long
    left = [F for F in below if all(F / sc.k < short for sc in found.scales)]
    hide = min([floor, *(F for F in keep if zero < F)])
    negligible = max((F for F in left if hide > F and F not in given), default=0.0)
    fixed = VIEW_SHORT_MM if any(negligible < F for F in left) else 0.0
    # (``over`` stays 1: each inset μ_F is marked and stated, its arrows may outgrow the
    # view's shortest, and the view's room is taken for the longer arrows in it)
    return ForceScales(scales, zero, negligible, insets=True, limit=negligible / big,
                       short=VIEW_SHORT_MM, least=live[first], fixed=fixed)  # fmt: skip


#: A force's arrow on a free body keeps this far (mm) from the centre lines of what is drawn
#: there (the links, the symbols of their pairs, the hatching, the arrows drawn before it) …
CLEAR_MM = 2.0
#: … and this far from the force arrows drawn before it (two arrows on one line of action, tail
#: to tail, would read as one double-headed arrow); its head this much farther from a line
#: (the head's half width and a gap): no head in a hatch. Near its point of application, within
#: AT_POINT_MM (a joint's circle), it may touch the body.
ARROW_GAP_MM = 4.0
#: A line within this angle of the arrow runs with it; one at a larger angle crosses it, and
#: only its nearest CROSS_MM count.
PARALLEL = math.radians(25.0)
CROSS_MM = 0.6
#: A line that runs with the arrow this near it reads as the arrow drawn along it (review 9:
#: the compressor's Φ3 2 mm under its rod MB), so that much of the arrow costs as on it.
ALONG_MM = 2.5
HEAD_CLEAR_MM = ARROW_HALF_WIDTH + 0.4
AT_POINT_MM = JOINT_R + 0.5
#: The costs of an arrow's place (per mm): of its shaft on a line, of its head on one, of it
#: outside its view's box or within ARROW_GAP_MM of another arrow, of the gap between its
#: point of application and its nearer end; and the cost of the end the caller did not ask for
#: (leaving instead of arriving, or back).
_W_LINE, _W_HEAD, _W_OUT, _W_GAP, _W_END = 1.0, 4.0, 3.0, 0.1, 0.5
#: The cost (per mm) of an arrow outside its view's whole box (:attr:`Clearance.limit`): on
#: another view, or past the sheet's frame, worse than along a link, where it is drawn but
#: hidden (_W_LINE + _W_INK): a load along its own link slid past the link's end stays in the
#: view (a sweep of the force positions: the clipper's F_N at its positions 6 and 9 slid 40 mm
#: past the knife bar's end, over the frame). Outside the arrows' field but in the box (the
#: margin under the caption) costs _W_OUT as before.
_W_BOX = 10.0
#: The cost (per mm) of the arrow across a line (a link outline crossed), and of the thin line
#: of action that ties a moved arrow back to its point where it runs along a line or across
#: one (review 9: Φ1 slid past A, its line of action along the crank OA, read as the arrow
#: drawn along the crank).
_W_CROSS, _W_TIE = 2.0, 1.0
#: … of the thin line of action where it runs along a line (a load along its link, slid past
#: the link's end: its line of action lies under the link's thick line), well under an arrow
#: along one (_W_LINE): a load is drawn on its own line, never on a parallel beside it nor with
#: an elbow (review 14: the walkbeam's F_D 10 mm under its guide)
_W_TIE_ALONG = 0.25
#: An arrow's shaft this near (mm) a line that runs with it lies under that line's ink (a
#: link's main line is up to 1 mm wide): the arrow is not seen there, only its head, and each
#: such mm costs _W_INK more than one along a line (review 14: the crusher's G₂ drawn down its
#: own link, rocking_cylinder_rocker's Φ₁ on its crank, tangent_rocking_slider's F_D on its
#: rod). Sliding it along its line of action past the link's end, its thin line of action
#: under the link, is then cheaper wherever there is room.
INK_MM = 0.6
_W_INK = 3.0
#: How far (mm) an arrow may be moved along its line of action beyond either of its ends
#: (farther, it would no longer read as acting at its point).
SLIDE_MM = 60.0
#: An arrow that runs along a line drawn wherever it slides on its line of action (a load
#: along its link) is drawn this far (mm) beside it, parallel, tied to its point by a thin line;
#: each mm aside costs as much as _W_BESIDE mm of the arrow on a line (half: a short load
#: wholly on its link, review 4's offset_slider_gas Φ1 7 mm up its crank, goes beside it); room
#: for a link's 3.5 mm number between them (the crusher's "5" beside G5 at 3 or 4 mm touched it).
BESIDE_MM = 5.0
_W_BESIDE = 0.5
_STEP = 0.5


def chord_points(it: Polyline | CircleItem | ArcItem) -> list[XY]:
    """A drawn line's points in sheet mm, in order: a polyline's (closed: back to its first), a
    circle's or an arc's as a chord polygon (24 and 16 chords)."""
    if isinstance(it, Polyline):
        return list(it.points) + ([it.points[0]] if it.closed else [])
    if isinstance(it, CircleItem):
        a = np.linspace(0.0, 2.0 * math.pi, 25)
        return [(it.c[0] + it.r * math.cos(t), it.c[1] + it.r * math.sin(t)) for t in a]
    a0 = math.atan2(it.start[1] - it.c[1], it.start[0] - it.c[0])
    a = np.linspace(a0, a0 + it.sweep, 17)
    return [(it.c[0] + it.r * math.cos(t), it.c[1] + it.r * math.sin(t)) for t in a]


@dataclass
class Clearance:
    """Where the force arrows of a free body go: each on its line of action, at its point of
    application (leaving it, or arriving at it) where that is clear, else moved along its line
    of action (a force on a rigid body acts anywhere on its line) until it is: an arrow never
    runs along a link or a guide, nor ends in a hatch.

    Everything drawn on ``sheet`` from item ``start`` on is in the way (the scheme of the body,
    its moments' arcs, the arrows placed before); ``box`` (sheet mm) is the view's, which the
    arrows keep inside where they can.
    """

    sheet: Sheet
    start: int
    box: tuple[float, float, float, float] | None = None
    #: the view's whole box (sheet mm): an arrow outside it is on another view or past the
    #: frame (:data:`_W_BOX` a mm); ``None``: ``box``'s cost alone
    limit: tuple[float, float, float, float] | None = None
    #: The first of the sheet's vectors drawn on this free body (set from ``sheet``).
    first_vector: int = -1

    def __post_init__(self) -> None:
        if self.first_vector < 0:
            self.first_vector = len(self.sheet.vectors)
        # the pieces of the items drawn so far, kept as the drawing grows
        self._segments: tuple[int, npt.NDArray[np.float64]] = (0, np.zeros((0, 2, 2)))

    def segments(self) -> npt.NDArray[np.float64]:
        """The straight pieces (n, 2, 2) in sheet mm of what is drawn from ``start`` on: lines,
        outlines (a filled head's too), circles and arcs as chords."""
        done, known = self._segments
        items = self.sheet.items
        if done == len(items):
            return known
        out: list[tuple[XY, XY]] = []
        for it in items[max(done, self.start) :]:
            if isinstance(it, TextItem) or it.role == "centre":  # an axis: a load may run on it
                continue
            pts = chord_points(it)
            out += [(a_, b_) for a_, b_ in itertools.pairwise(pts) if a_ != b_]
        found = np.concatenate([known, np.array(out, dtype=float).reshape(-1, 2, 2)])
        self._segments = (len(items), found)
        return found

    def solids(self) -> list[npt.NDArray[np.float64]]:
        """The filled shapes (k, 2) drawn from ``start`` on that are not arrowheads: the
        blocks of sliders, which hide what is drawn inside them."""
        return [
            np.array(it.points, dtype=float)
            for it in self.sheet.items[self.start :]
            if isinstance(it, Polyline) and it.fill and it.closed and len(it.points) > 3
        ]

    def place(self, p: XY, u: XY, length: float, arrive: bool) -> tuple[XY, XY]:
        """The (tail, tip) in sheet mm of an arrow ``length`` mm long along the paper unit
        direction ``u`` on the line through ``p``: the cheapest place by the costs above
        (``arrive``: the arrow the caller would draw ends at ``p``)."""
        return self.best(p, u, length, arrive)[1:]

    def beside(self, p: XY, u: XY, length: float, arrive: bool) -> tuple[XY, XY, XY]:
        """:meth:`place`'s arrow, or, where every place on its line of action runs along a
        line drawn (a load along its link: the link hides it), the cheapest one on a parallel
        line :data:`BESIDE_MM` (or twice that) to either side, each mm aside costing
        :data:`_W_BESIDE`: (foot, tail, tip) in sheet mm, the foot the point beside ``p`` its
        line passes (``p`` itself on the line of action; the caller ties it to ``p``)."""
        cost, tail, tip = self.best(p, u, length, arrive)
        out = (p, tail, tip)
        if cost <= _W_BESIDE * BESIDE_MM:
            return out
        for off in (BESIDE_MM, 2.0 * BESIDE_MM):
            for side in (1.0, -1.0):
                q = (p[0] - side * off * u[1], p[1] + side * off * u[0])
                c, t, h = self.best(q, u, length, arrive)
                if c + _W_BESIDE * off < cost:
                    cost, out = c + _W_BESIDE * off, (q, t, h)
        return out

    def best(self, p: XY, u: XY, length: float, arrive: bool) -> tuple[float, XY, XY]:
        """:meth:`place`'s arrow with its cost (0: at its point and clear of everything)."""
        # past its point by up to SLIDE_MM beyond the arrows drawn on its line so far (F_E and
        # Φ₅ of the yarn guide's slider, both along its bar: Φ₅ on before F_E's tail)
        drawn = np.array(self.sheet.vectors[self.first_vector :], dtype=float).reshape(-1, 2, 2)
        drawn = drawn[_near_line(drawn, p, u, mask=True)] if len(drawn) else drawn
        lens = np.linalg.norm(drawn[:, 1] - drawn[:, 0], axis=1) if len(drawn) else [0.0]
        longest = float(np.max(lens))
        reach = SLIDE_MM + min(longest, SLIDE_MM * 2.0)
        lo, hi = -length - reach, length + reach
        ts = np.arange(lo, hi + _STEP / 2.0, _STEP)
        pts = np.column_stack([p[0] + ts * u[0], p[1] + ts * u[1]])
        segs = _near_line(self.segments(), p, u)
        d, along = _distances(pts, segs, u)
        # near a line that runs with the arrow (within PARALLEL), or on one it crosses
        on_along = ((d < ALONG_MM) & along).any(axis=1)
        on_ink = ((d < INK_MM) & along).any(axis=1)
        on_cross = (d < CROSS_MM).any(axis=1) & ~on_along
        # a head clear of every line but those through the point of application (the body
        # the force acts on: the joint there, the links that meet in it)
        body = (
            _distances(np.array([p], dtype=float), segs, u)[0][0] <= AT_POINT_MM
            if len(segs)
            else np.zeros(0, dtype=bool)
        )
        on_head = (d[:, ~body] < CLEAR_MM + HEAD_CLEAR_MM).any(axis=1)
        arrows = np.array(self.sheet.vectors[self.first_vector :], dtype=float).reshape(-1, 2, 2)
        arrows = _near_line(arrows, p, u)
        on_arrow = (_distances(pts, arrows, u)[0] < ARROW_GAP_MM).any(axis=1)
        free = np.abs(ts) <= AT_POINT_MM  # the point of application: the body is there
        # inside a slider's block (its filled outline): the arrow would lie on the body it
        # acts on, not outside it at its point (review 14: F_D through the walkbeam's block)
        solid = _inside(pts, self.solids()) & ~free
        on_along &= ~free
        on_ink &= ~free
        on_cross &= ~free
        on_head &= ~free
        out, far = _outside(pts, self.box), _outside(pts, self.limit)
        cum = {
            k: np.concatenate([[0.0], np.cumsum(a.astype(float))])
            for k, a in (
                ("far", far),
                ("line", on_along),
                ("ink", on_ink),
                ("cross", on_cross),
                ("head", on_head),
                ("out", out),
                ("arrow", on_arrow),
                ("solid", solid),
            )
        }

        def run(key: str, a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]) -> Any:
            i = np.searchsorted(ts, a, "left")
            j = np.searchsorted(ts, b, "right")
            return (cum[key][j] - cum[key][i]) * _STEP

        slide = np.arange(0.0, reach + _STEP, 1.0)
        S = np.array(sorted({0.0, -length, *slide, *(-length - slide)}))
        E = S + length
        # a head inside a filled shape (a slider's block) is hidden under it: its tip and
        # its base outside every one
        ends = np.concatenate([E, E - ARROW_LEN])
        hidden = _inside(np.column_stack([p[0] + ends * u[0], p[1] + ends * u[1]]), self.solids())
        hidden = hidden[: len(E)] | hidden[len(E) :]
        # the thin line of action from the arrow's nearer end back to its point
        t0, t1 = np.where(S > 0.0, 0.0, np.minimum(E, 0.0)), np.where(S > 0.0, S, 0.0)
        cost = (
            _W_HEAD * 2.0 * ARROW_LEN * hidden
            + _W_LINE * run("line", S, E)
            + _W_INK * run("ink", S, E)
            + _W_LINE * run("solid", S, E)
            + _W_CROSS * run("cross", S, E)
            + _W_TIE_ALONG * run("line", t0, t1)
            + _W_TIE * run("cross", t0, t1)
            + _W_HEAD * run("head", E - ARROW_LEN, E)
            + _W_OUT * run("out", S, E)
            + _W_BOX * run("far", S, E)
            + _W_OUT * run("arrow", S, E)
            + _W_GAP * np.minimum(np.abs(S), np.abs(E))
            + _W_END * (((S >= 0.0) & arrive) | ((E <= 0.0) & (not arrive)))
        )
        # the cheapest; of equal ones (within round-off) the first, nearest the far back
        k = int(np.flatnonzero(cost <= cost.min() + tol.DERIVED)[0])
        best = (float(cost[k]), float(S[k]))
        assert best is not None
        s = best[1]
        tail = (p[0] + u[0] * s, p[1] + u[1] * s)
        tip = (p[0] + u[0] * (s + length), p[1] + u[1] * (s + length))
        return best[0], tail, tip


def _outside(pts: npt.NDArray[np.float64], box: tuple[float, float, float, float] | None) -> Any:
    """Which points (m, 2) lie outside ``box`` (sheet mm; none where ``box`` is ``None``)."""
    if box is None:
        return np.zeros(len(pts), dtype=bool)
    x0, y0, x1, y1 = box
    return (pts[:, 0] < x0) | (pts[:, 0] > x1) | (pts[:, 1] < y0) | (pts[:, 1] > y1)


def _inside(pts: npt.NDArray[np.float64], shapes: list[npt.NDArray[np.float64]]) -> Any:
    """Which points (m, 2) lie inside one of the closed ``shapes`` (each (k, 2)), by the
    crossings of a ray from each point."""
    out = np.zeros(len(pts), dtype=bool)
    x, y = pts[:, 0:1], pts[:, 1:2]
    for q in shapes:
        a, b = q, np.roll(q, -1, axis=0)
        up = (a[:, 1] > y) != (b[:, 1] > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            cx = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
        out |= (np.count_nonzero(up & (x < cx), axis=1) % 2) == 1
    return out


def _near_line(segs: npt.NDArray[np.float64], p: XY, u: XY, mask: bool = False) -> Any:
    """The segments (n, 2, 2) that come near the line through ``p`` along ``u``: within the
    largest clearance of it, or across it (the others cost an arrow on it nothing); ``mask``:
    which of them, (n,) booleans."""
    if len(segs) == 0:
        return np.zeros(0, dtype=bool) if mask else segs
    reach = max(CLEAR_MM + HEAD_CLEAR_MM, ARROW_GAP_MM) + _STEP
    side = (segs[..., 0] - p[0]) * u[1] - (segs[..., 1] - p[1]) * u[0]  # (n, 2)
    keep = (np.abs(side).min(axis=1) < reach) | (side[:, 0] * side[:, 1] < 0.0)
    return keep if mask else np.asarray(segs[keep], dtype=np.float64)


def _distances(
    pts: npt.NDArray[np.float64], segs: npt.NDArray[np.float64], u: XY
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """The distance (mm) of each point (m, 2) to each segment (n, 2, 2), (m, n), and which
    segments run within :data:`PARALLEL` of the direction ``u`` (n,)."""
    if len(segs) == 0:
        return np.full((len(pts), 0), np.inf), np.zeros(0, dtype=bool)
    a, ab = segs[:, 0], segs[:, 1] - segs[:, 0]
    n2 = (ab**2).sum(axis=1)
    t = np.clip(((pts[:, None, :] - a[None]) * ab[None]).sum(axis=2) / n2, 0.0, 1.0)
    foot = a[None] + t[..., None] * ab[None]
    d = np.linalg.norm(pts[:, None, :] - foot, axis=2)
    sin = np.abs(ab[:, 0] * u[1] - ab[:, 1] * u[0]) / np.sqrt(n2)
    return d, sin <= math.sin(PARALLEL)


def force(
    v: Viewport,
    at: PointLike,
    F: Vec,
    k_F: float,
    label: str = "",
    arrive: bool = False,
    role: str = "vector",
    height: float = 3.5,
    prefer: tuple[float, float] | None = None,
    clear: Clearance | None = None,
) -> tuple[XY, XY] | None:
    """The force ``F`` (N, model directions) at model point ``at``, |F|/k_F mm long.

    ``arrive`` draws it ending at the point instead of leaving it; ``clear`` (a free body's
    :class:`Clearance`) draws it where its line of action is clear of the drawing instead. The
    label goes at the arrow's end away from the point. Returns the (tail, tip) in sheet mm, or
    ``None`` for a zero force (nothing is drawn then).
    """
    length = F.norm / k_F
    if length <= 0.0:
        return None
    p = v.p(at)
    ux, uy = F.x / F.norm, -F.y / F.norm  # paper direction (y down)
    if clear is not None:
        tail, tip = clear.place(p, (ux, uy), length, arrive)
        line_of_action(v.sheet, p, tail, tip)
    elif arrive:
        tail, tip = (p[0] - ux * length, p[1] - uy * length), p
    else:
        tail, tip = p, (p[0] + ux * length, p[1] + uy * length)
    _arrow(v.sheet, tail, tip, role)
    if label:
        # the end farther from the point of application, the label beyond it
        back = math.dist(tail, p) > math.dist(tip, p)
        end = tail if back else tip
        mid = ((tail[0] + tip[0]) / 2.0, (tail[1] + tip[1]) / 2.0)
        away = (-ux, -uy) if back else (ux, uy)
        room = (end[0] + away[0] * LABEL_ROOM_MM, end[1] + away[1] * LABEL_ROOM_MM)
        box = clear.box if clear is not None else None
        if box is not None and not (box[0] <= room[0] <= box[2] and box[1] <= room[1] <= box[3]):
            # no room beyond the end inside the view (an arrow at its edge): beside its middle
            v.d.label(mid, label, height, prefer=prefer or (-uy, ux), clear=1.0)
        else:
            v.d.label(end, label, height, prefer=prefer or away, clear=1.0, others=(mid,))
    return tail, tip


#: The room (mm) a force's label takes beyond the arrow's end: where that leaves the view's
#: box (an arrow at its edge), the label goes beside the arrow's middle instead.
LABEL_ROOM_MM = 8.0


def line_of_action(
    sheet: Sheet, p: XY, tail: XY, tip: XY, beside: XY | None = None
) -> Polyline | None:
    """An arrow moved along its line of action off its point of application ``p`` (sheet mm)
    carries that line back to ``p`` as a thin solid line (GOST 2.303), from its nearer end:
    the force reads as acting at ``p``. An arrow that reaches ``p`` (within
    :data:`AT_POINT_MM`, a joint's circle) or runs past it draws nothing; returns the line.
    ``beside``: the arrow is drawn on a parallel line beside its line of action (off a link
    that would hide it), through this point across from ``p``: the line runs from its nearer
    end along its own line to there (where it is off it) and across to ``p``."""
    length = math.dist(tail, tip)
    if length <= 0.0:
        return None
    q = p if beside is None else beside
    u = ((tip[0] - tail[0]) / length, (tip[1] - tail[1]) / length)
    s = (q[0] - tail[0]) * u[0] + (q[1] - tail[1]) * u[1]  # q's place along the arrow
    if -AT_POINT_MM <= s <= length + AT_POINT_MM:
        if beside is None:
            return None
        line = Polyline((beside, p), "thin")
        sheet.add(line)
        return line
    end = tail if s < 0.0 else tip
    line = Polyline((end, p) if beside is None else (end, beside, p), "thin")
    sheet.add(line)
    return line


def moment(
    v: Viewport,
    c: PointLike,
    M: float,
    r_mm: float = 7.0,
    label: str = "",
    role: str = "vector",
    start: float = math.radians(-35.0),
    height: float = 3.5,
) -> None:
    """A moment ``M`` (N·m, counter-clockwise positive) about model point ``c``: an arc of radius
    ``r_mm`` from the model angle ``start`` with an arrowhead at its end in the moment's sense.
    A zero moment draws nothing."""
    v.turn(c, M, math.degrees(start), label, r_mm, math.degrees(MOMENT_SWEEP), role, height)


def spring(v: Viewport, a: PointLike, b: PointLike, width_mm: float = 4.0, coils: int = 6) -> None:
    """A spring (GOST 2.770) from model point a to b: short straight ends and a zigzag of
    ``coils`` turns, ``width_mm`` across."""
    pa, pb = v.p(a), v.p(b)
    dx, dy = pb[0] - pa[0], pb[1] - pa[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    lead = min(2.0, 0.15 * length)
    body = length - 2.0 * lead
    pts: list[XY] = [pa, (pa[0] + ux * lead, pa[1] + uy * lead)]
    n = 2 * coils
    for i in range(n):
        t = lead + body * (i + 0.5) / n
        side = width_mm / 2.0 * (1.0 if i % 2 == 0 else -1.0)
        pts.append((pa[0] + ux * t + nx * side, pa[1] + uy * t + ny * side))
    pts += [(pb[0] - ux * lead, pb[1] - uy * lead), pb]
    v.sheet.add(Polyline(tuple(pts), "link"))


def damper(v: Viewport, a: PointLike, b: PointLike, width_mm: float = 5.0) -> None:
    """A viscous damper (dashpot) from model point a (its rod) to b (its cylinder's bottom): an
    open cylinder on b's side and a piston on a rod from a."""
    pa, pb = v.p(a), v.p(b)
    dx, dy = pb[0] - pa[0], pb[1] - pa[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    h = width_mm / 2.0
    cyl = 0.55 * length  # the cylinder's length, from b towards a

    def at(t: float, side: float = 0.0) -> XY:
        return (pa[0] + ux * t + nx * side, pa[1] + uy * t + ny * side)

    mouth = length - cyl
    v.sheet.add(Polyline((at(mouth, h), at(length, h), at(length, -h), at(mouth, -h)), "link"))
    v.sheet.add(Polyline((at(length), pb), "link"))
    piston = mouth + 0.3 * cyl
    v.sheet.add(Polyline((pa, at(piston)), "link"))
    v.sheet.add(Polyline((at(piston, 0.7 * h), at(piston, -0.7 * h)), "link"))


def ground(
    v: Viewport, a: PointLike, b: PointLike, side: tuple[float, float] = (0.0, -1.0)
) -> None:
    """A fixed support from model point a to b, hatched on the model side ``side``."""
    symbols.ground(v.sheet, v.p(a), v.p(b), v.paper_dir(side))


#: A curved arrow (ω1, a moment's arc) keeps this far (mm) from every line and text drawn
#: before it; it is tried at these radii (× the asked one) and at starts this many degrees
#: apart all round its centre, the asked place first (review 9: the compressor's ω1 crossed
#: rod 2 and its head landed on S2).
ARC_CLEAR_MM = 1.0
ARC_RADII = (1.0, 0.8, 1.25, 0.65, 1.5)
ARC_STEP_DEG = 20.0
#: The cost of moving the arc off the asked place: per degree of start, per mm of radius.
_W_ARC_TURN, _W_ARC_R = 0.01, 0.1
#: A mm of the arc on a link, a joint, a hatch or an arrow (roles ARC_HARD) costs this many of
#: it on a text (a letter can still move off it), one on a thin line (the positions' lines of a
#: kinematic sheet, everywhere round the crank) this many.
ARC_HARD = frozenset({"link", "joint", "ground", "vector", "result"})
_W_ARC_LINE, _W_ARC_THIN = 3.0, 0.2
_NO_BOXES, _NO_SEGS = np.zeros((0, 4)), np.zeros((0, 2, 2))


def _text_boxes(items: Iterable[Any]) -> npt.NDArray[np.float64]:
    """The boxes (n, 4: x0, y0, x1, y1, sheet mm) of the upright texts among ``items``."""
    out = [
        (t.at[0], t.at[1] - 1.1 * t.height, t.at[0] + t.width, t.at[1] + 0.35 * t.height)
        for t in items
        if isinstance(t, TextItem) and t.angle == 0.0 and t.text.strip()
    ]
    return np.array(out, dtype=float).reshape(-1, 4)


def arc_hits(
    c: XY, r_mm: float, a0: float, a1: float, segs: npt.NDArray[np.float64],
    boxes: npt.NDArray[np.float64], gap: float = ARC_CLEAR_MM,
) -> float:  # fmt: skip
    """How much (mm) of the arc of radius ``r_mm`` about sheet point ``c`` from model angle
    ``a0`` to ``a1`` (rad, ccw) runs within ``gap`` of the segments (n, 2, 2) or inside the
    text boxes (m, 4) grown by ``gap``."""
    n = max(8, int(abs(a1 - a0) * r_mm / 0.5))
    a = np.linspace(a0, a1, n)
    pts = np.column_stack([c[0] + r_mm * np.cos(a), c[1] - r_mm * np.sin(a)])
    step = abs(a1 - a0) * r_mm / n
    hit = np.zeros(n, dtype=bool)
    if len(segs):
        hit |= (_distances(pts, segs, (1.0, 0.0))[0] < gap).any(axis=1)
    if len(boxes):
        x, y = pts[:, 0:1], pts[:, 1:2]
        hit |= (
            (x > boxes[:, 0] - gap) & (x < boxes[:, 2] + gap)
            & (y > boxes[:, 1] - gap) & (y < boxes[:, 3] + gap)
        ).any(axis=1)  # fmt: skip
    return float(np.count_nonzero(hit) * step)


def clear_turn(
    sheet: Sheet, c: XY, sense: float, start_deg: float, r_mm: float, sweep_deg: float,
    r_range: tuple[float, float] | None = None,
) -> tuple[float, float]:  # fmt: skip
    """The (start_deg, r_mm) of a curved arrow about sheet point ``c`` (see
    :meth:`~geomcad.sheet.drawing.Viewport.turn`) clear of what ``sheet`` holds: the asked
    place where nothing is within :data:`ARC_CLEAR_MM` of it, else the least crossed of the
    radii :data:`ARC_RADII` (within ``r_range`` mm) and starts all round, each step off the
    asked place costing a little (:data:`_W_ARC_TURN`, :data:`_W_ARC_R`)."""
    lo, hi = r_range if r_range is not None else (0.0, math.inf)
    reach = max(ARC_RADII) * r_mm + ARC_CLEAR_MM + 1.0
    near: list[tuple[XY, XY]] = []
    soft: list[tuple[XY, XY]] = []
    for it in sheet.items:
        if isinstance(it, TextItem):
            continue
        pts = chord_points(it)
        xs, ys = [q[0] for q in pts], [q[1] for q in pts]
        if (
            min(xs) > c[0] + reach or max(xs) < c[0] - reach
            or min(ys) > c[1] + reach or max(ys) < c[1] - reach
        ):  # fmt: skip
            continue
        pieces = [(a_, b_) for a_, b_ in itertools.pairwise(pts) if a_ != b_]
        (near if it.role in ARC_HARD else soft).extend(pieces)
    segs = np.array(near, dtype=float).reshape(-1, 2, 2)
    thin = np.array(soft, dtype=float).reshape(-1, 2, 2)
    boxes = _text_boxes(sheet.items)
    if len(boxes):
        boxes = boxes[
            (boxes[:, 2] > c[0] - reach) & (boxes[:, 0] < c[0] + reach)
            & (boxes[:, 3] > c[1] - reach) & (boxes[:, 1] < c[1] + reach)
        ]  # fmt: skip
    s = 1.0 if sense > 0.0 else -1.0
    best: tuple[float, float, float] | None = None
    for k in ARC_RADII:
        r = min(max(k * r_mm, lo), hi)
        for turn in np.arange(0.0, 360.0, ARC_STEP_DEG):
            a0 = math.radians(start_deg + s * turn)
            a1 = a0 + s * math.radians(sweep_deg)
            hits = (
                _W_ARC_LINE * arc_hits(c, r, a0, a1, segs, _NO_BOXES)
                + _W_ARC_THIN * arc_hits(c, r, a0, a1, thin, _NO_BOXES)
                + arc_hits(c, r, a0, a1, _NO_SEGS, boxes)
            )
            cost = hits + _W_ARC_TURN * min(turn, 360.0 - turn) + _W_ARC_R * abs(r - r_mm)
            if best is None or cost < best[0] - tol.DERIVED:
                best = (cost, start_deg + s * float(turn), r)
            if hits == 0.0 and k == 1.0 and turn == 0.0:
                return start_deg, r
    assert best is not None
    return best[1], best[2]
