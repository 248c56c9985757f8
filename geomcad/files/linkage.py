"""A linkage file as a problem (:mod:`geomcad.documents`): the model, the solution, the sheets.

The file is the data: the problem has no parameters (``--set`` edits the file's keys), no seed,
and its ``inputs`` are the file's data. Its results are those of ``../shared/linkages.md``, and
``scales`` are the sheet's own (k_l of the mechanism, k_v and k_a of the plans), asked of the sheet
layer lazily, only where ``geomcad verify`` reads drawn values at the scales they are drawn at: a
solve loads no sheet module and lays out no sheet.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from geomcad.construction import Construction
from geomcad.errors import GeomcadError, SheetsFailed
from geomcad.linkage import parse
from geomcad.linkage.solution import Solved, results, solve
from geomcad.problem import Build, ParamValue, Problem, ResultSpec, Solution

if TYPE_CHECKING:
    from geomcad.sheet import Sheet
    from geomcad.sheet.motion import Frames


class Protocol(Construction):
    """The protocols of several positions' constructions, one after another."""

    def __init__(self, title: str, parts: Sequence[Construction]) -> None:
        super().__init__(title)
        self.parts = list(parts)

    def trace(self) -> str:
        return "\n\n".join(p.trace() for p in self.parts)


#: How each result is drawn (verify's precision): name prefix → (unit, plan, meaning).
SPECS: tuple[tuple[str, str, str | None, str], ...] = (
    ("x_", "m", "l", "a point's x coordinate"),
    ("y_", "m", "l", "a point's y coordinate"),
    ("V_rel_", "m/s", "v", "relative velocity in a sliding pair"),
    ("a_cor_", "m/s²", "a", "Coriolis acceleration in a sliding pair"),
    ("V_", "m/s", "v", "a point's velocity"),
    ("a_", "m/s²", "a", "a point's acceleration"),
    ("omega_", "rad/s", None, "a link's angular velocity, ccw > 0"),
    ("eps_", "rad/s²", None, "a link's angular acceleration, ccw > 0"),
    ("R_", "N", "F", "a reaction: the force of link i on link j"),
    ("M_bal", "N·m", None, "the balancing moment on the crank"),
    # the dynamics (issue 15)
    ("A_cycle", "J", None, "the work of the resistances per cycle"),
    ("M_drive", "N·m", None, "the constant motor moment"),
    ("J_flywheel", "kg·m²", None, "the flywheel's moment of inertia"),
    ("delta_achieved", "1", None, "δ by the equation of motion with the flywheel"),
    ("D_flywheel", "m", None, "the flywheel's diameter"),
    ("b_flywheel", "m", None, "the flywheel's width (a rim: its section's side)"),
    ("m_flywheel", "kg", None, "the flywheel's mass"),
)


#: The file's top-level results (the positions' fields are found by :data:`SPECS`' prefixes).
TOP: tuple[ResultSpec, ...] = (
    ResultSpec("W", "1", "Chebyshev's mobility"),
    ResultSpec("stroke", "m", "the output's stroke H", "l"),
    ResultSpec("swing_deg", "deg", "a rocker output's swing ψ_max − ψ_min"),
    ResultSpec("forces_phi_deg", "deg", "the crank angle of the force analysis"),
    ResultSpec("K", "1", "the coefficient of velocity change"),
    ResultSpec("phi_deg", "deg", "the crank angle"),
    ResultSpec("I_pr", "kg·m²", "the reduced moment of inertia at the numbered positions"),
    ResultSpec("M_pr", "N·m", "the reduced moment of the loads at the numbered positions"),
    ResultSpec("omega_max", "rad/s", "the largest crank speed allowed by δ"),
    ResultSpec("omega_min", "rad/s", "the smallest crank speed allowed by δ"),
    # results.synthesis (issue 31): the lengths found, θ, γ_min
    ResultSpec("l1", "m", "the crank's length found by the synthesis", "ls"),
    ResultSpec("l2", "m", "the rod's (coupler's) length found by the synthesis", "ls"),
    ResultSpec("l3", "m", "the lever's length C–B found by the synthesis", "ls"),
    ResultSpec("theta_deg", "deg", "the angle of overlap θ = 180°·(K − 1)/(K + 1)"),
    ResultSpec("gamma_min_deg", "deg", "the least transmission angle over a turn"),
)


