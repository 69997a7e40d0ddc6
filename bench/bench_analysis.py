"""Analysis and reachability benchmarks: ``python -m bench analysis``.

1. Raw in-process FK rate: ``pin.forwardKinematics`` + ``pin.updateFramePlacement`` in a
   Python loop over pre-converted Pinocchio configurations (the reference).
2. Reachability build throughput (samples/s, FK + Jacobian + manipulability + binning +
   merge), in the calling thread (one core) and over worker processes (every core, process
   start-up included), and the ratio to (1).
3. Query latency for 10 000 poses in one request (HTTP through the ASGI app in process, the
   ``poses`` and the compact ``positions``/``orientations`` forms; plus the core lookup).
4. Manipulability: one request, and the batch endpoint per configuration.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np
import orjson
import pinocchio as pin

from app.kinematics.reachability.build import MapBuilder
from app.kinematics.reachability.spec import make_spec
from app.robots.registry import Registry
from app.workers import default_processes
from app.workers.map_build import build_map

ROBOTS = ("panda", "ur5")


def raw_fk_rate(robot, n: int = 100_000) -> float:
    """FK + frame placement per second, Pinocchio in a Python loop (best of 3 loops)."""
    rng = np.random.default_rng(0)
    lo = np.where(np.isfinite(robot.lower), robot.lower, -np.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, np.pi)
    qp = robot.to_pin_batch(rng.uniform(lo, hi, size=(n, robot.n)))
    model, data = robot.model, robot.data
    fid = robot.frame_id(robot.ee_frame)
    fk, upd = pin.forwardKinematics, pin.updateFramePlacement
    best = 0.0
    for _ in range(3):
        t = time.perf_counter()
        for q in qp:
            fk(model, data, q)
            upd(model, data, fid)
        best = max(best, n / (time.perf_counter() - t))
    return best


def build_rate(robot, spec, processes: int) -> tuple[float, float]:
    """Samples/s of a whole build, and the share of the wall time this process was on a CPU
    (with worker processes: the parent's own merging and bookkeeping)."""
    c = time.process_time()
    t = time.perf_counter()
    build_map(robot, spec, processes=processes, min_samples_per_process=1)
    wall = time.perf_counter() - t
    return spec.samples / wall, (time.process_time() - c) / wall


def steady_rate(robot, spec, n: int = 200_000) -> float:
    """Samples/s of the per-chunk work alone (no merge), best of 3."""
    b = MapBuilder(robot, spec)
    best = 0.0
    for _ in range(3):
        t = time.perf_counter()
        for a in range(0, n, 32_768):
            b.cells(a, min(n, a + 32_768))
        best = max(best, n / (time.perf_counter() - t))
    return best


def bench_build() -> None:
    reg = Registry()
    cores = default_processes()
    print(f"machine: {os.cpu_count()} cores ({cores} usable); load {os.getloadavg()}")
    robot = reg.get("panda")
    tiny = make_spec(robot, robot.ee_frame, voxel_size=0.08, samples=2 * 32_768)
    for _ in range(2):
        t = time.perf_counter()
        build_map(robot, tiny, processes=cores, min_samples_per_process=1)
        print(f"process start-up: a 2-chunk build over {cores} processes takes "
              f"{time.perf_counter() - t:.2f} s")  # fmt: skip
    print(
        "Interleaved passes (best and median of 3): raw FK, map chunk work on one core, whole "
        f"builds in this thread and over {cores} processes."
    )
    print(
        f"robot | samples | raw FK /s | chunk work /s | build 1 process /s | ratio | "
        f"build {cores} processes /s | ratio | speed-up | parent CPU"
    )
    for rid in ROBOTS:
        robot = reg.get(rid)
        n = 4_000_000
        spec = make_spec(robot, robot.ee_frame, voxel_size=0.08, samples=n)
        fk, chunk, one, many, parent = [], [], [], [], []
        for _ in range(3):
            fk.append(raw_fk_rate(robot, 50_000))
            chunk.append(steady_rate(robot, spec))
            one.append(build_rate(robot, spec, 1)[0])
            rate, share = build_rate(robot, spec, cores)
            many.append(rate)
            parent.append(share)
        fk_best = max(fk)

        def cell(xs: list[float]) -> str:
            return f"{max(xs):,.0f} (median {statistics.median(xs):,.0f})"

        print(
            f"{rid} | {n:,} | {cell(fk)} | {cell(chunk)} | {cell(one)} | "
            f"{max(one) / fk_best:.2f}× | {cell(many)} | {max(many) / fk_best:.2f}× | "
            f"{max(many) / max(one):.2f}× | {max(parent):.0%} of wall   "
            f"(grid {spec.shape} × {spec.bins} bins; load {os.getloadavg()[0]:.1f})"
        )


def bench_query() -> None:
    from fastapi.testclient import TestClient

    from app.main import create_app
    from app.operations.settings import Settings

    with tempfile.TemporaryDirectory() as tmp:
        app = create_app(Settings(data_dir=Path(tmp)))
        with TestClient(app) as c:
            r = c.post(
                "/robots/panda/reachability",
                json={"voxel_size": 0.08, "samples": 300_000, "orientation_divisions": 4},
            )
            job = r.json()["job_id"]
            while (j := c.get(f"/robots/panda/reachability/jobs/{job}").json())["status"] in (
                "queued",
                "running",
            ):
                time.sleep(0.05)
            map_id = j["map_id"]
            rng = np.random.default_rng(1)
            pos = rng.uniform(-0.9, 0.9, (10_000, 3))
            quat = rng.normal(size=(10_000, 4))
            quat /= np.linalg.norm(quat, axis=1, keepdims=True)
            poses = {
                "map_id": map_id,
                "poses": [
                    {"position": p.tolist(), "orientation": q.tolist()}
                    for p, q in zip(pos, quat, strict=True)
                ],
            }
            compact = {
                "map_id": map_id,
                "positions": pos.tolist(),
                "orientations": quat.tolist(),
            }
            hdr = {"content-type": "application/json"}
            for name, body in (("poses", poses), ("positions/orientations", compact)):
                raw = orjson.dumps(body)  # encoded once: the client's JSON work is not timed
                times = []
                for _ in range(7):
                    t = time.perf_counter()
                    r = c.post("/robots/panda/reachability/query", content=raw, headers=hdr)
                    times.append(time.perf_counter() - t)
                    assert r.status_code == 200, r.text
                print(
                    f"query 10 000 poses ({name}), HTTP in process: median "
                    f"{statistics.median(times) * 1e3:.1f} ms, best {min(times) * 1e3:.1f} ms"
                )
            store, _ = app.state.reachability
            m = store.get("panda", map_id)
            times = []
            for _ in range(20):
                t = time.perf_counter()
                m.query(pos, quat)
                times.append(time.perf_counter() - t)
            print(f"core lookup of 10 000 poses: median {statistics.median(times) * 1e3:.2f} ms")

            q = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.0]
            for path in ("fk", "jacobian", "manipulability", "statics"):
                body = {"q": q}
                if path == "statics":
                    body["wrench"] = [1.0, 2.0, 3.0, 0.1, 0.2, 0.3]
                raw = orjson.dumps(body)
                times = []
                for _ in range(300):
                    t = time.perf_counter()
                    r = c.post(f"/robots/panda/{path}", content=raw, headers=hdr)
                    times.append(time.perf_counter() - t)
                    assert r.status_code == 200, r.text
                print(
                    f"POST {path} (panda), HTTP in process: median "
                    f"{statistics.median(times) * 1e6:.0f} µs"
                )
            raw = orjson.dumps({"configurations": rng.uniform(-1, 1, (10_000, 8)).tolist()})
            times = []
            for _ in range(5):
                t = time.perf_counter()
                c.post("/robots/panda/manipulability/batch", content=raw, headers=hdr)
                times.append(time.perf_counter() - t)
            med = statistics.median(times)
            print(
                f"POST manipulability/batch, 10 000 configurations: median {med * 1e3:.0f} ms "
                f"({10_000 / med:,.0f} configurations/s)"
            )


def main() -> None:
    bench_build()
    bench_query()


if __name__ == "__main__":
    main()
