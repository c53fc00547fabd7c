"""The crank force gain of a crank driving a plate (a coupler): the one definition that the compactor's machine
layer, the population evaluator and the compiled population kernels all call.

Source: M.A. Asfandiyarov et al., *Mathematical modelling of the modernised impact-vibration mechanism*
(seed 003, Bulletin of SUSU, Mechanical Engineering, 2019), eq 1 and Fig. 3b; its exact meaning is repro 003.3
of ``reference/seed-reproduction.md``.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def crank_force_gain(alpha: Any) -> Any:
    """Seed 003 force gain k1 = 1 / cos α (eq 1 and Fig. 3b).

    By virtual work, a crank force P tangential at the crank pin A (P = driving torque / r) balances a force
    P / cos α **normal to the plate at A** (V_A · n_plate = r ω1 cos α; repro 003.3); not the force along the
    plate, which would be P / sin α.

    Parameters
    ----------
    alpha : float or array
        The crank-plate angle α = θ2 − φ [rad] (the plate's direction less the crank's), |α| ≠ 90° (there the
        gain is unbounded: ±inf, or about 1e16 at the rounded angle).

    Returns
    -------
    float or array
        k1 [-], negative when the plate's normal opposes the crank's tangent; its magnitude is the gain.

    Plain ufuncs: floats, arrays, and scalars inside a numba kernel alike (:mod:`.fused_reduce` compiles it).

    Examples
    --------
    >>> round(float(crank_force_gain(np.radians(60.0))), 12)
    2.0
    """
    return 1.0 / np.cos(alpha)
