"""The wire form of a placement: the ``Pose`` model and the conversion of a 4×4 transform."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from pydantic import ConfigDict, Field

from app.api.schemas.common import Matrix4, Position3, Quat, Schema, Vec3
from app.kinematics.placement import Placement, placement


def _no_null_defaults(schema: dict[str, Any]) -> None:
    """Drop ``default: null`` from the properties (pydantic writes it in validation mode,
    FastAPI leaves it out): one ``Pose`` component, whichever way it is generated."""
    for prop in schema.get("properties", {}).values():
        if "default" in prop and prop["default"] is None:
            del prop["default"]


class Pose(Schema):
    """A frame's placement in the robot's root (world) frame, the same shape in and out.

    Answers fill all four fields. A request may give any subset that states what its
    endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
    ``orientation``: a rotation; reachability queries: a position, the rotation optional;
    obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
    request is a 422 naming them. An answer's pose can be sent back as is."""

    # Absent fields are None, but null is not a value (the schema has no null, no default).
    model_config = ConfigDict(json_schema_extra=_no_null_defaults)

    position: Position3 = Field(
        None,
        description="[x, y, z] in metres. A position is given by `position` or `matrix`.",
    )
    orientation: Quat = Field(
        None,
        description="Quaternion [x, y, z, w] (answers: unit, w ≥ 0); normalised if |q| is "
        "within 1e-3 of 1; q and −q are the same rotation. A rotation is given by "
        "`orientation`, `rpy` or `matrix`.",
    )
    rpy: Vec3 = Field(
        None, description="[roll, pitch, yaw] in rad, R = Rz(yaw)·Ry(pitch)·Rx(roll)."
    )
    matrix: Matrix4 = Field(
        None,
        description="4×4 homogeneous transform root ← frame (metres): a rigid transform "
        "(orthonormal rotation within 1e-6, determinant +1, last row [0, 0, 0, 1]).",
    )

    def placement(
        self,
        field: str,
        *,
        need_position: bool = False,
        need_rotation: bool = False,
        need: str = "",
    ) -> Placement:
        """The validated placement (:func:`app.kinematics.placement.placement`), errors
        naming ``<field>.position`` etc."""
        return placement(
            self.position,
            self.orientation,
            self.rpy,
            self.matrix,
            field,
            need_position=need_position,
            need_rotation=need_rotation,
            need=need,
        )


def pose_json(T: np.ndarray) -> dict[str, Any]:
    """Wire form of a 4×4 placement.

    One pose at a time, the rotation conversions run on Python floats
    (:func:`quaternion_rpy`): NumPy's per-call overhead made the vectorised ones cost
    ~60 µs here, a third of a single-pose FK request.
    """
    M = T.tolist()
    quat, rpy = quaternion_rpy(M)
    return {
        "position": [M[0][3], M[1][3], M[2][3]],
        "orientation": quat,
        "rpy": rpy,
        "matrix": M,
    }


def quaternion_rpy(M: list[list[float]]) -> tuple[list[float], list[float]]:
    """Quaternion [x, y, z, w] (w ≥ 0) and rpy of the rotation in ``M``'s top-left 3×3.

    The scalar twins of :func:`~app.kinematics.rotations.matrix_to_quaternion` (Shepperd's
    method, same branch choice and normalisation) and
    :func:`~app.kinematics.rotations.matrix_to_rpy` (R = Rz(yaw)·Ry(pitch)·Rx(roll); at the
    gimbal lock roll = 0), for one matrix given as nested lists.
    """
    (m00, m01, m02), (m10, m11, m12), (m20, m21, m22) = (row[:3] for row in M[:3])
    cand = (
        1.0 + m00 + m11 + m22,
        1.0 + m00 - m11 - m22,
        1.0 - m00 + m11 - m22,
        1.0 - m00 - m11 + m22,
    )
    k = max(range(4), key=cand.__getitem__)  # first maximum, like np.argmax
    s = 2.0 * math.sqrt(cand[k])
    if k == 0:
        q = [(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s]
    elif k == 1:
        q = [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s]
    elif k == 2:
        q = [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s]
    else:
        q = [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s]
    norm = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    q = [v / norm for v in q] if q[3] / norm >= 0.0 else [-v / norm for v in q]
    h = math.hypot(m00, m10)
    pitch = math.atan2(-m20, h)
    if h < 1e-12:
        roll, yaw = 0.0, math.atan2(-m01, m11)
    else:
        roll, yaw = math.atan2(m21, m22), math.atan2(m10, m00)
    return q, [roll, pitch, yaw]
