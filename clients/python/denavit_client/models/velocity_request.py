from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.ik_mode import IKMode
from ..models.twist_reference import TwistReference
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="VelocityRequest")


@_attrs_define
class VelocityRequest:
    """A configuration plus exactly one of ``joint_velocities`` (forward) or ``twist``.

    Attributes:
        q (list[float] | None | Unset): One value per actuated joint, in the order of GET /robots/{id} (rad for revolute
            and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is
            accepted too.
        joint_positions (JointPositions | None | Unset): Joint name → value (rad or m); joints not given take their
            neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader +
            offset within 1e-9 (see mimic_joints of GET /robots/{id}).
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
        frame (None | str | Unset): Frame; default the end effector (with `group`: the group's tip).
        reference (TwistReference | Unset):
        joint_velocities (list[float] | None | Unset): Forward: q̇, one per joint in joint order (rad/s, m/s); with
            `group`, one per joint of the group is accepted too (the others at rest).
        twist (list[float] | None | Unset): Inverse: [vx, vy, vz, wx, wy, wz] (m/s, rad/s) to realise.
        mode (IKMode | Unset):
        singular_threshold (float | Unset): Inverse: σ_min below which damping starts. Default: 0.01.
        max_damping (float | Unset): Inverse: damping λ at an exact singularity. Default: 0.1.
    """

    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET
    frame: None | str | Unset = UNSET
    reference: TwistReference | Unset = UNSET
    joint_velocities: list[float] | None | Unset = UNSET
    twist: list[float] | None | Unset = UNSET
    mode: IKMode | Unset = UNSET
    singular_threshold: float | Unset = 0.01
    max_damping: float | Unset = 0.1

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        q: list[float] | None | Unset
        if isinstance(self.q, Unset):
            q = UNSET
        elif isinstance(self.q, list):
            q = self.q

        else:
            q = self.q

        joint_positions: dict[str, Any] | None | Unset
        if isinstance(self.joint_positions, Unset):
            joint_positions = UNSET
        elif isinstance(self.joint_positions, JointPositions):
            joint_positions = self.joint_positions.to_dict()
        else:
            joint_positions = self.joint_positions

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        reference: str | Unset = UNSET
        if not isinstance(self.reference, Unset):
            reference = self.reference.value

        joint_velocities: list[float] | None | Unset
        if isinstance(self.joint_velocities, Unset):
            joint_velocities = UNSET
        elif isinstance(self.joint_velocities, list):
            joint_velocities = self.joint_velocities

        else:
            joint_velocities = self.joint_velocities

        twist: list[float] | None | Unset
        if isinstance(self.twist, Unset):
            twist = UNSET
        elif isinstance(self.twist, list):
            twist = self.twist

        else:
            twist = self.twist

        mode: str | Unset = UNSET
        if not isinstance(self.mode, Unset):
            mode = self.mode.value

        singular_threshold = self.singular_threshold

        max_damping = self.max_damping

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if q is not UNSET:
            field_dict["q"] = q
        if joint_positions is not UNSET:
            field_dict["joint_positions"] = joint_positions
        if group is not UNSET:
            field_dict["group"] = group
        if frame is not UNSET:
            field_dict["frame"] = frame
        if reference is not UNSET:
            field_dict["reference"] = reference
        if joint_velocities is not UNSET:
            field_dict["joint_velocities"] = joint_velocities
        if twist is not UNSET:
            field_dict["twist"] = twist
        if mode is not UNSET:
            field_dict["mode"] = mode
        if singular_threshold is not UNSET:
            field_dict["singular_threshold"] = singular_threshold
        if max_damping is not UNSET:
            field_dict["max_damping"] = max_damping

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_q(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[float], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        q = _parse_q(d.pop("q", UNSET))

        def _parse_joint_positions(data: object) -> JointPositions | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                joint_positions_type_0 = JointPositions.from_dict(data)

                return joint_positions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointPositions | None | Unset, data)

        joint_positions = _parse_joint_positions(d.pop("joint_positions", UNSET))

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        _reference = d.pop("reference", UNSET)
        reference: TwistReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = TwistReference(_reference)

        def _parse_joint_velocities(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                joint_velocities_type_0 = cast(list[float], data)

                return joint_velocities_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        joint_velocities = _parse_joint_velocities(d.pop("joint_velocities", UNSET))

        def _parse_twist(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                twist_type_0 = cast(list[float], data)

                return twist_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        twist = _parse_twist(d.pop("twist", UNSET))

        _mode = d.pop("mode", UNSET)
        mode: IKMode | Unset
        if isinstance(_mode, Unset):
            mode = UNSET
        else:
            mode = IKMode(_mode)

        singular_threshold = d.pop("singular_threshold", UNSET)

        max_damping = d.pop("max_damping", UNSET)

        velocity_request = cls(
            q=q,
            joint_positions=joint_positions,
            group=group,
            frame=frame,
            reference=reference,
            joint_velocities=joint_velocities,
            twist=twist,
            mode=mode,
            singular_threshold=singular_threshold,
            max_damping=max_damping,
        )

        return velocity_request
