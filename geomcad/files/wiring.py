"""Each file kind's problem wired to the sheet functions its lazy references name, for mypy.

As ``geomcad_constructions.wiring`` does for the seed problems: a kind's ``make_problem`` reaches
its sheets through :func:`~geomcad.problem.lazy` references (so that a solve imports no sheet),
which mypy cannot follow; here the same functions are handed to :func:`dataclasses.replace`,
whose arguments mypy checks against the problem's model type. ``tests/test_typing.py`` checks
that these are the functions the lazy references resolve to. Nothing imports this module.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from geomcad.problem import Problem

    from .cam import CamDesign
    from .gears import GearsDesign


def cam(problem: Problem[CamDesign]) -> Problem[CamDesign]:
    """A cam file's problem (``cam.make_problem``) with its sheet functions themselves."""
    from . import cam_sheets

    return replace(problem, draw=cam_sheets.sheets, scales=cam_sheets.scales)


def gears(problem: Problem[GearsDesign]) -> Problem[GearsDesign]:
    """A gear file's problem (``gears.make_problem``) with its sheet functions themselves."""
    from . import gears_sheets

    return replace(problem, draw=gears_sheets.sheets, scales=gears_sheets.scales)
