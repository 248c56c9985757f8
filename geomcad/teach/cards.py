"""The sheets of a set of variants: an A4 task card per variant and the answer-key table.

A task card (A4 portrait, frame and title block form 1) says what a student gets, in one
language: the variant's number, the student's name and group (a roster's), the problem's title,
a scheme of the mechanism with its letters (a linkage file's in its first position at a GOST
scale; a problem id's from its ``motion`` at its defaults, not to scale), the given data as named
quantities with symbols, values and units, and what to find in words
(:mod:`geomcad.teach.quantities`). The title block carries the course (organisation field), the
variant in the designation, the student as "Drawn" with the group, and the teacher as "Checked".
No answer, file key, seed or solver check is on the card.

The answer-key sheet is a ruled table: one row per variant, one column per key result, values to
four significant figures; columns that do not fit an A3 sheet go on to further sheets.
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from geomcad.errors import GeomcadError
from geomcad.sheet import Scale, ScaleStyle, Sheet, TitleBlock, gost_scale_to_fit, start
from geomcad.sheet.drawing import Drawing
from geomcad.sheet.frame import fill_title_blocks
from geomcad.sheet.lang import Lang
from geomcad.sheet.scale import WORDS as SCALE_WORDS
from geomcad.sheet.text import box, parse
from geomcad.teach import quantities

if TYPE_CHECKING:
    from geomcad.problem import Problem, Solution

#: Paper layout of an A4 card (mm): the field inside the frame above the title block.
LEFT, RIGHT, TOP, BOTTOM = 20.0, 205.0, 5.0, 237.0
PAD = 4.0
ROW_H = 5.0
TEXT_H = 2.5
#: The largest room the scheme takes on a card (mm).
SCHEME_W, SCHEME_H = RIGHT - LEFT - 2 * PAD, 75.0

UNIT_TEXT = {"1": "", "": "", "deg": "°"}


def _title(problem: Problem[Any], lang: Lang) -> str:
    """A problem's title in the cards' language (its package's ``titles`` table)."""
    from geomcad.registry import title

    return title(problem, lang)


@dataclass(frozen=True)
class CardInfo:
    """Who and what the title blocks name, and the language of the cards' own words."""

    course: str = "TMM"
    teacher: str = ""
    lang: Lang = "en"
    student: str = ""
    group: str = ""


#: The cards' own words per language (a problem's parameter and result texts are its own).
WORDS: dict[str, dict[str, str]] = {
    "en": {
        "variant": "Variant",
        "given": "Given:",
        "find": "Find:",
        "quantity": "Quantity",
        "symbol": "Symbol",
        "value": "Value",
        "unit": "Unit",
        "keycol": "Key",
        "at": "at",
        "each": "in each of the {n} numbered positions",
        "items": "items",
        "rest": "... and the rest of the answer key's results",
        "key": "Answer key",
        "answers": "answers",
        "no": "No.",
        "pos": "pos.",
        "student": "Student",
        "scheme": "Scheme of the mechanism (not to scale)",
        "group": "group",
    },
    "ru": {
        "variant": "Вариант",
        "given": "Дано:",
        "find": "Определить:",
        "quantity": "Величина",
        "symbol": "Обозн.",
        "value": "Значение",
        "unit": "Ед.",
        "keycol": "Ключ",
        "at": "при",
        "each": "в каждом из {n} положений",
        "items": "элементы",
        "rest": "... и остальные величины ключа ответов",
        "key": "Ключ ответов",
        "answers": "ответы",
        "no": "№",
        "pos": "пол.",
        "student": "Студент",
        "scheme": "Схема механизма (без масштаба)",
        "group": "группа",
    },
}


def _unit(u: str) -> str:
    return UNIT_TEXT.get(u, u)


def _value(v: object) -> str:
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, int | float):
        return format(v, ".10g")
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return str(v)


def _esc(text: str) -> str:
    """Plain text as label markup (underscores and carets stay themselves)."""
    return text.replace("\\", "\\\\").replace("_", "\\_").replace("^", "\\^")


