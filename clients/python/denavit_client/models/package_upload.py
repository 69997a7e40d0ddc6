from __future__ import annotations

from collections.abc import Mapping
from io import BytesIO
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from .. import types
from ..types import UNSET, File, Unset

T = TypeVar("T", bound="PackageUpload")


@_attrs_define
class PackageUpload:
    """A robot as a description package: an archive with its description and meshes.

    Sent as ``multipart/form-data``; every field but ``archive`` is a text part.

        Attributes:
            name (str): Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).
            archive (File): The package: a zip or tar.gz archive (size and entry limits: DENAVIT_MAX_PACKAGE_BYTES, _FILES,
                _UNPACKED_BYTES).
            description (str): Path inside the archive of the robot description: .urdf, .xacro or MJCF .xml (e.g.
                panda_description/urdf/panda.urdf).
            srdf (None | str | Unset): Path of an SRDF file; one ending .xacro (e.g. ur_moveit_config/srdf/ur.srdf.xacro) is
                expanded like a .xacro description, with the same packages.
            xacro_args (None | str | Unset): JSON object of xacro arguments: names to strings, numbers or booleans
                ({"arm_id": "panda"}); also those of a .xacro SRDF unless srdf_xacro_args is given.
            srdf_xacro_args (None | str | Unset): JSON object of the arguments of a .xacro SRDF, when they differ from
                xacro_args ({"name": "ur5e", "prefix": ""}); same rules as xacro_args.
            ee_frame (None | str | Unset): Default end-effector frame (default: the SRDF end effector's parent link, else
                the tip of the longest serial chain that is not a gripper finger).
            summary (str | Unset): Short description of the robot. Default: ''.
    """

    name: str
    archive: File
    description: str
    srdf: None | str | Unset = UNSET
    xacro_args: None | str | Unset = UNSET
    srdf_xacro_args: None | str | Unset = UNSET
    ee_frame: None | str | Unset = UNSET
    summary: str | Unset = ""

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        archive = self.archive.to_tuple()

        description = self.description

        srdf: None | str | Unset
        if isinstance(self.srdf, Unset):
            srdf = UNSET
        else:
            srdf = self.srdf

        xacro_args: None | str | Unset
        if isinstance(self.xacro_args, Unset):
            xacro_args = UNSET
        else:
            xacro_args = self.xacro_args

        srdf_xacro_args: None | str | Unset
        if isinstance(self.srdf_xacro_args, Unset):
            srdf_xacro_args = UNSET
        else:
            srdf_xacro_args = self.srdf_xacro_args

        ee_frame: None | str | Unset
        if isinstance(self.ee_frame, Unset):
            ee_frame = UNSET
        else:
            ee_frame = self.ee_frame

        summary = self.summary

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
                "archive": archive,
                "description": description,
            }
        )
        if srdf is not UNSET:
            field_dict["srdf"] = srdf
        if xacro_args is not UNSET:
            field_dict["xacro_args"] = xacro_args
        if srdf_xacro_args is not UNSET:
            field_dict["srdf_xacro_args"] = srdf_xacro_args
        if ee_frame is not UNSET:
            field_dict["ee_frame"] = ee_frame
        if summary is not UNSET:
            field_dict["summary"] = summary

        return field_dict

    def to_multipart(self) -> types.RequestFiles:
        files: types.RequestFiles = []

        files.append(("name", (None, str(self.name).encode(), "text/plain")))

        files.append(("archive", self.archive.to_tuple()))

        files.append(("description", (None, str(self.description).encode(), "text/plain")))

        if not isinstance(self.srdf, Unset):
            if isinstance(self.srdf, str):
                files.append(("srdf", (None, str(self.srdf).encode(), "text/plain")))
            else:
                files.append(("srdf", (None, str(self.srdf).encode(), "text/plain")))

        if not isinstance(self.xacro_args, Unset):
            if isinstance(self.xacro_args, str):
                files.append(("xacro_args", (None, str(self.xacro_args).encode(), "text/plain")))
            else:
                files.append(("xacro_args", (None, str(self.xacro_args).encode(), "text/plain")))

        if not isinstance(self.srdf_xacro_args, Unset):
            if isinstance(self.srdf_xacro_args, str):
                files.append(
                    ("srdf_xacro_args", (None, str(self.srdf_xacro_args).encode(), "text/plain"))
                )
            else:
                files.append(
                    ("srdf_xacro_args", (None, str(self.srdf_xacro_args).encode(), "text/plain"))
                )

        if not isinstance(self.ee_frame, Unset):
            if isinstance(self.ee_frame, str):
                files.append(("ee_frame", (None, str(self.ee_frame).encode(), "text/plain")))
            else:
                files.append(("ee_frame", (None, str(self.ee_frame).encode(), "text/plain")))

        if not isinstance(self.summary, Unset):
            files.append(("summary", (None, str(self.summary).encode(), "text/plain")))

        return files

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        archive = File(payload=BytesIO(d.pop("archive")))

        description = d.pop("description")

        def _parse_srdf(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        srdf = _parse_srdf(d.pop("srdf", UNSET))

        def _parse_xacro_args(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        xacro_args = _parse_xacro_args(d.pop("xacro_args", UNSET))

        def _parse_srdf_xacro_args(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        srdf_xacro_args = _parse_srdf_xacro_args(d.pop("srdf_xacro_args", UNSET))

        def _parse_ee_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        ee_frame = _parse_ee_frame(d.pop("ee_frame", UNSET))

        summary = d.pop("summary", UNSET)

        package_upload = cls(
            name=name,
            archive=archive,
            description=description,
            srdf=srdf,
            xacro_args=xacro_args,
            srdf_xacro_args=srdf_xacro_args,
            ee_frame=ee_frame,
            summary=summary,
        )

        return package_upload
