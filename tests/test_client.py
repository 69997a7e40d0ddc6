"""A Python client generated from the committed docs/openapi.json (openapi-python-client)
drives a live server (``python -m app`` on loopback): FK, batch FK, Jacobian and IK.

The answers are checked against independent references computed through the client itself:
the Jacobian against central finite differences of FK, batch FK against single FK, the IK
solution by forward kinematics of the returned configuration.
"""

from __future__ import annotations

import importlib
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import serve

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "denavit_client"
ROBOT = "ur5"
EE = "tool0"


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> Iterator[object]:
    """Generate the client package into a temporary directory and import it."""
    out = tmp_path_factory.mktemp("client")
    bin_dir = Path(sys.executable).parent
    done = subprocess.run(
        [
            str(bin_dir / "openapi-python-client"),
            "generate",
            "--path",
            str(ROOT / "docs" / "openapi.json"),
            "--meta",
            "none",
            "--output-path",
            str(out / PACKAGE),
        ],
        env={**os.environ, "PATH": f"{bin_dir}:{os.environ.get('PATH', '')}"},
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    sys.path.insert(0, str(out))
    try:
        yield importlib.import_module(PACKAGE)
    finally:
        sys.path.remove(str(out))
        for name in [m for m in sys.modules if m == PACKAGE or m.startswith(PACKAGE + ".")]:
            del sys.modules[name]


@pytest.fixture(scope="module")
def api(generated, tmp_path_factory):
    """(client, module namespace) against a live server."""
    with serve(tmp_path_factory.mktemp("client-data") / "data", settings={}) as server:
        client = generated.Client(base_url=server.url, timeout=60.0)
        with client:
            yield client


def _mod(name: str):
    return importlib.import_module(f"{PACKAGE}.{name}")


def fk(api, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position and rotation matrix of the end effector, through the generated client."""
    models = _mod("models")
    compute_fk = _mod("api.kinematics.compute_fk")
    out = compute_fk.sync(ROBOT, client=api, body=models.FKRequest(q=q.tolist(), frames=[EE]))
    assert isinstance(out, models.FKResponse), out
    T = np.array(out.poses[EE].matrix)
    return T[:3, 3], T[:3, :3]


def _random_q(api, n: int, seed: int) -> np.ndarray:
    robot = _mod("api.robots.get_robot").sync(ROBOT, client=api)
    lower = np.array([j.limits.lower for j in robot.joints])
    upper = np.array([j.limits.upper for j in robot.joints])
    rng = np.random.default_rng(seed)
    return rng.uniform(np.maximum(lower, -3.0), np.minimum(upper, 3.0), size=(n, len(lower)))


def _rotation_angle(R: np.ndarray) -> float:
    return float(np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0)))


def test_fk_and_batch_fk(api) -> None:
    models = _mod("models")
    batch = _mod("api.kinematics.compute_fk_batch")
    qs = _random_q(api, 4, seed=1)
    out = batch.sync(
        ROBOT, client=api, body=models.FKBatchRequest(configurations=qs.tolist(), frame=EE)
    )
    assert isinstance(out, models.FKBatchResponse), out
    for q, position in zip(qs, out.positions, strict=True):
        p, R = fk(api, q)
        np.testing.assert_allclose(position, p, atol=1e-12)
        assert np.allclose(R @ R.T, np.eye(3), atol=1e-12)


def test_jacobian_matches_finite_differences_of_fk(api) -> None:
    models = _mod("models")
    compute = _mod("api.kinematics.compute_jacobian")
    q = _random_q(api, 1, seed=2)[0]
    out = compute.sync(ROBOT, client=api, body=models.JacobianRequest(q=q.tolist(), frame=EE))
    assert isinstance(out, models.JacobianResponse), out
    J = np.array(out.jacobian)
    assert J.shape == (6, len(q))
    h = 1e-6
    for i in range(len(q)):
        dq = np.zeros_like(q)
        dq[i] = h
        p_plus, R_plus = fk(api, q + dq)
        p_minus, R_minus = fk(api, q - dq)
        np.testing.assert_allclose(J[:3, i], (p_plus - p_minus) / (2 * h), atol=1e-7)
        S = R_plus @ R_minus.T  # rotation over 2h, expressed in world axes
        omega = np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2
        np.testing.assert_allclose(J[3:, i], omega / (2 * h), atol=1e-7)


def test_ik_round_trip(api) -> None:
    models = _mod("models")
    solve = _mod("api.inverse_kinematics.solve_ik")
    q_true = _random_q(api, 1, seed=3)[0]
    p, R = fk(api, q_true)
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    body = models.IKRequest(target=models.Pose(matrix=T.tolist()), frame=EE, timeout_ms=500.0)
    out = solve.sync(ROBOT, client=api, body=body)
    assert isinstance(out, models.IKResponse), out
    assert out.success, out
    p_sol, R_sol = fk(api, np.array(out.q))
    assert np.linalg.norm(p_sol - p) <= 1e-5
    assert _rotation_angle(R_sol @ R.T) <= 1e-5
    # FK's answer, the generated Pose object itself, is an IK target as is.
    compute_fk = _mod("api.kinematics.compute_fk")
    fk_out = compute_fk.sync(
        ROBOT, client=api, body=models.FKRequest(q=q_true.tolist(), frames=[EE])
    )
    assert isinstance(fk_out, models.FKResponse), fk_out
    pose = fk_out.poses[EE]
    assert isinstance(pose, models.Pose)
    body = models.IKRequest(target=pose, frame=EE, timeout_ms=500.0)
    out = solve.sync(ROBOT, client=api, body=body)
    assert isinstance(out, models.IKResponse) and out.success, out
    p_sol, R_sol = fk(api, np.array(out.q))
    assert np.linalg.norm(p_sol - p) <= 1e-5
    assert _rotation_angle(R_sol @ R.T) <= 1e-5


def test_errors_parse_as_problems(api) -> None:
    models = _mod("models")
    compute_fk = _mod("api.kinematics.compute_fk")
    response = compute_fk.sync_detailed(
        "no_such_robot", client=api, body=models.FKRequest(q=[0.0] * 6)
    )
    assert response.status_code == 404
    assert isinstance(response.parsed, models.Problem)
    assert response.parsed.field == "robot_id"
    bad = compute_fk.sync_detailed(ROBOT, client=api, body=models.FKRequest(q=[0.0]))
    assert bad.status_code == 422 and isinstance(bad.parsed, models.Problem)
    assert bad.parsed.field.startswith("q")
    health = _mod("api.service.get_health").sync(client=api)
    assert health.status == "ok"
