"""Drive trains: gear, belt and chain stages, clutch and brake, single stroke, and the sizing of parts
(bearings, pins, links) for their loads; see ``docs/drivetrain.md``."""

#: The package's public API is its modules (``from machdyn.drivetrain import bearings``).
__all__ = [
    "bearings", "clutch", "parts", "parts_stage", "single_stroke", "stage", "strength", "train"
]
