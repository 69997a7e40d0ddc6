"""The solver's mixed-unit thresholds at any size of arm (app.kinematics.ik.scale).

The invariant is kinematics' own: an arm whose every length is s times another's places
its frame at s·p for the same joint angles (prismatic values × s). So the same arm at
×10 (a 10 m chain) and ×0.05 (a few centimetres) must get the same verdicts as at ×1:
which solutions are distinct (``SolverParameters.distinct``), which configurations are
singular (``SINGULAR_SIGMA``), and, beyond the band where the built-in robots keep
``SolverParameters.rot_weight``, the same restart ranking. References: the planar 2R
Jacobian written out, and the scaled copy of each arm built here from its URDF text.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.ik.failure import classify
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS
from app.kinematics.ik.precompute import ik_chain, k_smallest
from app.kinematics.ik.problem import IKOptions, IKProblem
from app.kinematics.ik.scale import RANKING_BAND, length_scale, rotation_weight
from app.kinematics.ik.search import Search
from app.kinematics.models import RobotModel
from app.kinematics.paths.failures import SINGULAR_SIGMA, smallest_singular_value
from app.robots.registry import Registry
from tests.kinematics.chains import planar_2link

SCALES = (1.0, 10.0, 0.05)


def scaled(urdf: str, s: float) -> str:
    """The URDF with every length times ``s``: joint and frame origins, prismatic limits
    (visual, collision and inertial elements dropped: kinematics only)."""
    root = ET.fromstring(urdf)
    for parent in list(root.iter()):
        for child in list(parent):
            if child.tag in ("visual", "collision", "inertial"):
                parent.remove(child)
    for origin in root.iter("origin"):
        if origin.get("xyz"):
            origin.set("xyz", " ".join(repr(float(v) * s) for v in origin.get("xyz").split()))
    for joint in root.iter("joint"):
        limit = joint.find("limit")
        if joint.get("type") == "prismatic" and limit is not None:
            for key in ("lower", "upper"):
                limit.set(key, repr(float(limit.get(key)) * s))
    return ET.tostring(root, encoding="unicode")


def slide_pair() -> str:
    """Two prismatic joints along x in series, 0.1 m offsets before each and to the tip:
    in position mode along x, every (d1, d2) with d1 + d2 fixed reaches the same point.
    Chain length 0.1 + 0.1 + 0.5 + 0.5 = 1.2 m."""
    limit = '<limit lower="0" upper="0.5" velocity="1" effort="1"/>'
    return f"""<?xml version="1.0"?>
<robot name="slides">
  <link name="base"/><link name="s1"/><link name="s2"/><link name="tip"/>
  <joint name="d1" type="prismatic"><parent link="base"/><child link="s1"/>
    <origin xyz="0 0 0"/><axis xyz="1 0 0"/>{limit}</joint>
  <joint name="d2" type="prismatic"><parent link="s1"/><child link="s2"/>
    <origin xyz="0.1 0 0"/><axis xyz="1 0 0"/>{limit}</joint>
  <joint name="tip_joint" type="fixed"><parent link="s2"/><child link="tip"/>
    <origin xyz="0.1 0 0"/></joint>
