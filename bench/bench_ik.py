"""IK benchmark with TRAC-IK's protocol, in process and over HTTP.

Protocol (Beeson & Ames, TRAC-IK, 2015): for each robot, N joint configurations drawn
uniformly within the joint limits of the chain's joints; the target is the FK pose of each;
the seed is the middle of the joint limits; full 6-D pose; success = position error
≤ 1e-5 m and orientation error ≤ 1e-5 rad within 5 ms. Reported: solve rate and the
mean / p50 / p99 wall-clock solve time (successes and failures alike, failures count their
full budget), plus the mean CPU time of the solving thread and a second pass whose success
is counted against 5 ms of thread CPU time (wall budget 100 ms): both are insensitive to
preemption by other processes on a loaded machine.

Over HTTP, a real uvicorn server (1 worker) is started on loopback and a few hundred
POST /robots/{id}/ik requests are sent sequentially on one keep-alive connection; the
time is the client's round trip.

Environment: ``DENAVIT_BENCH_IK_N`` (targets per robot in process, default 10000),
``DENAVIT_BENCH_IK_HTTP`` (requests per robot over HTTP, default 300),
``DENAVIT_BENCH_IK_ROBOTS`` (comma-separated ``id`` or ``id:frame``; default panda:panda_link8,
ur5:tool0 and every DH robot of the registry with its ``tool`` frame),
``DENAVIT_BENCH_IK_LM_N`` (targets per robot of the side-by-side run with the Robotics
Toolbox's ``ik_LM``, default ``DENAVIT_BENCH_IK_N``; 0 skips it; see :func:`versus_ik_lm`),
``DENAVIT_BENCH_IK_AB`` (targets of the compiled-versus-Python loop comparison, default 2000;
0 skips it).
"""

from __future__ import annotations

import math
import os
import sys
import time
from dataclasses import replace
from pathlib import Path

import httpx
import numpy as np
import pinocchio as pin

from app.kinematics import ik
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.kinematics.models import RobotModel
from app.kinematics.rotations import matrix_to_quaternion
from app.robots.registry import Registry
from bench._http import serve
from bench.rtb_side import IkLM

TOL = 1e-5
BUDGET_MS = 5.0
#: The same solver on its Python loop only.
PYTHON_LOOP = replace(DEFAULT_PARAMETERS, compiled=False)


def _chains(reg: Registry) -> list[tuple[str, str]]:
    spec = os.environ.get("DENAVIT_BENCH_IK_ROBOTS")
    if spec:
        out = []
        for item in spec.split(","):
            rid, _, frame = item.strip().partition(":")
            out.append((rid, frame or reg.get(rid).ee_frame))
        return out
    out = [("panda", "panda_link8"), ("ur5", "tool0")]
    for s in reg.summaries():
        if s.source == "dh":
            out.append((s.id, reg.get(s.id).ee_frame))
    return out


def targets(robot: RobotModel, frame: str, n: int, seed: int = 2015) -> list[pin.SE3]:
    """FK poses of n configurations uniform within the limits of the frame's joints."""
    ch = ik_chain(robot, frame)
    rng = np.random.default_rng(seed)
    q = np.tile(robot.mid_range(), (n, 1))
    q[:, ch.active] = rng.uniform(ch.sample_lo, ch.sample_hi, (n, ch.k))
    model, data = robot.model, robot.data
    out = []
    for row in q:
        pin.forwardKinematics(model, data, robot.to_pin(row))
        out.append(pin.updateFramePlacement(model, data, ch.frame_id).copy())
    return out


def _verify(robot: RobotModel, frame: str, q: np.ndarray, target: pin.SE3) -> bool:
    """Independent success check: FK of the answer against the target, and the limits."""
    if robot.limit_violations(q):
        return False
    model, data = robot.model, robot.data
    pin.forwardKinematics(model, data, robot.to_pin(q))
    T = pin.updateFramePlacement(model, data, robot.frame_id(frame))
    dp = float(np.linalg.norm(T.translation - target.translation))
    dr = float(np.linalg.norm(pin.log3(T.rotation.T @ target.rotation)))
    return dp <= TOL and dr <= TOL


def _stats(times_ms: np.ndarray) -> tuple[float, float, float]:
    return float(times_ms.mean()), float(np.median(times_ms)), float(np.percentile(times_ms, 99))


