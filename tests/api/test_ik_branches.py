"""IK over HTTP: branches, rank_by, typed failures, solver version and determinism.

References are independent of the solver: the planar arm's textbook closed form,
the /manipulability and /collisions endpoints, and a live two-worker server for
determinism. Budgets are iteration caps with generous time limits.
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import httpx
import numpy as np
import pytest

from app.kinematics.ik.failure import UNREACHABLE_ITERATIONS
from app.kinematics.ik.version import SOLVER_VERSION
from tests.helpers import problem, serve
from tests.kinematics.reference import planar2_elbows

L1, L2 = 1.0, 0.8  # robots/dh/planar2.yaml
UR5_Q = [0.3, -1.1, 1.4, -0.6, 0.9, 0.2]
#: Budget of the tests' solves: a cap on iterations, time generous enough never to bind.
CAPPED = {"timeout_ms": 1000, "max_iterations": 2000}


def _planar_solutions(x: float, y: float) -> list[tuple[float, float]]:
    """Both elbows of the planar 2-link arm (textbook closed form): θ2 = ±acos(c2)."""
    return planar2_elbows(x, y, L1, L2)


def _tool(client, robot_id: str, q: list[float]) -> dict:
    resp = client.post(f"/robots/{robot_id}/fk", json={"q": q})
    assert resp.status_code == 200, resp.text
    return resp.json()["poses"]


# ---------------------------------------------------------------------- seed distance
def test_seed_distance_is_the_largest_joint_move_not_the_sum(client) -> None:
    """A seed where the elbow nearest by the largest joint move is the farther one by the sum
    (and by the Euclidean norm): the answer follows the largest move."""
    x, y = 1.2, 0.7
    sols = [np.array(s) for s in _planar_solutions(x, y)]
    seed = None
    for s1, s2 in itertools.product(np.linspace(-3, 3, 121), repeat=2):
        d = [np.abs(q - (s1, s2)) for q in sols]
        by_max = int(np.argmin([v.max() for v in d]))
        by_sum = int(np.argmin([v.sum() for v in d]))
        by_l2 = int(np.argmin([np.linalg.norm(v) for v in d]))
        gap_max = abs(d[0].max() - d[1].max())
        gap_sum = abs(d[0].sum() - d[1].sum())
        gap_l2 = abs(np.linalg.norm(d[0]) - np.linalg.norm(d[1]))
        if by_max != by_sum and by_max != by_l2 and min(gap_max, gap_sum, gap_l2) > 0.05:
            seed, nearest = [float(s1), float(s2)], by_max
            break
    assert seed is not None
    body = {
        "target": {"position": [x, y, 0.0]}, "mode": "position", "num_solutions": 2,
        "seed": seed, **CAPPED,
    }  # fmt: skip
    r = client.post("/robots/planar2/ik", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["success"] and len(out["solutions"]) == 2
    first, second = out["solutions"]
    assert first["q"] == pytest.approx(sols[nearest].tolist(), abs=1e-6)
    assert out["q"] == first["q"]
    for s in out["solutions"]:
        assert s["seed_distance"] == pytest.approx(np.abs(np.array(s["q"]) - seed).max(), abs=1e-12)
    assert first["seed_distance"] < second["seed_distance"]
    assert {s["branch"] for s in out["solutions"]} == {"elbow_up", "elbow_down"}
    for s in out["solutions"]:
        assert s["branch"] == ("elbow_up" if s["q"][1] > 0 else "elbow_down")
        assert s["clearance"] is None


# ------------------------------------------------------------------------------ ranking
def test_rank_by_manipulability_agrees_with_the_analysis_endpoint(client) -> None:
    target = _tool(client, "ur5", UR5_Q)["tool0"]
    body = {
        "target": {"matrix": target["matrix"]}, "num_solutions": 8, "seed": UR5_Q,
        "rank_by": "manipulability", **CAPPED,
    }  # fmt: skip
    out = client.post("/robots/ur5/ik", json=body).json()
    assert out["success"] and len(out["solutions"]) == 8
    assert len({s["branch"] for s in out["solutions"]}) == 8
    w = []
    for s in out["solutions"]:
        ref = client.post("/robots/ur5/manipulability", json={"q": s["q"], "frame": "tool0"})
        assert ref.status_code == 200, ref.text
        assert s["manipulability"] == pytest.approx(ref.json()["yoshikawa"], rel=1e-9)
        w.append(ref.json()["yoshikawa"])
    # Descending (mirror-image elbows have equal measures: equal up to rounding).
    assert all(a >= b * (1 - 1e-9) for a, b in itertools.pairwise(w))
    assert w[0] > w[-1] * 1.1


def test_rank_by_clearance_needs_obstacles(client) -> None:
    body = {"target": {"position": [1.2, 0.7, 0.0]}, "mode": "position", "rank_by": "clearance"}
    problem(client.post("/robots/planar2/ik", json=body), 422, "rank_by")
    problem(
        client.post("/robots/planar2/ik", json={**body, "avoid_collisions": True}), 422, "rank_by"
    )
    problem(client.post("/robots/planar2/ik", json={**body, "rank_by": "speed"}), 422, "rank_by")


def test_rank_by_clearance_puts_the_elbow_away_from_the_obstacle_first(client) -> None:
    x, y = 1.2, 0.7
    near_elbow = min(_planar_solutions(x, y), key=lambda s: s[1])  # θ2 < 0: elbow_down
    ex, ey = L1 * math.cos(near_elbow[0]), L1 * math.sin(near_elbow[0])
    # A ball 0.25 m beyond the elbow_down elbow, radially: clear of both arms' links.
    rock = {
        "name": "rock", "shape": "sphere", "radius": 0.05,
        "pose": {"position": [1.25 * ex, 1.25 * ey, 0.0]},
    }  # fmt: skip
    body = {
        "target": {"position": [x, y, 0.0]}, "mode": "position", "num_solutions": 2,
        "avoid_collisions": True, "obstacles": [rock], "rank_by": "clearance", **CAPPED,
    }  # fmt: skip
    out = client.post("/robots/planar2/ik", json=body).json()
    assert out["success"] and len(out["solutions"]) == 2
    assert [s["branch"] for s in out["solutions"]] == ["elbow_up", "elbow_down"]
    clear = [s["clearance"] for s in out["solutions"]]
    assert clear[0] > clear[1] > 0
    for s in out["solutions"]:
        check = client.post(
            "/robots/planar2/collisions",
            json={"q": s["q"], "obstacles": [rock], "distances": True},
        ).json()
        ref = min(p["distance"] for p in check["pairs"] if p["b"] == "rock")
        assert s["clearance"] == pytest.approx(ref, abs=1e-9)


# ----------------------------------------------------------------------------- failures
def test_unreachable_is_answered_at_once_with_a_reason(client) -> None:
    body = {
        "target": {"position": [10.0, 0.0, 0.0], "orientation": [0, 0, 0, 1]},
        "timeout_ms": 1000,
    }
    out = client.post("/robots/ur5/ik", json=body).json()
    assert not out["success"] and out["reason"] == "unreachable"
    assert out["status"] == "not_converged" and out["iterations"] <= UNREACHABLE_ITERATIONS
    assert "m" in out["detail"] and out["solutions"] == []
    assert out["solver_version"] == SOLVER_VERSION


def test_joint_limits_reason_on_a_dh_robot_with_tight_limits(client) -> None:
    table = {
        "name": "tight_planar",
        "convention": "standard",
        "joints": [
            {"name": "j1", "a": L1, "alpha": 0.0, "d": 0.0, "theta": 0.0,
             "lower": -1.0, "upper": 1.0},
            {"name": "j2", "a": L2, "alpha": 0.0, "d": 0.0, "theta": 0.0,
             "lower": -0.3, "upper": 0.3},
        ],
    }  # fmt: skip
    assert client.post("/robots/dh", json=table).status_code == 201
    t1, t2 = 0.2, 1.2  # θ2 = ±1.2 needed, the limit is 0.3
    x, y = L1 * math.cos(t1) + L2 * math.cos(t1 + t2), L1 * math.sin(t1) + L2 * math.sin(t1 + t2)
    body = {"target": {"position": [x, y, 0.0]}, "mode": "position", "timeout_ms": 1000,
            "max_iterations": 300}  # fmt: skip
    out = client.post("/robots/tight_planar/ik", json=body).json()
    assert not out["success"] and out["reason"] == "joint_limits", out["detail"]
    assert "j2" in out["detail"]


def test_collision_reason_when_every_solution_collides(client) -> None:
    target = _tool(client, "planar2", [0.4, 1.1])["tool"]["position"]
    ball = {"name": "ball", "shape": "sphere", "radius": 0.1, "pose": {"position": target}}
    body = {
        "target": {"position": target}, "mode": "position", "num_solutions": 2,
        "avoid_collisions": True, "obstacles": [ball], **CAPPED,
    }  # fmt: skip
    out = client.post("/robots/planar2/ik", json=body).json()
    assert not out["success"] and out["reason"] == "collision", out["detail"]


def test_batch_items_carry_reasons_and_the_solver_version(client) -> None:
    good = _tool(client, "ur5", UR5_Q)["tool0"]
    body = {
        "targets": [
            {"matrix": good["matrix"]},
            {"position": [10.0, 0.0, 0.0], "orientation": [0, 0, 0, 1]},
        ],
        "seed": UR5_Q, **CAPPED,
    }  # fmt: skip
    out = client.post("/robots/ur5/ik/batch", json=body).json()
    assert out["solver_version"] == SOLVER_VERSION
    ok, far = out["results"]
    assert ok["success"] and ok["reason"] is None and ok["detail"] is None
    assert not far["success"] and far["reason"] == "unreachable" and far["detail"]


# -------------------------------------------------------------------------- determinism
def _without_timing(body: dict) -> dict:
    return {k: v for k, v in body.items() if k not in ("solve_time_ms", "total_time_ms")}


def test_same_random_seed_same_answer_on_two_workers(tmp_path: Path) -> None:
    """The same request with random_seed to a live two-worker server, from fresh connections,
    answers identical JSON (timing aside); another seed answers differently on a target that
    needs random restarts (many Panda clusters: beyond the 32 nearest table samples)."""
    body = {
        "target": {"position": [0.4, 0.1, 0.5], "orientation": [1, 0, 0, 0]},
        "frame": "panda_link8", "num_solutions": 12, "timeout_ms": 30000,
        "max_iterations": 3000, "random_seed": 7,
    }  # fmt: skip
    env = {"DENAVIT_IK_MAX_TIMEOUT_MS": "30000"}  # a budget that never binds: the cap does
    with serve(tmp_path / "data", "--workers", "2", env=env) as server:
        answers = []
        for _ in range(8):
            with httpx.Client(base_url=server.url, timeout=120) as own:  # a fresh connection
                r = own.post("/robots/panda/ik", json=body)
                assert r.status_code == 200, r.text
                answers.append(_without_timing(r.json()))
        with httpx.Client(base_url=server.url, timeout=120) as own:
            other = _without_timing(
                own.post("/robots/panda/ik", json={**body, "random_seed": 8}).json()
            )
    first = answers[0]
    assert first["restarts"] > 32 and first["solver_version"] == SOLVER_VERSION
    assert all(a == first for a in answers[1:])
    assert other["solutions"] != first["solutions"]
