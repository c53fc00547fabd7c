"""machdyn: analysis and design of machine mechanisms and bulk-material machinery.

The planar linkage engine lives in :mod:`machdyn.linkage`; screw conveyors in :mod:`machdyn.conveyor`.
Everything computes in SI floats; units are parsed and printed at the boundary by :mod:`machdyn.units`.
"""

__version__ = "0.1.0"

_LAZY = {
    "load_problem": "reading",
    "dump_problem": "problem",
    "run_problem": "runner",
    "check_problem": "runner",
    "RunResult": "runner",
}


__all__ = ["RunResult", "check_problem", "dump_problem", "load_problem", "run_problem"]


def __getattr__(name: str):
    # Re-exports load on first use so that `machdyn --version` and `import machdyn` stay light.
    if name in _LAZY:
        from importlib import import_module

        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module 'machdyn' has no attribute {name!r}")
