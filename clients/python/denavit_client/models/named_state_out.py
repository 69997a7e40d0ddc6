from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="NamedStateOut")


@_attrs_define
class NamedStateOut:
    """An SRDF group state: usable as an IK seed by name (``"seed": "ready"``).

    Attributes:
        name (str):
        group (None | str): The group it is a state of (null if not given).
        joint_positions (JointPositions): Joint name → value: rad for revolute and continuous joints, m for prismatic
            ones, each within ±10000 (a value beyond is a 422 naming `<field>.<joint>`).
    """

    name: str
    group: None | str
    joint_positions: JointPositions
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        group: None | str
        group = self.group

        joint_positions = self.joint_positions.to_dict()

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "group": group,
                "joint_positions": joint_positions,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        def _parse_group(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        group = _parse_group(d.pop("group"))

        joint_positions = JointPositions.from_dict(d.pop("joint_positions"))

        named_state_out = cls(
            name=name,
            group=group,
            joint_positions=joint_positions,
        )

        named_state_out.additional_properties = d
        return named_state_out

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
