"""POST /robots/{id}/reachability with ``{}`` (every documented default) builds a coarse map
on every catalog robot, and the map agrees with forward kinematics.

Every catalog robot has an end effector (its default tip), so none is expected to refuse
``{}``; a robot without one would need its ``frame`` named. The checks use facts that do not
come from the map's own code: Pinocchio's FK (``POST /fk``) of seeded random configurations
must land in reachable voxels (position-only queries: any orientation), and a corner of the
default box, farther from the chain's first joint than the chain's total length, must be
unreached.
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.kinematics.reachability.bins import orientation_bins
from app.kinematics.reachability.spec import (
    DEFAULT_VOXELS_PER_EDGE,
    MAX_CELLS,
    default_bounds,
    make_spec,
)
from app.main import create_app
from app.operations.settings import Settings
from app.robots.registry import Registry

CATALOG = Registry().ids()  # the ids GET /robots lists (checked below)
CONFIGURATIONS = 5


@pytest.fixture(scope="module")
def shared(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TestClient]:
    data = Path(tmp_path_factory.mktemp("reach-defaults")) / "data"
    with TestClient(create_app(Settings(data_dir=data)), raise_server_exceptions=False) as c:
        yield c


def wait_done(client: TestClient, robot_id: str, job_id: str) -> dict:
    """Poll a build until it ends (120 s: a guard against a hang, not a speed limit)."""
    end = time.monotonic() + 120
    while True:
        job = client.get(f"/robots/{robot_id}/reachability/jobs/{job_id}").json()
        if job["status"] not in ("queued", "running"):
            return job
        assert time.monotonic() < end, job
        time.sleep(0.02)


def test_the_parametrisation_is_get_robots(shared: TestClient) -> None:
    assert sorted(r["id"] for r in shared.get("/robots").json()["robots"]) == sorted(CATALOG)
    assert len(CATALOG) >= 10


@pytest.mark.parametrize("robot_id", CATALOG)
def test_empty_build_request_makes_a_coarse_map_that_fk_agrees_with(
    shared: TestClient, robot_id: str
) -> None:
    detail = shared.get(f"/robots/{robot_id}").json()
    tip = detail["end_effector"]
    assert tip, f"{robot_id} has no default tip"

    resp = shared.post(f"/robots/{robot_id}/reachability", json={})
    assert resp.status_code == 202, resp.text
    assert resp.json()["frame"] == tip
    job = wait_done(shared, robot_id, resp.json()["job_id"])
    assert job["status"] == "done", job
    meta = shared.get(f"/robots/{robot_id}/reachability/maps/{job['map_id']}").json()

    # Coarse: the box's longest edge over 24 voxels, the documented sample count and bins.
    lower, upper = np.array(meta["bounds"]["min"]), np.array(meta["bounds"]["max"])
    assert max(meta["shape"]) == DEFAULT_VOXELS_PER_EDGE
    assert np.allclose(upper - lower, np.array(meta["shape"]) * meta["voxel_size"])
    assert meta["samples"] == 200_000 and meta["orientation_divisions"] == 4
    assert meta["cells"] <= MAX_CELLS
    assert 0 < meta["reachable_voxels"] < math.prod(meta["shape"])

    # FK (Pinocchio, not the map's vectorised chain) of seeded random configurations.
    rng = np.random.default_rng(2024)
    limits = [j["limits"] for j in detail["joints"]]
    lo = np.array([-math.pi if x["lower"] is None else x["lower"] for x in limits])
    hi = np.array([math.pi if x["upper"] is None else x["upper"] for x in limits])
    positions = []
    for _ in range(CONFIGURATIONS):
        fk = shared.post(
            f"/robots/{robot_id}/fk", json={"q": rng.uniform(lo, hi).tolist(), "frames": [tip]}
        )
        assert fk.status_code == 200, fk.text
        positions.append(fk.json()["poses"][tip]["position"])
    # The corner of the (cubic) default box: √3 × the half-size from its centre, farther
    # than the chain's total length from the first joint (the centre), so never reached.
    corner = (lower + 1e-6).tolist()
    query = {"map_id": meta["map_id"], "poses": [{"position": p} for p in [*positions, corner]]}
    answer = shared.post(f"/robots/{robot_id}/reachability/query", json=query)
    assert answer.status_code == 200, answer.text
    body = answer.json()
    assert body["reachable"] == [True] * CONFIGURATIONS + [False], body
    assert body["in_bounds"] == [True] * (CONFIGURATIONS + 1)


@pytest.mark.parametrize("divisions", [0, 4, 8, 12])
def test_default_voxels_shrink_to_fit_the_cell_limit(registry: Registry, divisions: int) -> None:
    """Without voxel_size, any orientation_divisions fits MAX_CELLS, with the finest voxel
    of the documented steps (24 voxels on the longest edge, then 5 % larger each)."""
    robot = registry.get("ur10")  # the longest reach of the catalog arms
    spec = make_spec(robot, robot.ee_frame, orientation_divisions=divisions)
    assert spec.cells <= MAX_CELLS
    lower, upper = default_bounds(robot, robot.ee_frame)  # the box the voxels cover
    edge = float(max(upper - lower))
    steps = round(math.log(spec.voxel_size * DEFAULT_VOXELS_PER_EDGE / edge) / math.log(1.05))
    assert spec.voxel_size == pytest.approx(edge / DEFAULT_VOXELS_PER_EDGE * 1.05**steps)
    if steps:  # one step finer would not fit
        finer = make_spec(robot, robot.ee_frame, voxel_size=spec.voxel_size / 1.05)
        assert finer.cells // finer.bins * orientation_bins(divisions) > MAX_CELLS
    else:
        assert max(spec.shape) == DEFAULT_VOXELS_PER_EDGE


def test_default_voxels_of_a_box_too_large_name_bounds(shared: TestClient) -> None:
    huge = {"bounds": {"min": [-1e308, 0, 0], "max": [1e308, 1, 1]}}
    resp = shared.post("/robots/ur3/reachability", json=huge)
    assert resp.status_code == 422 and resp.json()["field"] == "bounds", resp.text
