"""An IK query's options and inputs, validated once: :class:`IKOptions`, targets, seeds.

Everything semantic about an IK request is checked here, in the core, whoever calls it (the
HTTP routes, the benchmark, the tests): the mode and its task rows, weights that leave the
mode nothing to drive, tolerances, budgets, the frame, a target's shape (matrix or
position/orientation, the components a mode needs), and the seed. Each failure raises
:class:`~app.kinematics.errors.InvalidInputError` naming the field as the wire spells it
(``weights``, ``targets.3.orientation``, ``seed.4``). The HTTP layer only checks the wire
shape (types and ranges, which the OpenAPI document shows).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, NamedTuple

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group, expand, state_configuration
from app.kinematics.models import MAX_POSITION, RobotModel
from app.kinematics.placement import placement

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain

Mode = Literal["pose", "position", "orientation"]
Status = Literal["converged", "not_converged", "timeout"]

MODES: tuple[str, ...] = ("pose", "position", "orientation")
#: What the distinct solutions can be ranked by (:mod:`app.kinematics.ik.ranking`).
RANK_BY: tuple[str, ...] = ("seed_distance", "manipulability", "clearance")
#: Task rows of each mode in e = [e_p; e_R].
MODE_ROWS = {"pose": (0, 1, 2, 3, 4, 5), "position": (0, 1, 2), "orientation": (3, 4, 5)}

#: Default tolerances: position (m) and orientation (rad).
DEFAULT_TOLERANCE = (1e-5, 1e-5)
#: Default time budget (ms).
DEFAULT_TIMEOUT_MS = 5.0


@dataclass(frozen=True, slots=True)
class IKOptions:
    """How to solve: the same for every target of a request. Validated on construction.

    Attributes
    ----------
    frame
        The frame to place (any named frame); None: the robot's end effector.
    mode
        ``pose`` (6-D), ``position`` (orientation free) or ``orientation`` (position free).
    weights
        Optional non-negative weights of the six error components [e_p; e_R] (world axes).
        A zero weight frees that component; tolerances are checked only on the components
        with positive weight, position and orientation separately. At least one weight of
        the mode's rows must be positive.
    tolerance
        (position m, orientation rad): success when ‖e_p‖ and ‖e_R‖ (over the checked
        components) are within them.
    timeout_ms, max_iterations
        Budget per target (``time.perf_counter``) and optional cap on Jacobian evaluations.
    num_solutions
        How many distinct solutions to collect (sorted by distance to the seed).
    analytic
        Try closed forms (:mod:`app.kinematics.analytic_ik`) first where the chain admits one.
    group
        A planning group (:mod:`app.kinematics.groups`): only its joints among those that
        move the frame are active, and the default frame is its tip.
    rank_by
        Order of the distinct solutions (one per branch, :mod:`app.kinematics.ik.ranking`):
        ``seed_distance`` (smallest first), ``manipulability`` or ``clearance`` (largest
        first; needs obstacles).
    """

    frame: str | None = None
    mode: Mode = "pose"
    weights: tuple[float, ...] | None = None
    tolerance: tuple[float, float] = DEFAULT_TOLERANCE
    timeout_ms: float = DEFAULT_TIMEOUT_MS
    max_iterations: int | None = None
    num_solutions: int = 1
    analytic: bool = True
    group: str | None = None
    rank_by: str = "seed_distance"

    def __post_init__(self) -> None:
        mode = self.mode
        if mode not in MODE_ROWS:
            raise InvalidInputError(f"unknown mode {mode!r}; use one of {', '.join(MODES)}", "mode")
        if self.rank_by not in RANK_BY:
            raise InvalidInputError(
                f"unknown {self.rank_by!r}; use one of {', '.join(RANK_BY)}", "rank_by"
            )
        if self.num_solutions < 1:
            raise InvalidInputError("must be at least 1", "num_solutions")
        if not self.timeout_ms > 0.0:
            raise InvalidInputError("must be positive", "timeout_ms")
        if self.max_iterations is not None and self.max_iterations < 1:
            raise InvalidInputError("must be at least 1", "max_iterations")
        tol_p, tol_r = self.tolerance
        if not (tol_p > 0.0 and tol_r > 0.0):
            raise InvalidInputError("tolerances must be positive", "tolerance")
        if self.weights is not None:
            w = np.asarray(self.weights, dtype=float)
            if w.shape != (6,) or not np.all(np.isfinite(w)) or np.any(w < 0.0):
                raise InvalidInputError("give 6 finite, non-negative weights", "weights")
            if not any(w[i] > 0.0 for i in MODE_ROWS[mode]):
                raise InvalidInputError(f"every weight of mode {mode!r} is zero", "weights")

    def task(self) -> Task:
        """The task rows this mode and these weights drive (see :class:`Task`)."""
        if self.weights is None:
            return _TASKS[self.mode]
        rows = np.array(MODE_ROWS[self.mode], dtype=int)
        w = np.asarray(self.weights, dtype=float)[rows]
        keep = w > 0.0
        rows, w = rows[keep], w[keep]
        sw = None if np.all(w == 1.0) else np.sqrt(w)
        return Task(rows, sw, bool(np.any(rows < 3)), bool(np.any(rows >= 3)))


@dataclass(frozen=True, slots=True)
class Task:
    """The rows of e = [e_p; e_R] the solver drives, their √weights (None when all 1), and
    which errors the tolerances check (position, orientation)."""

    rows: np.ndarray
    sw: np.ndarray | None
    check_pos: bool
    check_rot: bool

    @property
    def full_pose(self) -> bool:
        """All six rows with unit weights: the error and step of the module docstring as is."""
        return self.rows.size == 6 and self.sw is None


class IKProblem(NamedTuple):
    """One validated query: what :class:`~app.kinematics.ik.search.Search` works on
    (immutable; a named tuple, built once per query at a fraction of a dataclass's cost).

    Attributes
    ----------
    robot, chain
        The robot and the solver's precomputed chain of the frame to place.
    target
        Desired placement of the frame in the root (world) frame.
    seed
        Wire configuration to start from; joints that do not support the frame keep their
        seed value in every answer.
    options, task
        The options, and the task rows they select.
    """

    robot: RobotModel
    chain: IKChain
    target: pin.SE3
    seed: np.ndarray
    options: IKOptions
    task: Task


_TASKS = {
    mode: Task(np.array(rows, dtype=int), None, rows[0] < 3, rows[-1] >= 3)
    for mode, rows in MODE_ROWS.items()
}


def frame_name(robot: RobotModel, frame: str | None) -> str:
    """``frame``, or the robot's end effector when None (UnknownNameError for a bad name)."""
    frame = frame or robot.ee_frame
    robot.frame_id(frame)
    return frame


def check_target(target: pin.SE3) -> None:
    """Refuse a target position that is not finite or beyond ±MAX_POSITION (``target.position``)."""
    x, y, z = target.translation.tolist()
    # (NaN compares false, inf is beyond the bound)
    if not (abs(x) <= MAX_POSITION and abs(y) <= MAX_POSITION and abs(z) <= MAX_POSITION):
        raise InvalidInputError(f"must be finite, within ±{MAX_POSITION:g} m", "target.position")


def target_placement(
    position: Sequence[float] | None,
    orientation: Sequence[float] | None,
    matrix: Sequence[Sequence[float]] | None,
    mode: str,
    field: str = "target",
    rpy: Sequence[float] | None = None,
    default: pin.SE3 | None = None,
) -> pin.SE3:
    """An IK target as a Pinocchio SE3, validated by :func:`~app.kinematics.placement.placement`
    (redundant components must agree); components the mode ignores may be omitted.

    Parameters
    ----------
    position, orientation, rpy, matrix
        [x, y, z] (m), the unit quaternion [x, y, z, w], [roll, pitch, yaw] (rad) and the
        4×4 homogeneous transform, in the root frame; any subset that agrees.
    mode
        The IK mode: ``pose`` needs a position and a rotation, ``position`` a position,
        ``orientation`` a rotation (the missing part is ``default``'s).
    field
        The wire name of the target (``target``, ``targets.3``) for error messages.
    default
        Where the part a mode does not need comes from (a path's previous pose); the
        identity by default.
    """
    return placement(
        position,
        orientation,
        rpy,
        matrix,
        field,
        need_position=mode != "orientation",
        need_rotation=mode != "position",
        need=f"for mode {mode!r}",
    ).se3(default)


def seed_configuration(
    robot: RobotModel,
    seed: Sequence[float] | np.ndarray | Mapping[str, float] | None,
    field: str = "seed",
) -> np.ndarray:
    """Wire seed from a list or a joint → value map (others: middle of their limits; mimic
    followers checked against their leader, :meth:`RobotModel.apply_joint_map`); default the
    middle of the joint limits. Names ``field``, ``field.4``, ``field.<joint>`` (``seed``;
    a path's ``start``)."""
    if seed is None:
        return robot.mid_range()
    if isinstance(seed, Mapping):
        return robot.apply_joint_map(robot.mid_range(), seed, field)
    return robot.configuration(seed, field=field)


def group_seed(
    robot: RobotModel,
    grp: Group | None,
    seed: Sequence[float] | np.ndarray | Mapping[str, float] | str | None,
    field: str = "seed",
) -> np.ndarray:
    """A seed with planning groups and named states (:func:`seed_configuration` otherwise).

    A string names a state of the SRDF (``"ready"``: its joints set, the others at the
    middle of their limits); with a group, a list may hold the group's joints only (the
    others at the middle of their limits).
    """
    if isinstance(seed, str):
        return state_configuration(robot, seed, grp, robot.mid_range(), field)
    if grp is not None and seed is not None and not isinstance(seed, Mapping):
        return expand(robot, grp, seed, robot.mid_range(), field)
    return seed_configuration(robot, seed, field)
