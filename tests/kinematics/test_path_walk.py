"""The compiled walk of a path (app/kinematics/paths/walk_kernel.py): runs of waypoints in one
compiled call find exactly the points of the per-point walk.

The reference is the per-point walk (every waypoint through
:meth:`app.kinematics.paths.follow._Walk.advance`, the compiled point one call per
waypoint), obtained by making :meth:`LocalSolver.walk` accept no waypoint. Both follow the
same lines (:mod:`bench._lines`, the bench's and test_paths.py's workload) and must give the
same answer: configurations within 1e-12, the same s, errors, iterations, and the same
failure (index, s, reason, configuration). The lines include ones that fail, ones that
densify (a tight ``max_deviation``), arcs and turning segments, and lines with a collision
predicate (which keep the per-point walk). The sampled waypoints as arrays are checked bit
for bit against :meth:`CartesianPath.sample_targets`, and the deadline is read before each
run. Every point is also checked against yourdfpy (``check_points``). Fixed seeds, iteration
caps with a generous time budget: nothing depends on the machine's speed.
"""

from __future__ import annotations

import numba
import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import jit
from app.kinematics.paths import follow as follow_module
from app.kinematics.paths import point_kernel, walk_kernel
from app.kinematics.paths.follow import WALK_RUN, PathOptions, PathResult, follow
from app.kinematics.paths.local import LocalSolver
from app.kinematics.paths.segments import Arc, CartesianPath, Line
from bench._lines import random_lines
from tests.kinematics.path_checks import check_points, ik_options

ARMS = [("ur5", "tool0"), ("panda", "panda_hand"), ("kinova", "j2s6s200_end_effector")]
#: The bench's options, and a tight deviation bound with longer steps (densifies).
PLAIN = PathOptions(max_step=(0.01, 0.05), max_joint_step=0.1)
DENSE = PathOptions(max_step=(0.01, 0.05), max_joint_step=0.1, max_deviation=(1e-4, 1e-3))


class _Spy:
    """Counts the compiled walk's calls and accepted waypoints; ``off`` makes it accept
    none (the per-point walk)."""

    def __init__(self, mp: pytest.MonkeyPatch, off: bool = False) -> None:
        self.calls = self.accepted = 0
        self.halves: set[tuple[float, float]] = set()
        original = LocalSolver.walk

        def walk(solver, *args):
            self.calls += 1
            self.halves.add(args[5])
            if off:
                return 0, 0
            out = original(solver, *args)
            self.accepted += out[0]
            return out

        mp.setattr(LocalSolver, "walk", walk)


def _both(robot, q0, path, opts, options, **kw) -> tuple[PathResult, PathResult, _Spy]:
    """The answer of the compiled walk and of the per-point walk (fixed rng seeds)."""
    with pytest.MonkeyPatch.context() as mp:
        spy = _Spy(mp)
        new = follow(robot, q0, path, opts, options, rng=np.random.default_rng(5), **kw)
    with pytest.MonkeyPatch.context() as mp:
        _Spy(mp, off=True)
        old = follow(robot, q0, path, opts, options, rng=np.random.default_rng(5), **kw)
    return new, old, spy


def _assert_same(new: PathResult, old: PathResult) -> None:
    assert len(new.points) == len(old.points)
    for a, b in zip(new.points, old.points, strict=True):
        assert a.s == b.s
        np.testing.assert_allclose(a.q, b.q, rtol=0.0, atol=1e-12)
        assert a.position_error == pytest.approx(b.position_error, abs=1e-12)
        assert a.orientation_error == pytest.approx(b.orientation_error, abs=1e-12)
    assert new.fraction == old.fraction
    assert new.iterations == old.iterations
    assert new.waypoints == old.waypoints and new.branch == old.branch
    assert (new.failure is None) == (old.failure is None)
    if new.failure is not None:
        f, g = new.failure, old.failure
        assert (f.index, f.s, f.reason) == (g.index, g.s, g.reason)
        np.testing.assert_allclose(f.q, g.q, rtol=0.0, atol=1e-12)


