"""Following a Cartesian path: one joint configuration per point, the arm on one branch.

:func:`follow` walks the waypoints of :meth:`CartesianPath.sample
<app.kinematics.paths.segments.CartesianPath.sample>` from the start configuration. Each
waypoint is solved seeded by the previous accepted configuration, and a solution is accepted
only when

- no joint moves more than ``max_joint_step`` (rad or m; continuous joints measured around
  the circle, :func:`~app.kinematics.ik.search.joint_distance`),
- its branch label (:func:`branch_of`) is the start's,
- and the caller's ``accept`` (collision-free) holds.

The first attempt at a waypoint is the local solve of :mod:`.local`: one compiled damped
least-squares attempt from the previous point (full pose; a few iterations), its answer
re-checked independently (a separate forward kinematics against the waypoint within the IK
tolerance, the joint limits, and the guards above; on chains the compiled kernel supports
the attempt and every check but the caller's ``accept`` are one compiled call,
:mod:`.point_kernel`, which also measures the deviation at the middle of the step); where
it fails, the Cartesian step is halved (at most :data:`MAX_BISECT` times) with local
attempts only. When even that fails,
:func:`app.kinematics.ik.solve` takes over with the guards *inside* the solver (as its
``accept`` predicate, so a restart that lands on another branch is dropped and the search
goes on): first with a local budget (at most :data:`LOCAL_ITERATIONS` Jacobian evaluations,
the closed forms' candidates first where they exist), halving the step on failure, and only
then a last attempt with the caller's whole budget decides, which also records why the
candidates it met were refused (:mod:`.failures`).

Densification: between two accepted points a, b the joints move linearly; the frame's pose
along that motion is checked (forward kinematics at fractions :data:`FRACTIONS` of the step)
against the path's pose at the same fraction of s. Where it deviates more than
``max_deviation`` (m, rad, on the components the IK mode checks), the path's pose at the
middle s is solved (seeded by a) and inserted, and both halves are checked again, at most
:data:`MAX_DENSIFY_DEPTH` levels deep.

The first waypoint that cannot be reached ends the walk: the result keeps the points reached
(``fraction`` = s of the last one) and a :class:`PathFailure` with the waypoint's index in
the sampled list, a typed ``reason`` and the best configuration met. A ``deadline``
(:func:`time.perf_counter` instant) bounds the whole call: once passed, the walk stops
before the next waypoint with the reason ``timeout``.

The compiled walk: where no ``accept`` is given and the compiled point applies, runs of
consecutive waypoints of one segment go through one compiled call
(:mod:`.walk_kernel`), which stops at the first waypoint that is not a plain point (the
local attempt accepted, the middle within half ``max_deviation``) and hands it to the
walk above, so the points are those of the per-point walk. The deadline is then read
before each run of at most :data:`WALK_RUN` waypoints (~0.1 ms of compiled work), not
before each of them.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import replace

import numpy as np
import pinocchio as pin

from app.kinematics import ik
from app.kinematics.errors import InvalidInputError
from app.kinematics.fk import frame_pose
from app.kinematics.groups import default_frame, group
from app.kinematics.ik.branches import branch_label
from app.kinematics.ik.precompute import IKChain, ik_chain
from app.kinematics.ik.problem import IKOptions, frame_name
from app.kinematics.ik.search import Clock
from app.kinematics.models import RobotModel
from app.kinematics.paths.failures import Guard, PathFailure, classify, residuals
from app.kinematics.paths.local import LOCAL_ITERATIONS, LocalSolver, verify
from app.kinematics.paths.options import PathOptions
from app.kinematics.paths.result import PathPoint, PathResult
from app.kinematics.paths.segments import CartesianPath, Samples, Target

__all__ = ["PathFailure", "PathOptions", "PathPoint", "PathResult", "follow", "start_pose"]

#: The default clock of ``deadline`` when :func:`follow` is given none (a module attribute,
#: so that a test going through HTTP can replace it).
_clock = time.perf_counter
#: Halvings of a Cartesian step that the local attempt could not make, before giving up.
MAX_BISECT = 4
#: Levels of midpoints inserted between two accepted points to meet ``max_deviation``.
MAX_DENSIFY_DEPTH = 6
#: Fractions of a joint-space step at which the deviation from the path is checked.
FRACTIONS = (0.25, 0.5, 0.75)
MIDDLE_FIRST = (0.5, 0.25, 0.75)
#: Smallest time budget (ms) of an IK solve once the path's deadline is near or past.
MIN_SOLVE_MS = 0.1
#: Most waypoints the compiled walk takes between two readings of the deadline's clock.
WALK_RUN = 16


#: A failed attempt: the IK result, its guard, the pose attempted and its s.
_Failed = tuple[ik.IKResult, Guard, pin.SE3, float]


def branch_of(robot: RobotModel, chain: IKChain, q: np.ndarray) -> str | None:
    """The branch label of wire configuration ``q`` (None: the chain has no labels;
    :func:`app.kinematics.ik.branches.branch_label`)."""
    return branch_label(robot, chain, q)


def _frame_and_chain(robot: RobotModel, options: IKOptions) -> IKChain:
    grp = group(robot, options.group)
    return ik_chain(robot, frame_name(robot, default_frame(robot, grp, options.frame)), grp)


def start_pose(robot: RobotModel, start: np.ndarray, options: IKOptions) -> pin.SE3:
    """The path's start: the placement of the IK frame (``options.frame`` or the group's tip)
    at wire configuration ``start``, in the root frame."""
    ch = _frame_and_chain(robot, options)
    return frame_pose(robot, robot.configuration(start, field="start"), ch.frame_id)


class _Walk:
    """One call of :func:`follow`: its inputs, counters and solve helpers."""

    def __init__(
        self,
        robot: RobotModel,
        path: CartesianPath,
        ik_options: IKOptions,
        options: PathOptions,
        accept: Callable[[np.ndarray], bool] | None,
        rng: np.random.Generator | None,
        cancel: threading.Event | None,
        deadline: float | None = None,
        clock: Clock | None = None,
    ) -> None:
        self.robot, self.path, self.options = robot, path, options
        self.deadline = deadline
        #: The deadline's clock, and the IK solves' (``time.perf_counter`` unless injected).
        self.now: Clock = _clock if clock is None else clock
        self.ik_clock: Clock = time.perf_counter if clock is None else clock
        self.ch = _frame_and_chain(robot, ik_options)
        self.task = ik_options.task()
        self.full = replace(ik_options, num_solutions=1)
        cap = ik_options.max_iterations
        local_cap = LOCAL_ITERATIONS if cap is None else min(cap, LOCAL_ITERATIONS)
        self.local = replace(self.full, max_iterations=local_cap)
        self.tol = (float(ik_options.tolerance[0]), float(ik_options.tolerance[1]))
        self.warm = LocalSolver(robot, self.ch, self.task, self.tol, cap)
        self.accept, self.rng, self.cancel = accept, rng, cancel
        self.iterations = 0
        self.label: str | None = None
        self.points: list[PathPoint] = []
        #: Deviations at the middle measured by the compiled point, by id of the point:
        #: (the point, the configuration it was solved from, position m, rotation rad).
        self.middles: dict[int, tuple[PathPoint, np.ndarray, float, float]] = {}

    # ------------------------------------------------------------------ solving
    def guard(self, q_prev: np.ndarray, record_all: bool = False) -> Guard:
        return Guard(
            self.robot,
            self.ch,
            q_prev,
            self.options.max_joint_step,
            self.label,
            lambda q: branch_of(self.robot, self.ch, q),
            self.accept,
            record_all,
        )

    def warm_start(
        self, q_prev: np.ndarray, s_prev: float, T: Target, s: float
    ) -> PathPoint | None:
        """The point at ``T`` (path parameter ``s``) by the local attempt from ``q_prev``
        (at ``s_prev``; :mod:`.local`), verified independently; None when it fails or is
        refused.

        With the compiled point (:meth:`LocalSolver.point`) the attempt and the checks are
        one call, which also measures the deviation at the middle of the step from the
        path's pose at the middle s (kept for :meth:`deviation`); the caller's ``accept``
        follows in Python."""
        if self.warm.compiled is not None:
            middle = self.path.piece_at(0.5 * (s_prev + s))
            status, q, ep, er, n, dev_p, dev_r = self.warm.point(q_prev, T.R, T.p, middle)
            self.iterations += n
            if q is None or (self.accept is not None and not self.accept(q)):
                return None
            b = PathPoint(q, ep, er, s)
            self.middles[id(b)] = (b, q_prev, dev_p, dev_r)
            return b
        q, n = self.warm.attempt(q_prev, T.se3)
        self.iterations += n
        if q is None:
            return None
        ok = verify(self.robot, self.ch, self.task, self.tol, q, T.se3, self.guard(q_prev))
        return None if ok is None else PathPoint(ok[0], ok[1], ok[2], s)

    def solve(self, q_prev: np.ndarray, T: Target, full: bool = False) -> tuple[ik.IKResult, Guard]:
        """IK of ``T`` seeded by ``q_prev`` under the guards (local budget unless ``full``)."""
        g = self.guard(q_prev, record_all=full)
        opts = self.full if full else self.local
        if self.deadline is not None:
            left_ms = (self.deadline - self.now()) * 1e3
            if left_ms < opts.timeout_ms:
                opts = replace(opts, timeout_ms=max(left_ms, MIN_SOLVE_MS))
        res = ik.solve(
            self.robot,
            T.se3,
            opts,
            seed=q_prev,
            accept=g,
            rng=self.rng,
            cancel=self.cancel,
            clock=self.ik_clock,
        )
        self.iterations += res.iterations
        return res, g

    # ------------------------------------------------------------------- walking
    def warm_chain(
        self, q_a: np.ndarray, s_a: float, T_b: Target, s_b: float, depth: int
    ) -> list[PathPoint] | None:
        """Verified points from ``q_a`` (at ``s_a``) to ``T_b`` (at ``s_b``, the last one)
        by local attempts only (:meth:`warm_start`), halving the step where one fails (down
        to depth :data:`MAX_BISECT`); None when some half still fails. Nothing is appended."""
        b = self.warm_start(q_a, s_a, T_b, s_b)
        if b is not None:
            return [b]
        if depth >= MAX_BISECT:
            return None
        s_m = 0.5 * (s_a + s_b)
        first = self.warm_chain(q_a, s_a, self.path.target_at(s_m), s_m, depth + 1)
        if first is None:
            return None
        rest = self.warm_chain(first[-1].q, s_m, T_b, s_b, depth + 1)
        return None if rest is None else first + rest

    def advance(self, T_b: Target, s_b: float, depth: int = 0, warm: bool = True) -> _Failed | None:
        """Append the points from the last one to the pose ``T_b`` at ``s_b`` (included);
        on failure the last attempt (the points reached on the way stay).

        First by local attempts (:meth:`warm_chain`, the step halved where they fail); when
        they cannot, by :func:`app.kinematics.ik.solve` with the local budget, halving the
        step when it fails, then with the whole budget at the last level."""
        a = self.points[-1]
        chain = self.warm_chain(a.q, a.s, T_b, s_b, depth) if warm else None
        if chain is not None:
            for b in chain:
                out = self.densify(self.points[-1], b)
                if out is not None:
                    return out
            return None
        res, g = self.solve(a.q, T_b)
        if not res.success and depth >= MAX_BISECT:
            res, g = self.solve(a.q, T_b, full=True)
        if res.success:
            return self.densify(a, PathPoint(res.q, res.position_error, res.orientation_error, s_b))
        if depth >= MAX_BISECT:
            return res, g, T_b.se3, s_b
        s_m = 0.5 * (a.s + s_b)
        return self.advance(self.path.target_at(s_m), s_m, depth + 1, False) or self.advance(
            T_b, s_b, depth + 1, False
        )

    def deviation(self, a: PathPoint, b: PathPoint) -> tuple[float, float]:
        """The largest position and rotation deviation (m, rad) from the path of the frame
        while the joints move linearly from a to b, at :data:`FRACTIONS`.

        The middle is checked first: a smooth deviation vanishes at both ends and bulges like
        f(1 − f), largest at f = 1/2, so when the middle is within half the bounds the other
        fractions are skipped."""
        robot, warm = self.robot, self.warm
        middle = self.middles.pop(id(b), None)
        dev_p, dev_r = self.options.max_deviation
        if middle is not None and middle[0] is b and middle[1] is a.q:
            # the middle measured by the compiled point, within half the bounds: done
            if middle[2] <= 0.5 * dev_p and middle[3] <= 0.5 * dev_r:
                return middle[2], middle[3]
        dq = robot.difference(a.q, b.q)
        worst_p = worst_r = 0.0
        for k, f in enumerate(MIDDLE_FIRST):
            if k == 0 and middle is not None and middle[0] is b and middle[1] is a.q:
                ep, er = middle[2], middle[3]
            elif warm.compiled is not None:
                q = (a.q + f * dq)[self.ch.active]
                ep, er = warm.residuals_at(q, self.path.pose_at(a.s + f * (b.s - a.s)))
            else:
                T = frame_pose(robot, a.q + f * dq, self.ch.frame_id)
                ep, er = residuals(T, self.path.pose_at(a.s + f * (b.s - a.s)), self.task)
            worst_p, worst_r = max(worst_p, ep), max(worst_r, er)
            if k == 0 and worst_p <= 0.5 * dev_p and worst_r <= 0.5 * dev_r:
                break
        return worst_p, worst_r

    def densify(self, a: PathPoint, b: PathPoint, depth: int = 0) -> _Failed | None:
        """Append ``b`` preceded by the midpoints needed to keep the linear joint motion from
        ``a`` (the last point) within ``max_deviation`` of the path; on failure the failing
        attempt (the midpoints appended so far stay)."""
        dev_p, dev_r = self.options.max_deviation
        ep, er = self.deviation(a, b)
        if ep <= dev_p and er <= dev_r:
            self.points.append(b)
            return None
        s_m = 0.5 * (a.s + b.s)
        T_m = self.path.target_at(s_m)
        if depth >= MAX_DENSIFY_DEPTH:
            res, g = self.solve(a.q, T_m, full=True)
            g.deviation = (ep, er, depth)
            return res, g, T_m.se3, s_m
        m = self.warm_start(a.q, a.s, T_m, s_m)
        if m is None:
            res, g = self.solve(a.q, T_m)
            if not res.success:
                res, g = self.solve(a.q, T_m, full=True)
                if not res.success:
                    return res, g, T_m.se3, s_m
            m = PathPoint(res.q, res.position_error, res.orientation_error, s_m)
        return self.densify(a, m, depth + 1) or self.densify(m, b, depth + 1)


def _timed_out(walk: _Walk, index: int, s: float) -> PathFailure:
    """The ``timeout`` failure at waypoint ``index``: the path's budget ran out before it."""
    last = walk.points[-1]
    return PathFailure(
        index,
        s,
        "timeout",
        f"the path's time budget ran out before waypoint {index} (s = {s:.4f}); the points "
        f"up to s = {last.s:.4f} are returned",
        last.q.copy(),
        last.position_error,
        last.orientation_error,
    )


