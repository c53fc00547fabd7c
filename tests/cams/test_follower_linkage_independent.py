"""``[follower_linkage]`` cross-checked by a second, independent method: plain trigonometry and Lagrange's equation.

Nothing of the linkage engine or of :mod:`machdyn.cams.follower_linkage` is used for the reference values. The
machine of ``examples/cam_rocker_linkage.toml`` (and a translating variant of it, each also as a clockwise cam with
the mirrored drawing) is rebuilt here:

* the follower's motion s(phi) from the motion laws written out (cycloidal rise, 3-4-5 polynomial return; Norton,
  *Design of Machinery*, 5th ed., ch. 8), checked against :meth:`machdyn.cams.program.Program.svaj`;
* the linkage placed by loop closure of the arm-rod-slide chain: the arm's pin A from the follower's angle
  psi = psi_0 + s (cos psi_0 = (d^2 + l^2 - R_p^2)/(2 d l), the triangle cam centre - pivot - roller centre), or
  the translating follower's pin at (e - a_y, sqrt(R_p^2 - e^2) + s + a_x); the slide B on its guide y = y_G at
  x_B = x_A +- sqrt(L^2 - (y_G - y_A)^2) [m];
* the positions differentiated by fourth-order central differences;
* (energy method) the camshaft torque the linkage adds from the power balance T_cam Omega = dT/dt + dV/dt - P_loads
  with dT/dt = sum(m v.a) + I w alpha, the derivatives taken in the cam angle phi [rad] (Uicker, Pennock &
  Shigley, *Theory of Machines and Mechanisms*, 4th ed., ch. 17, energy methods);
* (Lagrange) the linkage's generalised force on the follower's coordinate q = s, Lagrange's equation of the
  one-degree-of-freedom system Q = M(q) q'' + M'(q) q'^2 / 2 + dV/dq - Q_loads with M(q) = sum(m |dr/dq|^2) +
  I (dbeta/dq)^2 (Thomson, *Theory of Vibration with Applications*, the chapter "Lagrange's equation"), the
  derivatives in q, with q' = s'(phi) Omega and q'' = s''(phi) Omega^2; split as A Omega^2 + B. The contact
  force is then Norton's eq 15.3 with the load Q, and the jump speed the lowest Omega at which its minimum over
  the cam angles reaches zero, found by bisection (not by the quadratic's root).

Tolerance. Differences of step k = 1e-4 (rad or m) of positions of order 0.4 m: truncation k^4 f^(6)/90 ~ 1e-17;
rounding about 5 eps |r| / k^2 ~ 5e-8 in the second derivatives, ~1e-7 of them. Where a central stencil in phi
straddles a segment's end the jerk jumps, an error k dj / 9 ~ 3e-5 rad/rad^2 in s'', but every segment here ends
with s' = 0, so the power sum(m r'.r'') and Q s' do not feel it. Hence 1e-6 of the peak of each compared quantity.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from machdyn.reading import load_problem
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "examples" / "cam_rocker_linkage.toml").read_text()
TEXT = TEXT[:TEXT.index("[flywheel]")].replace("positions = 720", "positions = 360")
G = 9.80665  # standard gravity [m/s^2]
DEG = np.pi / 180.0
ROD_MASS, ROD_INERTIA, SLIDE_MASS, FEED = 1.2, 0.00625, 3.0, -150.0  # [kg], [kg*m^2], [kg], [N] (the example)
FOLLOWER_MASS, RATE, PRELOAD = 1.5, 1000.0, 130.0  # [kg] at the roller, [N/m], [N] (the example)
STEP = 1e-4
TOL = 1e-6


def _variant(text: str, pairs) -> str:
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


#: the example mirrored about the y axis, turning clockwise
MIRROR = [('rotation = "ccw"', 'rotation = "cw"'), ('"-109.7 mm"', '"109.7 mm"'), ('G = ["370 mm"', 'G = ["-370 mm"'),
          ('angle = "0 deg" }', 'angle = "180 deg" }'), ('fx = "-150 N"', 'fx = "150 N"')]
#: a translating roller follower (offset 5 mm, lift 20 mm) carrying the rod's pin 60 mm above its roller centre
TRANSLATING = [('motion = "oscillating"', 'motion = "translating"\noffset = "5 mm"'),
               ('pivot_distance = "120 mm"\narm_length = "100 mm"\n', ''),
               ('swing = "20 deg"', 'lift = "20 mm"'), ('swing = "20 deg"', 'lift = "20 mm"'),
               ('A = ["102.3 mm", "-109.7 mm"]', 'A = ["60 mm", "0 mm"]'),
               ('G = ["370 mm", "150 mm"]', 'G = ["250 mm", "300 mm"]')]
TRANSLATING_MIRROR = [('rotation = "ccw"', 'rotation = "cw"'), ('G = ["250 mm"', 'G = ["-250 mm"'),
                      ('angle = "0 deg" }', 'angle = "180 deg" }'), ('fx = "-150 N"', 'fx = "150 N"')]


def _law(name: str, x):
    """Normalised rise y(x) and its first two derivatives over x in [0, 1] (Norton, ch. 8)."""
    if name == "cycloidal":
        return x - np.sin(2 * np.pi * x) / (2 * np.pi), 1 - np.cos(2 * np.pi * x), 2 * np.pi * np.sin(2 * np.pi * x)
    return 10 * x**3 - 15 * x**4 + 6 * x**5, 30 * x**2 - 60 * x**3 + 30 * x**4, 60 * x - 180 * x**2 + 120 * x**3


def _motion(phi, lift):
    """s, ds/dphi, d2s/dphi2 of the example's program: cycloidal rise 0-100 deg, dwell, 3-4-5 return 180-300 deg,
    dwell [m|rad per rad^n]."""
    t = np.mod(phi, 2 * np.pi)
    s, v, a = np.zeros_like(t), np.zeros_like(t), np.zeros_like(t)
    b = 100 * DEG
    rise = t < b
    y, y1, y2 = _law("cycloidal", np.clip(t / b, 0, 1))
    s, v, a = np.where(rise, lift * y, s), np.where(rise, lift * y1 / b, v), np.where(rise, lift * y2 / b**2, a)
    s = np.where((t >= b) & (t < 180 * DEG), lift, s)
    b = 120 * DEG
    ret = (t >= 180 * DEG) & (t < 300 * DEG)
    y, y1, y2 = _law("poly345", np.clip((t - 180 * DEG) / b, 0, 1))
    return (np.where(ret, lift * (1 - y), s), np.where(ret, -lift * y1 / b, v), np.where(ret, -lift * y2 / b**2, a))


class _Machine:
    """The example's follower and linkage placed by trigonometry; ``mirror`` -1 for the clockwise cam's drawing."""

    def __init__(self, kind: str, mirror: int):
        self.kind, self.m = kind, mirror
        rp = 0.065
        if kind == "oscillating":
            self.d, self.arm, self.lift = 0.12, 0.10, 20 * DEG
            self.psi0 = np.arccos((self.d**2 + self.arm**2 - rp**2) / (2 * self.d * self.arm))
            self.pin, self.yg = (0.1023, -0.1097 * mirror), 0.15
        else:
            self.e, self.arm, self.lift = 0.005, 1.0, 0.02
            self.y0 = np.sqrt(rp**2 - self.e**2)
            self.pin, self.yg = (0.06, 0.0), 0.30
        self.rod = 0.25

    def place(self, q):
        """Rod centre [m], rod angle [rad], slide B [m] at the follower's coordinate q [rad|m]."""
        m, (ax, ay) = self.m, self.pin
        if self.kind == "oscillating":
            psi = self.psi0 + q
            e1 = np.array([-m * np.cos(psi), np.sin(psi)])  # pivot -> roller
            e2 = np.array([-np.sin(psi), -m * np.cos(psi)])  # e1 turned +90 deg
            a = np.array([m * self.d, 0.0])[:, None] + ax * e1 + ay * e2
        else:
            a = np.array([m * self.e - ay + 0 * q, self.y0 + q + ax])
        b = np.array([a[0] + m * np.sqrt(self.rod**2 - (self.yg - a[1]) ** 2), np.full_like(a[1], self.yg)])
        return 0.5 * (a + b), np.arctan2(b[1] - a[1], b[0] - a[0]), b


