"""Per-design reductions of the population kernels (:mod:`.fused_population`), compiled with numba.

A population kernel computes, for one design, a small table of rows over the crank positions (closure, the
dyads' normalised determinants and transmission angles, each output's value and rate, the inertia loads, the
compactor plate's angle) and hands it to :func:`motion_summary`, which reduces it to that design's numbers with
the definitions of the NumPy reference (:func:`machdyn.results.population.evaluate_population`): the status
checks, the transmission angles, the strokes (:func:`numpy.unwrap` for a rocker), the time ratios
(:func:`machdyn.linkage.diagnostics.time_ratio`), the inertial shaking force and moment and the compactor's
figures. The operations are those of the reference, in the same order, so that both agree to rounding.

Imported only by the generated population kernels (numba is imported here).
"""

from __future__ import annotations

import math

import numba

from .force_gain import crank_force_gain
from .reductions import worst_of

#: The worst transmission angle of :mod:`.reductions`, the same code compiled for the kernels' scalars.
_worst_of = numba.njit(cache=True, error_model="numpy", nogil=True)(worst_of)
#: The compactor's crank force gain of :mod:`.force_gain`, the same code compiled for the kernels' scalars.
_crank_force_gain = numba.njit(cache=True, error_model="numpy", nogil=True)(crank_force_gain)

#: |normalised determinant| below which a position is dead (machdyn.linkage.kinematics.DEAD_TOL).
DEAD_TOL = 1e-6
#: |normalised determinant| below which a design is near a dead point (results.population.NEAR_DEAD).
NEAR_DEAD = math.sin(math.radians(1.0))
TWO_PI = 2.0 * math.pi

#: Columns of the status part of a design's summary row, then 3 per dyad, 2 per output, 2 inertial, 2 plate.
STATUS = ("assembled", "assembled_fraction", "dead_point", "near_dead_point", "branch_change")


@numba.njit(cache=True, error_model="numpy", nogil=True)
def _pymod(a, b):
    """a mod b with the sign of b (numpy.mod of floats, b > 0); a itself when 0 <= a < b, as fmod gives it,
    without the division."""
    if 0.0 <= a < b:
        return a
    return a % b


@numba.njit(cache=True, error_model="numpy", nogil=True)
def _stroke(values, ok, angle, m):
    """max - min of an output over the regular positions; a rocker's angle unwrapped first as
    numpy.unwrap(where(ok, angle, 0)) does (period 2 pi, discontinuity pi, corrections summed in order)."""
    hi = -math.inf
    lo = math.inf
    prev = values[0] if ok[0] > 0.5 else 0.0
    total = 0.0
    for j in range(m):
        p = values[j] if ok[j] > 0.5 else 0.0
        if angle and j > 0:
            dd = p - prev
            if abs(dd) >= math.pi:  # numpy.unwrap's correction (zero for a smaller step)
                ddmod = _pymod(dd + math.pi, TWO_PI) - math.pi
                if ddmod == -math.pi and dd > 0.0:
                    ddmod = math.pi
                total += ddmod - dd
            prev = p
            p = p + total
        if ok[j] > 0.5:
            if p > hi:
                hi = p
            if p < lo:
                lo = p
    return hi - lo


@numba.njit(cache=True, error_model="numpy", nogil=True)
def _time_ratio(rates, ok, full, phi, step, m):
    """Quick-return ratio (machdyn.linkage.diagnostics.time_ratio, Uicker, Pennock & Shigley, *Theory of
    Machines and Mechanisms*, 5th ed., §1.9): the longer over the shorter crank interval between the output's
    two limit positions, each located by linear interpolation; NaN unless there are exactly two."""
    count = 0
    w1 = 0.0
    w2 = 0.0
    for j in range(m):
        k = j + 1 if j + 1 < m else 0
        if not (ok[j] > 0.5 and ok[k] > 0.5) or (j == m - 1 and not full):
            continue
        r = rates[j]
        nxt = rates[k]
        if r == 0.0 or r * nxt < 0.0:
            frac = 0.0 if r == 0.0 else r / (r - nxt)
            where = phi[j] + step[j] * frac
            if count == 0:
                w1 = where
            elif count == 1:
                w2 = where
            count += 1
    if count != 2 or not full:
        return math.nan
    forward = _pymod(w2 - w1, TWO_PI)
    back = TWO_PI - forward
    return max(forward, back) / min(forward, back)


