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

Optional per-row dynamics of the link the row moves (link i), all in the DH frame at the
END of the row's transform (frame i, world pose ``B·A_1⋯A_i``, as the Robotics Toolbox's and
Corke's ``r`` and ``I``): ``mass`` (kg, always SI, ≥ 0), ``com`` [x, y, z] (table length
units) and ``inertia`` [ixx, ixy, ixz, iyy, iyz, izz] (kg·m², always SI, about the com in
frame i's axes; a physical rigid body: positive semi-definite, each principal moment at most
the sum of the other two). ``com`` and ``inertia`` default to 0 (a point mass at frame i's
origin) and need ``mass``. A row without them gives a link without ``<inertial>``::

      - {a: 0.4318, alpha: 0, d: 0, theta: 0, mass: 17.4, com: [-0.3638, 0.006, 0.2275],
         inertia: [0.13, 0, 0, 0.524, 0, 0.539]}

Every value is converted to SI (m, rad) when the table is built. Errors raise
:class:`DHError`, whose message names the offending field as a path into the document with
0-based list indices, e.g. ``joints[2].lower: lower (10) > upper (5)``. The checks live in
:mod:`dh2urdf.parse`, the strict YAML/JSON readers in :mod:`dh2urdf.loaders`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from dh2urdf.joint import (
    CONVENTIONS,
    DEFAULT_GEOMETRY_RADIUS,
    JOINT_TYPES,
    Convention,
    DHJoint,
    JointType,
    LinkDynamics,
    Transform,
)
from dh2urdf.loaders import format_for_path, load_json, load_yaml
from dh2urdf.parse import table_fields

__all__ = [
    "Convention",
    "JointType",
    "DHJoint",
    "DHTable",
    "LinkDynamics",
    "Transform",
    "CONVENTIONS",
    "JOINT_TYPES",
    "DEFAULT_GEOMETRY_RADIUS",
]


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
    def has_dynamics(self) -> bool:
        """Whether any row gives its link's mass (and so the URDF any ``<inertial>``)."""
        return any(j.dynamics is not None for j in self.joints)

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
        return cls(**table_fields(data))

    @classmethod
    def from_yaml(cls, text: str) -> DHTable:
        """Parse and validate a YAML document (``1e-3`` style floats are accepted)."""
        return cls.from_dict(load_yaml(text))

    @classmethod
    def from_json(cls, text: str) -> DHTable:
        """Parse and validate a JSON document."""
        return cls.from_dict(load_json(text))

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
            if j.dynamics is not None:
                row["mass"] = j.dynamics.mass
                row["com"] = list(j.dynamics.com)
                row["inertia"] = list(j.dynamics.inertia)
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
