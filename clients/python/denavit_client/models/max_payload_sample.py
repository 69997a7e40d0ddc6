from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.max_payload_sample_per_joint import MaxPayloadSamplePerJoint


T = TypeVar("T", bound="MaxPayloadSample")


@_attrs_define
class MaxPayloadSample:
    """The payload bound at one configuration.

    Attributes:
        max_payload (float | None): The largest payload (kg) every joint's effort limit holds at rest; null = unbounded
            (the payload loads no joint that has a limit); 0 when the arm cannot hold itself.
        limiting_joint (None | str): The joint whose limit sets max_payload; null when unbounded.
        per_joint (MaxPayloadSamplePerJoint): Each joint's own bound (kg); null where the joint has no limit or the
            payload does not load it.
        gravity_torques (list[float]): g(q) of the robot and any attached tool, without the payload (N·m, N).
        torques_at_max (list[float]): g(q) with max_payload attached (= gravity_torques when unbounded).
        holds_itself (bool): Every |g_i| ≤ its limit without the payload.
    """

    max_payload: float | None
    limiting_joint: None | str
    per_joint: MaxPayloadSamplePerJoint
    gravity_torques: list[float]
    torques_at_max: list[float]
    holds_itself: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        max_payload: float | None
        max_payload = self.max_payload

        limiting_joint: None | str
        limiting_joint = self.limiting_joint

        per_joint = self.per_joint.to_dict()

        gravity_torques = self.gravity_torques

        torques_at_max = self.torques_at_max

        holds_itself = self.holds_itself

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "max_payload": max_payload,
                "limiting_joint": limiting_joint,
                "per_joint": per_joint,
                "gravity_torques": gravity_torques,
                "torques_at_max": torques_at_max,
                "holds_itself": holds_itself,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.max_payload_sample_per_joint import MaxPayloadSamplePerJoint  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_max_payload(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        max_payload = _parse_max_payload(d.pop("max_payload"))

        def _parse_limiting_joint(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        limiting_joint = _parse_limiting_joint(d.pop("limiting_joint"))

        per_joint = MaxPayloadSamplePerJoint.from_dict(d.pop("per_joint"))

        gravity_torques = cast(list[float], d.pop("gravity_torques"))

        torques_at_max = cast(list[float], d.pop("torques_at_max"))

        holds_itself = d.pop("holds_itself")

        max_payload_sample = cls(
            max_payload=max_payload,
            limiting_joint=limiting_joint,
            per_joint=per_joint,
            gravity_torques=gravity_torques,
            torques_at_max=torques_at_max,
            holds_itself=holds_itself,
        )

        max_payload_sample.additional_properties = d
        return max_payload_sample

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
