"""The ``[rotary_screen]`` problem: the rotary grading screen of seed 002 from the paper's inputs.

The table holds the paper's symbols (R, m1, L, m2, m3, l_AS1, l_BS2, l_CS2, m_e, r_e), each with its unit; the
crank speed omega is ``[drive] speed``. ``spring = true`` adds the energy-storing spring of eq 17 (stiffness
m_C omega^2 unless ``stiffness`` is given). The run analyses the engine's model of the screen
(:meth:`machdyn.screen.model.RotaryScreen.mechanism`) and reports the paper's energy figures
(T1max, T2, T3, the range of W) next to the engine's exact values.
"""

from __future__ import annotations

from pydantic import Field

from ..problem.fields import Mass, NonNegativeLength, PositiveLength, PositiveMass, Stiffness
from ..problem.schema import DriveSpec, Meta, OutputSpec, Spec
from .model import RotaryScreen


class RotaryScreenSpec(Spec):
    """Seed 002's inputs: crank radius R, masses m1 (crank), m2 (rod, i.e. the screen body), m3 (slider);
    rod length L; centroid distances l_AS1 (crank, from A), l_BS2 and l_CS2 (rod, from B and C); counterweight
    m_e at radius r_e. ``spring`` adds the compensating spring, of ``stiffness`` (default eq 17)."""

    R: PositiveLength
    m1: Mass
    L: PositiveLength
    m2: PositiveMass
    m3: Mass
    l_AS1: NonNegativeLength
    l_BS2: PositiveLength
    l_CS2: PositiveLength
    m_e: Mass
    r_e: PositiveLength
    spring: bool = Field(False, strict=True)
    stiffness: Stiffness | None = None


class RotaryScreenProblem(Spec):
    """A rotary grading screen problem: ``[meta]``, ``[rotary_screen]``, ``[drive]``, ``[output]``."""

    meta: Meta = Meta(name="rotary grading screen")
    rotary_screen: RotaryScreenSpec
    drive: DriveSpec
    output: OutputSpec = OutputSpec()

    def screen(self):
        """The :class:`~machdyn.screen.model.RotaryScreen` of these inputs."""
        s = self.rotary_screen
        return RotaryScreen(
            R=s.R, m1=s.m1, L=s.L, m2=s.m2, m3=s.m3, l_AS1=s.l_AS1, l_BS2=s.l_BS2, l_CS2=s.l_CS2,
            m_e=s.m_e, r_e=s.r_e, omega=self.drive.speed,
        )

    def mechanism(self):
        """The engine's model of the screen (with the spring if asked for)."""
        return self.screen().mechanism(spring=self.rotary_screen.spring, stiffness=self.rotary_screen.stiffness)
