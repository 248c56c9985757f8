"""A mechanism over one crank turn as an animated SVG: SMIL, no script, one self-contained file.

The input is a :class:`~geomcad.sheet.motion.Frames` (named points per frame, which points the
links join), so any mechanism can be animated: a problem's six-bar, a slotted link, a linkage
file's mechanism.

What the file shows, in paper millimetres at true scale (``width="…mm"``, one user unit = 1 mm):

- left, the mechanism at a GOST 2.302 scale (μ_l and the ratio printed above it): the frame's
  supports, the guides (dash-dot), the traced paths of the named points (thin), and the links,
  joints and slider blocks moving;
- right, when the motion has velocities, the velocity plan turning with it: the pole p, the
  absolute velocities pa, pb … as arrows from the pole and the relative ones (ab …) as thin
  lines, at a rounded factor μ_V.

Every moving coordinate is a SMIL ``<animate>`` with ``calcMode="discrete"``: frame i is held
for 1/N of the period and each frame shows the exact positions (a linear blend between frames
would shorten the links). The static attributes hold frame 0, so a viewer without animation
shows the first position. Numbers have at most three decimals and the output is byte-stable.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence

import numpy as np

from geomcad.render.svg import num
from geomcad.sheet.lang import Words
from geomcad.sheet.motion import Arr, Frames
from geomcad.sheet.scale import Scale, gost_scale_to_fit, nice_factor
from geomcad.sheet.text import FONT_FAMILY, SUB_DROP, metrics, parse, run_size, sup_rise

SVG_NS = "http://www.w3.org/2000/svg"

#: The animation's words (``geomcad/sheet/strings/<lang>/animate.toml``), in the language being
#: drawn.
WORDS = Words("geomcad.sheet", "animate")

#: Seconds per crank turn in the animation (the real turn at ω1 = 10 rad/s takes 0.6 s).
PERIOD_S = 6.0

MARGIN = 10.0
TITLE_H = 16.0  # the title and the scale lines above the fields
MECH_ROOM = (250.0, 170.0)  # the mechanism's field (mm)
PLAN_ROOM = 110.0  # the velocity plan's field: a square (mm)
GAP = 15.0
PAD = 8.0  # room round the mechanism for supports and slider blocks

S = 0.7  # main line (mm)
JOINT_R = 1.2
SLIDER = (8.0, 4.0)
HEAD = (3.0, 1.0)  # arrowhead length and half width (mm)
TEXT_H = 3.5

INK = "#000000"
TRACE = "#1f4e9c"
VECTOR = "#b01c1c"


def _pt(x: float, y: float) -> str:
    return f"{num(x)},{num(y)}"


class _Frame:
    """Model → paper: a viewport at scale k with y flipped once (DESIGN.md rule 7)."""

    def __init__(self, k: Scale, x0: float, y1: float, ox: float, oy: float) -> None:
        self.k, self.x0, self.y1, self.ox, self.oy = k, x0, y1, ox, oy

    def xy(self, x: Arr | float, y: Arr | float) -> tuple[Arr, Arr]:
        return (
            np.asarray(self.ox + (np.asarray(x) - self.x0) / self.k.k, dtype=np.float64),
            np.asarray(self.oy + (self.y1 - np.asarray(y)) / self.k.k, dtype=np.float64),
        )

    def path(self, arr: Arr) -> tuple[Arr, Arr]:
        return self.xy(arr[:, 0], arr[:, 1])


class _Doc:
    def __init__(self, frames: int, period: float) -> None:
        self.frames = frames
        self.dur = f"{num(period)}s"

    def animate(self, el: ET.Element, attr: str, values: Sequence[str]) -> None:
        """Hold ``values[i]`` through frame i, looping forever; the static attribute is frame 0."""
        el.set(attr, values[0])
        a = ET.SubElement(el, "animate")
        a.set("attributeName", attr)
        a.set("calcMode", "discrete")
        a.set("dur", self.dur)
        a.set("repeatCount", "indefinite")
        a.set("values", ";".join(values))

    def coords(self, el: ET.Element, xa: str, ya: str, x: Arr, y: Arr) -> None:
        self.animate(el, xa, [num(v) for v in x])
        self.animate(el, ya, [num(v) for v in y])

    def points(self, el: ET.Element, xs: Sequence[Arr], ys: Sequence[Arr]) -> None:
        """Animate a polyline's or polygon's ``points`` (the same number of vertices per frame)."""
        frames = [
            " ".join(_pt(float(x[i]), float(y[i])) for x, y in zip(xs, ys, strict=True))
            for i in range(self.frames)
        ]
        self.animate(el, "points", frames)


def _group(parent: ET.Element, gid: str, **attrs: str) -> ET.Element:
    g = ET.SubElement(parent, "g", {"id": gid, "fill": "none", "stroke-linecap": "round"})
    g.set("stroke-linejoin", "round")
    for k, v in attrs.items():
        g.set(k.replace("_", "-"), v)
    return g


def _text(
    parent: ET.Element, x: float, y: float, markup: str, height: float = TEXT_H
) -> ET.Element:
    """A label from sheet markup (``μ_l``): a subscript is a smaller ``tspan`` moved down by
    ``dy`` and the next run moved back up (SVG renderers differ on ``baseline-shift``)."""
    fs = metrics().font_size(height)
    el = ET.SubElement(parent, "text", {"x": num(x), "y": num(y), "font-size": num(fs)})
    shift = 0.0
    last: ET.Element | None = None
    for run in parse(markup):
        want = {"base": 0.0, "sub": SUB_DROP * fs, "sup": -sup_rise(fs)}[run.shift]
        if want == shift and last is None and run.shift == "base":
            el.text = run.text
            continue
        span = ET.SubElement(el, "tspan")
        if want != shift:
            span.set("dy", num(want - shift))
            shift = want
        if run.shift != "base":
            span.set("font-size", num(run_size(fs, run.shift)))
        span.text = run.text
        last = span
    return el


def _support(g: ET.Element, x: float, y: float) -> None:
    """A revolute joint on the frame (GOST 2.770): a stand, a ground line and its hatching."""
    d, h = 4.0, 3.0
    ET.SubElement(g, "polyline", {"points": f"{_pt(x - h, y + d)} {_pt(x, y)} {_pt(x + h, y + d)}"})
    ET.SubElement(g, "line", {"x1": num(x - h - 1.5), "y1": num(y + d)})
    g[-1].set("x2", num(x + h + 1.5))
    g[-1].set("y2", num(y + d))
    for i in range(5):
        sx = x - h - 1.5 + i * (2.0 * h + 3.0) / 4.0
        ET.SubElement(
            g, "line", {"x1": num(sx), "y1": num(y + d), "x2": num(sx - 1.5), "y2": num(y + d + 2)}
        )


def _head(tip: tuple[Arr, Arr], tail: tuple[Arr, Arr]) -> tuple[list[Arr], list[Arr]]:
    """An arrowhead's three corners per frame; a vector shorter than its head has none (its
    corners fall on the tip)."""
    tx, ty = tip
    dx, dy = tx - tail[0], ty - tail[1]
    length = np.hypot(dx, dy)
    show = length > HEAD[0]
    ux = np.where(show, dx / np.where(show, length, 1.0), 0.0)
    uy = np.where(show, dy / np.where(show, length, 1.0), 0.0)
    bx, by = tx - ux * HEAD[0], ty - uy * HEAD[0]
    return [tx, bx - uy * HEAD[1], bx + uy * HEAD[1]], [ty, by + ux * HEAD[1], by - ux * HEAD[1]]


def _markup(name: str) -> str:
    """A point's name as label markup: its trailing digits as a subscript (O1 → O_1)."""
    stem = name.rstrip("0123456789")
    return stem if stem == name or not stem else f"{stem}_{{{name[len(stem) :]}}}"


