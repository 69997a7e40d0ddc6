from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="RobotFilesOut")


@_attrs_define
class RobotFilesOut:
    """Where a viewer fetches the files (meshes, textures) a robot's URDF names.

    Attributes:
        uri_prefix (str): Mesh URIs of the URDF that start with this prefix are files served here.
        url (str): Replace uri_prefix by this URL path (GET /robots/{robot_id}/files/{path}).
    """

    uri_prefix: str
    url: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        uri_prefix = self.uri_prefix

        url = self.url

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "uri_prefix": uri_prefix,
                "url": url,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        uri_prefix = d.pop("uri_prefix")

        url = d.pop("url")

        robot_files_out = cls(
            uri_prefix=uri_prefix,
            url=url,
        )

        robot_files_out.additional_properties = d
        return robot_files_out

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
