"""Obstacles: simple solids placed in a robot's root frame, for environment collision checks.

An obstacle is ``{name, shape, size | radius (+ length), pose {position, orientation}}``:

``box``
    ``size`` = [x, y, z], the full edge lengths (m) along the obstacle's own axes (as URDF's
    ``<box size>``); centred on ``pose.position``.
``sphere``
    ``radius`` (m), centred on ``pose.position``.
``cylinder``
    ``radius`` and ``length`` (m): a cylinder along the obstacle's local z axis, ``length``
    its full height (as URDF's ``<cylinder>``), centred on ``pose.position``.
``capsule``
    ``radius`` and ``length`` (m): the points within ``radius`` of the segment of length
    ``length`` along the local z axis, centred on ``pose.position`` (total extent along z is
    ``length + 2·radius``; coal's ``Capsule(radius, length)``).

``pose.position`` is [x, y, z] (m) and ``pose.orientation`` a quaternion [x, y, z, w] in the
robot's root (world) frame; a missing pose is the identity. Orientations are normalised; a
quaternion whose norm differs from 1 by more than
:data:`app.kinematics.rotations.QUATERNION_NORM_TOLERANCE` is rejected as a likely mistake.

Validation lives here, not in the HTTP layer, so obstacles read back from a stored scene go
through the same checks as obstacles given inline. Every error names its field
(``obstacles.2.radius``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import coal
import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.rotations import quaternion_to_matrix, unit_quaternion
from app.kinematics.text import check_text

SHAPES = ("box", "sphere", "cylinder", "capsule")
#: Most obstacles in one request or scene.
MAX_OBSTACLES = 1000
#: Longest obstacle name.
MAX_NAME_LENGTH = 128
#: Largest dimension and largest |coordinate| of a position (m): beyond this coal's
#: bounding-volume arithmetic loses all precision.
MAX_EXTENT = 1000.0

# Which dimension fields each shape takes.
_FIELDS = {
    "box": ("size",),
    "sphere": ("radius",),
    "cylinder": ("radius", "length"),
    "capsule": ("radius", "length"),
}


@dataclass(frozen=True, slots=True)
class Obstacle:
    """One validated obstacle (hashable: it keys the per-robot cache of combined models).

    Attributes
    ----------
    name : str
        Unique within its set; reported as ``b`` of environment collision pairs.
    shape : {"box", "sphere", "cylinder", "capsule"}
    size : tuple of 3 float or None
        Box edge lengths (m).
    radius, length : float or None
        Sphere, cylinder and capsule radius (m); cylinder height / capsule segment (m).
    position : tuple of 3 float
        Centre in the root frame (m).
    orientation : tuple of 4 float
        Unit quaternion [x, y, z, w], w ≥ 0, root frame ← obstacle frame.
    """

    name: str
    shape: str
    size: tuple[float, float, float] | None
    radius: float | None
    length: float | None
    position: tuple[float, float, float]
    orientation: tuple[float, float, float, float]

    def placement(self) -> pin.SE3:
        """The obstacle frame in the root frame."""
        R = quaternion_to_matrix(np.array(self.orientation))
        return pin.SE3(R, np.array(self.position))

    def geometry(self) -> coal.CollisionGeometry:
        """The coal shape, expressed in the obstacle frame."""
        if self.shape == "box":
            return coal.Box(*self.size)
        if self.shape == "sphere":
            return coal.Sphere(self.radius)
        if self.shape == "cylinder":
            return coal.Cylinder(self.radius, self.length)
        return coal.Capsule(self.radius, self.length)

    def to_json(self) -> dict[str, Any]:
        """The wire form (what a scene stores and GET /scenes/{name} returns)."""
        out: dict[str, Any] = {"name": self.name, "shape": self.shape}
        if self.size is not None:
            out["size"] = list(self.size)
        if self.radius is not None:
            out["radius"] = self.radius
        if self.length is not None:
            out["length"] = self.length
        out["pose"] = {"position": list(self.position), "orientation": list(self.orientation)}
        return out


def _number(value: Any, field: str, *, positive: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise InvalidInputError("must be a number", field)
    out = float(value)
    if not math.isfinite(out):
        raise InvalidInputError("must be a finite number", field)
    if positive and out <= 0.0:
        raise InvalidInputError(f"must be positive (got {out!r})", field)
    if abs(out) > MAX_EXTENT:
        raise InvalidInputError(f"must be within ±{MAX_EXTENT:g} m (got {out!r})", field)
    return out


def _vector(value: Any, length: int, field: str, *, positive: bool = False) -> tuple[float, ...]:
    if not isinstance(value, Sequence) or isinstance(value, str | bytes):
        raise InvalidInputError(f"must be a list of {length} numbers", field)
    if len(value) != length:
        raise InvalidInputError(f"must have {length} values, got {len(value)}", field)
    return tuple(_number(v, f"{field}.{i}", positive=positive) for i, v in enumerate(value))


def _orientation(value: Any, field: str) -> tuple[float, float, float, float]:
    quat = unit_quaternion(np.array(_vector(value, 4, field)), field)
    if quat[3] < 0.0:
        quat = -quat
    return tuple(float(v) + 0.0 for v in quat)  # type: ignore[return-value]


def parse_obstacle(item: Mapping[str, Any], field: str) -> Obstacle:
    """One obstacle from its wire form; raises :class:`InvalidInputError` naming the field."""
    if not isinstance(item, Mapping):
        raise InvalidInputError("must be an object", field)
    known = {"name", "shape", "size", "radius", "length", "pose"}
    for key in item:
        if key not in known:
            raise InvalidInputError("unknown field", f"{field}.{key}")
    name = item.get("name")
    if not isinstance(name, str) or not name.strip():
        raise InvalidInputError("must be a non-empty string", f"{field}.name")
    if len(name) > MAX_NAME_LENGTH:
        raise InvalidInputError(f"must be at most {MAX_NAME_LENGTH} characters", f"{field}.name")
    check_text(name, f"{field}.name")
    shape = item.get("shape")
    if shape not in SHAPES:
        raise InvalidInputError(
            f"unknown shape {shape!r}; expected one of {', '.join(SHAPES)}", f"{field}.shape"
        )
    wanted = _FIELDS[shape]
    for key in ("size", "radius", "length"):
        present = item.get(key) is not None
        if key in wanted and not present:
            raise InvalidInputError(f"required for a {shape}", f"{field}.{key}")
        if key not in wanted and present:
            raise InvalidInputError(
                f"not used by a {shape} (give {' and '.join(wanted)})", f"{field}.{key}"
            )
    size = _vector(item["size"], 3, f"{field}.size", positive=True) if "size" in wanted else None
    radius = _number(item["radius"], f"{field}.radius", positive=True) if shape != "box" else None
    length = (
        _number(item["length"], f"{field}.length", positive=True) if "length" in wanted else None
    )

    pose = item.get("pose")
    position: tuple[float, ...] = (0.0, 0.0, 0.0)
    orientation: tuple[float, ...] = (0.0, 0.0, 0.0, 1.0)
    if pose is not None:
        if not isinstance(pose, Mapping):
            raise InvalidInputError("must be an object {position, orientation}", f"{field}.pose")
        for key in pose:
            if key not in ("position", "orientation"):
                raise InvalidInputError("unknown field", f"{field}.pose.{key}")
        if pose.get("position") is not None:
            position = _vector(pose["position"], 3, f"{field}.pose.position")
        if pose.get("orientation") is not None:
            orientation = _orientation(pose["orientation"], f"{field}.pose.orientation")
    return Obstacle(
        name=name,
        shape=shape,
        size=size,  # type: ignore[arg-type]
        radius=radius,
        length=length,
        position=position,  # type: ignore[arg-type]
        orientation=orientation,  # type: ignore[arg-type]
    )


def parse_obstacles(
    items: Sequence[Mapping[str, Any]], field: str = "obstacles"
) -> tuple[Obstacle, ...]:
    """Validate a list of obstacles (shapes, sizes, poses, unique names).

    Raises
    ------
    InvalidInputError
        Naming the first offending field, e.g. ``obstacles.1.size.2`` or ``obstacles.3.name``
        for a duplicate name.
    """
    if not isinstance(items, Sequence) or isinstance(items, str | bytes):
        raise InvalidInputError("must be a list of obstacles", field)
    if len(items) > MAX_OBSTACLES:
        raise InvalidInputError(f"at most {MAX_OBSTACLES} obstacles, got {len(items)}", field)
    out: list[Obstacle] = []
    seen: dict[str, int] = {}
    for i, item in enumerate(items):
        obstacle = parse_obstacle(item, f"{field}.{i}")
        if obstacle.name in seen:
            raise InvalidInputError(
                f"duplicate obstacle name {obstacle.name!r} (also {field}.{seen[obstacle.name]})",
                f"{field}.{i}.name",
            )
        seen[obstacle.name] = i
        out.append(obstacle)
    return tuple(out)