def _fit(text: str, width: float, height: float = TEXT_H, markup: bool = False) -> str:
    """The text cut with an ellipsis to fit ``width`` mm (markup only at spaces: its braces
    hold none)."""
    if markup:
        if box(parse(text), height)[0] <= width:
            return text
        words = _words(text)
        while len(words) > 1 and box(parse(" ".join(words) + "..."), height)[0] > width:
            words.pop()
        return " ".join(words) + "..."
    if box(parse(_esc(text)), height)[0] <= width:
        return text
    while text and box(parse(_esc(text + "...")), height)[0] > width:
        text = text[:-1]
    return text.rstrip() + "..."


def _words(markup: str) -> list[str]:
    """Markup split at its spaces, never inside braces (``r_{0 min}`` stays one word)."""
    out, depth, word = [], 0, ""
    for ch in markup:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        if ch == " " and depth == 0:
            out.append(word)
            word = ""
        else:
            word += ch
    return [*out, word]


def _wrap(text: str, width: float, height: float = TEXT_H, markup: bool = False) -> list[str]:
    lines: list[list[str]] = [[]]
    for word in _words(text) if markup else text.split(" "):
        trial = " ".join([*lines[-1], word])
        if lines[-1] and box(parse(trial if markup else _esc(trial)), height)[0] > width:
            lines.append([])
        lines[-1].append(word)
    return [" ".join(w) for w in lines]


def _table(
    d: Drawing,
    x: float,
    y: float,
    widths: Sequence[float],
    rows: Sequence[Sequence[str]],
    markup: bool = False,
) -> float:
    """A ruled table of plain text (cut to fit its cells), or of label markup (not cut);
    returns the y below it."""
    cut = [
        [
            (_fit(cell, w - 2.0, markup=True) if markup else _esc(_fit(cell, w - 2.0)))
            if cell
            else ""
            for w, cell in zip(widths, row, strict=True)
        ]
        for row in rows
    ]
    _, height = d.table(x, y, widths, cut, TEXT_H, ROW_H)
    return y + height


def _col_widths(
    rows: Sequence[Sequence[str]], room: float, flex: int, markup: bool = False
) -> list[float]:
    """Column widths that fit each column's text; column ``flex`` takes what room is left."""
    n = len(rows[0])
    natural = [
        max(box(parse(r[i] if markup else _esc(r[i])), TEXT_H)[0] for r in rows) + 2.5
        for i in range(n)
    ]
    fixed = sum(w for i, w in enumerate(natural) if i != flex)
    natural[flex] = max(20.0, min(natural[flex], room - fixed))
    if sum(natural) > room:  # still too wide: the widest column gives in, its cells cut to fit
        i = max(range(n), key=natural.__getitem__)
        natural[i] = max(12.0, room - (sum(natural) - natural[i]))
    return natural


# --- the linkage scheme -----------------------------------------------------------------------


def _point(
    position: Mapping[str, Any], frame: Mapping[str, Any], name: object
) -> tuple[float, float] | None:
    n = str(name)
    x, y = position.get(f"x_{n}"), position.get(f"y_{n}")
    if isinstance(x, int | float) and isinstance(y, int | float):
        return (float(x), float(y))
    p = frame.get(n)
    if isinstance(p, list | tuple) and len(p) == 2:
        return (float(p[0]), float(p[1]))
    return None


def _scheme_points(
    data: Mapping[str, Any], position: Mapping[str, Any]
) -> dict[str, tuple[float, float]]:
    """Every frame point, joint and named point of the file in one solved position."""
    frame = data.get("frame", {}) if isinstance(data.get("frame"), Mapping) else {}
    drive = data.get("drive", {}) if isinstance(data.get("drive"), Mapping) else {}
    groups = [g for g in data.get("group", []) if isinstance(g, Mapping)]
    names: list[str] = [str(k) for k in frame]
    names += [str(drive.get("joint", ""))]
    for g in groups:
        for field in ("joint", "slider", "point"):
            if field in g:
                names.append(str(g[field]))
    for p in data.get("point", []) or []:
        if isinstance(p, Mapping) and "name" in p:
            names.append(str(p["name"]))
    return {n: q for n in dict.fromkeys(names) if n and (q := _point(position, frame, n))}


def _extent(pts: Mapping[str, tuple[float, float]]) -> tuple[float, float, float, float, float]:
    xs = [q[0] for q in pts.values()]
    ys = [q[1] for q in pts.values()]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    return min(xs), min(ys), w, h, 0.15 * (max(w, h) or 1.0)


