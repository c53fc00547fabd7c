"""Motor duty beyond continuous running: the intermittent periodic duty S3 and the continuous periodic duty with
intermittent load S6 of IEC 60034-1, and the starts per hour an induction motor stands.

All torques are at one shaft (the crank, in :mod:`machdyn.dynamics.stage`); all checks are thermal, by the
equivalent-torque (RMS) method: the winding losses, and so the temperature rise, grow nearly with the square of
the torque near the rated point, so a varying torque heats the motor like its root mean square over time
(Pyrhönen, Jokinen & Hrabovcová, *Design of Rotating Electrical Machines*, 2nd ed. 2014, §10.1; the same
formula as a selection rule: Groschopp, "Understanding Variable Torque Requirements", 2012, and Kollmorgen, "How
to Calculate RMS Torque", 2017).

Duty types (IEC 60034-1:2022, §4.2): S1 continuous (§4.2.1); S3 identical cycles of running at constant load and
rest, de-energised, with the cyclic duration factor ``cdf`` = running time / cycle time (§4.2.3); S6 identical
cycles of running at load and running at no load, no rest (§4.2.6), ``cdf`` = load time / cycle time. The
standard's preferred factors are 15, 25, 40 and 60 % with a cycle of 10 min; the RMS method below holds for
cycles short against the motor's thermal time constant (tens of minutes for motors above ~1 kW), i.e. for a
press's strokes and pauses, not for hour-long cycles.

**Rating for S3/S6 from the S1 rating.** A motor whose S1 rated torque is T_S1 may carry, in a duty with load share
``cdf`` and zero torque otherwise, the torque T_S1/√cdf (Parvalux, "What is an S3 duty cycle?", FAQ: "the rated
torque is equal to the continuous torque multiplied by 1/√(x/100)" — stated there for permanent-magnet DC motors;
the thermal argument, losses growing with the square of the torque, is the same for an induction motor near its
rated point); it is the RMS rule with a rest at zero torque. It is neither bound of a catalogue's S3 rating: it
neglects the poorer cooling of a self-ventilated motor at rest (manufacturers then derate more), and it also counts
every loss as growing with the torque squared, whereas the iron and friction losses are fixed while running and
stop at a de-energised rest — with them the torque allowed while running is higher (H2W Technologies' rotary
motion calculator allows 1.75 times the continuous torque of an AC motor at 50 %, against 1/√0.5 = 1.41 here).
Where the maker gives an S3 rating, it should be preferred. The
``rest_cooling`` factor h = heat dissipated at rest / heat dissipated running (h = 1: the rule above; a
self-ventilated motor cools much less at rest, and h comes from its maker; the same constant "heat dissipation ratio
(ventilated/non-ventilated motor)" that Vanhoucke's duty-cycle calculator for MEZ motors asks for) weighs the rest
periods in the mean heat balance: the mean loss cdf·T² over the mean dissipation cdf + h(1 − cdf) must not exceed
T_S1² over 1, so T_eq = T √(cdf/(cdf + h(1 − cdf))) in S3. In S6 the no-load periods carry a no-load torque T_0
(friction, the idling flywheel's losses), and the load torque allowed is √((T_S1² − (1 − cdf) T_0²)/cdf).

**Starting.** During a run-up the rotor of an induction motor dissipates T·ω_s·s (slip s, air-gap torque T,
synchronous speed ω_s): the rotor copper loss is the slip times the air-gap power (Fitzgerald, Kingsley &
Umans, *Electric Machinery*, 6th ed. 2003, ch. 6, the induction machine's power balance). Against an inertia
J [kg·m²] and a constant load torque T_L with a mean motor torque T_M, J dω/dt = T_M − T_L, so the rotor loss
from rest to ω_s is

    W_r = ½ J ω_s² · T_M / (T_M − T_L)

— the kinetic energy given to the inertia, times (1 + T_L/(T_M − T_L)); at no load the rotor dissipates exactly
the kinetic energy the run-up stores, a standard result (e.g. Hughes & Drury, *Electric Motors and Drives*, 4th
ed. 2013, ch. 6, the run-up of an induction motor; the derivation above is complete in itself). The stage integrates
T·ω_s·s along its simulated start-up instead (:func:`run_up_rotor_loss`), which holds for any load.

The permissible rotor heat per hour used here is the rotor copper loss at rated load for an hour:
Q_h = 3600 s · P_r s_r/(1 − s_r) (rated power P_r, rated slip s_r; the air-gap power is P_r/(1 − s_r), friction
neglected). Running at an equivalent load L = T_eq/T_r already spends L² of it (the rotor loss T ω_s s grows with
T², s ∝ T on the slip line), so the starts per hour the motor stands are z = Q_h (1 − L²)/W_r. This is a thermal
budget of the rotor alone: it neglects the stator's starting losses and the poorer cooling at low speed, and a
catalogue's permissible no-load starts per hour, where known, should be preferred.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError

DUTIES = ("S1", "S3", "S6")


def _check_duty(duty: str, cdf: float) -> None:
    if duty not in DUTIES:
        raise InputError(f"duty must be one of {', '.join(DUTIES)}; got {duty!r}.")
    if not (np.isfinite(cdf) and 0.0 < cdf <= 1.0):
        raise InputError(f"cyclic_duration_factor must be in (0, 1]; got {cdf!r}.")


def _check_cooling(h: float) -> None:
    if not (np.isfinite(h) and 0.0 < h <= 1.0):
        raise InputError(f"rest_cooling must be in (0, 1]; got {h!r}.")


def rms_torque(torques, durations) -> float:
    """The equivalent (RMS) torque [N·m] of a cycle of segments: √(Σ T_i² t_i / Σ t_i).

    torques : T_i [N·m] of each segment; durations : t_i [s] >= 0, not all 0 (Groschopp 2012; Kollmorgen 2017).
    """
    t = np.asarray(torques, dtype=float)
    d = np.asarray(durations, dtype=float)
    if t.shape != d.shape or t.size == 0:
        raise InputError(f"torques and durations must have the same non-empty shape; got {t.shape} and {d.shape}.")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(d)) and np.all(d >= 0) and d.sum() > 0):
        raise InputError("durations must be finite, >= 0 and not all 0, torques finite.")
    return float(np.sqrt(np.sum(t * t * d) / np.sum(d)))


def equivalent_torque(load_rms: float, duty: str = "S1", cdf: float = 1.0, no_load_torque: float = 0.0,
                      rest_cooling: float = 1.0) -> float:
    """The thermally equivalent continuous torque [N·m] of a duty (IEC 60034-1:2022 §4.2.1, 4.2.3, 4.2.6):
    S1: T_load; S3: T_load √(cdf/(cdf + h(1 − cdf))) (rest at zero torque; √cdf · T_load for h = 1);
    S6: √(cdf T_load² + (1 − cdf) T_0²).

    load_rms : the RMS torque [N·m] while loaded; cdf : cyclic duration factor in (0, 1]; no_load_torque : T_0
    [N·m] in the no-load periods of S6; rest_cooling : h in (0, 1], the cooling at rest against running (S3).
    Valid for cycles short against the thermal time constant.
    """
    _check_duty(duty, cdf)
    _check_cooling(rest_cooling)
    if duty == "S1":
        return float(load_rms)
    if duty == "S3":
        return rms_torque([load_rms, 0.0], [cdf, rest_cooling * (1.0 - cdf)])
    return rms_torque([load_rms, no_load_torque], [cdf, 1.0 - cdf])


def rated_torque_for_duty(rated_s1: float, duty: str = "S1", cdf: float = 1.0, no_load_torque: float = 0.0,
                          rest_cooling: float = 1.0) -> float:
    """The load torque [N·m] a motor of S1 rated torque ``rated_s1`` [N·m] carries in the duty: S3
    T_S1 √((cdf + h(1 − cdf))/cdf), T_S1/√cdf for h = 1 (Parvalux FAQ "What is an S3 duty cycle?"), S6
    √((T_S1² − (1 − cdf) T_0²)/cdf) (0 if the no-load torque alone overloads it). The inverse of
    :func:`equivalent_torque`; same validity."""
    _check_duty(duty, cdf)
    _check_cooling(rest_cooling)
    if duty == "S1":
        return float(rated_s1)
    if duty == "S3":
        return float(rated_s1 * np.sqrt((cdf + rest_cooling * (1.0 - cdf)) / cdf))
    t0 = no_load_torque if duty == "S6" else 0.0
    room = rated_s1**2 - (1.0 - cdf) * t0**2
    return float(np.sqrt(room / cdf)) if room > 0 else 0.0


def start_rotor_loss(inertia: float, synchronous_speed: float, motor_torque: float, load_torque: float = 0.0) -> float:
    """The rotor loss [J] of a direct-on-line run-up from rest to the synchronous speed: ½ J ω_s² T_M/(T_M − T_L).

    inertia : J [kg·m²] > 0 at the motor shaft; synchronous_speed : ω_s [rad/s] > 0; motor_torque : mean motor
    torque T_M [N·m] over the run-up; load_torque : constant load torque T_L [N·m] < T_M (see the module)."""
    if not (inertia > 0 and synchronous_speed > 0):
        raise InputError(f"inertia and synchronous speed must be > 0; got {inertia!r}, {synchronous_speed!r}.")
    if not motor_torque > load_torque:
        raise InputError(f"the motor torque {motor_torque!r} N*m must exceed the load torque {load_torque!r} N*m "
                         "for the motor to run up.")
    return 0.5 * inertia * synchronous_speed**2 * motor_torque / (motor_torque - load_torque)


def run_up_rotor_loss(t, motor_speed, motor_torque, synchronous_speed: float) -> float:
    """The rotor loss [J] along a simulated run-up: ∫ T (ω_s − ω) dt (trapezoidal rule).

    t [s] increasing; motor_speed ω [rad/s] and motor_torque T [N·m] (air-gap torque) at the motor shaft."""
    t = np.asarray(t, dtype=float)
    p = np.asarray(motor_torque, dtype=float) * (synchronous_speed - np.asarray(motor_speed, dtype=float))
    if t.size < 2:
        return 0.0
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(t)))


def rotor_heat_per_hour(rated_power: float, rated_slip: float) -> float:
    """The permissible rotor heat per hour [J/h]: 3600 s · P_r s_r/(1 − s_r), the rated rotor copper loss for an
    hour (rated_power [W] > 0, rated_slip in (0, 1)); see the module for the assumption."""
    if not (rated_power > 0 and 0 < rated_slip < 1):
        raise InputError(f"rated power must be > 0 and rated slip in (0, 1); got {rated_power!r}, {rated_slip!r}.")
    return 3600.0 * rated_power * rated_slip / (1.0 - rated_slip)


def starts_per_hour(heat_per_hour: float, load_ratio: float, loss_per_start: float) -> float:
    """The starts per hour a motor stands: Q_h (1 − L²)/W_r (0 when the running load L = T_eq/T_r >= 1)."""
    if not loss_per_start > 0:
        raise InputError(f"the rotor loss per start must be > 0; got {loss_per_start!r} J.")
    return max(0.0, heat_per_hour * (1.0 - load_ratio**2) / loss_per_start)


@dataclass(frozen=True)
class DutyCheck:
    """The motor's duty figures (SI, torques at the crank): the duty, its cyclic duration factor, the RMS torque
    while loaded, the equivalent torque of the duty, the rated S1 torque, the duty's load/rating ratio; the rotor
    loss of one start, the permissible rotor heat per hour and the starts per hour the motor stands (NaN without
    a start-up), and the starts per hour asked for (None if not given)."""

    duty: str
    cdf: float
    load_rms: float
    equivalent: float
    rated: float
    start_loss: float
    heat_per_hour: float
    starts_allowed: float
    starts_required: float | None
    no_load_torque: float = 0.0
    rest_cooling: float = 1.0

    @property
    def load_ratio(self) -> float:
        return self.equivalent / self.rated

    @property
    def rated_for_duty(self) -> float:
        """The torque [N·m] the motor may carry while loaded in its duty (:func:`rated_torque_for_duty`)."""
        return rated_torque_for_duty(self.rated, self.duty, self.cdf, self.no_load_torque, self.rest_cooling)

    def failures(self) -> list[str]:
        """The failed checks: an overloaded motor, too few starts per hour."""
        return self.overload() + self.too_many_starts()

    def overload(self) -> list[str]:
        out = []
        if self.load_ratio > 1.0 + 1e-9:
            what = {"S1": "continuous duty S1", "S3": f"intermittent periodic duty S3 at {100 * self.cdf:g} %",
                    "S6": f"continuous periodic duty S6 at {100 * self.cdf:g} % load"}[self.duty]
            out.append(f"the induction motor is overloaded for {what} (IEC 60034-1): the equivalent torque "
                       f"{self.equivalent:.4g} N*m at the crank (RMS while loaded {self.load_rms:.4g} N*m) is "
                       f"{100 * self.load_ratio:.4g} % of its rated torque {self.rated:.4g} N*m at the crank; it "
                       "will overheat. Choose a larger motor or a shorter duty.")
        return out

    def too_many_starts(self) -> list[str]:
        out = []
        if self.starts_required is not None and np.isfinite(self.starts_allowed) \
                and self.starts_required > self.starts_allowed:
            out.append(f"the induction motor stands {self.starts_allowed:.4g} starts per hour (rotor loss "
                       f"{self.start_loss:.4g} J per start against {self.heat_per_hour:.4g} J/h permissible rotor "
                       f"heat, load {100 * self.load_ratio:.3g} %), fewer than the {self.starts_required:g} asked "
                       "for (flywheel.motor.starts_per_hour)")
        return out


def motor_duty(drive, load_rms: float, duty: str = "S1", cdf: float = 1.0, no_load_torque: float = 0.0,
               start_up=None, starts_required: float | None = None, rest_cooling: float = 1.0) -> DutyCheck:
    """The duty check of an :class:`~machdyn.dynamics.drives.InductionMotor` (single design) whose steady
    RMS torque at the crank is ``load_rms`` [N·m]; ``start_up`` a :class:`~machdyn.dynamics.motion.StartUp`
    (its trajectory up to the time to steady running gives the rotor loss of a start)."""
    ratio, eff = float(np.max(drive.ratio)), float(np.max(drive.efficiency))
    rated = float(np.max(drive.rated_torque)) * ratio * eff
    equivalent = equivalent_torque(load_rms, duty, cdf, no_load_torque, rest_cooling)
    loss = heat = allowed = float("nan")
    if start_up is not None:
        tr = start_up.trajectory
        end = float(np.ravel(start_up.time_to_steady)[0])
        keep = np.ravel(tr.t) <= end if np.isfinite(end) else np.ones(np.size(tr.t), bool)
        crank_torque = np.ravel(tr.drive_torque)[keep]
        motor_torque = np.where(crank_torque >= 0, crank_torque / (ratio * eff), crank_torque * eff / ratio)
        ws = float(np.max(drive.synchronous_speed))
        loss = run_up_rotor_loss(np.ravel(tr.t)[keep], ratio * np.ravel(tr.omega)[keep], motor_torque, ws)
        heat = rotor_heat_per_hour(float(np.max(drive.rated_power)), float(np.max(drive.rated_slip)))
        allowed = starts_per_hour(heat, equivalent / rated, loss) if loss > 0 else float("inf")
    return DutyCheck(duty, cdf, float(load_rms), equivalent, rated, loss, heat, allowed, starts_required,
                     no_load_torque, rest_cooling)
