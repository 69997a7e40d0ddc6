"""The dynamics core against pybullet (Bullet's Featherstone multibody), an independent
implementation: inverse dynamics at random states, gravity torques and the mass matrix of
the catalog's UR5, Kinova and Panda from the robots' own URDF text, and a payload baked into
the URDF as an extra fixed link carrying the payload's inertial.

pybullet runs DIRECT (no GUI), the URDF written to a temporary file without its visual and
collision elements (no meshes needed), ``useFixedBase``, the inertias as the file states them
(``URDF_USE_INERTIA_FROM_FILE``; without it Bullet derives them from the collision shapes),
gravity −9.81 along z. pybullet knows no mimic joints: the Panda's second finger is a joint
of its own, driven at ``q2 = multiplier·q1 + offset`` (its rates × multiplier), and by
virtual work the leader's torque is ``τ_finger1 + multiplier·τ_finger2``; the mass matrix
likewise ``Gᵀ M G``.

Measured (relative to the largest entry): τ, g and M within 2e-15 for the UR5 and the Kinova;
the Panda's τ within 6e-12 and M within 1.1e-10, and every payload case within 6e-11:
Bullet's URDF loader diagonalises each inertia tensor numerically (its principal axes
become the link's inertial frame), which costs ~1e-10 where a tensor has products of
inertia (the Panda's links, the payload here); with those set to 0 the Panda agrees within
1e-15. Hence :data:`RTOL` = 1e-9.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet as p
import pytest

from app.kinematics.dynamics import GRAVITY, compute_dynamics, inverse_dynamics, payload
from app.kinematics.models import RobotModel

#: Relative agreement (to the largest |entry| of the compared vector or matrix, at least 1).
RTOL = 1e-9
STATES = 5


def strip_geometry(urdf: str) -> str:
    """The URDF without ``<visual>`` and ``<collision>`` elements (no meshes to load)."""
    for tag in ("visual", "collision"):
        urdf = re.sub(rf"<{tag}\b.*?</{tag}>", "", urdf, flags=re.DOTALL)
        urdf = re.sub(rf"<{tag}\b[^>]*/>", "", urdf)
    return urdf


class Bullet:
    """One robot loaded into a pybullet DIRECT client, its movable joints by name."""

    def __init__(self, urdf: str, path: Path) -> None:
        path.write_text(strip_geometry(urdf))
        self.client = p.connect(p.DIRECT)
        p.setGravity(0, 0, -GRAVITY, physicsClientId=self.client)
        self.body = p.loadURDF(
            str(path),
            useFixedBase=True,
            flags=p.URDF_USE_INERTIA_FROM_FILE,
            physicsClientId=self.client,
        )
        self.names = []
        for j in range(p.getNumJoints(self.body, physicsClientId=self.client)):
            info = p.getJointInfo(self.body, j, physicsClientId=self.client)
            if info[2] in (p.JOINT_REVOLUTE, p.JOINT_PRISMATIC):
                self.names.append(info[1].decode())

    def rnea(self, q: np.ndarray, qd: np.ndarray, qdd: np.ndarray) -> np.ndarray:
        return np.array(
            p.calculateInverseDynamics(
                self.body, q.tolist(), qd.tolist(), qdd.tolist(), physicsClientId=self.client
            )
        )

    def mass_matrix(self, q: np.ndarray) -> np.ndarray:
        return np.array(p.calculateMassMatrix(self.body, q.tolist(), physicsClientId=self.client))

    def close(self) -> None:
        p.disconnect(self.client)


def mapping(robot: RobotModel, bullet: Bullet) -> tuple[np.ndarray, np.ndarray]:
    """``G`` (pybullet's joints × wire joints) and the offsets: pybullet's value of joint k
    is ``G[k] · q + c[k]`` (followers: multiplier × leader + offset)."""
    G, c = np.zeros((len(bullet.names), robot.n)), np.zeros(len(bullet.names))
    mimic = {m.name: m for m in robot.mimic_joints}
    for k, name in enumerate(bullet.names):
        if name in mimic:
            G[k, mimic[name].leader_index] = mimic[name].multiplier
            c[k] = mimic[name].offset
        else:
            G[k, robot.joint_index(name)] = 1.0
    return G, c


def close(actual: np.ndarray, expected: np.ndarray) -> float:
    """The largest difference relative to the largest |expected| entry (at least 1)."""
    return float(np.abs(actual - expected).max() / max(1.0, np.abs(expected).max()))


def states(robot: RobotModel, seed: int) -> Iterator[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    rng = np.random.default_rng(seed)
    lo, hi = np.maximum(robot.lower, -3.0), np.minimum(robot.upper, 3.0)
    for _ in range(STATES):
        yield rng.uniform(lo, hi), rng.normal(size=robot.n), rng.normal(size=robot.n)


@pytest.fixture(scope="module", params=["ur5", "kinova", "panda"])
def pair(request, registry, tmp_path_factory) -> Iterator[tuple[RobotModel, Bullet]]:
    robot = registry.get(request.param)
    bullet = Bullet(robot.urdf_text, tmp_path_factory.mktemp("pb") / f"{request.param}.urdf")
    yield robot, bullet
    bullet.close()


def test_joints_match(pair):
    robot, bullet = pair
    followers = {m.name for m in robot.mimic_joints}
    assert sorted(set(bullet.names) - followers) == sorted(robot.joint_names)


def test_inverse_dynamics_matches_pybullet(pair):
    robot, bullet = pair
    G, c = mapping(robot, bullet)
    worst = 0.0
    qs, qds, qdds = map(np.array, zip(*states(robot, 7), strict=True))
    batch = inverse_dynamics(robot, qs, qds, qdds)
    for k, (q, qd, qdd) in enumerate(zip(qs, qds, qdds, strict=True)):
        expected = G.T @ bullet.rnea(G @ q + c, G @ qd, G @ qdd)
        d = compute_dynamics(robot, q, qd, qdd)
        worst = max(worst, close(d.torques, expected), close(batch[k], expected))
        # the parts add up to τ, and M q̈ is pybullet's mass matrix times q̈
        M = G.T @ bullet.mass_matrix(G @ q + c) @ G
        assert close(d.inertial, M @ qdd) < RTOL
        assert close(d.gravity + d.coriolis + d.inertial, d.torques) < 1e-12
    assert worst < RTOL, worst


def test_gravity_matches_pybullet(pair):
    robot, bullet = pair
    G, c = mapping(robot, bullet)
    zero = np.zeros(len(bullet.names))
    for q, _, _ in states(robot, 11):
        expected = G.T @ bullet.rnea(G @ q + c, zero, zero)
        assert close(compute_dynamics(robot, q).gravity, expected) < RTOL


def test_mass_matrix_matches_pybullet(pair):
    robot, bullet = pair
    G, c = mapping(robot, bullet)
    for q, _, _ in states(robot, 13):
        expected = G.T @ bullet.mass_matrix(G @ q + c) @ G
        assert close(compute_dynamics(robot, q).mass_matrix, expected) < RTOL


def with_payload(urdf: str, link: str, mass: float, com, inertia) -> str:
    """``urdf`` with a link ``payload`` fixed to ``link`` carrying the payload's inertial
    (``com`` in the link's axes, ``inertia`` the six URDF entries about it)."""
    names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    entries = " ".join(f'{n}="{v!r}"' for n, v in zip(names, inertia, strict=True))
    extra = (
        f'<link name="payload"><inertial><origin xyz="{com[0]!r} {com[1]!r} {com[2]!r}"/>'
        f'<mass value="{mass!r}"/><inertia {entries}/></inertial></link>'
        f'<joint name="payload_joint" type="fixed"><parent link="{link}"/>'
        '<child link="payload"/></joint>'
    )
    return urdf.replace("</robot>", extra + "</robot>")


@pytest.mark.parametrize(
    "robot_id, link",
    [("ur5", "tool0"), ("kinova", "j2s6s200_link_6"), ("panda", "panda_hand")],
)
def test_payload_matches_pybullet_with_the_payload_as_a_link(robot_id, link, registry, tmp_path):
    robot = registry.get(robot_id)
    mass, com, inertia = 2.5, (0.03, -0.02, 0.08), (0.02, 0.001, -0.002, 0.03, 0.0015, 0.015)
    load = payload(robot, mass, link, com, inertia)
    bullet = Bullet(with_payload(robot.urdf_text, link, mass, com, inertia), tmp_path / "p.urdf")
    try:
        G, c = mapping(robot, bullet)
        for q, qd, qdd in states(robot, 17):
            expected = G.T @ bullet.rnea(G @ q + c, G @ qd, G @ qdd)
            d = compute_dynamics(robot, q, qd, qdd, load=load)
            assert close(d.torques, expected) < RTOL
            M = G.T @ bullet.mass_matrix(G @ q + c) @ G
            assert close(d.mass_matrix, M) < RTOL
            # the payload matters: without it the torques differ well beyond the tolerance
            assert close(compute_dynamics(robot, q, qd, qdd).torques, expected) > 1e-3
    finally:
        bullet.close()
