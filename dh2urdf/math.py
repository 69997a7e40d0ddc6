"""Reference Denavit–Hartenberg matrices and rigid-transform helpers (pure NumPy).

Everything here is the *reference* the generated URDF is checked against; it does not
depend on yourdfpy or Pinocchio.

Conventions
-----------
* Homogeneous transforms are 4×4 ``numpy.ndarray`` (float64); a transform ``T_a_b`` maps
  coordinates in frame *b* to coordinates in frame *a*.
* Lengths in metres, angles in radians (a :class:`~dh2urdf.table.DHTable` is already SI).
* ``rpy`` is the URDF convention: ``R = Rz(yaw) · Ry(pitch) · Rx(roll)`` for
  ``rpy = (roll, pitch, yaw)`` (fixed axes x, y, z).
* Standard (distal) DH: ``A_i = Rz(θ_i) · Tz(d_i) · Tx(a_i) · Rx(α_i)``.
* Modified (proximal, Craig) DH: ``A_i = Rx(α_{i-1}) · Tx(a_{i-1}) · Rz(θ_i) · Tz(d_i)``;
  a table row holds ``a_{i-1}, α_{i-1}, d_i, θ_i``.
* Chain: ``T_world_tool = B · A_1 ⋯ A_n · T_tool``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from dh2urdf.table import DHJoint, DHTable

__all__ = [
    "rot_x",
    "rot_y",
    "rot_z",
    "translation",
    "rpy_to_rotation",
    "xyz_rpy_to_matrix",
    "rotation_to_rpy",
    "dh_standard",
    "dh_modified",
    "joint_dh_parameters",
    "joint_transform",
    "chain",
    "tool_pose",
]


def rot_x(angle: float) -> np.ndarray:
    """Homogeneous rotation about x by ``angle`` (rad)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array(
        [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
    )


def rot_y(angle: float) -> np.ndarray:
    """Homogeneous rotation about y by ``angle`` (rad)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array(
        [[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]]
    )


def rot_z(angle: float) -> np.ndarray:
    """Homogeneous rotation about z by ``angle`` (rad)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array(
        [[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
    )


def translation(x: float, y: float, z: float) -> np.ndarray:
    """Homogeneous translation by ``(x, y, z)`` (m)."""
    t = np.eye(4)
    t[:3, 3] = (x, y, z)
    return t


def rpy_to_rotation(rpy: Sequence[float]) -> np.ndarray:
    """3×3 rotation ``Rz(yaw) · Ry(pitch) · Rx(roll)`` for ``rpy = (roll, pitch, yaw)`` (rad)."""
    roll, pitch, yaw = (float(v) for v in rpy)
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def xyz_rpy_to_matrix(xyz: Sequence[float], rpy: Sequence[float]) -> np.ndarray:
    """4×4 transform of a URDF ``<origin xyz rpy>``: ``T(xyz) · R(rpy)`` (m, rad)."""
    t = np.eye(4)
    t[:3, :3] = rpy_to_rotation(rpy)
    t[:3, 3] = [float(v) for v in xyz]
    return t


def rotation_to_rpy(rotation: np.ndarray) -> tuple[float, float, float]:
    """URDF ``(roll, pitch, yaw)`` (rad) of a rotation matrix, robust at gimbal lock.

    The angles are extracted one at a time, each from the residual rotation left after
    removing the ones found so far (yaw, then pitch, then roll). The product
    ``Rz(yaw) · Ry(pitch) · Rx(roll)`` therefore reproduces the input to a few ulps even
    at or near ``pitch = ±π/2``, where the individual angles are ill-conditioned and the
    textbook formulas lose accuracy. At exact gimbal lock yaw is 0.

    Parameters
    ----------
    rotation : numpy.ndarray
        3×3 rotation matrix (a 4×4 transform is accepted; its rotation block is used).

    Returns
    -------
    tuple of float
        ``(roll, pitch, yaw)`` with ``pitch`` in [−π/2, π/2] and the others in (−π, π].
    """
    r = np.asarray(rotation, dtype=float)[:3, :3]
    yaw = math.atan2(r[1, 0], r[0, 0])
    # M = Rz(yaw)^T · R = Ry(pitch) · Rx(roll)
    m = rot_z(-yaw)[:3, :3] @ r
    pitch = math.atan2(-m[2, 0], m[0, 0])
    # N = Ry(pitch)^T · M = Rx(roll)
    n = rot_y(-pitch)[:3, :3] @ m
    roll = math.atan2(n[2, 1], n[1, 1])
    return (roll + 0.0, pitch + 0.0, yaw + 0.0)


def dh_standard(a: float, alpha: float, d: float, theta: float) -> np.ndarray:
    """Standard (distal) DH matrix ``A_i = Rz(θ) · Tz(d) · Tx(a) · Rx(α)``.

    Parameters
    ----------
    a, d : float
        Link length along x_i and link offset along z_{i-1} (m).
    alpha, theta : float
        Link twist about x_i and joint angle about z_{i-1} (rad), *including* the joint
        variable (θ = q + θ_offset for a revolute joint, d = q + d_offset for a prismatic one).

    Returns
    -------
    numpy.ndarray
        4×4 transform from frame i to frame i−1.
    """
    ct, st = math.cos(theta), math.sin(theta)
    ca, sa = math.cos(alpha), math.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0.0, sa, ca, d],
            [0.0, 0.0, 0.0, 1.0],
        ]
    )


