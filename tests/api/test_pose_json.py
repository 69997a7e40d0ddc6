"""The wire form of a pose (``pose_json``): its scalar quaternion and rpy conversions agree
with the vectorised ones and reconstruct the rotation, edge cases included."""

from __future__ import annotations

import numpy as np
import pytest

from app.api.schemas.poses import pose_json
from app.kinematics.rotations import (
    matrix_to_quaternion,
    matrix_to_rpy,
    quaternion_to_matrix,
    rpy_to_matrix,
)


def _rotations() -> list[np.ndarray]:
    rng = np.random.default_rng(7)
    q = rng.normal(size=(300, 4))
    out = list(quaternion_to_matrix(q))
    for axis in np.eye(3):  # 180° about each axis: w = 0, the other Shepperd branches
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        out.append(np.eye(3) + 2 * K @ K)
    out.append(np.eye(3))
    out += list(rpy_to_matrix([[0.3, np.pi / 2, -1.0], [0.2, -np.pi / 2, 2.0]]))  # gimbal lock
    return out


@pytest.mark.parametrize("R", _rotations())
def test_pose_json_matches_the_vectorised_conversions(R) -> None:
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, [0.1, -0.2, 0.3]
    pose = pose_json(T)
    assert pose["position"] == [0.1, -0.2, 0.3]
    assert pose["matrix"] == T.tolist()
    quat, rpy = np.array(pose["orientation"]), np.array(pose["rpy"])
    np.testing.assert_allclose(quat, matrix_to_quaternion(R), atol=1e-15)
    np.testing.assert_allclose(rpy, matrix_to_rpy(R), atol=1e-15)
    assert quat[3] >= 0 and abs(np.linalg.norm(quat) - 1) < 1e-15
    np.testing.assert_allclose(quaternion_to_matrix(quat), R, atol=1e-14)
    np.testing.assert_allclose(rpy_to_matrix(rpy), R, atol=1e-14)


def test_pose_json_is_plain_json_types() -> None:
    pose = pose_json(np.eye(4))
    for value in pose.values():
        assert isinstance(value, list)
    assert all(type(v) is float for v in pose["orientation"] + pose["rpy"] + pose["position"])
