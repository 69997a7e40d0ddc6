"""dh2urdf: Denavit–Hartenberg tables to URDF (library and ``dh2urdf`` command).

Public API
----------
* :class:`DHTable` (``from_dict``, ``from_yaml``, ``from_json``, ``from_text``,
  ``from_file``, ``to_dict``), :class:`DHJoint`, :class:`Transform`, :class:`DHError`
  — the validated SI model of a table (:mod:`dh2urdf.table`).
* :func:`to_urdf`, :func:`to_yourdfpy`, :func:`write_urdf` — the conversion
  (:mod:`dh2urdf.urdf`).
* :mod:`dh2urdf.math` — the pure-NumPy reference: ``dh_standard``, ``dh_modified``,
  ``chain``.

This package never imports the service (``app``).
"""

from __future__ import annotations

from dh2urdf.table import DHError, DHJoint, DHTable, Transform
from dh2urdf.urdf import to_urdf, to_yourdfpy, write_urdf

__all__ = ["DHError", "DHJoint", "DHTable", "Transform", "to_urdf", "to_yourdfpy", "write_urdf"]
