"""Shared pytest options: ``--update-golden`` regenerates the golden sheets in ``tests/golden/``.

The tests run the installed package, as a user gets it: ``geomcad`` and ``geomcad_constructions``
are imported from what ``pip install .`` (or a developer's ``pip install -e .``) installed, never
from the checkout's folders (``tests/installed.py``).

Hypothesis runs derandomized, so CI and a developer's machine try the same examples: a failure is
reproducible, never a coin toss on one run (``HYPOTHESIS_PROFILE=explore`` draws new examples).
"""

from __future__ import annotations

import os

import pytest
from hypothesis import settings
from installed import NotInstalled, use_installed

try:
    use_installed()
except NotInstalled as exc:
    raise pytest.UsageError(str(exc)) from None

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
