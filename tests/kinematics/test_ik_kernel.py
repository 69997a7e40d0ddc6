"""The compiled IK loop (app.kinematics.ik.kernel) against independent references: its
kinematics against Pinocchio, its rotation log against Pinocchio's and exp3, its table
distances against NumPy, and the solver's answers on both loops against yourdfpy."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik, jit
from app.kinematics.analytic_ik import planar2, ur
from app.kinematics.fk import forward_kinematics
from app.kinematics.ik import kernel as ik_kernel
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel
from tests.kinematics.chains import continuous_arm, rrp_like
from tests.kinematics.reference import TOL, pose_error, random_q, reference_pose, se3

#: The same solver on the Python loop only.
PYTHON_LOOP = replace(DEFAULT_PARAMETERS, compiled=False)


def test_numba_is_used() -> None:
    assert jit.available()


@pytest.mark.parametrize(
    ("robot_id", "frame"),
    [("panda", "panda_link8"), ("ur5", "tool0"), ("kinova", None), ("stanford_arm", None),
     ("rrp", None), ("armar1_arm", "dh_4"), ("panda_dh", "tool")],
)  # fmt: skip
def test_pose_and_jacobian_match_pinocchio(registry, robot_id: str, frame: str | None) -> None:
    """Revolute, prismatic, offsets, mm/deg DH tables: pose and world Jacobian to 1e-12."""
    robot = registry.get(robot_id)
    frame = frame or robot.ee_frame
    ch = ik_chain(robot, frame)
    assert ch.compiled is not None
    rng = np.random.default_rng(3)
    for _ in range(20):
        q = random_q(robot, rng)
        R, p, J = ch.compiled.pose(q[ch.active])
        T = forward_kinematics(robot, q, [frame])[frame]
        np.testing.assert_allclose(R, T[:3, :3], rtol=0, atol=1e-12)
        np.testing.assert_allclose(p, T[:3, 3], rtol=0, atol=1e-12)
        Jp = frame_jacobian(robot, q, frame, "world")[:, ch.active]
        np.testing.assert_allclose(J, Jp, rtol=0, atol=1e-12)


def test_hand_written_chains_with_prismatic_and_continuous_joints() -> None:
    for urdf, frame in ((rrp_like(), "tip"), (continuous_arm(), None)):
        robot = RobotModel("chain", urdf)
        frame = frame or robot.ee_frame
        ch = ik_chain(robot, frame)
        assert ch.compiled is not None
        for q in np.random.default_rng(5).uniform(-3.0, 3.0, (10, robot.n)):
            q = np.clip(q, robot.lower, robot.upper)
            R, p, J = ch.compiled.pose(q[ch.active])
            T = forward_kinematics(robot, q, [frame])[frame]
            np.testing.assert_allclose(R, T[:3, :3], atol=1e-12)
            np.testing.assert_allclose(p, T[:3, 3], atol=1e-12)
            np.testing.assert_allclose(J, frame_jacobian(robot, q, frame)[:, ch.active], atol=1e-12)


def test_mimic_chains_take_the_python_loop(registry) -> None:
    """panda_rightfinger moves with a mimic joint: not a plain serial chain."""
    robot = registry.get("panda")
    assert ik_chain(robot, "panda_rightfinger").compiled is None
    q = robot.mid_range()
    q[7] = 0.02
    T = forward_kinematics(robot, q, ["panda_rightfinger"])["panda_rightfinger"]
    res = ik.solve(robot, se3(T), IKOptions(frame="panda_rightfinger", timeout_ms=500))
    assert res.success


@pytest.mark.parametrize("angle", [0.0, 1e-12, 1e-6, 1e-4, 0.3, 2.0, math.pi - 1e-3,
                                   math.pi - 1e-7, math.pi])  # fmt: skip
def test_log3_against_pinocchio_and_exp3(angle: float) -> None:
    rng = np.random.default_rng(int(angle * 1e6) % 1000)
    for _ in range(20):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        R = pin.exp3(axis * angle)
        phi = ik_kernel.log3(R)
        assert np.linalg.norm(phi) == pytest.approx(angle, abs=1e-12)
        np.testing.assert_allclose(pin.exp3(phi), R, atol=1e-12)
        if angle < math.pi - 1e-3:  # at π both ±axis are the rotation vector
            np.testing.assert_allclose(phi, pin.log3(R), atol=1e-12)


def test_table_distances_match_numpy(registry) -> None:
    robot = registry.get("panda")
    ch = ik_chain(robot, "panda_link8")
    M, W2, _ = ch.poses
    rng = np.random.default_rng(9)
    for _ in range(10):
        target = pin.SE3(pin.exp3(rng.normal(size=3)), rng.uniform(-0.5, 0.5, 3))
        d, k_t, i = ch.sample_distances_argmin(target)
        x = np.concatenate((target.translation, target.rotation.ravel()))
        exact = M.astype(float) @ x + W2 + k_t  # ‖p − p_t‖² + c‖R − R_t‖²_F per sample
        np.testing.assert_allclose(d + k_t, exact, rtol=0, atol=1e-4)
        assert exact[i] <= exact.min() + 1e-4


@pytest.mark.parametrize("robot_id", ["panda", "kinova"])
def test_both_loops_solve_and_agree_with_yourdfpy(registry, robot_id: str) -> None:
    """The compiled and the Python loop on the same targets: every answer reaches its
    target by yourdfpy's FK and stays within the limits."""
    robot = registry.get(robot_id)
    frame = robot.ee_frame
    assert ik_chain(robot, frame).compiled is not None
    assert ik_chain(robot, frame, parameters=PYTHON_LOOP).compiled is None
    rng = np.random.default_rng(21)
    for _ in range(25):
        q_true = random_q(robot, rng)
        target = reference_pose(robot, q_true, frame)
        for parameters in (DEFAULT_PARAMETERS, PYTHON_LOOP):
            options = IKOptions(frame=frame, timeout_ms=500, analytic=False)
            res = ik.solve(robot, se3(target), options, parameters=parameters)
            assert res.success, parameters
            assert np.all(res.q >= robot.lower) and np.all(res.q <= robot.upper)
            dp, dr = pose_error(reference_pose(robot, res.q, frame), target)
            assert dp <= TOL and dr <= TOL


