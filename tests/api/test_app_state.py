"""The app's stores and pools (:mod:`app.api.state`): made once by the lifespan, used by
every request, closed at shutdown; an app whose lifespan has not run answers 503 where it
would need them, never 500."""

from __future__ import annotations

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest
from fastapi.testclient import TestClient

from app.storage.scenes import SceneStore
from tests.helpers import problem

#: A build that runs for minutes (cancelled long before).
LONG_BUILD = {
    "voxel_size": 0.05,
    "bounds": {"min": [-2, -2, -0.025], "max": [2, 2, 0.025]},
    "orientation_divisions": 0,
    "samples": 500_000_000,
}


def test_concurrent_first_uses_share_one_scene_store(app, monkeypatch) -> None:
    """Two first uses of the scene store at once see one store. A store made on first use
    without a lock (as ``SceneStoreDep`` once did, from the thread pool) is made twice
    here: both requests wait for each other inside the store's constructor."""
    both = threading.Barrier(2, timeout=30)
    real_init, real_list = SceneStore.__init__, SceneStore.list
    used: list[int] = []

    def init(self, root) -> None:
        try:
            both.wait()
        except threading.BrokenBarrierError:  # a single construction: nobody to meet
            pass
        real_init(self, root)

    def listing(self):
        used.append(id(self))
        return real_list(self)

    with TestClient(app, raise_server_exceptions=False) as client:
        monkeypatch.setattr(SceneStore, "__init__", init)
        monkeypatch.setattr(SceneStore, "list", listing)
        with ThreadPoolExecutor(2) as pool:
            answers = list(pool.map(lambda _: client.get("/scenes"), range(2)))
    assert [r.status_code for r in answers] == [200, 200]
    assert len(used) == 2 and len(set(used)) == 1


def test_the_lifespan_makes_the_services_and_shutdown_stops_them(app) -> None:
    """Made at start-up (the routes use those), closed at shutdown: a running build is
    cancelled (its processes stop), the work pools take no more work, the batch IK pool
    has no process left."""
    assert getattr(app.state, "services", None) is None  # nothing before the lifespan
    with TestClient(app, raise_server_exceptions=False) as client:
        services = app.state.services
        r = client.post("/robots/planar2/reachability", json=LONG_BUILD)
        assert r.status_code == 202, r.text
        job = services.jobs.jobs[r.json()["job_id"]]
        assert client.get("/scenes").status_code == 200
    assert app.state.services is None
    end = time.monotonic() + 120  # generous: the build thread notices the cancel flag
    while job.status in ("queued", "running") and time.monotonic() < end:
        time.sleep(0.05)
    assert job.status == "cancelled"
    for pool in (services.compute, services.uploads):
        with pytest.raises(RuntimeError):
            pool.submit(int)
    assert services.ik_batch._executor is None


def test_an_app_whose_lifespan_has_not_run_answers_503(app) -> None:
    """Without start-up there is no store: 503 problem details, not a 500."""
    client = TestClient(app, raise_server_exceptions=False)  # no ``with``: no lifespan
    r = client.get("/scenes")
    problem(r, 503)
    assert "not started" in r.json()["detail"]
    assert client.get("/health").status_code == 200
