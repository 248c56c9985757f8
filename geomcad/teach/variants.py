"""``geomcad variants``: reproducible variants of a problem id or a file, each solved before kept.

A TEMPLATE is a problem id (``2013-6``) or a file (``mech.toml``, see :mod:`geomcad.documents`).
``--vary KEY=LO..HI[:STEP]`` names a key to vary (a parameter of a problem id, a dotted key of a
file, as ``--set`` takes them) with its range and rounding step: the values are the multiples of
STEP from LO to HI (printed data: 0.005 m, not 0.0049731). STEP defaults to the last decimal
place written in LO or HI (``0.15..0.25`` → 0.01). ``KEY=a|b|c`` draws one of the words.

The draws come from :func:`numpy.random.default_rng` seeded with ``--seed``, as whole-number
indices into each key's list of values, so the same seed gives the same variants on every
machine (NumPy keeps ``Generator.integers`` streams stable). Each drawn variant is solved; it is
rejected and another one drawn when it

- duplicates a variant drawn before (the same values of every varied key),
- cannot be solved (bad input, a construction that fails; for a linkage file also a mechanism
  that cannot assemble over a full crank turn),
- is a linkage file whose transmission angle falls below ``--min-transmission-deg`` (40° by
  default) somewhere on the turn (:mod:`geomcad.teach.transmission`).

Which variants are kept does not depend on ``--jobs``: candidates are drawn in one sequence and
judged in that order, whatever process judges them.
"""

from __future__ import annotations

import copy
import json
import math
from collections import Counter
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from geomcad import documents, registry
from geomcad.errors import GeomcadError, ParameterError, shorten
from geomcad.teach import MIN_TRANSMISSION_DEG, keys, quantities, transmission

if TYPE_CHECKING:
    from geomcad.problem import ParamValue, Problem, Solution


#: Draws allowed per variant asked for, before the run gives up (rejections included).
DRAWS_PER_VARIANT = 50

#: The most variants one run makes (a class, or a course's several classes).
MAX_COUNT = 1000

#: The most values one ``--vary`` range may hold (multiples of its step), and the largest and
#: smallest size of LO, HI and STEP: a range is printed data, not a stream of digits.
MAX_VALUES = 10**9
MAX_EXPONENT = 30

#: Rejection reasons, in the order they are reported.
REASONS = ("duplicate", "unsolvable", "transmission")


@dataclass(frozen=True)
class Vary:
    """A key to vary: its values are ``words``, or ``(first + i)·step`` for i in 0 … n − 1."""

    key: str
    n: int
    first: int = 0
    step: Decimal = Decimal(1)
    words: tuple[str, ...] = ()

    def text(self, i: int) -> str:
        """The i-th value as it is written into the variant (a plain decimal or a word)."""
        if self.words:
            return self.words[i]
        d = (Decimal(self.first + i) * self.step).normalize()
        return format(d, "f")


def _decimal(key: str, text: str, what: str) -> Decimal:
    t = text.strip()
    try:
        d = Decimal(t)
    except InvalidOperation:
        raise ParameterError(f"--vary {key}", text, f"{what} must be a number") from None
    if not d.is_finite():
        raise ParameterError(f"--vary {key}", text, f"{what} must be a finite number")
    if d and not -MAX_EXPONENT <= d.adjusted() < MAX_EXPONENT:
        raise ParameterError(
            f"--vary {key}",
            text,
            f"{what} must lie between 1e-{MAX_EXPONENT} and 1e{MAX_EXPONENT} in size",
        )
    return d


def parse_vary(text: str) -> Vary:
    """``KEY=LO..HI[:STEP]`` or ``KEY=a|b|c`` (see the module's docstring)."""
    key, eq, spec = text.partition("=")
    key = key.strip()
    if not eq or not key or not spec.strip():
        raise GeomcadError(f"--vary {text}: expected KEY=LO..HI[:STEP] or KEY=a|b|c")
    if "|" in spec:
        words = tuple(w.strip() for w in spec.split("|"))
        if any(not w for w in words) or len(set(words)) != len(words):
            raise ParameterError(f"--vary {key}", spec, "the words must be distinct and not empty")
        return Vary(key, len(words), words=words)
    rng, colon, step_text = spec.partition(":")
    lo_text, dots, hi_text = rng.partition("..")
    if not dots:
        raise GeomcadError(f"--vary {text}: expected KEY=LO..HI[:STEP] or KEY=a|b|c")
    lo = _decimal(key, lo_text, "LO")
    hi = _decimal(key, hi_text, "HI")
    if colon:
        step = _decimal(key, step_text, "STEP")
        if step <= 0:
            raise ParameterError(f"--vary {key}", step_text, "STEP must be > 0")
    else:
        places = max(-int(lo.as_tuple().exponent), -int(hi.as_tuple().exponent), 0)
        step = Decimal(1).scaleb(-places)
    if not lo < hi:
        raise ParameterError(f"--vary {key}", spec, "LO must be less than HI")
    if (hi - lo) / step > MAX_VALUES:
        raise ParameterError(
            f"--vary {key}", spec, f"the range holds over {MAX_VALUES:,} steps: take a coarser STEP"
        )
    first = math.ceil(lo / step)
    last = math.floor(hi / step)
    if last - first < 1:
        raise ParameterError(
            f"--vary {key}", spec, f"the range holds fewer than two multiples of the step {step}"
        )
    return Vary(key, last - first + 1, first, step)


