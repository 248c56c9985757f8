"""One error family for the whole library.

``GeomcadError`` is the root. ``ParameterError`` names a parameter, its value and the allowed
range; ``ConstructionError`` names the construction step that failed and why. Both derive from
``ValueError`` too, so callers that only know the standard library can still catch them. The CLI
turns any of them into one ``error:`` line and exit status 2.
"""

from __future__ import annotations

from typing import Any

#: The most of a bad value (or of a name) an error message quotes, in characters: a 5 MB
#: string given as a parameter is named by its start, not repeated.
QUOTE_CHARS = 60


def shorten(text: str, limit: int = QUOTE_CHARS) -> str:
    """``text``, or its first ``limit`` characters and "…" when it is longer.

    >>> shorten("x" * 100, 5)
    'xxxxx…'
    """
    return text if len(text) <= limit else text[:limit] + "…"


def shorten_name(name: str, limit: int = QUOTE_CHARS) -> str:
    """A name for an error message: a file's path keeps its end (the file's own name), anything
    else its start (:func:`shorten`).

    >>> shorten_name("/tmp/" + "d" * 80 + "/mech.toml", 16)
    '…dddddd/mech.toml'
    """
    if len(name) > limit and ("/" in name or name.lower().endswith(".toml")):
        return "…" + name[len(name) - limit :]
    return shorten(name, limit)


def quote(value: object, limit: int = QUOTE_CHARS) -> str:
    """``repr(value)`` for an error message, at most about ``limit`` characters of it: a long
    string or a deeply nested list is quoted by its start (``reprlib`` bounds the nesting).

    >>> quote("abc")
    "'abc'"
    >>> quote("y" * 100, 8)
    "'yyyyyyy…"
    >>> quote([[[[[[1]]]]]], 20)
    '[[[[[...]]]]]'
    """
    if isinstance(value, str):
        return shorten(repr(value[: limit + 1]), limit)
    import reprlib

    r = reprlib.Repr()
    r.maxlevel = 4
    r.maxstring = r.maxother = r.maxlong = limit
    return shorten(r.repr(value), limit)


#: The prefix of the note that a solve adds to an unexpected exception (not a GeomcadError): the
#: step that was running, which the CLI's "internal error in STEP" line quotes.
STEP_NOTE = "geomcad step: "


class GeomcadError(ValueError):
    """Root of every error geomcad raises on purpose."""


class ParameterError(GeomcadError):
    """A parameter is outside its allowed range, of the wrong type, or unknown.

    >>> str(ParameterError("K", 0.8, "must be > 1 (K = 1 gives θ = 0)"))
    'parameter K = 0.8: must be > 1 (K = 1 gives θ = 0)'
    """

    def __init__(self, name: str, value: object, why: str) -> None:
        self.name = name
        self.value = value
        self.why = why
        super().__init__(f"parameter {shorten_name(name)} = {quote(value)}: {why}")


class ConstructionError(GeomcadError):
    """A construction step cannot be carried out.

    >>> str(ConstructionError("B0 = circle(O2, l3) ∩ circle(C0, l4)", "the circles do not meet"))
    'step "B0 = circle(O2, l3) ∩ circle(C0, l4)": the circles do not meet'
    """

    def __init__(self, step: str, why: str) -> None:
        self.step = step
        self.why = why
        super().__init__(f'step "{step}": {why}')


class NoIntersection(ConstructionError):
    """Two objects that a step intersects do not meet (or meet on no admissible branch)."""


class ParallelLines(ConstructionError):
    """Two lines that a step intersects are parallel."""


class DegenerateInput(ConstructionError):
    """A step's input is degenerate: coincident points, a zero-length direction, a zero radius."""


class MissingDependency(GeomcadError):
    """An optional system component (libcairo for PDF and PNG) is not installed."""


class UnknownProblem(GeomcadError):
    """No construction is registered under the requested id."""


class FileKeyError(ParameterError):
    """A key of an input file (a linkage file …) is missing, unknown, of the wrong type or out of
    its domain; the message names the key as the file writes it.

    >>> str(FileKeyError("group 2", "", 'point "Q" is not known yet'))
    'group 2: point "Q" is not known yet'
    """

    def __init__(self, key: str, value: object, why: str) -> None:
        super().__init__(key, value, why)
        self.args = (f"{shorten_name(key)}: {why}",)

    def __str__(self) -> str:
        return f"{shorten_name(self.name)}: {self.why}"


class SheetsFailed(GeomcadError):
    """Some sheets of a document could not be drawn; the others were (issue 27, review 14).

    ``sheets`` holds the document's sheets in order as ``(name, Sheet)``, a failed sheet as
    ``(name, None)`` so that it keeps its place: the drawn sheets keep the numbers of the whole
    planned document (Лист i of Листов n counts the failed sheet too), and a sheet drawn later
    by hand takes the missing number. ``failures`` pairs each failed sheet's name with its error;
    the message names every one of them, each with its own construction step or parameter.

    >>> e = SheetsFailed([("", None)], [("forces", ParameterError("layout", "x", "no room"))])
    >>> str(e)
    "sheet forces: parameter layout = 'x': no room"
    """

    def __init__(
        self, sheets: list[tuple[str, Any]], failures: list[tuple[str, Exception]]
    ) -> None:
        self.sheets = sheets
        self.failures = failures
        super().__init__("; ".join(f"sheet {name}: {exc}" for name, exc in failures))

    @staticmethod
    def sheet_own(exc: Exception) -> bool:
        """Whether ``exc`` is a failure of one sheet's drawing (a construction step of it, or its
        layout finding no room), which leaves the document's other sheets drawn; an error of the
        input (a file key, a parameter the user gave: ``sheet.format``, a point name the font
        cannot letter …) refuses the whole document, as a solve would, and writes nothing.

        >>> SheetsFailed.sheet_own(ParameterError("layout", "x", "has no room on the sheet"))
        True
        >>> SheetsFailed.sheet_own(ParameterError("sheet.format", "B5", "must be one of A4, A1"))
        False
        """
        if isinstance(exc, ConstructionError):
            return True
        return (
            isinstance(exc, ParameterError)
            and not isinstance(exc, FileKeyError)
            and exc.name == "layout"
        )

    def drawn(self) -> list[tuple[str, Any]]:
        """The sheets that were drawn, in order (the failed ones left out)."""
        return [(n, s) for n, s in self.sheets if s is not None]
