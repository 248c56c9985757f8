"""Golden sheets (DESIGN.md, "Tests (four kinds)"): every sheet of every problem, rendered to SVG,
matches its canonical file in ``tests/golden/`` after parsing.

The comparison parses both documents (xml.etree) and walks them together: the same tags, the same
attribute names, the same text; attribute values equal except for the numbers in them (points,
path data, dash arrays, sizes), which may differ by :data:`TOL_MM` — less than anyone can see, more
than the last written decimal. A mismatch names the first differing element and both values.

Regenerate after an intended change of the drawings::

    python3 -m pytest tests/test_golden.py --update-golden
"""

from __future__ import annotations

import dataclasses
import functools
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import geomcad
from geomcad.render import to_svg
from geomcad.sheet.model import Item, Polyline, Run, Sheet, TextItem

GOLDEN_DIR = Path(__file__).parent / "golden"
UPDATE_CMD = "python3 -m pytest tests/test_golden.py --update-golden"

#: Numbers in attribute values may differ by this much (sheet mm).
TOL_MM = 0.002

_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def golden_name(pid: str, name: str) -> str:
    """``ID.svg`` for a problem's main sheet, ``ID-NAME.svg`` for the others."""
    return f"{pid}-{name}.svg" if name else f"{pid}.svg"


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def _split_numbers(value: str) -> tuple[list[str], list[float]]:
    """The value's non-numeric pieces and its numbers (``points="1,2 3,4"``, path data …)."""
    return _NUMBER.split(value), [float(n) for n in _NUMBER.findall(value)]


def _values_match(a: str, b: str) -> bool:
    words_a, nums_a = _split_numbers(a)
    words_b, nums_b = _split_numbers(b)
    if words_a != words_b or len(nums_a) != len(nums_b):
        return False
    return all(abs(x - y) <= TOL_MM + 1e-12 for x, y in zip(nums_a, nums_b, strict=True))


def _step(el: ET.Element, index: int) -> str:
    """One step of an element path: the tag, its index among same-tag siblings, its id."""
    ident = el.get("id")
    return f"{_local(el.tag)}[{index}]" + (f"[@id={ident!r}]" if ident else "")


def _first_diff(got: ET.Element, want: ET.Element, path: str) -> str | None:
    if got.tag != want.tag:
        return f"{path}: tag {_local(got.tag)!r} != golden {_local(want.tag)!r}"
    names_got, names_want = set(got.attrib), set(want.attrib)
    if names_got != names_want:
        extra = sorted(names_got - names_want)
        missing = sorted(names_want - names_got)
        return f"{path}: attributes differ (extra {extra}, missing {missing})"
    for name in sorted(names_got):
        a, b = got.attrib[name], want.attrib[name]
        if not _values_match(a, b):
            return f"{path}/@{_local(name)}: {a!r} != golden {b!r}"
    for what, t_got, t_want in (("text", got.text, want.text), ("tail", got.tail, want.tail)):
        if (t_got or "") != (t_want or ""):
            return f"{path}: {what} {t_got or ''!r} != golden {t_want or ''!r}"
    kids_got, kids_want = list(got), list(want)
    seen: dict[str, int] = {}
    for k_got, k_want in zip(kids_got, kids_want, strict=False):
        tag = _local(k_want.tag)
        seen[tag] = seen.get(tag, 0) + 1
        diff = _first_diff(k_got, k_want, f"{path}/{_step(k_want, seen[tag])}")
        if diff is not None:
            return diff
    if len(kids_got) != len(kids_want):
        n = min(len(kids_got), len(kids_want))
        longer, which = (kids_got, "extra") if len(kids_got) > n else (kids_want, "missing")
        el = longer[n]
        attrs = " ".join(f"{_local(k)}={v!r}" for k, v in sorted(el.attrib.items()))
        return (
            f"{path}: {len(kids_got)} children != golden {len(kids_want)}; first {which}: "
            f"<{_local(el.tag)} {attrs}>{el.text or ''}"
        )
    return None


