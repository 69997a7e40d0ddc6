"""Validation of a DH table document (the format is in :mod:`dh2urdf.table`) into SI.

:func:`table_fields` takes the document as plain Python values (from
:mod:`dh2urdf.loaders` or an HTTP body), checks every field, converts lengths and angles
to SI (m, rad), fills the defaults and returns the fields of a
:class:`~dh2urdf.table.DHTable`. The first offending field raises
:class:`~dh2urdf.errors.DHError` with its path into the document
(0-based list indices, e.g. ``joints[2].lower``).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from dh2urdf.errors import DHError
from dh2urdf.joint import (
    CONVENTIONS,
    DEFAULT_GEOMETRY_RADIUS,
    JOINT_TYPES,
    DHJoint,
    LinkDynamics,
    Transform,
)
from dh2urdf.loaders import HugeInt
from dh2urdf.names import reserved_names

#: Length units and how many of them make one metre.
LENGTH_UNITS: dict[str, int] = {"m": 1, "cm": 100, "mm": 1000}
ANGLE_UNITS: tuple[str, ...] = ("rad", "deg")
#: Default velocity limits (SI): rad/s for revolute/continuous joints, m/s for prismatic ones.
DEFAULT_VELOCITY = {"revolute": math.pi, "continuous": math.pi, "prismatic": 1.0}
#: Default effort limit (SI): N·m for revolute/continuous joints, N for prismatic ones.
DEFAULT_EFFORT = 100.0

ROBOT_NAME_PATTERN = re.compile(r"[a-z0-9_-]{1,64}")
JOINT_NAME_PATTERN = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_-]{0,63}")
MAX_DESCRIPTION_LENGTH = 1000
#: Largest magnitude of a length (m, after unit conversion) or an angle (rad) in a table.
MAX_ABS_VALUE = 1e6

#: Largest link mass (kg) a row may give.
MAX_LINK_MASS = 1e6
#: Largest |entry| (kg·m²) of a row's rotational inertia.
MAX_LINK_INERTIA = 1e6
#: Tolerance (relative to the largest |entry|) of the inertia checks: positive
#: semi-definiteness and the triangle inequality of the principal moments.
INERTIA_TOLERANCE = 1e-9
#: The six entries of a row's ``inertia``, in order (URDF's ``<inertia>`` attributes).
INERTIA_ENTRIES = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")

_TOP_KEYS = ("name", "description", "convention", "units", "base", "tool", "geometry", "joints")
_JOINT_KEYS = (
    "name",
    "type",
    "a",
    "alpha",
    "d",
    "theta",
    "lower",
    "upper",
    "velocity",
    "effort",
    "mass",
    "com",
    "inertia",
)
_TRANSFORM_KEYS = ("xyz", "rpy")


def _describe(value: Any) -> str:
    if isinstance(value, HugeInt):
        return f"an integer literal of {len(value)} digits"
    text = repr(value)
    if len(text) > 40:
        text = text[:37] + "..."
    return f"{type(value).__name__} ({text})" if not isinstance(value, str) else text


def _fmt(value: float) -> str:
    """A table value for messages: ``10`` rather than ``10.0``."""
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else repr(value)


def _mapping(value: Any, path: str) -> Mapping[str, Any]:
    if not isinstance(value, Mapping):
        what = "a mapping (YAML/JSON object)"
        raise DHError(path or None, f"expected {what}, got {_describe(value)}")
    for key in value:
        if not isinstance(key, str) or isinstance(key, HugeInt):
            raise DHError(path or None, f"keys must be strings, got {_describe(key)}")
        if _SURROGATE.search(key):
            raise DHError(path or None, "keys must be valid Unicode text (a lone surrogate is not)")
    return value


def _check_keys(data: Mapping[str, Any], allowed: Sequence[str], path: str) -> None:
    for key in data:
        if key not in allowed:
            where = f"{path}.{key}" if path else key
            raise DHError(where, f"unknown field (expected one of: {', '.join(allowed)})")


def _number(value: Any, path: str) -> float:
    if isinstance(value, HugeInt):
        raise DHError(path, f"number too large (an integer literal of {len(value)} digits)")
    if isinstance(value, bool) or not isinstance(value, int | float):
        hint = ""
        if isinstance(value, str) and "," in value:
            hint = " (use '.' as the decimal separator)"
        raise DHError(path, f"expected a number, got {_describe(value)}{hint}")
    try:
        result = float(value)
    except OverflowError as exc:
        raise DHError(path, "must be finite, got a number too large for a float") from exc
    if not math.isfinite(result):
        raise DHError(path, f"must be finite, got {result!r}")
    return result


def _required_number(data: Mapping[str, Any], key: str, path: str) -> float:
    if key not in data or data[key] is None:
        raise DHError(f"{path}.{key}", "field required")
    return _number(data[key], f"{path}.{key}")


def _optional_number(data: Mapping[str, Any], key: str, path: str) -> float | None:
    if key not in data or data[key] is None:
        return None
    return _number(data[key], f"{path}.{key}")


def _string(value: Any, path: str) -> str:
    if not isinstance(value, str) or isinstance(value, HugeInt):
        raise DHError(path, f"expected a string, got {_describe(value)}")
    if _SURROGATE.search(value):
        raise DHError(path, "must be valid Unicode text (a lone UTF-16 surrogate is not)")
    return value


_SURROGATE = re.compile("[\ud800-\udfff]")


def _bounded(value: float, path: str, unit: str) -> float:
    """``value`` (SI) unless its magnitude exceeds :data:`MAX_ABS_VALUE`."""
    if abs(value) > MAX_ABS_VALUE:
        raise DHError(
            path, f"magnitude above {MAX_ABS_VALUE:g} {unit} is not accepted, got {value!r} {unit}"
        )
    return value


def _triple(
    value: Any, path: str, scale: Callable[[float], float], unit: str
) -> tuple[float, float, float]:
    if isinstance(value, str | bytes) or not isinstance(value, Sequence):
        raise DHError(path, f"expected a list of 3 numbers, got {_describe(value)}")
    if len(value) != 3:
        raise DHError(path, f"expected a list of 3 numbers, got {len(value)} items")
    x, y, z = (
        _bounded(scale(_number(v, f"{path}[{i}]")), f"{path}[{i}]", unit)
        for i, v in enumerate(value)
    )
    return (x, y, z)


def _transform(
    data: Any,
    path: str,
    length: Callable[[float], float],
    angle: Callable[[float], float],
) -> Transform:
    if data is None:
        return Transform()
    m = _mapping(data, path)
    _check_keys(m, _TRANSFORM_KEYS, path)
    xyz = _triple(m["xyz"], f"{path}.xyz", length, "m") if m.get("xyz") is not None else (0.0,) * 3
    rpy = _triple(m["rpy"], f"{path}.rpy", angle, "rad") if m.get("rpy") is not None else (0.0,) * 3
    return Transform(xyz=xyz, rpy=rpy)  # type: ignore[arg-type]


def _length_scale(unit: str) -> Callable[[float], float]:
    divisor = LENGTH_UNITS[unit]
    if divisor == 1:
        return lambda v: v + 0.0
    # Division by an exact integer is correctly rounded (223.5 mm -> 0.2235 m exactly).
    return lambda v: v / divisor + 0.0


def _angle_scale(unit: str) -> Callable[[float], float]:
    if unit == "rad":
        return lambda v: v + 0.0
    return lambda v: math.radians(v) + 0.0


def _parse_units(data: Any) -> tuple[str, str]:
    if data is None:
        return "m", "rad"
    m = _mapping(data, "units")
    _check_keys(m, ("length", "angle"), "units")
    length = m.get("length", "m")
    angle = m.get("angle", "rad")
    if not isinstance(length, str) or length not in LENGTH_UNITS:
        expected = ", ".join(repr(u) for u in LENGTH_UNITS)
        raise DHError("units.length", f"unknown length unit {length!r} (expected {expected})")
    if not isinstance(angle, str) or angle not in ANGLE_UNITS:
        expected = ", ".join(repr(u) for u in ANGLE_UNITS)
        raise DHError("units.angle", f"unknown angle unit {angle!r} (expected {expected})")
    return length, angle


def _parse_joint(
    data: Any,
    index: int,
    length: Callable[[float], float],
    angle: Callable[[float], float],
) -> DHJoint:
    path = f"joints[{index}]"
    m = _mapping(data, path)
    _check_keys(m, _JOINT_KEYS, path)

    name = m.get("name")
    if name is None:
        name = f"j{index + 1}"
    else:
        name = _string(name, f"{path}.name")
        if not JOINT_NAME_PATTERN.fullmatch(name):
            raise DHError(
                f"{path}.name",
                f"invalid joint name {name!r} (1 to 64 letters, digits, '_' or '-', "
                "not starting with '-')",
            )

    jtype = m.get("type", "revolute")
    if jtype is None:
        jtype = "revolute"
    if jtype not in JOINT_TYPES:
        expected = ", ".join(repr(t) for t in JOINT_TYPES)
        raise DHError(f"{path}.type", f"unknown joint type {jtype!r} (expected {expected})")

    a = _bounded(length(_required_number(m, "a", path)), f"{path}.a", "m")
    alpha = _bounded(angle(_required_number(m, "alpha", path)), f"{path}.alpha", "rad")
    d = _bounded(length(_required_number(m, "d", path)), f"{path}.d", "m")
    theta = _bounded(angle(_required_number(m, "theta", path)), f"{path}.theta", "rad")

    variable = length if jtype == "prismatic" else angle
    raw_lower = _optional_number(m, "lower", path)
    raw_upper = _optional_number(m, "upper", path)
    lower: float | None
    upper: float | None
    if jtype == "continuous":
        for key, raw in (("lower", raw_lower), ("upper", raw_upper)):
            if raw is not None:
                raise DHError(f"{path}.{key}", "a continuous joint has no position limits")
        lower = upper = None
    else:
        if jtype == "prismatic":
            for key, raw in (("lower", raw_lower), ("upper", raw_upper)):
                if raw is None:
                    raise DHError(f"{path}.{key}", "field required for a prismatic joint")
        if raw_lower is not None and raw_upper is not None and raw_lower > raw_upper:
            raise DHError(f"{path}.lower", f"lower ({_fmt(raw_lower)}) > upper ({_fmt(raw_upper)})")
        unit = "m" if jtype == "prismatic" else "rad"
        lower = variable(raw_lower) if raw_lower is not None else -math.pi
        upper = variable(raw_upper) if raw_upper is not None else math.pi
        _bounded(lower, f"{path}.lower", unit)
        _bounded(upper, f"{path}.upper", unit)
        if lower > upper:
            # Only one bound given and it lies beyond the default of the other one.
            given = "lower" if raw_lower is not None else "upper"
            raise DHError(
                f"{path}.{given}",
                f"lower ({lower!r} rad) > upper ({upper!r} rad) with the default ±180° bound",
            )

    raw_velocity = _optional_number(m, "velocity", path)
    if raw_velocity is None:
        velocity = DEFAULT_VELOCITY[jtype]
    else:
        if raw_velocity <= 0:
            raise DHError(f"{path}.velocity", f"must be > 0, got {_fmt(raw_velocity)}")
        velocity = variable(raw_velocity)
    effort = _optional_number(m, "effort", path)
    if effort is None:
        effort = DEFAULT_EFFORT
    elif effort <= 0:
        raise DHError(f"{path}.effort", f"must be > 0, got {_fmt(effort)}")

    dynamics = _parse_dynamics(m, path, length)

    return DHJoint(
        name=name,
        type=jtype,
        a=a,
        alpha=alpha,
        d=d,
        theta=theta,
        lower=lower,
        upper=upper,
        velocity=velocity,
        effort=effort,
        dynamics=dynamics,
    )


def _parse_dynamics(
    m: Mapping[str, Any], path: str, length: Callable[[float], float]
) -> LinkDynamics | None:
    """A row's ``mass`` (kg), ``com`` (table length units, frame i) and ``inertia`` (six
    entries, kg·m², about the com in frame i's axes); ``None`` when the row has none."""
    given = [key for key in ("mass", "com", "inertia") if m.get(key) is not None]
    if not given:
        return None
    mass = _optional_number(m, "mass", path)
    if mass is None:
        raise DHError(f"{path}.mass", f"field required when the row gives {given[0]}")
    if mass < 0:
        raise DHError(f"{path}.mass", f"must be >= 0 kg, got {_fmt(mass)}")
    if mass > MAX_LINK_MASS:
        raise DHError(f"{path}.mass", f"above {MAX_LINK_MASS:g} kg is not accepted, got {mass!r}")
    com = (0.0, 0.0, 0.0)
    if m.get("com") is not None:
        com = _triple(m["com"], f"{path}.com", length, "m")
    inertia = (0.0,) * 6
    if m.get("inertia") is not None:
        inertia = _inertia(m["inertia"], f"{path}.inertia")
    return LinkDynamics(mass=mass + 0.0, com=com, inertia=inertia)


