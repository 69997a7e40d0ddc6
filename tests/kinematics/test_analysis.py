"""Jacobian analysis core: closed forms (planar 2-link arm), NumPy SVD, invariants, statics."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.kinematics.analysis import (
    compute_manipulability,
    manipulability_batch,
    manipulability_of,
    task_rows,
    torques_from_wrench,
    wrench_from_torques,
)
from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel
from tests.kinematics.chains import L1, L2, planar2_urdf


@pytest.fixture(scope="module")
def planar() -> RobotModel:
    return RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")


@pytest.mark.parametrize("t1", [0.0, 0.4, -2.1])
@pytest.mark.parametrize("t2", [0.3, 1.2, -0.7, 2.9])
def test_planar_det_closed_form(planar, t1, t2):
    m = compute_manipulability(planar, np.array([t1, t2]), "tip", rows=["vx", "vy"])
    det = L1 * L2 * abs(math.sin(t2))
    assert m.rows == ["vx", "vy"] and m.joints == ["j1", "j2"]
    assert m.yoshikawa == pytest.approx(det, rel=1e-12, abs=1e-15)
    assert m.det_jjt == pytest.approx(det**2, rel=1e-11)
    assert not m.singular and m.rank == 2
    assert m.lost_directions.shape == (2, 0) and m.dependent_joints == []
    # closed-form Jacobian of the course
    s1, c1 = math.sin(t1), math.cos(t1)
    s12, c12 = math.sin(t1 + t2), math.cos(t1 + t2)
    Jc = np.array([[-L1 * s1 - L2 * s12, -L2 * s12], [L1 * c1 + L2 * c12, L2 * c12]])
    np.testing.assert_allclose(m.jacobian, Jc, atol=1e-14)
    np.testing.assert_allclose(m.singular_values, np.linalg.svd(Jc, compute_uv=False), rtol=1e-12)


@pytest.mark.parametrize("t2", [0.0, math.pi])
@pytest.mark.parametrize("t1", [0.0, 0.7, -2.5])
def test_planar_singular_lost_direction_along_arm(planar, t1, t2):
    m = compute_manipulability(planar, np.array([t1, t2]), "tip", rows=["vx", "vy"])
    assert m.singular and m.rank == 1
    assert m.yoshikawa == pytest.approx(0.0, abs=1e-14)
    assert m.condition_number is None
    assert m.force_half_lengths[1] is None and m.force_half_lengths[0] is not None
    assert m.lost_directions.shape == (2, 1)
    u = m.lost_directions[:, 0]
    along = np.array([math.cos(t1), math.sin(t1)])  # the arm lies along (c1, s1)
    assert abs(abs(u @ along) - 1.0) < 1e-12
    assert m.dependent_joints == ["j1", "j2"]
    # the null vector makes J_1·a + J_2·b = 0
    np.testing.assert_allclose(m.jacobian @ m.joint_null_space[:, 0], 0.0, atol=1e-14)


def test_planar_full_rows_is_not_singular_when_stretched(planar):
    """With all six rows the ωz row keeps the two columns independent: why rows matter."""
    m = compute_manipulability(planar, np.array([0.3, 0.0]), "tip")
    assert m.rank == 2 and not m.singular
    assert m.det_jjt == 0.0  # 6 rows, 2 joints
    assert m.lost_directions.shape == (6, 4)
    assert sum(h is None for h in m.force_half_lengths) == 4


def test_singular_values_match_numpy_svd(registry):
    robot = registry.get("panda")
    rng = np.random.default_rng(3)
    lo, hi = robot.lower, robot.upper
    for _ in range(5):
        q = rng.uniform(lo, hi)
        for part, rows in (("full", slice(0, 6)), ("translation", slice(0, 3))):
            m = compute_manipulability(robot, q, robot.ee_frame, part=part)
            J = frame_jacobian(robot, q, robot.ee_frame, "world")[rows][:, :7]
            s = np.linalg.svd(J, compute_uv=False)
            np.testing.assert_allclose(m.singular_values, s, rtol=1e-12)
            assert m.yoshikawa == pytest.approx(math.sqrt(np.linalg.det(J @ J.T)), rel=1e-9)
            assert m.joints == robot.joint_names[:7]  # the finger does not move the hand TCP
            # velocity ellipsoid: J Jᵀ u_i = σ_i² u_i
            A = J @ J.T
            for i, u in enumerate(m.axes.T):
                np.testing.assert_allclose(A @ u, m.velocity_half_lengths[i] ** 2 * u, atol=1e-12)
            for h, sv in zip(m.force_half_lengths, m.velocity_half_lengths, strict=True):
                assert h == pytest.approx(1.0 / sv, rel=1e-12)


def test_yoshikawa_invariant_under_world_frame_change():
    a = RobotModel("p_a", planar2_urdf(), ee_frame="tip")
    b = RobotModel(
        "p_b", planar2_urdf(base_xyz=(0.3, -1.2, 0.5), base_rpy=(0.4, -0.9, 2.2)), ee_frame="tip"
    )
    rng = np.random.default_rng(0)
    for _ in range(10):
        q = rng.uniform(-3, 3, size=2)
        for part in ("full", "translation", "rotation"):
            ma = compute_manipulability(a, q, "tip", part=part)
            mb = compute_manipulability(b, q, "tip", part=part)
            np.testing.assert_allclose(mb.singular_values, ma.singular_values, atol=1e-12)
            assert mb.yoshikawa == pytest.approx(ma.yoshikawa, abs=1e-12)
        # in the rotated base the planar task is the base's x-y plane: the local rows
        # (frame axes: z stays the joint axis) still give the closed form
        mb = compute_manipulability(b, q, "tip", rows=["vx", "vy"], reference="local")
        assert mb.yoshikawa == pytest.approx(L1 * L2 * abs(math.sin(q[1])), abs=1e-12)


def test_batch_matches_single(registry):
    robot = registry.get("ur5")
    rng = np.random.default_rng(1)
    qs = rng.uniform(-3, 3, size=(6, 6))
    qs[2, 4] = 0.0  # wrist singularity (q5 = 0)
    out = manipulability_batch(robot, qs, robot.ee_frame, part="full")
    for i, q in enumerate(qs):
        m = compute_manipulability(robot, q, robot.ee_frame)
        assert out["yoshikawa"][i] == pytest.approx(m.yoshikawa, rel=1e-10, abs=1e-14)
        assert out["min_singular_value"][i] == pytest.approx(m.min_singular_value, abs=1e-13)
        assert out["rank"][i] == m.rank and bool(out["singular"][i]) == m.singular
        assert out["condition_number"][i] == (
            None if m.condition_number is None else pytest.approx(m.condition_number)
        )
    assert out["singular"][2]


def test_statics_against_jacobian_transpose(registry):
    robot = registry.get("ur5")
    q = np.array([0.1, -1.0, 1.3, -0.4, 0.8, 0.2])
    F = np.array([3.0, -2.0, 10.0, 0.5, 0.1, -0.3])
    for ref in ("world", "local", "world_spatial"):
        J = frame_jacobian(robot, q, robot.ee_frame, ref)
        st = torques_from_wrench(robot, q, robot.ee_frame, F, ref)
        np.testing.assert_allclose(st.torques, J.T @ F, atol=1e-12)
        back = wrench_from_torques(robot, q, robot.ee_frame, st.torques, ref)
        np.testing.assert_allclose(back.wrench, F, atol=1e-9)
        assert back.residual_norm < 1e-9 and back.rank == 6


def test_statics_virtual_work_by_finite_differences(planar):
    """τ·δq = F·δx: torques from a force at the tip match the work along a small motion."""
    q = np.array([0.5, 1.1])
    f = np.array([2.0, -1.0, 0.0, 0.0, 0.0, 0.0])
    tau = torques_from_wrench(planar, q, "tip", f, "world").torques

    def tip(qq):
        return np.array(
            [L1 * math.cos(qq[0]) + L2 * math.cos(qq[0] + qq[1]),
             L1 * math.sin(qq[0]) + L2 * math.sin(qq[0] + qq[1])]
        )  # fmt: skip

    h = 1e-6
    for j in range(2):
        dq = np.zeros(2)
        dq[j] = h
        work = f[:2] @ (tip(q + dq) - tip(q - dq)) / (2 * h)
        assert tau[j] == pytest.approx(work, rel=1e-8)


def test_inverse_statics_least_squares_residual(planar):
    q = np.array([0.3, 0.9])
    tau = np.array([1.0, -2.0])
    st = wrench_from_torques(planar, q, "tip", tau, "world")
    J = frame_jacobian(planar, q, "tip", "world")
    expected = np.linalg.lstsq(J.T, tau, rcond=None)[0]  # minimum-norm solution
    np.testing.assert_allclose(st.wrench, expected, atol=1e-12)
    np.testing.assert_allclose(st.residual, tau - J.T @ expected, atol=1e-12)


def test_task_rows_parsing_and_errors():
    assert task_rows("translation").tolist() == [0, 1, 2]
    assert task_rows(None, ["vx", "ωz", 1]).tolist() == [0, 5, 1]
    with pytest.raises(InvalidInputError) as e:
        task_rows("full", ["vx"])
    assert e.value.field == "rows"
    for bad, field in ((["vx", "vx"], "rows.1"), (["vq"], "rows.0"), ([7], "rows.0"), ([], "rows")):
        with pytest.raises(InvalidInputError) as e:
            task_rows(None, bad)
        assert e.value.field == field


def test_frame_errors(planar):
    with pytest.raises(UnknownNameError):
        compute_manipulability(planar, np.zeros(2), "nope")
    with pytest.raises(InvalidInputError) as e:
        compute_manipulability(planar, np.zeros(2), "base")
    assert e.value.field == "frame"


def test_zero_jacobian_rows():
    """A prismatic-only chain cannot rotate: rotation rows are all zero, rank 0, singular."""
    m = manipulability_of(np.zeros((3, 2)))
    assert m.rank == 0 and m.singular and m.yoshikawa == 0.0 and m.inverse_condition == 0.0
    assert all(h is None for h in m.force_half_lengths)
