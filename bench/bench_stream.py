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
- **stream, binary, blocking client**: the same frames on a second socket read by the
  calling thread itself (:class:`bench._ws.BlockingWebSocket`): the ``websockets`` sync
  client hands each message over from a background reader thread, ~0.07 ms a round trip
  here, which a servo loop waiting for each answer need not pay;
- **stream, binary, asyncio client**: the same frames on a third socket, the ``websockets``
  asyncio client (``websockets.asyncio.client``, the standard library's event loop), each
  round trip timed inside its coroutine (send, then await the answer), as a servo loop
  written with asyncio would: no reader thread, the loop's own wake-up instead;
- **stream, binary, denavit_client**: the same targets on a fourth socket, through the
  project's Python client (``denavit_client.stream.open_stream``, ``Stream.ik_step``: its
  frame built and its answer unpacked with NumPy, the socket read in the calling thread by
  ``websockets``' own sans-I/O protocol, :class:`denavit_client.stream.CallingThreadWebSocket`),
  what a lab's servo loop written with the client pays;
- **stream, binary, 8 in flight**: the same frames pipelined (the time between answers;
  "median" and "p99" are then of that interval, not of a round trip).

Two runs: the server and the client free to migrate between cores, then each pinned to a
core of its own (a servo-rate deployment pins its server: the wake-ups that cross cores and
a process moved mid-request are most of the p99). Per transport: round trips per second
(1 / mean round trip, the target's measure), median and p99 round trip, and the ratio of
HTTP's median to the transport's (on a loaded machine the mean follows the other processes'
scheduling more than either transport).
Targets: the stream ≥ 5× HTTP's round trips per second, p99 < 1 ms for the UR5 step; a
line per run says met or not, for each one-at-a-time binary row.

With ``DENAVIT_BENCH_BASELINE_TREE`` naming a checkout of earlier code, a server of that
code beside this one's: the same binary frames alternating between the two, one at a time,
with the blocking and the ``websockets`` sync clients (medians, and the change).

Then where one binary round trip goes, stage by stage, and the floors below the service (a
bare WebSocket echo and a raw TCP echo, same client): :mod:`bench._stream_profile`.
"""

from __future__ import annotations

import asyncio
import os
import statistics
import time

import httpx
import numpy as np
import orjson
from denavit_client.models import IKRequest
from denavit_client.stream import open_stream
from websockets.asyncio.client import connect as aio_connect
from websockets.sync.client import connect

from bench._http import serve
from bench._stream_profile import floors, profile
from bench._ws import BlockingWebSocket
from bench.bench_ik_http import JSON, ROBOTS, N, _serve_tree, pose_target

STEP_M = 2e-4
#: Binary frames with several in flight (the seeding is the server's, so a client may send
#: the next targets before the answers come back; HTTP has no such mode).
WINDOW = 8
PIPELINED = f"stream, binary, {WINDOW} in flight"
BLOCKING = "stream, binary, blocking client"
ASYNCIO = "stream, binary, asyncio client"
CLIENT = "stream, binary, denavit_client"
TRANSPORTS = ("HTTP", "stream, JSON", "stream, binary", BLOCKING, ASYNCIO, CLIENT, PIPELINED)
#: The one-at-a-time binary rows (each gets its target line).
ONE_AT_A_TIME = ("stream, binary", BLOCKING, ASYNCIO, CLIENT)
#: The targets: one-at-a-time stream round trips per second over HTTP's, UR5 p99 (ms).
TARGET_RATIO, TARGET_P99_MS = 5.0, 1.0


def _targets(pose: dict) -> list[tuple[list[float], list[float]]]:
    """A line of N targets from ``pose`` (back and forth over 2 cm), same orientation."""
    p0 = np.array(pose["position"])
    steps = np.arange(N) % 200
    steps = np.where(steps < 100, steps, 200 - steps)
    return [((p0 + [STEP_M * s, 0.0, 0.0]).tolist(), pose["orientation"]) for s in steps]


async def _aio_round(aws, message: bytes | str) -> tuple[float, bytes | str]:
    """One round trip of the asyncio client, timed inside the coroutine."""
    t = time.perf_counter()
    await aws.send(message)
    reply = await aws.recv()
    return time.perf_counter() - t, reply


def _run(url: str, robot_id: str, q: list[float]) -> dict[str, list[float]]:
    times: dict[str, list[float]] = {name: [] for name in TRANSPORTS}
    ws_url = url.replace("http://", "ws://") + f"/robots/{robot_id}/stream"
    loop = asyncio.new_event_loop()
    try:
        aws = loop.run_until_complete(
            aio_connect(ws_url, compression=None, proxy=None, open_timeout=60)
        )
        try:
            return _run_on(url, ws_url, robot_id, q, times, loop, aws)
        finally:
            loop.run_until_complete(aws.close())
    finally:
        loop.close()


def _run_on(url, ws_url, robot_id, q, times, loop, aws) -> dict[str, list[float]]:
    with (
        httpx.Client(base_url=url, timeout=120) as http,
        connect(ws_url, compression=None, proxy=None, open_timeout=60) as ws,
        open_stream(url, robot_id) as client,
    ):
        fk = http.post(f"/robots/{robot_id}/fk", json={"q": q}).json()
        pose = next(iter(fk["poses"].values()))
        targets = _targets(pose)
        seed = q
        port = int(url.rsplit(":", 1)[1])
        lean = BlockingWebSocket("127.0.0.1", port, f"/robots/{robot_id}/stream")
        first = orjson.dumps({"id": 0, "op": "ik", "seed": q, "target": pose_target(pose)})
        for sock in (ws, lean):
            sock.send(first.decode())
            assert orjson.loads(sock.recv())["success"]
        assert orjson.loads(loop.run_until_complete(_aio_round(aws, first.decode()))[1])["success"]
        assert client.ik(IKRequest.from_dict({"seed": q, "target": pose_target(pose)})).success
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

            t = time.perf_counter()
            lean.send(frame)
            reply = lean.recv()
            times[BLOCKING].append(time.perf_counter() - t)
            assert isinstance(reply, bytes), reply

            dt, reply = loop.run_until_complete(_aio_round(aws, frame))
            times[ASYNCIO].append(dt)
            assert isinstance(reply, bytes), reply

            t = time.perf_counter()
            client.ik_step(p, o)
            times[CLIENT].append(time.perf_counter() - t)
        lean.close()
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


def _against_baseline(tree: str, poses: dict[str, dict]) -> None:
    """Binary frames one at a time, alternating between this code's server and ``tree``'s,
    through the blocking and the ``websockets`` sync clients: medians (ms)."""
    rows = []
    with _serve_tree(None) as new, _serve_tree(tree) as old:
        for robot_id, q in ROBOTS.items():
            pose = next(iter(poses[robot_id]["poses"].values()))
            first = orjson.dumps({"id": 0, "op": "ik", "seed": q, "target": pose_target(pose)})
            socks = {}
            for who, server in (("baseline", old), ("this code", new)):
                port = int(server.url.rsplit(":", 1)[1])
                path = f"/robots/{robot_id}/stream"
                ws_url = server.url.replace("http://", "ws://") + path
                socks[who, "blocking"] = BlockingWebSocket("127.0.0.1", port, path)
                socks[who, "websockets sync"] = connect(ws_url, compression=None, proxy=None)
            for sock in socks.values():
                sock.send(first.decode())
                assert orjson.loads(sock.recv())["success"]
            times: dict[tuple[str, str], list[float]] = {k: [] for k in socks}
            for i, (p, o) in enumerate(_targets(pose)):
                frame = np.array([3.0, float(i), *p, *o], "<f8").tobytes()
                for key, sock in socks.items():
                    t = time.perf_counter()
                    sock.send(frame)
                    reply = sock.recv()
                    if i >= 50:
                        times[key].append(time.perf_counter() - t)
                    assert isinstance(reply, bytes), reply
            for sock in socks.values():
                sock.close()
            for client in ("blocking", "websockets sync"):
                a = statistics.median(times["baseline", client]) * 1e3
                b = statistics.median(times["this code", client]) * 1e3
                rows.append((robot_id, client, a, b))
    print(f"\nBinary IK frames one at a time, this code against {tree} (alternating frame by "
          f"frame, not pinned; load average {os.getloadavg()[0]:.1f})\n")  # fmt: skip
    print("| robot | client | baseline median (ms) | this code median (ms) | change |")
    print("|---|---|---:|---:|---:|")
    for robot_id, client, a, b in rows:
        print(f"| {robot_id} | {client} | {a:.3f} | {b:.3f} | {(b - a) * 1e3:+.1f} µs |")


def _pin(pids: list[int], cpu: int) -> None:
    """Every thread of ``pids`` onto ``cpu``."""
    for pid in pids:
        for tid in os.listdir(f"/proc/{pid}/task"):
            os.sched_setaffinity(int(tid), {cpu})


def main() -> None:
    cpus = sorted(os.sched_getaffinity(0))
    for pinned in (False, True) if len(cpus) >= 2 else (False,):
        _table(pinned, cpus)
    with serve(workers="1") as server, httpx.Client(base_url=server.url) as http:
        poses = {r: http.post(f"/robots/{r}/fk", json={"q": q}).json() for r, q in ROBOTS.items()}
    tree = os.environ.get("DENAVIT_BENCH_BASELINE_TREE")
    if tree:
        _against_baseline(tree, poses)
    for robot_id, q in ROBOTS.items():
        pose = next(iter(poses[robot_id]["poses"].values()))
        profile(robot_id, q, pose_target(pose), _targets(pose), min(N, 2000))
    floors(min(N, 2000))


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
    print(f"\nload average {os.getloadavg()[0]:.1f}")
    print(f"IK round trips, one connection, sequential ({N} jog steps of {STEP_M * 1e3:g} mm, "
          f"each seeded by the previous solution; {where})\n")  # fmt: skip
    print(
        "| robot | transport | round trips/s | × HTTP | median (ms) | × HTTP by median | p99 (ms) |"
    )
    print("|---|---|---:|---:|---:|---:|---:|")
    for robot_id, times in results.items():
        http_rate = 1.0 / statistics.fmean(times["HTTP"])
        http_median = statistics.median(times["HTTP"]) * 1e3
        for name in TRANSPORTS:
            t = np.array(times[name]) * 1e3
            rate = 1e3 / t.mean()
            print(f"| {robot_id} | {name} | {rate:,.0f} | {rate / http_rate:.1f}× | "
                  f"{np.median(t):.3f} | {http_median / np.median(t):.1f}× | "
                  f"{np.percentile(t, 99):.3f} |")  # fmt: skip
    print()
    for robot_id, times in results.items():
        http_rate = 1.0 / statistics.fmean(times["HTTP"])
        for name in ONE_AT_A_TIME:
            t = np.array(times[name]) * 1e3
            ratio, p99 = 1e3 / t.mean() / http_rate, np.percentile(t, 99)
            line = (f"target ({where}), {robot_id}, {name}: ≥ {TARGET_RATIO:g}× HTTP's round "
                    f"trips/s (HTTP {http_rate:,.0f}/s in this run): {ratio:.1f}× — "
                    f"{'met' if ratio >= TARGET_RATIO else 'NOT met'} (by median: "
                    f"{statistics.median(times['HTTP']) * 1e3 / np.median(t):.1f}×)")  # fmt: skip
            if robot_id == "ur5":
                line += (f"; p99 < {TARGET_P99_MS:g} ms: {p99:.3f} ms — "
                         f"{'met' if p99 < TARGET_P99_MS else 'NOT met'}")  # fmt: skip
            print(line)


if __name__ == "__main__":
    main()
