"""``python -m geomcad`` and the ``geomcad`` command: :func:`geomcad.cli.main`, with SIGINT,
SIGTERM and SIGHUP caught before the command line's modules load (a signal in the first tenth of
a second ends the command with its one line too, not with an import's traceback)."""

from __future__ import annotations

import sys

from geomcad import interrupts


def run() -> int:
    """The console script: catch the signals, then load and run the command line."""
    old = interrupts.catch()
    try:
        from geomcad.cli import main

        return main()
    except (interrupts.Interrupted, KeyboardInterrupt) as exc:
        stop = exc if isinstance(exc, interrupts.Interrupted) else interrupts.Interrupted(2)
        command = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else ""
        try:
            sys.stderr.write(stop.line(command[:40] or "geomcad"))
            sys.stderr.flush()
        except (OSError, ValueError, AttributeError):
            pass  # stderr closed or full: the status says it
        return stop.status
    finally:
        interrupts.restore(old)
        # the command is over: a signal while the interpreter shuts down just ends it
        interrupts.default()


if __name__ == "__main__":
    sys.exit(run())
