from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="PayloadOut")


@_attrs_define
class PayloadOut:
    """The payload the answer includes (the request's, with its defaults filled in).

    Attributes:
        mass (float): kg.
        frame (str):
        com (list[float]): m, in the frame's axes.
        inertia (list[float]): [ixx, ixy, ixz, iyy, iyz, izz] about the centre of mass (kg·m²).
    """

    mass: float
    frame: str
    com: list[float]
    inertia: list[float]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        mass = self.mass

        frame = self.frame

        com = self.com

        inertia = self.inertia

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "mass": mass,
                "frame": frame,
                "com": com,
                "inertia": inertia,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        mass = d.pop("mass")

        frame = d.pop("frame")

        com = cast(list[float], d.pop("com"))

        inertia = cast(list[float], d.pop("inertia"))

        payload_out = cls(
            mass=mass,
            frame=frame,
            com=com,
            inertia=inertia,
        )

        payload_out.additional_properties = d
        return payload_out

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
