"""geomcad.structure: Chebyshev's W for textbook mechanisms, local mobilities and redundant
constraints from the pairs' velocities, higher-pair replacement, Assur groups."""

from __future__ import annotations

import doctest
import importlib
import math

import pytest

from geomcad.errors import ConstructionError, DegenerateInput, ParameterError
from geomcad.geom import Vec
from geomcad.structure import (
    Link,
    Mechanism,
    Pair,
    assur_groups,
    chebyshev,
    higher,
    local_mobilities,
    mobility,
    prismatic,
    remove_local_mobilities,
    replace_higher_pairs,
    revolute,
)


def links(*ids: str) -> tuple[Link, ...]:
    return tuple(Link(i) for i in ids)


def four_bar() -> Mechanism:
    return Mechanism(
        links("1", "2", "3"),
        (
            revolute("O", "0", "1", (0, 0)),
            revolute("A", "1", "2", (0.02, 0.05)),
            revolute("B", "2", "3", (0.2, 0.12)),
            revolute("C", "3", "0", (0.25, 0.0)),
        ),
    )


def slider_crank() -> Mechanism:
    return Mechanism(
        links("1", "2", "3"),
        (
            revolute("O", "0", "1", (0, 0)),
            revolute("A", "1", "2", (0.03, 0.04)),
            revolute("B", "2", "3", (0.2, 0.01)),
            prismatic("B0", "3", "0", (0.2, 0.01), (1, 0)),
        ),
    )


def cam_roller() -> Mechanism:
    """Disc cam 1 on O, roller 2 on the translating follower 3 (offset guide along y)."""
    k = Vec(0.01, 0.05)  # the contact
    c_r = Vec(0.014, 0.062)  # the roller's centre
    n = (c_r - k).unit()
    return Mechanism(
        links("1", "2", "3"),
        (
            revolute("O", "0", "1", (0, 0)),
            revolute("C", "2", "3", c_r),
            prismatic("G", "3", "0", c_r, (0, 1)),
            higher("K", "1", "2", k, n, centre_a=k - n * 0.03, centre_b=c_r, kind="cam"),
        ),
    )


def _mesh(name: str, a: str, b: str, ca: Vec, cb: Vec, p: Vec) -> Pair:
    """An involute mesh at pitch point p: the line of action at 20° to the common tangent; the
    profiles' centres of curvature are the base circles' points of tangency on it."""
    d = (cb - ca).unit()
    alpha = math.radians(20.0)
    n = d.perp() * math.cos(alpha) + d * math.sin(alpha)
    feet = [p + n * (c - p).dot(n) for c in (ca, cb)]
    return higher(name, a, b, p, n, feet[0], feet[1], kind="gear")


def planetary(planets: int = 1) -> Mechanism:
    """One stage: sun 1 (r 20 mm), planets (r 15 mm) on carrier H, the ring on the frame."""
    o = Vec(0.0, 0.0)
    r1, r2 = 0.02, 0.015
    ls = [Link("1"), Link("H")]
    pairs = [revolute("O1", "0", "1", o), revolute("OH", "0", "H", o)]
    for i in range(planets):
        u = Vec.polar(1.0, 2.0 * math.pi * i / planets + 0.3)
        c = u * (r1 + r2)
        pid = f"2{chr(ord('a') + i)}"
        ls.append(Link(pid))
        pairs += [
            revolute(f"C{pid}", "H", pid, c),
            _mesh(f"S{pid}", "1", pid, o, c, u * r1),
            _mesh(f"R{pid}", pid, "0", c, o, u * (r1 + 2 * r2)),
        ]
    return Mechanism(tuple(ls), tuple(pairs))


def two_stage_planetary() -> Mechanism:
    """Two stages in series: carrier H1 of the first carries the second stage's sun."""
    o = Vec(0.0, 0.0)
    r1, r2 = 0.02, 0.015
    u, w = Vec(1.0, 0.0), Vec(0.0, 1.0)
    c2, c4 = u * (r1 + r2), w * (r1 + r2)
    return Mechanism(
        links("1", "2", "3", "4", "5"),
        (
            revolute("O1", "0", "1", o),
            revolute("O3", "0", "3", o),
            revolute("O5", "0", "5", o),
            revolute("C2", "3", "2", c2),
            revolute("C4", "5", "4", c4),
            _mesh("K12", "1", "2", o, c2, u * r1),
            _mesh("K20", "2", "0", c2, o, u * (r1 + 2 * r2)),
            _mesh("K34", "3", "4", o, c4, w * r1),
            _mesh("K40", "4", "0", c4, o, w * (r1 + 2 * r2)),
        ),
    )


