"""The ``geomcad`` command line (the interface of problems.md).

    geomcad list
    geomcad params ID [--json]
    geomcad solve ID [--set NAME=VALUE ...] [--json] [--trace]
    geomcad build [ID ...] [--out DIR] [--format svg,pdf,png,dxf] [--review] [--color]
                  [--lang ru|en] [--student NAME] [--checker NAME] [--group G] [--org ORG]
                  [--date D] [--designation DES]
    geomcad verify ID --measured NAME=VALUE ... [--set NAME=VALUE ...] [--scale K] [--json]
    geomcad animate ID [--set NAME=VALUE ...] [--out DIR] [--frames N] [--lang ru|en]

Exit status: 0 done (and, for ``verify``, every measurement within precision), 1 a measurement
out of precision, 2 bad input. Bad input prints nothing on stdout and exactly one line on stderr,
``error: ...``, naming the parameter or the construction step (prefixed with the problem id).
Anything else that goes wrong is a bug of geomcad's: one line ``error: internal error in STEP:
TYPE: message (please report)`` and exit status 70 (EX_SOFTWARE), never a traceback
(``GEOMCAD_TRACEBACK=1`` shows it, for a developer). stdout or stderr that cannot be written is
the OS's reason in one line and exit status 74 (EX_IOERR); SIGINT, SIGTERM and SIGHUP stop a
command with one line and the status 130, 143 or 129 (:mod:`geomcad.interrupts`).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import re
import signal
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any, NoReturn

import geomcad
from geomcad import interrupts, registry
from geomcad.errors import (
    QUOTE_CHARS,
    STEP_NOTE,
    GeomcadError,
    MissingDependency,
    ParameterError,
    SheetsFailed,
    UnknownProblem,
    shorten_name,
)

if TYPE_CHECKING:
    from geomcad.problem import ParamValue, Problem, Solution
    from geomcad.verify import Item, Report

FORMATS = ("svg", "pdf", "png", "dxf", "html")
DEFAULT_FORMATS = ("svg", "pdf", "png")
#: Formats that need no system library (the fallback when libcairo is missing).
PLAIN_FORMATS = ("svg", "dxf")

EXIT_OK = 0
EXIT_OUT_OF_PRECISION = 1
EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 70  # EX_SOFTWARE (sysexits.h)


class _UsageError(Exception):
    """A command line argparse rejects; reported as one ``error:`` line."""


class _Failed(Exception):
    """Bad input, already worded as the text of the ``error:`` line."""


class _StreamError(Exception):
    """stdout or stderr cannot be written (closed, a full disk, an I/O error): exit status 74."""

    def __init__(self, name: str, why: str) -> None:
        self.name = name
        self.why = why
        super().__init__(f"cannot write to {name}: {why}")


class _Parser(argparse.ArgumentParser):
    # argparse's own error() prints the usage and exits; the interface wants one line
    def error(self, message: str) -> NoReturn:
        raise _UsageError(f"{self.prog}: {message}")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); return the exit status.

    SIGINT, SIGTERM and SIGHUP stop the command at any moment with one ``error:`` line and the
    status 130, 143 or 129 (:mod:`geomcad.interrupts`); stdout or stderr that cannot be written
    gives the OS's reason in one line (when stderr can take it) and the status 74.
    """
    args = list(sys.argv[1:] if argv is None else argv)
    old = interrupts.catch()
    try:
        try:
            status = _run(args)
            _flush(sys.stdout)
            signum = interrupts.received()
            if signum is not None:  # its exception was swallowed (a finaliser's)
                raise interrupts.Interrupted(signum)
            return status
        except interrupts.Interrupted as exc:
            return _stopped(args, exc.signum)
        except KeyboardInterrupt:
            return _stopped(args, signal.SIGINT)
        except _StreamError as exc:
            return _stream_failed(exc)
        except BrokenPipeError:
            _quiet(sys.stdout)
            return EXIT_OK
    finally:
        interrupts.restore(old)


def _run(args: list[str]) -> int:
    try:
        ns = _parser(_help_topic(args)).parse_args(args)
    except _UsageError as exc:
        return _fail(str(exc))
    except SystemExit as exc:  # --help
        if _HELP_FAILED:  # the help was printed, one part of it with an error: line
            return EXIT_INTERNAL
        return exc.code if isinstance(exc.code, int) else EXIT_OK
    except Exception as exc:
        if os.environ.get("GEOMCAD_TRACEBACK"):
            raise
        return _internal(argparse.Namespace(command=args[0] if args else "geomcad"), None, exc)
    pid: str | None = getattr(ns, "id", None)
    try:
        status: int = _call(ns)
    except (_Failed, _UsageError) as exc:
        return _fail(str(exc))
    except UnknownProblem as exc:
        return _fail(str(exc))
    except GeomcadError as exc:
        return _fail(_prefixed(pid, exc))
    except _StreamError:
        raise
    except BrokenPipeError:
        # the reader (e.g. `| head`) went away; keep the interpreter's last flush quiet too
        _quiet(sys.stdout)
        return EXIT_OK
    except OSError as exc:
        # an OSError that no command caught: stdout or stderr written past a command's back
        # (a full disk) is the user's trouble, anything else is a bug
        stream = _failing_stream()
        if stream is not None:
            raise _StreamError(stream, exc.strerror or str(exc)) from exc
        if os.environ.get("GEOMCAD_TRACEBACK"):
            raise
        return _internal(ns, pid, exc)
    except Exception as exc:
        if os.environ.get("GEOMCAD_TRACEBACK"):
            raise
        return _internal(ns, pid, exc)
    return status


def _call(ns: argparse.Namespace) -> int:
    """Run the command; an exception that a signal caused (raised inside a C extension's
    import, which turns it into an ImportError, or a library that wraps it) is the signal's."""
    try:
        status: int = ns.func(ns)
    except Exception:
        signum = interrupts.received()
        if signum is not None:
            raise interrupts.Interrupted(signum) from None
        raise
    return status


