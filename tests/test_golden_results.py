"""Every shipped example's results.json matches the recorded one, value by value, to 1e-12 relative.

The recorded files in ``tests/golden/`` were written by the analysis before the results stage was restructured,
each value in its display unit then (mm, deg, rpm, kW); since results.json became SI throughout they hold the
same recorded values converted once to SI with pint (not recomputed), and say ``"units": "SI"``. A result whose
unit differs between the recording and a run (none today) is still compared after conversion with pint. A result
renamed since is found under its new key through the one documented mapping,
:func:`machdyn.results.catalogue.canonical` (``shaking_force.max`` is now ``frame_force.max``,
``sweep.max_driving_torque`` is ``sweep.driving_torque.max_abs``). New results may be added; none may disappear
or change.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from machdyn.results.catalogue import canonical, find
from machdyn.runner import run_problem
from machdyn.units import ureg

ROOT = Path(__file__).resolve().parents[1]

#: Results computed more exactly on purpose since the recording, with the relative tolerance that covers it.
CORRECTED = {
    # The torque diagram is now integrated by the trapezoidal rule, exact for the piecewise-linear diagram the
    # samples define, rather than by the rectangle rule: the two differ by about 1e-5 relative at 360 samples.
    "flywheel.energy_fluctuation": 1e-4,
}
#: The extremes of a series are now the closed form's between the samples (machdyn.linkage.extremes), no longer
#: the largest sample: at 360 positions they move by the series' change over half a step, ~1e-4 relative for
#: these examples, and only ever outwards (an extreme of the samples is never beyond the true one).
EXTREMES = 2e-3
GOLDEN = sorted((ROOT / "tests" / "golden").glob("*.results.json"))


def _in_unit(value, unit_from: str, unit_to: str):
    if unit_from == unit_to:
        return value
    factor = ureg.Quantity(1.0, unit_from or "dimensionless").to(unit_to or "dimensionless").magnitude
    if isinstance(value, list):
        return [v * factor for v in value]
    return value * factor


def _close(a, b) -> bool:
    if isinstance(a, list):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, bool | str) or a is None:
        return a == b
    return abs(a - b) <= 1e-12 * max(abs(a), abs(b)) + 1e-300


def _refined(key: str) -> str | None:
    """The reduction of a result refined between the samples (max, min, max_abs, range), else None."""
    found = find(key)
    if found is None or not found[0].series or found[0].over_positions not in ("max", "min", "max_abs", "range"):
        return None
    return found[0].over_positions


def _more_extreme(old: float, new: float, how: str) -> bool:
    slack = 1e-12 * max(abs(old), abs(new))
    if how == "min":
        return new <= old + slack
    if how == "max_abs":
        return abs(new) >= abs(old) - slack
    return new >= old - slack


@pytest.mark.parametrize("golden", GOLDEN, ids=lambda p: p.name.split(".")[0])
def test_results_json_unchanged(golden: Path) -> None:
    recording = json.loads(golden.read_text(encoding="utf-8"))
    recorded = recording["scalars"]
    example = ROOT / "examples" / (golden.name.split(".")[0] + ".toml")
    written = run_problem(example).results_json()
    assert recording["units"] == written["units"] == "SI"
    now = written["scalars"]
    missing = sorted(k for k in recorded if canonical(k) not in now)
    assert not missing, f"results no longer reported: {missing}"
    changed = []
    for key, old in recorded.items():
        new = now[canonical(key)]
        value = _in_unit(new["value"], new["unit"], old["unit"]) if new["unit"] != old["unit"] else new["value"]
        how = _refined(canonical(key))
        if how is not None and isinstance(value, float):
            # a figure that is rounding noise beside another (zero_below) is compared on that one's scale
            below = find(canonical(key))[0].zero_below
            scale = max(abs(old["value"]), abs(now[below]["value"]) if below in now else 0.0)
            noise = abs(old["value"]) < 1e-9 * scale
            if (not noise and not _more_extreme(old["value"], value, how)) \
                    or abs(old["value"] - value) > EXTREMES * scale:
                changed.append((key, old, new))
        elif key in CORRECTED:
            if abs(old["value"] - value) > CORRECTED[key] * abs(old["value"]):
                changed.append((key, old, new))
        elif not _close(old["value"], value):
            changed.append((key, old, new))
    assert not changed, f"results changed: {changed[:5]}"
