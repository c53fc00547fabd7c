"""Drive trains: gear, belt and chain stages, clutch and brake, single stroke, and the sizing of parts
(bearings, pins, links) for their loads, and the population forms of the parts and the clutch for N designs at
once (:mod:`.population`, :mod:`.parts_population`); see ``docs/drivetrain.md`` and ``docs/population.md``."""

#: The package's public API is its modules (``from machdyn.drivetrain import bearings``).
__all__ = [
    "bearings", "clutch", "parts", "parts_population", "parts_stage", "population", "single_stroke", "stage",
    "strength", "train"
]
