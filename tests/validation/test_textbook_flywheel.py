"""Published worked examples of the maximum fluctuation of energy of a turning-moment diagram.

Sources (read from the text of each page, not from a figure):

F1  R. S. Khurmi & J. K. Gupta, *Theory of Machines*, Example 16.4 (ch. 16 "Turning moment diagrams and
    flywheel"; its inputs m = 36 kg, k = 150 mm, N = 1800 r.p.m. as in the FOSSEE Python Textbook Companion,
    https://tbc-python.fossee.in/convert-notebook/Theory_Of_Machines/ch16.ipynb, fourth example). Petrol
    engine, scales 1 mm = 5 N-m and 1 mm = 1°, the diagram repeats every half revolution, the areas above and
    below the mean turning-moment line taken in order 295, 685, 40, 340, 960, 270 mm². Printed solution:
    dE = (E + 295) - (E - 690) = 985 mm² = 86 N-m, C_S = 86 / 28 787 = 0.003 or 0.3 % (as reproduced at
    https://www.drjackthetutor.com/questions/1819365/the-turning-moment-diagram-for-a-petrol-engine-is-drawn-to-
    the-following-scales).
F2  A four-stroke gas engine whose turning-moment diagram is four triangles over the four strokes (720°), areas
    from the zero line: suction 0.45e-3 m², compression 1.7e-3 m², expansion 6.8e-3 m², exhaust 0.65e-3 m²,
    each m² being 3 MN-m; uniform resisting torque. Printed steps: net work 12,000 N-m, T_mean = 12,000 / 4 pi
    = 954.93 N-m, height of the expansion triangle BF = 12987 N-m, excess BG = 12033.07 N-m, the maximum
    fluctuation being the triangle DBE similar to ABC (holooly.com, "Question 10.50", https://holooly.com/
    solutions/the-turning-moment-diagram-for-a-four-stroke-gas-engine-may-be-assumed-for-simplicity-to-be-
    represented-by-four-triangles-the-areas-of-which-from-the-line-of-zero-pressure-are-as-follows-suction-str).
    The page's final figure was not legible in the stored text; dE is compared with the book's construction
    evaluated from its printed intermediates, dE = (1/2) pi BG² / BF (see the test for the book's BG).

The widths of F1's loops are not given (only their areas); dE does not depend on them, which the test shows by
using two different sets of widths. The diagrams are built piecewise linear with their corners on samples,
where the trapezoidal rule and the crossing interpolation of ``energy_fluctuation`` are exact to rounding.
"""

import numpy as np

from machdyn.linkage import energy_fluctuation


def lobes(areas, widths, mean, samples_per_degree=4):
    """A turning-moment diagram of triangular loops of signed ``areas`` [J] over ``widths`` [deg] about ``mean``
    [N*m]: crank angles [rad] (end point excluded) and the torque."""
    step = np.radians(1.0 / samples_per_degree)
    edges = np.radians(np.concatenate([[0.0], np.cumsum(widths)]))
    phi = np.arange(round(edges[-1] / step)) * step
    torque = np.full(phi.shape, float(mean))
    for area, start, end in zip(areas, edges[:-1], edges[1:], strict=True):
        height = 2.0 * area / (end - start)
        mid = 0.5 * (start + end)
        inside = (phi >= start) & (phi < end)
        torque[inside] += height * (1.0 - np.abs(phi[inside] - mid) / (0.5 * (end - start)))
    return phi, torque


def test_khurmi_16_4_fluctuation_of_energy_and_of_speed():
    scale = 5.0 * np.pi / 180.0  # J per mm²: 5 N-m x 1° per mm²
    areas = scale * np.array([295.0, -685.0, 40.0, -340.0, 960.0, -270.0])
    for widths in ([30.0] * 6, [20.0, 40.0, 15.0, 35.0, 50.0, 20.0]):
        # The diagram repeats every half revolution: two repeats make the whole turn energy_fluctuation needs.
        phi, torque = lobes(np.tile(areas, 2), widths * 2, mean=150.0)
        d_e = float(energy_fluctuation(torque, phi))
        np.testing.assert_allclose(d_e, 985.0 * scale, rtol=1e-12)  # the book's 985 mm², exactly
        assert abs(d_e - 86.0) <= 0.5  # printed 86 N-m: half a unit of the last digit
        omega = 2 * np.pi * 1800.0 / 60.0
        c_s = d_e / (36.0 * 0.150**2 * omega**2)
        assert abs(c_s - 0.003) <= 0.0005  # printed 0.003 (0.3 %)


def test_four_stroke_triangles_over_720_degrees():
    to_joule = 3e6  # J per m²
    areas = to_joule * np.array([-0.45e-3, -1.7e-3, 6.8e-3, -0.65e-3])  # suction, compression, expansion, exhaust
    phi, torque = lobes(areas, [180.0] * 4, mean=0.0)
    assert np.isclose(phi[-1] + (phi[1] - phi[0]), 4 * np.pi)
    t_mean = float(np.mean(torque))
    assert abs(t_mean - 954.93) <= 0.005  # printed 954.93 N-m
    d_e = float(energy_fluctuation(torque, phi))  # a 4 pi cycle, found from the crank angles
    bf = 2 * 20_400.0 / np.pi  # exact height of the expansion triangle, printed 12987 N-m
    assert abs(bf - 12_987.0) <= 0.5
    exact = 0.5 * np.pi * (bf - t_mean) ** 2 / bf
    np.testing.assert_allclose(d_e, exact, rtol=1e-12)
    # The book's construction from its printed intermediates. Its BG = 12033.07 N-m is 1.00 N-m above its own
    # BF - T_mean = 12987 - 954.93 = 12032.07 N-m (an arithmetic slip, 8e-5 relative, 1.7e-4 on dE); with BG
    # from its BF and T_mean, the only error left is BF's rounding to 5 digits (0.5 / 12987 = 4e-5 on dE, x 2).
    printed = 0.5 * np.pi * (12_987.0 - 954.93) ** 2 / 12_987.0
    assert abs(d_e - printed) <= 8e-5 * printed
    slip = 0.5 * np.pi * 12_033.07**2 / 12_987.0
    assert abs(d_e - slip) <= (8e-5 + 2 * 1.0 / 12_033.07) * slip
    # The same with the cycle stated.
    np.testing.assert_allclose(energy_fluctuation(torque, phi, cycle=4 * np.pi), d_e, rtol=1e-15)
