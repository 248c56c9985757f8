#!/bin/sh
# Install geomcad, and whatever a fresh Debian machine lacks for it.
#   sh scripts/setup.sh        the library, the `geomcad` command and the PDF/PNG renderer
#   sh scripts/setup.sh test   the same, plus the test tools (pytest, hypothesis, ruff, mypy, pypdf)
#                              and a second SVG renderer (rsvg-convert) and pdftoppm for the tests,
#                              and headless Chromium with its driver for the interactive page's test
# The lettering font (osifont) ships inside the package, so no font is installed system-wide.
set -eu
extra="${1:-}"
need=""
ldconfig -p 2>/dev/null | grep -q 'libcairo\.so\.2' || need="$need libcairo2"
if [ "$extra" = test ]; then
    command -v rsvg-convert >/dev/null 2>&1 || need="$need librsvg2-bin"
    command -v pdftoppm >/dev/null 2>&1 || need="$need poppler-utils"
    command -v chromium >/dev/null 2>&1 || need="$need chromium"
    command -v chromedriver >/dev/null 2>&1 || need="$need chromium-driver"
fi
if [ -n "$need" ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $need >/dev/null
    else
        echo "setup: geomcad needs the Debian packages:$need (sudo apt-get install$need)" >&2
    fi
fi
venv_hint() {
    echo "setup: make a virtual environment, enter it and run this again:" >&2
    echo "    python3 -m venv .venv && . .venv/bin/activate && sh scripts/setup.sh $extra" >&2
    echo "  (if python3 -m venv fails, Debian lacks its venv module: sudo apt-get install python3-venv)" >&2
}
if ! command -v python3 >/dev/null 2>&1; then
    echo "setup: python3 is missing (Debian: sudo apt-get install python3 python3-venv)" >&2
    exit 1
fi
if ! python3 -m pip --version >/dev/null 2>&1; then
    echo "setup: $(command -v python3) has no pip." >&2
    venv_hint
    echo "  (or give the system Python its pip: sudo apt-get install python3-pip)" >&2
    exit 1
fi
target=.
[ -n "$extra" ] && target=".[$extra]"
if ! python3 -m pip install -q "$target"; then
    echo "setup: pip could not install geomcad (see above). If it says \"externally-managed-environment\"," >&2
    echo "  this Python's packages belong to the system (PEP 668)." >&2
    venv_hint
    exit 1
fi
