"""The SRDF semantics of a robot on the wire: groups, end effectors and named states.

Part of ``GET /robots/{robot_id}`` (and of every upload's 201): the response models and
their values, from :mod:`app.kinematics.groups`.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, Field

from app.api.schemas.common import JointPositions
from app.kinematics.groups import named_states, robot_groups
from app.kinematics.models import RobotModel


class GroupOut(BaseModel):
    """A planning group of the SRDF, resolved against the model."""

    name: str
    joints: list[str] = Field(
        description="Its configuration joints (actuated, no mimic followers), in joint order: "
        "a `q` of this length is accepted with `group`."
    )
    tip: str = Field(
        description="Its default frame: its chain's tip_link, else the parent_link of an end "
        "effector attached to it, else its deepest link."
    )


class EndEffectorOut(BaseModel):
    """An SRDF end effector: the tool group ``group`` attached at ``parent_link``."""

    name: str
    parent_link: str
    group: str
    parent_group: str | None


class NamedStateOut(BaseModel):
    """An SRDF group state: usable as an IK seed by name (``"seed": "ready"``)."""

    name: str
    group: str | None = Field(description="The group it is a state of (null if not given).")
    joint_positions: JointPositions = Field(description="Joint → value (rad or m).")


def semantics_detail(robot: RobotModel) -> dict[str, Any]:
    """The ``groups``, ``end_effectors`` and ``named_states`` of a robot's description."""
    return {
        "groups": [
            {"name": g.name, "joints": list(g.joints), "tip": g.tip}
            for g in robot_groups(robot).values()
        ],
        "end_effectors": [
            {
                "name": e.name,
                "parent_link": e.parent_link,
                "group": e.group,
                "parent_group": e.parent_group,
            }
            for e in robot.semantics.end_effectors
        ],
        "named_states": [
            {"name": s.name, "group": s.group, "joint_positions": s.joint_positions}
            for s in named_states(robot)
        ],
    }
