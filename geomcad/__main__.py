"""``python -m geomcad``: the command line of :mod:`geomcad.cli`."""

from __future__ import annotations

import sys

from geomcad.cli import main

if __name__ == "__main__":
    sys.exit(main())
