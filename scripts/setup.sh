#!/bin/sh
# Install geomcad, and whatever a fresh Debian machine lacks for it.
#   sh scripts/setup.sh        the library, the `geomcad` command and the PDF/PNG renderer
#   sh scripts/setup.sh test   the same, plus the test tools (pytest, hypothesis, ruff, mypy, pypdf)
#                              and a second SVG renderer (rsvg-convert) and pdftoppm for the tests
# The lettering font (osifont) ships inside the package, so no font is installed system-wide.
set -eu
extra="${1:-}"
need=""
ldconfig -p 2>/dev/null | grep -q 'libcairo\.so\.2' || need="$need libcairo2"
if [ "$extra" = test ]; then
    command -v rsvg-convert >/dev/null 2>&1 || need="$need librsvg2-bin"
    command -v pdftoppm >/dev/null 2>&1 || need="$need poppler-utils"
fi
if [ -n "$need" ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $need >/dev/null
    else
        echo "setup: geomcad needs the Debian packages:$need (sudo apt-get install$need)" >&2
    fi
fi
if [ -n "$extra" ]; then
    python3 -m pip install -q ".[$extra]"
else
    python3 -m pip install -q .
fi