def scheme_scale(data: Mapping[str, Any], position: Mapping[str, Any]) -> Scale | None:
    """The GOST scale the card draws the mechanism at (``None``: nothing to draw)."""
    pts = _scheme_points(data, position)
    if len(pts) < 2:
        return None
    _, _, w, h, pad = _extent(pts)
    return gost_scale_to_fit(w + 2 * pad, h + 2 * pad, SCHEME_W, SCHEME_H - 8.0)


def linkage_scheme(d: Drawing, data: Mapping[str, Any], position: Mapping[str, Any],
                   top: float, lang: Lang = "en") -> float:  # fmt: skip
    """The mechanism in one solved position at a GOST scale, from ``top``; returns the y below.

    Links are straight lines between their joints, frame pivots hatched, sliders as blocks on
    their guides; every joint and named point is labelled.
    """
    frame = data.get("frame", {}) if isinstance(data.get("frame"), Mapping) else {}
    drive = data.get("drive", {}) if isinstance(data.get("drive"), Mapping) else {}
    groups = [g for g in data.get("group", []) if isinstance(g, Mapping)]
    pts = _scheme_points(data, position)
    k = scheme_scale(data, position)
    if k is None:
        return top
    x_min, y_min, w, h, pad = _extent(pts)
    height = min(SCHEME_H, (h + 2 * pad) / k.k + 8.0)
    centre = (x_min + w / 2, y_min + h / 2)
    v = d.viewport(k, centre, ((LEFT + RIGHT) / 2, top + 8.0 + (height - 8.0) / 2))
    phi = position.get("phi_deg")
    where = f"   φ_1 = {float(phi):.4g}°" if isinstance(phi, int | float) else ""
    ratio = SCALE_WORDS("ratio", lang, ratio=k.ratio_text() or "-")
    d.text(f"{k.label(ScaleStyle(lang=lang))}   ({ratio}){where}",
           (LEFT + PAD, top + 4.0), TEXT_H)  # fmt: skip

    def seg(a: object, b: object) -> None:
        pa, pb = pts.get(str(a)), pts.get(str(b))
        if pa is not None and pb is not None and pa != pb:
            v.seg(pa, pb, "link")

    pivots: set[str] = set()
    moving: set[str] = set()
    if "pivot" in drive:
        seg(drive["pivot"], drive.get("joint"))
        pivots.add(str(drive["pivot"]))
        moving.add(str(drive.get("joint")))
    for g in groups:
        kind = g.get("kind")
        if kind == "RRR":
            for e in g.get("ends", []):
                seg(e, g.get("joint"))
                if str(e) in frame:
                    pivots.add(str(e))
            moving.add(str(g.get("joint")))
        elif kind == "RRP":
            seg(g.get("end"), g.get("joint"))
            q = pts.get(str(g.get("joint")))
            guide = g.get("guide", {})
            if q is not None and isinstance(guide, Mapping) and "link" not in guide:
                ang = math.radians(float(guide.get("angle", 0.0)))
                u = (math.cos(ang), math.sin(ang))
                span = k.model(25.0)
                v.seg((q[0] - u[0] * span, q[1] - u[1] * span),
                      (q[0] + u[0] * span, q[1] + u[1] * span), "centre")  # fmt: skip
                v.slider(q, u)
        elif kind == "RPR":
            c, a = pts.get(str(g.get("pivot"))), pts.get(str(g.get("slider")))
            if c is not None and a is not None and c != a:
                far = (c[0] + (a[0] - c[0]) * 1.3, c[1] + (a[1] - c[1]) * 1.3)
                v.seg(c, far, "link")
                v.slider(a, (a[0] - c[0], a[1] - c[1]))
            if str(g.get("pivot")) in frame:
                pivots.add(str(g.get("pivot")))
        elif kind == "PRP":
            e, a = pts.get(str(g.get("point"))), pts.get(str(g.get("slider")))
            if e is not None and a is not None:
                v.seg(e, a, "link")
                v.slider(a, (a[0] - e[0], a[1] - e[1]) if e != a else (0.0, 1.0))
    for p in data.get("point", []) or []:
        if isinstance(p, Mapping) and "name" in p and "from" in p:
            seg(p["from"], p["name"])
    for n in sorted(pivots):
        if n in pts:
            v.pivot(pts[n])
    for n in sorted(moving):
        if n in pts:
            v.joint(pts[n])
    for n, q in pts.items():
        v.label(q, n, height=3.5)
    return top + height


