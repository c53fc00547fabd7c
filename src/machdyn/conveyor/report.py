"""The conveyor's report sections now live in :mod:`machdyn.report.conveyor`; this name stays for the registry."""

from __future__ import annotations

from typing import Any


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The screw conveyor's report sections (see :func:`machdyn.report.conveyor.sections`)."""
    from ..report.conveyor import sections as _sections

    return _sections(outcome)