def _stopped(args: Sequence[str], signum: int) -> int:
    """The line a signal ends a command with; the status 128 + its number."""
    command = args[0] if args and not args[0].startswith("-") else "geomcad"
    name = signal.Signals(signum).name
    with contextlib.suppress(_StreamError):
        _write(
            sys.stderr,
            _error_line(
                f"{command[:40]}: stopped by {name}; every file written is complete, no partial "
                "or temporary file is left"
            ),
        )
    return 128 + signum


#: sysexits.h's EX_IOERR: an input/output error (stdout or stderr cannot be written).
EXIT_IO = 74


def _stream_failed(exc: _StreamError) -> int:
    """stdout or stderr failed: say so on stderr when it can take it; exit status 74."""
    _quiet(sys.stdout)
    if exc.name != "stderr":
        with contextlib.suppress(_StreamError):
            _write(sys.stderr, _error_line(str(exc)))
    return EXIT_IO


def _failing_stream() -> str | None:
    """``stdout`` or ``stderr`` when it cannot be written (closed, or its buffered text cannot
    be flushed), else ``None``."""
    for name, stream in (("stdout", sys.stdout), ("stderr", sys.stderr)):
        try:
            _flush(stream)
        except _StreamError:
            return name
    return None


def _quiet(stream: IO[str] | None) -> None:
    """Point the process's own stdout at /dev/null, so that the interpreter's last flush of
    text that could not be written fails no more (it would print "Exception ignored" and exit
    120). A stream put in its place (a test's capture) is left alone."""
    own = sys.__stdout__
    if own is None or stream is not own:
        return
    with contextlib.suppress(OSError, ValueError):
        os.dup2(os.open(os.devnull, os.O_WRONLY), own.fileno())


EXAMPLES = """\
examples:
  geomcad list                                  the problem ids and titles
  geomcad params 2013-6                         its parameters (units, defaults, ranges), results
  geomcad solve 2013-6                          results beside the seed's published values
  geomcad solve 2013-6 --set K=1.4 --json       a variant, as one JSON object
  geomcad solve 2013-6 --trace                  the results, then the construction step by step
  geomcad build 2013-6 --out out --format svg,pdf,png
  geomcad verify 2013-6 --measured O1B1_mm=89.5 --measured theta_deg=23.5

ID is a problem id from `geomcad list`, or a file FILE.toml that states a problem.
exit status: 0 done, 1 (verify) a measurement out of precision, 2 bad input (one error: line),
70 an internal error of geomcad's (one error: line; please report), 74 stdout or stderr cannot be
written, 130/143/129 stopped by SIGINT/SIGTERM/SIGHUP.
"""

VERIFY_RULES = """\
measurements:
  NAME=VALUE      a result in its own SI unit (angles *_deg in degrees)
  NAME_mm=VALUE   a length read off the drawing in sheet mm, converted at k_l (--scale, else the
                  seed's k_l, else the project's sheet's)
  NAME.INDEX=...  an item of a list result, counted from 0 (e.g. r.2, solutions.1.O1B0_mm)

precision (each item is within or not):
  a length read in mm            0.5 mm on the sheet
  an angle *_deg                 0.5°
  a result drawn on the sheet    0.5 mm at its plan's scale (k_l, k_v, k_a or k_F)
  a number not drawn             0.5 % of the exact value (a ratio, a shift coefficient)

exit status: 0 every item within precision, 1 one or more are not, 2 bad input.
"""


def _internal(ns: argparse.Namespace, pid: str | None, exc: Exception) -> int:
    """A bug of geomcad's, in one line naming where it happened; exit status 70."""
    where = " ".join(w for w in (ns.command, pid) if w)
    step = next(
        (
            n.removeprefix(STEP_NOTE)
            for n in getattr(exc, "__notes__", ())
            if n.startswith(STEP_NOTE)
        ),
        None,
    )
    if step:
        where = f"{where}, {step}"
    text = _one_line(str(exc))
    if len(text) > 300:
        text = text[:300] + " …"
    msg = f"internal error in {where}: {type(exc).__name__}: {text} (please report)"
    with contextlib.suppress(_StreamError, OSError):
        _write(sys.stderr, _error_line(msg))
    return EXIT_INTERNAL


