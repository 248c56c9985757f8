"""Fuzzing every problem's parameters, mutated example files (linkage, cam and gear files), the
arguments of ``variants`` and ``verify --batch``, and signals at any moment of a command: a result
with only finite numbers, or a GeomcadError (one clean ``error:`` line at the command line).

Never another exception, never a warning, never a hang: each call must answer within
:data:`CALL_SECONDS` (an alarm stops a call that does not). The values mix the ordinary (a
default scaled or with its sign flipped, values across the parameter's own range) with the
hostile (0, −0, the smallest subnormal, 1e±308, huge integers, NaN, ±inf, the ends of each
physical range, text). In CI the examples are derandomized and few (a budget of about 15 s);
``HYPOTHESIS_PROFILE=explore`` draws fresh ones, and ``GEOMCAD_FUZZ_EXAMPLES=N`` sets how many per
problem (e.g. ``HYPOTHESIS_PROFILE=explore GEOMCAD_FUZZ_EXAMPLES=400 pytest tests/test_fuzz.py``);
``GEOMCAD_FUZZ_SHEETS=1`` draws the sheets of every result too.
"""

from __future__ import annotations

import copy
import io
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
import warnings
from collections.abc import Iterator
from contextlib import contextmanager, redirect_stderr, redirect_stdout
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import geomcad
from geomcad import registry
from geomcad.cli import MAX_ERROR_LINE, main
from geomcad.problem import Param
from geomcad.render.files import TEMP_NAME

IDS = registry.problem_ids()
EXAMPLES = int(os.environ.get("GEOMCAD_FUZZ_EXAMPLES", "40"))
SHEETS = bool(os.environ.get("GEOMCAD_FUZZ_SHEETS"))
#: The longest a call may take (the budgets of iterative steps are ~1 s on an idle machine; CI
#: machines are shared, so the bound is generous: it catches hangs, not slowness).
CALL_SECONDS = 20.0

HOSTILE: list[object] = [
    0.0,
    -0.0,
    5e-324,
    -5e-324,
    1e-308,
    1e-300,
    1e308,
    -1e308,
    1e30,
    -1e30,
    math.nan,
    math.inf,
    -math.inf,
    10**40,
    -(10**40),
    10**400,
    True,
    "1",
    None,
    [1.0],
]


class _Hang(Exception):
    pass


@contextmanager
def _time_bound(seconds: float) -> Iterator[None]:
    def ring(signum: int, frame: object) -> None:
        raise _Hang(f"no answer within {seconds} s")

    old = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, old)


def _values(p: Param) -> st.SearchStrategy[object]:
    """Values for one parameter: ordinary ones near its default and in its range, and hostile
    ones (see :data:`HOSTILE`), including the ends of its physical range."""
    if p.choices:
        return st.sampled_from([*p.choices, "", "linear ", "НЕТ", 1.0])
    lo, hi = p.magnitudes()
    edges: list[object] = [lo, hi, -lo, -hi, hi * (1.0 + 1e-9), lo * (1.0 - 1e-9)]
    for b in (p.gt, p.ge, p.lt, p.le):
        if b is not None:
            edges += [b, math.nextafter(b, math.inf), math.nextafter(b, -math.inf)]
    if p.integer:
        base = int(p.default) if isinstance(p.default, int) else 1
        ordinary: st.SearchStrategy[object] = st.one_of(
            st.integers(-3, 3 * max(abs(base), 3)), st.integers(-(10**6), 10**6)
        )
        edges = [int(e) for e in edges if isinstance(e, float) and abs(e) < 1e18]
    else:
        base_f = float(p.default) if isinstance(p.default, int | float) else 1.0
        scale = abs(base_f) or 1.0
        ordinary = st.one_of(
            st.floats(0.1, 10.0).map(lambda f: base_f * f),
            st.floats(-10.0 * scale, 10.0 * scale, allow_nan=False),
            st.floats(-hi, hi, allow_nan=False, allow_infinity=False),
        )
    return st.one_of(ordinary, ordinary, st.sampled_from(HOSTILE + edges))


def _params(pid: str) -> st.SearchStrategy[dict[str, object]]:
    problem = registry.get(pid)
    names = [p.name for p in problem.params]
    return st.lists(st.sampled_from(names), min_size=1, max_size=4, unique=True).flatmap(
        lambda chosen: st.fixed_dictionaries({n: _values(problem.param(n)) for n in chosen})
    )


