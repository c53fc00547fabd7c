"""The screw as a beam on two supports: bending under lateral, moment and axial loads (seed 004, eqs 2.39-2.45).

Governing equation (a beam-column, small deflections, v positive along the lateral load):

    EJ·v'''' + (N(x)·v')' = w(x),   M = EJ·v'',   v(0) = v(l) = 0,   M(0) = M(l) = 0

with w(x) = q(x) − m'(x) the net transverse load of the lateral load intensity q (seed 004, eqs 2.37-2.38) and
the distributed bending moment m (eqs 2.32-2.33), and N(x) >= 0 the axial compression (the axial load of
eq 2.47 and the reaction S of eq 2.41). Differentiating EJ·v'' = M + M1 (2.39) twice gives this equation; 2.42
is its once-integrated form with N = S − k·x²/2.

:func:`beam_column` solves it numerically with :func:`scipy.integrate.solve_bvp`; :func:`moment_one_term` is the
paper's one-term approximation 2.45, exact when N = 0 and the span is a whole number of pitches.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class BeamSolution:
    """Deflection v [m], slope [rad], bending moment M = EJ·v'' [N·m] and shear EJ·v''' [N] along x [m]."""

    x: np.ndarray
    deflection: np.ndarray
    slope: np.ndarray
    moment: np.ndarray
    shear: np.ndarray
    iterations_ok: bool


def beam_column(length: float, flexural_rigidity: float, load: Callable[[np.ndarray], np.ndarray], *,
                axial_start: float = 0.0, axial_end: float = 0.0, nodes: int = 101,
                tol: float = 1e-10) -> BeamSolution:
    """Solve EJ·v'''' + (N·v')' = w on a simply supported span with :func:`scipy.integrate.solve_bvp`.

    Parameters
    ----------
    length : float
        Span l between the two supports [m], > 0.
    flexural_rigidity : float
        EJ [N·m²], > 0.
    load : callable
        Net transverse load w(x) [N/m] (lateral load minus the derivative of the distributed moment), vectorised.
    axial_start, axial_end : float
        Axial compression N at x = 0 and x = l [N] (linear in between), each below the Euler load π²EJ/l².
    nodes : int
        Initial mesh nodes.
    tol : float
        Relative tolerance of :func:`~scipy.integrate.solve_bvp`.

    Returns
    -------
    BeamSolution
        Source: seed 004, eqs 2.39-2.42 (the beam on two fulcrums under continuous loads); solved numerically.
        Valid for small deflections, a prismatic section and compression below the buckling load.

    Examples
    --------
    >>> s = beam_column(3.0, 1e5, lambda x: 100.0 + 0 * x)
    >>> round(float(s.moment.min()), 6)  # -q·l²/8
    -112.5
    """
    from scipy.integrate import solve_bvp

    if not (length > 0 and flexural_rigidity > 0 and math.isfinite(length) and math.isfinite(flexural_rigidity)):
        raise InputError(f"The span and the flexural rigidity must be finite and > 0; got {length:g} m and "
                         f"{flexural_rigidity:g} N*m^2.")
    euler = math.pi**2 * flexural_rigidity / length**2
    if max(axial_start, axial_end) >= euler:
        raise InputError(f"The axial compression must stay below the Euler load {euler:.4g} N of the span; got "
                         f"{max(axial_start, axial_end):.4g} N.")
    xs = np.linspace(0.0, length, 2001)
    scale = float(np.max(np.abs(load(xs)))) or 1.0
    # unknowns scaled so that they are of order one: u = v·EJ/(w_max·l⁴), ξ = x/l
    n0, n1 = axial_start, (axial_end - axial_start) / length

    def rhs(xi: np.ndarray, y: np.ndarray) -> np.ndarray:
        x = xi * length
        axial = (n0 + n1 * x) * length**2 / flexural_rigidity
        d_axial = n1 * length**3 / flexural_rigidity
        w = load(x) / scale
        return np.vstack([y[1], y[2], y[3], w - d_axial * y[1] - axial * y[2]])

    def bc(ya: np.ndarray, yb: np.ndarray) -> np.ndarray:
        return np.array([ya[0], ya[2], yb[0], yb[2]])

    xi = np.linspace(0.0, 1.0, nodes)
    sol = solve_bvp(rhs, bc, xi, np.zeros((4, xi.size)), tol=tol, max_nodes=100000)
    if not sol.success:
        raise InputError(f"The bending of the span could not be solved: {sol.message}")
    xi_out = np.linspace(0.0, 1.0, 401)
    y = sol.sol(xi_out)
    f = scale * length**4 / flexural_rigidity
    return BeamSolution(x=xi_out * length, deflection=f * y[0], slope=f * y[1] / length,
                        moment=flexural_rigidity * f * y[2] / length**2,
                        shear=flexural_rigidity * f * y[3] / length**3, iterations_ok=bool(sol.success))


def uniform_load_moment(x: Any, load: float, length: float) -> Any:
    """Bending moment M = EJ·v'' = −q·x·(l − x)/2 [N·m] of a simply supported span under a uniform load.

    Parameters
    ----------
    x : float or array
        Position 0 <= x <= l [m].
    load : float
        Uniform load q [N/m] (along v).
    length : float
        Span l [m].

    Returns
    -------
    float or array
        M [N·m] (negative for a positive load in this sign convention). Source: any strength-of-materials text,
        e.g. Timoshenko & Gere, *Mechanics of Materials*, simply supported beam, uniform load.

    Examples
    --------
    >>> uniform_load_moment(1.5, 100.0, 3.0)
    -112.5
    """
    return -load * x * (length - x) / 2.0


def uniform_load_deflection(x: Any, load: float, length: float, flexural_rigidity: float) -> Any:
    """Deflection v = q·x·(l³ − 2·l·x² + x³)/(24·EJ) [m] of a simply supported span under a uniform load.

    Parameters
    ----------
    x : float or array
        Position [m].
    load : float
        q [N/m].
    length : float
        Span l [m].
    flexural_rigidity : float
        EJ [N·m²].

    Returns
    -------
    float or array
        v [m]; at mid-span 5·q·l⁴/(384·EJ). Source: Timoshenko & Gere, *Mechanics of Materials*, table of beam
        deflections, simply supported beam with uniform load.

    Examples
    --------
    >>> round(uniform_load_deflection(1.5, 100.0, 3.0, 1e5) * 1e6, 6)
    1054.6875
    """
    return load * x * (length**3 - 2.0 * length * x**2 + x**3) / (24.0 * flexural_rigidity)


def harmonic_amplitudes(pressure: float, r1: float, r2: float, tan_beta: float, pitch: float) -> tuple[float, float]:
    """Amplitudes (A, B) of the lateral load q = −A·cos(ax) [N/m] and distributed moment m = −B·sin(ax) [N·m/m].

    A = p·tan β·(R1² − R2²)/2·a (seed 004, eq 2.37), B = p·(R1³ − R2³)/3·a (eqs 2.32-2.33), a = 2π/t.
    The paper prints B with (R1 − R2)/3, which is not a moment per length (Pa·m instead of N·m/m): the
    amplitude of 2.32-2.33 is meant.

    Parameters
    ----------
    pressure : float
        Flight pressure p_N [Pa].
    r1, r2 : float
        Flight and pipe radii [m], r1 > r2.
    tan_beta : float
        tan β of the flight [-].
    pitch : float
        Pitch t [m].

    Returns
    -------
    tuple of float
        (A [N/m], B [N·m/m]).

    Examples
    --------
    >>> a, b = harmonic_amplitudes(1e4, 0.1, 0.05, 0.4, 0.2)
    >>> round(a, 4), round(b, 4)
    (471.2389, 91.6298)
    """
    a = 2.0 * math.pi / pitch
    return pressure * tan_beta * (r1**2 - r2**2) / 2.0 * a, pressure * (r1**3 - r2**3) / 3.0 * a


def harmonic_load(amp_lateral: float, amp_moment: float, pitch: float) -> Callable[[np.ndarray], np.ndarray]:
    """The net transverse load w = q − m' = (a·B − A)·cos(ax) of :func:`harmonic_amplitudes` [N/m]."""
    a = 2.0 * math.pi / pitch
    return lambda x: (a * amp_moment - amp_lateral) * np.cos(a * np.asarray(x))


