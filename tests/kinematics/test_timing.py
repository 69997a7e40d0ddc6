"""Time parameterization of joint paths (app.kinematics.paths.timing) against closed forms
(bang-bang and trapezoidal profiles), finite differences of the answer, toppra's own
trajectory, and limits read from the URDF (yourdfpy) and the DH table (YAML)."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml
from pydantic import ValidationError

from app.api.schemas.timing import TimingIn, timing_of
from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.models import RobotModel
from app.kinematics.paths import timing as timing_mod
from app.kinematics.paths.timing import parameterize, toppra_modules
from tests.kinematics.chains import continuous_arm, planar_2link, rrp_like
from tests.kinematics.reference import reference_velocity_limits

ROOT = Path(__file__).resolve().parents[2]
#: Relative slack on a limit (rounding of the answer; the module verifies to rounding).
SLACK = 1e-9


def curved_path(n_points: int, start: np.ndarray, amplitude: float = 0.8) -> np.ndarray:
    """A smooth joint path (every joint moving, with turns) of ``n_points`` points."""
    u = np.linspace(0.0, 1.0, n_points)[:, None]
    k = np.arange(1, start.size + 1)
    return start + amplitude * np.sin(2.0 * u * k) * np.cos(1.3 * u * k)


def corner_path(n_points: int) -> np.ndarray:
    """Two straight joint-space segments of UR5 joints 0-3 meeting at a sharp corner."""
    u = np.linspace(0.0, 1.0, n_points // 2)
    first = np.outer(u, [1.0, 0.5, 0.0, 0.0, 0.0, 0.0])
    second = first[-1] + np.outer(u[1:], [0.0, -0.5, 1.0, 0.3, 0.0, 0.0])
    return np.vstack([first, second])


def check_limits(qs: np.ndarray, result) -> None:
    """Reported velocities and accelerations, and finite differences of (t, q), within the
    limits: the mean velocity over an interval and twice a second divided difference are
    averages of q̇ and q̈ on the true motion, so they cannot exceed its bounds."""
    moving = ~np.isnan(result.velocity_limits)
    v, a = result.velocity_limits[moving], result.acceleration_limits[moving]
    assert np.all(np.abs(result.qd[:, moving]) <= v * (1 + SLACK))
    assert np.all(np.abs(result.qdd[:, moving]) <= a * (1 + SLACK))
    assert np.all(result.qd[:, ~moving] == 0) and np.all(result.qdd[:, ~moving] == 0)
    t, q = result.t, qs[:, moving]
    dt = np.diff(t)
    assert np.all(dt > 0)
    mean_v = np.diff(q, axis=0) / dt[:, None]
    assert np.all(np.abs(mean_v) <= v * (1 + 1e-6))
    dd = 2 * (mean_v[1:] - mean_v[:-1]) / (t[2:] - t[:-2])[:, None]
    assert np.all(np.abs(dd) <= a * (1 + 1e-6))


def robot_of(urdf: str, name: str = "test") -> RobotModel:
    return RobotModel(name, urdf)


# --------------------------------------------------------------------------- limits hold
@pytest.mark.parametrize("n_points", [5, 60, 400, 3000])
def test_limits_hold_at_every_sample_of_a_curved_ur5_path(registry, n_points) -> None:
    robot = registry.get("ur5")
    qs = curved_path(n_points, np.array([0.1, -1.4, 1.2, -0.5, 1.0, 0.3]))
    result = parameterize(robot, qs, acceleration_fraction=2.0)
    check_limits(qs, result)
    assert result.t[0] == 0.0 and result.duration == result.t[-1]
    np.testing.assert_array_equal(result.qd[[0, -1]], 0.0)  # rest to rest
    # Time-optimal, not merely slow: some joint is at its velocity or acceleration limit.
    v, a = result.velocity_limits, result.acceleration_limits
    peak = max(np.abs(result.qd / v).max(), np.abs(result.qdd / a).max())
    assert peak >= 0.98


def test_reported_velocities_are_the_motion_through_the_points(registry) -> None:
    """Central differences of the answer's (t, q) agree with its velocities (dense path)."""
    robot = registry.get("ur5")
    qs = curved_path(2000, np.zeros(6), amplitude=0.5)
    result = parameterize(robot, qs)
    h1, h2 = np.diff(result.t)[:-1, None], np.diff(result.t)[1:, None]
    # The three-point derivative on uneven steps (exact for quadratics).
    central = (
        -h2 / (h1 * (h1 + h2)) * qs[:-2]
        + (h2 - h1) / (h1 * h2) * qs[1:-1]
        + h1 / (h2 * (h1 + h2)) * qs[2:]
    )
    error = np.abs(central - result.qd[1:-1]) / np.nanmax(result.velocity_limits)
    # O(h²) where the motion is smooth, O(h) where the acceleration jumps (switch points).
    assert error.max() < 5e-3 and np.median(error) < 1e-5


