from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.dh_joint_type import DHJointType
from ..types import UNSET, Unset

T = TypeVar("T", bound="DHRowDoc")


@_attrs_define
class DHRowDoc:
    """One row: joint i's DH parameters.

    Attributes:
        a (float): Link length (a_i; a_{i-1} in the modified convention).
        alpha (float): Link twist (α_i; α_{i-1} in the modified convention).
        d (float): Link offset; the constant part for a prismatic joint.
        theta (float): Joint angle offset (θ = q + theta for revolute joints).
        name (None | str | Unset): Joint name (default j<i>, 1-based).
        type_ (DHJointType | None | Unset): Joint kind (null: revolute). Default: DHJointType.REVOLUTE.
        lower (float | None | Unset): Lower limit of q (table units).
        upper (float | None | Unset): Upper limit of q (table units).
        velocity (float | None | Unset): Velocity limit (units per second).
        effort (float | None | Unset): Effort limit (N·m or N).
        mass (float | None | Unset): Mass of the link the row moves (kg, always SI); needed with com or inertia. Rows
            without it give a link without inertia (dynamics answer 422 missing-inertia).
        com (list[float] | None | Unset): The link's centre of mass [x, y, z] in frame i, the DH frame at the end of the
            row (as the Robotics Toolbox's r), in the table's length unit; default 0.
        inertia (list[float] | None | Unset): The link's rotational inertia about its centre of mass in frame i's axes,
            [ixx, ixy, ixz, iyy, iyz, izz] (kg·m², always SI): positive semi-definite, each principal moment at most the sum
            of the other two; default 0 (a point mass).
    """

    a: float
    alpha: float
    d: float
    theta: float
    name: None | str | Unset = UNSET
    type_: DHJointType | None | Unset = DHJointType.REVOLUTE
    lower: float | None | Unset = UNSET
    upper: float | None | Unset = UNSET
    velocity: float | None | Unset = UNSET
    effort: float | None | Unset = UNSET
    mass: float | None | Unset = UNSET
    com: list[float] | None | Unset = UNSET
    inertia: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        a = self.a

        alpha = self.alpha

        d = self.d

        theta = self.theta

        name: None | str | Unset
        if isinstance(self.name, Unset):
            name = UNSET
        else:
            name = self.name

        type_: None | str | Unset
        if isinstance(self.type_, Unset):
            type_ = UNSET
        elif isinstance(self.type_, DHJointType):
            type_ = self.type_.value
        else:
            type_ = self.type_

        lower: float | None | Unset
        if isinstance(self.lower, Unset):
            lower = UNSET
        else:
            lower = self.lower

        upper: float | None | Unset
        if isinstance(self.upper, Unset):
            upper = UNSET
        else:
            upper = self.upper

        velocity: float | None | Unset
        if isinstance(self.velocity, Unset):
            velocity = UNSET
        else:
            velocity = self.velocity

        effort: float | None | Unset
        if isinstance(self.effort, Unset):
            effort = UNSET
        else:
            effort = self.effort

        mass: float | None | Unset
        if isinstance(self.mass, Unset):
            mass = UNSET
        else:
            mass = self.mass

        com: list[float] | None | Unset
        if isinstance(self.com, Unset):
            com = UNSET
        elif isinstance(self.com, list):
            com = self.com

        else:
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
                "a": a,
                "alpha": alpha,
                "d": d,
                "theta": theta,
            }
        )
        if name is not UNSET:
            field_dict["name"] = name
        if type_ is not UNSET:
            field_dict["type"] = type_
        if lower is not UNSET:
            field_dict["lower"] = lower
        if upper is not UNSET:
            field_dict["upper"] = upper
        if velocity is not UNSET:
            field_dict["velocity"] = velocity
        if effort is not UNSET:
            field_dict["effort"] = effort
        if mass is not UNSET:
            field_dict["mass"] = mass
        if com is not UNSET:
            field_dict["com"] = com
        if inertia is not UNSET:
            field_dict["inertia"] = inertia

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        a = d.pop("a")

        alpha = d.pop("alpha")

        d = d.pop("d")

        theta = d.pop("theta")

        def _parse_name(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        name = _parse_name(d.pop("name", UNSET))

        def _parse_type_(data: object) -> DHJointType | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                type_type_0 = DHJointType(data)

                return type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(DHJointType | None | Unset, data)

        type_ = _parse_type_(d.pop("type", UNSET))

        def _parse_lower(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        lower = _parse_lower(d.pop("lower", UNSET))

        def _parse_upper(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        upper = _parse_upper(d.pop("upper", UNSET))

        def _parse_velocity(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        velocity = _parse_velocity(d.pop("velocity", UNSET))

        def _parse_effort(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        effort = _parse_effort(d.pop("effort", UNSET))

        def _parse_mass(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mass = _parse_mass(d.pop("mass", UNSET))

        def _parse_com(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                com_type_0 = cast(list[float], data)

                return com_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        com = _parse_com(d.pop("com", UNSET))

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

        dh_row_doc = cls(
            a=a,
            alpha=alpha,
            d=d,
            theta=theta,
            name=name,
            type_=type_,
            lower=lower,
            upper=upper,
            velocity=velocity,
            effort=effort,
            mass=mass,
            com=com,
            inertia=inertia,
        )

        return dh_row_doc
