"""One self-contained interactive HTML page of a mechanism: turn the crank, watch the plans.

``geomcad build FILE --format html`` writes ``DIR/STEM.html``: no network, no server, one file
of inline SVG, a small script (``page.js``) and the numbers it shows, all computed here by the
library. What the page shows (:class:`Page`):

- the mechanism at the crank angle a slider chooses (play and pause, a speed, the numbered
  positions as stops), the paths of its named points;
- the velocity and the acceleration plans of that angle, each at one factor μ for the whole
  turn (so that their change is seen), their points lettered as on the sheet;
- the output's diagrams (a slider's s, v, a; a rocker's ψ, ω, ε) with a cursor at the angle,
  and a table of the values at that angle;
- the static sheets as tabs, and the title and the data of the file.

The frames are precomputed: a linkage file's over a turn of :func:`frame_count` positions from
position 0 by the sweep kernel (:func:`geomcad.linkage.sweep.sweep`), its plans' points by
:func:`geomcad.linkage.plan_sweep.plan_points` (the recorded plans' own points, held to them by
the tests), its diagrams by the kinematic sheet's own curves. A problem of the seed with a
motion (``Problem.motion``) gets the mechanism and its velocity plan; a problem without one is
refused (:func:`page_of` raises :class:`~geomcad.errors.GeomcadError`).

Every drawn length is in the SVG's user unit = 1 mm at the stated factor (as the animation,
:mod:`geomcad.render.animate`); the page scales it to the screen. The drawings are lettered in
osifont, embedded in the page as a data URL; the page's own text uses the system's sans-serif
font. The same input gives the same bytes.
"""

from __future__ import annotations

import base64
import html
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from importlib import resources
from typing import Any

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import GeomcadError
from geomcad.render.svg import num, to_svg
from geomcad.sheet.lang import Words, current
from geomcad.sheet.motion import Frames
from geomcad.sheet.scale import Scale, fmt_number, gost_scale_to_fit, nice_factor
from geomcad.sheet.text import parse

Arr = npt.NDArray[np.float64]

WORDS = Words("geomcad.sheet", "html")
UNITS = Words("geomcad.sheet", "linkage")

#: Frames of a turn (about one per degree; a multiple of the numbered positions' count).
FRAMES = 360
#: Seconds per crank turn at speed 1 (the real turn is usually far too quick to follow).
PERIOD_S = 6.0
#: The fields (mm): the mechanism, each plan (a square), each diagram.
MECH_ROOM = (250.0, 150.0)
PLAN_ROOM = 80.0
DIAGRAM = (250.0, 52.0)
PAD = 10.0  # room round the mechanism for supports, blocks and labels
TEXT_H = 4.5  # labels on the drawings (mm of the field)


@dataclass(frozen=True)
class PlanFrames:
    """One plan over the frames: its points (name → ``(N, 2)``, plan units from the pole), the
    vectors drawn (tail, head, known), the points at the pole in every frame, its factor."""

    kind: str  # "v" or "a"
    title: str
    points: dict[str, Arr]
    vectors: tuple[tuple[str, str, bool], ...]
    at_pole: tuple[str, ...]
    scale: Scale


@dataclass(frozen=True)
class Series:
    """A quantity over the frames: ``key`` (its name in ``solve --json``, or ""), its label
    markup, unit markup, meaning, and ``values`` ``(N,)``."""

    key: str
    label: str
    unit: str
    meaning: str
    values: Arr


@dataclass(frozen=True)
class Page:
    """Everything the page shows (module docstring): ``motion`` holds the frames' crank angles
    (rad) and the mechanism; ``psi`` each frame's crank turn from position 0 (rad); ``stops``
    (position number, frame index); ``slide`` a slider's guide angle per frame (rad), where it
    turns; ``sheets`` (tab title, SVG); ``data`` (heading, text) blocks of the data tab."""

    title: str
    motion: Frames
    psi: Arr
    stops: tuple[tuple[int, int], ...]
    plans: tuple[PlanFrames, ...] = ()
    diagrams: tuple[Series, ...] = ()
    table: tuple[Series, ...] = ()
    slide: dict[str, Arr] = field(default_factory=dict)
    sheets: tuple[tuple[str, str], ...] = ()
    data: tuple[tuple[str, str], ...] = ()


