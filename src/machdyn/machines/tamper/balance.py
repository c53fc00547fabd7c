"""The double tamper balanced over all its operating states (seed 000 section 3, eq 22, Tables 1-2).

The complete machine: one eccentric shaft carrying both journals (the main journal eccentricity along the
shaft frame's x axis, the auxiliary one opposite it), a sleeve on each journal turned to the sleeve angle of a
Table 1 stroke, so that the main crank pin sits at the resultant eccentricity r_1 at angle |phi_d1| and the
auxiliary pin at r_2 and pi + |phi_d2| in the shaft frame (their difference is Table 1's phase Phi, repro
000.2); the two beams as offset slider-cranks on those pins with Table 2's masses and centroids; the sleeves'
masses at the pins (seed 000 eqs 15, 19: "rotating masses at r_E, r_F").

What Table 2 leaves open, and what is assumed here (``TamperBeams`` defaults):

- l_EB = 2 p1 (centroid at mid-length) and l_FC = 0.832 l_EB, the ratio that gives magnitude balance of the
  first harmonic (repro 000.3); centroidal inertias m l^2 / 12;
- sleeve masses m_d1 = 0 and m_d4 = 11.79 kg, one solution of m_d4 r_d2 - m_d1 r_d1 = 35.37 kg*mm (the summed
  real parts of eq 22, repro 000.3);
- slide lines through the shaft axis (offsets e = 0), beams hanging below the shaft, gravity off.

:func:`table2_check` evaluates that design at its own state (5 mm / 6 mm strokes, Phi = 180 deg) and shows what
shaking force it leaves and why eq 22 cannot hold exactly; :func:`corrected_balance` chooses new sleeve masses
and a shaft counterweight that minimise the screed's shaking force over all 20 stroke/phase states of Table 1.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ...balancing.frame import cycle, frame_loads
from ...balancing.general import CounterweightSlot, MassSlot
from ...balancing.robust import OperatingState, RobustResult, robust_counterweights
from ...errors import InputError, check_positive
from .geometry import AUX_SLEEVE_ANGLES, MAIN_SLEEVE_ANGLES, eccentricity_phase, resultant_eccentricity
from .model import balance_analysis, double_tamper

__all__ = [
    "PAPER_RMS_REDUCTION",
    "TamperBeams",
    "tamper_state",
    "tamper_states",
    "Table2Check",
    "table2_check",
    "corrected_balance",
]

#: Seed 000, section 4: measured RMS acceleration of the screed reduced by 43.48 % (10 Hz) and 43.70 % (20 Hz).
PAPER_RMS_REDUCTION = (0.4348, 0.4370)


@dataclass(frozen=True)
class TamperBeams:
    """Beams, sleeves and eccentricities of the double tamper (SI). Defaults: Table 2 (m_d2 = 90 kg,
    m_d3 = 63.21 kg, p1 = 233.19, q1 = 2.7, p2 = 229.84, q2 = 13.03 mm), Table 1's eccentricities (3, 1.5, 3,
    3 mm), and the assumptions of the module docstring for what Table 2 leaves open; ``offset_main``,
    ``offset_aux`` [m] are the offsets e of the beams' slide lines from the shaft axis (seed 000 eqs 5-10)."""

    m_main: float = 90.0
    m_aux: float = 63.21
    p1: float = 233.19e-3
    q1: float = 2.7e-3
    p2: float = 229.84e-3
    q2: float = 13.03e-3
    l_main: float = 2 * 233.19e-3
    l_aux: float = 0.832 * 2 * 233.19e-3
    sleeve_main: float = 0.0
    sleeve_aux: float = 11.79
    e_journal_main: float = 3.0e-3
    e_sleeve_main: float = 1.5e-3
    e_journal_aux: float = 3.0e-3
    e_sleeve_aux: float = 3.0e-3
    offset_main: float = 0.0
    offset_aux: float = 0.0

    def __post_init__(self) -> None:
        for name in ("m_main", "m_aux", "l_main", "l_aux"):
            check_positive(f"tamper {name}", getattr(self, name), "kg" if name.startswith("m") else "m")
        for name in ("sleeve_main", "sleeve_aux"):
            check_positive(f"tamper {name} mass", getattr(self, name), "kg", allow_zero=True)


def tamper_state(beams: TamperBeams, r_main: float, phase_main: float, r_aux: float, phase_aux: float,
                 name: str = "double_tamper"):
    """The double tamper with crank pins at radius r_main [m], angle phase_main [rad] and r_aux, pi + phase_aux
    in the shaft frame (r_aux = 0: the auxiliary beam stands still); sleeves as point masses at the pins."""
    check_positive("main resultant eccentricity", r_main, "m")
    check_positive("auxiliary resultant eccentricity", r_aux, "m", allow_zero=True)
    mech = double_tamper(
        r_main, beams.l_main, max(r_aux, r_main), beams.l_aux, np.pi,
        offset_main=beams.offset_main, offset_aux=beams.offset_aux,
        beam_masses=(beams.m_main, beams.m_aux), beam_coms=((beams.p1, beams.q1), (beams.p2, beams.q2)),
        sleeve_masses=(beams.sleeve_main, beams.sleeve_aux), name=name,
    )
    a1 = (r_main * np.cos(phase_main), r_main * np.sin(phase_main))
    a2 = (r_aux * np.cos(np.pi + phase_aux), r_aux * np.sin(np.pi + phase_aux))
    pins = {"A1": tuple(map(float, a1)), "A2": tuple(map(float, a2))}
    bodies = tuple(replace(b, points={**b.points, **pins}) if b.name == mech.crank.body else b for b in mech.bodies)
    sleeves = {"sleeve_main": pins["A1"], "sleeve_aux": pins["A2"]}
    masses = tuple(replace(p, position=sleeves[p.name]) if p.name in sleeves else p for p in mech.point_masses)
    return replace(mech, bodies=bodies, point_masses=masses, gravity=(0.0, 0.0))


