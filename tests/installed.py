"""The tests run what pip installed, not the checkout's folders.

``python3 -m pytest`` puts the current folder first on ``sys.path``, so a plain run would import
``geomcad`` from the checkout whatever the wheel holds: a module or data file left out of the
package would pass every test and fail every user. :func:`use_installed` takes the checkout off
``sys.path`` (and off the path of every Python the tests start, by ``PYTHONSAFEPATH``) before any
test imports ``geomcad``, so ``geomcad`` and ``geomcad_constructions`` come from the install.

Two installs are accepted:

- ``pip install .`` (``sh scripts/setup.sh test``, as CI does): the install must be this checkout
  as it stands: a file whose installed copy differs from the tree's stops the run with the
  command to reinstall, so a stale install is never tested in the tree's name;
- ``pip install -e '.[test]'`` (a developer's editable install of *this* checkout): edits count
  at once. What an editable install cannot show, a file the wheel would leave out, is what
  ``tests/test_installed.py`` checks by building the wheel from the tree.
"""

from __future__ import annotations

import base64
import hashlib
import importlib.util
import json
import os
import sys
from importlib.metadata import PackageNotFoundError, distribution
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: The tree's package folders and the names they install under (pyproject.toml's package-dir).
PACKAGES = {"geomcad": ROOT / "geomcad", "geomcad_constructions": ROOT / "constructions"}

REINSTALL = "sh scripts/setup.sh test (or, to work on the code, pip install -e '.[test]')"


class NotInstalled(RuntimeError):
    """The package the tests would run is missing, stale, or another checkout's."""


def _off_path(entry: str) -> bool:
    """Whether a ``sys.path`` entry is the checkout itself ('' and '.' are the current folder)."""
    path = Path(entry or ".").resolve() if entry in ("", ".") else Path(entry).resolve()
    return path == ROOT


def tree_files() -> dict[str, Path]:
    """Every file of the package folders, by the name it installs under (``geomcad/...``)."""
    files: dict[str, Path] = {}
    for name, folder in PACKAGES.items():
        for path in folder.rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
                files[f"{name}/{path.relative_to(folder).as_posix()}"] = path
    return files


def _sha256(path: Path) -> str:
    digest = hashlib.sha256(path.read_bytes()).digest()
    return "sha256=" + base64.urlsafe_b64encode(digest).rstrip(b"=").decode()


def editable_of_this_checkout() -> bool:
    """Whether the installed ``geomcad`` is an editable install of this checkout (PEP 610)."""
    try:
        text = distribution("geomcad").read_text("direct_url.json")
    except PackageNotFoundError:
        return False
    if not text:
        return False
    url = json.loads(text)
    editable = bool(url.get("dir_info", {}).get("editable"))
    where = str(url.get("url", "")).removeprefix("file://")
    return editable and Path(where).resolve() == ROOT


def stale_files() -> list[str]:
    """The tree's files whose installed copy differs or is missing, by RECORD's hashes (empty
    for an editable install of this checkout, whose files are the tree's)."""
    if editable_of_this_checkout():
        return []
    record = distribution("geomcad").read_text("RECORD") or ""
    hashes = {line.split(",")[0]: line.split(",")[1] for line in record.splitlines() if line}
    return sorted(
        name
        for name, path in tree_files().items()
        if hashes.get(name) is not None and hashes[name] != _sha256(path)
    )


def use_installed() -> None:
    """Take the checkout off ``sys.path`` (here and in every child Python) and check that the
    installed ``geomcad`` is this checkout's; raise :class:`NotInstalled` saying what to run."""
    loaded = sys.modules.get("geomcad")
    if loaded is not None:
        raise NotInstalled(f"geomcad was imported from {loaded.__file__} before the tests started")
    sys.path[:] = [p for p in sys.path if not _off_path(p)]
    os.environ["PYTHONSAFEPATH"] = "1"  # python -m geomcad / python -c in a test: same rule
    importlib.invalidate_caches()
    for name in PACKAGES:
        if importlib.util.find_spec(name) is None:
            raise NotInstalled(f"{name} is not installed: {REINSTALL}")
    try:
        distribution("geomcad")
    except PackageNotFoundError as exc:
        raise NotInstalled(f"geomcad has no installed metadata: {REINSTALL}") from exc
    spec = importlib.util.find_spec("geomcad")
    origin = Path(spec.origin if spec and spec.origin else "").resolve()
    if origin.is_relative_to(ROOT) and not editable_of_this_checkout():
        raise NotInstalled(f"geomcad is imported from the checkout, not an install: {REINSTALL}")
    if not origin.is_relative_to(ROOT) and editable_of_this_checkout():
        raise NotInstalled(f"geomcad comes from {origin}, not this checkout: {REINSTALL}")
    if not origin.is_relative_to(ROOT):
        stale = stale_files()
        if stale:
            shown = ", ".join(stale[:3]) + (f" and {len(stale) - 3} more" if len(stale) > 3 else "")
            raise NotInstalled(
                f"the installed geomcad is not this checkout ({shown} differ): {REINSTALL}"
            )
