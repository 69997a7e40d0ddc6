"""POST /robots/{id}/velocity: forward twist against the Jacobian endpoint and FK, inverse."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.fk import forward_kinematics

Q_UR5 = [0.3, -1.0, 1.2, 0.2, 0.5, 0.1]
QDOT = [0.2, -0.1, 0.3, 0.05, -0.4, 0.25]


@pytest.mark.parametrize("reference", ["world", "local"])
def test_forward_equals_jacobian_endpoint_times_qdot(client, reference) -> None:
    J = client.post("/robots/ur5/jacobian", json={"q": Q_UR5, "reference": reference}).json()
    r = client.post(
        "/robots/ur5/velocity",
        json={"q": Q_UR5, "joint_velocities": QDOT, "reference": reference},
    )
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["direction"] == "forward" and out["residual"] is None
    np.testing.assert_allclose(out["twist"], np.array(J["jacobian"]) @ QDOT, atol=1e-12)


def test_forward_matches_finite_differences_of_fk(client, registry) -> None:
    robot = registry.get("ur5")
    q, qd, h = np.array(Q_UR5), np.array(QDOT), 1e-6
    Tp = forward_kinematics(robot, q + h * qd, ["tool0"])["tool0"]
    Tm = forward_kinematics(robot, q - h * qd, ["tool0"])["tool0"]
    v = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
    w = pin.log3(Tp[:3, :3] @ Tm[:3, :3].T) / (2 * h)
    out = client.post("/robots/ur5/velocity", json={"q": Q_UR5, "joint_velocities": QDOT}).json()
    np.testing.assert_allclose(out["twist"], np.concatenate([v, w]), atol=1e-6)


def test_inverse_round_trip(client) -> None:
    twist = [0.05, -0.02, 0.1, 0.2, -0.1, 0.3]
    out = client.post("/robots/ur5/velocity", json={"q": Q_UR5, "twist": twist}).json()
    assert out["direction"] == "inverse"
    assert out["damping"] == 0.0 and out["residual"] < 1e-12 and out["sigma_min"] > 0.01
    back = client.post(
        "/robots/ur5/velocity", json={"q": Q_UR5, "joint_velocities": out["joint_velocities"]}
    ).json()
    np.testing.assert_allclose(back["twist"], twist, atol=1e-12)


def test_inverse_at_a_singularity_reports_damping(client) -> None:
    body = {"q": [0.4, 0.0], "twist": [1, 0, 0, 0, 0, 0], "mode": "position"}
    out = client.post("/robots/planar2/velocity", json=body).json()
    assert out["damping"] > 0.0 and out["sigma_min"] < 1e-12
    assert all(np.isfinite(out["joint_velocities"]))


@pytest.mark.parametrize(
    ("body", "status", "field"),
    [
        ({"q": Q_UR5}, 422, "twist"),
        ({"q": Q_UR5, "twist": [0] * 6, "joint_velocities": [0] * 6}, 422, "twist"),
        ({"q": Q_UR5, "twist": [0] * 5}, 422, "twist"),
        ({"q": Q_UR5, "joint_velocities": [0] * 5}, 422, "joint_velocities"),
        ({"q": Q_UR5[:5], "joint_velocities": [0] * 6}, 422, "q"),
        ({"q": Q_UR5, "twist": [0] * 6, "reference": "world_spatial"}, 422, "reference"),
        ({"q": Q_UR5, "twist": [0] * 6, "frame": "nope"}, 422, "frame"),
        ({"q": Q_UR5, "twist": [0] * 6, "singular_threshold": 0}, 422, "singular_threshold"),
        ({"q": Q_UR5, "twist": [0] * 6, "mode": "all"}, 422, "mode"),
    ],
)
def test_bad_inputs(client, body, status, field) -> None:
    r = client.post("/robots/ur5/velocity", json=body)
    assert r.status_code == status, r.text
    assert r.json()["field"] == field


def test_nan_twist(client) -> None:
    raw = '{"q": [0, 0, 0, 0, 0, 0], "twist": [0, 0, NaN, 0, 0, 0]}'
    r = client.post(
        "/robots/ur5/velocity", content=raw, headers={"content-type": "application/json"}
    )
    assert r.status_code == 422 and r.json()["field"].startswith("twist")
