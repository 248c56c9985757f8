"""Structural schemes: a :class:`~geomcad.structure.Mechanism` drawn with ESKD kinematic symbols
(GOST 2.770).

Each pair gets its symbol where it sits: a revolute on the frame is a hinge on a hatched support
(turned away from the links it carries), a revolute between moving links a joint circle, a
prismatic pair on the frame a guide hatched on both sides of the sliding axis (with a slider
block when the sliding link is a block), a prismatic pair between moving links a block on the
other link's guide, a higher pair a roller's circle on the other link's profile. Each link is drawn
as its body: by default the lines between its pairs (a closed outline for three or more), or the
polylines the caller gives (a slot, a lid plate). Highlighted links (a substitute link) are drawn
in the result role.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass

from geomcad import tol
from geomcad.geom import PointLike, Vec, vec
from geomcad.sheet import symbols
from geomcad.sheet.drawing import JOINT_R, Viewport
from geomcad.sheet.model import CircleItem, Polyline
from geomcad.sheet.style import MAIN_LINE, STYLES
from geomcad.sheet.symbols import SLIDER_SIZE
from geomcad.structure import Mechanism, Pair

#: Half the length (mm) of a guide drawn for a prismatic pair on the frame.
GUIDE_HALF = 7.0
#: A guide's dash-dot axis runs this far (mm) past its hatched ends (where no travel is drawn).
GUIDE_AXIS_PAST = 4.0


@dataclass(frozen=True)
class Body:
    """A polyline of a link's body, in model coordinates."""

    points: tuple[Vec, ...]
    closed: bool = False

    @staticmethod
    def of(points: Sequence[PointLike], closed: bool = False) -> Body:
        return Body(tuple(vec(q) for q in points), closed)


#: Points closer than this fraction of the scheme's size are drawn as one.
_REL = 1.0 / 4096.0


def _same(a: Vec, b: Vec, size: float) -> bool:
    return a.dist(b) <= size * _REL


def _points(mech: Mechanism, link: str) -> list[Vec]:
    """The distinct points where ``link`` takes part in its pairs."""
    size = mech.size()
    out: list[Vec] = []
    for p in mech.pairs_of(link):
        q = p.at if p.lower else (p.centre_on(link) or p.at)
        if not any(_same(q, o, size) for o in out):
            out.append(q)
    return out


def default_body(mech: Mechanism, link: str) -> list[Body]:
    """The lines between a link's pairs: a segment, or a closed outline around three or more."""
    pts = _points(mech, link)
    if len(pts) < 2:
        return []
    if len(pts) == 2:
        return [Body(tuple(pts))]
    cx = sum(q.x for q in pts) / len(pts)
    cy = sum(q.y for q in pts) / len(pts)
    ring = sorted(pts, key=lambda q: math.atan2(q.y - cy, q.x - cx))
    return [Body(tuple(ring), closed=True)]


def is_block(mech: Mechanism, link: str) -> bool:
    """True when every pair of ``link`` sits at one point (a slider block or a roller)."""
    return len(_points(mech, link)) == 1


