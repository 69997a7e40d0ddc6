"""The length scale of a chain: the solver's mixed-unit thresholds for an arm of any size.

Kinematics is scale-equivariant in its lengths: the arm whose every length (link offsets,
prismatic travel) is s times another's places its frame at s·p, with the same rotation,
for the same joint angles and s times the prismatic values; its Jacobian's position rows
and prismatic columns scale accordingly. A threshold written in "rad or m" holds for one
size of arm only. The thresholds are stated for an arm whose chain is 1 m long, and the
chain's length scale ``L`` (:func:`length_scale`, dimensionless: the chain length in
metres) carries them to any other:

``distinct`` (:class:`~app.kinematics.ik.parameters.SolverParameters`)
    Two solutions are the same when no revolute joint differs by more than ``distinct``
    rad and no prismatic joint by more than ``distinct·L`` m (:func:`joint_units`).
``SINGULAR_SIGMA`` (:mod:`app.kinematics.ik.failure`, :mod:`app.kinematics.paths.failures`)
    Compared with σ_min of the dimensionless task Jacobian (:func:`dimensionless`): the
    position rows divided by ``L`` (m per L m), the prismatic columns multiplied by ``L``.
    The rows of rotation and the revolute columns are unchanged (rad per rad).
``rot_weight`` (:class:`~app.kinematics.ik.parameters.SolverParameters`, the restart ranking)
    The pose distance ‖p − p_t‖² + c‖R − R_t‖²_F (m²) weighs the rotation with
    ``c = rot_weight·κ²`` m² (:func:`rotation_weight`), κ = L / clip(L, 0.4, 2.5): κ = 1 for
    chains 0.4–2.5 m long (every built-in robot: their restart order, and so their answers,
    are those of the fixed weight), proportional to the length outside that band (a 10 m
    arm ranks its restarts as a 2.5 m one scaled, a 5 cm arm as a 0.4 m one).

The chain length is the seed-free form of the reach bound of
:func:`app.kinematics.ik.failure.reach_bound`: the lengths of the joint placements from
the first joint of the frame's support path to the frame, plus the largest travel of each
prismatic joint on the way (one without finite limits adds nothing). A chain without any
length (a wrist alone) has ``L = 1``. Built-in robots: 0.42 m (so100) to 2.3 m (planar3r).
"""

from __future__ import annotations

import math

import numpy as np

from app.kinematics.joint_types import PRISMATIC_MODELS
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel

#: Chain lengths (m) whose restart ranking keeps ``SolverParameters.rot_weight`` as is.
RANKING_BAND = (0.4, 2.5)


def length_scale(robot: RobotModel, frame_id: int) -> float:
    """The chain length of frame ``frame_id`` in metres, as a number (see the module doc);
    1.0 for a chain without length. Cached per model and frame (the model's lazy cache, which
    a chain's own build may call into: its lock is reentrant)."""
    key = LazyKey(f"ik.length_scale:{frame_id}", float)
    return robot.lazy(key, lambda r: _chain_length(r, frame_id))


def _chain_length(robot: RobotModel, frame_id: int) -> float:
    model = robot.model
    frame = model.frames[frame_id]
    path = [int(j) for j in model.supports[frame.parentJoint] if int(j) > 0]
    total = float(np.linalg.norm(frame.placement.translation))
    for k, jid in enumerate(path):
        if k > 0:
            total += float(np.linalg.norm(model.jointPlacements[jid].translation))
        if model.joints[jid].shortname() in PRISMATIC_MODELS:
            i = model.idx_qs[jid]
            travel = max(abs(model.lowerPositionLimit[i]), abs(model.upperPositionLimit[i]))
            if math.isfinite(travel):
                total += float(travel)
    return total if math.isfinite(total) and total > 0.0 else 1.0


def rotation_weight(robot: RobotModel, frame_id: int, weight: float) -> float:
    """The restart ranking's rotation weight ``weight·κ²`` (m²) for this chain (module doc)."""
    length = length_scale(robot, frame_id)
    lo, hi = RANKING_BAND
    kappa = length / min(max(length, lo), hi)
    return weight * kappa * kappa


def joint_units(robot: RobotModel, length: float) -> np.ndarray:
    """Per wire joint, the unit its thresholds are counted in: 1 (rad) for a revolute or
    continuous joint, ``length`` (m) for a prismatic one."""
    return np.array([length if j.type == "prismatic" else 1.0 for j in robot.joints])


def dimensionless(
    J: np.ndarray, rows: np.ndarray, prismatic: np.ndarray, length: float
) -> np.ndarray:
    """The task Jacobian ``J`` (``rows`` of [position; rotation], columns of the moving
    joints) without units: position rows divided by ``length``, the ``prismatic`` columns
    (boolean mask) multiplied by it. Equal for an arm and any scaled copy of it."""
    if length == 1.0:
        return J
    out = J.copy()
    out[np.asarray(rows) < 3] /= length
    out[:, prismatic] *= length
    return out
