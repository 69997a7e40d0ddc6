"""Cartesian path benchmark: :func:`app.kinematics.paths.follow.follow` on random lines.

Workload (:mod:`bench._lines`): per robot, N straight tool lines of 0.1–0.5 m with the
orientation fixed, inside the reachable set, from random start configurations (fixed seed).
Each line is sampled at ``max_step`` = (0.01 m, 0.05 rad); ``max_joint_step`` = 0.1 rad;
IK tolerance 1e-5 m / 1e-5 rad, at most 200 iterations and 50 ms per solve.

Reported per robot:

- completed lines: ``follow`` (guards, bisection, densification) against the naive
  baseline "``ik.solve`` per waypoint seeded by the previous solution, no guards", which
  counts as complete only when every waypoint is solved and no joint moves more than
  ``max_joint_step`` between consecutive waypoints;
- time per point, over the completed lines: ``follow``'s wall time over the points it
  returned (densified points included), against a single
  ``ik.solve`` per point on the same poses from a cold seed (the middle of the joint limits,
  what a client calling POST /ik per point gets), and their ratio (target ≤ 0.5); beside
  it the same ``follow`` waypoint by waypoint (the compiled walk of
  :mod:`app.kinematics.paths.walk_kernel` switched off: one compiled point per waypoint,
  the code before it) and with the per-point checks in Python (the compiled point of
  :mod:`app.kinematics.paths.point_kernel` switched off too), the four timed line by line
  in rotating order so that load hits all alike, and whether the three ``follow`` s
  answered the same points;
- the failure reasons of ``follow``, and its mean wall time on a line it could not finish
  (the halved steps and the last full-budget attempt).

Every ``follow`` has the service's deadline (now + 30 s, ``ik_max_request_s``'s default),
so the compiled walk goes by runs of at most ``WALK_RUN`` waypoints, as served.

Environment: ``DENAVIT_BENCH_PATHS_N`` (lines per robot, default 1000).
"""

from __future__ import annotations

import os
import time
from collections import Counter
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import numpy as np

from app.kinematics import ik
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.search import joint_distance
from app.kinematics.models import RobotModel
from app.kinematics.paths.follow import PathOptions, PathResult, follow
from app.kinematics.paths.local import LocalSolver
from app.kinematics.paths.segments import CartesianPath, Line
from app.robots.registry import Registry
from bench._lines import RandomLine, random_lines

ROBOTS = (("ur5", "tool0"), ("panda", "panda_hand"))
OPTIONS = PathOptions(max_step=(0.01, 0.05), max_joint_step=0.1)
SEED = 2026
#: The target: follow's time per point at most this fraction of a cold single IK.
TARGET = 0.5


#: The service's deadline of a path (s from the call): ``ik_max_request_s``'s default.
DEADLINE_S = 30.0


@contextmanager
def per_point() -> Iterator[None]:
    """The walk before the compiled walk: every waypoint through the per-point walk (one
    compiled point per waypoint; :meth:`LocalSolver.walk` accepts none)."""
    walk = LocalSolver.walk
    LocalSolver.walk = lambda self, *args: (0, 0)  # type: ignore[method-assign]
    try:
        yield
    finally:
        LocalSolver.walk = walk  # type: ignore[method-assign]


@contextmanager
def python_checks() -> Iterator[None]:
    """The baseline: ``follow`` with the per-point checks in Python (the compiled point
    never prepared, as for a chain the kernel does not support)."""
    prepare = LocalSolver.prepare
    LocalSolver.prepare = lambda self, *args: False  # type: ignore[method-assign]
    try:
        yield
    finally:
        LocalSolver.prepare = prepare  # type: ignore[method-assign]


def _timed(fn: Callable[[], PathResult | None]) -> tuple[PathResult | None, float]:
    t0 = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - t0


def naive(robot: RobotModel, line: RandomLine, opts: IKOptions) -> bool:
    """IK per waypoint seeded by the previous solution; complete when every waypoint is
    solved and no joint jumps more than ``max_joint_step``."""
    path = CartesianPath.from_segments(line.start, [Line(line.end)])
    poses, _ = path.sample(OPTIONS.max_step)
    q = line.q0
    for T in poses[1:]:
        res = ik.solve(robot, T, opts, seed=q)
        if not res.success or joint_distance(robot, res.q, q).max() > OPTIONS.max_joint_step:
            return False
        q = res.q
    return True


