from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.payload_in import PayloadIn


T = TypeVar("T", bound="DynamicsBatchRequest")


@_attrs_define
class DynamicsBatchRequest:
    """Many states (q, q̇, q̈), one optional payload.

    Attributes:
        configurations (list[list[float]]): N configurations, each one value per joint in joint order (rad, m); with
            `group`, rows of the group's joints only are accepted too (others neutral).
        velocities (list[list[float]] | None | Unset): N rows of joint velocities, as wide as `configurations`' rows;
            zeros when absent.
        accelerations (list[list[float]] | None | Unset): N rows of joint accelerations, as wide as `configurations`'
            rows; zeros when absent.
        payload (None | PayloadIn | Unset): A load fixed to a frame.
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
    """

    configurations: list[list[float]]
    velocities: list[list[float]] | None | Unset = UNSET
    accelerations: list[list[float]] | None | Unset = UNSET
    payload: None | PayloadIn | Unset = UNSET
    group: None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.payload_in import PayloadIn  # noqa: PLC0415

        configurations = []
        for configurations_item_data in self.configurations:
            configurations_item = configurations_item_data

            configurations.append(configurations_item)

        velocities: list[list[float]] | None | Unset
        if isinstance(self.velocities, Unset):
            velocities = UNSET
        elif isinstance(self.velocities, list):
            velocities = []
            for velocities_type_0_item_data in self.velocities:
                velocities_type_0_item = velocities_type_0_item_data

                velocities.append(velocities_type_0_item)

        else:
            velocities = self.velocities

        accelerations: list[list[float]] | None | Unset
        if isinstance(self.accelerations, Unset):
            accelerations = UNSET
        elif isinstance(self.accelerations, list):
            accelerations = []
            for accelerations_type_0_item_data in self.accelerations:
                accelerations_type_0_item = accelerations_type_0_item_data

                accelerations.append(accelerations_type_0_item)

        else:
            accelerations = self.accelerations

        payload: dict[str, Any] | None | Unset
        if isinstance(self.payload, Unset):
            payload = UNSET
        elif isinstance(self.payload, PayloadIn):
            payload = self.payload.to_dict()
        else:
            payload = self.payload

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "configurations": configurations,
            }
        )
        if velocities is not UNSET:
            field_dict["velocities"] = velocities
        if accelerations is not UNSET:
            field_dict["accelerations"] = accelerations
        if payload is not UNSET:
            field_dict["payload"] = payload
        if group is not UNSET:
            field_dict["group"] = group

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.payload_in import PayloadIn  # noqa: PLC0415

        d = dict(src_dict)
        configurations = []
        _configurations = d.pop("configurations")
        for configurations_item_data in _configurations:
            configurations_item = cast(list[float], configurations_item_data)

            configurations.append(configurations_item)

        def _parse_velocities(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                velocities_type_0 = []
                _velocities_type_0 = data
                for velocities_type_0_item_data in _velocities_type_0:
                    velocities_type_0_item = cast(list[float], velocities_type_0_item_data)

                    velocities_type_0.append(velocities_type_0_item)

                return velocities_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        velocities = _parse_velocities(d.pop("velocities", UNSET))

        def _parse_accelerations(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                accelerations_type_0 = []
                _accelerations_type_0 = data
                for accelerations_type_0_item_data in _accelerations_type_0:
                    accelerations_type_0_item = cast(list[float], accelerations_type_0_item_data)

                    accelerations_type_0.append(accelerations_type_0_item)

                return accelerations_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        accelerations = _parse_accelerations(d.pop("accelerations", UNSET))

        def _parse_payload(data: object) -> None | PayloadIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                payload_type_0 = PayloadIn.from_dict(data)

                return payload_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PayloadIn | Unset, data)

        payload = _parse_payload(d.pop("payload", UNSET))

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        dynamics_batch_request = cls(
            configurations=configurations,
            velocities=velocities,
            accelerations=accelerations,
            payload=payload,
            group=group,
        )

        return dynamics_batch_request