def _parser(help_for: tuple[str, str] | None = None) -> _Parser:
    """The command line; ``help_for`` = (command, ID) adds that problem's lists to its help."""
    p = _Parser(
        prog="geomcad",
        description="Theory of Machines and Mechanisms by exact graphical constructions.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action="version", version=f"geomcad {geomcad.__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="command")
    raw = argparse.RawDescriptionHelpFormatter

    s = sub.add_parser("list", help="ids and titles of the registered problems")
    s.set_defaults(func=_cmd_list)

    s = sub.add_parser(
        "params",
        help="a problem's parameters (units, defaults, ranges, choices) and results",
        description="List a problem's parameters and results.",
    )
    s.add_argument("id", metavar="ID", help=ID_HELP)
    s.add_argument("--json", action="store_true", help="print one JSON object")
    s.set_defaults(func=_cmd_params)

    s = sub.add_parser(
        "solve",
        help="solve a problem and compare with the seed",
        description="Solve a problem: its parameters, results, the seed's values beside them.",
        epilog=_help_epilog("solve", help_for),
        formatter_class=raw,
    )
    s.add_argument("id", metavar="ID", help=ID_HELP)
    _add_set(s)
    s.add_argument("--json", action="store_true", help="print one JSON object")
    s.add_argument(
        "--trace",
        action="store_true",
        help="after the results, print the construction protocol, one line per named step "
        "(with --json: to stderr)",
    )
    s.add_argument(
        "--emit-linkage",
        action="store_true",
        help="a file with [synthesis]: print the explicit linkage file it found (TOML)",
    )
    s.set_defaults(func=_cmd_solve)

    s = sub.add_parser("build", help="draw the sheets of problems")
    s.add_argument(
        "ids",
        nargs="*",
        metavar="ID",
        help="problem ids, FILE.toml or a variant file DIR/variant-NN.json (default: every id)",
    )
    _add_set(s)
    s.add_argument("--out", default="out", help="output folder (default: out)")
    s.add_argument(
        "--format",
        default=",".join(DEFAULT_FORMATS),
        help="comma-separated svg,pdf,png,dxf,html (default: svg,pdf,png); html: one interactive "
        "page per linkage file or problem with a crank mechanism",
    )
    s.add_argument(
        "--review",
        action="store_true",
        help="also write ID-review sheets: the results beside the published solution",
    )
    s.add_argument(
        "--color", action="store_true", help="colour the construction and results (for screens)"
    )
    s.add_argument(
        "--jobs", type=int, default=1, metavar="N", help="worker processes (default 1; 0: per core)"
    )
    _add_lang(s, "the sheets' language: ru (GOST 2.104 title block) or en (ISO 7200); "
              "default: [sheet] lang of the file or ./geomcad.toml, else ru")  # fmt: skip
    _add_title_options(s)
    s.set_defaults(func=_cmd_build)

    s = sub.add_parser("animate", help="an animated SVG of the mechanism over one crank turn")
    s.add_argument(
        "id",
        metavar="ID",
        help="a problem id with a crank mechanism (2013-6, kulisa-23110713) or FILE.toml",
    )
    _add_set(s)
    s.add_argument("--out", default="out", help="output folder (default: out)")
    s.add_argument(
        "--frames", default="120", metavar="N", help="positions over the turn (default: 120)"
    )
    _add_lang(s, "the words' language: ru or en (default: ./geomcad.toml's [sheet] lang, else ru)")
    s.set_defaults(func=_cmd_animate)

    s = sub.add_parser(
        "verify",
        help="compare measurements off a drawing with the exact values",
        description="Compare values measured off a drawing with the exact construction.",
        epilog=VERIFY_RULES + "\n" + _help_epilog("verify", help_for),
        formatter_class=raw,
    )
    s.add_argument("id", metavar="ID", help=ID_HELP + " (with --batch: the students' CSV)")
    s.add_argument(
        "--measured",
        action="append",
        metavar="NAME=VALUE",
        help="a result in SI units, NAME_mm=VALUE for a length in sheet mm, NAME.INDEX for an item",
    )
    _add_set(s)
    s.add_argument("--scale", metavar="K", help="k_l in m/mm for NAME_mm readings")
    s.add_argument(
        "--json", action="store_true", help="print one JSON object (with --batch: the verdicts)"
    )
    s.add_argument(
        "--batch", metavar="ANSWERS.csv", help="grade a class: the answers.csv of geomcad variants"
    )
    s.add_argument(
        "--out",
        metavar="FILE",
        help="with --batch: the register, FILE.xlsx or FILE.csv (default: the verdicts on stdout)",
    )
    s.add_argument(
        "--tol",
        action="append",
        default=[],
        metavar="[NAME=]2%|1mm|1deg",
        help="with --batch: a tolerance for each value or NAME (default 0.5 mm, 0.5°, 0.5 %%)",
    )
    _add_lang(s, "with --batch: the register's language (default ru)")
    s.set_defaults(func=_cmd_verify)

    from geomcad.teach.cli import add_variants

    add_variants(sub, _add_set)
    return p


#: Title-block options of ``build``: (option, TitleData field, help).
_TITLE_OPTIONS = (
    ("--student", "student", "Разраб.: the student's name"),
    ("--checker", "checker", "Пров.: the teacher's name"),
    ("--group", "group", "the student's group (графа 9)"),
    ("--org", "org", "the organisation (графа 9)"),
    ("--date", "date", "the date of the Разраб. row"),
    ("--designation", "designation", "the document's designation (графы 2 and 26)"),
)


#: The sheets' languages (:data:`geomcad.sheet.lang.LANGS`, spelt out here so that the parser
#: imports no drawing code; a test keeps the two equal).
LANGS = ("ru", "en")


def _add_lang(s: argparse.ArgumentParser, text: str) -> None:
    """``--lang``, as every command that draws takes it (``variants`` too)."""
    s.add_argument("--lang", choices=LANGS, default=None, help=text)


def _add_title_options(s: argparse.ArgumentParser) -> None:
    g = s.add_argument_group(
        "title block", "GOST 2.104 cells; these override a [sheet] table in ./geomcad.toml"
    )
    for option, dest, text in _TITLE_OPTIONS:
        g.add_argument(option, dest=f"tb_{dest}", metavar="TEXT", help=text)


def _title_data(ns: argparse.Namespace) -> tuple[Any, Any]:
    """The title-block data of ``build``: (the options, ./geomcad.toml's [sheet] table)."""
    from geomcad.sheet.titleblock import TitleData

    given = {dest: getattr(ns, f"tb_{dest}") for _, dest, _ in _TITLE_OPTIONS}
    given["lang"] = ns.lang
    try:
        options = TitleData.from_mapping(
            {k: v for k, v in given.items() if v is not None}, "title-block option"
        )
    except ParameterError as exc:  # named as the command line writes it: --student
        option = {dest: opt for opt, dest, _ in _TITLE_OPTIONS}.get(exc.name.rpartition(".")[2])
        if option is None:
            raise
        raise ParameterError(option, exc.value, exc.why) from None
    return options, TitleData.from_workdir()


ID_HELP = "a problem id (geomcad list), e.g. 2013-6, or a file FILE.toml"

#: Options of solve and verify that take a value (skipped when looking for the ID).
_VALUED = ("--set", "--measured", "--scale", "--out", "--format", "--batch", "--tol", "--lang")


def _help_topic(args: Sequence[str]) -> tuple[str, str] | None:
    """(command, ID) when ``args`` ask for the help of solve or verify with an ID given."""
    if not args or args[0] not in ("solve", "verify") or not {"-h", "--help"} & set(args):
        return None
    rest = iter(args[1:])
    for a in rest:
        if a in _VALUED:
            next(rest, None)
        elif not a.startswith("-"):
            return args[0], a
    return None


#: Set when a part of a --help could not be built (its error: line is written; exit 70).
_HELP_FAILED: list[Exception] = []


def _help_epilog(command: str, help_for: tuple[str, str] | None) -> str:
    """The lists of the problem whose help is asked for, or how to get them."""
    if help_for is None or help_for[0] != command:
        return "geomcad solve ID --help (or geomcad params ID) lists ID's parameters.\n"
    from geomcad import reference

    try:
        problem = _problem(help_for[1])
        text = reference.params_text(problem)
        if command == "verify":
            text += "\n" + reference.results_text(problem)
    except GeomcadError as exc:
        return f"{_one_line(str(exc))}\n"
    except Exception as exc:
        # the help is printed all the same; what could not be listed is one error: line
        if os.environ.get("GEOMCAD_TRACEBACK"):
            raise
        _HELP_FAILED.append(exc)
        text = _one_line(f"{type(exc).__name__}: {exc}")[:300]
        with contextlib.suppress(OSError, ValueError):
            _write(
                sys.stderr,
                _error_line(
                    f"internal error listing the parameters of {help_for[1]} for --help: "
                    f"{text} (please report)"
                ),
            )
        return "geomcad params ID lists ID's parameters.\n"
    return text


def _add_set(s: argparse.ArgumentParser) -> None:
    s.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a parameter in SI units (angles *_deg in degrees), or one of its choices",
    )


