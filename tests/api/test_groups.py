"""SRDF planning groups over HTTP: the catalog Panda's URDF uploaded with a MoveIt-style SRDF.

References are independent of the service's group code: yourdfpy's FK of the URDF, finite
differences of the service's own full-configuration FK, and the SRDF written here.
"""

from __future__ import annotations

import io

import numpy as np
import pinocchio as pin
import pytest
import yourdfpy
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from app.robots.catalog import load_catalog
from tests.helpers import problem

ARM = [f"panda_joint{i}" for i in range(1, 8)]
READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]
SRDF = f"""<?xml version="1.0"?>
<robot name="panda">
  <group name="panda_arm"><chain base_link="panda_link0" tip_link="panda_link8"/></group>
  <group name="hand">
    <link name="panda_hand"/><link name="panda_leftfinger"/><link name="panda_rightfinger"/>
  </group>
  <group name="panda_arm_hand"><group name="panda_arm"/><group name="hand"/></group>
  <group_state name="ready" group="panda_arm">
    {"".join(f'<joint name="{j}" value="{v}"/>' for j, v in zip(ARM, READY, strict=True))}
  </group_state>
  <group_state name="open" group="hand"><joint name="panda_finger_joint1" value="0.035"/>
  </group_state>
  <end_effector name="hand" parent_link="panda_link8" group="hand" parent_group="panda_arm"/>
  <disable_collisions link1="panda_link0" link2="panda_link1" reason="Adjacent"/>
</robot>
"""


@pytest.fixture(scope="module")
def urdf() -> str:
    return load_catalog()["panda"].urdf_path.read_text()


@pytest.fixture(scope="module")
def client(tmp_path_factory: pytest.TempPathFactory, urdf: str):
    settings = Settings(
        data_dir=tmp_path_factory.mktemp("groups"), ik_max_request_s=1e4, ik_max_timeout_ms=1e5
    )
    with TestClient(create_app(settings)) as c:
        resp = c.post("/robots/urdf", json={"name": "lab-panda", "urdf": urdf, "srdf": SRDF})
        assert resp.status_code == 201, resp.text
        yield c


@pytest.fixture(scope="module")
def reference(urdf: str) -> yourdfpy.URDF:
    return yourdfpy.URDF.load(io.BytesIO(urdf.encode()), load_meshes=False)


def ref_pose(ref: yourdfpy.URDF, q: np.ndarray, link: str) -> np.ndarray:
    ref.update_cfg(q)
    return ref.get_transform(link, ref.base_link)


def random_arm(rng: np.random.Generator, n: int, client: TestClient) -> np.ndarray:
    joints = client.get("/robots/lab-panda").json()["joints"][:7]
    lo = np.array([j["limits"]["lower"] for j in joints])
    hi = np.array([j["limits"]["upper"] for j in joints])
    return rng.uniform(lo, hi, (n, 7))


def matrix(pose: dict) -> np.ndarray:
    return np.array(pose["matrix"])


# ---------------------------------------------------------------------------- description
def test_get_lists_groups_end_effectors_states_and_the_default_tip(client: TestClient) -> None:
    body = client.get("/robots/lab-panda").json()
    groups = {g["name"]: g for g in body["groups"]}
    assert list(groups) == ["panda_arm", "hand", "panda_arm_hand"]
    assert groups["panda_arm"] == {"name": "panda_arm", "joints": ARM, "tip": "panda_link8"}
    # the finger's mimic follower (panda_finger_joint2) and the fixed hand joint are not
    # configuration entries
    assert groups["hand"]["joints"] == ["panda_finger_joint1"]
    assert groups["panda_arm_hand"]["joints"] == [*ARM, "panda_finger_joint1"]
    assert body["end_effectors"] == [
        {
            "name": "hand",
            "parent_link": "panda_link8",
            "group": "hand",
            "parent_group": "panda_arm",
        }
    ]
    states = {s["name"]: s for s in body["named_states"]}
    assert states["ready"]["group"] == "panda_arm"
    assert states["ready"]["joint_positions"] == dict(zip(ARM, READY, strict=True))
    # rule 1 of the default tip: the SRDF end effector's parent link (the flange)
    assert body["end_effector"] == "panda_link8"


def test_default_tip_is_the_srdf_end_effector_unless_ee_frame_is_given(tmp_path, urdf: str) -> None:
    with TestClient(create_app(Settings(data_dir=tmp_path))) as c:
        plain = c.post("/robots/urdf", json={"name": "p1", "urdf": urdf, "srdf": SRDF})
        assert plain.status_code == 201, plain.text
        assert plain.json()["end_effector"] == "panda_link8"
        explicit = c.post(
            "/robots/urdf",
            json={"name": "p2", "urdf": urdf, "srdf": SRDF, "ee_frame": "panda_hand_tcp"},
        )
        assert explicit.status_code == 201, explicit.text
        assert explicit.json()["end_effector"] == "panda_hand_tcp"
        # and the stored robot answers with it
        assert c.get("/robots/p1").json()["end_effector"] == "panda_link8"


