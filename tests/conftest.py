"""Shared pytest options: ``--update-golden`` regenerates the golden sheets in ``tests/golden/``.

The tests run the working tree: ``geomcad`` and ``geomcad_constructions`` (the ``constructions/``
folder) are imported from this checkout, not from an installed copy (``tests/tree.py``).

Hypothesis runs derandomized, so CI and a developer's machine try the same examples: a failure is
reproducible, never a coin toss on one run (``HYPOTHESIS_PROFILE=explore`` draws new examples).
"""

from __future__ import annotations

import os

import pytest
from hypothesis import settings
from tree import use_working_tree

use_working_tree()

settings.register_profile("ci", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="write the golden sheets in tests/golden/ from the current code instead of comparing",
    )


@pytest.fixture
def update_golden(request: pytest.FixtureRequest) -> bool:
    """Whether the run was asked to rewrite the golden files (``pytest --update-golden``)."""
    return bool(request.config.getoption("--update-golden"))