@pytest.mark.parametrize(("robot_id", "frame"), [("panda", "panda_link8"), ("puma560", None)])
def test_compiled_and_python_loops_take_the_same_iterates(registry, robot_id, frame) -> None:
    """The compiled driver repeats the Python loop step for step: from the same seeds, the
    same iteration and restart counts and the same answers (to rounding), reachable or not."""
    compiled = registry.get(robot_id)
    frame = frame or compiled.ee_frame
    options = IKOptions(frame=frame, timeout_ms=60_000, max_iterations=150, analytic=False)
    rng = np.random.default_rng(8)
    for k in range(12):
        target = se3(reference_pose(compiled, random_q(compiled, rng), frame))
        if k % 4 == 3:  # out of reach: the cap ends both searches
            target.translation = target.translation * 3.0
        seed = random_q(compiled, rng)
        a = ik.solve(compiled, target, options, seed=seed)
        b = ik.solve(compiled, target, options, seed=seed, parameters=PYTHON_LOOP)
        assert (a.success, a.iterations, a.restarts) == (b.success, b.iterations, b.restarts)
        np.testing.assert_allclose(a.q, b.q, rtol=0, atol=1e-8)


def test_iteration_cap_and_best_effort_on_the_compiled_loop(registry) -> None:
    """An unreachable target: the cap ends the search, the best iterate is reported with
    its true error (Pinocchio FK), inside the limits."""
    robot = registry.get("panda")
    target = pin.SE3(np.eye(3), np.array([2.0, 0.0, 0.5]))  # Panda reaches ~0.86 m
    res = ik.solve(
        robot, target, IKOptions(frame="panda_link8", timeout_ms=2000, max_iterations=60)
    )
    assert not res.success and res.status == "not_converged" and res.iterations == 60
    assert np.all(res.q >= robot.lower) and np.all(res.q <= robot.upper)
    T = forward_kinematics(robot, res.q, ["panda_link8"])["panda_link8"]
    assert res.position_error == pytest.approx(np.linalg.norm(T[:3, 3] - [2.0, 0.0, 0.5]))
    assert 1.0 < res.position_error < 1.3  # stretched towards the target


