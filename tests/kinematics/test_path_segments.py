"""The Cartesian path (app.kinematics.paths.segments) against hand-worked poses: the path
parameter s, lines, arcs (circle and two-part slerp), sampling bounds and exact ends, and
the fields named by bad paths."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.errors import InvalidInputError
from app.kinematics.paths.segments import (
    MAX_POINTS,
    ROTATION_LENGTH,
    Arc,
    CartesianPath,
    Line,
)


def rz(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rx(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def pose(R: np.ndarray, p: list[float]) -> pin.SE3:
    return pin.SE3(R, np.array(p, dtype=float))


def angle_between(A: np.ndarray, B: np.ndarray) -> float:
    """Rotation angle of AᵀB from its trace and skew part (independent of pin.log3)."""
    R = A.T @ B
    s = 0.5 * math.hypot(R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1])
    return math.atan2(s, (np.trace(R) - 1.0) / 2.0)


def test_line_midpoint_and_slerp_angle_proportional() -> None:
    start = pose(np.eye(3), [0.1, 0.2, 0.3])
    end = pose(rz(0.8), [0.5, -0.2, 0.7])
    path = CartesianPath.from_segments(start, [Line(end)])
    for s in (0.0, 0.25, 0.5, 0.9, 1.0):
        T = path.pose_at(s)
        np.testing.assert_allclose(
            T.translation, np.array([0.1, 0.2, 0.3]) + s * np.array([0.4, -0.4, 0.4]), atol=1e-15
        )
        np.testing.assert_allclose(T.rotation, rz(0.8 * s), atol=1e-15)


def test_quarter_circle_arc_through_a_known_via() -> None:
    """Unit circle about the origin from (1, 0, 0) via (cos 60°, sin 60°, 0) to (0, 1, 0):
    position at angle s·π/2; orientation Rz(0.3) at the via (u = 2/3), two slerp parts."""
    start = pose(np.eye(3), [1.0, 0.0, 0.0])
    via = pose(rz(0.3), [0.5, math.sqrt(3) / 2, 0.0])
    end = pose(rz(1.2), [0.0, 1.0, 0.0])
    path = CartesianPath.from_segments(start, [Arc(via, end)])
    # Length √((π/2)² + (ρ·(0.3 + 0.9))²): one segment, so s = u.
    assert path.length == pytest.approx(math.hypot(math.pi / 2, ROTATION_LENGTH * 1.2))
    for s in (0.1, 0.5, 2 / 3, 0.8, 1.0):
        T = path.pose_at(s)
        a = s * math.pi / 2
        np.testing.assert_allclose(T.translation, [math.cos(a), math.sin(a), 0.0], atol=1e-14)
        expected = 0.3 * s / (2 / 3) if s <= 2 / 3 else 0.3 + 0.9 * (s - 2 / 3) / (1 / 3)
        np.testing.assert_allclose(T.rotation, rz(expected), atol=1e-14)


def test_arc_in_a_tilted_plane_goes_the_way_of_its_via() -> None:
    """Circle of radius 0.2 about c in the plane x = 0.4 rotated about x by 0.7; the via is
    on the far side (start → via → end is 270° round the circle, not the short 90°)."""
    c = np.array([0.4, 0.1, 0.5])
    R = rx(0.7)

    def on(a: float) -> list[float]:
        return list(c + R @ np.array([0.0, 0.2 * math.cos(a), 0.2 * math.sin(a)]))

    start, via, end = (
        pose(np.eye(3), on(0.0)),
        pose(np.eye(3), on(math.pi)),
        pose(np.eye(3), on(-math.pi / 2)),
    )
    path = CartesianPath.from_segments(start, [Arc(via, end)])
    assert path.length == pytest.approx(0.2 * 1.5 * math.pi)
    for s in (0.2, 0.5, 0.7):
        np.testing.assert_allclose(path.pose_at(s).translation, on(1.5 * math.pi * s), atol=1e-14)


def test_s_is_proportional_to_the_combined_length() -> None:
    """Two lines: 0.3 m, then 0.1 m with a 0.4 rad turn (length √(0.1² + (ρ·0.4)²))."""
    start = pose(np.eye(3), [0.0, 0.0, 0.0])
    a = pose(np.eye(3), [0.3, 0.0, 0.0])
    b = pose(rz(0.4), [0.3, 0.1, 0.0])
    path = CartesianPath.from_waypoints(start, [a, b])
    l2 = math.hypot(0.1, ROTATION_LENGTH * 0.4)
    s_a = 0.3 / (0.3 + l2)
    assert path.ends == pytest.approx([s_a, 1.0])
    np.testing.assert_allclose(path.pose_at(s_a / 2).translation, [0.15, 0.0, 0.0], atol=1e-15)
    T = path.pose_at(s_a + 0.5 * (1 - s_a))
    np.testing.assert_allclose(T.translation, [0.3, 0.05, 0.0], atol=1e-15)
    np.testing.assert_allclose(T.rotation, rz(0.2), atol=1e-15)


def _check_sample(path: CartesianPath, segment_ends: list[pin.SE3], step: tuple) -> None:
    poses, s = path.sample(step)
    assert len(poses) == len(s)
    assert s[0] == 0.0 and s[-1] == 1.0
    assert np.all(np.diff(s) > 0.0)
    for a, b in zip(poses, poses[1:], strict=False):
        assert np.linalg.norm(b.translation - a.translation) <= step[0] * (1 + 1e-9)
        assert angle_between(a.rotation, b.rotation) <= step[1] * (1 + 1e-9)
    for T in segment_ends:  # every segment's end is a sample, exactly
        assert any(
            np.array_equal(T.translation, P.translation) and np.array_equal(T.rotation, P.rotation)
            for P in poses
        )
    for P, si in zip(poses, s, strict=True):  # pose_at(s) agrees with the sample
        Q = path.pose_at(si)
        np.testing.assert_allclose(Q.translation, P.translation, atol=1e-12)
        np.testing.assert_allclose(Q.rotation, P.rotation, atol=1e-12)


@pytest.mark.parametrize("step", [(0.01, 0.05), (0.05, 0.01), (0.3, 2.0)])
def test_sample_bounds_steps_and_keeps_ends_exact(step: tuple[float, float]) -> None:
    start = pose(np.eye(3), [0.3, 0.0, 0.4])
    ends = [
        pose(rz(0.5), [0.5, 0.1, 0.4]),
        pose(rz(0.5) @ rx(0.4), [0.5, 0.1, 0.4]),  # rotation in place
        pose(rz(0.5) @ rx(0.4), [0.5, 0.1, 0.4]),  # zero length: adds nothing
        pose(rz(-0.3), [0.2, 0.3, 0.6]),
    ]
    via = pose(rz(2.0), [0.35, 0.25, 0.5])
    path = CartesianPath.from_segments(
        start, [Line(ends[0]), Line(ends[1]), Line(ends[2]), Arc(via, ends[3])]
    )
    _check_sample(path, ends, step)
    poses, _ = path.sample(step)
    dup = sum(
        np.array_equal(P.translation, ends[1].translation)
        and np.array_equal(P.rotation, ends[1].rotation)
        for P in poses
    )
    assert dup == 1
    assert path.count(step) == len(poses)  # the route's budget check counts without sampling


def test_a_path_of_zero_length_is_its_start() -> None:
    start = pose(rz(0.2), [0.1, 0.2, 0.3])
    path = CartesianPath.from_waypoints(start, [start, start])
    poses, s = path.sample((0.01, 0.01))
    assert len(poses) == 1 and s.tolist() == [0.0]
    np.testing.assert_array_equal(path.pose_at(0.7).translation, start.translation)


@pytest.mark.parametrize(
    ("via", "field"),
    [
        ([0.25, 0.0, 0.0], "segments.1.via"),  # on the line start–end
        ([0.1, 0.0, 0.0], "segments.1.via"),  # coincides with the start
        ([0.5, 0.0, 0.0], "segments.1.via"),  # coincides with the end
    ],
)
def test_degenerate_arcs_name_the_via(via: list[float], field: str) -> None:
    start = pose(np.eye(3), [0.0, 0.0, 0.0])
    a = pose(np.eye(3), [0.1, 0.0, 0.0])
    with pytest.raises(InvalidInputError) as err:
        CartesianPath.from_segments(
            start, [Line(a), Arc(pose(np.eye(3), via), pose(np.eye(3), [0.5, 0.0, 0.0]))]
        )
    assert err.value.field == field


def test_bad_paths_and_steps_name_the_field() -> None:
    start = pose(np.eye(3), [0.0, 0.0, 0.0])
    with pytest.raises(InvalidInputError) as err:
        CartesianPath.from_segments(start, [])
    assert err.value.field == "segments"
    with pytest.raises(InvalidInputError) as err:
        CartesianPath.from_waypoints(start, [])
    assert err.value.field == "waypoints"
    path = CartesianPath.from_segments(start, [Line(pose(np.eye(3), [1.0, 0.0, 0.0]))])
    for step, field in [
        ((0.0, 0.1), "max_step.position"),
        ((math.nan, 0.1), "max_step.position"),
        ((0.1, -1.0), "max_step.orientation"),
        ((0.1, math.inf), "max_step.orientation"),
        ((1.0 / MAX_POINTS, 0.1), "max_step"),  # one point too many
        ((1e-300, 0.1), "max_step"),
    ]:
        with pytest.raises(InvalidInputError) as err:
            path.sample(step)
        assert err.value.field == field, step
    assert len(path.sample((1.0 / (MAX_POINTS - 1), 0.1))[0]) == MAX_POINTS
