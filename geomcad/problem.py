"""The problem protocol: what a construction module declares, and what solving it returns.

A problem module in ``constructions/`` defines ``PROBLEM = Problem(...)`` with its parameters
(defaults = the seed's data), the results it reports, the seed's published values and two
functions: ``build(params) -> Build`` (the construction and its results) and
``draw(solution) -> [(name, Sheet), ...]`` (its drawing sheets; name ``""`` is the main sheet).

``Build``, ``Problem`` and ``Solution`` are generic in the type of the problem's model, the
``data`` its build returns: a spec declares ``PROBLEM: Problem[Geometry] = Problem(...)``, its
build returns ``Build[Geometry]``, and a sheet function taking ``Solution[Geometry]`` reads
``sol.data`` type-checked. Code that handles any problem takes ``Problem[Any]``/``Solution[Any]``.

The library never imports a problem module; :mod:`geomcad.registry` discovers them through the
``geomcad.constructions`` entry-point group.

``build`` and ``draw`` may be :func:`lazy` references (``"module:attribute"``, imported on the
first call). A problem package can then keep its ``Problem`` (title, parameters, results, seed)
in a light module that imports neither numpy nor the construction code, so that ``geomcad list``
and ``geomcad solve ID --help`` read every title and parameter without loading scipy.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import numbers
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Generic, Literal, TypeVar

from geomcad.errors import ConstructionError, ParameterError, SheetsFailed
from geomcad.units import PHYSICAL, check_display, wrap_deg

if TYPE_CHECKING:
    from geomcad.construction import Construction
    from geomcad.sheet import Sheet
    from geomcad.sheet.motion import Frames
    from geomcad.sheet.titleblock import TitleData

ParamValue = float | int | str

#: The type of a problem's model: what its build returns as ``Build.data``.
D = TypeVar("D")

#: The largest count (teeth, links, pairs, divisions) a parameter may take unless it says.
MAX_COUNT = 10_000


def _short(value: object) -> object:
    """A value as an error may quote it: a huge integer or a long text is cut short."""
    text = repr(value)
    return value if len(text) <= 40 else f"{text[:20]}…{text[-8:]} ({len(text)} characters)"


SeedKind = Literal["measured", "rounded", "erratum"]


@dataclass(frozen=True)
class Param:
    """One input of a problem.

    ``unit`` is the SI unit ("m", "N", "kg", "1"), or "deg" for names ending in ``_deg``.
    A parameter with ``choices`` takes one of those words; an ``integer`` one takes a whole number;
    any other takes a finite real number, optionally bounded by ``gt``/``ge``/``lt``/``le``.

    An ``optional`` parameter has the default ``None``: unless it is given, it is absent from the
    values that ``build`` receives, and the problem derives it (e.g. a tooth count from a
    coaxiality condition); given, it is checked like any other and the problem checks it against
    what it would have derived. Passing ``None`` for it through the API means "not given".

    Every number has a physical range, checked before any computation: ``span = (lo, hi)`` bounds
    its magnitude, |x| ≤ hi, and where the sign bounds refuse 0 (a length, a mass) also lo ≤ |x|
    (a quantity that may be 0 may also be as small as it likes). By
    default the span is its unit's from :data:`PHYSICAL` (wide enough for any real machine: a
    length from a micron to a kilometre) and, for an integer, at most :data:`MAX_COUNT`.
    A ``turn`` angle means a direction or a position on a turn: it is reduced into [0°, 360°).

    On a sheet's table (:meth:`geomcad.sheet.views.Table.of_specs`) it is written as ``symbol``
    (label markup; default: the name as markup, ``l_AB`` → ``l_{AB}``), in ``display`` (a unit of
    :data:`geomcad.units.DISPLAY` the subject writes it in, e.g. "mm" for a module; default: its
    SI ``unit``), to ``digits`` significant figures.

    >>> Param("H", 0.2, "stroke", "m", gt=0.0).check(1e-308)
    Traceback (most recent call last):
    ...
    geomcad.errors.ParameterError: parameter H = 1e-308: must be between 1e-06 and 1000 m
    >>> Param("psi_deg", 90.0, "direction", "deg", turn=True).check(-90.0)
    270.0
    """

    name: str
    default: ParamValue | None
    doc: str
    unit: str = "1"
    choices: tuple[str, ...] = ()
    integer: bool = False
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    optional: bool = False
    span: tuple[float, float] | None = None
    turn: bool = False
    symbol: str = ""
    display: str = ""
    digits: int = 4

    def __post_init__(self) -> None:
        check_display(self.name, self.unit, self.display)
        if self.optional != (self.default is None):
            raise ValueError(
                f"parameter {self.name}: an optional parameter has the default None, "
                "and only an optional one"
            )

    def parse(self, text: str) -> ParamValue:
        """Read a value given as text (``--set NAME=TEXT``) and check it."""
        if self.choices:
            return self.check(text.strip())
        t = text.strip().replace(",", ".") if text.count(",") == 1 and "." not in text else text
        try:
            value: ParamValue = int(t) if self.integer else float(t)
        except ValueError:
            if self.integer:
                try:
                    f = float(t)
                except ValueError:
                    f = math.nan
                if math.isfinite(f) and f == int(f):
                    value = int(f)
                else:
                    raise ParameterError(self.name, text, "must be a whole number") from None
            else:
                raise ParameterError(self.name, text, "must be a number") from None
        return self.check(value)

    def check(self, value: object) -> ParamValue:
        """Check a value's type and range; return it normalised (int for integer parameters)."""
        if self.choices:
            if not isinstance(value, str) or value not in self.choices:
                raise ParameterError(
                    self.name, _short(value), f"must be one of {', '.join(self.choices)}"
                )
            return value
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise ParameterError(self.name, _short(value), "must be a number")
        try:
            x = float(value)
        except (OverflowError, ValueError, TypeError):
            raise ParameterError(self.name, _short(value), f"must be {self.domain()}") from None
        shown = _short(value)
        if not math.isfinite(x):
            raise ParameterError(self.name, value, "must be a finite number")
        if self.integer:
            if x != int(x):
                raise ParameterError(self.name, shown, "must be a whole number")
            value = int(x)
        else:
            value = x
        if self.gt is not None and not x > self.gt:
            raise ParameterError(self.name, shown, f"must be > {self.gt:g}{self._u()}")
        if self.ge is not None and not x >= self.ge:
            raise ParameterError(self.name, shown, f"must be ≥ {self.ge:g}{self._u()}")
        if self.lt is not None and not x < self.lt:
            raise ParameterError(self.name, shown, f"must be < {self.lt:g}{self._u()}")
        if self.le is not None and not x <= self.le:
            raise ParameterError(self.name, shown, f"must be ≤ {self.le:g}{self._u()}")
        lo, hi = self.magnitudes()
        if not abs(x) <= hi or (abs(x) < lo and not self._signs_allow(0.0)):
            raise ParameterError(self.name, shown, f"must be {self.domain()}")
        if self.turn and not self.integer:
            return wrap_deg(x) if self.unit == "deg" else x
        return value

    def magnitudes(self) -> tuple[float, float]:
        """The span (lo, hi) of |x|: declared, else the unit's physical range."""
        if self.span is not None:
            return self.span
        lo, hi = PHYSICAL.get(self.unit, PHYSICAL["1"])
        if self.integer:
            return 1.0, float(MAX_COUNT)
        return lo, hi

    def domain(self) -> str:
        """The allowed values in words, e.g. "between 1e-06 and 1000 m" (for help and errors)."""
        if self.choices:
            return f"one of {', '.join(self.choices)}"
        lo, hi = self.magnitudes()
        low, high = -hi, hi
        for b in (self.gt, self.ge):
            low = low if b is None else max(low, b)
        for b in (self.lt, self.le):
            high = high if b is None else min(high, b)
        u = self._u()
        if lo == hi and not self._signs_allow(0.0):
            return f"{lo:g}{u}" if low >= 0.0 else f"+{lo:g} or −{lo:g}{u}"
        if not self._signs_allow(0.0):  # a positive quantity: at least its physical least
            return f"between {max(lo, low):g} and {high:g}{u}"
        return f"between {low:g} and {high:g}{u}"

    def _signs_allow(self, x: float) -> bool:
        return not (
            (self.gt is not None and not x > self.gt)
            or (self.ge is not None and not x >= self.ge)
            or (self.lt is not None and not x < self.lt)
            or (self.le is not None and not x <= self.le)
        )

    def _u(self) -> str:
        return "" if self.unit == "1" else f" {self.unit}"


