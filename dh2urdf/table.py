"""The DH table: a validated, SI-unit model of a serial arm's Denavit–Hartenberg parameters.

A table is a mapping (written as YAML or JSON, or received as an HTTP body)::

    name: armar1_arm                  # robot id, ^[a-z0-9_-]{1,64}$
    description: ARMAR-I arm          # optional free text
    convention: standard              # standard | modified
    units: {length: mm, angle: deg}   # optional; default m and rad (length m|cm|mm, angle rad|deg)
    base: {xyz: [0, 0, 0], rpy: [0, 0, 0]}   # optional world -> DH frame 0 (table units)
    tool: {xyz: [0, 0, 100], rpy: [0, 0, 0]} # optional DH frame n -> TCP (table units)
    geometry: {radius: 0.03}          # optional capsule radius in METRES (0 = no geometry)
    joints:
      - {name: shoulder, type: revolute, a: 30, alpha: -90, d: 0, theta: 0, lower: -170, upper: 170}
      - {type: prismatic, a: 0, alpha: 0, d: 100, theta: 0, lower: 0, upper: 400}

Per row: ``a``, ``alpha``, ``d``, ``theta`` are required. ``type`` is ``revolute``
(default), ``prismatic`` or ``continuous`` (a revolute joint without position limits).
``theta`` is the constant offset of a revolute joint (θ = q + theta) and ``d`` the constant
offset of a prismatic one (d = q + d). In the ``modified`` convention row i holds
``a_{i-1}, α_{i-1}, d_i, θ_i``. ``name`` defaults to ``j<i>`` (1-based). ``lower``/``upper``
are in table units (default ±180° for revolute joints, required for prismatic joints,
forbidden for continuous ones); ``velocity`` is in table units per second (default π rad/s
or 1 m/s); ``effort`` is always SI, N·m or N (default 100).

Every value is converted to SI (m, rad) when the table is built. Errors raise
:class:`DHError`, whose message names the offending field as a path into the document with
0-based list indices, e.g. ``joints[2].lower: lower (10) > upper (5)``.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
import yaml

from dh2urdf.math import xyz_rpy_to_matrix
from dh2urdf.names import reserved_names

__all__ = [
    "DHError",
    "DHJoint",
    "DHTable",
    "Transform",
    "CONVENTIONS",
    "JOINT_TYPES",
    "LENGTH_UNITS",
    "ANGLE_UNITS",
    "DEFAULT_GEOMETRY_RADIUS",
    "format_for_path",
    "ROBOT_NAME_PATTERN",
    "JOINT_NAME_PATTERN",
]

Convention = Literal["standard", "modified"]
JointType = Literal["revolute", "prismatic", "continuous"]

CONVENTIONS: tuple[str, ...] = ("standard", "modified")
JOINT_TYPES: tuple[str, ...] = ("revolute", "prismatic", "continuous")
#: Length units and how many of them make one metre.
LENGTH_UNITS: dict[str, int] = {"m": 1, "cm": 100, "mm": 1000}
ANGLE_UNITS: tuple[str, ...] = ("rad", "deg")
#: Radius (m) of the generated capsules when the table has no ``geometry`` section.
DEFAULT_GEOMETRY_RADIUS = 0.02
#: Default velocity limits (SI): rad/s for revolute/continuous joints, m/s for prismatic ones.
DEFAULT_VELOCITY = {"revolute": math.pi, "continuous": math.pi, "prismatic": 1.0}
#: Default effort limit (SI): N·m for revolute/continuous joints, N for prismatic ones.
DEFAULT_EFFORT = 100.0

ROBOT_NAME_PATTERN = re.compile(r"[a-z0-9_-]{1,64}")
JOINT_NAME_PATTERN = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_-]{0,63}")
MAX_DESCRIPTION_LENGTH = 1000
#: Largest magnitude of a length (m, after unit conversion) or an angle (rad) in a table.
MAX_ABS_VALUE = 1e6
#: Longest integer literal read as a number (longer ones are refused, naming the field:
#: Python refuses to convert integers of more than 4300 digits, and none is needed here).
MAX_INT_DIGITS = 400

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
)
_TRANSFORM_KEYS = ("xyz", "rpy")


class DHError(ValueError):
    """Invalid DH table; the message is ``"<field>: <reason>"``.

    Attributes
    ----------
    field : str or None
        Path of the offending field in the document (``joints[2].lower``, 0-based indices),
        or ``None`` when the document as a whole is at fault (unreadable YAML, ...).
    reason : str
        What is wrong, without the field path.
    """

    def __init__(self, field: str | None, reason: str) -> None:
        self.field = field
        self.reason = reason
        super().__init__(f"{field}: {reason}" if field else reason)


@dataclass(frozen=True, slots=True)
class Transform:
    """A rigid transform written as a URDF origin: translation ``xyz`` (m) then ``rpy`` (rad).

    The matrix is ``T(xyz) · Rz(yaw) · Ry(pitch) · Rx(roll)`` with ``rpy = (roll, pitch, yaw)``.
    """

    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def is_identity(self) -> bool:
        """Whether both translation and rotation are exactly zero."""
        return all(v == 0.0 for v in self.xyz + self.rpy)

    def matrix(self) -> np.ndarray:
        """The 4×4 homogeneous transform."""
        return xyz_rpy_to_matrix(self.xyz, self.rpy)


@dataclass(frozen=True, slots=True)
class DHJoint:
    """One row of a DH table, in SI units (m, rad).

    Attributes
    ----------
    name : str
        Joint name (unique in the table).
    type : {"revolute", "prismatic", "continuous"}
        Joint kind. Revolute and continuous joints turn about their DH z axis, prismatic
        joints slide along it.
    a, alpha, d, theta : float
        DH parameters (m, rad, m, rad). ``theta`` is the constant offset of a revolute joint
        (θ = q + theta), ``d`` the constant offset of a prismatic joint (d = q + d). In the
        modified convention ``a`` and ``alpha`` are ``a_{i-1}`` and ``α_{i-1}``.
    lower, upper : float or None
        Position limits of the joint variable q (rad or m); ``None`` for continuous joints.
    velocity : float
        Velocity limit (rad/s or m/s).
    effort : float
        Effort limit (N·m or N).
    """

    name: str
    type: JointType
    a: float
    alpha: float
    d: float
    theta: float
    lower: float | None
    upper: float | None
    velocity: float
    effort: float

    @property
    def is_prismatic(self) -> bool:
        """Whether the joint slides (its variable is a length)."""
        return self.type == "prismatic"


@dataclass(frozen=True, slots=True)
class DHTable:
    """A validated DH table in SI units; build it with :meth:`from_dict` and friends.

    Attributes
    ----------
    name : str
        Robot id (``^[a-z0-9_-]{1,64}$``).
    convention : {"standard", "modified"}
        DH convention of the rows.
    joints : tuple of DHJoint
        The rows, base to tip.
    base : Transform
        World (root) frame → DH frame 0.
    tool : Transform
        DH frame n → tool (TCP); identity when the table has none.
    geometry_radius : float
        Radius (m) of the generated capsule geometry; 0 means no geometry.
    description : str
        Free text (may be empty).
    """

    name: str
    convention: Convention
    joints: tuple[DHJoint, ...]
    base: Transform = field(default_factory=Transform)
    tool: Transform = field(default_factory=Transform)
    geometry_radius: float = DEFAULT_GEOMETRY_RADIUS
    description: str = ""

    @property
    def dof(self) -> int:
        """Number of actuated joints (rows)."""
        return len(self.joints)

    @property
    def joint_names(self) -> list[str]:
        """Joint names in row order (the configuration order)."""
        return [j.name for j in self.joints]

    # ------------------------------------------------------------------ constructors

    @classmethod
    def from_dict(cls, data: Any) -> DHTable:
        """Validate a parsed document (a mapping) and convert it to SI.

        Raises
        ------
        DHError
            With the path of the first offending field.
        """
        return _parse_table(data)

    @classmethod
    def from_yaml(cls, text: str) -> DHTable:
        """Parse and validate a YAML document (``1e-3`` style floats are accepted)."""
        return cls.from_dict(_load_yaml(text))

    @classmethod
    def from_json(cls, text: str) -> DHTable:
        """Parse and validate a JSON document."""
        return cls.from_dict(_load_json(text))

    @classmethod
    def from_text(cls, text: str, format: Literal["yaml", "json"] = "yaml") -> DHTable:
        """Parse and validate a document in the given format."""
        if format == "json":
            return cls.from_json(text)
        if format == "yaml":
            return cls.from_yaml(text)
        raise ValueError(f"unknown format {format!r} (expected 'yaml' or 'json')")

    @classmethod
    def from_file(cls, path: str | Path) -> DHTable:
        """Read a ``.yaml``/``.yml`` or ``.json`` file and validate it.

        Raises
        ------
        DHError
            For an unsupported extension, unreadable YAML/JSON or an invalid table.
        OSError
            When the file cannot be read.
        """
        p = Path(path)
        fmt = format_for_path(p)
        return cls.from_text(p.read_text(encoding="utf-8"), fmt)

    def to_dict(self) -> dict[str, Any]:
        """The table as a document in SI units (``units: {length: m, angle: rad}``).

        ``DHTable.from_dict(table.to_dict()) == table`` holds exactly.
        """
        joints = []
        for j in self.joints:
            row: dict[str, Any] = {
                "name": j.name,
                "type": j.type,
                "a": j.a,
                "alpha": j.alpha,
                "d": j.d,
                "theta": j.theta,
            }
            if j.lower is not None:
                row["lower"] = j.lower
            if j.upper is not None:
                row["upper"] = j.upper
            row["velocity"] = j.velocity
            row["effort"] = j.effort
            joints.append(row)
        doc: dict[str, Any] = {"name": self.name}
        if self.description:
            doc["description"] = self.description
        doc.update(
            {
                "convention": self.convention,
                "units": {"length": "m", "angle": "rad"},
                "base": {"xyz": list(self.base.xyz), "rpy": list(self.base.rpy)},
                "tool": {"xyz": list(self.tool.xyz), "rpy": list(self.tool.rpy)},
                "geometry": {"radius": self.geometry_radius},
                "joints": joints,
            }
        )
        return doc


def format_for_path(path: str | Path) -> Literal["yaml", "json"]:
    """``"yaml"`` or ``"json"`` from a file name's extension; :class:`DHError` otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix in (".yaml", ".yml"):
        return "yaml"
    if suffix == ".json":
        return "json"
    raise DHError(
        None, f"unsupported file extension {suffix or '(none)'!r} (use .yaml, .yml or .json)"
    )


