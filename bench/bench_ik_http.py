"""What an IK request costs over HTTP beyond its solve, against an FK request.

``python -m bench ik_http`` prints one markdown table (docs/benchmarks.md, "IK over HTTP"):
for UR5 (closed form) and Panda, side by side in one run,

- **live**: a real server (``python -m app``, 1 uvicorn worker, access log on, as deployed)
  on 127.0.0.1, one keep-alive ``httpx`` client, sequential requests: median round trip of
  POST /fk (one configuration), of POST /ik (the pose of that configuration, default budget),
  the median ``solve_time_ms`` the server reports, and **IK − solve − FK**: what IK costs
  beyond its own solve and an FK request's round trip (target ≤ 0.1 ms);
- **in process**: the same requests through the ASGI app called directly (no socket, no
  client), in CPU time of the calling thread (``time.thread_time``), so load from other
  processes does not count; trimmed mean (the slowest 10 % dropped).

FK and IK requests alternate one by one so load hits both alike. ``DENAVIT_BENCH_N``
requests of each (default 2000).

A second table, **the served solve against ik_LM** (docs/benchmarks.md, "The served
solve"): TRAC-IK's protocol (``DENAVIT_BENCH_SERVED_N`` targets per robot, default 2000,
FK poses of configurations uniform within the limits; seed the middle of the limits;
‖e‖ ≤ 1e-5 m and rad; 5 ms), each target sent to a live server as above and the
``solve_time_ms`` it reports collected (mean, median), beside the Robotics Toolbox's C++
``ik_LM`` (tuned: ``tol`` 5e-11, so ‖e‖ ≤ 1e-5) on the same targets in its child process
(:mod:`bench.rtb_side`, ``DENAVIT_BENCH_PYTHON``), mean CPU per target. Blocks of 250
targets alternate between the two (and, with ``DENAVIT_BENCH_BASELINE_TREE`` naming a
checkout of older code, a server of that code too), so load hits all alike. Target: the
served mean ≤ 0.5× ik_LM's.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import math
import os
import statistics
import tempfile
import time
from pathlib import Path

import httpx
import numpy as np
import orjson

from app.kinematics.ik.precompute import ik_chain
from app.kinematics.rotations import matrix_to_quaternion
from bench._http import serve
from bench.bench_ik import IK_LM, targets
from bench.rtb_side import IkLM

N = int(os.environ.get("DENAVIT_BENCH_N", "2000"))
JSON = {"content-type": "application/json"}
ROBOTS = {
    "ur5": [0.3, -1.1, 1.4, -0.6, 1.2, 0.4],
    "panda": [0.2, -0.5, 0.1, -2.0, 0.3, 1.6, 0.6, 0.02],
}


def pose_target(pose: dict) -> dict:
    """The IK target of an FK answer's pose (position and quaternion)."""
    return {"position": pose["position"], "orientation": pose["orientation"]}


def _ik_body(pose: dict) -> bytes:
    return orjson.dumps({"target": pose_target(pose)})


def _trimmed_ms(values: list[float]) -> float:
    kept = sorted(values)[: max(1, int(len(values) * 0.9))]
    return statistics.fmean(kept) * 1e3


def live() -> dict[str, tuple[float, float, float]]:
    """Robot → (FK, IK, solve) medians in ms, on a live server."""
    out = {}
    with serve(workers="1") as server, httpx.Client(base_url=server.url, timeout=120) as c:
        for robot_id, q in ROBOTS.items():
            fk = orjson.dumps({"q": q})
            pose = next(iter(c.post(f"/robots/{robot_id}/fk", content=fk, headers=JSON)
                             .json()["poses"].values()))  # fmt: skip
            ik = _ik_body(pose)
            for _ in range(50):  # warm-up: kernels compiled, caches filled
                c.post(f"/robots/{robot_id}/ik", content=ik, headers=JSON).raise_for_status()
            fks, iks, solves = [], [], []
            for _ in range(N):
                t = time.perf_counter()
                c.post(f"/robots/{robot_id}/fk", content=fk, headers=JSON)
                fks.append(time.perf_counter() - t)
                t = time.perf_counter()
                r = c.post(f"/robots/{robot_id}/ik", content=ik, headers=JSON)
                iks.append(time.perf_counter() - t)
                solves.append(r.json()["solve_time_ms"])
            m = statistics.median
            out[robot_id] = (m(fks) * 1e3, m(iks) * 1e3, m(solves))
    return out


