from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.jacobian_reference import JacobianReference
from ..types import UNSET, Unset

T = TypeVar("T", bound="WrenchIn")


@_attrs_define
class WrenchIn:
    """A wrench a frame exerts on its environment (as in statics: τ = Jᵀ·F).

    Attributes:
        values (list[float]): [fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its environment.
        frame (None | str | Unset): Frame; default the end effector (with `group`: the group's tip).
        reference (JacobianReference | Unset):
    """

    values: list[float]
    frame: None | str | Unset = UNSET
    reference: JacobianReference | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        values = self.values

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        reference: str | Unset = UNSET
        if not isinstance(self.reference, Unset):
            reference = self.reference.value

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "values": values,
            }
        )
        if frame is not UNSET:
            field_dict["frame"] = frame
        if reference is not UNSET:
            field_dict["reference"] = reference

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        values = cast(list[float], d.pop("values"))

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        _reference = d.pop("reference", UNSET)
        reference: JacobianReference | Unset
        if isinstance(_reference, Unset):
            reference = UNSET
        else:
            reference = JacobianReference(_reference)

        wrench_in = cls(
            values=values,
            frame=frame,
            reference=reference,
        )

        return wrench_in
