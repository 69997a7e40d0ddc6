from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="UrdfUpload")


@_attrs_define
class UrdfUpload:
    """A robot given as URDF text (and optionally SRDF).

    Attributes:
        name (str): Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).
        urdf (str): URDF document. No DTD or entities; mesh filenames must be package://<package>/<path> URIs; only
            revolute, continuous, prismatic and fixed joints.
        srdf (None | str | Unset): SRDF document: disabled collision pairs, planning groups (chain, joints, links,
            subgroups), end effectors and group states, checked against the URDF.
        ee_frame (None | str | Unset): Default end-effector frame (default: the parent_link of the SRDF's first end
            effector, else the tip of the longest serial chain that is not a gripper finger; see end_effector in GET
            /robots/{robot_id}).
        description (str | Unset): Short description. Default: ''.
    """

    name: str
    urdf: str
    srdf: None | str | Unset = UNSET
    ee_frame: None | str | Unset = UNSET
    description: str | Unset = ""

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        urdf = self.urdf

        srdf: None | str | Unset
        if isinstance(self.srdf, Unset):
            srdf = UNSET
        else:
            srdf = self.srdf

        ee_frame: None | str | Unset
        if isinstance(self.ee_frame, Unset):
            ee_frame = UNSET
        else:
            ee_frame = self.ee_frame

        description = self.description

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
                "urdf": urdf,
            }
        )
        if srdf is not UNSET:
            field_dict["srdf"] = srdf
        if ee_frame is not UNSET:
            field_dict["ee_frame"] = ee_frame
        if description is not UNSET:
            field_dict["description"] = description

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        urdf = d.pop("urdf")

        def _parse_srdf(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        srdf = _parse_srdf(d.pop("srdf", UNSET))

        def _parse_ee_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        ee_frame = _parse_ee_frame(d.pop("ee_frame", UNSET))

        description = d.pop("description", UNSET)

        urdf_upload = cls(
            name=name,
            urdf=urdf,
            srdf=srdf,
            ee_frame=ee_frame,
            description=description,
        )

        return urdf_upload