def in_process(reg: Registry, n: int) -> list[tuple]:
    rows = []
    for rid, frame in _chains(reg):
        robot = reg.get(rid)
        goals = targets(robot, frame, n)
        ik.solve(robot, goals[0], IKOptions(frame=frame))  # warm-up: chain and closed-form set-up
        wall = np.empty(n)
        cpu = np.empty(n)
        its = np.empty(n)
        ok = 0
        methods: dict[str, int] = {}
        perf, thread_time = time.perf_counter, time.thread_time
        for i, T in enumerate(goals):
            c0 = thread_time()
            t0 = perf()
            res = ik.solve(robot, T, IKOptions(frame=frame, timeout_ms=BUDGET_MS))
            wall[i] = perf() - t0
            cpu[i] = thread_time() - c0
            its[i] = res.iterations
            if res.success and wall[i] <= BUDGET_MS * 1e-3:
                ok += _verify(robot, frame, res.q, T)
            methods[res.method] = methods.get(res.method, 0) + 1
        # Load-robust companion: the same targets with a generous wall budget, success
        # counted when the solving thread used at most 5 ms of CPU time.
        ok_cpu = 0
        for T in goals:
            c0 = thread_time()
            res = ik.solve(robot, T, IKOptions(frame=frame, timeout_ms=20 * BUDGET_MS))
            used = thread_time() - c0
            if res.success and used <= BUDGET_MS * 1e-3:
                ok_cpu += _verify(robot, frame, res.q, T)
        mean, p50, p99 = _stats(wall * 1e3)
        method = ", ".join(f"{k} {v}" for k, v in sorted(methods.items()))
        it_txt = f"{its.mean():.1f} / {np.percentile(its, 99):.0f} / {its.max():.0f}"
        rows.append(
            (
                rid,
                frame,
                robot.n,
                n,
                ok / n,
                mean,
                p50,
                p99,
                cpu.mean() * 1e3,
                ok_cpu / n,
                it_txt,
                method,
            )  # fmt: skip
        )
        print(f"  {rid}: {100 * ok / n:.2f}% mean {mean:.3f} ms", file=sys.stderr, flush=True)
    return rows


def loops_side_by_side(reg: Registry, n: int) -> list[tuple]:
    """The numeric solver (closed forms off) with its compiled loop and with its Python loop
    on the same targets, alternating target by target so that load affects both alike:
    solve rate and mean / p50 thread CPU time (ms), and mean iterations."""
    rows = []
    for rid, frame in (("panda", "panda_link8"), ("ur5", "tool0"), ("puma560", None)):
        robot = reg.get(rid)
        frame = frame or robot.ee_frame
        if ik_chain(robot, frame).compiled is None:
            continue
        loops = (("compiled", DEFAULT_PARAMETERS), ("python", PYTHON_LOOP))
        goals = targets(robot, frame, n, seed=11)
        cpu = {"compiled": np.empty(n), "python": np.empty(n)}
        ok = {"compiled": 0, "python": 0}
        its = {"compiled": 0, "python": 0}
        for i, T in enumerate(goals):
            for name, parameters in loops:
                c0 = time.thread_time()
                options = IKOptions(frame=frame, timeout_ms=20 * BUDGET_MS, analytic=False)
                res = ik.solve(robot, T, options, parameters=parameters)
                cpu[name][i] = time.thread_time() - c0
                ok[name] += res.success and cpu[name][i] <= BUDGET_MS * 1e-3
                its[name] += res.iterations
        for name in ("compiled", "python"):
            c = cpu[name] * 1e3
            rows.append((rid, name, ok[name] / n, c.mean(), float(np.median(c)), its[name] / n))
    return rows


#: The solvers of the side-by-side run: (name, closed forms) for ours, (name, setting) for
#: ik_LM (see bench/rtb_ik_lm.py).
OURS = (("ours, closed forms on", True), ("ours, closed forms off", False))
IK_LM = (("ik_LM tol 5e-11 (‖e‖ ≤ 1e-5)", "tuned"), ("ik_LM defaults", "default"))


