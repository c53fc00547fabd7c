"""Measured records: exact RMS of sines after integration, band limits, spectra, CSV reading and bad input."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.vibration import (
    Record,
    analyse_record,
    band_limit,
    compare_records,
    crest_factor,
    integrate_to_velocity,
    order_spectrum,
    read_record,
    rms,
    welch_spectrum,
)

FS = 4096.0
N = 8192  # 2 s


@settings(max_examples=50, deadline=None)
@given(amplitude=st.floats(1e-3, 1e3), cycles=st.integers(21, 1999), phase=st.floats(0, 2 * np.pi))
def test_pure_sine_gives_the_exact_rms_velocity(amplitude, cycles, phase):
    # a(t) = A sin(2 pi f t + p) with a whole number of periods in the record; v = -A/(2 pi f) cos(...), so
    # v_rms = A / (2 pi f sqrt 2) exactly (the DFT of a sine on a bin is one line). Rounding only: rel 1e-9.
    f = cycles / (N / FS)  # 10.5 ... 999.5 Hz, inside the 10-1000 Hz band
    t = np.arange(N) / FS
    a = amplitude * np.sin(2 * np.pi * f * t + phase)
    v = integrate_to_velocity(a, FS, (10.0, 1000.0))
    assert rms(v) == pytest.approx(amplitude / (2 * np.pi * f * np.sqrt(2)), rel=1e-9)
    # and the velocity itself, sample by sample:
    np.testing.assert_allclose(v, -amplitude / (2 * np.pi * f) * np.cos(2 * np.pi * f * t + phase),
                               atol=1e-9 * amplitude / (2 * np.pi * f))


def test_band_limit_removes_what_lies_outside():
    t = np.arange(N) / FS
    inside = 2.0 * np.sin(2 * np.pi * 100 * t)
    x = 5.0 + 3.0 * np.sin(2 * np.pi * 2 * t) + inside + 1.5 * np.cos(2 * np.pi * 1500 * t)
    np.testing.assert_allclose(band_limit(x, FS, (10.0, 1000.0)), inside, atol=1e-12)


def test_peak_rms_crest_factor_of_a_sine_and_a_square():
    t = np.arange(N) / FS
    s = np.sin(2 * np.pi * 8 * t)
    assert crest_factor(s) == pytest.approx(np.sqrt(2), rel=1e-6)
    assert crest_factor(np.sign(np.sin(2 * np.pi * 8 * t + 0.1))) == pytest.approx(1.0)


def test_welch_psd_integrates_to_the_mean_square():
    # Parseval for Welch's estimate of a stationary sine: the integral of the PSD is A^2/2 (rel 1e-3: the Hann
    # window's side lobes at 1 Hz resolution hold all the power within the summed band).
    t = np.arange(4 * N) / FS
    f, p = welch_spectrum(3.0 * np.sin(2 * np.pi * 160 * t), FS)
    assert np.sum(p) * (f[1] - f[0]) == pytest.approx(4.5, rel=1e-3)
    assert f[np.argmax(p)] == pytest.approx(160.0)


def test_order_spectrum_finds_the_orders_of_the_crank():
    # Crank at 25 rev/s (157.08 rad/s): orders 1 and 2 with amplitudes 4 and 1 -> RMS 4/sqrt2 and 1/sqrt2. The
    # flat-top window reads amplitudes to within 0.1 % (Brandt 2011, Table 9.1).
    t = np.arange(N) / FS
    x = 4.0 * np.sin(2 * np.pi * 25 * t) + 1.0 * np.cos(2 * np.pi * 50 * t + 0.3)
    orders, amp = order_spectrum(x, FS, 2 * np.pi * 25)
    for order, a in ((1, 4.0), (2, 1.0)):
        i = np.argmin(np.abs(orders - order))
        assert amp[i] == pytest.approx(a / np.sqrt(2), rel=1e-3)


def write_record(path, header, rows):
    path.write_text(header + "\n" + "\n".join(",".join(f"{v:.10g}" for v in r) for r in rows) + "\n")


def test_read_record_converts_units_and_analyses(tmp_path):
    t = np.arange(N) / FS
    f = 50.0
    a_g = 0.5 * np.sin(2 * np.pi * f * t)  # in g
    v_mm = 6.0 * np.sin(2 * np.pi * f * t)  # in mm/s
    path = tmp_path / "rec.csv"
    write_record(path, "# test record\ntime [s],frame [g],bearing [mm/s]", np.column_stack([t, a_g, v_mm]))
    rec = read_record(path)
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-9)
    assert rec.quantities == {"frame": "acceleration", "bearing": "velocity"}
    res = analyse_record(rec, crank_speed=2 * np.pi * f)
    frame, bearing = res.channel("frame"), res.channel("bearing")
    # 0.5 g at 50 Hz: v_rms = 0.5 * 9.80665 / (2 pi 50 sqrt2); the CSV keeps 10 digits: rel 1e-8.
    assert frame.velocity_rms == pytest.approx(0.5 * 9.80665 / (2 * np.pi * f * np.sqrt(2)), rel=1e-8)
    assert frame.acceleration_rms == pytest.approx(0.5 * 9.80665 / np.sqrt(2), rel=1e-8)
    assert bearing.velocity_rms == pytest.approx(6e-3 / np.sqrt(2), rel=1e-8)
    assert bearing.acceleration_rms is None
    assert bearing.crest_factor == pytest.approx(np.sqrt(2), rel=1e-6)
    i = np.argmin(np.abs(frame.orders - 1.0))
    assert frame.order_rms[i] == pytest.approx(frame.velocity_rms, rel=1e-3)
    # before/after: halve the bearing channel
    path2 = tmp_path / "after.csv"
    write_record(path2, "time [ms],frame [g],bearing [mm/s]", np.column_stack([t * 1e3, a_g, v_mm / 2]))
    red = compare_records(res, analyse_record(read_record(path2)))
    assert red["bearing"] == pytest.approx(50.0, abs=1e-6) and red["frame"] == pytest.approx(0.0, abs=1e-6)


# ------------------------------------------------------------------------------------------- bad input


def test_too_few_samples_for_the_band():
    x = np.sin(np.arange(300))
    with pytest.raises(InputError, match=r"too few samples for the band 10-1000 Hz: 300 samples .* at least 2048"):
        integrate_to_velocity(x, 4096.0, (10.0, 1000.0))


def test_sampling_rate_below_twice_the_band_top():
    with pytest.raises(InputError, match=r"at least twice the band's top \(2 x 1000 = 2000 Hz\); got 1500 Hz"):
        band_limit(np.zeros(20000), 1500.0, (10.0, 1000.0))


def test_nan_samples_are_refused_in_arrays_and_files(tmp_path):
    x = np.zeros(N)
    x[123] = np.nan
    with pytest.raises(InputError, match="NaN or infinite sample.*index 123"):
        integrate_to_velocity(x, FS)
    t = np.arange(N) / FS
    rows = np.column_stack([t, np.sin(t)])
    path = tmp_path / "nan.csv"
    text = "time [s],front [m/s^2]\n" + "\n".join(f"{a:.10g},{b:.10g}" for a, b in rows)
    text = text.replace(f"{rows[10, 0]:.10g},{rows[10, 1]:.10g}", f"{rows[10, 0]:.10g},")
    path.write_text(text)
    with pytest.raises(InputError, match=r"channel 'front' .* 1 NaN or empty sample\(s\), the first at t = "):
        read_record(path)


def test_record_file_errors(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        read_record(tmp_path / "missing.csv")
    p = tmp_path / "nounit.csv"
    p.write_text("time [s],front\n0,1\n0.1,2\n")
    with pytest.raises(InputError, match="Column 2 of .*nounit.csv has no unit in its header"):
        read_record(p)
    p.write_text("time [s],front [N]\n0,1\n0.1,2\n")
    with pytest.raises(InputError, match="unit in the header of column 2 of .* is not a time, acceleration or "
                                         "velocity unit"):
        read_record(p)
    p.write_text("time [s],front [m/s]\n0,1\n0.1,2\n0.15,3\n")
    with pytest.raises(InputError, match="even steps"):
        read_record(p)
    p.write_text("time [s],front [m/s]\n" + "0,1\n" * 10)
    with pytest.raises(InputError, match="record files are limited|limited to"):
        read_record(p, max_bytes=10)
    with pytest.raises(InputError, match="band must satisfy"):
        band_limit(np.zeros(100), 100.0, (20.0, 10.0))


def test_a_constant_channel_is_refused_not_judged_as_zero_vibration():
    # A dead or saturated sensor gives a constant channel; band-limited it reads 0 mm/s (zone A "good").
    t = np.arange(N) / FS
    record = Record(t, {"front": np.full(N, 9.81)}, {"front": "acceleration"}, FS, "dead.csv")
    with pytest.raises(InputError, match=r"channel 'front' of dead.csv is constant"):
        analyse_record(record)


def _periodic_band_random(low, high, fs, n, seed):
    # Random phases and amplitudes on the FFT lines inside (low, high): band-limited and exactly periodic.
    rng = np.random.default_rng(seed)
    f = np.fft.rfftfreq(n, 1 / fs)
    lines = (f > low) & (f < high)
    spectrum = np.where(lines, rng.normal(size=f.size) + 1j * rng.normal(size=f.size), 0.0)
    return np.fft.irfft(spectrum, n=n)


def test_frequency_domain_integration_matches_time_domain_trapezoid():
    # Second method: cumulative trapezoid in time, its integration constant removed (the mean). The trapezoid
    # rule scales a line at f by (w h / 2) / tan(w h / 2) ~ 1 - (w h)^2 / 12: at most 0.8 % at 200 Hz and 4096 Hz
    # sampling, less in the RMS where the 1/f weighting favours the low lines: tolerance 1 %.
    from scipy.integrate import cumulative_trapezoid

    a = _periodic_band_random(20.0, 200.0, FS, N, 3)
    v_freq = integrate_to_velocity(a, FS, (10.0, 1000.0))
    v_time = cumulative_trapezoid(a, dx=1 / FS, initial=0.0)
    v_time -= v_time.mean()
    assert rms(v_time) == pytest.approx(rms(v_freq), rel=1e-2)
    assert np.max(np.abs(v_time - v_freq)) < 2e-2 * np.max(np.abs(v_freq))


def test_welch_spectrum_integrates_to_the_variance():
    # Parseval: the integral of a one-sided PSD is the variance. Welch averages Hann-windowed segments, so the
    # integral of a random band signal scatters around the variance by a few 0.1 %: tolerance 2 %.
    x = _periodic_band_random(30.0, 600.0, FS, 8 * N, 5) + 0.3  # the offset is not vibration
    f, p = welch_spectrum(x, FS)
    assert np.trapezoid(p, f) == pytest.approx(np.var(x), rel=2e-2)


def test_duplicate_time_stamps_are_named_with_their_row(tmp_path):
    t = np.arange(N) / FS
    t = np.insert(t, 10, t[9])  # the sample at row 10 written twice
    path = tmp_path / "dup.csv"
    path.write_text("time [s],front [m/s^2]\n" + "\n".join(f"{a:.10g},{np.sin(a):.10g}" for a in t))
    with pytest.raises(InputError, match=r"must increase strictly: row 11 .* does not follow row 10 .*duplicate"):
        read_record(path)
