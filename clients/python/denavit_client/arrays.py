"""NumPy arrays in and out of the generated models (hand-written, never generated).

The generated models carry JSON lists; these helpers turn NumPy arrays into the lists a
request takes and answers into arrays. Conventions are the service's: lengths in metres,
angles in radians, quaternions ``[x, y, z, w]``, poses in the robot's root frame,
configurations in joint order.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray


class PoseLike(Protocol):
    """Anything with the pose fields of the service's pose (an FK answer's pose, a target)."""

    @property
    def position(self) -> object: ...

    @property
    def orientation(self) -> object: ...


def q_list(q: ArrayLike) -> list[float]:
    """A configuration (one value per joint, rad or m) as the list a request takes.

    Raises
    ------
    ValueError
        When ``q`` is not one-dimensional or holds a value that is not finite.
    """
    arr = np.asarray(q, dtype=np.float64)
    if arr.ndim != 1 or not np.all(np.isfinite(arr)):
        raise ValueError(f"a configuration is a 1-D array of finite numbers, not {arr!r}")
    return [float(v) for v in arr]


def q_lists(qs: ArrayLike) -> list[list[float]]:
    """Configurations (an m×n array: m configurations of n joints) as a batch request's lists."""
    arr = np.asarray(qs, dtype=np.float64)
    if arr.ndim != 2:
        raise ValueError(f"configurations are an m×n array, not shape {arr.shape}")
    return [q_list(row) for row in arr]


def array(values: object) -> NDArray[np.float64]:
    """An answer's numbers (a configuration, a Jacobian, a list of positions) as an array.

    A Jacobian (``JacobianResponse.jacobian``) becomes its 6×n array: linear rows first (m/rad),
    then angular rows, columns in joint order.
    """
    return np.asarray(values, dtype=np.float64)


def quaternion_matrix(quaternion: ArrayLike) -> NDArray[np.float64]:
    """The 3×3 rotation matrix of a unit quaternion ``[x, y, z, w]``."""
    x, y, z, w = np.asarray(quaternion, dtype=np.float64) / np.linalg.norm(quaternion)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def matrix_quaternion(rotation: ArrayLike) -> list[float]:
    """The unit quaternion ``[x, y, z, w]`` (w ≥ 0) of a 3×3 rotation matrix."""
    R = np.asarray(rotation, dtype=np.float64)
    # The largest of 4w², 4x², 4y², 4z² gives the best-conditioned formula.
    t = np.array([np.trace(R), R[0, 0], R[1, 1], R[2, 2]])
    k = int(np.argmax(t))
    if k == 0:
        s = 2.0 * np.sqrt(1.0 + t[0])
        q = [(R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s, s / 4]
    elif k == 1:
        s = 2.0 * np.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2])
        q = [s / 4, (R[0, 1] + R[1, 0]) / s, (R[0, 2] + R[2, 0]) / s, (R[2, 1] - R[1, 2]) / s]
    elif k == 2:
        s = 2.0 * np.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2])
        q = [(R[0, 1] + R[1, 0]) / s, s / 4, (R[1, 2] + R[2, 1]) / s, (R[0, 2] - R[2, 0]) / s]
    else:
        s = 2.0 * np.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1])
        q = [(R[0, 2] + R[2, 0]) / s, (R[1, 2] + R[2, 1]) / s, s / 4, (R[1, 0] - R[0, 1]) / s]
    quat = np.array(q) / np.linalg.norm(q)
    return [float(v) for v in (-quat if quat[3] < 0 else quat)]


def pose_matrix(pose: PoseLike) -> NDArray[np.float64]:
    """The 4×4 homogeneous transform (root ← frame, metres) of a pose with a position and an
    orientation (an FK answer's pose, for one).

    Raises
    ------
    ValueError
        When the pose has no position or no orientation (a position-only target).
    """
    position, orientation = pose.position, pose.orientation
    if not isinstance(position, list) or not isinstance(orientation, list):
        raise ValueError("the pose needs both a position and an orientation")
    T = np.eye(4)
    T[:3, :3] = quaternion_matrix(orientation)
    T[:3, 3] = position
    return T


def pose_lists(matrix: ArrayLike) -> tuple[list[float], list[float]]:
    """``(position, orientation)`` of a 4×4 homogeneous transform, the fields of a pose in a
    request: ``[x, y, z]`` (m) and the quaternion ``[x, y, z, w]`` (w ≥ 0)."""
    T = np.asarray(matrix, dtype=np.float64)
    if T.shape != (4, 4):
        raise ValueError(f"a pose matrix is 4×4, not {T.shape}")
    return [float(v) for v in T[:3, 3]], matrix_quaternion(T[:3, :3])
