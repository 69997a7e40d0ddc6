"""GET /robots and GET /robots/{robot_id}: what robots exist and what they are made of."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Depends
from pydantic import BaseModel, Field

from app.api.common import ORJSONResponse, RobotId, registry
from app.api.errors import ERROR_RESPONSES
from app.kinematics.collision import collision_link_pairs
from app.registry import Registry

router = APIRouter(prefix="/robots", tags=["robots"])


class RobotSummaryOut(BaseModel):
    """One robot in the list."""

    id: str = Field(description="Robot id, used in every /robots/{robot_id} URL.")
    name: str = Field(description="Human-readable name.")
    source: str = Field(description="example-robot-data | dh | upload.")
    joints: int = Field(description="Number of actuated joints (length of a configuration).")
    description: str = Field("", description="Short description.")


class RobotList(BaseModel):
    """All robots the service knows."""

    robots: list[RobotSummaryOut]


class JointLimits(BaseModel):
    """Joint limits, SI units; ``null`` where the URDF gives none (continuous joints)."""

    lower: float | None = Field(description="Lower position limit (rad or m).")
    upper: float | None = Field(description="Upper position limit (rad or m).")
    velocity: float | None = Field(description="Velocity limit (rad/s or m/s).")
    effort: float | None = Field(description="Effort limit (N·m or N).")


class JointOut(BaseModel):
    """An actuated joint, in configuration order."""

    name: str
    type: str = Field(description="revolute | prismatic | continuous.")
    parent: str = Field(description="Parent link.")
    child: str = Field(description="Child link.")
    axis: list[float] = Field(description="Joint axis in the joint frame (URDF <axis>).")
    limits: JointLimits
    continuous: bool = Field(description="Unbounded revolute joint (one angle on the wire).")


class FrameOut(BaseModel):
    """A named frame."""

    name: str
    kind: str = Field(description="link | fixed (URDF fixed joint) | joint.")
    parent_joint: str | None = Field(description="The actuated joint that moves it, if any.")


class RobotDetail(BaseModel):
    """Everything a client needs to talk about a robot."""

    id: str
    name: str
    source: str
    description: str
    joints: list[JointOut] = Field(description="Actuated joints in configuration order.")
    frames: list[FrameOut] = Field(description="Every named frame (links and fixed frames).")
    end_effector: str = Field(description="Default frame of fk, jacobian and ik.")
    neutral: list[float] = Field(description="Neutral configuration (0, clipped to limits).")
    has_collision_geometry: bool = Field(description="Whether the URDF has <collision>.")
    collision_pairs: list[list[str]] = Field(
        description="Self-collision link pairs [a, b] that collision checks test (same-body, "
        "adjacent and SRDF-disabled pairs removed)."
    )


@router.get("", operation_id="list_robots", response_model=RobotList)
async def list_robots(reg: Annotated[Registry, Depends(registry)]) -> ORJSONResponse:
    """List every robot: catalog robots, DH robots and user-added ones."""
    return ORJSONResponse(
        {
            "robots": [
                {
                    "id": s.id,
                    "name": s.name,
                    "source": s.source,
                    "joints": s.joints,
                    "description": s.description,
                }
                for s in reg.summaries()
            ]
        }
    )


@router.get(
    "/{robot_id}",
    operation_id="get_robot",
    response_model=RobotDetail,
    responses={404: ERROR_RESPONSES[404]},
)
def get_robot(robot_id: RobotId, reg: Annotated[Registry, Depends(registry)]) -> ORJSONResponse:
    """Describe a robot: joints in order, frames, default end effector, neutral configuration.

    Runs in the thread pool: the first request for a robot parses its URDF.
    """
    robot = reg.get(robot_id)
    return ORJSONResponse(
        {
            "id": robot.id,
            "name": robot.name,
            "source": robot.source,
            "description": robot.description,
            "joints": [robot.describe_joint(j) for j in robot.joints],
            "frames": [
                {"name": f.name, "kind": f.kind, "parent_joint": f.parent_joint}
                for f in robot.frames
            ],
            "end_effector": robot.ee_frame,
            "neutral": robot.neutral().tolist(),
            "has_collision_geometry": robot.has_collision_geometry,
            "collision_pairs": [list(p) for p in collision_link_pairs(robot)],
        }
    )