def dh_modified(a: float, alpha: float, d: float, theta: float) -> np.ndarray:
    """Modified (proximal, Craig) DH matrix ``A_i = Rx(α_{i-1}) · Tx(a_{i-1}) · Rz(θ_i) · Tz(d_i)``.

    Parameters
    ----------
    a, alpha : float
        ``a_{i-1}`` (m) along x_{i-1} and ``α_{i-1}`` (rad) about x_{i-1}, as held by row i.
    d, theta : float
        ``d_i`` (m) along z_i and ``θ_i`` (rad) about z_i, including the joint variable.

    Returns
    -------
    numpy.ndarray
        4×4 transform from frame i to frame i−1.
    """
    ct, st = math.cos(theta), math.sin(theta)
    ca, sa = math.cos(alpha), math.sin(alpha)
    return np.array(
        [
            [ct, -st, 0.0, a],
            [st * ca, ct * ca, -sa, -sa * d],
            [st * sa, ct * sa, ca, ca * d],
            [0.0, 0.0, 0.0, 1.0],
        ]
    )


def joint_dh_parameters(joint: DHJoint, q: float) -> tuple[float, float, float, float]:
    """``(a, alpha, d, theta)`` of a row at joint value ``q`` (SI).

    Revolute and continuous joints: ``θ = q + theta``; prismatic joints: ``d = q + d``.
    """
    if joint.type == "prismatic":
        return joint.a, joint.alpha, q + joint.d, joint.theta
    return joint.a, joint.alpha, joint.d, q + joint.theta


def joint_transform(joint: DHJoint, q: float, convention: str) -> np.ndarray:
    """``A_i`` of one row at joint value ``q`` (rad or m) in the given convention."""
    params = joint_dh_parameters(joint, q)
    if convention == "standard":
        return dh_standard(*params)
    if convention == "modified":
        return dh_modified(*params)
    raise ValueError(f"unknown DH convention {convention!r}")


def chain(table: DHTable, q: Sequence[float]) -> list[np.ndarray]:
    """World poses of every DH frame and of the tool at configuration ``q``.

    Parameters
    ----------
    table : DHTable
        The (SI) table.
    q : sequence of float
        One value per row, in row order: the joint angle (rad) without the θ offset for
        revolute/continuous joints, the displacement (m) without the d offset for
        prismatic joints.

    Returns
    -------
    list of numpy.ndarray
        ``n + 2`` 4×4 transforms in the world (root) frame: ``dh_0 = B``,
        ``dh_i = B · A_1 ⋯ A_i`` for i = 1..n, and last ``tool = dh_n · T_tool``.
    """
    values = [float(v) for v in q]
    if len(values) != len(table.joints):
        raise ValueError(f"expected {len(table.joints)} joint values, got {len(values)}")
    t = table.base.matrix()
    frames = [t]
    for joint, value in zip(table.joints, values, strict=True):
        t = t @ joint_transform(joint, value, table.convention)
        frames.append(t)
    frames.append(t @ table.tool.matrix())
    return frames


def tool_pose(table: DHTable, q: Sequence[float]) -> np.ndarray:
    """World pose of the tool (TCP), ``B · A_1 ⋯ A_n · T_tool`` (4×4)."""
    return chain(table, q)[-1]
