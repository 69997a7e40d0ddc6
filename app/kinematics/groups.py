"""Planning groups of a robot: which joints a request moves, its default frame, named states.

A :class:`Group` is an SRDF group (:mod:`app.kinematics.semantics`) resolved against the
robot's model: its configuration joints (actuated, not mimic followers) in the robot's
joint order (the order of ``GET /robots/{id}``), their wire indices, and its tip.

With a group, a request

- may give ``q`` (or ``seed``) as the group's joints only, in the group's joint order
  (:func:`configuration`; the full-length form is still accepted); the other joints take the
  ``base`` configuration's values (the seed's for IK, neutral elsewhere);
- defaults its frame to the group's tip (:func:`default_frame`);
- moves only the group's joints among those that move the frame
  (:meth:`RobotModel.supporting_joints` with ``among``): Jacobian columns, IK's active
  joints, manipulability and velocity columns.

Named states (``<group_state>``) are configurations by name (:func:`state_configuration`),
e.g. an IK ``"seed": "ready"``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel, check_joint_value, check_joint_values
from app.kinematics.semantics import NamedState, resolve, usable_states


@dataclass(frozen=True, slots=True)
class Group:
    """A planning group on a robot.

    Attributes
    ----------
    name
        The SRDF group name.
    joints
        Its configuration joints, in the robot's joint order.
    indices
        Their wire indices (positions in a full configuration).
    tip
        Its default frame (module :mod:`app.kinematics.semantics` states the rule).
    """

    name: str
    joints: tuple[str, ...]
    indices: np.ndarray
    tip: str

    @property
    def size(self) -> int:
        """Number of configuration joints."""
        return len(self.joints)


#: The model's lazy-cache keys of its groups and named states.
GROUPS_KEY: LazyKey[dict] = LazyKey("groups", dict)
STATES_KEY: LazyKey[tuple] = LazyKey("groups.states", tuple)


def robot_groups(robot: RobotModel) -> dict[str, Group]:
    """The robot's groups by name, in SRDF order (built once per model)."""
    return robot.lazy(GROUPS_KEY, _build_groups)


def _build_groups(robot: RobotModel) -> dict[str, Group]:
    resolved = resolve(robot.semantics, robot.urdf_joints, strict=False)
    out: dict[str, Group] = {}
    for name, g in resolved.items():
        idx = sorted(robot.joint_index(j) for j in g.joints if j in robot.joint_names)
        tip = g.tip if g.tip is not None and g.tip in robot.frame_names else robot.ee_frame
        out[name] = Group(
            name, tuple(robot.joint_names[i] for i in idx), np.array(idx, dtype=int), tip
        )
    return out


def group(robot: RobotModel, name: str | None, field: str = "group") -> Group | None:
    """The group called ``name`` (``None`` for ``None``); unknown: 422 listing the groups."""
    if name is None:
        return None
    groups = robot_groups(robot)
    g = groups.get(name)
    if g is None:
        known = ", ".join(map(repr, groups)) if groups else "none (the robot has no SRDF groups)"
        raise InvalidInputError(f"unknown group {name!r}; the robot's groups: {known}", field)
    return g


def default_frame(robot: RobotModel, grp: Group | None, frame: str | None) -> str:
    """``frame`` if given, else the group's tip, else the robot's end effector."""
    if frame:
        return frame
    return grp.tip if grp is not None else robot.ee_frame


def _length_error(robot: RobotModel, grp: Group, got: object, field: str) -> InvalidInputError:
    return InvalidInputError(
        f"expected {grp.size} values (the joints of group {grp.name!r}: "
        f"{', '.join(grp.joints)}) or {robot.n} (one per joint: {', '.join(robot.joint_names)}), "
        f"got {got}",
        field,
    )


def expand(
    robot: RobotModel,
    grp: Group,
    values: Sequence[float] | np.ndarray,
    base: np.ndarray,
    field: str = "q",
) -> np.ndarray:
    """A full wire configuration from the group's joints only (or a full one, as is).

    ``values`` holds either one value per group joint (group order; the other joints take
    ``base``'s values) or one per robot joint. Values are checked like every configuration.
    """
    arr = np.asarray(values, dtype=float)
    if arr.ndim != 1 or arr.shape[0] not in (grp.size, robot.n):
        raise _length_error(robot, grp, arr.shape[0] if arr.ndim == 1 else arr.shape, field)
    check_joint_values(arr, field)
    if arr.shape[0] == robot.n:
        return arr
    out = np.array(base, dtype=float)
    out[grp.indices] = arr
    return out


def expand_rows(robot: RobotModel, grp: Group | None, rows: np.ndarray) -> np.ndarray:
    """Checked batch rows (N, n) or, with a group, (N, group size) → (N, n), others neutral."""
    if grp is None or rows.shape[1] == robot.n:
        return rows
    out = np.tile(robot.neutral(), (rows.shape[0], 1))
    out[:, grp.indices] = rows
    return out


def row_width(robot: RobotModel, grp: Group | None, rows: Sequence[Sequence[float]]) -> int:
    """The width a batch's rows must have: the robot's, or the group's when the first row has
    the group's length (rows of the wrong width are then refused by the batch check)."""
    if grp is not None and len(rows) and len(rows[0]) == grp.size:
        return grp.size
    return robot.n


def configuration(
    robot: RobotModel,
    grp: Group | None,
    q: Sequence[float] | np.ndarray | None = None,
    joint_positions: Mapping[str, float] | None = None,
    *,
    base: np.ndarray | None = None,
    field: str = "q",
    map_field: str = "joint_positions",
) -> np.ndarray:
    """A validated wire configuration, the group-aware form of
    :meth:`RobotModel.configuration`.

    Without a group, or with a full-length ``q`` or a ``joint_positions`` map, it is
    :meth:`RobotModel.configuration`'s answer. With a group and a ``q`` of the group's
    length, the group's joints take ``q`` and the others ``base`` (default neutral).
    """
    if grp is None or q is None or joint_positions is not None:
        return robot.configuration(q, joint_positions, field=field, map_field=map_field)
    return expand(robot, grp, q, robot.neutral() if base is None else base, field)


def named_states(robot: RobotModel) -> tuple[NamedState, ...]:
    """The SRDF's usable named states (``<group_state>``), in document order (a catalog
    state beyond the joint limits is left out: :func:`~app.kinematics.semantics.usable_states`)."""
    return robot.lazy(STATES_KEY, lambda r: usable_states(r.semantics, r.urdf_joints))


def state_configuration(
    robot: RobotModel, name: str, grp: Group | None, base: np.ndarray, field: str = "seed"
) -> np.ndarray:
    """The configuration of named state ``name``: ``base`` with the state's joints set.

    With several states of that name (for different groups), the one of ``grp`` is taken,
    else the first. Mimic followers in the state are skipped (they follow their leader).
    Unknown name: 422 naming ``field`` and listing the states.
    """
    matches = [s for s in named_states(robot) if s.name == name]
    if not matches:
        names = sorted({s.name for s in named_states(robot)})
        known = ", ".join(map(repr, names)) if names else "none (the robot's SRDF names none)"
        raise InvalidInputError(f"unknown named state {name!r}; the robot's states: {known}", field)
    state = next((s for s in matches if grp is not None and s.group == grp.name), matches[0])
    out = np.array(base, dtype=float)
    for joint, value in state.joint_positions.items():
        if joint in robot.joint_names:
            out[robot.joint_index(joint)] = check_joint_value(value, f"{field}.{joint}")
    return out
