"""Routes: /manipulability, /manipulability/batch, /statics (references: /jacobian, NumPy)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.kinematics.models import RobotModel
from tests.kinematics.chains import L1, L2, planar2_urdf

Q_UR5 = [0.1, -1.0, 1.3, -0.4, 0.8, 0.2]


@pytest.fixture
def planar_client(client, app):
    """The client with a hand-written planar 2-link arm registered as ``planar2_test``."""
    reg = app.state.registry
    reg._cache["planar2_test"] = RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")
    return client


def jacobian(client, robot, q, frame=None, reference="world"):
    body = {"q": q, "reference": reference}
    if frame:
        body["frame"] = frame
    r = client.post(f"/robots/{robot}/jacobian", json=body)
    assert r.status_code == 200, r.text
    return np.array(r.json()["jacobian"])


def test_manipulability_planar_closed_form(planar_client):
    for t2 in (0.4, -1.3, 2.5):
        r = planar_client.post(
            "/robots/planar2_test/manipulability", json={"q": [0.2, t2], "rows": ["vx", "vy"]}
        )
        assert r.status_code == 200, r.text
        b = r.json()
        assert b["yoshikawa"] == pytest.approx(L1 * L2 * abs(math.sin(t2)), rel=1e-12)
        assert b["singular"] is False and b["rank"] == 2 and b["lost_directions"] == []
        assert b["rows"] == ["vx", "vy"] and b["joints"] == ["j1", "j2"]


def test_manipulability_planar_singular(planar_client):
    r = planar_client.post(
        "/robots/planar2_test/manipulability",
        json={"joint_positions": {"j1": 0.5, "j2": 0.0}, "rows": [0, 1]},
    )
    b = r.json()
    assert r.status_code == 200 and b["singular"] is True and b["rank"] == 1
    (u,) = b["lost_directions"]
    assert abs(abs(u[0] * math.cos(0.5) + u[1] * math.sin(0.5)) - 1) < 1e-12
    assert b["force_ellipsoid"]["half_lengths"][1] is None
    assert b["condition_number"] is None
    assert b["dependent_joints"] == ["j1", "j2"]


def test_manipulability_against_numpy_svd(client):
    J = jacobian(client, "ur5", Q_UR5)
    r = client.post("/robots/ur5/manipulability", json={"q": Q_UR5, "part": "translation"})
    b = r.json()
    s = np.linalg.svd(J[:3], compute_uv=False)
    np.testing.assert_allclose(b["singular_values"], s, rtol=1e-12)
    assert b["yoshikawa"] == pytest.approx(np.prod(s), rel=1e-12)
    assert b["inverse_condition"] == pytest.approx(s[-1] / s[0], rel=1e-12)
    assert b["condition_number"] == pytest.approx(s[0] / s[-1], rel=1e-12)
    assert b["det_jjt"] == pytest.approx(np.linalg.det(J[:3] @ J[:3].T), rel=1e-9)
    np.testing.assert_allclose(b["velocity_ellipsoid"]["half_lengths"], s, rtol=1e-12)
    np.testing.assert_allclose(b["force_ellipsoid"]["half_lengths"], 1 / s, rtol=1e-12)


def test_manipulability_batch(client):
    qs = [Q_UR5, [0.0, -1.2, 1.0, 0.3, 0.0, 0.1]]  # second: wrist singular (q5 = 0)
    r = client.post("/robots/ur5/manipulability/batch", json={"configurations": qs})
    assert r.status_code == 200, r.text
    b = r.json()
    for i, q in enumerate(qs):
        s = np.linalg.svd(jacobian(client, "ur5", q), compute_uv=False)
        assert b["yoshikawa"][i] == pytest.approx(np.prod(s), rel=1e-9, abs=1e-14)
        assert b["min_singular_value"][i] == pytest.approx(s[-1], abs=1e-13)
    assert b["singular"] == [False, True] and b["condition_number"][1] is None


def test_statics_matches_jacobian_transpose(client):
    F = [3.0, -2.0, 10.0, 0.5, 0.1, -0.3]
    for ref in ("world", "local"):
        J = jacobian(client, "ur5", Q_UR5, reference=ref)
        r = client.post("/robots/ur5/statics", json={"q": Q_UR5, "wrench": F, "reference": ref})
        assert r.status_code == 200, r.text
        tau = r.json()["torques"]
        np.testing.assert_allclose(tau, J.T @ np.array(F), atol=1e-12)
        back = client.post(
            "/robots/ur5/statics", json={"q": Q_UR5, "torques": tau, "reference": ref}
        ).json()
        np.testing.assert_allclose(back["wrench"], F, atol=1e-9)
        assert back["residual_norm"] < 1e-9


def test_statics_planar_residual(planar_client):
    """A planar arm cannot produce z torque profiles: τ is matched, the wrench is min-norm."""
    r = planar_client.post(
        "/robots/planar2_test/statics", json={"q": [0.3, 0.9], "torques": [1.0, -2.0]}
    )
    b = r.json()
    J = jacobian(planar_client, "planar2_test", [0.3, 0.9])
    np.testing.assert_allclose(b["wrench"], np.linalg.lstsq(J.T, [1.0, -2.0])[0], atol=1e-12)
    assert b["residual_norm"] < 1e-12


@pytest.mark.parametrize(
    ("path", "body", "status", "field"),
    [
        ("manipulability", {"q": Q_UR5, "part": "full", "rows": ["vx"]}, 422, "rows"),
        ("manipulability", {"q": Q_UR5, "rows": ["vx", "vx"]}, 422, "rows.1"),
        ("manipulability", {"q": Q_UR5, "rows": [False]}, 422, "rows.0"),
        ("manipulability", {"q": Q_UR5, "rows": ["vx", True]}, 422, "rows.1"),
        ("manipulability", {"q": Q_UR5, "rows": ["speed"]}, 422, "rows.0"),
        ("manipulability", {"q": Q_UR5, "rows": [9]}, 422, "rows.0"),
        ("manipulability", {"q": Q_UR5, "rows": []}, 422, "rows"),
        ("manipulability", {"q": Q_UR5, "part": "elbow"}, 422, "part"),
        ("manipulability", {"q": Q_UR5, "reference": "moon"}, 422, "reference"),
        ("manipulability", {"q": Q_UR5, "relative_tolerance": -1}, 422, "relative_tolerance"),
        ("manipulability", {"q": Q_UR5, "frame": "nope"}, 422, "frame"),
        ("manipulability", {"q": Q_UR5, "frame": "base_link"}, 422, "frame"),
        ("manipulability", {"q": [1.0]}, 422, "q"),
        ("manipulability", {"q": Q_UR5, "bogus": 1}, 422, "bogus"),
        ("manipulability/batch", {"configurations": []}, 422, "configurations"),
        ("manipulability/batch", {"configurations": [[1.0, 2.0]]}, 422, "configurations.0"),
        ("manipulability/batch", {"configurations": [Q_UR5], "rows": ["x"]}, 422, "rows.0"),
        ("statics", {"q": Q_UR5}, 422, "wrench"),
        ("statics", {"q": Q_UR5, "wrench": [0] * 6, "torques": [0] * 6}, 422, "wrench"),
        ("statics", {"q": Q_UR5, "wrench": [0] * 5}, 422, "wrench"),
        ("statics", {"q": Q_UR5, "torques": [0] * 5}, 422, "torques"),
        ("statics", {"q": Q_UR5, "wrench": [0] * 6, "frame": "nope"}, 422, "frame"),
    ],
)
def test_bad_inputs(client, path, body, status, field):
    r = client.post(f"/robots/ur5/{path}", json=body)
    assert r.status_code == status, r.text
    assert r.json()["field"] == field


def test_batch_limit(client, app):
    app.state.settings.max_batch = 2
    r = client.post("/robots/ur5/manipulability/batch", json={"configurations": [Q_UR5] * 3})
    assert r.status_code == 422 and r.json()["field"] == "configurations"


def test_unknown_robot(client):
    r = client.post("/robots/nope/manipulability", json={})
    assert r.status_code == 404 and r.json()["field"] == "robot_id"


def test_batch_body_errors(client):
    url = "/robots/ur5/manipulability/batch"
    r = client.post(url, content=b"{not json", headers={"content-type": "application/json"})
    assert r.status_code == 400 and r.json()["field"] == "body"
    r = client.post(url, json={"configurations": [[True, 0, 0, 0, 0, 0]]})
    assert r.status_code == 422 and r.json()["field"] == "configurations.0.0"
    r = client.post(url, json={"configurations": [Q_UR5], "part": "nope"})
    assert r.status_code == 422 and r.json()["field"] == "part"
    r = client.post(url, json=[1, 2])
    assert r.status_code == 422
    r = client.post(url, json={"configurations": [Q_UR5], "rows": ["vx", "vy"], "frame": "x"})
    assert r.status_code == 422 and r.json()["field"] == "frame"


@pytest.mark.parametrize("t2", [0.5, -2.0, 0.0, math.pi])
def test_registry_planar2_dh_robot(client, t2):
    """The DH built-in planar2 (l1 = 1.0 m, l2 = 0.8 m, frame tool): det J = l1·l2·sin θ2."""
    r = client.post("/robots/planar2/manipulability", json={"q": [0.3, t2], "rows": ["vx", "vy"]})
    assert r.status_code == 200, r.text
    b = r.json()
    assert b["frame"] == "tool"
    assert b["yoshikawa"] == pytest.approx(1.0 * 0.8 * abs(math.sin(t2)), abs=1e-12)
    assert b["singular"] is (math.sin(t2) ** 2 < 1e-20)
    if b["singular"]:
        (u,) = b["lost_directions"]
        assert abs(abs(u[0] * math.cos(0.3) + u[1] * math.sin(0.3)) - 1) < 1e-12


def test_registry_planar3r_task_rows(client):
    """Planar 3R on (x, y, φ) rows: det J = a1·a2·sin θ2. At θ2 = 0 the joint origins
    o_i = s_i·d lie on one line (s = 0, a1, a1 + a2); Σc_i J_i = 0 needs Σc_i = 0 and
    Σc_i s_i = 0, so the null vector is ∝ (s1 − s2, s2 − s0, s0 − s1) = (−a2, a1 + a2, −a1)."""
    for t2 in (0.7, -1.9):
        r = client.post(
            "/robots/planar3r/manipulability",
            json={"q": [0.2, t2, 0.4], "rows": ["vx", "vy", "wz"]},
        )
        assert r.json()["yoshikawa"] == pytest.approx(1.0 * 0.8 * abs(math.sin(t2)), rel=1e-12)
    b = client.post(
        "/robots/planar3r/manipulability", json={"q": [0.2, 0.0, 0.4], "rows": ["vx", "vy", "wz"]}
    ).json()
    assert b["singular"] is True and b["rank"] == 2
    assert b["dependent_joints"] == ["joint1", "joint2", "joint3"]
    (v,) = b["joint_null_space"]
    expected = np.array([-0.8, 1.8, -1.0]) / np.linalg.norm([-0.8, 1.8, -1.0])
    assert abs(abs(np.dot(v, expected)) - 1) < 1e-12


@pytest.mark.parametrize(
    ("path", "body", "field"),
    [
        ("manipulability", {"q": [0.3, 0.2, 1e308], "part": "translation"}, "q.2"),
        ("manipulability/batch", {"configurations": [[0.2, 0.3, 0.1], [0.2, 0.3, 1e308]]},
         "configurations.1.2"),
        ("statics", {"q": [0.2, 0.3, 0.1], "wrench": [1e300, 0, 0, 0, 0, 0]}, "wrench.0"),
        ("statics", {"q": [0.2, 0.3, 0.1], "torques": [0, -1e13, 0]}, "torques.1"),
    ],
)  # fmt: skip
def test_overflowing_inputs_are_422(client, path, body, field):
    """A prismatic joint at 1e308 m overflows positions: a 422 naming the field, not nulls."""
    r = client.post(f"/robots/rrp/{path}", json=body)
    assert r.status_code == 422, r.text
    assert r.json()["field"] == field