def svg_difference(got: str, want: str) -> str | None:
    """``None`` when two SVG documents draw the same, else where and how they first differ."""
    root_got = ET.fromstring(got.encode("utf-8"))
    root_want = ET.fromstring(want.encode("utf-8"))
    return _first_diff(root_got, root_want, _local(root_want.tag))


#: Linkage files with golden sheets, under the name ``linkage-STEM``.
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
GOLDEN_FILES = {f"linkage-{stem}": EXAMPLES / f"{stem}.toml" for stem in ("shaper", "four-bar")}
KEYS = [*geomcad.problem_ids(), *GOLDEN_FILES]


@functools.cache
def _sheets(pid: str) -> list[tuple[str, Sheet]]:
    """A problem's (or a golden linkage file's) sheets, drawn once per test run (test_dxf reads
    the same ones)."""
    if pid in GOLDEN_FILES:
        from geomcad import documents

        return documents.solve(str(GOLDEN_FILES[pid])).sheets()
    return geomcad.solve(pid).sheets()


@pytest.mark.parametrize("pid", KEYS)
def test_golden_sheets(pid: str, update_golden: bool) -> None:
    sheets = _sheets(pid)
    assert sheets, f"{pid} draws no sheet"
    if update_golden:
        GOLDEN_DIR.mkdir(exist_ok=True)
        written = []
        for name, sheet in sheets:
            path = GOLDEN_DIR / golden_name(pid, name)
            path.write_text(to_svg(sheet), encoding="utf-8")
            written.append(path.name)
        pytest.skip(f"golden files written: {', '.join(written)}")
    for name, sheet in sheets:
        path = GOLDEN_DIR / golden_name(pid, name)
        if not path.exists():
            pytest.fail(f"no golden file {path}: run `{UPDATE_CMD}` to create it")
        diff = svg_difference(to_svg(sheet), path.read_text(encoding="utf-8"))
        assert diff is None, (
            f"sheet {golden_name(pid, name)} differs from its golden file: {diff}\n"
            f"If the change is intended, run `{UPDATE_CMD}` and review the diff."
        )


def test_every_golden_file_belongs_to_a_sheet() -> None:
    """A stale golden file (a renamed sheet or problem) would otherwise be compared with nothing."""
    expected = {golden_name(pid, name) for pid in KEYS for name, _ in _sheets(pid)}
    stale = sorted(p.name for p in GOLDEN_DIR.glob("*.svg") if p.name not in expected)
    assert not stale, f"golden files without a sheet: {stale}; delete them"


def test_missing_golden_file_says_how_to_create_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(sys.modules[__name__], "GOLDEN_DIR", tmp_path)
    with pytest.raises(pytest.fail.Exception, match="--update-golden"):
        test_golden_sheets("2013-6", update_golden=False)


def test_update_writes_the_golden_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sys.modules[__name__], "GOLDEN_DIR", tmp_path)
    with pytest.raises(pytest.skip.Exception, match=r"2013-6\.svg"):
        test_golden_sheets("2013-6", update_golden=True)
    written = (tmp_path / "2013-6.svg").read_text(encoding="utf-8")
    assert written == to_svg(_sheets("2013-6")[0][1])
    test_golden_sheets("2013-6", update_golden=False)  # and now it matches


# -- the comparison itself must see a changed drawing ----------------------------------------------


@pytest.fixture(scope="module")
def sheet_2013_6() -> Sheet:
    _name, sheet = geomcad.solve("2013-6").sheets()[0]
    return sheet


def _with_items(sheet: Sheet, items: list[Item]) -> Sheet:
    return dataclasses.replace(sheet, items=list(items))


def _moved(sheet: Sheet, dx: float) -> tuple[Sheet, int]:
    """The sheet with the first point of its first link line moved ``dx`` mm to the right."""
    items = list(sheet.items)
    i = next(j for j, it in enumerate(items) if isinstance(it, Polyline) and it.role == "link")
    line = items[i]
    assert isinstance(line, Polyline)
    (x, y), *rest = line.points
    items[i] = dataclasses.replace(line, points=((x + dx, y), *rest))
    return _with_items(sheet, items), i


def test_identical_sheets_match(sheet_2013_6: Sheet) -> None:
    assert svg_difference(to_svg(sheet_2013_6), to_svg(sheet_2013_6)) is None


