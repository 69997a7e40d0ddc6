from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.jacobian_part import JacobianPart
from ..models.jacobian_reference import JacobianReference
from ..types import UNSET, Unset

T = TypeVar("T", bound="ManipulabilityBatchRequest")


@_attrs_define
class ManipulabilityBatchRequest:
    """Many configurations, one task.

    Attributes:
        configurations (list[list[float]]): N configurations, each one value per joint in joint order (rad, m); with
            `group`, rows of the group's joints only are accepted too (others neutral).
        frame (None | str | Unset): Frame; default the end effector (with `group`: the group's tip).
        part (JacobianPart | None | Unset): Task rows: full (vx vy vz wx wy wz, default) | translation (vx vy vz) |
            rotation (wx wy wz). Give either part or rows.
        rows (list[int | str] | None | Unset): Explicit task rows by name (vx, vy, vz, wx, wy, wz) or index 0–5, e.g.
            ["vx", "vy"] for a planar arm in the x-y plane. Give either part or rows.
        reference (JacobianReference | Unset):
        relative_tolerance (float | Unset): Relative rank tolerance: σ_i counts toward the rank when σ_i >
            relative_tolerance·σ_max. Default: 1e-10.
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
    """

    configurations: list[list[float]]
    frame: None | str | Unset = UNSET
    part: JacobianPart | None | Unset = UNSET
    rows: list[int | str] | None | Unset = UNSET
    reference: JacobianReference | Unset = UNSET
    relative_tolerance: float | Unset = 1e-10
    group: None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        configurations = []
        for configurations_item_data in self.configurations:
            configurations_item = configurations_item_data

            configurations.append(configurations_item)

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

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "configurations": configurations,
            }
        )
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
        if group is not UNSET:
            field_dict["group"] = group

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        configurations = []
        _configurations = d.pop("configurations")
        for configurations_item_data in _configurations:
            configurations_item = cast(list[float], configurations_item_data)

            configurations.append(configurations_item)

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

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        manipulability_batch_request = cls(
            configurations=configurations,
            frame=frame,
            part=part,
            rows=rows,
            reference=reference,
            relative_tolerance=relative_tolerance,
            group=group,
        )

        return manipulability_batch_request
