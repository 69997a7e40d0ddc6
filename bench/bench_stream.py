"""IK round trips over HTTP and over ``WS /robots/{id}/stream``, side by side in one run.

``python -m bench stream`` prints one markdown table (docs/benchmarks.md, "IK stream"): a
real server (``python -m app``, 1 uvicorn worker, as deployed) on 127.0.0.1; a jog
trajectory of ``DENAVIT_BENCH_N`` targets (default 2000; 0.2 mm steps along a line near a
mid-range configuration, UR5 and Panda), each target solved once per transport, the
transports alternating target by target so load hits them alike:

- **HTTP**: POST /ik on one keep-alive ``httpx`` connection, each request seeded by the
  previous answer (``seed``), sequential;
- **stream, JSON**: one socket (``websockets`` sync client, no compression), one ``ik``
  message at a time, seeded by the stream itself (the last solution);
- **stream, binary**: the same socket, binary IK frames (the options of the JSON message);
- **stream, binary, 8 in flight**: the same frames pipelined (the time between answers;
  "median" and "p99" are then of that interval, not of a round trip).

Two runs: the server and the client free to migrate between cores, then each pinned to a
core of its own (a servo-rate deployment pins its server: the wake-ups that cross cores and
a process moved mid-request are most of the p99). Per transport: round trips per second
(1 / mean round trip), median and p99 round trip.
Targets: the stream ≥ 5× HTTP's round trips per second, p99 < 1 ms for the UR5 step.
"""

from __future__ import annotations

import os
import statistics
import time

import httpx
import numpy as np
import orjson
from websockets.sync.client import connect

from bench._http import serve
from bench.bench_ik_http import JSON, ROBOTS, N, pose_target

STEP_M = 2e-4
#: Binary frames with several in flight (the seeding is the server's, so a client may send
#: the next targets before the answers come back; HTTP has no such mode).
WINDOW = 8
PIPELINED = f"stream, binary, {WINDOW} in flight"
TRANSPORTS = ("HTTP", "stream, JSON", "stream, binary", PIPELINED)


def _targets(pose: dict) -> list[tuple[list[float], list[float]]]:
    """A line of N targets from ``pose`` (back and forth over 2 cm), same orientation."""
    p0 = np.array(pose["position"])
    steps = np.arange(N) % 200
    steps = np.where(steps < 100, steps, 200 - steps)
    return [((p0 + [STEP_M * s, 0.0, 0.0]).tolist(), pose["orientation"]) for s in steps]


def _run(url: str, robot_id: str, q: list[float]) -> dict[str, list[float]]:
    times: dict[str, list[float]] = {name: [] for name in TRANSPORTS}
    ws_url = url.replace("http://", "ws://") + f"/robots/{robot_id}/stream"
    with (
        httpx.Client(base_url=url, timeout=120) as http,
        connect(ws_url, compression=None, proxy=None, open_timeout=60) as ws,
    ):
        fk = http.post(f"/robots/{robot_id}/fk", json={"q": q}).json()
        pose = next(iter(fk["poses"].values()))
        targets = _targets(pose)
        seed = q
        ws.send(
            orjson.dumps({"id": 0, "op": "ik", "seed": q, "target": pose_target(pose)}).decode()
        )
        assert orjson.loads(ws.recv())["success"]
        for _ in range(50):  # warm-up
            http.post(f"/robots/{robot_id}/ik", json={"target": pose_target(pose)})
        for i, (p, o) in enumerate(targets):
            target = {"position": p, "orientation": o}
            t = time.perf_counter()
            r = http.post(f"/robots/{robot_id}/ik", content=orjson.dumps(
                {"target": target, "seed": seed}), headers=JSON)  # fmt: skip
            times["HTTP"].append(time.perf_counter() - t)
            answer = r.json()
            seed = answer["q"] if answer["success"] else seed

            t = time.perf_counter()
            ws.send(orjson.dumps({"id": i, "op": "ik", "target": target}).decode())
            answer = orjson.loads(ws.recv())
            times["stream, JSON"].append(time.perf_counter() - t)
            assert answer["id"] == i

            frame = np.array([3.0, float(i), *p, *o], "<f8").tobytes()
            t = time.perf_counter()
            ws.send(frame)
            reply = ws.recv()
            times["stream, binary"].append(time.perf_counter() - t)
            assert isinstance(reply, bytes), reply
        times[PIPELINED] = _pipelined(ws, targets)
    return times


def _pipelined(ws, targets: list[tuple[list[float], list[float]]]) -> list[float]:
    """Binary IK frames with up to :data:`WINDOW` unanswered (the server still solves them in
    order, each seeded by the previous solution): the time per answer, arrival to arrival."""
    frames = [np.array([3.0, i, *p, *o], "<f8").tobytes() for i, (p, o) in enumerate(targets)]
    out = []
    for frame in frames[:WINDOW]:
        ws.send(frame)
    last = time.perf_counter()
    for i in range(len(frames)):
        ws.recv()
        if i + WINDOW < len(frames):
            ws.send(frames[i + WINDOW])
        now = time.perf_counter()
        out.append(now - last)
        last = now
    return out


def _pin(pids: list[int], cpu: int) -> None:
    """Every thread of ``pids`` onto ``cpu``."""
    for pid in pids:
        for tid in os.listdir(f"/proc/{pid}/task"):
            os.sched_setaffinity(int(tid), {cpu})


def main() -> None:
    cpus = sorted(os.sched_getaffinity(0))
    for pinned in (False, True) if len(cpus) >= 2 else (False,):
        _table(pinned, cpus)


def _table(pinned: bool, cpus: list[int]) -> None:
    """One run: the server and this client free to migrate between cores, or each pinned to
    a core of its own (as a servo-rate deployment would: ``docker run --cpuset-cpus``)."""
    results = {}
    mine = os.sched_getaffinity(0)
    with serve(workers="1") as server:
        if pinned:
            _pin(server.pids(), cpus[0])
            os.sched_setaffinity(0, {cpus[1]})  # threads made from now on inherit it
        try:
            for robot_id, q in ROBOTS.items():
                results[robot_id] = _run(server.url, robot_id, q)
        finally:
            os.sched_setaffinity(0, mine)
    where = "server and client each pinned to a core" if pinned else "not pinned"
    print(f"\nIK round trips, one connection, sequential ({N} jog steps of {STEP_M * 1e3:g} mm, "
          f"each seeded by the previous solution; {where})\n")  # fmt: skip
    print("| robot | transport | round trips/s | × HTTP | median (ms) | p99 (ms) |")
    print("|---|---|---:|---:|---:|---:|")
    for robot_id, times in results.items():
        http_rate = 1.0 / statistics.fmean(times["HTTP"])
        for name in TRANSPORTS:
            t = np.array(times[name]) * 1e3
            rate = 1e3 / t.mean()
            print(f"| {robot_id} | {name} | {rate:,.0f} | {rate / http_rate:.1f}× | "
                  f"{np.median(t):.3f} | {np.percentile(t, 99):.3f} |")  # fmt: skip


if __name__ == "__main__":
    main()
