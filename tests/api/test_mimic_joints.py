"""Mimic joints over HTTP: GET lists them, a ROS JointState of the whole Panda is accepted as
is by every endpoint taking a configuration, an inconsistent follower is a 422 naming it.

The reference for "accepted as is" is the same request without the follower: the answers
must be identical. The mimic description is checked against the URDF's own ``<mimic>``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from tests.helpers import problem

ARM = [0.1, -0.4, 0.2, -2.0, 0.3, 1.8, 0.6]
FINGER = 0.025
NAMES = [f"panda_joint{i}" for i in range(1, 8)]
#: What a ROS JointState of the Panda holds (its nine names, the two fingers equal).
JOINT_STATE = {
    **dict(zip(NAMES, ARM, strict=True)),
    "panda_finger_joint1": FINGER,
    "panda_finger_joint2": FINGER,
}
ACTUATED = {k: v for k, v in JOINT_STATE.items() if k != "panda_finger_joint2"}
FRAME = "panda_rightfinger"

# (path, body without the configuration, key of the configuration map)
ENDPOINTS = [
    ("fk", {"frames": [FRAME, "panda_hand_tcp"]}, "joint_positions"),
    ("jacobian", {"frame": FRAME}, "joint_positions"),
    ("manipulability", {"frame": FRAME}, "joint_positions"),
    ("statics", {"frame": FRAME, "wrench": [1, 2, 3, 0.1, 0.2, 0.3]}, "joint_positions"),
    ("velocity", {"frame": FRAME, "twist": [0.01, 0, 0, 0, 0, 0]}, "joint_positions"),
    ("collisions", {}, "joint_positions"),
    (
        "ik",
        # An iteration cap and a budget it never reaches (the default 5 ms can run out
        # under load, and the two answers then differ).
        {
            "target": {"position": [0.4, 0.1, 0.5]},
            "mode": "position",
            "max_iterations": 200,
            "timeout_ms": 1000,
        },
        "seed",
    ),
]


def _strip(body: dict) -> dict:
    """An answer without what varies between two identical calls (timings)."""
    return {k: v for k, v in body.items() if not k.endswith("_ms")}


@pytest.mark.parametrize(("path", "body", "key"), ENDPOINTS, ids=[e[0] for e in ENDPOINTS])
def test_full_joint_state_is_accepted_as_is(client, path: str, body: dict, key: str) -> None:
    full = client.post(f"/robots/panda/{path}", json={**body, key: JOINT_STATE})
    assert full.status_code == 200, full.text
    actuated = client.post(f"/robots/panda/{path}", json={**body, key: ACTUATED})
    assert actuated.status_code == 200, actuated.text
    assert _strip(full.json()) == _strip(actuated.json())


@pytest.mark.parametrize(("path", "body", "key"), ENDPOINTS, ids=[e[0] for e in ENDPOINTS])
def test_inconsistent_follower_is_a_422_naming_it(client, path: str, body: dict, key: str) -> None:
    state = {**JOINT_STATE, "panda_finger_joint2": FINGER + 0.01}
    r = client.post(f"/robots/panda/{path}", json={**body, key: state})
    detail = problem(r, 422, f"{key}.panda_finger_joint2")["detail"]
    assert f"expected {FINGER!r}" in detail and "panda_finger_joint1" in detail


def test_unknown_joint_still_refused_with_followers_suggested(client) -> None:
    r = client.post("/robots/panda/fk", json={"joint_positions": {"panda_finger_joint": 0.0}})
    body = problem(r, 422, "joint_positions.panda_finger_joint")
    assert {"panda_finger_joint1", "panda_finger_joint2"} <= set(body["suggestions"])


def test_get_robot_lists_mimic_joints_as_the_urdf_says(client, registry) -> None:
    root = ET.fromstring(registry.get("panda").urdf_text)
    expected = [
        {
            "name": j.get("name"),
            "type": j.get("type"),
            "leader": j.find("mimic").get("joint"),
            "multiplier": float(j.find("mimic").get("multiplier", 1.0)),
            "offset": float(j.find("mimic").get("offset", 0.0)),
        }
        for j in root.iter("joint")
        if j.find("mimic") is not None
    ]
    assert expected and client.get("/robots/panda").json()["mimic_joints"] == expected
    assert client.get("/robots/ur5").json()["mimic_joints"] == []
