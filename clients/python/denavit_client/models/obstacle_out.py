from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.obstacle_shape import ObstacleShape
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.pose import Pose


T = TypeVar("T", bound="ObstacleOut")


@_attrs_define
class ObstacleOut:
    """A stored obstacle (normalised orientation).

    Attributes:
        name (str):
        shape (ObstacleShape):
        pose (Pose): A frame's placement in the robot's root (world) frame, the same shape in and out.

            Answers fill all four fields. A request may give any subset that states what its
            endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
            ``orientation``: a rotation; reachability queries: a position, the rotation optional;
            obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
            request is a 422 naming them. An answer's pose can be sent back as is.
        size (list[float] | None | Unset):
        radius (float | None | Unset):
        length (float | None | Unset):
    """

    name: str
    shape: ObstacleShape
    pose: Pose
    size: list[float] | None | Unset = UNSET
    radius: float | None | Unset = UNSET
    length: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        shape = self.shape.value

        pose = self.pose.to_dict()

        size: list[float] | None | Unset
        if isinstance(self.size, Unset):
            size = UNSET
        elif isinstance(self.size, list):
            size = self.size

        else:
            size = self.size

        radius: float | None | Unset
        if isinstance(self.radius, Unset):
            radius = UNSET
        else:
            radius = self.radius

        length: float | None | Unset
        if isinstance(self.length, Unset):
            length = UNSET
        else:
            length = self.length

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "shape": shape,
                "pose": pose,
            }
        )
        if size is not UNSET:
            field_dict["size"] = size
        if radius is not UNSET:
            field_dict["radius"] = radius
        if length is not UNSET:
            field_dict["length"] = length

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pose import Pose  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        shape = ObstacleShape(d.pop("shape"))

        pose = Pose.from_dict(d.pop("pose"))

        def _parse_size(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                size_type_0 = cast(list[float], data)

                return size_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        size = _parse_size(d.pop("size", UNSET))

        def _parse_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        radius = _parse_radius(d.pop("radius", UNSET))

        def _parse_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        length = _parse_length(d.pop("length", UNSET))

        obstacle_out = cls(
            name=name,
            shape=shape,
            pose=pose,
            size=size,
            radius=radius,
            length=length,
        )

        obstacle_out.additional_properties = d
        return obstacle_out

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
