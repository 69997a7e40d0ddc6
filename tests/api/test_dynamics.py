"""The dynamics endpoints over HTTP: POST /robots/{id}/dynamics, /dynamics/batch and
/dynamics/max_payload.

References independent of the service: the vertical 2-link arm in closed form (Spong,
Hutchinson & Vidyasagar §7.4, uploaded as a URDF), the statics endpoint's τ = Jᵀ·F, the max
payload's joint bounds solved by hand on that arm, and the single endpoint for the batch;
then every bad input of the new fields (422 naming the field, never a 500).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem
from tests.kinematics.chains import C1, C2, E1, E2, I1, I2, L1, L2, M1, M2, vertical_2link

G = 9.81
ARM = "vertical2"
Q_UR5 = [0.3, -1.1, 1.4, -0.6, 0.8, 0.2]
#: A DH table without inertias: its moving links carry none.
DH_NO_INERTIA = {
    "name": "lab_rr_bare",
    "convention": "standard",
    "joints": [
        {"name": "j1", "type": "revolute", "a": 0.4, "alpha": 0, "d": 0, "theta": 0},
        {"name": "j2", "type": "revolute", "a": 0.3, "alpha": 0, "d": 0, "theta": 0},
    ],
}


@pytest.fixture(scope="module")
def client(tmp_path_factory: pytest.TempPathFactory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("dynamics"), max_batch=50)
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        r = c.post("/robots/urdf", json={"name": ARM, "urdf": vertical_2link(), "ee_frame": "tip"})
        assert r.status_code == 201, r.text
        assert c.post("/robots/dh", json=DH_NO_INERTIA).status_code == 201
        yield c


def closed_form(q, qd, qdd):
    """Spong §7.4: M, C (Christoffel), g and τ of the vertical 2-link arm (angles from the
    horizontal, links along x, centres of mass C1, C2 along the links)."""
    c1, c12, c2, s2 = math.cos(q[0]), math.cos(q[0] + q[1]), math.cos(q[1]), math.sin(q[1])
    m11 = M1 * C1**2 + M2 * (L1**2 + C2**2 + 2 * L1 * C2 * c2) + I1 + I2
    m12 = M2 * (C2**2 + L1 * C2 * c2) + I2
    M = np.array([[m11, m12], [m12, M2 * C2**2 + I2]])
    h = -M2 * L1 * C2 * s2
    C = np.array([[h * qd[1], h * (qd[0] + qd[1])], [-h * qd[0], 0.0]])
    g = np.array([(M1 * C1 + M2 * L1) * G * c1 + M2 * C2 * G * c12, M2 * C2 * G * c12])
    return M, C, g


def post(client: TestClient, path: str, body: dict, status: int = 200) -> dict:
    r = client.post(path, json=body)
    assert r.status_code == status, r.text
    return r.json()


STATES = [((0.3, -0.8), (1.1, -0.4), (0.5, 2.0)), ((-1.2, 2.1), (-0.7, 1.9), (-1.5, 0.3))]


@pytest.mark.parametrize("q, qd, qdd", STATES)
def test_two_link_closed_form(client, q, qd, qdd):
    M, C, g = closed_form(q, qd, qdd)
    b = post(
        client,
        f"/robots/{ARM}/dynamics",
        {"q": list(q), "velocities": list(qd), "accelerations": list(qdd)},
    )
    qd, qdd = np.array(qd), np.array(qdd)
    tau = M @ qdd + C @ qd + g
    assert b["joint_names"] == ["j1", "j2"]
    np.testing.assert_allclose(b["mass_matrix"], M, atol=1e-12)
    np.testing.assert_allclose(b["coriolis_matrix"], C, atol=1e-12)
    np.testing.assert_allclose(b["gravity_torques"], g, atol=1e-12)
    np.testing.assert_allclose(b["coriolis_torques"], C @ qd, atol=1e-12)
    np.testing.assert_allclose(b["inertial_torques"], M @ qdd, atol=1e-12)
    np.testing.assert_allclose(b["torques"], tau, atol=1e-12)
    assert b["wrench_torques"] == [0.0, 0.0] and b["payload"] is None
    assert b["total_mass"] == pytest.approx(M1 + M2, abs=1e-12)
    com = (M1 * C1 * math.cos(q[0]) + M2 * (L1 * math.cos(q[0]) + C2 * math.cos(sum(q)))) / (
        M1 + M2
    )
    # the links along x, rotating about −y: the arm lifts into +z
    z = (M1 * C1 * math.sin(q[0]) + M2 * (L1 * math.sin(q[0]) + C2 * math.sin(sum(q)))) / (M1 + M2)
    np.testing.assert_allclose(b["center_of_mass"], [com, 0.0, z], atol=1e-12)
    np.testing.assert_allclose(b["effort_limits"], [E1, E2])
    ratios = np.abs(tau) / [E1, E2]
    np.testing.assert_allclose(b["effort_ratios"], ratios, rtol=1e-12)
    assert b["binding_joint"] == ["j1", "j2"][int(np.argmax(ratios))]


def test_maps_equal_lists(client):
    q, qd, qdd = STATES[0]
    as_lists = post(
        client,
        f"/robots/{ARM}/dynamics",
        {"q": list(q), "velocities": list(qd), "accelerations": list(qdd)},
    )
    as_maps = post(
        client,
        f"/robots/{ARM}/dynamics",
        {
            "joint_positions": {"j2": q[1], "j1": q[0]},
            "velocities": {"j2": qd[1], "j1": qd[0]},
            "accelerations": {"j1": qdd[0], "j2": qdd[1]},
        },
    )
    assert as_maps == as_lists
    # a joint not named takes 0
    only_j1 = post(client, f"/robots/{ARM}/dynamics", {"q": list(q), "velocities": {"j1": 1.0}})
    M, C, g = closed_form(q, (1.0, 0.0), (0, 0))
    np.testing.assert_allclose(only_j1["torques"], C @ [1.0, 0.0] + g, atol=1e-12)


def test_payload_at_the_tip_adds_its_weight_and_is_echoed(client):
    """A point mass m with its centre d beyond the tip along the link: g gains
    m·G·[(L1 c1 + (L2+d) c12), (L2+d) c12] (the moment of its weight about each joint)."""
    q, m, d = (0.4, -0.9), 1.7, 0.05
    b = post(
        client,
        f"/robots/{ARM}/dynamics",
        {"q": list(q), "payload": {"mass": m, "com": [d, 0.0, 0.0]}},
    )
    c1, c12 = math.cos(q[0]), math.cos(sum(q))
    extra = m * G * np.array([L1 * c1 + (L2 + d) * c12, (L2 + d) * c12])
    np.testing.assert_allclose(b["gravity_torques"], closed_form(q, (0, 0), (0, 0))[2] + extra)
    assert b["payload"] == {
        "mass": m,
        "frame": "tip",
        "com": [d, 0.0, 0.0],
        "inertia": [0.0] * 6,
    }
    assert b["total_mass"] == pytest.approx(M1 + M2 + m, abs=1e-12)


def test_payload_inertia_adds_to_the_mass_matrix(client):
    """A payload's rotational inertia iyy about its centre at the tip adds iyy to every
    entry of M (both joints turn it about y) and m·(distance)² terms."""
    q, m, iyy = (0.2, 0.7), 0.5, 0.03
    body = {"q": list(q), "payload": {"mass": m, "inertia": [0.02, 0, 0, iyy, 0, 0.015]}}
    b = post(client, f"/robots/{ARM}/dynamics", body)
    M = closed_form(q, (0, 0), (0, 0))[0]
    r1 = math.hypot(L1 + L2 * math.cos(q[1]), L2 * math.sin(q[1]))  # tip from joint 1
    dot = L2 * (L1 * math.cos(q[1]) + L2)  # (tip − o1)·(tip − o2)
    M += np.array([[m * r1**2, m * dot], [m * dot, m * L2**2]]) + iyy
    np.testing.assert_allclose(b["mass_matrix"], M, atol=1e-12)
    assert b["payload"]["inertia"] == [0.02, 0, 0, iyy, 0, 0.015]


def test_wrench_adds_the_statics_torques(client):
    F = [3.0, -2.0, 10.0, 0.5, 0.1, -0.3]
    for ref, frame in (("world", None), ("local", "wrist_2_link")):
        wrench = {"values": F, "reference": ref, **({"frame": frame} if frame else {})}
        dyn = post(client, "/robots/ur5/dynamics", {"q": Q_UR5, "wrench": wrench})
        statics = post(
            client,
            "/robots/ur5/statics",
            {"q": Q_UR5, "wrench": F, "reference": ref, **({"frame": frame} if frame else {})},
        )
        plain = post(client, "/robots/ur5/dynamics", {"q": Q_UR5})
        np.testing.assert_allclose(dyn["wrench_torques"], statics["torques"], atol=1e-12)
        np.testing.assert_allclose(
            dyn["torques"], np.add(plain["torques"], statics["torques"]), atol=1e-12
        )


def test_group_restricts_the_answer(client):
    """Panda's `arm` group: the 7 arm joints; every vector and matrix is the full answer's
    restriction (the finger at its neutral value and at rest)."""
    rng = np.random.default_rng(3)
    q, qd, qdd = rng.uniform(-1, 1, 7), rng.normal(size=7), rng.normal(size=7)
    full = post(
        client,
        "/robots/panda/dynamics",
        {
            "q": [*q, 0.0],
            "velocities": [*qd, 0.0],
            "accelerations": [*qdd, 0.0],
            "payload": {"mass": 1.0},
        },
    )
    arm = post(
        client,
        "/robots/panda/dynamics",
        {
            "q": q.tolist(),
            "group": "arm",
            "velocities": qd.tolist(),
            "accelerations": qdd.tolist(),
            "payload": {"mass": 1.0},
        },
    )
    assert arm["joint_names"] == full["joint_names"][:7]
    for key in ("torques", "gravity_torques", "coriolis_torques", "effort_limits"):
        assert arm[key] == full[key][:7], key
    assert arm["mass_matrix"] == [row[:7] for row in full["mass_matrix"][:7]]
    assert arm["coriolis_matrix"] == [row[:7] for row in full["coriolis_matrix"][:7]]
    ratios = np.array(full["effort_ratios"][:7])
    assert arm["binding_joint"] == arm["joint_names"][int(np.argmax(ratios))]
    # the payload's default frame: the group's tip (the SRDF's arm ends at the hand's TCP)
    assert arm["payload"]["frame"] == full["payload"]["frame"] == "panda_hand_tcp"


def test_batch_matches_single(client):
    rng = np.random.default_rng(5)
    qs, qds, qdds = rng.uniform(-2, 2, (4, 6)), rng.normal(size=(4, 6)), rng.normal(size=(4, 6))
    pl = {"mass": 2.0, "com": [0.0, 0.0, 0.1]}
    b = post(
        client,
        "/robots/ur5/dynamics/batch",
        {
            "configurations": qs.tolist(),
            "velocities": qds.tolist(),
            "accelerations": qdds.tolist(),
            "payload": pl,
        },
    )
    assert b["payload"]["mass"] == 2.0
    for k in range(4):
        one = post(
            client,
            "/robots/ur5/dynamics",
            {
                "q": qs[k].tolist(),
                "velocities": qds[k].tolist(),
                "accelerations": qdds[k].tolist(),
                "payload": pl,
            },
        )
        np.testing.assert_allclose(b["torques"][k], one["torques"], atol=1e-12)
        np.testing.assert_allclose(b["gravity_torques"][k], one["gravity_torques"], atol=1e-12)
    # without rates the torques are the gravity torques
    rest = post(client, "/robots/ur5/dynamics/batch", {"configurations": qs.tolist()})
    assert rest["torques"] == rest["gravity_torques"]


def test_batch_with_a_group(client):
    rng = np.random.default_rng(9)
    qs, qds = rng.uniform(-1, 1, (3, 7)), rng.normal(size=(3, 7))
    b = post(
        client,
        "/robots/panda/dynamics/batch",
        {"configurations": qs.tolist(), "velocities": qds.tolist(), "group": "arm"},
    )
    assert len(b["joint_names"]) == 7
    for k in range(3):
        one = post(
            client,
            "/robots/panda/dynamics",
            {"q": qs[k].tolist(), "velocities": qds[k].tolist(), "group": "arm"},
        )
        np.testing.assert_allclose(b["torques"][k], one["torques"], atol=1e-12)


def hand_bounds(q):
    """Each joint's largest point payload at the tip of the vertical arm at rest, by hand:
    joint i holds |g_i + m·b_i| ≤ E_i with b the weight's lever G·(horizontal distance)."""
    g = closed_form(q, (0, 0), (0, 0))[2]
    c1, c12 = math.cos(q[0]), math.cos(sum(q))
    b = G * np.array([L1 * c1 + L2 * c12, L2 * c12])
    out = []
    for gi, bi, e in zip(g, b, (E1, E2), strict=True):
        out.append((e - gi) / bi if bi > 0 else (e + gi) / -bi)
    return np.array(out)