def draw_scheme(
    v: Viewport,
    mech: Mechanism,
    bodies: Mapping[str, Sequence[Body]] | None = None,
    highlight: Collection[str] = (),
    pair_labels: Mapping[str, str] | None = None,
    link_labels: Mapping[str, PointLike] | None = None,
    label_height: float = 3.5,
    ghosts: Collection[str] = (),
    supports: Mapping[str, tuple[float, float]] | None = None,
    guides: Mapping[str, PointLike] | None = None,
    travel: Mapping[str, Sequence[PointLike]] | None = None,
    link_space: float = 0.0,
    letter_space: float = 0.0,
    guide_axes: bool = False,
    cut_free: bool = False,
    swept: Sequence[Sequence[PointLike]] = (),
) -> None:
    """Draw ``mech`` in viewport ``v`` (see the module docstring).

    ``bodies`` replaces the default body of the links it names; ``pair_labels`` maps pair names
    to label markup (pairs it omits are not labelled; ``None`` labels every pair by its name, one
    label per point); ``link_labels`` places each link's number at a model point (default: the
    middle of the link's first body line). ``ghosts`` are links left undrawn and unlabelled: the
    links an Assur group hangs on, when the group is drawn on its own; their pairs with the drawn
    links still get their symbols (a joint, a block with a stub of its guide). ``supports`` maps
    a frame hinge's pair name to the model direction its support points in, where the drawing
    needs that side free (default: :func:`_support_direction`'s). ``guides`` maps a prismatic
    pair on the frame to the model point on its axis where its hatched guide is drawn (default:
    the pair's point), for a link that slides on the frame by a rod off its other pairs (a
    yoke). ``travel`` maps a prismatic pair on the frame to the points its slider takes in the
    positions drawn: the guide's axis is drawn as a line over that whole travel and the fixed
    guide hatched along it (GOST 2.770: the frame's guide over the slider's travel). A link
    given a body is drawn as that body, never as a block. ``link_space``: mm the links'
    numbers keep further than usual from other texts (where position numbers stand near them),
    ``letter_space`` the pairs' letters. ``guide_axes``: each guide of the frame without a
    ``travel`` gets its axis, dash-dot (a caller that draws no axis of its own). ``cut_free``:
    ``mech`` is a free body cut from the frame (a cut-out Assur group or the crank of the
    kinetostatics, whose frame's reactions R_0j stand for the frame): a revolute on the frame
    is drawn as its joint only and a prismatic pair on the frame as its block on a dash-dot
    stub of the guide's axis (the direction the reaction is normal to), neither with the
    frame's hatched support or guide. ``swept``: the polylines (model) of the links in the other
    positions drawn: a fixed guide's hatched walls are drawn clear of them and of the links drawn
    here (:func:`guide_walls`).
    """
    bodies = dict(bodies or {})
    size = mech.size()
    role = {lk: ("result" if lk in highlight else "link") for lk in mech.ids}
    drawn: dict[str, list[Body]] = {}
    for lk in mech.ids:
        if lk in ghosts:
            drawn[lk] = []
            continue
        drawn[lk] = list(bodies.get(lk, default_body(mech, lk)))
        for b in drawn[lk]:
            v.polyline(b.points, role[lk], closed=b.closed)
    for p in mech.pairs:
        if not p.lower:
            _higher(v, mech, p, role)
    knots = _knots(mech, drawn, ghosts)  # a knot's carried block drawn last, in its slider
    lines = [tuple(vec(q) for q in pl) for pl in swept]
    lines += [b.points + ((b.points[0],) if b.closed else ()) for bs in drawn.values() for b in bs]
    for p in sorted((p for p in mech.pairs if p.kind == "P"), key=lambda p: p.name in knots):
        at = (guides or {}).get(p.name)
        run = [vec(q) for q in (travel or {}).get(p.name, ())]
        knot = p.name in knots or p.name in knots.values()
        _prismatic(v, mech, p, role, ghosts, drawn, None if at is None else vec(at), run, knot,
                   guide_axes, cut_free, lines)  # fmt: skip
    for p in mech.pairs:
        if p.kind == "R":
            if mech.frame in p.links and not cut_free:
                v.pivot(p.at, (supports or {}).get(p.name) or _support_direction(mech, p, drawn))
            else:
                v.joint(p.at)
    _labels(v, mech, drawn, size, pair_labels, link_labels, label_height, ghosts, link_space,
            letter_space)  # fmt: skip


#: Where a slider on the frame's guide carries, at its own point, a block that slides on a moving
#: link (a knot: review 10's slider_rocker_rpr, block 4 on arm 5 at the slider's pin B ≡ K), the
#: carried block is drawn this size (mm) on its link and the slider round it, large enough to
#: hold it at any turn (:data:`KNOT_SLIDER`), on a guide that wide: neither hides the other.
KNOT_BLOCK = (6.0, 3.5)
#: The knot's slider: the carried block's circumscribed circle with 0.5 mm to spare across the
#: guide, and 3 mm of its ends showing beyond that circle along it.
KNOT_SLIDER = (math.hypot(*KNOT_BLOCK) + 6.0, math.hypot(*KNOT_BLOCK) + 1.0)


