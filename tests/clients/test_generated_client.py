"""The committed Python client (clients/python, installed by ``make install``) drives a live
server (``python -m app`` on loopback): FK, batch FK, Jacobian, IK, problem answers, the
answers that are not JSON (URDF text, PNG heat map), a write without a token, the NumPy
helpers and the WebSocket stream.

Answers are checked against independent references: the Jacobian against central finite
differences of FK, batch FK against single FK, IK by forward kinematics of its answer, the
quaternion helpers against SciPy's rotations, the PNG by its signature and header, the
stream against the HTTP answers.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator

import numpy as np
import pytest
from denavit_client.api.collisions import create_scene, get_scene
from denavit_client.api.inverse_kinematics import solve_ik
from denavit_client.api.kinematics import compute_fk, compute_fk_batch, compute_jacobian
from denavit_client.api.reachability import (
    build_reachability_map,
    get_reachability_job,
    get_reachability_slice,
)
from denavit_client.api.robots import get_robot, get_robot_file, get_robot_urdf
from denavit_client.api.service import get_health
from denavit_client.arrays import array, matrix_quaternion, pose_lists, pose_matrix, q_list
from denavit_client.client import AuthenticatedClient, Client
from denavit_client.models import (
    BuildRequest,
    FKBatchRequest,
    FKRequest,
    FKResponse,
    IKRequest,
    IKResponse,
    JacobianRequest,
    JacobianResponse,
    JobStatus,
    ObstacleIn,
    ObstacleShape,
    Pose,
    Problem,
    SceneIn,
    SceneOut,
)
from denavit_client.session import connect
from denavit_client.stream import StreamError, open_stream
from denavit_client.types import File
from scipy.spatial.transform import Rotation

from tests.helpers import poll_live, serve

ROBOT = "ur5"
EE = "tool0"


@pytest.fixture(scope="module")
def server(tmp_path_factory) -> Iterator[str]:
    """The base URL of a live server without a token."""
    with serve(tmp_path_factory.mktemp("client-data") / "data", settings={}) as live:
        yield live.url


@pytest.fixture(scope="module")
def api(server: str) -> Iterator[AuthenticatedClient]:
    with connect(server) as client:
        yield client


def fk(api, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position and rotation matrix of the end effector, through the client."""
    out = compute_fk.sync(ROBOT, client=api, body=FKRequest(q=q_list(q), frames=[EE]))
    assert isinstance(out, FKResponse), out
    T = np.array(out.poses[EE].matrix)
    return T[:3, 3], T[:3, :3]


def _random_q(api, n: int, seed: int) -> np.ndarray:
    robot = get_robot.sync(ROBOT, client=api)
    lower = np.array([j.limits.lower for j in robot.joints])
    upper = np.array([j.limits.upper for j in robot.joints])
    rng = np.random.default_rng(seed)
    return rng.uniform(np.maximum(lower, -3.0), np.minimum(upper, 3.0), size=(n, len(lower)))


def _rotation_angle(R: np.ndarray) -> float:
    return float(np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0)))


def test_fk_and_batch_fk(api) -> None:
    qs = _random_q(api, 4, seed=1)
    out = compute_fk_batch.sync(
        ROBOT, client=api, body=FKBatchRequest(configurations=qs.tolist(), frame=EE)
    )
    assert out is not None and not isinstance(out, Problem), out
    for q, position in zip(qs, out.positions, strict=True):
        p, R = fk(api, q)
        np.testing.assert_allclose(position, p, atol=1e-12)
        assert np.allclose(R @ R.T, np.eye(3), atol=1e-12)


def test_jacobian_matches_finite_differences_of_fk(api) -> None:
    q = _random_q(api, 1, seed=2)[0]
    out = compute_jacobian.sync(ROBOT, client=api, body=JacobianRequest(q=q_list(q), frame=EE))
    assert isinstance(out, JacobianResponse), out
    J = array(out.jacobian)
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
    q_true = _random_q(api, 1, seed=3)[0]
    p, R = fk(api, q_true)
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    position, orientation = pose_lists(T)
    body = IKRequest(target=Pose(position=position, orientation=orientation), frame=EE)
    out = solve_ik.sync(ROBOT, client=api, body=body)
    assert isinstance(out, IKResponse), out
    assert out.success, out
    p_sol, R_sol = fk(api, np.array(out.q))
    assert np.linalg.norm(p_sol - p) <= 1e-5
    assert _rotation_angle(R_sol @ R.T) <= 1e-5


def test_pose_helpers_agree_with_scipy_and_the_served_matrix(api) -> None:
    q = _random_q(api, 1, seed=4)[0]
    out = compute_fk.sync(ROBOT, client=api, body=FKRequest(q=q_list(q), frames=[EE]))
    assert isinstance(out, FKResponse)
    pose = out.poses[EE]
    # The helper's matrix (from position and quaternion) is the one the service computed.
    np.testing.assert_allclose(pose_matrix(pose), np.array(pose.matrix), atol=1e-12)
    for seed in range(20):
        R = Rotation.random(random_state=seed)
        quat = matrix_quaternion(R.as_matrix())
        expected = R.as_quat()  # [x, y, z, w], the service's order
        expected = -expected if expected[3] < 0 else expected
        np.testing.assert_allclose(quat, expected, atol=1e-12)
    with pytest.raises(ValueError, match="finite"):
        q_list([0.0, float("nan")])