def test_max_payload_at_one_configuration(client):
    q = [0.2, 0.3]
    b = post(client, f"/robots/{ARM}/dynamics/max_payload", {"q": q})
    bounds = hand_bounds(q)
    assert b["max_payload"] == pytest.approx(bounds.min(), rel=1e-12)
    assert b["limiting_joint"] == ["j1", "j2"][int(np.argmin(bounds))]
    assert b["per_joint"] == pytest.approx(dict(zip(["j1", "j2"], bounds, strict=True)))
    assert b["holds_itself"] and b["frame"] == "tip"
    limit = [E1, E2][int(np.argmin(bounds))]
    assert abs(b["torques_at_max"][int(np.argmin(bounds))]) == pytest.approx(limit)
    assert b["samples"] is None and b["min_sample"] is None


def test_max_payload_along_a_path_finds_the_minimum(client):
    # the last two reach back past the vertical: levers (and b_i) of either sign
    path = [[0.2, 0.3], [0.0, 0.0], [0.9, -0.4], [1.2, 0.5], [2.0, 0.3]]
    b = post(client, f"/robots/{ARM}/dynamics/max_payload", {"path": path})
    masses = [hand_bounds(q).min() for q in path]
    for q, sample in zip(path, b["samples"], strict=True):
        assert list(sample["per_joint"].values()) == pytest.approx(hand_bounds(q), rel=1e-12)
    k = int(np.argmin(masses))
    assert b["min_sample"] == k == 1  # stretched out horizontally
    assert b["min_max_payload"] == pytest.approx(masses[k], rel=1e-12)
    assert b["max_payload"] == b["min_max_payload"]
    assert [s["max_payload"] for s in b["samples"]] == pytest.approx(masses, rel=1e-12)
    assert b["limiting_joint"] == b["samples"][k]["limiting_joint"]