@functools.cache
def _seed_frames(pid: str) -> Any:
    """The first frames of a problem id's mechanism as its defaults (the seed's) solve it."""
    from geomcad import registry

    problem = registry.get(pid)
    assert problem.motion is not None
    return problem.motion(problem.solve(), 2)


def motion_scheme(d: Drawing, sol: Solution[Any], top: float, lang: Lang = "en") -> float:
    """A problem id's mechanism as a scheme with its letters, from ``top``; returns the y below
    (``top`` when the problem has no :attr:`Problem.motion`, the mechanism ``geomcad animate``
    draws). It is the mechanism of the problem's own defaults, marked "not to scale": every
    variant's card shows the same scheme, and a synthesis problem's answers (2013-6's crank and
    rod) cannot be measured off it. Links as lines, frame points as supports, sliders as
    blocks on their guides, every point labelled."""
    if sol.problem.motion is None:
        return top
    try:
        frames = _seed_frames(sol.problem.id)
    except GeomcadError:
        return top
    pts = {n: (float(a[0, 0]), float(a[0, 1])) for n, a in frames.points.items()}
    if len(pts) < 2:
        return top
    x_min, y_min, w, h, pad = _extent(pts)
    k = gost_scale_to_fit(w + 2 * pad, h + 2 * pad, SCHEME_W, SCHEME_H - 8.0)
    height = min(SCHEME_H, (h + 2 * pad) / k.k + 8.0)
    centre = (x_min + w / 2, y_min + h / 2)
    v = d.viewport(k, centre, ((LEFT + RIGHT) / 2, top + 8.0 + (height - 8.0) / 2))
    d.text(_esc(WORDS[lang]["scheme"]), (LEFT + PAD, top + 4.0), TEXT_H)
    for name, u in frames.sliders.items():
        q = pts.get(name)
        if q is None:
            continue
        span = k.model(25.0)
        v.seg((q[0] - u[0] * span, q[1] - u[1] * span),
              (q[0] + u[0] * span, q[1] + u[1] * span), "centre")  # fmt: skip
    for chain in frames.links:
        for a, b in itertools.pairwise(chain):
            if a in pts and b in pts and pts[a] != pts[b]:
                v.seg(pts[a], pts[b], "link")
    for name, u in frames.sliders.items():
        if name in pts:
            v.slider(pts[name], u)
    for n in frames.fixed:
        if n in pts:
            v.pivot(pts[n])
    joints = frames.joints if frames.joints is not None else tuple(
        n for chain in frames.links for n in chain)  # fmt: skip
    for n in dict.fromkeys(joints):
        if n in pts and n not in frames.fixed and n not in frames.sliders:
            v.joint(pts[n])
    labelled = frames.labelled if frames.labelled is not None else tuple(pts)
    for n in labelled:
        if n in pts:
            v.label(pts[n], n, height=3.5)
    return top + height


# --- sheets -----------------------------------------------------------------------------------