def six_bar() -> Mechanism:
    """Crank 1, coupler 2, rocker 3 (a four-bar), then link 4 and slider 5 (as in 2013-6)."""
    return Mechanism(
        links("1", "2", "3", "4", "5"),
        (
            revolute("O1", "0", "1", (0, 0)),
            revolute("A", "1", "2", (0.05, 0.04)),
            revolute("B", "2", "3", (0.3, 0.25)),
            revolute("O2", "3", "0", (0.35, 0.0)),
            revolute("B'", "3", "4", (0.32, 0.15)),
            revolute("C", "4", "5", (0.6, 0.3)),
            prismatic("C0", "5", "0", (0.6, 0.3), (1, 0)),
        ),
    )


def triad() -> Mechanism:
    """Crank 1 and a class III group: base link 3 with three binary links 2, 4, 5."""
    return Mechanism(
        links("1", "2", "3", "4", "5"),
        (
            revolute("O", "0", "1", (0, 0)),
            revolute("A", "1", "2", (0.1, 0.05)),
            revolute("P1", "2", "3", (0.3, 0.2)),
            revolute("P2", "3", "4", (0.45, 0.1)),
            revolute("P3", "3", "5", (0.35, 0.35)),
            revolute("F4", "4", "0", (0.6, -0.05)),
            revolute("F5", "5", "0", (0.5, 0.55)),
        ),
    )


def class_four() -> Mechanism:
    """Crank 1 and a class IV group: the contour 2-3-4-5, outer pairs on 2 and 4."""
    return Mechanism(
        links("1", "2", "3", "4", "5"),
        (
            revolute("O", "0", "1", (0, 0)),
            revolute("A", "1", "2", (0.08, 0.06)),
            revolute("J23", "2", "3", (0.2, 0.25)),
            revolute("J25", "2", "5", (0.25, 0.02)),
            revolute("J34", "3", "4", (0.45, 0.3)),
            revolute("J45", "4", "5", (0.5, 0.05)),
            revolute("F", "4", "0", (0.65, 0.2)),
        ),
    )


# -- Chebyshev's count -------------------------------------------------------------------------


def test_chebyshev_counts() -> None:
    assert chebyshev(3, 4, 0) == 1
    assert chebyshev(7, 9, 1) == 2
    assert chebyshev(8, 11, 0) == 2
    assert chebyshev(7, 10, 0) == 1


@pytest.mark.parametrize(("n", "p5", "p4"), [(-1, 0, 0), (3, -4, 0), (3, 4, -1)])
def test_negative_counts_are_parameter_errors(n: int, p5: int, p4: int) -> None:
    with pytest.raises(ParameterError, match="must be ≥ 0"):
        chebyshev(n, p5, p4)


def test_counts_must_be_whole() -> None:
    with pytest.raises(ParameterError, match="whole"):
        chebyshev(3, 4.0, 0)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("build", "counts", "formal", "local", "q", "true"),
    [
        (four_bar, (3, 4, 0), 1, 0, 0, 1),
        (slider_crank, (3, 4, 0), 1, 0, 0, 1),
        (cam_roller, (3, 3, 1), 2, 1, 0, 1),
        (two_stage_planetary, (5, 5, 4), 1, 0, 0, 1),
        (planetary, (3, 3, 2), 1, 0, 0, 1),
        (lambda: planetary(3), (5, 5, 6), -1, 0, 2, 1),
        (six_bar, (5, 7, 0), 1, 0, 0, 1),
    ],
    ids=["four-bar", "slider-crank", "cam-roller", "two-stage", "planetary", "3-planets", "6-bar"],
)
def test_textbook_mechanisms(
    build: object, counts: tuple[int, int, int], formal: int, local: int, q: int, true: int
) -> None:
    m = mobility(build())  # type: ignore[operator]
    assert (m.n, m.p5, m.p4) == counts
    assert (m.formal, m.w_local, m.redundant, m.true) == (formal, local, q, true)


def test_the_roller_spins_about_its_centre() -> None:
    (lm,) = local_mobilities(cam_roller())
    assert lm.link == "2"
    assert lm.centre is not None
    assert lm.centre.dist(Vec(0.014, 0.062)) < 1e-12
    assert "turns alone" in lm.describe()


