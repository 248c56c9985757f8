"""Floating-point trouble inside a construction is an error naming the step, never a warning.

:func:`guarded` runs a solve (or a drawing) under ``np.errstate(all="raise")`` with numpy's and
scipy's run-time warnings raised as exceptions, and turns what escapes from the arithmetic —
``FloatingPointError``, ``OverflowError``, ``ZeroDivisionError``, a ``math domain error``, a
``LinAlgError`` that did not converge, a warning — into a
:class:`~geomcad.errors.ConstructionError` that names the step that was running. Every
:class:`~geomcad.construction.Construction` made inside it is watched, so the step is known
even where the arithmetic ran between two recorded steps ("the step after «O»").

:class:`Budget` is the wall-clock and evaluation budget of an iterative step (an ODE
integration, a root search): spent, it is a ``ConstructionError`` naming the step, never a hang.

    >>> import math
    >>> from geomcad.construction import Construction
    >>> from geomcad.errors import ConstructionError
    >>> try:
    ...     with guarded("demo"):
    ...         c = Construction("demo")
    ...         _ = c.value("a", 1.0, "given")
    ...         x = math.exp(1000.0)
    ... except ConstructionError as exc:
    ...     print(exc.step)
    the step after «a» in demo
"""

from __future__ import annotations

import contextlib
import time
import warnings
from collections.abc import Iterator
from contextvars import ContextVar
from typing import TYPE_CHECKING

import numpy as np

from geomcad.errors import STEP_NOTE, ConstructionError, GeomcadError

if TYPE_CHECKING:
    from geomcad.construction.recorder import Construction

#: The constructions made inside the innermost :func:`guarded` block.
_WATCHED: ContextVar[list[Construction] | None] = ContextVar("geomcad_watched", default=None)

#: What the arithmetic raises when a number leaves float64 or a formula leaves its domain.
NUMERIC = (
    FloatingPointError,
    OverflowError,
    ZeroDivisionError,
    np.linalg.LinAlgError,
    RuntimeWarning,
    UserWarning,  # scipy's IntegrationWarning, ODE and optimiser warnings
)


def watch(c: Construction) -> None:
    """Called by every new :class:`Construction`: remember it for the step names of errors."""
    box = _WATCHED.get()
    if box is not None:
        box.append(c)


def is_numeric(exc: BaseException) -> bool:
    """True for an exception the arithmetic raises on a value out of range (see :data:`NUMERIC`;
    a ``ValueError`` only when it is the ``math`` module's domain error)."""
    if isinstance(exc, NUMERIC):
        return True
    return type(exc) is ValueError and "math domain error" in str(exc)


def why(exc: BaseException) -> str:
    """The arithmetic failure in words, for the ``error:`` line."""
    kind = type(exc).__name__
    text = str(exc) or kind
    if isinstance(exc, ZeroDivisionError) or "divide by zero" in text:
        what = "a division by zero"
    elif isinstance(exc, OverflowError) or "overflow" in text:
        what = "a number overflowed"
    elif "underflow" in text:
        what = "a number underflowed to zero"
    elif "invalid value" in text or "domain" in text:
        what = "a formula left its domain (not a number)"
    elif isinstance(exc, np.linalg.LinAlgError):
        what = "a linear system could not be solved"
    else:
        what = "the arithmetic failed"
    return f"{what} ({kind}: {text}); the parameters are probably too extreme for this method"


def running_step(title: str, constructions: list[Construction]) -> str:
    """The name of the step that was running: after the last recorded step, if any."""
    for c in reversed(constructions):
        if c.steps:
            return f"the step after «{c.steps[-1].name}» in {c.title}"
    if constructions:
        return f"the first step of {constructions[-1].title}"
    return title


@contextlib.contextmanager
def guarded(title: str) -> Iterator[list[Construction]]:
    """Run the block with floating-point trouble raised, and report it as a ConstructionError.

    ``title`` names the work when no construction step is known (e.g. "drawing the sheets").
    A :class:`ConstructionError` raised inside passes unchanged.
    """
    box: list[Construction] = []
    token = _WATCHED.set(box)
    try:
        # a float that underflows to 0 is exact enough for a drawing; its consequences (a
        # division by it) are caught where they happen
        with np.errstate(all="raise", under="ignore"), warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            warnings.simplefilter("error", UserWarning)
            yield box
    except ConstructionError:
        raise
    except Exception as exc:
        if not is_numeric(exc):
            if not isinstance(exc, GeomcadError):
                # an unexpected exception keeps its type; the note says where it happened
                exc.add_note(STEP_NOTE + running_step(title, box))
            raise
        raise ConstructionError(running_step(title, box), why(exc)) from exc
    finally:
        _WATCHED.reset(token)


class BudgetSpent(ConstructionError):
    """An iterative step used up its budget of evaluations or of wall-clock time."""


class Budget:
    """A budget of ``evaluations`` and ``seconds`` for the iterative step ``step``.

    Call :meth:`spend` once per evaluation (e.g. in an ODE's right-hand side); it raises
    :class:`BudgetSpent` naming the step, with ``hint`` (what makes the step costly), when
    either limit is passed.
    """

    def __init__(self, step: str, evaluations: int, seconds: float, hint: str = "") -> None:
        self.step = step
        self.evaluations = evaluations
        self.seconds = seconds
        self.hint = hint
        self.used = 0
        self._start = time.monotonic()

    def spend(self, n: int = 1) -> None:
        """Count ``n`` evaluations; raise :class:`BudgetSpent` when the budget is gone."""
        self.used += n
        if self.used > self.evaluations:
            self._fail(f"{self.evaluations} evaluations")
        # the clock is read every 64 evaluations: cheap, and still within a few ms
        if self.used % 64 == 0 and time.monotonic() - self._start > self.seconds:
            self._fail(f"{self.seconds:g} s")

    def _fail(self, what: str) -> None:
        hint = f"; {self.hint}" if self.hint else ""
        raise BudgetSpent(self.step, f"the step did not finish within its budget of {what}{hint}")
