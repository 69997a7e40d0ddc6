from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.max_payload_response_per_joint import MaxPayloadResponsePerJoint
    from ..models.max_payload_sample import MaxPayloadSample


T = TypeVar("T", bound="MaxPayloadResponse")


@_attrs_define
class MaxPayloadResponse:
    """At one configuration, its bound; along a path, the bound of the sample where it is
    smallest (`min_sample`) and every sample's.

        Attributes:
            max_payload (float | None): The largest payload (kg) every joint's effort limit holds at rest; null = unbounded
                (the payload loads no joint that has a limit); 0 when the arm cannot hold itself.
            limiting_joint (None | str): The joint whose limit sets max_payload; null when unbounded.
            per_joint (MaxPayloadResponsePerJoint): Each joint's own bound (kg); null where the joint has no limit or the
                payload does not load it.
            gravity_torques (list[float]): g(q) of the robot and any attached tool, without the payload (N·m, N).
            torques_at_max (list[float]): g(q) with max_payload attached (= gravity_torques when unbounded).
            holds_itself (bool): Every |g_i| ≤ its limit without the payload.
            robot_id (str):
            frame (str):
            com (list[float]):
            joint_names (list[str]):
            min_max_payload (float | None | Unset): Along a path: the smallest max_payload over its samples (null: unbounded
                everywhere, or no path).
            min_sample (int | None | Unset): Along a path: the sample where max_payload is smallest.
            samples (list[MaxPayloadSample] | None | Unset): Along a path: each sample's bound, in order; null without a
                path.
    """

    max_payload: float | None
    limiting_joint: None | str
    per_joint: MaxPayloadResponsePerJoint
    gravity_torques: list[float]
    torques_at_max: list[float]
    holds_itself: bool
    robot_id: str
    frame: str
    com: list[float]
    joint_names: list[str]
    min_max_payload: float | None | Unset = UNSET
    min_sample: int | None | Unset = UNSET
    samples: list[MaxPayloadSample] | None | Unset = UNSET
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

        robot_id = self.robot_id

        frame = self.frame

        com = self.com

        joint_names = self.joint_names

        min_max_payload: float | None | Unset
        if isinstance(self.min_max_payload, Unset):
            min_max_payload = UNSET
        else:
            min_max_payload = self.min_max_payload

        min_sample: int | None | Unset
        if isinstance(self.min_sample, Unset):
            min_sample = UNSET
        else:
            min_sample = self.min_sample

        samples: list[dict[str, Any]] | None | Unset
        if isinstance(self.samples, Unset):
            samples = UNSET
        elif isinstance(self.samples, list):
            samples = []
            for samples_type_0_item_data in self.samples:
                samples_type_0_item = samples_type_0_item_data.to_dict()
                samples.append(samples_type_0_item)

        else:
            samples = self.samples

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
                "robot_id": robot_id,
                "frame": frame,
                "com": com,
                "joint_names": joint_names,
            }
        )
        if min_max_payload is not UNSET:
            field_dict["min_max_payload"] = min_max_payload
        if min_sample is not UNSET:
            field_dict["min_sample"] = min_sample
        if samples is not UNSET:
            field_dict["samples"] = samples

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.max_payload_response_per_joint import MaxPayloadResponsePerJoint  # noqa: PLC0415
        from ..models.max_payload_sample import MaxPayloadSample  # noqa: PLC0415

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

        per_joint = MaxPayloadResponsePerJoint.from_dict(d.pop("per_joint"))

        gravity_torques = cast(list[float], d.pop("gravity_torques"))

        torques_at_max = cast(list[float], d.pop("torques_at_max"))

        holds_itself = d.pop("holds_itself")

        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        com = cast(list[float], d.pop("com"))

        joint_names = cast(list[str], d.pop("joint_names"))

        def _parse_min_max_payload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        min_max_payload = _parse_min_max_payload(d.pop("min_max_payload", UNSET))

        def _parse_min_sample(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        min_sample = _parse_min_sample(d.pop("min_sample", UNSET))

        def _parse_samples(data: object) -> list[MaxPayloadSample] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                samples_type_0 = []
                _samples_type_0 = data
                for samples_type_0_item_data in _samples_type_0:
                    samples_type_0_item = MaxPayloadSample.from_dict(samples_type_0_item_data)

                    samples_type_0.append(samples_type_0_item)

                return samples_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[MaxPayloadSample] | None | Unset, data)

        samples = _parse_samples(d.pop("samples", UNSET))

        max_payload_response = cls(
            max_payload=max_payload,
            limiting_joint=limiting_joint,
            per_joint=per_joint,
            gravity_torques=gravity_torques,
            torques_at_max=torques_at_max,
            holds_itself=holds_itself,
            robot_id=robot_id,
            frame=frame,
            com=com,
            joint_names=joint_names,
            min_max_payload=min_max_payload,
            min_sample=min_sample,
            samples=samples,
        )

        max_payload_response.additional_properties = d
        return max_payload_response

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