def task_card(
    sol: Solution[Any],
    number: int,
    width: int,
    columns: Sequence[str],
    info: CardInfo,
    data: Mapping[str, Any] | None = None,
    stem: str = "",
) -> Sheet:
    """The A4 task card of one variant (see the module's docstring)."""
    problem = sol.problem
    words = WORDS[info.lang]
    title = str(data.get("title")) if data and data.get("title") else _title(problem, info.lang)
    positions = sol.results.get("positions")
    # numbered positions start at the output's extreme, a dead centre where the links lie
    # folded on one line: the scheme shows position 1 instead
    numbered = data is not None and "positions" in (data.get("drive") or {})
    pick = 1 if numbered and isinstance(positions, list) and len(positions) > 1 else 0
    first = positions[pick] if isinstance(positions, list) and positions else None
    k = scheme_scale(data, first) if data is not None and isinstance(first, Mapping) else None
    tb = TitleBlock(
        title=_fit(title, 200.0, 5.0),
        designation=f"{info.course} {stem or problem.id} V{number:0{width}d}",
        scale=k.ratio_text() if k is not None else "",
        organisation=info.course,
        developer=info.student,
        group=info.group,
        checker=info.teacher,
        lang=info.lang,
    )
    d = start("A4", tb)
    x0, room = LEFT + PAD, RIGHT - LEFT - 2 * PAD
    d.text(f"{words['variant']} {number:0{width}d}", (x0, TOP + 11.0), 7.0)
    y = TOP + 15.0
    if info.student:
        who = f"{words['student']}: {info.student}"
        who += f", {words['group']} {info.group}" if info.group else ""
        y += 6.0
        d.text(_esc(_fit(who, room, 5.0)), (x0, y), 5.0)
    for line in _wrap(title, room, 3.5):
        y += 5.5
        d.text(_esc(line), (x0, y), 3.5)
    y += 3.0
    if data is not None and isinstance(first, Mapping):
        y = linkage_scheme(d, data, first, y, info.lang) + 2.0
    elif data is None:
        y = motion_scheme(d, sol, y, info.lang) + 2.0
    linkage = data is not None and _is_linkage(data)
    head = [words["quantity"], words["symbol"], words["value"], words["unit"]]
    if data is None:
        rows = [head, *map(list, quantities.problem_rows(problem, sol.params, info.lang))]
    elif linkage:
        rows = [head, *map(list, quantities.linkage_rows(data, info.lang))]
    else:
        rows = [head, *map(list, quantities.file_rows(data, info.lang))]
    pos = positions if isinstance(positions, list) else []
    lines = quantities.find_lines(
        problem, columns, pos, info.lang, linkage, words["at"], words["each"]
    )
    find: list[tuple[float, str]] = []  # (indent, text) of each line of "Find"
    for i, line in enumerate(lines, start=1):
        wrapped = _wrap(f"{i}. {line}", room - 4.0, markup=True)
        find += [(4.0 if j else 0.0, t) for j, t in enumerate(wrapped)]
    lead = TEXT_H * 1.7
    find_h = 8.0 + 8.0 + lead * len(find) + 2.0
    d.text(words["given"], (x0, y + 5.0), 3.5)
    y += 8.0
    y = _given(d, rows, x0, y, room, BOTTOM - y - find_h, markup=True) + 4.0
    d.text(words["find"], (x0, y + 5.0), 3.5)
    y += 8.0
    fits = int((BOTTOM - 1.0 - y) / lead)
    if len(find) > fits:  # never into the title block: the answer key lists the rest
        find = [*find[: max(fits - 1, 0)], (0.0, _esc(words["rest"]))]
    for indent, text in find:
        y += lead
        d.text(text, (x0 + indent, y), TEXT_H)
    return _filled([d.finish()])[0]


def _filled(sheets: list[Sheet]) -> list[Sheet]:
    """The sheets with their title blocks filled as one document (Лист i of Листов n)."""
    fill_title_blocks(sheets)
    return sheets


def _is_linkage(data: Mapping[str, Any]) -> bool:
    """True for a linkage file's data (a drive or a synthesis table)."""
    return isinstance(data.get("drive"), Mapping) or isinstance(data.get("synthesis"), Mapping)


def _given(
    d: Drawing,
    rows: list[list[str]],
    x0: float,
    y: float,
    room: float,
    space: float,
    markup: bool = False,
) -> float:
    """The data table, cut into two or three parts side by side when it is taller than
    ``space`` mm (a linkage file's many values); returns the y below it."""
    body = rows[1:]
    n = next((k for k in (1, 2, 3) if (math.ceil(len(body) / k) + 1) * ROW_H <= space), 3)
    per = math.ceil(len(body) / n)
    gap = 4.0
    col = (room - gap * (n - 1)) / n
    bottoms = []
    for k in range(n):
        part = [rows[0], *body[k * per : (k + 1) * per]]
        # a problem's quantity text gives way first; a file's key stays whole, its value gives way
        flex = 0 if len(part[0]) > 2 else len(part[0]) - 1
        if markup:
            part = [[_esc(c) for c in part[0]], *part[1:]]
        widths = _col_widths(part, col, flex, markup)
        bottoms.append(_table(d, x0 + k * (col + gap), y, widths, part, markup))
    return max(bottoms)


#: A table of the answer key: its column widths, header rows and body rows (all text).
Table = tuple[list[float], list[list[str]], list[list[str]]]