@dataclass(frozen=True)
class SeedValue:
    """A value the seed published, converted to SI, with the class that sets its comparison.

    - ``measured``: read off the seed's drawing; ``tol`` is 0.5 mm at the seed's scale.
    - ``rounded``: printed after rounding; ``tol`` is half a unit of the last printed digit.
    - ``erratum``: the seed is wrong; ``note`` says how, and the results' notes repeat it.
    """

    value: float
    kind: SeedKind
    tol: float
    printed: str
    note: str = ""

    def agrees(self, exact: float) -> bool:
        """True when ``exact`` lies within this value's comparison tolerance."""
        return self.kind != "erratum" and abs(exact - self.value) <= self.tol


def measured(mm: float, k: float, printed: str) -> SeedValue:
    """A length measured off the seed's drawing: ``mm`` sheet millimetres at ``k`` units/mm."""
    return SeedValue(mm * k, "measured", 0.5 * k, printed)


def measured_value(value: float, k: float, printed: str) -> SeedValue:
    """A quantity (in its SI unit) the seed derived from drawing measurements at ``k`` units/mm."""
    return SeedValue(value, "measured", 0.5 * k, printed)


def rounded(value: float, decimals: int, printed: str, unit: float = 1.0) -> SeedValue:
    """A value printed with ``decimals`` decimals in a unit that is ``unit`` SI units."""
    return SeedValue(value * unit, "rounded", 0.5 * 10.0 ** (-decimals) * unit, printed)


