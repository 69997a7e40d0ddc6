from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="PayloadIn")


@_attrs_define
class PayloadIn:
    """A rigid load fixed to a frame: its mass, centre of mass and rotational inertia.

    Attributes:
        mass (float): Mass (kg), within [0, 10⁶].
        frame (None | str | Unset): The frame the load is fixed to; default the robot's tip (with `group`: the group's
            tip).
        com (list[float] | Unset): Its centre of mass (m) in the frame's axes, from the frame's origin.
        inertia (list[float] | None | Unset): Rotational inertia about the centre of mass in the frame's axes, the six
            URDF entries [ixx, ixy, ixz, iyy, iyz, izz] (kg·m²); absent: a point mass. It must be one a rigid body has
            (positive semi-definite, triangle inequality).
    """

    mass: float
    frame: None | str | Unset = UNSET
    com: list[float] | Unset = UNSET
    inertia: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        mass = self.mass

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        com: list[float] | Unset = UNSET
        if not isinstance(self.com, Unset):
            com = self.com

        inertia: list[float] | None | Unset
        if isinstance(self.inertia, Unset):
            inertia = UNSET
        elif isinstance(self.inertia, list):
            inertia = self.inertia

        else:
            inertia = self.inertia

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "mass": mass,
            }
        )
        if frame is not UNSET:
            field_dict["frame"] = frame
        if com is not UNSET:
            field_dict["com"] = com
        if inertia is not UNSET:
            field_dict["inertia"] = inertia

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        mass = d.pop("mass")

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        com = cast(list[float], d.pop("com", UNSET))

        def _parse_inertia(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                inertia_type_0 = cast(list[float], data)

                return inertia_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        inertia = _parse_inertia(d.pop("inertia", UNSET))

        payload_in = cls(
            mass=mass,
            frame=frame,
            com=com,
            inertia=inertia,
        )

        return payload_in
