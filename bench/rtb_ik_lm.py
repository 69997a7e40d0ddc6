"""The Robotics Toolbox's C++ ``ik_LM``, run in the bench-only venv (``.venv-bench``).

Started by :mod:`bench.bench_ik` as ``<bench python> bench/rtb_ik_lm.py``; imports nothing
from the service (it runs on another NumPy). Protocol, one line per request on stdin:

``load <robot> <urdf path> <frame>``
    builds ``rtb.Robot.URDF(path).ets(end=frame)`` (the URDF without visual and collision
    elements: kinematics only); answers ``ok <joints>``.
``solve <robot> <in.npz> <out.npz> <setting>``
    solves every target of ``in.npz`` (``T``: n × 4 × 4 homogeneous matrices, ``seed``: the
    chain's joints) from the seed with ``ik_LM`` and the named setting, and writes ``q``
    (n × joints), ``success`` (ik_LM's own claim), ``wall`` and ``cpu`` (s per target,
    ``time.perf_counter`` and ``time.thread_time``) to ``out.npz``; answers ``ok``.

Settings (``SETTINGS``): ``tuned`` asks for TRAC-IK's tolerance (ik_LM's ``tol`` bounds
½eᵀe, so 5e-11 makes ‖e‖ ≤ 1e-5) with its default iteration and restart limits and joint
limits on; ``default`` is ik_LM as called with no options (``tol`` 1e-6: ‖e‖ ≤ 1.4e-3, so
most answers miss a 1e-5 check).
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np
import roboticstoolbox as rtb

SETTINGS = {
    "tuned": {"ilimit": 30, "slimit": 100, "tol": 5e-11, "joint_limits": True},
    "default": {},
}


def main() -> None:
    chains = {}
    for line in sys.stdin:
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "load":
            _, rid, path, frame = parts
            with warnings.catch_warnings():  # Robot.URDF is deprecated in 1.5, still works
                warnings.simplefilter("ignore", DeprecationWarning)
                chains[rid] = rtb.Robot.URDF(path).ets(end=frame)
            print(f"ok {chains[rid].n}", flush=True)
        elif parts[0] == "solve":
            _, rid, src, dst, setting = parts
            ets = chains[rid]
            data = np.load(src)
            T, seed = data["T"], data["seed"]
            n = T.shape[0]
            kwargs = SETTINGS[setting]
            q = np.empty((n, ets.n))
            ok = np.zeros(n, bool)
            wall = np.empty(n)
            cpu = np.empty(n)
            perf, thread_time = time.perf_counter, time.thread_time
            for i in range(n):
                c0 = thread_time()
                t0 = perf()
                sol = ets.ik_LM(T[i], q0=seed, **kwargs)
                wall[i] = perf() - t0
                cpu[i] = thread_time() - c0
                q[i] = sol.q
                ok[i] = bool(sol.success)
            np.savez(dst, q=q, success=ok, wall=wall, cpu=cpu)
            print("ok", flush=True)
        else:
            print(f"error unknown command {parts[0]!r}", flush=True)


if __name__ == "__main__":
    main()
