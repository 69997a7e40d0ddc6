"""The compiled branch label and manipulability of an answer (:mod:`app.kinematics.ik.annotate`)
against the Python/Pinocchio references: :func:`~app.kinematics.ik.branches.branch_label`
(Pinocchio's joint Jacobians) and :func:`~app.kinematics.ik.ranking.manipulability`
(Pinocchio's frame Jacobian, √det(J Jᵀ) by LAPACK), on random configurations of catalog
robots of every branch form (UR type, spherical wrist, prismatic elbow, planar 2-link,
redundant), and through :func:`app.kinematics.ik.solve` with ``annotate=True``."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik
from app.kinematics.ik.annotate import annotate, yoshikawa
from app.kinematics.ik.branches import branch_label
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.ik.problem import IKOptions
from app.kinematics.ik.ranking import manipulability

#: (robot, whether it has branch flags): UR type (URDF and DH), spherical wrist, prismatic
#: joint 3 (no elbow flag), planar 2-link, redundant 7-DoF.
ROBOTS = [
    ("ur5", True),
    ("ur5_dh", True),
    ("puma560", True),
    ("stanford_arm", True),
    ("planar2", True),
    ("panda", False),
]
SAMPLES = 300


def _configurations(robot, ch, n: int, seed: int) -> np.ndarray:
    """n wire configurations uniform within the chain's sampling box (others mid-range)."""
    rng = np.random.default_rng(seed)
    q = np.tile(robot.mid_range(), (n, 1))
    q[:, ch.active] = rng.uniform(ch.sample_lo, ch.sample_hi, (n, ch.k))
    return q


@pytest.mark.parametrize(("robot_id", "labelled"), ROBOTS)
def test_compiled_annotation_matches_pinocchio(registry, robot_id: str, labelled: bool) -> None:
    robot = registry.get(robot_id)
    ch = ik_chain(robot, robot.ee_frame)
    assert ch.annotation is not None and ch.annotation.labelled is labelled
    labels = set()
    for q in _configurations(robot, ch, SAMPLES, seed=17):
        label, w = annotate(ch, q[ch.active])
        assert label == branch_label(robot, ch, q)
        labels.add(label)
        ref = manipulability(robot, ch, q)
        assert w == pytest.approx(ref, rel=1e-9, abs=1e-12)
    if labelled:  # the samples cover several branches (a constant label would pass too)
        assert len(labels) >= 2


def test_yoshikawa_matches_the_singular_values() -> None:
    """√det of the smaller Gram matrix = ∏σ_i, for wide, tall and rank-deficient matrices."""
    rng = np.random.default_rng(7)
    for shape in [(6, 7), (6, 6), (6, 2), (3, 5)]:
        for _ in range(50):
            J = rng.normal(size=shape)
            assert yoshikawa(J) == pytest.approx(np.prod(np.linalg.svd(J, compute_uv=False)))
    J = rng.normal(size=(6, 7))
    J[:, 3] = J[:, 1]
    J[:, 5] = 2 * J[:, 1]  # rank 5
    assert yoshikawa(J) < 1e-6


@pytest.mark.parametrize("robot_id", ["ur5", "panda", "puma560"])
def test_served_answers_carry_the_reference_labels(registry, robot_id: str) -> None:
    """One solution wanted with ``annotate`` (the HTTP answer): the compiled path's branch
    and manipulability are Pinocchio's at the answered configuration."""
    robot = registry.get(robot_id)
    ch = ik_chain(robot, robot.ee_frame)
    model, data = robot.model, robot.data
    for q in _configurations(robot, ch, 20, seed=2017):
        pin.forwardKinematics(model, data, robot.to_pin(q))
        target = pin.updateFramePlacement(model, data, ch.frame_id).copy()
        res = ik.solve(robot, target, IKOptions(timeout_ms=1000.0), annotate=True)
        assert res.success
        (s,) = res.solutions
        ref = branch_label(robot, ch, s.q)
        assert s.branch == (ref if ref is not None else "cluster_0")
        assert s.manipulability == pytest.approx(manipulability(robot, ch, s.q), rel=1e-9)
