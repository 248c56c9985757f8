"""The one sweep kernel (geomcad.kinematics.chain): blocks and output rows, the two-point array
helpers that refuse a sliding pair, and the dynamics' analogues read off the kernel."""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import geomcad.kinematics.chain as chain_module
from geomcad import documents
from geomcad.dynamics.analogues import linear
from geomcad.errors import DegenerateInput, ParameterError
from geomcad.kinematics import angular_acceleration, angular_velocity
from geomcad.kinematics.chain import RRR, Chain, Crank, run
from geomcad.linkage import parse, sweep
from geomcad.linkage.sweep import plan

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.toml"))
LINKAGES = [p for p in EXAMPLES if documents.kind_of(tomllib.loads(p.read_text())) == "linkage"]


def files() -> list[dict[str, Any]]:
    from test_linkage import ODD

    return [tomllib.loads(p.read_text()) for p in LINKAGES] + [
        copy.deepcopy(d) for d in ODD.values()
    ]


@pytest.mark.parametrize("order", [0, 1, 2])
def test_one_allocation_holds_every_output(order: int, monkeypatch: pytest.MonkeyPatch) -> None:
    """The rows counted from the plan are the rows the kernel fills (no array allocated on the
    side), for every group kind, guide and point of the examples."""
    made: list[Any] = []
    real = chain_module._Out

    class Spy(real):  # type: ignore[misc,valid-type]
        def __init__(self, n: int, rows: int) -> None:
            super().__init__(n, rows)
            made.append(self)

    monkeypatch.setattr(chain_module, "_Out", Spy)
    for data in files():
        made.clear()
        run(plan(parse(data)), np.linspace(0.0, 6.0, 5), order)
        assert made[0].used == made[0].buf.shape[0]


def test_blocks_do_not_change_the_numbers() -> None:
    phi = np.linspace(0.0, 2.0 * math.pi, 101)
    for data in files():
        ch = plan(parse(data))
        ref, got = run(ch, phi, 2), run(ch, phi, 2, block=7)
        for table in ("pos", "vel", "acc", "omega", "eps", "v_rel", "a_cor", "slide"):
            a, b = getattr(ref, table), getattr(got, table)
            assert a.keys() == b.keys()
            for k in a:
                assert np.array_equal(a[k], b[k]), (table, k)


def test_an_empty_sweep_has_every_name() -> None:
    lk = parse(tomllib.loads(LINKAGES[0].read_text()))
    st = sweep(lk, np.array([]))
    assert all(v.shape == (0, 2) for v in st.pos.values()) and st.pos


def slotted_lever() -> dict[str, Any]:
    """The issue's case: crank 0.1 m, pivots 0.3 m apart, φ = 30°, ω1 = 10; the point P of the
    lever at the pin's place at 30° (|CA|² = r² + d² + 2rd·sin φ)."""
    ca = math.sqrt(0.1**2 + 0.3**2 + 2 * 0.1 * 0.3 * 0.5)
    return {
        "frame": {"O": [0.0, 0.0], "C": [0.0, -0.3]},
        "drive": {"pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0, "phi": [30.0]},
        "group": [{"kind": "RPR", "links": [2, 3], "slider": "A", "pivot": "C"}],
        "point": [{"name": "P", "link": 3, "from": "C", "toward": "A", "along": ca}],
    }


def test_the_two_point_helpers_refuse_a_sliding_pair() -> None:
    st = sweep(parse(slotted_lever()), [math.radians(30.0)])
    C, A, P = "C", "A", "P"
    p, vp, ap = st.pos[C], st.vel[C], st.acc[C]
    assert np.allclose(st.pos[P], st.pos[A], atol=1e-15)
    # through the block's joint A the Coriolis term is lost (19.985 rad/s²): no answer at all
    with pytest.raises(ParameterError, match="no point of the link"):
        angular_acceleration(p, vp, ap, st.pos[A], st.vel[A], st.acc[A])
    with pytest.raises(ParameterError, match="no point of the link"):
        angular_velocity(p, vp, st.pos[A], st.vel[A])
    # through the lever's own point under the block: the right ε3 and ω3
    eps = angular_acceleration(p, vp, ap, st.pos[P], st.vel[P], st.acc[P])
    assert eps[0] == pytest.approx(12.29858562, rel=1e-8) == st.eps[3][0]
    assert angular_velocity(p, vp, st.pos[P], st.vel[P])[0] == pytest.approx(st.omega[3][0])
    with pytest.raises(ParameterError, match="must not coincide"):
        angular_velocity(p, vp, p, vp)


def test_linear_analogues_refuse_a_mechanism_that_is_not_linear() -> None:
    four_bar = Chain(
        {"O": (0.0, 0.0), "Q": (0.3, 0.0)},
        Crank("O", "A", 0.1),
        (RRR("B", ("A", "Q"), (0.3, 0.25), 1, (2, 3), "B", "b"),),
    )
    with pytest.raises(DegenerateInput, match="not linear"):
        linear(four_bar, lambda st: {"x": st.pos["B"][:, 0]})