def _key_tables(
    columns: Sequence[str],
    units: Mapping[str, str],
    rows: Sequence[Sequence[str]],
    words: Mapping[str, str],
) -> list[Table]:
    """The key as tables: one row per variant for the single results, and, where the key has
    results per position (``positions.i.NAME``), one row per variant and position."""
    single = [i for i, c in enumerate(columns) if not c.startswith("positions.")]
    per_pos: dict[str, dict[int, int]] = {}
    for i, c in enumerate(columns):
        parts = c.split(".")
        if c.startswith("positions.") and len(parts) == 3 and parts[1].isdecimal():
            per_pos.setdefault(parts[2], {})[int(parts[1])] = i
        elif c.startswith("positions."):
            single.append(i)
    tables: list[tuple[list[list[str]], list[list[str]]]] = []
    if single:
        head = [[words["no"], *(columns[i] for i in single)],
                ["", *(_unit(units.get(columns[i], "")) for i in single)]]  # fmt: skip
        tables.append((head, [[r[0], *(r[i + 1] for i in single)] for r in rows]))
    if per_pos:
        names = list(per_pos)
        positions = sorted({j for cols in per_pos.values() for j in cols})
        unit_row = [_unit(units.get(columns[next(iter(per_pos[n].values()))], "")) for n in names]
        head = [[words["no"], words["pos"], *names], ["", "", *unit_row]]
        body = []
        for r in rows:
            for j in positions:
                cells = [r[per_pos[n][j] + 1] if j in per_pos[n] else "" for n in names]
                body.append([r[0], str(j), *cells])
        tables.append((head, body))
    out: list[Table] = []
    for head, body in tables:
        full = head + body
        widths = [
            max(box(parse(_esc(r[i])), TEXT_H)[0] for r in full) + 3.0 for i in range(len(head[0]))
        ]
        out.append((widths, head, body))
    return out


def _split_wide(table: Table, room: float) -> list[Table]:
    """A table wider than ``room`` cut into column chunks that repeat its key columns."""
    widths, head, body = table
    keep = 2 if len(head[0]) > 1 and head[0][1] in ("pos.", "пол.") else 1
    if sum(widths) <= room:
        return [table]
    chunks: list[list[int]] = [[]]
    used = sum(widths[:keep])
    for i in range(keep, len(widths)):
        if chunks[-1] and used + widths[i] > room:
            chunks.append([])
            used = sum(widths[:keep])
        chunks[-1].append(i)
        used += widths[i]
    out = []
    for chunk in chunks:
        idx = [*range(keep), *chunk]
        out.append(([widths[i] for i in idx], [[r[i] for i in idx] for r in head],
                    [[r[i] for i in idx] for r in body]))  # fmt: skip
    return out


def answer_sheets(
    title: str,
    columns: Sequence[str],
    units: Mapping[str, str],
    rows: Sequence[Sequence[str]],
    info: CardInfo,
    stem: str,
) -> list[Sheet]:
    """The answer key on A3 sheets: its tables (:func:`_key_tables`) cut into blocks of rows
    that flow left to right across the field above the title block, then onto further sheets."""
    words = WORDS[info.lang]
    x_min, x_max = LEFT + PAD, 420.0 - 5.0 - PAD
    y_top, y_max = TOP + 16.0, 297.0 - 5.0 - 55.0 - PAD
    per_block = int((y_max - y_top) / ROW_H) - 2
    gap = 8.0
    pages: list[list[tuple[float, Table]]] = [[]]
    x = x_min
    for table in _key_tables(columns, units, rows, words):
        for part in _split_wide(table, x_max - x_min):
            widths, head, body = part
            w = sum(widths)
            for k in range(0, max(len(body), 1), per_block):
                if pages[-1] and x + w > x_max:
                    pages.append([])
                    x = x_min
                pages[-1].append((x, (widths, head, body[k : k + per_block])))
                x += w + gap
    sheets = []
    for n, blocks in enumerate(pages, start=1):
        tb = TitleBlock(
            title=_fit(f"{words['key']}: {title}", 200.0, 5.0),
            designation=f"{info.course} {stem} {words['answers']}",
            organisation=info.course,
            checker=info.teacher,
            sheet_no=n,
            sheets=len(pages),
            lang=info.lang,
        )
        d = start("A3", tb)
        d.text(_esc(f"{words['key']}: {title}"), (LEFT + PAD, TOP + 11.0), 5.0)
        for bx, (widths, head, body) in blocks:
            _table(d, bx, y_top, widths, [*head, *body])
        sheets.append(d.finish())
    return _filled(sheets)
