"""Dynamics over HTTP against FK over HTTP, and batch dynamics against raw Pinocchio.

``python -m bench dynamics`` prints two markdown tables (docs/benchmarks.md, "Dynamics"):

1. Single requests/s on one real uvicorn server (``python -m app``, one worker, loopback,
   wrk with 16 connections): POST /robots/{id}/fk and POST /robots/{id}/dynamics at the same
   configuration, for the UR5 and the Panda (mimic fingers), the dynamics once with the
   configuration alone and once with velocities, accelerations and a payload. Rows are
   measured in interleaved rounds (best of ``DENAVIT_BENCH_ROUNDS``, default 2,
   ``DENAVIT_BENCH_SECONDS`` per run, default 8) so load from other processes hits them
   alike. Target: every dynamics row ≥ 0.9× the FK row of its robot (within 10 %); the last
   lines print each ratio and "met" or "NOT met".
2. Batch: POST /robots/{id}/dynamics/batch with 10 000 states (q, q̇, q̈) against raw
   Pinocchio in a Python loop in process (``pin.rnea`` per state on the robot's model, the
   torques copied out), states/s.
"""

from __future__ import annotations

import os
import time

import httpx
import numpy as np
import orjson
import pinocchio as pin

from app.robots.registry import Registry
from bench._http import ensure_wrk, load, serve

CONNECTIONS = 16
BATCH = 10_000
ROBOTS = ("ur5", "panda")
#: The target: a dynamics request's requests/s at least this fraction of FK's.
TARGET_RATIO = 0.9
JSON = {"content-type": "application/json"}


def bodies(robot_id: str) -> dict[str, tuple[str, bytes]]:
    """Row name → (path, body) for ``robot_id`` at a fixed configuration."""
    robot = Registry().get(robot_id)
    rng = np.random.default_rng(1)
    lo, hi = np.maximum(robot.lower, -3), np.minimum(robot.upper, 3)
    q = rng.uniform(lo, hi).tolist()
    qd = rng.normal(size=robot.n).tolist()
    qdd = rng.normal(size=robot.n).tolist()
    full = {
        "q": q,
        "velocities": qd,
        "accelerations": qdd,
        "payload": {"mass": 1.5, "com": [0.0, 0.0, 0.05]},
    }
    return {
        "FK": (f"/robots/{robot_id}/fk", orjson.dumps({"q": q})),
        "dynamics, q only": (f"/robots/{robot_id}/dynamics", orjson.dumps({"q": q})),
        "dynamics, q, q̇, q̈ and a payload": (f"/robots/{robot_id}/dynamics", orjson.dumps(full)),
    }


def single(seconds: float, rounds: int) -> dict[tuple[str, str], tuple[float, float, float]]:
    """(robot, row) → best (requests/s, p50 ms, p99 ms)."""
    best: dict[tuple[str, str], tuple[float, float, float]] = {}
    rows = [(rid, name, path, body) for rid in ROBOTS for name, (path, body) in bodies(rid).items()]
    with serve() as server:
        for _, _, path, body in rows:
            check = httpx.post(server.url + path, content=body, headers=JSON)
            assert check.status_code == 200, check.text
            load(server.url + path, body, 1.0, CONNECTIONS)  # warm-up
        for _ in range(rounds):
            for rid, name, path, body in rows:
                r = load(server.url + path, body, seconds, CONNECTIONS)
                assert r.errors == 0, (rid, name, r)
                if r.rps > best.get((rid, name), (0.0,))[0]:
                    best[(rid, name)] = (r.rps, r.p50_ms, r.p99_ms)
    return best


