"""Vulcanizer-lid mechanism: structural analysis and the pusher's dead position.

- The mechanism is data (``geomcad.structure``): links, and the revolute, prismatic and higher
  pairs where they sit.
- Chebyshev's W = 3n − 2p₅ − p₄, with the roller's free spin (a local mobility) and the
  redundant constraints found from the pairs' velocity conditions.
- The higher pair is replaced by a substitute link at the centres of curvature: W is unchanged
  (2 and 2); the seed's "2 before, 1 after" counts the roller once only.
- Assur groups with their class, order and kind.
- The zero-velocity positions (ML ⊥ MO) are built as the pusher path ∩ the circle of radius e
  about O that the slot always touches, and checked against θ1 = ψ ± arccos(h/e) and the sign
  changes of V_T/ω1 over a turn.
- Sheet (A2): the schemes before and after the replacement, the groups drawn apart, the dead
  position with its velocity plan (V_M1 = −V_M6M1), the plan at the given θ1, and tables.
- Set ``n``, ``p5``, ``p4``, ``local`` to count another mechanism.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build lives in p2013_1.py, the sheet and its scales in sheets_2013_1.py; both load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, erratum, lazy, rounded

if TYPE_CHECKING:
    from .p2013_1 import Geometry

ID = "2013-1"

PARAMS = (
    Param(
        "n",
        7,
        "number of moving links (set a count to analyse another mechanism)",
        integer=True,
        ge=0,
    ),
    Param("p5", 9, "number of lower pairs, class 5", integer=True, ge=0),
    Param("p4", 1, "number of higher pairs, class 4", integer=True, ge=0),
    Param("local", 1, "number of local mobilities (a roller's free spin)", integer=True, ge=0),
    Param("e", 0.1, "offset of the slot's centre line from O (signed, ≠ 0)", "m"),
    Param("psi_deg", 90.0, "direction ψ of the pusher path", "deg", turn=True),
    Param("h", -0.05, "signed distance h of the pusher path from O", "m"),
    Param("theta1_deg", 0.0, "direction θ1 of the slot (the lever's position)", "deg", turn=True),
)

RESULTS = (
    ResultSpec("W_formal", "1", "Chebyshev's W = 3n − 2p5 − p4 (local mobility included)"),
    ResultSpec("W_local", "1", "local mobilities (the roller's free spin)"),
    ResultSpec("W_true", "1", "W_formal + q − W_local: the mobility of the motion that matters"),
    ResultSpec("W_after_replacement", "1", "W after the standard replacement of the higher pair"),
    ResultSpec("W_after_seed", "1", "W by the seed's route: roller taken out, then replacement"),
    ResultSpec("zero_theta1_deg", "deg", "slot directions θ1 at which V_T = 0 (ML ⊥ MO)"),
    ResultSpec("VT_over_omega1", "m", "V_T/ω1 at θ1, signed along the pusher path"),
)

SEED = {
    "W_formal": rounded(2, 0, "W = 3·7 − 2·9 − 1 = 2"),
    "W_after_replacement": erratum(
        1.0,
        "the seed's count after the replacement, 3·7 − 2·10 = 1, is made with the roller taken "
        "out (it becomes the slider block), while its count before, 3·7 − 2·9 − 1 = 2, keeps the "
        "roller's free spin; the standard replacement adds a link and two lower pairs: "
        "3·8 − 2·11 = 2, W unchanged, with one local mobility in both counts (W_true = 1)",
        "после замены W = 3·7 − 2·10 = 1",
    ),
    "W_after_seed": rounded(1, 0, "W = 3·7 − 2·10 = 1"),
}

PROBLEM: Problem[Geometry] = Problem(
    id=ID,
    title="Vulcanizer-lid mechanism: structure and the pusher's dead position",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p2013_1:build", __package__),
    draw=lazy(".sheets_2013_1:sheets", __package__),
    scales=lazy(".sheets_2013_1:scales", __package__),
)
