"""Closed-form inverse kinematics where a chain's geometry admits one.

The numeric solver (:mod:`app.kinematics.ik`) asks :func:`candidates` first; a closed form
returns *every* candidate configuration of the moving joints, and the solver verifies each
one by forward kinematics (mode, tolerances, limits, ``accept``) before reporting it, so a
closed form can only add answers, never wrong ones.

- Planar 2-link (RR) arms: :mod:`app.kinematics.analytic_ik.planar2`.
- UR-type 6R arms (three parallel axes, intersecting last two):
  :mod:`app.kinematics.analytic_ik.ur`, built on the Paden–Kahan subproblems of
  :mod:`app.kinematics.analytic_ik.subproblems`.

A frame moved by a mimic follower has none (its moving joints are not its serial chain).

This module detects which closed form a chain admits (:func:`prepare`) and returns its
candidates (:func:`candidates`).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.analytic_ik import ur
from app.kinematics.analytic_ik.planar2 import (
    Planar2,
    into_limits,
    planar2_geometry,
    planar2_solutions,
)
from app.kinematics.analytic_ik.ur import (
    URType,
    ur_candidates_compiled,
    ur_geometry,
    ur_solutions,
)
from app.kinematics.jit import available as _compiled_available
from app.kinematics.mimic import has_followers
from app.kinematics.models import RobotModel

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain


def warm_up() -> None:
    """Compile the closed forms' compiled parts (the UR one: :func:`ur.warm_up`)."""
    ur.warm_up()


def closed_forms(robot: RobotModel, ch: IKChain) -> tuple[URType | None, Planar2 | None]:
    """The closed-form geometries of the chain (UR, planar 2R; None where none applies):
    :attr:`IKChain.closed_form <app.kinematics.ik.precompute.IKChain.closed_form>`."""
    fid = ch.frame_id
    if has_followers(robot.model.supports[robot.model.frames[fid].parentJoint], robot.mimic_joints):
        # A mimic follower moves the frame: its chain is not the serial chain of ch.active.
        return (None, None)
    return (ur_geometry(robot, ch.active, fid), planar2_geometry(robot, ch.active, fid))


def prepare(robot: RobotModel, ch: IKChain) -> tuple[URType | None, Planar2 | None]:
    """The chain's closed forms, with the UR one compiled for its argument types, so that
    no query's budget pays for either."""
    forms = ch.closed_form
    ur = forms[0]
    if ur is not None and _compiled_available():
        seed = np.ascontiguousarray(robot.mid_range()[ch.active])
        ur_candidates_compiled(ur, ur.M, seed, robot.lower[ch.active], robot.upper[ch.active])
    return forms


def candidates(
    robot: RobotModel, ch: IKChain, target: pin.SE3, mode: str, seed: np.ndarray
) -> Iterator[np.ndarray] | None:
    """Closed-form candidates for the active joints of ``ch`` (an ``IKChain``).

    ``None`` when no closed form applies to this chain and mode; otherwise an iterator over
    candidate configurations of the active joints, moved into the joint limits, roughly
    nearest to the seed first (it may be empty: the closed form proves the target
    unreachable).
    """
    active = ch.active
    ur, planar = ch.closed_form
    if ur is None and planar is None:
        return None
    lo, hi = ch.lower, ch.upper  # the limits, within ±MAX_JOINT_VALUE
    s = seed[active]
    raw: Iterable[np.ndarray] | None = None
    if ur is not None and mode == "pose" and _compiled_available():
        return iter(ur_candidates_compiled(ur, target, np.ascontiguousarray(s), lo, hi))
    if ur is not None and mode == "pose":
        raw = ur_solutions(ur, target, s)
    elif planar is not None and mode != "orientation":
        raw = [np.array(q) for q in planar2_solutions(planar, target.translation)]
    if raw is None:
        return None
    return (
        np.array([into_limits(float(x), lo[i], hi[i], s[i]) for i, x in enumerate(q)]) for q in raw
    )
