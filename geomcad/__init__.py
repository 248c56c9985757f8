"""geomcad: Theory of Machines and Mechanisms by exact graphical constructions.

>>> import geomcad
>>> sol = geomcad.solve("2013-6")
>>> round(sol.results["theta_deg"], 4)
23.4783
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from geomcad.errors import (
    ConstructionError,
    DegenerateInput,
    GeomcadError,
    MissingDependency,
    NoIntersection,
    ParallelLines,
    ParameterError,
    UnknownProblem,
)

if TYPE_CHECKING:
    from geomcad.problem import Solution

__version__ = "0.1.0"

__all__ = [
    "ConstructionError",
    "DegenerateInput",
    "GeomcadError",
    "MissingDependency",
    "NoIntersection",
    "ParallelLines",
    "ParameterError",
    "UnknownProblem",
    "problem_ids",
    "solve",
]


def solve(problem_id: str, **params: object) -> Solution[Any]:
    """Solve a registered problem with the given parameters (SI units; ``*_deg`` in degrees),
    or a linkage, cam or gear file (a path ending in ``.toml``; its data are its parameters)."""
    from geomcad import documents, registry
    from geomcad.errors import ParameterError

    if isinstance(problem_id, str) and documents.is_file_id(problem_id):
        for name, value in params.items():
            raise ParameterError(name, value, f"{problem_id} is a file: change the file instead")
        return documents.solve(problem_id)
    return registry.get(problem_id).solve(**params)


def problem_ids() -> list[str]:
    """The ids of every registered problem."""
    from geomcad import registry

    return registry.problem_ids()