def frame_count(positions: int) -> int:
    """The frames of a turn: the multiple of ``positions`` nearest :data:`FRAMES`, so that every
    numbered position is a frame."""
    return positions * max(1, round(FRAMES / positions))


# --- the pages of a linkage file and of a problem with a motion ---------------------------------


def page_of(sol: Any, sheets: Sequence[tuple[str, Any]] = (), source: str = "") -> Page:
    """The page of a solution: a linkage file's in full, a problem's with a motion as its
    mechanism and velocity plan. ``sheets`` are its (name, Sheet) pairs for the tabs,
    ``source`` the file's text for the data tab. Raises
    :class:`~geomcad.errors.GeomcadError` for a problem with no crank mechanism to turn."""
    check(sol)
    svgs = tuple(
        (_tab_name(sheet.title) or WORDS("sheet", i=i + 1), to_svg(sheet))
        for i, (_, sheet) in enumerate(sheets)
    )
    data = _data(sol, source)
    from geomcad.linkage.solution import Solved

    if isinstance(sol.data, Solved):
        return linkage_page(sol.data, svgs, data)
    assert sol.problem.motion is not None
    motion = sol.problem.motion(sol, FRAMES)
    return motion_page(motion, svgs, data, f"{sol.problem.id}. {sol.problem.title}")


def check(sol: Any) -> None:
    """Raise :class:`~geomcad.errors.GeomcadError` unless ``sol`` has a crank mechanism to turn
    (a linkage file's, or a problem's ``motion``)."""
    from geomcad.linkage.solution import Solved

    if not isinstance(sol.data, Solved) and sol.problem.motion is None:
        raise GeomcadError(
            "--format html: this problem has no crank mechanism to turn (an html page is made "
            "for linkage files and for the problems that `geomcad animate` takes)"
        )


def _tab_name(title: str) -> str:
    """A sheet's tab: the first sentence of its title ("Кинематический анализ")."""
    return title.split(". ")[0].strip()


def _data(sol: Any, source: str) -> tuple[tuple[str, str], ...]:
    """The data tab: the file's text (or the problem's parameters) and its scalar results."""
    out: list[tuple[str, str]] = []
    if source:
        out.append((WORDS("source"), source))
    else:
        lines = [f"{k} = {v}" for k, v in sol.params.items()]
        out.append((WORDS("params"), "\n".join(lines)))
    scalars = [
        f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
        for k, v in sol.results.items()
        if isinstance(v, int | float | str)
    ]
    if scalars:
        out.append((WORDS("results"), "\n".join(scalars)))
    return tuple(out)


def motion_page(
    motion: Frames,
    sheets: tuple[tuple[str, str], ...] = (),
    data: tuple[tuple[str, str], ...] = (),
    title: str = "",
) -> Page:
    """The page of a problem's motion: the mechanism and, where the motion has velocities, the
    velocity plan (its absolute vectors from the pole and the relative ones of its edges);
    ``title`` defaults to the motion's."""
    n = motion.frames
    sense = 1.0 if motion.omega1 > 0 else -1.0
    psi = (motion.phi - motion.phi[0]) * sense
    plans: list[PlanFrames] = []
    table: list[Series] = [_phi_series(motion.phi)]
    if motion.velocities:
        pts = {"p": np.zeros((n, 2)), **{_low(k): v for k, v in motion.velocities.items()}}
        vectors = [("p", _low(k), False) for k in motion.velocities]
        vectors += [(_low(a), _low(b), False) for a, b in motion.plan_edges]
        plans.append(
            PlanFrames("v", WORDS("vplan"), pts, tuple(vectors), ("p",), _plan_scale(pts, "v"))
        )
        for name, v in motion.velocities.items():
            table.append(
                Series(
                    f"V_{name}",
                    f"V_{{{name}}}",
                    UNITS("m_s"),
                    WORDS("velocity", p=name),
                    np.hypot(v[:, 0], v[:, 1]),
                )
            )
    return Page(title or motion.title, motion, psi, ((0, 0),), tuple(plans), (), tuple(table),
                {}, sheets, data)  # fmt: skip


