"""POST /robots/{id}/ik/path: answers checked by yourdfpy FK against an independent line,
the failure contract, the branch guard, determinism across workers, the error contract."""

from __future__ import annotations

import math

import httpx
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from app.kinematics.collision import collision_filter
from app.kinematics.fk import forward_kinematics
from app.kinematics.obstacles import parse_obstacle
from tests.helpers import problem, serve
from tests.kinematics.reference import pose_error, reference_pose, reference_velocity_limits

UR5_START = [0.1, -1.4, 1.2, -0.5, 1.0, 0.3]
#: A request as a client writes it: one straight line, the step bounds, a seed.
LINE_BODY = {
    "start": UR5_START,
    "frame": "tool0",
    "segments": [
        {"type": "line", "to": {"position": [0.4, 0.2, 0.3], "orientation": [0, 1, 0, 0]}}
    ],
    "max_step": {"position": 0.005, "orientation": 0.02},
    "max_joint_step": 0.1,
    "random_seed": 7,
}
#: A budget that does not depend on the machine's speed.
BUDGET = {"timeout_ms": 100, "max_iterations": 400}


def _pose(registry, robot_id: str, q, frame: str) -> np.ndarray:
    return forward_kinematics(registry.get(robot_id), np.array(q), [frame])[frame]


def _line_pose(T0: np.ndarray, T1: np.ndarray, s: float) -> np.ndarray:
    """The pose at s ∈ [0, 1] of a straight line: position linear, orientation by slerp
    (scipy), independent of the service's own interpolation."""
    r0, r1 = Rotation.from_matrix(T0[:3, :3]), Rotation.from_matrix(T1[:3, :3])
    delta = (r0.inv() * r1).as_rotvec()
    T = np.eye(4)
    T[:3, :3] = (r0 * Rotation.from_rotvec(s * delta)).as_matrix()
    T[:3, 3] = T0[:3, 3] + s * (T1[:3, 3] - T0[:3, 3])
    return T


def _quat(T: np.ndarray) -> list[float]:
    return Rotation.from_matrix(T[:3, :3]).as_quat().tolist()  # [x, y, z, w]


def _check_line(registry, robot_id, frame, out, T0, T1, max_joint_step, tol=1e-5) -> None:
    """Every point on the line at its s (yourdfpy FK), every step within max_joint_step,
    s increasing, the last point at `fraction`."""
    robot = registry.get(robot_id)
    pts = out["points"]
    assert pts and pts[0]["s"] == 0.0
    assert [p["s"] for p in pts] == sorted(p["s"] for p in pts)
    assert pts[-1]["s"] == out["fraction"]
    for a, b in zip(pts, pts[1:], strict=False):
        assert np.abs(np.subtract(b["q"], a["q"])).max() <= max_joint_step + 1e-12
    for p in pts:
        T = reference_pose(robot, np.array(p["q"]), frame)
        dp, dr = pose_error(T, _line_pose(T0, T1, p["s"]))
        assert dp <= tol and dr <= tol, (p["s"], dp, dr)


def test_a_line_request_as_a_client_writes_it(client, registry) -> None:
    r = client.post("/robots/ur5/ik/path", json=LINE_BODY)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["solver_version"] and out["frame"] == "tool0"
    assert out["joint_names"] == registry.get("ur5").joint_names
    assert out["points"][0]["q"] == pytest.approx(UR5_START, abs=1e-15)
    T0 = _pose(registry, "ur5", UR5_START, "tool0")
    T1 = np.eye(4)
    T1[:3, :3] = Rotation.from_quat([0, 1, 0, 0]).as_matrix()
    T1[:3, 3] = [0.4, 0.2, 0.3]
    _check_line(registry, "ur5", "tool0", out, T0, T1, 0.1)
    if out["fraction"] == 1.0:
        assert out["failure"] is None
    else:
        f = out["failure"]
        assert f["reason"] and f["detail"] and f["s"] > out["fraction"]


