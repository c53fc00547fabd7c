"""Input checks of the seed machines: clear messages naming the field, the rule and the value."""

from __future__ import annotations

import re

import numpy as np
import pytest

from machdyn import screen as rotary_screen
from machdyn.errors import AssemblyError, InputError
from machdyn.machines import compactor, tamper


def raises(exc, message):
    return pytest.raises(exc, match="^" + re.escape(message) + "$")


def test_tamper_inputs():
    with raises(InputError, "The stroke must lie between 2|e_journal - e_sleeve| = 0.003 m and "
                            "2(e_journal + e_sleeve) = 0.009 m; got 0.01 m."):
        tamper.sleeve_angle_for_stroke(0.010, 3e-3, 1.5e-3)
    with raises(InputError, "The journal eccentricity e_journal must be >= 0 m; got -0.003 m."):
        tamper.resultant_eccentricity(-3e-3, 1e-3, 0.0)
    with raises(InputError, "The sleeve angle must be a finite number; got nan rad."):
        tamper.eccentricity_phase(3e-3, 1e-3, np.nan)
    with raises(InputError, "The offset slider-crank cannot close: it needs |r sin(theta) + e| < l at every angle; "
                            "got r = 0.0025 m, l = 0.005 m, e = 0.005 m."):
        tamper.exact_position(np.pi / 2, 2.5e-3, 5e-3, 5e-3)
    with raises(InputError, "The beam length must be > 0 m; got 0 m."):
        tamper.complex_mass_substitution(90.0, 0.0, 0.2, 0.0)


def test_tamper_balance_inputs():
    from machdyn.machines.tamper import balance

    with raises(InputError, "The tamper m_aux must be > 0 kg; got -1 kg."):
        balance.TamperBeams(m_aux=-1.0)
    with raises(InputError, "The tamper sleeve_aux mass must be >= 0 kg; got -2 kg."):
        balance.TamperBeams(sleeve_aux=-2.0)
    with raises(InputError, "The main resultant eccentricity must be > 0 m; got 0 m."):
        balance.tamper_state(balance.TamperBeams(), 0.0, 0.0, 3e-3, 0.0)
    with raises(InputError, "The shaft speed must be > 0 rad/s; got 0 rad/s."):
        balance.tamper_states(speed=0.0)
    with raises(InputError, "The counterweight radius must be > 0 m; got -0.05 m."):
        balance.corrected_balance(counterweight_radius=-0.05)
    with raises(InputError, "The robust balancing mode must be 'sum' or 'worst'; got 'max'."):
        balance.corrected_balance(mode="max")


def test_rotary_screen_inputs():
    with raises(InputError, "The rotary screen crank radius R must be smaller than the rod length L = 3.6 m; "
                            "got 4 m."):
        rotary_screen.RotaryScreen(R=4.0)
    with raises(InputError, "The rotary screen rod centroid distances must add up to L = 3.6 m; got l_BS2 + l_CS2 = "
                            "3.7 m."):
        rotary_screen.RotaryScreen(l_BS2=2.0)
    with raises(InputError, "The rotary screen omega must be > 0 rad/s; got -21 rad/s."):
        rotary_screen.RotaryScreen(omega=-21.0)
    with raises(InputError, "The crank angle alpha must be a finite number; got inf rad."):
        rotary_screen.t1(rotary_screen.PAPER_SCREEN, np.inf)


def test_compactor_inputs():
    with raises(InputError, "The compactor branch must be +1 or -1; got 0."):
        compactor.Compactor(branch=0)
    with raises(InputError, "The compaction force must act on the plate: q_from_b must be within 0 ... 0.5 m; "
                            "got 0.6 m."):
        compactor.Compactor(q_from_b=0.6)
    with raises(InputError, "The lever arm a must not exceed the plate length l = 0.5 m; got 0.6 m."):
        compactor.force_gain_lever(0.5, 0.6)
    with raises(AssemblyError, "The compactor four-bar cannot close at some crank angles: it needs |l - R| <= "
                               "|C - A| <= l + R; got r = 0.3 m, l = 0.5 m, h = 0.25 m, R = 0.25 m."):
        compactor.closed_form(np.linspace(0, 2 * np.pi, 37), 0.3, 0.5, 0.25, 0.25)
    # the engine reports the same design with the crank-angle ranges
    with pytest.raises(AssemblyError, match="cannot be assembled for crank angles"):
        compactor.Compactor(r=0.3).kinematics(np.linspace(0, 2 * np.pi, 37))
