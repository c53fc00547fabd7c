"""Cams: follower motion programs, followers, profiles, the designer's checks and the cam machine's dynamics."""

#: The package's public API is its modules (``from machdyn.cams import checks``).
__all__ = [
    "checks", "dxf", "dynamics", "follower_linkage", "followers", "laws", "linkage_stage", "population", "profile",
    "program", "schema", "shaft", "stage"
]