def versus_ik_lm(reg: Registry, n: int, block: int = 500) -> tuple[list[tuple], str | None]:
    """Ours (closed forms on and off) and the Robotics Toolbox's C++ ``ik_LM`` on the same
    targets (TRAC-IK's protocol), in alternating blocks of ``block`` targets so that load
    hits all alike; ours from its default seed, the middle of the limits (the seed
    ik_LM is given). Every answer is judged by :func:`_verify` (ours and ik_LM's alike) and
    counts as solved within 5 ms of wall-clock time. Rows: robot, solver, solve rate, mean
    and p50 wall time, mean CPU time (ms), and the mean CPU time over ik_LM's (tuned);
    plus why ik_LM did not run, if it did not."""
    lm = IkLM()
    rows = []
    try:
        for rid, frame in (("panda", "panda_link8"), ("ur5", "tool0")):
            robot = reg.get(rid)
            ch = ik_chain(robot, frame)
            goals = targets(robot, frame, n)
            T = np.array([g.homogeneous for g in goals])
            seed = robot.mid_range()
            joints = lm.load(rid, robot.urdf_text, frame)
            names = [name for name, _ in OURS] + ([name for name, _ in IK_LM] if joints else [])
            wall = {k: np.empty(n) for k in names}
            cpu = {k: np.empty(n) for k in names}
            ok = dict.fromkeys(names, 0)
            for _name, analytic in OURS:  # warm-up: chain and closed-form set-up
                ik.solve(robot, goals[0], IKOptions(frame=frame, analytic=analytic))
            for a in range(0, n, block):
                b = min(n, a + block)
                for name, analytic in OURS:
                    opts = IKOptions(frame=frame, timeout_ms=BUDGET_MS, analytic=analytic)
                    for i in range(a, b):
                        c0 = time.thread_time()
                        t0 = time.perf_counter()
                        res = ik.solve(robot, goals[i], opts)  # default seed: mid-limits
                        wall[name][i] = time.perf_counter() - t0
                        cpu[name][i] = time.thread_time() - c0
                        if res.success and wall[name][i] <= BUDGET_MS * 1e-3:
                            ok[name] += _verify(robot, frame, res.q, goals[i])
                for name, setting in IK_LM if joints else ():
                    out = lm.solve(rid, T[a:b], seed[ch.active], setting)
                    wall[name][a:b], cpu[name][a:b] = out["wall"], out["cpu"]
                    for i, q_chain in zip(range(a, b), out["q"], strict=True):
                        if out["wall"][i - a] <= BUDGET_MS * 1e-3:
                            q = seed.copy()
                            q[ch.active] = q_chain
                            ok[name] += _verify(robot, frame, q, goals[i])
            ref = cpu[IK_LM[0][0]].mean() if joints else math.nan
            for name in names:
                w, c = wall[name] * 1e3, cpu[name] * 1e3
                ratio = c.mean() / (ref * 1e3)
                rows.append(
                    (rid, name, ok[name] / n, w.mean(), float(np.median(w)), c.mean(), ratio)
                )
            print(f"  {rid}: side by side done", file=sys.stderr, flush=True)
    finally:
        lm.close()
    return rows, lm.unavailable


def calibration() -> float:
    """Best-of-5 time (µs) of a 6×6 ``np.linalg.solve``: a yardstick of the machine's load."""
    A = np.eye(6) * 2.0
    b = np.ones(6)
    best = math.inf
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(20000):
            np.linalg.solve(A, b)
        best = min(best, (time.perf_counter() - t0) / 20000 * 1e6)
    return best


def over_http(reg: Registry, n: int) -> list[tuple]:
    rows = []
    with serve(log_level="warning", access_log="false") as server:
        base = server.url
        with httpx.Client(base_url=base, timeout=30.0) as client:
            for rid, frame in _chains(reg):
                robot = reg.get(rid)
                goals = targets(robot, frame, n, seed=7)
                bodies = [
                    {
                        "frame": frame,
                        "target": {
                            "position": T.translation.tolist(),
                            "orientation": matrix_to_quaternion(T.rotation).tolist(),
                        },
                    }
                    for T in goals
                ]
                client.post(f"/robots/{rid}/ik", json=bodies[0]).raise_for_status()
                wall = np.empty(n)
                server_ms = np.empty(n)
                ok = 0
                for i, (body, T) in enumerate(zip(bodies, goals, strict=True)):
                    t0 = time.perf_counter()
                    r = client.post(f"/robots/{rid}/ik", json=body)
                    wall[i] = time.perf_counter() - t0
                    r.raise_for_status()
                    out = r.json()
                    server_ms[i] = out["solve_time_ms"]
                    if out["success"] and out["solve_time_ms"] <= BUDGET_MS:
                        ok += _verify(robot, frame, np.array(out["q"]), T)
                mean, p50, p99 = _stats(wall * 1e3)
                rows.append((rid, n, ok / n, mean, p50, p99, float(server_ms.mean())))
    return rows