def _knots(
    mech: Mechanism, drawn: Mapping[str, Sequence[Body]], ghosts: Collection[str]
) -> dict[str, str]:
    """The knots of ``mech``: each prismatic pair between moving links whose block sits at the
    point of a block sliding on the frame's guide, mapped to that frame pair's name."""
    size = mech.size()

    def block(p: Pair) -> bool:
        return any(is_block(mech, lk) and not drawn.get(lk) and lk not in ghosts
                   for lk in p.links if lk != mech.frame)  # fmt: skip

    slides = [p for p in mech.pairs if p.kind == "P" and mech.frame in p.links and block(p)]
    out: dict[str, str] = {}
    for p in mech.pairs:
        if p.kind == "P" and mech.frame not in p.links and block(p):
            on = next((f for f in slides if _same(f.at, p.at, size)), None)
            if on is not None and not any(lk in ghosts for lk in (*p.links, *on.links)):
                out[p.name] = on.name
    return out


def knots_axis(mech: Mechanism, p: Pair) -> Vec:
    """The axis of the frame's guide whose slider carries the knot's block of pair ``p``."""
    size = mech.size()
    f = next(q for q in mech.pairs if q.kind == "P" and mech.frame in q.links
             and _same(q.at, p.at, size))  # fmt: skip
    assert f.axis is not None
    return f.axis


def _across(v: Viewport, q: Vec, u: Vec, size: tuple[float, float], along: Vec, role: str) -> None:
    """The line of a link through ``q`` along model direction ``u`` drawn across a slider
    block of ``size`` (mm) centred on ``q`` along ``along`` (the block's fill hides it there):
    a strip of the main line's width on the fill's layer, to the block's outline."""
    c, w = Vec(*v.p(q)), Vec(*v.paper_dir(u)).unit()
    a = Vec(*v.paper_dir(along)).unit()
    n = a.perp()
    t = min(
        size[0] / 2.0 / abs(w.dot(a)) if abs(w.dot(a)) > 0.0 else math.inf,
        size[1] / 2.0 / abs(w.dot(n)) if abs(w.dot(n)) > 0.0 else math.inf,
    )
    S = MAIN_LINE.get(v.sheet.format, 0.7)
    half = (STYLES[role].weight - STYLES["joint"].weight) * S / 2.0
    h = w.perp() * half
    strip = (c - w * t + h, c + w * t + h, c + w * t - h, c - w * t - h)
    v.sheet.add(Polyline(tuple((x.x, x.y) for x in strip), "joint", closed=True))


#: A frame hinge's support stands upright (pointing down) unless a link it carries comes
#: closer than this to that direction (rad); then it takes the axis direction farthest from them.
SUPPORT_CLEAR = math.radians(50.0)
#: The axis directions a support may point in (model), the upright one first.
_SUPPORT_AXES = (Vec(0.0, -1.0), Vec(0.0, 1.0), Vec(-1.0, 0.0), Vec(1.0, 0.0))


def _support_direction(
    mech: Mechanism, p: Pair, drawn: Mapping[str, Sequence[Body]] | None = None
) -> tuple[float, float]:
    """The direction (model) of a frame hinge's support: drawn square to the sheet (its hatch
    horizontal or vertical, never skewed with the links), down where the links it carries leave
    :data:`SUPPORT_CLEAR` of room there, else the axis direction farthest from them. The links'
    directions: to their other pairs, and along each line of their ``drawn`` bodies that leaves
    the hinge (a lever's offset arm, square to its slide)."""
    link = p.other(mech.frame)
    dirs = [(q - p.at).unit() for q in _points(mech, link) if (q - p.at).norm > 0.0]
    dirs += body_directions(p.at, (drawn or {}).get(link, ()), mech.size() * _REL)
    return support_direction(dirs)