def _derivatives(f, x):
    """f(x), f'(x), f''(x) for each of the arrays f returns, fourth-order central differences of step STEP."""
    vals = [f(x + i * STEP) for i in (-2, -1, 0, 1, 2)]
    out = []
    for j in range(len(vals[0])):
        y = [np.asarray(v[j]) for v in vals]
        out.append((y[2], (y[0] - 8 * y[1] + 8 * y[3] - y[4]) / (12 * STEP),
                    (-y[0] + 16 * y[1] - 30 * y[2] + 16 * y[3] - y[4]) / (12 * STEP**2)))
    return out


def _feed(phi, mirror):
    """The feed resistance's x component [N], active over cam angles 0-100 deg."""
    return np.where(np.mod(phi, 2 * np.pi) <= 100 * DEG + 1e-12, mirror * FEED, 0.0)


def _energy_torque(mc: _Machine, phi, omega):
    """T_cam = (dT/dt + dV/dt - P_loads) / Omega [N*m], positions differentiated in the cam angle."""
    (_, c1, c2), (_, b1, b2), (_, s1, s2) = _derivatives(lambda p: mc.place(_motion(p, mc.lift)[0]), phi)
    kinetic_rate = omega**3 * (ROD_MASS * np.sum(c1 * c2, 0) + ROD_INERTIA * b1 * b2 + SLIDE_MASS * np.sum(s1 * s2, 0))
    potential_rate = omega * G * (ROD_MASS * c1[1] + SLIDE_MASS * s1[1])
    load_power = _feed(phi, mc.m) * s1[0] * omega
    return (kinetic_rate + potential_rate - load_power) / omega


