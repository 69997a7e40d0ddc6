"""Wire models of robots: the list, a robot's description (joints in joint order, limits in
SI units, frames, semantics, files), and the bodies of robot writes (DH tables, URDF)."""

from __future__ import annotations

from pydantic import BaseModel, Field

from app.api.schemas.common import Schema, Text, Vec3Out
from app.api.schemas.semantics import EndEffectorOut, GroupOut, NamedStateOut
from app.api.schemas.values import AngleUnit, DHConvention, DHJointType, LengthUnit
from app.storage.store import ID_PATTERN


class RobotSummaryOut(BaseModel):
    """One robot in the list."""

    id: str = Field(description="Robot id, used in every /robots/{robot_id} URL.")
    name: str = Field(description="Human-readable name.")
    source: str = Field(description="example-robot-data | dh | upload | package.")
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
    axis: Vec3Out = Field(description="Joint axis in the joint frame (URDF <axis>).")
    limits: JointLimits
    continuous: bool = Field(description="Unbounded revolute joint (one angle on the wire).")


class MimicJointOut(BaseModel):
    """A mimic joint: it follows its leader and is not a configuration entry."""

    name: str
    type: str = Field(description="revolute | prismatic (the URDF type).")
    leader: str = Field(description="The actuated joint it follows.")
    multiplier: float = Field(description="value = multiplier × value(leader) + offset.")
    offset: float = Field(description="Offset (rad or m).")


class FrameOut(BaseModel):
    """A named frame."""

    name: str
    kind: str = Field(description="link | fixed (URDF fixed joint) | joint.")
    parent_joint: str | None = Field(description="The actuated joint that moves it, if any.")


class RobotFilesOut(BaseModel):
    """Where a viewer fetches the files (meshes, textures) a robot's URDF names."""

    uri_prefix: str = Field(
        description="Mesh URIs of the URDF that start with this prefix are files served here."
    )
    url: str = Field(
        description="Replace uri_prefix by this URL path (GET /robots/{robot_id}/files/{path})."
    )


class RobotDetail(BaseModel):
    """Everything a client needs to talk about a robot."""

    id: str
    name: str
    source: str
    description: str
    joints: list[JointOut] = Field(description="Actuated joints in configuration order.")
    mimic_joints: list[MimicJointOut] = Field(
        description="Mimic joints (URDF <mimic>): not in configurations, moved by their "
        "leader. A joint_positions or seed map may name them (a ROS JointState of the whole "
        "robot) when the value is multiplier × leader + offset within 1e-9 (the leader's "
        "value from the same map, else its default)."
    )
    frames: list[FrameOut] = Field(description="Every named frame (links and fixed frames).")
    end_effector: str = Field(
        description="Default frame of fk, jacobian and ik (the default tip): the ee_frame given "
        "at upload (or the catalog's choice), else the parent_link of the SRDF's first end "
        "effector, else the tip of the longest serial chain that is not a gripper finger (a "
        "finger: a link moved by one of at least two sibling branches made only of prismatic "
        "and mimic joints; among links held by the same joint, a link without geometry such "
        "as a TCP or tool0 first, then the farthest), else the deepest link."
    )
    groups: list[GroupOut] = Field(description="SRDF planning groups (`group` in requests).")
    end_effectors: list[EndEffectorOut] = Field(description="SRDF end effectors.")
    named_states: list[NamedStateOut] = Field(description="SRDF group states (IK seeds).")
    neutral: list[float] = Field(description="Neutral configuration (0, clipped to limits).")
    has_collision_geometry: bool = Field(description="Whether the URDF has <collision>.")
    collision_pairs: list[list[str]] = Field(
        description="Self-collision link pairs [a, b] that collision checks test (same-body, "
        "adjacent and SRDF-disabled pairs removed)."
    )
    files: RobotFilesOut | None = Field(
        None,
        description="How the URDF's mesh URIs map to GET /robots/{robot_id}/files/{path} "
        "(catalog and package robots; null for others).",
    )


# ---------------------------------------------------------------------- DH table documents
class DHUnitsDoc(Schema):
    """Units of the table's numbers (the service converts to SI on import)."""

    length: LengthUnit = Field("m", description="Unit of a, d, xyz, limits.")
    angle: AngleUnit = Field("rad", description="Unit of alpha, theta, rpy, limits.")