def _low(name: str) -> str:
    return name[:1].lower() + name[1:]


def _phi_series(phi: Arr) -> Series:
    return Series("phi_deg", "φ_1", "°", WORDS("crank"), np.degrees(phi) % 360.0)


def linkage_page(
    s: Any, sheets: tuple[tuple[str, str], ...] = (), data: tuple[tuple[str, str], ...] = ()
) -> Page:
    """The page of a solved linkage file (:class:`~geomcad.linkage.solution.Solved`)."""
    from geomcad.linkage.model import Linkage
    from geomcad.linkage.plan_sweep import plan_points
    from geomcad.linkage.solution import moving_points
    from geomcad.linkage.sweep import sweep
    from geomcad.sheet.linkage import _output_curves, _turns, file_title
    from geomcad.sheet.linkage import motion as linkage_motion

    lk: Linkage = s.linkage
    # the numbered positions are always solved (linkages.md, second round); `phi` only lists
    # angles of interest, so the stops are the numbered positions
    numbered = s.drawn or s.positions
    n = frame_count(len(numbered))
    motion = linkage_motion(s, n)
    sense = 1.0 if lk.omega > 0 else -1.0
    psi = np.arange(n, dtype=np.float64) * (2.0 * math.pi / n)
    st = sweep(lk, motion.phi, order=2)
    vp, ap = plan_points(lk, st)
    P0 = numbered[0]
    plans = (
        _plan_frames("v", WORDS("vplan"), P0.vp, vp),
        _plan_frames("a", WORDS("aplan"), P0.ap, ap),
    )
    names, s_m, v_m, a_m = _output_curves(s, psi)
    diagrams = tuple(
        Series(f"out_{i}", sym, unit, WORDS(f"out_{i}"), np.asarray(vals, dtype=np.float64))
        for i, ((sym, unit, _), vals) in enumerate(zip(names, (s_m, v_m, a_m), strict=True))
    )
    table: list[Series] = [_phi_series(motion.phi), *diagrams]
    for p in moving_points(lk):
        for key, label, unit, what, arr in (
            (f"V_{p}", f"V_{{{p}}}", UNITS("m_s"), "velocity", st.vel[p]),
            (f"a_{p}", f"a_{{{p}}}", UNITS("m_s2"), "acceleration", st.acc[p]),
        ):
            table.append(Series(key, label, unit, WORDS(what, p=p), np.hypot(arr[:, 0], arr[:, 1])))
    for i in lk.moving_links:
        if i != 1 and _turns(lk, i):
            table.append(Series(f"omega_{i}", f"ω_{{{i}}}", UNITS("per_s"),
                                WORDS("omega", i=i), st.omega[i]))  # fmt: skip
            table.append(Series(f"eps_{i}", f"ε_{{{i}}}", UNITS("per_s2"),
                                WORDS("eps", i=i), st.eps[i]))  # fmt: skip
    table = _once(table)
    stops = []
    for i, P in enumerate(numbered):
        k = round(((P.phi - P0.phi) * sense) % (2.0 * math.pi) / (2.0 * math.pi / n)) % n
        stops.append((i, int(k)))
    slide = {}
    blocks = dict(motion.sliders)
    for g in lk.groups:
        if g.kind in ("RRP", "PRP") and g.guide is not None and not g.guide.fixed:
            d = st.slide[g.links[1]]
            slide[g.joint] = np.arctan2(d[:, 1], d[:, 0])
        elif g.kind == "RPR":  # the block on the slotted link, along its slide
            d = st.slide[g.links[0]]
            slide[g.slider] = np.arctan2(d[:, 1], d[:, 0])
            blocks[g.slider] = (float(d[0, 0]), float(d[0, 1]))
    motion = replace(motion, sliders=blocks)
    title = file_title(lk) or lk.title
    return Page(title, motion, psi, tuple(stops), plans, diagrams, tuple(table), slide,
                sheets, data)  # fmt: skip


