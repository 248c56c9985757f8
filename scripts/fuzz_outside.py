"""Fuzz the command line from outside, as issue 29's reporter did (not run in CI).

A pre-loaded process forks :func:`geomcad.cli.main` for each call (stdout and stderr to files,
a time bound per call), and the signal cases run the real ``geomcad`` command:

    python scripts/fuzz_outside.py files N SEED [BUILD_SHARE]   mutated example files: solve, build
    python scripts/fuzz_outside.py args N SEED                  variants / verify --batch arguments
    python scripts/fuzz_outside.py signals N SEED               SIGINT/SIGTERM/SIGHUP at a moment

It prints the counts (calls, results, clean errors, internal errors or tracebacks, hangs, error
lines over 300 characters, --json that is not JSON) and one example of each finding.
"""

from __future__ import annotations

import copy
import json
import math
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
import traceback
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import tomli_w

from geomcad import documents
from geomcad.cli import main

ROOT = Path(__file__).resolve().parents[1]
FILES = sorted((ROOT / "examples").glob("*.toml"))
_BESIDE = Path(sys.executable).with_name("geomcad")  # the venv's console script
GEOMCAD = str(_BESIDE) if _BESIDE.exists() else shutil.which("geomcad") or "geomcad"
HANG_SECONDS = 60.0

VALUES: list[object] = [
    0, -1, 1, 0.0, -0.0, 5e-324, 1e-300, 1e308, -1e308, math.inf, -math.inf, math.nan,
    2**63 - 1, -(2**63), 10**30, 360, 720, "", "A", "O", "x", "E💥", "a_{b", "Ivanov 😀", "\t",
    "ö", [0.0, 0.0], [1e308, 0.0], [1, 2, 3], [], {}, {"a": 1}, True, "9" * 400, [[[[1]]]],
    1e9, 1e-9, 0.5, 2, 3, 100,
]  # fmt: skip


