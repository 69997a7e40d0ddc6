"""Rotation conventions of the wire, vectorised.

- Quaternions are [x, y, z, w] (ROS, Eigen ``coeffs()``, SciPy), normalised, with w ≥ 0 so
  that each rotation has exactly one representation.
- RPY is [roll, pitch, yaw] with R = Rz(yaw)·Ry(pitch)·Rx(roll) (the URDF convention).
"""

from __future__ import annotations

import math

import numpy as np

from app.kinematics.errors import InvalidInputError

#: Largest accepted | ‖q‖ − 1 | of a quaternion given on the wire; within it the quaternion
#: is normalised, beyond it the request is refused (one value for every endpoint).
QUATERNION_NORM_TOLERANCE = 1e-3


def unit_quaternions(quats: np.ndarray, field: str, index: np.ndarray | None = None) -> np.ndarray:
    """Quaternions (N, 4) [x, y, z, w] → normalised copies, or the one error for a bad norm.

    Parameters
    ----------
    quats
        Finite quaternions, one per row.
    field
        The field of row i as ``field.format(i)`` (i = the row, or ``index[row]``).

    Raises
    ------
    InvalidInputError
        For the first row whose norm is off 1 by more than
        :data:`QUATERNION_NORM_TOLERANCE` (including a norm that overflows to inf).
    """
    quats = np.asarray(quats, dtype=float).reshape(-1, 4)
    with np.errstate(over="ignore"):  # a huge component: norm inf, reported below
        norms = np.linalg.norm(quats, axis=1)
    bad = np.flatnonzero(~(np.abs(norms - 1.0) <= QUATERNION_NORM_TOLERANCE))
    if bad.size:
        i = int(bad[0] if index is None else index[bad[0]])
        raise InvalidInputError(_norm_reason(float(norms[bad[0]])), field.format(i))
    return quats / norms[:, None]


def unit_quaternion(quat: np.ndarray | list[float], field: str) -> np.ndarray:
    """One quaternion [x, y, z, w] → its normalised copy (4,); see :func:`unit_quaternions`.

    Scalar arithmetic (a single IK target is on the request's hot path: NumPy's per-call
    overhead was ~20 µs here), bit for bit the vectorised result.
    """
    arr = np.asarray(quat, dtype=float)
    if arr.shape != (4,):
        return unit_quaternions(arr, field)[0]
    x, y, z, w = arr.tolist()
    norm = quaternion_norm(x, y, z, w)
    if not abs(norm - 1.0) <= QUATERNION_NORM_TOLERANCE:  # NaN fails too
        raise InvalidInputError(_norm_reason(norm), field.format(0))
    return np.array((x / norm, y / norm, z / norm, w / norm))


def _norm_reason(norm: float) -> str:
    return (
        f"must be a unit quaternion [x, y, z, w]: its norm {norm:.6g} is off 1 by more "
        f"than {QUATERNION_NORM_TOLERANCE:g}"
    )


