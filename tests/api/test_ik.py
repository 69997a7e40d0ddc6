"""POST /robots/{id}/ik and /ik/batch: answers checked by FK, and the error contract."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.api.routes import ik as ik_api
from app.kinematics.fk import forward_kinematics
from app.kinematics.rotations import matrix_to_quaternion
from tests.helpers import fk_target, problem

Q_UR5 = [0.3, -1.0, 1.2, 0.2, 0.5, 0.1]
GOOD_TARGET = {"position": [0.3, 0.2, 0.4], "orientation": [0.0, 0.0, 0.0, 1.0]}


def ur5_target(registry, q=Q_UR5) -> dict:
    return fk_target(registry, q, "ur5", "tool0")


def check_pose(registry, q, target, frame="tool0", robot_id="ur5", tol=1e-5) -> None:
    """FK of ``q`` reaches ``target`` (computed here, independently of the response)."""
    T = forward_kinematics(registry.get(robot_id), np.array(q), [frame])[frame]
    assert np.linalg.norm(T[:3, 3] - np.array(target["position"])) <= tol
    qt = np.array(target["orientation"])
    qa = matrix_to_quaternion(T[:3, :3])
    assert 2 * math.acos(min(1.0, abs(float(qa @ qt)))) <= tol


def test_solve_pose(client, registry) -> None:
    target = ur5_target(registry)
    r = client.post("/robots/ur5/ik", json={"target": target})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["success"] and body["status"] == "converged"
    assert body["position_error"] <= 1e-5 and body["orientation_error"] <= 1e-5
    assert list(body["joint_positions"]) == registry.get("ur5").joint_names
    assert list(body["joint_positions"].values()) == body["q"]
    assert body["solutions"][0]["q"] == body["q"]
    assert body["method"] == "analytic"  # UR-type closed form, verified by FK
    assert body["iterations"] >= 0 and body["solve_time_ms"] >= 0.0
    check_pose(registry, body["q"], target)


def test_solve_matrix_and_several_solutions(client, registry) -> None:
    T = forward_kinematics(registry.get("ur5"), np.array(Q_UR5), ["tool0"])["tool0"]
    body = {"target": {"matrix": T.tolist()}, "num_solutions": 3, "timeout_ms": 500}
    r = client.post("/robots/ur5/ik", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["success"] and 2 <= len(out["solutions"]) <= 3
    target = ur5_target(registry)
    for s in out["solutions"]:
        check_pose(registry, s["q"], target)


def test_planar2_both_elbows_over_http(client) -> None:
    body = {"target": {"position": [1.2, 0.7, 0.0]}, "mode": "position", "num_solutions": 2}
    out = client.post("/robots/planar2/ik", json=body).json()
    assert out["success"] and out["method"] == "analytic"
    elbows = sorted(round(s["q"][1], 9) for s in out["solutions"])
    c2 = (1.2**2 + 0.7**2 - 1.0 - 0.64) / (2 * 0.8)
    assert elbows == [round(-math.acos(c2), 9), round(math.acos(c2), 9)]


def test_unreachable_is_200_with_success_false(client) -> None:
    body = {"target": {"position": [3.0, 0.0, 0.5], "orientation": [0, 0, 0, 1]}, "timeout_ms": 5}
    r = client.post("/robots/ur5/ik", json=body)
    assert r.status_code == 200
    out = r.json()
    assert not out["success"] and out["status"] in {"timeout", "not_converged"}
    assert out["solutions"] == [] and out["position_error"] > 2.0
    assert len(out["q"]) == 6


def test_seed_as_map_and_frame(client, registry) -> None:
    target = ur5_target(registry)
    seed = {"shoulder_pan_joint": 0.3, "elbow_joint": 1.2}
    body = {"target": target, "seed": seed, "frame": "tool0", "timeout_ms": 500}
    out = client.post("/robots/ur5/ik", json=body).json()
    assert out["success"] and out["frame"] == "tool0"


def test_budgets_above_5_ms_and_collision_checks_run_in_the_pool(
    client, registry, monkeypatch
) -> None:
    """Up to 5 ms without collision checks: solved on the event loop; otherwise offloaded."""
    offloaded = []
    real = ik_api.offload_cancellable

    async def spy(request, fn, *args, **kwargs):
        offloaded.append(getattr(fn, "func", fn).__name__)  # a partial
        return await real(request, fn, *args, **kwargs)

    monkeypatch.setattr(ik_api, "offload_cancellable", spy)
    target = ur5_target(registry)
    # the first query of a robot and frame builds its restart table, in the pool
    client.post("/robots/ur5/ik", json={"target": target, "timeout_ms": 100})
    for body, pooled in [
        ({"timeout_ms": 5.0}, False),
        ({"timeout_ms": 6.0}, True),
        ({"timeout_ms": 100, "max_iterations": 1000}, True),
        ({"timeout_ms": 5.0, "avoid_collisions": True}, True),
    ]:
        offloaded.clear()
        out = client.post("/robots/ur5/ik", json={"target": target, **body}).json()
        assert out["success"]
        check_pose(registry, out["q"], target)
        assert offloaded == (["_solve_one"] if pooled else []), body


def test_the_seed_picks_the_answer(client, registry) -> None:
    """UR5: each closed-form branch, sent as the seed (list or joint map), is the answer;
    Panda: a seed that already solves the target comes back after one evaluation."""
    target = ur5_target(registry)
    out = client.post("/robots/ur5/ik", json={"target": target, "num_solutions": 8}).json()
    branches = [s["q"] for s in out["solutions"]]
    assert len(branches) == 8
    names = registry.get("ur5").joint_names
    for q in branches:
        check_pose(registry, q, target)
        for seed in (q, dict(zip(names, q, strict=True))):
            out = client.post("/robots/ur5/ik", json={"target": target, "seed": seed}).json()
            np.testing.assert_allclose(out["q"], q, atol=1e-12)
    q_panda = [0.3, 0.2, -0.2, -1.8, 0.1, 1.9, 0.5, 0.03]
    target = fk_target(registry, q_panda, "panda", "panda_link8")
    body = {"target": target, "frame": "panda_link8", "seed": q_panda, "timeout_ms": 500}
    out = client.post("/robots/panda/ik", json=body).json()
    assert out["success"] and out["iterations"] <= 1 and out["q"] == q_panda


def test_batch_seeds_chained_or_not(client, registry) -> None:
    """Panda, one target twice from a far seed: chained, the second target starts at the
    first answer (one evaluation); not chained, it repeats the first search exactly. A seed
    that solves the target is the answer."""
    q_panda = [0.3, 0.2, -0.2, -1.8, 0.1, 1.9, 0.5, 0.03]
    target = fk_target(registry, q_panda, "panda", "panda_link8")
    body = {"targets": [target, target], "frame": "panda_link8", "timeout_ms": 500}
    far = [-0.5, 0.8, 0.6, -1.0, -0.7, 2.5, -0.5, 0.01]
    for chain in (True, False):
        r = client.post("/robots/panda/ik/batch", json={**body, "seed": far, "chain_seeds": chain})
        first, second = r.json()["results"]
        assert first["success"] and second["success"] and first["iterations"] > 1
        assert second["q"] == first["q"]
        assert second["iterations"] == (1 if chain else first["iterations"])
    first, _ = client.post("/robots/panda/ik/batch", json={**body, "seed": q_panda}).json()[
        "results"
    ]
    assert first["iterations"] <= 1 and first["q"] == q_panda


def test_batch_chained_and_from_one_seed(client, registry) -> None:
    qs = [np.array(Q_UR5) + 0.05 * k for k in range(5)]
    targets = [ur5_target(registry, q) for q in qs]
    for chain in (True, False):
        r = client.post("/robots/ur5/ik/batch", json={"targets": targets, "chain_seeds": chain})
        assert r.status_code == 200, r.text
        out = r.json()
        assert out["solved"] == 5 and len(out["results"]) == 5
        for res, t in zip(out["results"], targets, strict=True):
            assert res["success"]
            check_pose(registry, res["q"], t)
    # Chained seeds follow the trajectory's branch: consecutive answers stay close.
    out = client.post("/robots/ur5/ik/batch", json={"targets": targets, "seed": Q_UR5}).json()
    qs_out = np.array([r["q"] for r in out["results"]])
    assert np.abs(np.diff(qs_out, axis=0)).max() < 0.2


def test_batch_limit(client, app, registry) -> None:
    app.state.settings.max_batch = 2
    r = client.post("/robots/ur5/ik/batch", json={"targets": [ur5_target(registry)] * 3})
    problem(r, 422, "targets")


BAD = [
    ({"target": {"position": [0, 0, 0], "orientation": [0, 0, 0, 0]}}, 422, "target.orientation"),
    ({"target": {"position": [0, 0, 0], "orientation": [0, 0, 0, 2]}}, 422, "target.orientation"),
    ({"target": {"orientation": [0, 0, 0, 1]}}, 422, "target.position"),
    ({"target": {"position": [0, 0, 0]}}, 422, "target.orientation"),
    ({"target": {**GOOD_TARGET, "matrix": np.eye(4).tolist()}}, 422, "target.matrix"),
    ({"target": {"matrix": (2 * np.eye(4)).tolist()}}, 422, "target.matrix"),
    (
        {"target": {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]}},
        422,
        "target.matrix",
    ),
    (
        {"target": {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}},
        422,
        "target.matrix",
    ),
    ({"target": GOOD_TARGET, "frame": "tool9"}, 422, "frame"),
    ({"target": GOOD_TARGET, "timeout_ms": -1}, 422, "timeout_ms"),
    ({"target": GOOD_TARGET, "timeout_ms": 0}, 422, "timeout_ms"),
    ({"target": GOOD_TARGET, "timeout_ms": 5000}, 422, "timeout_ms"),
    ({"target": GOOD_TARGET, "max_iterations": -3}, 422, "max_iterations"),
    ({"target": GOOD_TARGET, "num_solutions": 0}, 422, "num_solutions"),
    ({"target": GOOD_TARGET, "seed": [0, 0]}, 422, "seed"),
    ({"target": GOOD_TARGET, "seed": {"wrist_9_joint": 0.1}}, 422, "seed.wrist_9_joint"),
    ({"target": GOOD_TARGET, "mode": "twist"}, 422, "mode"),
    ({"target": GOOD_TARGET, "weights": [1, 1, 1, 1, 1]}, 422, "weights"),
    ({"target": GOOD_TARGET, "weights": [1, 1, 1, 1, 1, -1]}, 422, "weights.5"),
    ({"target": GOOD_TARGET, "weights": [1, 1, 1, 0, 0, 0], "mode": "orientation"}, 422, "weights"),
    ({"target": GOOD_TARGET, "tolerance": {"position": -1e-5}}, 422, "tolerance.position"),
    ({"target": GOOD_TARGET, "bogus": 1}, 422, "bogus"),
    ({}, 422, "target"),
]


@pytest.mark.parametrize(("body", "status", "field"), BAD)
def test_bad_inputs(client, body, status, field) -> None:
    problem(client.post("/robots/ur5/ik", json=body), status, field)


@pytest.mark.parametrize(
    ("raw", "field"),
    [
        ('{"target": {"position": [0, 0, NaN], "orientation": [0, 0, 0, 1]}}', "target.position.2"),
        (
            '{"target": {"position": [0, 0, 0], "orientation": [0, 0, 0, 1]}, "seed": [0, 0, 0, '
            "0, 0, Infinity]}",
            "seed",
        ),
    ],
)
def test_non_finite_numbers(client, raw, field) -> None:
    r = client.post("/robots/ur5/ik", content=raw, headers={"content-type": "application/json"})
    assert r.status_code == 422, r.text
    assert r.json()["field"].startswith(field)


def test_batch_bad_target_names_its_index(client) -> None:
    body = {"targets": [GOOD_TARGET, {"position": [0, 0, 0], "orientation": [0, 0, 0, 0]}]}
    problem(client.post("/robots/ur5/ik/batch", json=body), 422, "targets.1.orientation")


def test_unknown_robot(client) -> None:
    problem(client.post("/robots/nope/ik", json={"target": GOOD_TARGET}), 404, "robot_id")


def test_malformed_json(client) -> None:
    r = client.post("/robots/ur5/ik", content="{", headers={"content-type": "application/json"})
    assert r.status_code == 400
