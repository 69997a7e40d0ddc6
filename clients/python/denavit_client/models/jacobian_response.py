from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.jacobian_reference import JacobianReference

T = TypeVar("T", bound="JacobianResponse")


@_attrs_define
class JacobianResponse:
    """The Jacobian, rows [vx, vy, vz, ωx, ωy, ωz], columns in joint order (with `group`:
    the group's joints, in the group's order).

        Attributes:
            robot_id (str):
            frame (str):
            reference (JacobianReference):
            q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
                joints, m for prismatic ones.
            jacobian (list[list[float]]): 6×n (with `group`: 6×k, k the group's joints); linear rows in m/rad or m/m.
            joint_names (list[str]): The joint of each column.
    """

    robot_id: str
    frame: str
    reference: JacobianReference
    q: list[float]
    jacobian: list[list[float]]
    joint_names: list[str]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        reference = self.reference.value

        q = self.q

        jacobian = []
        for jacobian_item_data in self.jacobian:
            jacobian_item = jacobian_item_data

            jacobian.append(jacobian_item)

        joint_names = self.joint_names

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "reference": reference,
                "q": q,
                "jacobian": jacobian,
                "joint_names": joint_names,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        reference = JacobianReference(d.pop("reference"))

        q = cast(list[float], d.pop("q"))

        jacobian = []
        _jacobian = d.pop("jacobian")
        for jacobian_item_data in _jacobian:
            jacobian_item = cast(list[float], jacobian_item_data)

            jacobian.append(jacobian_item)

        joint_names = cast(list[str], d.pop("joint_names"))

        jacobian_response = cls(
            robot_id=robot_id,
            frame=frame,
            reference=reference,
            q=q,
            jacobian=jacobian,
            joint_names=joint_names,
        )

        jacobian_response.additional_properties = d
        return jacobian_response

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