def tamper_states(beams: TamperBeams = TamperBeams(), speed: float = 2 * np.pi * 20.0) -> tuple[OperatingState, ...]:
    """The 20 stroke/phase states of Table 1 (main labels 3-9 mm x auxiliary 0-12 mm) from the sleeve angles
    (repro 000.2 item 4), each at crank ``speed`` [rad/s] (default 20 Hz, the paper's test frequency)."""
    check_positive("shaft speed", speed, "rad/s")
    states = []
    for m_label, th1 in MAIN_SLEEVE_ANGLES.items():
        r1 = float(resultant_eccentricity(beams.e_journal_main, beams.e_sleeve_main, th1))
        f1 = float(abs(eccentricity_phase(beams.e_journal_main, beams.e_sleeve_main, th1)))
        for a_label, th2 in AUX_SLEEVE_ANGLES.items():
            r2 = float(resultant_eccentricity(beams.e_journal_aux, beams.e_sleeve_aux, th2))
            r2 = 0.0 if r2 < 1e-12 else r2
            f2 = float(abs(eccentricity_phase(beams.e_journal_aux, beams.e_sleeve_aux, th2)))
            label = f"main {m_label} mm / aux {a_label} mm"
            states.append(OperatingState(label, tamper_state(beams, r1, f1, r2, f2, name=label), speed))
    return tuple(states)


@dataclass(frozen=True)
class Table2Check:
    """Table 2's design at its own state (r_d1 = 2.5 mm, r_d2 = 3 mm, Phi = 180 deg), SI:

    - ``rms_pair``, ``peak_pair`` [N]: shaking force of the two beams and sleeves together
    - ``rms_main_alone``, ``peak_main_alone`` [N]: the main beam and its sleeve alone (what eq 22 tries to cancel)
    - ``first_harmonic_left``, ``second_harmonic_left`` [-]: amplitude of the 1st and 2nd harmonics of the
      pair's vertical force over the main beam's 1st harmonic
    - ``phase_mismatch`` [rad]: arg m_C - arg m_B; eq 22 (F_B = -F_C as complex numbers) needs it to be 0
    - ``magnitude_residual`` [-]: 2 sin(mismatch / 2), the part of the first harmonic no beam length can cancel
    """

    rms_pair: float
    peak_pair: float
    rms_main_alone: float
    peak_main_alone: float
    first_harmonic_left: float
    second_harmonic_left: float
    phase_mismatch: float
    magnitude_residual: float


def _harmonic(values: np.ndarray, order: int) -> float:
    spectrum = np.fft.rfft(values) / values.size
    return float(2.0 * abs(spectrum[order]))


def table2_check(beams: TamperBeams = TamperBeams(), speed: float = 2 * np.pi * 20.0,
                 r_main: float = 2.5e-3, r_aux: float = 3.0e-3) -> Table2Check:
    """Evaluate Table 2 as printed with the engine (assumptions in the module docstring)."""
    phi = cycle(360)
    state = tamper_state(beams, r_main, 0.0, r_aux, 0.0)
    pair = frame_loads(state, phi, speed)
    alone = replace(
        state,
        bodies=tuple(replace(b, mass=0.0, inertia=0.0) if b.name == "rod_2" else b for b in state.bodies),
        point_masses=tuple(replace(p, mass=0.0) if p.name == "sleeve_aux" else p for p in state.point_masses),
    )
    main = frame_loads(alone, phi, speed)
    ref = _harmonic(main.fy, 1)
    if ref <= 0:
        raise InputError("The main beam of the tamper produces no shaking force; check its mass and stroke.")
    ba = balance_analysis(r_main, beams.m_main, beams.p1, beams.q1, r_aux, beams.m_aux, beams.p2, beams.q2)
    return Table2Check(pair.rms_force, pair.peak_force, main.rms_force, main.peak_force,
                       _harmonic(pair.fy, 1) / ref, _harmonic(pair.fy, 2) / ref, ba.phase_mismatch, ba.residual)


def corrected_balance(beams: TamperBeams = TamperBeams(), mode: str = "sum", speed: float = 2 * np.pi * 20.0,
                      counterweight_radius: float = 0.05, sleeve_bounds=(0.0, 60.0), crank_angle=None) -> RobustResult:
    """New sleeve masses m_d1, m_d4 (within ``sleeve_bounds`` [kg]) and a counterweight on the shaft at
    ``counterweight_radius`` [m] minimising the screed's shaking force over all 20 states of Table 1
    (:func:`~machdyn.balancing.robust.robust_counterweights`, ``mode`` 'sum' or 'worst'). "Before" is Table 2
    with the assumed sleeves (:class:`TamperBeams`)."""
    check_positive("counterweight radius", counterweight_radius, "m")
    slots = (MassSlot("sleeve_main", tuple(sleeve_bounds)), MassSlot("sleeve_aux", tuple(sleeve_bounds)),
             CounterweightSlot("crank", radius=counterweight_radius))
    return robust_counterweights(tamper_states(beams, speed), slots, mode, crank_angle)