def test_a_parallelogram_with_a_second_coupler_has_one_redundant_constraint() -> None:
    m = mobility(
        Mechanism(
            links("1", "2", "3", "4"),
            (
                revolute("A0", "0", "1", (0, 0)),
                revolute("A", "1", "2", (0, 1)),
                revolute("B", "2", "3", (2, 1)),
                revolute("B0", "3", "0", (2, 0)),
                revolute("E0", "0", "4", (1, 0)),
                revolute("E", "4", "2", (1, 1)),
            ),
        )
    )
    assert (m.formal, m.redundant, m.true) == (0, 1, 1)
    assert "q = 1" in m.report()


def test_a_dangling_slider_is_a_local_slide() -> None:
    mech = Mechanism(
        links("1", "2"),
        (revolute("O", "0", "1", (0, 0)), prismatic("G", "2", "1", (0.1, 0), (1, 0))),
    )
    (lm,) = local_mobilities(mech)
    assert lm.centre is None and lm.direction is not None and "slides" in lm.describe()


# -- replacement and removal -------------------------------------------------------------------


@pytest.mark.parametrize("build", [cam_roller, two_stage_planetary, planetary])
def test_replacement_keeps_w(build: object) -> None:
    mech = build()  # type: ignore[operator]
    before = mobility(mech)
    rep = replace_higher_pairs(mech)
    after = mobility(rep.mechanism)
    assert after.p4 == 0
    assert after.n == before.n + before.p4
    assert after.p5 == before.p5 + 2 * before.p4
    assert (after.formal, after.true, after.w_local) == (before.formal, before.true, before.w_local)
    assert after.instantaneous == before.instantaneous
    assert len(rep.substitutes) == before.p4


def test_a_straight_profile_becomes_a_prismatic_pair() -> None:
    m = Vec(0.05, 0.1)
    mech = Mechanism(
        links("1", "2"),
        (
            revolute("O", "0", "1", (0, 0)),
            prismatic("T", "2", "0", m, (0, 1)),
            higher("K", "2", "1", m - Vec(0, 0.01), (0, 1), centre_a=m, kind="slot"),
        ),
    )
    rep = replace_higher_pairs(mech)
    (s,) = rep.substitutes
    a, b = rep.mechanism.pair(s.pair_a), rep.mechanism.pair(s.pair_b)
    assert (a.kind, b.kind) == ("R", "P")
    assert a.at == m and b.axis is not None and abs(b.axis.y) < 1e-15
    assert mobility(rep.mechanism).true == mobility(mech).true == 1


def test_removing_the_roller_before_and_after_the_replacement_agree() -> None:
    mech = cam_roller()
    first = replace_higher_pairs(remove_local_mobilities(mech).mechanism).mechanism
    after = remove_local_mobilities(replace_higher_pairs(mech).mechanism)
    assert after.removed == ("2",)
    for m in (first, after.mechanism):
        mb = mobility(m)
        assert (mb.n, mb.p5, mb.p4, mb.formal, mb.w_local) == (3, 4, 0, 1, 0)
    d = assur_groups(after.mechanism, ["1"])
    (g,) = d.groups
    assert (g.group_class, g.order, g.kind_no) == (2, 2, 2)


def test_a_local_mobility_that_is_no_roller_is_not_removed() -> None:
    mech = Mechanism(
        links("1", "2"),
        (revolute("O", "0", "1", (0, 0)), prismatic("G", "2", "1", (0.1, 0), (1, 0))),
    )
    with pytest.raises(ConstructionError, match="not a roller"):
        remove_local_mobilities(mech)


# -- Assur groups ------------------------------------------------------------------------------


def test_six_bar_groups() -> None:
    d = assur_groups(six_bar(), ["1"])
    assert [g.links for g in d.groups] == [("2", "3"), ("4", "5")]
    assert [(g.group_class, g.order, g.kind) for g in d.groups] == [(2, 2, "RRR"), (2, 2, "RRP")]
    assert [g.kind_no for g in d.groups] == [1, 2]
    assert d.mechanism_class == 2
    assert d.formula() == "I(0, 1) → II(2, 3) → II(4, 5)"
    assert set(d.groups[0].external) == {"A", "O2"} and d.groups[0].internal == ("B",)


