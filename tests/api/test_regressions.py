"""Regressions found in integration: single-joint robots, first IK budget, IK metrics."""

from __future__ import annotations

import numpy as np
import pytest


def test_single_joint_robot_jacobian_analysis_statics(client) -> None:
    """Pinocchio returns a 1-D Jacobian for a 1-DoF model; every route must still answer."""
    table = {"name": "one", "convention": "standard",
             "joints": [{"a": 0.5, "alpha": 0, "d": 0, "theta": 0}]}  # fmt: skip
    assert client.post("/robots/dh", json=table).status_code == 201
    th = 0.3
    J = np.array(client.post("/robots/one/jacobian", json={"q": [th]}).json()["jacobian"])
    # tool at (0.5 cos θ, 0.5 sin θ, 0), rotating about z
    np.testing.assert_allclose(J[:, 0], [-0.5 * np.sin(th), 0.5 * np.cos(th), 0, 0, 0, 1],
                               atol=1e-12)  # fmt: skip
    m = client.post("/robots/one/manipulability", json={"q": [th]})
    assert m.status_code == 200, m.text
    # one column of norm √(0.5² + 1): one singular value, full column rank, not singular
    body = m.json()
    assert body["joints"] == ["j1"] and body["rank"] == 1 and body["singular"] is False
    np.testing.assert_allclose(body["singular_values"], [np.sqrt(1.25)], rtol=1e-12)
    assert body["yoshikawa"] == pytest.approx(np.sqrt(1.25), rel=1e-12)
    tau = client.post("/robots/one/statics", json={"q": [th], "wrench": [1, 0, 0, 0, 0, 0]})
    assert tau.status_code == 200
    np.testing.assert_allclose(tau.json()["torques"], [-0.5 * np.sin(th)], atol=1e-12)


def test_first_ik_query_gets_its_whole_budget(monkeypatch) -> None:
    """The one-time chain set-up is not charged to the first query's budget.

    Deterministic: a fake clock advances 1 µs per reading, and building the chain (restart
    table) costs a whole simulated second; a 5 ms budget must still be available in full.
    """
    import pinocchio as pin

    from app.kinematics import ik
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.problem import IKOptions
    from app.robots.registry import Registry

    now = [0.0]

    def clock() -> float:
        now[0] += 1e-6
        return now[0]

    build = IKChain.__init__

    def slow_build(self, *args, **kwargs) -> None:
        build(self, *args, **kwargs)
        now[0] += 1.0

    monkeypatch.setattr(IKChain, "__init__", slow_build)
    robot = Registry().get("panda")  # a fresh model: no chain cached yet
    target = pin.SE3(np.diag([1.0, -1.0, -1.0]), np.array([0.4, 0.1, 0.5]))
    res = ik.solve(robot, target, IKOptions(frame="panda_hand_tcp", timeout_ms=5.0), clock=clock)
    assert res.success and res.status == "converged" and res.iterations > 0


def test_ik_outcomes_are_counted_in_metrics(client) -> None:
    def count(result: str) -> float:
        for line in client.get("/metrics").text.splitlines():
            if line.startswith(f'denavit_ik_requests_total{{result="{result}"}}'):
                return float(line.split()[-1])
        return 0.0

    before_ok, before_fail = count("success"), count("failure")
    target = {"position": [0.4, 0.1, 0.5], "orientation": [1, 0, 0, 0]}
    ok = client.post("/robots/panda/ik", json={"target": target, "timeout_ms": 500})
    assert ok.json()["success"]
    far = {"position": [5.0, 0, 0], "orientation": [0, 0, 0, 1]}
    assert not client.post("/robots/panda/ik", json={"target": far}).json()["success"]
    assert count("success") == before_ok + 1 and count("failure") == before_fail + 1