def raw_pinocchio_states_per_s(
    robot_id: str, states: tuple[np.ndarray, ...], repeats: int = 3
) -> float:
    """States/s of ``pin.rnea`` in a Python loop on the robot's own model (torques copied)."""
    robot = Registry().get(robot_id)
    model, data = robot.model, robot.model.createData()
    qs, qds, qdds = states
    qps = [robot.to_pin(q) for q in qs]
    v = robot.v_index
    vs, accs = [], []
    for qd, qdd in zip(qds, qdds, strict=True):
        a, b = np.zeros(model.nv), np.zeros(model.nv)
        a[v], b[v] = qd, qdd
        vs.append(a)
        accs.append(b)
    best = 0.0
    for _ in range(repeats):
        t0 = time.perf_counter()
        for qp, qd, qdd in zip(qps, vs, accs, strict=True):
            pin.rnea(model, data, qp, qd, qdd).copy()
        best = max(best, len(qps) / (time.perf_counter() - t0))
    return best


def batch(robot_id: str, repeats: int = 5) -> tuple[float, float, int]:
    """(HTTP states/s, raw Pinocchio states/s, body bytes) for BATCH random states."""
    robot = Registry().get(robot_id)
    rng = np.random.default_rng(0)
    lo, hi = np.maximum(robot.lower, -3), np.minimum(robot.upper, 3)
    qs = rng.uniform(lo, hi, size=(BATCH, robot.n))
    qds, qdds = rng.normal(size=qs.shape), rng.normal(size=qs.shape)
    body = orjson.dumps(
        {
            "configurations": qs.tolist(),
            "velocities": qds.tolist(),
            "accelerations": qdds.tolist(),
        }
    )
    best = 0.0
    path = f"/robots/{robot_id}/dynamics/batch"
    with serve() as server, httpx.Client(base_url=server.url, timeout=120) as client:
        r = client.post(path, content=body, headers=JSON)  # warm-up
        assert r.status_code == 200, r.text
        for _ in range(repeats):
            t0 = time.perf_counter()
            r = client.post(path, content=body, headers=JSON)
            elapsed = time.perf_counter() - t0
            assert r.status_code == 200 and len(r.json()["torques"]) == BATCH
            best = max(best, BATCH / elapsed)
    return best, raw_pinocchio_states_per_s(robot_id, (qs, qds, qdds)), len(body)


def main() -> None:
    seconds = float(os.environ.get("DENAVIT_BENCH_SECONDS", "8"))
    rounds = int(os.environ.get("DENAVIT_BENCH_ROUNDS", "2"))
    tool = "wrk" if ensure_wrk() else "python asyncio client (wrk unavailable)"
    print(f"machine: {os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; load: {tool}, "
          f"{CONNECTIONS} connections, {seconds:g} s per run, best of {rounds}")  # fmt: skip
    print("\n### Dynamics vs FK, requests/s (uvicorn, 1 worker, loopback)\n")
    print("| robot | request | requests/s | p50 ms | p99 ms | vs FK |")
    print("|---|---|---|---|---|---|")
    best = single(seconds, rounds)
    verdicts = []
    for rid in ROBOTS:
        fk = best[(rid, "FK")][0]
        for (r, name), (rps, p50, p99) in best.items():
            if r != rid:
                continue
            print(f"| {rid} | {name} | {rps:.0f} | {p50:.2f} | {p99:.2f} | {rps / fk:.2f}× |")
            if name != "FK":
                ratio = rps / fk
                verdict = "met" if ratio >= TARGET_RATIO else "NOT met"
                verdicts.append(
                    f"Target: {rid} {name} ≥ {TARGET_RATIO:.2f}× FK | baseline (FK, same run): "
                    f"{fk:.0f} requests/s | measured {rps:.0f} = {ratio:.2f}× | {verdict}"
                )
    print()
    print("\n".join(verdicts))
    print(f"\n### Batch dynamics, states/s ({BATCH} states q, q̇, q̈)\n")
    print("| robot | path | states/s | vs raw |")
    print("|---|---|---|---|")
    for rid in ROBOTS:
        http, raw, size = batch(rid)
        print(f"| {rid} | raw Pinocchio `rnea`, Python loop, in process | {raw:.0f} | 1.00× |")
        print(f"| {rid} | POST /robots/{rid}/dynamics/batch ({size / 1e6:.1f} MB body) | "
              f"{http:.0f} | {http / raw:.2f}× |")  # fmt: skip


if __name__ == "__main__":
    main()