def follow(
    robot: RobotModel,
    start: np.ndarray,
    path: CartesianPath,
    ik_options: IKOptions,
    options: PathOptions = PathOptions(),  # noqa: B008 (frozen: never mutated)
    *,
    accept: Callable[[np.ndarray], bool] | None = None,
    rng: np.random.Generator | None = None,
    cancel: threading.Event | None = None,
    deadline: float | None = None,
    clock: Clock | None = None,
) -> PathResult:
    """Joint configurations following ``path`` from ``start`` (see the module docstring).

    Parameters
    ----------
    robot
        The robot.
    start
        Full wire configuration (rad or m) where the path starts; the path's start pose
        must be the frame's placement there (:func:`start_pose`).
    path
        The Cartesian path of the frame, in the root frame.
    ik_options
        Frame or group, mode, weights, tolerances and budget of each IK solve (per point).
    options
        Sampling step, joint-step bound, deviation bound, required branch.
    accept
        Optional predicate on a wire configuration (collision-free); points that fail it are
        never returned.
    rng, cancel
        Passed to every :func:`app.kinematics.ik.solve` (restarts; the client went away).
    deadline
        Optional :func:`time.perf_counter` instant bounding the whole call: once it has
        passed, the walk stops before the next waypoint with the failure reason ``timeout``
        (the points reached so far are kept). Each IK solve keeps its own ``timeout_ms``, at
        most the time left.
    clock
        The clock (s) of ``deadline`` and of every IK solve's budget; default
        ``time.perf_counter`` (a test passes a fake one).

    Returns
    -------
    PathResult
        The points reached and, when the path could not be completed, the typed failure.
    """
    t0 = time.perf_counter()
    walk = _Walk(robot, path, ik_options, options, accept, rng, cancel, deadline, clock)
    q0 = robot.configuration(start, field="start")
    for i in np.flatnonzero((q0 < robot.lower) | (q0 > robot.upper)):
        raise InvalidInputError(
            f"joint {robot.joints[i].name} = {q0[i]:g} lies outside its limits "
            f"[{robot.lower[i]:g}, {robot.upper[i]:g}]",
            f"start.{i}",
        )
    walk.label = label = branch_of(robot, walk.ch, q0)
    if options.branch is not None and label != options.branch:
        where = "has no branch labels" if label is None else f"starts on branch {label!r}"
        raise InvalidInputError(f"the path {where}, not {options.branch!r}", "branch")
    compiled_walk = walk.warm.prepare(q0, label, options.max_joint_step)
    ep, er = residuals(frame_pose(robot, q0, walk.ch.frame_id), path.start, walk.task)
    tol_p, tol_r = ik_options.tolerance
    if ep > tol_p or er > tol_r:
        raise InvalidInputError(
            f"the path does not start at the frame's pose at start ({ep:.3g} m, {er:.3g} rad away)",
            "start",
        )
    samples = path.sample_arrays(options.max_step)
    points = walk.points
    failure: PathFailure | None = None
    if accept is not None and not accept(q0):
        failure = PathFailure(
            0, 0.0, "collision", "the start configuration is in collision", q0.copy(), ep, er
        )
    else:
        points.append(PathPoint(q0.copy(), ep, er, 0.0))
        failure = _walk(walk, samples, compiled_walk and accept is None, clock is None)
    return PathResult(
        points,
        points[-1].s if points else 0.0,
        failure,
        label,
        len(samples),
        walk.iterations,
        (time.perf_counter() - t0) * 1e3,
    )


