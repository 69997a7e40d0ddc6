"""POST /robots/{id}/fk, /fk/batch, /jacobian and GET /robots: answers and error contract."""

from __future__ import annotations

import numpy as np
import pytest

from app.kinematics.fk import forward_kinematics
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.rotations import quaternion_to_matrix, rpy_to_matrix
from tests.helpers import problem
from tests.kinematics.reference import reference_pose

UR5_JOINTS = [
    f"{j}_joint"
    for j in ("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3")
]

PANDA_READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]


def post_raw(client, url: str, raw: str):
    """POST a body verbatim as JSON (to send what json.dumps never would)."""
    return client.post(url, content=raw, headers={"content-type": "application/json"})


def test_list_and_describe(client) -> None:
    robots = {r["id"]: r for r in client.get("/robots").json()["robots"]}
    for rid in ["panda", "ur3", "ur5", "ur10", "kinova", "xarm", "z1", "so100"]:
        assert robots[rid]["source"] == "example-robot-data"
    assert robots["panda"]["joints"] == 8
    detail = client.get("/robots/kinova").json()
    assert [j["continuous"] for j in detail["joints"]] == [True, False, False, True, False, True]
    assert detail["joints"][0]["limits"]["lower"] is None
    assert detail["end_effector"] == "j2s6s200_end_effector"
    assert len(detail["neutral"]) == 6 and detail["has_collision_geometry"]
    names = {f["name"] for f in detail["frames"]}
    assert {"j2s6s200_link_base", "j2s6s200_end_effector", "j2s6s200_link_6"} <= names


def test_fk_pose_fields_are_consistent(client, registry) -> None:
    resp = client.post("/robots/panda/fk", json={"q": PANDA_READY})
    assert resp.status_code == 200
    body = resp.json()
    pose = body["poses"]["panda_hand_tcp"]
    T = np.array(pose["matrix"])
    robot = registry.get("panda")
    expected = forward_kinematics(robot, np.array(PANDA_READY), ["panda_hand_tcp"])
    np.testing.assert_allclose(T, expected["panda_hand_tcp"], atol=1e-15)
    np.testing.assert_allclose(pose["position"], T[:3, 3], atol=1e-15)
    np.testing.assert_allclose(
        quaternion_to_matrix(np.array(pose["orientation"])), T[:3, :3], atol=1e-12
    )
    np.testing.assert_allclose(rpy_to_matrix(np.array(pose["rpy"])), T[:3, :3], atol=1e-12)
    assert pose["orientation"][3] >= 0
    assert body["within_limits"] and body["joints_outside_limits"] == []


def test_fk_all_frames_and_joint_positions(client) -> None:
    body = client.post(
        "/robots/ur5/fk", json={"joint_positions": {"elbow_joint": 1.0}, "frames": ["*"]}
    ).json()
    assert {"tool0", "ee_link", "base_link", "wrist_3_link"} <= body["poses"].keys()
    assert body["q"] == [0, 0, 1.0, 0, 0, 0]


def test_fk_out_of_limits_flagged(client) -> None:
    body = client.post("/robots/ur5/fk", json={"q": [0, 0, 4.0, 0, 0, 0]}).json()
    assert body["within_limits"] is False and body["joints_outside_limits"] == ["elbow_joint"]


def test_fk_continuous_joint_one_angle(client, registry) -> None:
    """A continuous joint takes one angle (not Pinocchio's cos/sin pair); θ and θ + 2π give
    the pose yourdfpy gives for θ."""
    q = [0.5, 2, 2, 1, 1, 0]
    a = client.post("/robots/kinova/fk", json={"q": q}).json()
    b = client.post("/robots/kinova/fk", json={"q": [0.5 + 2 * np.pi, *q[1:]]}).json()
    ee = "j2s6s200_end_effector"
    ref = reference_pose(registry.get("kinova"), np.array(q, dtype=float), ee)
    np.testing.assert_allclose(a["poses"][ee]["matrix"], ref, atol=1e-12)
    np.testing.assert_allclose(b["poses"][ee]["matrix"], ref, atol=1e-12)


def test_batch_matches_single(client) -> None:
    rng = np.random.default_rng(0)
    qs = rng.uniform(-1, 1, size=(30, 6))
    body = client.post(
        "/robots/ur5/fk/batch", json={"configurations": qs.tolist(), "frame": "tool0"}
    ).json()
    assert np.array(body["positions"]).shape == (30, 3)
    assert np.array(body["orientations"]).shape == (30, 4)
    for i in (0, 17, 29):
        single = client.post("/robots/ur5/fk", json={"q": qs[i].tolist(), "frames": ["tool0"]})
        pose = single.json()["poses"]["tool0"]
        np.testing.assert_allclose(body["positions"][i], pose["position"], atol=1e-15)
        np.testing.assert_allclose(body["orientations"][i], pose["orientation"], atol=1e-12)


def test_jacobian_endpoint(client, registry) -> None:
    q = [0.1, -0.4, 0.3, -1.5, 0.2, 1.0, 0.4, 0.01]
    robot = registry.get("panda")
    for ref in ("world", "local", "world_spatial"):
        body = client.post(
            "/robots/panda/jacobian", json={"q": q, "reference": ref, "frame": "panda_link8"}
        ).json()
        assert body["joint_names"] == robot.joint_names
        expected = frame_jacobian(robot, np.array(q), "panda_link8", ref)
        np.testing.assert_allclose(body["jacobian"], expected, atol=1e-15)


def test_health_loads_no_robot(app, client) -> None:
    assert client.get("/health").json() == {"status": "ok"}
    assert app.state.registry._cache == {}


