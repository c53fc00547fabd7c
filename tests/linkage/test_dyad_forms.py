"""Each dyad's closed form is written once (machdyn.linkage.dyad_forms) and both engines compute it: the NumPy
engine with arrays, the fused engine with the same code compiled for scalars."""

from __future__ import annotations

import inspect

import numpy as np
import pytest

from machdyn.linkage import builders, crank_angles, dyad_forms, dyads, fused_dyads, kinematics


def _transmission(mech, phi):
    return kinematics(mech, phi, 10.0, 0.0).dyad_reports[0].transmission


def test_an_inverted_slider_cranks_transmission_angle_does_not_depend_on_its_size():
    """The transmission angle of an RPR dyad is arcsin(|d . u| / D) (d = P - Q, u the slide direction, D = |d|),
    a ratio of lengths: the same for a machine ten times larger. On the slide line through the rocker's pivot
    (no offset) it is 90 degrees at every crank angle."""
    phi = crank_angles(72)
    small = builders.inverted_slider_crank(0.1, 0.3, offset=0.02)
    large = builders.inverted_slider_crank(1.0, 3.0, offset=0.2)
    np.testing.assert_allclose(_transmission(large, phi), _transmission(small, phi), rtol=1e-12)
    straight = builders.inverted_slider_crank(1.0, 3.0)
    # arcsin near 1 turns a rounding of 1e-16 in its argument into sqrt(2e-16) = 1.4e-8 rad: hence 1e-7 rad
    np.testing.assert_allclose(_transmission(straight, phi), np.pi / 2, rtol=0.0, atol=1e-7)


def test_the_engines_hold_no_closed_form_of_their_own():
    """dyads.py and fused_dyads.py call the forms; neither computes a square root, an arcsine or a distance of a
    dyad's closure itself (the fused engine's kernel text names the forms)."""
    numpy_side = inspect.getsource(dyads)
    fused_side = inspect.getsource(fused_dyads)
    for name in ("rrr", "rrp", "rpr", "prp"):
        assert f"forms.{name}_motion(" in numpy_side and f"forms.{name}_forces(" in numpy_side
        assert f'"{name}_motion"' in fused_side and f'"{name}_forces"' in fused_side
    for closure in ("sqrt", "asin"):  # what closes a dyad; lengths (hypot), guides (cos, sin) are geometry
        assert f"math.{closure}" not in fused_side and f"np.{closure}" not in numpy_side, closure


def test_the_scalar_forms_equal_the_array_forms():
    """The same code with the scalar ops gives, element by element, what the NumPy ops give for arrays
    (assembled and not, a toggle position included)."""
    pytest.importorskip("numba")
    scalar = dyad_forms.scalar_forms()
    rng = np.random.default_rng(7)
    args = [rng.normal(size=40) for _ in range(12)] + [np.full(40, 0.3), np.ones(40), np.zeros(40),
                                                        np.full(40, 0.25), np.ones(40), np.zeros(40), 1.0]
    arrays = dyad_forms.rrr_motion(*args)
    assert not np.all(arrays[0]) and np.any(arrays[0])  # some of the random dyads close, some do not
    for i in range(40):
        one = scalar.rrr_motion(*(a[i] if np.ndim(a) else a for a in args))
        for got, want in zip(one, arrays, strict=True):
            np.testing.assert_allclose(got, np.asarray(want)[i] if np.ndim(want) else want, rtol=1e-15,
                                       equal_nan=True)


def test_a_kernel_is_named_by_the_forms_it_inlines(monkeypatch):
    """A change to the forms gives every kernel a new name, so that a kernel compiled with the old forms is never
    loaded from the cache."""
    from machdyn.linkage.fused_source import generate

    generated = generate(builders.four_bar(0.04, 0.12, 0.08, 0.1), crank_angles(36))
    before = generated.key("summary")
    assert "F_rrr_motion(" in generated.source("summary")
    monkeypatch.setattr("machdyn.linkage.fused_source.forms_version", lambda: "changed")
    assert generated.key("summary") != before