def matrix_to_quaternion(R: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) → unit quaternions (..., 4) as [x, y, z, w], w ≥ 0.

    Uses Shepperd's method: the largest of 1 + trace and the 1 ± 2R_ii − trace terms is
    taken under the square root, so no branch divides by a small number.
    """
    R = np.asarray(R, dtype=float)
    m00, m11, m22 = R[..., 0, 0], R[..., 1, 1], R[..., 2, 2]
    cand = np.stack(
        [
            1.0 + m00 + m11 + m22,
            1.0 + m00 - m11 - m22,
            1.0 - m00 + m11 - m22,
            1.0 - m00 - m11 + m22,
        ],
        axis=-1,
    )
    k = np.argmax(cand, axis=-1)
    s = 2.0 * np.sqrt(np.take_along_axis(cand, k[..., None], axis=-1)[..., 0])
    d21 = R[..., 2, 1] - R[..., 1, 2]
    d02 = R[..., 0, 2] - R[..., 2, 0]
    d10 = R[..., 1, 0] - R[..., 0, 1]
    s01 = R[..., 0, 1] + R[..., 1, 0]
    s02 = R[..., 0, 2] + R[..., 2, 0]
    s12 = R[..., 1, 2] + R[..., 2, 1]
    q = np.empty(R.shape[:-2] + (4,))
    # k == 0: w largest
    w0 = k == 0
    q[w0] = np.stack([d21[w0] / s[w0], d02[w0] / s[w0], d10[w0] / s[w0], 0.25 * s[w0]], -1)
    x0 = k == 1
    q[x0] = np.stack([0.25 * s[x0], s01[x0] / s[x0], s02[x0] / s[x0], d21[x0] / s[x0]], -1)
    y0 = k == 2
    q[y0] = np.stack([s01[y0] / s[y0], 0.25 * s[y0], s12[y0] / s[y0], d02[y0] / s[y0]], -1)
    z0 = k == 3
    q[z0] = np.stack([s02[z0] / s[z0], s12[z0] / s[z0], 0.25 * s[z0], d10[z0] / s[z0]], -1)
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    return np.where(q[..., 3:4] < 0.0, -q, q)


def quaternion_to_matrix(quat: np.ndarray) -> np.ndarray:
    """Quaternions (..., 4) as [x, y, z, w] (normalised here) → rotation matrices (..., 3, 3)."""
    q = np.asarray(quat, dtype=float)
    if q.shape == (4,):  # one quaternion: scalar arithmetic, the same formula
        return _quaternion_to_matrix_one(*q.tolist())
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    x, y, z, w = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    R = np.empty(q.shape[:-1] + (3, 3))
    R[..., 0, 0] = 1 - 2 * (y * y + z * z)
    R[..., 0, 1] = 2 * (x * y - z * w)
    R[..., 0, 2] = 2 * (x * z + y * w)
    R[..., 1, 0] = 2 * (x * y + z * w)
    R[..., 1, 1] = 1 - 2 * (x * x + z * z)
    R[..., 1, 2] = 2 * (y * z - x * w)
    R[..., 2, 0] = 2 * (x * z - y * w)
    R[..., 2, 1] = 2 * (y * z + x * w)
    R[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def quaternion_norm(x: float, y: float, z: float, w: float) -> float:
    """‖(x, y, z, w)‖ summed in NumPy's order for 4 values (bit for bit ``np.linalg.norm``
    along an axis); inf when a square overflows."""
    return math.sqrt(x * x + y * y + z * z + w * w)


def quaternion_entries(x: float, y: float, z: float, w: float) -> tuple[float, ...]:
    """The rotation matrix of the quaternion [x, y, z, w] (normalised here) as its 9 entries,
    row-major: :func:`quaternion_to_matrix`'s formula for one quaternion, in Python floats
    (for callers that build a larger array from them: :func:`.placement.pose_se3`)."""
    n = quaternion_norm(x, y, z, w)
    x, y, z, w = x / n, y / n, z / n, w / n
    return (
        1 - 2 * (y * y + z * z),
        2 * (x * y - z * w),
        2 * (x * z + y * w),
        2 * (x * y + z * w),
        1 - 2 * (x * x + z * z),
        2 * (y * z - x * w),
        2 * (x * z - y * w),
        2 * (y * z + x * w),
        1 - 2 * (x * x + y * y),
    )


def _quaternion_to_matrix_one(x: float, y: float, z: float, w: float) -> np.ndarray:
    return np.array(quaternion_entries(x, y, z, w)).reshape(3, 3)


def matrix_to_rpy(R: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) → [roll, pitch, yaw] with R = Rz(yaw)·Ry(pitch)·Rx(roll).

    Pitch lies in [−π/2, π/2]; at the gimbal lock (|pitch| = π/2) roll is set to 0 and the
    whole rotation about z is given to yaw.
    """
    R = np.asarray(R, dtype=float)
    pitch = np.arctan2(-R[..., 2, 0], np.hypot(R[..., 0, 0], R[..., 1, 0]))
    lock = np.hypot(R[..., 0, 0], R[..., 1, 0]) < 1e-12
    roll = np.where(lock, 0.0, np.arctan2(R[..., 2, 1], R[..., 2, 2]))
    yaw = np.where(
        lock,
        np.arctan2(-R[..., 0, 1], R[..., 1, 1]),
        np.arctan2(R[..., 1, 0], R[..., 0, 0]),
    )
    return np.stack([roll, pitch, yaw], axis=-1)


def rpy_to_matrix(rpy: np.ndarray) -> np.ndarray:
    """[roll, pitch, yaw] (..., 3) → R = Rz(yaw)·Ry(pitch)·Rx(roll) (..., 3, 3)."""
    rpy = np.asarray(rpy, dtype=float)
    cr, sr = np.cos(rpy[..., 0]), np.sin(rpy[..., 0])
    cp, sp = np.cos(rpy[..., 1]), np.sin(rpy[..., 1])
    cy, sy = np.cos(rpy[..., 2]), np.sin(rpy[..., 2])
    R = np.empty(rpy.shape[:-1] + (3, 3))
    R[..., 0, 0] = cy * cp
    R[..., 0, 1] = cy * sp * sr - sy * cr
    R[..., 0, 2] = cy * sp * cr + sy * sr
    R[..., 1, 0] = sy * cp
    R[..., 1, 1] = sy * sp * sr + cy * cr
    R[..., 1, 2] = sy * sp * cr - cy * sr
    R[..., 2, 0] = -sp
    R[..., 2, 1] = cp * sr
    R[..., 2, 2] = cp * cr
    return R