def test_a_sharp_corner_is_refined_not_slowed_globally(registry) -> None:
    """More points than the first grid: the corner's curvature exceeds the limits between
    grid points; refinement fixes it there instead of slowing the whole motion."""
    robot = registry.get("ur5")
    qs = corner_path(3000)
    result = parameterize(robot, qs, acceleration_fraction=2.0)
    check_limits(qs, result)
    assert result.time_scale < 1.01
    few = parameterize(robot, corner_path(200), acceleration_fraction=2.0)
    assert abs(result.duration - few.duration) < 0.02 * few.duration


def test_a_random_walk_of_thousands_of_corners_stays_near_optimal(registry) -> None:
    """Every point a corner: the grid holds every point, refinement the rest; the uniform
    slow-down left is small, and the limits hold."""
    robot = registry.get("ur5")
    qs = np.cumsum(np.random.default_rng(7).normal(size=(2500, 6)) * 0.01, axis=0)
    result = parameterize(robot, qs, acceleration_fraction=1.0)
    check_limits(qs, result)
    assert result.time_scale < 1.01


def test_duration_matches_toppras_own_trajectory(registry) -> None:
    """toppra's standard pipeline (its automatic grid and output trajectory) on the same
    path: the same optimum within 1 %."""
    robot = registry.get("ur5")
    qs = curved_path(80, np.zeros(6))
    result = parameterize(robot, qs, acceleration_fraction=1.5)
    ta, algo, constraint = toppra_modules()
    knots = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(qs, axis=0), axis=1))])
    v = np.array([3.15, 3.15, 3.15, 3.2, 3.2, 3.2])
    instance = algo.TOPPRA(
        [constraint.JointVelocityConstraint(v), constraint.JointAccelerationConstraint(1.5 * v)],
        ta.SplineInterpolator(knots, qs),
        gridpt_min_nb_points=1000,
    )
    reference = instance.compute_trajectory(0, 0)
    assert abs(result.duration - reference.duration) < 0.01 * reference.duration


@pytest.mark.parametrize(
    ("v", "a", "length", "n_points"),
    [
        (1.0, 1.0, 3e-8, 3),
        (1.0, 1e-3, 1e-6, 50),
        (1e-6, 1e-6, 1.0, 7),
        (1e9, 1e-6, 1e-6, 7),
        (1e-3, 1e9, 1e4, 50),
        (1e6, 1e6, 2e-9, 2),
    ],
)
def test_limits_hold_at_any_scale_of_path_and_limits(v, a, length, n_points) -> None:
    """TOPP-RA's tolerances are absolute: tiny or huge paths and limits must still give a
    motion within the limits (they were refused as 'not controllable' before scaling)."""
    robot = robot_of(planar_2link(limit=1e4))
    rng = np.random.default_rng(n_points)
    qs = np.cumsum(rng.normal(size=(n_points, 2)), axis=0)
    qs = (qs - qs[0]) * length / np.linalg.norm(np.diff(qs, axis=0), axis=1).sum()
    # The second joint's limits differ, within the accepted range [1e-6, 1e9].
    v_max = np.array([v, 3 * v if 3 * v <= 1e9 else v / 3])
    a_max = np.array([a, 2 * a if 2 * a <= 1e9 else a / 2])
    result = parameterize(robot, qs, velocity_limits=v_max, acceleration_limits=a_max)
    check_limits(qs, result)
    peak = max(np.abs(result.qd / v_max).max(), np.abs(result.qdd / a_max).max())
    assert peak >= 0.98


# ------------------------------------------------------------------------ closed forms
def bang_bang_time(q: np.ndarray, distance: float, v: float, a: float) -> np.ndarray:
    """Time at which a rest-to-rest trapezoidal (or triangular) profile reaches q ∈ [0, D]."""
    ramp = min(v * v / a, distance) / 2  # distance covered accelerating
    peak = math.sqrt(2 * a * ramp)
    total = 2 * peak / a + (distance - 2 * ramp) / peak
    return np.where(
        q <= ramp,
        np.sqrt(2 * q / a),
        np.where(
            q <= distance - ramp,
            peak / a + (q - ramp) / peak,
            total - np.sqrt(np.maximum(2 * (distance - q) / a, 0.0)),
        ),
    )


