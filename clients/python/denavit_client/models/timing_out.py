from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="TimingOut")


@_attrs_define
class TimingOut:
    """Times, joint velocities and accelerations at the path's points (joint order). The
    limits hold at every point and at samples between them (``time_scale``).

        Attributes:
            t (list[float]): Time of each point (s), 0 at the first.
            velocities (list[list[float]]): Joint velocities at each point (rad/s or m/s); 0 at both ends.
            accelerations (list[list[float]]): Joint accelerations at each point (rad/s² or m/s²), just after it (at the
                last point: just before).
            duration (float): Time of the last point (s).
            velocity_limits (list[float | None]): The velocity limit applied to each joint; null: the joint does not move.
            acceleration_limits (list[float | None]): The acceleration limit applied to each joint; null: the joint does not
                move.
            time_scale (float): How much the motion was slowed after TOPP-RA so that every verified sample keeps its limits
                (1.0: not at all).
    """

    t: list[float]
    velocities: list[list[float]]
    accelerations: list[list[float]]
    duration: float
    velocity_limits: list[float | None]
    acceleration_limits: list[float | None]
    time_scale: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        t = self.t

        velocities = []
        for velocities_item_data in self.velocities:
            velocities_item = velocities_item_data

            velocities.append(velocities_item)

        accelerations = []
        for accelerations_item_data in self.accelerations:
            accelerations_item = accelerations_item_data

            accelerations.append(accelerations_item)

        duration = self.duration

        velocity_limits = []
        for velocity_limits_item_data in self.velocity_limits:
            velocity_limits_item: float | None
            velocity_limits_item = velocity_limits_item_data
            velocity_limits.append(velocity_limits_item)

        acceleration_limits = []
        for acceleration_limits_item_data in self.acceleration_limits:
            acceleration_limits_item: float | None
            acceleration_limits_item = acceleration_limits_item_data
            acceleration_limits.append(acceleration_limits_item)

        time_scale = self.time_scale

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "t": t,
                "velocities": velocities,
                "accelerations": accelerations,
                "duration": duration,
                "velocity_limits": velocity_limits,
                "acceleration_limits": acceleration_limits,
                "time_scale": time_scale,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        t = cast(list[float], d.pop("t"))

        velocities = []
        _velocities = d.pop("velocities")
        for velocities_item_data in _velocities:
            velocities_item = cast(list[float], velocities_item_data)

            velocities.append(velocities_item)

        accelerations = []
        _accelerations = d.pop("accelerations")
        for accelerations_item_data in _accelerations:
            accelerations_item = cast(list[float], accelerations_item_data)

            accelerations.append(accelerations_item)

        duration = d.pop("duration")

        velocity_limits = []
        _velocity_limits = d.pop("velocity_limits")
        for velocity_limits_item_data in _velocity_limits:

            def _parse_velocity_limits_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            velocity_limits_item = _parse_velocity_limits_item(velocity_limits_item_data)

            velocity_limits.append(velocity_limits_item)

        acceleration_limits = []
        _acceleration_limits = d.pop("acceleration_limits")
        for acceleration_limits_item_data in _acceleration_limits:

            def _parse_acceleration_limits_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            acceleration_limits_item = _parse_acceleration_limits_item(
                acceleration_limits_item_data
            )

            acceleration_limits.append(acceleration_limits_item)

        time_scale = d.pop("time_scale")

        timing_out = cls(
            t=t,
            velocities=velocities,
            accelerations=accelerations,
            duration=duration,
            velocity_limits=velocity_limits,
            acceleration_limits=acceleration_limits,
            time_scale=time_scale,
        )

        timing_out.additional_properties = d
        return timing_out

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
