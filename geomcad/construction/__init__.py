"""The construction layer: the step recorder, branch rules and the text protocol."""

from geomcad.construction.branch import (
    Any_,
    Index,
    LeftOf,
    Nearest,
    OnArc,
    RightOf,
    Rule,
    Where,
    left_of,
    nearest,
    right_of,
)
from geomcad.construction.recorder import Construction, Step, fmt

__all__ = [
    "Any_",
    "Construction",
    "Index",
    "LeftOf",
    "Nearest",
    "OnArc",
    "RightOf",
    "Rule",
    "Step",
    "Where",
    "fmt",
    "left_of",
    "nearest",
    "right_of",
]
