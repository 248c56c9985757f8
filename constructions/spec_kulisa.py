"""Course work "dynamics of the slotted-link mechanism": flywheel, scotch yoke, rolling roller.

- The inputs are reconstructed. I_pr = A + B·sin²φ from the velocity analogues (the yoke's
  velocity plan, the roller's instantaneous centre), dI_pr/dφ, the equation of motion.
- ω1 by the kinetic-energy theorem and by ``solve_ivp`` (they agree to 1e-9), ε1, the reactions
  X_O, Y_O, N_A by kinetostatics with inertia loads, and the balancing force F_x at the roller's
  axis by equal power and by a force balance.
- Reports the report's inconsistent I_pr formula, its sign slip in x_C3, and its ε1, N_A, X_O
  computed from rounded intermediates.
- Three A3 sheets: the scheme with the velocities and the velocity plan; I_pr(φ) and ω1(φ) over a
  turn; the free-body diagrams of flywheel, yoke and roller and the balanced mechanism.
"""

# This module loads without numpy or the construction code: `geomcad list` and `--help` read it.
# build and draw live in p_kulisa.py and load on first use.

from __future__ import annotations

from typing import TYPE_CHECKING

from geomcad.problem import Param, Problem, ResultSpec, erratum, lazy, rounded

if TYPE_CHECKING:
    from .p_kulisa import Data

ID = "kulisa-23110713"

PARAMS = (
    Param("m1", 80.0, "flywheel's mass (a homogeneous disc)", "kg"),
    Param("R1", 0.36, "flywheel's radius", "m", gt=0.0),
    Param("OA", 0.24, "radius of the pin A on the flywheel", "m", gt=0.0),
    Param("m2", 20.0, "yoke's mass", "kg"),
    Param("m3", 25.0, "roller's mass", "kg"),
    Param("R3", 0.12, "roller's rolling radius (on the base)", "m", gt=0.0),
    Param("r3", 0.05, "roller's hub radius (under the yoke)", "m", ge=0.0),
    Param("rho3", 0.04, "roller's radius of gyration about its axis", "m", ge=0.0),
    Param("M", 34.0, "constant moment on the flywheel", "N·m"),
    Param("phi_deg", 150.0, "position φ of the flywheel", "deg"),
    Param("phi0_deg", 0.0, "starting position φ0 (from rest)", "deg"),
)

RESULTS = (
    ResultSpec("I_pr_A", "kg·m²", "A in I_pr = A + B·sin²φ: the flywheel's I1", symbol="A"),
    ResultSpec("I_pr_B", "kg·m²", "B in I_pr = A + B·sin²φ", symbol="B"),
    ResultSpec("I_pr", "kg·m²", "reduced moment of inertia at φ"),
    ResultSpec("dI_pr", "kg·m²", "dI_pr/dφ at φ (signed)"),
    ResultSpec("omega1", "rad/s", "flywheel's angular velocity at φ (kinetic-energy theorem)"),
    ResultSpec("eps1", "rad/s²", "flywheel's angular acceleration φ'' at φ (signed)", symbol="ε_1"),
    ResultSpec("N_A", "N", "force between the pin A and the yoke's slot", "F"),
    ResultSpec("X_O", "N", "bearing reaction at O along x (magnitude)", "F"),
    ResultSpec("Y_O", "N", "bearing reaction at O along y (magnitude)", "F"),
    ResultSpec(
        "F_x", "N", "horizontal force at the roller's axis that balances M (equal power)", "F"
    ),
    ResultSpec("t_reach", "s", "time from rest at φ0 to φ (solve_ivp)", symbol="t(φ)"),
    ResultSpec("omega_ode", "rad/s", "ω1 at φ from integrating the equation of motion"),
)

EPS_NOTE = (
    "it comes from the rounded I_pr = 5.67 and ω1 = 5.60: (34 + 0.844·5.60²)/5.67 = 10.665; the "
    "exact value 10.6668 rounds to 10.67"
)
NA_NOTE = (
    "it is (34 − 5.184·10.66)/(0.24·sin 150°) = 177.2 with the report's rounded ε1 = 10.66; with "
    "the exact ε1 = 10.6668 the flywheel's moment balance gives 177.47 N (the force changes by "
    "I1/(OA·sin φ) = 43.2 N per rad/s² of ε1), and so does the yoke and roller's balance"
)

SEED = {
    "I_pr_A": rounded(5.184, 3, "(5,184 + 1,949·sin²φ)·φ'' + …"),
    "I_pr_B": rounded(1.949, 3, "(5,184 + 1,949·sin²φ)·φ'' + …"),
    "I_pr": rounded(5.67, 2, "I_пр = 5,67 кг·м²"),
    "dI_pr": rounded(-1.688, 3, "dI_пр/dφ = −1.688"),
    "omega1": rounded(5.60, 2, "ω1 = 5,60 рад/с"),
    "eps1": erratum(10.66, EPS_NOTE, "ε1 = 10,66 рад/с²"),
    "N_A": erratum(177.2, NA_NOTE, "N_A = 177,2 Н"),
    "X_O": erratum(177.2, NA_NOTE, "X_O = 177,2 Н"),
    "Y_O": rounded(0.0, 0, "Y_O = 0"),
    "F_x": rounded(401.4, 1, "F_x = 401,4 Н"),
}

PROBLEM: Problem[Data] = Problem(
    id=ID,
    title="Course work: dynamics of the slotted-link mechanism (flywheel, yoke, roller)",
    params=PARAMS,
    results=RESULTS,
    seed=SEED,
    build=lazy(".p_kulisa:build", __package__),
    draw=lazy(".sheets_kulisa:sheets", __package__),
    motion=lazy(".sheets_kulisa:motion", __package__),
    scales=lazy(".sheets_kulisa:scales", __package__),
)