def in_process() -> dict[str, tuple[float, float, float]]:
    """Robot → (FK, IK, solve) in CPU ms per request, the ASGI app called directly."""
    from app.main import create_app
    from app.operations.settings import Settings

    app = create_app(Settings(data_dir=Path(tempfile.mkdtemp(prefix="denavit-bench-"))))

    async def call(path: str, body: bytes) -> bytes:
        sent = False

        async def receive() -> dict:
            nonlocal sent
            if not sent:
                sent = True
                return {"type": "http.request", "body": body, "more_body": False}
            await asyncio.sleep(3600)
            return {"type": "http.disconnect"}

        chunks: list[bytes] = []

        async def send(message: dict) -> None:
            if message["type"] == "http.response.body":
                chunks.append(message.get("body", b""))

        headers = [(b"content-type", b"application/json"), (b"host", b"bench"),
                   (b"content-length", str(len(body)).encode())]  # fmt: skip
        scope = {"type": "http", "asgi": {"version": "3.0"}, "http_version": "1.1",
                 "method": "POST", "scheme": "http", "path": path, "raw_path": path.encode(),
                 "query_string": b"", "root_path": "", "headers": headers,
                 "client": ("127.0.0.1", 1), "server": ("127.0.0.1", 80), "state": {}}  # fmt: skip
        await app(scope, receive, send)
        return b"".join(chunks)

    async def run() -> dict[str, tuple[float, float, float]]:
        out = {}
        async with app.router.lifespan_context(app):
            for robot_id, q in ROBOTS.items():
                fk = orjson.dumps({"q": q})
                pose = next(iter(orjson.loads(await call(f"/robots/{robot_id}/fk", fk))
                                 ["poses"].values()))  # fmt: skip
                ik = _ik_body(pose)
                for _ in range(50):
                    await call(f"/robots/{robot_id}/ik", ik)
                fks, iks, solves = [], [], []
                for _ in range(N):
                    t = time.thread_time()
                    await call(f"/robots/{robot_id}/fk", fk)
                    fks.append(time.thread_time() - t)
                    t = time.thread_time()
                    r = await call(f"/robots/{robot_id}/ik", ik)
                    iks.append(time.thread_time() - t)
                    solves.append(orjson.loads(r)["solve_time_ms"] * 1e-3)
                out[robot_id] = (_trimmed_ms(fks), _trimmed_ms(iks), _trimmed_ms(solves))
        return out

    return asyncio.run(run())


SERVED_N = int(os.environ.get("DENAVIT_BENCH_SERVED_N", "2000"))
SERVED_ROBOTS = {"panda": "panda_link8", "ur5": "tool0"}
#: The issue's target: the served solve's mean at most this fraction of ik_LM's mean CPU.
SERVED_TARGET = 0.5
BLOCK = 250


def _serve_tree(tree: str | None) -> contextlib.AbstractContextManager:
    """A live server (1 worker, access log on) of this checkout, or of ``tree``'s code."""
    if tree is None:
        return serve(workers="1")
    code = (f"import sys, runpy; sys.path.insert(0, {tree!r}); "
            "runpy.run_module('app', run_name='__main__')")  # fmt: skip
    return serve(code, workers="1")


def _ik_bodies(goals: list, frame: str) -> list[bytes]:
    tol = {"position": 1e-5, "orientation": 1e-5}
    return [
        orjson.dumps({"frame": frame, "timeout_ms": 5.0, "tolerance": tol, "target": {
            "position": g.translation.tolist(),
            "orientation": matrix_to_quaternion(g.rotation).tolist()}})
        for g in goals
    ]  # fmt: skip