def _once(rows: list[Series]) -> list[Series]:
    """The table with each label once: a rocker output's ω and ε are its link's, so the
    output's row keeps its place and takes the link's name in ``solve --json``."""
    first: dict[str, int] = {}
    out: list[Series] = []
    for row in rows:
        j = first.get(row.label)
        if j is None:
            first[row.label] = len(out)
            out.append(row)
        elif out[j].key.startswith("out_"):
            out[j] = replace(out[j], key=row.key)
    return out


def _plan_frames(kind: str, title: str, plan: Any, points: dict[str, Arr]) -> PlanFrames:
    """A recorded plan's vectors and lettering, its points over the frames."""
    pts = {name: points[name] for name in plan.points}
    vectors = tuple((v.tail, v.head, bool(v.known)) for v in plan.vectors)
    at_pole = tuple(dict.fromkeys([plan.pole, *sorted(plan.at_pole)]))
    return PlanFrames(kind, title, pts, vectors, at_pole, _plan_scale(pts, kind))


def _plan_scale(points: dict[str, Arr], kind: str) -> Scale:
    """One factor for the plan over the whole turn: its widest extent fits the field."""
    allp = np.concatenate(list(points.values()))
    span = float(max(np.ptp(allp[:, 0]), np.ptp(allp[:, 1])))
    return nice_factor(max(span, math.ulp(0.0)), PLAN_ROOM - 12.0, "v" if kind == "v" else "a")


# --- the document ---------------------------------------------------------------------------------


def _r(x: float) -> float:
    """A drawn coordinate (mm) to 0.01 mm."""
    v = round(float(x), 2)
    return 0.0 if v == 0.0 else v


def _flat(xs: Arr, ys: Arr) -> list[float]:
    out: list[float] = []
    for x, y in zip(xs.tolist(), ys.tolist(), strict=True):
        out += [_r(x), _r(y)]
    return out


def _sig(x: float, digits: int = 7) -> float:
    """A value for the table: 7 significant figures (the crank angle: 10, as ``solve``)."""
    return float(f"{float(x):.{digits}g}") + 0.0


def _column(s: Series) -> list[float]:
    """A table row's values over the frames: 7 significant figures (the crank angle 10, as
    ``solve`` gives it), the round-off of a zero (at most ``tol.DERIVED`` of the quantity's
    largest value over the turn) as 0, as the sheet's tables write it."""
    if s.key == "phi_deg":
        return [_sig(v, 10) for v in s.values.tolist()]
    zero = tol.DERIVED * float(np.abs(s.values).max())
    return [0.0 if abs(v) <= zero else _sig(v) for v in s.values.tolist()]


def _svg_markup(markup: str) -> str:
    """Label markup as SVG text content: sub- and superscripts as smaller shifted tspans."""
    out: list[str] = []
    shift = 0.0
    for run in parse(markup):
        want = {"base": 0.0, "sub": 0.3, "sup": -0.45}[run.shift]
        text = html.escape(run.text)
        size = "" if run.shift == "base" else ' font-size="70%"'
        if want == shift and not size:
            out.append(f"<tspan>{text}</tspan>" if out else text)
            continue
        out.append(f'<tspan dy="{num(want - shift)}em"{size}>{text}</tspan>')
        shift = want
    if shift:
        out.append(f'<tspan dy="{num(-shift)}em"></tspan>')
    return "".join(out)


def _html_markup(markup: str) -> str:
    """Label markup as HTML: ``V_{B}`` → V<sub>B</sub>."""
    out = []
    for run in parse(markup):
        text = html.escape(run.text)
        out.append(
            {"base": text, "sub": f"<sub>{text}</sub>", "sup": f"<sup>{text}</sup>"}[run.shift]
        )
    return "".join(out)