def test_a_reachable_line_completes_and_is_dense(client, registry) -> None:
    """UR5, 0.3 m straight line with fixed orientation between two poses of nearby
    configurations: complete, every point on the line, and the joint-linear motion between
    neighbours within max_deviation of the line at the middle."""
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    T0 = _pose(registry, "ur5", q0, "tool0")
    T1 = T0.copy()
    T1[:3, 3] += [0.1, 0.25, -0.12]
    body = {
        "start": q0,
        "segments": [
            {"type": "line", "to": {"position": T1[:3, 3].tolist(), "orientation": _quat(T1)}}
        ],
        "max_deviation": {"position": 5e-4, "orientation": 5e-3},
        **BUDGET,
    }
    out = client.post("/robots/ur5/ik/path", json=body).json()
    assert out["fraction"] == 1.0 and out["failure"] is None, out["failure"]
    _check_line(registry, "ur5", "tool0", out, T0, T1, 0.1)
    robot = registry.get("ur5")
    for a, b in zip(out["points"], out["points"][1:], strict=False):
        qm = (np.array(a["q"]) + np.array(b["q"])) / 2
        dp, dr = pose_error(
            reference_pose(robot, qm, "tool0"), _line_pose(T0, T1, (a["s"] + b["s"]) / 2)
        )
        assert dp <= 5e-4 + 1e-9 and dr <= 5e-3 + 1e-9


def test_a_line_out_of_the_workspace_stops_with_its_reason(client, registry) -> None:
    """A line 2 m out: the arm stretches to the edge of its workspace (an elbow singularity)
    and stops there, or at the first point beyond its reach bound."""
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    T0 = _pose(registry, "ur5", q0, "tool0")
    far = (T0[:3, 3] + [2.0, 0.0, 0.0]).tolist()
    body = {
        "start": q0,
        "segments": [{"type": "line", "to": {"position": far, "orientation": _quat(T0)}}],
        **BUDGET,
    }
    out = client.post("/robots/ur5/ik/path", json=body).json()
    assert 0.0 < out["fraction"] < 1.0
    f = out["failure"]
    assert f["reason"] in {"singular", "unreachable"}, f
    assert f["index"] >= 1 and f["s"] > out["fraction"] and f["detail"]
    assert len(f["q"]) == 6
    T1 = T0.copy()
    T1[:3, 3] = far
    _check_line(registry, "ur5", "tool0", out, T0, T1, 0.1)


def test_an_obstacle_on_the_line_stops_the_path_before_it(client, registry) -> None:
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    T0 = _pose(registry, "ur5", q0, "tool0")
    T1 = T0.copy()
    T1[:3, 3] += [0.0, 0.3, 0.0]
    ball = (T0[:3, 3] + [0.0, 0.2, 0.0]).tolist()
    obstacle = {"name": "ball", "shape": "sphere", "radius": 0.03, "pose": {"position": ball}}
    body = {
        "start": q0,
        "segments": [
            {"type": "line", "to": {"position": T1[:3, 3].tolist(), "orientation": _quat(T1)}}
        ],
        "avoid_collisions": True,
        "obstacles": [obstacle],
        **BUDGET,
    }
    out = client.post("/robots/ur5/ik/path", json=body).json()
    f = out["failure"]
    assert f is not None and f["reason"] == "collision", f
    # Stopped before the ball: the tool is still short of its surface (0.2 − 0.03 m along y).
    assert out["fraction"] < 0.2 / 0.3
    free = collision_filter(registry.get("ur5"), (parse_obstacle(obstacle, "obstacle"),))
    assert all(free(np.array(p["q"])) for p in out["points"])
    _check_line(registry, "ur5", "tool0", out, T0, T1, 0.1)


