"""The compiled point of a path (app/kinematics/paths/point_kernel.py, pose_kernel.py)
against the Python checks it replaces and against Pinocchio.

- its forward kinematics (frame pose, joint axes and points, wrist point) against
  Pinocchio's at random configurations, and its branch flags against
  :func:`app.kinematics.ik.branches.branch_label`;
- its checks against the Python ones (:func:`app.kinematics.paths.local.verify` and the
  path's :class:`~app.kinematics.paths.failures.Guard`, each reason spelled out) on random
  candidates built to reach every status: accepted, outside the limits (NaN too), off the
  pose, too large a joint step, another branch; continuous joints wrapped (Kinova);
- the whole step (attempt, checks, deviation at the middle) against the Python attempt,
  :func:`verify` and the path's pose at the middle;
- a segment's compiled pose against :meth:`CartesianPath.pose_at` on lines and arcs.

Fixed seeds throughout.
"""

from __future__ import annotations

import math

import numba
import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.fk import frame_pose
from app.kinematics.ik.branch_kernel import label
from app.kinematics.ik.branches import branch_label
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.ranking import joint_distance
from app.kinematics.paths import point_kernel as pk
from app.kinematics.paths.failures import Guard, residuals
from app.kinematics.paths.follow import PathOptions, _frame_and_chain, follow
from app.kinematics.paths.local import LocalSolver, verify
from app.kinematics.paths.pose_kernel import piece_pose
from app.kinematics.paths.segments import Arc, CartesianPath, Line
from bench._lines import random_lines

#: Labelled 6R forms (UR type, spherical wrist, prismatic third joint), a redundant arm
#: without labels, continuous joints.
ROBOTS = ["ur5", "puma560", "stanford_arm", "panda", "kinova"]
TOL = 1e-6


def _setup(registry, robot_id: str, max_joint_step: float = 0.1):
    robot = registry.get(robot_id)
    opts = IKOptions(tolerance=(TOL, TOL))
    ch = _frame_and_chain(robot, opts)
    solver = LocalSolver(robot, ch, opts.task(), (TOL, TOL), None)
    assert solver.available
    return robot, ch, opts.task(), solver


def _random_q(robot, rng) -> np.ndarray:
    lo = np.where(np.isfinite(robot.lower), robot.lower, -math.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, math.pi)
    return rng.uniform(lo, hi)


@pytest.mark.parametrize("robot_id", ROBOTS)
def test_frames_match_pinocchio(registry, robot_id: str) -> None:
    robot, ch, _, solver = _setup(registry, robot_id)
    pc = solver.constants(0.1)
    form = ch.branch_form
    model, data = robot.model, robot.model.createData()
    rng = np.random.default_rng(5)
    k = ch.k
    for _ in range(100):
        q = _random_q(robot, rng)
        R, p, z, o, w = (
            np.empty((3, 3)),
            np.empty(3),
            np.empty((k, 3)),
            np.empty((k, 3)),
            np.zeros(3),
        )
        pk.frames(np.ascontiguousarray(q[ch.active]), pc.chain, R, p, z, o, w, pc.wrist)
        T = frame_pose(robot, q, ch.frame_id)
        np.testing.assert_allclose(R, T.rotation, atol=1e-12)
        np.testing.assert_allclose(p, T.translation, atol=1e-12)
        pin.forwardKinematics(model, data, robot.to_pin(q))
        for s, i in enumerate(ch.active):
            j = robot.joints[int(i)]
            M = data.oMi[j.pin_id]
            axis = M.rotation @ (np.asarray(j.axis, float) / np.linalg.norm(j.axis))
            np.testing.assert_allclose(z[s], axis, atol=1e-12)
            # o is a point of the axis: o − (the joint's origin) is along it
            np.testing.assert_allclose(np.cross(o[s] - M.translation, axis), 0.0, atol=1e-12)
        if form is not None and form.wrist is not None:
            np.testing.assert_allclose(w, data.oMi[form.pin_ids[4]].act(form.wrist), atol=1e-12)


@pytest.mark.parametrize("robot_id", ["ur5", "puma560", "stanford_arm"])
def test_label_code_names_the_python_label(registry, robot_id: str) -> None:
    robot, ch, _, solver = _setup(registry, robot_id)
    pc = solver.constants(0.1)
    rng = np.random.default_rng(6)
    seen = set()
    for _ in range(300):
        q = _random_q(robot, rng)
        code = pk.label_code(q, pc)
        assert label(ch.branch_form, code) == branch_label(robot, ch, q)
        seen.add(code)
    assert len(seen) >= 4  # several branches met


