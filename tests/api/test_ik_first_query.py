"""The first IK query of a robot and frame builds the solver's restart table (one FK per
sample, tens of ms): it must not run on the event loop, which keeps answering /health
meanwhile. Later queries within the inline budget run on the loop."""

from __future__ import annotations

import asyncio
import threading

import numpy as np
import pytest

from app.kinematics.fk import forward_kinematics
from app.kinematics.ik import precompute
from app.kinematics.rotations import matrix_to_quaternion


def _on_event_loop() -> bool:
    try:
        asyncio.get_running_loop()
    except RuntimeError:
        return False
    return True


def _target(registry) -> dict:
    q = np.array([0.3, -0.4, 0.2, -1.8, 0.1, 1.6, 0.5, 0.0])
    T = forward_kinematics(registry.get("panda"), q, ["panda_link8"])["panda_link8"]
    return {"position": T[:3, 3].tolist(), "orientation": matrix_to_quaternion(T[:3, :3]).tolist()}


@pytest.fixture
def table_builds(monkeypatch) -> list[bool]:
    """One entry per restart-table build: whether it ran on an event loop."""
    calls: list[bool] = []
    real = precompute.table_poses

    def spy(robot, ch):
        calls.append(_on_event_loop())
        return real(robot, ch)

    monkeypatch.setattr(precompute, "table_poses", spy)
    return calls


def test_restart_table_is_built_off_the_event_loop(client, registry, table_builds) -> None:
    calls = table_builds
    body = {"target": _target(registry), "frame": "panda_link8"}  # default budget: inline
    # (success is not asserted: a 5 ms budget on a loaded machine may run out; where the
    # table is built is what matters)
    r = client.post("/robots/panda/ik", json=body)
    assert r.status_code == 200, r.text
    assert calls == [False]  # built once, in the pool
    assert client.post("/robots/panda/ik", json=body).status_code == 200
    assert calls == [False]  # cached


def test_health_answers_while_the_table_is_built(client, registry, monkeypatch) -> None:
    building, release = threading.Event(), threading.Event()
    real = precompute.table_poses

    def slow(robot, ch):
        building.set()
        assert release.wait(timeout=60)
        return real(robot, ch)

    monkeypatch.setattr(precompute, "table_poses", slow)
    answers: list[int] = []
    body = {"target": _target(registry), "frame": "panda_link8"}
    ik = threading.Thread(
        target=lambda: answers.append(client.post("/robots/panda/ik", json=body).status_code)
    )
    ik.start()
    health: list[int] = []
    try:
        assert building.wait(timeout=60)
        # the table is being built; the event loop is free: /health answers (a loop blocked
        # by the build would answer only after the release below: a generous timeout fails)
        probe = threading.Thread(target=lambda: health.append(client.get("/health").status_code))
        probe.start()
        probe.join(timeout=60)
        assert health == [200]
    finally:
        release.set()
        ik.join(timeout=120)
    assert answers == [200]
    assert health == [200]


def test_the_stream_builds_the_restart_table_off_the_event_loop(
    client, registry, table_builds
) -> None:
    """The stream's first IK message of a robot and frame is the same first query."""
    calls = table_builds
    message = {"id": 1, "op": "ik", "target": _target(registry), "frame": "panda_link8"}
    with client.websocket_connect("/robots/panda/stream") as ws:
        ws.send_json(message)
        assert ws.receive_json()["id"] == 1
        ws.send_json({**message, "id": 2})
        assert ws.receive_json()["id"] == 2
    assert calls == [False]  # built once, in the pool
