"""The readable ``geomcad solve FILE.toml`` report of a linkage file: tables, not a wall.

The top-level results one a line with their units; then, for the positions (and for the force
analysis' position, ``results.forces``), one table per group of quantities: the points
(x, y, V, a with their components), the links (ω, ε), the sliding pairs (V_rel, a_cor), the
reactions (R_i_j with its components) and the moments (M_bal, M_bal_lever); the dynamics'
I_pr and M_pr over the numbered positions. Every column's header carries its unit; a value
below :data:`ZERO` of its column's scale (the largest magnitude of that quantity in the table)
is the round-off of a zero and prints as 0.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from typing import Any

from geomcad import tol

#: A value at most this fraction of its quantity's scale prints as 0.
ZERO = tol.REL_LENGTH

_POINT = re.compile(r"^(x|y|V|a)_(.+?)(_x|_y)?$")


def _num(x: float, scale: float) -> str:
    if not math.isfinite(x):
        return str(x)
    if abs(x) <= ZERO * scale:
        return "0"
    return f"{x:.6g}"


#: The lists that the dynamics' table shows.
DYNAMICS_LISTS = ("I_pr", "M_pr", "dynamics_phi_deg")


def _value(v: object) -> str:
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return _num(v, abs(v))
    if isinstance(v, list):
        nums = [abs(x) for x in v if isinstance(x, float) and math.isfinite(x)]
        scale = max(nums, default=0.0)
        return "[" + ", ".join(_num(x, scale) if isinstance(x, float) else str(x) for x in v) + "]"
    return str(v)


def _unit(u: str) -> str:
    if u in ("", "1"):
        return ""
    return "°" if u == "deg" else f" {u}"


def table(
    head: Sequence[str], rows: Sequence[Sequence[float | str]], indent: str = "  "
) -> list[str]:
    """Rows under a header, numbers to 6 significant figures, round-off of a zero as 0 (by
    each column's largest magnitude), columns aligned."""
    n = len(head)
    scales = []
    for j in range(n):
        nums = [abs(float(c)) for r in rows if not isinstance(c := r[j], str) and math.isfinite(c)]
        scales.append(max(nums, default=0.0))
    cells = [list(head)] + [
        [c if isinstance(c, str) else _num(float(c), scales[j]) for j, c in enumerate(r)]
        for r in rows
    ]
    widths = [max(len(r[j]) for r in cells) for j in range(n)]

    def line(r: Sequence[str]) -> str:
        return (
            indent
            + "  ".join(
                c.rjust(w) if i > 0 else c.ljust(w)
                for i, (c, w) in enumerate(zip(r, widths, strict=True))
            ).rstrip()
        )

    out = [line(cells[0]), indent + "  ".join("-" * w for w in widths)]
    out += [line(r) for r in cells[1:]]
    return out


def _points(objs: Sequence[dict[str, Any]], nos: Sequence[str]) -> list[str]:
    names: list[str] = []
    for k in objs[0]:
        m = _POINT.match(k)
        if m and m.group(1) == "x":
            names.append(m.group(2))
    if not names:
        return []
    head = ["№", "φ1, °", "point", "x, m", "y, m", "V, m/s", "V_x, m/s", "V_y, m/s",
            "a, m/s²", "a_x, m/s²", "a_y, m/s²"]  # fmt: skip
    rows: list[list[float | str]] = []
    for i, o in enumerate(objs):
        for p in names:
            rows.append([nos[i], o["phi_deg"], p, o[f"x_{p}"], o[f"y_{p}"],
                         o[f"V_{p}"], o[f"V_{p}_x"], o[f"V_{p}_y"],
                         o[f"a_{p}"], o[f"a_{p}_x"], o[f"a_{p}_y"]])  # fmt: skip
    return ["points:", *table(head, rows)]


def _columns(
    title: str, objs: Sequence[dict[str, Any]], cols: list[tuple[str, str]], nos: Sequence[str]
) -> list[str]:
    if not cols:
        return []
    head = ["№", "φ1, °", *[h for _, h in cols]]
    rows = [[nos[i], o["phi_deg"], *[o[k] for k, _ in cols]] for i, o in enumerate(objs)]
    return [f"{title}:", *table(head, rows)]


def _reactions(objs: Sequence[dict[str, Any]], nos: Sequence[str]) -> list[str]:
    pairs = [k for k in objs[0] if re.fullmatch(r"R_\d+_\d+", k)]
    if not pairs:
        return []
    head = ["№", "φ1, °", "pair i–j", "R_i_j, N", "R_i_j_x, N", "R_i_j_y, N"]
    rows: list[list[float | str]] = []
    for i, o in enumerate(objs):
        for k in pairs:
            a, b = k.split("_")[1:]
            rows.append([nos[i], o["phi_deg"], f"{a}–{b}", o[k], o[f"{k}_x"], o[f"{k}_y"]])
    return ["reactions (R_i_j: the force of link i on link j):", *table(head, rows)]


def positions(
    objs: Sequence[dict[str, Any]], what: str, nos: Sequence[str] | None = None
) -> list[str]:
    """The tables of a list of position objects (``nos``: their numbers, default 0, 1, …)."""
    if not objs:
        return []
    nos = nos if nos is not None else [str(i) for i in range(len(objs))]
    o0 = objs[0]
    links = [k for k in o0 if re.fullmatch(r"(omega|eps)_\d+", k)]
    lcols = [(k, f"{'ω' if k.startswith('omega') else 'ε'}{k.split('_')[1]}, "
              f"{'rad/s' if k.startswith('omega') else 'rad/s²'}") for k in links]  # fmt: skip
    pcols = [(k, f"{k}, {'m/s' if k.startswith('V_rel') else 'm/s²'}")
             for k in o0 if k.startswith(("V_rel_", "a_cor_"))]  # fmt: skip
    mcols: list[tuple[str, str]] = [(k, f"{k}, N·m") for k in ("M_bal", "M_bal_lever") if k in o0]
    out = [f"{what}:"]
    for part in (
        _points(objs, nos),
        _columns("links", objs, lcols, nos),
        _columns("sliding pairs (V_rel, a_cor: magnitudes)", objs, pcols, nos),
        _reactions(objs, nos),
        _columns("moments on the crank", objs, mcols, nos),
    ):
        if part:
            out += ["", *[f"  {line}" for line in part]]
    return out


def report(
    ident: str,
    title: str,
    results: dict[str, Any],
    unit_of: Callable[[str], str],
    notes: Sequence[str],
    numbered: bool = True,
    force_no: int | None = None,
) -> str:
    """The text report: the top-level results, then the tables (``numbered``: the positions
    are the numbered ones, else the file's ``phi``; ``force_no``: the force position's
    number, ``None`` for a ``[forces] phi`` that is none)."""
    lines = [f"{ident} · {title}", "", "results:"]
    lists: dict[str, list[float]] = {}
    for name, value in results.items():
        if name in ("positions", "forces", "structure"):
            continue
        if name in DYNAMICS_LISTS and isinstance(value, list):
            lists[name] = value
            continue
        if isinstance(value, dict):  # a table of results (a synthesis' data)
            lines.append(f"  {name}:")
            lines += [f"    {k} = {_value(v)}{_unit(unit_of(k))}" for k, v in value.items()]
            continue
        lines.append(f"  {name} = {_value(value)}{_unit(unit_of(name))}")
    objs = results.get("positions") or []
    if objs:
        what = "the numbered positions" if numbered else "the positions of drive.phi, as listed"
        lines += ["", *positions(objs, f"{what} ({len(objs)})")]
    forces = results.get("forces")
    if isinstance(forces, dict):
        phi = forces.get("phi_deg", 0.0)
        no = "φ" if force_no is None else str(force_no)
        head = f"the force analysis' position (φ1 = {phi:.6g}°)"
        lines += ["", *positions([forces], head, [no])]
    if "I_pr" in lists:
        phis = lists.get("dynamics_phi_deg") or [math.nan] * len(lists["I_pr"])
        rows: list[list[float | str]] = [
            [str(i), p, a, b]
            for i, (p, a, b) in enumerate(
                zip(phis, lists["I_pr"], lists.get("M_pr", []), strict=False)
            )
        ]
        lines += ["", "dynamics over the numbered positions:"]
        lines += table(["№", "φ1, °", "I_pr, kg·m²", "M_pr, N·m"], rows)
    if notes:
        lines += ["", "notes:"] + [f"  - {' '.join(n.split())}" for n in notes]
    return "\n".join(lines) + "\n"
