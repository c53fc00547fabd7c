"""The ``[mechanism]`` kind and the linkage analysis it shares with the rotary screen; registered by one line in
:mod:`machdyn.kinds`."""

#: The package's public API is its modules (``from machdyn.pipelines import linkage_run``).
__all__ = [
    "linkage_run", "mechanism"
]