def _python_status(robot, ch, task, q, q_prev, target, lab, max_step):
    """The Python checks, in verify's order, with the reason of a refusal."""
    qw = robot.wrap(q)
    if not ((qw >= robot.lower) & (qw <= robot.upper)).all():
        return pk.LIMITS, None
    ep, er = residuals(frame_pose(robot, qw, ch.frame_id), target, task)
    if not (ep <= TOL and er <= TOL):
        return pk.OFF_POSE, (ep, er)
    if joint_distance(robot, qw, q_prev)[ch.active].max() > max_step:
        return pk.JOINT_STEP, (ep, er)
    if lab is not None and branch_label(robot, ch, qw) != lab:
        return pk.BRANCH, (ep, er)
    return pk.OK, (ep, er)


def _candidate(robot, ch, q_prev, kind: int, rng):
    """A candidate and its target for status ``kind`` (mostly; the reference decides)."""
    a = ch.active
    q = q_prev.copy()
    q[a] += rng.normal(0.0, 0.02, a.size)
    if kind == 1:  # anywhere: another branch, or the same
        q = _random_q(robot, rng)
    if kind == 3:  # one joint beyond a limit, or NaN
        i = int(rng.choice(a))
        q[i] = np.nan if rng.random() < 0.2 else robot.upper[i] + 0.05
        if not np.isfinite(robot.upper[i]):
            q[i] = np.nan
    if kind == 4:  # one joint jumps
        q[int(rng.choice(a))] += rng.choice([-1.0, 1.0]) * rng.uniform(0.15, 0.5)
    cont = [i for i in a if robot.joints[int(i)].continuous]
    for i in cont:  # whole turns: the checks wrap them
        q[i] += 2.0 * math.pi * rng.integers(-2, 3)
    T = frame_pose(robot, robot.wrap(np.nan_to_num(q)), ch.frame_id)
    if kind == 2:  # off the pose, just beyond or just within the tolerance
        d = rng.normal(size=3)
        off = TOL * rng.choice([0.5, 3.0])
        if rng.random() < 0.5:
            T = pin.SE3(T.rotation, T.translation + off * d / np.linalg.norm(d))
        else:
            T = pin.SE3(T.rotation @ pin.exp3(off * d / np.linalg.norm(d)), T.translation)
    return q, T


@pytest.mark.parametrize("robot_id", ROBOTS)
def test_compiled_checks_agree_with_python(registry, robot_id: str) -> None:
    """Every candidate gets the same status from the compiled checks as from the Python
    ones, the same errors, and verify() accepts exactly the OK ones; every status is
    reached (BRANCH on labelled chains)."""
    robot, ch, task, solver = _setup(registry, robot_id)
    rng = np.random.default_rng(7)
    reached: dict[int, int] = {}
    for trial in range(400):
        q_prev = _random_q(robot, rng)
        lab = branch_label(robot, ch, q_prev)
        max_step = 10.0 if trial % 5 == 1 else 0.1
        assert solver.prepare(q_prev, lab, max_step)
        q, T = _candidate(robot, ch, q_prev, trial % 5, rng)
        status, qw, ep, er = solver.check(q_prev, q, T)
        want, errs = _python_status(robot, ch, task, q, q_prev, T, lab, max_step)
        assert status == want, (trial, pk.STATUSES[status], pk.STATUSES[want])
        if errs is not None:
            assert ep == pytest.approx(errs[0], abs=1e-12)
            assert er == pytest.approx(errs[1], abs=1e-12)
        if status != pk.LIMITS:
            np.testing.assert_array_equal(qw, robot.wrap(q))
        guard = Guard(robot, ch, q_prev, max_step, lab, lambda x: branch_label(robot, ch, x), None)
        ok = verify(robot, ch, task, (TOL, TOL), q, T, guard)
        assert (ok is not None) == (status == pk.OK)
        reached[status] = reached.get(status, 0) + 1
    expected = {pk.OK, pk.LIMITS, pk.OFF_POSE, pk.JOINT_STEP}
    if ch.branch_form is not None:
        expected.add(pk.BRANCH)
    assert expected <= set(reached), reached