# --- templates --------------------------------------------------------------------------------


@dataclass
class Template:
    """A problem id with fixed ``--set`` values, or a file's data with its ``--set`` applied.

    It is plain data (picklable), so worker processes solve variants from it.
    """

    ref: str
    data: dict[str, Any] | None = None
    fixed: dict[str, str] = field(default_factory=dict)

    @property
    def is_file(self) -> bool:
        return self.data is not None

    @property
    def stem(self) -> str:
        return documents.stem(self.ref) if self.is_file else self.ref

    @property
    def kind(self) -> str:
        """``problem`` for a problem id, else the file's kind (``linkage``, ``cam`` …)."""
        return "problem" if self.data is None else documents.kind_of(self.data)

    def variant_data(self, values: Sequence[tuple[str, str]]) -> dict[str, Any]:
        """The file's data with the variant's values set."""
        assert self.data is not None
        data = copy.deepcopy(self.data)
        for key, text in values:
            if isinstance(_file_value(data, key), float) and text.lstrip("-").isdecimal():
                text += ".0"  # a float stays a float (omega = 15.0, not 15)
            documents.apply_set(data, key, text)
        return data

    def problem(self, values: Sequence[tuple[str, str]] = (), file_id: str = "") -> Problem[Any]:
        """The problem of the variant (for a file: made from its data, not yet solved)."""
        if self.data is None:
            return registry.get(self.ref)
        return documents.from_data(file_id or self.ref, self.variant_data(values))

    def params(self, values: Sequence[tuple[str, str]]) -> dict[str, ParamValue]:
        """A problem id's parameters for the variant (fixed ones, then the varied ones)."""
        problem = registry.get(self.ref)
        out: dict[str, ParamValue] = {}
        for name, text in [*self.fixed.items(), *values]:
            out[name] = problem.param(name).parse(text)
        return out

    def solve(self, values: Sequence[tuple[str, str]], file_id: str = "") -> Solution[Any]:
        """Solve the variant with ``values`` (pairs of key and text)."""
        if self.data is None:
            return registry.get(self.ref).solve(**self.params(values))
        return self.problem(values, file_id).solve()


def load_template(ref: str, sets: Sequence[tuple[str, str]] = ()) -> Template:
    """The template ``ref`` (a problem id or a file) with the ``--set`` pairs applied."""
    if documents.is_file_id(ref):
        data = documents.read(ref)
        for key, text in sets:
            documents.apply_set(data, key, text)
        return Template(ref, data)
    problem = registry.get(ref)
    fixed: dict[str, str] = {}
    for name, text in sets:
        problem.param(name).parse(text)
        fixed[name] = text
    return Template(ref, None, fixed)


def _file_value(data: Mapping[str, Any], key: str) -> Any:
    """The value at a dotted key of file data (list items counted from 1), or an error."""
    node: Any = data
    where: list[str] = []
    for part in key.split("."):
        where.append(part)
        if isinstance(node, list) and part.isdigit() and 1 <= int(part) <= len(node):
            node = node[int(part) - 1]
        elif isinstance(node, Mapping) and part in node:
            node = node[part]
        else:
            raise ParameterError(
                f"--vary {key}", "", f"the file has no {'.'.join(where)} (list items count from 1)"
            )
    return node