def test_catalog_panda_lists_its_srdf_groups(client: TestClient) -> None:
    body = client.get("/robots/panda").json()
    groups = {g["name"]: g for g in body["groups"]}
    assert set(groups) == {"arm", "hand", "arm_and_hand"}
    assert groups["arm"]["joints"] == ARM
    assert groups["hand"]["joints"] == ["panda_finger_joint1"]
    assert [s["name"] for s in body["named_states"]] == ["default"]
    assert body["end_effectors"][0]["parent_link"] == "panda_hand_tcp"
    assert body["end_effector"] == "panda_hand_tcp"  # the catalog's configured ee_frame


# ---------------------------------------------------------------------------- FK, Jacobian
def test_fk_with_group_equals_full_q_and_yourdfpy(client: TestClient, reference) -> None:
    rng = np.random.default_rng(16)
    for q7 in random_arm(rng, 20, client):
        grouped = client.post(
            "/robots/lab-panda/fk", json={"q": q7.tolist(), "group": "panda_arm"}
        ).json()
        assert list(grouped["poses"]) == ["panda_link8"]  # the group's tip by default
        full = np.append(q7, 0.0)  # the finger at neutral
        plain = client.post(
            "/robots/lab-panda/fk", json={"q": full.tolist(), "frames": ["panda_link8"]}
        ).json()
        assert grouped["q"] == full.tolist()
        T = matrix(grouped["poses"]["panda_link8"])
        np.testing.assert_array_equal(T, matrix(plain["poses"]["panda_link8"]))
        np.testing.assert_allclose(T, ref_pose(reference, full, "panda_link8"), atol=1e-12)


def test_fk_batch_with_group_rows(client: TestClient, reference) -> None:
    qs = random_arm(np.random.default_rng(3), 5, client)
    body = client.post(
        "/robots/lab-panda/fk/batch", json={"configurations": qs.tolist(), "group": "panda_arm"}
    ).json()
    assert body["frame"] == "panda_link8"
    for q7, p in zip(qs, body["positions"], strict=True):
        T = ref_pose(reference, np.append(q7, 0.0), "panda_link8")
        np.testing.assert_allclose(p, T[:3, 3], atol=1e-12)


def test_jacobian_with_group_has_the_group_columns(client: TestClient) -> None:
    q7 = random_arm(np.random.default_rng(5), 1, client)[0]
    body = client.post(
        "/robots/lab-panda/jacobian", json={"q": q7.tolist(), "group": "panda_arm"}
    ).json()
    assert body["joint_names"] == ARM
    assert body["frame"] == "panda_link8"
    J = np.array(body["jacobian"])
    assert J.shape == (6, 7)

    def pose(q: np.ndarray) -> np.ndarray:
        out = client.post(
            "/robots/lab-panda/fk", json={"q": [*q.tolist(), 0.0], "frames": ["panda_link8"]}
        ).json()
        return matrix(out["poses"]["panda_link8"])

    h = 1e-6
    for i in range(7):
        dq = np.zeros(7)
        dq[i] = h
        Tp, Tm = pose(q7 + dq), pose(q7 - dq)
        v = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
        w = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * h)
        np.testing.assert_allclose(J[:3, i], v, atol=1e-7)
        np.testing.assert_allclose(J[3:, i], w, atol=1e-7)