def _lagrange(mc: _Machine, phi):
    """The linkage's generalised force on q = s: its inertial part A [N*m*s^2|N*s^2] and static part B [N*m|N]."""
    s, v, a = _motion(phi, mc.lift)
    (_, c1, c2), (_, b1, b2), (_, s1, s2) = _derivatives(mc.place, s)
    inertial = (ROD_MASS * np.sum(c1 * (c1 * a + c2 * v**2), 0) + ROD_INERTIA * b1 * (b1 * a + b2 * v**2)
                + SLIDE_MASS * np.sum(s1 * (s1 * a + s2 * v**2), 0))
    static = G * (ROD_MASS * c1[1] + SLIDE_MASS * s1[1]) - _feed(phi, mc.m) * s1[0]
    return inertial, static


CASES = {"oscillating-ccw": ([], "oscillating", 1), "oscillating-cw": (MIRROR, "oscillating", -1),
         "translating-ccw": (TRANSLATING, "translating", 1),
         "translating-cw": (TRANSLATING + TRANSLATING_MIRROR, "translating", -1)}


@pytest.fixture(scope="module", params=list(CASES))
def case(request):
    pairs, kind, mirror = CASES[request.param]
    outcome = run_problem(load_problem(_variant(TEXT, pairs))).outcomes["follower_linkage"]
    return outcome, _Machine(kind, mirror)


def test_the_program_written_out_is_machdyns(case):
    outcome, mc = case
    phi = outcome.results.cam_angle
    m = outcome.results.cam.model.program.svaj(phi)
    for mine, theirs in zip(_motion(phi, mc.lift), (m.s, m.v, m.a), strict=True):
        np.testing.assert_allclose(mine, theirs, atol=1e-12)


def test_camshaft_torque_agrees_with_the_energy_method_and_with_lagranges_equation(case):
    outcome, mc = case
    res = outcome.results
    phi, omega = res.cam_angle, float(res.load.speed)
    theirs = res.load.camshaft_torque
    peak = float(np.max(np.abs(theirs)))
    assert peak > 1.0
    np.testing.assert_allclose(_energy_torque(mc, phi, omega), theirs, atol=TOL * peak)
    inertial, static = _lagrange(mc, phi)
    np.testing.assert_allclose((inertial * omega**2 + static) * _motion(phi, mc.lift)[1], theirs, atol=TOL * peak)


