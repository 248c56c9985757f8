"""Lettering: the pinned font's metrics, GOST cap heights, and labels with subscripts.

The sheets use one font, osifont (ISO 3098 / GOST 2.304 style), shipped inside the package so
that text metrics, and the golden sheets with them, are the same on every machine. Widths come
from the font's own advance widths (fontTools), which match cairo's: cairo's text path applies no
kerning. A cap height (GOST 2.304: 2.5, 3.5, 5, 7, 10, 14 mm) becomes a font size through the
font's own cap-height/em.

Label markup: ``O_1``, ``V_{B3B2}`` (subscript), ``x^2`` (superscript); ``\\_`` is a literal
underscore. A character the font lacks is bad input (a :class:`~geomcad.errors.GeomcadError`
naming the character and the text) at drawing time, never an empty box: an ESKD sheet is lettered
in its one font (GOST 2.304), and a fallback font would put a different letter shape on it. The
user's own words (a title block's names) are checked as they are read (:func:`lacking`) and
written as plain text (:func:`escape`), never as markup.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from functools import cache, lru_cache
from importlib import resources
from pathlib import Path

from geomcad.errors import GeomcadError, quote
from geomcad.sheet.model import Run, Shift, TextItem

FONT_FAMILY = "osifont"
FONT_FILE = "osifont.ttf"

#: GOST 2.304 cap heights (mm).
HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0)

#: Subscripts and superscripts are set at this fraction of the font size, never with a cap
#: height under :data:`INDEX_MIN_H` (GOST 2.304's least size, as SHEETS.md asks of every letter:
#: an index O_1, V_B, S_2 and a mark a^n, a^τ, R^*, i^{-1} alike), nor larger than their text …
SUB_SCALE = 0.7
INDEX_MIN_H = 2.5
#: … and shifted by these fractions of the base font size (down for sub, up for sup; a
#: superscript the least height makes larger than :data:`SUB_SCALE` rises less, see
#: :func:`sup_rise`).
SUB_DROP = 0.25
SUP_RISE = 0.45

#: Characters osifont lacks, written with ones it has.
SUBSTITUTE = {"\u2212": "\u2013", "\u2032": "'", "\u2033": '"', "\u2026": "..."}


def font_path() -> Path:
    """The shipped TTF file."""
    return Path(str(resources.files("geomcad.fonts").joinpath(FONT_FILE)))


@dataclass(frozen=True)
class FontMetrics:
    """Advance widths and the cap height of the pinned font, in em units."""

    units_per_em: int
    cap_height: int
    ascent: int
    descent: int
    widths: dict[int, int]
    #: each text's advance in em units, as it was first summed (the layout and the label
    #: placer measure the same words thousands of times)
    _units: dict[str, int] = field(default_factory=dict, compare=False, repr=False)
    #: each label's :func:`box`, by its runs and cap height, as it was first measured
    _boxes: dict[tuple[tuple[Run, ...], float], tuple[float, float, float]] = field(
        default_factory=dict, compare=False, repr=False
    )

    def font_size(self, cap_height_mm: float) -> float:
        """The em size (mm) whose capital letters are ``cap_height_mm`` tall."""
        return cap_height_mm * self.units_per_em / self.cap_height

    def advance(self, text: str, font_size: float) -> float:
        """The advance width (mm) of ``text`` set at ``font_size`` mm; no kerning. A character
        the font lacks is a :class:`~geomcad.errors.GeomcadError` naming it and the text."""
        units = self._units.get(text)
        if units is None:
            if any(ord(c) not in self.widths for c in text):
                raise GeomcadError(f"the text {quote(text)} {no_glyph(text)}")
            units = self._units[text] = sum(self.widths[ord(c)] for c in text)
        return units * font_size / self.units_per_em


def lacking(text: str) -> str:
    """The characters of ``text`` (as a label writes them) that the sheet font has no glyph
    for, each once, in order; ``""`` when it has them all."""
    widths = metrics().widths
    out = ""
    for c in text:
        c = SUBSTITUTE.get(c, c)
        if ord(c[0]) not in widths and c not in out:
            out += c
    return out


def no_glyph(text: str) -> str:
    """The words for ``text``'s characters that the sheet font lacks (see :func:`lacking`)."""
    chars = lacking(text)
    shown = ", ".join(f"{c!r} (U+{ord(c):04X})" for c in chars[:5])
    more = f" and {len(chars) - 5} more" if len(chars) > 5 else ""
    return (
        f"has {'a character' if len(chars) == 1 else 'characters'} the sheet font "
        f"{FONT_FAMILY} lacks: {shown}{more}; an ESKD sheet is lettered in its one font, so "
        "write it with other characters"
    )


def escape(text: str) -> str:
    """``text`` as label markup that draws it as it is (``_``, ``^`` and ``\\`` escaped)."""
    return "".join("\\" + c if c in "\\_^" else c for c in text)


#: The font's metrics as :func:`read_metrics` reads them, with the SHA-256 of the font they
#: were read from (``python scripts/font_metrics.py`` writes it): a process reads this small
#: file instead of importing fontTools and parsing the font (0.035 s of a sheet set's build).
METRICS_FILE = "osifont-metrics.json"


