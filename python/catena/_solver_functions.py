# SPDX-License-Identifier: MIT
"""One function per solver of the registry, `solve_<name>`, with the solver's knobs as keyword
arguments: written out (not generated at import) so that IDEs, type checkers and `help()` see
their signatures and docstrings. Each is `catena.run_solver(name, ...)` with the knobs given; a knob
left at None is not set, so the solver uses its registry default, the value the docstring states.
python/tests/test_solver_functions.py checks that names, types, defaults and valid ranges match
`catena.solvers()` (the knob tables of src/solvers/*/, docs/reference/solver-knobs.md).
"""

from typing import Literal, Optional, Union

from ._catena import Problem, Request, SolverResult, Statics, run_solver

__all__ = ["solve_fe", "solve_shooting", "solve_frobenius", "solve_asymptotic", "solve_airy"]

_KnobValue = Union[int, float, bool, str]


def _run(name: str, problem: Problem, request: Optional[Request], statics: Optional[Statics],
         time_limit_s: Optional[float], knobs: dict[str, Optional[_KnobValue]]) -> SolverResult:
    given = {knob: value for knob, value in knobs.items() if value is not None}
    return run_solver(name, problem, request, given, statics=statics, time_limit_s=time_limit_s)


def solve_fe(problem: Problem, request: Optional[Request] = None, *, statics: Optional[Statics] = None,
             time_limit_s: Optional[float] = None, elements: Optional[int] = None,
             richardson: Optional[bool] = None, kappa: Optional[float] = None,
             observed_order: Optional[bool] = None, tolerance: Optional[float] = None,
             max_elements: Optional[int] = None) -> SolverResult:
    """Natural modes by the lumped-mass finite-element solver ``fe``.

    A chain of N bar elements about its own exact statics; banded shift-invert Lanczos (thick
    restart), the mode count proved by Sylvester inertia, Richardson N/2N extrapolation
    (docs/explanation/methods/fe.md). Same as ``catena.run_solver("fe", problem, request, knobs)``
    with the knobs given here; a knob left at None keeps its default.

    Parameters
    ----------
    problem : Problem
        The cable or line and its supports.
    request : Request, optional
        What to compute; None: ``Request()``, the 6 lowest in-plane modes.
    statics : Statics, optional
        ``catena.solve_statics(problem)``, solved here when None.
    time_limit_s : float, optional
        Cooperative wall-clock budget [s]: the solver stops with what it has (no limit when None).
    elements : int, default 400
        Number of bar elements N [-], in [2, 5e+07]: the coarse mesh with Richardson; resolves up
        to N/2 modes per plane.
    richardson : bool, default True
        Solve N and 2N and extrapolate (order 2 -> 4); N/2 too, for the error estimate.
    kappa : float, default 1e-06
        Inextensible cables: penalty H/EA [-], in (0, 0.01] (and 2 kappa, extrapolated to 0;
        4 kappa for the error estimate).
    observed_order : bool, default False
        Also solve 4N and report the observed convergence order.
    tolerance : float, default 1e-06
        Accuracy target of each frequency, relative [-], in [0, 1] (default fe's declared accuracy):
        while a mode's error estimate exceeds it, fe solves again on a finer mesh (up to
        max_elements); a mode that still exceeds it is named and the plane not converged (0: none).
    max_elements : int, default 51200
        The largest N [-] a tolerance may refine to, in [2, 5e+07] (at or below elements: no
        refinement).

    Returns
    -------
    SolverResult
        ``inplane`` and ``outofplane`` modes (None when not asked), ``forced`` responses and the
        ``summary``. Numerical trouble is its status, never an exception.

    Raises
    ------
    InvalidInput
        A knob out of its range or of the wrong type, a bad request, or statics of another problem.
    """
    return _run("fe", problem, request, statics, time_limit_s,
                {"elements": elements, "richardson": richardson, "kappa": kappa,
                 "observed_order": observed_order, "tolerance": tolerance, "max_elements": max_elements})


