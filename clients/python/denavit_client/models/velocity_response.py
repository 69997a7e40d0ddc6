from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.twist_reference import TwistReference
from ..models.velocity_direction import VelocityDirection
from ..types import UNSET, Unset

T = TypeVar("T", bound="VelocityResponse")


@_attrs_define
class VelocityResponse:
    """Both directions fill ``twist`` and ``joint_velocities``; inverse adds its diagnostics.

    Attributes:
        robot_id (str):
        frame (str):
        reference (TwistReference):
        direction (VelocityDirection):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        joint_velocities (list[float]): q̇ in joint order (rad/s, m/s).
        twist (list[float]): J·q̇ = [vx, vy, vz, wx, wy, wz] (m/s, rad/s).
        residual (float | None | Unset): Inverse: ‖J q̇ − twist‖ on the task rows.
        damping (float | None | Unset): Inverse: damping λ used (0: none).
        sigma_min (float | None | Unset): Inverse: smallest singular value of the task Jacobian.
    """

    robot_id: str
    frame: str
    reference: TwistReference
    direction: VelocityDirection
    q: list[float]
    joint_velocities: list[float]
    twist: list[float]
    residual: float | None | Unset = UNSET
    damping: float | None | Unset = UNSET
    sigma_min: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        reference = self.reference.value

        direction = self.direction.value

        q = self.q

        joint_velocities = self.joint_velocities

        twist = self.twist

        residual: float | None | Unset
        if isinstance(self.residual, Unset):
            residual = UNSET
        else:
            residual = self.residual

        damping: float | None | Unset
        if isinstance(self.damping, Unset):
            damping = UNSET
        else:
            damping = self.damping

        sigma_min: float | None | Unset
        if isinstance(self.sigma_min, Unset):
            sigma_min = UNSET
        else:
            sigma_min = self.sigma_min

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "reference": reference,
                "direction": direction,
                "q": q,
                "joint_velocities": joint_velocities,
                "twist": twist,
            }
        )
        if residual is not UNSET:
            field_dict["residual"] = residual
        if damping is not UNSET:
            field_dict["damping"] = damping
        if sigma_min is not UNSET:
            field_dict["sigma_min"] = sigma_min

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        reference = TwistReference(d.pop("reference"))

        direction = VelocityDirection(d.pop("direction"))

        q = cast(list[float], d.pop("q"))

        joint_velocities = cast(list[float], d.pop("joint_velocities"))

        twist = cast(list[float], d.pop("twist"))

        def _parse_residual(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        residual = _parse_residual(d.pop("residual", UNSET))

        def _parse_damping(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        damping = _parse_damping(d.pop("damping", UNSET))

        def _parse_sigma_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        sigma_min = _parse_sigma_min(d.pop("sigma_min", UNSET))

        velocity_response = cls(
            robot_id=robot_id,
            frame=frame,
            reference=reference,
            direction=direction,
            q=q,
            joint_velocities=joint_velocities,
            twist=twist,
            residual=residual,
            damping=damping,
            sigma_min=sigma_min,
        )

        velocity_response.additional_properties = d
        return velocity_response

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