def moment_one_term(x: Any, amp_lateral: float, amp_moment: float, pitch: float) -> Any:
    """The paper's one-term bending moment EJ·v'' = (B/a − A/a²)·(1 − cos ax) [N·m] (seed 004, eq 2.45).

    Parameters
    ----------
    x : float or array
        Position from the left support [m].
    amp_lateral, amp_moment : float
        A [N/m] and B [N·m/m] of :func:`harmonic_amplitudes`.
    pitch : float
        Pitch t [m]; a = 2π/t.

    Returns
    -------
    float or array
        M [N·m]. It is exact for no axial force and a span of a whole number of pitches; otherwise see
        :func:`one_term_error`.

    Examples
    --------
    >>> round(float(moment_one_term(0.1, 100.0, 50.0, 0.2)), 6)  # (50/a − 100/a²)·2 at x = t/2
    2.980456
    """
    a = 2.0 * math.pi / pitch
    return (amp_moment / a - amp_lateral / a**2) * (1.0 - np.cos(a * np.asarray(x)))


def one_term_error(length: float, pitch: float, axial: float, flexural_rigidity: float) -> float:
    """Upper estimate of the relative error of 2.45 against the beam-column: end term plus axial amplification.

    The exact moment without axial force is 2.45 minus C·(1 − cos al)·x/l, so its relative error is at most
    (1 − cos al)/2 (zero for a span of whole pitches); a compression N adds at most about N/(N_cr − N),
    N_cr = π²EJ/l² (the amplification of the first buckling mode of a beam-column). 2.45 is therefore good to
    1 % where the span is a whole number of pitches and N <= 0.01·N_cr.

    Parameters
    ----------
    length : float
        Span l [m].
    pitch : float
        Pitch t [m].
    axial : float
        Largest axial compression N [N], >= 0.
    flexural_rigidity : float
        EJ [N·m²].

    Returns
    -------
    float
        The estimate [-].

    Examples
    --------
    >>> one_term_error(0.6, 0.2, 0.0, 1e5) < 1e-12
    True
    """
    a = 2.0 * math.pi / pitch
    euler = math.pi**2 * flexural_rigidity / length**2
    return (1.0 - math.cos(a * length)) / 2.0 + axial / (euler - axial)