def test_planar2_keeps_the_chosen_elbow(client) -> None:
    """The two elbows of a planar 2-link target carry different branch labels; a path
    started on either keeps it (θ2 keeps its sign), and asking for the other is a 422."""
    ik = {"target": {"position": [1.2, 0.7, 0.0]}, "mode": "position", "num_solutions": 2}
    sols = client.post("/robots/planar2/ik", json=ik).json()["solutions"]
    assert len(sols) == 2 and sols[0]["branch"] != sols[1]["branch"]
    for sol in sols:
        body = {
            "start": sol["q"],
            "mode": "position",
            "branch": sol["branch"],
            "segments": [{"type": "line", "to": {"position": [0.9, -0.6, 0.0]}}],
            **BUDGET,
        }
        out = client.post("/robots/planar2/ik/path", json=body).json()
        assert out["fraction"] == 1.0 and out["branch"] == sol["branch"], out["failure"]
        sign = math.copysign(1.0, sol["q"][1])
        assert all(math.copysign(1.0, p["q"][1]) == sign for p in out["points"])
        other = next(s["branch"] for s in sols if s["branch"] != sol["branch"])
        r = client.post("/robots/planar2/ik/path", json={**body, "branch": other})
        problem(r, 422, "branch")


def test_waypoints_and_position_mode_keep_the_orientation(client, registry) -> None:
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    p0 = _pose(registry, "ur5", q0, "tool0")[:3, 3]
    wps = [{"position": (p0 + d).tolist()} for d in ([0.05, 0, 0], [0.05, 0.05, 0])]
    body = {"start": q0, "mode": "position", "waypoints": wps, **BUDGET}
    out = client.post("/robots/ur5/ik/path", json=body).json()
    assert out["fraction"] == 1.0 and out["mode"] == "position"
    robot = registry.get("ur5")
    ends = [reference_pose(robot, np.array(p["q"]), "tool0")[:3, 3] for p in out["points"]]
    assert np.linalg.norm(ends[-1] - (p0 + [0.05, 0.05, 0])) <= 1e-5


def test_same_random_seed_same_answer_on_two_workers(tmp_path) -> None:
    """A Panda path with random_seed: every answer identical apart from its timing, from
    fresh connections to a two-worker server."""
    body = {
        "start": [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8, 0.02],
        "segments": [
            {"type": "line", "to": {"position": [0.45, 0.15, 0.35], "orientation": [1, 0, 0, 0]}}
        ],
        "random_seed": 11,
        "timeout_ms": 500,
        "max_iterations": 300,
    }
    answers = []
    with serve(tmp_path / "data", "--workers", "2") as srv:
        for _ in range(8):
            with httpx.Client(base_url=srv.url, timeout=60) as c:
                r = c.post("/robots/panda/ik/path", json=body)
                assert r.status_code == 200, r.text
                out = r.json()
                out.pop("solve_time_ms")
                answers.append(out)
    assert all(a == answers[0] for a in answers[1:])
    assert len(answers[0]["points"]) > 2


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"waypoints": [{"position": [0.3, 0.1, 0.3], "orientation": [0, 0, 0, 1]}]}, "segments"),
        ({"segments": None}, "segments"),
        ({"segments": []}, "segments"),
        ({"segments": [{"type": "spline", "to": {"position": [0.3, 0.1, 0.3]}}]}, "segments.0"),
        (
            {"segments": [{"type": "line", "to": {"orientation": [0, 0, 0, 1]}}]},
            "segments.0.to.position",
        ),
        ({"start": [0.1, 0.2]}, "start"),
        ({"start": "nowhere"}, "start"),
        ({"start": {"no_such_joint": 0.1}}, "start.no_such_joint"),
        ({"max_joint_step": 0}, "max_joint_step"),
        ({"max_step": {"position": -0.01}}, "max_step.position"),
        ({"max_deviation": {"orientation": 0}}, "max_deviation.orientation"),
        ({"obstacles": []}, "obstacles"),
        ({"frame": "no_such_frame"}, "frame"),
        ({"timeout_ms": 1e9}, "timeout_ms"),
        ({"branch": "shoulder_left/elbow_sideways/wrist_noflip"}, "branch"),
    ],
)
def test_bad_requests_name_the_field(client, change, field) -> None:
    body = {k: v for k, v in {**LINE_BODY, **change}.items() if v is not None}
    problem(client.post("/robots/ur5/ik/path", json=body), 422, field)