def _plan_name(point: str) -> str:
    return point[:1].lower() + point[1:]


def to_animated_svg(
    motion: Frames,
    period: float = PERIOD_S,
    label: Callable[[Scale], str] | None = None,
    plan_title: str | None = None,
) -> str:
    """The motion as an animated SVG document (UTF-8 text with its XML declaration).

    ``label`` writes a scale factor (default: :meth:`Scale.label` in the language being drawn,
    e.g. "μ_l = 0,005 м/мм"); ``plan_title`` defaults to the language's "velocity plan";
    ``period`` is the seconds per turn. Raises
    :class:`~geomcad.errors.ParameterError` for a mechanism or plan too large for any scale.
    """
    write = label or (lambda s: s.label())
    plan_title = WORDS("vplan") if plan_title is None else plan_title
    n = motion.frames
    doc = _Doc(n, period)
    xmin, ymin, xmax, ymax = motion.extent()
    span_x, span_y = xmax - xmin, ymax - ymin
    k_l = gost_scale_to_fit(span_x, span_y, MECH_ROOM[0], MECH_ROOM[1])
    mech_w, mech_h = k_l.mm(span_x) + 2 * PAD, k_l.mm(span_y) + 2 * PAD
    top = MARGIN + TITLE_H
    mech = _Frame(k_l, xmin, ymax, MARGIN + PAD, top + PAD)

    vmax = max(
        (float(np.hypot(v[:, 0], v[:, 1]).max()) for v in motion.velocities.values()), default=0.0
    )
    has_plan = vmax > 0.0
    width = MARGIN + mech_w + MARGIN
    height = top + mech_h + MARGIN
    k_v: Scale | None = None
    if has_plan:
        k_v = nice_factor(vmax, PLAN_ROOM / 2.0 - 6.0, "v")
        width += GAP + PLAN_ROOM
        height = max(height, top + PLAN_ROOM + MARGIN)

    root = ET.Element(
        "svg",
        {
            "xmlns": SVG_NS,
            "version": "1.1",
            "width": f"{num(width)}mm",
            "height": f"{num(height)}mm",
            "viewBox": f"0 0 {num(width)} {num(height)}",
            "font-family": f"{FONT_FAMILY}, sans-serif",
        },
    )
    ET.SubElement(root, "title").text = motion.title
    ET.SubElement(root, "rect", {"width": "100%", "height": "100%", "fill": "#ffffff"})
    heading = _group(root, "heading", fill=INK, stroke="none")
    _text(heading, MARGIN, MARGIN + 5.0, motion.title, 5.0)
    ratio = k_l.ratio_text()
    scale = WORDS("ratio", ratio=ratio) if ratio else ""
    _text(heading, MARGIN, MARGIN + 12.0, write(k_l) + scale)

    thin = _group(root, "guides", stroke=INK, stroke_width=num(S / 3))
    for (ax, ay), (bx, by) in motion.guides:
        (x1, x2), (y1, y2) = mech.xy(np.array([ax, bx]), np.array([ay, by]))
        line = ET.SubElement(thin, "line", {"x1": num(x1), "y1": num(y1)})
        line.set("x2", num(x2))
        line.set("y2", num(y2))
        line.set("stroke-dasharray", "12 1.5 0.5 1.5")

    paths = _group(root, "paths", stroke=TRACE, stroke_width=num(S / 3))
    for name in motion.traced:
        xs, ys = mech.path(motion.points[name])
        pl = ET.SubElement(paths, "polygon", {"id": f"path-{name}"})
        pl.set("points", " ".join(_pt(float(a), float(b)) for a, b in zip(xs, ys, strict=True)))

    frame = _group(root, "frame", stroke=INK, stroke_width=num(S / 3))
    for name in motion.fixed:
        x, y = mech.path(motion.points[name][:1])
        _support(frame, float(x[0]), float(y[0]))

    links = _group(root, "links", stroke=INK, stroke_width=num(S))
    for name, radii in motion.discs.items():
        x, y = mech.path(motion.points[name])
        for i, r in enumerate(radii):
            c = ET.SubElement(links, "circle", {"id": f"disc-{name}-{i + 1}", "r": num(k_l.mm(r))})
            doc.coords(c, "cx", "cy", x, y)
    for i, chain in enumerate(motion.links):
        tag = "polygon" if i in motion.closed_links else "polyline"
        el = ET.SubElement(links, tag, {"id": "link-" + "".join(chain)})
        xy = [mech.path(motion.points[p]) for p in chain]
        doc.points(el, [a for a, _ in xy], [b for _, b in xy])

    blocks = _group(root, "sliders", stroke=INK, stroke_width=num(S), fill="#ffffff")
    for name, (dx, dy) in motion.sliders.items():
        x, y = mech.path(motion.points[name])
        d = math.hypot(dx, dy)
        ux, uy = dx / d, -dy / d  # paper direction of the guide
        hx, hy = SLIDER[0] / 2.0, SLIDER[1] / 2.0
        corners = [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]
        el = ET.SubElement(blocks, "polygon", {"id": f"slider-{name}"})
        doc.points(
            el,
            [x + a * ux - b * uy for a, b in corners],
            [y + a * uy + b * ux for a, b in corners],
        )

    joints = _group(root, "joints", stroke=INK, stroke_width=num(S / 2), fill="#ffffff")
    labels = _group(root, "labels", fill=INK, stroke="none")
    chained = {p for chain in motion.links for p in chain}
    jointed = chained if motion.joints is None else set(motion.joints)
    named = set(motion.points) if motion.labelled is None else set(motion.labelled)
    for name, arr in motion.points.items():
        x, y = mech.path(arr)
        if name in jointed:
            c = ET.SubElement(joints, "circle", {"id": f"joint-{name}", "r": num(JOINT_R)})
            doc.coords(c, "cx", "cy", x, y)
        if name not in named:
            continue
        t = _text(labels, 0.0, 0.0, _markup(name))
        rise = SLIDER[1] / 2.0 + 1.0 if name in motion.sliders else 1.8
        doc.coords(t, "x", "y", x + 1.8, y - rise)

    if has_plan and k_v is not None:
        _plan(root, doc, motion, k_v, MARGIN + mech_w + GAP, top, write, plan_title)

    ET.indent(root, space="")
    body = ET.tostring(root, encoding="unicode", short_empty_elements=True)
    return '<?xml version="1.0" encoding="utf-8" ?>\n' + body + "\n"