@pytest.mark.parametrize(
    ("distance", "v", "a"),
    [(2.0, 3.15, 1.0), (2.0, 3.15, 10.0), (0.3, 1.0, 50.0), (5.0, 0.5, 0.2)],
)
def test_one_joint_line_has_the_textbook_profile(registry, distance, v, a) -> None:
    robot = registry.get("ur5")
    qs = np.tile([0.2, -1.0, 0.5, 0.0, 0.0, 0.0], (41, 1))
    qs[:, 2] += np.linspace(0.0, distance, 41)
    result = parameterize(
        robot, qs, velocity_limits={"elbow_joint": v}, acceleration_limits=[a] * 6
    )
    ramp = min(v * v / a, distance) / 2
    expected = 2 * math.sqrt(2 * a * ramp) / a + (distance - 2 * ramp) / math.sqrt(2 * a * ramp)
    # d ≥ v²/a: D/v + v/a; else 2·sqrt(D/a)
    assert expected == pytest.approx(
        distance / v + v / a if distance >= v * v / a else 2 * math.sqrt(distance / a)
    )
    assert result.duration == pytest.approx(expected, rel=0.01)
    np.testing.assert_allclose(
        result.t, bang_bang_time(qs[:, 2] - qs[0, 2], distance, v, a), atol=0.01 * expected
    )
    assert np.abs(result.qd[:, 2]).max() == pytest.approx(min(v, math.sqrt(a * distance)), rel=0.01)
    check_limits(qs, result)


def test_acceleration_fraction_is_per_second_of_the_velocity_limit() -> None:
    robot = robot_of(planar_2link())  # both joints: velocity 1 rad/s
    qs = np.zeros((21, 2))
    qs[:, 0] = np.linspace(0.0, 0.4, 21)
    for fraction in (0.5, 4.0):
        result = parameterize(robot, qs, acceleration_fraction=fraction)
        a = fraction * 1.0
        expected = 2 * math.sqrt(0.4 / a) if 0.4 < 1 / a else 0.4 + 1 / a
        assert result.acceleration_limits[0] == a
        assert result.duration == pytest.approx(expected, rel=0.01)
    default = parameterize(robot, qs)
    assert default.acceleration_limits[0] == 1.0  # default fraction 1: a = v / (1 s)


def test_velocity_scale_scales_the_velocity_limits(registry) -> None:
    robot = registry.get("ur5")
    qs = np.zeros((11, 6))
    qs[:, 0] = np.linspace(0.0, 3.0, 11)
    result = parameterize(robot, qs, velocity_scale=0.5, acceleration_limits=[100.0] * 6)
    assert result.velocity_limits[0] == pytest.approx(3.15 / 2)
    assert np.abs(result.qd[:, 0]).max() == pytest.approx(3.15 / 2, rel=1e-6)


# ---------------------------------------------------------------------- description limits
def test_ur5_velocity_limits_come_from_its_urdf(registry) -> None:
    robot = registry.get("ur5")
    expected = reference_velocity_limits(robot, robot.joint_names)
    qs = np.outer(np.linspace(0.0, 1.0, 30), [2.0, -1.5, 1.0, 2.5, 0.5, 1.2])
    result = parameterize(robot, qs, acceleration_limits=[1000.0] * 6)
    np.testing.assert_allclose(result.velocity_limits, expected, rtol=1e-15)
    # A joint-space line, almost no acceleration bound: wrist 1 cruises at its URDF limit.
    assert np.abs(result.qd / expected).max() == pytest.approx(1.0, rel=1e-6)


def test_dh_robot_velocity_limits_come_from_its_table(registry) -> None:
    robot = registry.get("ur5_dh")
    table = yaml.safe_load((ROOT / "robots" / "dh" / "ur5_dh.yaml").read_text())
    expected = [math.radians(j["velocity"]) for j in table["joints"]]  # deg/s in the table
    qs = np.zeros((11, 6))
    qs[:, 4] = np.linspace(0.0, 4.0, 11)
    result = parameterize(robot, qs, acceleration_limits=[1000.0] * 6)
    assert result.velocity_limits[4] == pytest.approx(expected[4], rel=1e-12)
    assert np.abs(result.qd[:, 4]).max() == pytest.approx(expected[4], rel=1e-6)
    assert np.isnan(result.velocity_limits[[0, 1, 2, 3, 5]]).all()  # static: none applied


