"""IK batches with ``chain_seeds: false`` spread over worker processes.

The reference is the core's single-target solve, called here target by target with the
documented per-target generator (child ``i`` of ``SeedSequence(random_seed)``): a batch must
give exactly those answers whatever the number of processes and the chunking. Budgets are
iteration caps with time limits generous enough never to bind.
"""

from __future__ import annotations

import os
import signal
import threading
from pathlib import Path

import httpx
import numpy as np
import pinocchio as pin
import pytest
from fastapi.testclient import TestClient

from app.kinematics import ik
from app.kinematics.collision import collision_filter
from app.kinematics.errors import Cancelled
from app.kinematics.ik.problem import IKOptions, target_placement
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import parse_obstacles
from app.main import create_app
from app.operations.settings import Settings
from app.workers import ik_batch
from tests.api.ik_batch_segments import leftover_segments
from tests.helpers import descendants, parse_metrics, problem, send_and_hang_up, serve

RANDOM_SEED = 1234
CAPPED = {"timeout_ms": 200.0, "max_iterations": 300}
#: Changing fields: everything else of an answer must be equal bit for bit.
TIMES = ("solve_time_ms",)
BOX = {"name": "box", "shape": "box", "size": [0.3, 0.3, 0.3], "pose": {"position": [0.45, 0, 0.5]}}


def _targets(robot, frame: str, n: int, seed: int) -> list[pin.SE3]:
    """FK of ``n`` configurations uniform within the limits (a few beyond reach appended)."""
    rng = np.random.default_rng(seed)
    lo, hi = np.clip(robot.lower, -np.pi, np.pi), np.clip(robot.upper, -np.pi, np.pi)
    out = []
    for _ in range(n - 2):
        q = rng.uniform(lo, hi)
        model, data = robot.model, robot.model.createData()
        pin.forwardKinematics(model, data, robot.to_pin(q))
        out.append(pin.updateFramePlacement(model, data, robot.frame_id(frame)).copy())
    far = pin.SE3(np.eye(3), np.array([0.0, 1.0, 0.333]))  # beyond reach, inside the bound
    return out + [far, far]


def _body(robot, frame: str, targets: list[pin.SE3], **extra) -> dict:
    return {
        "frame": frame,
        "targets": [{"matrix": T.homogeneous.tolist()} for T in targets],
        "seed": robot.mid_range().tolist(),
        "chain_seeds": False,
        "random_seed": RANDOM_SEED,
        **CAPPED,
        **extra,
    }


def _reference(robot, frame: str, targets: list[pin.SE3], accept=None) -> list[dict]:
    """Each target solved alone by the core, with its own generator."""
    options = IKOptions(
        frame=frame, timeout_ms=CAPPED["timeout_ms"], max_iterations=CAPPED["max_iterations"]
    )
    out = []
    for i, wire in enumerate(targets):
        # the server's reading of the wire matrix (it re-orthonormalises the rotation)
        T = target_placement(None, None, wire.homogeneous.tolist(), "pose")
        rng = np.random.default_rng(np.random.SeedSequence(RANDOM_SEED, spawn_key=(i,)))
        res = ik.solve(robot, T, options, seed=robot.mid_range(), accept=accept, rng=rng)
        out.append(
            {
                "success": res.success,
                "q": res.q.tolist(),
                "position_error": res.position_error,
                "orientation_error": res.orientation_error,
                "iterations": res.iterations,
                "restarts": res.restarts,
                "status": res.status,
                "reason": res.reason,
                "detail": res.detail,
            }
        )
    return out


def _same(results: list[dict], reference: list[dict]) -> None:
    assert len(results) == len(reference)
    for i, (got, want) in enumerate(zip(results, reference, strict=True)):
        got = {k: v for k, v in got.items() if k not in TIMES}
        assert got == want, f"target {i}"


@pytest.fixture
def pooled(tmp_path: Path):
    """A client whose server solves batches in 2 worker processes (the app's pool, stopped
    by its lifespan)."""
    app = create_app(Settings(data_dir=tmp_path / "data", ik_batch_processes=2))
    with TestClient(app, raise_server_exceptions=False) as c:
        yield c


def _pool_pids(client: TestClient) -> list[int]:
    pool = client.app.state.services.ik_batch
    executor = pool._executor
    return [] if executor is None else list(executor._processes)


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("ur5", "tool0")])
def test_two_processes_answer_as_each_target_alone(pooled, registry, robot_id, frame) -> None:
    robot = registry.get(robot_id)
    targets = _targets(robot, frame, 40, seed=3)
    r = pooled.post(f"/robots/{robot_id}/ik/batch", json=_body(robot, frame, targets))
    assert r.status_code == 200, r.text
    assert len(_pool_pids(pooled)) == 2  # the batch went through the worker processes
    out = r.json()
    _same(out["results"], _reference(robot, frame, targets))
    assert out["solved"] == sum(x["success"] for x in out["results"]) >= 38