def _plan(
    root: ET.Element,
    doc: _Doc,
    motion: Frames,
    k_v: Scale,
    left: float,
    top: float,
    write: Callable[[Scale], str],
    title: str,
) -> None:
    """The velocity plan beside the mechanism: pole p in the middle of its square field."""
    px, py = left + PLAN_ROOM / 2.0, top + PLAN_ROOM / 2.0 + 4.0
    heading = _group(root, "plan-heading", fill=INK, stroke="none")
    _text(heading, left, top + 3.5, f"{title}, {write(k_v)}")
    tips: dict[str, tuple[Arr, Arr]] = {}
    for name, v in motion.velocities.items():
        tips[name] = (px + v[:, 0] / k_v.k, py - v[:, 1] / k_v.k)
    rel = _group(root, "plan-relative", stroke=INK, stroke_width=num(S / 3))
    for a, b in motion.plan_edges:
        el = ET.SubElement(rel, "line", {"id": f"v-{_plan_name(a)}{_plan_name(b)}"})
        doc.coords(el, "x1", "y1", *tips[a])
        doc.coords(el, "x2", "y2", *tips[b])
    vec = _group(root, "plan-vectors", stroke=VECTOR, stroke_width=num(S / 2), fill=VECTOR)
    pole = (np.full(doc.frames, px), np.full(doc.frames, py))
    for name, tip in tips.items():
        el = ET.SubElement(vec, "line", {"id": f"v-p{_plan_name(name)}"})
        el.set("x1", num(px))
        el.set("y1", num(py))
        doc.coords(el, "x2", "y2", *tip)
        head = ET.SubElement(vec, "polygon", {"stroke": "none"})
        doc.points(head, *_head(tip, pole))
    labels = _group(root, "plan-labels", fill=INK, stroke="none")
    _text(labels, px - 3.0, py + 4.0, "p")
    ET.SubElement(labels, "circle", {"cx": num(px), "cy": num(py), "r": num(0.6)})
    for name, (tx, ty) in tips.items():
        t = _text(labels, 0.0, 0.0, _markup(_plan_name(name)))
        doc.coords(t, "x", "y", tx + 1.5, ty - 1.5)
