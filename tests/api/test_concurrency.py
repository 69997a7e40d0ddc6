"""Hundreds of concurrent requests on a real server, each answer checked."""

from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor

import httpx
import numpy as np

from app.kinematics.fk import forward_kinematics
from app.kinematics.jacobian import frame_jacobian
from tests.helpers import serve
from tests.kinematics.reference import random_configurations


def test_concurrent_requests_each_get_their_own_answer(tmp_path, registry) -> None:
    robots = {rid: registry.get(rid) for rid in ("panda", "ur5", "kinova")}
    jobs = []
    for k, (rid, robot) in enumerate(robots.items()):
        for i, q in enumerate(random_configurations(robot, 120, seed=k)):
            jobs.append((rid, ["fk", "jacobian", "batch"][i % 3], q))

    # One client (one connection) per thread: httpcore's shared sync pool can close a
    # connection another thread was just handed (encode/httpcore#1110), which shows up as
    # a client-side ReadError that says nothing about the server.
    local = threading.local()
    clients: list[httpx.Client] = []

    def call(job) -> tuple:
        client = getattr(local, "client", None)
        if client is None:
            client = local.client = httpx.Client(base_url=url, timeout=60)
            clients.append(client)
        rid, kind, q = job
        if kind == "fk":
            r = client.post(f"/robots/{rid}/fk", json={"q": q.tolist()})
        elif kind == "jacobian":
            r = client.post(f"/robots/{rid}/jacobian", json={"q": q.tolist()})
        else:
            r = client.post(f"/robots/{rid}/fk/batch", json={"configurations": [q.tolist()] * 3})
        return job, r.status_code, r.json()

    with serve(tmp_path / "data") as server:
        url = server.url
        try:
            with ThreadPoolExecutor(max_workers=48) as pool:
                results = list(pool.map(call, jobs))
        finally:
            for client in clients:
                client.close()

    assert len(results) == 360
    for (rid, kind, q), status, body in results:
        assert status == 200, body
        robot = robots[rid]
        ee = robot.ee_frame
        if kind == "jacobian":
            np.testing.assert_allclose(body["jacobian"], frame_jacobian(robot, q, ee), atol=1e-12)
            continue
        T = forward_kinematics(robot, q, [ee])[ee]
        if kind == "fk":
            np.testing.assert_allclose(body["q"], q, atol=0)
            np.testing.assert_allclose(body["poses"][ee]["matrix"], T, atol=1e-12)
        else:
            np.testing.assert_allclose(body["positions"], [T[:3, 3]] * 3, atol=1e-12)