def test_max_payload_straight_up_is_unbounded(client):
    """Pointing straight up the weight passes through both axes: no joint is loaded (null)."""
    b = post(client, f"/robots/{ARM}/dynamics/max_payload", {"q": [math.pi / 2, 0.0]})
    assert b["max_payload"] is None and b["limiting_joint"] is None
    assert b["per_joint"] == {"j1": None, "j2": None}


def test_max_payload_with_a_tool_attached(client):
    """A tool of mass t at the tip: the payload bound drops by exactly t."""
    q, t = [0.2, 0.3], 1.5
    plain = post(client, f"/robots/{ARM}/dynamics/max_payload", {"q": q})
    tooled = post(client, f"/robots/{ARM}/dynamics/max_payload", {"q": q, "payload": {"mass": t}})
    assert tooled["max_payload"] == pytest.approx(plain["max_payload"] - t, rel=1e-12)


def test_effort_limits_null_where_the_urdf_gives_none(client):
    urdf = vertical_2link().replace(f'effort="{E2}"', 'effort="0"')
    assert client.post("/robots/urdf", json={"name": "nolimit", "urdf": urdf}).status_code == 201
    b = post(client, "/robots/nolimit/dynamics", {"q": [0.1, 0.2]})
    assert b["effort_limits"][1] is None and b["effort_ratios"][1] is None
    assert b["binding_joint"] == "j1"


