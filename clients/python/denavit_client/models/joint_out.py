from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.joint_limits import JointLimits


T = TypeVar("T", bound="JointOut")


@_attrs_define
class JointOut:
    """An actuated joint, in configuration order.

    Attributes:
        name (str):
        type_ (str): revolute | prismatic | continuous.
        parent (str): Parent link.
        child (str): Child link.
        axis (list[float]): Joint axis in the joint frame (URDF <axis>).
        limits (JointLimits): Joint limits, SI units; ``null`` where the URDF gives none (continuous joints).
        continuous (bool): Unbounded revolute joint (one angle on the wire).
    """

    name: str
    type_: str
    parent: str
    child: str
    axis: list[float]
    limits: JointLimits
    continuous: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        type_ = self.type_

        parent = self.parent

        child = self.child

        axis = self.axis

        limits = self.limits.to_dict()

        continuous = self.continuous

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "type": type_,
                "parent": parent,
                "child": child,
                "axis": axis,
                "limits": limits,
                "continuous": continuous,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_limits import JointLimits  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        type_ = d.pop("type")

        parent = d.pop("parent")

        child = d.pop("child")

        axis = cast(list[float], d.pop("axis"))

        limits = JointLimits.from_dict(d.pop("limits"))

        continuous = d.pop("continuous")

        joint_out = cls(
            name=name,
            type_=type_,
            parent=parent,
            child=child,
            axis=axis,
            limits=limits,
            continuous=continuous,
        )

        joint_out.additional_properties = d
        return joint_out

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