def solve_shooting(problem: Problem, request: Optional[Request] = None, *,
                   statics: Optional[Statics] = None, time_limit_s: Optional[float] = None,
                   rtol: Optional[float] = None, atol: Optional[float] = None,
                   root_tolerance: Optional[float] = None,
                   method: Optional[Literal["rk", "adams", "bdf"]] = None,
                   nonlinear_solver: Optional[Literal["newton", "fixed_point"]] = None,
                   max_steps: Optional[int] = None, max_condition: Optional[float] = None,
                   error_estimate: Optional[bool] = None,
                   root_finder: Optional[Literal["newton", "brent"]] = None) -> SolverResult:
    """Natural modes by the exact shooting solver ``shooting``.

    The linear boundary-value problem solved exactly: principal solutions integrated by
    Runge-Kutta 6(5), modes counted by conjugate points (Morse index) and refined by safeguarded
    Newton steps with the frequency derivative of the shot (Brent's method as fallback); any sag,
    inclination, EA (inf exact), added mass (docs/explanation/methods/shooting.md). Same as
    ``catena.run_solver("shooting", problem, request, knobs)`` with the knobs given here; a knob
    left at None keeps its default.

    Parameters
    ----------
    problem : Problem
        The cable or line and its supports.
    request : Request, optional
        What to compute; None: ``Request()``, the 6 lowest in-plane modes.
    statics : Statics, optional
        ``catena.solve_statics(problem)``, solved here when None.
    time_limit_s : float, optional
        Cooperative wall-clock budget [s]: the solver stops with what it has (no limit when None).
    rtol : float, default 1e-10
        Relative tolerance of the integration [-], in [1e-14, 0.01].
    atol : float, default 0
        Absolute tolerance of the integration on the scaled state [-], in [0, 0.01] (0: rtol/100).
    root_tolerance : float, default 0
        Relative width of the final frequency bracket [-], in [0, 0.01] (0: rtol).
    method : {"rk", "adams", "bdf"}, default "rk"
        Explicit Runge-Kutta 6(5), or CVODE's Adams or BDF.
    nonlinear_solver : {"newton", "fixed_point"}, default "newton"
        CVODE's Newton (dense LU, analytic Jacobian) or fixed-point iteration.
    max_steps : int, default 500000
        Maximum integration steps per shot [-], in [100, inf).
    max_condition : float, default 100
        Re-orthonormalise the principal pair when cond(Gram) [-] exceeds this, in [2, 1e+08].
    error_estimate : bool, default True
        One extra shot per mode at 100x tighter tolerances.
    root_finder : {"newton", "brent"}, default "newton"
        Refine each root by Newton with the shot's frequency derivative, or by Brent.

    Returns
    -------
    SolverResult
        ``inplane`` and ``outofplane`` modes (None when not asked), ``forced`` responses and the
        ``summary``. Numerical trouble is its status, never an exception.

    Raises
    ------
    InvalidInput
        A knob out of its range or of the wrong type, a bad request, or statics of another problem.
    """
    return _run("shooting", problem, request, statics, time_limit_s,
                {"rtol": rtol, "atol": atol, "root_tolerance": root_tolerance, "method": method,
                 "nonlinear_solver": nonlinear_solver, "max_steps": max_steps,
                 "max_condition": max_condition, "error_estimate": error_estimate,
                 "root_finder": root_finder})


