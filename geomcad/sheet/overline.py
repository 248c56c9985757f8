"""Overlined letters on a drawn sheet: a combining macron (s̄, h̄) turned into a bar over its letter.

The lettering font sets U+0304 as a spacing glyph after its letter; a gear caliper's symbols
(s̄, h̄: the chordal thickness and height) and any other overlined symbol need the bar over the
letter. :func:`overline_marks` rewrites a finished sheet: each barred letter becomes a run of
its own and the bar a thin line over it, in the role of its text (the tables' thin line, or a
dimension's).
"""

from __future__ import annotations

import dataclasses
import math

from geomcad.sheet.model import Polyline, Run, Sheet, TextItem
from geomcad.sheet.text import SUB_DROP, metrics, run_size, sup_rise
from geomcad.sheet.text import width as text_width

MACRON = "\u0304"


def overline_marks(sheet: Sheet) -> None:
    """Turn each combining macron (s̄, h̄) into a bar drawn over the letter before it.

    The lettering font sets U+0304 as a spacing glyph after its letter; the caliper's symbols
    need the bar over the letter, so the bar is drawn as a thin line and the mark is dropped."""
    m = metrics()
    for i, it in enumerate(sheet.items):
        if not isinstance(it, TextItem) or MACRON not in it.text:
            continue
        x = 0.0  # along the baseline from ``it.at``
        runs: list[Run] = []
        bars: list[tuple[tuple[float, float], tuple[float, float]]] = []
        for run in it.runs:
            fs = run_size(it.font_size, run.shift)
            cap = it.height * fs / it.font_size
            dy = {"base": 0.0, "sub": SUB_DROP * it.font_size, "sup": -sup_rise(it.font_size)}
            kept = ""
            for ch in run.text:
                if ch == MACRON and kept:
                    # the barred letter becomes a run of its own, so that the renderer sets it
                    # exactly where the bar goes; the bar spans the letter's ink (about
                    # 0.27 … 0.9 of its advance), clear of an ascender or of the x-height
                    letter = kept[-1]
                    w = m.advance(letter, fs)
                    if kept[:-1]:
                        runs.append(Run(kept[:-1], run.shift))
                    runs.append(Run(letter, run.shift))
                    kept = ""
                    tall = letter.isupper() or letter in "bdfhklt"
                    y_bar = dy[run.shift] - (1.15 if tall else 0.92) * cap
                    bars.append((_turned(it, x - 0.73 * w, y_bar), _turned(it, x - 0.1 * w, y_bar)))
                    continue
                kept += ch
                x += m.advance(ch, fs)
            if kept:
                runs.append(Run(kept, run.shift))
        new_runs = tuple(runs)
        sheet.items[i] = dataclasses.replace(
            it, runs=new_runs, width=text_width(new_runs, it.font_size)
        )
        # a bar belongs with its text: the tables' thin line, or a dimension's
        role = "frame_thin" if it.role == "title" else "dimension"
        for a, b in bars:
            sheet.add(Polyline((a, b), role))


def _turned(it: TextItem, x: float, y: float) -> tuple[float, float]:
    """A point given in the text's own frame (x along its baseline from ``it.at``, y down across
    it) on the paper: turned with the text by its angle (counter-clockwise on the paper)."""
    c, s = math.cos(math.radians(it.angle)), math.sin(math.radians(it.angle))
    return (it.at[0] + x * c + y * s, it.at[1] - x * s + y * c)