#: A child timing ``ik.solve`` in a tight loop with the code of the checkout in argv[1]:
#: prints {"robot" or "robot+annotate": best-of-3 thread CPU µs per solve}.
_TIGHT_CHILD = """
import json, sys, time
sys.path.insert(0, sys.argv[1])
import numpy as np, pinocchio as pin
from app.kinematics import ik
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.robots.registry import Registry
n = int(sys.argv[2])
reg, out = Registry(), {}
for rid, frame in (("panda", "panda_link8"), ("ur5", "tool0")):
    robot = reg.get(rid)
    ch = ik_chain(robot, frame)
    rng = np.random.default_rng(0)
    goals = []
    for _ in range(n):
        q = robot.mid_range()
        q[ch.active] = rng.uniform(ch.sample_lo, ch.sample_hi)
        pin.forwardKinematics(robot.model, robot.data, robot.to_pin(q))
        goals.append(pin.updateFramePlacement(robot.model, robot.data, ch.frame_id).copy())
    opts = IKOptions(frame=frame, tolerance=(1e-5, 1e-5), timeout_ms=5.0)
    for annotate in (False, True):
        for g in goals[:200]:
            ik.solve(robot, g, opts, annotate=annotate)
        best = float("inf")
        for _ in range(3):
            t0 = time.thread_time()
            for g in goals:
                ik.solve(robot, g, opts, annotate=annotate)
            best = min(best, (time.thread_time() - t0) / n * 1e6)
        out[rid + ("+annotate" if annotate else "")] = best
print(json.dumps(out))
"""


def tight_loop(n: int, rounds: int, trees: dict[str, str]) -> dict[str, dict[str, list[float]]]:
    """Checkout label → case → µs per solve of each round: ``ik.solve`` in a tight loop
    (thread CPU, best of 3 passes over ``n`` targets, TRAC-IK protocol, seed 0), one child
    process per checkout and round, the checkouts alternating."""
    import json
    import subprocess

    out: dict[str, dict[str, list[float]]] = {label: {} for label in trees}
    for _ in range(rounds):
        for label, tree in trees.items():
            done = subprocess.run([sys.executable, "-c", _TIGHT_CHILD, tree, str(n)],
                                  capture_output=True, text=True, check=True)  # fmt: skip
            for case, us in json.loads(done.stdout.strip().splitlines()[-1]).items():
                out[label].setdefault(case, []).append(us)
    return out


def print_tight_loop() -> None:
    """The tight-loop table, this checkout beside ``DENAVIT_BENCH_BASELINE_TREE`` (a
    checkout of the older code) when given: ``DENAVIT_BENCH_IK_TIGHT`` targets (default
    2000; 0 skips), 3 alternating rounds."""
    n = int(os.environ.get("DENAVIT_BENCH_IK_TIGHT", "2000"))
    if n <= 0:
        return
    here = str(Path(__file__).resolve().parents[1])
    trees = {"this code": here}
    base = os.environ.get("DENAVIT_BENCH_BASELINE_TREE")
    if base:
        trees = {"baseline tree": base} | trees
    load = os.getloadavg()[0]
    print(f"\n### Tight loop: ik.solve per target, thread CPU µs, best of 3 passes over {n} "
          f"targets; checkouts alternating, 3 rounds (load {load:.1f})\n")  # fmt: skip
    res = tight_loop(n, 3, trees)
    cases = list(next(iter(res.values())))
    print("| case | " + " | ".join(trees) + (" | this ÷ baseline |" if base else " |"))
    print("|---|" + "---:|" * (len(trees) + bool(base)))
    for case in cases:
        cells = [", ".join(f"{v:.1f}" for v in res[label][case]) for label in trees]
        row = f"| {case} | " + " | ".join(cells)
        if base:
            ratio = min(res["this code"][case]) / min(res["baseline tree"][case])
            row += f" | {ratio:.2f} |"
        print(row + (" |" if not base else ""))


