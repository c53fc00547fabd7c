"""The drive train's stages and shafts: the model lives in :mod:`machdyn.dynamics.driveline` (the one drive line
every capability reads); these names stay importable from here."""

from __future__ import annotations

from ..dynamics.driveline import DriveLine, DriveTrain, Stage

__all__ = ["DriveLine", "DriveTrain", "Stage"]
