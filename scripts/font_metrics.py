"""Write the pinned font's metrics file (geomcad/fonts/osifont-metrics.json) from the font.

Usage: ``python3 scripts/font_metrics.py`` after the font changes (scripts/patch_osifont.py);
``tests/test_font.py`` fails while the file is not the shipped font's.
"""

from __future__ import annotations

from geomcad.sheet.text import METRICS_FILE, font_path, metrics_record

if __name__ == "__main__":
    font = font_path()
    font.with_name(METRICS_FILE).write_text(metrics_record(font), encoding="utf-8")
    print(font.with_name(METRICS_FILE))
