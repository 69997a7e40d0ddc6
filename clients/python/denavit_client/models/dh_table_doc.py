from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.dh_convention import DHConvention
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.dh_geometry_doc import DHGeometryDoc
    from ..models.dh_row_doc import DHRowDoc
    from ..models.dh_transform_doc import DHTransformDoc
    from ..models.dh_units_doc import DHUnitsDoc


T = TypeVar("T", bound="DHTableDoc")


@_attrs_define
class DHTableDoc:
    """A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type: application/yaml``).

    ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
    Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
    DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
    dh_n·T_tool.

        Attributes:
            name (str): Robot id: 1-64 of a-z, 0-9, '_' and '-'.
            convention (DHConvention):
            joints (list[DHRowDoc]):
            description (None | str | Unset):  Default: ''.
            units (DHUnitsDoc | None | Unset):
            base (DHTransformDoc | None | Unset): World → DH frame 0.
            tool (DHTransformDoc | None | Unset): DH frame n → tool (TCP).
            geometry (DHGeometryDoc | None | Unset):
    """

    name: str
    convention: DHConvention
    joints: list[DHRowDoc]
    description: None | str | Unset = ""
    units: DHUnitsDoc | None | Unset = UNSET
    base: DHTransformDoc | None | Unset = UNSET
    tool: DHTransformDoc | None | Unset = UNSET
    geometry: DHGeometryDoc | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.dh_geometry_doc import DHGeometryDoc  # noqa: PLC0415
        from ..models.dh_transform_doc import DHTransformDoc  # noqa: PLC0415
        from ..models.dh_units_doc import DHUnitsDoc  # noqa: PLC0415

        name = self.name

        convention = self.convention.value

        joints = []
        for joints_item_data in self.joints:
            joints_item = joints_item_data.to_dict()
            joints.append(joints_item)

        description: None | str | Unset
        if isinstance(self.description, Unset):
            description = UNSET
        else:
            description = self.description

        units: dict[str, Any] | None | Unset
        if isinstance(self.units, Unset):
            units = UNSET
        elif isinstance(self.units, DHUnitsDoc):
            units = self.units.to_dict()
        else:
            units = self.units

        base: dict[str, Any] | None | Unset
        if isinstance(self.base, Unset):
            base = UNSET
        elif isinstance(self.base, DHTransformDoc):
            base = self.base.to_dict()
        else:
            base = self.base

        tool: dict[str, Any] | None | Unset
        if isinstance(self.tool, Unset):
            tool = UNSET
        elif isinstance(self.tool, DHTransformDoc):
            tool = self.tool.to_dict()
        else:
            tool = self.tool

        geometry: dict[str, Any] | None | Unset
        if isinstance(self.geometry, Unset):
            geometry = UNSET
        elif isinstance(self.geometry, DHGeometryDoc):
            geometry = self.geometry.to_dict()
        else:
            geometry = self.geometry

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
                "convention": convention,
                "joints": joints,
            }
        )
        if description is not UNSET:
            field_dict["description"] = description
        if units is not UNSET:
            field_dict["units"] = units
        if base is not UNSET:
            field_dict["base"] = base
        if tool is not UNSET:
            field_dict["tool"] = tool
        if geometry is not UNSET:
            field_dict["geometry"] = geometry

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.dh_geometry_doc import DHGeometryDoc  # noqa: PLC0415
        from ..models.dh_row_doc import DHRowDoc  # noqa: PLC0415
        from ..models.dh_transform_doc import DHTransformDoc  # noqa: PLC0415
        from ..models.dh_units_doc import DHUnitsDoc  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        convention = DHConvention(d.pop("convention"))

        joints = []
        _joints = d.pop("joints")
        for joints_item_data in _joints:
            joints_item = DHRowDoc.from_dict(joints_item_data)

            joints.append(joints_item)

        def _parse_description(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        description = _parse_description(d.pop("description", UNSET))

        def _parse_units(data: object) -> DHUnitsDoc | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                units_type_0 = DHUnitsDoc.from_dict(data)

                return units_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DHUnitsDoc | None | Unset, data)

        units = _parse_units(d.pop("units", UNSET))

        def _parse_base(data: object) -> DHTransformDoc | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                base_type_0 = DHTransformDoc.from_dict(data)

                return base_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DHTransformDoc | None | Unset, data)

        base = _parse_base(d.pop("base", UNSET))

        def _parse_tool(data: object) -> DHTransformDoc | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                tool_type_0 = DHTransformDoc.from_dict(data)

                return tool_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DHTransformDoc | None | Unset, data)

        tool = _parse_tool(d.pop("tool", UNSET))

        def _parse_geometry(data: object) -> DHGeometryDoc | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                geometry_type_0 = DHGeometryDoc.from_dict(data)

                return geometry_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DHGeometryDoc | None | Unset, data)

        geometry = _parse_geometry(d.pop("geometry", UNSET))

        dh_table_doc = cls(
            name=name,
            convention=convention,
            joints=joints,
            description=description,
            units=units,
            base=base,
            tool=tool,
            geometry=geometry,
        )

        return dh_table_doc