def run(reg: Registry, rid: str, frame: str, n: int) -> dict:
    robot = reg.get(rid)
    opts = IKOptions(frame=frame, max_iterations=200, timeout_ms=50.0)
    lines = random_lines(robot, frame, n, SEED)
    done = naive_done = points = 0
    t_follow = t_point = t_old = t_cold = t_failed = 0.0
    same = True
    reasons: Counter[str] = Counter()
    for i, line in enumerate(lines):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])

        def new(path=path, line=line, i=i) -> PathResult:
            deadline = time.perf_counter() + DEADLINE_S
            rng = np.random.default_rng(i)
            return follow(robot, line.q0, path, opts, OPTIONS, rng=rng, deadline=deadline)

        def point(new=new) -> PathResult:
            with per_point():
                return new()

        def old(new=new) -> PathResult:
            with python_checks():
                return new()

        res, dt = _timed(new)
        naive_done += naive(robot, line, opts)
        if res.failure is not None:
            reasons[res.failure.reason] += 1
            t_failed += dt
            continue
        done += 1
        pts = res.points[1:]
        points += len(pts)

        def cold(path=path, pts=pts) -> None:
            for p in pts:
                ik.solve(robot, path.pose_at(p.s), opts)

        # the four in rotating order, each timed once more (the first run above warmed up)
        timed: dict[str, float] = {}
        names = ("new", "point", "old", "cold")
        for name in names[i % 4 :] + names[: i % 4]:
            out, timed[name] = _timed({"new": new, "point": point, "old": old, "cold": cold}[name])
            if name in ("new", "point", "old"):
                same = same and _same(res, out)
        t_follow += timed["new"]
        t_point += timed["point"]
        t_old += timed["old"]
        t_cold += timed["cold"]
    return {
        "robot": rid,
        "frame": frame,
        "lines": n,
        "follow": done / n,
        "naive": naive_done / n,
        "follow_ms": 1e3 * t_follow / max(points, 1),
        "point_ms": 1e3 * t_point / max(points, 1),
        "old_ms": 1e3 * t_old / max(points, 1),
        "cold_ms": 1e3 * t_cold / max(points, 1),
        "points": points,
        "same": same,
        "failed_ms": 1e3 * t_failed / max(n - done, 1),
        "reasons": ", ".join(f"{k} {v}" for k, v in reasons.most_common()),
    }


def _same(a: PathResult, b: PathResult | None) -> bool:
    """Whether two answers have the same points (s exactly; configurations and errors to
    1e-12)."""
    return (
        b is not None
        and len(a.points) == len(b.points)
        and all(
            p.s == r.s
            and np.allclose(p.q, r.q, rtol=0.0, atol=1e-12)
            and abs(p.position_error - r.position_error) <= 1e-12
            and abs(p.orientation_error - r.orientation_error) <= 1e-12
            for p, r in zip(a.points, b.points, strict=True)
        )
    )


def main() -> None:
    n = int(os.environ.get("DENAVIT_BENCH_PATHS_N", "1000"))
    reg = Registry()
    print(f"machine: {os.cpu_count()} cores; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print(f"\n### {n} random lines per robot (0.1–0.5 m, orientation fixed)\n")
    print("| robot | frame | lines completed, follow | lines completed, naive | points "
          "| follow (ms per point) | follow, per point (ms per point) "
          "| follow, Python checks (ms per point) "
          "| cold single IK (ms per point) | ratio | ratio, per point | ratio, Python checks "
          "| same points | follow's failures | ms per failed line |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for rid, frame in ROBOTS:
        r = run(reg, rid, frame, n)
        rows.append(r)
        print(f"| {r['robot']} | {r['frame']} | {100 * r['follow']:.1f}% | "
              f"{100 * r['naive']:.1f}% | {r['points']} | {r['follow_ms']:.3f} | "
              f"{r['point_ms']:.3f} | {r['old_ms']:.3f} | {r['cold_ms']:.3f} | "
              f"{r['follow_ms'] / r['cold_ms']:.2f} | {r['point_ms'] / r['cold_ms']:.2f} | "
              f"{r['old_ms'] / r['cold_ms']:.2f} | {'yes' if r['same'] else 'NO'} | "
              f"{r['reasons']} | {r['failed_ms']:.1f} |",
              flush=True)  # fmt: skip
    print()
    for r in rows:
        ratio = r["follow_ms"] / r["cold_ms"]
        print(f"target: {r['robot']} path per point ≤ {TARGET}× a cold single IK; baselines "
              f"(per point) {r['point_ms'] / r['cold_ms']:.2f}×, "
              f"(Python checks) {r['old_ms'] / r['cold_ms']:.2f}×, measured {ratio:.2f}× "
              f"({r['follow_ms']:.3f} / {r['cold_ms']:.3f} ms): "
              f"{'met' if ratio <= TARGET else 'not met'}")  # fmt: skip
    print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