def check_varies(template: Template, varies: Sequence[Vary]) -> None:
    """Refuse a varied key the template does not have, or a range outside its domain."""
    names = [v.key for v in varies]
    if not varies:
        raise GeomcadError("variants: give at least one --vary KEY=LO..HI[:STEP]")
    if len(set(names)) != len(names):
        raise GeomcadError(f"variants: a key is varied twice ({', '.join(names)})")
    for v in varies:
        ends = [v.text(0), v.text(v.n - 1)] if not v.words else list(v.words)
        if template.data is None:
            p = registry.get(template.ref).param(v.key)
            if p.choices and not v.words:
                raise ParameterError(
                    f"--vary {v.key}", "", f"takes one of {', '.join(p.choices)}: KEY=a|b"
                )
            if p.integer and v.step != v.step.to_integral_value():
                raise ParameterError(f"--vary {v.key}", str(v.step), "a whole-number step")
            for t in ends:
                try:
                    p.parse(t)
                except ParameterError as exc:
                    raise ParameterError(f"--vary {v.key}", t, exc.why) from None
            if v.key in template.fixed:
                raise GeomcadError(f"variants: {v.key} is both --set and --vary")
        else:
            old = _file_value(template.data, v.key)
            number = isinstance(old, int | float) and not isinstance(old, bool)
            if v.words and not isinstance(old, str):
                raise ParameterError(f"--vary {v.key}", old, "is not a word; vary it as LO..HI")
            if not v.words and not number:
                raise ParameterError(f"--vary {v.key}", old, "is not a number in the file")


# --- judging a candidate ----------------------------------------------------------------------


@dataclass(frozen=True)
class Outcome:
    """What solving a candidate gave: ``status`` "ok" or a rejection reason, and its words.

    ``refused`` is set when the check itself cannot be made (a capability geomcad lacks): the
    run stops with that message instead of rejecting the candidate.
    """

    status: str
    message: str = ""
    results: dict[str, float | int] = field(default_factory=dict)
    transmission_deg: float | None = None
    refused: bool = False


def judge(template: Template, values: tuple[tuple[str, str], ...], min_tr: float) -> Outcome:
    """Solve one candidate and check it (never raises for the candidate's own failings)."""
    try:
        sol = template.solve(values)
    except GeomcadError as exc:
        return Outcome("unsolvable", _one_line(str(exc)))
    flat = keys.flatten(sol.results)
    if template.data is None or template.kind != "linkage" or min_tr <= 0.0:
        return Outcome("ok", results=flat)
    data = template.variant_data(values)
    kin = transmission.kinematic_copy(data)
    try:
        turn = documents.from_data(template.ref, kin).solve()
    except GeomcadError as exc:
        return Outcome("unsolvable", f"over a full crank turn: {_one_line(str(exc))}")
    positions = turn.results.get("positions")
    if not isinstance(positions, list) or not positions:
        return Outcome(
            "ok",
            "the linkage results have no positions to check the transmission angle on",
            refused=True,
        )
    try:
        gamma = transmission.minimum(data, positions)
    except GeomcadError as exc:
        return Outcome("ok", _one_line(str(exc)), refused=True)
    if gamma < min_tr:
        return Outcome(
            "transmission",
            f"the transmission angle falls to {gamma:.1f}° (< {min_tr:g}°)",
            transmission_deg=gamma,
        )
    flat["transmission_min_deg"] = gamma
    return Outcome("ok", results=flat, transmission_deg=gamma)


def _one_line(text: str) -> str:
    return " ".join(text.split())


# --- drawing the set --------------------------------------------------------------------------

Mapper = Callable[[Callable[..., Any], Sequence[tuple[Any, ...]]], list[Any]]


def serial_map(fn: Callable[..., Any], args: Sequence[tuple[Any, ...]]) -> list[Any]:
    """Apply ``fn`` to each argument tuple in this process, in order."""
    return [fn(*a) for a in args]


@dataclass
class Variant:
    """A kept variant: its number (from 1), the varied values, the key results."""

    number: int
    values: tuple[tuple[str, str], ...]
    results: dict[str, float | int]


@dataclass
class Drawn:
    """The kept variants, the rejections by reason with a first example each, the draws made."""

    variants: list[Variant]
    rejected: Counter[str]
    examples: dict[str, str]
    draws: int


def candidates(varies: Sequence[Vary], seed: int) -> Iterator[tuple[int, ...]]:
    """The endless sequence of index tuples the seed gives (one index per varied key)."""
    rng = np.random.default_rng(seed)
    sizes = [v.n for v in varies]
    while True:
        yield tuple(int(rng.integers(0, n)) for n in sizes)


