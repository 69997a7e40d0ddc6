"""One bound on joint values wherever a configuration enters, bounded targets and rates, and
IK answers that are numbers or refusals (never null, NaN or a 500).

A joint value of 1e300 is finite but meaningless (float64's spacing there is ~1e284, so its
sine carries no information): every endpoint refuses |q| > MAX_JOINT_VALUE (1e4) with a 422
naming the value, and answers right up to the bound (checked here against closed forms).
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest
from fastapi.testclient import TestClient

from app.kinematics import ik
from app.kinematics.errors import InvalidInputError
from app.kinematics.ik.problem import MODES, IKOptions
from app.kinematics.models import MAX_JOINT_VALUE, MAX_POSITION, RobotModel
from tests.helpers import problem
from tests.kinematics.chains import planar_2link

BIG = 1e300
JUST_OVER = MAX_JOINT_VALUE * (1 + 1e-12)
Q6 = [0.1, -0.4, 0.3, 0.2, 0.5, -0.1]
POSE = {"position": [0.3, 0.2, 0.4], "orientation": [0.0, 0.0, 0.0, 1.0]}


def with_value(i: int, value: float, base=Q6) -> list[float]:
    q = list(base)
    q[i] = value
    return q


# ------------------------------------------------------------------ one configuration
@pytest.mark.parametrize("value", [BIG, -BIG, JUST_OVER, -JUST_OVER])
@pytest.mark.parametrize(
    ("path", "extra"),
    [
        ("fk", {}),
        ("jacobian", {}),
        ("velocity", {"joint_velocities": [0.0] * 6}),
        ("velocity", {"twist": [0.0] * 6}),
        ("manipulability", {}),
        ("statics", {"wrench": [1.0, 0, 0, 0, 0, 0]}),
        ("collisions", {}),
    ],
)
def test_every_single_configuration_is_bounded(client: TestClient, path, extra, value) -> None:
    r = client.post(f"/robots/ur5/{path}", json={"q": with_value(3, value), **extra})
    body = problem(r, 422, "q.3")
    assert "10000" in body["detail"]
    r = client.post(
        f"/robots/ur5/{path}", json={"joint_positions": {"elbow_joint": value}, **extra}
    )
    problem(r, 422, "joint_positions.elbow_joint")


@pytest.mark.parametrize(
    ("path", "extra"),
    [("fk/batch", {}), ("manipulability/batch", {}), ("collisions/batch", {})],
)
def test_every_batch_is_bounded(client: TestClient, path, extra) -> None:
    rows = [Q6] * 5 + [with_value(2, BIG)] + [Q6]
    problem(
        client.post(f"/robots/ur5/{path}", json={"configurations": rows}), 422, "configurations.5.2"
    )
    rows[5] = with_value(0, -JUST_OVER)
    problem(
        client.post(f"/robots/ur5/{path}", json={"configurations": rows}), 422, "configurations.5.0"
    )


def test_ik_seed_is_bounded(client: TestClient) -> None:
    r = client.post("/robots/ur5/ik", json={"target": POSE, "seed": with_value(4, BIG)})
    problem(r, 422, "seed.4")
    r = client.post("/robots/ur5/ik", json={"target": POSE, "seed": {"wrist_2_joint": -BIG}})
    problem(r, 422, "seed.wrist_2_joint")
    r = client.post(
        "/robots/ur5/ik/batch", json={"targets": [POSE], "seed": {"wrist_2_joint": JUST_OVER}}
    )
    problem(r, 422, "seed.wrist_2_joint")


def test_up_to_the_bound_the_answer_is_right(client: TestClient) -> None:
    """A planar 2-link arm (l1 = 1, l2 = 0.7) at q1 = ±1e4 rad: the closed form
    x = cos q1 + 0.7 cos(q1 + q2), y = sin q1 + 0.7 sin(q1 + q2)."""
    r = client.post("/robots/urdf", json={"name": "p2", "urdf": planar_2link(), "ee_frame": "tip"})
    assert r.status_code == 201, r.text
    for q1 in (MAX_JOINT_VALUE, -MAX_JOINT_VALUE):
        q = [q1, 0.25]
        r = client.post("/robots/p2/fk", json={"q": q})
        assert r.status_code == 200, r.text
        x, y, _ = r.json()["poses"]["tip"]["position"]
        assert x == pytest.approx(math.cos(q1) + 0.7 * math.cos(q1 + 0.25), abs=1e-9)
        assert y == pytest.approx(math.sin(q1) + 0.7 * math.sin(q1 + 0.25), abs=1e-9)
        r = client.post("/robots/p2/fk/batch", json={"configurations": [q, q]})
        assert r.status_code == 200, r.text
        assert r.json()["positions"][1][:2] == pytest.approx([x, y], abs=1e-9)


# ------------------------------------------------------------------ targets and rates
@pytest.mark.parametrize("value", [BIG, -2 * MAX_POSITION])
def test_ik_target_positions_are_bounded(client: TestClient, value: float) -> None:
    target = {"position": [0.3, value, 0.4], "orientation": [0, 0, 0, 1]}
    problem(client.post("/robots/ur5/ik", json={"target": target}), 422, "target.position.1")
    problem(
        client.post(
            "/robots/ur5/ik", json={"target": {"position": [0, value, 0]}, "mode": "position"}
        ),
        422,
        "target.position.1",
    )
    M = np.eye(4)
    M[2, 3] = value
    problem(
        client.post("/robots/ur5/ik", json={"target": {"matrix": M.tolist()}}),
        422,
        "target.matrix.2.3",
    )
    r = client.post("/robots/ur5/ik/batch", json={"targets": [POSE, target]})
    problem(r, 422, "targets.1.position.1")


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        ({"joint_velocities": [0, 0, BIG, 0, 0, 0]}, "joint_velocities.2"),
        ({"joint_velocities": [1e308] * 6}, "joint_velocities.0"),
        ({"twist": [0, 0, 0, 0, -BIG, 0]}, "twist.4"),
        ({"twist": [1e300] * 6, "mode": "position"}, "twist.0"),
    ],
)
def test_velocities_and_twists_are_bounded(client: TestClient, extra: dict, field: str) -> None:
    """Before: 200 with null in `twist` / `residual` (J·q̇ overflowed to inf)."""
    problem(client.post("/robots/ur5/velocity", json={"q": Q6, **extra}), 422, field)


# ------------------------------------------------------------------ IK: numbers or refusals
def _numbers(out: dict) -> None:
    for key in ("position_error", "orientation_error"):
        assert isinstance(out[key], float) and math.isfinite(out[key]), out


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # overflowing geometry, on purpose
def test_ik_on_an_overflowing_dh_robot_is_never_null(client: TestClient) -> None:
    """a = d = 1e308: the import may refuse it; if stored, IK answers numbers or a 4xx."""
    table = {
        "name": "huge",
        "convention": "standard",
        "joints": [
            {"name": "j1", "a": 1e308, "alpha": 0.0, "d": 1e308, "theta": 0.0},
            {"name": "j2", "a": 1e308, "alpha": 0.0, "d": 1e308, "theta": 0.0},
        ],
    }
    r = client.post("/robots/dh", json=table)
    assert r.status_code in (201, 422), r.text
    if r.status_code == 422:
        return
    targets = {
        "pose": {"position": [0.1, 0.2, 0.3], "orientation": [0, 0, 0, 1]},
        "position": {"position": [0.1, 0.2, 0.3]},
        "orientation": {"orientation": [0, 0, 0, 1]},
    }
    for mode, target in targets.items():
        for path, body in (
            ("ik", {"target": target}),
            ("ik/batch", {"targets": [target, target]}),
        ):
            r = client.post(f"/robots/huge/{path}", json={**body, "mode": mode})
            assert r.status_code in (200, 422), r.text
            assert "null" not in r.text and "NaN" not in r.text, r.text
            if r.status_code == 422:
                assert r.json()["field"] == "robot_id"
            else:
                for out in r.json().get("results", [r.json()]):
                    _numbers(out)


HUGE = """<robot name="huge"><link name="base"/><link name="l1"/><link name="l2"/>
<link name="tip"/>
<joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
<origin xyz="1e308 0 1e308"/><axis xyz="0 0 1"/>
<limit lower="-3" upper="3" velocity="1" effort="1"/></joint>
<joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/>
<origin xyz="1e308 0 1e308"/><axis xyz="0 0 1"/>
<limit lower="-3" upper="3" velocity="1" effort="1"/></joint>
<joint name="t" type="fixed"><parent link="l2"/><child link="tip"/>
<origin xyz="1e308 0 0"/></joint></robot>"""


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # overflowing geometry, on purpose
@pytest.mark.parametrize("mode", MODES)
def test_ik_core_refuses_a_pose_that_overflows(mode: str) -> None:
    """Whatever import rules apply, the solver itself never reports a non-finite error (nor
    a 'converged' orientation whose position error is inf)."""
    robot = RobotModel("huge", HUGE, ee_frame="tip")
    target = pin.SE3(np.eye(3), np.array([0.1, 0.2, 0.3]))
    with pytest.raises(InvalidInputError) as err:
        ik.solve(robot, target, IKOptions(frame="tip", mode=mode, timeout_ms=5.0))
    assert err.value.field == "robot_id"


def test_ik_searches_within_the_bound_when_limits_are_wider() -> None:
    """A URDF with limits ±1e300 (planar2's chain, closed-form IK): the answer, and the
    search, stay within ±MAX_JOINT_VALUE, so FK accepts the answer back; before, the closed
    form's shift into the limits enumerated ~1e299 multiples of 2π."""
    urdf = planar_2link(limit=1e300)
    robot = RobotModel("wide", urdf, ee_frame="tip")
    q_true = np.array([0.4, 1.1])
    x = math.cos(0.4) + 0.7 * math.cos(1.5)
    y = math.sin(0.4) + 0.7 * math.sin(1.5)
    options = IKOptions(frame="tip", mode="position", timeout_ms=1000.0, num_solutions=2)
    res = ik.solve(robot, pin.SE3(np.eye(3), np.array([x, y, 0.0])), options)
    assert res.success
    assert np.all(np.abs(res.q) <= MAX_JOINT_VALUE)
    assert any(np.allclose(s.q, q_true, atol=1e-6) for s in res.solutions), res.solutions
    robot.configuration(res.q)  # accepted back