@pytest.mark.parametrize("options", [PLAIN, DENSE], ids=["plain", "densify"])
@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_compiled_walk_finds_the_per_point_walks_points(
    registry, robot_id: str, frame: str, options: PathOptions
) -> None:
    """Along random lines both walks answer the same points and failures; the compiled walk
    takes most waypoints, and the lines include failures and hand-backs (densification)."""
    robot = registry.get(robot_id)
    opts = ik_options(frame)
    failed = densified = accepted = waypoints = 0
    for line in random_lines(robot, frame, 24, seed=77, checks=4):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])
        new, old, spy = _both(robot, line.q0, path, opts, options)
        _assert_same(new, old)
        check_points(robot, frame, line.q0, path, new, options)
        failed += new.failure is not None
        densified += len(new.points) > new.waypoints
        accepted += spy.accepted
        waypoints += new.waypoints - 1
        dev_p, dev_r = options.max_deviation
        assert spy.halves == {(0.5 * dev_p, 0.5 * dev_r)}  # the middle's test of deviation()
    assert failed > 0
    # plain: the compiled walk takes almost every waypoint; dense: about half of them
    assert accepted >= (0.8 if options is PLAIN else 0.3) * waypoints
    if options is DENSE:
        assert densified > 0


@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_compiled_walk_on_arcs_turning_segments_and_waypoints(
    registry, robot_id: str, frame: str
) -> None:
    """Paths of several segments (an arc, turning lines, a zero-length segment, a polyline
    of waypoints): the runs stop at each segment's end and both walks agree."""
    robot = registry.get(robot_id)
    opts = ik_options(frame)
    rng = np.random.default_rng(12)
    runs = accepted = waypoints = 0
    for line in random_lines(robot, frame, 8, seed=78, checks=4):
        T0, T1 = line.start, line.end
        mid = 0.5 * (T0.translation + T1.translation)
        side = np.cross(T1.translation - T0.translation, rng.normal(size=3))
        side *= 0.03 / np.linalg.norm(side)
        turned = pin.SE3(T1.rotation @ pin.exp3(rng.normal(scale=0.15, size=3)), T1.translation)
        via = pin.SE3(T0.rotation @ pin.exp3(rng.normal(scale=0.1, size=3)), mid + side)
        for path in (
            CartesianPath.from_segments(T0, [Arc(via, turned), Line(turned), Line(T0)]),
            CartesianPath.from_waypoints(T0, [via, turned, T1]),
        ):
            new, old, spy = _both(robot, line.q0, path, opts, PLAIN)
            _assert_same(new, old)
            check_points(robot, frame, line.q0, path, new, PLAIN)
            runs += spy.calls
            accepted += spy.accepted
            waypoints += new.waypoints - 1
    assert runs > 16
    assert accepted >= 0.7 * waypoints


@pytest.mark.parametrize(("robot_id", "frame"), ARMS[:2])
def test_a_collision_predicate_keeps_the_per_point_walk(
    registry, robot_id: str, frame: str
) -> None:
    """With ``accept`` the compiled walk is never called (the predicate runs after each
    point in Python): a predicate that refuses part of the joint space stops lines with
    ``collision``, and one that refuses nothing gives the answer without it."""
    robot = registry.get(robot_id)
    opts = ik_options(frame)
    collided = 0
    for line in random_lines(robot, frame, 12, seed=79, checks=4):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])
        wall = line.q0[1] + 0.05  # joint 2 may not pass this angle

        def accept(q, wall=wall) -> bool:
            return bool(q[1] < wall)

        with pytest.MonkeyPatch.context() as mp:
            spy = _Spy(mp)
            res = follow(robot, line.q0, path, opts, PLAIN, accept=accept)
            free = follow(robot, line.q0, path, opts, PLAIN, accept=lambda q: True)
        assert spy.calls == 0
        assert all(p.q[1] < wall for p in res.points)
        collided += res.failure is not None and res.failure.reason == "collision"
        new, _, _ = _both(robot, line.q0, path, opts, PLAIN)
        _assert_same(free, new)
    assert collided > 0


