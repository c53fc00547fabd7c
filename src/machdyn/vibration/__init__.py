"""What the frame feels: a machine frame on elastic mounts driven by the mechanism's shaking loads, and measured
vibration records judged by the severity standards.

- :mod:`.frame` — the frame as a rigid planar body on mounts (springs, rubber mounts, tyres, hanging ropes)
- :mod:`.modes` — natural frequencies and mode shapes
- :mod:`.response` — steady-state response to the shaking-load harmonics, RMS, transmitted forces, comparisons
- :mod:`.signals` — reading and analysing acceleration/velocity records (band limits, integration, spectra)
- :mod:`.severity` — ISO 10816-1 / ISO 2372 zones and classes (tables in ``data/``)
"""

from .frame import STANDARD_GRAVITY, Frame, Mount, critical_damping, pendulum_stiffness, rope, rubber_mount, tyre
from .modes import Modes, check_supported, modes
from .response import (
    Comparison,
    FrameResponse,
    ShakingLoads,
    compare,
    harmonic_loads,
    reduction_percent,
    shaking_loads,
    steady_state,
    transmissibility,
)
from .severity import Severity, classify, compare_severity, severity_range, zone_boundaries
from .signals import (
    DEFAULT_BAND,
    ChannelSummary,
    Record,
    RecordAnalysis,
    analyse_record,
    band_limit,
    compare_records,
    crest_factor,
    integrate_to_velocity,
    order_spectrum,
    peak,
    read_record,
    rms,
    welch_spectrum,
)

__all__ = [
    "STANDARD_GRAVITY", "Comparison", "Frame", "FrameResponse", "Modes", "Mount", "ShakingLoads",
    "check_supported", "compare", "critical_damping", "harmonic_loads", "modes", "pendulum_stiffness",
    "reduction_percent", "rope", "rubber_mount", "shaking_loads", "steady_state", "transmissibility", "tyre",
]
__all__ += [
    "DEFAULT_BAND", "ChannelSummary", "Record", "RecordAnalysis", "Severity", "analyse_record", "band_limit",
    "classify", "compare_records", "compare_severity", "crest_factor", "integrate_to_velocity", "order_spectrum",
    "peak", "read_record", "rms", "severity_range", "welch_spectrum", "zone_boundaries",
]
