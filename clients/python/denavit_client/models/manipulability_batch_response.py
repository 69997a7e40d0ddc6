from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.jacobian_reference import JacobianReference

T = TypeVar("T", bound="ManipulabilityBatchResponse")


@_attrs_define
class ManipulabilityBatchResponse:
    """Compact arrays: entry i belongs to configuration i.

    Attributes:
        robot_id (str):
        frame (str):
        reference (JacobianReference):
        rows (list[str]):
        joints (list[str]):
        yoshikawa (list[float]):
        min_singular_value (list[float]):
        max_singular_value (list[float]):
        inverse_condition (list[float]):
        condition_number (list[float | None]): null where singular.
        det_jjt (list[float]):
        rank (list[int]):
        singular (list[bool]):
    """

    robot_id: str
    frame: str
    reference: JacobianReference
    rows: list[str]
    joints: list[str]
    yoshikawa: list[float]
    min_singular_value: list[float]
    max_singular_value: list[float]
    inverse_condition: list[float]
    condition_number: list[float | None]
    det_jjt: list[float]
    rank: list[int]
    singular: list[bool]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        reference = self.reference.value

        rows = self.rows

        joints = self.joints

        yoshikawa = self.yoshikawa

        min_singular_value = self.min_singular_value

        max_singular_value = self.max_singular_value

        inverse_condition = self.inverse_condition

        condition_number = []
        for condition_number_item_data in self.condition_number:
            condition_number_item: float | None
            condition_number_item = condition_number_item_data
            condition_number.append(condition_number_item)

        det_jjt = self.det_jjt

        rank = self.rank

        singular = self.singular

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "reference": reference,
                "rows": rows,
                "joints": joints,
                "yoshikawa": yoshikawa,
                "min_singular_value": min_singular_value,
                "max_singular_value": max_singular_value,
                "inverse_condition": inverse_condition,
                "condition_number": condition_number,
                "det_jjt": det_jjt,
                "rank": rank,
                "singular": singular,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        reference = JacobianReference(d.pop("reference"))

        rows = cast(list[str], d.pop("rows"))

        joints = cast(list[str], d.pop("joints"))

        yoshikawa = cast(list[float], d.pop("yoshikawa"))

        min_singular_value = cast(list[float], d.pop("min_singular_value"))

        max_singular_value = cast(list[float], d.pop("max_singular_value"))

        inverse_condition = cast(list[float], d.pop("inverse_condition"))

        condition_number = []
        _condition_number = d.pop("condition_number")
        for condition_number_item_data in _condition_number:

            def _parse_condition_number_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            condition_number_item = _parse_condition_number_item(condition_number_item_data)

            condition_number.append(condition_number_item)

        det_jjt = cast(list[float], d.pop("det_jjt"))

        rank = cast(list[int], d.pop("rank"))

        singular = cast(list[bool], d.pop("singular"))

        manipulability_batch_response = cls(
            robot_id=robot_id,
            frame=frame,
            reference=reference,
            rows=rows,
            joints=joints,
            yoshikawa=yoshikawa,
            min_singular_value=min_singular_value,
            max_singular_value=max_singular_value,
            inverse_condition=inverse_condition,
            condition_number=condition_number,
            det_jjt=det_jjt,
            rank=rank,
            singular=singular,
        )

        manipulability_batch_response.additional_properties = d
        return manipulability_batch_response

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