def test_chunk_boundaries_do_not_change_answers(pooled, registry, monkeypatch) -> None:
    """Chunks of 3 over 11 targets (a short last chunk), in order."""
    monkeypatch.setattr(ik_batch, "CHUNK_MAX", 3)
    monkeypatch.setattr(ik_batch, "MIN_PARALLEL", 2)
    robot = registry.get("panda")
    targets = _targets(robot, "panda_link8", 11, seed=5)
    r = pooled.post("/robots/panda/ik/batch", json=_body(robot, "panda_link8", targets))
    assert r.status_code == 200, r.text
    assert len(_pool_pids(pooled)) == 2
    _same(r.json()["results"], _reference(robot, "panda_link8", targets))


def test_collision_aware_batch_in_the_pool(pooled, registry) -> None:
    robot = registry.get("panda")
    targets = _targets(robot, "panda_link8", 34, seed=8)
    body = _body(robot, "panda_link8", targets, avoid_collisions=True, obstacles=[BOX])
    r = pooled.post("/robots/panda/ik/batch", json=body)
    assert r.status_code == 200, r.text
    assert len(_pool_pids(pooled)) == 2
    accept = collision_filter(robot, parse_obstacles([BOX]), margin=0.0, mode="mesh")
    _same(r.json()["results"], _reference(robot, "panda_link8", targets, accept))


def test_cancel_withdraws_the_batch(registry) -> None:
    """The caller's event set while a batch of slow targets runs (64 × 400 ms beyond reach
    but inside the reach bound, each searching its whole budget: 12.8 s of work): Cancelled
    is raised, only the chunks solved before are recorded, the segment is unlinked, and the
    pool answers the next batch in full (the withdrawn batch's drains stop claiming its
    chunks)."""
    robot = registry.get("panda")
    slow = [pin.SE3(np.eye(3), np.array([0.0, 0.95, 0.333]))] * 64
    cancel = threading.Event()
    seen: list[bool] = []
    pool = ik_batch.BatchPool(2)
    failed: list[BaseException] = []

    def run() -> None:
        options = IKOptions(frame="panda_link8", mode="position", timeout_ms=400.0)
        task = ik_batch.BatchTask(robot.mid_range(), options, random_seed=1)
        try:
            pool.solve(robot, slow, task, cancel=cancel, record=seen.append)
        except Cancelled as exc:
            failed.append(exc)

    thread = threading.Thread(target=run)
    try:
        thread.start()
        event = threading.Event()
        while thread.is_alive() and not leftover_segments():  # the batch is in the pool
            event.wait(0.005)
        cancel.set()
        thread.join(timeout=120)
        assert not thread.is_alive() and len(failed) == 1
        assert len(seen) < 64 and not any(seen)  # the chunks solved before, all unreachable
        assert not leftover_segments()  # the batch's shared segment was unlinked
        options = IKOptions(frame="panda_link8", timeout_ms=1000.0, max_iterations=400)
        good = _targets(robot, "panda_link8", 34, seed=4)
        out = pool.solve(robot, good, ik_batch.BatchTask(robot.mid_range(), options))
        assert out.solved >= 32 and len(out) == 34
    finally:
        pool.shutdown()


def test_a_killed_worker_gives_503_then_a_fresh_pool(pooled, registry) -> None:
    """kill -9 of a worker during a batch: 503 problem naming ``targets``; the next batch
    is answered by new workers."""
    robot = registry.get("panda")
    slow = [pin.SE3(np.eye(3), np.array([0.0, 1.0, 0.333]))] * 64  # 64 × 400 ms unreachable
    body = {**_body(robot, "panda_link8", slow), "mode": "position", "timeout_ms": 400.0}
    del body["max_iterations"]
    answer = {}
    thread = threading.Thread(
        target=lambda: answer.update(r=pooled.post("/robots/panda/ik/batch", json=body))
    )
    thread.start()
    event = threading.Event()
    while not _pool_pids(pooled) and thread.is_alive():
        event.wait(0.01)
    pids = _pool_pids(pooled)
    assert pids, answer
    os.kill(pids[0], signal.SIGKILL)
    thread.join(timeout=120)
    assert not thread.is_alive()
    problem(answer["r"], 503, "targets")
    assert not leftover_segments()
    good = _targets(robot, "panda_link8", 34, seed=4)
    r = pooled.post("/robots/panda/ik/batch", json=_body(robot, "panda_link8", good))
    assert r.status_code == 200, r.text
    assert pids[0] not in _pool_pids(pooled) and len(_pool_pids(pooled)) == 2


def _ik_failures(client: httpx.Client) -> float:
    metrics = parse_metrics(client.get("/metrics").text)
    return metrics['denavit_ik_requests_total{result="failure"}']