def draw(
    template: Template,
    varies: Sequence[Vary],
    count: int,
    seed: int,
    min_transmission_deg: float = MIN_TRANSMISSION_DEG,
    mapper: Mapper = serial_map,
    progress: Callable[[int], None] | None = None,
) -> Drawn:
    """Draw ``count`` variants that solve and pass the checks (see the module's docstring)."""
    if count < 1:
        raise ParameterError("--count", count, "must be ≥ 1")
    check_varies(template, varies)
    total = math.prod(v.n for v in varies)
    if total < count:
        raise GeomcadError(
            f"variants: the ranges give only {total} different variants, fewer than --count {count}"
        )
    max_draws = max(100, DRAWS_PER_VARIANT * count)
    stream = candidates(varies, seed)
    seen: set[tuple[int, ...]] = set()
    kept: list[Variant] = []
    rejected: Counter[str] = Counter({r: 0 for r in REASONS})
    examples: dict[str, str] = {}
    draws = 0
    while len(kept) < count:
        batch: list[tuple[tuple[str, str], ...]] = []
        while len(batch) < count - len(kept):
            if draws >= max_draws or len(seen) >= total:
                raise GeomcadError(
                    f"variants: {len(kept)} of {count} variants found in {draws} draws "
                    f"(rejected: {_reasons(rejected)}); widen the ranges or relax the checks"
                    + (f"; e.g. {examples['unsolvable']}" if "unsolvable" in examples else "")
                )
            idx = next(stream)
            draws += 1
            if idx in seen:
                rejected["duplicate"] += 1
                continue
            seen.add(idx)
            batch.append(tuple((v.key, v.text(i)) for v, i in zip(varies, idx, strict=True)))
        outcomes = mapper(judge, [(template, vals, min_transmission_deg) for vals in batch])
        for vals, out in zip(batch, outcomes, strict=True):
            if out.refused:
                raise GeomcadError(f"variants: {out.message}")
            if out.status != "ok":
                rejected[out.status] += 1
                examples.setdefault(out.status, out.message)
                continue
            kept.append(Variant(len(kept) + 1, vals, out.results))
            if progress is not None:
                progress(1)
    return Drawn(kept, rejected, examples, draws)


def _reasons(rejected: Mapping[str, int]) -> str:
    words = {
        "duplicate": "duplicates",
        "unsolvable": "not solvable",
        "transmission": "transmission angle too small",
    }
    return ", ".join(f"{rejected.get(r, 0)} {words[r]}" for r in REASONS)


def summary(drawn: Drawn, template: Template, seed: int, out: Path) -> str:
    """The one-paragraph report of a run."""
    n = len(drawn.variants)
    lines = [
        f"{n} variants of {template.ref} in {out} (seed {seed}); {drawn.draws} drawn, "
        f"{sum(drawn.rejected.values())} rejected: {_reasons(drawn.rejected)}"
    ]
    for reason in REASONS:
        if reason in drawn.examples:
            lines.append(f"  first {reason}: {drawn.examples[reason]}")
    return "\n".join(lines) + "\n"


# --- the key ----------------------------------------------------------------------------------


def default_key(template: Template, results: Mapping[str, float | int]) -> list[str]:
    """The key's patterns when ``--key`` is not given (``results``: a variant's, flattened).

    A linkage file: stroke, K, ω and ε of each link, the output's V and a at the plans'
    positions, M_bal and J_flywheel (those the results have). Any other: every result that is
    a number or a short list of numbers (a problem's other solutions and curves left out, and
    the solver's own checks, ``H_check``).
    """
    if template.kind != "linkage":
        names: list[str] = []
        for path in results:
            head, _, rest = path.partition(".")
            if (not rest or rest.isdecimal()) and head not in names:
                names.append(head)
        return [
            n
            for n in names
            if not any(p.startswith(f"{n}.") and not p[len(n) + 1 :].isdecimal() for p in results)
            and not quantities.is_internal(n)
        ]
    data = template.data or {}
    drive = data.get("drive", {}) if isinstance(data.get("drive"), Mapping) else {}
    groups = data.get("group", [])
    output = drive.get("output")
    if output is None and isinstance(groups, list) and groups:
        output = groups[-1].get("joint")
    pats = ["stroke", "K", "positions.*.omega_*", "positions.*.eps_*"]
    if output is not None:
        pats += [f"positions.*.V_{output}", f"positions.*.a_{output}"]
    return [*pats, "positions.*.M_bal", "J_flywheel"]


