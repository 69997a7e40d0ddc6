from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="JointLimits")


@_attrs_define
class JointLimits:
    """Joint limits, SI units; ``null`` where the URDF gives none (continuous joints).

    Attributes:
        lower (float | None): Lower position limit (rad or m).
        upper (float | None): Upper position limit (rad or m).
        velocity (float | None): Velocity limit (rad/s or m/s).
        effort (float | None): Effort limit (N·m or N).
    """

    lower: float | None
    upper: float | None
    velocity: float | None
    effort: float | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        lower: float | None
        lower = self.lower

        upper: float | None
        upper = self.upper

        velocity: float | None
        velocity = self.velocity

        effort: float | None
        effort = self.effort

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "lower": lower,
                "upper": upper,
                "velocity": velocity,
                "effort": effort,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_lower(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        lower = _parse_lower(d.pop("lower"))

        def _parse_upper(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        upper = _parse_upper(d.pop("upper"))

        def _parse_velocity(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        velocity = _parse_velocity(d.pop("velocity"))

        def _parse_effort(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        effort = _parse_effort(d.pop("effort"))

        joint_limits = cls(
            lower=lower,
            upper=upper,
            velocity=velocity,
            effort=effort,
        )

        joint_limits.additional_properties = d
        return joint_limits

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