def test_a_mimic_follower_bounds_its_leaders_velocity() -> None:
    urdf = planar_2link().replace(
        "</robot>",
        """<link name="finger"/>
  <joint name="f" type="revolute">
    <parent link="link2"/><child link="finger"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" velocity="0.5" effort="1"/>
    <mimic joint="j2" multiplier="4" offset="0"/>
  </joint>
</robot>""",
    )
    robot = robot_of(urdf)
    qs = np.zeros((11, 2))
    qs[:, 1] = np.linspace(0.0, 2.0, 11)
    result = parameterize(robot, qs, acceleration_limits=[100.0, 100.0])
    assert result.velocity_limits[1] == pytest.approx(0.5 / 4)  # the follower's 0.5 / 4
    assert np.abs(4 * result.qd[:, 1]).max() == pytest.approx(0.5, rel=1e-6)


# ------------------------------------------------------------------------ degenerate paths
def test_fewer_than_two_distinct_points_take_no_time() -> None:
    robot = robot_of(planar_2link())
    one = parameterize(robot, np.array([[0.1, 0.2]]))
    assert one.t.tolist() == [0.0] and one.duration == 0.0 and one.qd.shape == (1, 2)
    same = parameterize(robot, np.tile([0.1, 0.2], (4, 1)))
    assert same.t.tolist() == [0.0] * 4 and not same.qd.any() and not same.qdd.any()


def test_repeated_points_share_their_time() -> None:
    robot = robot_of(planar_2link())
    qs = np.array([[0.0, 0.0], [0.3, 0.1], [0.3, 0.1], [0.6, 0.3], [0.6, 0.3 + 1e-12]])
    result = parameterize(robot, qs)
    assert result.t[1] == result.t[2] and result.t[3] == result.t[4]
    np.testing.assert_array_equal(result.qd[1], result.qd[2])
    keep = [0, 1, 3]
    check_limits(qs[keep], type(result)(**{
        **{f: getattr(result, f) for f in result.__dataclass_fields__},
        "t": result.t[keep], "qd": result.qd[keep], "qdd": result.qdd[keep],
    }))  # fmt: skip


def test_same_input_gives_the_same_answer_bit_for_bit(registry) -> None:
    robot = registry.get("panda")
    qs = curved_path(300, robot.mid_range(), amplitude=0.3)
    first, second = parameterize(robot, qs), parameterize(robot, qs.copy())
    for name in ("t", "qd", "qdd"):
        np.testing.assert_array_equal(getattr(first, name), getattr(second, name))


def test_prismatic_joint_in_metres_per_second() -> None:
    robot = robot_of(rrp_like())
    qs = np.zeros((11, 3))
    qs[:, 2] = np.linspace(0.0, 0.8, 11)
    result = parameterize(robot, qs, acceleration_limits={"j3": 0.5})
    assert result.duration == pytest.approx(2 * math.sqrt(0.8 / 0.5), rel=0.01)


# ----------------------------------------------------------------------------- errors
def test_a_moving_joint_without_velocity_limit_is_named() -> None:
    robot = robot_of(continuous_arm())  # c1: continuous, no <limit>
    qs = np.zeros((5, 2))
    qs[:, 1] = np.linspace(0.0, 0.5, 5)
    parameterize(robot, qs)  # c1 does not move: no limit needed
    qs[:, 0] = np.linspace(0.0, 1.0, 5)
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, qs)
    assert err.value.field == "timing.velocity_limits.c1"
    assert parameterize(robot, qs, velocity_limits={"c1": 2.0}).velocity_limits[0] == 2.0
    for placeholder in ("0", "1e12"):  # none, or "unlimited" written as a huge number
        urdf = planar_2link().replace('velocity="1"', f'velocity="{placeholder}"', 1)
        with pytest.raises(InvalidInputError) as err:
            parameterize(robot_of(urdf), np.array([[0.0, 0.0], [0.5, 0.0]]))
        assert err.value.field == "timing.velocity_limits.j1"


@pytest.mark.parametrize(
    ("options", "field"),
    [
        ({"acceleration_limits": [1.0, 1.0, 1.0, 0.0, 1.0, 1.0]}, "timing.acceleration_limits.3"),
        ({"acceleration_limits": {"elbow_joint": -2.0}}, "timing.acceleration_limits.elbow_joint"),
        ({"velocity_limits": [1.0, 2.0]}, "timing.velocity_limits"),
        ({"velocity_limits": [1.0] * 5 + [math.inf]}, "timing.velocity_limits.5"),
        ({"velocity_limits": [1e10] + [1.0] * 5}, "timing.velocity_limits.0"),
        (
            {"acceleration_limits": {"wrist_1_joint": 1e-7}},
            "timing.acceleration_limits.wrist_1_joint",
        ),
        ({"acceleration_fraction": 1e-7}, "timing.acceleration_fraction"),
        ({"velocity_scale": 1e-7}, "timing.velocity_scale"),
        (
            {"acceleration_limits": [1.0] * 6, "acceleration_fraction": 0.5},
            "timing.acceleration_fraction",
        ),
        ({"acceleration_fraction": 0.0}, "timing.acceleration_fraction"),
        ({"velocity_scale": 1.5}, "timing.velocity_scale"),
    ],
)
def test_bad_limits_are_named(registry, options, field) -> None:
    robot = registry.get("ur5")
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, curved_path(5, np.zeros(6)), **options)
    assert err.value.field == field


