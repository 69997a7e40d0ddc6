"""Contains all the data models used in inputs/outputs"""

from .angle_unit import AngleUnit
from .arc_segment import ArcSegment
from .bounds import Bounds
from .build_request import BuildRequest
from .collision_batch_request import CollisionBatchRequest
from .collision_batch_response import CollisionBatchResponse
from .collision_geometry import CollisionGeometry
from .collision_pair_kind import CollisionPairKind
from .collision_pairs_response import CollisionPairsResponse
from .collision_request import CollisionRequest
from .collision_response import CollisionResponse
from .dh_convention import DHConvention
from .dh_geometry_doc import DHGeometryDoc
from .dh_joint_type import DHJointType
from .dh_row_doc import DHRowDoc
from .dh_table_doc import DHTableDoc
from .dh_transform_doc import DHTransformDoc
from .dh_units_doc import DHUnitsDoc
from .dynamics_batch_request import DynamicsBatchRequest
from .dynamics_batch_response import DynamicsBatchResponse
from .dynamics_request import DynamicsRequest
from .dynamics_response import DynamicsResponse
from .ellipsoid import Ellipsoid
from .end_effector_out import EndEffectorOut
from .field_error import FieldError
from .fk_batch_request import FKBatchRequest
from .fk_batch_response import FKBatchResponse
from .fk_request import FKRequest
from .fk_response import FKResponse
from .fk_response_poses import FKResponsePoses
from .frame_out import FrameOut
from .group_out import GroupOut
from .health import Health
from .ik_batch_item import IKBatchItem
from .ik_batch_request import IKBatchRequest
from .ik_batch_response import IKBatchResponse
from .ik_mode import IKMode
from .ik_rank_by import IKRankBy
from .ik_reason import IKReason
from .ik_request import IKRequest
from .ik_response import IKResponse
from .ik_solution_out import IKSolutionOut
from .ik_status import IKStatus
from .jacobian_part import JacobianPart
from .jacobian_reference import JacobianReference
from .jacobian_request import JacobianRequest
from .jacobian_response import JacobianResponse
from .job_list import JobList
from .job_response import JobResponse
from .job_status import JobStatus
from .joint_limits import JointLimits
from .joint_out import JointOut
from .joint_positions import JointPositions
from .joint_rates import JointRates
from .length_unit import LengthUnit
from .line_segment import LineSegment
from .manipulability_batch_request import ManipulabilityBatchRequest
from .manipulability_batch_response import ManipulabilityBatchResponse
from .manipulability_request import ManipulabilityRequest
from .manipulability_response import ManipulabilityResponse
from .map_bounds import MapBounds
from .map_info import MapInfo
from .map_list import MapList
from .max_deviation import MaxDeviation
from .max_payload_request import MaxPayloadRequest
from .max_payload_response import MaxPayloadResponse
from .max_payload_response_per_joint import MaxPayloadResponsePerJoint
from .max_payload_sample import MaxPayloadSample
from .max_payload_sample_per_joint import MaxPayloadSamplePerJoint
from .max_step import MaxStep
from .mimic_joint_out import MimicJointOut
from .named_state_out import NamedStateOut
from .obstacle_in import ObstacleIn
from .obstacle_out import ObstacleOut
from .obstacle_shape import ObstacleShape
from .package_upload import PackageUpload
from .pair_out import PairOut
from .path_failure_out import PathFailureOut
from .path_failure_reason import PathFailureReason
from .path_point_out import PathPointOut
from .path_request import PathRequest
from .path_response import PathResponse
from .payload_in import PayloadIn
from .payload_out import PayloadOut
from .pose import Pose
from .problem import Problem
from .progress_out import ProgressOut
from .query_request import QueryRequest
from .query_response import QueryResponse
from .reachability_sampling import ReachabilitySampling
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
from .self_collision_mode import SelfCollisionMode
from .statics_request import StaticsRequest
from .statics_response import StaticsResponse
from .timing_in import TimingIn
from .timing_in_acceleration_limits_type_1 import TimingInAccelerationLimitsType1
from .timing_in_velocity_limits_type_1 import TimingInVelocityLimitsType1
from .timing_out import TimingOut
from .tolerance import Tolerance
from .twist_reference import TwistReference
from .urdf_upload import UrdfUpload
from .velocity_direction import VelocityDirection
from .velocity_request import VelocityRequest
from .velocity_response import VelocityResponse
from .wrench_in import WrenchIn

__all__ = (
    "AngleUnit",
    "ArcSegment",
    "Bounds",
    "BuildRequest",
    "CollisionBatchRequest",
    "CollisionBatchResponse",
    "CollisionGeometry",
    "CollisionPairKind",
    "CollisionPairsResponse",
    "CollisionRequest",
    "CollisionResponse",
    "DHConvention",
    "DHGeometryDoc",
    "DHJointType",
    "DHRowDoc",
    "DHTableDoc",
    "DHTransformDoc",
    "DHUnitsDoc",
    "DynamicsBatchRequest",
    "DynamicsBatchResponse",
    "DynamicsRequest",
    "DynamicsResponse",
    "Ellipsoid",
    "EndEffectorOut",
    "FieldError",
    "FKBatchRequest",
    "FKBatchResponse",
    "FKRequest",
    "FKResponse",
    "FKResponsePoses",
    "FrameOut",
    "GroupOut",
    "Health",
    "IKBatchItem",
    "IKBatchRequest",
    "IKBatchResponse",
    "IKMode",
    "IKRankBy",
    "IKReason",
    "IKRequest",
    "IKResponse",
    "IKSolutionOut",
    "IKStatus",
    "JacobianPart",
    "JacobianReference",
    "JacobianRequest",
    "JacobianResponse",
    "JobList",
    "JobResponse",
    "JobStatus",
    "JointLimits",
    "JointOut",
    "JointPositions",
    "JointRates",
    "LengthUnit",
    "LineSegment",
    "ManipulabilityBatchRequest",
    "ManipulabilityBatchResponse",
    "ManipulabilityRequest",
    "ManipulabilityResponse",
    "MapBounds",
    "MapInfo",
    "MapList",
    "MaxDeviation",
    "MaxPayloadRequest",
    "MaxPayloadResponse",
    "MaxPayloadResponsePerJoint",
    "MaxPayloadSample",
    "MaxPayloadSamplePerJoint",
    "MaxStep",
    "MimicJointOut",
    "NamedStateOut",
    "ObstacleIn",
    "ObstacleOut",
    "ObstacleShape",
    "PackageUpload",
    "PairOut",
    "PathFailureOut",
    "PathFailureReason",
    "PathPointOut",
    "PathRequest",
    "PathResponse",
    "PayloadIn",
    "PayloadOut",
    "Pose",
    "Problem",
    "ProgressOut",
    "QueryRequest",
    "QueryResponse",
    "ReachabilitySampling",
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
    "SelfCollisionMode",
    "StaticsRequest",
    "StaticsResponse",
    "TimingIn",
    "TimingInAccelerationLimitsType1",
    "TimingInVelocityLimitsType1",
    "TimingOut",
    "Tolerance",
    "TwistReference",
    "UrdfUpload",
    "VelocityDirection",
    "VelocityRequest",
    "VelocityResponse",
    "WrenchIn",
)