def served() -> tuple[list[tuple], str | None]:
    """Rows (robot, who, success rate, mean ms, median ms) of the served solve beside
    ik_LM's mean CPU on the same targets; and why ik_LM did not run, if it did not."""
    from app.robots.registry import Registry

    logging.getLogger("httpx").setLevel(logging.WARNING)  # (the in-process app logs INFO)
    reg = Registry()
    tree = os.environ.get("DENAVIT_BENCH_BASELINE_TREE")
    trees = {"served (this code)": None} | ({"served (baseline tree)": tree} if tree else {})
    rows = []
    lm = IkLM()
    with contextlib.ExitStack() as stack:
        stack.callback(lm.close)
        clients = {}
        for who, t in trees.items():
            server = stack.enter_context(_serve_tree(t))
            clients[who] = stack.enter_context(httpx.Client(base_url=server.url, timeout=120))
        for rid, frame in SERVED_ROBOTS.items():
            robot = reg.get(rid)
            goals = targets(robot, frame, SERVED_N)
            bodies = _ik_bodies(goals, frame)
            T = np.array([g.homogeneous for g in goals])
            seed = robot.mid_range()[ik_chain(robot, frame).active]
            joints = lm.load(rid, robot.urdf_text, frame)
            lm_wall = IK_LM[0][0] + ", wall"
            times = {who: [] for who in clients}
            times |= {IK_LM[0][0]: [], lm_wall: []} if joints else {}
            ok = dict.fromkeys(times, 0)
            for c in clients.values():  # warm-up: kernels compiled, chain built
                for b in bodies[:50]:
                    c.post(f"/robots/{rid}/ik", content=b, headers=JSON).raise_for_status()
            for a in range(0, SERVED_N, BLOCK):
                for who, c in clients.items():
                    for b in bodies[a : a + BLOCK]:
                        out = orjson.loads(c.post(f"/robots/{rid}/ik", content=b, headers=JSON)
                                           .content)  # fmt: skip
                        times[who].append(out["solve_time_ms"])
                        ok[who] += out["success"]
                if joints:
                    res = lm.solve(rid, T[a : a + BLOCK], seed, IK_LM[0][1])
                    times[IK_LM[0][0]] += (res["cpu"] * 1e3).tolist()
                    times[lm_wall] += (res["wall"] * 1e3).tolist()
                    ok[IK_LM[0][0]] += int(res["success"].sum())
                    ok[lm_wall] += int(res["success"].sum())
            for who, v in times.items():
                rows.append((rid, who, ok[who] / SERVED_N, statistics.fmean(v),
                             statistics.median(v)))  # fmt: skip
    return rows, lm.unavailable


def print_served(rows: list[tuple], unavailable: str | None) -> None:
    print(f"\nThe served solve against ik_LM ({SERVED_N} targets per robot, TRAC-IK protocol, "
          f"blocks of {BLOCK} alternating; load {os.getloadavg()[0]:.1f})\n")  # fmt: skip
    print("| robot | solver (served: wall solve_time_ms; ik_LM: CPU, and wall) | success "
          "| mean (ms) | median (ms) | mean / ik_LM CPU |")  # fmt: skip
    print("|---|---|---:|---:|---:|---:|")
    ref = {r[0]: r[3] for r in rows if r[1] == IK_LM[0][0]}
    for rid, who, rate, mean, med in rows:
        ratio = mean / ref[rid] if rid in ref else math.nan
        print(f"| {rid} | {who} | {rate:.1%} | {mean:.4f} | {med:.4f} | {ratio:.2f}× |")
    if unavailable:
        print(f"\nik_LM did not run: {unavailable}")
    for rid, who, _rate, mean, _med in rows:
        if rid in ref and who == "served (this code)":
            ratio = mean / ref[rid]
            verdict = "met" if ratio <= SERVED_TARGET else "not met"
            print(f"target {rid}: served solve_time_ms mean ≤ {SERVED_TARGET}× ik_LM's CPU mean; "
                  f"baseline ik_LM {ref[rid]:.4f} ms; measured {mean:.4f} ms = {ratio:.2f}×: "
                  f"{verdict}")  # fmt: skip


def main() -> None:
    if os.environ.get("DENAVIT_BENCH_SERVED_ONLY"):
        print_served(*served())
        return
    rows = [("live, wall median", live()), ("in process, CPU", in_process())]
    print(f"\nIK over HTTP beyond its solve ({N} FK and IK requests each, alternating)\n")
    print("| robot | measured | FK round trip (ms) | IK round trip (ms) | solve_time_ms | "
          "IK − solve − FK (ms) |")  # fmt: skip
    print("|---|---|---:|---:|---:|---:|")
    for robot_id in ROBOTS:
        for label, table in rows:
            fk, ik, solve = table[robot_id]
            print(f"| {robot_id} | {label} | {fk:.3f} | {ik:.3f} | {solve:.3f} | "
                  f"{ik - solve - fk:+.3f} |")  # fmt: skip
    print_served(*served())


if __name__ == "__main__":
    main()