def test_sampled_arrays_are_the_sampled_targets_bit_for_bit() -> None:
    """:meth:`CartesianPath.sample_arrays` against :meth:`sample_targets` on lines (turning
    and not), arcs, zero-length segments and polylines; its runs cover every waypoint."""
    rng = np.random.default_rng(9)
    for trial in range(30):
        start = pin.SE3.Random()
        flat = pin.SE3(start.rotation, rng.normal(size=3))
        segs = [Line(flat), Line(pin.SE3.Random()), Line(pin.SE3.Random())]
        if trial % 3 == 0:
            segs.insert(1, Arc(pin.SE3.Random(), pin.SE3.Random()))
        if trial % 4 == 0:
            segs.insert(2, Line(segs[1].to))  # zero length
        path = CartesianPath.from_segments(start, segs)
        step = (float(rng.uniform(0.05, 0.5)), float(rng.uniform(0.05, 0.5)))
        samples = path.sample_arrays(step)
        targets, ss = path.sample_targets(step)
        assert len(samples) == len(targets)
        np.testing.assert_array_equal(samples.s, ss)
        for k, T in enumerate(targets):
            np.testing.assert_array_equal(samples.R[k], T.R)
            np.testing.assert_array_equal(samples.p[k], T.p)
            assert samples.target(k) is samples.target(k)
            np.testing.assert_array_equal(samples.target(k).R, T.R)
        covered = [k for first, stop, *_ in samples.runs for k in range(first, stop)]
        assert covered == list(range(1, len(targets)))
        for first, stop, a, b, piece in samples.runs:
            assert a < ss[first] and ss[stop - 1] == b
            assert path.piece_at(b)[0] is piece


@pytest.mark.parametrize(("robot_id", "frame"), ARMS[:2])
def test_the_deadline_is_read_before_each_run(registry, robot_id: str, frame: str) -> None:
    """``follow``'s own clock (replaced by one that advances one unit per reading; deadline
    3) is read before each run of at most :data:`WALK_RUN` waypoints: the walk stops with
    ``timeout`` at the first run after the third reading, keeping the points of the full
    answer before it."""
    robot = registry.get(robot_id)
    opts = ik_options(frame)
    options = PathOptions(max_step=(0.002, 0.05), max_joint_step=0.1)
    for line in random_lines(robot, frame, 10, seed=80, checks=4):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])
        with pytest.MonkeyPatch.context() as mp:
            spy = _Spy(mp)
            full = follow(robot, line.q0, path, opts, options)
        # every waypoint a plain point, in one run (no deadline: the whole segment)
        if full.failure is None and spy.calls == 1 and full.waypoints > 4 * WALK_RUN:
            break
    else:
        raise AssertionError("no line of plain points of more than 4 runs in 10 draws")
    readings: list[float] = []

    def clock() -> float:
        readings.append(float(len(readings)))
        return readings[-1]

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(follow_module, "_clock", clock)
        res = follow(robot, line.q0, path, opts, options, deadline=3.0)
    assert res.failure is not None and res.failure.reason == "timeout"
    assert readings == [0.0, 1.0, 2.0, 3.0]
    assert res.failure.index == 1 + 3 * WALK_RUN
    assert len(res.points) == 1 + 3 * WALK_RUN
    for p, q in zip(res.points, full.points, strict=False):
        assert p.s == q.s
        np.testing.assert_array_equal(p.q, q.q)


