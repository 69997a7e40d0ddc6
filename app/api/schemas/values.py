"""The named value sets of the wire: one OpenAPI component per set, referenced everywhere.

Each value set is defined once, in the core, the storage or dh2urdf (where its meaning
lives), and named here once as a :class:`typing_extensions.TypeAliasType`: pydantic emits a
named ``$defs`` entry for it, so the OpenAPI document has one ``components/schemas`` entry
per set (a generated client one enum class) and every request or response field that
carries the set — IK status and reasons, job status, pair kind, ... — references it.
The joint map and the configuration are named the same way in :mod:`app.api.schemas.common`.

``TwistReference`` (``world``, ``local``) is not ``JacobianReference`` minus one value: a
twist is expressed in the world or the frame's axes, while a Jacobian's ``world_spatial``
(the spatial velocity at the root's origin) has no twist counterpart in /velocity.
"""

from __future__ import annotations

from typing import Literal

from typing_extensions import TypeAliasType

from app.kinematics.analysis import Part
from app.kinematics.collision import GEOMETRY_MODES, PAIR_KINDS
from app.kinematics.ik.failure import REASONS
from app.kinematics.ik.problem import RANK_BY, Mode, Status
from app.kinematics.jacobian import TWIST_REFERENCES, Reference
from app.kinematics.obstacles import SHAPES
from app.kinematics.paths.failures import PATH_REASONS
from app.kinematics.reachability.spec import SAMPLINGS, SELF_COLLISION_MODES
from app.kinematics.velocity import DIRECTIONS
from app.storage.build_jobs import JOB_STATUSES
from dh2urdf.joint import Convention, JointType
from dh2urdf.parse import ANGLE_UNITS, LENGTH_UNITS

IKMode = TypeAliasType("IKMode", Mode)
IKStatus = TypeAliasType("IKStatus", Status)
IKReason = TypeAliasType("IKReason", Literal[REASONS])  # type: ignore[valid-type]
IKRankBy = TypeAliasType("IKRankBy", Literal[RANK_BY])  # type: ignore[valid-type]
PathFailureReason = TypeAliasType(
    "PathFailureReason",
    Literal[PATH_REASONS],  # type: ignore[valid-type]
)
CollisionGeometry = TypeAliasType(
    "CollisionGeometry",
    Literal[GEOMETRY_MODES],  # type: ignore[valid-type]
)
CollisionPairKind = TypeAliasType("CollisionPairKind", Literal[PAIR_KINDS])  # type: ignore[valid-type]
ObstacleShape = TypeAliasType("ObstacleShape", Literal[SHAPES])  # type: ignore[valid-type]
JacobianReference = TypeAliasType("JacobianReference", Reference)
TwistReference = TypeAliasType("TwistReference", Literal[TWIST_REFERENCES])  # type: ignore[valid-type]
JacobianPart = TypeAliasType("JacobianPart", Part)
VelocityDirection = TypeAliasType("VelocityDirection", Literal[DIRECTIONS])  # type: ignore[valid-type]
ReachabilitySampling = TypeAliasType(
    "ReachabilitySampling",
    Literal[SAMPLINGS],  # type: ignore[valid-type]
)
SelfCollisionMode = TypeAliasType(
    "SelfCollisionMode",
    Literal[SELF_COLLISION_MODES],  # type: ignore[valid-type]
)
JobStatus = TypeAliasType("JobStatus", Literal[JOB_STATUSES])  # type: ignore[valid-type]
DHConvention = TypeAliasType("DHConvention", Convention)
DHJointType = TypeAliasType("DHJointType", JointType)
LengthUnit = TypeAliasType("LengthUnit", Literal[tuple(LENGTH_UNITS)])  # type: ignore[misc]
AngleUnit = TypeAliasType("AngleUnit", Literal[ANGLE_UNITS])  # type: ignore[valid-type]