# --- commands ---------------------------------------------------------------------------------


def _cmd_list(ns: argparse.Namespace) -> int:
    ids = registry.problem_ids()
    width = max((len(i) for i in ids), default=0)
    lines = [f"{pid:<{width}}  {registry.get(pid).title}" for pid in ids]
    _write(sys.stdout, "".join(line + "\n" for line in lines))
    return EXIT_OK


def _cmd_params(ns: argparse.Namespace) -> int:
    from geomcad import reference

    problem = _problem(ns.id)
    if ns.json:
        _write(sys.stdout, _dumps(reference.problem_json(problem)) + "\n")
    else:
        _write(sys.stdout, reference.problem_text(problem))
    return EXIT_OK


def _cmd_solve(ns: argparse.Namespace) -> int:
    sol = _solve(ns.id, ns.set)
    if ns.emit_linkage:  # the explicit linkage file a [synthesis] found (issue 31)
        from geomcad.linkage import synthesis

        _write(sys.stdout, synthesis.emitted(ns.id, sol.data))
        return EXIT_OK
    if ns.json:
        text = _dumps(sol.to_json()) + "\n"
        trace = sol.trace().rstrip("\n") + "\n" if ns.trace else ""
        _write(sys.stdout, text)
        if trace:
            _write(sys.stderr, trace)
        return EXIT_OK
    text = _solve_report(sol)
    if ns.trace:
        text += "\nconstruction protocol:\n" + sol.trace().rstrip("\n") + "\n"
    _write(sys.stdout, text)
    return EXIT_OK


def _cmd_build(ns: argparse.Namespace) -> int:
    ids: list[str] = list(ns.ids) or registry.problem_ids()
    if not ids:
        raise _Failed("no problems are registered (is geomcad installed with pip install .?)")
    formats = _formats(ns.format)
    from geomcad import documents
    from geomcad.teach import jobs

    n_jobs = jobs.check_jobs(ns.jobs)
    pages: dict[str, str] | None = None
    if "html" in formats:  # the pages are made in this process, beside the sheets
        formats.remove("html")
        pages, n_jobs = {}, 1
    if ns.set and not ns.ids:
        raise _Failed("build --set: name the problem ids or files it applies to")
    for text in ns.set:
        _pair(text, "--set")
    for pid in ids:
        if not documents.is_file_id(pid) and not _is_variant_file(pid):
            registry.get(pid)  # an unknown id fails before anything is written
    out = Path(ns.out)
    if out.exists() and not out.is_dir():
        raise _Failed(f"--out {out}: is a file, not a folder")
    options, workdir = _title_data(ns)
    # without libcairo the SVGs are still written, and the DXFs when asked for
    plain = ["svg"] + [f for f in formats if f in PLAIN_FORMATS and f != "svg"]
    started = time.perf_counter()
    if n_jobs > 1:
        return _build_parallel(ns, ids, formats, plain, n_jobs, started, (options, workdir))
    # solve and draw everything first, so that bad input writes no file and prints nothing
    prepared: list[tuple[str, Any, str]] = []
    with jobs.bar(2 * len(ids), "step", "build") as tick:
        for pid in ids:
            prepared.append(
                _prepare(pid, options, workdir, ns.review, pages, bool(ns.ids), tuple(ns.set))
            )
            tick(1)
        return _write_prepared(ns, prepared, formats, plain, tick, started, pages)


def _is_variant_file(pid: str) -> bool:
    """True for a problem id's variant file that ``geomcad variants`` wrote (``.json``)."""
    return pid.lower().endswith(".json")