def test_errors_parse_as_problems(api) -> None:
    response = compute_fk.sync_detailed("no_such_robot", client=api, body=FKRequest(q=[0.0] * 6))
    assert response.status_code == 404
    assert isinstance(response.parsed, Problem)
    assert response.parsed.field == "robot_id"
    bad = compute_fk.sync_detailed(ROBOT, client=api, body=FKRequest(q=[0.0]))
    assert bad.status_code == 422 and isinstance(bad.parsed, Problem)
    assert bad.parsed.field.startswith("q")
    health = get_health.sync(client=api)
    assert health is not None and health.status == "ok"


def test_a_write_needs_no_token_on_a_service_without_one(server: str) -> None:
    """connect() without a token sends no Authorization header; a plain Client works too."""
    box = ObstacleIn(name="b", shape=ObstacleShape.SPHERE, radius=0.1)
    with connect(server) as client:
        assert "authorization" not in client.get_httpx_client().headers
        made = create_scene.sync(client=client, body=SceneIn(name="no_token", obstacles=[box]))
    assert isinstance(made, SceneOut), made
    with Client(base_url=server) as plain:
        assert isinstance(get_scene.sync("no_token", client=plain), SceneOut)


def test_text_and_binary_answers_are_read(api) -> None:
    """The URDF is text; the heat map and a package file are bytes (a PNG: its signature and
    the size in its header)."""
    urdf = get_robot_urdf.sync(ROBOT, client=api)
    assert isinstance(urdf, str) and "<robot" in urdf
    mesh = get_robot_file.sync(ROBOT, "meshes/ur5/collision/base.stl", client=api)
    assert isinstance(mesh, File), mesh
    stl = mesh.payload.read()  # binary STL: 80-byte header, triangle count, 50 bytes each
    assert len(stl) == 84 + 50 * struct.unpack("<I", stl[80:84])[0]
    job = build_reachability_map.sync(
        ROBOT, client=api, body=BuildRequest(samples=500, voxel_size=0.1)
    )
    assert not isinstance(job, Problem) and job is not None, job
    url = str(api.get_httpx_client().base_url).rstrip("/")
    poll_live(f"{url}/robots/{ROBOT}/reachability/jobs/{job.job_id}", lambda j: j["map_id"])
    done = get_reachability_job.sync(ROBOT, job.job_id, client=api)
    assert done is not None and not isinstance(done, Problem)
    assert done.status == JobStatus.DONE and isinstance(done.map_id, str)
    png = get_reachability_slice.sync(ROBOT, done.map_id, client=api, z=0.3, scale=2)
    assert isinstance(png, File), png
    data = png.payload.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    assert width > 0 and height > 0


def test_the_stream_answers_as_the_http_routes(api, server: str) -> None:
    q = _random_q(api, 1, seed=5)[0]
    http = compute_fk.sync(ROBOT, client=api, body=FKRequest(q=q_list(q), frames=[EE]))
    assert isinstance(http, FKResponse)
    with open_stream(server, ROBOT) as stream:
        streamed = stream.fk(FKRequest(q=q_list(q), frames=[EE]))
        assert streamed.poses[EE].matrix == http.poses[EE].matrix
        pose = http.poses[EE]
        # Binary frames: the end effector's pose, then an IK step back to it.
        np.testing.assert_array_equal(stream.fk_pose(q), [*pose.position, *pose.orientation])
        target = pose
        ik = stream.ik(IKRequest(target=target, max_iterations=200))
        assert ik.success
        ok, q_ik, position_error, _ = stream.ik_step(pose.position, pose.orientation)
        assert ok and position_error <= 1e-6
        p_ik, _ = fk(api, q_ik)
        assert np.linalg.norm(p_ik - np.array(pose.position)) <= 1e-6
        J = stream.jacobian_matrix(q)
        http_J = compute_jacobian.sync(ROBOT, client=api, body=JacobianRequest(q=q_list(q)))
        assert isinstance(http_J, JacobianResponse)
        np.testing.assert_array_equal(J, array(http_J.jacobian))
        with pytest.raises(StreamError) as bad:
            stream.fk(FKRequest(q=[0.0]))
        assert bad.value.problem.status == 422 and bad.value.problem.field.startswith("q")
        assert stream.fk(FKRequest(q=q_list(q))).q == http.q  # the socket stays usable
        with pytest.raises(StreamError) as short:  # a 6-number target: the service says why
            stream.ik_step(pose.position[:2], pose.orientation)
        assert short.value.problem.status == 422
        ok, q_again, _, _ = stream.ik_step(pose.position, pose.orientation)
        assert ok and np.linalg.norm(fk(api, q_again)[0] - np.array(pose.position)) <= 1e-6