def body_directions(at: Vec, bodies: Sequence[Body], near: float) -> list[Vec]:
    """The unit directions of the lines of ``bodies`` that leave the point ``at`` (an end of
    theirs within ``near`` of it)."""
    out: list[Vec] = []
    for b in bodies:
        pts = (*b.points, *b.points[: int(b.closed)])
        for a, e in itertools.pairwise(pts):
            for end, other in ((a, e), (e, a)):
                if end.dist(at) <= near and other.dist(end) > near:
                    out.append((other - end).unit())
    return out


def support_direction(dirs: Sequence[Vec]) -> tuple[float, float]:
    """A frame hinge's support direction (model) clear of the unit directions ``dirs`` of the
    lines that leave the hinge (see :func:`_support_direction`)."""
    if not dirs:
        return (0.0, -1.0)

    def clearance(u: Vec) -> float:
        return min(math.acos(max(-1.0, min(1.0, u.dot(d)))) for d in dirs)

    down = _SUPPORT_AXES[0]
    best = down if clearance(down) >= SUPPORT_CLEAR else max(_SUPPORT_AXES, key=clearance)
    return (best.x, best.y)


def _block(
    v: Viewport, q: Vec, along: Vec, role: str, drawn: Mapping[str, Sequence[Body]] | None = None,
    size: tuple[float, float] = SLIDER_SIZE,
) -> None:  # fmt: skip
    """A slider block centred on q along the sliding axis (no joint circle: a joint, where
    there is one, is its own pair); a highlighted block is filled. A line of the ``drawn``
    bodies that ends at q runs on over the block's fill to q (GOST 2.770: a rod jointed to the
    block reaches its joint circle, not the block's edge): a strip of the main line's width
    on the fill's layer, under the joint circle drawn after it."""
    symbols.block(v.sheet, v.p(q), v.paper_dir(along), role, with_joint=False, size=size)
    reach = math.hypot(*size) / 2.0  # mm: the block's half-diagonal
    c = Vec(*v.p(q))
    S = MAIN_LINE.get(v.sheet.format, 0.7)
    half = (STYLES["link"].weight - STYLES["joint"].weight) * S / 2.0
    for bodies in (drawn or {}).values():
        for b in bodies:
            pts = [Vec(*v.p(t)) for t in (*b.points, *b.points[:1])][: len(b.points) + b.closed]
            for a, e in itertools.pairwise(pts):
                for end, other in ((a, e), (e, a)):
                    d = end.dist(other)
                    if end.dist(c) > ROD_AT or d == 0.0:
                        continue
                    u = (other - end) * (1.0 / d)
                    tip, n = c + u * min(reach, d), u.perp() * half
                    strip = (c + n, tip + n, tip - n, c - n)
                    v.sheet.add(Polyline(tuple((w.x, w.y) for w in strip), "joint", closed=True))


#: A body's line ends at a block's centre when its end is within this (mm) of it.
ROD_AT = 0.05