def test_a_hung_up_batch_frees_the_pool(tmp_path: Path, registry) -> None:
    """A live server (1 worker, a pool of 2): a batch of 64 unreachable targets × 400 ms
    (12.8 s of the pool's time), its client gone at once; the next batch (in the pool too)
    is answered while fewer than half of the abandoned targets were ever solved (the batch
    was withdrawn: its drains stopped claiming chunks, not queued ahead of the next batch).
    Beyond reach but inside the reach bound (0.95 m): each target searches its whole budget
    (1.0 m is outside the bound, classified unreachable in ~10 ms: all 64 could be solved
    before the server sees the client gone)."""
    robot = registry.get("panda")
    slow = [pin.SE3(np.eye(3), np.array([0.0, 0.95, 0.333]))] * 64
    abandoned = {**_body(robot, "panda_link8", slow), "mode": "position", "timeout_ms": 400.0}
    del abandoned["max_iterations"]
    good = _body(robot, "panda_link8", _targets(robot, "panda_link8", 34, seed=6)[:32])
    with serve(tmp_path / "data", settings={"ik_batch_processes": "2"}) as server:
        with httpx.Client(base_url=server.url, timeout=120) as c:
            assert c.post("/robots/panda/ik/batch", json=good).status_code == 200  # pool warm
            before = _ik_failures(c)
            send_and_hang_up(server.url, "/robots/panda/ik/batch", abandoned)
            r = c.post("/robots/panda/ik/batch", json=good)
            assert r.status_code == 200 and r.json()["solved"] == 32, r.text
            assert _ik_failures(c) - before < 32
            # the batches ran in the pool: the forkserver and its 2 workers below the server
            assert len(descendants(server.proc.pid)) >= 3


def test_a_replaced_robot_is_rebuilt_in_the_workers(registry) -> None:
    """The workers' cache key is the robot id and a digest of what it is built from: a robot
    replaced under the same id gets a new key, so workers never solve with the old one."""
    panda, ur5 = registry.get("panda"), registry.get("ur5")
    old = RobotModel("arm", panda.urdf_text, package_dirs=panda.package_dirs)
    new = RobotModel("arm", ur5.urdf_text, package_dirs=ur5.package_dirs)
    a, b = ik_batch.RobotRecipe.of(old), ik_batch.RobotRecipe.of(new)
    assert a.robot_id == b.robot_id == "arm" and a.key != b.key
    assert ik_batch.RobotRecipe.of(RobotModel("arm", panda.urdf_text)).key != a.key  # dirs
    rebuilt = b.build()
    assert rebuilt.joint_names == ur5.joint_names and rebuilt.urdf_text == ur5.urdf_text


#: Run in a fresh interpreter (no forkserver yet): a pool used from a short-lived thread (as
#: an app's compute pool thread, stopped with its app) until a worker has forked (so the
#: forkserver has set its death signal), then the forkserver's state once that thread has
#: left the kernel's task list.
_FORKSERVER_PROBE = """
import json, multiprocessing.forkserver, os, threading, time
from app.workers.ik_batch import BatchPool

pool = BatchPool(2)
t = threading.Thread(target=lambda: pool._pool().submit(int).result())  # a worker forked
t.start()
t.join()
end = time.monotonic() + 60
while os.path.exists(f"/proc/self/task/{t.native_id}") and time.monotonic() < end:
    time.sleep(0.01)
pid = multiprocessing.forkserver._forkserver._forkserver_pid
with open(f"/proc/{pid}/stat") as f:
    state = f.read().rpartition(")")[2].split()[0]
with open(f"/proc/{pid}/status") as f:
    pending = {k: int(v, 16) for k, _, v in (line.partition(":") for line in f)
               if k in ("SigPnd", "ShdPnd")}
print(json.dumps({"state": state, "kill_pending": any(v >> 8 & 1 for v in pending.values())}))
pool.shutdown()
"""


def test_the_forkserver_outlives_the_thread_that_started_the_pool() -> None:
    """The forkserver dies with the thread that started it (``PR_SET_PDEATHSIG``): a pool
    first used from a thread that ends (an app's compute pool, stopped by its lifespan)
    must not take it down, else the next pool of the process finds it gone. Checked
    without timing: once the thread has left the kernel's task list, its death signal
    has been sent, so the forkserver is either still clean or already doomed."""
    import json
    import subprocess
    import sys

    out = subprocess.run(
        [sys.executable, "-c", _FORKSERVER_PROBE],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
        cwd=Path(__file__).resolve().parents[2],
    )
    seen = json.loads(out.stdout.strip().splitlines()[-1])
    assert seen["state"] in ("R", "S", "D") and not seen["kill_pending"], seen  # alive, clean