def erratum(value: float, note: str, printed: str) -> SeedValue:
    """A published value that is wrong; ``note`` says what the seed should have written."""
    return SeedValue(value, "erratum", 0.0, printed, note)


#: A seed entry: one value, or a list result's values item by item (radius vectors at the
#: division points …), each with its own class.
SeedEntry = SeedValue | tuple[SeedValue, ...]


def _seed_items(name: str, entry: SeedEntry) -> list[tuple[str, int | None, SeedValue]]:
    """The entry's values with their report names: ``name``, or ``name.INDEX`` for a list."""
    if isinstance(entry, SeedValue):
        return [(name, None, entry)]
    return [(f"{name}.{i}", i, v) for i, v in enumerate(entry)]


def _exact_item(results: Mapping[str, Any], name: str, index: int | None) -> object:
    value = results.get(name)
    if index is None:
        return value
    if isinstance(value, list | tuple) and index < len(value):
        return value[index]
    return None


@dataclass(frozen=True)
class ResultSpec:
    """What a result means, for reports and for ``verify``.

    ``drawn`` names the plan scale it is drawn at on the project's own sheet: "l" (mechanism,
    k_l), "v", "a", "F"; ``None`` when it is not drawn (a ratio, a count).
    ``symbol``, ``display``, ``digits``: how a sheet's table writes it, as :class:`Param`'s.
    """

    name: str
    unit: str
    doc: str
    drawn: str | None = None
    symbol: str = ""
    display: str = ""
    digits: int = 4

    def __post_init__(self) -> None:
        check_display(self.name, self.unit, self.display)


@dataclass
class Build(Generic[D]):
    """What a problem's ``build`` returns: ``data`` is the problem's model, of type ``D``
    (``None`` for a problem that keeps none: a ``Build[None]``)."""

    results: dict[str, Any]
    construction: Construction
    notes: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    # The default stands for a Build[None] only; mypy cannot say so of a generic field.
    data: D = None  # type: ignore[assignment]


class _Lazy:
    """A callable named ``module:attribute``, imported when it is first called."""

    def __init__(self, ref: str, package: str | None) -> None:
        module, sep, attr = ref.partition(":")
        if not sep or not module or not attr:
            raise ValueError(f"lazy reference {ref!r}: expected 'module:attribute'")
        self.ref = ref
        #: The absolute name of the module that holds the callable.
        self.module = importlib.util.resolve_name(module, package) if module[0] == "." else module
        self._module = module
        self._attr = attr
        self._package = package
        self._target: Callable[..., Any] | None = None

    def resolve(self) -> Callable[..., Any]:
        """The callable itself (its module is imported on the first use)."""
        if self._target is None:
            module = importlib.import_module(self._module, self._package)
            target = getattr(module, self._attr)
            if not callable(target):
                raise TypeError(f"lazy reference {self.ref!r} is not callable")
            self._target = target
        return self._target

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        return self.resolve()(*args, **kwargs)

    def __repr__(self) -> str:
        return f"lazy({self.ref!r})"


def lazy(ref: str, package: str | None = None) -> Callable[..., Any]:
    """A stand-in for the callable ``ref`` (``"module:attribute"``) that imports its module on
    the first call; a relative ``ref`` (``".p2013_6:build"``) is taken inside ``package``.

    >>> f = lazy("math:hypot")
    >>> f(3.0, 4.0)
    5.0
    """
    return _Lazy(ref, package)


