"""The step recorder: names, branch rules, errors that name the step, the protocol."""

from __future__ import annotations

import pytest

from geomcad.construction import Construction, left_of, nearest, right_of
from geomcad.errors import DegenerateInput, NoIntersection, ParallelLines
from geomcad.geom import Vec


def two_circles() -> tuple[Construction, object, object]:
    c = Construction("t")
    a = c.point("A", (0, 0))
    b = c.point("B", (1, 0))
    return c, c.circle("ka", a, 1.0), c.circle("kb", b, 1.0)


def test_branch_rules_pick_explicitly() -> None:
    c, ka, kb = two_circles()
    up = c.intersect("P", ka, kb, left_of((0, 0), (1, 0), "AB"))  # type: ignore[arg-type]
    down = c.intersect("Q", ka, kb, right_of((0, 0), (1, 0), "AB"))  # type: ignore[arg-type]
    near = c.intersect("R", ka, kb, nearest((0, -5), "S"))  # type: ignore[arg-type]
    assert up.y > 0 > down.y and near == down
    assert c.step("P").rule == "left of AB"


def test_empty_intersection_names_the_step() -> None:
    c = Construction("t")
    a = c.point("A", (0, 0))
    far = c.point("F", (5, 0))
    ka, kf = c.circle("ka", a, 1.0), c.circle("kf", far, 1.0)
    with pytest.raises(
        NoIntersection, match=r'step "X = circle ka ∩ circle kf": the circles do not'
    ):
        c.intersect("X", ka, kf)


def test_rule_that_keeps_nothing_says_so() -> None:
    c, ka, kb = two_circles()
    with pytest.raises(NoIntersection, match="no intersection point is left of far away"):
        c.intersect("X", ka, kb, left_of((0, 10), (1, 10), "far away"))  # type: ignore[arg-type]


def test_parallel_lines_and_degenerate_input_name_the_step() -> None:
    c = Construction("t")
    a, b = c.point("A", (0, 0)), c.point("B", (1, 0))
    la = c.line("la", a, (1, 0), "x axis")
    lb = c.line("lb", b + Vec(0, 1), (1, 0), "y = 1")
    with pytest.raises(ParallelLines, match='step "X = line la ∩ line lb"'):
        c.intersect("X", la, lb)
    with pytest.raises(DegenerateInput, match='step "bad = line AA"'):
        c.line_through("bad", a, a)


def test_duplicate_step_names_are_refused() -> None:
    c = Construction("t")
    c.point("A", (0, 0))
    with pytest.raises(ValueError, match="used twice"):
        c.point("A", (1, 0))


def test_trace_has_one_line_per_step() -> None:
    c, ka, kb = two_circles()
    c.intersect("P", ka, kb)  # type: ignore[arg-type]
    lines = c.trace().splitlines()
    assert len(lines) == 1 + len(c.steps)
    assert lines[-1].startswith("5. P = circle ka ∩ circle kb")
    assert lines[-1].endswith("→ (0.500000, 0.866025)")