def equivalent_stress_along(moment: Any, axial: Any, torque: Any, outer_diameter: float,
                            inner_diameter: float) -> Any:
    """Tresca equivalent stress along the screw σ_eq = √((|M|·c/I + N/A)² + 4·(T·c/J_p)²) [Pa].

    Seed 004, eqs 2.48-2.53 applied section by section of the pipe (c = d_o/2, I = J_p/2); the paper's
    solid-core form 2.53 (F = πR2², W_c = πR2³/2) is :func:`machdyn.conveyor.checks.screw_equivalent_stress`.

    Parameters
    ----------
    moment : float or array
        Bending moment M [N·m].
    axial : float or array
        Axial force N [N].
    torque : float or array
        Torque T [N·m].
    outer_diameter, inner_diameter : float
        Pipe diameters [m].

    Returns
    -------
    float or array
        σ_eq [Pa].

    Examples
    --------
    >>> round(float(equivalent_stress_along(0.0, 0.0, 100.0, 0.1, 0.0)) / 1e6, 6)
    1.018592
    """
    jp = math.pi * (outer_diameter**4 - inner_diameter**4) / 32.0
    area = math.pi / 4.0 * (outer_diameter**2 - inner_diameter**2)
    c = outer_diameter / 2.0
    return np.sqrt((np.abs(moment) * c / (jp / 2.0) + axial / area) ** 2 + 4.0 * (torque * c / jp) ** 2)