def test_follower_load_contact_force_and_jump_speed_agree_with_lagranges_equation(case):
    outcome, mc = case
    res = outcome.results
    phi, omega = res.cam_angle, float(res.load.speed)
    inertial, static = _lagrange(mc, phi)
    for mine, theirs in ((inertial, res.load.inertial), (static, res.load.static),
                         (inertial * omega**2 + static, res.load.moment)):
        np.testing.assert_allclose(mine, theirs, atol=TOL * float(np.max(np.abs(mine))))
    load = float(np.max(np.abs(inertial * omega**2 + static))) / mc.arm
    assert outcome.scalars["follower_linkage.follower_load.max"] == pytest.approx(load, rel=TOL)
    # Norton eq 15.3 along the follower's coordinate, the train's mass at the roller, then as a force at the roller
    s, _, a = _motion(phi, mc.lift)
    fixed = RATE * mc.arm**2 * s + PRELOAD * mc.arm + static
    moving = FOLLOWER_MASS * mc.arm**2 * a + inertial
    contact = (moving * omega**2 + fixed) / mc.arm
    np.testing.assert_allclose(res.contact, contact, atol=TOL * float(np.max(np.abs(contact))))
    assert outcome.scalars["follower_linkage.min_contact_force"] == pytest.approx(float(np.min(contact)), rel=TOL)
    low, high = 0.0, 1e3
    for _ in range(100):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if np.min(moving * mid**2 + fixed) > 0 else (low, mid)
    assert 0 < low < 1e3 - 1.0
    assert outcome.scalars["follower_linkage.jump_speed"] == pytest.approx(low, rel=TOL)


def test_output_stroke_is_the_slides_travel_placed_by_trigonometry(case):
    outcome, mc = case
    _, _, slide = mc.place(_motion(outcome.results.cam_angle, mc.lift)[0])
    assert outcome.scalars["follower_linkage.output_stroke"] == pytest.approx(float(np.ptp(slide[0])), rel=1e-12)
    np.testing.assert_allclose(np.abs(outcome.results.position - outcome.results.position[0]),
                               np.abs(slide[0] - slide[0][0]), atol=1e-12)


def test_the_flywheels_reduced_machine_has_the_linkages_inertia_potential_and_load_moment():
    """J = sum(m |dr/dphi|^2) + I (dbeta/dphi)^2 [kg*m^2], V = g sum(m y) [J] up to a constant and the reduced
    moment of the feed resistance F_x dx_B/dphi [N*m] (Uicker, Pennock & Shigley, ch. 17, the equivalent system),
    at the 360 nodes of the reduced machine."""
    res = run_problem(load_problem(TEXT)).outcomes["follower_linkage"].results
    base = res.cam.machine(360)
    machine = res.added_to(base, 360)
    phi = res.cam_angle
    mc = _Machine("oscillating", 1)
    (c, c1, _), (_, b1, _), (s, s1, _) = _derivatives(lambda p: mc.place(_motion(p, mc.lift)[0]), phi)
    inertia = ROD_MASS * np.sum(c1**2, 0) + ROD_INERTIA * b1**2 + SLIDE_MASS * np.sum(s1**2, 0)
    np.testing.assert_allclose(machine.inertia(phi) - base.inertia(phi), inertia, atol=TOL * float(np.max(inertia)))
    potential = G * (ROD_MASS * c[1] + SLIDE_MASS * s[1])
    difference = machine.potential(phi) - base.potential(phi) - potential
    assert float(np.ptp(difference)) < 1e-9 * float(np.ptp(potential))
    moment = _feed(phi, 1) * s1[0]
    np.testing.assert_allclose(machine.moment(phi) - base.moment(phi), moment, atol=TOL * float(np.max(np.abs(moment))))