def _prepare(
    pid: str,
    options: Any,
    workdir: Any,
    review: bool,
    pages: dict[str, str] | None = None,
    strict: bool = True,
    sets: tuple[str, ...] = (),
) -> tuple[str, Any, str]:
    """Solve and draw one problem, file or variant file for ``build`` (with the ``--set``
    pairs): (its file stem, its sheets), in the language the title data name (``--lang``, else
    the file's or ./geomcad.toml's); with ``pages``, its interactive page too
    (geomcad.render.html), by its stem (a problem with no motion is bad input, or, not
    ``strict``, gets no page); and the text of the ``error:`` line of the sheets that could not
    be drawn ("" when all were: the others are returned and written, review 14)."""
    from geomcad import documents
    from geomcad.sheet.lang import language

    failed = ""
    try:
        if _is_variant_file(pid):
            from geomcad.teach.variants import variant_sets

            vid, pairs = variant_sets(Path(pid))
            pairs += [_pair(t, "--set") for t in sets]
            sol = _solve(vid, [f"{k}={v}" for k, v in pairs])
            own = _variant_title(pid)
        elif sets or documents.is_file_id(pid):
            sol = _solve(pid, sets)
            own = _file_title(pid, sol)
        else:
            sol = geomcad.solve(pid)
            own = _file_title(pid, sol)
        paged = pages is not None
        if paged:
            from geomcad.render.html import check

            try:
                check(sol)  # before the sheets are drawn
            except GeomcadError:
                if strict:
                    raise
                paged = False  # `build --format html` of every id: pages where there is a motion
        # the options over the file's own [sheet] table over ./geomcad.toml's
        title = options.over(workdir if own is None else own.over(workdir))
        with language(title.lang or "ru"):
            try:
                sheets = sol.sheets(title)
            except SheetsFailed as exc:  # the other sheets are written all the same
                sheets, failed = exc.drawn(), _prefixed(pid, exc)
            if review:
                from geomcad.review import review_sheets

                sheets += review_sheets(sol, title)
            named = documents.is_file_id(pid) or _is_variant_file(pid)
            stem = documents.stem(pid) if named else pid
            if pages is not None and paged:
                from geomcad.render.html import page_of, to_html

                source = Path(pid).read_text(encoding="utf-8") if documents.is_file_id(pid) else ""
                pages[stem] = to_html(page_of(sol, sheets, source))
    except GeomcadError as exc:
        raise _Failed(_prefixed(pid, exc)) from exc
    return (stem, sheets, failed)


def _write_prepared(
    ns: argparse.Namespace,
    prepared: list[tuple[str, Any, str]],
    formats: list[str],
    plain: list[str],
    tick: Any,
    started: float,
    pages: dict[str, str] | None = None,
) -> int:
    from geomcad.render import write_sheets
    from geomcad.render.files import write_atomic

    out = Path(ns.out)
    missing: MissingDependency | None = None
    try:
        out.mkdir(parents=True, exist_ok=True)
        for pid, sheets, _failed in prepared:
            if missing is None:
                try:
                    paths = write_sheets(pid, sheets, out, formats, colour=ns.color)
                except MissingDependency as exc:
                    # the SVGs (and DXFs) are written; write them again to learn their names
                    missing = exc
                    paths = write_sheets(pid, sheets, out, plain, colour=ns.color)
            else:
                paths = write_sheets(pid, sheets, out, plain, colour=ns.color)
            if pages is not None and pid in pages:
                paths.append(out / f"{pid}.html")
                write_atomic(paths[-1], pages[pid].encode("utf-8"))
            _write(sys.stdout, "".join(f"{p}\n" for p in paths))
            tick(1)
    except BrokenPipeError:
        raise
    except OSError as exc:
        where = exc.filename if exc.filename else out
        raise _Failed(f"cannot write to {where}: {exc.strerror or exc}") from exc
    failed = [f for _, _, f in prepared if f]
    for f in failed:  # a sheet that could not be drawn: its own error: line, the rest written
        _write(sys.stderr, _error_line(f))
    if missing is not None:
        what = "SVG and DXF files" if "dxf" in plain else "SVGs"
        _write(sys.stderr, _error_line(f"{_one_line(str(missing))}; only the {what} were written"))
        return EXIT_BAD_INPUT
    if failed:
        return EXIT_BAD_INPUT
    _build_summary(sum(len(sheets) for _, sheets, _ in prepared), len(prepared), started)
    return EXIT_OK


def _build_summary(n_sheets: int, n_ids: int, started: float) -> None:
    """The one line a build ends with, on stderr (stdout keeps the written paths only)."""
    seconds = time.perf_counter() - started
    _write(sys.stderr, f"built {n_sheets} sheets of {n_ids} problems in {seconds:.1f} s\n")


def _build_parallel(
    ns: argparse.Namespace,
    ids: list[str],
    formats: list[str],
    plain: list[str],
    n_jobs: int,
    started: float,
    title: tuple[Any, Any],
) -> int:
    """``build --jobs N``: solve, draw and render in worker processes (each through
    ``write_sheets``, as a serial build); each problem's files are written as soon as its worker
    is done (a killed build keeps what was finished), their paths printed in the order of the
    ids. Files that do not load fail before any work starts; a problem that fails later is
    reported after the others are written."""
    from geomcad import documents
    from geomcad.teach import build, jobs

    files_ids = [pid for pid in ids if documents.is_file_id(pid)]
    for pid in files_ids:  # bad input (a file that does not load) writes nothing
        try:
            documents.load(pid)
        except GeomcadError as exc:
            raise _Failed(_prefixed(pid, exc)) from exc
    jobs.warm(files_ids, formats)
    args = [
        (pid, tuple(formats), tuple(plain), ns.color, *title, ns.review, tuple(ns.set))
        for pid in ids
    ]
    out = Path(ns.out)
    missing, failed, n_sheets = "", "", 0
    partly: list[str] = []  # the error: lines of sheets not drawn, the file's others written
    done: dict[int, list[Path]] = {}
    shown = 0
    try:  # a signal unwinds through here as geomcad.interrupts.Interrupted: the pool is torn down
        with jobs.bar(len(ids), "problem", "build") as tick, jobs.pool(n_jobs, tick) as run:
            for i, (_stem, n, files, error, lacking) in run.stream(build.build_one, args):
                if error and not files:
                    failed = failed or _prefixed(ids[i], GeomcadError(error))
                    done[i] = []
                else:  # with an error, the sheets that were drawn (review 14)
                    if error:
                        partly.append(error)
                    missing = missing or lacking
                    n_sheets += n
                    done[i] = build.write(out, files)
                while shown in done:  # the paths in the order of the ids
                    _write(sys.stdout, "".join(f"{p}\n" for p in done.pop(shown)))
                    shown += 1
    except OSError as exc:
        raise _Failed(f"cannot write to {out}: {exc.strerror or exc}") from exc
    for error in partly:
        _write(sys.stderr, _error_line(error))
    if failed:
        raise _Failed(failed)
    if missing:
        what = "SVG and DXF files" if "dxf" in plain else "SVGs"
        _write(sys.stderr, _error_line(f"{_one_line(missing)}; only the {what} were written"))
        return EXIT_BAD_INPUT
    if partly:
        return EXIT_BAD_INPUT
    _build_summary(n_sheets, len(ids), started)
    return EXIT_OK


