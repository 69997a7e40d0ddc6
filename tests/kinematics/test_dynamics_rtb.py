"""The dynamics of the catalog's DH robots (puma560, ur5_dh: DH table → URDF by dh2urdf →
Pinocchio) against the Robotics Toolbox's own DH models (fixture by bench/rtb_dynamics.py,
``make rtb-fixtures``): τ (rne), g (gravload), M (inertia), C·q̇ and C (coriolis); and
``mdh3``, a modified-DH arm (revolute, revolute, prismatic) whose rows the fixture holds,
against the toolbox's RevoluteMDH/PrismaticMDH model of the same rows.

The toolbox computes with its DH link frames directly (``r`` and ``I`` in frame i, the DH
frame at the end of row i); the service with the URDF dh2urdf writes (``<inertial>`` on
``link_i``, whose frame is not frame i in the standard convention). Agreement to 1e-9 says
the com and inertia land in the right frame; measured on all three: ≤ 1.3e-14 N·m on τ,
g and C·q̇, ≤ 1.4e-15 on M, ≤ 2.5e-15 on C. Putting the com in link_i's frame without the
row's transform, or keeping link_i's axes for the inertia, fails it (puma560, ur5_dh); so
does reading a modified row's com in frame i−1 (mdh3).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.kinematics.dynamics import compute_dynamics
from app.kinematics.models import RobotModel
from dh2urdf import DHTable, to_urdf

FIXTURE = Path(__file__).with_name("data") / "rtb_dynamics.json"
DOC = json.loads(FIXTURE.read_text(encoding="utf-8"))
QUANTITIES = {
    "torques": "torques",
    "gravity": "gravity",
    "mass_matrix": "mass_matrix",
    "coriolis_torques": "coriolis",
    "coriolis_matrix": "coriolis_matrix",
}
CASES = [
    (robot_id, index)
    for robot_id, robot in DOC["robots"].items()
    for index in range(len(robot["states"]))
]


def robot_of(registry, robot_id: str) -> RobotModel:
    if robot_id != "mdh3":
        robot = registry.get(robot_id)
        assert robot.joint_names == registry.dh_table(robot_id).joint_names
        return robot
    rows = DOC["robots"]["mdh3"]["rows"]
    table = DHTable.from_dict({"name": "mdh3", "convention": "modified", "joints": rows})
    return RobotModel("mdh3", to_urdf(table), ee_frame="tool")


def test_fixture_is_the_rigid_body_model_of_the_robots():
    assert set(DOC["robots"]) == {"puma560", "ur5_dh", "mdh3"}
    assert DOC["gravity"] == [0.0, 0.0, -9.81]
    assert all(len(r["states"]) >= 8 for r in DOC["robots"].values())


@pytest.mark.parametrize("robot_id, index", CASES)
def test_dynamics_match_the_robotics_toolbox(registry, robot_id, index):
    state = DOC["robots"][robot_id]["states"][index]
    robot = robot_of(registry, robot_id)
    q, qd, qdd = (np.array(state[k]) for k in ("q", "qd", "qdd"))
    d = compute_dynamics(robot, q, qd, qdd)
    for key, attribute in QUANTITIES.items():
        np.testing.assert_allclose(
            getattr(d, attribute), np.array(state[key]), rtol=0, atol=1e-9, err_msg=key
        )
    # and the parts add up to the toolbox's rne
    np.testing.assert_allclose(
        np.array(state["mass_matrix"]) @ qdd
        + np.array(state["coriolis_torques"])
        + np.array(state["gravity"]),
        d.torques,
        rtol=0,
        atol=1e-9,
    )


@pytest.mark.parametrize("q2", [0.0, 0.7, -2.3])
def test_planar2_is_the_textbook_arm_of_two_solid_cylinders(registry, q2):
    """robots/dh/planar2.yaml: l = 1.0, 0.8 m, m = 2.0, 1.6 kg, mid-link centres of mass,
    solid cylinders of radius 0.03 m (I_zz = m(3r² + l²)/12); horizontal, so g = 0.
    Spong, Hutchinson & Vidyasagar §7.4 give M and C."""
    l1, m1, m2, r = 1.0, 2.0, 1.6, 0.03
    c1, c2 = 0.5, 0.4
    i1, i2 = m1 * (3 * r * r + 1.0) / 12, m2 * (3 * r * r + 0.64) / 12
    q, qd = np.array([0.4, q2]), np.array([0.9, -1.3])
    cos2, sin2 = np.cos(q2), np.sin(q2)
    m11 = m1 * c1**2 + m2 * (l1**2 + c2**2 + 2 * l1 * c2 * cos2) + i1 + i2
    m12 = m2 * (c2**2 + l1 * c2 * cos2) + i2
    m22 = m2 * c2**2 + i2
    h = -m2 * l1 * c2 * sin2
    c = np.array([[h * qd[1], h * (qd[0] + qd[1])], [-h * qd[0], 0.0]])
    d = compute_dynamics(registry.get("planar2"), q, qd)
    np.testing.assert_allclose(d.mass_matrix, [[m11, m12], [m12, m22]], rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.coriolis_matrix, c, rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.gravity, 0.0, rtol=0, atol=1e-12)
    assert d.mass == pytest.approx(m1 + m2, abs=1e-12)
