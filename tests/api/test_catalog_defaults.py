"""Every catalog robot answers the documented defaults: ``{}`` to FK, the Jacobian,
manipulability and collisions (the neutral configuration, the end effector, no obstacles),
and IK of a target that FK gave for a seeded random configuration within the limits.

The IK answer is checked against FK of its own solution (Pinocchio, ``POST /fk``):
the solution's tip lies within 1 mm of the target. IK's time budget is the one default
replaced: ``random_seed`` and ``max_iterations`` with a budget that never ends first make
the answer the same on a loaded machine (docs/ik.md). Statics and velocity
have no all-default request (a wrench or torques, a twist or joint velocities is needed):
``{}`` is a 422 naming the field, also checked here. Reachability's ``{}`` is in
test_reachability_defaults.py.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from app.robots.registry import Registry
from tests.helpers import problem

CATALOG = Registry().ids()
#: IK options that make an answer independent of the machine's speed.
DETERMINISTIC = {"random_seed": 0, "max_iterations": 100_000, "timeout_ms": 1e6}


@pytest.fixture(scope="module")
def shared(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TestClient]:
    data = Path(tmp_path_factory.mktemp("catalog-defaults")) / "data"
    settings = Settings(data_dir=data, ik_max_timeout_ms=1e6, ik_max_request_s=1e4)
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


@pytest.mark.parametrize("robot_id", CATALOG)
def test_documented_defaults_answer_on_every_catalog_robot(
    shared: TestClient, robot_id: str
) -> None:
    base = f"/robots/{robot_id}"
    detail = shared.get(base).json()
    tip = detail["end_effector"]
    for op in ("fk", "jacobian", "manipulability", "collisions"):
        resp = shared.post(f"{base}/{op}", json={})
        assert resp.status_code == 200, (op, resp.text)
    assert shared.post(f"{base}/fk", json={}).json()["q"] == detail["neutral"]
    problem(shared.post(f"{base}/statics", json={}), 422, "wrench")
    problem(shared.post(f"{base}/velocity", json={}), 422, "twist")

    rng = np.random.default_rng(11)
    limits = [j["limits"] for j in detail["joints"]]
    lo = np.array([-math.pi if x["lower"] is None else x["lower"] for x in limits])
    hi = np.array([math.pi if x["upper"] is None else x["upper"] for x in limits])
    q = rng.uniform(lo, hi).tolist()
    pose = shared.post(f"{base}/fk", json={"q": q}).json()["poses"][tip]
    target = {"position": pose["position"], "orientation": pose["orientation"]}
    ik = shared.post(f"{base}/ik", json={"target": target, **DETERMINISTIC})
    assert ik.status_code == 200 and ik.json()["status"] == "converged", ik.text
    got = shared.post(f"{base}/fk", json={"q": ik.json()["q"]}).json()["poses"][tip]
    assert np.linalg.norm(np.subtract(got["position"], pose["position"])) < 1e-3
