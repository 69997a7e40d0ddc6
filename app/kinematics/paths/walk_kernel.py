"""The compiled walk: a run of consecutive waypoints of one segment in one compiled call.

Where no collision predicate is given, :func:`app.kinematics.paths.follow.follow` hands a
run of waypoints (``first ≤ k < stop``, all on one segment, :class:`~.segments.Samples`) to
:func:`run`, which does for each waypoint k in turn what the per-point walk does on its plain
path, and stops at the first waypoint that is not plain, handing it back to the Python walk
(which then does exactly what it always did there: the step halving, densification, the
fallback to :func:`app.kinematics.ik.solve`, the failure). So the points are the same, bit
for bit, as those of the per-point walk.

The plain path of waypoint k, from the last point (the configuration ``q_{k−1}`` at
``s_{k−1}``; the start, or the previous waypoint of the run):

1. the compiled point (:func:`app.kinematics.paths.point_kernel.step`) from ``q_{k−1}``
   towards the waypoint's pose (``R[k]``, ``p[k]``) returns ``OK`` (the attempt converged
   and every check holds: limits, pose error by an independent forward kinematics, joint
   step, branch flags), with the frame's deviation from the path at the middle of the
   joint-space step measured against the path's pose at s_m = ½(s_{k−1} + s_k), which
   lies on this segment at u = (s_m − a)/(b − a) (what
   :meth:`~.segments.CartesianPath.piece_at` finds for a < s_m ≤ b ≤ 1; otherwise the
   waypoint is handed back);
2. that deviation is within half the bounds on both components (``half_p`` m, ``half_r``
   rad): :meth:`app.kinematics.paths.follow._Walk.deviation` then stops at the middle and
   the point is appended as it is.

Anything else (a refused or unconverged attempt, a middle beyond half the bounds, a middle
off the segment) ends the run before waypoint k; its attempt's iterations are not counted,
since the Python walk makes the same attempt again and counts them.
"""

from __future__ import annotations

import numpy as np

from app.kinematics.ik import warmup
from app.kinematics.jit import jit
from app.kinematics.paths import point_kernel
from app.kinematics.paths.point_kernel import OK, step


@jit
def run(
    q0, pc, label, R, p, s, first, stop, piece, a, b, half_p, half_r, Q, E, out
):  # pragma: no cover
    """The plain points of waypoints ``first ≤ k < stop`` (see the module docstring).

    Parameters
    ----------
    q0
        (n,) wire configuration of the last point (at ``s[first − 1]``).
    pc, label
        :class:`~app.kinematics.paths.point_kernel.PointConstants` and the path's branch
        flags (as :func:`~app.kinematics.paths.point_kernel.step` takes them).
    R, p, s
        (N, 3, 3), (N, 3), (N,): every waypoint's rotation, position (root frame, m) and
        path parameter (:class:`~app.kinematics.paths.segments.Samples`).
    first, stop
        The run's waypoints, all on the segment ``piece``
        (:class:`~app.kinematics.paths.pose_kernel.PieceArrays`) spanning a < s ≤ b.
    half_p, half_r
        Half the deviation bounds (m, rad).
    Q, E
        (N, n), (N, 2): row k receives waypoint k's configuration (wrapped) and its
        position and rotation errors (m, rad), for the waypoints accepted.
    out
        (1,): out[0] receives the Jacobian evaluations of the accepted waypoints' attempts.

    Returns
    -------
    int
        How many waypoints from ``first`` on were accepted (``stop − first``: all of them).
    """
    o = np.empty(5)
    q_prev = q0
    iterations = 0
    k = first
    while k < stop:
        s_m = 0.5 * (s[k - 1] + s[k])
        if not (s_m > a and s_m <= b and s_m <= 1.0):
            break
        q = Q[k]
        if step(q_prev, pc, R[k], p[k], label, piece, (s_m - a) / (b - a), q, o) != OK:
            break
        if not (o[3] <= half_p and o[4] <= half_r):
            break
        iterations += int(o[2])
        E[k, 0] = o[0]
        E[k, 1] = o[1]
        q_prev = q
        k += 1
    out[0] = iterations
    return k - first


def warm_up_arguments() -> tuple:
    """Arguments of :func:`run` of the types :mod:`.local` passes (the dummy one-joint chain
    of :func:`app.kinematics.paths.point_kernel.warm_up_arguments`, two waypoints)."""
    q, pc, eye, z3, label, piece, _, _, _ = point_kernel.warm_up_arguments()
    R = np.ascontiguousarray(np.stack([eye, eye]))
    p = np.zeros((2, 3))
    s = np.array([0.0, 1.0])
    n = q.shape[0]
    return (
        q, pc, label, R, p, s, 1, 2, piece, 0.0, 1.0, 0.5, 0.5, np.zeros((2, n)),
        np.zeros((2, 2)), np.zeros(1),
    )  # fmt: skip


def warm_up() -> None:
    """Compile (or load from the cache) :func:`run` once, with the argument types
    :mod:`.local` passes, so that the first path does not wait for the compiler."""
    run(*warm_up_arguments())


# Compiled with the solver's kernels, before any query's budget starts (ik.warmup.register).
warmup.register(warm_up)
