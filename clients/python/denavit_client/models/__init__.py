"""Contains all the data models used in inputs/outputs"""

from .arc_segment import ArcSegment
from .bounds import Bounds
from .build_request import BuildRequest
from .build_request_part_type_0 import BuildRequestPartType0
from .build_request_sampling import BuildRequestSampling
from .build_request_self_collision import BuildRequestSelfCollision
from .collision_batch_request import CollisionBatchRequest
from .collision_batch_request_geometry import CollisionBatchRequestGeometry
from .collision_batch_response import CollisionBatchResponse
from .collision_pairs_response import CollisionPairsResponse
from .collision_request import CollisionRequest
from .collision_request_geometry import CollisionRequestGeometry
from .collision_request_joint_positions_type_0 import CollisionRequestJointPositionsType0
from .collision_response import CollisionResponse
from .dh_geometry_doc import DHGeometryDoc
from .dh_row_doc import DHRowDoc
from .dh_row_doc_type_type_0 import DHRowDocTypeType0
from .dh_table_doc import DHTableDoc
from .dh_table_doc_convention import DHTableDocConvention
from .dh_transform_doc import DHTransformDoc
from .dh_units_doc import DHUnitsDoc
from .dh_units_doc_angle import DHUnitsDocAngle
from .dh_units_doc_length import DHUnitsDocLength
from .ellipsoid import Ellipsoid
from .end_effector_out import EndEffectorOut
from .field_error import FieldError
from .fk_batch_request import FKBatchRequest
from .fk_batch_response import FKBatchResponse
from .fk_request import FKRequest
from .fk_request_joint_positions_type_0 import FKRequestJointPositionsType0
from .fk_response import FKResponse
from .fk_response_poses import FKResponsePoses
from .frame_out import FrameOut
from .group_out import GroupOut
from .health import Health
from .ik_batch_item import IKBatchItem
from .ik_batch_item_reason_type_0 import IKBatchItemReasonType0
from .ik_batch_item_status import IKBatchItemStatus
from .ik_batch_request import IKBatchRequest
from .ik_batch_request_collision_geometry import IKBatchRequestCollisionGeometry
from .ik_batch_request_mode import IKBatchRequestMode
from .ik_batch_request_seed_type_1 import IKBatchRequestSeedType1
from .ik_batch_response import IKBatchResponse
from .ik_request import IKRequest
from .ik_request_collision_geometry import IKRequestCollisionGeometry
from .ik_request_mode import IKRequestMode
from .ik_request_rank_by import IKRequestRankBy
from .ik_request_seed_type_1 import IKRequestSeedType1
from .ik_response import IKResponse
from .ik_response_joint_positions import IKResponseJointPositions
from .ik_response_reason_type_0 import IKResponseReasonType0
from .ik_response_status import IKResponseStatus
from .ik_solution_out import IKSolutionOut
from .ik_solution_out_joint_positions import IKSolutionOutJointPositions
from .jacobian_request import JacobianRequest
from .jacobian_request_joint_positions_type_0 import JacobianRequestJointPositionsType0
from .jacobian_request_reference import JacobianRequestReference
from .jacobian_response import JacobianResponse
from .job_list import JobList
from .job_response import JobResponse
from .job_response_status import JobResponseStatus
from .joint_limits import JointLimits
from .joint_out import JointOut
from .line_segment import LineSegment
from .manipulability_batch_request import ManipulabilityBatchRequest
from .manipulability_batch_request_part_type_0 import ManipulabilityBatchRequestPartType0
from .manipulability_batch_request_reference import ManipulabilityBatchRequestReference
from .manipulability_batch_response import ManipulabilityBatchResponse
from .manipulability_request import ManipulabilityRequest
from .manipulability_request_joint_positions_type_0 import ManipulabilityRequestJointPositionsType0
from .manipulability_request_part_type_0 import ManipulabilityRequestPartType0
from .manipulability_request_reference import ManipulabilityRequestReference
from .manipulability_response import ManipulabilityResponse
from .map_bounds import MapBounds
from .map_info import MapInfo
from .map_list import MapList
from .max_deviation import MaxDeviation
from .max_step import MaxStep
from .mimic_joint_out import MimicJointOut
from .named_state_out import NamedStateOut
from .named_state_out_joint_positions import NamedStateOutJointPositions
from .obstacle_in import ObstacleIn
from .obstacle_in_shape import ObstacleInShape
from .obstacle_out import ObstacleOut
from .obstacle_pose import ObstaclePose
from .package_upload import PackageUpload
from .pair_out import PairOut
from .pair_out_kind import PairOutKind
from .path_failure_out import PathFailureOut
from .path_failure_out_reason import PathFailureOutReason
from .path_point_out import PathPointOut
from .path_request import PathRequest
from .path_request_collision_geometry import PathRequestCollisionGeometry
from .path_request_mode import PathRequestMode
from .path_request_start_type_1 import PathRequestStartType1
from .path_response import PathResponse
from .pose import Pose
from .pose_in import PoseIn
from .problem import Problem
from .progress_out import ProgressOut
from .query_request import QueryRequest
from .query_response import QueryResponse
from .ready import Ready
from .ready_checks import ReadyChecks
from .robot_detail import RobotDetail
from .robot_files_out import RobotFilesOut
from .robot_list import RobotList
from .robot_summary_out import RobotSummaryOut
from .scene_in import SceneIn
from .scene_list import SceneList
from .scene_out import SceneOut
from .scene_summary import SceneSummary
from .statics_request import StaticsRequest
from .statics_request_joint_positions_type_0 import StaticsRequestJointPositionsType0
from .statics_request_reference import StaticsRequestReference
from .statics_response import StaticsResponse
from .target import Target
from .timing_in import TimingIn
from .timing_in_acceleration_limits_type_1 import TimingInAccelerationLimitsType1
from .timing_in_velocity_limits_type_1 import TimingInVelocityLimitsType1
from .timing_out import TimingOut
from .tolerance import Tolerance
from .urdf_upload import UrdfUpload
from .velocity_request import VelocityRequest
from .velocity_request_joint_positions_type_0 import VelocityRequestJointPositionsType0
from .velocity_request_mode import VelocityRequestMode
from .velocity_request_reference import VelocityRequestReference
from .velocity_response import VelocityResponse
from .velocity_response_direction import VelocityResponseDirection