# ------------------------------------------------------------------------ error contract
def test_unknown_robot(client) -> None:
    body = problem(client.post("/robots/pand/fk", json={}), 404, "robot_id")
    assert "panda" in body["suggestions"]
    problem(client.get("/robots/nope"), 404, "robot_id")


def test_unknown_frame(client) -> None:
    body = problem(
        client.post("/robots/panda/fk", json={"frames": ["panda_link88"]}), 422, "frames.0"
    )
    assert "panda_link8" in body["suggestions"]
    problem(client.post("/robots/panda/jacobian", json={"frame": "x"}), 422, "frame")
    problem(
        client.post("/robots/ur5/fk/batch", json={"configurations": [[0] * 6], "frame": "tool"}),
        422,
        "frame",
    )


def test_unknown_joint(client) -> None:
    body = problem(
        client.post("/robots/ur5/fk", json={"joint_positions": {"elbow": 1}}),
        422,
        "joint_positions.elbow",
    )
    assert "elbow_joint" in body["suggestions"]
    # The message lists every known joint (a client building a JointState can fix its names).
    assert all(name in body["detail"] for name in UR5_JOINTS), body["detail"]


def test_wrong_length(client) -> None:
    problem(client.post("/robots/ur5/fk", json={"q": [0] * 5}), 422, "q")
    problem(client.post("/robots/ur5/jacobian", json={"q": [0] * 7}), 422, "q")
    problem(
        client.post("/robots/ur5/fk/batch", json={"configurations": [[0] * 6, [0] * 5]}),
        422,
        "configurations.1",
    )


@pytest.mark.parametrize("token", ["NaN", "Infinity", "-Infinity"])
def test_non_finite(client, token: str) -> None:
    raw = '{"q": [0, 0, TOKEN, 0, 0, 0]}'.replace("TOKEN", token)
    problem(post_raw(client, "/robots/ur5/fk", raw), 422, "q.2")
    raw = '{"configurations": [[0, 0, 0, 0, 0, 0], [0, 0, 0, TOKEN, 0, 0]]}'
    problem(
        post_raw(client, "/robots/ur5/fk/batch", raw.replace("TOKEN", token)),
        422,
        "configurations.1.3",
    )
    raw = '{"joint_positions": {"elbow_joint": TOKEN}}'.replace("TOKEN", token)
    problem(post_raw(client, "/robots/ur5/jacobian", raw), 422, "joint_positions.elbow_joint")


@pytest.mark.parametrize("value", ['"0.5"', "true", "null", "[1]", "{}"])
def test_non_numbers(client, value: str) -> None:
    raw = '{"q": [0, VALUE, 0, 0, 0, 0]}'.replace("VALUE", value)
    problem(post_raw(client, "/robots/ur5/fk", raw), 422, "q.1")


@pytest.mark.parametrize("raw", ['{"q": [0, 0', "", "not json", '{"q": [1,]}'])
def test_malformed_json(client, raw: str) -> None:
    resp = post_raw(client, "/robots/ur5/fk", raw)
    if raw == "":
        # an empty body is "no body": a 422 naming the missing body
        problem(resp, 422, "body")
    else:
        problem(resp, 400, "body")


def test_wrong_types_and_extra_fields(client) -> None:
    problem(client.post("/robots/ur5/fk", json={"q": 1}), 422, "q")
    problem(client.post("/robots/ur5/fk", json={"qq": [0] * 6}), 422, "qq")
    problem(client.post("/robots/ur5/fk", json={"frames": "tool0"}), 422, "frames")
    problem(client.post("/robots/ur5/jacobian", json={"reference": "global"}), 422, "reference")
    problem(client.post("/robots/ur5/fk", json={"q": [0] * 6, "joint_positions": {}}), 422, "q")
    problem(client.post("/robots/ur5/fk", json=[1, 2]), 422)


def test_oversize_and_empty_batch(client, app) -> None:
    app.state.settings.max_batch = 10
    problem(
        client.post("/robots/ur5/fk/batch", json={"configurations": [[0] * 6] * 11}),
        422,
        "configurations",
    )
    assert client.post("/robots/ur5/fk/batch", json={"configurations": [[0] * 6] * 10}).is_success
    problem(client.post("/robots/ur5/fk/batch", json={"configurations": []}), 422, "configurations")
    problem(client.post("/robots/ur5/fk/batch", json={"configurations": [0] * 6}), 422)


@pytest.mark.parametrize(
    ("raw", "field"),
    [
        ('{"configurations": [[0, 0, 0, 0, 0, 0], [0, true, 0, 0, 0, 0]]}', "configurations.1.1"),
        ('{"configurations": [[0, 0, 0, 0, 0, "1"]]}', "configurations.0.5"),
        ('{"configurations": [[0, 0, 0, 0, 0, null]]}', "configurations.0.5"),
        ('{"configurations": [[0, 0, 0, 0, 0, [0]]]}', "configurations.0.5"),
        ('{"configurations": [[0, 0, 0, 0, 0, 0]], "frame": 3}', "frame"),
        ('{"configurations": [[0, 0, 0, 0, 0, 0]], "extra": 1}', "extra"),
        ('{"configurations": [[0, 0, 0, 0, 0, 1e999]]}', "configurations.0.5"),
        ('{"frame": "tool0"}', "configurations"),
    ],
)
def test_batch_bad_elements_named(client, raw: str, field: str) -> None:
    problem(post_raw(client, "/robots/ur5/fk/batch", raw), 422, field)


def test_batch_malformed_and_unknown_robot(client) -> None:
    problem(post_raw(client, "/robots/ur5/fk/batch", '{"configurations": [[0, 0'), 400, "body")
    problem(post_raw(client, "/robots/nope/fk/batch", '{"configurations": [[0]]}'), 404)
