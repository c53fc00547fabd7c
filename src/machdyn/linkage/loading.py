"""Adding loads to a built mechanism: ``with_loads`` returns a new frozen model with the extra loads.

The builders (``slider_crank``, ``four_bar``, ...) return a mechanism without external loads. A gas force on a
piston, a process torque on a rocker, a spring, a counterweight or a different gravity vector are added here;
the original model is left unchanged (models are frozen) and the new one is validated like any other.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from typing import Any, TypeVar

from ..errors import InputError
from .model import BodyTorque, Mechanism, PointForce, PointMass, Spring

_Load = TypeVar("_Load", PointForce, BodyTorque, Spring, PointMass)


def with_loads(
    mech: Mechanism,
    *,
    forces: PointForce | Iterable[PointForce] = (),
    torques: BodyTorque | Iterable[BodyTorque] = (),
    springs: Spring | Iterable[Spring] = (),
    point_masses: PointMass | Iterable[PointMass] = (),
    gravity: tuple[float, float] | None = None,
) -> Mechanism:
    """The mechanism ``mech`` with extra loads: a new frozen model, ``mech`` itself is not changed.

    Parameters
    ----------
    mech : Mechanism
        The model to add loads to (from a builder or built by hand); its existing loads are kept.
    forces : PointForce or iterable of PointForce
        External forces [N] at named points, global axes (constant or functions of the crank angle [rad]).
    torques : BodyTorque or iterable of BodyTorque
        External torques [N*m] on bodies, counter-clockwise positive.
    springs : Spring or iterable of Spring
        Linear springs, stiffness [N/m] and free length [m], between two named points.
    point_masses : PointMass or iterable of PointMass
        Masses [kg] rigidly attached to bodies (counterweights, a piston pin), position [m] in the body frame.
    gravity : (gx, gy) [m/s^2], optional
        Replaces the gravity vector; ``(0, 0)`` switches gravity off. ``None`` keeps the model's.

    Returns
    -------
    Mechanism
        A new model; the loads are appended to those already there, in the order given.

    Raises
    ------
    InputError
        An item of the wrong type, a load whose name repeats one of the same kind, or any rule the model
        checks (a point that does not exist, a negative stiffness, ...), naming the load and the value.

    Examples
    --------
    >>> from machdyn.linkage import PointForce, slider_crank, with_loads
    >>> engine = slider_crank(0.2, 0.6, masses=(0.0, 0.0, 60.0), gravity=(0.0, 0.0))
    >>> loaded = with_loads(engine, forces=PointForce("gas", "slider.B", fx=-23_700.0))
    >>> [f.name for f in loaded.forces], engine.forces
    (['gas'], ())
    """
    if not isinstance(mech, Mechanism):
        raise InputError(f"with_loads needs a Mechanism as its first argument; got {type(mech).__name__}.")
    new_forces = _items("forces", forces, PointForce)
    new_torques = _items("torques", torques, BodyTorque)
    new_springs = _items("springs", springs, Spring)
    new_masses = _items("point_masses", point_masses, PointMass)
    changes: dict[str, Any] = {
        "forces": _join("forces", mech.forces, new_forces),
        "torques": _join("torques", mech.torques, new_torques),
        "springs": _join("springs", mech.springs, new_springs),
        "point_masses": _join("point_masses", mech.point_masses, new_masses),
    }
    if gravity is not None:
        try:
            gx, gy = gravity
        except (TypeError, ValueError):
            raise InputError(f"The gravity must be a vector (gx, gy) in m/s^2; got {gravity!r}.") from None
        changes["gravity"] = (gx, gy)
    # The model validates itself on construction: a bad reference is reported like for any other model.
    return replace(mech, **changes)


def _items(argument: str, value: Any, kind: type[_Load]) -> tuple[_Load, ...]:
    items = (value,) if isinstance(value, kind) else value
    try:
        items = tuple(items)
    except TypeError:
        raise InputError(
            f"The {argument} of with_loads must be a {kind.__name__} or a list of them; got {value!r}."
        ) from None
    for item in items:
        if not isinstance(item, kind):
            raise InputError(
                f"Every item of {argument} in with_loads must be a {kind.__name__}; got {type(item).__name__} "
                f"{item!r}."
            )
    return items


def _join(argument: str, old: tuple[_Load, ...], new: tuple[_Load, ...]) -> tuple[_Load, ...]:
    names = [item.name for item in old + new]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated and new:
        raise InputError(
            f"The names of {argument} must be unique in a mechanism; got {', '.join(repeated)} more than once."
        )
    return old + new