def test_missing_inertia(client):
    for path, body in (
        ("dynamics", {"q": [0.1, 0.2]}),
        ("dynamics/batch", {"configurations": [[0.1, 0.2]]}),
        ("dynamics/max_payload", {"q": [0.1, 0.2]}),
    ):
        r = client.post(f"/robots/lab_rr_bare/{path}", json=body)
        p = problem(r, 422)
        assert p["type"].endswith("missing-inertia"), p
        assert "'link_1'" in p["detail"], p


NAN = float("nan")
BAD = [
    ("dynamics", {"q": Q_UR5, "velocities": [1.0, 2.0]}, "velocities"),
    ("dynamics", {"q": Q_UR5, "velocities": [0, 0, 0, NAN, 0, 0]}, "velocities.3"),
    ("dynamics", {"q": Q_UR5, "velocities": [0, 0, 0, 2e6, 0, 0]}, "velocities.3"),
    ("dynamics", {"q": Q_UR5, "velocities": {"elbw": 1.0}}, "velocities.elbw"),
    ("dynamics", {"q": Q_UR5, "velocities": ["a", 0, 0, 0, 0, 0]}, "velocities.0"),
    ("dynamics", {"q": Q_UR5, "velocities": "fast"}, "velocities"),
    ("dynamics", {"q": Q_UR5, "velocities": {"elbow_joint": NAN}}, "velocities.elbow_joint"),
    ("dynamics", {"q": Q_UR5, "accelerations": [0.0] * 7}, "accelerations"),
    ("dynamics", {"q": Q_UR5, "accelerations": [0, 0, 0, 0, 0, -1e7]}, "accelerations.5"),
    ("dynamics", {"q": Q_UR5, "accelerations": {"x": 1.0}}, "accelerations.x"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": -1.0}}, "payload.mass"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 2e6}}, "payload.mass"),
    ("dynamics", {"q": Q_UR5, "payload": {}}, "payload.mass"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "com": [0, NAN, 0]}}, "payload.com.1"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "com": [0, 0]}}, "payload.com"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "com": [0, 0, 5e3]}}, "payload.com.2"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "inertia": [1, 0, 0]}}, "payload.inertia"),
    (
        "dynamics",
        {"q": Q_UR5, "payload": {"mass": 1, "inertia": [1, 0, 0, 1, 0, 5]}},
        "payload.inertia",
    ),
    (
        "dynamics",
        {"q": Q_UR5, "payload": {"mass": 1, "inertia": [-1, 0, 0, 1, 0, 1]}},
        "payload.inertia",
    ),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "frame": "nope"}}, "payload.frame"),
    ("dynamics", {"q": Q_UR5, "payload": {"mass": 1, "bogus": 0}}, "payload.bogus"),
    ("dynamics", {"q": Q_UR5, "wrench": {"values": [0.0] * 5}}, "wrench.values"),
    ("dynamics", {"q": Q_UR5, "wrench": {"values": [0.0] * 6, "frame": "x"}}, "wrench.frame"),
    (
        "dynamics",
        {"q": Q_UR5, "wrench": {"values": [0.0] * 6, "reference": "moon"}},
        "wrench.reference",
    ),
    ("dynamics", {"q": Q_UR5, "group": "arm"}, "group"),
    ("dynamics", {"q": [0.1]}, "q"),
    ("dynamics/batch", {"configurations": []}, "configurations"),
    ("dynamics/batch", {"configurations": [[0.0] * 6] * 51}, "configurations"),
    ("dynamics/batch", {"configurations": [[0.0] * 5]}, "configurations.0"),
    ("dynamics/batch", {"configurations": [Q_UR5], "velocities": [Q_UR5] * 2}, "velocities"),
    ("dynamics/batch", {"configurations": [Q_UR5], "velocities": [[0.0] * 5]}, "velocities.0"),
    ("dynamics/batch", {"configurations": [Q_UR5], "velocities": [[NAN] * 6]}, "velocities.0.0"),
    (
        "dynamics/batch",
        {"configurations": [Q_UR5], "accelerations": [[0, 2e6, 0, 0, 0, 0]]},
        "accelerations.0.1",
    ),
    ("dynamics/batch", {"configurations": [Q_UR5], "payload": {"mass": -1}}, "payload.mass"),
    ("dynamics/max_payload", {"q": Q_UR5, "path": [Q_UR5]}, "path"),
    ("dynamics/max_payload", {"path": []}, "path"),
    ("dynamics/max_payload", {"path": [[0.0] * 6] * 51}, "path"),
    ("dynamics/max_payload", {"path": [Q_UR5, [0.0] * 5]}, "path.1"),
    ("dynamics/max_payload", {"q": Q_UR5, "frame": "nope"}, "payload.frame"),
    ("dynamics/max_payload", {"q": Q_UR5, "com": [0, 0, NAN]}, "com.2"),
    ("dynamics/max_payload", {"q": Q_UR5, "payload": {"mass": NAN}}, "payload.mass"),
]


