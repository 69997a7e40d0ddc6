"""Wire models of rigid-body dynamics (docs/dynamics.md): joint torques at one state, many
states, and the largest payload the effort limits hold at rest.

Units: joint values rad (revolute) or m (prismatic); velocities rad/s or m/s; accelerations
rad/s² or m/s²; torques N·m (forces N for prismatic joints); masses kg; lengths m; rotational
inertias kg·m². Gravity is 9.81 m/s² along −z of the robot's root (world) frame. Values the
service cannot give as a number are JSON ``null``: an effort limit the URDF does not state
(and the ratio against it), an unbounded payload.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Annotated

import numpy as np
from pydantic import BaseModel, Field, Strict, WrapValidator
from typing_extensions import TypeAliasType

from app.api.schemas.analysis import Load
from app.api.schemas.common import (
    Configuration,
    ConfigurationIn,
    Finite,
    JointValue,
    Schema,
    Vec3,
    Vec3Out,
    group_field,
)
from app.api.schemas.timing import _one_form as one_form  # the list-or-map error namer
from app.api.schemas.values import JacobianReference
from app.kinematics.dynamics import MAX_JOINT_RATE, Payload, check_rates, payload
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group
from app.kinematics.models import RobotModel

#: The largest number of joints a request names (as for configurations).
MAX_JOINTS = 1024

#: A joint rate as the request gives it: a JSON number (ints accepted; strings and booleans
#: rejected). NaN and ±Infinity (which some clients send) pass here so that
#: :func:`~app.kinematics.dynamics.check_rates` refuses them naming ``velocities.3`` or
#: ``velocities.<joint>`` (a union's validation error would name its branch).
Rate = Annotated[float, Strict(), Field(allow_inf_nan=True)]

#: Joint name → rate: one named component for joint velocities and accelerations by name.
JointRates = TypeAliasType(
    "JointRates",
    Annotated[
        dict[str, Rate],
        Field(
            max_length=MAX_JOINTS,
            description="Joint name → value (rad/s or m/s for velocities, rad/s² or m/s² for "
            "accelerations); joints not named take 0. A mimic follower may be named when its "
            "value equals multiplier × its leader's.",
        ),
    ],
)
#: Joint rates as a list in joint order or a map by name.
Rates = Annotated[
    Annotated[list[Rate], Field(max_length=MAX_JOINTS)] | JointRates, WrapValidator(one_form)
]

RATES_DOC = (
    "One value per joint in joint order (with `group`: one per joint of the group, in its "
    "order, is accepted too; the others take 0), or a joint name → value map; zeros when "
    f"absent. Each value within ±{MAX_JOINT_RATE:g}."
)


def rates(
    robot: RobotModel,
    grp: Group | None,
    values: Sequence[float] | Mapping[str, float] | None,
    field: str,
) -> np.ndarray:
    """Joint rates (velocities or accelerations) in wire order from a list (all joints, or
    the group's joints) or a joint → value map; zeros for ``None``. Errors name
    ``field.i`` or ``field.<joint>``."""
    out = np.zeros(robot.n)
    if values is None:
        return out
    if isinstance(values, Mapping):
        followers = {m.name: m for m in robot.mimic_joints}
        given: dict[str, float] = {}
        for name, value in values.items():
            path = f"{field}.{name}"
            check_rates(np.asarray(float(value)), path)
            if name in followers:
                given[name] = float(value)
            else:
                out[robot.joint_index(name, field=path)] = value
        for name, value in given.items():  # a follower's rate: multiplier × its leader's
            m = followers[name]
            expected = m.multiplier * out[m.leader_index]
            if abs(value - expected) > 1e-9 * max(1.0, abs(expected)):
                raise InvalidInputError(
                    f"a mimic joint's value must be {m.multiplier:g} × its leader's "
                    f"({robot.joint_names[m.leader_index]}): expected {expected:g}, got {value:g}",
                    f"{field}.{name}",
                )
        return out
    arr = np.asarray(values, dtype=float)
    check_rates(arr, field)
    if arr.shape[0] == robot.n:
        return arr
    if grp is not None and arr.shape[0] == grp.size:
        out[grp.indices] = arr
        return out
    sizes = f"{robot.n} (one per joint: {', '.join(robot.joint_names)})"
    if grp is not None:
        sizes = f"{grp.size} (the joints of group {grp.name!r}) or " + sizes
    raise InvalidInputError(f"expected {sizes} values, got {arr.shape[0]}", field)


class PayloadIn(Schema):
    """A rigid load fixed to a frame: its mass, centre of mass and rotational inertia."""

    mass: Finite = Field(ge=0.0, le=1e6, description="Mass (kg), within [0, 10⁶].")
    frame: str | None = Field(
        None,
        max_length=256,
        description="The frame the load is fixed to; default the robot's tip (with `group`: "
        "the group's tip).",
    )
    com: Vec3 = Field(
        [0.0, 0.0, 0.0],
        description="Its centre of mass (m) in the frame's axes, from the frame's origin.",
    )
    inertia: Annotated[list[Finite], Field(min_length=6, max_length=6)] | None = Field(
        None,
        description="Rotational inertia about the centre of mass in the frame's axes, the "
        "six URDF entries [ixx, ixy, ixz, iyy, iyz, izz] (kg·m²); absent: a point mass. "
        "It must be one a rigid body has (positive semi-definite, triangle inequality).",
    )

    def to_core(self, robot: RobotModel, default_frame: str, field: str = "payload") -> Payload:
        """The checked core payload (errors name ``field.mass``, ``field.com.i``, …)."""
        return payload(
            robot, self.mass, self.frame or default_frame, self.com, self.inertia, field=field
        )


class PayloadOut(BaseModel):
    """The payload the answer includes (the request's, with its defaults filled in)."""

    mass: float = Field(description="kg.")
    frame: str
    com: Vec3Out = Field(description="m, in the frame's axes.")
    inertia: list[float] = Field(
        description="[ixx, ixy, ixz, iyy, iyz, izz] about the centre of mass (kg·m²)."
    )


class WrenchIn(Schema):
    """A wrench a frame exerts on its environment (as in statics: τ = Jᵀ·F)."""

    frame: str | None = Field(
        None,
        max_length=256,
        description="Frame; default the end effector (with `group`: the group's tip).",
    )
    reference: JacobianReference = Field(
        "world",
        description="Axes of the wrench (as for the Jacobian). world: force and moment about "
        "the frame origin, world axes | local: frame axes | world_spatial: moment about the "
        "world origin.",
    )
    values: Annotated[list[Load], Field(min_length=6, max_length=6)] = Field(
        description="[fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its "
        "environment."
    )


class DynamicsRequest(ConfigurationIn):
    """A state (q, q̇, q̈), an optional payload and an optional wrench."""

    velocities: Rates | None = Field(None, description="Joint velocities q̇. " + RATES_DOC)
    accelerations: Rates | None = Field(None, description="Joint accelerations q̈. " + RATES_DOC)
    payload: PayloadIn | None = Field(None, description="A load fixed to a frame.")
    wrench: WrenchIn | None = Field(
        None, description="A wrench a frame exerts on its environment (adds Jᵀ·F)."
    )


class DynamicsResponse(BaseModel):
    """τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F and its parts, over `joint_names` (the robot's
    joints, or with `group` the group's)."""

    robot_id: str
    q: Configuration
    joint_names: list[str] = Field(description="The joints of every vector and matrix, in order.")
    torques: list[float] = Field(description="τ, the joint torques (N·m; N for prismatic).")
    gravity_torques: list[float] = Field(description="g(q): the torques holding the arm still.")
    coriolis_torques: list[float] = Field(description="C(q, q̇)·q̇: Coriolis and centrifugal.")
    inertial_torques: list[float] = Field(description="M(q)·q̈.")
    wrench_torques: list[float] = Field(description="Jᵀ·F (zeros without a wrench).")
    mass_matrix: list[list[float]] = Field(
        description="M(q), n×n, symmetric positive definite (kg·m², kg for prismatic joints)."
    )
    coriolis_matrix: list[list[float]] = Field(
        description="C(q, q̇), n×n (Christoffel symbols: Ṁ − 2C is skew-symmetric)."
    )
    center_of_mass: Vec3Out = Field(
        description="Centre of mass of the robot and payload (m, world frame)."
    )
    total_mass: float = Field(description="Mass of the robot and payload (kg).")
    effort_limits: list[float | None] = Field(
        description="URDF effort limits (N·m, N); null where the URDF gives none."
    )
    effort_ratios: list[float | None] = Field(
        description="|τ| / effort limit; null where there is no limit."
    )
    binding_joint: str | None = Field(
        description="The joint with the largest effort ratio; null when no joint has a limit."
    )
    payload: PayloadOut | None = Field(description="The payload included, or null.")


class DynamicsBatchRequest(Schema):
    """Many states (q, q̇, q̈), one optional payload."""

    configurations: list[list[JointValue]] = Field(
        description="N configurations, each one value per joint in joint order (rad, m); "
        "with `group`, rows of the group's joints only are accepted too (others neutral)."
    )
    velocities: list[list[Finite]] | None = Field(
        None,
        description="N rows of joint velocities, as wide as `configurations`' rows; zeros "
        "when absent.",
    )
    accelerations: list[list[Finite]] | None = Field(
        None,
        description="N rows of joint accelerations, as wide as `configurations`' rows; zeros "
        "when absent.",
    )
    payload: PayloadIn | None = Field(None, description="A load fixed to a frame.")
    group: str | None = group_field()


class DynamicsBatchResponse(BaseModel):
    """Row i belongs to state i; columns are `joint_names`."""

    robot_id: str
    joint_names: list[str]
    torques: list[list[float]] = Field(description="N×n joint torques τ (N·m, N).")
    gravity_torques: list[list[float]] = Field(description="N×n gravity torques g(q).")
    payload: PayloadOut | None = Field(description="The payload included, or null.")


class MaxPayloadRequest(ConfigurationIn):
    """One configuration (`q` or `joint_positions`) or a `path` of configurations, the point
    the payload hangs from, and a tool already attached."""

    path: list[list[JointValue]] | None = Field(
        None,
        description="N configurations in joint order (with `group`: rows of the group's "
        "joints are accepted too), instead of `q`/`joint_positions`.",
    )
    frame: str | None = Field(
        None,
        max_length=256,
        description="The frame the payload hangs from; default the robot's tip (with "
        "`group`: the group's tip).",
    )
    com: Vec3 = Field(
        [0.0, 0.0, 0.0], description="The payload's centre of mass (m) in the frame's axes."
    )
    payload: PayloadIn | None = Field(
        None, description="A load already attached (a tool): its weight counts."
    )


class MaxPayloadSample(BaseModel):
    """The payload bound at one configuration."""

    max_payload: float | None = Field(
        description="The largest payload (kg) every joint's effort limit holds at rest; null "
        "= unbounded (the payload loads no joint that has a limit); 0 when the arm cannot "
        "hold itself."
    )
    limiting_joint: str | None = Field(
        description="The joint whose limit sets max_payload; null when unbounded."
    )
    per_joint: dict[str, float | None] = Field(
        description="Each joint's own bound (kg); null where the joint has no limit or the "
        "payload does not load it."
    )
    gravity_torques: list[float] = Field(
        description="g(q) of the robot and any attached tool, without the payload (N·m, N)."
    )
    torques_at_max: list[float] = Field(
        description="g(q) with max_payload attached (= gravity_torques when unbounded)."
    )
    holds_itself: bool = Field(description="Every |g_i| ≤ its limit without the payload.")


class MaxPayloadResponse(MaxPayloadSample):
    """At one configuration, its bound; along a path, the bound of the sample where it is
    smallest (`min_sample`) and every sample's."""

    robot_id: str
    frame: str
    com: Vec3Out
    joint_names: list[str]
    min_max_payload: float | None = Field(
        None,
        description="Along a path: the smallest max_payload over its samples (null: "
        "unbounded everywhere, or no path).",
    )
    min_sample: int | None = Field(
        None, description="Along a path: the sample where max_payload is smallest."
    )
    samples: list[MaxPayloadSample] | None = Field(
        None, description="Along a path: each sample's bound, in order; null without a path."
    )
