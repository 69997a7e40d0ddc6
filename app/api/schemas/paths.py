"""The wire shapes of Cartesian paths: POST /robots/{robot_id}/ik/path."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, Field

from app.api.schemas.common import Configuration, Finite, JointPositions, Schema
from app.api.schemas.ik import IKTaskIn, Positive
from app.api.schemas.poses import Pose
from app.api.schemas.timing import TimingIn, TimingOut
from app.api.schemas.values import IKMode, PathFailureReason


class MaxStep(Schema):
    """Largest Cartesian step between consecutive waypoints of the interpolated path."""

    position: Positive = Field(0.01, le=10.0, description="Metres (default 0.01).")
    orientation: Positive = Field(0.05, le=3.2, description="Radians (default 0.05).")


class MaxDeviation(Schema):
    """Largest deviation from the Cartesian path of the joint-linear motion between two
    returned points (the path is densified until it holds)."""

    position: Positive = Field(1e-3, le=10.0, description="Metres (default 0.001).")
    orientation: Positive = Field(1e-2, le=3.2, description="Radians (default 0.01).")


class LineSegment(Schema):
    """A straight line from the previous pose to `to` (orientation by slerp)."""

    type: Literal["line"]
    to: Pose


class ArcSegment(Schema):
    """A circular arc from the previous pose through `via` to `to`; orientation by slerp to
    `via`'s on the first part of the arc and to `to`'s on the second."""

    type: Literal["arc"]
    via: Pose
    to: Pose


Segment = Annotated[LineSegment | ArcSegment, Field(discriminator="type")]


class PathRequest(IKTaskIn):
    """A Cartesian path from a start configuration: waypoints or segments (exactly one)."""

    start: list[Finite] | JointPositions | Annotated[str, Field(max_length=256)] = Field(
        description="Start configuration: one value per joint (joint order; with `group`, one "
        "per joint of the group is accepted too), joint → value (others: middle of their "
        'limits), or a named state of the SRDF (e.g. "ready"). The path starts at the '
        "frame's pose there; it is the first point of the answer."
    )
    waypoints: list[Pose] | None = Field(
        None,
        min_length=1,
        max_length=10_000,
        description="Poses to pass through, joined by straight lines (instead of segments); "
        "each a Pose as the `target` of /ik (an FK pose as is; redundant fields must agree).",
    )
    segments: list[Segment] | None = Field(
        None,
        min_length=1,
        max_length=10_000,
        description="Lines and arcs, each from the previous segment's end (instead of "
        "waypoints). A target's missing orientation (mode position) or position (mode "
        "orientation) keeps the previous pose's.",
    )
    max_step: MaxStep = Field(default_factory=MaxStep)
    max_joint_step: Positive = Field(
        0.1,
        le=10.0,
        description="Largest move of any one joint between consecutive points (rad or m, "
        "default 0.1): a larger one is a jump (another branch, or a singularity), and the "
        "path stops there instead of returning it.",
    )
    max_deviation: MaxDeviation = Field(default_factory=MaxDeviation)
    branch: str | None = Field(
        None,
        max_length=256,
        description="Branch the whole path must stay on (the `branch` of an IK solution, e.g. "
        '"shoulder_left/elbow_up/wrist_noflip"); the start must be on it. Without it, the '
        "path keeps the start's branch anyway.",
    )
    timing: TimingIn | None = Field(
        None,
        description="Time-parameterize the joint path (time-optimal under joint velocity and "
        "acceleration limits, at rest at both ends): the answer's `timing` holds the time, "
        "velocity and acceleration of every point.",
    )


class PathPointOut(BaseModel):
    """One point of the joint path, verified by forward kinematics."""

    q: Configuration = Field(description="Configuration in joint order (rad, m).")
    position_error: float = Field(description="‖p − p_path(s)‖ (m).")
    orientation_error: float = Field(description="Rotation angle to the path's pose (rad).")
    s: float = Field(description="Path parameter in [0, 1] of this point's pose.")


class PathFailureOut(BaseModel):
    """The first point that could not be reached, and why."""

    index: int = Field(description="Index of the failed waypoint of the interpolated path.")
    s: float = Field(description="Its path parameter in [0, 1].")
    reason: PathFailureReason = Field(
        description="Why the path stops there: an IK reason, or joint_step (a jump larger "
        "than max_joint_step) | branch (the point is on another branch)."
    )
    detail: str = Field(description="What went wrong, with numbers.")
    q: Configuration = Field(description="Best configuration found for that point.")
    position_error: float = Field(description="Of q (m).")
    orientation_error: float = Field(description="Of q (rad).")


class PathResponse(BaseModel):
    """The joint path as far as it goes; `failure` says where and why it stopped."""

    robot_id: str
    frame: str
    mode: IKMode
    joint_names: list[str]
    fraction: float = Field(description="Path parameter s reached (1.0: the whole path).")
    points: list[PathPointOut] = Field(description="The start, then every accepted point.")
    failure: PathFailureOut | None
    branch: str | None = Field(description="The start's branch label (null: no closed form).")
    waypoints: int = Field(description="Points of the interpolated path (before densifying).")
    iterations: int = Field(description="Solver iterations over the whole path.")
    solve_time_ms: float
    solver_version: str
    timing: TimingOut | None = Field(
        description="With the request's `timing`: times, velocities and accelerations of the "
        "points (null otherwise)."
    )
