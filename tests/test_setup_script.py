"""scripts/setup.sh says what to do when pip is missing or refuses to install (PEP 668), with
stand-ins for python3, ldconfig and apt-get so that nothing is installed."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

FAKE_PYTHON = """#!/bin/sh
case "$*" in
    "-m pip --version") exit "$FAKE_PIP_STATUS" ;;
    *) echo "error: externally-managed-environment" >&2; exit 1 ;;
esac
"""


def _run(tmp_path: Path, pip_status: int) -> subprocess.CompletedProcess[str]:
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    for name, text in {
        "python3": FAKE_PYTHON,
        "ldconfig": "#!/bin/sh\necho 'libcairo.so.2 (libc6,x86-64) => /lib/libcairo.so.2'\n",
        "apt-get": "#!/bin/sh\nexit 1\n",
        "rsvg-convert": "#!/bin/sh\n",
        "pdftoppm": "#!/bin/sh\n",
    }.items():
        path = bin_dir / name
        path.write_text(text)
        path.chmod(0o755)
    env = {**os.environ, "PATH": f"{bin_dir}:/usr/bin:/bin", "FAKE_PIP_STATUS": str(pip_status)}
    return subprocess.run(
        ["sh", "scripts/setup.sh", "test"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )


@pytest.mark.parametrize(("pip_status", "words"), [(1, "python3-pip"), (0, "PEP 668")])
def test_setup_says_to_make_a_virtual_environment(
    tmp_path: Path, pip_status: int, words: str
) -> None:
    proc = _run(tmp_path, pip_status)
    assert proc.returncode == 1
    assert words in proc.stderr
    assert (
        "python3 -m venv .venv && . .venv/bin/activate && sh scripts/setup.sh test" in proc.stderr
    )
    assert "python3-venv" in proc.stderr