def _point_markup(name: str) -> str:
    """A mechanism point's name: its trailing digits as a subscript (O1 → O_1)."""
    stem = name.rstrip("0123456789")
    return stem if stem == name or not stem else f"{stem}_{{{name[len(stem) :]}}}"


def _mech(page: Page) -> tuple[str, str, dict[str, Any]]:
    """The mechanism's field: its caption (HTML), its static SVG and the moving points'
    data."""
    m = page.motion
    xmin, ymin, xmax, ymax = m.extent()
    k = gost_scale_to_fit(xmax - xmin, ymax - ymin, *MECH_ROOM)
    w, h = k.mm(xmax - xmin) + 2 * PAD, k.mm(ymax - ymin) + 2 * PAD

    def xy(arr: Arr) -> tuple[Arr, Arr]:
        return PAD + (arr[:, 0] - xmin) / k.k, PAD + (ymax - arr[:, 1]) / k.k

    pts = {name: _flat(*xy(arr)) for name, arr in m.points.items()}
    caption = f"{html.escape(WORDS('mech'))}, {_html_markup(k.label())}{html.escape(_ratio(k))}"
    parts: list[str] = []
    for (ax, ay), (bx, by) in m.guides:
        (x1, x2), (y1, y2) = xy(np.array([[ax, ay], [bx, by]]))
        parts.append(f'<line class="guide" x1="{num(x1)}" y1="{num(y1)}" x2="{num(x2)}" '
                     f'y2="{num(y2)}"/>')  # fmt: skip
    for name in m.traced:
        xs, ys = xy(m.points[name])
        line = " ".join(f"{num(a)},{num(b)}" for a, b in zip(xs.tolist(), ys.tolist(), strict=True))
        parts.append(f'<polygon class="path" points="{line}"/>')
    for name in m.fixed:
        xs, ys = xy(m.points[name][:1])
        x, y = float(xs[0]), float(ys[0])
        hatch = "".join(f"M{num(x - 5 + 2.5 * i)},{num(y + 4)}l-2,2.5" for i in range(5))
        parts.append(f'<path class="support" d="M{num(x - 3)},{num(y + 4)}L{num(x)},{num(y)}'
                     f'L{num(x + 3)},{num(y + 4)}M{num(x - 5)},{num(y + 4)}H{num(x + 5)}'
                     f'{hatch}"/>')  # fmt: skip
    links = []
    for i, chain in enumerate(m.links):
        tag = "polygon" if i in m.closed_links else "polyline"
        parts.append(f'<{tag} class="link" id="m-link-{i}"/>')
        links.append(list(chain))
    sliders = {}
    for name, (dx, dy) in m.sliders.items():
        parts.append(f'<rect class="block" id="m-slider-{html.escape(name)}" x="-5" y="-2.75" '
                     f'width="10" height="5.5"/>')  # fmt: skip
        ang = page.slide.get(name)
        deg = (
            np.degrees(ang)
            if ang is not None
            else np.full(m.frames, math.degrees(math.atan2(dy, dx)))
        )
        sliders[name] = [round(float(a), 2) for a in deg]
    chained = {p for chain in m.links for p in chain}
    jointed = chained if m.joints is None else set(m.joints)
    named = list(m.points) if m.labelled is None else list(m.labelled)
    joints = [p for p in m.points if p in jointed]
    for p in joints:
        parts.append(f'<circle class="joint" id="m-j-{html.escape(p)}" r="1.3"/>')
    for p in named:
        parts.append(f'<text class="label" id="m-l-{html.escape(p)}">'
                     f"{_svg_markup(_point_markup(p))}</text>")  # fmt: skip
    svg = (f'<svg id="mech" viewBox="0 0 {num(w)} {num(h)}" data-k="{k.k!r}" role="img" '
           f'aria-label="{html.escape(WORDS("mech"))}">' + "".join(parts) + "</svg>")  # fmt: skip
    return caption, svg, {"points": pts, "links": links, "closed": list(m.closed_links),
                 "sliders": sliders, "joints": joints, "labels": named}  # fmt: skip