@dataclass(frozen=True)
class Problem(Generic[D]):
    """A problem id with its parameters, results, seed values, construction and drawings;
    ``D`` is the type of its model (``Build.data``, ``Solution.data``)."""

    id: str
    title: str
    params: tuple[Param, ...]
    results: tuple[ResultSpec, ...]
    seed: Mapping[str, SeedEntry]
    build: Callable[[Mapping[str, ParamValue]], Build[D]]
    draw: Callable[[Solution[D]], Sequence[tuple[str, Sheet]]]
    seed_k_l: float | None = None
    #: A problem stated by a file (:mod:`geomcad.documents`): the file's data, printed as the
    #: ``params`` of ``solve --json``; ``None`` for a registered problem id.
    inputs: Mapping[str, Any] | None = None
    #: The mechanism over one crank turn, ``motion(solution, frames)``, for ``geomcad animate``;
    #: ``None`` for a problem without a crank mechanism to animate.
    motion: Callable[[Solution[D], int], Frames] | None = None
    #: The sheet's scale factors (``{"l": k_l, "v": k_v, ...}``, SI per mm), chosen by the sheet
    #: layer from the solved model, for ``verify`` to turn a student's millimetres into values;
    #: ``None`` when the build itself states them (``Build.scales``) or the sheet has none.
    scales: Callable[[Solution[D]], Mapping[str, float]] | None = None
    #: Notes on the seed's own statement (a misprinted formula), given before the construction's
    #: notes by every solve with the seed's data; the problem's spec states them, so the
    #: construction takes values and never asks whether they are the seed's.
    seed_notes: tuple[str, ...] = ()

    def param(self, name: str, value: object = "?") -> Param:
        """The declared parameter ``name``; an unknown name is a :class:`ParameterError` that
        quotes ``value``, the value it was given."""
        for p in self.params:
            if p.name == name:
                return p
        known = ", ".join(p.name for p in self.params) or "none"
        raise ParameterError(name, value, f"{self.id} has no such parameter (it has {known})")

    def result_spec(self, name: str) -> ResultSpec | None:
        """The spec of result ``name``, or of the field ``name`` inside a list of objects."""
        for r in self.results:
            if r.name == name:
                return r
        return None

    @property
    def defaults(self) -> dict[str, ParamValue]:
        """The default values; optional parameters (default ``None``) are absent."""
        return {p.name: p.default for p in self.params if p.default is not None}

    def solve(self, **params: object) -> Solution[D]:
        """Check the parameters, run the construction and return the :class:`Solution`.

        ``None`` for an optional parameter leaves it out (the problem derives it)."""
        values = self.defaults
        for name, value in params.items():
            p = self.param(name, value)
            if value is None and p.optional:
                values.pop(name, None)
                continue
            values[name] = p.check(value)
        from geomcad.construction.guard import guarded

        with guarded(f"the construction of {self.id}"):
            b = self.build(values)
        _check_finite(b.results, "results")
        return Solution(self, values, b)


def _check_finite(value: object, path: str) -> None:
    """No result may hold a NaN or an infinity: it is an error naming the result."""
    if isinstance(value, float) and not math.isfinite(value):
        raise ConstructionError(path, f"the construction produced the non-finite number {value}")
    if hasattr(value, "dtype") and hasattr(value, "shape"):  # a numpy array or scalar
        import numpy as np

        a = np.asarray(value)
        if a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
            raise ConstructionError(path, "the construction produced a non-finite number")
        return
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, f"{path}.{k}")
    elif isinstance(value, list | tuple):
        for i, v in enumerate(value):
            _check_finite(v, f"{path}.{i}")


