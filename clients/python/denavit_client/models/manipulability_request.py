from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.jacobian_part import JacobianPart
from ..models.jacobian_reference import JacobianReference
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="ManipulabilityRequest")


@_attrs_define
class ManipulabilityRequest:
    """A configuration and the task to analyse.

    Attributes:
        frame (None | str | Unset): Frame; default the end effector (with `group`: the group's tip).
        part (JacobianPart | None | Unset): Task rows: full (vx vy vz wx wy wz, default) | translation (vx vy vz) |
            rotation (wx wy wz). Give either part or rows.
        rows (list[int | str] | None | Unset): Explicit task rows by name (vx, vy, vz, wx, wy, wz) or index 0–5, e.g.
            ["vx", "vy"] for a planar arm in the x-y plane. Give either part or rows.
        reference (JacobianReference | Unset):
        relative_tolerance (float | Unset): Relative rank tolerance: σ_i counts toward the rank when σ_i >
            relative_tolerance·σ_max. Default: 1e-10.
        q (list[float] | None | Unset): One value per actuated joint, in the order of GET /robots/{id} (rad for revolute
            and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is
            accepted too.
        joint_positions (JointPositions | None | Unset): Joint name → value (rad or m); joints not given take their
            neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader +
            offset within 1e-9 (see mimic_joints of GET /robots/{id}).
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
    """

    frame: None | str | Unset = UNSET
    part: JacobianPart | None | Unset = UNSET
    rows: list[int | str] | None | Unset = UNSET
    reference: JacobianReference | Unset = UNSET
    relative_tolerance: float | Unset = 1e-10
    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        part: None | str | Unset
        if isinstance(self.part, Unset):
            part = UNSET
        elif isinstance(self.part, JacobianPart):
            part = self.part.value
        else:
            part = self.part

        rows: list[int | str] | None | Unset
        if isinstance(self.rows, Unset):
            rows = UNSET
        elif isinstance(self.rows, list):
            rows = []
            for rows_type_0_item_data in self.rows:
                rows_type_0_item: int | str
                rows_type_0_item = rows_type_0_item_data
                rows.append(rows_type_0_item)

        else:
            rows = self.rows

        reference: str | Unset = UNSET
        if not isinstance(self.reference, Unset):
            reference = self.reference.value

        relative_tolerance = self.relative_tolerance

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

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if frame is not UNSET:
            field_dict["frame"] = frame
        if part is not UNSET:
            field_dict["part"] = part
        if rows is not UNSET:
            field_dict["rows"] = rows
        if reference is not UNSET:
            field_dict["reference"] = reference
        if relative_tolerance is not UNSET:
            field_dict["relative_tolerance"] = relative_tolerance
        if q is not UNSET:
            field_dict["q"] = q
        if joint_positions is not UNSET:
            field_dict["joint_positions"] = joint_positions
        if group is not UNSET:
            field_dict["group"] = group

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        def _parse_part(data: object) -> JacobianPart | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                part_type_0 = JacobianPart(data)

                return part_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JacobianPart | None | Unset, data)

        part = _parse_part(d.pop("part", UNSET))

        def _parse_rows(data: object) -> list[int | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rows_type_0 = []
                _rows_type_0 = data
                for rows_type_0_item_data in _rows_type_0:

                    def _parse_rows_type_0_item(data: object) -> int | str:
                        return cast(int | str, data)

                    rows_type_0_item = _parse_rows_type_0_item(rows_type_0_item_data)

                    rows_type_0.append(rows_type_0_item)

                return rows_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[int | str] | None | Unset, data)

        rows = _parse_rows(d.pop("rows", UNSET))

        _reference = d.pop("reference", UNSET)
        reference: JacobianReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = JacobianReference(_reference)

        relative_tolerance = d.pop("relative_tolerance", UNSET)

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

        manipulability_request = cls(
            frame=frame,
            part=part,
            rows=rows,
            reference=reference,
            relative_tolerance=relative_tolerance,
            q=q,
            joint_positions=joint_positions,
            group=group,
        )

        return manipulability_request