@pytest.mark.parametrize(("robot_id", "frame"), [("ur5", "tool0"), ("ur10", "tool0"),
                                                 ("ur5_dh", "tool")])  # fmt: skip
def test_compiled_ur_closed_form_equals_the_python_one(registry, robot_id, frame) -> None:
    """Same branches, same order, same shifts into the limits as ur_solutions + into_limits
    (whose answers test_ik checks against yourdfpy)."""
    robot = registry.get(robot_id)
    ch = ik_chain(robot, frame)
    geo = ch.closed_form[0]
    assert geo is not None
    lo, hi = robot.lower[ch.active], robot.upper[ch.active]
    rng = np.random.default_rng(17)
    counts = set()
    for _ in range(200):
        target = se3(reference_pose(robot, random_q(robot, rng), frame))
        seed = rng.uniform(-3.0, 3.0, 6)
        expected = [
            [planar2.into_limits(float(x), lo[i], hi[i], seed[i]) for i, x in enumerate(q)]
            for q in ur.ur_solutions(geo, target, seed)
        ]
        got = ur.ur_candidates_compiled(geo, target, seed, lo, hi)
        assert got.shape == (len(expected), 6)
        if expected:
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9)
        counts.add(len(expected))
    assert 8 in counts


def test_jit_without_a_writable_cache_still_compiles(monkeypatch) -> None:
    """Numba refuses cache=True when it finds no writable cache location: compile anyway."""
    real = jit.numba.njit

    def njit(**kw):
        if kw.get("cache"):
            raise RuntimeError("cannot cache function 'f': no locator available for file 'x'")
        return real(**kw)

    monkeypatch.setattr(jit.numba, "njit", njit)

    def add_one(x):
        return x + 1.0

    compiled = jit.jit(add_one)
    assert compiled(1.0) == 2.0 and compiled.signatures  # a Numba dispatcher, compiled


@pytest.mark.parametrize("case", ["random", "ties", "equal", "nan", "short"])
def test_nearest_and_ranking_match_a_stable_sort(case: str) -> None:
    """The compiled argmin of the table distances and the ranking of the nearest samples:
    NumPy's first minimum and stable sort (ties by index), with ties, a NaN entry past the
    first ``count`` (never ranked: no comparison with it holds) and a table shorter than
    the ranking."""
    from app.kinematics.ik import search_kernel

    rng = np.random.default_rng(4)
    n = 40 if case == "short" else 4096
    d = rng.random(n).astype(np.float32)
    if case == "ties":
        d = np.round(d * 60.0).astype(np.float32)
    if case == "equal":
        d[:] = 0.5
    if case == "nan":
        d[1000] = np.nan
    near = np.empty(64, dtype=np.int64)
    count = search_kernel._rank_nearest(d, near, 64)
    order = np.argsort(np.where(np.isnan(d), np.inf, d), kind="stable")
    assert count == min(n, 64)
    np.testing.assert_array_equal(near[:count], order[:count])
    MT = rng.random((12, n)).astype(np.float32)
    x = np.zeros(12, dtype=np.float32)
    x[3] = -1.0  # d = W2 − MT[3]: ties in W2 stay ties when MT[3] is constant
    if case in ("ties", "equal"):
        MT[3] = 0.5
    out = np.empty(n, dtype=np.float32)
    best = ik_kernel.sample_distances(MT, d, x, out)
    np.testing.assert_array_equal(out, d + MT[0] * x[0] + MT[1] * x[1] + MT[2] * x[2] - MT[3])
    assert best == int(np.argmin(np.where(np.isnan(out), np.inf, out)))