def test_comparison_sees_a_moved_point(sheet_2013_6: Sheet) -> None:
    moved, _ = _moved(sheet_2013_6, 0.5)
    diff = svg_difference(to_svg(moved), to_svg(sheet_2013_6))
    assert diff is not None
    assert "layer-link" in diff and "polyline[1]/@points" in diff, diff


def test_comparison_tolerates_half_a_micrometre(sheet_2013_6: Sheet) -> None:
    moved, _ = _moved(sheet_2013_6, 0.0005)
    assert svg_difference(to_svg(moved), to_svg(sheet_2013_6)) is None


def test_comparison_sees_five_micrometres(sheet_2013_6: Sheet) -> None:
    moved, _ = _moved(sheet_2013_6, 0.005)
    diff = svg_difference(to_svg(moved), to_svg(sheet_2013_6))
    assert diff is not None and "@points" in diff, diff


def test_comparison_sees_a_dropped_item(sheet_2013_6: Sheet) -> None:
    items = list(sheet_2013_6.items)
    # the last item of the joint layer, so that the layer has one child fewer
    joint = max(j for j, it in enumerate(items) if it.role == "joint")
    del items[joint]
    diff = svg_difference(to_svg(_with_items(sheet_2013_6, items)), to_svg(sheet_2013_6))
    assert diff is not None
    assert "layer-joint" in diff and "children" in diff and "missing" in diff, diff


def test_comparison_sees_a_changed_label(sheet_2013_6: Sheet) -> None:
    items = list(sheet_2013_6.items)
    k = next(
        j
        for j, it in enumerate(items)
        if isinstance(it, TextItem) and it.role == "label" and it.text == "B0"
    )
    label = items[k]
    assert isinstance(label, TextItem)
    # same width, so only the text itself differs
    items[k] = dataclasses.replace(label, runs=(Run("B"), Run("9", "sub")))
    diff = svg_difference(to_svg(_with_items(sheet_2013_6, items)), to_svg(sheet_2013_6))
    assert diff is not None
    assert "text '9' != golden '0'" in diff, diff


def test_comparison_sees_a_changed_role(sheet_2013_6: Sheet) -> None:
    moved_items = list(sheet_2013_6.items)
    i = next(j for j, it in enumerate(moved_items) if it.role == "extreme")
    moved_items[i] = dataclasses.replace(moved_items[i], role="link")
    diff = svg_difference(to_svg(_with_items(sheet_2013_6, moved_items)), to_svg(sheet_2013_6))
    assert diff is not None


@pytest.mark.parametrize(
    ("got", "want", "words"),
    [
        ('<svg><g stroke="#000000"/></svg>', '<svg><g stroke="#b01c1c"/></svg>', "@stroke"),
        (
            '<svg><polyline points="1,2 3,4"/></svg>',
            '<svg><polygon points="1,2 3,4"/></svg>',
            "tag",
        ),
        ('<svg><path d="M0,0 L1,1"/></svg>', '<svg><path d="M0,0 A1,1"/></svg>', "@d"),
        ('<svg><path d="M0,0 1,1"/></svg>', '<svg><path d="M0,0 1,1 2,2"/></svg>', "@d"),
        ('<svg><circle r="1"/></svg>', '<svg><circle r="1" fill="red"/></svg>', "missing"),
        (
            '<svg><g stroke-dasharray="12 1.5 0.5"/></svg>',
            '<svg><g stroke-dasharray="12 1.5 0.6"/></svg>',
            "stroke-dasharray",
        ),
        ("<svg><text>Лист</text></svg>", "<svg><text>Лист 1</text></svg>", "text"),
    ],
)
def test_comparison_on_small_documents(got: str, want: str, words: str) -> None:
    diff = svg_difference(got, want)
    assert diff is not None and words in diff, diff


def test_comparison_number_tolerance_is_absolute() -> None:
    a = '<svg><polyline points="100.001,2 3,-4"/></svg>'
    assert svg_difference(a, '<svg><polyline points="100.003,2 3,-4.002"/></svg>') is None
    assert svg_difference(a, '<svg><polyline points="100.004,2 3,-4"/></svg>') is not None
