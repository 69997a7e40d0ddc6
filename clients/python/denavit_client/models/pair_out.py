from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.collision_pair_kind import CollisionPairKind
from ..types import UNSET, Unset

T = TypeVar("T", bound="PairOut")


@_attrs_define
class PairOut:
    """A checked pair: two links (self) or a link and an obstacle (environment).

    Attributes:
        a (str): Link name.
        b (str): Link name (self) or obstacle name (environment).
        kind (CollisionPairKind):
        in_collision (bool): Closer than the margin.
        distance (float | None): Distance (m); negative = penetration depth where coal computes it (convex hulls,
            primitives); 0 for penetrating meshes.
        point_a (list[float] | None | Unset): Witness point on a, root frame (m); with distances.
        point_b (list[float] | None | Unset): Witness point on b, root frame (m); with distances.
    """

    a: str
    b: str
    kind: CollisionPairKind
    in_collision: bool
    distance: float | None
    point_a: list[float] | None | Unset = UNSET
    point_b: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        a = self.a

        b = self.b

        kind = self.kind.value

        in_collision = self.in_collision

        distance: float | None
        distance = self.distance

        point_a: list[float] | None | Unset
        if isinstance(self.point_a, Unset):
            point_a = UNSET
        elif isinstance(self.point_a, list):
            point_a = self.point_a

        else:
            point_a = self.point_a

        point_b: list[float] | None | Unset
        if isinstance(self.point_b, Unset):
            point_b = UNSET
        elif isinstance(self.point_b, list):
            point_b = self.point_b

        else:
            point_b = self.point_b

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "a": a,
                "b": b,
                "kind": kind,
                "in_collision": in_collision,
                "distance": distance,
            }
        )
        if point_a is not UNSET:
            field_dict["point_a"] = point_a
        if point_b is not UNSET:
            field_dict["point_b"] = point_b

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        a = d.pop("a")

        b = d.pop("b")

        kind = CollisionPairKind(d.pop("kind"))

        in_collision = d.pop("in_collision")

        def _parse_distance(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        distance = _parse_distance(d.pop("distance"))

        def _parse_point_a(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                point_a_type_0 = cast(list[float], data)

                return point_a_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        point_a = _parse_point_a(d.pop("point_a", UNSET))

        def _parse_point_b(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                point_b_type_0 = cast(list[float], data)

                return point_b_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        point_b = _parse_point_b(d.pop("point_b", UNSET))

        pair_out = cls(
            a=a,
            b=b,
            kind=kind,
            in_collision=in_collision,
            distance=distance,
            point_a=point_a,
            point_b=point_b,
        )

        pair_out.additional_properties = d
        return pair_out

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
