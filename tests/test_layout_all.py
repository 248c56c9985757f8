"""Every sheet of every problem through the one layout checker (tests/layout.py, issue 14).

``layout_problems`` must be empty on every sheet. The drafting ``findings`` (labels crossed by
lines, labels far from their points, vectors shorter than twice their head, an empty field) are
held to the counts below, which may only fall: lower a count when a sheet is fixed. Variants
go through the same checker in the problems' own tests (test_sheet.py: 2013-6 variants).
"""

from __future__ import annotations

import collections

import pytest
from layout import KINDS, findings, layout_problems

import geomcad
from geomcad import registry

#: (problem id, sheet name) → the most findings of each kind the sheet may still have.
BASELINE: dict[tuple[str, str], dict[str, int]] = {
    ("2013-1", ""): {"anchor": 6, "empty": 1},
    ("2013-2", ""): {"short-vector": 3},
    ("2013-3", ""): {"anchor": 5, "empty": 1},
    ("2013-4", ""): {"label-line": 4, "short-vector": 2},
    ("2013-5", ""): {"short-vector": 2},
    ("2013-6", ""): {"anchor": 4},
    ("2013-6", "kinematics"): {"label-line": 5, "short-vector": 2, "empty": 1},
    # composed (sheet.compose): the mechanism 1:2.5, the plans 1 N/mm, the joints only 1:1 in a
    # strip under the mechanism, whose labels crowd; the strip leaves the field 58 % empty
    ("2013-7", ""): {"anchor": 5, "short-vector": 3, "empty": 1},
    ("2013-8", ""): {"anchor": 1, "empty": 1},
    ("2013-9", ""): {"anchor": 1},
    # composed: φ(t) and φ'(t) fill their boxes, 51 % of the field empty (78 % before)
    ("2013-9", "motion"): {"label-line": 1, "empty": 1},
    ("kulisa-23110713", ""): {"anchor": 2},
    ("kulisa-23110713", "fbd"): {"anchor": 3},
}


def _all_sheets() -> list[tuple[str, str, object]]:
    return [
        (pid, name, sheet)
        for pid in registry.problem_ids()
        for name, sheet in geomcad.solve(pid).sheets()
    ]


@pytest.fixture(scope="module")
def seed_sheets() -> list[tuple[str, str, object]]:
    return _all_sheets()


def test_every_seed_sheet_passes_the_checker(seed_sheets: list[tuple[str, str, object]]) -> None:
    bad = {(pid, name): layout_problems(s) for pid, name, s in seed_sheets}  # type: ignore[arg-type]
    bad = {k: v for k, v in bad.items() if v}
    assert not bad, bad


def test_findings_do_not_grow(seed_sheets: list[tuple[str, str, object]]) -> None:
    grown = []
    for pid, name, sheet in seed_sheets:
        count = collections.Counter(f.kind for f in findings(sheet))  # type: ignore[arg-type]
        allowed = BASELINE.get((pid, name), {})
        for kind, n in count.items():
            assert kind in KINDS
            if n > allowed.get(kind, 0):
                texts = [f.text for f in findings(sheet) if f.kind == kind]  # type: ignore[arg-type]
                grown.append(
                    f"{pid} {name!r}: {n} × {kind} (allowed {allowed.get(kind, 0)}): {texts}"
                )
    assert not grown, "\n".join(grown)
