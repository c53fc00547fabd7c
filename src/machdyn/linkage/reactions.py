"""What a kinetostatic analysis returns: the reaction at each joint, the joints of a mechanism, and the
driving torque and frame loads (:class:`Forces`), one type for the NumPy and the fused engine."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .model import Mechanism
from .motion import Kinematics


@dataclass(frozen=True)
class Reaction:
    """The force [N] on the later body of a joint from the earlier one (global axes). Prismatic joints also
    carry the signed normal force [N] along the guide's left normal and the couple [N*m]."""

    fx: np.ndarray
    fy: np.ndarray
    normal: np.ndarray | None = None
    couple: np.ndarray | None = None

    @property
    def magnitude(self) -> np.ndarray:
        return np.hypot(self.fx, self.fy)


@dataclass(frozen=True)
class Joint:
    """A joint: its name, kind ('R' revolute, 'P' prismatic) and the two bodies (earlier, later)."""

    name: str
    kind: str
    body_1: str
    body_2: str


@dataclass(frozen=True)
class Forces:
    """Kinetostatic results at every position: joint reactions, driving torque and the frame loads."""

    kinematics: Kinematics
    joint_list: tuple[Joint, ...]
    reactions: dict
    driving_torque: np.ndarray
    frame_fx: np.ndarray
    frame_fy: np.ndarray
    frame_moment_origin: np.ndarray

    @property
    def mechanism(self) -> Mechanism:
        return self.kinematics.mechanism

    @property
    def joints(self) -> tuple[Joint, ...]:
        return self.joint_list

    def joint(self, name: str) -> Reaction:
        """Reaction of the joint ``name`` (see :attr:`joints` for the names)."""
        try:
            return self.reactions[name]
        except KeyError:
            raise InputError(f"No joint '{name}'; joints: {', '.join(self.reactions)}.") from None

    @property
    def input_power(self) -> np.ndarray:
        """Power delivered by the drive [W]: driving torque x crank speed."""
        return self.driving_torque * self.kinematics.speed

    @property
    def frame_force(self) -> tuple[np.ndarray, np.ndarray]:
        """Total force [N] the moving mechanism puts on the frame (shaking force), global axes."""
        return self.frame_fx, self.frame_fy

    @property
    def shaking_force(self) -> np.ndarray:
        """Magnitude of the shaking force [N]."""
        return np.hypot(self.frame_fx, self.frame_fy)

    def shaking_moment(self, about=(0.0, 0.0)) -> np.ndarray:
        """Moment [N*m] of all loads on the frame about the point ``about`` [m], including the reaction of
        the driving torque on the motor's stator (counter-clockwise positive)."""
        zx, zy = about
        return self.frame_moment_origin - (zx * self.frame_fy - zy * self.frame_fx)
