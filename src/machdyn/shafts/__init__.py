"""Shaft lines: masses and cylinders at several axial positions on one shaft.

The frame loads in space (force and the couples about the transverse axes), their harmonics and the bearing
reactions (:mod:`.rotating`); static and two-plane balancing (:mod:`.balance`); ISO 21940-11 balance quality
grades (:mod:`.grades`); in-line, V, opposed and radial engines with exact and two-term primary and secondary
forces and couples (:mod:`.reciprocating`); a locomotive's partial balance (:mod:`.locomotive`); field balancing
by influence coefficients (:mod:`.field`); two-plane balance and the grade of N shaft lines at once
(:mod:`.population`); and the ``[shaft_line]`` problem kind (:mod:`.kind`).
"""

#: The package's public API is its modules (``from machdyn.shafts import balance``).
__all__ = [
    "balance", "field", "frame6", "grades", "kind", "linkages", "locomotive", "model", "phases", "reciprocating",
    "population", "record_stage", "records", "rotating", "schema"
]
