"""Forward kinematics against independent references: yourdfpy and closed forms."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest
import yourdfpy

from app.kinematics.fk import forward_kinematics, forward_kinematics_batch
from app.kinematics.models import RobotModel
from app.kinematics.rotations import matrix_to_quaternion
from tests.kinematics.chains import continuous_arm, planar_2link
from tests.kinematics.reference import random_configurations

CATALOG = ["panda", "ur3", "ur5", "ur10", "kinova", "xarm", "z1", "so100"]


@pytest.mark.parametrize("robot_id", CATALOG)
def test_fk_matches_yourdfpy(registry, robot_id: str) -> None:
    """Every link of every catalog robot agrees with yourdfpy's FK to 1e-9."""
    robot = registry.get(robot_id)
    urdf = yourdfpy.URDF.load(
        str(registry.catalog[robot_id].urdf_path),
        load_meshes=False,
        build_collision_scene_graph=False,
        load_collision_meshes=False,
    )
    assert urdf.actuated_joint_names == robot.joint_names
    links = [f.name for f in robot.frames if f.kind == "link"]
    for q in random_configurations(robot, 10):
        urdf.update_cfg(q)
        poses = forward_kinematics(robot, q, links)
        for link in links:
            expected = urdf.get_transform(link, urdf.base_link)
            np.testing.assert_allclose(poses[link], expected, atol=1e-9, err_msg=link)


def test_planar_chain_closed_form() -> None:
    l1, l2 = 1.0, 0.7
    robot = RobotModel("p2", planar_2link(l1, l2), ee_frame="tip")
    for t1, t2 in random_configurations(robot, 50, seed=1):
        T = forward_kinematics(robot, np.array([t1, t2]), ["tip"])["tip"]
        x = l1 * np.cos(t1) + l2 * np.cos(t1 + t2)
        y = l1 * np.sin(t1) + l2 * np.sin(t1 + t2)
        np.testing.assert_allclose(T[:3, 3], [x, y, 0.0], atol=1e-12)
        c, s = np.cos(t1 + t2), np.sin(t1 + t2)
        np.testing.assert_allclose(T[:3, :3], [[c, -s, 0], [s, c, 0], [0, 0, 1]], atol=1e-12)


def test_continuous_joint_is_one_angle() -> None:
    robot = RobotModel("c", continuous_arm())
    assert robot.model.nq == 3 and robot.model.nv == 2 and robot.n == 2
    assert robot.joints[0].continuous and robot.joints[0].lower is None
    for th, b in [(0.3, 0.2), (3.0, -0.5), (-2.5, 0.9), (7.0, 0.0)]:
        T = forward_kinematics(robot, np.array([th, b]), ["l2"])["l2"]
        np.testing.assert_allclose(T[:3, 3], [0.5 * np.cos(th), 0.5 * np.sin(th), 0.1], atol=1e-12)
        back = robot.from_pin(robot.to_pin(np.array([th, b])))
        assert np.isclose(np.cos(back[0]), np.cos(th)) and np.isclose(np.sin(back[0]), np.sin(th))
        assert -np.pi < back[0] <= np.pi


def test_batch_equals_single(registry) -> None:
    robot = registry.get("kinova")
    qs = random_configurations(robot, 20, seed=3)
    pos, quat = forward_kinematics_batch(robot, qs, robot.ee_frame)
    for i, q in enumerate(qs):
        T = forward_kinematics(robot, q, [robot.ee_frame])[robot.ee_frame]
        np.testing.assert_allclose(pos[i], T[:3, 3], atol=1e-12)
        ref = pin.Quaternion(T[:3, :3]).coeffs()  # Eigen coeffs: [x, y, z, w]
        ref = ref if ref[3] >= 0 else -ref
        np.testing.assert_allclose(quat[i], ref, atol=1e-12)


def test_quaternion_convention_against_pinocchio() -> None:
    """[x, y, z, w] with w >= 0, equal to Eigen's coeffs(), on random and near-π rotations."""
    rotations = [pin.SE3.Random().rotation for _ in range(200)]
    rotations += [pin.exp3(axis * (np.pi - 1e-3)) for axis in np.eye(3)]  # Shepperd branches
    rotations += [pin.exp3(np.array([1.0, -1.0, 0.5]) / 1.5 * np.pi)]
    for R in rotations:
        q = matrix_to_quaternion(R)
        ref = pin.Quaternion(R).coeffs()
        ref = ref if ref[3] >= 0 else -ref
        np.testing.assert_allclose(q, ref, atol=1e-12)
        x, y, z, w = q
        np.testing.assert_allclose(pin.Quaternion(w, x, y, z).matrix(), R, atol=1e-12)


@pytest.mark.parametrize("robot_id", CATALOG)
def test_vectorised_batch_equals_pinocchio(registry, robot_id: str) -> None:
    """SerialChain (app.kinematics.chain) agrees with Pinocchio on every link of every robot."""
    robot = registry.get(robot_id)
    qs = random_configurations(robot, 25, seed=9)
    for frame in [f.name for f in robot.frames if f.kind == "link"]:
        pos, quat = forward_kinematics_batch(robot, qs, frame)
        for i in (0, 12, 24):
            T = forward_kinematics(robot, qs[i], [frame])[frame]
            np.testing.assert_allclose(pos[i], T[:3, 3], atol=1e-12, err_msg=frame)
            np.testing.assert_allclose(
                _qm(quat[i]),
                T[:3, :3],
                atol=1e-12,
            )


def test_vectorised_batch_prismatic_and_continuous() -> None:
    from tests.kinematics.chains import rrp_like

    for robot, frame in [
        (RobotModel("rrp", rrp_like(), ee_frame="tip"), "tip"),
        (RobotModel("c", continuous_arm()), "l2"),
    ]:
        qs = random_configurations(robot, 40, seed=2)
        pos, quat = forward_kinematics_batch(robot, qs, frame)
        for i, q in enumerate(qs):
            T = forward_kinematics(robot, q, [frame])[frame]
            np.testing.assert_allclose(pos[i], T[:3, 3], atol=1e-12)
            np.testing.assert_allclose(_qm(quat[i]), T[:3, :3], atol=1e-12)


def _qm(q: np.ndarray) -> np.ndarray:
    x, y, z, w = q
    return pin.Quaternion(w, x, y, z).matrix()