def solve_frobenius(problem: Problem, request: Optional[Request] = None, *,
                    statics: Optional[Statics] = None, time_limit_s: Optional[float] = None,
                    tolerance: Optional[float] = None, max_terms: Optional[int] = None,
                    step_ratio: Optional[float] = None, scan_fraction: Optional[float] = None,
                    extended_precision: Optional[bool] = None) -> SolverResult:
    """Natural modes of an inextensible catenary by Gale's power series, solver ``frobenius``.

    Gale's power series (Gale 1976), chained expansions to any sag, adaptive terms, extended
    precision when needed (docs/explanation/methods/frobenius.md). Declines (status
    ``not-applicable``) an extensible cable or a general line. Same as
    ``catena.run_solver("frobenius", problem, request, knobs)`` with the knobs given here; a knob
    left at None keeps its default.

    Parameters
    ----------
    problem : Problem
        The cable and its supports (e.g. ``Problem.gale_sag``).
    request : Request, optional
        What to compute; None: ``Request()``, the 6 lowest in-plane modes.
    statics : Statics, optional
        ``catena.solve_statics(problem)``, solved here when None.
    time_limit_s : float, optional
        Cooperative wall-clock budget [s]: the solver stops with what it has (no limit when None).
    tolerance : float, default 1e-12
        Target relative accuracy of each frequency [-], in [1e-15, 0.001].
    max_terms : int, default 600
        Cap on the terms of one expansion [-], in [8, 5000].
    step_ratio : float, default 0.5
        Expansion-centre spacing as a fraction of the radius of convergence [-], in [0.1, 0.8].
    scan_fraction : float, default 0.2
        Root-scan grid as a fraction of the mode spacing [-], in [0.01, 0.5].
    extended_precision : bool, default True
        Allow long double / quad when double loses digits.

    Returns
    -------
    SolverResult
        ``inplane`` and ``outofplane`` modes (None when not asked), ``forced`` responses and the
        ``summary``. Numerical trouble is its status, never an exception.

    Raises
    ------
    InvalidInput
        A knob out of its range or of the wrong type, a bad request, or statics of another problem.
    """
    return _run("frobenius", problem, request, statics, time_limit_s,
                {"tolerance": tolerance, "max_terms": max_terms, "step_ratio": step_ratio,
                 "scan_fraction": scan_fraction, "extended_precision": extended_precision})


def solve_asymptotic(problem: Problem, request: Optional[Request] = None, *,
                     statics: Optional[Statics] = None, time_limit_s: Optional[float] = None,
                     shape_formula: Optional[Literal["34", "28"]] = None,
                     eps_warning_threshold: Optional[float] = None, max_eps: Optional[float] = None,
                     quadrature_panels: Optional[int] = None) -> SolverResult:
    """Natural modes of a taut inclined cable by Grinfogel's perturbation solution, ``asymptotic``.

    Grinfogel (1984): eq. (21) frequencies (exact root count), WKB out of plane, shapes eq. (34),
    (28) or (37), tension eq. (38); error O(eps^2) (docs/explanation/methods/asymptotic.md).
    Declines (status ``not-applicable``) a cable beyond max_eps or a general line. Same as
    ``catena.run_solver("asymptotic", problem, request, knobs)`` with the knobs given here; a knob
    left at None keeps its default.

    Parameters
    ----------
    problem : Problem
        The cable and its supports (e.g. ``Problem.taut_inclined``).
    request : Request, optional
        What to compute; None: ``Request()``, the 6 lowest in-plane modes.
    statics : Statics, optional
        ``catena.solve_statics(problem)``, solved here when None.
    time_limit_s : float, optional
        Cooperative wall-clock budget [s]: the solver stops with what it has (no limit when None).
    shape_formula : {"34", "28"}, default "34"
        Transverse shape formula: eq. (34) uniformly valid, or eq. (28) zeroth order.
    eps_warning_threshold : float, default 0.3
        Grinfogel's eps [-] above which a validity warning is given, in (0, 10] (at most max_eps).
    max_eps : float, default 1
        Grinfogel's eps [-] above which the solver declines, in (0, 10].
    quadrature_panels : int, default 4
        Panels of 20-point Gauss-Legendre for the WKB integral [-], in [1, 1000].

    Returns
    -------
    SolverResult
        ``inplane`` and ``outofplane`` modes (None when not asked), ``forced`` responses and the
        ``summary``. Numerical trouble is its status, never an exception.

    Raises
    ------
    InvalidInput
        A knob out of its range or of the wrong type, a bad request, or statics of another problem.
    """
    return _run("asymptotic", problem, request, statics, time_limit_s,
                {"shape_formula": shape_formula, "eps_warning_threshold": eps_warning_threshold,
                 "max_eps": max_eps, "quadrature_panels": quadrature_panels})