def test_collinear_arc_and_too_many_points_are_422(client, registry) -> None:
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    T0 = _pose(registry, "ur5", q0, "tool0")
    o = _quat(T0)
    p = T0[:3, 3]
    arc = {"type": "arc", "via": {"position": (p + [0.1, 0, 0]).tolist(), "orientation": o},
           "to": {"position": (p + [0.2, 0, 0]).tolist(), "orientation": o}}  # fmt: skip
    problem(
        client.post("/robots/ur5/ik/path", json={"start": q0, "segments": [arc]}),
        422,
        "segments.0.via",
    )
    line = {"type": "line", "to": {"position": (p + [0.3, 0, 0]).tolist(), "orientation": o}}
    body = {"start": q0, "segments": [line], "max_step": {"position": 1e-6}, "timeout_ms": 1000}
    problem(client.post("/robots/ur5/ik/path", json=body), 422, "max_step")


def test_unknown_robot_is_404(client) -> None:
    problem(client.post("/robots/nope/ik/path", json=LINE_BODY), 404)


def test_timing_respects_the_limits_at_every_point(client, registry) -> None:
    """UR5 line with timing: times from 0, increasing; every point's velocity within the
    URDF's limits (read by yourdfpy) and acceleration within the given ones; the mean
    velocity over every interval within the limit too; at rest at both ends."""
    q0 = [0.2, -1.2, 1.4, -1.6, -1.5, 0.3]
    T0 = _pose(registry, "ur5", q0, "tool0")
    to = {"position": (T0[:3, 3] + [0.1, 0.2, -0.1]).tolist(), "orientation": _quat(T0)}
    acc = [2.0, 2.0, 3.0, 4.0, 4.0, 4.0]
    body = {
        "start": q0,
        "segments": [{"type": "line", "to": to}],
        "timing": {"acceleration_limits": acc},
        **BUDGET,
    }
    out = client.post("/robots/ur5/ik/path", json=body).json()
    assert out["fraction"] == 1.0, out["failure"]
    tm = out["timing"]
    vmax = reference_velocity_limits(registry.get("ur5"), out["joint_names"])
    t = np.array(tm["t"])
    q = np.array([p["q"] for p in out["points"]])
    v, a = np.array(tm["velocities"]), np.array(tm["accelerations"])
    assert t.shape == (len(q),) and t[0] == 0.0 and np.all(np.diff(t) >= 0.0)
    assert tm["duration"] == t[-1] > 0.0
    assert np.all(np.abs(v) <= vmax * (1 + 1e-9))
    assert np.all(np.abs(a) <= np.array(acc) * (1 + 1e-9))
    dt = np.diff(t)
    moving = dt > 0
    mean_v = np.abs(np.diff(q, axis=0)[moving]) / dt[moving, None]
    assert np.all(mean_v <= vmax * (1 + 1e-9))
    assert np.abs(v[0]).max() == 0.0 and np.abs(v[-1]).max() <= 1e-9
    # Time-optimal, not merely slow: some joint gets near one of its limits.
    assert max((np.abs(v) / vmax).max(), (np.abs(a) / acc).max()) >= 0.95


def test_timing_errors_name_the_field(client) -> None:
    body = {**LINE_BODY, "timing": {"acceleration_limits": [1.0, 2.0]}}
    problem(client.post("/robots/ur5/ik/path", json=body), 422, "timing.acceleration_limits")
    body = {**LINE_BODY, "timing": {"acceleration_limits": {"elbow": 1.0}}}
    problem(client.post("/robots/ur5/ik/path", json=body), 422, "timing.acceleration_limits.elbow")


def test_the_request_budget_is_the_paths_deadline(client, monkeypatch) -> None:
    """Past its deadline (now + ik_max_request_s) a path stops with reason timeout and the
    points so far; a fake clock far in the future stands for a path that ran out of time."""
    from app.kinematics.paths import follow

    monkeypatch.setattr(follow, "_clock", lambda: 1e18)
    out = client.post("/robots/ur5/ik/path", json=LINE_BODY).json()
    f = out["failure"]
    assert f["reason"] == "timeout" and "budget" in f["detail"], f
    assert out["fraction"] == 0.0 and len(out["points"]) == 1 and f["index"] == 1
