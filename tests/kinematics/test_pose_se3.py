"""``pose_se3``: a position and a quaternion as 7 floats → the SE3 of the one pose conversion.

References: :func:`app.kinematics.placement.placement` (the conversion every endpoint uses:
the binary stream frames' targets must be bit for bit the JSON targets'), and Pinocchio's own
quaternion → rotation matrix (``pin.Quaternion.toRotationMatrix``, an independent formula)
to rounding.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.errors import InvalidInputError
from app.kinematics.models import MAX_POSITION
from app.kinematics.placement import placement, pose_se3
from app.kinematics.rotations import QUATERNION_NORM_TOLERANCE


def _reference(pose: list[float]) -> pin.SE3:
    return placement(pose[:3], pose[3:], None, None, "target").se3()


def _poses(rng: np.random.Generator, n: int) -> list[list[float]]:
    """Positions of every magnitude up to the bound (±0, the bound itself) and quaternions
    of either sign with norms across the accepted band (its edges included)."""
    out = []
    for k in range(n):
        p = rng.normal(size=3) * 10.0 ** rng.integers(-12, 6, 3)
        if k % 50 == 0:
            p = np.array([MAX_POSITION, -MAX_POSITION, -0.0])
        quat = rng.normal(size=4)
        quat /= np.linalg.norm(quat)
        quat *= 1.0 + rng.uniform(-0.99, 0.99) * QUATERNION_NORM_TOLERANCE
        if k % 7 == 0:
            quat = np.array([0.0, 0.0, 0.0, -1.0 if k % 2 else 1.0])
        out.append([*np.clip(p, -MAX_POSITION, MAX_POSITION).tolist(), *quat.tolist()])
    return out


def test_the_se3_is_the_pose_conversions_bit_for_bit() -> None:
    """2000 random poses: rotation and translation are the general conversion's, bit for bit."""
    rng = np.random.default_rng(29)
    for pose in _poses(rng, 2000):
        got, ref = pose_se3(pose, "target"), _reference(pose)
        assert got.rotation.tobytes() == ref.rotation.tobytes(), pose
        assert got.translation.tobytes() == ref.translation.tobytes(), pose


def test_the_rotation_is_the_quaternions() -> None:
    """Against Pinocchio's quaternion → matrix (the quaternion normalised), to 1e-14."""
    rng = np.random.default_rng(30)
    for pose in _poses(rng, 500):
        x, y, z, w = pose[3:]
        n = math.sqrt(x * x + y * y + z * z + w * w)
        R = pin.Quaternion(w / n, x / n, y / n, z / n).toRotationMatrix()
        T = pose_se3(pose, "target")
        np.testing.assert_allclose(T.rotation, R, rtol=0, atol=1e-14)
        np.testing.assert_array_equal(T.translation, pose[:3])


BAD = [
    [math.nan, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0],
    [0.4, math.inf, 0.3, 0.0, 0.0, 0.0, 1.0],
    [0.4, 0.1, -math.inf, 0.0, 0.0, 0.0, 1.0],
    [0.4, 0.1, MAX_POSITION * (1 + 1e-15), 0.0, 0.0, 0.0, 1.0],
    [-MAX_POSITION * 2, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0],
    [0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0 + 1.01 * QUATERNION_NORM_TOLERANCE],
    [0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 1.0 - 1.01 * QUATERNION_NORM_TOLERANCE],
    [0.4, 0.1, 0.3, 0.0, 0.0, 0.0, 0.0],
    [0.4, 0.1, 0.3, math.nan, 0.0, 0.0, 1.0],
    [0.4, 0.1, 0.3, 0.0, math.inf, 0.0, 1.0],
    [0.4, 0.1, 0.3, 1e200, 1e200, 0.0, 1.0],  # the norm overflows
    [math.nan, 0.1, 0.3, 0.0, 0.0, 0.0, 2.0],  # both: the position is named first
]


@pytest.mark.parametrize("pose", BAD)
def test_a_bad_pose_gets_the_conversions_error(pose: list[float]) -> None:
    """The same error (field and message) as the general conversion."""
    with pytest.raises(InvalidInputError) as ref:
        _reference(pose)
    with pytest.raises(InvalidInputError) as got:
        pose_se3(pose, "target")
    assert (got.value.field, str(got.value)) == (ref.value.field, str(ref.value))
    assert got.value.field.startswith(("target.position.", "target.orientation"))