@pytest.mark.parametrize("bound", ["position", "rotation"])
@pytest.mark.parametrize(("robot_id", "frame"), ARMS)
def test_a_run_stops_exactly_at_the_first_waypoint_that_is_not_plain(
    registry, robot_id: str, frame: str, bound: str
) -> None:
    """The compiled walk against the per-point compiled step (:meth:`LocalSolver.point`,
    the middle from :meth:`CartesianPath.piece_at`) on the segments of a polyline: it
    accepts waypoints while the step is ``OK`` and the middle's deviation within the half
    bounds given (here the median deviation on one component, unbounded on the other), with
    the step's configurations, errors and iterations, and stops at the first other one."""
    robot = registry.get(robot_id)
    opts = ik_options(frame)
    ch = follow_module._frame_and_chain(robot, opts)
    solver = LocalSolver(robot, ch, opts.task(), opts.tolerance, None)
    for line in random_lines(robot, frame, 8, seed=81, checks=4):
        T0, T1 = line.start, line.end
        bend = pin.SE3(T1.rotation, 0.5 * (T0.translation + T1.translation) + [0, 0, 0.04])
        path = CartesianPath.from_waypoints(T0, [bend, T1])
        label = follow_module.branch_of(robot, ch, line.q0)
        assert solver.prepare(line.q0, label, PLAIN.max_joint_step)
        samples = path.sample_arrays(PLAIN.max_step)
        s = samples.s
        # the per-point steps along the path from the start (each from the previous point)
        steps, q_prev = [None], line.q0
        for k in range(1, len(samples)):
            middle = path.piece_at(0.5 * (s[k - 1] + s[k]))
            steps.append(solver.point(q_prev, samples.R[k], samples.p[k], middle))
            if steps[-1][0] != point_kernel.OK:
                break
            q_prev = steps[-1][1]
        if len(steps) == len(samples) and steps[-1][0] == point_kernel.OK:
            break
    else:
        raise AssertionError("no line of OK steps in 8 draws")
    devs = np.array([(o[5], o[6]) for o in steps[1:]])
    i = 0 if bound == "position" else 1
    half = [np.inf, np.inf]
    half[i] = float(np.median(devs[:, i]))
    stopped = 0
    for seg, (first, stop, *_) in enumerate(samples.runs):
        Q, E = np.full((len(samples), robot.n), np.nan), np.full((len(samples), 2), np.nan)
        q_prev = line.q0 if first == 1 else steps[first - 1][1]
        m, n = solver.walk(q_prev, samples, first, stop, seg, tuple(half), Q, E)
        plain = [steps[k][5 + i] <= half[i] for k in range(first, stop)]
        want = plain.index(False) if False in plain else stop - first
        assert m == want
        stopped += m < stop - first
        assert n == sum(steps[k][4] for k in range(first, first + m))
        for k in range(first, first + m):
            np.testing.assert_array_equal(Q[k], steps[k][1])
            assert (E[k, 0], E[k, 1]) == (steps[k][2], steps[k][3])
    assert len(samples.runs) == 2 and stopped > 0


def test_warm_up_compiles_the_signature_the_walk_uses(registry) -> None:
    """warm_up() compiles run() for exactly the argument types LocalSolver.walk passes, and
    registers with the solver's warm-up (so a warmed process never compiles on a path
    request, and a chain is prepared only once the walk is compiled)."""
    from app.kinematics.ik import warmup

    assert walk_kernel.warm_up in warmup._CALLERS
    walk_kernel.warm_up()
    robot = registry.get("ur5")
    opts = ik_options("tool0")
    ch = follow_module._frame_and_chain(robot, opts)
    solver = LocalSolver(robot, ch, opts.task(), opts.tolerance, None)
    line = random_lines(robot, "tool0", 1, seed=3, checks=2)[0]
    assert solver.prepare(line.q0, follow_module.branch_of(robot, ch, line.q0), 0.1)
    samples = CartesianPath.from_segments(line.start, [Line(line.end)]).sample_arrays(
        PLAIN.max_step
    )
    seen: list[tuple] = []
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(jit, "direct", lambda fn, *args: seen.append(args) or fn)
        solver.walk(line.q0, samples, 1, 2, 0, (5e-4, 5e-3), np.empty((2, 6)), np.empty((2, 2)))
    warm = walk_kernel.warm_up_arguments()
    assert [numba.typeof(a) for a in seen[0]] == [numba.typeof(a) for a in warm]
    assert tuple(numba.typeof(a) for a in warm) in walk_kernel.run.signatures