def _ratio(k: Scale) -> str:
    r = k.ratio_text()
    return Words("geomcad.sheet", "animate")("ratio", ratio=r) if r else ""


def _plan(i: int, plan: PlanFrames) -> tuple[str, str, dict[str, Any]]:
    """A plan's field: its title with μ (HTML), its SVG and the points' data (the pole in the
    middle of the turn's extent)."""
    allp = np.concatenate(list(plan.points.values()))
    cx = (float(allp[:, 0].min()) + float(allp[:, 0].max())) / 2.0
    cy = (float(allp[:, 1].min()) + float(allp[:, 1].max())) / 2.0
    k = plan.scale.k
    ox, oy = PLAN_ROOM / 2.0 - cx / k, PLAN_ROOM / 2.0 + cy / k
    from geomcad.sheet.plans import markup_of

    pts = {}
    for name, arr in plan.points.items():
        if name not in plan.at_pole:
            pts[name] = _flat(ox + arr[:, 0] / k, oy - arr[:, 1] / k)
    pole = [_r(ox), _r(oy)]
    caption = f"{html.escape(plan.title)}, {_html_markup(plan.scale.label())}"
    parts: list[str] = []
    for j, (_, _, known) in enumerate(plan.vectors):
        cls = "vec known" if known else "vec"
        parts.append(f'<g class="{cls}" id="p{i}-v{j}"><line/><polygon/></g>')
    pole_label = ", ".join(markup_of(n) for n in plan.at_pole)
    parts.append(f'<circle class="dot" cx="{num(pole[0])}" cy="{num(pole[1])}" r="0.8"/>')
    parts.append(f'<text class="label" x="{num(pole[0] - 2)}" y="{num(pole[1] + 6)}">'
                 f"{_svg_markup(pole_label)}</text>")  # fmt: skip
    for name in pts:
        parts.append(f'<circle class="dot" id="p{i}-d-{html.escape(name)}" r="0.8"/>')
        parts.append(f'<text class="label" id="p{i}-l-{html.escape(name)}">'
                     f"{_svg_markup(markup_of(name))}</text>")  # fmt: skip
    h = PLAN_ROOM
    svg = (f'<svg id="plan{i}" class="plan" viewBox="0 0 {num(PLAN_ROOM)} {num(h)}" '
           f'data-k="{k!r}" data-pole="{num(pole[0])} {num(pole[1])}" role="img" '
           f'aria-label="{html.escape(plan.title)}">' + "".join(parts) + "</svg>")  # fmt: skip
    vectors = [[t, hd] for t, hd, _ in plan.vectors]
    return caption, svg, {"points": pts, "pole": pole, "vectors": vectors}


