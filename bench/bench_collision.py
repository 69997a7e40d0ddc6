"""Collision benchmarks: in-process checks vs Pinocchio directly, and requests/s over HTTP.

``python -m bench collision`` prints markdown tables:

1. Panda self-collision, in process, per check (µs): Pinocchio's ``computeCollisions`` called
   directly on the very GeometryModel/GeometryData the service uses (Pinocchio
   configurations prepared in advance), against :meth:`CollisionModel.check` (wire
   configuration in, verdict and colliding link pairs out) and :meth:`CollisionModel.collides`
   (first hit) against ``computeCollisions(..., stop_at_first_collision=True)``; with the
   meshes and with their convex hulls. Target: ≤ 1.5× the direct call.
2. Requests/s of POST /robots/panda/collisions (and the batch route) against a real uvicorn
   started on 127.0.0.1 by this script (one process, keep-alive client).
"""

from __future__ import annotations

import os
import time
from concurrent.futures import ThreadPoolExecutor

import httpx
import numpy as np
import pinocchio as pin

from app.kinematics.collision import collision_model
from app.robots.registry import Registry
from bench._http import serve

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
OBSTACLES = [
    {"name": "table", "shape": "box", "size": [1.0, 1.0, 0.05], "pose": {"position": [0.6, 0, 0]}},
    {"name": "post", "shape": "cylinder", "radius": 0.05, "length": 1.0,
     "pose": {"position": [0.0, 0.6, 0.5]}},
    {"name": "ball", "shape": "sphere", "radius": 0.1, "pose": {"position": [0.4, -0.4, 0.6]}},
]  # fmt: skip


def _interleaved(fns: list, items: list, repeats: int = 7) -> list[float]:
    """Best mean time per item (µs) of each function; passes alternate between the
    functions so that load from other processes hits them alike."""
    best = [float("inf")] * len(fns)
    for _ in range(repeats):
        for i, (fn, xs) in enumerate(zip(fns, items, strict=True)):
            t0 = time.perf_counter()
            for x in xs:
                fn(x)
            best[i] = min(best[i], (time.perf_counter() - t0) / len(xs))
    return [b * 1e6 for b in best]


def _mode_row(robot, mode: str, qs: list[np.ndarray]) -> tuple:
    cm = collision_model(robot, mode)
    comp = cm.compiled()
    scratch = comp.scratch(0.0)
    model, data, gm, gd = robot.model, scratch.data, comp.gm, scratch.geom_data
    qps = [robot.to_pin(q) for q in qs]
    hits = sum(cm.collides(q) for q in qs)

    def direct(qp: np.ndarray) -> bool:
        return pin.computeCollisions(model, data, gm, gd, qp, False)

    def direct_first(qp: np.ndarray) -> bool:
        return pin.computeCollisions(model, data, gm, gd, qp, True)

    def ours(q: np.ndarray) -> object:
        return cm.check(q, pair_distances=False)

    d, o, f, df, c = _interleaved(
        [direct, ours, cm.check, direct_first, cm.collides], [qps, qs, qs, qps, qs]
    )
    return (mode, len(cm.link_pairs), comp.npairs, hits, len(qs), d, o, f, df, c)


def in_process(n: int = 300) -> list[tuple]:
    robot = Registry().get("panda")
    rng = np.random.default_rng(0)
    qs = list(rng.uniform(robot.lower, robot.upper, (n, robot.n)))
    qs[: n // 3] = [np.array(READY)] * (n // 3)
    return [_mode_row(robot, mode, qs) for mode in ("mesh", "convex")]


def _rate(client: httpx.Client, path: str, body: dict, seconds: float, cap: int) -> float:
    client.post(path, json=body).raise_for_status()  # warm-up (model build)
    count, t0 = 0, time.perf_counter()
    while count < cap and time.perf_counter() - t0 < seconds:
        client.post(path, json=body).raise_for_status()
        count += 1
    return count / (time.perf_counter() - t0)


def over_http(seconds: float = 4.0, cap: int = 20_000) -> list[tuple[str, float, str]]:
    with serve(log_level="warning", access_log="false") as server:
        base = server.url
        rng = np.random.default_rng(1)
        robot = Registry().get("panda")
        batch = rng.uniform(robot.lower, robot.upper, (100, robot.n)).tolist()
        path = "/robots/panda/collisions"
        cases = [
            ("baseline: POST /robots/panda/fk", "/robots/panda/fk", {"q": READY}),
            ("self, meshes", path, {"q": READY}),
            ("self, convex hulls", path, {"q": READY, "geometry": "convex"}),
            ("self + 3 obstacles, meshes", path, {"q": READY, "obstacles": OBSTACLES}),
            ("self + 3 obstacles, distances, hulls", path,
             {"q": READY, "obstacles": OBSTACLES, "distances": True, "geometry": "convex"}),
            ("batch of 100, meshes", path + "/batch", {"configurations": batch}),
            ("batch of 100, hulls", path + "/batch",
             {"configurations": batch, "geometry": "convex"}),
        ]  # fmt: skip
        out = []
        with httpx.Client(base_url=base, timeout=30.0) as client:
            for name, p, body in cases:
                rate = _rate(client, p, body, seconds, cap)
                per = "configurations/s: %.0f" % (rate * 100) if "batch" in name else ""
                out.append((name, rate, per))

        def worker(_: int) -> int:
            with httpx.Client(base_url=base, timeout=30.0) as c:
                n, t0 = 0, time.perf_counter()
                while time.perf_counter() - t0 < seconds and n < cap:
                    c.post(path, json={"q": READY}).raise_for_status()
                    n += 1
                return n

        t0 = time.perf_counter()
        with ThreadPoolExecutor(4) as pool:
            total = sum(pool.map(worker, range(4)))
        out.append(("self, meshes, 4 concurrent clients", total / (time.perf_counter() - t0), ""))
        return out


def main() -> None:
    print(f"machine: {os.cpu_count()} cores; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print("\n### Panda self-collision, in process (µs per check; best of 7 interleaved passes)\n")
    print(
        "| geometry | link pairs | geometry pairs | configs in collision | direct "
        "computeCollisions | check() | ratio | check() + pair distances | direct first-hit "
        "| collides() | ratio |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for mode, lp, gp, hits, n, direct, ours, full, dfirst, first in in_process():
        print(f"| {mode} | {lp} | {gp} | {hits}/{n} | {direct:.1f} | {ours:.1f} | "
              f"{ours / direct:.2f}× | {full:.1f} | {dfirst:.1f} | {first:.1f} | "
              f"{first / dfirst:.2f}× |")  # fmt: skip
    print("\n### POST /robots/panda/collisions over HTTP (uvicorn, 1 worker, loopback)\n")
    print("| request | requests/s | |")
    print("|---|---|---|")
    for name, rate, extra in over_http():
        print(f"| {name} | {rate:.0f} | {extra} |")


if __name__ == "__main__":
    main()