__all__ = (
    "ArcSegment",
    "Bounds",
    "BuildRequest",
    "BuildRequestPartType0",
    "BuildRequestSampling",
    "BuildRequestSelfCollision",
    "CollisionBatchRequest",
    "CollisionBatchRequestGeometry",
    "CollisionBatchResponse",
    "CollisionPairsResponse",
    "CollisionRequest",
    "CollisionRequestGeometry",
    "CollisionRequestJointPositionsType0",
    "CollisionResponse",
    "DHGeometryDoc",
    "DHRowDoc",
    "DHRowDocTypeType0",
    "DHTableDoc",
    "DHTableDocConvention",
    "DHTransformDoc",
    "DHUnitsDoc",
    "DHUnitsDocAngle",
    "DHUnitsDocLength",
    "Ellipsoid",
    "EndEffectorOut",
    "FieldError",
    "FKBatchRequest",
    "FKBatchResponse",
    "FKRequest",
    "FKRequestJointPositionsType0",
    "FKResponse",
    "FKResponsePoses",
    "FrameOut",
    "GroupOut",
    "Health",
    "IKBatchItem",
    "IKBatchItemReasonType0",
    "IKBatchItemStatus",
    "IKBatchRequest",
    "IKBatchRequestCollisionGeometry",
    "IKBatchRequestMode",
    "IKBatchRequestSeedType1",
    "IKBatchResponse",
    "IKRequest",
    "IKRequestCollisionGeometry",
    "IKRequestMode",
    "IKRequestRankBy",
    "IKRequestSeedType1",
    "IKResponse",
    "IKResponseJointPositions",
    "IKResponseReasonType0",
    "IKResponseStatus",
    "IKSolutionOut",
    "IKSolutionOutJointPositions",
    "JacobianRequest",
    "JacobianRequestJointPositionsType0",
    "JacobianRequestReference",
    "JacobianResponse",
    "JobList",
    "JobResponse",
    "JobResponseStatus",
    "JointLimits",
    "JointOut",
    "LineSegment",
    "ManipulabilityBatchRequest",
    "ManipulabilityBatchRequestPartType0",
    "ManipulabilityBatchRequestReference",
    "ManipulabilityBatchResponse",
    "ManipulabilityRequest",
    "ManipulabilityRequestJointPositionsType0",
    "ManipulabilityRequestPartType0",
    "ManipulabilityRequestReference",
    "ManipulabilityResponse",
    "MapBounds",
    "MapInfo",
    "MapList",
    "MaxDeviation",
    "MaxStep",
    "MimicJointOut",
    "NamedStateOut",
    "NamedStateOutJointPositions",
    "ObstacleIn",
    "ObstacleInShape",
    "ObstacleOut",
    "ObstaclePose",
    "PackageUpload",
    "PairOut",
    "PairOutKind",
    "PathFailureOut",
    "PathFailureOutReason",
    "PathPointOut",
    "PathRequest",
    "PathRequestCollisionGeometry",
    "PathRequestMode",
    "PathRequestStartType1",
    "PathResponse",
    "Pose",
    "PoseIn",
    "Problem",
    "ProgressOut",
    "QueryRequest",
    "QueryResponse",
    "Ready",
    "ReadyChecks",
    "RobotDetail",
    "RobotFilesOut",
    "RobotList",
    "RobotSummaryOut",
    "SceneIn",
    "SceneList",
    "SceneOut",
    "SceneSummary",
    "StaticsRequest",
    "StaticsRequestJointPositionsType0",
    "StaticsRequestReference",
    "StaticsResponse",
    "Target",
    "TimingIn",
    "TimingInAccelerationLimitsType1",
    "TimingInVelocityLimitsType1",
    "TimingOut",
    "Tolerance",
    "UrdfUpload",
    "VelocityRequest",
    "VelocityRequestJointPositionsType0",
    "VelocityRequestMode",
    "VelocityRequestReference",
    "VelocityResponse",
    "VelocityResponseDirection",
)