def key_columns(variants: Sequence[Variant], patterns: Sequence[str], explicit: bool) -> list[str]:
    """The key's columns: the paths the patterns match, in the results' order."""
    paths: list[str] = []
    seen: set[str] = set()
    for v in variants:
        for p in keys.select(v.results, patterns):
            if p not in seen and p != "transmission_min_deg":
                seen.add(p)
                paths.append(p)
    if not explicit:
        # the default key leaves out what is given or identically zero (the crank's ω_1 and
        # ε_1, a slider's ω and ε)
        paths = [
            p
            for p in paths
            if keys.leaf(p) not in ("omega_1", "eps_1")
            and any(v.results.get(p, 0) != 0 for v in variants)
        ]
    if explicit:
        for pat in patterns:
            if not any(keys.matches(p, pat) for v in variants for p in v.results):
                names = list(variants[0].results) if variants else []
                known = ", ".join(names[:12]) + (f" … ({len(names)} in all)" * (len(names) > 12))
                raise GeomcadError(
                    f"--key {shorten(pat)}: no result matches it; the results are {known}"
                )
    if not paths:
        raise GeomcadError("variants: the key is empty (no result matches --key)")
    return paths


def unit_of(problem: Problem[Any], path: str) -> str:
    """The SI unit of a key column, from the result specs (the field's, else its parent's)."""
    for part in reversed(path.split(".")):
        if part.isdecimal():
            continue
        spec = problem.result_spec(part)
        if spec is not None:
            return "deg" if part.endswith("_deg") else spec.unit
    return "deg" if path.endswith("_deg") else ""


# --- files ------------------------------------------------------------------------------------


def number_width(count: int) -> int:
    return max(2, len(str(count)))


def variant_name(template: Template, number: int, width: int) -> str:
    """``variant-07.toml`` for a file, ``variant-07.json`` for a problem id."""
    return f"variant-{number:0{width}d}." + ("toml" if template.is_file else "json")


def variant_file(
    template: Template, variant: Variant, width: int, sheet: Mapping[str, str] | None = None
) -> bytes:
    """The variant as a file: the TOML with its values set, or the id with its ``--set`` list;
    ``sheet``: its title-block data (the student, the group, the teacher), the file's
    ``[sheet]`` table (a problem id's: ``"sheet"``), which ``geomcad build`` puts in the title
    block of the variant's sheets."""
    if template.is_file:
        import tomli_w

        data = template.variant_data(variant.values)
        if sheet:
            own = data.get("sheet")
            data["sheet"] = {**(own if isinstance(own, Mapping) else {}), **sheet}
        return tomli_w.dumps(data).encode("utf-8")
    sets = {**template.fixed, **dict(variant.values)}
    obj: dict[str, Any] = {"id": template.ref, "variant": variant.number, "set": sets}
    if sheet:
        obj["sheet"] = dict(sheet)
    return (json.dumps(obj, ensure_ascii=False, indent=2) + "\n").encode("utf-8")


def variant_sets(path: Path) -> tuple[str, list[tuple[str, str]]]:
    """A problem-id variant file read back: the id and its ``--set`` pairs."""
    try:
        obj = json.loads(path.read_text(encoding="utf-8-sig"))  # a BOM (Notepad's) is dropped
    except FileNotFoundError:
        raise ParameterError(str(path), "", "no such file") from None
    except RecursionError:
        raise ParameterError(str(path), "", "is not a variant file (nested too deeply)") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ParameterError(str(path), "", f"is not a variant file ({exc})") from None
    if (
        not isinstance(obj, dict)
        or not isinstance(obj.get("id"), str)
        or not isinstance(obj.get("set"), dict)
    ):
        raise ParameterError(str(path), "", 'is not a variant file (needs "id" and "set")')
    return obj["id"], [(str(k), str(v)) for k, v in obj["set"].items()]


def echoes(template: Template, variants: Sequence[Variant], columns: Sequence[str]) -> list[str]:
    """The key's columns that only repeat a file's given data (a gear file's z1 as a result):
    a single result named as a value of the file, equal to it in every variant."""
    if template.data is None:
        return []

    def given(data: Mapping[str, Any]) -> dict[str, Any]:
        out: dict[str, Any] = {}

        def walk(node: Any, name: str) -> None:
            if isinstance(node, Mapping):
                for k, v in node.items():
                    walk(v, str(k))
            elif isinstance(node, list):
                for v in node:
                    walk(v, name)
            elif isinstance(node, int | float) and not isinstance(node, bool):
                out.setdefault(name, node)

        walk(data, "")
        return out

    data = [given(template.variant_data(v.values)) for v in variants]
    return [
        c
        for c in columns
        if "." not in c
        and all(
            c in d and c in v.results and d[c] == v.results[c]
            for d, v in zip(data, variants, strict=True)
        )
    ]
