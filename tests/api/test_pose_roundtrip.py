"""One ``Pose`` in and out: FK's answer is accepted verbatim wherever a pose goes in (IK
targets, path waypoints, obstacle poses, reachability queries), and its redundant fields
(position, orientation, rpy, matrix) must agree within 1e-9 or the request is a 422 naming
them.

References: yourdfpy's FK of the Panda URDF (independent of the service's Pinocchio), and
rotations written out here from their definitions (R = Rz(yaw)·Ry(pitch)·Rx(roll); the
quaternion [x, y, z, w] from its axis and angle).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import yourdfpy

from tests.helpers import problem
from tests.packages import PANDA_DIR

Q0 = [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.6, 0.02]
FRAME = "panda_link8"


@pytest.fixture(scope="module")
def reference() -> yourdfpy.URDF:
    return yourdfpy.URDF.load(
        str(PANDA_DIR / "urdf" / "panda.urdf"), load_meshes=False, build_scene_graph=True
    )


def ref_fk(reference: yourdfpy.URDF, joint_positions: dict[str, float]) -> np.ndarray:
    """The 4×4 placement of FRAME in the root frame by yourdfpy."""
    cfg = [joint_positions.get(name, 0.0) for name in reference.actuated_joint_names]
    reference.update_cfg(cfg)
    return reference.get_transform(frame_to=FRAME, frame_from=reference.base_link)


def rot_x(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def rpy_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    return rot_z(yaw) @ rot_y(pitch) @ rot_x(roll)


def angle_between(A: np.ndarray, B: np.ndarray) -> float:
    return float(np.arccos(np.clip((np.trace(A.T @ B) - 1.0) / 2.0, -1.0, 1.0)))


def fk_pose(client, q: list[float] = Q0) -> dict:
    r = client.post("/robots/panda/fk", json={"q": q, "frames": [FRAME]})
    assert r.status_code == 200, r.text
    return r.json()["poses"][FRAME]


def joint_map(client, q: list[float]) -> dict[str, float]:
    names = [j["name"] for j in client.get("/robots/panda").json()["joints"]]
    return dict(zip(names, q, strict=True))


def test_fk_pose_is_every_field_of_the_reference(client, reference) -> None:
    """FK answers fill all four fields, each equal to yourdfpy's placement."""
    pose = fk_pose(client)
    T = ref_fk(reference, joint_map(client, Q0))
    assert np.allclose(pose["matrix"], T, atol=1e-12)
    assert np.allclose(pose["position"], T[:3, 3], atol=1e-12)
    assert angle_between(rpy_matrix(*pose["rpy"]), T[:3, :3]) < 1e-7
    x, y, z, w = pose["orientation"]
    R_q = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
    assert angle_between(R_q, T[:3, :3]) < 1e-7


