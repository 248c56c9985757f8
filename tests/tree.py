"""Test against the working tree: ``geomcad`` and ``geomcad_constructions`` are imported from
this checkout, whatever ``pip`` installed.

``python3 -m pytest`` finds ``geomcad`` in the checkout (the current directory comes first on
``sys.path``), but the problems live in ``constructions/`` and install as
``geomcad_constructions``: a non-editable install (``pip install .``, as ``scripts/setup.sh``
does) would leave the tests running the copy in site-packages, and an edit in ``constructions/``
untested until the next install. :func:`use_working_tree` maps the package name to the folder, the
way setuptools' ``package-dir`` does. The problem ids themselves are read from the installed
entry points; ``tests/test_tree.py`` checks that they are the ones ``pyproject.toml`` declares.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "geomcad_constructions"
FOLDER = ROOT / "constructions"


def use_working_tree() -> None:
    """Put the checkout first on ``sys.path`` and bind ``geomcad_constructions`` to its
    ``constructions/`` folder (before any test imports either)."""
    if sys.path[:1] != [str(ROOT)]:
        sys.path.insert(0, str(ROOT))
    loaded = sys.modules.get("geomcad")
    if loaded is not None and not Path(loaded.__file__ or "").is_relative_to(ROOT):
        raise RuntimeError(f"geomcad was imported from {loaded.__file__} before the tests started")
    for name in [m for m in sys.modules if m == PACKAGE or m.startswith(PACKAGE + ".")]:
        del sys.modules[name]
    spec = importlib.util.spec_from_file_location(
        PACKAGE, FOLDER / "__init__.py", submodule_search_locations=[str(FOLDER)]
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[PACKAGE] = module
    spec.loader.exec_module(module)