class Solution(Generic[D]):
    """A solved problem: parameters, results, the recorded construction, seed comparison, and
    the problem's model ``data`` (of type ``D``)."""

    def __init__(self, problem: Problem[D], params: dict[str, ParamValue], build: Build[D]) -> None:
        self.problem = problem
        self.params = params
        self.results = build.results
        self.construction = build.construction
        self._scales: Mapping[str, float] | None = build.scales or None
        self.data: D = build.data
        self._notes = list(build.notes)
        self._main_svg: str | None = None

    @property
    def scales(self) -> Mapping[str, float]:
        """The sheet's scale factors (see ``Problem.scales``), computed on first use."""
        if self._scales is None:
            hook = self.problem.scales
            self._scales = dict(hook(self)) if hook is not None else {}
        return self._scales

    @property
    def is_seed(self) -> bool:
        """True when every parameter has its default (the seed's) value."""
        return self.params == self.problem.defaults

    @property
    def seed(self) -> dict[str, Any]:
        """The seed's published values under the result names, in SI (a list for a list
        result); empty for a variant."""
        if not self.is_seed:
            return {}
        return {
            k: v.value if isinstance(v, SeedValue) else [x.value for x in v]
            for k, v in self.problem.seed.items()
        }

    @property
    def diff(self) -> dict[str, Any]:
        """exact − seed for every published value (a list for a list result); empty for a
        variant."""
        out: dict[str, Any] = {}
        for k, v in self.seed.items():
            exact = self.results.get(k)
            if isinstance(v, list):
                if isinstance(exact, list) and len(exact) >= len(v):
                    out[k] = [float(e) - s for e, s in zip(exact, v, strict=False)]
            elif isinstance(exact, int | float):
                out[k] = float(exact) - v
        return out

    @property
    def notes(self) -> list[str]:
        """The construction's notes, plus the notes on the seed's statement and every seed
        erratum when the seed's data are used."""
        seed = self.is_seed
        notes = [*self.problem.seed_notes, *self._notes] if seed else list(self._notes)
        if seed:
            for k, entry in self.problem.seed.items():
                for name, _, v in _seed_items(k, entry):
                    if v.kind == "erratum":
                        notes.append(f"erratum {name}: the seed prints {v.printed}; {v.note}")
        return notes

    def seed_report(self) -> list[dict[str, Any]]:
        """Per seed value: exact, published, difference, class, tolerance, agreement."""
        rows = []
        for k, entry in self.problem.seed.items():
            for name, index, v in _seed_items(k, entry):
                exact = _exact_item(self.results, k, index)
                if not isinstance(exact, int | float):
                    continue
                rows.append(self._seed_row(name, float(exact), v))
        return rows

    @staticmethod
    def _seed_row(name: str, exact: float, v: SeedValue) -> dict[str, Any]:
        return {
            "name": name,
            "exact": exact,
            "seed": v.value,
            "diff": exact - v.value,
            "class": v.kind,
            "tol": v.tol,
            "agrees": v.agrees(exact),
            "printed": v.printed,
        }

    def to_json(self) -> dict[str, Any]:
        """The ``solve --json`` object of the interface."""
        return {
            "id": self.problem.id,
            "params": dict(self.params) if self.problem.inputs is None else self.problem.inputs,
            "results": self.results,
            "seed": self.seed,
            "diff": self.diff,
            "notes": self.notes,
        }

    def sheets(self, title: TitleData | None = None) -> list[tuple[str, Sheet]]:
        """The problem's hand-in sheets: ``[(name, Sheet)]``, name ``""`` for the main sheet.

        Their title blocks are filled as one document (Лист i of Листов n, one designation)
        with the user's ``title`` data; without it the people's cells stay empty. They are drawn
        in ``title.lang`` when it is given (``TitleData(lang="en")``), else in the language being
        drawn (Russian unless inside ``with geomcad.sheet.lang.language("en"):``). Each sheet
        shows itself as SVG in Jupyter (:mod:`geomcad.notebook`).

        A sheet that cannot be drawn raises :class:`~geomcad.errors.SheetsFailed` once the
        others are drawn: its ``sheets`` are those others, filled as sheets of the whole planned
        document (Лист i of Листов n counting the failed one).
        """
        import geomcad.notebook  # noqa: F401  (sets the sheets' SVG display)
        from geomcad.construction.guard import guarded
        from geomcad.sheet.frame import fill_title_blocks
        from geomcad.sheet.lang import current, language

        lang = (title.lang if title is not None else "") or current()
        with guarded(f"drawing the sheets of {self.problem.id}"), language(lang):
            try:
                out = list(self.problem.draw(self))
            except SheetsFailed as exc:
                # the sheets that were drawn, filled as the planned document (a failed sheet
                # keeps its number), handed back on the error
                fill_title_blocks([s for _, s in exc.sheets], title)
                exc.sheets = exc.drawn()
                raise
            fill_title_blocks([s for _, s in out], title)
        return out

    def _repr_html_(self) -> str:
        """Jupyter's view of a solution: the table of its results (:mod:`geomcad.notebook`)."""
        from geomcad.notebook import results_html

        return results_html(self)

    def _repr_svg_(self) -> str:
        """The main sheet as SVG (drawn once per solution)."""
        if self._main_svg is None:
            from geomcad.notebook import sheet_svg

            self._main_svg = sheet_svg(self.sheets()[0][1])
        return self._main_svg

    def trace(self) -> str:
        """The construction protocol, one line per named step."""
        return self.construction.trace()
