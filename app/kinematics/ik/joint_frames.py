"""The chain's joint frames in compiled code, from the solver's chain constants.

:func:`frames` walks a chain (:class:`~app.kinematics.ik.boundary.ChainConstants`: each moving
joint's fixed placement in its parent, the joint axis along the local z) at a configuration
and gives what the compiled checks need besides the frame's pose: each moving joint's world
axis and a point on it (its origin), and the wrist point carried by the fifth moving joint,
the inputs of :func:`app.kinematics.ik.branch_kernel.flags` and of the frame's world
Jacobian. :func:`wrist_in_kernel_frame` puts a branch form's wrist point (given in
Pinocchio's frame of that joint) into the chain's frame of it, once per chain. Users: the
answer's annotation (:mod:`.annotate`) and the paths' compiled point
(:mod:`app.kinematics.paths.point_kernel`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.jit import jit

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.models import RobotModel


@jit
def frames(qa, C, t, prism, last_C, last_t, R, p, z, o, w, wrist):  # pragma: no cover
    """Forward kinematics of the chain at ``qa`` (k,) from its constants (``C``, ``t``,
    ``prism``, ``last_C``, ``last_t``: :class:`~app.kinematics.ik.boundary.ChainConstants`):
    the frame's rotation R (3, 3) and position p (3,), each moving joint's world axis z
    (k, 3) and a point o (k, 3) on it, and the wrist point w (3,) = the placement of the
    fifth moving joint applied to ``wrist`` (when k ≥ 5), all in the root frame (m), written
    in place."""
    k = qa.shape[0]
    tmp = np.empty((3, 3))
    for i in range(3):
        p[i] = 0.0
        for j in range(3):
            R[i, j] = 1.0 if i == j else 0.0
    for s in range(k):
        for i in range(3):
            p[i] += R[i, 0] * t[s, 0] + R[i, 1] * t[s, 1] + R[i, 2] * t[s, 2]
        for i in range(3):
            for j in range(3):
                tmp[i, j] = R[i, 0] * C[s, 0, j] + R[i, 1] * C[s, 1, j] + R[i, 2] * C[s, 2, j]
        for i in range(3):
            for j in range(3):
                R[i, j] = tmp[i, j]
            z[s, i] = R[i, 2]
            o[s, i] = p[i]
        if prism[s]:
            for i in range(3):
                p[i] += qa[s] * R[i, 2]
        else:
            c = math.cos(qa[s])
            sn = math.sin(qa[s])
            for i in range(3):
                x = R[i, 0]
                y = R[i, 1]
                R[i, 0] = c * x + sn * y
                R[i, 1] = c * y - sn * x
        if s == 4:
            for i in range(3):
                w[i] = p[i] + R[i, 0] * wrist[0] + R[i, 1] * wrist[1] + R[i, 2] * wrist[2]
    for i in range(3):
        p[i] += R[i, 0] * last_t[0] + R[i, 1] * last_t[1] + R[i, 2] * last_t[2]
    for i in range(3):
        for j in range(3):
            tmp[i, j] = R[i, 0] * last_C[0, j] + R[i, 1] * last_C[1, j] + R[i, 2] * last_C[2, j]
    for i in range(3):
        for j in range(3):
            R[i, j] = tmp[i, j]


def wrist_in_kernel_frame(robot: RobotModel, ch: IKChain) -> np.ndarray:
    """The chain's branch-form wrist point (given in Pinocchio's frame of the fifth moving
    joint) in the chain constants' frame of that joint (z along its axis; m), from both
    placements at one configuration (a generic one: any gives the same point, but at zero a
    symmetric rotation of joint 5 would hide a transposed placement); zeros without a wrist
    point or chain constants."""
    form, cc = ch.branch_form, ch.chain_constants
    if form is None or form.wrist is None or cc is None:
        return np.zeros(3)
    model, k = robot.model, ch.k
    data = model.createData()
    qa = 0.3 + 0.1 * np.arange(k)
    q = np.zeros(robot.n)
    q[ch.active] = qa
    pin.forwardKinematics(model, data, robot.to_pin(q))
    w0 = data.oMi[form.pin_ids[4]].act(np.asarray(form.wrist, dtype=float))
    # frames() applies joint 5's placement (R5, p5) to a point: p5 from 0, R5's columns
    # from the unit vectors
    R, p, z, o = np.empty((3, 3)), np.empty(3), np.empty((k, 3)), np.empty((k, 3))
    placed = []
    for u in (np.zeros(3), *np.eye(3)):
        w = np.empty(3)
        frames(qa, cc.C, cc.t, cc.prism, cc.last_C, cc.last_t, R, p, z, o, w, u.copy())
        placed.append(w)
    R5 = np.column_stack([placed[i] - placed[0] for i in (1, 2, 3)])
    return np.ascontiguousarray(R5.T @ (w0 - placed[0]))
