"""dh2urdf: Denavit–Hartenberg tables to URDF (library and ``dh2urdf`` command).

Public API
----------
* :class:`DHTable` (``from_dict``, ``from_yaml``, ``from_json``, ``from_text``,
  ``from_file``, ``to_dict``), :class:`DHJoint`, :class:`LinkDynamics`, :class:`Transform`
  — the validated SI model of a table (:mod:`dh2urdf.table`), read by
  :mod:`dh2urdf.loaders` (strict YAML and JSON) and checked by :mod:`dh2urdf.parse`.
* :class:`DHError` — every bad table or document (:mod:`dh2urdf.errors`).
* :func:`to_urdf`, :func:`to_yourdfpy`, :func:`write_urdf` — the conversion
  (:mod:`dh2urdf.urdf`).
* :mod:`dh2urdf.math` — the pure-NumPy reference: ``dh_standard``, ``dh_modified``,
  ``chain``.

This package never imports the service (``app``).
"""

from __future__ import annotations

from dh2urdf.errors import DHError
from dh2urdf.table import DHJoint, DHTable, LinkDynamics, Transform
from dh2urdf.urdf import to_urdf, to_yourdfpy, write_urdf

__all__ = [
    "DHError",
    "DHJoint",
    "DHTable",
    "LinkDynamics",
    "Transform",
    "to_urdf",
    "to_yourdfpy",
    "write_urdf",
]