def main() -> None:
    n = int(os.environ.get("DENAVIT_BENCH_IK_N", "10000"))
    n_http = int(os.environ.get("DENAVIT_BENCH_IK_HTTP", "300"))
    if os.environ.get("DENAVIT_BENCH_IK_TIGHT_ONLY"):
        print_tight_loop()
        return
    reg = Registry()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else math.nan
    print(
        f"machine: {os.cpu_count()} cores; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
        f"load average {load:.1f} at start; calibration {calibration():.2f} µs"
    )
    print(f"\n### In process: {n} targets per robot, 6-D pose, seed mid-range, 5 ms budget\n")
    print("| robot | frame | joints | targets | solve rate | mean (ms) | p50 (ms) | p99 (ms) "
          "| mean CPU (ms) | solve rate, ≤ 5 ms CPU | iterations mean / p99 / max "
          "| method |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for row in in_process(reg, n):
        rid, frame, joints, cnt, rate, mean, p50, p99, cpu, rate_cpu, its, method = row
        print(f"| {rid} | {frame} | {joints} | {cnt} | {100 * rate:.2f}% | {mean:.3f} | "
              f"{p50:.3f} | {p99:.3f} | {cpu:.3f} | {100 * rate_cpu:.2f}% | {its} "
              f"| {method} |")  # fmt: skip
    print(
        f"\ncalibration after the run: 6×6 np.linalg.solve {calibration():.2f} µs "
        "(best of 5 × 20000; the same machine unloaded: ≈ 4.3 µs)"
    )
    n_lm = int(os.environ.get("DENAVIT_BENCH_IK_LM_N", str(n)))
    if n_lm > 0:
        print(f"\n### Side by side with the Robotics Toolbox's ik_LM: the same {n_lm} targets, "
              "alternating blocks of 500, every answer checked by our FK\n")  # fmt: skip
        rows, why = versus_ik_lm(reg, n_lm)
        print("| robot | solver | solve rate (checked, ≤ 5 ms) | mean (ms) | p50 (ms) "
              "| mean CPU (ms) | mean CPU ÷ ik_LM tol 5e-11 |")  # fmt: skip
        print("|---|---|---|---|---|---|---|")
        for rid, name, rate, mean, p50, cpu, ratio in rows:
            print(f"| {rid} | {name} | {100 * rate:.2f}% | {mean:.3f} | {p50:.3f} | {cpu:.3f} "
                  f"| {ratio:.2f} |")  # fmt: skip
        if why is not None:
            print(f"\nik_LM rows skipped: {why}")
        else:
            print("\nik_LM tol 5e-11: ilimit 30, slimit 100, joint_limits on (its defaults but "
                  "tol; tol bounds ½eᵀe); ik_LM defaults: tol 1e-6.")  # fmt: skip
    n_ab = int(os.environ.get("DENAVIT_BENCH_IK_AB", "2000"))
    if n_ab > 0:
        print(f"\n### Compiled and Python loop, same {n_ab} targets, alternating (CPU time)\n")
        print("| robot | loop | solve rate, ≤ 5 ms CPU | mean CPU (ms) | p50 CPU (ms) "
              "| iterations mean |")  # fmt: skip
        print("|---|---|---|---|---|---|")
        for rid, name, rate, mean, p50, its in loops_side_by_side(reg, n_ab):
            print(f"| {rid} | {name} | {100 * rate:.2f}% | {mean:.3f} | {p50:.3f} | {its:.1f} |")
    print_tight_loop()
    if n_http > 0:
        print(f"\n### Over HTTP: {n_http} requests per robot, uvicorn 1 worker, loopback\n")
        print("| robot | requests | solve rate | mean round trip (ms) | p50 (ms) | p99 (ms) "
              "| mean solve_time_ms (server) |")  # fmt: skip
        print("|---|---|---|---|---|---|---|")
        for rid, cnt, rate, mean, p50, p99, server in over_http(reg, n_http):
            print(f"| {rid} | {cnt} | {100 * rate:.2f}% | {mean:.3f} | {p50:.3f} | "
                  f"{p99:.3f} | {server:.3f} |")  # fmt: skip


if __name__ == "__main__":
    main()
