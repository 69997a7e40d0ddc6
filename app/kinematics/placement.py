"""A pose given on the wire → a validated placement: the one conversion of every endpoint.

A pose (IK targets, path waypoints, reachability query poses, obstacle poses, the stream's
ik messages) may give its placement redundantly, as the pose every answer returns does:

- ``position`` [x, y, z] (m) in the robot's root (world) frame;
- ``orientation``, a quaternion [x, y, z, w] (normalised if its norm is within
  :data:`~app.kinematics.rotations.QUATERNION_NORM_TOLERANCE` of 1; q and −q are the same
  rotation);
- ``rpy`` [roll, pitch, yaw] (rad), R = Rz(yaw)·Ry(pitch)·Rx(roll) (the URDF convention);
- ``matrix``, the 4×4 homogeneous transform root ← frame (a rigid transform: orthonormal
  rotation within :data:`MATRIX_TOL`, determinant +1, last row [0, 0, 0, 1]).

Every component given must agree with the others within :data:`AGREEMENT_TOL` (position in
m, rotation as the angle between the rotation matrices in rad), else
:class:`~app.kinematics.errors.InvalidInputError` names the fields. What an endpoint needs
(a position, a rotation) it says with ``need_position`` / ``need_rotation``; a missing one is
an error naming ``<field>.position`` or ``<field>.orientation``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.models import MAX_POSITION, check_bounded
from app.kinematics.rotations import (
    QUATERNION_NORM_TOLERANCE,
    matrix_to_quaternion,
    quaternion_entries,
    quaternion_norm,
    quaternion_to_matrix,
    rpy_to_matrix,
    unit_quaternion,
)

#: Largest disagreement between redundant components of one pose: metres for positions,
#: radians for the angle between two rotations.
AGREEMENT_TOL = 1e-9
#: Largest deviation of RᵀR from I (and of the bottom row from [0 0 0 1]) accepted in a matrix.
MATRIX_TOL = 1e-6


@dataclass(frozen=True, slots=True)
class Placement:
    """A validated pose; ``None`` where the wire gave no such component.

    Attributes
    ----------
    translation
        (3,) position in the root frame (m), from ``position`` or the matrix.
    rotation
        (3, 3) rotation root ← frame, from ``orientation``, ``rpy`` or the matrix (the
        matrix's projected onto the nearest rotation).
    quaternion
        (4,) the given ``orientation`` normalised ([x, y, z, w], sign as given), else the
        ``rotation``'s; ``None`` without a rotation.
    """

    translation: np.ndarray | None
    rotation: np.ndarray | None
    quaternion: np.ndarray | None

    def se3(self, default: pin.SE3 | None = None) -> pin.SE3:
        """The placement as a Pinocchio SE3; missing parts from ``default`` (the identity)."""
        base = pin.SE3.Identity() if default is None else default
        R = base.rotation if self.rotation is None else self.rotation
        p = base.translation if self.translation is None else self.translation
        return pin.SE3(R, p)


def rotation_angle(A: np.ndarray, B: np.ndarray) -> float:
    """The angle (rad) of the rotation between two rotation matrices, accurate near 0
    (from ‖A − B‖_F = 2√2·sin(θ/2))."""
    d = float(np.linalg.norm(A - B)) / (2.0 * math.sqrt(2.0))
    return 2.0 * math.asin(min(d, 1.0))


def _rigid(matrix: Sequence[Sequence[float]], field: str) -> tuple[np.ndarray, np.ndarray]:
    """(rotation, translation) of a 4×4 rigid transform (the rotation projected onto the
    nearest rotation, removing rounding), or the error naming ``field``."""
    M = np.array(matrix, dtype=float)
    if M.shape != (4, 4):
        raise InvalidInputError("must be a 4×4 matrix", field)
    if np.abs(M[3] - np.array([0.0, 0.0, 0.0, 1.0])).max() > MATRIX_TOL:
        raise InvalidInputError("the last row must be [0, 0, 0, 1]", field)
    R = M[:3, :3]
    if np.abs(R.T @ R - np.eye(3)).max() > MATRIX_TOL or np.linalg.det(R) <= 0.0:
        raise InvalidInputError("the rotation part must be orthonormal with determinant +1", field)
    for i in range(3):  # the translation column: target.matrix.<row>.3
        check_bounded(M[i, 3], f"{field}.{i}.3", MAX_POSITION, "m")
    U, _, Vt = np.linalg.svd(R)
    return U @ Vt, M[:3, 3].copy()


def _disagree(a: str, b: str, by: float, unit: str) -> InvalidInputError:
    return InvalidInputError(
        f"{a} and {b} disagree by {by:.2g} {unit} (redundant components of a pose must agree "
        f"within {AGREEMENT_TOL:g} {unit})",
        b,
    )


def placement(
    position: Sequence[float] | None,
    orientation: Sequence[float] | None,
    rpy: Sequence[float] | None,
    matrix: Sequence[Sequence[float]] | None,
    field: str,
    *,
    need_position: bool = False,
    need_rotation: bool = False,
    need: str = "",
) -> Placement:
    """Validate a wire pose (see the module docstring) into a :class:`Placement`.

    Parameters
    ----------
    position, orientation, rpy, matrix
        The pose's components (``None``: not given).
    field
        The wire name of the pose (``target``, ``targets.3``, ``obstacles.0.pose``): errors
        name ``<field>.position``, ``<field>.matrix`` …
    need_position, need_rotation
        Whether the endpoint needs a position (``position`` or ``matrix``) or a rotation
        (``orientation``, ``rpy`` or ``matrix``).
    need
        Why, for the error message (e.g. ``"for mode 'pose'"``).

    Raises
    ------
    InvalidInputError
        A bad quaternion norm, a non-rigid matrix, a position beyond ±MAX_POSITION,
        redundant components that disagree, or a needed component missing.
    """
    p = None if position is None else np.array(position, dtype=float)
    if p is not None:
        check_bounded(p, f"{field}.position", MAX_POSITION, "m")
    quat = R = None
    if orientation is not None:
        quat = unit_quaternion(orientation, f"{field}.orientation")
        R = quaternion_to_matrix(quat)
    if rpy is not None:
        R_rpy = rpy_to_matrix(np.array(rpy, dtype=float))
        if R is not None and (angle := rotation_angle(R, R_rpy)) > AGREEMENT_TOL:
            raise _disagree(f"{field}.orientation", f"{field}.rpy", angle, "rad")
        R = R_rpy if R is None else R
    if matrix is not None:
        R_m, p_m = _rigid(matrix, f"{field}.matrix")
        if p is not None and (dist := float(np.abs(p - p_m).max())) > AGREEMENT_TOL:
            raise _disagree(f"{field}.position", f"{field}.matrix", dist, "m")
        if R is not None and (angle := rotation_angle(R, R_m)) > AGREEMENT_TOL:
            other = f"{field}.orientation" if orientation is not None else f"{field}.rpy"
            raise _disagree(other, f"{field}.matrix", angle, "rad")
        p = p_m if p is None else p
        R = R_m if R is None else R
    if need_position and p is None:
        raise InvalidInputError(f"required{' ' + need if need else ''}", f"{field}.position")
    if need_rotation and R is None:
        raise InvalidInputError(
            f"required{' ' + need if need else ''} (or give rpy or matrix)",
            f"{field}.orientation",
        )
    if quat is None and R is not None:
        quat = matrix_to_quaternion(R)
    return Placement(p, R, quat)


def pose_se3(pose: Sequence[float], field: str) -> pin.SE3:
    """A position and a quaternion, ``[x, y, z, qx, qy, qz, qw]`` (m; [x, y, z, w]) in the
    root frame → their placement as a Pinocchio SE3: bit for bit
    ``placement(pose[:3], pose[3:], None, None, field).se3()``, with its errors (it raises
    them: a position not finite or beyond ±MAX_POSITION names ``<field>.position.<i>``, a
    quaternion norm off 1 by more than the tolerance ``<field>.orientation``).

    The stream's binary IK frames' conversion, one per frame: the same checks and formulas
    (the quaternion normalised, then :func:`~app.kinematics.rotations.quaternion_entries`,
    which normalises again, as :func:`placement` does) in Python floats, and one 4×4 array
    for the SE3, instead of a NumPy array per component and the :class:`Placement`
    (13.1 → 6.8 µs warm; docs/benchmarks.md)."""
    x, y, z, qx, qy, qz, qw = pose
    n = quaternion_norm(qx, qy, qz, qw)
    if not (
        abs(x) <= MAX_POSITION  # NaN compares false: it goes to the report below
        and abs(y) <= MAX_POSITION
        and abs(z) <= MAX_POSITION
        and abs(n - 1.0) <= QUATERNION_NORM_TOLERANCE
    ):
        return placement(pose[:3], pose[3:], None, None, field).se3()  # raises the error
    r = quaternion_entries(qx / n, qy / n, qz / n, qw / n)
    H = np.array((*r[0:3], x, *r[3:6], y, *r[6:9], z, 0.0, 0.0, 0.0, 1.0)).reshape(4, 4)
    return pin.SE3(H)