@pytest.mark.parametrize(("path", "body", "field"), BAD, ids=[b[2] for b in BAD])
def test_bad_input_names_the_field(client, path, body, field):
    r = client.post(
        f"/robots/ur5/{path}",
        content=json.dumps(body),
        headers={"content-type": "application/json"},
    )
    problem(r, 422, field)


def test_payload_frame_defaults_to_the_groups_tip(client):
    """Panda's `arm_and_hand` group ends at the left finger (its SRDF tip), not at the
    robot's tip: a payload without a frame hangs there."""
    q = [0.1, -0.4, 0.2, -2.0, 0.3, 1.5, 0.6, 0.02]
    grouped = post(
        client,
        "/robots/panda/dynamics",
        {"q": q, "group": "arm_and_hand", "payload": {"mass": 1.0}},
    )
    explicit = post(
        client,
        "/robots/panda/dynamics",
        {"q": q, "payload": {"mass": 1.0, "frame": "panda_leftfinger"}},
    )
    at_tip = post(client, "/robots/panda/dynamics", {"q": q, "payload": {"mass": 1.0}})
    assert grouped["payload"]["frame"] == "panda_leftfinger"
    assert grouped["gravity_torques"] == explicit["gravity_torques"]
    assert grouped["gravity_torques"] != at_tip["gravity_torques"]


def test_a_mimic_followers_rate_must_follow_its_leader(client):
    """A ROS JointState names the Panda's second finger too: accepted at multiplier × the
    leader's rate (the same answer as without it), refused otherwise naming it."""
    q = [0.1, -0.4, 0.2, -2.0, 0.3, 1.5, 0.6, 0.02]
    leader = {"panda_finger_joint1": 0.2}
    alone = post(client, "/robots/panda/dynamics", {"q": q, "velocities": leader})
    both = {**leader, "panda_finger_joint2": 0.2}
    assert post(client, "/robots/panda/dynamics", {"q": q, "velocities": both}) == alone
    bad = {**leader, "panda_finger_joint2": 0.3}
    r = client.post("/robots/panda/dynamics", json={"q": q, "accelerations": bad})
    problem(r, 422, "accelerations.panda_finger_joint2")