def test_analysis_velocity_and_collisions_take_the_group(client: TestClient) -> None:
    q7 = random_arm(np.random.default_rng(9), 1, client)[0].tolist()
    full = [*q7, 0.0]
    man = client.post("/robots/lab-panda/manipulability", json={"q": q7, "group": "panda_arm"})
    assert man.status_code == 200, man.text
    assert man.json()["joints"] == ARM and man.json()["frame"] == "panda_link8"
    batch = client.post(
        "/robots/lab-panda/manipulability/batch",
        json={"configurations": [q7], "group": "panda_arm"},
    ).json()
    assert batch["yoshikawa"][0] == pytest.approx(man.json()["yoshikawa"], rel=1e-12)
    statics = client.post(
        "/robots/lab-panda/statics",
        json={"q": q7, "group": "panda_arm", "wrench": [0, 0, 10, 0, 0, 0]},
    ).json()
    assert statics["joint_names"] == ARM and len(statics["torques"]) == 7
    jac = np.array(
        client.post("/robots/lab-panda/jacobian", json={"q": q7, "group": "panda_arm"}).json()[
            "jacobian"
        ]
    )
    np.testing.assert_allclose(statics["torques"], jac.T @ [0, 0, 10, 0, 0, 0], atol=1e-12)
    qdot = [0.1, -0.2, 0.3, 0.0, 0.5, -0.1, 0.2]
    vel = client.post(
        "/robots/lab-panda/velocity",
        json={"q": q7, "group": "panda_arm", "joint_velocities": qdot},
    ).json()
    np.testing.assert_allclose(vel["twist"], jac @ qdot, atol=1e-12)
    inv = client.post(
        "/robots/lab-panda/velocity",
        json={
            "q": full,
            "group": "hand",
            "frame": "panda_leftfinger",
            "twist": [0, 0.1, 0, 0, 0, 0],
        },
    ).json()
    assert [i for i, v in enumerate(inv["joint_velocities"]) if v != 0.0] == [7]  # finger only
    one = client.post("/robots/lab-panda/collisions", json={"q": q7, "group": "panda_arm"})
    assert one.status_code == 200, one.text
    same = client.post("/robots/lab-panda/collisions", json={"q": full}).json()
    assert one.json()["q"] == full and one.json()["in_collision"] == same["in_collision"]
    many = client.post(
        "/robots/lab-panda/collisions/batch", json={"configurations": [q7], "group": "panda_arm"}
    ).json()
    assert many["in_collision"] == [same["in_collision"]]


# ---------------------------------------------------------------------------- IK
def test_ik_on_panda_arm_solves_random_reachable_targets(client: TestClient, reference) -> None:
    """≥ 99.9 % of 1000 targets (FK of random configurations within the limits), from a
    7-value seed (the arm's joints only, as a MoveIt client sends it); capped by iterations,
    not by the clock."""
    qs = random_arm(np.random.default_rng(2026), 1000, client)
    targets = []
    for q7 in qs:
        T = ref_pose(reference, np.append(q7, 0.0), "panda_link8")
        quat = pin.Quaternion(T[:3, :3]).coeffs().tolist()
        targets.append({"position": T[:3, 3].tolist(), "orientation": quat})
    resp = client.post(
        "/robots/lab-panda/ik/batch",
        json={
            "targets": targets,
            "group": "panda_arm",
            "seed": [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785],
            "chain_seeds": False,
            "timeout_ms": 10_000,
            "max_iterations": 5000,
        },
    )
    assert resp.status_code == 200, resp.text
    body = resp.json()
    assert body["frame"] == "panda_link8"
    assert body["solved"] >= 999, body["solved"]
    for item, target in zip(body["results"], targets, strict=True):
        assert len(item["q"]) == 8
        assert item["q"][7] == 0.02  # the finger stays at the seed (middle of its range)
        if item["success"]:
            T = ref_pose(reference, np.array(item["q"]), "panda_link8")
            assert np.linalg.norm(T[:3, 3] - target["position"]) < 2e-5
            R = pin.Quaternion(np.array(target["orientation"])).matrix()
            assert np.linalg.norm(pin.log3(R.T @ T[:3, :3])) < 2e-5


def test_ik_with_a_seven_value_seed_keeps_the_finger(client: TestClient, reference) -> None:
    q7 = random_arm(np.random.default_rng(11), 2, client)
    T = ref_pose(reference, np.append(q7[0], 0.0), "panda_link8")
    target = {
        "position": T[:3, 3].tolist(),
        "orientation": pin.Quaternion(T[:3, :3]).coeffs().tolist(),
    }
    body = client.post(
        "/robots/lab-panda/ik",
        json={"target": target, "group": "panda_arm", "seed": q7[1].tolist(), "timeout_ms": 2000},
    ).json()
    assert body["success"] and body["frame"] == "panda_link8"
    assert body["q"][7] == 0.02 and body["joint_positions"]["panda_finger_joint1"] == 0.02
    full = [*q7[1].tolist(), 0.031]
    body = client.post(
        "/robots/lab-panda/ik",
        json={"target": target, "group": "panda_arm", "seed": full, "timeout_ms": 2000},
    ).json()
    assert body["success"] and body["q"][7] == 0.031
    Tq = ref_pose(reference, np.array(body["q"]), "panda_link8")
    assert np.linalg.norm(Tq[:3, 3] - T[:3, 3]) < 2e-5


