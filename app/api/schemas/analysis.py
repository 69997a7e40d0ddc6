"""Wire models of Jacobian analysis: manipulability (one and many configurations) and statics
(task rows by name vx … wz or index 0–5; references as for the Jacobian; forces in N,
moments and torques in N·m, prismatic joint forces in N)."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, BeforeValidator, Field

from app.api.schemas.common import (
    Configuration,
    ConfigurationIn,
    Finite,
    JointValue,
    Schema,
    group_field,
)
from app.api.schemas.jacobian import REFERENCE_DOC
from app.api.schemas.values import JacobianPart, JacobianReference
from app.kinematics.analysis import DEFAULT_RELATIVE_TOLERANCE

PART_DOC = (
    "Task rows: full (vx vy vz wx wy wz, default) | translation (vx vy vz) | rotation "
    "(wx wy wz). Give either part or rows."
)
ROWS_DOC = (
    'Explicit task rows by name (vx, vy, vz, wx, wy, wz) or index 0–5, e.g. ["vx", "vy"] '
    "for a planar arm in the x-y plane. Give either part or rows."
)
TOL_DOC = "Relative rank tolerance: σ_i counts toward the rank when σ_i > relative_tolerance·σ_max."


def _not_bool(value: object) -> object:
    # JSON true/false would otherwise be coerced to rows 1/0
    if isinstance(value, bool):
        raise ValueError("a row is a name (vx … wz) or an index 0–5, not a boolean")
    return value


Row = Annotated[
    str | int,
    BeforeValidator(_not_bool),
    Field(description="Row name (vx … wz) or index 0–5."),
]
#: A force, moment or joint torque: finite and at most 10¹² in magnitude (N, N·m).
Load = Annotated[Finite, Field(ge=-1e12, le=1e12)]


class TaskOptions(Schema):
    """Which frame, which Jacobian rows, which reference, which rank tolerance."""

    frame: str | None = Field(
        None, description="Frame; default the end effector (with `group`: the group's tip)."
    )
    part: JacobianPart | None = Field(None, description=PART_DOC)
    rows: list[Row] | None = Field(None, description=ROWS_DOC, max_length=6)
    reference: JacobianReference = Field("world", description=REFERENCE_DOC)
    relative_tolerance: Finite = Field(
        DEFAULT_RELATIVE_TOLERANCE, ge=0.0, lt=1.0, description=TOL_DOC
    )


class ManipulabilityRequest(ConfigurationIn, TaskOptions):
    """A configuration and the task to analyse."""


class Ellipsoid(BaseModel):
    """An ellipsoid in task space (the task's rows as coordinates)."""

    axes: list[list[float]] = Field(description="m unit axes (left singular vectors u_i).")
    half_lengths: list[float | None] = Field(
        description="Half-length along each axis; null = infinite (lost direction)."
    )


class ManipulabilityResponse(BaseModel):
    """Manipulability measures of the task Jacobian J_t = J[rows][:, joints]."""

    robot_id: str
    frame: str
    reference: JacobianReference
    q: Configuration
    rows: list[str] = Field(description="The task's Jacobian rows, in order.")
    joints: list[str] = Field(
        description="The task Jacobian's columns: the joints that move the frame."
    )
    yoshikawa: float = Field(description="∏σ_i (= √det(J_t J_tᵀ) when rows ≤ joints).")
    singular_values: list[float] = Field(description="σ_1 ≥ … ≥ σ_p, p = min(rows, joints).")
    min_singular_value: float
    inverse_condition: float = Field(description="σ_min / σ_max (0 for a zero Jacobian).")
    condition_number: float | None = Field(description="σ_max / σ_min; null when singular.")
    det_jjt: float = Field(description="det(J_t J_tᵀ); exactly 0 when rows > joints.")
    rank: int
    tolerance: float = Field(description="Absolute threshold used for the rank: σ_i > this.")
    relative_tolerance: float
    singular: bool = Field(description="rank < min(rows, joints).")
    velocity_ellipsoid: Ellipsoid = Field(description="Axes u_i, half-lengths σ_i.")
    force_ellipsoid: Ellipsoid = Field(description="Axes u_i, half-lengths 1/σ_i.")
    lost_directions: list[list[float]] = Field(
        description="Orthonormal basis of the left null space: task directions the frame "
        "cannot move in (coordinates over `rows`)."
    )
    dependent_joints: list[str] = Field(
        description="Joints whose columns take part in a linear dependency (null-space support)."
    )
    joint_null_space: list[list[float]] = Field(
        description="Orthonormal basis of the null space: joint velocities (over `joints`) "
        "that do not move the task."
    )


class ManipulabilityBatchRequest(TaskOptions):
    """Many configurations, one task."""

    configurations: list[list[JointValue]] = Field(
        description="N configurations, each one value per joint in joint order (rad, m); "
        "with `group`, rows of the group's joints only are accepted too (others neutral)."
    )
    group: str | None = group_field()


class ManipulabilityBatchResponse(BaseModel):
    """Compact arrays: entry i belongs to configuration i."""

    robot_id: str
    frame: str
    reference: JacobianReference
    rows: list[str]
    joints: list[str]
    yoshikawa: list[float]
    min_singular_value: list[float]
    max_singular_value: list[float]
    inverse_condition: list[float]
    condition_number: list[float | None] = Field(description="null where singular.")
    det_jjt: list[float]
    rank: list[int]
    singular: list[bool]


class StaticsRequest(ConfigurationIn):
    """Exactly one of wrench (→ torques) or torques (→ wrench); with `group`, the torques are
    those of the group's joints (in the group's order)."""

    frame: str | None = Field(
        None, description="Frame; default the end effector (with `group`: the group's tip)."
    )
    reference: JacobianReference = Field(
        "world",
        description="Axes of the wrench (as for the Jacobian). world: force and moment about "
        "the frame origin, world axes | local: frame axes | world_spatial: moment about the "
        "world origin.",
    )
    wrench: Annotated[list[Load], Field(min_length=6, max_length=6)] | None = Field(
        None,
        description="[fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its "
        "environment.",
    )
    torques: list[Load] | None = Field(
        None, description="Joint torques/forces in joint order (N·m, N).", max_length=1024
    )


class StaticsResponse(BaseModel):
    """τ = Jᵀ·F, forward or least-squares inverse."""

    robot_id: str
    frame: str
    reference: JacobianReference
    q: Configuration
    wrench: list[float] = Field(description="[fx, fy, fz, mx, my, mz] (N, N·m).")
    torques: list[float] = Field(description="Jᵀ·F in joint order (N·m, N).")
    joint_names: list[str]
    residual: list[float] = Field(
        description="Given torques − Jᵀ·F (zeros when the wrench was given)."
    )
    residual_norm: float
    rank: int = Field(description="Rank of the 6×n Jacobian (σ_i > 1e-10·σ_max).")