def _variant_title(path: str) -> Any:
    """A variant file's ``"sheet"`` object (the student, the group), or ``None``."""
    import json

    from geomcad.sheet.titleblock import TitleData

    obj = json.loads(Path(path).read_text(encoding="utf-8"))
    table = obj.get("sheet") if isinstance(obj, dict) else None
    return None if table is None else TitleData.from_mapping(table, f"{path}: sheet")


def _file_title(pid: str, sol: Solution[Any]) -> Any:
    """A file's own ``[sheet]`` table, or ``None``."""
    from geomcad.sheet.titleblock import TitleData

    table = (sol.problem.inputs or {}).get("sheet")
    if isinstance(table, dict):  # its "format" is the sheet's format (cam and gear files)
        table = {k: v for k, v in table.items() if k != "format"}
    return None if table is None else TitleData.from_mapping(table, "sheet")


def _cmd_animate(ns: argparse.Namespace) -> int:
    from geomcad import documents
    from geomcad.sheet.motion import MAX_FRAMES

    try:
        frames = int(ns.frames)
    except ValueError:
        frames = 0
    if not 2 <= frames <= MAX_FRAMES:
        raise ParameterError(
            "--frames", ns.frames, f"must be a whole number from 2 to {MAX_FRAMES}"
        )
    sol = _solve(ns.id, ns.set)
    if sol.problem.motion is None:
        able = [p for p in registry.problem_ids() if registry.get(p).motion is not None]
        raise _Failed(
            f"{ns.id}: has no crank mechanism to animate (animate takes {', '.join(able)})"
        )
    from geomcad.render.animate import to_animated_svg
    from geomcad.render.files import write_atomic
    from geomcad.sheet.lang import language
    from geomcad.sheet.titleblock import TitleData

    with language(ns.lang or TitleData.from_workdir().lang or "ru"):
        svg = to_animated_svg(sol.problem.motion(sol, frames))
    stem = documents.stem(ns.id) if documents.is_file_id(ns.id) else ns.id
    out = Path(ns.out)
    path = out / f"{stem}-animated.svg"
    try:
        out.mkdir(parents=True, exist_ok=True)
        write_atomic(path, svg.encode("utf-8"))
    except OSError as exc:
        raise _Failed(f"cannot write to {out}: {exc.strerror or exc}") from exc
    _write(sys.stdout, f"{path}\n")
    return EXIT_OK


def _cmd_verify(ns: argparse.Namespace) -> int:
    from geomcad.verify import verify

    if ns.batch is not None:
        from geomcad.teach.batch import parse_tol, run_batch

        scale = None if ns.scale is None else _scale(ns.scale)
        tols = [parse_tol(t) for t in ns.tol]
        if ns.json:
            return _batch_json(ns, scale, tols)
        return run_batch(
            ns.batch, ns.id, ns.out, scale, sys.stdout, sys.stderr, tols, ns.lang or "ru"
        )
    if not ns.measured:
        raise _UsageError("geomcad verify: the following arguments are required: --measured")
    measured = dict(_pair(text, "--measured") for text in ns.measured)
    scale = None if ns.scale is None else _scale(ns.scale)
    sol = _solve(ns.id, ns.set)
    report = verify(sol, measured, scale)
    if ns.json:
        _write(sys.stdout, _dumps(report.to_json()) + "\n")
    else:
        _write(sys.stdout, _verify_report(report))
    return EXIT_OK if report.ok else EXIT_OUT_OF_PRECISION


#: The verdict fields that are numbers (the rest are text; ``ok`` is true or false).
_BATCH_NUMBERS = ("measured", "exact", "deviation", "deviation_mm", "precision")


def _batch_json(ns: argparse.Namespace, scale: float | None, tols: Sequence[Any] = ()) -> int:
    """``verify --batch … --json``: the verdicts as one JSON object (to ``--out`` when given,
    else stdout), the summary as ``verify --batch`` writes it (stderr, or stdout with --out)."""
    from geomcad.teach.batch import COLUMNS, grade

    graded = grade(ns.batch, ns.id, scale, tols)
    verdicts: list[dict[str, Any]] = []
    for line in graded.lines:
        v: dict[str, Any] = {c: line.get(c, "") for c in COLUMNS}
        v["row"] = int(v["row"]) if str(v["row"]).isdecimal() else v["row"]
        for c in _BATCH_NUMBERS:
            v[c] = float(v[c]) if v[c] else None
        v["ok"] = {"yes": True, "no": False}.get(v["ok"])
        v["error"] = v["error"] or None
        verdicts.append(v)
    obj = {
        "answers": ns.batch,
        "students": ns.id,
        "ok": graded.ok,
        "verdicts": verdicts,
        "summary": graded.summary,
    }
    text = _dumps(obj) + "\n"
    summary = "\n".join(graded.summary) + "\n"
    if ns.out is None:
        _write(sys.stdout, text)
        _write(sys.stderr, summary)
    else:
        from geomcad.render.files import write_atomic

        try:
            write_atomic(Path(ns.out), text.encode("utf-8"))
        except OSError as exc:
            raise _Failed(f"--out {ns.out}: cannot write ({exc.strerror or exc})") from exc
        _write(sys.stdout, summary + f"verdicts: {ns.out}\n")
    return EXIT_OK if graded.ok else EXIT_OUT_OF_PRECISION


