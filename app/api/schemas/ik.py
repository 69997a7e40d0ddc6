"""The wire shapes of inverse kinematics: requests and responses of /ik, /ik/batch (and the
task part shared with /ik/path)."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, Field

from app.api.schemas.common import Configuration, Finite, JointPositions, Schema, group_field
from app.api.schemas.poses import Pose
from app.api.schemas.scenes import ObstacleIn
from app.api.schemas.values import (
    CollisionGeometry,
    IKMode,
    IKRankBy,
    IKReason,
    IKStatus,
)
from app.kinematics.ik.problem import (
    DEFAULT_TIMEOUT_MS,
    DEFAULT_TOLERANCE,
)

NonNegative = Annotated[float, Field(ge=0.0, allow_inf_nan=False, strict=True)]
Positive = Annotated[float, Field(gt=0.0, allow_inf_nan=False, strict=True)]

REASON_DOC = (
    "Why no solution was found (null on success): unreachable (the target position is "
    "beyond the chain's reach bound; the search is skipped) | joint_limits (reached only "
    "outside the limits, or the best configuration is pinned at a limit) | collision (every "
    "solution found collides) | singular (the search stalled at a singular configuration) | "
    "timeout (the time budget or max_iterations ended the search). See docs/ik.md."
)
SOLVER_VERSION_DOC = (
    "The solver's name and version: with random_seed (and max_iterations), the same request "
    "gives the same answer, bit for bit, on any worker of the same solver_version."
)

TARGET_DOC = (
    "Desired placement of the frame in the root (world) frame; a pose an answer returns "
    "(e.g. FK's) is accepted as is. Mode pose needs a position (`position` or `matrix`) and "
    "a rotation (`orientation`, `rpy` or `matrix`); mode position a position; mode "
    "orientation a rotation. Redundant fields must agree within 1e-9."
)
MODE_DOC = (
    "pose (default): full 6-D pose | position: the frame origin only, orientation free "
    "(3 task rows, fine for arms with fewer than 6 joints) | orientation: the rotation only."
)


class Tolerance(Schema):
    """Success thresholds."""

    position: Positive = Field(
        DEFAULT_TOLERANCE[0], description="Largest position error ‖p − p_t‖ (m)."
    )
    orientation: Positive = Field(
        DEFAULT_TOLERANCE[1], description="Largest rotation angle to the target (rad)."
    )


class IKTaskIn(Schema):
    """What to solve and how, shared by single IK, batch IK and paths (the wire shape of
    :class:`~app.kinematics.ik.problem.IKOptions` and of collision-aware IK)."""

    frame: str | None = Field(
        None, description="Frame to place; default the end effector (with `group`: its tip)."
    )
    group: str | None = group_field()
    mode: IKMode = Field("pose", description=MODE_DOC)
    weights: Annotated[list[NonNegative], Field(min_length=6, max_length=6)] | None = Field(
        None,
        description="Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); "
        "0 frees a component (not checked against the tolerance).",
    )
    tolerance: Tolerance = Field(default_factory=Tolerance)
    timeout_ms: Positive = Field(
        DEFAULT_TIMEOUT_MS,
        description="Time budget (ms) per target; capped by the server's ik_max_timeout_ms.",
    )
    max_iterations: int | None = Field(
        None, ge=1, le=10_000_000, description="Cap on solver iterations (Jacobian evaluations)."
    )
    avoid_collisions: bool = Field(
        False,
        strict=True,
        description="Return only solutions free of self-collision and of collision with "
        "`obstacles` / `scene` (other branches and restarts are searched within the budget).",
    )
    obstacles: list[ObstacleIn] | None = Field(
        None, max_length=1000, description="With avoid_collisions: obstacles (root frame)."
    )
    scene: str | None = Field(
        None, max_length=64, description="With avoid_collisions: a stored scene's name."
    )
    margin: NonNegative = Field(
        0.0, le=10.0, description="With avoid_collisions: clearance (m) a solution must keep."
    )
    collision_geometry: CollisionGeometry = Field(
        "mesh", description="With avoid_collisions: meshes, or their convex hulls (faster)."
    )
    random_seed: int | None = Field(
        None,
        ge=0,
        le=2**63 - 1,
        strict=True,
        description="Seed of the random restarts: the same request gives the same answer, bit "
        "for bit, on any worker (unless the time budget ends the search: give max_iterations "
        "for a budget that does not depend on the machine's speed). Default: a fixed table of "
        "restarts, also reproducible.",
    )


class IKOptionsIn(IKTaskIn):
    """Options shared by single and batch IK: the task and a seed."""

    # Finite, not JointValue: the union's validation errors would be named
    # seed.list[constrained-float].4; seed_configuration checks the bound, naming seed.4.
    seed: list[Finite] | JointPositions | Annotated[str, Field(max_length=256)] | None = Field(
        None,
        description="Start configuration: one value per joint (joint order; with `group`, one "
        "per joint of the group is accepted too), joint → value (others: middle of their "
        'limits), or the name of a named state of the SRDF (e.g. "ready"; GET '
        "/robots/{id} lists them). Default: the middle of the joint limits. Values within "
        "±10000 (rad or m), as every configuration. IK answers always hold every joint.",
    )


class IKRequest(IKOptionsIn):
    """One IK query."""

    target: Pose = Field(description=TARGET_DOC)
    num_solutions: int = Field(
        1,
        ge=1,
        le=64,
        description="Distinct solutions wanted: one per branch (shoulder/elbow/wrist flags "
        "where the arm has them, else clusters in joint space; see docs/ik.md).",
    )
    rank_by: IKRankBy = Field(
        "seed_distance",
        description="Order of the solutions: seed_distance (smallest largest-joint move "
        "first) | manipulability (largest Yoshikawa measure first) | clearance (largest "
        "distance to the obstacles first; needs avoid_collisions with obstacles or a scene).",
    )


class IKSolutionOut(BaseModel):
    """A verified solution."""

    q: Configuration = Field(description="Configuration in joint order (rad, m).")
    joint_positions: JointPositions
    position_error: float = Field(description="‖p − p_t‖ (m), by forward kinematics.")
    orientation_error: float = Field(description="Rotation angle to the target (rad).")
    branch: str = Field(
        description='Its branch: flags such as "shoulder_left/elbow_up/wrist_noflip" '
        '(UR-type and spherical-wrist 6R arms; planar 2-link arms: "elbow_up"/"elbow_down"), '
        'else "cluster_<k>" (joint-space clusters, cluster_0 nearest the seed).'
    )
    seed_distance: float = Field(
        description="Largest single-joint move from the seed (rad or m; continuous joints "
        "around the circle)."
    )
    manipulability: float = Field(
        description="Yoshikawa measure ∏σ_i of the frame Jacobian over the moving joints."
    )
    clearance: float | None = Field(
        description="With obstacles: smallest robot–obstacle distance (m), else null."
    )


class IKResponse(BaseModel):
    """Result; no solution is not an error (success false, best configuration found)."""

    robot_id: str
    frame: str
    mode: IKMode
    success: bool
    status: IKStatus
    q: Configuration = Field(description="Best configuration (first solution, or lowest error).")
    joint_positions: JointPositions
    position_error: float = Field(description="Of q: ‖p − p_t‖ (m).")
    orientation_error: float = Field(description="Of q: rotation angle to the target (rad).")
    solutions: list[IKSolutionOut] = Field(
        description="Distinct solutions, one per branch, in rank_by order."
    )
    iterations: int
    restarts: int
    solve_time_ms: float
    method: str = Field(description="analytic | numeric | analytic+numeric")
    reason: IKReason | None = Field(description=REASON_DOC)
    detail: str | None = Field(description="The reason in a sentence, with numbers.")
    solver_version: str = Field(description=SOLVER_VERSION_DOC)


class IKBatchRequest(IKOptionsIn):
    """Many targets for one frame."""

    targets: list[Pose] = Field(
        min_length=1, description="Targets, solved in order. Each as `target` of /ik."
    )
    chain_seeds: bool = Field(
        True,
        description="Seed each target with the previous solution (trajectories); false: every "
        "target starts from `seed`, the targets are solved independently (spread over the "
        "server's batch worker processes), and with random_seed target i draws its restarts "
        "from its own generator, child i of SeedSequence(random_seed), so answers do not "
        "depend on how the batch is split.",
    )


class IKBatchItem(BaseModel):
    """Result for one target."""

    success: bool
    status: IKStatus
    q: Configuration
    position_error: float
    orientation_error: float
    iterations: int
    restarts: int
    solve_time_ms: float
    reason: IKReason | None = Field(description=REASON_DOC)
    detail: str | None = Field(description="The reason in a sentence, with numbers.")


class IKBatchResponse(BaseModel):
    """Results in target order."""

    robot_id: str
    frame: str
    mode: IKMode
    joint_names: list[str]
    solved: int = Field(description="How many targets succeeded.")
    results: list[IKBatchItem]
    total_time_ms: float
    solver_version: str = Field(description=SOLVER_VERSION_DOC)
