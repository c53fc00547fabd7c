"""Drives with electrical states in a transient run: the flux linkages of an induction motor's dq model
(:mod:`machdyn.transient.induction`) integrated with the machine.

The run's state vector (:mod:`machdyn.transient.run`) is extended after its four works by, for each such drive,
its four flux linkages [Wb] and four integrals [J]: the electrical energy into the stator, the copper loss, the
air-gap work T_e omega_m on the motor shaft, and the magnetic energy lost when the stator is switched off (the
contactor opens: the stator current falls to zero at once, and the energy of the stator's leakage field goes into
the arc). The crank equations see the motor's electromagnetic torque through the gear; the flux equations see
the crank's speed: the electrical and the mechanical states are integrated together (Krause, Wasynczuk, Sudhoff
and Pekarek, *Analysis of Electric Machinery and Drive Systems*, 3rd ed., 2013, §6.14: the machine's equations
with the load's).

The energy balance of such a run: electrical input = copper loss + switching loss + change of magnetic energy +
gear loss + the drive's work at the crank, the last being the transient's own balance (change of kinetic and
potential energy + work on the loads + mount and brake dissipation).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["ElectricDrives", "MotorRun", "electrical_drives", "motor_run"]

#: integrals per drive after its states: input, copper loss, air-gap work, switching loss
INTEGRALS = 4


def _gear(torque: float, ratio: float, efficiency: float) -> float:
    return ratio * (torque * efficiency if torque >= 0.0 else torque / efficiency)


class ElectricDrives:
    """The drives of a run that carry electrical states (``drive.states`` > 0), their rows in the state vector
    from ``offset`` on, and the right-hand side that integrates them with the machine."""

    def __init__(self, drives: list, offset: int, cranks: int, torsion=None) -> None:
        self.drives = drives  # the run's list: a speed change replaces its entries
        self.index = [k for k, d in enumerate(drives) if getattr(d, "states", 0)]
        self.offset = offset
        self.cranks = cranks
        # the row of each motor's speed referred to the crank: the crank's, or its group's behind a stiff stage
        self.speed_rows = {k: (torsion.speed_row(k) if torsion is not None and k in torsion.lines else cranks + k)
                           for k in self.index}
        self.torque = [0.0] * len(drives)
        self.readers = [(lambda _w, k=k: self.torque[k]) for k in range(len(drives))]
        self.switched_off = False

    @property
    def width(self) -> int:
        """Rows per drive (its states and its integrals)."""
        return 4 + INTEGRALS

    @property
    def size(self) -> int:
        return self.width * len(self.index)

    def initial(self) -> np.ndarray:
        """De-energised at the start: every flux linkage and integral 0 (the motor switched on at t = 0)."""
        return np.zeros(self.size)

    def tolerances(self) -> np.ndarray:
        """Absolute tolerances: flux linkages to 1e-10 of V / omega_e, energies to 1e-9 J."""
        out = []
        for k in self.index:
            d = self.drives[k]
            scale = math.sqrt(2.0) * d.phase_voltage / d.supply_frequency
            out += [1e-10 * scale] * 4 + [1e-9] * INTEGRALS
        return np.array(out)

    def wrap(self, rhs, state: dict):
        """f(t, y) of the whole state from the machine's ``rhs`` (which reads the drives' torques through
        ``state["torques"]``, here the electromagnetic torques at the crank set from the fluxes)."""
        offset, width = self.offset, self.width

        def f(t, y):
            on = state["on"]
            extra = np.empty(self.size)
            for j, k in enumerate(self.index):
                motor = self.drives[k]
                base = offset + width * j
                wm = motor.ratio * float(y[self.speed_rows[k]])
                rates, te, power, copper = motor.rates(t, y[base:base + 4], wm, on)
                self.torque[k] = _gear(te, motor.ratio, motor.efficiency)
                extra[width * j:width * j + 4] = rates
                extra[width * j + 4:width * (j + 1)] = (power, copper, te * wm, 0.0)
            state["torques"] = self.readers
            return np.concatenate([rhs(t, y[:offset]), extra])

        return f

    def enter(self, y: np.ndarray, state: dict) -> np.ndarray:
        """The state at the start of a segment: at the switch-off the stator current falls to zero, psi_s =
        L_m / L_r psi_r, the magnetic energy that goes is booked as the switching loss."""
        if state["on"] or self.switched_off:
            return y
        self.switched_off = True
        y = y.copy()
        for j, k in enumerate(self.index):
            motor = self.drives[k]
            base = self.offset + self.width * j
            psi = y[base:base + 4].copy()
            before = float(motor.magnetic_energy(psi))
            _, lr, lm = motor.inductances
            psi[:2] = lm / lr * psi[2:]
            y[base:base + 4] = psi
            y[base + 7] += before - float(motor.magnetic_energy(psi))
        return y


def electrical_drives(drives: list, offset: int, cranks: int, torsion=None) -> ElectricDrives | None:
    """The :class:`ElectricDrives` of ``drives`` (behind the stiff stages of ``torsion``, a
    :class:`~machdyn.transient.torsion.TorsionalStates`), or None when none has electrical states."""
    found = ElectricDrives(drives, offset, cranks, torsion)
    return found if found.index else None


@dataclass(frozen=True)
class MotorRun:
    """The electrical side of a run of one induction motor (SI): t (T,), flux linkages psi (4 x T) [Wb],
    currents (4 x T) [A] (i_qs, i_ds, i_qr, i_dr), electromagnetic torque (T,) [N*m] on the motor shaft, stator
    current amplitude (T,) [A] (the peak of the phase current), the integrals [J] at the end: electrical input,
    copper loss, air-gap work, switching loss; the change of magnetic energy [J]; the steady state's breakdown
    and starting torques of the motor [N*m]."""

    motor: object
    t: np.ndarray
    psi: np.ndarray
    currents: np.ndarray
    torque: np.ndarray
    current: np.ndarray
    electrical_input: float
    copper_loss: float
    air_gap_work: float
    switching_loss: float
    magnetic_energy_change: float
    breakdown_torque: float
    starting_torque: float

    @property
    def peak_torque(self) -> float:
        """Largest electromagnetic torque on the motor shaft [N*m]."""
        return float(np.max(np.abs(self.torque)))

    @property
    def peak_current(self) -> float:
        """Largest stator phase current (amplitude) [A]."""
        return float(np.max(self.current))


def motor_run(run, k: int = 0) -> MotorRun | None:
    """The :class:`MotorRun` of crank ``k``'s drive in a :class:`~machdyn.transient.run.Transient`, or None when
    it has no electrical states."""
    electric = run.electric
    if electric is None or k not in electric["index"]:
        return None
    j = electric["index"].index(k)
    rows = electric["rows"][(4 + INTEGRALS) * j:(4 + INTEGRALS) * (j + 1)]
    motor = electric["drives"][j]
    psi = rows[:4]
    currents = np.array(motor.currents(psi))
    torque = motor.electromagnetic_torque(psi)
    energy = motor.magnetic_energy(psi)
    breakdown = float(motor.breakdown[0])
    starting = float(motor.air_gap_torque(1.0))
    return MotorRun(motor, run.t, psi, currents, torque, np.hypot(currents[0], currents[1]), float(rows[4, -1]),
                    float(rows[5, -1]), float(rows[6, -1]), float(rows[7, -1]), float(energy[-1] - energy[0]),
                    breakdown, starting)
