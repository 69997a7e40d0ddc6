from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.fk_response_poses import FKResponsePoses


T = TypeVar("T", bound="FKResponse")


@_attrs_define
class FKResponse:
    """Frame poses in the root frame.

    Attributes:
        robot_id (str):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        poses (FKResponsePoses): Frame name → pose in the root frame.
        within_limits (bool): Whether every joint lies within its limits.
        joints_outside_limits (list[str]): Joints outside their limits.
    """

    robot_id: str
    q: list[float]
    poses: FKResponsePoses
    within_limits: bool
    joints_outside_limits: list[str]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        q = self.q

        poses = self.poses.to_dict()

        within_limits = self.within_limits

        joints_outside_limits = self.joints_outside_limits

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "q": q,
                "poses": poses,
                "within_limits": within_limits,
                "joints_outside_limits": joints_outside_limits,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.fk_response_poses import FKResponsePoses  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        q = cast(list[float], d.pop("q"))

        poses = FKResponsePoses.from_dict(d.pop("poses"))

        within_limits = d.pop("within_limits")

        joints_outside_limits = cast(list[str], d.pop("joints_outside_limits"))

        fk_response = cls(
            robot_id=robot_id,
            q=q,
            poses=poses,
            within_limits=within_limits,
            joints_outside_limits=joints_outside_limits,
        )

        fk_response.additional_properties = d
        return fk_response

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
