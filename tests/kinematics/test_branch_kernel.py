"""The compiled branch flags against the Python definitions and the textbook signs.

:func:`app.kinematics.ik.branch_kernel.flags` is fed world axes and points from Pinocchio's
joint placements (each axis's own joint origin, not the Jacobian-derived points the Python
code uses), so agreement also checks that any point of an axis gives the same flags. The
UR5's wrist flag is compared with sin q5 and the planar arm's elbow with sin θ2 (textbook
signs, independent of both codes).
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.ik import branch_kernel
from app.kinematics.ik.branches import branch_form, branch_label
from app.kinematics.ik.precompute import ik_chain
from app.kinematics.models import RobotModel
from tests.kinematics.reference import random_q

CASES = [("ur5", "tool0"), ("ur5_dh", None), ("puma560", "tool"), ("stanford_arm", "tool")]
CASES += [("planar2", None)]


def _code(robot: RobotModel, frame: str, q: np.ndarray) -> tuple[int, str | None]:
    """The compiled code at wire configuration ``q`` and the Python label."""
    ch = ik_chain(robot, frame)
    form = branch_form(robot, ch)
    assert form is not None
    model = robot.model
    data = model.createData()
    pin.forwardKinematics(model, data, robot.to_pin(q))
    z = np.array([data.oMi[j].rotation @ a for j, a in zip(form.pin_ids, form.axes, strict=True)])
    o = np.array([data.oMi[j].translation for j in form.pin_ids])
    w = data.oMi[form.pin_ids[4]].act(form.wrist) if form.kind == "6r" else np.zeros(3)
    p = pin.updateFramePlacement(model, data, ch.frame_id).translation.copy()
    code = branch_kernel.flags(z, o, w, p, *branch_kernel.form_arrays(form))
    return code, branch_kernel.label(form, code) == branch_label(robot, ch, q)


@pytest.mark.parametrize(("name", "frame"), CASES)
def test_compiled_flags_spell_the_python_label(registry, name: str, frame: str | None) -> None:
    robot = registry.get(name)
    frame = frame or robot.ee_frame
    rng = np.random.default_rng(29)
    codes = set()
    for _ in range(300):
        q = random_q(robot, rng)
        code, same = _code(robot, frame, q)
        assert same, (name, q, code)
        codes.add(code)
    # Random configurations visit every branch the form has (else the test proves little).
    form = branch_form(robot, ik_chain(robot, frame))
    assert form is not None
    expected = 2 if form.kind == "planar2" else (8 if form.elbow else 4)
    assert len(codes) == expected, (name, sorted(codes))


def test_ur5_wrist_and_planar_elbow_follow_the_textbook_signs(registry) -> None:
    ur5, planar = registry.get("ur5"), registry.get("planar2")
    rng = np.random.default_rng(7)
    for _ in range(100):
        q = rng.uniform(-math.pi, math.pi, 6)
        if abs(math.sin(q[4])) < 1e-3:
            continue
        code, _ = _code(ur5, "tool0", q)
        assert bool(code & branch_kernel.WRIST_NOFLIP) == (math.sin(q[4]) > 0), q
        qp = random_q(planar, rng)
        if abs(math.sin(qp[1])) < 1e-3:
            continue
        code, _ = _code(planar, planar.ee_frame, qp)
        assert bool(code & branch_kernel.PLANAR_ELBOW_UP) == (math.sin(qp[1]) > 0), qp
