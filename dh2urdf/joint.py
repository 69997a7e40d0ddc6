"""A DH table's rows and frames: :class:`DHJoint` (one row, SI), :class:`LinkDynamics` (a
row's optional mass, centre of mass and inertia), :class:`Transform` (a fixed base or tool
frame) and the value sets a table's fields take. The table itself is
:class:`dh2urdf.table.DHTable`; the checks that build these from a document are in
:mod:`dh2urdf.parse`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from dh2urdf.math import xyz_rpy_to_matrix

Convention = Literal["standard", "modified"]
JointType = Literal["revolute", "prismatic", "continuous"]

CONVENTIONS: tuple[str, ...] = ("standard", "modified")
JOINT_TYPES: tuple[str, ...] = ("revolute", "prismatic", "continuous")
#: Radius (m) of the generated capsules when the table has no ``geometry`` section.
DEFAULT_GEOMETRY_RADIUS = 0.02


@dataclass(frozen=True, slots=True)
class Transform:
    """A rigid transform written as a URDF origin: translation ``xyz`` (m) then ``rpy`` (rad).

    The matrix is ``T(xyz) · Rz(yaw) · Ry(pitch) · Rx(roll)`` with ``rpy = (roll, pitch, yaw)``.
    """

    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def is_identity(self) -> bool:
        """Whether both translation and rotation are exactly zero."""
        return all(v == 0.0 for v in self.xyz + self.rpy)

    def matrix(self) -> np.ndarray:
        """The 4×4 homogeneous transform."""
        return xyz_rpy_to_matrix(self.xyz, self.rpy)


@dataclass(frozen=True, slots=True)
class LinkDynamics:
    """The rigid body that row i moves (link i), in the DH frame at the END of the row.

    That frame is frame i of the chain (world pose ``B·A_1⋯A_i``, the URDF link ``dh_i``),
    the frame the Robotics Toolbox's and Corke's ``r`` and ``I`` are given in, in both
    conventions.

    Attributes
    ----------
    mass : float
        Mass (kg), ≥ 0.
    com : tuple of float
        Centre of mass (m) in frame i.
    inertia : tuple of float
        Rotational inertia about the centre of mass, in frame i's axes (kg·m²), as the six
        URDF entries ``(ixx, ixy, ixz, iyy, iyz, izz)``; all zero for a point mass.
    """

    mass: float
    com: tuple[float, float, float] = (0.0, 0.0, 0.0)
    inertia: tuple[float, float, float, float, float, float] = (0.0,) * 6

    def inertia_matrix(self) -> np.ndarray:
        """The 3×3 symmetric rotational inertia (kg·m², about the com, frame i's axes)."""
        ixx, ixy, ixz, iyy, iyz, izz = self.inertia
        return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])


@dataclass(frozen=True, slots=True)
class DHJoint:
    """One row of a DH table, in SI units (m, rad).

    Attributes
    ----------
    name : str
        Joint name (unique in the table).
    type : {"revolute", "prismatic", "continuous"}
        Joint kind. Revolute and continuous joints turn about their DH z axis, prismatic
        joints slide along it.
    a, alpha, d, theta : float
        DH parameters (m, rad, m, rad). ``theta`` is the constant offset of a revolute joint
        (θ = q + theta), ``d`` the constant offset of a prismatic joint (d = q + d). In the
        modified convention ``a`` and ``alpha`` are ``a_{i-1}`` and ``α_{i-1}``.
    lower, upper : float or None
        Position limits of the joint variable q (rad or m); ``None`` for continuous joints.
    velocity : float
        Velocity limit (rad/s or m/s).
    effort : float
        Effort limit (N·m or N).
    dynamics : LinkDynamics or None
        The mass, centre of mass and inertia of the link the row moves; ``None`` when the
        row gives none (the URDF link then has no ``<inertial>``).
    """

    name: str
    type: JointType
    a: float
    alpha: float
    d: float
    theta: float
    lower: float | None
    upper: float | None
    velocity: float
    effort: float
    dynamics: LinkDynamics | None = None

    @property
    def is_prismatic(self) -> bool:
        """Whether the joint slides (its variable is a length)."""
        return self.type == "prismatic"
