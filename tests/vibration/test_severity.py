"""Severity zones and classes read from the data tables."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.vibration import classify, compare_severity, severity_range, zone_boundaries


def test_tables_are_read_and_increasing():
    # ISO 10816-1:1995 Table B.1: class I 0.71/1.8/4.5, II 1.12/2.8/7.1, III 1.8/4.5/11.2, IV 2.8/7.1/18 mm/s.
    expected = {"I": (0.71, 1.8, 4.5), "II": (1.12, 2.8, 7.1), "III": (1.8, 4.5, 11.2), "IV": (2.8, 7.1, 18.0)}
    for c, b in expected.items():
        assert zone_boundaries(c) == pytest.approx(tuple(v * 1e-3 for v in b), rel=1e-12)
        assert zone_boundaries(c, "ISO 2372") == zone_boundaries(c, "ISO 20816-1")


@pytest.mark.parametrize(("mm_s", "zone"), [(0.0, "A"), (0.71, "A"), (0.72, "B"), (1.8, "B"), (4.49, "C"),
                                            (4.5, "C"), (4.51, "D"), (100.0, "D")])
def test_zone_edges_class_i(mm_s, zone):
    assert classify(mm_s * 1e-3, "I").zone == zone


def test_iso2372_labels_and_ranges():
    s = classify(2.0e-3, "II", "ISO 2372")
    assert (s.zone, s.index, s.standard) == ("satisfactory", 1, "ISO 2372")
    assert severity_range(2.0e-3) == "2.8" and severity_range(0.05e-3) == "0.11" and severity_range(0.1) == ">71"


def test_custom_boundaries_and_comparison():
    before, after, red = compare_severity(8e-3, 3e-3, "III", boundaries=(2e-3, 5e-3, 9e-3))
    assert (before.zone, after.zone) == ("C", "B") and red == pytest.approx(62.5)


def test_bad_input():
    with pytest.raises(InputError, match="machine class must be one of I, II, III, IV"):
        classify(1e-3, "V")
    with pytest.raises(InputError, match="severity standard must be one of"):
        classify(1e-3, "I", "VDI 2056")
    with pytest.raises(InputError, match="RMS velocity must be >= 0"):
        classify(-1e-3)
    with pytest.raises(InputError, match="three increasing velocities"):
        classify(1e-3, boundaries=(3e-3, 2e-3, 1e-3))


@settings(max_examples=100, deadline=None)
@given(a=st.floats(0.0, 0.05), b=st.floats(0.0, 0.05), machine_class=st.sampled_from(["I", "II", "III", "IV"]),
       standard=st.sampled_from(["ISO 10816-1", "ISO 2372"]))
def test_zone_never_improves_with_more_vibration(a, b, machine_class, standard):
    lo, hi = sorted((a, b))
    assert classify(lo, machine_class, standard).index <= classify(hi, machine_class, standard).index