def _finite(value: Any, path: str) -> None:
    if isinstance(value, bool | str) or value is None:
        return
    if isinstance(value, int | float | np.floating | np.integer):
        assert math.isfinite(float(value)), f"{path} = {value}"
    elif isinstance(value, np.ndarray):
        assert np.all(np.isfinite(value)), path
    elif isinstance(value, dict):
        for k, v in value.items():
            _finite(v, f"{path}.{k}")
    elif isinstance(value, list | tuple):
        for i, v in enumerate(value):
            _finite(v, f"{path}.{i}")


def _answer(pid: str, params: dict[str, object]) -> None:
    """Solve (and draw) under the time bound: finite results or a GeomcadError, nothing else."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a warning escaping the library is a finding too
        start = time.monotonic()
        try:
            with _time_bound(CALL_SECONDS):
                sol = geomcad.solve(pid, **params)
                _finite(sol.results, "results")
                if SHEETS:
                    sol.sheets()
        except geomcad.GeomcadError as exc:
            assert str(exc).strip(), "an error says what is wrong"
        finally:
            elapsed = time.monotonic() - start
        assert elapsed < CALL_SECONDS


@pytest.mark.parametrize("pid", IDS)
def test_every_parameter_gives_a_finite_result_or_a_geomcad_error(pid: str) -> None:
    @settings(
        max_examples=EXAMPLES,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    )
    @given(params=_params(pid))
    def run(params: dict[str, object]) -> None:
        _answer(pid, params)

    run()


TEXTS = st.one_of(
    st.sampled_from(
        [
            "nan",
            "inf",
            "-inf",
            "1e308",
            "-1e308",
            "5e-324",
            "0",
            "-0",
            "1,5",
            "1,5,5",
            "١٢",
            "0x10",
            "1_000",
            "",
            " ",
            "9" * 60,
            "9" * 5000,
            "1e999",
            "+",
            "e",
            "٣٫٥",
            "½",
            "linear",
            "∞",
        ]
    ),
    st.text(max_size=12),
)


@settings(max_examples=max(EXAMPLES, 10), deadline=None)
@given(
    pid=st.sampled_from(IDS),
    index=st.integers(0, 50),
    text=TEXTS,
    json_=st.booleans(),
)
def test_the_cli_takes_any_text_without_a_traceback(
    pid: str, index: int, text: str, json_: bool
) -> None:
    params = registry.get(pid).params
    name = params[index % len(params)].name
    argv = ["solve", pid, "--set", f"{name}={text}", *(["--json"] if json_ else [])]
    out_io, err_io = io.StringIO(), io.StringIO()
    with _time_bound(CALL_SECONDS), redirect_stdout(out_io), redirect_stderr(err_io):
        code = main(argv)
    out, err = out_io.getvalue(), err_io.getvalue()
    assert code in (0, 2), (argv, code, err)
    if code == 2:
        assert out == ""
        assert err.startswith("error: ") and err.count("\n") == 1, err
    else:
        assert err == ""


# --- mutated files: every example file (linkage, cam, gear), a few of its values replaced ---------

FILES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.toml"))
FILE_VALUES: list[object] = [
    *(v for v in HOSTILE if v is not None),  # TOML writes inf and nan too
    -1,
    0,
    1e-9,
    1e9,
    360,
    "A",
    "O",
    "x",
    "",
    "E💥",  # a character the sheet font lacks
    "a_{b",  # label markup left open
    "\t",
    [0.0, 0.0],
    [1e308, 0.0],
    [1, 2, 3],
    {},
    {"a": 1},
]


def _leaves(node: object, path: tuple[object, ...] = ()) -> Iterator[tuple[object, ...]]:
    """Every key path into a TOML table, tables and lists included."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield (*path, k)
            yield from _leaves(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield (*path, i)
            yield from _leaves(v, (*path, i))


@st.composite
def _mutated(draw: st.DrawFn) -> tuple[str, dict[str, Any]]:
    path = draw(st.sampled_from(FILES))
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    for _ in range(draw(st.integers(1, 3))):
        keys = list(_leaves(data))
        if not keys:
            break
        where = draw(st.sampled_from(keys))
        node: Any = data
        for k in where[:-1]:
            node = node[k]
        last = where[-1]
        old = node[last]
        if isinstance(node, dict) and draw(st.booleans()) and draw(st.booleans()):
            del node[last]
        elif (
            isinstance(old, int | float)
            and not isinstance(old, bool)
            and abs(old) < 2**53  # a huge integer planted before is replaced, not scaled
            and draw(st.booleans())
        ):
            node[last] = old * draw(st.sampled_from([-1.0, 0.0, 0.5, 2.0, 10.0, 1e-9, 1e9]))
        else:
            node[last] = copy.deepcopy(draw(st.sampled_from(FILE_VALUES)))
    return path.name, data


@settings(
    max_examples=max(EXAMPLES, 10) * 3,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(case=_mutated())
def test_mutated_files_give_a_finite_result_or_a_geomcad_error(
    case: tuple[str, dict[str, Any]],
) -> None:
    from geomcad import documents

    name, data = case
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        start = time.monotonic()
        try:
            with _time_bound(CALL_SECONDS):
                sol = documents.from_data(name, data).solve()
                _finite(sol.results, "results")
                if SHEETS:
                    sol.sheets()
        except geomcad.GeomcadError as exc:
            assert str(exc).strip(), "an error says what is wrong"
        finally:
            elapsed = time.monotonic() - start
        assert elapsed < CALL_SECONDS


# --- variants and verify --batch: their arguments, a class's CSV ----------------------------------

ROOT = Path(__file__).resolve().parents[1]


def _cli(argv: list[str]) -> tuple[int, str, str]:
    """``main(argv)`` under the time bound, warnings as errors: its status, stdout, stderr."""
    out_io, err_io = io.StringIO(), io.StringIO()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with _time_bound(CALL_SECONDS), redirect_stdout(out_io), redirect_stderr(err_io):
            code = main(argv)
    return code, out_io.getvalue(), err_io.getvalue()


def _clean(argv: list[str], code: int, out: str, err: str, results: tuple[int, ...]) -> None:
    assert code in (*results, 2), (argv, code, err[-2000:])
    if code == 2:
        assert err.startswith("error: ") and err.count("\n") == 1, (argv, err[-2000:])
        assert len(err) <= MAX_ERROR_LINE + 1, (argv, len(err))


ARG_TEXTS = st.one_of(
    st.sampled_from(
        ["0", "1", "2", "-1", "3", "1e9", "9" * 30, "nan", "", " ", "x", "😀", "1,5", "0.5", "-0"]
    ),
    st.text(max_size=8),
)
VARY_TEXTS = st.one_of(
    st.sampled_from(
        [
            "K=1.2..1.6:0.05",
            "K=1.2..1.6",
            "K=1.6..1.2",
            "K=1.2..1.6:1e-300",
            "K=1.2..1.6:0",
            "K=1.2..1.6:-0.1",
            "K=1e999999999..2e999999999",
            "K=a|b|b",
            "K=1.3|1.5",
            "H=0.1..0.2:0.01",
            "nope=1..2",
            "K=..",
            "=1..2",
            "K=nan..inf",
            "K=1.2..1.6:1e-12",
        ]
    ),
    st.builds(lambda k, t: f"{k}={t}", st.sampled_from(["K", "H", "l3"]), st.text(max_size=10)),
)


#: A run that works, option by option; the fuzz spoils one or two of them.
GOOD_VARIANTS = {
    "template": "2013-6",
    "--count": "2",
    "--seed": "7",
    "--vary": "K=1.2..1.6:0.05",
    "--set": "H=0.2",
    "--min-transmission-deg": "0",
    "--key": "theta_deg,l1",
    "--course": "ТММ",
    "--jobs": "1",
    "--format": "svg",
}
BAD_VARIANTS: dict[str, st.SearchStrategy[str]] = {
    "template": st.sampled_from(["2013-1", "nope", "x.toml", "", "-"]),
    "--count": st.sampled_from(["0", "-1", "x", "1", "1001", "9" * 30]),
    "--seed": ARG_TEXTS,
    "--vary": VARY_TEXTS,
    "--set": st.sampled_from(["K=0", "K=", "=", "H=1e308", "x", "K=nan", "H=😀"]),
    "--min-transmission-deg": ARG_TEXTS,
    "--key": st.sampled_from(["*", "nope", ",", "", "r.*", "😀"]),
    "--course": ARG_TEXTS,
    "--jobs": st.sampled_from(["0", "-1", "100000", "x", "2"]),
    "--format": st.sampled_from(["pdf", "x", "", "svg,svg", "SVG"]),
}


@st.composite
def _variants_argv(draw: st.DrawFn) -> list[str]:
    spoilt = draw(st.lists(st.sampled_from(sorted(GOOD_VARIANTS)), max_size=2, unique=True))
    values = {k: draw(BAD_VARIANTS[k]) if k in spoilt else v for k, v in GOOD_VARIANTS.items()}
    argv = ["variants", values.pop("template")]
    for option, value in values.items():
        argv += [option, value]
    return argv


@settings(
    max_examples=max(EXAMPLES // 3, 10),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(argv=_variants_argv())
def test_variants_takes_any_arguments(argv: list[str], tmp_path: Path) -> None:
    out = tmp_path / "v"
    code, _, err = _cli([*argv, "--out", str(out)])
    _clean(argv, code, "", err, (0,))
    if code == 0:
        assert (out / "answers.csv").is_file()


_ANSWERS: list[Path] = []


def _answers() -> Path:
    """An answers.csv of ``geomcad variants`` (made once per session)."""
    if not _ANSWERS:
        folder = Path(tempfile.mkdtemp(prefix="geomcad-fuzz-")) / "v"
        argv = ["variants", "2013-6", "--count", "2", "--seed", "1", "--out", str(folder)]
        code, _, err = _cli([*argv, "--vary", "K=1.2..1.6:0.05", "--format", "svg"])
        assert code == 0, err
        _ANSWERS.append(folder / "answers.csv")
    return _ANSWERS[0]


CELLS = st.one_of(
    st.sampled_from(["", "1", "2", "01", "3", "30", "0,03", "nan", "inf", "-1e308", "9" * 400]),
    st.text(max_size=6),
)


@st.composite
def _class_csv(draw: st.DrawFn) -> str:
    sep = draw(st.sampled_from([",", ";", "\t"]))
    head = draw(
        st.lists(
            st.sampled_from(["student", "variant", "theta_deg", "l1", "O1B1_mm", "nope", "", "x"]),
            min_size=1,
            max_size=6,
        )
    )
    rows = draw(st.lists(st.lists(CELLS, max_size=7), max_size=4))
    return "\n".join(sep.join(r) for r in [head, *rows]) + "\n"


@settings(
    max_examples=max(EXAMPLES // 2, 10),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(
    text=_class_csv(),
    raw=st.sampled_from([None, b"\xff\xfe\x00", b"\xef\xbb\xbf", b"", b"a\x00b"]),
    extra=st.lists(
        st.sampled_from(["--json", "--scale", "0.002", "--scale", "nan", "--out", "OUT"]),
        max_size=3,
    ),
)
def test_verify_batch_takes_any_class_csv(
    text: str, raw: bytes | None, extra: list[str], tmp_path: Path
) -> None:
    students = tmp_path / "class.csv"
    data = text.encode("utf-8")
    students.write_bytes(data if raw is None else raw + data)
    extra = [str(tmp_path / "verdicts") if a == "OUT" else a for a in extra]
    argv = ["verify", str(students), "--batch", str(_answers()), *extra]
    code, out, err = _cli(argv)
    _clean(argv, code, out, err, (0, 1))
    if code in (0, 1) and "--json" in argv and "--out" not in argv:
        assert isinstance(json.loads(out)["verdicts"], list)


# --- signals at any moment: one line, 128 + the signal, nothing partial ---------------------------


@settings(max_examples=3, deadline=None)
@given(
    sig=st.sampled_from([signal.SIGINT, signal.SIGTERM, signal.SIGHUP]),
    delay=st.floats(0.4, 3.0),
    argv=st.sampled_from(
        [
            ["build", "2013-3", "--format", "svg,pdf,png"],
            ["build", str(ROOT / "examples" / "four-bar.toml"), "--format", "svg,pdf"],
            ["variants", "2013-6", "--count", "3", "--seed", "1", "--vary", "K=1.2..1.6:0.05"],
            ["animate", "kulisa-23110713", "--frames", "600"],
        ]
    ),
)
def test_a_signal_at_any_moment(sig: int, delay: float, argv: list[str]) -> None:
    with tempfile.TemporaryDirectory(prefix="geomcad-sig-") as tmp:
        out = Path(tmp) / "out"
        proc = subprocess.Popen(
            [sys.executable, "-m", "geomcad", *argv, "--out", str(out)],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        time.sleep(delay)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=120)
        assert "Traceback" not in err and "Exception ignored" not in err, err
        # 0: done before the signal; -sig: done, and the interpreter was ending
        if proc.returncode not in (0, -sig) or "error:" in err:
            assert proc.returncode == 128 + sig, err
            assert err.count("\n") == 1 and f"stopped by {signal.Signals(sig).name}" in err
        left = [n for n in (os.listdir(out) if out.exists() else []) if TEMP_NAME.match(n)]
        assert not left, left