# ---------------------------------------------------------------------- text loaders


class HugeInt(str):
    """An integer literal too long to convert (kept as its text, refused by the validator)."""


def _int_literal(text: str) -> int | HugeInt:
    digits = len(text.lstrip("+-").replace("_", ""))
    return HugeInt(text) if digits > MAX_INT_DIGITS else int(text)


class _TableLoader(yaml.SafeLoader):
    """Safe YAML loader that rejects duplicate keys and reads ``1e-3`` as a float."""


_TableLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"),
)


def _construct_mapping(loader: _TableLoader, node: yaml.MappingNode) -> dict[Any, Any]:
    loader.flatten_mapping(node)
    result: dict[Any, Any] = {}
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=True)
        try:
            duplicate = key in result
        except TypeError as exc:
            raise DHError(
                None, f"invalid YAML: line {key_node.start_mark.line + 1}: unhashable key"
            ) from exc
        if duplicate:
            raise DHError(
                None,
                f"invalid YAML: line {key_node.start_mark.line + 1}: duplicate key {key!r}",
            )
        result[key] = loader.construct_object(value_node, deep=True)
    return result


_TableLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def _construct_int(loader: _TableLoader, node: yaml.ScalarNode) -> int | HugeInt:
    text = str(loader.construct_scalar(node))
    digits = len(text.lstrip("+-").replace("_", ""))
    if digits > MAX_INT_DIGITS:
        return HugeInt(text)
    return yaml.SafeLoader.construct_yaml_int(loader, node)


