"""The choice between the NumPy engine (the reference) and the fused, compiled engine."""

from __future__ import annotations

import importlib.util

import numpy as np

from ..errors import InputError
from .fused_generator import Unsupported
from .fused_source import generate

ENGINES = ("auto", "fused", "numpy")

#: Positions (designs x crank angles) from which "auto" compiles: about half a second of the NumPy engine,
#: the order of a first compilation (a cached kernel loads in a fraction of that).
AUTO_MIN_POSITIONS = 1_000_000


def available() -> bool:
    """True if numba, the fused engine's compiler, can be imported."""
    return importlib.util.find_spec("numba") is not None


def check_engine(engine: str) -> None:
    if engine not in ENGINES:
        raise InputError(f"The engine must be one of {', '.join(ENGINES)}; got {engine!r}.")


def use_fused(engine: str, mech, phi, positions: int) -> bool:
    """Whether a request of ``positions`` positions of ``mech`` at crank angles ``phi`` runs fused."""
    check_engine(engine)
    if engine == "numpy":
        return False
    if engine == "fused":
        if not available():
            raise InputError("The fused engine needs numba, which cannot be imported; use engine='numpy'.")
        if np.ndim(phi) != 1:
            raise InputError(f"The fused engine needs a 1-D array of crank angles; got shape {np.shape(phi)}.")
        return True
    if positions < AUTO_MIN_POSITIONS or np.ndim(phi) != 1 or not available():
        return False
    try:
        generate(mech, phi)
    except Unsupported:
        return False
    return True