# --- input ------------------------------------------------------------------------------------


def _solve(pid: str, sets: Sequence[str]) -> Solution[Any]:
    from geomcad import documents

    if documents.is_file_id(pid):
        return documents.solve(pid, [_pair(text, "--set") for text in sets])
    problem: Problem[Any] = registry.get(pid)
    params: dict[str, ParamValue] = {}
    for text in sets:
        name, value = _pair(text, "--set")
        params[name] = problem.param(name, value).parse(value)
    return problem.solve(**params)


def _problem(pid: str) -> Problem[Any]:
    """The problem an ID names: a registered id, or a file FILE.toml."""
    from geomcad import documents

    return documents.load(pid) if documents.is_file_id(pid) else registry.get(pid)


def _pair(text: str, option: str) -> tuple[str, str]:
    name, eq, value = text.partition("=")
    name = name.strip()
    if not eq or not name:
        raise GeomcadError(f"{option} {text}: expected NAME=VALUE")
    return name, value


def _scale(text: str) -> float:
    t = text.strip()
    if t.count(",") == 1 and "." not in t:
        t = t.replace(",", ".")
    try:
        k = float(t)
    except ValueError:
        raise ParameterError("--scale", text, "must be a number (k_l in m/mm)") from None
    if not (math.isfinite(k) and k > 0.0):
        raise ParameterError("--scale", text, "must be a number > 0 (k_l in m/mm)")
    return k


def _formats(text: str) -> list[str]:
    out: list[str] = []
    for f in (w.strip().lower() for w in text.split(",")):
        if f not in FORMATS:
            raise ParameterError(
                "--format", text, f"each format must be one of {', '.join(FORMATS)}"
            )
        if f not in out:
            out.append(f)
    return out


# --- output -----------------------------------------------------------------------------------


def _solve_report(sol: Solution[Any]) -> str:
    """The readable ``solve`` report: parameters, results, the seed comparison, notes."""
    problem = sol.problem
    own = getattr(problem, "report", None)  # a problem with its own report (a linkage file)
    if callable(own):
        return str(own(sol))
    lines = [f"{problem.id} · {problem.title}", ""]
    if problem.params:
        lines.append("parameters:")
    for p in problem.params:
        if p.name not in sol.params:
            lines.append(f"  {p.name}: not set (derived by the problem)")
            continue
        value = sol.params[p.name]
        default = "derived by the problem" if p.default is None else _fmt(p.default)
        mark = "" if value == p.default else f"   (set; default {default})"
        lines.append(f"  {p.name} = {_fmt(value)}{_unit(p.unit)}{mark}")
    lines += ["", "results:"] if problem.params else ["results:"]
    specs = {r.name: r for r in problem.results}
    for name, value in sol.results.items():
        spec = specs.get(name)
        unit = _unit(spec.unit) if spec is not None else ""
        if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            lines.append(f"  {name}: {len(value)}")
            for i, obj in enumerate(value):
                fields = ", ".join(
                    f"{k} = {_fmt(v)}{_field_unit(problem, k)}" for k, v in obj.items()
                )
                lines.append(f"    {name}.{i}: {fields}")
        else:
            lines.append(f"  {name} = {_fmt(value)}{unit}")
    lines.append("")
    if sol.is_seed and problem.seed:
        lines.append("the seed's values (SI), exact − seed, and the tolerance of each class:")
        head = ("name", "exact", "seed (printed)", "diff", "class", "within tolerance")
        rows = [head]
        for r in sol.seed_report():
            if r["class"] == "erratum":
                within = "n/a (erratum)"
            else:
                within = f"{'yes' if r['agrees'] else 'NO'} (±{r['tol']:.3g})"
            rows.append(
                (
                    r["name"],
                    _fmt(r["exact"]),
                    f"{_fmt(r['seed'])} ({r['printed']})",
                    _dev(r["diff"], r["exact"], r["seed"]),
                    r["class"],
                    within,
                )
            )
        lines += ["  " + line for line in _table(rows)]
    elif problem.seed:
        lines.append("seed: not compared (the parameters differ from the seed's)")
    notes = sol.notes
    if notes:
        lines += ["", "notes:"] + [f"  - {_one_line(n)}" for n in notes]
    return "\n".join(lines) + "\n"


def _verify_report(report: Report) -> str:
    lines = [_verify_line(it) for it in report.items]
    bad = sum(not it.ok for it in report.items)
    n = len(report.items)
    if n == 1:
        lines.append(f"{report.id}: the measurement is {'out of' if bad else 'within'} precision")
    elif bad:
        lines.append(f"{report.id}: {bad} of {n} measurements out of precision")
    else:
        lines.append(f"{report.id}: all {n} measurements within precision")
    return "\n".join(lines) + "\n"


def _dev(deviation: float, *values: float) -> str:
    """A deviation to 3 digits, without the float noise below the 6 digits that the values it
    is the difference of are printed with (−2.22e-16 is 0)."""
    big = max((abs(v) for v in values if math.isfinite(v)), default=0.0)
    if big > 0.0 and math.isfinite(deviation):
        q = 10.0 ** (math.floor(math.log10(big)) - 5)
        deviation = round(deviation / q) * q + 0.0  # + 0.0: no "-0"
    return "0" if deviation == 0.0 else f"{deviation:+.3g}"


