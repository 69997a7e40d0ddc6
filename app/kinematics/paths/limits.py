"""The joint limits a timed path obeys: velocity from the robot's description or per joint,
acceleration per joint or as a fraction of the velocity limit.

Units: rad/s or m/s, rad/s² or m/s². The URDF has no acceleration limits: a joint without
one gets ``acceleration_fraction × v_max`` per second, the fraction defaulting to
:data:`DEFAULT_ACCELERATION_FRACTION` (a UR5 joint, 3.15 rad/s, then accelerates at
3.15 rad/s²). Mimic followers are no configuration entries: each lowers its leader's default
velocity limit to what keeps the follower within its own.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TypedDict

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.models import RobotModel

#: Acceleration limit, as a fraction of the velocity limit per second, when a joint has none.
DEFAULT_ACCELERATION_FRACTION = 1.0
#: The range of a usable limit, velocity (rad/s or m/s) or acceleration (rad/s² or m/s²): a
#: description's velocity outside it is a placeholder (none usable), a given one an error.
#: 1e-6 rad/s is 0.2°/hour; beyond the range the time parameterization loses precision.
LIMIT_RANGE = (1e-6, 1e9)


def usable(value: float | None) -> bool:
    """Whether ``value`` is a usable limit: a number within :data:`LIMIT_RANGE`."""
    return value is not None and LIMIT_RANGE[0] <= value <= LIMIT_RANGE[1]


def _out_of_range(value: float) -> str:
    return f"must lie within [{LIMIT_RANGE[0]:g}, {LIMIT_RANGE[1]:g}] (got {value:g})"


def _given(
    robot: RobotModel,
    values: Sequence[float] | Mapping[str, float] | None,
    joints: np.ndarray,
    field: str,
) -> dict[int, float]:
    """Wire index → value of a per-joint list (over ``joints``, or over every joint when it
    has one value per joint) or joint map; every value within :data:`LIMIT_RANGE`."""
    if values is None:
        return {}
    if isinstance(values, Mapping):
        mimic = {m.name: m.leader for m in robot.mimic_joints}
        items = []
        for name, value in values.items():
            path = f"{field}.{name}"
            if name in mimic:
                raise InvalidInputError(
                    f"{name!r} is a mimic follower: it moves with {mimic[name]!r}, give that "
                    "joint's limit",
                    path,
                )
            items.append((robot.joint_index(name, field=path), value, path))
    else:
        if len(values) == robot.n:
            joints = np.arange(robot.n)
        if len(values) != len(joints):
            raise InvalidInputError(
                f"expected {len(joints)} values (one per joint: "
                f"{', '.join(robot.joint_names[i] for i in joints)}), got {len(values)}",
                field,
            )
        items = [(int(joints[i]), v, f"{field}.{i}") for i, v in enumerate(values)]
    out = {}
    for index, value, path in items:
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise InvalidInputError("must be a number", path) from None
        if not usable(number):
            raise InvalidInputError(_out_of_range(number), path)
        out[index] = number
    return out


def description_velocity(robot: RobotModel, index: int) -> float | None:
    """The velocity limit (rad/s or m/s) the robot's description gives wire joint ``index``,
    lowered to ``v_f / |m|`` by every mimic follower ``f`` it leads (multiplier ``m``) that has
    a usable one; ``None`` when the joint has no usable one (missing, 0, infinite: outside
    :data:`LIMIT_RANGE`)."""
    own = robot.joints[index].velocity
    if not usable(own):
        return None
    limits = [own]
    for m in robot.mimic_joints:
        v_f = robot.urdf_joints.get(m.name, {}).get("velocity")
        if m.leader_index == index and m.multiplier != 0.0 and usable(v_f):
            limits.append(v_f / abs(m.multiplier))
    lowest = min(limits)
    return lowest if usable(lowest) else None


class LimitOptions(TypedDict, total=False):
    """The limit options of a timed path: the keywords
    :func:`app.kinematics.paths.timing.parameterize` passes on to :func:`joint_limits`."""

    velocity_limits: Sequence[float] | Mapping[str, float] | None
    acceleration_limits: Sequence[float] | Mapping[str, float] | None
    acceleration_fraction: float | None
    velocity_scale: float
    joints: Sequence[int] | None


def joint_limits(
    robot: RobotModel,
    moving: np.ndarray,
    *,
    field: str = "timing",
    velocity_limits: Sequence[float] | Mapping[str, float] | None = None,
    acceleration_limits: Sequence[float] | Mapping[str, float] | None = None,
    acceleration_fraction: float | None = None,
    velocity_scale: float = 1.0,
    joints: Sequence[int] | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """The velocity and acceleration limits of the moving joints, (n,) each, NaN elsewhere.

    Velocity: ``velocity_limits`` (a list over ``joints``, default every joint, or a joint
    map), else the description's (:func:`description_velocity`), times ``velocity_scale``.
    Acceleration: ``acceleration_limits`` (list or map), else ``acceleration_fraction`` (or
    :data:`DEFAULT_ACCELERATION_FRACTION`) × the velocity limit before ``velocity_scale``:
    a fraction ``f`` gives ``a_max = f · v_max / (1 s)``. Errors name
    ``<field>.velocity_limits.<i or joint>`` and the like.
    """
    velocity_scale = float(velocity_scale)
    fraction_field = f"{field}.acceleration_fraction"
    sel = np.arange(robot.n) if joints is None else np.asarray(joints, dtype=int)
    if acceleration_limits is not None and acceleration_fraction is not None:
        raise InvalidInputError(
            "give either acceleration_limits or acceleration_fraction, not both", fraction_field
        )
    fraction = DEFAULT_ACCELERATION_FRACTION
    if acceleration_fraction is not None:
        fraction = float(acceleration_fraction)
        if not (math.isfinite(fraction) and fraction > 0.0):
            raise InvalidInputError(
                f"must be a finite number > 0 (got {fraction:g})", fraction_field
            )
    if not (math.isfinite(velocity_scale) and 0.0 < velocity_scale <= 1.0):
        raise InvalidInputError(
            f"must lie in (0, 1] (got {velocity_scale:g})", f"{field}.velocity_scale"
        )
    v_given = _given(robot, velocity_limits, sel, f"{field}.velocity_limits")
    a_given = _given(robot, acceleration_limits, sel, f"{field}.acceleration_limits")
    v = np.full(robot.n, np.nan)
    a = np.full(robot.n, np.nan)
    for i in map(int, moving):
        v_max = v_given[i] if i in v_given else description_velocity(robot, i)
        if v_max is None:
            joint = robot.joints[i]
            urdf = "missing or infinite" if joint.velocity is None else f"{joint.velocity:g}"
            raise InvalidInputError(
                f"joint {joint.name!r} moves along the path but its description has no usable "
                f"velocity limit (URDF velocity: {urdf}); give one in {field}.velocity_limits",
                f"{field}.velocity_limits.{joint.name}",
            )
        v[i] = v_max * velocity_scale
        a[i] = a_given[i] if i in a_given else fraction * v_max
        for value, name in ((v[i], f"{field}.velocity_scale"), (a[i], fraction_field)):
            if not usable(value):  # a product of two values in range can leave it
                raise InvalidInputError(
                    f"gives joint {robot.joints[i].name!r} a limit of {value:g}, outside "
                    f"[{LIMIT_RANGE[0]:g}, {LIMIT_RANGE[1]:g}]",
                    name,
                )
    return v, a
