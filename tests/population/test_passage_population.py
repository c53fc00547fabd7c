"""The closed-form passage through a resonance for many designs at once (:mod:`machdyn.transient.population`)
equals :func:`machdyn.transient.closed_forms.passage_envelope` and ``undamped_passage_peak`` of each to 1e-12, and
the designs they refuse are flagged."""

from __future__ import annotations

import numpy as np

from machdyn.errors import InputError
from machdyn.transient.closed_forms import passage_envelope, undamped_passage_peak
from machdyn.transient.population import passage_envelope_population, undamped_passage_population


def test_random_passages_equal_each_passage_and_refused_ones_are_flagged():
    rng = np.random.default_rng(4)
    n = 25
    w, alpha, zeta = rng.uniform(20.0, 200.0, n), rng.uniform(0.5, 50.0, n), rng.uniform(0.0, 0.05, n)
    alpha[3], zeta[8] = -1.0, -0.01
    s = np.linspace(-2.0, 6.0, 17)
    envelope, valid = passage_envelope_population(s, w, alpha, zeta)
    undamped = undamped_passage_population(w, alpha)
    for i in range(n):
        try:
            one = passage_envelope(s, w[i], alpha[i], zeta[i])
        except InputError:
            assert not valid[i] and np.all(np.isnan(envelope[i]))
            continue
        assert valid[i]
        np.testing.assert_allclose(envelope[i], one, rtol=1e-12)
        peak, when, after = undamped_passage_peak(w[i], alpha[i])
        for key, want in (("peak", peak), ("time", when), ("after", after)):
            assert abs(undamped[key][i] - want) <= 1e-12 * want, (key, i)
    assert valid.sum() == n - 2 and undamped["valid"].sum() == n - 1  # the undamped form takes no damping