def _leaves(node: object, path: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    if isinstance(node, dict):
        for k, v in node.items():
            yield (*path, k)
            yield from _leaves(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield (*path, i)
            yield from _leaves(v, (*path, i))


def _mutate(rng: random.Random, data: dict[str, Any]) -> dict[str, Any]:
    for _ in range(rng.randint(1, 3)):
        keys = list(_leaves(data))
        if not keys:
            break
        where = rng.choice(keys)
        node: Any = data
        for k in where[:-1]:
            node = node[k]
        last, r = where[-1], rng.random()
        old = node[last]
        if isinstance(node, dict) and r < 0.15:
            del node[last]
        elif (
            isinstance(old, int | float)
            and not isinstance(old, bool)
            and abs(old) < 2**53
            and (r < 0.55)
        ):
            node[last] = old * rng.choice([-1.0, 0.0, 0.5, 2.0, 10.0, 1e-9, 1e9, 1.0000001])
        elif isinstance(node, dict) and r < 0.6:
            key = rng.choice(["zz", "name", "mass", "title", "lang"])
            node[key] = copy.deepcopy(rng.choice(VALUES))
        else:
            node[last] = copy.deepcopy(rng.choice(VALUES))
    return data


def call(argv: list[str], cwd: str, timeout: float = HANG_SECONDS) -> tuple[object, str, str]:
    """``main(argv)`` in a forked child in ``cwd``: (status or "hang", stdout, stderr)."""
    out, err = os.path.join(cwd, ".out"), os.path.join(cwd, ".err")
    pid = os.fork()
    if pid == 0:  # the child
        code = 98
        try:
            os.chdir(cwd)
            with open(out, "w") as fo, open(err, "w") as fe:
                sys.stdout, sys.stderr = fo, fe
                os.dup2(fe.fileno(), 2)
                try:
                    code = main(argv)
                except BaseException:
                    fe.write("TRACEBACK " + traceback.format_exc())
                fo.flush()
                fe.flush()
        finally:
            os._exit(code)
    start = time.monotonic()
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        if time.monotonic() - start > timeout:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            return "hang", "", ""
        time.sleep(0.01)
    code = os.waitstatus_to_exitcode(status)
    with open(out, errors="replace") as fo, open(err, errors="replace") as fe:
        return code, fo.read(), fe.read()


class Tally:
    def __init__(self) -> None:
        self.counts = dict.fromkeys(
            ("calls", "results", "clean", "internal", "hang", "longline", "badjson", "other"), 0
        )
        self.finds: dict[str, tuple[str, list[str]]] = {}

    def add(self, argv: list[str], code: object, out: str, err: str) -> None:
        c = self.counts
        c["calls"] += 1
        lines = [ln for ln in err.splitlines() if ln.startswith("error:")]
        short = [a[:80] for a in argv]
        if code == "hang":
            c["hang"] += 1
            self.finds.setdefault("hang", ("hang", short))
        elif code in (0, 1):
            c["results"] += 1
        elif code == 2 and len(lines) == 1 and "Traceback" not in err:
            c["clean"] += 1
        elif code in (70, 98) or "Traceback" in err:
            c["internal"] += 1
            self.finds.setdefault(err.strip().splitlines()[-1][:120], (err[-600:], short))
        else:
            c["other"] += 1
            self.finds.setdefault(f"status {code}", (err[-400:], short))
        if any(len(ln) > 300 for ln in lines):
            c["longline"] += 1
            self.finds.setdefault(f"long {len(lines[0])}", (lines[0][:300], short))
        if code in (0, 1) and "--json" in argv and "--out" not in argv:
            try:
                json.loads(out)
            except ValueError:
                c["badjson"] += 1
                self.finds.setdefault("badjson", (out[:200], short))


def fuzz_files(n: int, seed: int, build_share: float) -> Tally:
    """Mutated example files (linkage, cam, gear): ``solve [--json]`` or ``build --format svg``."""
    rng, tally = random.Random(seed), Tally()
    for f in FILES:  # the kinds' modules load before the forks
        documents.load(str(f))
    with tempfile.TemporaryDirectory(prefix="geomcad-fuzz-") as d:
        for i in range(n):
            f = rng.choice(FILES)
            data = _mutate(rng, tomllib.loads(f.read_text(encoding="utf-8")))
            path = Path(d) / f"m{i % 5}-{f.stem}.toml"
            try:
                path.write_text(tomli_w.dumps(data), encoding="utf-8")
            except (TypeError, ValueError):
                continue  # not writable as TOML
            if rng.random() < build_share:
                argv = ["build", path.name, "--format", "svg", "--out", "o"]
            else:
                argv = ["solve", path.name, *(["--json"] if rng.random() < 0.5 else [])]
            tally.add(argv, *call(argv, d))
    return tally


GOOD = {
    "--count": "2", "--seed": "7", "--vary": "K=1.2..1.6:0.05", "--set": "H=0.2",
    "--min-transmission-deg": "0", "--key": "theta_deg,l1", "--course": "ТММ", "--jobs": "1",
    "--format": "svg",
}  # fmt: skip
TEXTS = ["0", "1", "-1", "1e9", "9" * 30, "nan", "", " ", "x", "😀", "1,5", "0.5", "-0",
         "9" * 5000, "a_{b", "\t"]  # fmt: skip
BAD: dict[str, list[str]] = {
    "--count": ["0", "-1", "x", "1001", "9" * 30],
    "--seed": TEXTS,
    "--vary": ["K=1.2..1.6", "K=1.6..1.2", "K=1.2..1.6:1e-300", "K=1.2..1.6:0",
               "K=1e999999999..2e999999999", "K=a|b|b", "K=1.3|1.5", "H=0.1..0.2:0.01",
               "nope=1..2", "K=..", "=1..2", "K=nan..inf", "K=1.2..1.6:1e-12", "K=" + "9" * 5000],
    "--set": ["K=0", "K=", "=", "H=1e308", "x", "K=nan", "H=😀"],
    "--min-transmission-deg": TEXTS,
    "--key": ["*", "nope", ",", "", "r.*", "😀"],
    "--course": TEXTS,
    "--jobs": ["0", "-1", "100000", "x", "2"],
    "--format": ["pdf", "x", "", "svg,svg", "SVG"],
}  # fmt: skip
CELLS = ["", "1", "2", "01", "3", "30", "0,03", "nan", "inf", "-1e308", "9" * 400, "😀", "a;b",
         '"', "x"]  # fmt: skip


def _variants_argv(rng: random.Random) -> list[str]:
    template = rng.choice(["2013-6"] * 6 + ["2013-1", "nope", "slider-crank.toml", "x.toml"])
    values = dict(GOOD)
    if template == "slider-crank.toml":
        values.update({"--vary": "drive.omega=8..12:0.5", "--key": "*"})
        values.pop("--set")
    for k in rng.sample(sorted(BAD), rng.randint(0, 2)):
        values[k] = rng.choice(BAD[k])
    argv = ["variants", template]
    for k, v in values.items():
        argv += [k, v]
    return [*argv, "--out", "v"]


def _batch_argv(rng: random.Random, d: str) -> list[str]:
    sep = rng.choice([",", ";", "\t"])
    names = ["student", "variant", "theta_deg", "l1", "O1B1_mm", "nope", "", "x"]
    head = [rng.choice(names) for _ in range(rng.randint(1, 6))]
    rows = [[rng.choice(CELLS) for _ in range(rng.randint(0, 7))] for _ in range(rng.randint(0, 4))]
    text = ("\n".join(sep.join(r) for r in [head, *rows]) + "\n").encode("utf-8")
    prefix = rng.choice([b"", b"", b"\xef\xbb\xbf", b"\xff\xfe", b"a\x00"])
    Path(d, "class.csv").write_bytes(prefix + text)
    extra = rng.choice([[], ["--json"], ["--json", "--out", "v.json"], ["--scale", "0.002"],
                        ["--scale", "nan"], ["--out", "v.csv"]])  # fmt: skip
    answers = rng.choice(["A/answers.csv"] * 4 + ["nope.csv", "class.csv"])
    return ["verify", "class.csv", "--batch", answers, *extra]


def fuzz_args(n: int, seed: int) -> Tally:
    """``variants`` with one or two options spoilt, ``verify --batch`` over any class CSV."""
    rng, tally = random.Random(seed), Tally()
    with tempfile.TemporaryDirectory(prefix="geomcad-fuzz-") as d:
        shutil.copy(ROOT / "examples" / "slider-crank.toml", d)
        made = ["variants", "2013-6", "--count", "3", "--seed", "1", "--out", "A", "--vary",
                "K=1.2..1.6:0.05", "--format", "svg"]  # fmt: skip
        code, _, err = call(made, d)
        assert code == 0, err
        for i in range(n):
            argv = _variants_argv(rng) if i % 2 == 0 else _batch_argv(rng, d)
            tally.add(argv, *call(argv, d, timeout=120.0))
    return tally


COMMANDS = [
    ["build", "2013-3", "--format", "svg,pdf,png", "--out", "o"],
    ["build", "kulisa-23110713", "--format", "svg,pdf", "--out", "o"],
    ["build", "sixbar-2013-6.toml", "--format", "svg,pdf,png", "--out", "o"],
    [
        "variants",
        "2013-6",
        "--count",
        "3",
        "--seed",
        "1",
        "--vary",
        "K=1.2..1.6:0.05",
        "--out",
        "o",
    ],
    ["animate", "kulisa-23110713", "--frames", "600", "--out", "o"],
    ["solve", "2013-9", "--json"],
]


def fuzz_signals(n: int, seed: int) -> dict[str, Any]:
    """The real command, a signal at a random moment: 128 + the signal and one line (or done
    before it), no traceback, no temporary file."""
    rng = random.Random(seed)
    counts = {"kills": 0, "stopped_clean": 0, "finished_first": 0, "bad": 0}
    bad = []
    for _ in range(n):
        with tempfile.TemporaryDirectory(prefix="geomcad-sig-") as d:
            for f in FILES:
                shutil.copy(f, d)
            argv = rng.choice(COMMANDS)
            sig = rng.choice([signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
            moment = rng.uniform(0.15, 6.0)
            proc = subprocess.Popen([GEOMCAD, *argv], cwd=d, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, text=True)  # fmt: skip
            time.sleep(moment)
            proc.send_signal(sig)
            try:
                err = proc.communicate(timeout=120)[1]
            except subprocess.TimeoutExpired:
                proc.kill()
                err = "HANG"
            counts["kills"] += 1
            temporaries = [str(p) for p in Path(d).rglob("*.tmp")]
            stopped = proc.returncode == 128 + sig and err.count("\n") == 1 and "stopped by" in err
            done = proc.returncode in (0, -sig) and "error:" not in err
            if (
                "Traceback" in err
                or "Exception ignored" in err
                or temporaries
                or not (stopped or done)
            ):
                counts["bad"] += 1
                bad.append((argv, sig.name, round(moment, 2), proc.returncode, err[-500:]))
            else:
                counts["stopped_clean" if stopped else "finished_first"] += 1
    return {"counts": counts, "bad": bad}


if __name__ == "__main__":
    mode, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    if mode == "signals":
        result = fuzz_signals(n, seed)
        print(mode, result["counts"])
        for b in result["bad"]:
            print("----", b)
    else:
        share = float(sys.argv[4]) if len(sys.argv) > 4 else 0.2
        tally = fuzz_files(n, seed, share) if mode == "files" else fuzz_args(n, seed)
        print(mode, tally.counts)
        for key, (text, argv) in tally.finds.items():
            print("----", key, argv, "\n", text)