_SIX = "expected a list of 6 numbers [ixx, ixy, ixz, iyy, iyz, izz] (kg·m²),"


def _inertia(value: Any, path: str) -> tuple[float, float, float, float, float, float]:
    """Six finite entries ``[ixx, ixy, ixz, iyy, iyz, izz]`` (kg·m²) of a physical rigid
    body's rotational inertia: bounded, diagonal ≥ 0, positive semi-definite, principal
    moments obeying the triangle inequality (each at most the sum of the other two)."""
    if isinstance(value, str | bytes | Mapping) or not isinstance(value, Sequence):
        raise DHError(path, f"{_SIX} got {_describe(value)}")
    if len(value) != 6:
        raise DHError(path, f"{_SIX} got {len(value)} items")
    entries = [_number(v, f"{path}[{i}]") + 0.0 for i, v in enumerate(value)]
    for i, v in enumerate(entries):
        if abs(v) > MAX_LINK_INERTIA:
            raise DHError(
                f"{path}[{i}]",
                f"magnitude above {MAX_LINK_INERTIA:g} kg·m² is not accepted, got {v!r}",
            )
    for i in (0, 3, 5):
        if entries[i] < 0:
            raise DHError(
                f"{path}[{i}]", f"{INERTIA_ENTRIES[i]} must be >= 0 kg·m², got {_fmt(entries[i])}"
            )
    ixx, ixy, ixz, iyy, iyz, izz = entries
    matrix = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    scale = max(abs(v) for v in entries)
    tolerance = INERTIA_TOLERANCE * scale
    moments = np.linalg.eigvalsh(matrix)  # ascending
    if moments[0] < -tolerance:
        raise DHError(
            path,
            "not positive semi-definite (principal moments "
            f"{', '.join(f'{p:.6g}' for p in moments)} kg·m²)",
        )
    if moments[0] + moments[1] < moments[2] - tolerance:
        raise DHError(
            path,
            "principal moments break the triangle inequality of a rigid body "
            f"({moments[0]:.6g} + {moments[1]:.6g} < {moments[2]:.6g} kg·m²)",
        )
    return (ixx, ixy, ixz, iyy, iyz, izz)


