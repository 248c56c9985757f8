"""Every problem of this package wired to the functions its lazy references name, for mypy.

A spec declares its model type (``PROBLEM: Problem[Geometry]``), its build returns
``Build[Geometry]`` and its sheet functions take ``Solution[Geometry]``; but the spec reaches them
through :func:`~geomcad.problem.lazy` references (so that ``geomcad list`` imports neither numpy
nor the construction code), which mypy cannot follow. Here the same functions are handed to
:func:`dataclasses.replace`, whose arguments mypy checks against the problem's declared type: a
spec, build or sheet function whose model type disagrees with the others' is a mypy error.
``tests/test_typing.py`` checks that these are the functions the lazy references resolve to.

Nothing in the library imports this module; it imports every problem's construction and sheets.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from geomcad.problem import Problem


def wired() -> list[Problem[Any]]:
    """Each registered problem with its lazy references replaced by the functions they name."""
    from . import (
        p2013_1,
        p2013_2,
        p2013_3,
        p2013_4,
        p2013_5,
        p2013_6,
        p2013_7,
        p2013_8,
        p2013_9,
        p_kulisa,
        sheets_2013_1,
        sheets_2013_2,
        sheets_2013_3,
        sheets_2013_4,
        sheets_2013_5,
        sheets_2013_6,
        sheets_2013_6_kin,
        sheets_2013_7,
        sheets_2013_8,
        sheets_2013_9,
        sheets_kulisa,
        spec_2013_1,
        spec_2013_2,
        spec_2013_3,
        spec_2013_4,
        spec_2013_5,
        spec_2013_6,
        spec_2013_7,
        spec_2013_8,
        spec_2013_9,
        spec_kulisa,
    )

    return [
        replace(
            spec_2013_1.PROBLEM,
            build=p2013_1.build,
            draw=sheets_2013_1.sheets,
            scales=sheets_2013_1.scales,
        ),
        replace(
            spec_2013_2.PROBLEM,
            build=p2013_2.build,
            draw=sheets_2013_2.sheets,
            scales=sheets_2013_2.scales,
        ),
        replace(
            spec_2013_3.PROBLEM,
            build=p2013_3.build,
            draw=sheets_2013_3.sheets,
            scales=sheets_2013_3.scales,
        ),
        replace(
            spec_2013_4.PROBLEM,
            build=p2013_4.build,
            draw=sheets_2013_4.sheets,
            scales=sheets_2013_4.scales,
        ),
        replace(
            spec_2013_5.PROBLEM,
            build=p2013_5.build,
            draw=sheets_2013_5.sheets,
            scales=sheets_2013_5.scales,
        ),
        replace(
            spec_2013_6.PROBLEM,
            build=p2013_6.build,
            draw=sheets_2013_6.sheets,
            motion=sheets_2013_6_kin.motion,
            scales=sheets_2013_6.scales,
        ),
        replace(
            spec_2013_7.PROBLEM,
            build=p2013_7.build,
            draw=sheets_2013_7.sheets,
            scales=sheets_2013_7.scales,
        ),
        replace(
            spec_2013_8.PROBLEM,
            build=p2013_8.build,
            draw=sheets_2013_8.sheets,
            scales=sheets_2013_8.scales,
        ),
        replace(
            spec_2013_9.PROBLEM,
            build=p2013_9.build,
            draw=sheets_2013_9.sheets,
            scales=sheets_2013_9.scales,
        ),
        replace(
            spec_kulisa.PROBLEM,
            build=p_kulisa.build,
            draw=sheets_kulisa.sheets,
            motion=sheets_kulisa.motion,
            scales=sheets_kulisa.scales,
        ),
    ]