def _diagram(i: int, d: Series, psi_deg: Arr, stops: Sequence[tuple[int, int]]) -> tuple[str, Any]:
    """A diagram's field: the curve over the turn, the φ axis with the numbered positions, the
    cursor's line and dot (moved by the script), and the curve's points per frame."""
    w, h = DIAGRAM
    left, top, bottom = 24.0, 4.0, 9.0
    y0, y1 = float(d.values.min()), float(d.values.max())
    if y1 - y0 <= tol.REL_LENGTH * max(abs(y0), abs(y1), 1.0):
        y0, y1 = y0 - 1.0, y1 + 1.0
    pad = 0.06 * (y1 - y0)
    y0, y1 = y0 - pad, y1 + pad
    xs = left + psi_deg / 360.0 * (w - left - 4.0)
    ys = top + (y1 - d.values) / (y1 - y0) * (h - top - bottom)
    line = " ".join(f"{num(a)},{num(b)}" for a, b in zip(xs.tolist(), ys.tolist(), strict=True))
    base = top + y1 / (y1 - y0) * (h - top - bottom) if y0 < 0.0 < y1 else h - bottom
    parts = [
        f'<line class="axis" x1="{num(left)}" y1="{num(base)}" x2="{num(w - 2)}" '
        f'y2="{num(base)}"/>',
        f'<line class="axis" x1="{num(left)}" y1="{num(top)}" x2="{num(left)}" '
        f'y2="{num(h - bottom)}"/>',
    ]
    if len(stops) < 6:  # few positions (a file's list of angles): a light tick each 30°
        for deg in range(30, 360, 30):
            x = left + deg / 360.0 * (w - left - 4.0)
            parts.append(f'<line class="tick" x1="{num(x)}" y1="{num(h - bottom)}" '
                         f'x2="{num(x)}" y2="{num(top)}"/>')  # fmt: skip
    for no, k in stops:
        x = float(xs[k])
        parts.append(f'<line class="tick" x1="{num(x)}" y1="{num(h - bottom)}" x2="{num(x)}" '
                     f'y2="{num(top)}"/>')  # fmt: skip
        parts.append(f'<text class="small" x="{num(x - 1)}" y="{num(h - 3)}">{no}</text>')
    lang = current()
    for val, y in ((y1 - pad, top + pad / (y1 - y0) * (h - top - bottom)),
                   (y0 + pad, h - bottom - pad / (y1 - y0) * (h - top - bottom))):  # fmt: skip
        parts.append(f'<text class="small" x="1" y="{num(y + 1.5)}">'
                     f"{html.escape(fmt_number(val, lang, digits=3))}</text>")  # fmt: skip
    parts.append(f'<polyline class="curve" points="{line}"/>')
    parts.append(f'<text class="label" x="{num(left + 2)}" y="{num(top + 4)}">'
                 f"{_svg_markup(d.label)}, {_svg_markup(d.unit)}</text>")  # fmt: skip
    parts.append(f'<line class="cursor" id="d{i}-c" y1="{num(top)}" y2="{num(h - bottom)}"/>')
    parts.append(f'<circle class="cursor-dot" id="d{i}-d" r="1.2"/>')
    svg = (f'<svg class="diagram" viewBox="0 0 {num(w)} {num(h)}" role="img" '
           f'aria-label="{html.escape(d.meaning)}">' + "".join(parts) + "</svg>")  # fmt: skip
    return svg, _flat(xs, ys)


def _asset(name: str) -> str:
    return resources.files("geomcad.render").joinpath(name).read_text(encoding="utf-8")


def _font() -> str:
    data = resources.files("geomcad.fonts").joinpath("osifont.ttf").read_bytes()
    return base64.b64encode(data).decode("ascii")