def table_fields(data: Any) -> dict[str, Any]:
    """The fields of the validated SI table of a parsed document (a mapping), the keyword
    arguments of :class:`dh2urdf.table.DHTable`; :class:`DHError` otherwise."""
    doc = _mapping(data, "")
    _check_keys(doc, _TOP_KEYS, "")

    if doc.get("name") is None:
        raise DHError("name", "field required")
    name = _string(doc["name"], "name")
    if not ROBOT_NAME_PATTERN.fullmatch(name):
        raise DHError(
            "name",
            f"invalid robot name {name!r} (1 to 64 lowercase letters, digits, '_' or '-')",
        )

    description = doc.get("description")
    description = "" if description is None else _string(description, "description")
    if len(description) > MAX_DESCRIPTION_LENGTH:
        raise DHError("description", f"longer than {MAX_DESCRIPTION_LENGTH} characters")

    if doc.get("convention") is None:
        raise DHError("convention", "field required")
    convention = doc["convention"]
    if convention not in CONVENTIONS:
        raise DHError(
            "convention", f"unknown convention {convention!r} (expected 'standard' or 'modified')"
        )

    length_unit, angle_unit = _parse_units(doc.get("units"))
    length = _length_scale(length_unit)
    angle = _angle_scale(angle_unit)

    base = _transform(doc.get("base"), "base", length, angle)
    tool = _transform(doc.get("tool"), "tool", length, angle)

    radius = DEFAULT_GEOMETRY_RADIUS
    if doc.get("geometry") is not None:
        g = _mapping(doc["geometry"], "geometry")
        _check_keys(g, ("radius",), "geometry")
        value = _optional_number(g, "radius", "geometry")
        if value is not None:
            if value < 0:
                raise DHError("geometry.radius", f"must be >= 0, got {_fmt(value)}")
            _bounded(value, "geometry.radius", "m")
            radius = value + 0.0

    rows = doc.get("joints")
    if rows is None:
        raise DHError("joints", "field required")
    if isinstance(rows, str | bytes | Mapping) or not isinstance(rows, Sequence):
        raise DHError("joints", f"expected a list of joint rows, got {_describe(rows)}")
    if len(rows) == 0:
        raise DHError("joints", "at least one joint is required")

    joints: list[DHJoint] = []
    seen: dict[str, int] = {}
    for index, row in enumerate(rows):
        joint = _parse_joint(row, index, length, angle)
        if joint.name in seen:
            raise DHError(
                f"joints[{index}].name",
                f"duplicate joint name {joint.name!r} (also joints[{seen[joint.name]}])",
            )
        seen[joint.name] = index
        joints.append(joint)

    # Joint names share Pinocchio's frame namespace with the generated links and fixed joints.
    reserved = reserved_names(len(joints))
    for index, joint in enumerate(joints):
        if joint.name in reserved:
            raise DHError(
                f"joints[{index}].name",
                f"{joint.name!r} is reserved for a frame of the generated model",
            )

    return dict(
        name=name,
        convention=convention,
        joints=tuple(joints),
        base=base,
        tool=tool,
        geometry_radius=radius,
        description=description,
    )