def test_ik_group_moves_only_its_joints(client: TestClient) -> None:
    """Group hand (the finger) placing the finger: the arm joints keep the seed."""
    seed = [0.3, -0.4, 0.1, -2.0, 0.2, 1.4, 0.6, 0.01]
    fk = client.post(
        "/robots/lab-panda/fk",
        json={"q": [*seed[:7], 0.03], "frames": ["panda_leftfinger"]},
    ).json()["poses"]["panda_leftfinger"]
    body = client.post(
        "/robots/lab-panda/ik",
        json={
            "target": {"position": fk["position"]},
            "mode": "position",
            "group": "hand",
            "frame": "panda_leftfinger",
            "seed": seed,
            "timeout_ms": 1000,
        },
    ).json()
    assert body["success"], body
    assert body["q"][:7] == seed[:7]
    assert body["q"][7] == pytest.approx(0.03, abs=1e-5)


def test_named_state_seed_sets_its_joints(client: TestClient) -> None:
    """The seed "ready" is the solution when the target is ready's own pose (no move)."""
    fk = client.post("/robots/lab-panda/fk", json={"q": READY, "group": "panda_arm"}).json()[
        "poses"
    ]["panda_link8"]
    body = client.post(
        "/robots/lab-panda/ik",
        json={
            "target": {"position": fk["position"], "orientation": fk["orientation"]},
            "group": "panda_arm",
            "seed": "ready",
        },
    )
    assert body.status_code == 200, body.text
    np.testing.assert_allclose(body.json()["q"][:7], READY, atol=1e-6)


# ---------------------------------------------------------------------------- errors
def test_unknown_group_is_422_listing_the_groups(client: TestClient) -> None:
    for path, extra in (
        ("fk", {"q": READY}),
        ("jacobian", {"q": READY}),
        ("ik", {"target": {"position": [0.3, 0, 0.5]}, "mode": "position"}),
        ("fk/batch", {"configurations": [READY]}),
    ):
        resp = client.post(f"/robots/lab-panda/{path}", json={**extra, "group": "arm"})
        body = problem(resp, 422)
        assert body["field"] == "group", path
        assert "panda_arm" in body["detail"] and "panda_arm_hand" in body["detail"]


def test_unknown_named_state_is_422_listing_the_states(client: TestClient) -> None:
    resp = client.post(
        "/robots/lab-panda/ik",
        json={"target": {"position": [0.3, 0, 0.5]}, "mode": "position", "seed": "home"},
    )
    body = problem(resp, 422)
    assert body["field"] == "seed" and "'ready'" in body["detail"] and "'open'" in body["detail"]


def test_wrong_length_with_a_group_is_422(client: TestClient) -> None:
    for q in (READY[:6], [*READY, 0.0, 0.0]):
        body = problem(
            client.post("/robots/lab-panda/fk", json={"q": q, "group": "panda_arm"}), 422
        )
        assert body["field"] == "q"
        assert "7 values" in body["detail"] and "8" in body["detail"]
    # without a group, 7 values are still refused
    assert problem(client.post("/robots/lab-panda/fk", json={"q": READY}), 422)["field"] == "q"
    body = problem(
        client.post(
            "/robots/lab-panda/ik",
            json={"target": {"position": [0.3, 0, 0.5]}, "mode": "position",
                  "group": "panda_arm", "seed": READY[:5]},
        ),
        422,
    )  # fmt: skip
    assert body["field"] == "seed"


@pytest.mark.parametrize(
    ("srdf", "needle"),
    [
        ('<group name="g"><joint name="nope"/></group>', "<joint name='nope'>"),
        ('<group name="g"><link name="nope"/></group>', "<link name='nope'>"),
        ('<group name="g"><group name="nope"/></group>', "subgroup <group name='nope'>"),
        (
            '<group name="a"><group name="b"/></group><group name="b"><group name="a"/></group>',
            "cycle",
        ),
        (
            '<group name="g"><chain base_link="panda_link8" tip_link="panda_link0"/></group>',
            "not above",
        ),
        (
            '<group_state name="s" group="nope"><joint name="panda_joint1" value="0"/>'
            "</group_state>",
            "group 'nope'",
        ),
        (
            '<group_state name="s"><joint name="nope" value="0"/></group_state>',
            "<joint name='nope'>",
        ),
        (
            '<group_state name="s"><joint name="panda_joint4" value="0.5"/></group_state>',
            "beyond the joint's limits",
        ),
        (
            '<end_effector name="e" parent_link="nope" group="g"/><group name="g"/>',
            "parent_link 'nope'",
        ),
    ],
)
def test_bad_srdf_semantics_are_422_and_store_nothing(
    client: TestClient, urdf: str, srdf: str, needle: str
) -> None:
    resp = client.post(
        "/robots/urdf",
        json={"name": "bad-panda", "urdf": urdf, "srdf": f'<robot name="p">{srdf}</robot>'},
    )
    body = problem(resp, 422)
    assert body["field"] == "srdf"
    assert needle in body["detail"], body["detail"]
    assert client.get("/robots/bad-panda").status_code == 404