</robot>"""


def test_length_scale_is_the_chain_length() -> None:
    for s in SCALES:
        robot = RobotModel("p", scaled(planar_2link(0.9, 0.6), s), ee_frame="tip")
        assert length_scale(robot, robot.frame_id("tip")) == pytest.approx(1.5 * s, rel=1e-12)
        robot = RobotModel("s", scaled(slide_pair(), s), ee_frame="tip")
        assert length_scale(robot, robot.frame_id("tip")) == pytest.approx(1.2 * s, rel=1e-12)


def test_built_in_robots_keep_the_rotation_weight(registry: Registry) -> None:
    """Every built-in chain is 0.4–2.5 m long: its restart ranking, and so its answers, are
    those of the fixed rot_weight."""
    lo, hi = RANKING_BAND
    for rid in registry.ids():
        robot = registry.get(rid)
        frame = robot.frame_id(robot.ee_frame)
        assert lo <= length_scale(robot, frame) <= hi, rid
        c = DEFAULT_PARAMETERS.rot_weight
        assert rotation_weight(robot, frame, c) == c, rid


# ------------------------------------------------------------------ distinct
@pytest.mark.parametrize("s", SCALES)
@pytest.mark.parametrize(("shift", "distinct"), [(0.01, True), (5e-4, False)])
def test_distinct_solutions_are_the_same_at_every_scale(
    s: float, shift: float, distinct: bool
) -> None:
    """Two solutions 1 cm apart on each slide are distinct and 0.5 mm apart are one, at
    ×1; so at ×10 (10 cm and 5 mm) and ×0.05 (0.5 mm and 25 µm). Before: a fixed 1 mm
    merged the ×0.05 pair and split the ×10 one."""
    robot = RobotModel("slides", scaled(slide_pair(), s), ee_frame="tip")
    options = IKOptions(frame="tip", mode="position", num_solutions=3, analytic=False)
    a = np.array([0.2, 0.3]) * s
    b = a + np.array([shift, -shift]) * s
    target = pin.SE3(np.eye(3), np.array([0.2 * s + a.sum(), 0.0, 0.0]))
    ch = ik_chain(robot, "tip")
    search = Search(IKProblem(robot, ch, target, np.zeros(2), options, options.task()))
    assert search.offer(a)
    assert search.offer(b) is distinct
    assert len(search.solutions) == (2 if distinct else 1)
    assert (
        DEFAULT_PARAMETERS.distinct == 1e-3
    )  # the threshold these shifts straddle at ×1 (1.2 m chain)


# ------------------------------------------------------------------ SINGULAR_SIGMA
def planar_sigma(l1: float, l2: float, q: np.ndarray) -> float:
    """σ_min of the planar 2R position Jacobian (x, y rows), written out, divided by the
    chain length l1 + l2."""
    s1, c1 = math.sin(q[0]), math.cos(q[0])
    s12, c12 = math.sin(q[0] + q[1]), math.cos(q[0] + q[1])
    J = np.array([[-l1 * s1 - l2 * s12, -l2 * s12], [l1 * c1 + l2 * c12, l2 * c12]])
    return float(np.linalg.svd(J, compute_uv=False).min()) / (l1 + l2)


@pytest.mark.parametrize("s", SCALES)
def test_singular_verdicts_are_the_same_at_every_scale(s: float) -> None:
    """The path planner's σ_min (app.kinematics.paths.failures) is the dimensionless one:
    the written-out Jacobian's over the chain length, the same for the arm at ×1, ×10 and
    ×0.05, and so is each verdict σ < SINGULAR_SIGMA (elbows from straight to 90°).
    Before: the raw σ_min, ×10 and ×0.05 with the arm (the 5 cm arm singular everywhere)."""
    l1, l2 = 0.9, 0.6
    robot = RobotModel("p", scaled(planar_2link(l1, l2), s), ee_frame="tip")
    ch = ik_chain(robot, "tip")
    task = IKOptions(frame="tip", mode="position", weights=(1, 1, 0, 0, 0, 0)).task()
    verdicts = []
    for elbow in (0.0, 0.005, 0.02, 0.05, 0.2, 1.0, math.pi / 2):
        q = np.array([0.3, elbow])
        sigma = smallest_singular_value(robot, ch, task, q)
        assert sigma == pytest.approx(planar_sigma(l1, l2, q), rel=1e-9, abs=1e-12)
        verdicts.append(sigma < SINGULAR_SIGMA)
    # Near the straight elbow singular (σ = 0.011 at 0.05 rad), from 0.2 rad on not.
    assert verdicts == [True, True, True, True, False, False, False]


# ------------------------------------------------------------------ rot_weight
@pytest.mark.parametrize("pair", [(10.0, 100.0), (0.05, 0.005)])
def test_restart_ranking_beyond_the_band_is_scale_equivariant(
    registry: Registry, pair: tuple[float, float]
) -> None:
    """Outside the band, the rotation weight follows the chain length: the 12 m UR5 and its
    ×10 copy rank the restart table alike, and so do the 6 cm and 6 mm ones (the same
    nearest samples for every target). Before: a fixed 0.2 m², negligible at 12 m and
    dominant at 6 mm, ranked them by position alone or rotation alone."""
    urdf = registry.urdf_text("ur5")
    chains = []
    for s in pair:
        robot = RobotModel(f"ur5x{s}", scaled(urdf, s), ee_frame="tool0")
        chains.append((s, robot, ik_chain(robot, "tool0")))
    rng = np.random.default_rng(11)
    agree = 0
    for _ in range(20):
        q = rng.uniform(-3.0, 3.0, 6)
        nearest = []
        for _s, robot, ch in chains:
            pin.forwardKinematics(robot.model, robot.data, robot.to_pin(q))
            T = pin.updateFramePlacement(robot.model, robot.data, ch.frame_id)
            d, k_t, i = ch.sample_distances_argmin(pin.SE3(T))
            nearest.append((i, set(k_smallest(d, 8).tolist())))
        agree += nearest[0] == nearest[1]
    assert agree >= 19, f"{agree} of 20 targets ranked alike"


@pytest.mark.parametrize("s", SCALES)
def test_ik_failure_singular_verdicts_are_the_same_at_every_scale(s: float) -> None:
    """The IK failure reason of a search that stalled at the elbow angle e, the target out
    of reach: ``singular`` exactly when the written-out dimensionless σ_min is below
    SINGULAR_SIGMA (1e-3), at ×1, ×10 and ×0.05. Before: the raw σ_min (×0.05: every
    elbow below 0.07 rad singular; ×10: none above 0.0007)."""
    l1, l2 = 0.9, 0.6
    robot = RobotModel("p", scaled(planar_2link(l1, l2), s), ee_frame="tip")
    options = IKOptions(frame="tip", mode="position", weights=(1, 1, 0, 0, 0, 0))
    target = pin.SE3(np.eye(3), np.array([2.0 * s, 0.5 * s, 0.0]))  # beyond l1 + l2
    ch = ik_chain(robot, "tip")
    reasons = []
    for elbow in (0.0005, 0.003, 0.005, 0.05):
        q = np.array([0.3, elbow])
        search = Search(IKProblem(robot, ch, target, q, options, options.task()))
        reason, _ = classify(search, q, 1.0 * s, 0.0, 10)
        expected = "singular" if planar_sigma(l1, l2, q) < 1e-3 else "timeout"
        assert reason == expected, (elbow, reason)
        reasons.append(reason)
    assert reasons == ["singular", "singular", "timeout", "timeout"]
