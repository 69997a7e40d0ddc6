"""IK on 1-DoF robots (fewer joints than task rows) over HTTP, against closed forms.

Three robots built here, each with a closed form independent of the service:

- ``r1``: one revolute joint about z at height H, the tip at distance L along the link's x:
  p(θ) = (L cos θ, L sin θ, H), R(θ) = Rz(θ). The position closest to a target is at
  θ = atan2(y, x), at distance √((ρ − L)² + (z − H)²), ρ = √(x² + y²).
- ``p1``: one prismatic joint along x, the tip offset by (0, D, 0): p(d) = (d, D, 0), R = I.
- ``m1``: one revolute joint and a mimic follower (multiplier 1) at distance A, the tip at
  B further: p(θ) = A(cos θ, sin θ, 0) + B(cos 2θ, sin 2θ, 0), R(θ) = Rz(2θ).

Every IK mode is asked on each (single and batch); unreachable targets are a 200 with
``success: false`` and the best configuration, never a 500.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

L, H, D, A, B = 0.5, 0.1, 0.2, 0.5, 0.3
LIMIT = 3.0


def _robot(name: str, joints: str, links: str) -> str:
    link_xml = "".join(f'<link name="{n}"/>' for n in links.split())
    return f'<?xml version="1.0"?>\n<robot name="{name}">{link_xml}{joints}</robot>'


def _joint(name: str, parent: str, child: str, kind: str, xyz: str, axis: str, extra="") -> str:
    limit = f'<limit lower="{-LIMIT}" upper="{LIMIT}" velocity="1" effort="1"/>'
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{xyz}" rpy="0 0 0"/><axis xyz="{axis}"/>{limit}{extra}</joint>'
    )


def _fixed(parent: str, child: str, xyz: str) -> str:
    return (
        f'<joint name="{child}_fixed" type="fixed"><parent link="{parent}"/>'
        f'<child link="{child}"/><origin xyz="{xyz}" rpy="0 0 0"/></joint>'
    )


R1 = _robot(
    "r1",
    _joint("j1", "base", "l1", "revolute", f"0 0 {H}", "0 0 1") + _fixed("l1", "tip", f"{L} 0 0"),
    "base l1 tip",
)
P1 = _robot(
    "p1",
    _joint("j1", "base", "l1", "prismatic", "0 0 0", "1 0 0") + _fixed("l1", "tip", f"0 {D} 0"),
    "base l1 tip",
)
M1 = _robot(
    "m1",
    _joint("j1", "base", "l1", "revolute", "0 0 0", "0 0 1")
    + _joint(
        "j2",
        "l1",
        "l2",
        "revolute",
        f"{A} 0 0",
        "0 0 1",
        extra='<mimic joint="j1" multiplier="1" offset="0"/>',
    )  # fmt: skip
    + _fixed("l2", "tip", f"{B} 0 0"),
    "base l1 l2 tip",
)


def quat_z(angle: float) -> list[float]:
    """Quaternion [x, y, z, w] of Rz(angle)."""
    return [0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)]


def angle_between_z(q: list[float], angle: float) -> float:
    """Rotation angle between the unit quaternion ``q`` and Rz(angle)."""
    return 2 * math.acos(min(1.0, abs(float(np.dot(q, quat_z(angle))))))


def r1_pos(t: float) -> list[float]:
    return [L * math.cos(t), L * math.sin(t), H]


def m1_pos(t: float) -> list[float]:
    return [A * math.cos(t) + B * math.cos(2 * t), A * math.sin(t) + B * math.sin(2 * t), 0.0]


def wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


@pytest.fixture
def one_dof(client: TestClient) -> TestClient:
    for name, urdf in (("r1", R1), ("p1", P1), ("m1", M1)):
        r = client.post("/robots/urdf", json={"name": name, "urdf": urdf, "ee_frame": "tip"})
        assert r.status_code == 201, r.text
        assert len(r.json()["joints"]) == 1
    return client


#: An iteration cap ends every search, not the clock: the same answers on a loaded machine.
BUDGET = {"timeout_ms": 1000, "max_iterations": 300, "random_seed": 0}


def solve(client: TestClient, robot: str, target: dict, mode: str, **extra) -> dict:
    body = {"target": target, "mode": mode, **BUDGET, **extra}
    r = client.post(f"/robots/{robot}/ik", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    for key in ("position_error", "orientation_error"):
        assert isinstance(out[key], float) and math.isfinite(out[key]), out
    return out


def batch(client: TestClient, robot: str, targets: list[dict], mode: str) -> list[dict]:
    body = {"targets": targets, "mode": mode, **BUDGET, "chain_seeds": False}
    r = client.post(f"/robots/{robot}/ik/batch", json=body)
    assert r.status_code == 200, r.text
    return r.json()["results"]


# ------------------------------------------------------------------ revolute: θ = atan2
@pytest.mark.parametrize("theta", [0.7, -2.2, 2.9])
def test_revolute_every_mode_matches_the_closed_form(one_dof: TestClient, theta: float) -> None:
    position, orientation = r1_pos(theta), quat_z(theta)
    targets = {
        "pose": {"position": position, "orientation": orientation},
        "position": {"position": position},
        "orientation": {"orientation": orientation},
    }
    for mode, target in targets.items():
        out = solve(one_dof, "r1", target, mode)
        assert out["success"] and out["status"] == "converged", (mode, out)
        # the closed form: θ = atan2(y, x) (position), the angle of Rz (orientation)
        assert out["q"][0] == pytest.approx(math.atan2(position[1], position[0]), abs=1e-6)
        assert out["q"][0] == pytest.approx(theta, abs=1e-6)
        res = batch(one_dof, "r1", [target, target], mode)
        assert [x["success"] for x in res] == [True, True], (mode, res)
        assert res[0]["q"][0] == pytest.approx(theta, abs=1e-6)


def test_revolute_partial_weights(one_dof: TestClient) -> None:
    """Pose mode with only x and y weighted: 2 task rows, 1 joint."""
    theta = -1.1
    target = {"position": r1_pos(theta), "orientation": [1.0, 0.0, 0.0, 0.0]}
    out = solve(one_dof, "r1", target, "pose", weights=[1, 1, 0, 0, 0, 0])
    assert out["success"] and out["q"][0] == pytest.approx(theta, abs=1e-6)


@pytest.mark.parametrize("mode", ["position", "pose"])
def test_revolute_unreachable_position_is_the_nearest_point(one_dof: TestClient, mode) -> None:
    """Off the circle: success false, and the error reported is that of the q returned (the
    closed form), no less than the distance to the circle (reached at θ = atan2(y, x))."""
    x, y, z = -0.9, 0.6, H + 0.2
    target = {"position": [x, y, z], "orientation": quat_z(math.atan2(y, x))}
    out = solve(one_dof, "r1", target, mode)
    assert not out["success"] and out["status"] in {"timeout", "not_converged"}
    assert out["solutions"] == []
    gap = np.subtract(r1_pos(out["q"][0]), [x, y, z])
    assert out["position_error"] == pytest.approx(float(np.linalg.norm(gap)), abs=1e-12)
    nearest = math.hypot(math.hypot(x, y) - L, z - H)
    assert nearest - 1e-12 <= out["position_error"] <= nearest + 0.05
    (item,) = batch(one_dof, "r1", [target], mode)
    assert not item["success"] and math.isfinite(item["position_error"])


def test_revolute_unreachable_orientation(one_dof: TestClient) -> None:
    """Rx(0.5) is not Rz(θ) for any θ: the nearest is θ = 0, 0.5 rad away."""
    target = {"orientation": [math.sin(0.25), 0.0, 0.0, math.cos(0.25)]}
    out = solve(one_dof, "r1", target, "orientation")
    assert not out["success"]
    assert out["q"][0] == pytest.approx(0.0, abs=1e-5)
    assert out["orientation_error"] == pytest.approx(0.5, abs=1e-9)


def test_revolute_beyond_its_limits(one_dof: TestClient) -> None:
    """θ = π is on the circle but outside [−3, 3]: an honest failure at the nearest limit."""
    out = solve(one_dof, "r1", {"position": r1_pos(math.pi)}, "position")
    assert not out["success"] and abs(out["q"][0]) == pytest.approx(LIMIT)
    assert out["position_error"] == pytest.approx(2 * L * math.sin((math.pi - LIMIT) / 2))


# ------------------------------------------------------------------ prismatic: d = x
def test_prismatic_every_mode(one_dof: TestClient) -> None:
    d = 0.37
    out = solve(one_dof, "p1", {"position": [d, D, 0.0]}, "position")
    assert out["success"] and out["q"][0] == pytest.approx(d, abs=1e-6)
    out = solve(one_dof, "p1", {"position": [d, D, 0.0], "orientation": [0, 0, 0, 1]}, "pose")
    assert out["success"] and out["q"][0] == pytest.approx(d, abs=1e-6)
    # any d has the identity orientation: the seed (middle of the limits) is a solution
    out = solve(one_dof, "p1", {"orientation": [0, 0, 0, 1]}, "orientation")
    assert out["success"] and out["q"] == [0.0]
    # off the line: the projection d = x, at the distance to the line
    out = solve(one_dof, "p1", {"position": [0.25, D + 0.3, 0.4]}, "position")
    assert not out["success"] and out["q"][0] == pytest.approx(0.25, abs=1e-6)
    assert out["position_error"] == pytest.approx(0.5, abs=1e-9)
    # beyond the stroke: the nearest limit
    out = solve(one_dof, "p1", {"position": [LIMIT + 0.8, D, 0.0]}, "position")
    assert not out["success"] and out["q"] == [LIMIT]
    assert out["position_error"] == pytest.approx(0.8, abs=1e-9)
    # a rotation no translation reaches
    out = solve(one_dof, "p1", {"orientation": quat_z(0.3)}, "orientation")
    assert not out["success"] and out["orientation_error"] == pytest.approx(0.3, abs=1e-9)
    for mode, target in (
        ("position", {"position": [d, D, 0.0]}),
        ("orientation", {"orientation": [0, 0, 0, 1]}),
        ("pose", {"position": [d, D, 0.0], "orientation": [0, 0, 0, 1]}),
    ):
        assert [x["success"] for x in batch(one_dof, "p1", [target] * 2, mode)] == [True, True]


# ------------------------------------------------------------------ mimic follower
@pytest.mark.parametrize("theta", [0.4, -1.3])
def test_mimic_chain_every_mode(one_dof: TestClient, theta: float) -> None:
    position, orientation = m1_pos(theta), quat_z(2 * theta)
    for mode, target in (
        ("pose", {"position": position, "orientation": orientation}),
        ("position", {"position": position}),
    ):
        out = solve(one_dof, "m1", target, mode)
        assert out["success"], (mode, out)
        t = out["q"][0]
        assert np.allclose(m1_pos(t), position, atol=1e-5), (mode, out)
        if mode == "pose":
            assert t == pytest.approx(theta, abs=1e-6)
        assert [x["success"] for x in batch(one_dof, "m1", [target] * 2, mode)] == [True, True]
    # orientation Rz(2θ): θ and θ ± π both give it; the answer is one of them
    out = solve(one_dof, "m1", {"orientation": orientation}, "orientation")
    assert out["success"] and angle_between_z(orientation, 2 * out["q"][0]) <= 1e-5
    assert min(abs(wrap(out["q"][0] - theta)), abs(wrap(out["q"][0] - theta - math.pi))) < 1e-5
    res = batch(one_dof, "m1", [{"orientation": orientation}], "orientation")
    assert res[0]["success"]


def test_mimic_chain_unreachable(one_dof: TestClient) -> None:
    """Beyond A + B from the base: a failure whose error is at least the radial gap."""
    target = {"position": [1.5, 0.2, 0.0]}
    out = solve(one_dof, "m1", target, "position")
    assert not out["success"] and out["solutions"] == []
    assert out["position_error"] >= math.hypot(1.5, 0.2) - (A + B) - 1e-9
    # and it is the error of the returned q, by the closed form
    gap = np.subtract(m1_pos(out["q"][0]), target["position"])
    assert out["position_error"] == pytest.approx(float(np.linalg.norm(gap)), abs=1e-9)


def test_pinocchio_chain_of_a_one_dof_mimic_robot() -> None:
    """Reachability's per-sample Pinocchio path (mimic chains) on nv = 1: J against the
    derivative of the closed form, dp/dθ = A(−sin θ, cos θ, 0) + 2B(−sin 2θ, cos 2θ, 0),
    ω = (0, 0, 2)."""
    from app.kinematics.chain import PinocchioChain, chain_for
    from app.kinematics.models import RobotModel

    robot = RobotModel("m1", M1, ee_frame="tip")
    ch = chain_for(robot, "tip")
    assert isinstance(ch, PinocchioChain)
    thetas = np.array([0.4, -1.3])
    R, p, J = ch(thetas[:, None])
    for t, pi, Ji in zip(thetas, p, J, strict=True):
        np.testing.assert_allclose(pi, m1_pos(t), atol=1e-12)
        dp = [-A * math.sin(t) - 2 * B * math.sin(2 * t), A * math.cos(t) + 2 * B * math.cos(2 * t)]
        np.testing.assert_allclose(Ji[:, 0], [*dp, 0.0, 0.0, 0.0, 2.0], atol=1e-12)
