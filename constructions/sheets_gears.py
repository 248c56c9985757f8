"""The gear design sheet (A1)."""

from __future__ import annotations

from typing import Any


def scales(des: Any) -> dict[str, float]:
    return {"l": 0.001}


def sheets(sol: Any) -> list[tuple[str, Any]]:
    return []