def solve_airy(problem: Problem, request: Optional[Request] = None, *, statics: Optional[Statics] = None,
               time_limit_s: Optional[float] = None,
               curvature_fit: Optional[Literal["tangent", "secant", "paper"]] = None,
               scan_step: Optional[float] = None, cutoff_fraction: Optional[float] = None,
               max_k_l_over_pi: Optional[float] = None, tolerance_bits: Optional[int] = None,
               eps_warning_threshold: Optional[float] = None, max_eps: Optional[float] = None,
               quadrature_panels: Optional[int] = None) -> SolverResult:
    """Natural modes of a taut inclined cable by Triantafyllou's Airy-function solution, ``airy``.

    Grinfogel (1984), eqs. 12-16: roots of the 4x4 boundary determinant with exponentially
    scaled Ai, Bi, the paper's 'exact' reference; out of plane, the string of linear tension,
    exactly in Bessel J0, Y0 (docs/explanation/methods/airy.md). Declines (status
    ``not-applicable``) a cable beyond max_eps or a general line. Same as
    ``catena.run_solver("airy", problem, request, knobs)`` with the knobs given here; a knob left
    at None keeps its default.

    Parameters
    ----------
    problem : Problem
        The cable and its supports (e.g. ``Problem.taut_inclined``).
    request : Request, optional
        What to compute; None: ``Request()``, the 6 lowest in-plane modes.
    statics : Statics, optional
        ``catena.solve_statics(problem)``, solved here when None.
    time_limit_s : float, optional
        Cooperative wall-clock budget [s]: the solver stops with what it has (no limit when None).
    curvature_fit : {"tangent", "secant", "paper"}, default "tangent"
        Linearisation of Q(s): tangent at s_a, secant through the ends, or the paper's
        eqs. (17)-(18).
    scan_step : float, default 0.05
        Scan step in kL/pi [-], in [0.0001, 0.5].
    cutoff_fraction : float, default 0.75
        Spurious-root cutoff as a fraction of the string bound [-], in (0, 1).
    max_k_l_over_pi : float, default 0
        Scan limit in kL/pi [-], in [0, inf) (0: 2 modes + 20).
    tolerance_bits : int, default 50
        Root tolerance in bits [-], in [20, 53].
    eps_warning_threshold : float, default 0.3
        Grinfogel's eps [-] above which a validity warning is given, in (0, 10] (at most max_eps).
    max_eps : float, default 1
        Grinfogel's eps [-] above which the solver declines, in (0, 10].
    quadrature_panels : int, default 4
        Panels of 20-point Gauss-Legendre for the travel time [-], in [1, 1000].

    Returns
    -------
    SolverResult
        ``inplane`` and ``outofplane`` modes (None when not asked), ``forced`` responses and the
        ``summary``. Numerical trouble is its status, never an exception.

    Raises
    ------
    InvalidInput
        A knob out of its range or of the wrong type, a bad request, or statics of another problem.
    """
    return _run("airy", problem, request, statics, time_limit_s,
                {"curvature_fit": curvature_fit, "scan_step": scan_step,
                 "cutoff_fraction": cutoff_fraction, "max_k_l_over_pi": max_k_l_over_pi,
                 "tolerance_bits": tolerance_bits, "eps_warning_threshold": eps_warning_threshold,
                 "max_eps": max_eps, "quadrature_panels": quadrature_panels})