@pytest.mark.parametrize("robot_id", ["ur5", "panda", "kinova"])
def test_compiled_step_agrees_with_the_python_attempt(registry, robot_id: str) -> None:
    """Along random lines: the compiled step accepts exactly what the Python attempt and
    verify() accept, with the same configuration and errors, and its deviation at the
    middle is Pinocchio's against the path's pose there."""
    robot, ch, task, solver = _setup(registry, robot_id)
    frame = robot.model.frames[ch.frame_id].name
    opts = PathOptions(max_step=(0.01, 0.05), max_joint_step=0.1)
    agreed = refused = 0
    for line in random_lines(robot, frame, 6, seed=31, checks=4):
        path = CartesianPath.from_segments(line.start, [Line(line.end)])
        res = follow(robot, line.q0, path, IKOptions(frame=frame, tolerance=(TOL, TOL)), opts)
        lab = res.branch
        assert solver.prepare(line.q0, lab, opts.max_joint_step)
        targets, ss = path.sample_targets(opts.max_step)
        qs = [p.q for p in res.points]
        for j, q_prev in enumerate(qs[:-1]):
            s_prev = res.points[j].s
            for k in (1, 3):  # the next waypoint, and one three steps on (often refused)
                idx = min(int(np.searchsorted(ss, s_prev, side="right")) + k - 1, len(ss) - 1)
                T, s = targets[idx], float(ss[idx])
                middle = path.piece_at(0.5 * (s_prev + s))
                status, q, ep, er, _, dev_p, dev_r = solver.point(q_prev, T.R, T.p, middle)
                q_py, _ = solver.attempt(q_prev, T.se3)
                guard = Guard(
                    robot, ch, q_prev, 0.1, lab, lambda x: branch_label(robot, ch, x), None
                )
                ok = (
                    None
                    if q_py is None
                    else verify(robot, ch, task, (TOL, TOL), q_py, T.se3, guard)
                )
                assert (ok is not None) == (status == pk.OK)
                if ok is None:
                    refused += 1
                    continue
                agreed += 1
                np.testing.assert_array_equal(q, ok[0])
                assert ep == pytest.approx(ok[1], abs=1e-12)
                assert er == pytest.approx(ok[2], abs=1e-12)
                qm = q_prev + 0.5 * robot.difference(q_prev, q)
                Tm = path.pose_at(0.5 * (s_prev + s))
                want = residuals(frame_pose(robot, qm, ch.frame_id), Tm, task)
                assert dev_p == pytest.approx(want[0], abs=1e-12)
                assert dev_r == pytest.approx(want[1], abs=1e-12)
    assert agreed > 20 and refused > 0


def test_segment_pose_matches_pose_at() -> None:
    """The compiled pose of lines and arcs (turning and not) at random s, the ends too."""
    rng = np.random.default_rng(8)
    for trial in range(40):
        start = pin.SE3.Random()
        end = pin.SE3.Random() if trial % 2 else pin.SE3(start.rotation, rng.normal(size=3))
        via = pin.SE3.Random()
        segs = [Line(end)] if trial % 3 else [Arc(via, end), Line(pin.SE3.Random())]
        path = CartesianPath.from_segments(start, segs)
        for s in [0.0, 1.0, *rng.uniform(0.0, 1.0, 20), *path.ends.tolist()]:
            piece, u = path.piece_at(s)
            R, p = np.empty((3, 3)), np.empty(3)
            piece_pose(piece, u, R, p)
            T = path.pose_at(s)
            np.testing.assert_allclose(R, T.rotation, atol=1e-13)
            np.testing.assert_allclose(p, T.translation, atol=1e-13)
            target = path.target_at(s)
            np.testing.assert_array_equal(target.R, T.rotation)
            np.testing.assert_array_equal(target.p, T.translation)


def test_warm_up_compiles_the_signatures_the_solver_uses(registry) -> None:
    """warm_up() compiles step() for exactly the argument types LocalSolver passes (so a
    warmed process never compiles on a path request)."""
    pk.warm_up()
    robot, ch, _, solver = _setup(registry, "ur5")
    line = random_lines(robot, "tool0", 1, seed=3, checks=2)[0]
    assert solver.prepare(line.q0, branch_label(robot, ch, line.q0), 0.1)
    path = CartesianPath.from_segments(line.start, [Line(line.end)])
    T = path.target_at(0.5)
    piece, u = path.piece_at(0.25)
    args = (line.q0, solver.compiled, T.R, T.p, 3, piece, u, np.empty(robot.n), np.empty(5))
    warm = pk.warm_up_arguments()
    assert [numba.typeof(a) for a in args] == [numba.typeof(a) for a in warm]
    assert tuple(numba.typeof(a) for a in warm) in pk.step.signatures
