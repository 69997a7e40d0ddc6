"""The dynamics of the catalog's DH robots (puma560, ur5_dh: DH table → URDF by dh2urdf →
Pinocchio) against the Robotics Toolbox's own DH models (fixture by bench/rtb_dynamics.py,
``make rtb-fixtures``): τ (rne), g (gravload), M (inertia), C·q̇ and C (coriolis).

The toolbox computes with its DH link frames directly (``r`` and ``I`` in frame i, the DH
frame at the end of row i); the service with the URDF dh2urdf writes (``<inertial>`` on
``link_i``, whose frame is not frame i in the standard convention). Agreement to 1e-9 says
the com and inertia land in the right frame; measured: ≤ 1.3e-14 N·m on τ, g and C·q̇,
≤ 1.4e-15 on M.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.kinematics.dynamics import compute_dynamics

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


def test_fixture_is_the_rigid_body_model_of_both_robots():
    assert set(DOC["robots"]) == {"puma560", "ur5_dh"}
    assert DOC["gravity"] == [0.0, 0.0, -9.81]
    assert all(len(r["states"]) >= 8 for r in DOC["robots"].values())


@pytest.mark.parametrize("robot_id, index", CASES)
def test_dynamics_match_the_robotics_toolbox(registry, robot_id, index):
    state = DOC["robots"][robot_id]["states"][index]
    robot = registry.get(robot_id)
    assert robot.joint_names == registry.dh_table(robot_id).joint_names
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