def test_unknown_and_mimic_joint_names_are_named(registry) -> None:
    robot = registry.get("panda")
    qs = curved_path(5, robot.mid_range(), amplitude=0.01)
    with pytest.raises(UnknownNameError) as err:
        parameterize(robot, qs, velocity_limits={"elbow": 1.0})
    assert err.value.field == "timing.velocity_limits.elbow"
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, qs, acceleration_limits={"panda_finger_joint2": 1.0})
    assert err.value.field == "timing.acceleration_limits.panda_finger_joint2"


def test_points_are_bounded_and_shaped(registry, monkeypatch) -> None:
    robot = registry.get("ur5")
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, np.zeros((3, 5)))
    assert err.value.field == "points"
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, np.array([[0.0] * 6, [0, 0, math.nan, 0, 0, 0]]))
    assert err.value.field == "points.1.2"
    monkeypatch.setattr(timing_mod, "MAX_POINTS", 10)
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, np.zeros((11, 6)))
    assert err.value.field == "points" and "at most 10" in err.value.message


def test_limit_lists_over_a_groups_joints() -> None:
    robot = robot_of(rrp_like())
    qs = np.zeros((11, 3))
    qs[:, 2] = np.linspace(0.0, 0.8, 11)
    result = parameterize(robot, qs, velocity_limits=[0.2, 0.1], joints=[0, 2])
    assert result.velocity_limits[2] == 0.1
    with pytest.raises(InvalidInputError) as err:
        parameterize(robot, qs, acceleration_limits=[1.0, -1.0], joints=[0, 2])
    assert err.value.field == "timing.acceleration_limits.1"


# ------------------------------------------------------------------------------- wire
def test_wire_errors_name_the_item_or_the_joint() -> None:
    cases = [
        ({"acceleration_limits": [1, 2, 3, "x"]}, ("acceleration_limits", 3)),
        ({"acceleration_limits": [1, 2, 3, 0]}, ("acceleration_limits", 3)),
        ({"velocity_limits": [1, 2e9]}, ("velocity_limits", 1)),
        ({"velocity_limits": {"elbow_joint": True}}, ("velocity_limits", "elbow_joint")),
        ({"velocity_limits": "fast"}, ("velocity_limits",)),
        ({"acceleration_fraction": -1}, ("acceleration_fraction",)),
    ]
    for body, loc in cases:
        with pytest.raises(ValidationError) as err:
            TimingIn.model_validate(body)
        assert err.value.errors()[0]["loc"] == loc, body


def test_timing_of_answers_in_joint_order(registry) -> None:
    robot = registry.get("ur5")
    qs = np.zeros((11, 6))
    qs[:, 1] = np.linspace(0.0, 1.0, 11)
    out = timing_of(robot, qs, TimingIn(acceleration_fraction=2.0))
    assert len(out["t"]) == 11 and len(out["velocities"][0]) == 6
    assert out["velocity_limits"][0] is None and out["velocity_limits"][1] == 3.15
    assert out["acceleration_limits"][1] == pytest.approx(6.3)
    assert out["duration"] == out["t"][-1] and out["time_scale"] >= 1.0


# --------------------------------------------------------------------------- the import
def test_toppra_is_imported_without_matplotlib() -> None:
    """Matplotlib (toppra imports it for plots) needs a writable home or temporary directory
    and 0.6 s: the service imports toppra without it."""
    code = (
        "import sys, numpy as np\n"
        "from app.kinematics.models import RobotModel\n"
        "from app.kinematics.paths.timing import parameterize\n"
        "from tests.kinematics.chains import planar_2link\n"
        "assert 'toppra' not in sys.modules\n"
        "r = parameterize(RobotModel('p', planar_2link()), np.array([[0, 0], [1, 0.5]]))\n"
        "assert r.duration > 0 and 'toppra' in sys.modules\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] == 'matplotlib'))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=300
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"
