from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="PathPointOut")


@_attrs_define
class PathPointOut:
    """One point of the joint path, verified by forward kinematics.

    Attributes:
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        position_error (float): ‖p − p_path(s)‖ (m).
        orientation_error (float): Rotation angle to the path's pose (rad).
        s (float): Path parameter in [0, 1] of this point's pose.
    """

    q: list[float]
    position_error: float
    orientation_error: float
    s: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        q = self.q

        position_error = self.position_error

        orientation_error = self.orientation_error

        s = self.s

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "q": q,
                "position_error": position_error,
                "orientation_error": orientation_error,
                "s": s,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        q = cast(list[float], d.pop("q"))

        position_error = d.pop("position_error")

        orientation_error = d.pop("orientation_error")

        s = d.pop("s")

        path_point_out = cls(
            q=q,
            position_error=position_error,
            orientation_error=orientation_error,
            s=s,
        )

        path_point_out.additional_properties = d
        return path_point_out

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