def _prismatic(
    v: Viewport,
    mech: Mechanism,
    p: Pair,
    role: Mapping[str, str],
    ghosts: Collection[str],
    drawn: Mapping[str, Sequence[Body]],
    guide_at: Vec | None = None,
    run: Sequence[Vec] = (),
    knot: bool = False,
    axis: bool = False,
    cut_free: bool = False,
    lines: Sequence[Sequence[Vec]] = (),
) -> None:
    """A prismatic pair's symbol (see the module docstring); ``knot``: the pair is a knot's
    (:data:`KNOT_BLOCK`): the frame's slider drawn round the carried block, on a guide that
    wide, the carried block smaller; ``cut_free``: a pair on the frame is drawn cut free of it
    (its block on a stub of the guide's axis, no hatched guide)."""
    assert p.axis is not None
    u = p.axis
    size = (KNOT_SLIDER if mech.frame in p.links else KNOT_BLOCK) if knot else SLIDER_SIZE

    def block(lk: str) -> bool:  # a link of one point, not given a body of its own
        return is_block(mech, lk) and not drawn.get(lk)

    on_frame = mech.frame in p.links
    if any(lk in ghosts for lk in p.links) or (cut_free and on_frame):
        # a group drawn on its own (or cut from the frame): its block with a stub of the guide
        # it slides on, at the guide's point (a yoke's rod slides off its block's point)
        g = p.at if guide_at is None or not on_frame else guide_at
        k = v.scale.model(GUIDE_HALF * 1.6)
        v.seg(g - u * k, g + u * k, "centre")
        for lk in p.links:
            if lk not in ghosts and lk != mech.frame and block(lk):
                _block(v, p.at, u, role[lk], drawn, size)
        return
    if on_frame:
        k = v.scale.model(GUIDE_HALF)
        g = p.at if guide_at is None else guide_at
        lo, hi = -k, k
        if run:  # the guide's axis over the slider's whole travel, a little past both ends
            # (the travel alone: the guide's point, the first position's, stands at one end
            # of it or, a yoke's, off it; review 13: the press's 18 mm stroke hatched 39 mm)
            ts = [(q - g).dot(u) for q in run]
            lo, hi = min(ts) - k, max(ts) + k
            v.seg(g + u * lo, g + u * hi, "thin")
        elif axis:  # the guide's axis (dash-dot) a little past the hatched guide's ends
            e = v.scale.model(GUIDE_AXIS_PAST)
            v.seg(g + u * (lo - e), g + u * (hi + e), "centre")
        # the fixed guide hatched on both sides over that travel (at least the slider's length),
        # each wall only where no link of any position drawn runs through it
        n = u.perp()
        for side, pieces in guide_walls(v, g, u, lo, hi, size, lines):
            for t0, t1 in pieces:
                a, b = g + u * t0, g + u * t1
                if side > 0.0:
                    v.guide(a, b, (n.x, n.y), size[1])
                else:
                    v.guide(b, a, (-n.x, -n.y), size[1])
        link = p.other(mech.frame)
        if block(link):
            _block(v, p.at, u, role[link], drawn, size)
        return
    for lk in p.links:
        if block(lk):
            if knot:  # the link it slides on runs across the slider's fill to the block
                on = p.other(lk)
                _across(v, p.at, u, KNOT_SLIDER, knots_axis(mech, p), role[on])
            _block(v, p.at, u, role[lk], drawn, size)
            return


#: A guide's wall is hatched only where no link line passes within this (mm) of its hatching.
WALL_CLEAR_MM = 1.5
#: A wall's clear piece shorter than this (mm) is not hatched (a scrap of hatching reads as
#: nothing): the slider's length.
WALL_MIN_MM = SLIDER_SIZE[0]


def _blocked(
    g: Vec, u: Vec, n: Vec, s0: float, s1: float, lines: Sequence[Sequence[Vec]]
) -> list[tuple[float, float]]:
    """The stretches (along ``u`` from ``g``) where a line of ``lines`` passes through the band
    ``s0 <= (q - g)·n <= s1`` beside the axis."""
    out: list[tuple[float, float]] = []
    for pl in lines:
        for a, b in itertools.pairwise(pl):
            sa, sb = (a - g).dot(n), (b - g).dot(n)
            ta, tb = (a - g).dot(u), (b - g).dot(u)
            if abs(sb - sa) <= tol.SHEET_MM:  # the segment along the band
                if s0 <= sa <= s1:
                    out.append((min(ta, tb), max(ta, tb)))
                continue
            k0, k1 = sorted(((s0 - sa) / (sb - sa), (s1 - sa) / (sb - sa)))
            k0, k1 = max(k0, 0.0), min(k1, 1.0)
            if k0 <= k1:
                t0, t1 = ta + (tb - ta) * k0, ta + (tb - ta) * k1
                out.append((min(t0, t1), max(t0, t1)))
    return out