def stress_along_screw(length: float, span: float, span_x: Any, span_moment: Any, axial: float, torque: float,
                       outer_diameter: float, inner_diameter: float, points: int = 801) -> tuple[Any, Any]:
    """Equivalent stress along the whole screw, x from the feed end (0) to the drive (L) [m, Pa].

    The torque and the axial force grow linearly from the feed end to the drive, T(x) = T·x/L and
    N(x) = F_a·x/L (the uniform m_0 and p_d of seed 004, eqs 2.92-2.94, as in the torque and axial-force
    diagrams behind 2.46-2.47); every hanger span bends like the span solved by :func:`beam_column`. The stress
    is :func:`equivalent_stress_along` section by section (eqs 2.48-2.53 corrected, on the pipe).

    Parameters
    ----------
    length : float
        Screw length L [m].
    span : float
        Hanger spacing l [m].
    span_x, span_moment : array
        The span's positions [m] and bending moments [N·m].
    axial : float
        Axial force at the drive F_a [N].
    torque : float
        Torque at the drive T [N·m].
    outer_diameter, inner_diameter : float
        Pipe diameters [m].
    points : int
        Number of positions.

    Returns
    -------
    tuple of arrays
        x [m] and σ_eq(x) [Pa].

    Examples
    --------
    >>> x, s = stress_along_screw(6.0, 3.0, np.array([0.0, 3.0]), np.zeros(2), 0.0, 100.0, 0.1, 0.0, points=3)
    >>> [round(float(v) / 1e6, 6) for v in s]  # pure torsion, growing to 2·τ at the drive
    [0.0, 0.509296, 1.018592]
    """
    x = np.linspace(0.0, length, points)
    moment = np.interp(np.mod(x, span), span_x, span_moment)
    sigma = equivalent_stress_along(moment, axial * x / length, torque * x / length, outer_diameter, inner_diameter)
    return x, sigma


@dataclass(frozen=True)
class SpanBending:
    """Bending of one span between hangers of a run: x [m], M [N·m], v [m], σ_eq [Pa] along the span."""

    x: np.ndarray
    moment: np.ndarray
    deflection: np.ndarray
    equivalent_stress: np.ndarray
    axial: float
    euler_load: float
    screw_x: np.ndarray  # positions along the whole screw [m]
    screw_stress: np.ndarray  # equivalent stress along the whole screw [Pa]

    def scalars(self) -> dict[str, float]:
        return {"span_moment_max": float(np.max(np.abs(self.moment))),
                "span_deflection_max": float(np.max(np.abs(self.deflection))),
                "span_stress_max": float(np.max(self.equivalent_stress)),
                "span_axial_ratio": self.axial / self.euler_load,
                "screw_stress_max": float(np.max(self.screw_stress))}


def span_bending(problem: Any, states: dict[str, Any]) -> SpanBending:
    """One span of the run's screw under its lateral load q and the whole axial force F_a (conservative)."""
    d_o = float(states["pipe_outer_diameter"])
    d_i = float(states["pipe_inner_diameter"])
    ej = problem.elastic_modulus * math.pi * (d_o**4 - d_i**4) / 64.0
    q = float(states["span_load"])
    axial = float(states["axial_force"])
    span = problem.hanger_spacing
    sol = beam_column(span, ej, lambda x: q + 0.0 * np.asarray(x), axial_start=axial, axial_end=axial)
    torque = float(states["torque"])
    sigma = equivalent_stress_along(sol.moment, axial, torque, d_o, d_i)
    x, along = stress_along_screw(problem.length, span, sol.x, sol.moment, axial, torque, d_o, d_i)
    return SpanBending(sol.x, sol.moment, sol.deflection, sigma, axial, math.pi**2 * ej / span**2, x, along)