_TableLoader.add_constructor("tag:yaml.org,2002:int", _construct_int)


def _load_yaml(text: str) -> Any:
    try:
        return yaml.load(text, Loader=_TableLoader)  # a SafeLoader subclass
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
        raise DHError(None, f"invalid YAML: {where}{exc.problem or exc.context}") from exc
    except yaml.YAMLError as exc:
        raise DHError(None, f"invalid YAML: {exc}") from exc


def _load_json(text: str) -> Any:
    def pairs(items: list[tuple[str, Any]]) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for k, v in items:
            if k in out:
                raise DHError(None, f"invalid JSON: duplicate key {k!r}")
            out[k] = v
        return out

    try:
        return json.loads(text, object_pairs_hook=pairs, parse_int=_int_literal)
    except json.JSONDecodeError as exc:
        raise DHError(
            None, f"invalid JSON: line {exc.lineno}, column {exc.colno}: {exc.msg}"
        ) from exc
    except RecursionError as exc:
        raise DHError(None, "invalid JSON: nested too deeply") from exc


# ---------------------------------------------------------------------- validation


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
    )


def _parse_table(data: Any) -> DHTable:
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

    return DHTable(
        name=name,
        convention=convention,
        joints=tuple(joints),
        base=base,
        tool=tool,
        geometry_radius=radius,
        description=description,
    )