def _clear_pieces(
    lo: float, hi: float, blocked: Sequence[tuple[float, float]], grow: float
) -> list[tuple[float, float]]:
    """[lo, hi] less the ``blocked`` stretches grown by ``grow`` at either end."""
    pieces, at = [], lo
    for b0, b1 in sorted((b0 - grow, b1 + grow) for b0, b1 in blocked):
        if b1 < at:
            continue
        if b0 > at:
            pieces.append((at, min(b0, hi)))
        at = max(at, b1)
        if at >= hi:
            break
    if at < hi:
        pieces.append((at, hi))
    return [(a, b) for a, b in pieces if b > a]


def guide_walls(
    v: Viewport,
    g: Vec,
    u: Vec,
    lo: float,
    hi: float,
    size: tuple[float, float],
    lines: Sequence[Sequence[Vec]],
) -> list[tuple[float, list[tuple[float, float]]]]:
    """The hatched walls of a fixed guide along ``u`` through ``g`` over ``[lo, hi]`` (model):
    ``(side, pieces)``, ``side`` ±1 along ``u.perp()``. GOST 2.770 draws a guide as a line hatched
    on one side or both; review 14: the ellipsograph's bar and its twelve positions ran straight
    through both hatched walls of its ram's and its slide's guides. So each wall is drawn only
    over its stretches clear of every link line (``lines``: the positions drawn, thin or main)
    by :data:`WALL_CLEAR_MM`, none shorter than :data:`WALL_MIN_MM`; a wall crossed anywhere is
    left out altogether where the other one is clear end to end (a guide hatched on the side the
    links do not pass). Where no clear stretch is left, both walls are drawn whole, as before."""
    n = u.perp()
    m = v.scale.model
    off = m(size[1] / 2.0 + 0.6)  # symbols.guide's wall, and its hatching outward
    depth = m(symbols.HATCH_LEN)
    grow, least = m(WALL_CLEAR_MM), m(WALL_MIN_MM)
    walls: list[tuple[float, list[tuple[float, float]], bool]] = []
    for side in (1.0, -1.0):
        s0, s1 = (off - grow, off + depth + grow)
        blocked = _blocked(g, u, n * side, s0, s1, lines)
        pieces = [(a, b) for a, b in _clear_pieces(lo, hi, blocked, grow) if b - a >= least]
        whole = len(pieces) == 1 and pieces[0] == (lo, hi)
        walls.append((side, pieces, whole))
    if not any(pieces for _, pieces, _ in walls):
        return [(1.0, [(lo, hi)]), (-1.0, [(lo, hi)])]
    if any(whole for *_, whole in walls):
        return [(side, pieces) for side, pieces, whole in walls if whole]
    return [(side, pieces) for side, pieces, _ in walls]


def _higher(v: Viewport, mech: Mechanism, p: Pair, role: Mapping[str, str]) -> None:
    for lk in p.links:
        c = p.centre_on(lk)
        if c is not None and c.dist(p.at) > 0.0:
            v.circle(c, c.dist(p.at), role[lk])
    x, y = v.p(p.at)
    v.sheet.add(CircleItem((x, y), 0.5, "point", fill=True))


def _labels(
    v: Viewport,
    mech: Mechanism,
    drawn: Mapping[str, list[Body]],
    size: float,
    pair_labels: Mapping[str, str] | None,
    link_labels: Mapping[str, PointLike] | None,
    height: float,
    ghosts: Collection[str],
    space: float = 0.0,
    letter_space: float = 0.0,
) -> None:
    seen: list[Vec] = []
    for p in mech.pairs:
        text = p.name if pair_labels is None else pair_labels.get(p.name)
        if not text or any(_same(p.at, q, size) for q in seen):
            continue
        seen.append(p.at)
        v.label(p.at, text, height, clear=JOINT_R + 0.5, space=letter_space)
    for lk in mech.ids:
        if lk in ghosts:
            continue
        if link_labels is not None and lk in link_labels:
            at = vec(link_labels[lk])
        elif drawn[lk]:
            b = drawn[lk][0].points
            at = (b[0] + b[1]) * 0.5
        else:
            pts = _points(mech, lk)
            if not pts:
                continue
            at = pts[0]
        v.label(at, lk, height, clear=1.0, space=space)
