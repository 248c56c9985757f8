"""Review 7 (issue 27): loads on one point (one link) act together, as their sum
(../shared/linkages.md, "Loads add up"); the order of the force analysis named each of them
like the sum (a press's "F_B = 10 820 Н" and "F_B = 250,0 Н" beside one F_B = 11 070 Н in the
table and on the drawing). Each is now named with its number among that point's loads and
their sum is stated after them; a point with one load keeps its plain name."""

from __future__ import annotations

from pathlib import Path

import pytest

import geomcad
from geomcad.linkage.analysis import analyse
from geomcad.sheet.linkage_forces import WORDS
from geomcad.sheet.views import step_text

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

FRICTION = """
[[load]]
point = "B"
value = 120.0
stroke = "both"

[[load]]
link = 3
moment = 4.0

[[load]]
link = 3
moment = -1.5
"""


@pytest.fixture(scope="module")
def solved(tmp_path_factory: pytest.TempPathFactory) -> object:
    text = (EXAMPLES / "slider-crank.toml").read_text(encoding="utf-8")
    head, sep, tail = text.partition("\n[[load]]")
    assert sep, "slider-crank.toml has a [[load]]"
    path = tmp_path_factory.mktemp("loads") / "press_two_loads.toml"
    path.write_text(head + FRICTION + sep + tail, encoding="utf-8")
    return geomcad.solve(str(path)).data


def test_loads_on_one_point_are_named_apart_and_summed(solved: object) -> None:
    an = analyse(solved)  # type: ignore[arg-type]
    assert an.forces
    seen_sum = 0
    for f in an.forces:
        steps = f.c.steps
        given = [st for st in steps if st.kind == "given_force" and dict(st.args)["at"] == "B"]
        sums = [st for st in steps if st.kind == "given_sum"]
        drawn = [a for ls in f.loads.values() for a in ls if a.kind == "given" and a.point == "B"]
        names = [str(dict(st.args)["F"]) for st in given]
        assert len(set(names)) == len(names), names  # never two loads of one name
        if len(given) < 2:
            assert not sums and all(n == "F_{B}" for n in names)
            continue
        seen_sum += 1
        (total,) = sums
        args = dict(total.args)
        assert args["terms"] == " + ".join(names)
        (F,) = drawn
        assert F.force is not None
        assert float(args["value"]) == pytest.approx(F.force.norm, rel=1e-12)
        assert float(args["value"]) == pytest.approx(
            sum(float(dict(st.args)["value"]) for st in given), rel=1e-9
        )  # both against the slider's velocity: their magnitudes add
        assert total.name in f.order
        assert "F_{B}^{(1)}" in names and "F_{B}^{(2)}" in names
        text = step_text(total, WORDS)
        assert text.startswith("F_{B} = F_{B}^{(1)} + F_{B}^{(2)} = "), text
    assert seen_sum, "no position where both loads act"


def test_moments_on_one_link_are_named_apart_and_summed(solved: object) -> None:
    an = analyse(solved)  # type: ignore[arg-type]
    assert an.forces
    for f in an.forces:
        parts = [st for st in f.c.steps if st.kind == "given_moment"]
        (total,) = [st for st in f.c.steps if st.kind == "given_moment_sum"]
        names = [str(dict(st.args)["M"]) for st in parts]
        assert names == ["M_{3}^{(1)}", "M_{3}^{(2)}"]
        assert float(dict(total.args)["value"]) == pytest.approx(2.5, rel=1e-12)