class DHTransformDoc(Schema):
    """A fixed transform: translation ``xyz`` then rotation ``rpy`` (R = Rz·Ry·Rx)."""

    xyz: list[float] | None = Field([0.0, 0.0, 0.0], min_length=3, max_length=3)
    rpy: list[float] | None = Field([0.0, 0.0, 0.0], min_length=3, max_length=3)


class DHGeometryDoc(Schema):
    """Generated capsule geometry."""

    radius: float | None = Field(0.02, ge=0, description="Capsule radius in metres (0: none).")


class DHRowDoc(Schema):
    """One row: joint i's DH parameters."""

    name: Text | None = Field(None, description="Joint name (default j<i>, 1-based).")
    type: DHJointType | None = Field("revolute", description="Joint kind (null: revolute).")
    a: float = Field(description="Link length (a_i; a_{i-1} in the modified convention).")
    alpha: float = Field(description="Link twist (α_i; α_{i-1} in the modified convention).")
    d: float = Field(description="Link offset; the constant part for a prismatic joint.")
    theta: float = Field(description="Joint angle offset (θ = q + theta for revolute joints).")
    lower: float | None = Field(None, description="Lower limit of q (table units).")
    upper: float | None = Field(None, description="Upper limit of q (table units).")
    velocity: float | None = Field(None, gt=0, description="Velocity limit (units per second).")
    effort: float | None = Field(None, gt=0, description="Effort limit (N·m or N).")
    mass: float | None = Field(
        None,
        ge=0,
        description="Mass of the link the row moves (kg, always SI); needed with com or "
        "inertia. Rows without it give a link without inertia (dynamics answer 422 "
        "missing-inertia).",
    )
    com: list[float] | None = Field(
        None,
        min_length=3,
        max_length=3,
        description="The link's centre of mass [x, y, z] in frame i, the DH frame at the end "
        "of the row (as the Robotics Toolbox's r), in the table's length unit; default 0.",
    )
    inertia: list[float] | None = Field(
        None,
        min_length=6,
        max_length=6,
        description="The link's rotational inertia about its centre of mass in frame i's "
        "axes, [ixx, ixy, ixz, iyy, iyz, izz] (kg·m², always SI): positive semi-definite, "
        "each principal moment at most the sum of the other two; default 0 (a point mass).",
    )


class DHTableDoc(Schema):
    """A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type: application/yaml``).

    ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
    Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
    DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
    dh_n·T_tool.
    """

    name: str = Field(
        pattern=ID_PATTERN.pattern, description="Robot id: 1-64 of a-z, 0-9, '_' and '-'."
    )
    description: Text | None = Field("", max_length=1000)
    convention: DHConvention
    units: DHUnitsDoc | None = Field(default_factory=DHUnitsDoc)
    base: DHTransformDoc | None = Field(None, description="World → DH frame 0.")
    tool: DHTransformDoc | None = Field(None, description="DH frame n → tool (TCP).")
    geometry: DHGeometryDoc | None = None
    joints: list[DHRowDoc] = Field(min_length=1, max_length=64)


class UrdfUpload(Schema):
    """A robot given as URDF text (and optionally SRDF)."""

    name: Text = Field(
        max_length=256,
        json_schema_extra={"pattern": ID_PATTERN.pattern},
        description="Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).",
    )
    urdf: Text = Field(
        min_length=1,
        description="URDF document. No DTD or entities; mesh filenames must be "
        "package://<package>/<path> URIs; only revolute, continuous, prismatic and fixed "
        "joints.",
    )
    srdf: Text | None = Field(
        None,
        description="SRDF document: disabled collision pairs, planning groups (chain, joints, "
        "links, subgroups), end effectors and group states, checked against the URDF.",
    )
    ee_frame: Text | None = Field(
        None,
        max_length=256,
        description="Default end-effector frame (default: the parent_link of the SRDF's first "
        "end effector, else the tip of the longest serial chain that is not a gripper finger; "
        "see end_effector in GET /robots/{robot_id}).",
    )
    description: Text = Field("", max_length=1000, description="Short description.")
