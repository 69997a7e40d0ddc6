"""One wrapping convention for continuous joints, (−π, π], everywhere.

The reference is ``arctan2(sin x, cos x)``, which is what an angle read back from Pinocchio's
(cos, sin) pair gives; the source scan keeps a second formula from creeping back in.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from app.kinematics.analytic_ik.planar2 import into_limits
from app.kinematics.angles import wrap_angle, wrap_scalar
from app.kinematics.models import RobotModel
from tests.kinematics.chains import continuous_arm

ROOT = Path(__file__).resolve().parents[2]
EDGES = [math.pi, -math.pi, 3 * math.pi, -3 * math.pi, 0.0, 2 * math.pi, -2 * math.pi]


def _reference(x: np.ndarray) -> np.ndarray:
    return np.arctan2(np.sin(x), np.cos(x))


def test_wrap_angle_is_arctan2_of_the_angle() -> None:
    x = np.random.default_rng(7).uniform(-60.0, 60.0, 10_000)
    assert np.max(np.abs(wrap_angle(x) - _reference(x))) < 1e-12
    assert all(
        abs(wrap_scalar(v) - r) < 1e-12 for v, r in zip(x[:500], _reference(x[:500]), strict=True)
    )


@pytest.mark.parametrize("x", EDGES)
def test_the_interval_is_open_at_minus_pi_closed_at_plus_pi(x: float) -> None:
    w = float(wrap_angle(x))
    assert -math.pi < w <= math.pi
    assert w == pytest.approx(float(_reference(np.array(x))), abs=1e-12) or abs(w) == math.pi
    assert wrap_scalar(x) == w
    if abs(math.remainder(x, 2 * math.pi)) == math.pi:
        assert w == math.pi


def test_the_model_wraps_as_pinocchio_reads_back() -> None:
    robot = RobotModel("c", continuous_arm())
    c = robot.continuous
    assert c.tolist() == [0]
    with pytest.raises(ValueError):
        c[0] = 1  # read-only
    rng = np.random.default_rng(3)
    qs = np.column_stack([rng.uniform(-20, 20, 200), rng.uniform(-1, 1, 200)])
    qs[:7, 0] = EDGES
    for q in qs:
        back = robot.from_pin(robot.to_pin(q))
        assert np.allclose(robot.wrap(q), back, atol=1e-12, rtol=0)
        assert robot.wrap(q)[0] != -math.pi
    a, b = np.array([3.0, 0.2]), np.array([-3.0, 0.5])
    d = robot.difference(a, b)
    assert d[0] == pytest.approx(2 * math.pi - 6.0) and d[1] == pytest.approx(0.3)
    path = robot.unwrap_path(np.array([[3.1, 0.0], [-3.1, 0.0], [-3.0, 0.0]]))
    assert np.max(np.abs(np.diff(path[:, 0]))) < 0.2


def test_the_closed_forms_wrap_the_same_way() -> None:
    assert into_limits(-math.pi, -math.inf, math.inf, 0.0) == math.pi
    assert into_limits(3 * math.pi, -math.inf, math.inf, 0.0) == math.pi


#: (x + π) mod 2π − π and floor((x + π) / 2π): the [−π, π) formulas this module replaced.
_OTHER_WRAPS = re.compile(r"\+\s*(math|np)\.pi\s*\)\s*%|floor\(\s*\(?\s*\w+\s*\+\s*math\.pi")


def test_no_second_wrapping_formula_in_the_service() -> None:
    bad = [
        f"{p.relative_to(ROOT)}:{i}"
        for p in sorted((ROOT / "app").rglob("*.py"))
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if _OTHER_WRAPS.search(line)
    ]
    assert not bad, f"wrap angles with app.kinematics.angles, not a formula of their own: {bad}"