@numba.njit(cache=True, error_model="numpy", nogil=True)
def _transmission(x, ok, acos, m, out, col):
    """Min, max and worst (nearest 0 or pi) transmission angle [rad] of a dyad over its regular positions
    where the angle is finite (inf, -inf, inf when none), from the argument ``x`` of arccos(clip(x, -1, 1))
    (``acos``) or arcsin(clip(x, 0, 1)). Both functions are monotonic, so the extremes of the angle are
    those of the argument: two inverse functions per design instead of one per position."""
    lo = math.inf
    hi = -math.inf
    for j in range(m):
        v = x[j]
        if ok[j] > 0.5 and v == v:
            v = min(max(v, -1.0 if acos else 0.0), 1.0)
            if v < lo:
                lo = v
            if v > hi:
                hi = v
    if lo == math.inf:
        out[col] = math.inf
        out[col + 1] = -math.inf
        out[col + 2] = math.inf
    elif acos:  # decreasing: the smallest angle at the largest argument
        small = math.acos(hi)
        large = math.acos(lo)
        out[col] = small
        out[col + 1] = large
        out[col + 2] = _worst_of(small, large)
    else:  # increasing, 0..pi/2: the worst angle is the smallest
        small = math.asin(lo)
        out[col] = small
        out[col + 1] = math.asin(hi)
        out[col + 2] = _worst_of(small, math.asin(hi))


@numba.njit(cache=True, error_model="numpy", nogil=True)
def _plate(c, s, ok, PH, m, out, col):
    """The compactor plate's largest angle to the horizontal gamma = |wrap(theta)| (at the position of its
    smallest cos: |theta| decreases with cos theta) and the smallest |k1| (:func:`.force_gain.crank_force_gain`
    of theta - phi) over the pressing window PH[2] (seed 003 eq 1, eq 10), theta = atan2(s, c) as the NumPy
    engine's body angle."""
    low = math.inf
    at = -1
    k1 = math.inf
    window = False
    for j in range(m):
        if ok[j] > 0.5 and c[j] < low:
            low = c[j]
            at = j
        if PH[2, j] > 0.0:
            window = True
            if ok[j] > 0.5:
                v = abs(_crank_force_gain(math.atan2(s[j], c[j]) - PH[0, j]))
                if v < k1:
                    k1 = v
    out[col] = abs(_pymod(math.atan2(s[at], c[at]) + math.pi, TWO_PI) - math.pi) if at >= 0 else -math.inf
    out[col + 1] = k1 if window else math.nan


@numba.njit(cache=True, error_model="numpy", nogil=True)
def motion_summary(B, nd, TK, kinds, inertial, plate, full, PH, out):
    """One design's status and motion figures from its rows ``B`` (see :mod:`.fused_population` for the
    layout): ``nd`` dyads whose transmission angle is an arccos (``TK`` 1) or an arcsin (0) of its row,
    ``kinds`` one flag per output (1 a rocker's angle, 0 a slider's travel, -1 no stroke wanted), the first
    row of the inertia loads ``inertial`` and of the plate's cos and sin ``plate`` (-1 when not computed),
    ``full`` whether the crank angles ``PH[0]`` (steps ``PH[1]``, pressing window ``PH[2]``) cover one turn.
    Writes ``out``: the :data:`STATUS` columns, per dyad min, max and worst (nearest 0 or pi) transmission
    angle [rad] over the regular positions (inf, -inf, inf when none), per output stroke [m or rad] and time
    ratio [-], then the peak inertial shaking force [N] and moment [N*m], then the plate's largest angle to
    the horizontal [rad] and the smallest k1 over the pressing window [-] (NaN without a window)."""
    m = B.shape[1]
    asm = B[0]
    ok = B[1]
    count = 0.0
    all_asm = True
    for j in range(m):
        count += asm[j]
        if asm[j] <= 0.5:
            all_asm = False
    dead = False
    near = False
    branch = False
    col = 5
    for d in range(nd):
        det = B[2 + d]
        for j in range(m):
            if asm[j] > 0.5:
                k = j + 1 if j + 1 < m else 0
                mag = abs(det[j])
                if not mag >= DEAD_TOL:
                    dead = True
                if mag < NEAR_DEAD:
                    near = True
                if asm[k] > 0.5 and (full or j < m - 1) and det[j] * det[k] < 0.0:
                    branch = True
        _transmission(B[2 + nd + d], ok, TK[d] == 1, m, out, col)
        col += 3
    out[0] = 1.0 if all_asm else 0.0
    out[1] = count / m
    out[2] = 1.0 if dead else 0.0
    out[3] = 1.0 if near else 0.0
    out[4] = 1.0 if branch else 0.0
    row = 2 + 2 * nd
    for o in range(kinds.shape[0]):
        out[col] = _stroke(B[row], ok, kinds[o] == 1, m) if kinds[o] >= 0 else math.nan
        out[col + 1] = _time_ratio(B[row + 1], ok, full, PH[0], PH[1], m)
        col += 2
        row += 2
    if inertial >= 0:
        fmax = -math.inf
        mmax = -math.inf
        for j in range(m):
            if ok[j] > 0.5:
                f = math.hypot(B[inertial, j], B[inertial + 1, j])
                if f > fmax:
                    fmax = f
                mz = abs(B[inertial + 2, j])
                if mz > mmax:
                    mmax = mz
        out[col] = fmax
        out[col + 1] = mmax
        col += 2
    if plate >= 0:
        _plate(B[plate], B[plate + 1], ok, PH, m, out, col)