def test_class_three_triad() -> None:
    d = assur_groups(triad(), ["1"])
    (g,) = d.groups
    assert sorted(g.links) == ["2", "3", "4", "5"]
    assert (g.group_class, g.order, g.roman, g.kind_no) == (3, 3, "III", None)
    assert "class III, order 3" in g.describe()


def test_class_four_group() -> None:
    d = assur_groups(class_four(), ["1"])
    (g,) = d.groups
    assert (g.group_class, g.order) == (4, 2)
    assert d.mechanism_class == 4


def test_four_bar_is_one_dyad_whichever_link_drives() -> None:
    for driver in ("1", "3"):
        d = assur_groups(four_bar(), [driver])
        (g,) = d.groups
        assert g.kind == "RRR" and g.group_class == 2


def test_groups_need_lower_pairs_one_driver_and_no_local_mobility() -> None:
    with pytest.raises(ConstructionError, match="replace the higher pairs"):
        assur_groups(cam_roller(), ["1"])
    with pytest.raises(ConstructionError, match="local mobilities out"):
        assur_groups(replace_higher_pairs(cam_roller()).mechanism, ["1"])
    with pytest.raises(ConstructionError, match="needs 1 different driving"):
        assur_groups(six_bar(), ["1", "3"])
    with pytest.raises(ConstructionError, match="no pair with the frame"):
        assur_groups(six_bar(), ["2"])
    with pytest.raises(ConstructionError, match="redundant"):
        assur_groups(replace_higher_pairs(planetary(3)).mechanism, ["1"])


def test_a_chain_with_no_small_group_is_refused() -> None:
    with pytest.raises(ConstructionError, match="no group of zero mobility of at most 2"):
        assur_groups(triad(), ["1"], max_links=2)


def test_three_prismatic_pairs_make_no_dyad() -> None:
    """A dyad PPP counts 3·2 = 2·3 but cannot turn into place: the rigidity check refuses it."""
    mech = Mechanism(
        links("1", "2", "3"),
        (
            prismatic("G1", "1", "0", (0, 0), (1, 0)),
            prismatic("G2", "1", "2", (0.1, 0.05), (0, 1)),
            prismatic("G3", "2", "3", (0.2, 0.1), (1, 1)),
            prismatic("G4", "3", "0", (0.3, 0.0), (1, -0.5)),
        ),
    )
    # formally W = 9 − 8 = 1, but a chain of sliders cannot turn: its turn is free
    m = mobility(mech)
    assert m.formal == 1 and m.true > 1
    with pytest.raises(ConstructionError):
        assur_groups(mech, ["1"])


# -- the model's checks ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("make", "words"),
    [
        (lambda: Mechanism(links("1", "1"), ()), "used twice"),
        (lambda: Mechanism(links("0"), ()), "frame"),
        (lambda: Mechanism(links("1"), (revolute("O", "0", "9", (0, 0)),)), "unknown link"),
        (lambda: Mechanism(links("1"), (revolute("O", "1", "1", (0, 0)),)), "to itself"),
        (
            lambda: Mechanism(
                links("1"), (revolute("O", "0", "1", (0, 0)), revolute("O", "0", "1", (1, 0)))
            ),
            "pair names",
        ),
        (lambda: higher("K", "1", "2", (0, 0), (0, 1)), "both profiles are straight"),
        (lambda: higher("K", "1", "2", (0, 0), (0, 1), centre_a=(1, 1)), "off the common normal"),
        (lambda: higher("K", "1", "2", (0, 0), (0, 0), centre_a=(0, 1)), "common normal"),
        (lambda: higher("K", "1", "2", (0, 0), (0, 1), (0, 1), kind="R"), "not a higher pair"),
        (lambda: prismatic("G", "1", "0", (0, 0), (0, 0)), "direction"),
        (lambda: four_bar().pair("Z"), "no pair"),
        (lambda: four_bar().link("9"), "no moving link"),
    ],
)
def test_bad_schemes(make: object, words: str) -> None:
    with pytest.raises(DegenerateInput, match=words):
        make()  # type: ignore[operator]


def test_a_loose_link_is_named() -> None:
    mech = Mechanism(links("1", "2"), (revolute("O", "0", "1", (0, 0)),))
    with pytest.raises(ConstructionError, match="links 2 are not joined to the frame"):
        mobility(mech)


@pytest.mark.parametrize("module", ["model", "mobility", "replace", "assur"])
def test_docstring_examples(module: str) -> None:
    result = doctest.testmod(importlib.import_module(f"geomcad.structure.{module}"))
    assert result.failed == 0