def _walk(walk: _Walk, samples: Samples, runs: bool, own_clock: bool) -> PathFailure | None:
    """Append the points of waypoints 1, 2, ... of ``samples`` after the start until the
    last one, or return the first failure.

    With ``runs`` (the compiled point on, no ``accept``) the waypoints go by runs through
    the compiled walk (:meth:`LocalSolver.walk`): a whole segment without a deadline, else
    at most :data:`WALK_RUN` waypoints of one (one waypoint when the clock is injected, not
    ``own_clock``: a test's clock is read before every waypoint). A run's first waypoint
    that is not a plain point is taken by :meth:`_Walk.advance`, as every waypoint is
    without ``runs``. The deadline is read before each run or waypoint so taken."""
    deadline, points, ss, size = walk.deadline, walk.points, samples.s, len(samples)
    longest = size if deadline is None else WALK_RUN if own_clock else 1
    if runs:
        Q, E, seg = np.empty((size, walk.robot.n)), np.empty((size, 2)), 0
        half = (0.5 * walk.options.max_deviation[0], 0.5 * walk.options.max_deviation[1])
    k = 1
    while k < size:
        if deadline is not None and walk.now() >= deadline:
            return _timed_out(walk, k, float(ss[k]))
        if runs:
            while samples.runs[seg][1] <= k:
                seg += 1
            stop = min(samples.runs[seg][1], k + longest)
            m, n = walk.warm.walk(points[-1].q, samples, k, stop, seg, half, Q, E)
            walk.iterations += n
            errors, s_run = E[k : k + m].tolist(), ss[k : k + m].tolist()
            for j in range(m):
                points.append(PathPoint(Q[k + j], errors[j][0], errors[j][1], s_run[j]))
            k += m
            if k == stop:
                continue
        out = walk.advance(samples.target(k), float(ss[k]))
        if out is not None:
            res, g, T, s = out
            return classify(walk.robot, walk.ch, walk.task, k, s, points[-1], res, g, T)
        k += 1
    return None