def test_fk_pose_verbatim_is_an_ik_target(client, reference) -> None:
    """The whole FK pose (position, orientation, rpy and matrix) posted as the IK target
    converges to a configuration whose reference FK is that pose."""
    pose = fk_pose(client)
    body = {"target": pose, "frame": FRAME, "random_seed": 3, "max_iterations": 20000}
    r = client.post("/robots/panda/ik", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["success"], out
    want = ref_fk(reference, joint_map(client, Q0))
    got = ref_fk(reference, out["joint_positions"])
    assert np.linalg.norm(got[:3, 3] - want[:3, 3]) < 1e-5
    assert angle_between(got[:3, :3], want[:3, :3]) < 1e-5
    # Batch IK takes the same pose, and any agreeing subset of it.
    subsets = [pose, {"matrix": pose["matrix"]}, {"position": pose["position"], "rpy": pose["rpy"]}]
    batch = {"targets": subsets, "frame": FRAME, "random_seed": 3, "chain_seeds": False}
    r = client.post("/robots/panda/ik/batch", json=batch)
    assert r.status_code == 200, r.text
    assert [item["success"] for item in r.json()["results"]] == [True] * 3


def test_fk_pose_is_a_path_waypoint(client, reference) -> None:
    """A path from Q0 to the FK pose of a nearby configuration ends at that pose."""
    q1 = [v + 0.05 for v in Q0[:7]] + [Q0[7]]
    target = fk_pose(client, q1)
    body = {"start": Q0, "frame": FRAME, "waypoints": [target]}
    r = client.post("/robots/panda/ik/path", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["fraction"] == 1.0 and out["failure"] is None, out
    end = ref_fk(reference, joint_map(client, out["points"][-1]["q"]))
    want = ref_fk(reference, joint_map(client, q1))
    assert np.linalg.norm(end[:3, 3] - want[:3, 3]) < 1e-4
    assert angle_between(end[:3, :3], want[:3, :3]) < 1e-3
    line = {"start": Q0, "frame": FRAME, "segments": [{"type": "line", "to": target}]}
    r = client.post("/robots/panda/ik/path", json=line)
    assert r.status_code == 200 and r.json()["fraction"] == 1.0, r.text


def test_fk_pose_is_an_obstacle_pose(client) -> None:
    """An FK pose placing a thin plate at the flange: the same verdict as the position and
    quaternion alone, and a scene stores the same placement."""
    pose = fk_pose(client)
    plate = {"name": "plate", "shape": "box", "size": [0.3, 0.3, 0.005]}
    full = {**plate, "pose": pose}
    classic = {**plate, "pose": {"position": pose["position"], "orientation": pose["orientation"]}}
    answers = []
    for obstacle in (full, classic):
        body = {"q": Q0, "obstacles": [obstacle], "distances": True, "geometry": "convex"}
        r = client.post("/robots/panda/collisions", json=body)
        assert r.status_code == 200, r.text
        answers.append(r.json())
    assert answers[0] == answers[1]
    assert answers[0]["environment_collision"] is True
    r = client.post("/scenes", json={"name": "flange", "obstacles": [full]})
    assert r.status_code == 201, r.text
    stored = r.json()["obstacles"][0]["pose"]
    assert np.allclose(stored["matrix"], pose["matrix"], atol=1e-12)
    # An empty pose is the identity; a rotation-only pose sits at the origin.
    r = client.post("/scenes", json={"name": "origin", "obstacles": [{**plate, "pose": {}}]})
    assert r.status_code == 201, r.text
    assert r.json()["obstacles"][0]["pose"]["matrix"] == np.eye(4).tolist()


def _mismatch(pose: dict, key: str, by: float) -> dict:
    """``pose`` with field ``key`` moved by ``by`` (m, or rad about z)."""
    out = {k: (np.array(v, dtype=float).copy()) for k, v in pose.items()}
    if key == "position":
        out["position"][0] += by
    elif key == "matrix_position":
        out["matrix"][0, 3] += by
    elif key == "rpy":
        out["rpy"][2] += by
    elif key == "orientation":  # rotate the quaternion about the world z axis by `by`
        x, y, z, w = out["orientation"]
        c, s = math.cos(by / 2), math.sin(by / 2)
        out["orientation"] = np.array(
            [c * x - s * y, c * y + s * x, c * z + s * w, c * w - s * z], dtype=float
        )
    elif key == "matrix_rotation":
        out["matrix"][:3, :3] = rot_z(by) @ out["matrix"][:3, :3]
    return {k: v.tolist() for k, v in out.items()}


@pytest.mark.parametrize(
    ("keep", "moved", "field", "other"),
    [
        (("position", "matrix"), "position", "target.matrix", "target.position"),
        (("position", "matrix"), "matrix_position", "target.matrix", "target.position"),
        (("position", "orientation", "rpy"), "rpy", "target.rpy", "target.orientation"),
        (("position", "orientation"), "orientation", None, None),  # no redundancy: fine
        (("orientation", "matrix"), "matrix_rotation", "target.matrix", "target.orientation"),
        (("orientation", "matrix"), "orientation", "target.matrix", "target.orientation"),
        (("rpy", "matrix"), "rpy", "target.matrix", "target.rpy"),
    ],
)
def test_redundant_fields_must_agree(client, keep, moved, field, other) -> None:
    """A disagreement of 1e-7 (m or rad), far above 1e-9, is a 422 naming both fields;
    FK's own fields (agreeing to rounding) are accepted."""
    pose = {k: v for k, v in fk_pose(client).items() if k in keep}
    base = {"frame": FRAME, "max_iterations": 1, "mode": "pose"}
    if "position" not in keep and "matrix" not in keep:
        base["mode"] = "orientation"
    assert client.post("/robots/panda/ik", json={**base, "target": pose}).status_code == 200
    r = client.post("/robots/panda/ik", json={**base, "target": _mismatch(pose, moved, 1e-7)})
    if field is None:
        assert r.status_code == 200, r.text
        return
    body = problem(r, 422, field)
    assert other in body["detail"] and "disagree by 1e-07" in body["detail"], body


def test_matrix_must_be_rigid_and_fields_not_null(client) -> None:
    pose = fk_pose(client)
    scaled = np.array(pose["matrix"])
    scaled[:3, :3] *= 1.001
    for target, field in [
        ({**pose, "matrix": scaled.tolist()}, "target.matrix"),
        ({"matrix": (-np.eye(4) + 2 * np.diag([0, 0, 0, 1])).tolist()}, "target.matrix"),
        ({**pose, "rpy": None}, "target.rpy"),
        ({**pose, "orientation": None}, "target.orientation"),
        ({"position": pose["position"]}, "target.orientation"),  # mode pose needs a rotation
        ({"rpy": pose["rpy"]}, "target.position"),
    ]:
        r = client.post("/robots/panda/ik", json={"target": target, "frame": FRAME})
        problem(r, 422, field)
    # Mode position: the matrix alone gives the position.
    body = {"target": {"matrix": pose["matrix"]}, "frame": FRAME, "mode": "position"}
    assert client.post("/robots/panda/ik", json=body).status_code == 200


def test_gimbal_lock_rpy_agrees_with_any_equivalent_split(client) -> None:
    """At pitch = ±π/2 only yaw − roll (pitch +π/2) or yaw + roll (pitch −π/2) is defined:
    an rpy that splits it differently from the matrix's still agrees."""
    for pitch, sign in ((math.pi / 2, -1.0), (-math.pi / 2, 1.0)):
        R = rpy_matrix(0.3, pitch, 0.5)
        M = np.eye(4)
        M[:3, :3] = R
        M[:3, 3] = [0.4, 0.1, 0.5]
        other_split = [0.0, pitch, 0.5 + sign * 0.3]  # same yaw ∓ roll
        assert np.allclose(rpy_matrix(*other_split), R, atol=1e-15)
        target = {"position": [0.4, 0.1, 0.5], "rpy": other_split, "matrix": M.tolist()}
        body = {"target": target, "frame": FRAME, "max_iterations": 1}
        r = client.post("/robots/panda/ik", json=body)
        assert r.status_code == 200, r.text
        moved = {**target, "rpy": [0.0, pitch, 0.5 + sign * 0.3 + 1e-7]}
        problem(
            client.post("/robots/panda/ik", json={**body, "target": moved}), 422, "target.matrix"
        )


def test_stream_takes_the_fk_pose_and_checks_agreement(client, reference) -> None:
    """The WebSocket stream's ik messages go through the same conversion: the FK pose is a
    target, a disagreeing one is the 422 problem naming the field."""
    pose = fk_pose(client)
    with client.websocket_connect("/robots/panda/stream") as ws:
        msg = {"id": 1, "op": "ik", "target": pose, "frame": FRAME, "random_seed": 3}
        ws.send_text(json.dumps(msg))
        out = ws.receive_json()
        assert out["id"] == 1 and out["success"], out
        got = ref_fk(reference, joint_map(client, out["q"]))
        want = ref_fk(reference, joint_map(client, Q0))
        assert np.linalg.norm(got[:3, 3] - want[:3, 3]) < 1e-5
        ws.send_text(json.dumps({**msg, "id": 2, "target": _mismatch(pose, "rpy", 1e-7)}))
        err = ws.receive_json()["error"]
        assert err["status"] == 422 and err["field"] == "target.rpy", err
