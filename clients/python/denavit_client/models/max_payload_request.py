from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions
    from ..models.payload_in import PayloadIn


T = TypeVar("T", bound="MaxPayloadRequest")


@_attrs_define
class MaxPayloadRequest:
    """One configuration (`q` or `joint_positions`) or a `path` of configurations, the point
    the payload hangs from, and a tool already attached.

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
            path (list[list[float]] | None | Unset): N configurations in joint order (with `group`: rows of the group's
                joints are accepted too), instead of `q`/`joint_positions`.
            frame (None | str | Unset): The frame the payload hangs from; default the robot's tip (with `group`: the group's
                tip).
            com (list[float] | Unset): The payload's centre of mass (m) in the frame's axes.
            payload (None | PayloadIn | Unset): A load already attached (a tool): its weight counts.
    """

    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET
    path: list[list[float]] | None | Unset = UNSET
    frame: None | str | Unset = UNSET
    com: list[float] | Unset = UNSET
    payload: None | PayloadIn | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.payload_in import PayloadIn  # noqa: PLC0415

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

        path: list[list[float]] | None | Unset
        if isinstance(self.path, Unset):
            path = UNSET
        elif isinstance(self.path, list):
            path = []
            for path_type_0_item_data in self.path:
                path_type_0_item = path_type_0_item_data

                path.append(path_type_0_item)

        else:
            path = self.path

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        com: list[float] | Unset = UNSET
        if not isinstance(self.com, Unset):
            com = self.com

        payload: dict[str, Any] | None | Unset
        if isinstance(self.payload, Unset):
            payload = UNSET
        elif isinstance(self.payload, PayloadIn):
            payload = self.payload.to_dict()
        else:
            payload = self.payload

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if q is not UNSET:
            field_dict["q"] = q
        if joint_positions is not UNSET:
            field_dict["joint_positions"] = joint_positions
        if group is not UNSET:
            field_dict["group"] = group
        if path is not UNSET:
            field_dict["path"] = path
        if frame is not UNSET:
            field_dict["frame"] = frame
        if com is not UNSET:
            field_dict["com"] = com
        if payload is not UNSET:
            field_dict["payload"] = payload

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.payload_in import PayloadIn  # noqa: PLC0415

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

        def _parse_path(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                path_type_0 = []
                _path_type_0 = data
                for path_type_0_item_data in _path_type_0:
                    path_type_0_item = cast(list[float], path_type_0_item_data)

                    path_type_0.append(path_type_0_item)

                return path_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        path = _parse_path(d.pop("path", UNSET))

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        com = cast(list[float], d.pop("com", UNSET))

        def _parse_payload(data: object) -> None | PayloadIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                payload_type_0 = PayloadIn.from_dict(data)

                return payload_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PayloadIn | Unset, data)

        payload = _parse_payload(d.pop("payload", UNSET))

        max_payload_request = cls(
            q=q,
            joint_positions=joint_positions,
            group=group,
            path=path,
            frame=frame,
            com=com,
            payload=payload,
        )

        return max_payload_request
