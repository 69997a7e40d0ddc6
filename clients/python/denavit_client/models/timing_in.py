from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.timing_in_acceleration_limits_type_1 import TimingInAccelerationLimitsType1
    from ..models.timing_in_velocity_limits_type_1 import TimingInVelocityLimitsType1


T = TypeVar("T", bound="TimingIn")


@_attrs_define
class TimingIn:
    """Time-optimal parameterization of the joint path: the fastest rest-to-rest motion along
    it within joint velocity and acceleration limits (TOPP-RA), verified on the output.

        Attributes:
            velocity_limits (list[float] | None | TimingInVelocityLimitsType1 | Unset): Joint velocity limits (rad/s or m/s,
                each within [1e-6, 1e9]): one per joint in joint order (with `group`: one per joint of the group), or joint →
                limit (the others keep theirs). Default: the robot description's (URDF `<limit velocity>`); a joint that moves
                and has none (missing, 0) is an error naming timing.velocity_limits.<joint>.
            acceleration_limits (list[float] | None | TimingInAccelerationLimitsType1 | Unset): Joint acceleration limits
                (rad/s² or m/s², each within [1e-6, 1e9]), as velocity_limits; joints not given: acceleration_fraction × their
                velocity limit. Not with acceleration_fraction.
            acceleration_fraction (float | None | Unset): Acceleration limit of every joint as a fraction of its velocity
                limit, per second: f gives a_max = f · v_max / (1 s) (v_max before velocity_scale). Default 1 (URDF has no
                acceleration limits). Not with acceleration_limits.
            velocity_scale (float | Unset): Every velocity limit multiplied by this, in (0, 1]. Default: 1.0.
    """

    velocity_limits: list[float] | None | TimingInVelocityLimitsType1 | Unset = UNSET
    acceleration_limits: list[float] | None | TimingInAccelerationLimitsType1 | Unset = UNSET
    acceleration_fraction: float | None | Unset = UNSET
    velocity_scale: float | Unset = 1.0

    def to_dict(self) -> dict[str, Any]:
        from ..models.timing_in_acceleration_limits_type_1 import TimingInAccelerationLimitsType1  # noqa: PLC0415
        from ..models.timing_in_velocity_limits_type_1 import TimingInVelocityLimitsType1  # noqa: PLC0415

        velocity_limits: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.velocity_limits, Unset):
            velocity_limits = UNSET
        elif isinstance(self.velocity_limits, list):
            velocity_limits = self.velocity_limits

        elif isinstance(self.velocity_limits, TimingInVelocityLimitsType1):
            velocity_limits = self.velocity_limits.to_dict()
        else:
            velocity_limits = self.velocity_limits

        acceleration_limits: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.acceleration_limits, Unset):
            acceleration_limits = UNSET
        elif isinstance(self.acceleration_limits, list):
            acceleration_limits = self.acceleration_limits

        elif isinstance(self.acceleration_limits, TimingInAccelerationLimitsType1):
            acceleration_limits = self.acceleration_limits.to_dict()
        else:
            acceleration_limits = self.acceleration_limits

        acceleration_fraction: float | None | Unset
        if isinstance(self.acceleration_fraction, Unset):
            acceleration_fraction = UNSET
        else:
            acceleration_fraction = self.acceleration_fraction

        velocity_scale = self.velocity_scale

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if velocity_limits is not UNSET:
            field_dict["velocity_limits"] = velocity_limits
        if acceleration_limits is not UNSET:
            field_dict["acceleration_limits"] = acceleration_limits
        if acceleration_fraction is not UNSET:
            field_dict["acceleration_fraction"] = acceleration_fraction
        if velocity_scale is not UNSET:
            field_dict["velocity_scale"] = velocity_scale

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.timing_in_acceleration_limits_type_1 import TimingInAccelerationLimitsType1  # noqa: PLC0415
        from ..models.timing_in_velocity_limits_type_1 import TimingInVelocityLimitsType1  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_velocity_limits(
            data: object,
        ) -> list[float] | None | TimingInVelocityLimitsType1 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                velocity_limits_type_0 = cast(list[float], data)

                return velocity_limits_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                velocity_limits_type_1 = TimingInVelocityLimitsType1.from_dict(data)

                return velocity_limits_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | TimingInVelocityLimitsType1 | Unset, data)

        velocity_limits = _parse_velocity_limits(d.pop("velocity_limits", UNSET))

        def _parse_acceleration_limits(
            data: object,
        ) -> list[float] | None | TimingInAccelerationLimitsType1 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                acceleration_limits_type_0 = cast(list[float], data)

                return acceleration_limits_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                acceleration_limits_type_1 = TimingInAccelerationLimitsType1.from_dict(data)

                return acceleration_limits_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | TimingInAccelerationLimitsType1 | Unset, data)

        acceleration_limits = _parse_acceleration_limits(d.pop("acceleration_limits", UNSET))

        def _parse_acceleration_fraction(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        acceleration_fraction = _parse_acceleration_fraction(d.pop("acceleration_fraction", UNSET))

        velocity_scale = d.pop("velocity_scale", UNSET)

        timing_in = cls(
            velocity_limits=velocity_limits,
            acceleration_limits=acceleration_limits,
            acceleration_fraction=acceleration_fraction,
            velocity_scale=velocity_scale,
        )

        return timing_in