@cache
def metrics() -> FontMetrics:
    """The pinned font's metrics, read once: from :data:`METRICS_FILE` where it was written
    for the shipped font (its SHA-256), else from the font itself (:func:`read_metrics`)."""
    font = font_path()
    try:
        kept = json.loads(font.with_name(METRICS_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        kept = None
    if (
        isinstance(kept, dict)
        and kept.get("sha256") == hashlib.sha256(font.read_bytes()).hexdigest()
    ):
        return FontMetrics(
            units_per_em=int(kept["units_per_em"]),
            cap_height=int(kept["cap_height"]),
            ascent=int(kept["ascent"]),
            descent=int(kept["descent"]),
            widths={int(code): int(w) for code, w in kept["widths"].items()},
        )
    return read_metrics(font)


def read_metrics(font: Path) -> FontMetrics:
    """The metrics of the TrueType font ``font``, read with fontTools."""
    from fontTools.ttLib import TTFont

    with TTFont(str(font), lazy=True) as f:
        cmap = f.getBestCmap()
        hmtx = f["hmtx"]
        widths = {code: int(hmtx[name][0]) for code, name in cmap.items()}
        return FontMetrics(
            units_per_em=int(f["head"].unitsPerEm),
            cap_height=int(f["OS/2"].sCapHeight),
            ascent=int(f["hhea"].ascent),
            descent=int(f["hhea"].descent),
            widths=widths,
        )


def metrics_record(font: Path) -> str:
    """:data:`METRICS_FILE`'s text for ``font``: its metrics and its SHA-256."""
    m = read_metrics(font)
    record = {
        "sha256": hashlib.sha256(font.read_bytes()).hexdigest(),
        "units_per_em": m.units_per_em,
        "cap_height": m.cap_height,
        "ascent": m.ascent,
        "descent": m.descent,
        "widths": {str(code): w for code, w in sorted(m.widths.items())},
    }
    return json.dumps(record, indent=0, sort_keys=False) + "\n"


#: The characters that label markup gives a meaning to (:func:`parse`).
MARKUP_CHARS = "\\_^{}"


def literal(text: str) -> str:
    """``text`` as markup that prints exactly as typed: every markup character escaped (a
    designation ``sixbar_press`` stays one line of plain letters, no subscript)."""
    return "".join("\\" + ch if ch in MARKUP_CHARS else ch for ch in text)


@lru_cache(maxsize=8192)
def parse(markup: str) -> tuple[Run, ...]:
    """Split label markup into runs: ``V_{B3B2}`` → V, B3B2 (sub); ``O_1`` → O, 1 (sub).
    (Runs are frozen: a label drawn again, or measured by the layout and drawn, is parsed once.)"""
    runs: list[Run] = []
    buf: list[str] = []
    i = 0

    def flush(shift: Shift = "base") -> None:
        if buf:
            runs.append(Run("".join(buf), shift))
            buf.clear()

    while i < len(markup):
        ch = markup[i]
        if ch == "\\" and i + 1 < len(markup):
            buf.append(markup[i + 1])
            i += 2
            continue
        if ch in "_^" and i + 1 < len(markup):
            flush()
            shift: Shift = "sub" if ch == "_" else "sup"
            if markup[i + 1] == "{":
                end = markup.find("}", i + 2)
                if end < 0:
                    raise GeomcadError(f"the label {quote(markup)} has an unclosed brace")
                buf.extend(markup[i + 2 : end])
                i = end + 1
            else:
                buf.append(markup[i + 1])
                i += 2
            flush(shift)
            continue
        buf.append(SUBSTITUTE.get(ch, ch))
        i += 1
    flush()
    return tuple(_merge(runs))


def _merge(runs: list[Run]) -> list[Run]:
    out: list[Run] = []
    for r in runs:
        text = "".join(SUBSTITUTE.get(c, c) for c in r.text)
        if out and out[-1].shift == r.shift:
            out[-1] = Run(out[-1].text + text, r.shift)
        else:
            out.append(Run(text, r.shift))
    return out


def run_size(font_size: float, shift: Shift) -> float:
    """The font size of a run: smaller for a subscript or a superscript (:data:`SUB_SCALE`), at
    least :data:`INDEX_MIN_H` high (never larger than the text's own size)."""
    if shift == "base":
        return font_size
    return min(font_size, max(font_size * SUB_SCALE, metrics().font_size(INDEX_MIN_H)))


def sup_rise(font_size: float) -> float:
    """How far (mm) a superscript's baseline is raised above its text's: :data:`SUP_RISE` of the
    font size, less what :data:`INDEX_MIN_H` adds to the superscript's cap height over
    :data:`SUB_SCALE`, so that its top stays where a :data:`SUB_SCALE` one's would be (a label is
    no taller, and the sheets' line pitch holds, with every letter at least 2.5 mm)."""
    m = metrics()
    grown = (run_size(font_size, "sup") - font_size * SUB_SCALE) * m.cap_height / m.units_per_em
    return SUP_RISE * font_size - grown


def width(runs: tuple[Run, ...], font_size: float) -> float:
    """The advance width (mm) of a label's runs at ``font_size``."""
    m = metrics()
    return sum(m.advance(r.text, run_size(font_size, r.shift)) for r in runs)


def box(runs: tuple[Run, ...], cap_height: float) -> tuple[float, float, float]:
    """(width, height above the baseline, depth below it) of a label, in mm.

    The height is the cap height (plus a superscript's rise); the depth covers a subscript.
    """
    m = metrics()
    known = m._boxes.get((runs, cap_height))
    if known is not None:
        return known  # (the layout and the label placer measure the same labels again)
    fs = m.font_size(cap_height)
    w = width(runs, fs)
    up = cap_height
    down = 0.0
    for r in runs:
        if r.shift == "sub":
            down = max(down, SUB_DROP * fs)
        elif r.shift == "sup":
            up = max(up, sup_rise(fs) + cap_height * run_size(fs, "sup") / fs)
    m._boxes[(runs, cap_height)] = w, up, down
    return w, up, down


def wrap(markup: str, width: float, height: float, indent: float = 0.0) -> list[str]:
    """``markup`` wrapped at spaces into lines of at most ``width`` mm at cap height ``height``
    (lines after the first ``indent`` mm narrower)."""
    return list(_wrapped(markup, width, height, indent))


@lru_cache(maxsize=4096)
def _wrapped(markup: str, width: float, height: float, indent: float) -> tuple[str, ...]:
    """:func:`wrap`, once per paragraph and measure (a sheet's tree is built again for each
    format and text height its layout tries, with the same paragraphs)."""
    lines: list[list[str]] = [[]]
    for word in markup.split(" "):
        room = width - (indent if len(lines) > 1 else 0.0)
        if lines[-1] and box(parse(" ".join([*lines[-1], word])), height)[0] > room:
            lines.append([])
        lines[-1].append(word)
    return tuple(" ".join(w) for w in lines)


def placed_runs(t: TextItem) -> Iterator[tuple[Run, float, float, float]]:
    """Each non-empty run of a text with the start of its baseline (x, y) on the paper, before
    the text is turned by its ``angle`` about ``t.at``, and its font size: the one layout every
    backend sets (subscripts dropped, superscripts raised, runs one after another), before
    its ``stretch`` (a width factor about ``t.at``, which each backend applies to the glyphs
    and their positions alike)."""
    m = metrics()
    x, base = t.at
    for run in t.runs:
        if not run.text:
            continue
        size = run_size(t.font_size, run.shift)
        y = base
        if run.shift == "sub":
            y += SUB_DROP * t.font_size
        elif run.shift == "sup":
            y -= sup_rise(t.font_size)
        yield run, x, y, size
        x += m.advance(run.text, size)


def break_points(markup: str) -> list[tuple[str, str]]:
    """The pieces a text may be broken between, each with what joins it to the next on one line:
    its words (joined by a space), a compound word's parts (``поперечно-`` joined to
    ``строгального`` by nothing: the hyphen stays at the line's end)."""
    out: list[tuple[str, str]] = []
    for word in markup.split(" "):
        parts = re.split(r"(?<=[^\W\d_]{2}-)(?=[^\W\d_]{2})", word)
        out += [(p, "") for p in parts[:-1]] + [(parts[-1], " ")]
    return out


def _join(tokens: Sequence[tuple[str, str]]) -> str:
    return "".join(t + j for t, j in tokens[:-1]) + tokens[-1][0]


def balanced(tokens: list[tuple[str, str]], n: int, height: float) -> list[str]:
    """The pieces set in ``n`` lines whose widest line is as narrow as it can be (exactly, over
    every way to break them: a title has a few words)."""
    if n == 1:
        return [_join(tokens)]
    k = len(tokens)
    width = {
        (i, j): box(parse(_join(tokens[i:j])), height)[0]
        for i in range(k)
        for j in range(i + 1, k + 1)
    }
    # best[m][j]: the least widest line setting tokens[:j] in m lines, with its last break
    inf = (math.inf, 0)
    best = [[inf] * (k + 1) for _ in range(n + 1)]
    best[0][0] = (0.0, 0)
    for m in range(1, n + 1):
        for j in range(m, k + 1):
            best[m][j] = min(
                ((max(best[m - 1][i][0], width[i, j]), i) for i in range(m - 1, j)),
                default=inf,
            )
    lines: list[str] = []
    j = k
    for m in range(n, 0, -1):
        i = best[m][j][1]
        lines.append(_join(tokens[i:j]))
        j = i
    return lines[::-1]


def wrap_balanced(markup: str, width: float, height: float) -> list[str]:
    """``markup`` in as few lines of at most ``width`` mm (at cap height ``height``) as it
    takes, the lines of about equal width (:func:`balanced`; a word wider than ``width`` stands
    on a line of its own)."""
    tokens = break_points(markup)
    for n in range(1, len(tokens) + 1):
        lines = balanced(tokens, n, height)
        if max(box(parse(ln), height)[0] for ln in lines) <= width:
            return lines
    return [t for t, _ in tokens]
