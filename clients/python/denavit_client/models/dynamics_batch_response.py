from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.payload_out import PayloadOut


T = TypeVar("T", bound="DynamicsBatchResponse")


@_attrs_define
class DynamicsBatchResponse:
    """Row i belongs to state i; columns are `joint_names`.

    Attributes:
        robot_id (str):
        joint_names (list[str]):
        torques (list[list[float]]): N×n joint torques τ (N·m, N).
        gravity_torques (list[list[float]]): N×n gravity torques g(q).
        payload (None | PayloadOut): The payload included, or null.
    """

    robot_id: str
    joint_names: list[str]
    torques: list[list[float]]
    gravity_torques: list[list[float]]
    payload: None | PayloadOut
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.payload_out import PayloadOut  # noqa: PLC0415

        robot_id = self.robot_id

        joint_names = self.joint_names

        torques = []
        for torques_item_data in self.torques:
            torques_item = torques_item_data

            torques.append(torques_item)

        gravity_torques = []
        for gravity_torques_item_data in self.gravity_torques:
            gravity_torques_item = gravity_torques_item_data

            gravity_torques.append(gravity_torques_item)

        payload: dict[str, Any] | None
        if isinstance(self.payload, PayloadOut):
            payload = self.payload.to_dict()
        else:
            payload = self.payload

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "joint_names": joint_names,
                "torques": torques,
                "gravity_torques": gravity_torques,
                "payload": payload,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.payload_out import PayloadOut  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        joint_names = cast(list[str], d.pop("joint_names"))

        torques = []
        _torques = d.pop("torques")
        for torques_item_data in _torques:
            torques_item = cast(list[float], torques_item_data)

            torques.append(torques_item)

        gravity_torques = []
        _gravity_torques = d.pop("gravity_torques")
        for gravity_torques_item_data in _gravity_torques:
            gravity_torques_item = cast(list[float], gravity_torques_item_data)

            gravity_torques.append(gravity_torques_item)

        def _parse_payload(data: object) -> None | PayloadOut:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                payload_type_0 = PayloadOut.from_dict(data)

                return payload_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PayloadOut, data)

        payload = _parse_payload(d.pop("payload"))

        dynamics_batch_response = cls(
            robot_id=robot_id,
            joint_names=joint_names,
            torques=torques,
            gravity_torques=gravity_torques,
            payload=payload,
        )

        dynamics_batch_response.additional_properties = d
        return dynamics_batch_response

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
