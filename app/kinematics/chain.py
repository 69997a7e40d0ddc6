"""Vectorised serial-chain geometry: pose and world Jacobian of one frame over many samples.

The one implementation used by batch FK (:func:`app.kinematics.fk.forward_kinematics_batch`),
reachability maps (:mod:`app.kinematics.reachability`) and the compiled IK kernels
(:class:`app.kinematics.ik.kernel.CompiledChain` reads its constants).

Each joint of the frame's chain is rewritten in a frame whose z axis is the joint axis
(rot(axis, θ) = A·Rz(θ)·Aᵀ, the constants folded into the fixed placements): joint j applies
its fixed placement (p += R·t_j, R = R·C_j), then its motion about or along z: R = R·Rz(q_j)
(revolute, continuous; θ is the wire angle, no (cos, sin) round trip) or p += q_j·R e_z
(prismatic). After the last joint the frame's own placement (last_C, last_t). Per sample, a
joint's axis is the third column of the running rotation and its origin the running
position, and the geometric Jacobian (reference ``world`` = Pinocchio LOCAL_WORLD_ALIGNED,
root frame, metres and radians) is J_j = [z_j × (p − o_j); z_j] for revolute joints,
[z_j; 0] for prismatic ones. A joint's motion is a rotation of two columns of R or a shift
along its third column: O(N) work with no per-sample matrix products.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.analysis import support_columns
from app.kinematics.models import RobotModel


def _z_to(axis: np.ndarray) -> np.ndarray:
    """A rotation A with A·e_z = axis (unit), so that rot(axis, θ) = A·Rz(θ)·Aᵀ."""
    z = np.array([0.0, 0.0, 1.0])
    c = float(axis @ z)
    if c > 1.0 - 1e-15:
        return np.eye(3)
    if c < -1.0 + 1e-15:
        return np.diag([1.0, -1.0, -1.0])  # rotation by π about x
    v = np.cross(z, axis)
    return pin.exp3(v / np.linalg.norm(v) * math.acos(max(-1.0, min(1.0, c))))


#: Constant coefficients smaller than this are treated as 0 (URDF origins are mostly
#: axis-aligned, so most of a fixed rotation's entries are 0 or ±1 up to rounding).
_ZERO = 1e-15


def _accumulate(P: np.ndarray, t: np.ndarray, M: np.ndarray) -> None:
    """P += Σ_j t_j·M[j] in place (P (3, N), M (3 columns, 3, N)); no BLAS: small products
    would otherwise start OpenBLAS threads that fight the worker processes."""
    for j in range(3):
        c = float(t[j])
        if abs(c) > _ZERO:
            P += c * M[j]


def _rotate_columns(M: np.ndarray, C: np.ndarray) -> np.ndarray:
    """Columns of R·C from the columns of R: new column k = Σ_j C[j, k]·M[j]."""
    out = np.empty_like(M)
    for k in range(3):
        first = True
        for j in range(3):
            c = float(C[j, k])
            if abs(c) <= _ZERO:
                continue
            if first:
                np.multiply(M[j], c, out=out[k])
                first = False
            else:
                out[k] += c * M[j]
        if first:
            out[k] = 0.0
    return out


@dataclass(frozen=True)
class ChainStep:
    """One joint: a constant transform into its z-aligned frame, then motion along/about z."""

    C: np.ndarray  # rotation: previous z-aligned frame → this joint's z-aligned frame
    t: np.ndarray  # translation in the previous z-aligned frame
    col: int  # column of the sample matrix (position in the chain)
    prismatic: bool


class SerialChain:
    """Vectorised pose and world Jacobian of one frame over many samples of its chain.

    Samples hold one column per chain joint (``self.wire`` gives their wire indices).
    :meth:`build` returns ``None`` unless every joint of the chain is a 1-DoF revolute,
    continuous or prismatic wire joint (no mimic, no multi-DoF joints); callers then fall
    back to Pinocchio (:class:`PinocchioChain`).
    """

    def __init__(self, steps: list[ChainStep], last_C: np.ndarray, last_t: np.ndarray, wire):
        self.steps = steps
        self.last_C = last_C
        self.last_t = last_t
        self.wire = np.asarray(wire, dtype=int)

    @classmethod
    def build(cls, robot: RobotModel, frame: str) -> SerialChain | None:
        model = robot.model
        f = model.frames[robot.frame_id(frame)]
        by_pin = {j.pin_id: j for j in robot.joints}
        steps: list[ChainStep] = []
        wire: list[int] = []
        prev_At = np.eye(3)  # Aᵀ of the previous joint: its real frame → its z-aligned frame
        for jid in list(model.supports[f.parentJoint])[1:]:
            joint = by_pin.get(jid)
            if joint is None or model.joints[jid].nv != 1:
                return None  # mimic or multi-DoF joint: not handled here
            axis = np.asarray(joint.axis, dtype=float)
            A = _z_to(axis / np.linalg.norm(axis))
            M = model.jointPlacements[jid]
            steps.append(
                ChainStep(prev_At @ M.rotation @ A, prev_At @ M.translation, len(wire),
                          joint.type == "prismatic")
            )  # fmt: skip
            wire.append(joint.index)
            prev_At = A.T
        return cls(steps, prev_At @ f.placement.rotation, prev_At @ f.placement.translation, wire)

    def evaluate(
        self, Q: np.ndarray, jacobian: bool = True
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """Component-major results for samples Q (N, k), one column per chain joint:
        rotations Rt (3, 3, N) with Rt[i, j] = R_ij, positions (3, N) (m, root frame), world
        Jacobians (6, k, N) (``None`` when ``jacobian`` is false). Every operation is
        elementwise over N."""
        n = Q.shape[0]
        k = len(self.steps)
        M = np.zeros((3, 3, n))  # M[j] = column j of R (3, N)
        M[0, 0] = M[1, 1] = M[2, 2] = 1.0
        P = np.zeros((3, n))
        J = np.zeros((6, k, n)) if jacobian else None
        origins = np.empty((k, 3, n)) if jacobian else None
        QT = np.ascontiguousarray(Q.T)
        cs = np.cos(QT)
        sn = np.sin(QT)
        for j, s in enumerate(self.steps):
            _accumulate(P, s.t, M)
            M = _rotate_columns(M, s.C)
            if J is not None:
                J[3:, j] = M[2]
                origins[j] = P
            if s.prismatic:
                P += QT[s.col] * M[2]
            else:
                c, si = cs[s.col], sn[s.col]
                x = M[0].copy()
                M[0] *= c
                M[0] += si * M[1]
                M[1] *= c
                M[1] -= si * x
        _accumulate(P, self.last_t, M)
        M = _rotate_columns(M, self.last_C)
        if J is not None:
            for j, s in enumerate(self.steps):
                z = J[3:, j]
                if s.prismatic:
                    J[:3, j] = z
                    J[3:, j] = 0.0
                else:
                    d = P - origins[j]
                    J[0, j] = z[1] * d[2] - z[2] * d[1]
                    J[1, j] = z[2] * d[0] - z[0] * d[2]
                    J[2, j] = z[0] * d[1] - z[1] * d[0]
        return M.transpose(1, 0, 2), P, J

    def pose(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rotations (N, 3, 3) and positions (N, 3) of the frame for samples Q (N, k)."""
        Rt, P, _ = self.evaluate(Q, jacobian=False)
        return Rt.transpose(2, 0, 1), P.T

    def __call__(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rotations (N, 3, 3), positions (N, 3) and world Jacobians (N, 6, k)."""
        Rt, P, J = self.evaluate(Q)
        return Rt.transpose(2, 0, 1), P.T, J.transpose(2, 0, 1)


class PinocchioChain:
    """The same interface as :class:`SerialChain`, computed by Pinocchio per sample."""

    def __init__(self, robot: RobotModel, frame: str, wire: np.ndarray) -> None:
        self.robot = robot
        self.fid = robot.frame_id(frame)
        self.wire = np.asarray(wire, dtype=int)

    def __call__(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        robot = self.robot
        model, data = robot.model, robot.data
        n = Q.shape[0]
        full = np.tile(robot.neutral(), (n, 1))
        full[:, self.wire] = Q
        qp = robot.to_pin_batch(full)
        R = np.empty((n, 3, 3))
        p = np.empty((n, 3))
        J = np.empty((n, 6, self.wire.size))
        for i in range(n):
            Ji = pin.computeFrameJacobian(model, data, qp[i], self.fid, pin.LOCAL_WORLD_ALIGNED)
            M = data.oMf[self.fid]
            R[i], p[i] = M.rotation, M.translation
            # (6,) from Pinocchio when nv == 1 (one joint and its mimic followers)
            J[i] = Ji.reshape(6, -1)[:, robot.v_index[self.wire]]
        return R, p, J

    def evaluate(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Component-major form of :meth:`__call__` (as :meth:`SerialChain.evaluate`)."""
        R, p, J = self(Q)
        return R.transpose(1, 2, 0), p.T, J.transpose(1, 2, 0)


def chain_for(robot: RobotModel, frame: str) -> SerialChain | PinocchioChain:
    """The vectorised chain of ``frame`` when its joints allow, else the Pinocchio loop."""
    chain = SerialChain.build(robot, frame)
    if chain is not None:
        return chain
    return PinocchioChain(robot, frame, support_columns(robot, frame))
