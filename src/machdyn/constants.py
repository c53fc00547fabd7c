"""Physical constants machdyn uses, each written once. A leaf module: it imports nothing, so the engine and
every package may use it."""

from __future__ import annotations

#: Standard acceleration of gravity g_n [m/s^2], exact by definition (3rd CGPM, 1901; ISO 80000-3:2019, 3-9.1).
STANDARD_GRAVITY = 9.80665
#: The weight direction machdyn assumes unless told: g_n towards -y [m/s^2].
DOWNWARD_GRAVITY = (0.0, -STANDARD_GRAVITY)