def spec_of(name: str) -> ResultSpec | None:
    """The spec of a linkage file's result or position field: a top-level name, or by the
    prefix of a point's, link's or pair's field (``V_B``, ``omega_3``, ``R_2_3_x``)."""
    for r in TOP:
        if r.name == name:
            return r
    for prefix, unit, drawn, doc in SPECS:
        if name.startswith(prefix):
            return ResultSpec(name, unit, doc, drawn)
    return None


def make_problem(file_id: str, data: dict[str, Any]) -> Problem[Solved]:
    """The problem a linkage file states (raises :class:`~geomcad.errors.FileKeyError` for a
    bad file)."""
    from geomcad.linkage import synthesis  # a [synthesis] table: the explicit file it finds

    syn = synthesis.synthesize(data) if synthesis.is_synthesis(data) else None
    lk = parse(syn.linkage if syn is not None else data)

    def build(values: Mapping[str, ParamValue]) -> Build[Solved]:
        s = solve(lk)
        res = results(s)
        from geomcad.linkage.analysis import analyse

        proto = Protocol(lk.title, [P.c for P in s.positions] + analyse(s).constructions)
        if syn is not None:
            synthesis.attach(s, syn, res, proto)
        return Build(res, proto, [], data=s)

    def scales(sol: Solution[Solved]) -> Mapping[str, float]:
        """The sheets' scales, asked (once, by ``Solution.scales``) where mm↔SI is needed: the
        kinematic sheet's, and k_l of the synthesis sheet as "ls" (verify's synthesis.l1_mm)."""
        from geomcad.sheet.linkage import sheet_scales

        found = dict(sheet_scales(sol.data))
        if syn is not None:
            from geomcad.sheet.synthesis import synthesis_scale

            found["ls"] = synthesis_scale(syn)
        return found

    def draw(sol: Solution[Solved]) -> list[tuple[str, Sheet]]:
        """The file's sheets, each drawn on its own: one that fails leaves the others drawn
        (:class:`~geomcad.errors.SheetsFailed` carries them, the failed one keeping its place
        and number)."""
        from geomcad.sheet.linkage import kinematic_sheets

        solved = sol.data
        from geomcad.files import code
        from geomcad.sheet.linkage_forces import force_sheets  # sheets 2 and 3 (issue 15)

        named = code(file_id, str(data.get("title", "")))  # the file's own title, if any
        failures: list[tuple[str, Exception]] = []
        kinematic: list[tuple[str, Any]]
        try:
            kinematic = list(kinematic_sheets(solved, named))
        except GeomcadError as exc:  # counted as one sheet (its plans sheet not known)
            if not SheetsFailed.sheet_own(exc):
                raise  # an error of the input: the whole file refused
            failures.append(("kinematic", exc))
            kinematic = [("", None)]
        sheets = kinematic + force_sheets(
            solved, named, first_no=len(kinematic) + 1, failures=failures
        )
        from geomcad.sheet.synthesis import with_sheet  # the synthesis' own sheet, first

        try:
            sheets = with_sheet(solved, named, sheets)
        except GeomcadError as exc:
            if not SheetsFailed.sheet_own(exc):
                raise
            failures.insert(0, ("synthesis", exc))
            sheets = [("synthesis", None), *sheets]
        if failures:
            raise SheetsFailed(list(sheets), failures)
        return sheets

    def motion(sol: Solution[Solved], frames: int) -> Frames:
        from geomcad.sheet.linkage import motion as linkage_motion

        return linkage_motion(sol.data, frames)

    from geomcad.files import file_problem

    return file_problem(
        file_id, data, lk.title, TOP, build, draw, motion, cls=_FileProblem, scales=scales
    )


class _FileProblem(Problem[Solved]):
    """A problem whose position fields are named after the file's own points and links."""

    def result_spec(self, name: str) -> ResultSpec | None:
        return spec_of(name)

    def report(self, sol: Solution[Solved]) -> str:
        """The readable ``solve`` report: tables per group of quantities
        (:mod:`geomcad.files.linkage_report`)."""
        from geomcad.files.linkage_report import report

        def unit(name: str) -> str:
            spec = spec_of(name)
            return spec.unit if spec is not None else ""

        from geomcad.linkage.analysis import analyse

        s = sol.data
        force_no = analyse(s).force_index
        return report(
            self.id, self.title, sol.results, unit, sol.notes, s.linkage.phi is None, force_no
        )