def to_html(page: Page) -> str:
    """The page as one HTML document (UTF-8 text), in the language being drawn."""
    lang = current()
    mech_caption, mech_svg, mech = _mech(page)
    plan_figures, plans = [], []
    for i, plan in enumerate(page.plans):
        caption, svg, data = _plan(i, plan)
        plan_figures.append(f"<figure><figcaption>{caption}</figcaption>{svg}</figure>")
        plans.append(data)
    psi_deg = np.degrees(page.psi)
    diag_svgs, diags = [], []
    for i, d in enumerate(page.diagrams):
        svg, data = _diagram(i, d, psi_deg, page.stops)
        diag_svgs.append(svg)
        diags.append(data)
    diagrams_caption = (
        f"<figcaption>{html.escape(WORDS('diagrams'))}; {html.escape(WORDS('diagrams_x'))}"
        "</figcaption>"
        if page.diagrams
        else ""
    )
    n = page.motion.frames
    table = [{"key": s.key, "values": _column(s)} for s in page.table]
    frames = {
        "n": n,
        "lang": lang,
        "period": PERIOD_S,
        "phi": [_sig(v, 10) for v in np.degrees(page.motion.phi) % 360.0],
        "stops": [list(s) for s in page.stops],
        "mech": mech,
        "plans": plans,
        "diagrams": diags,
        "table": table,
        "words": {"play": WORDS("play"), "pause": WORDS("pause")},
    }
    rows = "".join(
        f'<tr data-key="{html.escape(s.key)}" title="{html.escape(s.meaning)}">'
        f'<th>{_html_markup(s.label)}</th><td class="num" id="t-{j}"></td>'
        f"<td>{_html_markup(s.unit)}</td></tr>"
        for j, s in enumerate(page.table)
    )
    deg = np.degrees(page.motion.phi) % 360.0
    stops = "".join(
        f'<button type="button" class="stop" data-frame="{k}" '
        f'title="φ₁ = {html.escape(fmt_number(float(deg[k]), lang, 4))}°">{no}</button>'
        for no, k in page.stops
    )
    tabs = [("motion", WORDS("tab_motion"))]
    tabs += [(f"sheet{i}", name) for i, (name, _) in enumerate(page.sheets)]
    tabs.append(("data", WORDS("tab_data")))
    tab_buttons = "".join(
        f'<button type="button" role="tab" id="tab-{t}" aria-controls="panel-{t}" '
        f'aria-selected="{"true" if i == 0 else "false"}">{_html_markup(title)}</button>'
        for i, (t, title) in enumerate(tabs)
    )
    sheet_panels = "".join(
        f'<section class="panel sheet" role="tabpanel" id="panel-sheet{i}" hidden>'
        f"{_inline_svg(svg)}</section>"
        for i, (_, svg) in enumerate(page.sheets)
    )
    data_blocks = "".join(
        f"<h2>{html.escape(head)}</h2><pre>{html.escape(text)}</pre>" for head, text in page.data
    )
    speeds = "".join(
        f'<option value="{f}"{" selected" if f == 1 else ""}>'
        f"{html.escape(WORDS('turn', s=fmt_number(PERIOD_S / f, lang)))}</option>"
        for f in (0.25, 0.5, 1, 2, 4)
    )
    css = _asset("page.css").replace("@FONT@", _font())
    script = _asset("page.js")
    payload = json.dumps(frames, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    payload = payload.replace("</", "<\\/")
    title = html.escape(page.title)
    return f"""<!DOCTYPE html>
<html lang="{lang}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="geomcad">
<title>{title}</title>
<style>{css}</style>
</head>
<body>
<header><h1>{title}</h1>
<nav role="tablist">{tab_buttons}</nav></header>
<main>
<section class="panel" role="tabpanel" id="panel-motion">
<div class="controls">
<button type="button" id="play" aria-pressed="false">{html.escape(WORDS("play"))}</button>
<label class="angle"><span>{html.escape(WORDS("angle"))} \
φ<sub>1</sub>&nbsp;=&nbsp;<output id="phi"></output>°</span>
<input type="range" id="frame" min="0" max="{n - 1}" step="1" value="0"
 aria-label="{html.escape(WORDS("angle"))}"></label>
<label>{html.escape(WORDS("speed"))} <select id="speed">{speeds}</select></label>
<span class="stops" role="group" aria-label="{html.escape(WORDS("stops"))}">\
{html.escape(WORDS("stops"))}: {stops}</span>
</div>
<div class="grid">
<figure class="mech"><figcaption>{mech_caption}</figcaption>{mech_svg}</figure>
<div class="plans">{"".join(plan_figures)}</div>
<figure class="diagrams">{diagrams_caption}{"".join(diag_svgs)}</figure>
<table id="values"><caption>{html.escape(WORDS("values"))}</caption>
<thead><tr><th>{html.escape(WORDS("quantity"))}</th><th>{html.escape(WORDS("value"))}</th>\
<th>{html.escape(WORDS("unit"))}</th></tr></thead><tbody>{rows}</tbody></table>
</div>
<p class="note">{html.escape(WORDS("keys"))}</p>
<p class="note">{html.escape(WORDS("font"))}</p>
</section>
{sheet_panels}
<section class="panel" role="tabpanel" id="panel-data" hidden>{data_blocks}</section>
</main>
<script type="application/json" id="frames">{payload}</script>
<script>{script}</script>
</body>
</html>
"""


def _inline_svg(svg: str) -> str:
    """A sheet's SVG document as an element of the page (its XML declaration dropped)."""
    if svg.startswith("<?xml"):
        svg = svg[svg.index("?>") + 2 :].lstrip()
    return svg
