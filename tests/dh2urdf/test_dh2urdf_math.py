"""dh2urdf.math: closed-form DH matrices, rpy conversion and the chain."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dh2urdf.math import (
    chain,
    dh_modified,
    dh_standard,
    joint_dh_parameters,
    rotation_to_rpy,
    rpy_to_rotation,
    tool_pose,
    xyz_rpy_to_matrix,
)
from dh2urdf.table import DHTable

from .helpers import origin, reference_chain, rx, ry, rz, tr

finite = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
angle = st.floats(-7.0, 7.0, allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(a=finite, alpha=angle, d=finite, theta=angle)
def test_dh_standard_is_rz_tz_tx_rx(a: float, alpha: float, d: float, theta: float) -> None:
    expected = rz(theta) @ tr(z=d) @ tr(x=a) @ rx(alpha)
    np.testing.assert_allclose(dh_standard(a, alpha, d, theta), expected, rtol=0, atol=1e-13)


@settings(max_examples=200, deadline=None)
@given(a=finite, alpha=angle, d=finite, theta=angle)
def test_dh_modified_is_rx_tx_rz_tz(a: float, alpha: float, d: float, theta: float) -> None:
    expected = rx(alpha) @ tr(x=a) @ rz(theta) @ tr(z=d)
    np.testing.assert_allclose(dh_modified(a, alpha, d, theta), expected, rtol=0, atol=1e-13)


def test_course_matrix_entries() -> None:
    """The course's A_{i-1,i} written out entry by entry."""
    a, alpha, d, theta = 0.3, 0.7, -0.2, 1.1
    ct, st_, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    expected = np.array(
        [
            [ct, -st_ * ca, st_ * sa, a * ct],
            [st_, ct * ca, -ct * sa, a * st_],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    )
    np.testing.assert_array_equal(dh_standard(a, alpha, d, theta), expected)


@settings(max_examples=300, deadline=None)
@given(roll=angle, pitch=angle, yaw=angle)
def test_rpy_round_trip(roll: float, pitch: float, yaw: float) -> None:
    r = (rz(yaw) @ ry(pitch) @ rx(roll))[:3, :3]
    rpy = rotation_to_rpy(r)
    assert -math.pi / 2 <= rpy[1] <= math.pi / 2
    np.testing.assert_allclose(rpy_to_rotation(rpy), r, rtol=0, atol=1e-14)


@pytest.mark.parametrize("pitch", [math.pi / 2, -math.pi / 2])
@pytest.mark.parametrize("offset", [0.0, 1e-15, -1e-12, 1e-9, -1e-6, 1e-4])
@pytest.mark.parametrize("roll,yaw", [(0.3, -1.2), (2.9, 3.1), (-3.0, 0.0), (1.0, 1.0)])
def test_rpy_near_gimbal_lock(pitch: float, offset: float, roll: float, yaw: float) -> None:
    """Reconstruction stays at round-off level at and near pitch = ±π/2."""
    r = (rz(yaw) @ ry(pitch + offset) @ rx(roll))[:3, :3]
    np.testing.assert_allclose(rpy_to_rotation(rotation_to_rpy(r)), r, rtol=0, atol=1e-14)


def test_rpy_of_dh_style_rotations_is_exact() -> None:
    """Rx(α)·Rz(θ) with right angles (the modified-DH origins) reconstruct to round-off."""
    for alpha in (0.0, math.pi / 2, -math.pi / 2, math.pi):
        for theta in (0.0, math.pi / 2, -math.pi / 2, math.pi, 0.3):
            r = (rx(alpha) @ rz(theta))[:3, :3]
            np.testing.assert_allclose(rpy_to_rotation(rotation_to_rpy(r)), r, atol=1e-15)


def test_xyz_rpy_to_matrix_matches_urdf_origin() -> None:
    xyz, rpy = (0.1, -0.2, 0.3), (0.4, -1.1, 2.5)
    np.testing.assert_allclose(xyz_rpy_to_matrix(xyz, rpy), origin(xyz, rpy), atol=1e-15)


def _table() -> tuple[DHTable, dict]:
    doc = {
        "name": "t",
        "convention": "standard",
        "units": {"length": "mm", "angle": "deg"},
        "base": {"xyz": [10, 20, 30], "rpy": [5, 10, 15]},
        "tool": {"xyz": [0, 0, 50], "rpy": [0, 90, 0]},
        "joints": [
            {"a": 100, "alpha": 90, "d": 10, "theta": 30},
            {
                "type": "prismatic",
                "a": 0,
                "alpha": -90,
                "d": 40,
                "theta": -90,
                "lower": 0,
                "upper": 200,
            },
        ],
    }
    return DHTable.from_dict(doc), doc


def test_chain_frames_base_and_tool() -> None:
    table, doc = _table()
    q = [0.4, 0.05]
    frames = chain(table, q)
    assert len(frames) == table.dof + 2
    np.testing.assert_allclose(frames[0], table.base.matrix(), atol=1e-15)
    np.testing.assert_allclose(frames[-1], frames[-2] @ table.tool.matrix(), atol=1e-15)
    np.testing.assert_allclose(tool_pose(table, q), frames[-1], atol=0)
    for got, expected in zip(frames, reference_chain(doc, q), strict=True):
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-14)


def test_chain_rejects_wrong_length() -> None:
    table, _ = _table()
    with pytest.raises(ValueError, match="expected 2 joint values"):
        chain(table, [0.0])


def test_joint_variable_goes_into_theta_or_d() -> None:
    table, _ = _table()
    revolute, prismatic = table.joints
    assert joint_dh_parameters(revolute, 0.5) == (
        revolute.a,
        revolute.alpha,
        revolute.d,
        0.5 + revolute.theta,
    )
    assert joint_dh_parameters(prismatic, 0.1) == (
        prismatic.a,
        prismatic.alpha,
        0.1 + prismatic.d,
        prismatic.theta,
    )
