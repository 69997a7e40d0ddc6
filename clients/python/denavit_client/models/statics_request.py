from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.jacobian_reference import JacobianReference
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="StaticsRequest")


@_attrs_define
class StaticsRequest:
    """Exactly one of wrench (→ torques) or torques (→ wrench); with `group`, the torques are
    those of the group's joints (in the group's order).

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
            reference (JacobianReference | Unset):
            wrench (list[float] | None | Unset): [fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its
                environment.
            torques (list[float] | None | Unset): Joint torques/forces in joint order (N·m, N).
    """

    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET
    frame: None | str | Unset = UNSET
    reference: JacobianReference | Unset = UNSET
    wrench: list[float] | None | Unset = UNSET
    torques: list[float] | None | Unset = UNSET

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

        wrench: list[float] | None | Unset
        if isinstance(self.wrench, Unset):
            wrench = UNSET
        elif isinstance(self.wrench, list):
            wrench = self.wrench

        else:
            wrench = self.wrench

        torques: list[float] | None | Unset
        if isinstance(self.torques, Unset):
            torques = UNSET
        elif isinstance(self.torques, list):
            torques = self.torques

        else:
            torques = self.torques

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
        if wrench is not UNSET:
            field_dict["wrench"] = wrench
        if torques is not UNSET:
            field_dict["torques"] = torques

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
        reference: JacobianReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = JacobianReference(_reference)

        def _parse_wrench(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                wrench_type_0 = cast(list[float], data)

                return wrench_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        wrench = _parse_wrench(d.pop("wrench", UNSET))

        def _parse_torques(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                torques_type_0 = cast(list[float], data)

                return torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        torques = _parse_torques(d.pop("torques", UNSET))

        statics_request = cls(
            q=q,
            joint_positions=joint_positions,
            group=group,
            frame=frame,
            reference=reference,
            wrench=wrench,
            torques=torques,
        )

        return statics_request