def _verify_line(it: Item) -> str:
    """One item in words: measured, exact, deviation and the precision it was held to."""
    within = "within" if it.ok else "NOT within"
    if it.rule == "angle":
        return (
            f"{it.result}: measured {_g(it.measured)}°, exact {_g(it.exact)}°, off by "
            f"{_dev(it.deviation, it.measured, it.exact)}°, "
            f"{within} the angle precision of {_g(it.precision)}°"
        )
    if it.rule == "relative":
        u = _unit(it.unit)
        return (
            f"{it.result}: measured {_g(it.measured)}{u}, exact {_g(it.exact)}{u}, off by "
            f"{_dev(it.deviation, it.measured, it.exact)}{u}, "
            f"{within} 0.5 % of the exact value ({it.precision:.3g}{u})"
        )
    from geomcad.verify import PLAN_SCALES

    k = it.scale if it.scale is not None else math.nan
    k_name, k_unit = PLAN_SCALES.get(it.plan or "", ("k", "units/mm"))
    dev_mm = it.deviation_mm if it.deviation_mm is not None else math.nan
    prec_mm = it.precision / k
    u = _unit(it.unit)
    if it.measured_mm is not None:
        return (
            f"{it.result}: measured {_g(it.measured_mm)} mm, exact {_g(it.exact / k)} mm "
            f"({_g(it.exact)}{u} at {k_name} = {k:g} {k_unit}), "
            f"off by {_dev(dev_mm, it.measured_mm, it.exact / k)} mm, "
            f"{within} the drawing precision of {prec_mm:g} mm"
        )
    return (
        f"{it.result}: measured {_g(it.measured)}{u}, exact {_g(it.exact)}{u} "
        f"({_g(it.exact / k)} mm at {k_name} = {k:g} {k_unit}), "
        f"off by {_dev(it.deviation, it.measured, it.exact)}{u} "
        f"({_dev(dev_mm, it.measured / k, it.exact / k)} mm), "
        f"{within} the drawing precision of {prec_mm:g} mm "
        f"({it.precision:.3g}{u})"
    )


def _table(rows: Sequence[Sequence[str]]) -> list[str]:
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    return [" | ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]


def _g(x: float) -> str:
    return f"{x:.6g}"


def _fmt(value: object) -> str:
    """A result or parameter, readably: numbers to 6 digits, lists in brackets, bools in words."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return _g(value)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_fmt(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_fmt(v)}" for k, v in value.items()) + "}"
    return str(value)


def _field_unit(problem: Problem[Any], name: str) -> str:
    spec = problem.result_spec(name)
    return _unit(spec.unit) if spec is not None else ""


def _unit(unit: str) -> str:
    if unit in ("", "1"):
        return ""
    if unit == "deg":
        return "°"
    return f" {unit}"


def _dumps(obj: object) -> str:
    # allow_nan=False: the interface promises valid JSON, and NaN is not JSON
    return json.dumps(obj, ensure_ascii=False, allow_nan=False, indent=2, default=_json_default)


def _json_default(obj: object) -> Any:
    tolist = getattr(obj, "tolist", None)  # numpy scalars and arrays
    if callable(tolist):
        return tolist()
    raise TypeError(f"{type(obj).__name__} is not JSON serializable")


def _prefixed(pid: str | None, exc: GeomcadError) -> str:
    msg = _one_line(str(exc))
    if pid and not isinstance(exc, UnknownProblem):
        short = shorten_name(pid)
        if not msg.startswith((f"{pid}:", f"{short}:")):
            return f"{short}: {msg}"
    return msg


def _one_line(text: str) -> str:
    return " ".join(text.split())


#: An ``error:`` line longer than this has its long quoted values and words cut to their
#: start (:data:`QUOTE_CHARS`) …
LONG_ERROR_LINE = 300
#: … and one still longer than this (characters, the prefix included) keeps its start and its
#: end (the reason), with "…" for the middle.
MAX_ERROR_LINE = 400

_N = QUOTE_CHARS + 1
_LONG_QUOTE = re.compile(rf"""(['"])([^'"]{{{_N}}})[^'"]+\1""")
_LONG_WORD = re.compile(rf"\S{{{_N}}}\S+")


def _error_line(msg: str) -> str:
    """``error: MSG`` as one line of about :data:`LONG_ERROR_LINE` characters at most: a value
    an error repeats is quoted by its start (most errors quote at most that much already)."""
    text = f"error: {_one_line(msg)}"
    if len(text) > LONG_ERROR_LINE:
        text = _LONG_QUOTE.sub(lambda m: f"{m[1]}{m[2]}…{m[1]}", text)
        text = _LONG_WORD.sub(lambda m: m[0][:QUOTE_CHARS] + "…", text)
    if len(text) > MAX_ERROR_LINE:
        tail = MAX_ERROR_LINE // 3
        text = text[: MAX_ERROR_LINE - tail - 3] + " … " + text[-tail:]
    return text + "\n"


def _fail(msg: str) -> int:
    try:
        _write(sys.stderr, _error_line(msg))
    except _StreamError:
        return EXIT_IO  # the error cannot be told: stderr is closed or full
    return EXIT_BAD_INPUT


def _stream_name(stream: object) -> str:
    return "stderr" if stream is sys.stderr else "stdout"


def _write(stream: IO[str] | None, text: str) -> None:
    """Write and flush ``text``; a stream that cannot take it is a :class:`_StreamError`
    (a reader that went away stays a :class:`BrokenPipeError`)."""
    if stream is None:  # started with the descriptor closed (`>&-`)
        raise _StreamError(_stream_name(stream), "it is closed")
    try:
        try:
            stream.write(text)
        except UnicodeEncodeError:
            # a terminal that cannot show θ or Cyrillic still gets every line (and valid JSON)
            enc = getattr(stream, "encoding", None) or "ascii"
            stream.write(text.encode(enc, "backslashreplace").decode(enc))
    except BrokenPipeError:
        raise
    except (OSError, ValueError) as exc:  # ValueError: the stream was closed
        raise _StreamError(_stream_name(stream), _os_reason(exc)) from exc
    _flush(stream)


def _flush(stream: IO[str] | None) -> None:
    if stream is None:
        raise _StreamError(_stream_name(stream), "it is closed")
    try:
        stream.flush()
    except BrokenPipeError:
        raise
    except (OSError, ValueError) as exc:
        raise _StreamError(_stream_name(stream), _os_reason(exc)) from exc


def _os_reason(exc: Exception) -> str:
    return (exc.strerror if isinstance(exc, OSError) else None) or str(exc) or type(exc).__name__
