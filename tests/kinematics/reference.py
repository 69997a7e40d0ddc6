"""Independent references for kinematics tests: yourdfpy poses (not Pinocchio's), the pose
error between two placements, random configurations within the joint limits."""

from __future__ import annotations

import io
import math

import numpy as np
import pinocchio as pin
import yourdfpy

from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel

#: Position (m) and angle (rad) tolerance of an IK solution checked against a reference.
TOL = 1e-5


def _urdf(robot: RobotModel) -> yourdfpy.URDF:
    return robot.lazy(
        LazyKey("test.yourdfpy", yourdfpy.URDF),
        lambda r: yourdfpy.URDF.load(
            io.BytesIO(r.urdf_text.encode()),
            load_meshes=False,
            build_collision_scene_graph=False,
            load_collision_meshes=False,
        ),
    )


def reference_pose(robot: RobotModel, q: np.ndarray, frame: str) -> np.ndarray:
    """World pose of a link by yourdfpy (independent of Pinocchio)."""
    urdf = _urdf(robot)
    urdf.update_cfg(q)
    return urdf.get_transform(frame, urdf.base_link)


def reference_velocity_limits(robot: RobotModel, joints: list[str]) -> np.ndarray:
    """The URDF ``<limit velocity>`` of each joint of ``joints`` by yourdfpy (rad/s, m/s)."""
    urdf = _urdf(robot)
    return np.array([urdf.joint_map[name].limit.velocity for name in joints])


def _chain(robot: RobotModel, frame: str) -> list[tuple[object, int | None]]:
    """The yourdfpy joints from the base link to link ``frame``, each with its index in the
    wire configuration (None: not actuated)."""
    urdf = _urdf(robot)
    by_child = {j.child: j for j in urdf.robot.joints}
    names = urdf.actuated_joint_names
    out, link = [], frame
    while link in by_child:
        j = by_child[link]
        if j.mimic is not None:
            raise NotImplementedError("mimic joints: use reference_pose")
        out.append((j, names.index(j.name) if j.name in names else None))
        link = j.parent
    return out[::-1]


def reference_chain_pose(robot: RobotModel, q: np.ndarray, frame: str) -> np.ndarray:
    """World pose of link ``frame`` by yourdfpy's joint transforms composed along its chain
    (:func:`reference_pose` without the scene-graph update of every link: for many poses)."""
    urdf = _urdf(robot)
    T = np.eye(4)
    for j, i in robot.lazy(
        LazyKey(f"test.yourdfpy.chain:{frame}", list), lambda r: _chain(r, frame)
    ):
        T = T @ urdf._forward_kinematics_joint(j, q=None if i is None else float(q[i]))[0]
    return T


def pose_error(T: np.ndarray, target: np.ndarray) -> tuple[float, float]:
    """Position distance and rotation angle between two 4×4 poses.

    The angle of R = R_tᵀ·R_T is atan2(sin θ, cos θ) with sin θ = ‖vee(R − Rᵀ)‖/2 and
    cos θ = (tr R − 1)/2: accurate to ~1e-16 near θ = 0, where acos((tr R − 1)/2) cannot
    resolve angles below ~2e-8 (acos(1 − ε) = √(2ε)).
    """
    dp = float(np.linalg.norm(T[:3, 3] - target[:3, 3]))
    R = target[:3, :3].T @ T[:3, :3]
    s = 0.5 * math.hypot(R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1])
    c = (np.trace(R) - 1.0) / 2.0
    return dp, float(math.atan2(s, c))


def random_q(robot: RobotModel, rng: np.random.Generator) -> np.ndarray:
    lo = np.where(np.isfinite(robot.lower), robot.lower, -np.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, np.pi)
    return rng.uniform(lo, hi)


def within_limits(robot: RobotModel, q: np.ndarray) -> bool:
    """Whether every joint of wire ``q`` lies within its URDF limits (1e-12 slack)."""
    return all(
        j.continuous or (j.lower - 1e-12 <= v <= j.upper + 1e-12)
        for j, v in zip(robot.joints, q, strict=True)
    )


def se3(T: np.ndarray) -> pin.SE3:
    return pin.SE3(T[:3, :3].copy(), T[:3, 3].copy())


def random_configurations(robot: RobotModel, n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(robot.lower), robot.lower, -np.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, np.pi)
    return rng.uniform(lo, hi, size=(n, robot.n))


def planar2_elbows(x: float, y: float, l1: float, l2: float) -> list[tuple[float, float]]:
    """Closed-form planar 2-link IK (the textbook solution), both elbows (θ2 > 0 first):
    θ2 = ±acos c2, θ1 = atan2(y, x) − atan2(l2 s2, l1 + l2 c2)."""
    c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2)
    out = []
    for t2 in (math.acos(c2), -math.acos(c2)):
        t1 = math.atan2(y, x) - math.atan2(l2 * math.sin(t2), l1 + l2 * math.cos(t2))
        out.append((t1, t2))
    return out
