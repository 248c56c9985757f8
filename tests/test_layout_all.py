"""Every sheet of every problem through the one layout checker (tests/layout.py, issue 14).

``layout_problems`` must be empty on every sheet (every problem's and the golden linkage
files'), at the seed's parameters and on variants of
them (hypothesis: one to three parameters moved by up to a quarter, a choice switched, a count
changed by one or two). The drafting ``findings`` (labels crossed by lines, tick values crossed
by curves, labels far from their points, vectors shorter than twice their head, an empty field)
of the seed's sheets are held to the counts below, which may only fall: lower a count when a
sheet is fixed; a variant's are shown when it fails.

CI draws four variants over the problems (derandomized, a few seconds);
``GEOMCAD_FUZZ_EXAMPLES=N`` draws N per problem and ``HYPOTHESIS_PROFILE=explore`` fresh ones, as
for tests/test_fuzz.py (e.g. ``HYPOTHESIS_PROFILE=explore GEOMCAD_FUZZ_EXAMPLES=30 pytest
tests/test_layout_all.py -k variants``).
"""

from __future__ import annotations

import collections
import os

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from layout import KINDS, findings, layout_problems
from test_golden import KEYS
from test_golden import _sheets as golden_sheets

import geomcad
from geomcad import registry
from geomcad.problem import Param

#: Variants drawn in all: a few over the problems in CI, GEOMCAD_FUZZ_EXAMPLES per problem on
#: demand.
PER_PROBLEM = int(os.environ.get("GEOMCAD_FUZZ_EXAMPLES", "0"))
EXAMPLES = PER_PROBLEM * len(registry.problem_ids()) if PER_PROBLEM else 4

#: (problem id, sheet name) → the most findings of each kind the sheet may still have.
BASELINE: dict[tuple[str, str], dict[str, int]] = {
    # the T labels keep 6.5 mm off points crowded by four lines, M 7 mm (outside its roller);
    # 63 % empty: sparse schemes at GOST scales (1:4, 1:10, 1:2), the panel of tables
    ("2013-1", ""): {"anchor": 4, "empty": 1},
    # A2 (the whole rise at 2:1, S′(φ) beside S(φ), the scheme at 1:1): no short vector; 51 % of
    # the 10 mm cells empty (the open profile and the plan leave white inside their boxes)
    ("2013-2", ""): {"empty": 1},
    ("2013-3", ""): {"empty": 1},
    # issue 27: O1's support stands upright now (it was skewed with the crank); O1's letter,
    # crowded by the support, the crank and the O1B0 dimension, lands 15 mm off
    ("2013-6", ""): {"anchor": 1},
    # the bars over s̄, h̄ are part of their labels (layout.is_bar_of)
    ("2013-4", ""): {},
    # composed (sheet.compose): the mechanism 1:2.5, the joints 1:1, the plans 1 N/mm; 54 % empty
    ("2013-7", ""): {"empty": 1},
    # composed: the three views at 1:2 with room for their loads leave 51 % of the field empty
    ("2013-9", ""): {"empty": 1},
    # the 3 mm kept under графа 26 (a view's title no longer touches the form) costs the two
    # diagrams beside it one step of their μ: 51 % of the field empty
    ("2013-8", ""): {"empty": 1},
    ("2013-9", "motion"): {},
    ("kulisa-23110713", ""): {},
    ("kulisa-23110713", "graphs"): {},
    ("kulisa-23110713", "fbd"): {},
    # the golden linkage files (tests/test_golden.py): plan vectors under two arrowheads are
    # lettered points (with a note)
    # the principal position is the force position (1): the ram's symbol at D1 crowds D2, D11;
    # the ram's guide drawn over its whole travel (GOST 2.770) puts D1's and D11's numbers past
    # the block's hatching (9 mm)
    ("linkage-shaper", ""): {"anchor": 6, "empty": 1},
    # the forces sheet at the default force position (position 1, the ram at the start of its
    # cut, the rod 4 nearly along the guide); issue 27: the short forces at the slider D are
    # arrows at μ_F* … (they were dots): the letters 4, D, 5 by the crowded slider land 7–9 mm
    # off, on the mechanism and on group (4, 5); one μ_F per view (review 5): the thin circle of
    # the inset of G₃ round C, on the mechanism and on group (2, 3), sets C's letter 9 mm off;
    # review 6 item 5: group (4, 5) drawn at the mechanism's 1:2.5 (was 1:4) has the
    # mechanism's crowded slider D, its 4, D and 5 at 7 mm as on the mechanism (7 -> 8)
    # review 7 item 2: an inset's arrows from 5 mm (a head and a shaft), none longer than the
    # view's shortest: G_5 in group (4, 5)'s inset at 40 N/mm is 6.1 mm; review 8 item 2: a load
    # neither tier draws 5 mm long (G_4, Φ_4 on the mechanism, group (4, 5) and the lever) is a
    # 5 mm direction arrow, stated "стрелки 5 мм без масштаба" under its view's caption (7 × 5.00)
    # (anchor 9: the lever pole's "p, o, c" 6,8 mm off, pushed out by the twins Г1/Ж1 round it,
    # round 12's one μ_F per inset; round 13: lettered next to the twins' outline, 8; review
    # 17: S4, the rod's centre of mass its G4 and Ф4 act at, lettered at the rod's middle where
    # its number 4 stands, on the mechanism and on group (4, 5): both 7 mm off, 10)
    ("linkage-shaper", "forces"): {"anchor": 10, "empty": 1, "short-vector": 8},
    ("linkage-shaper", "dynamics"): {"empty": 1},
    # the twelve numbered positions drawn beside the file's phi: B's labels crowd near the
    # rocker's extreme (7 … 11 mm)
    ("linkage-four-bar", ""): {"anchor": 6, "empty": 1},
}


def _all_sheets() -> list[tuple[str, str, object]]:
    # drawn once per run for the golden files and here (test_golden keeps them)
    return [(key, name, sheet) for key in KEYS for name, sheet in golden_sheets(key)]


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


def _near(p: Param) -> st.SearchStrategy[object] | None:
    """Values of a parameter near its default (``None``: the parameter keeps its default)."""
    if p.choices:
        return st.sampled_from(p.choices)
    if p.optional or isinstance(p.default, bool) or not isinstance(p.default, int | float):
        return None
    if p.integer:
        return st.integers(-2, 2).map(lambda k: int(p.default) + k)  # type: ignore[arg-type]
    if p.default == 0.0:
        return None
    return st.floats(0.75, 1.25).map(lambda f: float(p.default) * f)  # type: ignore[arg-type]


def _variant(pid: str) -> st.SearchStrategy[dict[str, object]]:
    problem = registry.get(pid)
    moves = {p.name: v for p in problem.params if (v := _near(p)) is not None}
    return st.lists(st.sampled_from(sorted(moves)), min_size=1, max_size=3, unique=True).flatmap(
        lambda names: st.fixed_dictionaries({n: moves[n] for n in names})
    )


@settings(
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
@given(
    case=st.sampled_from(registry.problem_ids()).flatmap(
        lambda pid: st.tuples(st.just(pid), _variant(pid))
    )
)
def test_variants_pass_the_checker(case: tuple[str, dict[str, object]]) -> None:
    pid, params = case
    try:
        sheets = geomcad.solve(pid, **params).sheets()
    except geomcad.GeomcadError:
        assume(False)  # a variant the problem refuses is no layout case
        return
    for name, sheet in sheets:
        bad = layout_problems(sheet)
        seen = collections.Counter(f.kind for f in findings(sheet))
        assert not bad, f"{pid} {name!r} {params}: {bad}; findings {dict(seen)}"
